//! Independent problems integrated in lock-step ([`LANES`] at a time): one state per lane
//! of vectors (struct of arrays), each lane with its own time,
//! step size and controller, so that the stages of their steps run as one
//! chain of vector operations where a single problem's steps would wait on
//! each other. A lane whose step is rejected retries while the others go
//! on; a lane whose problem ends takes the next one ([`LaneSystem::refill`]),
//! starting with its neighbour's first step.
//!
//! The step's arithmetic is [`super::stages`](mod@super::stages)'s, the controller's
//! `super::controller`'s, the same as the single integrator's; what
//! happens between steps (events, the dense output where one falls) is the
//! system's, lane by lane, in scalar code.
//!
//! The vectors' type is a parameter ([`LaneReal`]): `wide`'s [`Lane`]
//! (SSE2 pairs in the baseline x86-64 build).

use std::ops::{Add, Mul, Sub};

use super::controller::{
    LOG2_ERROR_FLOOR, accepted_growth, initial_step, log2_error, rejected_growth,
};
use super::stages::{Stages, Vector, dense_c5, error_squared, inverse_scales, stages_into};
use super::{Control, DenseStep, Outcome, Settings, State, Stats, Step, too_small};

pub use super::super::real::{LANES, Lane, LaneReal};

/// The states (or slopes) of four problems: component i of lane j is
/// `self.0[i]`'s lane j. `V` is the lanes' number ([`Lane`]).
#[derive(Clone, Copy, Debug)]
pub struct Lanes<const N: usize, V = Lane>(pub [V; N]);

impl<const N: usize, V: LaneReal> Lanes<N, V> {
    #[inline(always)]
    pub fn zero() -> Self {
        Lanes([V::splat(0.0); N])
    }

    /// Lane `j`'s state.
    #[inline(always)]
    pub fn lane(&self, j: usize) -> State<N> {
        State::<N>::from_fn(|i, _| self.0[i].get(j))
    }

    /// Sets lane `j` to `state`.
    #[inline(always)]
    pub fn set_lane(&mut self, j: usize, state: &State<N>) {
        for (i, component) in self.0.iter_mut().enumerate() {
            component.set(j, state[i]);
        }
    }

    /// `if_true`'s lanes where `mask` holds, `if_false`'s elsewhere.
    #[inline(always)]
    pub fn select(mask: V::Mask, if_true: &Self, if_false: &Self) -> Self {
        let mut out = *if_false;
        for i in 0..N {
            out.0[i] = V::select(mask, if_true.0[i], if_false.0[i]);
        }
        out
    }
}

impl<const N: usize, V: LaneReal> Add for Lanes<N, V> {
    type Output = Self;
    #[inline(always)]
    fn add(mut self, other: Self) -> Self {
        for i in 0..N {
            self.0[i] = self.0[i] + other.0[i];
        }
        self
    }
}

impl<const N: usize, V: LaneReal> Sub for Lanes<N, V> {
    type Output = Self;
    #[inline(always)]
    fn sub(mut self, other: Self) -> Self {
        for i in 0..N {
            self.0[i] = self.0[i] - other.0[i];
        }
        self
    }
}

impl<const N: usize, V: LaneReal> Mul<V> for Lanes<N, V> {
    type Output = Self;
    #[inline(always)]
    fn mul(mut self, factor: V) -> Self {
        for i in 0..N {
            self.0[i] = self.0[i] * factor;
        }
        self
    }
}

impl<const N: usize, V: LaneReal> Vector<V> for Lanes<N, V> {
    const DIM: usize = N;
    #[inline(always)]
    fn component(&self, i: usize) -> V {
        self.0[i]
    }
}

/// Where a lane's next problem starts.
#[derive(Clone, Copy, Debug)]
pub struct LaneStart<const N: usize> {
    pub t0: f64,
    pub y0: State<N>,
    pub t_end: f64,
}

/// What the lock-step integrator needs of the problems it carries, on
/// lanes of `V`.
pub trait LaneSystem<const N: usize, V: LaneReal> {
    /// y' for every lane at once, each lane in its own problem.
    fn derivative(&self, t: V, y: &Lanes<N, V>) -> Lanes<N, V>;
    /// y' of lane `lane`'s problem alone (a restart's, a first step's).
    fn derivative_lane(&self, lane: usize, t: f64, y: &State<N>) -> State<N>;
    /// Sees lane `lane`'s accepted step, as the single integrator's
    /// observer does (the right-hand side it reads may change here).
    fn observe(&mut self, lane: usize, step: &Step<N>) -> Control;
    /// Of the lanes whose steps were accepted (`accepted`), those whose
    /// steps need no observer one by one (nothing happens inside them),
    /// and for those the time by which their next steps should end (+∞
    /// for no limit): as [`Control::EndNextBy`] or [`Control::Continue`]
    /// would say, for all lanes at once. The steps run from `t0` to `t1`
    /// (`h` long). By default, none.
    fn quiet(
        &mut self,
        accepted: V::Mask,
        (t0, t1, h): (V, V, V),
        (y0, y1): (&Lanes<N, V>, &Lanes<N, V>),
    ) -> (V::Mask, V) {
        let _ = (accepted, t0, t1, h, y0, y1);
        (V::mask_of([false; LANES]), V::splat(f64::INFINITY))
    }
    /// Lane `lane`'s problem has ended, at (t, y) = `end`.
    fn finish(&mut self, lane: usize, outcome: Outcome, stats: Stats, end: (f64, State<N>));
    /// The next problem for lane `lane` (its right-hand side set up), or
    /// `None` when there is none left.
    fn refill(&mut self, lane: usize) -> Option<LaneStart<N>>;
}

/// One lane's bookkeeping.
#[derive(Clone, Copy, Debug, Default)]
struct LaneState {
    active: bool,
    stats: Stats,
    last_rejected: bool,
    t_end: f64,
}

/// The lanes' times, states, slopes, step sizes and controllers.
struct Carried<const N: usize, V> {
    t: V,
    y: Lanes<N, V>,
    k1: Lanes<N, V>,
    h: V,
    previous_log2_error: V,
    lanes: [LaneState; LANES],
    /// Lanes whose slope k1 is to be evaluated (a new problem, or a
    /// restart), and among them those that need a first step.
    fresh: [bool; LANES],
    needs_first_step: [bool; LANES],
    /// The last first step a problem found: its neighbours' to try.
    neighbour_step: Option<f64>,
    first_steps: FirstSteps,
}

/// How a lane's problem picks its first step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FirstSteps {
    /// The step its neighbour's controller chose after its first (saves
    /// Hairer's guess, and usually a rejection); Hairer's guess until a
    /// neighbour has one.
    FromNeighbours,
    /// Hairer's guess for each problem alone, with the single integrator's
    /// scalar code: its first step, so its whole step sequence, is
    /// [`super::integrate`]'s without [`Settings::initial_step`], bit for
    /// bit where the right-hand sides agree bit for bit.
    Guessed,
}

/// Sets one lane of a vector.
#[inline(always)]
fn set<V: LaneReal>(v: &mut V, j: usize, x: f64) {
    v.set(j, x);
}

impl<const N: usize, V: LaneReal> Carried<N, V> {
    /// Takes lane `j`'s next problem, or idles it.
    fn refill<S: LaneSystem<N, V>>(&mut self, system: &mut S, j: usize) {
        self.lanes[j] = LaneState::default();
        self.fresh[j] = false;
        let Some(start) = system.refill(j) else {
            return;
        };
        self.lanes[j] = LaneState {
            active: true,
            t_end: start.t_end,
            ..LaneState::default()
        };
        set(&mut self.t, j, start.t0);
        self.y.set_lane(j, &start.y0);
        set(&mut self.previous_log2_error, j, LOG2_ERROR_FLOOR);
        self.fresh[j] = true;
        match self.neighbour_step {
            Some(h) if self.first_steps == FirstSteps::FromNeighbours => set(&mut self.h, j, h),
            _ => self.needs_first_step[j] = true,
        }
    }

    /// Ends lane `j`'s problem and takes the next.
    fn finish<S: LaneSystem<N, V>>(&mut self, system: &mut S, j: usize, outcome: Outcome) {
        let end = (self.t.to_array()[j], self.y.lane(j));
        system.finish(j, outcome, self.lanes[j].stats, end);
        self.refill(system, j);
    }

    /// Evaluates k1 for the fresh lanes (one evaluation for all), and the
    /// first step of those that have none (Hairer's guess, one more).
    fn start_fresh<S: LaneSystem<N, V>>(&mut self, system: &S, settings: &Settings) {
        let count = self.fresh.iter().filter(|&&fresh| fresh).count();
        if count == 0 {
            return;
        }
        // One lane (a restart, mostly) by itself; several at once.
        let all = if count > 1 {
            Some(system.derivative(self.t, &self.y))
        } else {
            None
        };
        for j in 0..LANES {
            if self.fresh[j] {
                let k = match &all {
                    Some(k) => k.lane(j),
                    None => system.derivative_lane(j, self.t.to_array()[j], &self.y.lane(j)),
                };
                self.k1.set_lane(j, &k);
                self.lanes[j].stats.evaluations += 1;
            }
        }
        self.fresh = [false; LANES];
        // Hairer's guess for the lanes that have no neighbour's first step.
        for j in 0..LANES {
            if self.needs_first_step[j] {
                let (t0, y0, k1) = (self.t.to_array()[j], self.y.lane(j), self.k1.lane(j));
                let mut f = |t: f64, y: &State<N>| system.derivative_lane(j, t, y);
                let h = initial_step(&mut f, t0, &y0, &k1, settings, &mut self.lanes[j].stats);
                set(&mut self.h, j, h);
                self.needs_first_step[j] = false;
            }
        }
    }
}

/// Integrates `system`'s problems, four at a time, until there are no
/// more: each as [`super::integrate`] would, with `settings` for all (its
/// `initial_step`, if given, for the first four, unless `first_steps` is
/// [`FirstSteps::Guessed`]). Never allocates.
pub fn integrate_lanes<const N: usize, V: LaneReal, S: LaneSystem<N, V>>(
    system: &mut S,
    settings: &Settings,
    first_steps: FirstSteps,
) {
    let tol = settings.tolerance;
    let (relative, absolute) = (V::splat(tol.relative), V::splat(tol.absolute));
    let mut c = Carried {
        t: V::splat(0.0),
        y: Lanes::zero(),
        k1: Lanes::zero(),
        h: V::splat(0.0),
        previous_log2_error: V::splat(LOG2_ERROR_FLOOR),
        lanes: [LaneState::default(); LANES],
        fresh: [false; LANES],
        needs_first_step: [false; LANES],
        neighbour_step: settings.initial_step.filter(|&h| h > 0.0),
        first_steps,
    };
    for j in 0..LANES {
        c.refill(system, j);
    }
    // The step's stages, written in place each step.
    let mut s = Stages {
        k: [Lanes::zero(); 6],
        y1: Lanes::zero(),
    };
    loop {
        c.start_fresh(system, settings);
        // Each lane's limits, as the single integrator checks them.
        let mut h = c.h.to_array();
        let t = c.t.to_array();
        let mut any_ended = false;
        for j in 0..LANES {
            let lane = &c.lanes[j];
            if !lane.active {
                h[j] = 0.0;
                continue;
            }
            let ended = if lane.stats.accepted + lane.stats.rejected >= settings.max_steps {
                Some(Outcome::StepLimit)
            } else if t[j] >= lane.t_end {
                Some(Outcome::ReachedEnd)
            } else {
                h[j] = h[j].min(settings.max_step).min(lane.t_end - t[j]);
                too_small(h[j], t[j]).then_some(Outcome::StepTooSmall)
            };
            if let Some(outcome) = ended {
                c.finish(system, j, outcome);
                any_ended = true;
            }
        }
        if any_ended {
            // The new problems' slopes first.
            continue;
        }
        if !c.lanes.iter().any(|lane| lane.active) {
            return;
        }
        let h = V::from_array(h);
        c.h = h;
        let (t0, y0, k1) = (c.t, c.y, c.k1);
        stages_into(
            &mut s,
            &mut |t, y: &Lanes<N, V>, slope: &mut Lanes<N, V>| *slope = system.derivative(t, y),
            t0,
            &y0,
            &k1,
            h,
        );
        let inverse = inverse_scales::<V, _, N>(&y0, &s.y1, relative, absolute);
        let error_squared = error_squared(&k1, &s, h, &inverse);
        let log2 = log2_error(error_squared);
        let accepted = error_squared.le(V::splat(1.0));
        let grown = h * accepted_growth(log2, c.previous_log2_error);
        let h_accepted = V::select(c.last_rejected(), grown.min(h), grown);
        let mut h_next = V::select(accepted, h_accepted, h * rejected_growth(log2));
        let t1 = t0 + h;
        let (quiet, end_by) = system.quiet(accepted, (t0, t1, h), (&y0, &s.y1));
        let quiet = quiet & accepted;
        let limited = quiet & t1.lt(end_by);
        let h_first = h_next.to_array();
        h_next = V::select(limited, h_next.min(end_by - t1), h_next);
        c.previous_log2_error = V::select(
            accepted,
            log2.max(V::splat(LOG2_ERROR_FLOOR)),
            c.previous_log2_error,
        );
        // Accepted lanes move to the step's end, unless their observer
        // says otherwise below.
        c.t = V::select(accepted, t1, t0);
        c.y = Lanes::select(accepted, &s.y1, &y0);
        c.k1 = Lanes::select(accepted, &s.k[5], &k1);
        c.h = h_next;
        let (accepted, quiet) = (V::bitmask(accepted), V::bitmask(quiet));
        let (h_all, t1_all) = (h.to_array(), t1.to_array());
        for j in 0..LANES {
            if !c.lanes[j].active {
                continue;
            }
            let lane = &mut c.lanes[j];
            lane.stats.evaluations += 6;
            if accepted & (1 << j) == 0 {
                lane.stats.rejected += 1;
                lane.last_rejected = true;
                continue;
            }
            if lane.stats.accepted == 0 {
                lane.stats.first_step = h_first[j];
                c.neighbour_step = Some(h_first[j]);
            }
            lane.stats.accepted += 1;
            lane.last_rejected = false;
            if quiet & (1 << j) != 0 {
                continue;
            }
            let (t0j, hj) = (t0.to_array()[j], h_all[j]);
            let y0j = y0.lane(j);
            let y1j = s.y1.lane(j);
            let build = || lane_dense(j, t0j, hj, (&y0j, &y1j), &k1, &s);
            let step = Step::new((t0j, t1_all[j]), (y0j, y1j), &build);
            let control = system.observe(j, &step);
            match control {
                Control::Stop => {
                    c.finish(system, j, Outcome::Stopped);
                    continue;
                }
                Control::RestartAt(_) => {
                    if let Some(time) = step.restart_time(control) {
                        let at = step.at(time);
                        set(&mut c.t, j, time);
                        c.y.set_lane(j, &at);
                        c.fresh[j] = true;
                    }
                }
                Control::EndNextBy(t_end_next) if t_end_next > t1_all[j] => {
                    set(&mut c.h, j, h_first[j].min(t_end_next - t1_all[j]));
                }
                _ => {}
            }
        }
    }
}

impl<const N: usize, V: LaneReal> Carried<N, V> {
    /// The lanes whose last step was rejected.
    #[inline(always)]
    fn last_rejected(&self) -> V::Mask {
        V::mask_of(self.lanes.map(|lane| lane.last_rejected))
    }
}

/// Lane `j`'s continuous extension over its step from (t0, y0) to y1.
#[inline(always)]
fn lane_dense<const N: usize, V: LaneReal>(
    j: usize,
    t0: f64,
    h: f64,
    (y0, y1): (&State<N>, &State<N>),
    k1: &Lanes<N, V>,
    s: &Stages<Lanes<N, V>>,
) -> DenseStep<N> {
    let k1 = k1.lane(j);
    let lane = Stages {
        k: std::array::from_fn(|m| s.k[m].lane(j)),
        y1: *y1,
    };
    let c5 = dense_c5(&k1, &lane, h);
    DenseStep::new(t0, h, (*y0, *y1), (&k1, &lane.k[5]), c5)
}
