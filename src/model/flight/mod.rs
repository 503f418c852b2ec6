//! The batted ball's flight: Eq. (25)–(29), integrated to the landing, with
//! the drag and lift of [`super::aero`]'s models and, if the scene gives it a
//! decay time, a spin that decays as ω₀·e^(−t/τ).

mod events;

use std::cell::Cell;

use nalgebra::Vector2;
use serde::Serialize;

use super::aero::{DragCurve, DragModel, LiftCurve, LiftModel};
use super::scene::Scene;
use crate::numerics::ode::{self, DenseStep, Outcome, Settings, State, Stats, Tolerance};
use events::Events;

/// The flight's state is (x, y, v_x, v_y): these name its components.
const DISTANCE: usize = 0;
const HEIGHT: usize = 1;
const VELOCITY_X: usize = 2;
const VERTICAL_VELOCITY: usize = 3;

/// The velocity part of a state (or of its derivative, the acceleration).
#[inline]
fn velocity(state: &State<4>) -> Vector2<f64> {
    Vector2::new(state[VELOCITY_X], state[VERTICAL_VELOCITY])
}

/// No flight is followed past this (s): far beyond any hit, but a bound, so
/// that no input (a ball held up by lift) can run forever.
pub const MAX_FLIGHT_TIME: f64 = 600.0;

/// A flight is followed for at most this many times the longest it could
/// stay up in a vacuum (launched straight up at its speed): drag only
/// shortens a flight, and lift that keeps a ball up ten times longer makes
/// it hover or loop, which is no batted ball. Bounds the work by the scene's
/// own time scale rather than by [`MAX_FLIGHT_TIME`] alone.
const VACUUM_TIMES: f64 = 10.0;

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
    /// r_b·|ω|, the surface speed from the launch spin, and the spin's sign.
    pub surface_speed: f64,
    pub spin_sign: f64,
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
            spin_sign: if spin > 0.0 {
                1.0
            } else if spin < 0.0 {
                -1.0
            } else {
                0.0
            },
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

    /// Whether the spin changes during the flight.
    #[inline]
    pub fn spin_decays(&self) -> bool {
        self.spin_decay_rate != 0.0
    }

    /// The spin at time `t` after launch: ω(t) = ω₀·e^(−t/τ), or ω₀ without
    /// decay (then no exponential is taken).
    #[inline]
    pub fn spin_at(&self, t: f64) -> SpinNow {
        let launch = SpinNow {
            rate: self.spin.abs(),
            surface_speed: self.surface_speed,
        };
        if !self.spin_decays() {
            return launch;
        }
        let remaining = (-t * self.spin_decay_rate).exp();
        SpinNow {
            rate: launch.rate * remaining,
            surface_speed: launch.surface_speed * remaining,
        }
    }

    /// C_D at time `t` and `velocity`, on the piece of the drag curve its
    /// Reynolds number lies on.
    pub fn drag_coefficient_at(&self, t: f64, velocity: Vector2<f64>) -> f64 {
        let re = self.reynolds(velocity);
        self.drag
            .coefficient_on(self.drag.piece(re), re, self.spin_at(t).rate)
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
        self.acceleration_on(velocity, None)
    }

    /// As [`Flight::acceleration`], with C_D taken from the given piece of
    /// the drag curve (continued past its ends) instead of the piece the
    /// Reynolds number lies on.
    #[inline]
    pub fn acceleration_on(&self, velocity: Vector2<f64>, piece: Option<usize>) -> Vector2<f64> {
        self.acceleration_at(0.0, velocity, piece)
    }

    /// As [`Flight::acceleration_on`], at time `t` after launch (which
    /// matters only when the spin decays).
    #[inline]
    pub fn acceleration_at(
        &self,
        t: f64,
        velocity: Vector2<f64>,
        piece: Option<usize>,
    ) -> Vector2<f64> {
        let spin = self.spin_at(t);
        let rel = self.relative_wind(velocity);
        let air_speed = rel.norm();
        let re = air_speed * self.reynolds_per_speed;
        let piece = piece.unwrap_or_else(|| self.drag.piece(re));
        let drag_coefficient = self.drag.coefficient_on(piece, re, spin.rate);
        // ẑ × V_b-direction, scaled by |V_r|: (V_r,y, −V_r,x).
        let lift_direction = Vector2::new(rel.y, -rel.x);
        let lift = self.spin_sign
            * self
                .lift
                .coefficient_times_speed(air_speed, spin.surface_speed);
        let aero =
            (rel * (drag_coefficient * air_speed) + lift_direction * lift) * self.force_per_mass;
        Vector2::new(aero.x, aero.y - self.gravity)
    }

    /// d/dt of the state (x, y, v_x, v_y) at the launch spin.
    #[inline]
    pub fn derivative(&self, state: &State<4>) -> State<4> {
        self.derivative_at(0.0, state, None)
    }

    /// d/dt of the state at time `t`, on a given piece of the drag curve
    /// (or the one its Reynolds number lies on).
    #[inline]
    pub fn derivative_at(&self, t: f64, state: &State<4>, piece: Option<usize>) -> State<4> {
        let a = self.acceleration_at(t, velocity(state), piece);
        State::<4>::new(state[VELOCITY_X], state[VERTICAL_VELOCITY], a.x, a.y)
    }

    /// The piece of the drag curve the ball is on at launch, or about to
    /// enter: at a kink, the one the Reynolds number is moving into.
    pub fn drag_piece(&self, state: &State<4>) -> usize {
        let velocity = velocity(state);
        let rel = self.relative_wind(velocity);
        let re = rel.norm() * self.reynolds_per_speed;
        // d|V_r|/dt = V_r·(−a)/|V_r|: only its sign matters.
        let rising = -rel.dot(&self.acceleration(velocity)) >= 0.0;
        let kinks = self.drag.kinks();
        if rising {
            kinks.iter().filter(|&&k| re >= k).count()
        } else {
            kinks.iter().filter(|&&k| re > k).count()
        }
    }
}

/// Where and how the flight starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Launch {
    pub position: Vector2<f64>,
    pub velocity: Vector2<f64>,
}

impl Launch {
    /// How long the flight is followed before it counts as not landing:
    /// [`VACUUM_TIMES`] the vacuum flight time of this speed straight up
    /// from this height, at least a second and at most [`MAX_FLIGHT_TIME`].
    pub fn time_limit(&self, gravity: f64) -> f64 {
        let speed = self.velocity.norm();
        let height = self.position.y.max(0.0);
        let vacuum = (speed + (speed * speed + 2.0 * gravity * height).sqrt()) / gravity;
        (VACUUM_TIMES * vacuum).clamp(1.0, MAX_FLIGHT_TIME)
    }

    fn state(&self) -> State<4> {
        State::<4>::new(
            self.position.x,
            self.position.y,
            self.velocity.x,
            self.velocity.y,
        )
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
    /// Horizontal distance from the contact point to the landing (m); negative
    /// for a ball that lands behind the plate.
    pub range: f64,
    pub flight_time: f64,
    /// Highest point above the ground (m), and its distance (m).
    pub apex: f64,
    pub apex_distance: f64,
    pub landing_speed: f64,
    /// Angle of the velocity below the horizontal at landing (rad).
    pub landing_angle: f64,
    /// False when the ball was still in the air at its time limit
    /// ([`Launch::time_limit`]) or the step limit; the other fields then
    /// describe the last point, and `range` is no range.
    pub landed: bool,
    pub stats: Stats,
}

/// Flies the ball to the ground (y = 0), locating the landing inside the step
/// with the continuous extension: never the last step's end.
pub fn fly(flight: &Flight, launch: &Launch, options: &FlightOptions) -> FlightSummary {
    fly_observed(flight, launch, options, |_| {})
}

/// As [`fly`], showing each accepted step (with its dense output) to `watch`,
/// e.g. to sample the trajectory.
pub fn fly_observed(
    flight: &Flight,
    launch: &Launch,
    options: &FlightOptions,
    watch: impl FnMut(&DenseStep<4>),
) -> FlightSummary {
    let stepper = Stepper::Adaptive(Settings::new(options.tolerance));
    fly_with(flight, launch, stepper, options.stop_at_kinks, watch)
}

/// As [`fly`], with the classical fixed-step Runge–Kutta method (step in s):
/// the benchmark's comparison for the adaptive default.
pub fn fly_fixed_step(
    flight: &Flight,
    launch: &Launch,
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

fn fly_with(
    flight: &Flight,
    launch: &Launch,
    stepper: Stepper,
    stop_at_kinks: bool,
    mut watch: impl FnMut(&DenseStep<4>),
) -> FlightSummary {
    let start = launch.state();
    let switching = stop_at_kinks && !flight.drag.kinks().is_empty();
    let piece = Cell::new(flight.drag_piece(&start));
    let mut events = Events::new(flight, &start, &piece, switching);
    let rhs = |t: f64, s: &State<4>| {
        let piece = if switching { Some(piece.get()) } else { None };
        flight.derivative_at(t, s, piece)
    };
    let observe = |step: &DenseStep<4>| events.observe(step, &mut watch);
    let time_limit = launch.time_limit(flight.gravity);
    let (outcome, stats) = match stepper {
        Stepper::Adaptive(settings) => {
            ode::integrate(rhs, 0.0, start, time_limit, &settings, observe)
        }
        Stepper::Fixed(step) => {
            ode::integrate_fixed(rhs, 0.0, start, time_limit, step, ode::MAX_STEPS, observe)
        }
    };
    let landed = outcome == Outcome::Stopped;
    let (time, state) = events.landing.unwrap_or(events.last);
    FlightSummary {
        range: state[DISTANCE] - launch.position.x,
        flight_time: time,
        apex: events.apex.0,
        apex_distance: events.apex.1 - launch.position.x,
        landing_speed: velocity(&state).norm(),
        landing_angle: (-state[VERTICAL_VELOCITY]).atan2(state[VELOCITY_X]),
        landed,
        stats,
    }
}

/// A point on a drawn trajectory.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TrajectoryPoint {
    pub time: f64,
    pub x: f64,
    pub y: f64,
    /// C_D at this point (Fig. 14).
    pub drag_coefficient: f64,
}

/// The flight sampled at `samples` equal time intervals from launch to
/// landing, read off the dense output (two passes: the first finds the flight
/// time, the second samples), so a drawing costs its resolution, not the
/// integrator's steps.
pub fn trajectory(
    flight: &Flight,
    launch: &Launch,
    options: &FlightOptions,
    samples: usize,
) -> (FlightSummary, Vec<TrajectoryPoint>) {
    let summary = fly(flight, launch, options);
    let samples = samples.max(2);
    let dt = summary.flight_time / (samples - 1) as f64;
    let mut points = Vec::with_capacity(samples);
    let mut push = |time: f64, s: State<4>| {
        points.push(TrajectoryPoint {
            time,
            x: s[DISTANCE],
            y: s[HEIGHT],
            drag_coefficient: flight.drag_coefficient_at(time, velocity(&s)),
        });
    };
    push(0.0, launch.state());
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
                state[HEIGHT] = 0.0; // the landing event defines y = 0 there
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
