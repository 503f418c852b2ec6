//! The planar flight: the paper's (Eq. 25–29), in the vertical plane of
//! the launch, with backspin only and the wind along the plane. The scene
//! flies it whenever nothing pushes the ball out of that plane (no
//! sidespin, no crosswind), because it is the cheaper of the two flights
//! and gives the paper's numbers bit for bit.

use nalgebra::Vector2;

use super::{Dynamics, spin_now, time_limit};
use crate::aero::{DragCurve, DragModel, LiftCurve, LiftModel};
use crate::scene::Scene;
use numerics::ode::State;
use numerics::real::Real;

/// The flight's state is (x, y, v_x, v_y): these name its components.
pub(super) const DISTANCE: usize = 0;
pub(super) const HEIGHT: usize = 1;
pub(super) const VELOCITY_X: usize = 2;
pub(super) const VERTICAL_VELOCITY: usize = 3;

/// The velocity part of a state (or of its derivative, the acceleration).
#[inline]
pub(super) fn velocity(state: &State<4>) -> Vector2<f64> {
    Vector2::new(state[VELOCITY_X], state[VERTICAL_VELOCITY])
}

/// A factor of the drag times `model.drag_scale`. At 1 the product is the
/// factor bit for bit; an unconditional multiplication costs fewer
/// instructions than a test for 1 (callgrind, 2000 planar `fly --batch`
/// rows: +0.9 % against +1.7 %).
#[inline(always)]
pub(super) fn scaled<R: Real>(coefficient: R, scale: R) -> R {
    coefficient * scale
}

/// What the planar forces hold fixed over a flight ([`Flight`]'s numbers),
/// for one flight (`f64`) or four in lock-step (`f64x4`).
#[derive(Clone, Copy, Debug)]
pub struct PlanarConstants<R> {
    pub gravity: R,
    pub wind: R,
    pub force_per_mass: R,
    pub reynolds_per_speed: R,
    /// r_b·|ω₀|, |ω₀| and 1/τ.
    pub surface_speed: R,
    pub spin_rate: R,
    pub spin_decay_rate: R,
    /// The spin's sign times `model.lift_scale`.
    pub spin_sign: R,
    pub drag_scale: R,
}

impl<R: Real> PlanarConstants<R> {
    /// V_r = V_w − V_b (Eq. 25), the wind being horizontal; |V_r|; and
    /// Re = 2|V_r|r_b/ν (Eq. 27), at velocity (v_x, v_y).
    #[inline(always)]
    pub fn air(&self, (vx, vy): (R, R)) -> ((R, R), R, R) {
        let (rel_x, rel_y) = (self.wind - vx, -vy);
        let air_speed = (rel_x * rel_x + rel_y * rel_y).sqrt();
        (
            (rel_x, rel_y),
            air_speed,
            air_speed * self.reynolds_per_speed,
        )
    }

    /// The ball's acceleration (a_x, a_y) at time `t` and velocity
    /// (v_x, v_y): gravity, drag along V_r (Eq. 25–27) and lift
    /// perpendicular to it (Eq. 28–29), C_D being `drag(Re, |ω|)` and C_L
    /// `lift`'s. See [`Flight::acceleration`] for the lift's sign.
    #[inline(always)]
    pub fn acceleration(
        &self,
        drag: impl Fn(R, R) -> R,
        lift: &impl LiftCurve,
        t: R,
        (vx, vy): (R, R),
    ) -> (R, R) {
        let (spin_rate, surface_speed) = spin_now(
            (self.spin_rate, self.surface_speed),
            self.spin_decay_rate,
            t,
        );
        let ((rel_x, rel_y), air_speed, re) = self.air((vx, vy));
        // ρA/(2M_b)·|V_r| (with `model.drag_scale` on C_D), ready while C_D
        // is computed, so that C_D waits on one product (see `scaled`).
        let per_coefficient = scaled(air_speed * self.force_per_mass, self.drag_scale);
        let along = drag(re, spin_rate) * per_coefficient;
        let lift = self.spin_sign
            * lift.coefficient_times_speed(air_speed, surface_speed)
            * self.force_per_mass;
        // Drag along V_r; lift along ẑ × V_b-direction, scaled by |V_r|:
        // (V_r,y, −V_r,x).
        let ax = rel_x * along + rel_y * lift;
        let ay = rel_y * along + -rel_x * lift;
        (ax, ay - self.gravity)
    }
}

/// The forces on the ball in flight, ready to evaluate. Which drag and lift
/// models they use is the models' business ([`DragCurve`], [`LiftCurve`]).
/// The spin is constant, as the paper assumes (it decays by a few per cent
/// over a flight), unless the scene gives it a decay time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flight {
    pub gravity: f64,
    pub wind: f64,
    pub drag: DragModel,
    pub lift: LiftModel,
    /// ρA/(2M_b): turns C·|V_r|·V_r into an acceleration (Eq. 26, 28).
    pub force_per_mass: f64,
    /// 2r_b/ν: turns |V_r| into Re (Eq. 27).
    pub reynolds_per_speed: f64,
    /// r_b·|ω|, the surface speed from the launch spin, and the spin's sign
    /// times `model.lift_scale` (a factor folded in here costs nothing, and
    /// at 1 leaves every bit as it was).
    pub surface_speed: f64,
    pub spin_sign: f64,
    /// `model.drag_scale`, on C_D (see `scaled`).
    pub drag_scale: f64,
    /// ω at launch (rad/s, backspin positive).
    pub spin: f64,
    /// 1/τ (1/s): the spin decays as ω(t) = ω₀·e^(−t/τ); 0 for constant spin.
    pub spin_decay_rate: f64,
}

/// The spin as the aerodynamic coefficients take it, at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpinNow {
    /// |ω| (rad/s).
    pub rate: f64,
    /// r_b·|ω| (m/s).
    pub surface_speed: f64,
}

impl Flight {
    pub fn new(scene: &Scene, spin: f64) -> Flight {
        let ball = scene.ball;
        let env = scene.environment;
        let area = std::f64::consts::PI * ball.radius * ball.radius;
        Flight {
            gravity: env.gravity,
            wind: env.wind,
            drag: scene.drag,
            lift: scene.lift,
            force_per_mass: env.air_density * area / (2.0 * ball.mass),
            reynolds_per_speed: 2.0 * ball.radius / env.kinematic_viscosity,
            surface_speed: ball.radius * spin.abs(),
            spin_sign: scene.lift_scale
                * if spin > 0.0 {
                    1.0
                } else if spin < 0.0 {
                    -1.0
                } else {
                    0.0
                },
            drag_scale: scene.drag_scale,
            spin,
            // A subnormal τ makes 1/τ infinite, and −t/τ NaN at t = 0:
            // capped, the spin is whole at launch and gone at any later
            // time, as e^(−t/τ) is for so small a τ.
            spin_decay_rate: if scene.spin_decay > 0.0 {
                (1.0 / scene.spin_decay).min(f64::MAX)
            } else {
                0.0
            },
        }
    }

    /// V_r = V_w − V_b (Eq. 25), the wind being horizontal.
    #[inline]
    pub fn relative_wind(&self, velocity: Vector2<f64>) -> Vector2<f64> {
        Vector2::new(self.wind - velocity.x, -velocity.y)
    }

    /// Re = 2|V_r|r_b/ν (Eq. 27).
    #[inline]
    pub fn reynolds(&self, velocity: Vector2<f64>) -> f64 {
        self.relative_wind(velocity).norm() * self.reynolds_per_speed
    }

    /// The spin at time `t` after launch: ω(t) = ω₀·e^(−t/τ), or ω₀ without
    /// decay (then no exponential is taken).
    #[inline]
    pub fn spin_at(&self, t: f64) -> SpinNow {
        let (rate, surface_speed) = spin_now(
            (self.spin.abs(), self.surface_speed),
            self.spin_decay_rate,
            t,
        );
        SpinNow {
            rate,
            surface_speed,
        }
    }

    /// This flight's constants as the generic forces take them.
    #[inline(always)]
    pub fn constants(&self) -> PlanarConstants<f64> {
        PlanarConstants {
            gravity: self.gravity,
            wind: self.wind,
            force_per_mass: self.force_per_mass,
            reynolds_per_speed: self.reynolds_per_speed,
            surface_speed: self.surface_speed,
            spin_rate: self.spin.abs(),
            spin_decay_rate: self.spin_decay_rate,
            spin_sign: self.spin_sign,
            drag_scale: self.drag_scale,
        }
    }

    /// C_D at time `t` and `velocity`, on the piece of the drag curve its
    /// Reynolds number lies on.
    pub fn drag_coefficient_at(&self, t: f64, velocity: Vector2<f64>) -> f64 {
        let re = self.reynolds(velocity);
        let cd = self
            .drag
            .coefficient_on(self.drag.piece(re), re, self.spin_at(t).rate);
        scaled(cd, self.drag_scale)
    }

    /// The ball's acceleration at the launch spin: gravity, drag along V_r
    /// (Eq. 26) and lift perpendicular to it (Eq. 28).
    ///
    /// Eq. (28) as printed, with the minus sign, points the lift of a backspun
    /// ball moving +x downward in this frame; the lift here is the Magnus
    /// force along ω × V_b, which is up for backspin (Fig. 4's positive C_L
    /// for batted backspin).
    #[inline]
    pub fn acceleration(&self, velocity: Vector2<f64>) -> Vector2<f64> {
        let a = self.acceleration_with((&self.drag, &self.lift), 0.0, velocity, None);
        Vector2::new(a.0, a.1)
    }

    /// As [`Flight::acceleration`], at time `t` after launch (which matters
    /// only when the spin decays), on the given piece of the drag curve
    /// (continued past its ends) or else the one the Reynolds number lies
    /// on, with the drag and lift models given as their own types (the
    /// integration's, compiled for each pair).
    #[inline(always)]
    pub fn acceleration_with(
        &self,
        (drag, lift): (&impl DragCurve, &impl LiftCurve),
        t: f64,
        velocity: Vector2<f64>,
        piece: Option<usize>,
    ) -> (f64, f64) {
        self.constants().acceleration(
            // Inlined, whatever the inliner's estimate: a C_D left out of
            // line (as it was once the exponential was written inline) costs
            // a call per evaluation, its result through memory.
            #[inline(always)]
            |re: f64, spin_rate: f64| {
                let piece = piece.unwrap_or_else(|| drag.piece(re));
                drag.coefficient_on(piece, re, spin_rate)
            },
            lift,
            t,
            (velocity.x, velocity.y),
        )
    }
}

/// Where and how the planar flight starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Launch {
    pub position: Vector2<f64>,
    pub velocity: Vector2<f64>,
}

impl Launch {
    /// How long the flight is followed before it counts as not landing:
    /// `VACUUM_TIMES` (10) the vacuum flight time of this speed straight up
    /// from this height, at least a second and at most
    /// [`MAX_FLIGHT_TIME`](super::MAX_FLIGHT_TIME).
    pub fn time_limit(&self, gravity: f64) -> f64 {
        time_limit(self.velocity.norm(), self.position.y, gravity)
    }

    pub(super) fn state(&self) -> State<4> {
        State::<4>::new(
            self.position.x,
            self.position.y,
            self.velocity.x,
            self.velocity.y,
        )
    }
}

impl Dynamics<4> for Flight {
    const HEIGHT: usize = HEIGHT;
    const VERTICAL_VELOCITY: usize = VERTICAL_VELOCITY;
    const VELOCITY_X: usize = VELOCITY_X;

    // Inlined into the integrator's stages, with the models' formulas.
    #[inline(always)]
    fn derivative_with(
        &self,
        models: (&impl DragCurve, &impl LiftCurve),
        t: f64,
        state: &State<4>,
        piece: Option<usize>,
        _in_wind: bool,
    ) -> State<4> {
        let (ax, ay) = self.acceleration_with(models, t, velocity(state), piece);
        State::<4>::new(state[VELOCITY_X], state[VERTICAL_VELOCITY], ax, ay)
    }

    #[inline]
    fn drag(&self) -> DragModel {
        self.drag
    }

    #[inline]
    fn lift(&self) -> LiftModel {
        self.lift
    }

    #[inline]
    fn gravity(&self) -> f64 {
        self.gravity
    }

    #[inline]
    fn reynolds_per_speed(&self) -> f64 {
        self.reynolds_per_speed
    }

    #[inline]
    fn air_speed_squared(&self, state: &State<4>, slope: &State<4>, _in_wind: bool) -> (f64, f64) {
        let rel = self.relative_wind(velocity(state));
        // d/dt |V_r|² = 2 V_r·dV_r/dt = −2 V_r·a.
        let rate = -2.0 * (rel.x * slope[VELOCITY_X] + rel.y * slope[VERTICAL_VELOCITY]);
        (rel.norm_squared(), rate)
    }

    #[inline]
    fn reynolds(&self, state: &State<4>, _in_wind: bool) -> f64 {
        Flight::reynolds(self, velocity(state))
    }

    fn drag_piece_at(&self, state: &State<4>, _in_wind: bool) -> usize {
        let velocity = velocity(state);
        let rel = self.relative_wind(velocity);
        let re = rel.norm() * self.reynolds_per_speed;
        // d|V_r|/dt = V_r·(−a)/|V_r|: only its sign matters.
        let rising = || -rel.dot(&self.acceleration(velocity)) >= 0.0;
        super::piece_entered(self.drag.kinks(), re, rising)
    }

    fn wind_height(&self) -> Option<f64> {
        None
    }

    #[inline]
    fn distance(state: &State<4>, origin: &State<4>) -> f64 {
        state[DISTANCE] - origin[DISTANCE]
    }

    #[inline]
    fn direction(_: &State<4>, _: &State<4>) -> f64 {
        0.0
    }

    #[inline]
    fn velocity_parts(state: &State<4>) -> (f64, f64) {
        (state[VELOCITY_X], state[VERTICAL_VELOCITY])
    }

    fn point(state: &State<4>) -> [f64; 3] {
        [state[DISTANCE], state[HEIGHT], 0.0]
    }

    fn drag_coefficient(&self, t: f64, state: &State<4>) -> f64 {
        self.drag_coefficient_at(t, velocity(state))
    }
}
