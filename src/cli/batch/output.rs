//! A batch's output: its columns, and each row written as a CSV line (into
//! a piece's byte buffer, numbers by [`fixed`]) or a JSON line.

use super::fixed;
use super::flights::RowFlight;
use super::rows::Job;
use super::savant_columns::{Setup, quoted, write_quoted};
use crate::cli::ground::clearing_json;
use crate::cli::shown::Shown;
use crate::units::Quantity;

/// The output's columns, in order: then [`STATCAST_COLUMNS`] when the input
/// has Statcast's distance, then `--keep`'s.
pub const OUTPUT_COLUMNS: [&str; 18] = [
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
];

/// What each output column measures, for its unit outside SI.
const OUTPUT_QUANTITIES: [Quantity; 18] = [
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
];

/// Statcast's distance and the model's range less it.
const STATCAST_COLUMNS: [(&str, Quantity); 2] = [
    ("statcast_distance", Quantity::Distance),
    ("difference", Quantity::Distance),
];

/// The CSV header line.
pub(super) fn csv_header(statcast: bool, setup: &Setup, shown: Shown) -> String {
    let mut names: Vec<String> = OUTPUT_COLUMNS
        .iter()
        .copied()
        .zip(OUTPUT_QUANTITIES)
        .chain(STATCAST_COLUMNS.into_iter().filter(|_| statcast))
        .map(|(name, quantity)| shown.csv_key(name, quantity))
        .collect();
    names.extend(setup.keep.iter().map(|n| quoted(n)));
    names.join(",") + "\n"
}

/// The row's park code, or "generic".
fn park_code<'a>(job: &Job, setup: &Setup<'a>) -> &'a str {
    job.park
        .map_or("generic", |i| setup.parks.parks[i].code.as_str())
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
    pub(super) fn write(&self, out: &mut Vec<u8>, job: &Job, flown: &RowFlight, kept: &[&str]) {
        let (launch, flight) = (&flown.launch, &flown.flight);
        let number = |out: &mut Vec<u8>, quantity, si, si_decimals| {
            let decimals = self.shown.unit(quantity).decimals(si_decimals);
            fixed::write(out, self.shown.convert(quantity, si), decimals);
            out.push(b',');
        };
        let word = |out: &mut Vec<u8>, text: &str| {
            out.extend_from_slice(text.as_bytes());
            out.push(b',');
        };
        word(out, itoa::Buffer::new().format(job.line));
        number(out, Quantity::Speed, launch.speed, 4);
        number(out, Quantity::Angle, launch.angle, 6);
        number(out, Quantity::Spin, launch.spin, 3);
        number(out, Quantity::Angle, launch.direction, 6);
        number(out, Quantity::Spin, launch.sidespin, 3);
        match flight.landed {
            true => number(out, Quantity::Distance, flight.range, 3),
            false => out.push(b','),
        }
        number(out, Quantity::Angle, flight.direction, 6);
        fixed::write(out, flight.flight_time, 3);
        out.push(b',');
        number(out, Quantity::Distance, flight.apex, 3);
        number(out, Quantity::Angle, flight.landing_angle, 4);
        word(out, if flight.landed { "true" } else { "false" });
        word(
            out,
            if flown.clearing.clears() {
                "true"
            } else {
                "false"
            },
        );
        write_quoted(out, park_code(job, self.setup));
        out.push(b',');
        word(out, flown.clearing.outcome.name());
        match flown.clearing.margin {
            Some(margin) => number(out, Quantity::Distance, margin, 3),
            None => out.push(b','),
        }
        word(out, itoa::Buffer::new().format(flown.parks_cleared));
        out.extend_from_slice(if job.launch.estimates_spin() {
            b"true"
        } else {
            b"false"
        });
        if self.statcast {
            for value in [job.statcast, difference(job, flown)] {
                out.push(b',');
                if let Some(m) = value {
                    let decimals = self.shown.unit(Quantity::Distance).decimals(2);
                    fixed::write(out, self.shown.convert(Quantity::Distance, m), decimals);
                }
            }
        }
        for cell in kept {
            out.push(b',');
            write_quoted(out, cell);
        }
        out.push(b'\n');
    }
}

/// A row's JSON line (SI, every digit).
pub(super) fn json_line(
    job: &Job,
    flown: &RowFlight,
    cleared: &[bool],
    kept: &[&str],
    setup: &Setup,
) -> String {
    let (launch, flight) = (&flown.launch, &flown.flight);
    let codes: Vec<&str> = setup
        .parks
        .parks
        .iter()
        .zip(cleared)
        .filter(|(_, c)| **c)
        .map(|(p, _)| p.code.as_str())
        .collect();
    let mut json = serde_json::json!({
        "line": job.line,
        // {speed, angle, spin, direction, sidespin}, as `fly --json`.
        "launch": launch,
        "flight": {
            "range": flight.landed.then_some(flight.range),
            "direction": flight.direction,
            "flight_time": flight.flight_time,
            "apex": flight.apex,
            "landing_angle": flight.landing_angle,
            "landed": flight.landed,
        },
        "clears_fence": flown.clearing.clears(),
        "fence": clearing_json(park_code(job, setup), &flown.clearing),
        "parks": {
            "cleared": flown.parks_cleared,
            "codes": codes,
        },
        "spin_estimated": job.launch.estimates_spin(),
    });
    if let Some(measured) = job.statcast {
        json["statcast"] = serde_json::json!({
            "distance": measured,
            "difference": difference(job, flown),
        });
    }
    if !kept.is_empty() {
        json["kept"] = setup
            .keep
            .iter()
            .zip(kept)
            .map(|(name, value)| (name.clone(), serde_json::Value::from(*value)))
            .collect::<serde_json::Map<_, _>>()
            .into();
    }
    json.to_string() + "\n"
}
