//! Bat tracking's columns (`hit --batch`, `fly --batch --spin swing`): the
//! swing Statcast measured (`bat_speed`, and since 2025 `attack_angle`,
//! `attack_direction`, `swing_path_tilt`) and the pitch's kinematics
//! (`vx0` … `az`, `release_spin_rate`, `spin_axis`), read in their own
//! units (mph, degrees, ft/s, ft/s², rpm) and made a
//! [`TrackedSwing`] with the row's launch, spray and side.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::columns::SwingColumn;
use crate::output::CsvLine;
use crate::row::Job;
use crate::setup::{Priors, quoted};
use analysis::bat_tracking::{
    self, Found, How, SeasonBat, SolvedSwing, SwingAnswer, TrackedSwing, collision_efficiency,
    savant_squared_up, season_bat,
};
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
    /// `release_speed` (mph).
    pub release_speed: Option<f64>,
    /// `game_year` (or `season`), and the year of `game_date`.
    pub season: Option<f64>,
    pub date_year: Option<f64>,
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
        if column == SwingColumn::Date {
            let year = crate::dates::year_month(value).map(|(year, _)| f64::from(year));
            self.date_year = Some(year.ok_or_else(|| {
                format!(
                    "{name} = {:?}: expected a date, YYYY-MM-DD or M/D/YYYY",
                    cut(value, 80)
                )
            })?);
            return Ok(());
        }
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
            SwingColumn::ReleaseSpeed => &mut self.release_speed,
            SwingColumn::Season => &mut self.season,
            SwingColumn::Date => &mut self.date_year,
        };
        *slot = Some(number);
        Ok(())
    }

    /// The row's season: `game_year` (or `season`), else its date's year.
    pub(crate) fn season(&self) -> Option<i32> {
        // Both read within 1800 to 2200: whole years.
        self.season
            .map(|y| y.floor())
            .or(self.date_year)
            .map(|y| y as i32)
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
    /// The season's bat it was solved with (`None`: the preset's).
    pub bat: Option<&'static SeasonBat>,
    /// The bat's effective mass it was solved with (kg).
    pub effective_mass: f64,
    /// Savant's squared-up, where the row has `release_speed`.
    pub savant_squared_up: Option<f64>,
    /// Whether the tilt not measured was given (`--set` or a column), not
    /// the league's prior.
    pub tilt_given: bool,
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

    /// How each swing quantity of the solved swing was found.
    pub(crate) fn found(&self) -> Option<Found> {
        Some(Found::of(self.tracked.as_ref().ok()?, self.solved()?))
    }

    /// How the solved swing's angle, direction, tilt, contact speed and
    /// undercut were found, as the output names them: a tilt neither
    /// measured nor the league's prior is `given` (`--set` or a column).
    pub(crate) fn found_names(&self) -> Option<[&'static str; 5]> {
        let found = self.found()?;
        let tilt = match found.tilt {
            How::Prior if self.tilt_given => "given",
            how => how.name(),
        };
        Some([
            found.angle.name(),
            found.direction.name(),
            tilt,
            found.contact_speed.name(),
            found.undercut.name(),
        ])
    }

    /// The bat's name, as the output gives it: its season, or `preset`.
    pub(crate) fn bat_name(&self) -> String {
        self.bat
            .map_or("preset".to_owned(), |b| b.season.to_string())
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
/// `priors` ([`Setup::priors`]): the bat's tilt where a tracked row
/// measured none, and whether the row's season picks its bat.
pub(crate) fn solve_row(job: &mut Job, spray: Spray, priors: Priors) {
    let tracked = job.tracked_swing();
    if let (Ok(swing), Some(prior)) = (&tracked, priors.tilt)
        && swing.tilt.is_none()
    {
        job.scene.bat.tilt = prior;
    }
    let season = job.tracked.season();
    let bat = (priors.season_bats && tracked.is_ok())
        .then(|| bat_tracking::season_bat(season))
        .flatten();
    if bat.is_some() {
        job.scene = bat_tracking::season_scene(&job.scene, season);
    }
    let effective_mass = job.scene.bat.effective_mass;
    let savant_squared_up = tracked.ok().and_then(|swing| {
        let mph = Quantity::Speed.unit(UnitSystem::Imperial, "");
        let release = mph.read(job.tracked.release_speed?);
        Some(savant_squared_up(
            swing.launch_speed,
            swing.bat_speed,
            release,
        ))
    });
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
        bat,
        effective_mass,
        savant_squared_up,
        tilt_given: priors.tilt.is_none(),
    });
}

/// The swing's CSV columns, after `line` (`hit --batch`).
pub(crate) const CSV_COLUMNS: [(&str, Quantity); 24] = [
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
    ("swing.from.angle", Quantity::Unchanged),
    ("swing.from.direction", Quantity::Unchanged),
    ("swing.from.tilt", Quantity::Unchanged),
    ("swing.from.contact_speed", Quantity::Unchanged),
    ("swing.from.undercut", Quantity::Unchanged),
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
    let from = swing.found_names();
    for k in 0..5 {
        if let Some(from) = from {
            out.extend_from_slice(from[k].as_bytes());
        }
        out.push(b',');
    }
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
                },
                tilt: s.scene.bat.tilt,
            }),
        gyrospin: solved.map(|s| s.launch.gyrospin),
    }
}

/// The bats a batch's tracked rows were solved with
/// ([`crate::tally::Swings::bats`]), for the summary line: "17436 with the
/// 2024 bat: M_B 0.884 kg, …".
pub(crate) fn bats_named(bats: &BTreeMap<(Option<i32>, u64), usize>) -> Vec<String> {
    (bats.iter())
        .map(
            |(&(season, mass), n)| match season.and_then(|s| season_bat(Some(s))) {
                Some(bat) => format!("{n} with the {}", bat.source),
                None => format!("{n} with the preset's (M_B {:.3} kg)", f64::from_bits(mass)),
            },
        )
        .collect()
}

/// The same as the summary's JSON: `[{"bat", "effective_mass", "source",
/// "tracked"}]`, masses in kg.
pub(crate) fn bats_json(bats: &BTreeMap<(Option<i32>, u64), usize>) -> serde_json::Value {
    (bats.iter())
        .map(|(&(season, mass), n)| {
            let bat = season.and_then(|s| season_bat(Some(s)));
            serde_json::json!({
                "bat": season.map_or("preset".to_owned(), |s| s.to_string()),
                "effective_mass": f64::from_bits(mass),
                "source": bat.map_or("the preset's bat", |b| b.source),
                "tracked": n,
            })
        })
        .collect()
}
