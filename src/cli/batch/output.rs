//! A batch's output: its columns, and each row written as a CSV line (into
//! a piece's byte buffer, numbers by [`fixed`]) or a JSON line.

use std::sync::OnceLock;

use super::fixed;
use super::flights::RowFlight;
use super::rows::Job;
use super::savant_columns::{Setup, quoted, write_quoted};
use crate::cli::ground::clearing_json;
use crate::cli::shown::Shown;
use crate::units::{Quantity, Unit, UnitSystem};

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

/// A printed number's column: its quantity and decimals in SI.
#[derive(Clone, Copy)]
enum Number {
    Speed = 0,
    Angle6,
    Spin3,
    Distance3,
    Time3,
    Angle4,
    Distance2,
}

const NUMBERS: [(Quantity, usize); 7] = [
    (Quantity::Speed, 4),
    (Quantity::Angle, 6),
    (Quantity::Spin, 3),
    (Quantity::Distance, 3),
    (Quantity::Unchanged, 3),
    (Quantity::Angle, 4),
    (Quantity::Distance, 2),
];

/// How each [`Number`] prints in a unit system: its unit (`None` where it
/// is SI's, printed as is) and decimals, worked out once, not per number.
type Printing = [(Option<Unit>, usize); NUMBERS.len()];

fn printing(shown: Shown) -> &'static Printing {
    static SYSTEMS: OnceLock<[Printing; 2]> = OnceLock::new();
    let systems = SYSTEMS.get_or_init(|| {
        [UnitSystem::Si, UnitSystem::Imperial].map(|system| {
            NUMBERS.map(|(quantity, si_decimals)| {
                let unit = Shown(system).unit(quantity);
                let decimals = unit.decimals(si_decimals);
                (Some(unit).filter(|u| !u.is_identity()), decimals)
            })
        })
    });
    &systems[usize::from(shown.0 != UnitSystem::Si)]
}

/// Room for a row's line but its kept cells: its numbers (at most 19
/// bytes each, with their commas, as [`fixed`] writes them), words and park
/// code, reserved at once so that no append of the line grows the buffer.
const LINE_ROOM: usize = 512;

/// Writes the number `si` of `column` in the units `printing` gives, then
/// `then`. Inlined: SI's decimals are then constants.
#[inline(always)]
fn number<const SI: bool>(
    out: &mut Vec<u8>,
    printing: &Printing,
    column: Number,
    si: f64,
    then: Option<u8>,
) {
    if SI {
        match NUMBERS[column as usize].1 {
            2 => fixed::write_with::<2>(out, si, then),
            3 => fixed::write_with::<3>(out, si, then),
            4 => fixed::write_with::<4>(out, si, then),
            6 => fixed::write_with::<6>(out, si, then),
            decimals => fixed::write_maybe_then(out, si, decimals, then),
        }
    } else {
        // As `Shown::convert` converts: exactly `si` where the unit is SI's.
        let (unit, decimals) = printing[column as usize];
        let shown = unit.map_or(si, |unit| unit.show(si));
        fixed::write_maybe_then(out, shown, decimals, then);
    }
}

impl CsvLine<'_> {
    pub(super) fn write(&self, out: &mut Vec<u8>, job: &Job, flown: &RowFlight, kept: &[&str]) {
        out.reserve(LINE_ROOM);
        // SI's decimals are constants, each number's writer inlined for its
        // own; other units' are looked up (`printing`).
        if self.shown.is_si() {
            self.write_line::<true>(out, job, flown, kept);
        } else {
            self.write_line::<false>(out, job, flown, kept);
        }
    }

    fn write_line<const SI: bool>(
        &self,
        out: &mut Vec<u8>,
        job: &Job,
        flown: &RowFlight,
        kept: &[&str],
    ) {
        let (launch, flight) = (&flown.launch, &flown.flight);
        let printing = printing(self.shown);
        let number = |out: &mut Vec<u8>, column: Number, si: f64, then: Option<u8>| {
            number::<SI>(out, printing, column, si, then);
        };
        let comma = Some(b',');
        let mut line = itoa::Buffer::new();
        out.extend_from_slice(line.format(job.line).as_bytes());
        out.push(b',');
        number(out, Number::Speed, launch.speed, comma);
        number(out, Number::Angle6, launch.angle, comma);
        number(out, Number::Spin3, launch.spin, comma);
        number(out, Number::Angle6, launch.direction, comma);
        number(out, Number::Spin3, launch.sidespin, comma);
        match flight.landed {
            true => number(out, Number::Distance3, flight.range, comma),
            false => out.push(b','),
        }
        number(out, Number::Angle6, flight.direction, comma);
        number(out, Number::Time3, flight.flight_time, comma);
        number(out, Number::Distance3, flight.apex, comma);
        number(out, Number::Angle4, flight.landing_angle, comma);
        for yes in [flight.landed, flown.clearing.clears()] {
            match yes {
                true => out.extend_from_slice(b"true,"),
                false => out.extend_from_slice(b"false,"),
            }
        }
        write_quoted(out, park_code(job, self.setup));
        out.push(b',');
        out.extend_from_slice(flown.clearing.outcome.name().as_bytes());
        out.push(b',');
        match flown.clearing.margin {
            Some(margin) => number(out, Number::Distance3, margin, comma),
            None => out.push(b','),
        }
        out.extend_from_slice(line.format(flown.parks_cleared).as_bytes());
        match job.launch.estimates_spin() {
            true => out.extend_from_slice(b",true"),
            false => out.extend_from_slice(b",false"),
        }
        if self.statcast {
            for value in [job.statcast, difference(job, flown)] {
                out.push(b',');
                if let Some(m) = value {
                    number(out, Number::Distance2, m, None);
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
