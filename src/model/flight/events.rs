//! What the flight watches for between steps: the drag curve's kinks (where
//! it switches C_D formula), the apex and the landing, each located on the
//! step's continuous extension, and a prediction of the next of them so that
//! the step that meets it wastes little beyond it.

use std::cell::Cell;

use super::{DISTANCE, Flight, HEIGHT, VELOCITY_X, VERTICAL_VELOCITY, velocity};
use crate::numerics::ode::{Control, DenseStep, State};
use crate::numerics::roots::find_root_newton;

/// Event times are located to this (s): far below anything that shows.
const ROOT_TOLERANCE: f64 = 1e-13;

/// The events seen so far, and the drag piece in force.
pub(super) struct Events<'a> {
    flight: &'a Flight,
    /// The kinks switched at: none when the flight does not stop at them.
    kinks: &'static [f64],
    /// The drag piece the current step uses. Shared with the right-hand
    /// side, which reads it during a step while this observer changes it
    /// between steps.
    piece: &'a Cell<usize>,
    /// The time of the last switch: a second switch at the same instant
    /// would undo the first.
    last_switch: f64,
    /// The highest point: height and distance.
    pub apex: (f64, f64),
    /// The landing: time and state.
    pub landing: Option<(f64, State<4>)>,
    /// The last accepted point: time and state.
    pub last: (f64, State<4>),
}

impl<'a> Events<'a> {
    pub fn new(
        flight: &'a Flight,
        start: &State<4>,
        piece: &'a Cell<usize>,
        switching: bool,
    ) -> Self {
        Events {
            flight,
            kinks: if switching { flight.drag.kinks() } else { &[] },
            piece,
            last_switch: f64::NEG_INFINITY,
            apex: (start[HEIGHT], start[DISTANCE]),
            landing: None,
            last: (0.0, *start),
        }
    }

    #[inline]
    fn switching(&self) -> bool {
        !self.kinks.is_empty()
    }

    #[inline]
    fn reynolds(&self, state: &State<4>) -> f64 {
        self.flight.reynolds(velocity(state))
    }

    /// Where the step leaves its drag piece, and the piece it enters, given
    /// the Reynolds numbers at its ends.
    #[inline]
    fn crossing(&self, step: &DenseStep<4>, re0: f64, re1: f64) -> Option<(f64, usize)> {
        let (kinks, p) = (self.kinks, self.piece.get());
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
            let speed = kink / self.flight.reynolds_per_speed;
            find_root_newton(
                |t| {
                    let (s, slope) = (step.at(t), step.slope_at(t));
                    let rel = self.flight.relative_wind(velocity(&s));
                    // d/dt |V_r|² = 2 V_r·dV_r/dt = −2 V_r·a.
                    let rate =
                        -2.0 * (rel.x * slope[VELOCITY_X] + rel.y * slope[VERTICAL_VELOCITY]);
                    (rel.norm_squared() - speed * speed, rate)
                },
                step.t0,
                step.t1,
                ROOT_TOLERANCE,
            )
        } else {
            // Already across at the start (it came back over the kink it
            // was just switched at): switch at once.
            step.t0
        };
        Some((t, next))
    }

    /// Where a component of the state crosses zero inside the step.
    #[inline]
    fn zero_of(step: &DenseStep<4>, component: usize) -> f64 {
        find_root_newton(
            |t| (step.at(t)[component], step.slope_at(t)[component]),
            step.t0,
            step.t1,
            ROOT_TOLERANCE,
        )
    }

    /// Sees one accepted step: switches the drag piece at a kink (cutting
    /// the step there), records the apex and the landing, and says how to go
    /// on. `watch` is shown the step as kept.
    #[inline]
    pub fn observe(
        &mut self,
        step: &DenseStep<4>,
        watch: &mut impl FnMut(&DenseStep<4>),
    ) -> Control {
        // The Reynolds numbers at the step's ends (each costs a square root:
        // computed once, for the kink check and the kink prediction).
        let (re0, re1) = if self.switching() {
            (self.reynolds(&step.y0), self.reynolds(&step.y1))
        } else {
            (0.0, 0.0)
        };
        // The step as shown: cut at a kink, or the step itself (by reference:
        // a DenseStep is 27 numbers, not worth copying on every step).
        let truncated;
        let mut shown = step;
        let mut control = Control::Continue;
        if self.switching()
            && let Some((t_kink, next)) = self.crossing(step, re0, re1)
        {
            let lands_first = step.y1[HEIGHT] <= 0.0 && Self::zero_of(step, HEIGHT) <= t_kink;
            // A second switch at the same instant would undo the first (Re
            // turning right at a kink): go on without it, so that every
            // switch is followed by progress in time.
            let stalls = t_kink <= self.last_switch;
            if !lands_first && !stalls {
                self.last_switch = t_kink;
                truncated = step.truncated(t_kink);
                shown = &truncated;
                self.piece.set(next);
                control = Control::RestartAt(t_kink);
            }
        }
        watch(shown);
        if shown.y0[VERTICAL_VELOCITY] > 0.0 && shown.y1[VERTICAL_VELOCITY] <= 0.0 {
            let s = shown.at(Self::zero_of(shown, VERTICAL_VELOCITY));
            if s[HEIGHT] > self.apex.0 {
                self.apex = (s[HEIGHT], s[DISTANCE]);
            }
        }
        self.last = (shown.t1, shown.y1);
        if shown.y1[HEIGHT] <= 0.0 {
            let t = Self::zero_of(shown, HEIGHT);
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
    /// end: a little past it rather than wherever the error control would.
    /// `step` was not cut, so re0 and re1 are its ends' Reynolds numbers.
    #[inline]
    fn next_event_by(&self, step: &DenseStep<4>, re0: f64, re1: f64) -> Option<f64> {
        let h = step.t1 - step.t0;
        let mut soonest = f64::INFINITY;
        // The landing: y(τ) ≈ y + v_y τ + a_y τ²/2, a_y from the step.
        let (y, vy) = (step.y1[HEIGHT], step.y1[VERTICAL_VELOCITY]);
        let ay = (step.y1[VERTICAL_VELOCITY] - step.y0[VERTICAL_VELOCITY]) / h;
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
        if self.switching() {
            let rate = (re1 - re0) / h;
            let (kinks, p) = (self.kinks, self.piece.get());
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
        // Past the predicted event by half its distance, so that the event
        // falls inside the next step despite the prediction's error; and not
        // for events closer than a tenth of this step, lest a Reynolds number
        // creeping up on a kink shrink the steps without end. (At 1e-5 the
        // landing error falls ~4× and a Fig. 7 surface's worst cell 10×, for
        // the same evaluations: `homerun bench`.)
        (soonest.is_finite() && soonest > 0.1 * h).then_some(step.t1 + 1.5 * soonest)
    }
}
