//! Bat tracking's columns (`hit --batch`, `fly --batch --spin swing`): the
//! swing Statcast measured (`bat_speed`, and since 2025 `attack_angle`,
//! `attack_direction`, `swing_path_tilt`) and the pitch's kinematics
//! (`vx0` … `az`, `release_spin_rate`, `spin_axis`), read in their own
//! units (mph, degrees, ft/s, ft/s², rpm) and made a
//! [`TrackedSwing`] with the row's launch, spray and side.

use crate::columns::SwingColumn;
use analysis::bat_tracking::{
    Found, How, SeasonBat, SolvedSwing, SwingAnswer, TrackedSwing, collision_efficiency,
};
use analysis::savant::DirectionFrom;
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
}

/// Why a row with a launch has no swing to solve.
pub(crate) const NO_BAT_SPEED: &str = "no bat_speed (the swing was not tracked)";
pub(crate) const NO_PITCH: &str = "no pitch kinematics (vx0, vy0, vz0, ax, ay, az)";
pub(crate) const PITCH_SHORT: &str = "the pitch's kinematics never reach the plate";
pub(crate) const REFUSED_CELL: &str = "a tracking cell outside its range";

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
            SwingColumn::ReleaseSpeed => &mut self.release_speed,
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
