//! What the flight watches for between steps: the drag curve's kinks (where
//! it switches C_D formula), the wind's layer (where the wind starts or
//! stops blowing), the apex and the landing, each located on the step's
//! continuous extension, and a prediction of the next of them so that the
//! step that meets it wastes little beyond it.

use super::{Dynamics, FlightSummary, RangeSummary, Regime};
use numerics::ode::{Control, State, Stats, Step};
use numerics::real::Real;
use numerics::roots::find_root_newton_from;

/// Event times are located to this (s): far below anything that shows.
const ROOT_TOLERANCE: f64 = 1e-13;

/// The events seen so far, and the regime in force.
pub(crate) struct Events<const N: usize, D: Dynamics<N>> {
    /// The flight (a copy: a few dozen numbers, and no borrow to keep).
    flight: D,
    /// The kinks switched at: none when the flight does not stop at them.
    kinks: &'static [f64],
    /// The height the wind blows above, if the flight switches there.
    wind_height: Option<f64>,
    /// The drag piece and wind layer the current step uses: the
    /// right-hand side's, which the integration hands it after each step.
    regime: Regime,
    /// Where the flight started: distances are measured from it.
    start: State<N>,
    /// The time of the last switch: a second switch at the same instant
    /// would undo the first.
    last_switch: f64,
    /// Whether the apex is located (a flight asked for its range alone
    /// needs none).
    locates_apex: bool,
    /// The highest point: height and horizontal distance.
    pub apex: (f64, f64),
    /// The landing: time and state.
    pub landing: Option<(f64, State<N>)>,
    /// The last accepted point: time and state.
    pub last: (f64, State<N>),
}

/// A change of regime inside a step: when, and to what.
#[derive(Clone, Copy)]
struct Switch {
    time: f64,
    regime: Regime,
}

impl<const N: usize, D: Dynamics<N>> Events<N, D> {
    /// The events of a flight from `start`, switching at the drag curve's
    /// kinks if `stop_at_kinks`, locating the apex if `locates_apex`.
    pub fn new(flight: D, start: &State<N>, (stop_at_kinks, locates_apex): (bool, bool)) -> Self {
        let regime = flight.starting_regime(start, stop_at_kinks);
        Events {
            flight,
            kinks: if regime.piece.is_some() {
                flight.drag().kinks()
            } else {
                &[]
            },
            wind_height: flight.wind_height(),
            regime,
            start: *start,
            last_switch: f64::NEG_INFINITY,
            locates_apex,
            apex: (start[D::HEIGHT], 0.0),
            landing: None,
            last: (0.0, *start),
        }
    }

    #[inline]
    fn switching(&self) -> bool {
        !self.kinks.is_empty()
    }

    /// The flight whose events these are.
    #[inline(always)]
    pub fn flight(&self) -> &D {
        &self.flight
    }

    /// The regime the next step is to use.
    #[inline(always)]
    pub fn regime(&self) -> Regime {
        self.regime
    }

    /// The flight's outcome, once the integration has ended (`landed` if
    /// the landing stopped it). Only for events that located the apex.
    pub fn summary(&self, landed: bool, stats: Stats) -> FlightSummary {
        debug_assert!(self.locates_apex, "a summary without its apex");
        let (time, state) = self.landing.unwrap_or(self.last);
        let (range, direction) = D::ground(&state, &self.start);
        let (horizontal, vertical) = D::velocity_parts(&state);
        FlightSummary {
            range,
            direction,
            flight_time: time,
            apex: self.apex.0,
            apex_distance: self.apex.1,
            // As a norm is computed (not hypot), so the plane's speed is bit
            // for bit what it was.
            landing_speed: (horizontal * horizontal + vertical * vertical).sqrt(),
            landing_angle: (-vertical).atan2(horizontal),
            landed,
            stats,
        }
    }

    /// What of [`Events::summary`] a range needs, bit for bit.
    pub fn range_summary(&self, landed: bool, stats: Stats) -> RangeSummary {
        let (time, state) = self.landing.unwrap_or(self.last);
        RangeSummary {
            range: D::distance(&state, &self.start),
            flight_time: time,
            landed,
            stats,
        }
    }

    /// Where the step leaves its drag piece, and the piece it enters, given
    /// the Reynolds numbers at its ends.
    #[inline(always)]
    fn kink_crossing(&self, step: &Step<N>, re0: f64, re1: f64) -> Option<Switch> {
        let regime = self.regime;
        let (kinks, p) = (self.kinks, regime.piece.unwrap_or_default());
        let (kink, next) = if p > 0 && re1 < kinks[p - 1] {
            (kinks[p - 1], p - 1)
        } else if p < kinks.len() && re1 > kinks[p] {
            (kinks[p], p + 1)
        } else {
            return None;
        };
        let time = if (re0 - kink) * (re1 - kink) < 0.0 {
            // Where |V_r|² = (kink/(2r_b/ν))²: the same root as Re = kink,
            // without a square root per iteration.
            let speed = kink / self.flight.reynolds_per_speed();
            let dense = step.dense();
            let excess = |state: &State<N>, slope: &State<N>| {
                let (squared, rate) = self.flight.air_speed_squared(state, slope, regime.in_wind);
                (squared - speed * speed, rate)
            };
            // At the ends, from the step's own states (the rates unused).
            let ends = |y: &State<N>| excess(y, y).0;
            // Inside, the velocity and its slope alone (all that |V_r|²
            // reads), component by component: the same numbers as the
            // whole state's, without the positions'.
            let velocity_at = |t: f64| {
                let (mut state, mut slope) = (State::<N>::zeros(), State::<N>::zeros());
                for i in D::VELOCITY_X..N {
                    (state[i], slope[i]) = dense.component_at(t, i);
                }
                (state, slope)
            };
            find_root_newton_from(
                |t| {
                    let (state, slope) = velocity_at(t);
                    excess(&state, &slope)
                },
                (step.t0, ends(&step.y0)),
                (step.t1, ends(&step.y1)),
                ROOT_TOLERANCE,
            )
        } else {
            // Already across at the start (it came back over the kink it
            // was just switched at): switch at once.
            step.t0
        };
        Some(Switch {
            time,
            regime: Regime {
                piece: Some(next),
                ..regime
            },
        })
    }

    /// Where the step enters or leaves the wind's layer, if it does.
    #[inline(always)]
    fn layer_crossing(&self, step: &Step<N>) -> Option<Switch> {
        let height = self.wind_height?;
        let regime = self.regime;
        let (y0, y1) = (step.y0[D::HEIGHT] - height, step.y1[D::HEIGHT] - height);
        let leaves = if regime.in_wind { y1 < 0.0 } else { y1 >= 0.0 };
        if !leaves {
            return None;
        }
        let time = if y0 * y1 < 0.0 {
            Self::zero_of(step, D::HEIGHT, height)
        } else {
            step.t0
        };
        let in_wind = !regime.in_wind;
        let piece = regime
            .piece
            .map(|_| self.flight.drag_piece_at(&step.at(time), in_wind));
        Some(Switch {
            time,
            regime: Regime { piece, in_wind },
        })
    }

    /// Where a component of the state crosses `level` inside the step.
    #[inline]
    fn zero_of(step: &Step<N>, component: usize, level: f64) -> f64 {
        let dense = step.dense();
        find_root_newton_from(
            |t| {
                let (value, slope) = dense.component_at(t, component);
                (value - level, slope)
            },
            (step.t0, step.y0[component] - level),
            (step.t1, step.y1[component] - level),
            ROOT_TOLERANCE,
        )
    }

    /// Sees one accepted step: switches the regime at a kink or the wind's
    /// layer (cutting the step there), records the apex and the landing, and
    /// says how to go on. `watch` is shown the step as kept.
    #[inline(always)]
    pub fn observe(&mut self, step: &Step<N>, watch: &mut impl FnMut(&Step<N>)) -> Control {
        let in_wind = self.regime.in_wind;
        // The Reynolds numbers at the step's ends (each costs a square root:
        // computed once, for the kink check and the kink prediction).
        let (re0, re1) = if self.switching() {
            (
                self.flight.reynolds(&step.y0, in_wind),
                self.flight.reynolds(&step.y1, in_wind),
            )
        } else {
            (0.0, 0.0)
        };
        // The step as shown: cut at a switch, or the step itself (by
        // reference: a step is dozens of numbers, not worth copying on
        // every step).
        let truncated;
        let mut shown = step;
        let mut control = Control::Continue;
        let kink = if self.switching() {
            self.kink_crossing(step, re0, re1)
        } else {
            None
        };
        let layer = self.layer_crossing(step);
        let first = match (kink, layer) {
            (Some(k), Some(l)) => Some(if l.time < k.time { l } else { k }),
            (k, l) => k.or(l),
        };
        if let Some(switch) = first {
            let lands_first =
                step.y1[D::HEIGHT] <= 0.0 && Self::zero_of(step, D::HEIGHT, 0.0) <= switch.time;
            // A second switch at the same instant would undo the first (Re
            // turning right at a kink): go on without it, so that every
            // switch is followed by progress in time.
            let stalls = switch.time <= self.last_switch;
            if !lands_first && !stalls {
                self.last_switch = switch.time;
                truncated = step.truncated(switch.time);
                shown = &truncated;
                self.regime = switch.regime;
                control = Control::RestartAt(switch.time);
            }
        }
        watch(shown);
        let vertical = (
            shown.y0[D::VERTICAL_VELOCITY],
            shown.y1[D::VERTICAL_VELOCITY],
        );
        if self.locates_apex && passes_apex(vertical) {
            let s = shown.at(Self::zero_of(shown, D::VERTICAL_VELOCITY, 0.0));
            if s[D::HEIGHT] > self.apex.0 {
                self.apex = (s[D::HEIGHT], D::ground(&s, &self.start).0);
            }
        }
        self.last = (shown.t1, shown.y1);
        if shown.y1[D::HEIGHT] <= 0.0 {
            let t = Self::zero_of(shown, D::HEIGHT, 0.0);
            self.landing = Some((t, shown.at(t)));
            return Control::Stop;
        }
        if control == Control::Continue
            && let Some(t) = self.next_event_by(shown, re0, re1)
        {
            return Control::EndNextBy(t);
        }
        control
    }

    /// When the next event is near, the time by which the next step should
    /// end (see [`end_next_by`]). `step` was not cut, so re0 and re1 are its
    /// ends' Reynolds numbers.
    #[inline(always)]
    fn next_event_by(&self, step: &Step<N>, re0: f64, re1: f64) -> Option<f64> {
        let ends = StepEnds {
            t1: step.t1,
            h: step.t1 - step.t0,
            heights: (step.y0[D::HEIGHT], step.y1[D::HEIGHT]),
            vertical_velocities: (step.y0[D::VERTICAL_VELOCITY], step.y1[D::VERTICAL_VELOCITY]),
            reynolds: (re0, re1),
        };
        let end = end_next_by(&ends, &self.bounds());
        end.is_finite().then_some(end)
    }

    /// What the regime in force bounds: the kinks on either side of its
    /// drag piece (±∞ where there is none, or no switching), and the wind's
    /// layer (−∞ without one, the ball then always in the wind).
    pub fn bounds(&self) -> Bounds<f64> {
        let (kinks, p) = (self.kinks, self.regime.piece.unwrap_or_default());
        let switching = self.switching();
        Bounds {
            kink_below: if switching && p > 0 {
                kinks[p - 1]
            } else {
                f64::NEG_INFINITY
            },
            kink_above: if switching && p < kinks.len() {
                kinks[p]
            } else {
                f64::INFINITY
            },
            wind_height: self.wind_height.unwrap_or(f64::NEG_INFINITY),
            in_wind: self.regime.in_wind,
        }
    }
}

/// What a step's ends say of the events ahead, for one flight (`f64`) or
/// several in lock-step: its end and size, and the height, vertical
/// velocity and Reynolds number at its start and end.
pub struct StepEnds<R> {
    pub t1: R,
    pub h: R,
    pub heights: (R, R),
    pub vertical_velocities: (R, R),
    pub reynolds: (R, R),
}

/// The regime's bounds (see [`Events::bounds`]).
#[derive(Clone, Copy, Debug)]
pub struct Bounds<R: Real> {
    pub kink_below: R,
    pub kink_above: R,
    pub wind_height: R,
    pub in_wind: R::Mask,
}

/// Whether anything but the apex happens inside a step: a kink or the
/// wind's layer crossed, the ground reached. Where nothing does (nor the
/// apex passed, [`passes_apex`], if it is located), the step's observer
/// need look no further than [`end_next_by`].
#[inline(always)]
pub fn switches_or_lands<R: Real>(ends: &StepEnds<R>, bounds: &Bounds<R>) -> R::Mask {
    let y1 = ends.heights.1;
    let re1 = ends.reynolds.1;
    let kink = re1.lt(bounds.kink_below) | bounds.kink_above.lt(re1);
    let leaves_layer = y1.lt(bounds.wind_height);
    let layer = (bounds.in_wind & leaves_layer) | (!bounds.in_wind & !leaves_layer);
    kink | layer | y1.le(R::splat(0.0))
}

/// Whether a step passes the apex: its vertical velocity, `(v_y0, v_y1)`
/// at its ends, turns from up to down.
#[inline(always)]
pub fn passes_apex<R: Real>((vy0, vy1): (R, R)) -> R::Mask {
    let zero = R::splat(0.0);
    zero.lt(vy0) & vy1.le(zero)
}

/// The time by which the step after this one should end, when an event is
/// near (else +∞): a little past the next predicted event rather than
/// wherever the error control would end it. The landing and the wind's
/// layer come from y(τ) ≈ y + v_y τ + a_y τ²/2 (a_y from the step), the
/// next kink from the Reynolds number's rate over the step.
#[inline(always)]
pub fn end_next_by<R: Real>(ends: &StepEnds<R>, bounds: &Bounds<R>) -> R {
    let infinity = R::splat(f64::INFINITY);
    let h = ends.h;
    let (y, (vy0, vy)) = (ends.heights.1, ends.vertical_velocities);
    let ay = (vy - vy0) / h;
    let mut soonest = time_to_height(y, vy, ay, R::splat(0.0));
    soonest = soonest.min(R::select(
        bounds.wind_height.eq(R::splat(f64::NEG_INFINITY)),
        infinity,
        time_to_height(y, vy, ay, bounds.wind_height),
    ));
    let (re0, re1) = ends.reynolds;
    let rate = (re1 - re0) / h;
    let zero = R::splat(0.0);
    let kink = R::select(
        rate.lt(zero),
        (bounds.kink_below - re1) / rate,
        R::select(zero.lt(rate), (bounds.kink_above - re1) / rate, infinity),
    );
    soonest = soonest.min(kink);
    // Past the predicted event by half its distance, so that the event
    // falls inside the next step despite the prediction's error; and not
    // for events closer than a tenth of this step, lest a Reynolds number
    // creeping up on a kink shrink the steps without end. (At 1e-5 the
    // landing error falls ~4× and a Fig. 7 surface's worst cell 10×, for
    // the same evaluations: `homerun bench`.)
    let near = soonest.lt(infinity) & (R::splat(0.1) * h).lt(soonest);
    R::select(near, ends.t1 + R::splat(1.5) * soonest, infinity)
}

/// The first τ > 0 at which y + v_y τ + a_y τ²/2 = `level`, or infinity.
#[inline(always)]
fn time_to_height<R: Real>(y: R, vy: R, ay: R, level: R) -> R {
    let (zero, infinity) = (R::splat(0.0), R::splat(f64::INFINITY));
    let y = y - level;
    let disc = vy * vy - R::splat(2.0) * ay * y;
    let root = disc.max(zero).sqrt();
    let positive = |tau: R| R::select(zero.lt(tau), tau, infinity);
    let quadratic = positive((-vy + root) / ay).min(positive((-vy - root) / ay));
    let linear = R::select(vy.lt(zero), -y / vy, infinity);
    R::select(
        ay.eq(zero),
        linear,
        R::select(zero.le(disc), quadratic, infinity),
    )
}
