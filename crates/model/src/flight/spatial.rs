//! The flight in three dimensions: the same forces as the plane's (Eq.
//! 25–29 and the aero models of [`crate::aero`]), with a spin vector
//! of any direction perpendicular to the launch (backspin and sidespin) and
//! a wind from any direction, blowing above a height. As in Nathan's
//! trajectory calculator, the spin keeps its direction in space during the
//! flight; its size decays as the plane's does. The frame and every sign
//! are [`crate::frame`]'s.

use nalgebra::Vector3;

use super::planar::scaled;
use super::{Dynamics, Regime, spin_now, time_limit};
use crate::aero::{DragCurve, DragModel, LiftCurve, LiftModel};
use crate::frame;
use crate::scene::Scene;
use numerics::ode::State;
use numerics::real::Real;

/// The state is (x, y, z, v_x, v_y, v_z): these name its components.
const X: usize = 0;
const HEIGHT: usize = 1;
const Z: usize = 2;
const VELOCITY_X: usize = 3;
const VERTICAL_VELOCITY: usize = 4;
const VELOCITY_Z: usize = 5;

#[inline]
fn velocity(state: &State<6>) -> Vector3<f64> {
    Vector3::new(
        state[VELOCITY_X],
        state[VERTICAL_VELOCITY],
        state[VELOCITY_Z],
    )
}

/// The forces on the ball in a 3-D flight, ready to evaluate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flight3d {
    pub gravity: f64,
    /// The wind's velocity above `wind_height` (m/s).
    pub wind: Vector3<f64>,
    /// Below this height (m) the air is still; at or below 0 the wind
    /// blows everywhere the ball goes.
    pub wind_height: f64,
    pub drag: DragModel,
    pub lift: LiftModel,
    /// ρA/(2M_b) (Eq. 26, 28).
    pub force_per_mass: f64,
    /// 2r_b/ν (Eq. 27).
    pub reynolds_per_speed: f64,
    /// ω̂, the spin's direction (zero without spin), fixed in space, times
    /// `model.lift_scale` (folded in: at 1 every bit is as it was).
    pub spin_axis: Vector3<f64>,
    /// `model.drag_scale`, on C_D (see `planar::scaled`).
    pub drag_scale: f64,
    /// |ω| at launch (rad/s), and r_b·|ω| (m/s).
    pub spin_rate: f64,
    pub surface_speed: f64,
    /// 1/τ (1/s); 0 for constant spin.
    pub spin_decay_rate: f64,
}

/// What the 3-D forces hold fixed over a flight ([`Flight3d`]'s
/// numbers), for one flight (`f64`) or four in lock-step (`f64x4`).
#[derive(Clone, Copy, Debug)]
pub struct SpatialConstants<R> {
    pub gravity: R,
    /// The wind's velocity in its layer.
    pub wind: [R; 3],
    pub force_per_mass: R,
    pub reynolds_per_speed: R,
    /// ω̂ times `model.lift_scale`.
    pub spin_axis: [R; 3],
    pub drag_scale: R,
    /// |ω₀|, r_b·|ω₀| and 1/τ.
    pub spin_rate: R,
    pub surface_speed: R,
    pub spin_decay_rate: R,
}

impl<R: Real> SpatialConstants<R> {
    /// V_r = V_w − V_b (Eq. 25), the wind blowing only `in_wind`; |V_r|;
    /// and Re = 2|V_r|r_b/ν (Eq. 27).
    #[inline(always)]
    pub fn air(&self, in_wind: R::Mask, [vx, vy, vz]: [R; 3]) -> ([R; 3], R, R) {
        let zero = R::splat(0.0);
        // Written out, not `map`: the lanes' closure was left uninlined.
        let [wx, wy, wz] = self.wind;
        let rel = [
            R::select(in_wind, wx, zero) - vx,
            R::select(in_wind, wy, zero) - vy,
            R::select(in_wind, wz, zero) - vz,
        ];
        let air_speed = (rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2]).sqrt();
        (rel, air_speed, air_speed * self.reynolds_per_speed)
    }

    /// The ball's acceleration at time `t` and `velocity`, in the wind or
    /// not (`in_wind`): see [`Flight3d::acceleration_at`]; C_D is
    /// `drag(Re, |ω|)`.
    #[inline(always)]
    pub fn acceleration(
        &self,
        drag: impl Fn(R, R) -> R,
        lift: &impl LiftCurve,
        (t, in_wind): (R, R::Mask),
        [vx, vy, vz]: [R; 3],
    ) -> [R; 3] {
        let (spin_rate, surface_speed) = spin_now(
            (self.spin_rate, self.surface_speed),
            self.spin_decay_rate,
            t,
        );
        let (rel, air_speed, re) = self.air(in_wind, [vx, vy, vz]);
        // As in the plane: ρA/(2M_b)·|V_r| ready while C_D is computed.
        let per_coefficient = scaled(air_speed * self.force_per_mass, self.drag_scale);
        let along = drag(re, spin_rate) * per_coefficient;
        // ω̂ × (V_b − V_w) = ω̂ × (−V_r) = V_r × ω̂, scaled by |V_r|.
        let a = self.spin_axis;
        let lift_direction = [
            rel[1] * a[2] - rel[2] * a[1],
            rel[2] * a[0] - rel[0] * a[2],
            rel[0] * a[1] - rel[1] * a[0],
        ];
        let lift = lift.coefficient_times_speed(air_speed, surface_speed) * self.force_per_mass;
        [
            rel[0] * along + lift_direction[0] * lift,
            rel[1] * along + lift_direction[1] * lift - self.gravity,
            rel[2] * along + lift_direction[2] * lift,
        ]
    }
}

impl Flight3d {
    /// The flight of a ball with spin vector `spin` (rad/s) in `scene`'s
    /// air, ball and wind.
    pub fn new(scene: &Scene, spin: Vector3<f64>) -> Flight3d {
        // One flight's constants, the plane's (so that a 3-D flight in the
        // plane sees the very same numbers).
        let planar = super::Flight::new(scene, 0.0);
        let env = scene.environment;
        let spin_rate = spin.norm();
        Flight3d {
            gravity: planar.gravity,
            wind: frame::wind_velocity(env.wind, env.wind_direction),
            wind_height: env.wind_height,
            drag: planar.drag,
            lift: planar.lift,
            force_per_mass: planar.force_per_mass,
            reynolds_per_speed: planar.reynolds_per_speed,
            spin_axis: if spin_rate > 0.0 {
                spin / spin_rate * scene.lift_scale
            } else {
                Vector3::zeros()
            },
            drag_scale: scene.drag_scale,
            spin_rate,
            surface_speed: scene.ball.radius * spin_rate,
            spin_decay_rate: planar.spin_decay_rate,
        }
    }

    /// The wind where the ball is, in `regime`'s layer.
    #[inline]
    fn wind_in(&self, in_wind: bool) -> Vector3<f64> {
        if in_wind { self.wind } else { Vector3::zeros() }
    }

    /// |ω(t)| and r_b·|ω(t)|, decayed as ω₀·e^(−t/τ) if a decay is set.
    #[inline]
    fn spin_at(&self, t: f64) -> (f64, f64) {
        spin_now(
            (self.spin_rate, self.surface_speed),
            self.spin_decay_rate,
            t,
        )
    }

    /// This flight's constants as the generic forces take them.
    #[inline(always)]
    pub fn constants(&self) -> SpatialConstants<f64> {
        SpatialConstants {
            gravity: self.gravity,
            wind: self.wind.into(),
            force_per_mass: self.force_per_mass,
            reynolds_per_speed: self.reynolds_per_speed,
            spin_axis: self.spin_axis.into(),
            drag_scale: self.drag_scale,
            spin_rate: self.spin_rate,
            surface_speed: self.surface_speed,
            spin_decay_rate: self.spin_decay_rate,
        }
    }

    /// The ball's acceleration at time `t` and `velocity`: gravity, drag
    /// along V_r = V_w − V_b (Eq. 25–26) and the Magnus lift along
    /// ω̂ × (V_b − V_w) with |lift| = ½ρA·C_L(S)·|V_r|²·|ω̂ × V̂_r| (Eq. 28–29,
    /// S = r_b|ω|/|V_r| from the whole spin). `piece` fixes the drag
    /// curve's piece, as in the plane.
    #[inline]
    pub fn acceleration_at(&self, t: f64, velocity: Vector3<f64>, regime: Regime) -> Vector3<f64> {
        self.acceleration_with((&self.drag, &self.lift), t, velocity, regime)
            .into()
    }

    /// As [`Flight3d::acceleration_at`], with the drag and lift models
    /// given as their own types (the integration's, compiled for each pair).
    #[inline(always)]
    pub fn acceleration_with(
        &self,
        (drag, lift): (&impl DragCurve, &impl LiftCurve),
        t: f64,
        velocity: Vector3<f64>,
        regime: Regime,
    ) -> [f64; 3] {
        self.constants().acceleration(
            // Inlined into the forces (see `planar::Flight::acceleration_with`).
            #[inline(always)]
            |re: f64, spin_rate: f64| {
                let piece = regime.piece.unwrap_or_else(|| drag.piece(re));
                drag.coefficient_on(piece, re, spin_rate)
            },
            lift,
            (t, regime.in_wind),
            velocity.into(),
        )
    }

    /// C_D at time `t` and `velocity`, in or out of the wind.
    pub fn drag_coefficient_at(&self, t: f64, velocity: Vector3<f64>, in_wind: bool) -> f64 {
        let re = (self.wind_in(in_wind) - velocity).norm() * self.reynolds_per_speed;
        let cd = self
            .drag
            .coefficient_on(self.drag.piece(re), re, self.spin_at(t).0);
        scaled(cd, self.drag_scale)
    }
}

impl Dynamics<6> for Flight3d {
    const HEIGHT: usize = HEIGHT;
    const VERTICAL_VELOCITY: usize = VERTICAL_VELOCITY;
    const VELOCITY_X: usize = VELOCITY_X;

    // Inlined into the integrator's stages, with the models' formulas.
    #[inline(always)]
    fn derivative_with(
        &self,
        models: (&impl DragCurve, &impl LiftCurve),
        t: f64,
        state: &State<6>,
        piece: Option<usize>,
        in_wind: bool,
    ) -> State<6> {
        let a = self.acceleration_with(models, t, velocity(state), Regime { piece, in_wind });
        State::<6>::new(
            state[VELOCITY_X],
            state[VERTICAL_VELOCITY],
            state[VELOCITY_Z],
            a[0],
            a[1],
            a[2],
        )
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
    fn air_speed_squared(&self, state: &State<6>, slope: &State<6>, in_wind: bool) -> (f64, f64) {
        let rel = self.wind_in(in_wind) - velocity(state);
        let acceleration = Vector3::new(
            slope[VELOCITY_X],
            slope[VERTICAL_VELOCITY],
            slope[VELOCITY_Z],
        );
        (rel.norm_squared(), -2.0 * rel.dot(&acceleration))
    }

    #[inline]
    fn reynolds(&self, state: &State<6>, in_wind: bool) -> f64 {
        (self.wind_in(in_wind) - velocity(state)).norm() * self.reynolds_per_speed
    }

    fn drag_piece_at(&self, state: &State<6>, in_wind: bool) -> usize {
        let rel = self.wind_in(in_wind) - velocity(state);
        let re = rel.norm() * self.reynolds_per_speed;
        let regime = Regime {
            piece: None,
            in_wind,
        };
        // d|V_r|/dt = V_r·(−a)/|V_r|: only its sign matters (as the plane's).
        let rising = || -rel.dot(&self.acceleration_at(0.0, velocity(state), regime)) >= 0.0;
        super::piece_entered(self.drag.kinks(), re, rising)
    }

    fn wind_height(&self) -> Option<f64> {
        (self.wind_height > 0.0 && self.wind != Vector3::zeros()).then_some(self.wind_height)
    }

    #[inline]
    fn distance(state: &State<6>, origin: &State<6>) -> f64 {
        let (x, z) = (state[X] - origin[X], state[Z] - origin[Z]);
        x.hypot(z)
    }

    #[inline]
    fn direction(state: &State<6>, origin: &State<6>) -> f64 {
        let (x, z) = (state[X] - origin[X], state[Z] - origin[Z]);
        frame::direction_of(x, z)
    }

    #[inline]
    fn velocity_parts(state: &State<6>) -> (f64, f64) {
        (
            state[VELOCITY_X].hypot(state[VELOCITY_Z]),
            state[VERTICAL_VELOCITY],
        )
    }

    fn point(state: &State<6>) -> [f64; 3] {
        [state[X], state[HEIGHT], state[Z]]
    }

    fn drag_coefficient(&self, t: f64, state: &State<6>) -> f64 {
        // In the wind at or above its height.
        let in_wind = state[HEIGHT] >= self.wind_height;
        self.drag_coefficient_at(t, velocity(state), in_wind)
    }
}

/// Where and how a 3-D flight starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Launch3d {
    pub position: Vector3<f64>,
    pub velocity: Vector3<f64>,
}

impl Launch3d {
    /// As [`super::Launch::time_limit`].
    pub fn time_limit(&self, gravity: f64) -> f64 {
        time_limit(self.velocity.norm(), self.position.y, gravity)
    }

    pub(super) fn state(&self) -> State<6> {
        State::<6>::new(
            self.position.x,
            self.position.y,
            self.position.z,
            self.velocity.x,
            self.velocity.y,
            self.velocity.z,
        )
    }
}
