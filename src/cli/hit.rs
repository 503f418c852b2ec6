//! One swing: `hit` (every impact quantity and the flight summary),
//! `trajectory` (the path, sampled) and `keys` (every input).

use std::fmt::Write as _;

use super::table::{Align, Cell, Column, Digits, Table, Width};
use super::{FIELD_KEYS, Format, UsageError, pretty};
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::precision::Purpose;
use crate::model::aero::{DragModel, LiftModel};
use crate::model::flight::{FlightSummary, TrajectoryPoint};
use crate::model::impact::Impact;
use crate::model::keys::{DRAG_KEY, LIFT_KEY, all_keys};
use crate::model::pitch;
use crate::picture::{self, FlightPath, TrajectoryPicture};
use crate::preset::Preset;

/// The most points `trajectory` samples.
pub const MAX_SAMPLES: usize = 100_000;

pub(super) fn hit(scene: &Scene, json: bool) -> String {
    let swing = crate::simulate(scene, Purpose::Readout);
    let impact = &swing.impact;
    let flight = &swing.flight;
    let vertical = pitch::vertical_velocity(scene.pitch.speed, scene.environment.gravity);
    let unlanded = landing::why_not_landed(scene, flight, Purpose::Readout);
    if json {
        return pretty(&serde_json::json!({
            "pitch": {
                "speed": scene.pitch.speed,
                "vertical_velocity": vertical,
                "angle": impact.descent_angle,
            },
            "impact": {
                "normal_angle": impact.normal_angle,
                "restitution": impact.restitution,
                "regime": impact.regime,
                "compression_impulse": impact.compression_impulse,
                "separation_impulse": impact.separation_impulse,
                "stick_impulse": impact.stick_impulse(),
                "launch_speed": impact.launch_speed(),
                "launch_spin": impact.launch_spin(),
                "launch_angle": impact.launch_angle(),
            },
            "flight": flight_json(flight, unlanded),
            "environment": environment_json(scene),
        }));
    }
    let bat = &scene.bat;
    let descent = impact.descent_angle;
    let stick = match impact.stick_impulse() {
        Some(p) => format!("slip halts at p_s = {p:.4} N·s (stick)"),
        None => "slips until separation".to_owned(),
    };
    labelled(&[
        (
            "pitch",
            format!(
                "{:.2} m/s at the plate, vertical velocity {vertical:.3} m/s, descending at {descent:.4} rad ({:.1}°)",
                scene.pitch.speed,
                descent.to_degrees()
            ),
        ),
        (
            "swing",
            format!(
                "E = {:.4} m, ψ = {:.4} rad, bat {:.2} m/s, μ = {}",
                bat.undercut, bat.swing_angle, bat.speed, bat.friction
            ),
        ),
        (
            "impact",
            format!(
                "θ = {:.4} rad, v1(0) = {:.3} m/s, v3(0) = {:.3} m/s, e* = {:.4}",
                impact.normal_angle,
                impact.initial_slip,
                impact.initial_approach,
                impact.restitution
            ),
        ),
        (
            "",
            format!(
                "p_c = {:.4} N·s, p_f = {:.4} N·s, {stick}",
                impact.compression_impulse, impact.separation_impulse
            ),
        ),
        ("launch", launch_text(impact)),
        (
            "flight",
            match unlanded {
                Some(why) => format!("{why}, apex {:.2} m", flight.apex),
                None => format!(
                    "range {:.3} m in {:.3} s, apex {:.2} m, lands at {:.2} m/s, {:.3} rad below horizontal",
                    flight.range,
                    flight.flight_time,
                    flight.apex,
                    flight.landing_speed,
                    flight.landing_angle
                ),
            },
        ),
    ])
}

/// A flight in JSON: its range (null if it did not land, with the reason in
/// `why_not_landed`), time, apex and landing, and `landed`.
pub(super) fn flight_json(flight: &FlightSummary, unlanded: Option<String>) -> serde_json::Value {
    let mut json = serde_json::json!({
        "range": flight.landed.then_some(flight.range),
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

/// The launch: speed, spin in words and angle.
/// "44.299 m/s, 191.83 rad/s of backspin, 0.4604 rad (26.4°)"
pub(super) fn launch_text(impact: &Impact) -> String {
    format!(
        "{:.3} m/s, {}, {:.4} rad ({:.1}°)",
        impact.launch_speed(),
        spin_text(impact.launch_spin()),
        impact.launch_angle(),
        impact.launch_angle().to_degrees()
    )
}

/// A batted spin in words: backspin is positive.
pub(super) fn spin_text(spin: f64) -> String {
    if spin < 0.0 {
        format!("{:.2} rad/s of topspin", -spin)
    } else {
        format!("{spin:.2} rad/s of backspin")
    }
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
    let (flight, launch, _, _) = crate::model::launch::scene_start(scene);
    let options = Purpose::Readout.flight_options();
    Ok(crate::model::flight::trajectory(
        &flight, &launch, &options, samples,
    ))
}

/// `trajectory --svg`: the flight in x–y with the preset's fence.
pub(super) fn trajectory_svg(preset: &Preset, samples: usize) -> Result<String, UsageError> {
    let (summary, points) = sampled(&preset.scene, samples)?;
    let end = points.last().map_or(0.0, |p| p.y);
    let picture = TrajectoryPicture {
        preset: preset.name.clone(),
        paths: vec![FlightPath {
            name: format!(
                "E = {} m, ψ = {} rad",
                preset.scene.bat.undercut, preset.scene.bat.swing_angle
            ),
            points: points.iter().map(|p| (p.x, p.y)).collect(),
        }],
        range: summary.landed.then_some(summary.range),
        apex: summary.apex,
        not_landed: (!summary.landed).then(|| landing::not_landed(&summary, end)),
        fence: preset.fence,
    };
    Ok(picture::trajectory_svg(&picture)?)
}

/// The flight at readout precision, sampled from the dense output.
pub(super) fn trajectory(
    scene: &Scene,
    samples: usize,
    format: Format,
) -> Result<String, UsageError> {
    let (summary, points) = sampled(scene, samples)?;
    let end = points.last().map_or(0.0, |p| p.y);
    let unlanded = (!summary.landed).then(|| landing::not_landed(&summary, end));
    let table = Table {
        columns: vec![
            Column::right("time", "t (s)", 8, Digits::Fixed(3)),
            Column::right("x", "x (m)", 9, Digits::Fixed(3)),
            Column::right("y", "y (m)", 8, Digits::Fixed(3)),
            Column::right("drag_coefficient", "C_D", 6, Digits::Fixed(3)),
        ],
        rows: points
            .iter()
            .map(|p| {
                [p.time, p.x, p.y, p.drag_coefficient]
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
                "flight of {:.3} m in {:.3} s\n{}",
                summary.range,
                summary.flight_time,
                table.text()
            ),
        },
    })
}

/// The input keys, as `--set` and the TOML presets take them.
pub(super) fn keys() -> String {
    let defaults = Scene::default();
    let left = |head, width| Column::text(head, Width::AtLeast(width), Align::Left, " ");
    let columns = vec![
        left("key", 33),
        left("symbol", 6),
        left("unit", 7),
        left("accepted", 24),
        Column::text("fastball", Width::AtLeast(10), Align::Right, " "),
        left("meaning", 0).after("  "),
    ];
    let text = |s: &str| Cell::Text(s.to_owned());
    let mut rows: Vec<Vec<Cell>> = all_keys()
        .map(|key| {
            vec![
                text(key.name),
                text(key.symbol),
                text(key.unit),
                Cell::Text(key.bounds.to_string()),
                Cell::Num((key.get)(&defaults)),
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
    let fence = crate::preset::bundled()
        .into_iter()
        .find(|p| p.name == "fastball")
        .and_then(|p| p.fence);
    rows.extend(FIELD_KEYS.iter().map(|key| {
        vec![
            text(key.name),
            text(""),
            text(key.unit),
            Cell::Text(key.bounds.to_string()),
            fence.map_or(Cell::Blank, |f| Cell::Num((key.get)(&f))),
            text(key.description),
        ]
    }));
    let mut out = Table { columns, rows }.text();
    let _ = writeln!(
        out,
        "\nAlso: bat.undercut must stay below r_b + r_B in size (the bat must reach the ball), and\n\
         pitch.speed must be fast enough for Eq. (3) to hold at the chosen gravity."
    );
    out
}
