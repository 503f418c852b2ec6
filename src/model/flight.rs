//! The batted ball's flight: Eq. (25)–(29), integrated to the landing.

use std::cell::Cell;

use nalgebra::Vector2;
use serde::Serialize;

use super::aero::{DragModel, lift_coefficient_times_speed};
use super::scene::Scene;
use crate::solve::ode::{self, Control, DenseStep, Outcome, Settings, State, Stats, Tolerance};

/// No flight is followed past this (s): far beyond any hit, but a bound, so
/// that no input (a ball held up by lift) can run forever.
pub const MAX_FLIGHT_TIME: f64 = 600.0;

/// The forces on the ball in flight, ready to evaluate (constant spin, as the
/// paper assumes: spin decays by a few per cent over a flight).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flight {
    pub gravity: f64,
    pub wind: f64,
    pub drag: DragModel,
    /// ρA/(2M_b): turns C·|V_r|·V_r into an acceleration (Eq. 26, 28).
    pub force_per_mass: f64,
    /// 2r_b/ν: turns |V_r| into Re (Eq. 27).
    pub reynolds_per_speed: f64,
    /// r_b·|ω|, the surface speed from spin, and the spin's sign.
    pub surface_speed: f64,
    pub spin_sign: f64,
    pub spin: f64,
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

    /// The ball's acceleration: gravity, drag along V_r (Eq. 26) and lift
    /// perpendicular to it (Eq. 28).
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
        let rel = self.relative_wind(velocity);
        let air_speed = rel.norm();
        let re = air_speed * self.reynolds_per_speed;
        let drag_coefficient = match piece {
            Some(piece) => self.drag.drag_coefficient_on(piece, re),
            None => self.drag.drag_coefficient(re),
        };
        // ẑ × V_b-direction, scaled by |V_r|: (V_r,y, −V_r,x).
        let lift_direction = Vector2::new(rel.y, -rel.x);
        let lift = self.spin_sign * lift_coefficient_times_speed(air_speed, self.surface_speed);
        let aero =
            (rel * (drag_coefficient * air_speed) + lift_direction * lift) * self.force_per_mass;
        Vector2::new(aero.x, aero.y - self.gravity)
    }

    /// d/dt of the state (x, y, v_x, v_y).
    #[inline]
    pub fn derivative(&self, state: &State<4>) -> State<4> {
        self.derivative_on(state, None)
    }

    /// d/dt of the state on a given piece of the drag curve.
    #[inline]
    pub fn derivative_on(&self, state: &State<4>, piece: Option<usize>) -> State<4> {
        let a = self.acceleration_on(Vector2::new(state[2], state[3]), piece);
        State::<4>::new(state[2], state[3], a.x, a.y)
    }

    /// The piece of the drag curve the ball is on at `state`, or about to
    /// enter: at a kink, the one the Reynolds number is moving into.
    pub fn drag_piece(&self, state: &State<4>) -> usize {
        let velocity = Vector2::new(state[2], state[3]);
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
    /// False when the ball was still in the air after [`MAX_FLIGHT_TIME`]
    /// (or the step limit); the other fields then describe the last point.
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
    let mut apex = (launch.position.y, launch.position.x);
    let mut landing: Option<(f64, State<4>)> = None;
    let mut last = (0.0, start);
    let root_tolerance = 1e-13;
    let kinks = flight.drag.kinks();
    let switching = stop_at_kinks && !kinks.is_empty();
    // The drag piece the current step uses (when switching).
    let piece = Cell::new(flight.drag_piece(&start));
    let last_switch = Cell::new(f64::NEG_INFINITY);
    let reynolds = |s: &State<4>| flight.reynolds(Vector2::new(s[2], s[3]));

    // Where the step leaves its drag piece, and the piece it enters, given
    // the Reynolds numbers at its ends.
    let crossing = |step: &DenseStep<4>, re0: f64, re1: f64| -> Option<(f64, usize)> {
        let p = piece.get();
        let (kink, next) = if p > 0 && re1 < kinks[p - 1] {
            (kinks[p - 1], p - 1)
        } else if p < kinks.len() && re1 > kinks[p] {
            (kinks[p], p + 1)
        } else {
            return None;
        };
        let t = if (re0 - kink) * (re1 - kink) < 0.0 {
            // Where |V_r|² = (kink/(2r_b/ν))²: the same root as Re = kink,
            // without a square root per iteration.
            let speed = kink / flight.reynolds_per_speed;
            ode::find_root_newton(
                |t| {
                    let (s, slope) = (step.at(t), step.slope_at(t));
                    let rel = flight.relative_wind(Vector2::new(s[2], s[3]));
                    // d/dt |V_r|² = 2 V_r·dV_r/dt = −2 V_r·a.
                    let rate = -2.0 * (rel.x * slope[2] + rel.y * slope[3]);
                    (rel.norm_squared() - speed * speed, rate)
                },
                step.t0,
                step.t1,
                root_tolerance,
            )
        } else {
            // Already across at the start (it came back over the kink it
            // was just switched at): switch at once.
            step.t0
        };
        Some((t, next))
    };
    let landing_time = |step: &DenseStep<4>| {
        ode::find_root_newton(
            |t| (step.at(t)[1], step.slope_at(t)[1]),
            step.t0,
            step.t1,
            root_tolerance,
        )
    };

    let rhs = |_t: f64, s: &State<4>| {
        if switching {
            flight.derivative_on(s, Some(piece.get()))
        } else {
            flight.derivative(s)
        }
    };
    let observe = |step: &DenseStep<4>| {
        // The Reynolds numbers at the step's ends (each costs a square root:
        // computed once, for the kink check and the kink prediction).
        let (re0, re1) = if switching {
            (reynolds(&step.y0), reynolds(&step.y1))
        } else {
            (0.0, 0.0)
        };
        // The step as shown: cut at a kink, or the step itself (by reference:
        // a DenseStep is 27 numbers, not worth copying on every step).
        let truncated;
        let mut shown = step;
        let mut control = Control::Continue;
        if switching && let Some((t_kink, next)) = crossing(step, re0, re1) {
            let lands_first = step.y1[1] <= 0.0 && landing_time(step) <= t_kink;
            // A second switch at the same instant would undo the first (Re
            // turning right at a kink): go on without it, so that every
            // switch is followed by progress in time.
            let stalls = t_kink <= last_switch.get();
            if !lands_first && !stalls {
                last_switch.set(t_kink);
                truncated = step.truncated(t_kink);
                shown = &truncated;
                piece.set(next);
                control = Control::RestartAt(t_kink);
            }
        }
        watch(shown);
        if shown.y0[3] > 0.0 && shown.y1[3] <= 0.0 {
            let t = ode::find_root_newton(
                |t| (shown.at(t)[3], shown.slope_at(t)[3]),
                shown.t0,
                shown.t1,
                root_tolerance,
            );
            let s = shown.at(t);
            if s[1] > apex.0 {
                apex = (s[1], s[0]);
            }
        }
        last = (shown.t1, shown.y1);
        if shown.y1[1] <= 0.0 {
            let t = landing_time(shown);
            landing = Some((t, shown.at(t)));
            return Control::Stop;
        }
        if control == Control::Continue {
            // When the next event is near, end the next step a little past
            // it rather than wherever the error control would.
            let h = shown.t1 - shown.t0;
            let mut soonest = f64::INFINITY;
            // The landing: y(τ) ≈ y + v_y τ + a_y τ²/2, a_y from the step.
            let (y, vy) = (shown.y1[1], shown.y1[3]);
            let ay = (shown.y1[3] - shown.y0[3]) / h;
            let disc = vy * vy - 2.0 * ay * y;
            if disc >= 0.0 && ay != 0.0 {
                for tau in [(-vy + disc.sqrt()) / ay, (-vy - disc.sqrt()) / ay] {
                    if tau > 0.0 {
                        soonest = soonest.min(tau);
                    }
                }
            } else if ay == 0.0 && vy < 0.0 {
                soonest = -y / vy;
            }
            // The next kink, from the Reynolds number's rate over the step.
            // (Not cut here, so `shown` is `step` and re0, re1 are its ends.)
            if switching {
                let rate = (re1 - re0) / h;
                let p = piece.get();
                let target = if rate < 0.0 && p > 0 {
                    Some(kinks[p - 1])
                } else if rate > 0.0 && p < kinks.len() {
                    Some(kinks[p])
                } else {
                    None
                };
                if let Some(kink) = target {
                    soonest = soonest.min((kink - re1) / rate);
                }
            }
            // Past the predicted event by half its distance, so that the
            // event falls inside the next step despite the prediction's
            // error; and not for events closer than a tenth of this step,
            // lest a Reynolds number creeping up on a kink shrink the steps
            // without end. (bench: at 1e-5 the landing error falls ~4× and a
            // Fig. 7 surface's worst cell 10×, for the same evaluations.)
            if soonest.is_finite() && soonest > 0.1 * h {
                return Control::EndNextBy(shown.t1 + 1.5 * soonest);
            }
        }
        control
    };
    let (outcome, stats) = match stepper {
        Stepper::Adaptive(settings) => {
            ode::integrate(rhs, 0.0, start, MAX_FLIGHT_TIME, &settings, observe)
        }
        Stepper::Fixed(step) => ode::integrate_fixed(
            rhs,
            0.0,
            start,
            MAX_FLIGHT_TIME,
            step,
            ode::MAX_STEPS,
            observe,
        ),
    };
    let landed = outcome == Outcome::Stopped;
    let (time, state) = landing.unwrap_or(last);
    FlightSummary {
        range: state[0] - launch.position.x,
        flight_time: time,
        apex: apex.0,
        apex_distance: apex.1 - launch.position.x,
        landing_speed: state.fixed_rows::<2>(2).norm(),
        landing_angle: (-state[3]).atan2(state[2]),
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
        let velocity = Vector2::new(s[2], s[3]);
        points.push(TrajectoryPoint {
            time,
            x: s[0],
            y: s[1],
            drag_coefficient: flight.drag.drag_coefficient(flight.reynolds(velocity)),
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
                state[1] = 0.0; // the landing event defines y = 0 there
            }
            push(t, state);
            next += 1;
        }
    });
    (summary, points)
}
