//! One swing: `hit` (every impact quantity and the flight summary),
//! `trajectory` (the path, sampled) and `keys` (every input).

use std::fmt::Write as _;

use super::shown::Shown;
use super::table::{Align, Cell, Column, Digits, Table, Width};
use super::{FIELD_KEYS, Format, UsageError, pretty};
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::precision::Purpose;
use crate::model::aero::{DragModel, LiftModel};
use crate::model::flight::{FlightSummary, TrajectoryPoint};
use crate::model::impact::{Collision, Impact3d, Regime};
use crate::model::keys::{DRAG_KEY, HAND_KEY, LIFT_KEY, all_keys};
use crate::model::launch::BattedBall;
use crate::model::pitch;
use crate::model::scene::Hand;
use crate::model::scene::SceneKind;
use crate::picture::{self, FlightPath, TrajectoryPicture};
use crate::preset::Preset;
use crate::units::{Quantity, Unit};

use super::shown::short;

/// The most points `trajectory` samples.
pub const MAX_SAMPLES: usize = 100_000;

pub(super) fn hit(scene: &Scene, json: bool, shown: Shown) -> String {
    let swing = crate::simulate(scene, Purpose::Readout);
    let impact = &swing.impact;
    let flight = &swing.flight;
    let vertical = pitch::vertical_velocity(scene.pitch.speed, scene.environment.gravity);
    let unlanded = landing::why_not_landed(scene, flight, Purpose::Readout);
    if json {
        let mut impact_json = serde_json::json!({
            "normal_angle": impact.normal_angle(),
            "restitution": impact.restitution(),
            "regime": impact.regime(),
            "compression_impulse": impact.compression_impulse(),
            "separation_impulse": impact.separation_impulse(),
            "stick_impulse": impact.stick_impulse(),
            "launch_speed": impact.launch_speed(),
            "launch_spin": impact.launch_spin(),
            "launch_angle": impact.launch_angle(),
            "launch_direction": impact.launch_direction(),
            "launch_sidespin": impact.launch_sidespin(),
            "launch_gyrospin": impact.launch_gyrospin(),
        });
        // A contact that grips: what it gave back after the slip halted.
        if scene.bat.tangential_restitution > 0.0 {
            impact_json["release_impulse"] = serde_json::json!(impact.release_impulse());
        }
        if let Some(spatial) = impact.spatial() {
            impact_json["initial_slip"] = serde_json::json!({
                "across": spatial.initial_slip.x,
                "along": spatial.initial_slip.y,
            });
            impact_json["slip_turn"] = serde_json::json!(spatial.slip_turn(SLIP_SAMPLES));
        }
        return pretty(&serde_json::json!({
            "pitch": {
                "speed": scene.pitch.speed,
                "vertical_velocity": vertical,
                "angle": impact.descent_angle(),
            },
            "impact": impact_json,
            "flight": flight_json(flight, unlanded),
            "environment": environment_json(scene),
        }));
    }
    let bat = &scene.bat;
    let stick = match impact.stick_impulse() {
        // A contact that grips then springs back (bat.tangential_restitution).
        Some(p) if bat.tangential_restitution > 0.0 => format!(
            "slip halts at p_s = {p:.4} N·s (stick), then springs back (e_T = {})",
            bat.tangential_restitution
        ),
        Some(p) => format!("slip halts at p_s = {p:.4} N·s (stick)"),
        None => "slips until separation".to_owned(),
    };
    let speed = |v, decimals| shown.value(Quantity::Speed, v, decimals);
    let angle = |rad, decimals| shown.value(Quantity::Angle, rad, decimals);
    // Text about a flight that did not land gives the height in the units shown.
    let unlanded = unlanded.map(|why| {
        if shown.is_si() {
            why
        } else {
            shown.not_landed(flight, landing::end_height(scene, Purpose::Readout))
        }
    });
    let slip = match impact {
        Collision::Planar(i) => format!("v1(0) = {}", speed(i.initial_slip, 3)),
        Collision::Spatial(i) => format!(
            "v1(0) = {}, v2(0) = {} along the bat",
            speed(i.initial_slip.x, 3),
            speed(i.initial_slip.y, 3)
        ),
    };
    let mut lines = vec![
        (
            "pitch",
            format!(
                "{} at the plate, vertical velocity {}, descending at {}",
                speed(scene.pitch.speed, 2),
                speed(vertical, 3),
                shown.angle_and_degrees(impact.descent_angle(), 4, 1),
            ),
        ),
        (
            "swing",
            format!(
                "E = {}, ψ = {}, bat {}, μ = {}",
                shown.value(Quantity::Size, bat.undercut, 4),
                angle(bat.swing_angle, 4),
                speed(bat.speed, 2),
                bat.friction
            ),
        ),
    ];
    if impact.spatial().is_some() {
        lines.push((
            "bat",
            format!(
                "{}, barrel {} below the hands, swung {}{}",
                bat.hand.description(),
                shown.angle_and_degrees(bat.tilt, 4, 1),
                shown.direction(bat.direction),
                // The bat's lead over its path, where it leads.
                match bat.lead == 0.0 {
                    true => String::new(),
                    false => format!(
                        ", leading its path by {}",
                        shown.angle_and_degrees(bat.lead, 4, 1)
                    ),
                },
            ),
        ));
    }
    let square = if impact.spatial().is_some() {
        " square to the bat"
    } else {
        ""
    };
    lines.extend([
        (
            "impact",
            format!(
                "θ = {}{square}, {slip}, v3(0) = {}, e* = {:.4}",
                angle(impact.normal_angle(), 4),
                speed(impact.initial_approach(), 3),
                impact.restitution()
            ),
        ),
        (
            "",
            format!(
                "p_c = {:.4} N·s, p_f = {:.4} N·s, {stick}",
                impact.compression_impulse(),
                impact.separation_impulse()
            ),
        ),
    ]);
    if let Some(spatial) = impact.spatial() {
        lines.extend(slip_turn_text(spatial).map(|text| ("slip", text)));
    }
    lines.extend([
        ("launch", launch_text(impact, shown)),
        ("flight", flight_text(flight, unlanded.as_deref(), shown)),
    ]);
    labelled(&lines)
}

/// How many points of the slip's turn `hit --json` gives.
const SLIP_SAMPLES: usize = 11;

/// "turns from 12.3° to 84.0° (0° square across the bat, ±90° along it)
/// before it halts": the slip's direction in the tangent plane at the start
/// and where it halts or the ball leaves. `None` without slip.
fn slip_turn_text(impact: &Impact3d) -> Option<String> {
    let turn = impact.slip_turn(SLIP_SAMPLES);
    let (first, last) = (turn.first()?, turn.last()?);
    let end = match impact.regime {
        Regime::Stick => "before it halts",
        Regime::Slip => "by separation",
    };
    Some(format!(
        "turns from {:.1}° to {:.1}° (0° square across the bat, ±90° along it) {end}",
        first.angle.to_degrees(),
        last.angle.to_degrees()
    ))
}

/// "range 134.699 m in 5.553 s, apex 27.03 m, lands at 23.34 m/s, 0.836
/// rad below horizontal", or why it did not land and its apex.
pub(super) fn flight_text(flight: &FlightSummary, unlanded: Option<&str>, shown: Shown) -> String {
    let apex = shown.value(Quantity::Distance, flight.apex, 2);
    match unlanded {
        Some(why) => format!("{why}, apex {apex}"),
        None => format!(
            "range {}{} in {:.3} s, apex {apex}, lands at {}, {} below horizontal",
            shown.value(Quantity::Distance, flight.range, 3),
            if flight.direction == 0.0 {
                String::new()
            } else {
                format!(" at {}", shown.direction(flight.direction))
            },
            flight.flight_time,
            shown.value(Quantity::Speed, flight.landing_speed, 2),
            shown.value(Quantity::Angle, flight.landing_angle, 3),
        ),
    }
}

/// A flight in JSON: its range (null if it did not land, with the reason in
/// `why_not_landed`), time, apex and landing, and `landed`.
pub(super) fn flight_json(flight: &FlightSummary, unlanded: Option<String>) -> serde_json::Value {
    let mut json = serde_json::json!({
        "range": flight.landed.then_some(flight.range),
        "direction": flight.direction,
        "flight_time": flight.flight_time,
        "apex": flight.apex,
        "landing_speed": flight.landing_speed,
        "landing_angle": flight.landing_angle,
        "landed": flight.landed,
    });
    if let Some(why) = unlanded {
        json["why_not_landed"] = why.into();
    }
    json
}

/// The air in force, as every command's JSON reports it: ρ and ν, and the
/// weather they were derived from (absent when they were given).
pub(super) fn environment_json(scene: &Scene) -> serde_json::Value {
    let air = scene.environment.air();
    let mut json = serde_json::json!({
        "air_density": air.density,
        "kinematic_viscosity": air.kinematic_viscosity,
    });
    if let Some(a) = air.atmosphere {
        json["atmosphere"] = serde_json::json!({
            "temperature": a.temperature,
            "elevation": a.elevation,
            "pressure": a.pressure,
            "humidity": a.humidity,
        });
    }
    json
}

/// Lines under a label, as `hit` and `optimize` print them: "launch   …".
pub(super) fn labelled(lines: &[(&str, String)]) -> String {
    lines
        .iter()
        .map(|(label, text)| format!("{label:<9}{text}\n"))
        .collect()
}

/// The launch: speed, spin in words and angle, and a 3-D swing's
/// direction and sidespin.
/// "44.299 m/s, 191.83 rad/s of backspin, 0.4604 rad (26.4°)"
pub(super) fn launch_text(impact: &Collision, shown: Shown) -> String {
    super::fly::batted_text(&BattedBall::of(impact), shown)
}

/// The flight at readout precision, `samples` points evenly in time read
/// off the dense output.
fn sampled(
    scene: &Scene,
    samples: usize,
) -> Result<(FlightSummary, Vec<TrajectoryPoint>), UsageError> {
    if !(2..=MAX_SAMPLES).contains(&samples) {
        return Err(UsageError::BadSamples { samples });
    }
    // A swing's flight or a batted ball's, as the scene is.
    let options = Purpose::Readout.flight_options();
    Ok(crate::model::launch::scene_start(scene)
        .0
        .trajectory(&options, samples))
}

/// `trajectory --svg`: the flight in x–y with the preset's fence.
pub(super) fn trajectory_svg(
    preset: &Preset,
    samples: usize,
    shown: Shown,
) -> Result<String, UsageError> {
    let (summary, points) = sampled(&preset.scene, samples)?;
    let end = points.last().map_or(0.0, |p| p.y);
    let picture = TrajectoryPicture {
        park: None,
        preset: preset.name.clone(),
        paths: vec![FlightPath {
            name: match preset.scene.kind {
                SceneKind::Swing if shown.is_si() => format!(
                    "E = {} m, ψ = {} rad",
                    preset.scene.bat.undercut, preset.scene.bat.swing_angle
                ),
                SceneKind::Swing => format!(
                    "E = {}, ψ = {}",
                    shown.value(Quantity::Size, preset.scene.bat.undercut, 3),
                    shown.value(Quantity::Angle, preset.scene.bat.swing_angle, 4)
                ),
                SceneKind::BattedBall => {
                    let launch = preset.scene.batted_ball();
                    if shown.is_si() {
                        format!(
                            "launched at {:.2} m/s, {:.4} rad up, {:.4} rad across",
                            launch.speed, launch.angle, launch.direction
                        )
                    } else {
                        format!(
                            "launched at {}, {} up, {} across",
                            shown.value(Quantity::Speed, launch.speed, 2),
                            shown.value(Quantity::Angle, launch.angle, 4),
                            shown.value(Quantity::Angle, launch.direction, 4)
                        )
                    }
                }
            },
            points: points.iter().map(|p| (p.distance, p.y)).collect(),
            ground: points.iter().map(|p| (p.x, p.z)).collect(),
        }],
        range: summary.landed.then_some(summary.range),
        apex: summary.apex,
        not_landed: (!summary.landed).then(|| landing::not_landed(&summary, end)),
        fence: preset.fence,
    };
    Ok(picture::trajectory_svg_in(&picture, shown.0)?)
}

/// The flight at readout precision, sampled from the dense output.
pub(super) fn trajectory(
    scene: &Scene,
    samples: usize,
    format: Format,
    shown: Shown,
) -> Result<String, UsageError> {
    let (summary, points) = sampled(scene, samples)?;
    let end = points.last().map_or(0.0, |p| p.y);
    // JSON is SI whatever the units shown.
    let shown = if format == Format::Json {
        Shown::default()
    } else {
        shown
    };
    let unlanded = (!summary.landed).then(|| shown.not_landed(&summary, end));
    let distance = |key: &str, width| {
        Column::right(
            &shown.csv_key(key, Quantity::Distance),
            &shown.head(key, Quantity::Distance, "m"),
            width,
            Digits::Fixed(shown.unit(Quantity::Distance).decimals(3)),
        )
    };
    let table = Table {
        columns: vec![
            Column::right("time", "t (s)", 8, Digits::Fixed(3)),
            distance("x", 9),
            distance("y", 8),
            distance("z", 8),
            Column::right("drag_coefficient", "C_D", 6, Digits::Fixed(3)),
        ],
        rows: points
            .iter()
            .map(|p| {
                [
                    p.time,
                    shown.convert(Quantity::Distance, p.x),
                    shown.convert(Quantity::Distance, p.y),
                    shown.convert(Quantity::Distance, p.z),
                    p.drag_coefficient,
                ]
                .map(Cell::Num)
                .to_vec()
            })
            .collect(),
    };
    Ok(match format {
        Format::Json => {
            let mut json = serde_json::json!({
                "range": summary.landed.then_some(summary.range),
                "flight_time": summary.flight_time,
                "landed": summary.landed,
                "points": table.json_rows(),
                "environment": environment_json(scene),
            });
            if let Some(why) = unlanded {
                json["why_not_landed"] = why.into();
            }
            pretty(&json)
        }
        Format::Csv => table.csv(),
        Format::Text => match unlanded {
            Some(why) => format!("a flight that {why}\n{}", table.text()),
            None => format!(
                "flight of {} in {:.3} s\n{}",
                shown.value(Quantity::Distance, summary.range, 3),
                summary.flight_time,
                table.text()
            ),
        },
    })
}

/// The input keys, as `--set` and the TOML presets take them, with their
/// ranges and the fastball's values in the units shown (`--set` takes SI).
/// `head` then `text` wrapped at words to `width` columns, the lines after
/// the first indented under the text.
fn hanging(head: &str, text: &str, width: usize) -> String {
    let indent = head.chars().count() + 2;
    let mut out = format!("{head}  ");
    let mut column = indent;
    for word in text.split_whitespace() {
        let length = word.chars().count();
        if column > indent && column + 1 + length > width {
            out += &format!("\n{}", " ".repeat(indent));
            column = indent;
        } else if column > indent {
            out.push(' ');
            column += 1;
        }
        out += word;
        column += length;
    }
    out
}

pub(super) fn keys(shown: Shown) -> String {
    let defaults = Scene::default();
    // Each column as wide as its widest field, two spaces apart, so that no
    // key, range or value runs into the next column however long it grows.
    let column = |head, align| Column::text(head, Width::Fit, align, "  ");
    let columns = vec![
        column("key", Align::Left),
        column("symbol", Align::Left),
        column("unit", Align::Left),
        column("accepted", Align::Left),
        column("fastball", Align::Right),
        Column::text("meaning", Width::AtLeast(0), Align::Left, "  "),
    ];
    let text = |s: &str| Cell::Text(s.to_owned());
    // In SI as it always was; otherwise converted and shortened.
    let value = |unit: Unit, si: f64| {
        if unit.is_identity() && si.to_string().len() > 12 {
            // A derived value (the launch keys read the impact's): six decimals.
            Cell::Text(crate::analysis::figures::trimmed(si))
        } else if unit.is_identity() {
            Cell::Num(si)
        } else {
            Cell::Text(short(unit.show(si)))
        }
    };
    let mut rows: Vec<Vec<Cell>> = all_keys()
        .map(|key| {
            let unit = key.unit_in(shown.0);
            vec![
                text(key.name),
                text(key.symbol),
                text(unit.symbol),
                Cell::Text(if unit.is_identity() {
                    key.bounds.to_string()
                } else {
                    shown.interval(key.bounds, unit)
                }),
                value(unit, (key.get)(&defaults)),
                text(key.description),
            ]
        })
        .collect();
    rows.push(vec![
        text(DRAG_KEY),
        text("C_D"),
        text(""),
        Cell::Text(DragModel::ALL.map(|m| m.name()).join(" | ")),
        text(defaults.drag.name()),
        text("drag model"),
    ]);
    rows.push(vec![
        text(LIFT_KEY),
        text("C_L"),
        text(""),
        Cell::Text(LiftModel::ALL.map(|m| m.name()).join(" | ")),
        text(defaults.lift.name()),
        text("lift model"),
    ]);
    rows.push(vec![
        text(HAND_KEY),
        text(""),
        text(""),
        Cell::Text(Hand::ALL.map(|h| h.name()).join(" | ")),
        text(defaults.bat.hand.name()),
        text("the batter's side (right: the barrel toward first base at a square contact)"),
    ]);
    let fence = crate::preset::bundled()
        .into_iter()
        .find(|p| p.name == "fastball")
        .and_then(|p| p.fence);
    rows.extend(FIELD_KEYS.iter().map(|key| {
        let unit = Quantity::Distance.unit(shown.0, key.unit);
        vec![
            text(key.name),
            text(""),
            text(unit.symbol),
            Cell::Text(if unit.is_identity() {
                key.bounds.to_string()
            } else {
                shown.interval(key.bounds, unit)
            }),
            fence.map_or(Cell::Blank, |f| value(unit, (key.get)(&f))),
            text(key.description),
        ]
    }));
    let mut out = Table { columns, rows }.text();
    let _ = writeln!(
        out,
        "\nAlso: bat.undercut must stay below r_b + r_B in size (the bat must reach the ball), and\n\
         pitch.speed must be fast enough for Eq. (3) to hold at the chosen gravity."
    );
    let _ = writeln!(out, "\nWhy each range is what it is:");
    let names = all_keys()
        .map(|k| k.name.chars().count())
        .max()
        .unwrap_or(0);
    for key in all_keys() {
        let head = format!("{:names$}", key.name);
        let _ = writeln!(out, "{}", hanging(&head, key.bounds_reason, 100));
    }
    if !shown.is_si() {
        let _ = writeln!(
            out,
            "Ranges and values are shown in imperial units; --set and presets take a bare number in\n\
             each key's SI unit (`homerun keys` without --units lists them), or a number with its\n\
             unit: 103mph, 28deg, 2500rpm, 70F, 29.92inHg (see docs/units-on-input.md)."
        );
    }
    out
}
