//! A batch's output: its columns, and each row written as a CSV line (into
//! a piece's byte buffer, numbers as `format!` writes them) or a JSON line
//! (serde's).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Write as _;

use serde::Serialize;

use super::flights::RowFlight;
use super::kinds::KindTally;
use super::plural;
use super::rows::Job;
use super::savant_columns::{Setup, quoted};
use crate::analysis::calibrate::{BAND_EDGES, band_of};
use crate::cli::shown::Shown;
use crate::model::clearing::Clearing;
use crate::preset::escape_cut;
use crate::units::Quantity;

/// The output's columns, in order: then [`STATCAST_COLUMNS`] when the input
/// has Statcast's distance, then `--keep`'s.
pub const OUTPUT_COLUMNS: [&str; 19] = [
    "line",
    "launch.speed",
    "launch.angle",
    "launch.spin",
    "launch.direction",
    "launch.sidespin",
    "range",
    "direction",
    "flight_time",
    "apex",
    "landing_angle",
    "landed",
    "clears_fence",
    "park",
    "outcome",
    "margin",
    "parks_cleared",
    "spin_estimated",
    "direction_from",
];

/// What each output column measures, for its unit outside SI.
const OUTPUT_QUANTITIES: [Quantity; 19] = [
    Quantity::Unchanged,
    Quantity::Speed,
    Quantity::Angle,
    Quantity::Spin,
    Quantity::Angle,
    Quantity::Spin,
    Quantity::Distance,
    Quantity::Angle,
    Quantity::Unchanged,
    Quantity::Distance,
    Quantity::Angle,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Distance,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Unchanged,
];

/// Statcast's distance and the model's range less it.
const STATCAST_COLUMNS: [(&str, Quantity); 2] = [
    ("statcast_distance", Quantity::Distance),
    ("difference", Quantity::Distance),
];

/// The CSV header line.
pub(super) fn csv_header(statcast: bool, setup: &Setup, shown: Shown) -> String {
    let swing = super::swing_columns::CSV_COLUMNS
        .iter()
        .copied()
        .filter(|_| setup.swing_columns);
    let mut names: Vec<String> = OUTPUT_COLUMNS[..1]
        .iter()
        .copied()
        .zip(OUTPUT_QUANTITIES)
        .chain(swing)
        .chain(
            OUTPUT_COLUMNS[1..]
                .iter()
                .copied()
                .zip(OUTPUT_QUANTITIES[1..].iter().copied()),
        )
        .chain(STATCAST_COLUMNS.into_iter().filter(|_| statcast))
        .map(|(name, quantity)| shown.csv_key(name, quantity))
        .collect();
    if setup.all_parks {
        for park in &setup.parks.parks {
            let code = &park.code;
            names.push(quoted(&format!("{code}_outcome")));
            names.push(quoted(
                &shown.csv_key(&format!("{code}_margin"), Quantity::Distance),
            ));
        }
    }
    names.extend(setup.keep.iter().map(|n| quoted(n)));
    names.join(",") + "\n"
}

/// The `park` of a row at no park.
const GENERIC: &str = "generic";

/// The row's park code, or "generic".
fn park_code<'a>(job: &Job, setup: &Setup<'a>) -> &'a str {
    job.park
        .map_or(GENERIC, |i| setup.parks.parks[i].code.as_str())
}

/// The model's range less Statcast's distance (m), if both are known.
fn difference(job: &Job, flown: &RowFlight) -> Option<f64> {
    let flight = &flown.flight;
    job.statcast
        .filter(|_| flight.landed)
        .map(|measured| flight.range - measured)
}

/// Writes a row's CSV line: its numbers, in the units shown, to the
/// decimals `fly --batch` has always printed.
pub(super) struct CsvLine<'a> {
    pub setup: &'a Setup<'a>,
    pub shown: Shown,
    pub statcast: bool,
}

impl CsvLine<'_> {
    /// A number of `quantity` to `si_decimals` in SI (about as fine in
    /// the other system), and its comma; nothing for none.
    pub(super) fn number(
        &self,
        out: &mut Vec<u8>,
        quantity: Quantity,
        si: Option<f64>,
        decimals: usize,
    ) {
        if let Some(si) = si {
            let decimals = self.shown.unit(quantity).decimals(decimals);
            let start = out.len();
            write_fixed(out, self.shown.convert(quantity, si), decimals);
            // Outside SI, a number as its reader wrote it: 99.9 mph,
            // not 99.9000 (trailing zeros trimmed, one decimal kept).
            if !self.shown.is_si() && decimals > 1 {
                let keep = out[start..]
                    .iter()
                    .rposition(|&b| b != b'0')
                    .map_or(out.len(), |last| start + last + 1);
                let point = out[start..].iter().position(|&b| b == b'.');
                let keep = point.map_or(keep, |p| keep.max(start + p + 2));
                out.truncate(keep);
            }
        }
        out.push(b',');
    }

    /// `judged`: with `--all-parks`, the row at each park, else empty.
    pub(super) fn write(
        &self,
        out: &mut Vec<u8>,
        job: &Job,
        flown: &RowFlight,
        judged: &[Clearing],
    ) {
        let (launch, flight) = (&flown.launch, &flown.flight);
        let number = |out: &mut Vec<u8>, quantity: Quantity, si: Option<f64>, decimals: usize| {
            self.number(out, quantity, si, decimals)
        };
        let _ = write!(out, "{},", job.line);
        if self.setup.swing_columns {
            super::swing_columns::write_csv(self, out, job);
        }
        number(out, Quantity::Speed, Some(launch.speed), 4);
        number(out, Quantity::Angle, Some(launch.angle), 6);
        number(out, Quantity::Spin, Some(launch.spin), 3);
        number(out, Quantity::Angle, Some(launch.direction), 6);
        number(out, Quantity::Spin, Some(launch.sidespin), 3);
        let range = flight.landed.then_some(flight.range);
        number(out, Quantity::Distance, range, 3);
        number(out, Quantity::Angle, Some(flight.direction), 6);
        number(out, Quantity::Unchanged, Some(flight.flight_time), 3);
        number(out, Quantity::Distance, Some(flight.apex), 3);
        number(out, Quantity::Angle, Some(flight.landing_angle), 4);
        let park = job.park.map(|i| self.setup.code_fields[i].as_str());
        let _ = write!(
            out,
            "{},{},{},{},",
            flight.landed,
            flown.clearing.clears(),
            park.unwrap_or(GENERIC),
            flown.clearing.outcome.name()
        );
        number(out, Quantity::Distance, flown.clearing.margin, 3);
        let _ = write!(
            out,
            "{},{},{}",
            flown.parks_cleared,
            job.launch.estimates_spin(),
            flown.direction_from.name()
        );
        if self.statcast {
            for value in [job.statcast, difference(job, flown)] {
                out.push(b',');
                number(out, Quantity::Distance, value, 2);
                out.pop();
            }
        }
        for there in judged {
            let _ = write!(out, ",{},", there.outcome.name());
            number(out, Quantity::Distance, there.margin, 3);
            out.pop();
        }
        for cell in &job.kept {
            out.push(b',');
            // Control characters reach a terminal escaped, a file as read.
            let cell = match self.setup.escape_kept {
                true => escape_cut(cell, usize::MAX),
                false => cell.clone(),
            };
            out.extend_from_slice(quoted(&cell).as_bytes());
        }
        out.push(b'\n');
    }
}

/// A row's JSON line (SI, every digit): keys in name order, as a tree of
/// `serde_json` values kept them.
#[derive(Serialize)]
struct JsonLine<'a> {
    /// With `--all-parks`: the row at each park.
    #[serde(skip_serializing_if = "Option::is_none")]
    all_parks: Option<Vec<AtParkJson<'a>>>,
    clears_fence: bool,
    direction_from: &'static str,
    fence: FenceJson<'a>,
    flight: FlightJson,
    #[serde(skip_serializing_if = "Option::is_none")]
    impact: Option<ImpactJson<'a>>,
    /// The kept cells by column name: a repeated name's last cell.
    #[serde(skip_serializing_if = "Option::is_none")]
    kept: Option<BTreeMap<&'a str, &'a str>>,
    launch: LaunchJson,
    line: usize,
    parks: ParksJson<'a>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pitch: Option<PitchJson>,
    /// Solving swings: why a row is not solved, and by how much speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    reason: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    shortfall: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    solved: Option<bool>,
    spin_estimated: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    statcast: Option<StatcastJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    swing: Option<SwingJson>,
}

#[derive(Serialize)]
struct FenceJson<'a> {
    direction: f64,
    distance: Option<f64>,
    height: Option<f64>,
    height_at_fence: Option<f64>,
    margin: Option<f64>,
    outcome: &'a str,
    park: &'a str,
}

#[derive(Serialize)]
struct AtParkJson<'a> {
    margin: Option<f64>,
    outcome: &'a str,
    park: &'a str,
}

#[derive(Serialize)]
struct FlightJson {
    apex: f64,
    direction: f64,
    flight_time: f64,
    landed: bool,
    landing_angle: f64,
    range: Option<f64>,
}

#[derive(Serialize)]
struct LaunchJson {
    angle: f64,
    direction: f64,
    /// Out of a solved impact: the spin about the launch velocity.
    #[serde(skip_serializing_if = "Option::is_none")]
    gyrospin: Option<f64>,
    sidespin: f64,
    speed: f64,
    spin: f64,
}

use super::swing_columns::{ImpactJson, PitchJson, SwingJson};

#[derive(Serialize)]
struct ParksJson<'a> {
    cleared: usize,
    codes: Vec<&'a str>,
}

#[derive(Serialize)]
struct StatcastJson {
    difference: Option<f64>,
    distance: f64,
}

/// Appends a row's JSON line.
pub(super) fn json_line(
    out: &mut Vec<u8>,
    job: &Job,
    flown: &RowFlight,
    (cleared, judged): (&[bool], &[Clearing]),
    setup: &Setup,
) {
    let (launch, flight, fence) = (&flown.launch, &flown.flight, &flown.clearing);
    let swing = super::swing_columns::json_parts(job);
    let parks = setup.parks.parks.iter().zip(cleared);
    let line = JsonLine {
        all_parks: setup.all_parks.then(|| {
            (setup.parks.parks.iter().zip(judged))
                .map(|(park, there)| AtParkJson {
                    margin: there.margin,
                    outcome: there.outcome.name(),
                    park: park.code.as_str(),
                })
                .collect()
        }),
        clears_fence: fence.clears(),
        fence: FenceJson {
            direction: fence.direction,
            distance: fence.wall.map(|w| w.distance),
            height: fence.wall.map(|w| w.height),
            height_at_fence: fence.height_at_fence,
            margin: fence.margin,
            outcome: fence.outcome.name(),
            park: park_code(job, setup),
        },
        flight: FlightJson {
            apex: flight.apex,
            direction: flight.direction,
            flight_time: flight.flight_time,
            landed: flight.landed,
            landing_angle: flight.landing_angle,
            range: flight.landed.then_some(flight.range),
        },
        kept: (!setup.keep.is_empty()).then(|| {
            let names = setup.keep.iter().map(String::as_str);
            names.zip(job.kept.iter().map(String::as_str)).collect()
        }),
        launch: LaunchJson {
            angle: launch.angle,
            direction: launch.direction,
            gyrospin: swing.gyrospin,
            sidespin: launch.sidespin,
            speed: launch.speed,
            spin: launch.spin,
        },
        line: job.line,
        parks: ParksJson {
            cleared: flown.parks_cleared,
            codes: (parks.filter(|(_, c)| **c))
                .map(|(park, _)| park.code.as_str())
                .collect(),
        },
        impact: swing.impact,
        pitch: swing.pitch,
        reason: swing.reason,
        shortfall: swing.shortfall,
        solved: swing.solved,
        swing: swing.swing,
        spin_estimated: job.launch.estimates_spin(),
        direction_from: flown.direction_from.name(),
        statcast: job.statcast.map(|distance| StatcastJson {
            difference: difference(job, flown),
            distance,
        }),
    };
    // Into a Vec, serde_json cannot fail.
    let _ = serde_json::to_writer(&mut *out, &line);
    out.push(b'\n');
}

/// What a batch's rows came to, for the one summary at its end: the
/// outcomes at each row's park, and the model's range less Statcast's
/// distance where the row has one.
#[derive(Clone, Debug, Default)]
pub(super) struct Tally {
    /// Clears, off the wall, short, foul.
    pub outcomes: [usize; 4],
    /// Launch angle (rad) and model − Statcast (m), one a row that has both.
    pub differences: Vec<(f64, f64)>,
    /// The same by kind of ball, and the home runs' verdicts.
    pub kinds: KindTally,
}

/// The summary's table looks at the model's error by launch-angle band, as
/// docs/accuracy.md does (a tilt by launch angle shows there, not in one
/// median): below 10°, then `calibrate`'s bands of balls in the air.
pub(super) const BANDS: usize = BAND_EDGES.len() + 1;

/// The summary's band of a launch angle (rad): 0 below the first edge,
/// band k from edge k − 1.
pub(super) fn band_index(angle: f64) -> usize {
    band_of(angle).map_or(0, |b| b + 1)
}

/// Band `band`'s launch angles (°): from (none for the lowest) up to (none
/// for the highest).
pub(super) fn band_bounds(band: usize) -> (Option<f64>, Option<f64>) {
    (
        band.checked_sub(1).map(|k| BAND_EDGES[k]),
        BAND_EDGES.get(band).copied(),
    )
}

/// A band's name in a table: "< 10°", "10–20°", "50°+".
pub(super) fn band_name((from, to): (Option<f64>, Option<f64>)) -> String {
    match (from, to) {
        (None, Some(to)) => format!("< {to}°"),
        (Some(from), None) => format!("{from}°+"),
        (Some(from), Some(to)) => format!("{from}–{to}°"),
        (None, None) => String::from("all"),
    }
}

/// One band's rows, median difference and median |difference| (m).
#[derive(Serialize)]
pub(super) struct Band {
    /// From this launch angle (°, none for the lowest band) up to `to`.
    from: Option<f64>,
    to: Option<f64>,
    rows: usize,
    median: Option<f64>,
    median_abs: Option<f64>,
}

impl Tally {
    pub(super) fn count(&mut self, job: &Job, flown: &RowFlight) {
        use crate::model::clearing::Outcome;
        let at = match flown.clearing.outcome {
            Outcome::Clears => 0,
            Outcome::OffTheWall => 1,
            Outcome::Short => 2,
            Outcome::Foul => 3,
        };
        self.outcomes[at] += 1;
        let angle = flown.launch.angle;
        let difference = difference(job, flown);
        self.differences.extend(difference.map(|d| (angle, d)));
        self.kinds.count(job.called, angle, difference, at == 0);
    }

    pub(super) fn add(&mut self, other: &Tally) {
        for (total, n) in self.outcomes.iter_mut().zip(other.outcomes) {
            *total += n;
        }
        self.differences.extend_from_slice(&other.differences);
        self.kinds.add(&other.kinds);
    }

    /// "flown 248 rows, skipped 0; at their parks 169 clear, 39 off the
    /// wall, 37 short, 3 foul; against hit_distance_sc (248 rows): median
    /// difference +1.3 ft, median |difference| 9.8 ft", in the units shown.
    pub(super) fn line(&self, flown: usize, skipped: usize, at: &str, shown: Shown) -> String {
        let [clear, wall, short, foul] = self.outcomes;
        let mut line = format!(
            "summary: flown {flown} row{}, skipped {skipped}; {at}: {clear} clear, {wall} off the wall, {short} short, {foul} foul",
            plural(flown)
        );
        if !self.differences.is_empty() {
            let mut signed: Vec<f64> = self.differences.iter().map(|d| d.1).collect();
            let unit = shown.unit(Quantity::Distance);
            let (median, typical) = medians(&mut signed);
            let _ = write!(
                line,
                "; against hit_distance_sc ({} rows): median difference {:+.1} {}, median |difference| {:.1} {}",
                signed.len(),
                unit.show(median),
                unit.symbol,
                unit.show(typical),
                unit.symbol
            );
        }
        line
    }
}

impl Tally {
    /// The differences by launch-angle band, in SI.
    pub(super) fn bands(&self) -> Vec<Band> {
        (0..BANDS)
            .map(|band| {
                let mut signed: Vec<f64> = (self.differences.iter())
                    .filter(|(angle, _)| band_index(*angle) == band)
                    .map(|d| d.1)
                    .collect();
                let both = (!signed.is_empty()).then(|| medians(&mut signed));
                let (from, to) = band_bounds(band);
                Band {
                    from,
                    to,
                    rows: signed.len(),
                    median: both.map(|m| m.0),
                    median_abs: both.map(|m| m.1),
                }
            })
            .collect()
    }

    /// The bands as a small table, in the units shown: a header, then a
    /// line a band ("10–20°  4,512  +17.8 ft  19.3 ft").
    pub(super) fn band_table(&self, shown: Shown) -> String {
        let unit = shown.unit(Quantity::Distance);
        let mut table = format!(
            "by launch angle, model − hit_distance_sc ({}):\n{:<8} {:>7} {:>8} {:>10}\n",
            unit.symbol, "angle", "rows", "median", "median |d|"
        );
        for band in self.bands() {
            let name = band_name((band.from, band.to));
            let show = |m: Option<f64>, sign: bool| match m {
                Some(m) if sign => format!("{:+.1}", unit.show(m)),
                Some(m) => format!("{:.1}", unit.show(m)),
                None => String::from("-"),
            };
            let _ = writeln!(
                table,
                "{name:<8} {:>7} {:>8} {:>10}",
                band.rows,
                show(band.median, true),
                show(band.median_abs, false)
            );
        }
        table.pop();
        table
    }
}

/// The median of `differences` (not empty) and the median of their sizes,
/// sorting them.
pub(super) fn medians(differences: &mut [f64]) -> (f64, f64) {
    let mut sizes: Vec<f64> = differences.iter().map(|d| d.abs()).collect();
    (median(differences), median(&mut sizes))
}

/// The median of `values` (not empty), sorting them.
pub(super) fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        (values[n / 2 - 1] + values[n / 2]) / 2.0
    }
}

/// `value` to `decimals` places, as `format!("{value:.decimals$}")` writes
/// it, through the integer of its scaled value: std's fixed-precision
/// formatting often falls back from Grisu to Dragon (measured: `{:.4}` of
/// values in [0, 150] ~570 ns, `{:.3}` ~190 ns): with this, 20k planar
/// rows 859 → 775 M instructions (callgrind), 200k planar rows 0.91 → 0.77 s
/// of CPU, 200k 3-D rows 1.59 → 1.34 s (best of 3), output byte-identical. A value whose
/// scaled integer is not exact in f64, or that lies within a few ulps of a
/// tie, goes to std, so every digit is std's (tested on 3.2M values).
fn write_fixed(out: &mut Vec<u8>, value: f64, decimals: usize) {
    const POWERS: [f64; 7] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6];
    let scaled = POWERS.get(decimals).map(|power| value * power);
    // Near a tie the product's own rounding may decide it: std's exact digits do.
    let clear_of_a_tie = |scaled: f64| {
        let fraction = (scaled - scaled.trunc()).abs();
        (fraction - 0.5).abs() > 8.0 * f64::EPSILON * scaled.abs().max(1.0)
    };
    match scaled {
        Some(scaled) if scaled.abs() < 9.0e15 && clear_of_a_tie(scaled) => {
            let scaled = scaled.round();
            if value.is_sign_negative() {
                out.push(b'-');
            }
            let digits = scaled.abs() as u64;
            let unit = 10u64.pow(decimals as u32);
            // The integers by `itoa` (serde_json's own): `write!`'s
            // formatting machinery was a tenth of a planar batch.
            let mut integer = itoa::Buffer::new();
            out.extend_from_slice(integer.format(digits / unit).as_bytes());
            if decimals > 0 {
                out.push(b'.');
                let part = integer.format(digits % unit).as_bytes();
                out.resize(out.len() + decimals - part.len(), b'0');
                out.extend_from_slice(part);
            }
        }
        _ => {
            let _ = write!(out, "{value:.decimals$}");
        }
    }
}

#[cfg(test)]
mod fixed_tests {
    #[test]
    fn fixed_decimals_are_std_s() {
        let mut uniform = numerics::xorshift::uniform(0x2545_f491_4f6c_dd1d);
        let mut specials = vec![
            0.0, -0.0, 0.5, 1.5, 2.5, -2.5, 1.03125, 0.00005, -1e-9, 1e300, -7.0,
        ];
        specials.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 123.456_789_5]);
        let mut out = Vec::new();
        for i in 0..400_000 {
            let value = if i < specials.len() {
                specials[i]
            } else {
                // Magnitudes from 1e-8 to 1e6, either sign.
                let magnitude = 10f64.powf(uniform() * 14.0 - 8.0);
                if uniform() < 0.5 {
                    -magnitude
                } else {
                    magnitude
                }
            };
            for decimals in 0..=7 {
                out.clear();
                super::write_fixed(&mut out, value, decimals);
                assert_eq!(
                    std::str::from_utf8(&out).unwrap(),
                    format!("{value:.decimals$}"),
                    "{value:e} to {decimals}"
                );
            }
        }
    }
}
