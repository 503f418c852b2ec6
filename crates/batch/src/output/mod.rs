//! A batch's output: its columns, and each row written as a CSV line (into
//! a piece's byte buffer, numbers as `format!` writes them) or a JSON line
//! (serde's).

use std::collections::BTreeMap;
use std::io::Write as _;

use serde::Serialize;

use crate::flights::{RowFlight, Scratch};
use crate::row::Job;
use crate::setup::{Setup, quoted};
use analysis::shown::Shown;
use model::clearing::Clearing;
use preset::escape_cut;
use units::Quantity;

mod swing;

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

/// Whether the row flew a tracker's measured spin, when the input has
/// `hit_spin_rate`: after [`STATCAST_COLUMNS`].
const SPIN_MEASURED: &str = "spin_measured";

/// Statcast's distance and the model's range less it.
const STATCAST_COLUMNS: [(&str, Quantity); 2] = [
    ("statcast_distance", Quantity::Distance),
    ("difference", Quantity::Distance),
];

/// The CSV header line.
pub(crate) fn csv_header(
    (statcast, spin_measured): (bool, bool),
    setup: &Setup,
    shown: Shown,
) -> String {
    let swing = swing::CSV_COLUMNS
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
        .chain(
            [(SPIN_MEASURED, Quantity::Unchanged)]
                .into_iter()
                .filter(|_| spin_measured),
        )
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
    for kept in &setup.keep {
        // A kept column named as one of the output's own is told apart.
        let name = match names.iter().any(|n| n == kept) {
            true => format!("kept.{kept}"),
            false => kept.clone(),
        };
        names.push(quoted(&name));
    }
    names.join(",") + "\n"
}

/// The `park` of a row at the preset's own fence (`[field]`, `field.*`),
/// and of a row at no park and no fence: no verdict is given there.
const GENERIC: &str = "generic";
const NO_PARK: &str = "none";

/// The row's park code, "generic" or "none".
fn park_code<'a>(job: &Job, setup: &Setup<'a>) -> &'a str {
    match job.park {
        Some(i) => setup.parks.parks[i].code.as_str(),
        None if job.fence_given => GENERIC,
        None => NO_PARK,
    }
}

/// The row's outcome: at no park and no fence only a foul ball is called.
fn outcome_name(job: &Job, clearing: &Clearing) -> &'static str {
    match clearing.outcome {
        model::clearing::Outcome::Foul => clearing.outcome.name(),
        _ if !job.fence_known() => "no_park",
        outcome => outcome.name(),
    }
}

/// What the output prints of a row.
#[derive(Clone, Copy)]
pub(crate) struct Printed {
    pub shown: Shown,
    /// The `difference` column (range less Statcast's) is printed.
    pub statcast: bool,
    /// The input has `hit_spin_rate`: each row says whether it flew it.
    pub spin_measured: bool,
    pub json: bool,
}

/// Appends the row's CSV or JSON line.
pub(crate) fn write_row(
    out: &mut Vec<u8>,
    (job, flown): (&Job, &RowFlight),
    scratch: &Scratch,
    setup: &Setup,
    printed: Printed,
) {
    let parks = setup.parks.parks.len();
    let judged = match setup.all_parks {
        true => &scratch.clearings[flown.cleared_from..][..parks],
        false => &[],
    };
    if printed.json {
        let cleared = &scratch.cleared[flown.cleared_from..][..parks];
        json_line(out, (job, flown), (cleared, judged), setup, printed);
    } else {
        let csv = CsvLine {
            setup,
            shown: printed.shown,
            statcast: printed.statcast,
            spin_measured: printed.spin_measured,
        };
        csv.write(out, job, flown, judged);
    }
}

/// Writes a row's CSV line: its numbers, in the units shown, to the
/// decimals `fly --batch` has always printed.
pub(crate) struct CsvLine<'a> {
    pub setup: &'a Setup<'a>,
    pub shown: Shown,
    pub statcast: bool,
    pub spin_measured: bool,
}

impl CsvLine<'_> {
    /// A number of `quantity` to `si_decimals` in SI (about as fine in
    /// the other system), and its comma; nothing for none.
    pub(crate) fn number(
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
    pub(crate) fn write(
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
            swing::write_csv(self, out, job);
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
        let known = job.fence_known();
        let _ = write!(
            out,
            "{},{},{},{},",
            flight.landed,
            if known {
                flown.clearing.clears().to_string()
            } else {
                String::new()
            },
            park.unwrap_or(park_code(job, self.setup)),
            outcome_name(job, &flown.clearing)
        );
        let margin = flown.clearing.margin.filter(|_| known);
        number(out, Quantity::Distance, margin, 3);
        let _ = write!(
            out,
            "{},{},{}",
            flown.parks_cleared,
            job.spin_estimated(),
            flown.direction_from.name()
        );
        if self.statcast {
            for value in [job.statcast, flown.difference(job)] {
                out.push(b',');
                number(out, Quantity::Distance, value, 2);
                out.pop();
            }
        }
        if self.spin_measured {
            let _ = write!(out, ",{}", job.spin_measured.taken());
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
    clears_fence: Option<bool>,
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
    spin_measured: Option<bool>,
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

use swing::{ImpactJson, PitchJson, SwingJson};

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
fn json_line(
    out: &mut Vec<u8>,
    (job, flown): (&Job, &RowFlight),
    (cleared, judged): (&[bool], &[Clearing]),
    setup: &Setup,
    printed: Printed,
) {
    let shown = printed.shown;
    let known = job.fence_known();
    let (launch, flight, fence) = (&flown.launch, &flown.flight, &flown.clearing);
    let swing = swing::json_parts(job);
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
        clears_fence: known.then(|| fence.clears()),
        fence: FenceJson {
            direction: fence.direction,
            distance: fence.wall.filter(|_| known).map(|w| w.distance),
            height: fence.wall.filter(|_| known).map(|w| w.height),
            height_at_fence: fence.height_at_fence.filter(|_| known),
            margin: fence.margin.filter(|_| known),
            outcome: outcome_name(job, fence),
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
        spin_estimated: job.spin_estimated(),
        spin_measured: printed.spin_measured.then(|| job.spin_measured.taken()),
        direction_from: flown.direction_from.name(),
        statcast: job.statcast.map(|distance| StatcastJson {
            difference: flown.difference(job),
            distance,
        }),
    };
    // Into a Vec, serde_json cannot fail.
    let start = out.len();
    if shown.is_si() {
        let _ = serde_json::to_writer(&mut *out, &line);
    } else {
        let mut value = serde_json::to_value(&line).unwrap_or_default();
        in_units(&mut value, shown);
        let _ = serde_json::to_writer(&mut *out, &value);
    }
    // To a terminal, the kept cells' controls and bidi characters as JSON
    // escapes (the same values).
    if setup.escape_kept {
        let text = String::from_utf8_lossy(&out[start..]).into_owned();
        if let std::borrow::Cow::Owned(escaped) = preset::json_for_terminal(&text) {
            out.truncate(start);
            out.extend_from_slice(escaped.as_bytes());
        }
    }
    out.push(b'\n');
}

/// What each JSON key that has a unit measures.
fn quantity_of(key: &str) -> Option<Quantity> {
    Some(match key {
        "speed" | "max_exit_speed" | "shortfall" | "bat_speed" | "contact_speed" => Quantity::Speed,
        "angle" | "direction" | "landing_angle" | "descent_angle" | "tilt" => Quantity::Angle,
        "spin" | "sidespin" | "gyrospin" => Quantity::Spin,
        "range" | "apex" | "distance" | "height" | "height_at_fence" | "margin" | "difference" => {
            Quantity::Distance
        }
        "undercut" => Quantity::Size,
        "effective_mass" => Quantity::Mass,
        _ => return None,
    })
}

/// A JSON line's numbers in the units shown, each key named with its unit
/// (`range_ft`), as the CSV's columns are.
fn in_units(value: &mut serde_json::Value, shown: Shown) {
    match value {
        serde_json::Value::Object(map) => {
            let taken = std::mem::take(map);
            for (key, mut inner) in taken {
                match (quantity_of(&key), inner.as_f64()) {
                    (Some(quantity), Some(si)) => {
                        let converted = shown.convert(quantity, si);
                        map.insert(shown.csv_key(&key, quantity), converted.into());
                    }
                    (Some(quantity), None) if inner.is_null() => {
                        map.insert(shown.csv_key(&key, quantity), inner);
                    }
                    _ => {
                        in_units(&mut inner, shown);
                        map.insert(key, inner);
                    }
                }
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(|v| in_units(v, shown)),
        _ => {}
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
