//! A row's swing columns (`hit --batch`): CSV and JSON.

use serde::Serialize;

use super::CsvLine;
use crate::row::Job;
use crate::setup::quoted;
use analysis::bat_tracking::How;
use units::Quantity;

/// The swing's CSV columns, after `line` (`hit --batch`).
pub(crate) const CSV_COLUMNS: [(&str, Quantity); 26] = [
    ("solved", Quantity::Unchanged),
    ("reason", Quantity::Unchanged),
    ("shortfall", Quantity::Speed),
    ("pitch.speed", Quantity::Speed),
    ("pitch.descent_angle", Quantity::Angle),
    ("swing.bat_speed", Quantity::Speed),
    ("swing.contact_speed", Quantity::Speed),
    ("swing.angle", Quantity::Angle),
    ("swing.direction", Quantity::Angle),
    ("swing.tilt", Quantity::Angle),
    ("swing.lead", Quantity::Angle),
    ("swing.from.angle", Quantity::Unchanged),
    ("swing.from.direction", Quantity::Unchanged),
    ("swing.from.tilt", Quantity::Unchanged),
    ("swing.from.contact_speed", Quantity::Unchanged),
    ("swing.from.undercut", Quantity::Unchanged),
    ("swing.from.lead", Quantity::Unchanged),
    ("impact.undercut", Quantity::Size),
    ("impact.regime", Quantity::Unchanged),
    ("impact.bat", Quantity::Unchanged),
    ("impact.effective_mass", Quantity::Mass),
    ("impact.collision_efficiency", Quantity::Unchanged),
    ("impact.max_exit_speed", Quantity::Speed),
    ("impact.squared_up", Quantity::Unchanged),
    ("impact.squared_up_savant", Quantity::Unchanged),
    ("launch.gyrospin", Quantity::Spin),
];

/// Writes a row's swing columns (each with its comma).
pub(crate) fn write_csv(csv: &CsvLine, out: &mut Vec<u8>, job: &Job) {
    let Some(swing) = &job.swing else {
        out.extend_from_slice(&[b','; CSV_COLUMNS.len()]);
        return;
    };
    let solved = swing.solved();
    out.extend_from_slice(if solved.is_some() {
        b"true,"
    } else {
        b"false,"
    });
    let reason = swing.reason().unwrap_or_default();
    out.extend_from_slice(quoted(&reason).as_bytes());
    out.push(b',');
    csv.number(out, Quantity::Speed, swing.shortfall(), 4);
    let tracked = swing.tracked.ok();
    let pitch = tracked.map(|t| t.pitch);
    csv.number(out, Quantity::Speed, pitch.map(|p| p.speed()), 4);
    csv.number(out, Quantity::Angle, pitch.map(|p| p.descent_angle()), 6);
    csv.number(out, Quantity::Speed, tracked.map(|t| t.bat_speed), 4);
    let bat = solved.map(|s| s.scene.bat);
    csv.number(out, Quantity::Speed, bat.map(|b| b.speed), 4);
    csv.number(out, Quantity::Angle, bat.map(|b| b.swing_angle), 6);
    csv.number(out, Quantity::Angle, bat.map(|b| b.direction), 6);
    csv.number(out, Quantity::Angle, bat.map(|b| b.tilt), 6);
    csv.number(out, Quantity::Angle, bat.map(|b| b.lead), 6);
    let from = swing.found_names();
    for k in 0..5 {
        if let Some(from) = from {
            out.extend_from_slice(from[k].as_bytes());
        }
        out.push(b',');
    }
    if let Some(lead) = lead_found(job) {
        out.extend_from_slice(lead.as_bytes());
    }
    out.push(b',');
    csv.number(out, Quantity::Size, bat.map(|b| b.undercut), 6);
    if let Some(solved) = solved {
        out.extend_from_slice(solved.regime.name().as_bytes());
    }
    out.push(b',');
    if tracked.is_some() {
        out.extend_from_slice(swing.bat_name().as_bytes());
    }
    out.push(b',');
    let mass = tracked.map(|_| swing.effective_mass);
    csv.number(out, Quantity::Mass, mass, 4);
    let q = swing.answer.map(|a| a.collision_efficiency);
    csv.number(out, Quantity::Unchanged, q, 5);
    csv.number(out, Quantity::Speed, solved.map(|s| s.max_exit_speed), 4);
    csv.number(out, Quantity::Unchanged, solved.map(|s| s.squared_up()), 5);
    csv.number(out, Quantity::Unchanged, swing.savant_squared_up, 5);
    csv.number(out, Quantity::Spin, solved.map(|s| s.launch.gyrospin), 3);
}

/// How the solved swing's lead over its path was found: `solved` (a
/// measured `attack_direction` and a spray), else `prior` (0, the square
/// bat) or `given` (`--set bat.lead` or a column).
fn lead_found(job: &Job) -> Option<&'static str> {
    let swing = job.swing.as_ref()?;
    let how = swing.found()?.lead;
    Some(match how {
        How::Prior if swing.solved()?.scene.bat.lead != 0.0 => "given",
        how => how.name(),
    })
}

#[derive(Serialize)]
pub(crate) struct ImpactJson<'a> {
    bat: Option<String>,
    collision_efficiency: Option<f64>,
    effective_mass: Option<f64>,
    max_exit_speed: Option<f64>,
    regime: Option<&'a str>,
    squared_up: Option<f64>,
    squared_up_savant: Option<f64>,
    undercut: Option<f64>,
}

#[derive(Serialize)]
pub(crate) struct PitchJson {
    descent_angle: f64,
    speed: f64,
}

/// How each swing quantity was found: `measured`, `solved`, `prior` or
/// (the tilt) `given`.
#[derive(Serialize)]
pub(crate) struct FromJson {
    angle: &'static str,
    direction: &'static str,
    tilt: &'static str,
    contact_speed: &'static str,
    undercut: &'static str,
    lead: &'static str,
}

#[derive(Serialize)]
pub(crate) struct SwingJson {
    angle: f64,
    /// `bat_speed`: the sweet spot's speed, measured.
    bat_speed: f64,
    /// The bat's speed where it met the ball: `bat_speed` at the sweet
    /// spot, else solved.
    contact_speed: f64,
    direction: f64,
    from: FromJson,
    /// The bat's lead over its path (rad): solved where the path is
    /// measured, else 0.
    lead: f64,
    /// The bat's tilt the swing was solved at: `swing_path_tilt`, or the
    /// league's where the row has none.
    tilt: f64,
}

/// The swing's parts of a row's JSON line (all `None` unless swings are
/// printed).
#[derive(Default)]
pub(crate) struct JsonParts<'a> {
    pub impact: Option<ImpactJson<'a>>,
    pub pitch: Option<PitchJson>,
    pub reason: Option<String>,
    pub shortfall: Option<f64>,
    pub solved: Option<bool>,
    pub swing: Option<SwingJson>,
    pub gyrospin: Option<f64>,
}

pub(crate) fn json_parts(job: &Job) -> JsonParts<'static> {
    let Some(swing) = &job.swing else {
        return JsonParts::default();
    };
    let solved = swing.solved();
    let tracked = swing.tracked.ok();
    JsonParts {
        impact: Some(ImpactJson {
            bat: tracked.map(|_| swing.bat_name()),
            collision_efficiency: swing.answer.map(|a| a.collision_efficiency),
            effective_mass: tracked.map(|_| swing.effective_mass),
            max_exit_speed: solved.map(|s| s.max_exit_speed),
            regime: solved.map(|s| s.regime.name()),
            squared_up: solved.map(|s| s.squared_up()),
            squared_up_savant: swing.savant_squared_up,
            undercut: solved.map(|s| s.scene.bat.undercut),
        }),
        pitch: tracked.map(|t| PitchJson {
            descent_angle: t.pitch.descent_angle(),
            speed: t.pitch.speed(),
        }),
        reason: swing.reason(),
        shortfall: swing.shortfall(),
        solved: Some(solved.is_some()),
        swing: solved
            .zip(tracked)
            .zip(swing.found_names())
            .map(|((s, t), from)| SwingJson {
                angle: s.scene.bat.swing_angle,
                bat_speed: t.bat_speed,
                contact_speed: s.scene.bat.speed,
                direction: s.scene.bat.direction,
                from: FromJson {
                    angle: from[0],
                    direction: from[1],
                    tilt: from[2],
                    contact_speed: from[3],
                    undercut: from[4],
                    lead: lead_found(job).unwrap_or_default(),
                },
                lead: s.scene.bat.lead,
                tilt: s.scene.bat.tilt,
            }),
        gyrospin: solved.map(|s| s.launch.gyrospin),
    }
}
