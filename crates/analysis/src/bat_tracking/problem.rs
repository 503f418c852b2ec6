//! One row's equations and their solve: the unknowns (E, then ψ or the
//! bat's speed at the contact, and the bat's direction or its lead where the
//! row has a spray) that make the paper's impact give the measured launch
//! ([`super::solve`]).

use super::*;

/// A start whose launch angle misses the target by more than this (rad)
/// is no root of the angle's equation ([`Problem::named`]).
const ROOT_ANGLE: f64 = 1e-6;
/// The most lead (rad) a solved bat may have: the key's bound.
const MOST_LEAD: f64 = model::impact::MOST_LEAD;

/// The second unknown beside E.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Second {
    SwingAngle,
    ContactSpeed,
}

/// The third unknown, which turns the launch toward the spray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Third {
    /// None: the row has no spray; x[2] is the bat's direction, held.
    Held,
    /// The bat's direction φ (no `attack_direction`).
    Direction,
    /// The bat's lead λ over its measured path (`attack_direction`
    /// measured): the direction is Statcast's, the barrel's heading is not.
    Lead,
}

impl Third {
    /// Where it lives in `bat`: the lead, or the bat's direction.
    fn of(self, bat: &mut model::scene::Bat) -> &mut f64 {
        match self {
            Third::Lead => &mut bat.lead,
            Third::Held | Third::Direction => &mut bat.direction,
        }
    }
}

/// One row's equations: unknowns x = (E, ψ or V̂_B0, φ or λ), targets (EV,
/// LA, spray).
#[derive(Clone, Copy)]
pub(super) struct Problem {
    pub(super) scene: Scene,
    pub(super) pitch: Vector3<f64>,
    pub(super) second: Second,
    pub(super) third: Third,
    pub(super) target: [f64; 3],
    pub(super) prior: f64,
    /// The bat's speed at the contact allowed, as multiples of the sweet
    /// spot's (when it is the second unknown).
    pub(super) contact_speeds: (f64, f64),
}

impl Problem {
    pub(super) fn new(base: &Scene, swing: &TrackedSwing) -> Problem {
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
            third: match (swing.spray_to_solve(), swing.attack_direction) {
                (None, _) => Third::Held,
                (Some(_), None) => Third::Direction,
                (Some(_), Some(_)) => Third::Lead,
            },
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
    pub(super) fn at(&self, x: [f64; 3]) -> Scene {
        let mut scene = self.scene;
        scene.bat.undercut = x[0];
        match self.second {
            Second::SwingAngle => scene.bat.swing_angle = x[1],
            Second::ContactSpeed => scene.bat.speed = x[1],
        }
        *self.third.of(&mut scene.bat) = x[2];
        scene
    }

    /// The third unknown's value in `bat`.
    pub(super) fn third_of(&self, bat: &model::scene::Bat) -> f64 {
        let mut bat = *bat;
        *self.third.of(&mut bat)
    }

    /// The bat's direction where the third unknown is `third`.
    fn direction_at(&self, third: f64) -> f64 {
        match self.third {
            Third::Lead => self.scene.bat.direction,
            Third::Held | Third::Direction => third,
        }
    }

    /// Whether the launch direction is a target (the row has a spray).
    fn aimed(&self) -> bool {
        self.third != Third::Held
    }

    /// About how far the launch turns per unit of the third unknown, for
    /// the secant's first step only (it measures its own slope after): 1
    /// for the bat's direction; for the lead, −1.5·h, a barrel ahead of its
    /// path pulling the ball (about 1.5° a degree of lead, session 19's
    /// patch, docs/swing-3d.md).
    fn turn_per_unknown(&self) -> f64 {
        match self.third {
            Third::Lead => -1.5 * self.scene.bat.hand.sign(),
            Third::Held | Third::Direction => 1.0,
        }
    }

    pub(super) fn impact(&self, x: [f64; 3]) -> Impact3d {
        Impact3d::with_pitch(&self.at(x), self.pitch)
    }

    pub(super) fn reach(&self) -> f64 {
        self.scene.reach()
    }

    /// The same equations at the prior swing angle, the bat's speed at the
    /// contact the second unknown (from a bunt's to the sweet spot's).
    pub(super) fn off_the_sweet_spot(&self) -> Problem {
        Problem {
            second: Second::ContactSpeed,
            contact_speeds: OFF_SWEET_SPOT_SPEEDS,
            ..*self
        }
    }

    /// At the prior swing angle, the bat's speed at the contact solved
    /// (slower than the sweet spot's); marked off the sweet spot.
    pub(super) fn off_sweet_spot(&self) -> Result<SolvedSwing, Unreached> {
        let off = self.off_the_sweet_spot();
        // A slow bat turns the ball less: its direction may lie far from
        // the spray's, so where the spray's fails the start is tried from
        // bats turned either way (with a free direction or lead). A ball
        // faster than the sweet spot gives is not reached by turning.
        let turns: &[f64] = match off.aimed() {
            true => &[0.0, -0.2, 0.2, -0.4, 0.4],
            false => &[0.0],
        };
        let mut failed = Unreached::NoConvergence;
        for turn in turns {
            let mut from = off;
            *from.third.of(&mut from.scene.bat) += turn;
            match from.solve() {
                Ok(solved) => return Ok(solved),
                Err(why @ Unreached::TooFast { .. }) => return Err(why),
                Err(why) => failed = why,
            }
        }
        Err(failed)
    }

    pub(super) fn solve(&self) -> Result<SolvedSwing, Unreached> {
        let x = self.unknowns()?;
        // A lead past the key's bounds is no swing (docs/swing-3d.md):
        // named, not kept.
        if self.third == Third::Lead && x[2].abs() > MOST_LEAD {
            return Err(Unreached::Lead { lead: x[2] });
        }
        Ok(self.solved_at(x))
    }

    /// The unknowns that give the launch.
    fn unknowns(&self) -> Result<[f64; 3], Unreached> {
        let direction = self.third_of(&self.scene.bat);
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
                    None => self.aim(start).map_err(|why| self.named(start, why))?,
                }
            }
        };
        Ok(x)
    }

    /// Why a solve from `start` failed, named: a start whose launch angle
    /// is not the measured one came from a bracket across the elevation's
    /// wrap at ±180° (a ball sent back and down on one side, forward on the
    /// other), a jump and not a root, so no undercut gives the angle there.
    /// 2025's popups at their measured attack angle ended so: none of eight
    /// scanned reaches its angle at any undercut within 0.97 of the reach
    /// and any contact speed from 0.3 to 2 times `bat_speed`.
    fn named(&self, start: [f64; 3], why: Unreached) -> Unreached {
        match why {
            Unreached::NoConvergence if self.residual(start).y.abs() > ROOT_ANGLE => {
                Unreached::Angle
            }
            why => why,
        }
    }

    /// The solved swing at x.
    pub(super) fn solved_at(&self, x: [f64; 3]) -> SolvedSwing {
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
    pub(super) fn undercut_for_angle(
        &self,
        second: f64,
        direction: f64,
        guess: Option<f64>,
    ) -> Option<(f64, f64)> {
        // The elevation of the ball's path in the bat's vertical plane,
        // signed past ±90° for a ball going back: it rises with E through
        // every forward launch, and is the launch angle for a ball going
        // forward.
        let forward = model::frame::horizontal(self.direction_at(direction));
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
    pub(super) fn bracket(
        &self,
        g: impl Fn(f64) -> f64,
        start: f64,
    ) -> Option<((f64, f64), (f64, f64))> {
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
    pub(super) fn swing_angle_start(&self, direction: f64) -> Result<[f64; 3], Unreached> {
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
    pub(super) fn contact_speed_guess(&self, direction: f64) -> Option<(f64, f64)> {
        let (sweet, pitch) = (self.scene.bat.speed, self.scene.pitch.speed);
        let (_, exit) = self.undercut_for_angle(sweet, direction, None)?;
        let q = collision_efficiency(exit, pitch, sweet);
        let v = (self.target[0] - q * pitch) / (1.0 + q);
        let (e, _) = self.undercut_for_angle(v, direction, None)?;
        Some((e, v))
    }

    /// E and V̂_B0 at the measured ψ: the exit speed rises with the bat's.
    pub(super) fn contact_speed_start(&self, direction: f64) -> Result<[f64; 3], Unreached> {
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
    pub(super) fn aim(&self, start: [f64; 3]) -> Result<[f64; 3], Unreached> {
        if !self.aimed() {
            return Err(Unreached::NoConvergence);
        }
        let at = |direction: f64| match self.second {
            Second::SwingAngle => self.swing_angle_start(direction),
            Second::ContactSpeed => self.contact_speed_start(direction),
        };
        let miss = |x: [f64; 3]| self.impact(x).launch_direction() - self.target[2];
        let (mut last, mut last_miss) = (start, miss(start));
        let mut x = at(start[2] - last_miss / self.turn_per_unknown())?;
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
    pub(super) fn residual(&self, x: [f64; 3]) -> Vector3<f64> {
        let impact = self.impact(x);
        let direction = if self.aimed() {
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

    pub(super) fn converged(&self, r: &Vector3<f64>) -> bool {
        r.x.abs() < SPEED_TOLERANCE && r.y.abs() < ANGLE_TOLERANCE && r.z.abs() < ANGLE_TOLERANCE
    }

    /// Newton's method on the unknowns with a forward-difference Jacobian
    /// (the direction fixed, its row and column the identity, when it is
    /// no unknown), halving a step that does not reduce the residual.
    pub(super) fn newton(&self, start: [f64; 3]) -> Option<[f64; 3]> {
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
            let unknowns = if self.aimed() { 3 } else { 2 };
            for j in 0..unknowns {
                let mut moved = x;
                moved[j] += STEPS[j];
                let column = (self.residual(moved) - r) / STEPS[j];
                jacobian.set_column(j, &column);
            }
            if !self.aimed() {
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
    pub(super) fn within_bounds(&self, x: [f64; 3]) -> bool {
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
