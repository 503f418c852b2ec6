//! Bat tracking's columns (`hit --batch`, `fly --batch --spin swing`): the
//! swing Statcast measured (`bat_speed`, and since 2025 `attack_angle`,
//! `attack_direction`, `swing_path_tilt`) and the pitch's kinematics
//! (`vx0` … `az`, `release_spin_rate`, `spin_axis`), read in their own
//! units (mph, degrees, ft/s, ft/s², rpm) and made a
//! [`TrackedSwing`] with the row's launch, spray and side.

use serde::Serialize;

use crate::columns::SwingColumn;
use crate::output::CsvLine;
use crate::row::Job;
use crate::setup::quoted;
use analysis::bat_tracking::{self, SolvedSwing, SwingAnswer, TrackedSwing, collision_efficiency};
use analysis::precision::Purpose;
use analysis::savant::{DirectionFrom, RowLaunch, Spray};
use model::scene::Hand;
use model::spin_estimate::Side;
use model::tracked_pitch::{PitchFit, topspin};
use preset::cut;
use units::{Quantity, UnitSystem};

/// What a row's tracking cells say, in their own units.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct SwingCells {
    pub bat_speed: Option<f64>,
    pub attack_angle: Option<f64>,
    pub attack_direction: Option<f64>,
    pub swing_path_tilt: Option<f64>,
    pub velocity: [Option<f64>; 3],
    pub acceleration: [Option<f64>; 3],
    pub spin_rate: Option<f64>,
    pub spin_axis: Option<f64>,
}

/// Why a row with a launch has no swing to solve.
pub(crate) const NO_BAT_SPEED: &str = "no bat_speed (the swing was not tracked)";
pub(crate) const NO_PITCH: &str = "no pitch kinematics (vx0, vy0, vz0, ax, ay, az)";
pub(crate) const PITCH_SHORT: &str = "the pitch's kinematics never reach the plate";

impl SwingCells {
    /// Reads one (trimmed, non-empty) cell: a number in the column's range,
    /// or the reason naming the field, the value and the range.
    pub(crate) fn read(
        &mut self,
        (column, (low, high)): (SwingColumn, (f64, f64)),
        value: &str,
    ) -> Result<(), String> {
        let name = crate::columns::name_of(crate::columns::Becomes::Swing(column, (low, high)));
        let number = value
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && (low..=high).contains(v))
            .ok_or_else(|| {
                format!(
                    "{name} = {:?}: expected a number from {low} to {high}",
                    cut(value, 80)
                )
            })?;
        let slot = match column {
            SwingColumn::BatSpeed => &mut self.bat_speed,
            SwingColumn::AttackAngle => &mut self.attack_angle,
            SwingColumn::AttackDirection => &mut self.attack_direction,
            SwingColumn::SwingPathTilt => &mut self.swing_path_tilt,
            SwingColumn::Velocity(i) => &mut self.velocity[i],
            SwingColumn::Acceleration(i) => &mut self.acceleration[i],
            SwingColumn::SpinRate => &mut self.spin_rate,
            SwingColumn::SpinAxis => &mut self.spin_axis,
        };
        *slot = Some(number);
        Ok(())
    }

    /// The row's tracked swing in SI, given its measured launch (m/s,
    /// rad), spray (rad) and side; or why it has none.
    pub(crate) fn swing(
        &self,
        (launch_speed, launch_angle): (f64, f64),
        spray: Option<f64>,
        side: Option<Side>,
    ) -> Result<TrackedSwing, &'static str> {
        let bat_speed = self.bat_speed.ok_or(NO_BAT_SPEED)?;
        let all = |v: [Option<f64>; 3]| Some([v[0]?, v[1]?, v[2]?]);
        let fit = PitchFit {
            velocity: all(self.velocity).ok_or(NO_PITCH)?,
            acceleration: all(self.acceleration).ok_or(NO_PITCH)?,
        };
        let pitch = fit.at_front_of_plate().ok_or(PITCH_SHORT)?;
        let hand = match side {
            Some(Side::Left) => Hand::Left,
            _ => Hand::Right,
        };
        let degrees = |d: f64| Quantity::Angle.unit(UnitSystem::Imperial, "").read(d);
        let mph = Quantity::Speed.unit(UnitSystem::Imperial, "");
        Ok(TrackedSwing {
            pitch,
            pitch_spin: self
                .spin_rate
                .zip(self.spin_axis)
                .map(|(r, a)| topspin(r, a)),
            // Statcast's sweet-spot speed taken as the paper's V̂_B0 at the
            // contact (analysis::bat_tracking says why).
            bat_speed: mph.read(bat_speed),
            attack_angle: self.attack_angle.map(degrees),
            // Savant's attack direction is positive toward the opposite
            // field: right field for a right-handed batter.
            attack_direction: self.attack_direction.map(|d| degrees(d) * hand.sign()),
            tilt: self.swing_path_tilt.map(degrees),
            hand,
            launch_speed,
            launch_angle,
            spray,
        })
    }
}

/// A row's swing: the tracked one (or why it has none) and the solve's
/// answer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RowSwing {
    pub tracked: Result<TrackedSwing, &'static str>,
    pub answer: Option<SwingAnswer>,
    /// Where a solved swing's launch direction came from (its flight is
    /// launched along the impact's, not aimed again).
    pub direction_from: Option<DirectionFrom>,
}

impl Job {
    /// Where the row's launch direction came from: a solved swing's, its
    /// impact's ([`bat_tracking::solve_landing`]); else `launched`, how the
    /// row's launch was completed.
    pub(crate) fn direction_from(&self, launched: DirectionFrom) -> DirectionFrom {
        (self.swing.as_ref())
            .and_then(|s| s.direction_from)
            .unwrap_or(launched)
    }

    /// The row's tracked swing, with its measured launch, spray and side;
    /// or why it has none.
    pub(crate) fn tracked_swing(&self) -> Result<TrackedSwing, &'static str> {
        let launch = self.scene.launch;
        let measured = (
            launch.speed.unwrap_or(f64::NAN),
            launch.angle.unwrap_or(f64::NAN),
        );
        (self.tracked).swing(measured, self.launch.spray, self.launch.side)
    }

    /// Whether the row flies its solved swing's launch.
    pub(crate) fn swing_solved(&self) -> bool {
        (self.swing.as_ref()).is_some_and(|s| s.solved().is_some())
    }
}

impl RowSwing {
    /// The solved swing, if any.
    pub(crate) fn solved(&self) -> Option<&SolvedSwing> {
        self.answer.as_ref().and_then(|a| a.solved.as_ref().ok())
    }

    /// Why the row has no solved swing.
    pub(crate) fn reason(&self) -> Option<String> {
        match (&self.tracked, &self.answer) {
            (Err(why), _) => Some((*why).to_owned()),
            (Ok(_), Some(answer)) => answer.solved.err().map(|e| e.to_string()),
            (Ok(_), None) => None,
        }
    }

    /// The model's missing exit speed (m/s), where speed is the trouble.
    pub(crate) fn shortfall(&self) -> Option<f64> {
        self.answer?.solved.err()?.shortfall()
    }

    /// The model's own q at E = 0 for the solved swing.
    pub(crate) fn model_efficiency(&self) -> Option<f64> {
        let tracked = self.tracked.ok()?;
        // The most the swing gives is the sweet spot's, solved on or off it.
        let solved = self.solved()?;
        Some(collision_efficiency(
            solved.max_exit_speed,
            tracked.pitch.speed(),
            tracked.bat_speed,
        ))
    }
}

/// Solves the row's swing (when it has a tracked one) and, solved, gives
/// its flight the impact's launch: the measured speed and angle, the
/// impact's direction, backspin and sidespin (nothing estimated). With
/// `spray` the landing (the default), the impact is solved toward the
/// direction whose flight lands on the spray
/// ([`bat_tracking::solve_landing`]); taken as the launch direction, toward
/// the spray itself. A row not solved keeps what `fly --batch` makes of it.
/// `tilt_prior` ([`super::Setup::tilt_prior`]) is the bat's tilt where a
/// tracked row measured none.
pub(crate) fn solve_row(job: &mut Job, spray: Spray, tilt_prior: Option<f64>) {
    let tracked = job.tracked_swing();
    if let (Ok(swing), Some(prior)) = (&tracked, tilt_prior)
        && swing.tilt.is_none()
    {
        job.scene.bat.tilt = prior;
    }
    let options = Purpose::Solve.flight_options();
    let solved = tracked.ok().map(|swing| match spray {
        Spray::Landing => bat_tracking::solve_landing(&job.scene, &swing, &options),
        Spray::Launch => {
            let given = match swing.spray_to_solve() {
                Some(_) => DirectionFrom::Spray,
                None => DirectionFrom::Scene,
            };
            (bat_tracking::solve(&job.scene, &swing), given)
        }
    });
    let (answer, direction_from) = (solved.map(|s| s.0), solved.map(|s| s.1));
    if let Some(solved) = answer.as_ref().and_then(|a| a.solved.as_ref().ok()) {
        job.scene.launch = solved.launch.given();
        job.launch = RowLaunch {
            spray: None,
            side: job.launch.side,
            estimate_backspin: false,
            estimate_sidespin: false,
        };
    }
    let solved = answer.is_some_and(|a| a.solved.is_ok());
    job.swing = Some(RowSwing {
        tracked,
        answer,
        direction_from: direction_from.filter(|_| solved),
    });
}

/// The swing's CSV columns, after `line` (`hit --batch`).
pub(crate) const CSV_COLUMNS: [(&str, Quantity); 15] = [
    ("solved", Quantity::Unchanged),
    ("reason", Quantity::Unchanged),
    ("shortfall", Quantity::Speed),
    ("pitch.speed", Quantity::Speed),
    ("pitch.descent_angle", Quantity::Angle),
    ("swing.speed", Quantity::Speed),
    ("swing.angle", Quantity::Angle),
    ("swing.direction", Quantity::Angle),
    ("swing.tilt", Quantity::Angle),
    ("impact.undercut", Quantity::Size),
    ("impact.regime", Quantity::Unchanged),
    ("impact.collision_efficiency", Quantity::Unchanged),
    ("impact.max_exit_speed", Quantity::Speed),
    ("impact.squared_up", Quantity::Unchanged),
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
    let pitch = swing.tracked.ok().map(|t| t.pitch);
    csv.number(out, Quantity::Speed, pitch.map(|p| p.speed()), 4);
    csv.number(out, Quantity::Angle, pitch.map(|p| p.descent_angle()), 6);
    let bat = solved.map(|s| s.scene.bat);
    csv.number(out, Quantity::Speed, bat.map(|b| b.speed), 4);
    csv.number(out, Quantity::Angle, bat.map(|b| b.swing_angle), 6);
    csv.number(out, Quantity::Angle, bat.map(|b| b.direction), 6);
    csv.number(out, Quantity::Angle, bat.map(|b| b.tilt), 6);
    csv.number(out, Quantity::Size, bat.map(|b| b.undercut), 6);
    if let Some(solved) = solved {
        out.extend_from_slice(solved.regime.name().as_bytes());
    }
    out.push(b',');
    let q = swing.answer.map(|a| a.collision_efficiency);
    csv.number(out, Quantity::Unchanged, q, 5);
    csv.number(out, Quantity::Speed, solved.map(|s| s.max_exit_speed), 4);
    csv.number(out, Quantity::Unchanged, solved.map(|s| s.squared_up()), 5);
    csv.number(out, Quantity::Spin, solved.map(|s| s.launch.gyrospin), 3);
}

#[derive(Serialize)]
pub(crate) struct ImpactJson<'a> {
    collision_efficiency: Option<f64>,
    max_exit_speed: Option<f64>,
    regime: Option<&'a str>,
    squared_up: Option<f64>,
    undercut: Option<f64>,
}

#[derive(Serialize)]
pub(crate) struct PitchJson {
    descent_angle: f64,
    speed: f64,
}

#[derive(Serialize)]
pub(crate) struct SwingJson {
    angle: f64,
    direction: f64,
    speed: f64,
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
    JsonParts {
        impact: Some(ImpactJson {
            collision_efficiency: swing.answer.map(|a| a.collision_efficiency),
            max_exit_speed: solved.map(|s| s.max_exit_speed),
            regime: solved.map(|s| s.regime.name()),
            squared_up: solved.map(|s| s.squared_up()),
            undercut: solved.map(|s| s.scene.bat.undercut),
        }),
        pitch: swing.tracked.ok().map(|t| PitchJson {
            descent_angle: t.pitch.descent_angle(),
            speed: t.pitch.speed(),
        }),
        reason: swing.reason(),
        shortfall: swing.shortfall(),
        solved: Some(solved.is_some()),
        swing: solved.map(|s| SwingJson {
            angle: s.scene.bat.swing_angle,
            direction: s.scene.bat.direction,
            tilt: s.scene.bat.tilt,
            speed: s.scene.bat.speed,
        }),
        gyrospin: solved.map(|s| s.launch.gyrospin),
    }
}
