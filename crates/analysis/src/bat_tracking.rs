//! The swing behind a tracked ball (issue 27; docs/bat-tracking.md): a
//! Statcast row's pitch (its kinematics at the plate), its swing (bat
//! tracking's `bat_speed`, and where measured `attack_angle`,
//! `attack_direction`, `swing_path_tilt`) and its launch (`launch_speed`,
//! `launch_angle`, the spray) put through the paper's impact, solving for
//! what tracking does not measure:
//! - the undercut E, always;
//! - the swing angle ψ where the row has no `attack_angle`; where it has
//!   one, the bat's speed at the contact point instead (the contact off
//!   the sweet spot: one measurement more needs one unknown more);
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
//! **The two swings.** For a given launch angle the exit speed, as a
//! function of ψ (the undercut following to keep the angle), rises to a
//! most and falls again: a measured speed below that most is given by two
//! swings, one swung flatter and meeting the ball below its centre, one
//! swung steeper and meeting it above. The solve takes the one whose ψ is
//! nearer the scene's `bat.swing_angle` (the paper's optimum, 0.1594 rad =
//! 9.1°, near MLB's mean attack angle of about 10°), or the measured
//! attack angle's.

use model::impact::{Impact3d, Regime};
use model::scene::{Hand, Scene};
use model::tracked_pitch::PitchAtPlate;
use nalgebra::{Matrix3, Vector3};

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
    /// Below the least any swing angle in the range searched gives.
    #[error("exit speed below what any swing angle from -0.6 to 1.0 rad gives")]
    TooSlow { shortfall: f64 },
    /// No undercut gives the launch angle.
    #[error("launch angle out of reach: no undercut gives it")]
    Angle,
    /// The bat's speed at the contact would have to leave 0.3–2 × the
    /// sweet spot's (with a measured attack angle).
    #[error("the bat's speed at the contact would be outside 0.3-2 x bat_speed")]
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
    let solved = match problem.solve() {
        // Slower than any swing angle gives at the sweet spot's speed: the
        // ball met the bat off its sweet spot (toward the hands, or a bunt),
        // where the bat moves slower. The swing angle is held at the prior
        // and the bat's speed at the contact solved instead (0.02 to 1 times
        // the sweet spot's), as a measured attack angle has it solved.
        Err(Unreached::TooSlow { shortfall }) if problem.second == Second::SwingAngle => {
            let off = Problem {
                second: Second::ContactSpeed,
                contact_speeds: OFF_SWEET_SPOT_SPEEDS,
                ..problem
            };
            // A slow bat turns the ball less: its direction may lie far
            // from the spray's, so where the spray's fails the start is
            // tried from bats turned either way (with a free direction).
            let turns: &[f64] = match off.free_direction {
                true => &[0.0, -0.2, 0.2, -0.4, 0.4],
                false => &[0.0],
            };
            let mut found = turns.iter().map(|turn| {
                let mut from = off;
                from.scene.bat.direction += turn;
                from.solve()
            });
            found
                .find_map(Result::ok)
                .map(|solved| SolvedSwing {
                    off_sweet_spot: true,
                    ..solved
                })
                .ok_or(Unreached::TooSlow { shortfall })
        }
        solved => solved,
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
            free_direction: swing.attack_direction.is_none() && swing.spray.is_some(),
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
            Second::ContactSpeed => None,
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
        let impact = self.impact(x);
        let scene = self.at(x);
        let mut centred = scene;
        centred.bat.undercut = 0.0;
        Ok(SolvedSwing {
            scene,
            regime: impact.regime,
            launch: ImpactLaunch::of(&impact),
            max_exit_speed: Impact3d::with_pitch(&centred, self.pitch).launch_speed(),
            off_sweet_spot: false,
        })
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
        Err(Unreached::TooSlow {
            shortfall: speed - least,
        })
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
        // On a grid: at the slowest contacts no undercut may give the
        // angle (a bat nearly at rest sends the ball back along the pitch),
        // so the bracket is the first pair of neighbours, both reached,
        // across which the exit speed passes the measured one.
        const STEPS: usize = 8;
        let (mut previous, mut reached, mut bracket) = (None, false, None);
        for i in 0..=STEPS {
            let v = low + (high - low) * i as f64 / STEPS as f64;
            let g = speed_less_target(v);
            if g.is_nan() {
                previous = None;
                continue;
            }
            reached = true;
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
            return Err(if reached {
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

/// A root of g between a and b (g(a) ≤ 0 ≤ g(b) or the reverse), by the
/// Illinois variant of regula falsi, to `tolerance` in the argument.
fn illinois(
    mut g: impl FnMut(f64) -> f64,
    ((mut a, mut ga), (mut b, mut gb)): ((f64, f64), (f64, f64)),
    tolerance: f64,
) -> f64 {
    let mut side = 0;
    for _ in 0..100 {
        if ga == 0.0 {
            return a;
        }
        if gb == 0.0 {
            return b;
        }
        let c = (a * gb - b * ga) / (gb - ga);
        let gc = g(c);
        if gc.is_nan() {
            // Outside where g is defined: bisect instead.
            let m = 0.5 * (a + b);
            let gm = g(m);
            if gm.is_nan() {
                return c;
            }
            if (gm > 0.0) == (gb > 0.0) {
                (b, gb) = (m, gm);
            } else {
                (a, ga) = (m, gm);
            }
            continue;
        }
        if (gc > 0.0) == (gb > 0.0) {
            (b, gb) = (c, gc);
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        } else {
            (a, ga) = (c, gc);
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        }
        if (b - a).abs() < tolerance || gc == 0.0 {
            return c;
        }
    }
    0.5 * (a + b)
}

/// The most of `f` on [a, b] and where: a golden-section search, 32
/// narrowings (to 2e-7 of the interval: the most is flat there, to 1e-13
/// of itself).
fn golden_max(mut f: impl FnMut(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..32 {
        if fc > fd {
            (b, d, fd) = (d, c, fc);
            c = b - ratio * (b - a);
            fc = f(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + ratio * (b - a);
            fd = f(d);
        }
    }
    if fc > fd { (c, fc) } else { (d, fd) }
}

/// `end`, or the first point from it toward `inner` (halving the way)
/// where `f` is defined, and f there.
fn defined_toward(f: impl Fn(f64) -> f64, end: f64, inner: f64) -> (f64, f64) {
    let mut x = end;
    for _ in 0..30 {
        let value = f(x);
        if !value.is_nan() {
            return (x, value);
        }
        x = 0.5 * (x + inner);
    }
    (inner, f(inner))
}

/// The `quantile` (0 to 1) of `values` (not empty) by the nearest rank.
pub fn quantile(values: &[f64], quantile: f64) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    sorted[(quantile * (sorted.len() - 1) as f64).round() as usize]
}

/// The most the scene's bat gives this row's pitch, as a collision
/// efficiency: the bat meeting the ball centred (E = 0) and head-on, its
/// velocity straight against the pitch's (ψ = γ, the bat's direction
/// against the pitch's path), at the row's bat speed, with the row's pitch
/// spin and the scene's bodies.
pub fn ceiling_efficiency(base: &Scene, swing: &TrackedSwing) -> f64 {
    let mut scene = *base;
    scene.pitch.spin = swing.pitch_spin.unwrap_or(base.pitch.spin);
    scene.bat.speed = swing.bat_speed;
    scene.bat.hand = swing.hand;
    scene.bat.tilt = 0.0;
    scene.bat.undercut = 0.0;
    scene.bat.swing_angle = swing.pitch.descent_angle();
    scene.bat.direction = -swing.pitch.lateral_angle();
    let exit = Impact3d::with_pitch(&scene, swing.pitch.velocity).launch_speed();
    collision_efficiency(exit, swing.pitch.speed(), swing.bat_speed)
}

/// `calibrate --impact`'s fit: the bat's effective mass M_B for which a
/// row's q exceeds its own ceiling ([`ceiling_efficiency`]: its pitch, its
/// bat speed, Eq. 19's e* at its approach) on only 1 − `quantile` of the
/// rows, so that the model's ceiling is the measured one row by row.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ImpactFit {
    pub rows: usize,
    pub quantile: f64,
    /// The data's q at the quantile.
    pub data: f64,
    /// The scene's M_B (kg), the model's ceiling at the quantile with it,
    /// and the share of rows above their ceiling.
    pub effective_mass_before: f64,
    pub ceiling_before: f64,
    pub above_before: f64,
    /// The fitted M_B (kg), and the same with it.
    pub effective_mass: f64,
    pub ceiling_after: f64,
    pub above_after: f64,
}

/// The range of M_B searched (kg).
pub const EFFECTIVE_MASSES: (f64, f64) = (0.2, 5.0);

/// Fits M_B by bisection (each ceiling rises with M_B: a heavier bat gives
/// back more of the ball's momentum); `None` without rows.
pub fn fit_effective_mass(base: &Scene, swings: &[TrackedSwing], at: f64) -> Option<ImpactFit> {
    if swings.is_empty() {
        return None;
    }
    let data: Vec<f64> = swings
        .iter()
        .map(|s| collision_efficiency(s.launch_speed, s.pitch.speed(), s.bat_speed))
        .collect();
    let ceilings = |mass: f64| -> Vec<f64> {
        let mut scene = *base;
        scene.bat.effective_mass = mass;
        swings
            .iter()
            .map(|s| ceiling_efficiency(&scene, s))
            .collect()
    };
    let excess =
        |ceilings: &[f64]| -> Vec<f64> { data.iter().zip(ceilings).map(|(q, c)| q - c).collect() };
    let above = |ceilings: &[f64]| {
        let above = data.iter().zip(ceilings).filter(|(q, c)| q > c).count();
        above as f64 / data.len() as f64
    };
    let (mut low, mut high) = EFFECTIVE_MASSES;
    for _ in 0..50 {
        let middle = 0.5 * (low + high);
        if quantile(&excess(&ceilings(middle)), at) > 0.0 {
            low = middle;
        } else {
            high = middle;
        }
    }
    let effective_mass = 0.5 * (low + high);
    let (before, after) = (ceilings(base.bat.effective_mass), ceilings(effective_mass));
    Some(ImpactFit {
        rows: swings.len(),
        quantile: at,
        data: quantile(&data, at),
        effective_mass_before: base.bat.effective_mass,
        ceiling_before: quantile(&before, at),
        above_before: above(&before),
        effective_mass,
        ceiling_after: quantile(&after, at),
        above_after: above(&after),
    })
}

#[cfg(test)]
mod tests;
