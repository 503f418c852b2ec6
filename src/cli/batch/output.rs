//! A batch's output: its columns, and each row written as a CSV line (into
//! a piece's byte buffer, numbers by [`fixed`]) or a JSON line.

use std::sync::OnceLock;

use super::fixed;
use super::flights::RowFlight;
use super::rows::Job;
use super::savant_columns::{Setup, quoted, write_quoted};
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
        let mut count = itoa::Buffer::new();
        out.extend_from_slice(count.format(job.line).as_bytes());
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
        // The park's code as its field, worked out once (GENERIC needs no
        // quotes).
        let park = job.park.map(|i| self.setup.code_fields[i].as_str());
        out.extend_from_slice(park.unwrap_or(GENERIC).as_bytes());
        out.push(b',');
        out.extend_from_slice(flown.clearing.outcome.name().as_bytes());
        out.push(b',');
        match flown.clearing.margin {
            Some(margin) => number(out, Number::Distance3, margin, comma),
            None => out.push(b','),
        }
        out.extend_from_slice(count.format(flown.parks_cleared).as_bytes());
        out.push(b',');
        match job.launch.estimates_spin() {
            true => out.extend_from_slice(b"true"),
            false => out.extend_from_slice(b"false"),
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

/// Appends a row's JSON line (SI, every digit): the object `fly --json`'s
/// pieces make (`clearing_json` for the fence), keys in order as
/// `serde_json`'s map keeps them, each value written by `serde_json` itself
/// (numbers, text), straight into the piece's buffer: a tree of values cost
/// 20 times the flight's own work.
pub(super) fn json_line(
    out: &mut Vec<u8>,
    job: &Job,
    flown: &RowFlight,
    cleared: &[bool],
    kept: &[&str],
    setup: &Setup,
) {
    use Member::*;
    let (launch, flight, fence) = (&flown.launch, &flown.flight, &flown.clearing);
    let fence = [
        ("direction", Number(fence.direction)),
        ("distance", Maybe(fence.wall.map(|w| w.distance))),
        ("height", Maybe(fence.wall.map(|w| w.height))),
        ("height_at_fence", Maybe(fence.height_at_fence)),
        ("margin", Maybe(fence.margin)),
        ("outcome", Text(fence.outcome.name())),
        ("park", Text(park_code(job, setup))),
    ];
    let flight = [
        ("apex", Number(flight.apex)),
        ("direction", Number(flight.direction)),
        ("flight_time", Number(flight.flight_time)),
        ("landed", Flag(flight.landed)),
        ("landing_angle", Number(flight.landing_angle)),
        ("range", Maybe(flight.landed.then_some(flight.range))),
    ];
    let launch = [
        ("angle", Number(launch.angle)),
        ("direction", Number(launch.direction)),
        ("sidespin", Number(launch.sidespin)),
        ("speed", Number(launch.speed)),
        ("spin", Number(launch.spin)),
    ];
    let codes = |out: &mut Vec<u8>| {
        let parks = setup.parks.parks.iter().zip(cleared);
        let mut open = b'[';
        for (park, _) in parks.filter(|(_, c)| **c) {
            out.push(open);
            open = b',';
            let _ = serde_json::to_writer(&mut *out, &park.code);
        }
        if open == b'[' {
            out.push(open);
        }
        out.push(b']');
    };
    let parks = [
        ("cleared", Count(flown.parks_cleared)),
        ("codes", With(&codes)),
    ];
    let statcast = job.statcast.map(|measured| {
        [
            ("difference", Maybe(difference(job, flown))),
            ("distance", Number(measured)),
        ]
    });
    let kept = |out: &mut Vec<u8>| kept_object(out, &setup.keep, kept);
    let members = [
        Some(("clears_fence", Flag(flown.clearing.clears()))),
        Some(("fence", Object(&fence))),
        Some(("flight", Object(&flight))),
        (!setup.keep.is_empty()).then_some(("kept", With(&kept))),
        Some(("launch", Object(&launch))),
        Some(("line", Count(job.line))),
        Some(("parks", Object(&parks))),
        Some(("spin_estimated", Flag(job.launch.estimates_spin()))),
        statcast.as_ref().map(|s| ("statcast", Object(s))),
    ];
    write_object(out, members.iter().flatten());
    out.push(b'\n');
}

/// A value of the batch's JSON line, written as `serde_json` writes it.
enum Member<'a> {
    /// A number (`null` if not finite, as a `serde_json::Value` holds it).
    Number(f64),
    Maybe(Option<f64>),
    Flag(bool),
    Count(usize),
    Text(&'a str),
    /// Members, their keys in order (plain words).
    Object(&'a [(&'a str, Member<'a>)]),
    /// Written by the function.
    With(&'a dyn Fn(&mut Vec<u8>)),
}

fn write_object<'a>(out: &mut Vec<u8>, members: impl Iterator<Item = &'a (&'a str, Member<'a>)>) {
    let mut open = b'{';
    for (key, member) in members {
        out.push(open);
        open = b',';
        out.push(b'"');
        out.extend_from_slice(key.as_bytes());
        out.extend_from_slice(b"\":");
        // Into a Vec, serde_json cannot fail.
        let _ = match member {
            Member::Number(x) => serde_json::to_writer(&mut *out, x),
            Member::Maybe(x) => serde_json::to_writer(&mut *out, x),
            Member::Flag(x) => serde_json::to_writer(&mut *out, x),
            Member::Count(x) => serde_json::to_writer(&mut *out, x),
            Member::Text(x) => serde_json::to_writer(&mut *out, x),
            Member::Object(members) => {
                write_object(out, members.iter());
                Ok(())
            }
            Member::With(write) => {
                write(out);
                Ok(())
            }
        };
    }
    out.push(b'}');
}

/// The kept cells as a map by column name: in name order, a repeated
/// name's last cell.
fn kept_object(out: &mut Vec<u8>, names: &[String], kept: &[&str]) {
    let mut last: Option<&str> = None;
    let mut open = b'{';
    loop {
        let mut next: Option<(&str, &str)> = None;
        for (name, cell) in names.iter().zip(kept) {
            let name = name.as_str();
            if last.is_some_and(|last| name <= last) {
                continue;
            }
            match next {
                Some((least, _)) if name > least => {}
                _ => next = Some((name, cell)),
            }
        }
        let Some((name, cell)) = next else { break };
        out.push(open);
        open = b',';
        let _ = serde_json::to_writer(&mut *out, name);
        out.push(b':');
        let _ = serde_json::to_writer(&mut *out, cell);
        last = Some(name);
    }
    if open == b'{' {
        out.push(open);
    }
    out.push(b'}');
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::savant::RowLaunch;
    use crate::cli::ground::clearing_json;
    use crate::model::clearing::{Clearing, Outcome};
    use crate::model::flight::FlightSummary;
    use crate::model::launch::BattedBall;
    use crate::model::park::FenceAt;
    use crate::preset::Fence;

    /// The line as a tree of values made it (the batch's JSON before it was
    /// written in place).
    fn json_value_line(
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

    #[test]
    fn json_lines_are_what_a_tree_of_values_wrote() {
        let parks = crate::preset::parks::all(None).unwrap();
        let preset = crate::preset::load("fly-ball", None).unwrap();
        let mut setup = Setup::new(&preset, &parks);
        let odd = [
            0.0,
            -0.0,
            1e-300,
            127.42651234,
            -3.5e12,
            f64::NAN,
            f64::INFINITY,
        ];
        let mut next = crate::numerics::xorshift::uniform(0x5eed_1234_abcd_0042);
        let mut lines = 0;
        for k in 0..400 {
            let mut pick = || {
                let u = next();
                if u < 0.3 {
                    odd[(u * 100.0) as usize % odd.len()]
                } else {
                    (u - 0.6) * 10f64.powi((u * 1e4) as i32 % 9 - 3)
                }
            };
            let job = Job {
                line: k * 7 + 2,
                scene: preset.scene,
                launch: RowLaunch {
                    estimate_backspin: k % 3 == 0,
                    ..RowLaunch::default()
                },
                fence: Fence::generic(),
                park: (k % 4 != 0).then_some(k % parks.parks.len()),
                statcast: (k % 5 != 0).then(&mut pick),
                hang_time: None,
                apex: None,
                kept: 0..0,
                given: setup.given,
            };
            let flown = RowFlight {
                launch: BattedBall {
                    speed: pick(),
                    angle: pick(),
                    spin: pick(),
                    direction: pick(),
                    sidespin: pick(),
                },
                flight: FlightSummary {
                    range: pick(),
                    direction: pick(),
                    flight_time: pick(),
                    apex: pick(),
                    apex_distance: pick(),
                    landing_speed: pick(),
                    landing_angle: pick(),
                    landed: k % 7 != 3,
                    stats: Default::default(),
                },
                clearing: Clearing {
                    outcome: [
                        Outcome::Clears,
                        Outcome::OffTheWall,
                        Outcome::Short,
                        Outcome::Foul,
                    ][k % 4],
                    margin: (k % 6 != 1).then(&mut pick),
                    direction: pick(),
                    wall: (k % 4 != 3).then(|| FenceAt {
                        distance: pick(),
                        height: pick(),
                    }),
                    height_at_fence: (k % 3 == 1).then(&mut pick),
                },
                parks_cleared: k % 31,
                cleared_from: 0,
                flights: 0,
            };
            let cleared: Vec<bool> = (0..parks.parks.len()).map(|p| (p * k) % 3 == 1).collect();
            // Kept cells: none, one, repeated names (the last cell wins),
            // names out of order, text to escape.
            let keeps: [&[(&str, &str)]; 4] = [
                &[],
                &[("des", "homers, to \"left\"\n")],
                &[
                    ("zeta", "1"),
                    ("alpha", "é\u{1}"),
                    ("zeta", "2"),
                    ("mid", ""),
                ],
                &[("b\"q", "\\"), ("a", "x"), ("a", "y"), ("a", "z")],
            ];
            let pairs = keeps[k % keeps.len()];
            setup.keep = pairs.iter().map(|(name, _)| name.to_string()).collect();
            let kept: Vec<&str> = pairs.iter().map(|(_, cell)| *cell).collect();
            let mut out = b"before\n".to_vec();
            json_line(&mut out, &job, &flown, &cleared, &kept, &setup);
            let expected = json_value_line(&job, &flown, &cleared, &kept, &setup);
            assert_eq!(
                String::from_utf8(out).unwrap(),
                format!("before\n{expected}")
            );
            lines += 1;
        }
        assert_eq!(lines, 400);
    }
}
