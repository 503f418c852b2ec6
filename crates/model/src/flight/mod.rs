//! The batted ball's flight: Eq. (25)–(29), integrated to the landing, with
//! the drag and lift of [`super::aero`]'s models and, if the scene gives it a
//! decay time, a spin that decays as ω₀·e^(−t/τ).
//!
//! Two flights share one integration ([`Dynamics`]): the planar one
//! ([`Flight`], the paper's, in the launch's vertical plane) and the 3-D
//! one ([`Flight3d`], with sidespin and a wind from any direction). A scene
//! flies the planar one whenever nothing leaves the plane
//! (`super::launch::SceneFlight`): it is cheaper and gives the paper's
//! numbers bit for bit.

mod events;
pub mod lanes;
mod planar;
mod spatial;

use std::cell::Cell;

use serde::Serialize;

use super::aero::{DragCurve, DragModel, LiftCurve, LiftModel, WithModels};
use events::Events;
use numerics::ode::{self, Outcome, Settings, State, Step, Tolerance};
use numerics::real::Real;
pub use planar::{Flight, Launch, PlanarConstants, SpinNow};
pub use spatial::{Flight3d, Launch3d, SpatialConstants};

/// No flight is followed past this (s): far beyond any hit, but a bound, so
/// that no input (a ball held up by lift) can run forever.
pub const MAX_FLIGHT_TIME: f64 = 600.0;

/// A flight is followed for at most this many times the longest it could
/// stay up in a vacuum (launched straight up at its speed): drag only
/// shortens a flight, and lift that keeps a ball up ten times longer makes
/// it hover or loop, which is no batted ball. Bounds the work by the scene's
/// own time scale rather than by [`MAX_FLIGHT_TIME`] alone.
const VACUUM_TIMES: f64 = 10.0;

/// How long a flight launched at `speed` (m/s) from `height` (m) is
/// followed before it counts as not landing: `VACUUM_TIMES` (10) the vacuum
/// flight time of that speed straight up from that height, at least a
/// second and at most [`MAX_FLIGHT_TIME`].
pub fn time_limit(speed: f64, height: f64, gravity: f64) -> f64 {
    let height = height.max(0.0);
    let vacuum = (speed + (speed * speed + 2.0 * gravity * height).sqrt()) / gravity;
    (VACUUM_TIMES * vacuum).clamp(1.0, MAX_FLIGHT_TIME)
}

/// What the right-hand side holds fixed during a step, switched between
/// steps by the events: the drag curve's piece (when the flight stops at
/// its kinks; `None` takes the piece Re lies on) and whether the ball is in
/// the wind's layer (always, unless the wind blows only above a height).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Regime {
    pub piece: Option<usize>,
    pub in_wind: bool,
}

/// The piece of a drag curve with `kinks` that a ball at Reynolds number
/// `re` is on, or about to enter: at a kink, the one Re is moving into
/// (`rising` says whether it moves up; asked only there).
pub(crate) fn piece_entered(kinks: &[f64], re: f64, rising: impl FnOnce() -> bool) -> usize {
    // The kinks below Re, and whether it sits on one, in one pass.
    let (mut below, mut on_kink) = (0, false);
    for &kink in kinks {
        below += usize::from(re > kink);
        on_kink |= re == kink;
    }
    // Which way Re moves (an acceleration, so an exponential on the drag
    // crisis) matters only on a kink itself: moving up, it enters the piece
    // above.
    if on_kink && rising() {
        below + 1
    } else {
        below
    }
}

/// The spin at time `t` after launch, (|ω|, r_b|ω|) from their launch
/// values: ω(t) = ω₀·e^(−t/τ), `decay_rate` being 1/τ; without decay (in
/// every lane) no exponential is taken.
#[inline(always)]
pub(crate) fn spin_now<R: Real>((rate, surface_speed): (R, R), decay_rate: R, t: R) -> (R, R) {
    if !R::any(!R::eq(decay_rate, R::splat(0.0))) {
        return (rate, surface_speed);
    }
    let remaining = (-t * decay_rate).exp();
    (rate * remaining, surface_speed * remaining)
}

/// What the integration needs of a flight whose state has `N` components:
/// positions then velocities, the height at [`Dynamics::HEIGHT`].
pub trait Dynamics<const N: usize>: Copy {
    const HEIGHT: usize;
    const VERTICAL_VELOCITY: usize;
    /// The velocity's first component: the velocity's run from it to the
    /// state's end.
    const VELOCITY_X: usize;

    /// d/dt of the state at time `t` in the regime of drag piece `piece`
    /// and wind layer `in_wind` (a [`Regime`]'s fields, passed apart so
    /// that they travel in registers: the call is the hot path), with the
    /// flight's drag and lift models given as their own types.
    fn derivative_with(
        &self,
        models: (&impl DragCurve, &impl LiftCurve),
        t: f64,
        state: &State<N>,
        piece: Option<usize>,
        in_wind: bool,
    ) -> State<N>;
    fn drag(&self) -> DragModel;
    fn lift(&self) -> LiftModel;
    fn gravity(&self) -> f64;
    /// 2r_b/ν: turns |V_r| into Re.
    fn reynolds_per_speed(&self) -> f64;
    /// |V_r|² and its rate of change, from a state and its slope.
    fn air_speed_squared(&self, state: &State<N>, slope: &State<N>, in_wind: bool) -> (f64, f64);
    fn reynolds(&self, state: &State<N>, in_wind: bool) -> f64;
    /// The drag piece at `state`, or the one it is about to enter.
    fn drag_piece_at(&self, state: &State<N>, in_wind: bool) -> usize;
    /// The height the wind blows above, if the flight has such a layer.
    fn wind_height(&self) -> Option<f64>;
    /// The horizontal distance and direction (rad) of `state` from `origin`.
    /// The plane's distance is signed (negative behind the plate) and its
    /// direction that of its plane, 0 here.
    fn ground(state: &State<N>, origin: &State<N>) -> (f64, f64) {
        (
            Self::distance(state, origin),
            Self::direction(state, origin),
        )
    }
    /// [`Dynamics::ground`]'s distance alone.
    fn distance(state: &State<N>, origin: &State<N>) -> f64;
    /// [`Dynamics::ground`]'s direction alone.
    fn direction(state: &State<N>, origin: &State<N>) -> f64;
    /// The horizontal (signed in the plane) and vertical velocity.
    fn velocity_parts(state: &State<N>) -> (f64, f64);
    /// (x, y, z) of `state`.
    fn point(state: &State<N>) -> [f64; 3];
    /// C_D at `state` (for drawing Fig. 14).
    fn drag_coefficient(&self, t: f64, state: &State<N>) -> f64;

    /// The regime a flight from `start` begins in: on the drag piece it is
    /// on (or about to enter) if it switches at the kinks, and in the wind
    /// if it starts in its layer.
    fn starting_regime(&self, start: &State<N>, stop_at_kinks: bool) -> Regime {
        let switching = stop_at_kinks && !self.drag().kinks().is_empty();
        let in_wind = self
            .wind_height()
            .is_none_or(|height| start[Self::HEIGHT] >= height);
        Regime {
            piece: switching.then(|| self.drag_piece_at(start, in_wind)),
            in_wind,
        }
    }
}

/// Where a flight starts: its state and how long it is followed.
pub trait Start<const N: usize> {
    fn state(&self) -> State<N>;
    fn time_limit(&self, gravity: f64) -> f64;
}

impl Start<4> for Launch {
    fn state(&self) -> State<4> {
        Launch::state(self)
    }
    fn time_limit(&self, gravity: f64) -> f64 {
        Launch::time_limit(self, gravity)
    }
}

impl Start<6> for Launch3d {
    fn state(&self) -> State<6> {
        Launch3d::state(self)
    }
    fn time_limit(&self, gravity: f64) -> f64 {
        Launch3d::time_limit(self, gravity)
    }
}

/// How accurately to fly.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FlightOptions {
    pub tolerance: Tolerance,
    /// End steps exactly on the drag curve's kinks, so that no step
    /// integrates across a jump in dC_D/dRe: each step keeps the C_D formula
    /// of the piece it started on, and where Re crosses a kink the flight
    /// ends the step there (read off the continuous extension) and goes on
    /// with the next piece's formula. Costs one evaluation per crossing and
    /// saves the rejected steps a corner would cause.
    pub stop_at_kinks: bool,
}

/// The outcome of one flight.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FlightSummary {
    /// Horizontal distance from the contact point to the landing (m). In a
    /// planar flight it is signed along the plane: negative for a ball that
    /// lands behind the plate.
    pub range: f64,
    /// Direction of the landing point from the contact point (rad from the
    /// centre-field line, positive toward right field).
    pub direction: f64,
    pub flight_time: f64,
    /// Highest point above the ground (m), and its horizontal distance from
    /// the contact point (m).
    pub apex: f64,
    pub apex_distance: f64,
    pub landing_speed: f64,
    /// Angle of the velocity below the horizontal at landing (rad).
    pub landing_angle: f64,
    /// False when the ball was still in the air at its time limit
    /// ([`Launch::time_limit`]) or the step limit; the other fields then
    /// describe the last point, and `range` is no range.
    pub landed: bool,
    pub stats: ode::Stats,
}

impl FlightSummary {
    /// What of it a range needs.
    pub fn range_summary(&self) -> RangeSummary {
        RangeSummary {
            range: self.range,
            flight_time: self.flight_time,
            landed: self.landed,
            stats: self.stats,
        }
    }
}

/// The part of a flight's outcome that a range needs (a surface's cell, a
/// sensitivity): flights asked for it alone locate no apex, and work out
/// no landing speed, angle or direction. Each field is bit for bit the
/// [`FlightSummary`]'s of the same flight.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RangeSummary {
    /// As [`FlightSummary::range`].
    pub range: f64,
    pub flight_time: f64,
    /// As [`FlightSummary::landed`]: when false, `range` is no range.
    pub landed: bool,
    pub stats: ode::Stats,
}

/// Flies the ball to the ground (y = 0), locating the landing inside the step
/// with the continuous extension: never the last step's end.
pub fn fly<const N: usize, D: Dynamics<N>, S: Start<N>>(
    flight: &D,
    launch: &S,
    options: &FlightOptions,
) -> FlightSummary {
    fly_observed(flight, launch, options, |_| {})
}

/// As [`fly`], showing each accepted step (with its dense output) to `watch`,
/// e.g. to sample the trajectory.
pub fn fly_observed<const N: usize, D: Dynamics<N>, S: Start<N>>(
    flight: &D,
    launch: &S,
    options: &FlightOptions,
    watch: impl FnMut(&Step<N>),
) -> FlightSummary {
    let stepper = Stepper::Adaptive(Settings::new(options.tolerance));
    fly_with(flight, launch, stepper, options.stop_at_kinks, watch)
}

/// As [`fly`], with the classical fixed-step Runge–Kutta method (step in s):
/// the benchmark's comparison for the adaptive default.
pub fn fly_fixed_step<const N: usize, D: Dynamics<N>, S: Start<N>>(
    flight: &D,
    launch: &S,
    step: f64,
    stop_at_kinks: bool,
) -> FlightSummary {
    fly_with(flight, launch, Stepper::Fixed(step), stop_at_kinks, |_| {})
}

/// Which integrator carries the flight.
enum Stepper {
    Adaptive(Settings),
    Fixed(f64),
}

/// One flight's integration, before its models are known as types.
struct Flying<'a, const N: usize, D, S, W> {
    flight: &'a D,
    launch: &'a S,
    stepper: Stepper,
    stop_at_kinks: bool,
    watch: W,
}

/// Asks the flight's models once, and flies with them as types.
fn fly_with<const N: usize, D: Dynamics<N>, S: Start<N>>(
    flight: &D,
    launch: &S,
    stepper: Stepper,
    stop_at_kinks: bool,
    watch: impl FnMut(&Step<N>),
) -> FlightSummary {
    let flying = Flying {
        flight,
        launch,
        stepper,
        stop_at_kinks,
        watch,
    };
    flight.drag().with_lift(flight.lift(), flying)
}

impl<const N: usize, D: Dynamics<N>, S: Start<N>, W: FnMut(&Step<N>)> WithModels
    for Flying<'_, N, D, S, W>
{
    type Output = FlightSummary;

    fn run<Dr: DragCurve + Copy, L: LiftCurve + Copy>(self, drag: Dr, lift: L) -> FlightSummary {
        let Flying {
            flight,
            launch,
            stepper,
            stop_at_kinks,
            mut watch,
        } = self;
        let start = launch.state();
        let mut events = Events::new(*flight, &start, (stop_at_kinks, true));
        // The regime the right-hand side reads during a step, which the
        // observer changes between steps.
        let regime = Cell::new(events.regime());
        // Inlined into the integrator's loop, whatever the inliner's
        // estimate of the models' formulas.
        let rhs = inlined(
            #[inline(always)]
            |t: f64, s: &State<N>| {
                let Regime { piece, in_wind } = regime.get();
                flight.derivative_with((&drag, &lift), t, s, piece, in_wind)
            },
        );
        let observe = inlined(
            #[inline(always)]
            |step: &Step<N>| {
                let control = events.observe(step, &mut watch);
                regime.set(events.regime());
                control
            },
        );
        let time_limit = launch.time_limit(flight.gravity());
        let (outcome, stats) = match stepper {
            Stepper::Adaptive(settings) => {
                ode::integrate(rhs, 0.0, start, time_limit, &settings, observe)
            }
            Stepper::Fixed(step) => {
                ode::integrate_fixed(rhs, 0.0, start, time_limit, step, ode::MAX_STEPS, observe)
            }
        };
        events.summary(outcome == Outcome::Stopped, stats)
    }
}

/// `f` itself: a place where a closure may carry an attribute (stable Rust
/// takes `#[inline(always)]` on a closure given as an argument, not on one
/// bound by `let`).
#[inline(always)]
fn inlined<F>(f: F) -> F {
    f
}

/// A point on a drawn trajectory.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TrajectoryPoint {
    pub time: f64,
    /// Toward centre field, up, and toward right field (m).
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// Horizontal distance from the contact point (m), signed along the
    /// plane in a planar flight: what a side view plots height against.
    pub distance: f64,
    /// C_D at this point (Fig. 14).
    pub drag_coefficient: f64,
}

/// The flight sampled at `samples` equal time intervals from launch to
/// landing, read off the dense output (two passes: the first finds the flight
/// time, the second samples), so a drawing costs its resolution, not the
/// integrator's steps.
pub fn trajectory<const N: usize, D: Dynamics<N>, S: Start<N>>(
    flight: &D,
    launch: &S,
    options: &FlightOptions,
    samples: usize,
) -> (FlightSummary, Vec<TrajectoryPoint>) {
    let summary = fly(flight, launch, options);
    let samples = samples.max(2);
    let dt = summary.flight_time / (samples - 1) as f64;
    let mut points = Vec::with_capacity(samples);
    let start = launch.state();
    let mut push = |time: f64, s: State<N>| {
        let [x, y, z] = D::point(&s);
        points.push(TrajectoryPoint {
            time,
            x,
            y,
            z,
            distance: D::ground(&s, &start).0,
            drag_coefficient: flight.drag_coefficient(time, &s),
        });
    };
    push(0.0, start);
    let mut next = 1;
    // The same steps as the first pass, so the landing time lies in the last.
    fly_observed(flight, launch, options, |step| {
        while next < samples {
            let t = if next == samples - 1 {
                summary.flight_time
            } else {
                next as f64 * dt
            };
            if t > step.t1 {
                break;
            }
            let mut state = step.at(t);
            if next == samples - 1 && summary.landed {
                state[D::HEIGHT] = 0.0; // the landing event defines y = 0 there
            }
            push(t, state);
            next += 1;
        }
    });
    (summary, points)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;
    use nalgebra::Vector2;

    #[test]
    fn the_piece_entered_at_a_kink_is_the_one_re_moves_into() {
        let kinks = [1.0e5, 1.5e5, 2.0e5];
        // Off a kink the direction is not asked (it costs an acceleration).
        let unasked = || -> bool { panic!("asked which way Re moves off a kink") };
        assert_eq!(piece_entered(&kinks, 0.5e5, unasked), 0);
        assert_eq!(piece_entered(&kinks, 1.2e5, unasked), 1);
        assert_eq!(piece_entered(&kinks, 2.5e5, unasked), 3);
        // On one, the piece above if Re rises, below if it falls.
        assert_eq!(piece_entered(&kinks, 1.5e5, || true), 2);
        assert_eq!(piece_entered(&kinks, 1.5e5, || false), 1);
    }

    #[test]
    fn the_time_limit_is_ten_vacuum_flights_straight_up() {
        // 45 m/s from 1 m at g = 9.81: (45 + √(45² + 2·9.81·1))/9.81 = 9.196 s.
        let launch = Launch {
            position: Vector2::new(0.0, 1.0),
            velocity: Vector2::new(36.0, 27.0),
        };
        let vacuum = (45.0 + (45.0f64.powi(2) + 2.0 * 9.81).sqrt()) / 9.81;
        assert!((launch.time_limit(9.81) - 10.0 * vacuum).abs() < 1e-12);
        // Never past MAX_FLIGHT_TIME, never under a second.
        assert_eq!(launch.time_limit(1e-6), MAX_FLIGHT_TIME);
        let resting = Launch {
            position: Vector2::new(0.0, 0.0),
            velocity: Vector2::new(0.0, 0.0),
        };
        assert_eq!(resting.time_limit(9.81), 1.0);
    }

    #[test]
    fn a_hovering_ball_is_not_landed_and_stops_at_its_limit() {
        // At a thousandth of Earth's gravity a fastball climbs for minutes.
        let mut scene = Scene::default();
        scene.environment.gravity = 1e-3;
        let launch = Launch {
            position: Vector2::new(0.0, 1.0),
            velocity: Vector2::new(40.0, 20.0),
        };
        let flight = Flight::new(&scene, 200.0);
        let options = FlightOptions {
            tolerance: Tolerance::uniform(1e-8),
            stop_at_kinks: true,
        };
        let summary = fly(&flight, &launch, &options);
        assert!(!summary.landed);
        assert_eq!(summary.flight_time, launch.time_limit(1e-3));
    }
}
