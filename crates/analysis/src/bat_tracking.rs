//! The swing behind a tracked ball (issue 27; docs/bat-tracking.md): a
//! Statcast row's pitch (its kinematics at the plate), its swing (bat
//! tracking's `bat_speed`, and where measured `attack_angle`,
//! `attack_direction`, `swing_path_tilt`) and its launch (`launch_speed`,
//! `launch_angle`, the spray) put through the paper's impact, solving for
//! what tracking does not measure:
//! - the undercut E, always;
//! - the bat's speed at the contact (a contact off the sweet spot), at
//!   the measured `attack_angle` or, without one, at the prior swing angle;
//!   only a ball faster than the sweet spot gives at the prior has its
//!   swing angle ψ solved instead, at the sweet spot;
//! - the bat's direction where the row has no `attack_direction` and has
//!   a spray, taken as the launch direction;
//! - where `attack_direction` measures the sweet spot's path, the bat's
//!   lead over it (the barrel turned ahead of square within the swing
//!   plane, `bat.lead`), toward the same spray; 0 (square) without a spray.
//!
//! So the impact gives the measured exit speed and launch angle (and
//! direction) exactly, and then says what tracking cannot: the spin the
//! ball left with, the regime (stick or slip), and how squarely it was hit.
//!
//! **Bat speed.** Statcast's `bat_speed` is the speed of the sweet spot,
//! about 6 in from the end of the barrel. The paper's V̂_B0 is the speed of
//! the bat's axis where the ball meets it, taken at the centre of
//! percussion (§II.A), about 6–7 in from the end of a 34-in wood bat: the
//! same point to within an inch, where the speed differs by ~3 % (an inch
//! in ~30 in of radius about the hands). So V̂_B0 = `bat_speed`, unscaled.
//!
//! **Which swing.** A shortfall of exit speed could be the swing's
//! obliquity or a contact off the sweet spot; 2024's tracking measures
//! neither. Solving ψ first put all of it into obliquity, and so into spin
//! (line drives at ψ ≈ −10° and 3,300 rpm against Trackman's 1,850); with ψ
//! at the prior, the scene's `bat.swing_angle` (the paper's optimum,
//! 0.1594 rad = 9.1°, near MLB's mean attack angle of about 10°), it is a
//! fifth below the measured from 10° to 50° (docs/bat-tracking.md, "Which
//! swing"). The bat's direction is solved so that the ball lands on the
//! spray ([`solve_landing`]). Where ψ is solved, a speed below its most is given by two
//! swings, one flatter and meeting the ball below its centre, one steeper
//! meeting it above: the solve takes the one nearer the prior.

use model::impact::{Impact3d, Regime};
use model::scene::{GivenLaunch, Hand, Scene};
use model::tracked_pitch::PitchAtPlate;
use nalgebra::{Matrix3, Vector3};

/// The swing path's tilt (rad) a tracked row without `swing_path_tilt` is
/// solved at: MLB's league average, "about 32°" (MLB glossary, Swing Path
/// (Tilt); 20° to 50° by hitter). The presets' level bat (`bat.tilt` = 0)
/// is the paper's plane, not a measured swing.
pub const LEAGUE_SWING_PATH_TILT: f64 = 32.0 * std::f64::consts::PI / 180.0;

/// One tracked swing, in SI and the flight frame's conventions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrackedSwing {
    pub pitch: PitchAtPlate,
    /// ω_b0 (rad/s, pitched topspin positive), where tracked.
    pub pitch_spin: Option<f64>,
    /// `bat_speed` (m/s): the sweet spot's speed, taken as V̂_B0.
    pub bat_speed: f64,
    /// `attack_angle` (rad), if measured.
    pub attack_angle: Option<f64>,
    /// `attack_direction` (rad from the centre-field line, positive
    /// toward right field), if measured.
    pub attack_direction: Option<f64>,
    /// `swing_path_tilt` as `bat.tilt` (rad), if measured.
    pub tilt: Option<f64>,
    pub hand: Hand,
    /// The measured launch: speed (m/s), angle (rad), and the spray (rad,
    /// as [`crate::savant::spray_angle`]) taken as the launch direction.
    pub launch_speed: f64,
    pub launch_angle: f64,
    pub spray: Option<f64>,
}

impl TrackedSwing {
    /// The spray, where the launch is turned toward it: by the bat's
    /// direction, or where `attack_direction` measures that, by the bat's
    /// lead over its path (docs/swing-3d.md).
    pub fn spray_to_solve(&self) -> Option<f64> {
        self.spray
    }
}

/// The collision efficiency q = (EV − V_bat)/(V_pitch + V_bat): the
/// linear form EV = q·V_pitch + (1 + q)·V_bat of Nathan ("Characterizing
/// the performance of baseball bats", Am. J. Phys. 71, 134 (2003)) that
/// Statcast's squared-up metric rests on. Speeds at the plate (m/s).
pub fn collision_efficiency(exit_speed: f64, pitch_speed: f64, bat_speed: f64) -> f64 {
    (exit_speed - bat_speed) / (pitch_speed + bat_speed)
}

/// What the impact gives for a solved swing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolvedSwing {
    /// The row's scene with its solved swing: bat speed, E, ψ, direction,
    /// tilt, hand, and the pitch's spin (its speed and path are
    /// `TrackedSwing::pitch`'s).
    pub scene: Scene,
    pub regime: Regime,
    /// The launch the impact gives (m/s, rad, rad/s).
    pub launch: ImpactLaunch,
    /// The same swing and pitch at E = 0 (m/s).
    pub max_exit_speed: f64,
    /// Solved off the sweet spot: the bat's speed at the contact (in
    /// `scene.bat.speed`) below the sweet spot's, at the prior swing angle,
    /// for a ball slower than the sweet spot gives.
    pub off_sweet_spot: bool,
}

impl SolvedSwing {
    /// EV over the most the same swing gives the same pitch (E = 0).
    pub fn squared_up(&self) -> f64 {
        self.launch.speed / self.max_exit_speed
    }
}

/// A launch out of the impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactLaunch {
    pub speed: f64,
    pub angle: f64,
    pub direction: f64,
    pub spin: f64,
    pub sidespin: f64,
    pub gyrospin: f64,
}

impl ImpactLaunch {
    /// As a scene's launch: every part given.
    pub fn given(&self) -> GivenLaunch {
        GivenLaunch {
            speed: Some(self.speed),
            angle: Some(self.angle),
            spin: Some(self.spin),
            direction: Some(self.direction),
            sidespin: Some(self.sidespin),
        }
    }

    fn of(impact: &Impact3d) -> ImpactLaunch {
        ImpactLaunch {
            speed: impact.launch_speed(),
            angle: impact.launch_angle(),
            direction: impact.launch_direction(),
            spin: impact.launch_spin(),
            sidespin: impact.launch_sidespin(),
            gyrospin: impact.launch_gyrospin(),
        }
    }
}

/// Why a row has no swing in the model.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum Unreached {
    /// The measured exit speed is above the most this bat speed and pitch
    /// give at the measured launch angle, whatever the swing angle.
    #[error("exit speed above the model's reach at this launch angle")]
    TooFast { shortfall: f64 },
    /// Below the least the swing angles or contact speeds searched give.
    #[error("exit speed below the model's least at this launch angle")]
    TooSlow { shortfall: f64 },
    /// No undercut gives the launch angle.
    #[error("launch angle out of reach: no undercut gives it")]
    Angle,
    /// No bat speed at the contact in the range searched gives the exit
    /// speed, though the range passes above and below it.
    #[error("no bat speed at the contact gives the exit speed")]
    BatSpeed,
    /// The Newton iteration did not reach the launch to 0.1 mph and 0.1°.
    #[error("the solve did not converge")]
    NoConvergence,
    /// The launch reached only with the bat leading its measured path by
    /// more than [`model::impact::MOST_LEAD`] (rad, the lead it took).
    #[error("the bat's lead over its path needed is beyond ±45°")]
    Lead { lead: f64 },
}

impl Unreached {
    /// The model's missing exit speed (m/s), measured less reachable:
    /// positive when the model falls short, negative when it cannot go
    /// slow enough; `None` when speed is not the trouble.
    pub fn shortfall(&self) -> Option<f64> {
        match *self {
            Unreached::TooFast { shortfall } | Unreached::TooSlow { shortfall } => Some(shortfall),
            _ => None,
        }
    }
}

/// A row's answer: q from the data (always), and the swing if solved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SwingAnswer {
    pub collision_efficiency: f64,
    pub solved: Result<SolvedSwing, Unreached>,
}

/// The swing angles searched: −0.6 to 1.0 rad (−34° to 57°), wider than
/// the attack angles bat tracking reports.
const SWING_ANGLES: (f64, f64) = (-0.6, 1.0);
/// The bat's speed at the contact, as a multiple of the sweet spot's.
const CONTACT_SPEEDS: (f64, f64) = (0.3, 2.0);
/// … and off the sweet spot: slower, down to a bat held nearly still (a
/// bunt meets the pitch with the barrel at rest).
const OFF_SWEET_SPOT_SPEEDS: (f64, f64) = (0.02, 1.0);
/// Solved rows reproduce the launch to far better than 0.1 mph and 0.1°.
const SPEED_TOLERANCE: f64 = 1e-9; // m/s
const ANGLE_TOLERANCE: f64 = 1e-11; // rad

/// Solves one row against `base` (the preset: ball, bat body, friction;
/// and the swing angle that picks between two swings).
pub fn solve(base: &Scene, swing: &TrackedSwing) -> SwingAnswer {
    let pitch_speed = swing.pitch.speed();
    let collision_efficiency =
        collision_efficiency(swing.launch_speed, pitch_speed, swing.bat_speed);
    let problem = Problem::new(base, swing);
    let solved = match problem.second {
        Second::ContactSpeed => problem.solve(),
        // No measured attack angle: the swing angle is held at the prior
        // and a ball slower than the sweet spot gives there met the bat off
        // it, where the bat moves slower (0.02 to 1 times the sweet spot's
        // speed, down to a bunt's nearly still barrel). Only a ball faster
        // than that, or one the prior cannot give, has its swing angle
        // solved, at the sweet spot, nearest the prior. Solving ψ first
        // would put every shortfall of a real collision's efficiency into
        // the swing's obliquity, and with it into spin: line drives at
        // ψ ≈ −10° and 3,300 rpm against 1,850 measured
        // (docs/bat-tracking.md, "Which swing").
        Second::SwingAngle => problem.off_sweet_spot().or_else(|_| problem.solve()),
    };
    SwingAnswer {
        collision_efficiency,
        solved,
    }
}

mod ceiling;
mod found;
mod landing;
mod problem;
mod search;
mod season;
#[cfg(test)]
mod tests;

pub use ceiling::{
    APPROACH_BANDS, ApproachBand, EFFECTIVE_MASSES, ImpactFit, ceiling_efficiency,
    fit_effective_mass, quantile,
};
pub use found::{Found, How, savant_squared_up};
pub use landing::solve_landing;
use problem::{Problem, Second};
use search::{defined_toward, golden_max, illinois};
pub use season::{SEASON_BATS, SeasonBat, season_bat, season_scene};
