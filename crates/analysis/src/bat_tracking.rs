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
//!   a spray, taken as the launch direction.
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
    /// The spray, where the bat's direction is solved from it (no measured
    /// attack direction).
    pub fn spray_to_solve(&self) -> Option<f64> {
        self.spray.filter(|_| self.attack_direction.is_none())
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

/// The second unknown beside E.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Second {
    SwingAngle,
    ContactSpeed,
}

/// One row's equations: unknowns x = (E, ψ or V̂_B0, φ), targets (EV, LA,
/// spray).
#[derive(Clone, Copy)]
struct Problem {
    scene: Scene,
    pitch: Vector3<f64>,
    second: Second,
    free_direction: bool,
    target: [f64; 3],
    prior: f64,
    /// The bat's speed at the contact allowed, as multiples of the sweet
    /// spot's (when it is the second unknown).
    contact_speeds: (f64, f64),
}

impl Problem {
    fn new(base: &Scene, swing: &TrackedSwing) -> Problem {
        let mut scene = *base;
        scene.pitch.speed = swing.pitch.speed();
        scene.pitch.spin = swing.pitch_spin.unwrap_or(base.pitch.spin);
        scene.bat.speed = swing.bat_speed;
        scene.bat.hand = swing.hand;
        scene.bat.tilt = swing.tilt.unwrap_or(base.bat.tilt);
        let direction = swing.attack_direction.or(swing.spray);
        scene.bat.direction = direction.unwrap_or(base.bat.direction);
        let second = match swing.attack_angle {
            Some(angle) => {
                scene.bat.swing_angle = angle;
                Second::ContactSpeed
            }
            None => Second::SwingAngle,
        };
        Problem {
            scene,
            pitch: swing.pitch.velocity,
            second,
            free_direction: swing.spray_to_solve().is_some(),
            target: [
                swing.launch_speed,
                swing.launch_angle,
                swing.spray.unwrap_or(0.0),
            ],
            prior: swing.attack_angle.unwrap_or(base.bat.swing_angle),
            contact_speeds: CONTACT_SPEEDS,
        }
    }

    /// The scene at x.
    fn at(&self, x: [f64; 3]) -> Scene {
        let mut scene = self.scene;
        scene.bat.undercut = x[0];
        match self.second {
            Second::SwingAngle => scene.bat.swing_angle = x[1],
            Second::ContactSpeed => scene.bat.speed = x[1],
        }
        scene.bat.direction = x[2];
        scene
    }

    fn impact(&self, x: [f64; 3]) -> Impact3d {
        Impact3d::with_pitch(&self.at(x), self.pitch)
    }

    fn reach(&self) -> f64 {
        self.scene.reach()
    }

    /// The same equations at the prior swing angle, the bat's speed at the
    /// contact the second unknown (from a bunt's to the sweet spot's).
    fn off_the_sweet_spot(&self) -> Problem {
        Problem {
            second: Second::ContactSpeed,
            contact_speeds: OFF_SWEET_SPOT_SPEEDS,
            ..*self
        }
    }

    /// At the prior swing angle, the bat's speed at the contact solved
    /// (slower than the sweet spot's); marked off the sweet spot.
    fn off_sweet_spot(&self) -> Result<SolvedSwing, Unreached> {
        let off = self.off_the_sweet_spot();
        // A slow bat turns the ball less: its direction may lie far from
        // the spray's, so where the spray's fails the start is tried from
        // bats turned either way (with a free direction). A ball faster than
        // the sweet spot gives is not reached by turning.
        let turns: &[f64] = match off.free_direction {
            true => &[0.0, -0.2, 0.2, -0.4, 0.4],
            false => &[0.0],
        };
        let mut failed = Unreached::NoConvergence;
        for turn in turns {
            let mut from = off;
            from.scene.bat.direction += turn;
            match from.solve() {
                Ok(solved) => return Ok(solved),
                Err(why @ Unreached::TooFast { .. }) => return Err(why),
                Err(why) => failed = why,
            }
        }
        Err(failed)
    }

    fn solve(&self) -> Result<SolvedSwing, Unreached> {
        let direction = self.scene.bat.direction;
        // Newton's method from the prior swing, the undercut set to give
        // the angle: for an exit speed that rises and falls with ψ (near a
        // parabola) it reaches the root nearer its start. Where it fails,
        // a search over every swing angle decides.
        let quick = match self.second {
            Second::SwingAngle => self
                .undercut_for_angle(self.prior, direction, None)
                .and_then(|(e, _)| self.newton([e, self.prior, direction])),
            Second::ContactSpeed => self
                .contact_speed_guess(direction)
                .and_then(|(e, v)| self.newton([e, v, direction])),
        };
        let x = match quick {
            Some(x) => x,
            None => {
                let start = match self.second {
                    Second::SwingAngle => self.swing_angle_start(direction)?,
                    Second::ContactSpeed => self.contact_speed_start(direction)?,
                };
                match self.newton(start) {
                    Some(x) => x,
                    None => self.aim(start)?,
                }
            }
        };
        Ok(self.solved_at(x))
    }

    /// The solved swing at x.
    fn solved_at(&self, x: [f64; 3]) -> SolvedSwing {
        let impact = self.impact(x);
        let scene = self.at(x);
        // The most this swing gives: centred, at the sweet spot.
        let mut centred = scene;
        centred.bat.undercut = 0.0;
        centred.bat.speed = self.scene.bat.speed;
        SolvedSwing {
            scene,
            regime: impact.regime,
            launch: ImpactLaunch::of(&impact),
            max_exit_speed: Impact3d::with_pitch(&centred, self.pitch).launch_speed(),
            off_sweet_spot: self.second == Second::ContactSpeed,
        }
    }

    /// The undercut that gives the launch angle for this second unknown and
    /// direction, near `guess` if given, and the exit speed there.
    fn undercut_for_angle(
        &self,
        second: f64,
        direction: f64,
        guess: Option<f64>,
    ) -> Option<(f64, f64)> {
        // The elevation of the ball's path in the bat's vertical plane,
        // signed past ±90° for a ball going back: it rises with E through
        // every forward launch, and is the launch angle for a ball going
        // forward.
        let forward = model::frame::horizontal(direction);
        let angle_less_target = |undercut: f64| {
            let impact = self.impact([undercut, second, direction]);
            let v = impact.after.ball_velocity;
            let level = v.x.hypot(v.z).copysign(v.dot(&forward));
            (v.y.atan2(level) - self.target[1], impact)
        };
        let found = self.bracket(|e| angle_less_target(e).0, guess.unwrap_or(0.0))?;
        let undercut = illinois(|e| angle_less_target(e).0, found, 1e-13);
        let (_, impact) = angle_less_target(undercut);
        Some((undercut, impact.launch_speed()))
    }

    /// A bracket [a, b] of E with g(a) ≤ 0 ≤ g(b), for g rising with E
    /// over the forward launches: from `start`, steps of 6 mm doubling
    /// toward the root, within ±0.97·(r_b + r_B) (beyond, the contact is
    /// a glancing one). Near the middle the contact sticks and an impact
    /// costs little; a glancing one slips, and its slip is integrated.
    fn bracket(&self, g: impl Fn(f64) -> f64, start: f64) -> Option<((f64, f64), (f64, f64))> {
        let reach = self.reach() * 0.97;
        let mut here = (start.clamp(-reach, reach), 0.0);
        here.1 = g(here.0);
        let upward = here.1 < 0.0;
        let mut step: f64 = 0.006;
        loop {
            let next = if upward { here.0 + step } else { here.0 - step }.clamp(-reach, reach);
            if next == here.0 {
                return None;
            }
            let there = (next, g(next));
            if (there.1 >= 0.0) == upward {
                return Some(if upward { (here, there) } else { (there, here) });
            }
            // Going the wrong way (a ball past ±90° going back): give up.
            if (there.1 > here.1) != upward && there.1 != here.1 {
                return None;
            }
            here = there;
            step *= 2.0;
        }
    }

    /// E and ψ on the branch nearer the prior, at the launch angle and
    /// speed (not yet the direction): the swing angle giving the most exit
    /// speed at this launch angle (a golden-section search over
    /// [`SWING_ANGLES`]), then the root between it and the end of the
    /// range on the prior's side (or, failing that, the other).
    fn swing_angle_start(&self, direction: f64) -> Result<[f64; 3], Unreached> {
        let speed = self.target[0];
        let guess = std::cell::Cell::new(None);
        let exit = |psi: f64| match self.undercut_for_angle(psi, direction, guess.get()) {
            Some((e, s)) => {
                guess.set(Some(e));
                s
            }
            None => f64::NAN,
        };
        let (low, high) = SWING_ANGLES;
        let exit_or_least = |psi: f64| exit(psi).max(f64::MIN);
        let (mut best, mut most) = golden_max(exit_or_least, low, high);
        if most == f64::MIN {
            // The angle may be reachable over a few swing angles only, which
            // the golden section's points missed: a scan, then the golden
            // section about its best point. (Only then: at the range's ends
            // the contact glances and slips, and its slip is integrated.)
            const SCAN: usize = 8;
            let step = (high - low) / SCAN as f64;
            let (mut at, mut top) = (low, f64::MIN);
            for k in 0..=SCAN {
                let psi = low + step * k as f64;
                let here = exit_or_least(psi);
                if here > top {
                    (at, top) = (psi, here);
                }
            }
            if top == f64::MIN {
                return Err(Unreached::Angle);
            }
            let around = ((at - step).max(low), (at + step).min(high));
            (best, most) = golden_max(exit_or_least, around.0, around.1);
            if most < top {
                (best, most) = (at, top);
            }
        }
        if most < speed {
            return Err(Unreached::TooFast {
                shortfall: speed - most,
            });
        }
        let sides = if self.prior < best {
            [low, high]
        } else {
            [high, low]
        };
        let mut least = f64::INFINITY;
        for end in sides {
            let (end, at_end) = defined_toward(exit, end, best);
            least = least.min(at_end);
            if at_end <= speed {
                let bracket = ((end, at_end - speed), (best, most - speed));
                let psi = illinois(|psi| exit(psi) - speed, bracket, 1e-12);
                let (undercut, _) = self
                    .undercut_for_angle(psi, direction, guess.get())
                    .ok_or(Unreached::Angle)?;
                return Ok([undercut, psi, direction]);
            }
        }
        // No end of the range defined (a steep swing tilted as steeply): no
        // speed is told short, only the angle unreached (never an infinite
        // shortfall).
        match least.is_finite() {
            true => Err(Unreached::TooSlow {
                shortfall: speed - least,
            }),
            false => Err(Unreached::Angle),
        }
    }

    /// A start for E and V̂_B0: the exit speed is near linear in the bat's
    /// (EV = q·V_pitch + (1 + q)·V_bat), with q taken where the bat has
    /// the sweet spot's speed.
    fn contact_speed_guess(&self, direction: f64) -> Option<(f64, f64)> {
        let (sweet, pitch) = (self.scene.bat.speed, self.scene.pitch.speed);
        let (_, exit) = self.undercut_for_angle(sweet, direction, None)?;
        let q = collision_efficiency(exit, pitch, sweet);
        let v = (self.target[0] - q * pitch) / (1.0 + q);
        let (e, _) = self.undercut_for_angle(v, direction, None)?;
        Some((e, v))
    }

    /// E and V̂_B0 at the measured ψ: the exit speed rises with the bat's.
    fn contact_speed_start(&self, direction: f64) -> Result<[f64; 3], Unreached> {
        let measured = self.scene.bat.speed;
        let (low, high) = (
            measured * self.contact_speeds.0,
            measured * self.contact_speeds.1,
        );
        let mut guess = None;
        let mut speed_less_target = |v: f64| match self.undercut_for_angle(v, direction, guess) {
            Some((e, s)) => {
                guess = Some(e);
                s - self.target[0]
            }
            None => f64::NAN,
        };
        // The exit speed rises with the bat's: a ball faster than the
        // sweet spot gives is told there, in one solve for the angle, not
        // nine (a tenth of the rows, with the bat at the league's tilt).
        if let Some((_, fastest)) = self.undercut_for_angle(high, direction, None)
            && fastest < self.target[0]
        {
            return Err(Unreached::TooFast {
                shortfall: self.target[0] - fastest,
            });
        }
        // On a grid: at the slowest contacts no undercut may give the
        // angle (a bat nearly at rest sends the ball back along the pitch),
        // so the bracket is the first pair of neighbours, both reached,
        // across which the exit speed passes the measured one.
        const STEPS: usize = 8;
        let (mut previous, mut bracket) = (None, None);
        let (mut least, mut most) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..=STEPS {
            let v = low + (high - low) * i as f64 / STEPS as f64;
            let g = speed_less_target(v);
            if g.is_nan() {
                previous = None;
                continue;
            }
            (least, most) = (least.min(g), most.max(g));
            if let Some((pv, pg)) = previous
                && pg <= 0.0
                && g >= 0.0
            {
                bracket = Some(((pv, pg), (v, g)));
                break;
            }
            previous = Some((v, g));
        }
        let Some(bracket) = bracket else {
            // No contact speed gives the angle at all: no speed is told
            // short (never an infinite shortfall).
            return Err(if !most.is_finite() {
                Unreached::Angle
            } else if most < 0.0 {
                Unreached::TooFast { shortfall: -most }
            } else if least > 0.0 {
                Unreached::TooSlow { shortfall: -least }
            } else if least.is_finite() {
                Unreached::BatSpeed
            } else {
                Unreached::Angle
            });
        };
        let v = illinois(&mut speed_less_target, bracket, 1e-12);
        let (undercut, _) = self
            .undercut_for_angle(v, direction, None)
            .ok_or(Unreached::Angle)?;
        Ok([undercut, v, direction])
    }

    /// Near the most a swing gives, Newton's method in all unknowns can
    /// fail (the speed's slope in ψ vanishes there): then the direction
    /// alone is iterated (a secant), each step solving E and ψ (or V̂_B0)
    /// at that direction as the start did.
    fn aim(&self, start: [f64; 3]) -> Result<[f64; 3], Unreached> {
        if !self.free_direction {
            return Err(Unreached::NoConvergence);
        }
        let at = |direction: f64| match self.second {
            Second::SwingAngle => self.swing_angle_start(direction),
            Second::ContactSpeed => self.contact_speed_start(direction),
        };
        let miss = |x: [f64; 3]| self.impact(x).launch_direction() - self.target[2];
        let (mut last, mut last_miss) = (start, miss(start));
        let mut x = at(start[2] - last_miss)?;
        for _ in 0..30 {
            let now = miss(x);
            if self.converged(&self.residual(x)) {
                return Ok(x);
            }
            let slope = (now - last_miss) / (x[2] - last[2]);
            let next = x[2]
                - now
                    / if slope.is_finite() && slope != 0.0 {
                        slope
                    } else {
                        1.0
                    };
            (last, last_miss) = (x, now);
            x = at(next)?;
        }
        Err(Unreached::NoConvergence)
    }

    /// The residual (speed, angle, direction) at x; the direction's is 0
    /// when it is not an unknown.
    fn residual(&self, x: [f64; 3]) -> Vector3<f64> {
        let impact = self.impact(x);
        let direction = if self.free_direction {
            impact.launch_direction() - self.target[2]
        } else {
            0.0
        };
        Vector3::new(
            impact.launch_speed() - self.target[0],
            impact.launch_angle() - self.target[1],
            direction,
        )
    }

    fn converged(&self, r: &Vector3<f64>) -> bool {
        r.x.abs() < SPEED_TOLERANCE && r.y.abs() < ANGLE_TOLERANCE && r.z.abs() < ANGLE_TOLERANCE
    }

    /// Newton's method on the unknowns with a forward-difference Jacobian
    /// (the direction fixed, its row and column the identity, when it is
    /// no unknown), halving a step that does not reduce the residual.
    fn newton(&self, start: [f64; 3]) -> Option<[f64; 3]> {
        const STEPS: [f64; 3] = [1e-7, 1e-7, 1e-7];
        let scale = Vector3::new(1.0, 30.0, 30.0); // m/s per rad, to compare
        let size = |r: &Vector3<f64>| r.component_mul(&scale).norm();
        let mut x = start;
        let mut r = self.residual(x);
        for _ in 0..16 {
            if self.converged(&r) {
                return self.within_bounds(x).then_some(x);
            }
            let mut jacobian = Matrix3::identity();
            let unknowns = if self.free_direction { 3 } else { 2 };
            for j in 0..unknowns {
                let mut moved = x;
                moved[j] += STEPS[j];
                let column = (self.residual(moved) - r) / STEPS[j];
                jacobian.set_column(j, &column);
            }
            if !self.free_direction {
                jacobian.set_column(2, &Vector3::z());
            }
            let step = jacobian.lu().solve(&-r)?;
            let mut length = 1.0;
            loop {
                let trial = [
                    x[0] + length * step.x,
                    x[1] + length * step.y,
                    x[2] + length * step.z,
                ];
                let tried = self.residual(trial);
                if size(&tried) < size(&r) || length < 1e-3 {
                    (x, r) = (trial, tried);
                    break;
                }
                length *= 0.5;
            }
        }
        None
    }

    /// E within reach, ψ within [`SWING_ANGLES`] (or V̂_B0 within
    /// [`CONTACT_SPEEDS`] of the sweet spot's), the direction within ±90°.
    fn within_bounds(&self, x: [f64; 3]) -> bool {
        let second = match self.second {
            Second::SwingAngle => SWING_ANGLES,
            Second::ContactSpeed => {
                let v = self.scene.bat.speed;
                (self.contact_speeds.0 * v, self.contact_speeds.1 * v)
            }
        };
        x.iter().all(|v| v.is_finite())
            && x[0].abs() < self.reach()
            && (second.0..=second.1).contains(&x[1])
            && x[2].abs() < std::f64::consts::FRAC_PI_2
    }
}

mod ceiling;
mod landing;
mod search;
mod season;
#[cfg(test)]
mod tests;

pub use ceiling::{
    APPROACH_BANDS, ApproachBand, EFFECTIVE_MASSES, ImpactFit, ceiling_efficiency,
    fit_effective_mass, quantile,
};
pub use landing::solve_landing;
use search::{defined_toward, golden_max, illinois};
pub use season::{SEASON_BATS, SeasonBat, season_bat, season_scene};
