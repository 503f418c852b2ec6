//! The flight's side of the lock-step integrator
//! ([`crate::numerics::ode::lanes`]): four flights' forces at once (the
//! same generic formulas as one flight's, on lanes of four numbers), and
//! each lane's events in scalar code, as a single flight sees them.

use super::events::{Bounds, Events, StepEnds, end_next_by, passes_apex, switches_or_lands};
use super::{Dynamics, Flight, Flight3d, FlightOptions, FlightSummary, RangeSummary, Regime};
use super::{PlanarConstants, SpatialConstants};
use crate::model::aero::{DragCurve, LiftCurve, WithModels};
use crate::model::clearing::{planar_reach_at, spatial_reach_at};
use crate::numerics::ode::lanes::{
    FirstSteps, LANES, Lane, LaneReal, LaneStart, LaneSystem, Lanes, integrate_lanes,
};
use crate::numerics::ode::{Control, Outcome, Settings, State, Stats, Step};

/// A flight the lanes can carry.
pub trait LaneFlight<const N: usize>: Dynamics<N> {
    /// The constants of one flight (`f64`) …
    type Constants: Copy + Default;
    /// … and of four, one per lane.
    type LaneConstants<V: LaneReal>: Copy;

    fn constants_of(&self) -> Self::Constants;
    fn gather<V: LaneReal>(each: &[Self::Constants; LANES]) -> Self::LaneConstants<V>;
    /// Sets lane `j` of `lanes` to `one` (a refill's: the other lanes
    /// left as they are, not gathered again).
    fn set_lane<V: LaneReal>(lanes: &mut Self::LaneConstants<V>, j: usize, one: &Self::Constants);

    /// y' of four flights at once: C_D by `drag` on each lane's piece
    /// (`pieces`, or the piece its Re is on if `None`), C_L by `lift`, in
    /// the wind where `in_wind`.
    fn derivative_lanes<V: LaneReal>(
        constants: &Self::LaneConstants<V>,
        models: (&impl DragCurve, &impl LiftCurve),
        regime: (Option<V>, V::Mask),
        t: V,
        y: &Lanes<N, V>,
    ) -> Lanes<N, V>;

    /// The Reynolds number of four flights at `y`, in the wind where
    /// `in_wind`.
    fn reynolds_lanes<V: LaneReal>(
        constants: &Self::LaneConstants<V>,
        in_wind: V::Mask,
        y: &Lanes<N, V>,
    ) -> V;

    /// How far from home plate four flights are at `y` (m), bit for bit
    /// as the fences' watch reckons a step's reach
    /// ([`crate::model::clearing`]); a planar flight's only ahead of the
    /// plate, +∞ behind it (where its direction is no longer its plane's).
    fn reach_lanes<V: LaneReal>(y: &Lanes<N, V>) -> V;
}

/// Each lane's value of one constant.
#[inline]
fn lanes_of<C, V: LaneReal>(each: &[C; LANES], field: impl Fn(&C) -> f64) -> V {
    V::from_array(std::array::from_fn(|j| field(&each[j])))
}

/// C_D of four flights: by each lane's piece (`pieces`), or by the piece
/// its Re is on if `None`.
///
#[inline(always)]
fn drag_lanes<V: LaneReal>(drag: &impl DragCurve, pieces: Option<V>, re: V, spin_rate: V) -> V {
    let pieces = match pieces {
        Some(pieces) => pieces,
        None => drag.piece_lanes(re),
    };
    drag.coefficient_lanes(pieces, re, spin_rate)
}

impl Default for PlanarConstants<f64> {
    fn default() -> Self {
        Flight::new(&crate::model::scene::Scene::default(), 0.0).constants()
    }
}

impl LaneFlight<4> for Flight {
    type Constants = PlanarConstants<f64>;
    type LaneConstants<V: LaneReal> = PlanarConstants<V>;

    fn constants_of(&self) -> Self::Constants {
        self.constants()
    }

    fn gather<V: LaneReal>(each: &[Self::Constants; LANES]) -> Self::LaneConstants<V> {
        PlanarConstants {
            gravity: lanes_of(each, |c| c.gravity),
            wind: lanes_of(each, |c| c.wind),
            force_per_mass: lanes_of(each, |c| c.force_per_mass),
            reynolds_per_speed: lanes_of(each, |c| c.reynolds_per_speed),
            surface_speed: lanes_of(each, |c| c.surface_speed),
            spin_rate: lanes_of(each, |c| c.spin_rate),
            spin_decay_rate: lanes_of(each, |c| c.spin_decay_rate),
            spin_sign: lanes_of(each, |c| c.spin_sign),
            drag_scale: lanes_of(each, |c| c.drag_scale),
        }
    }

    fn set_lane<V: LaneReal>(lanes: &mut Self::LaneConstants<V>, j: usize, one: &Self::Constants) {
        lanes.gravity.set(j, one.gravity);
        lanes.wind.set(j, one.wind);
        lanes.force_per_mass.set(j, one.force_per_mass);
        lanes.reynolds_per_speed.set(j, one.reynolds_per_speed);
        lanes.surface_speed.set(j, one.surface_speed);
        lanes.spin_rate.set(j, one.spin_rate);
        lanes.spin_decay_rate.set(j, one.spin_decay_rate);
        lanes.spin_sign.set(j, one.spin_sign);
        lanes.drag_scale.set(j, one.drag_scale);
    }

    #[inline(always)]
    fn derivative_lanes<V: LaneReal>(
        c: &Self::LaneConstants<V>,
        (drag, lift): (&impl DragCurve, &impl LiftCurve),
        (pieces, _): (Option<V>, V::Mask),
        t: V,
        y: &Lanes<4, V>,
    ) -> Lanes<4, V> {
        let [_, _, vx, vy] = y.0;
        let (ax, ay) = c.acceleration(
            #[inline(always)]
            |re, spin_rate| drag_lanes(drag, pieces, re, spin_rate),
            lift,
            t,
            (vx, vy),
        );
        Lanes([vx, vy, ax, ay])
    }

    #[inline(always)]
    fn reynolds_lanes<V: LaneReal>(c: &Self::LaneConstants<V>, _: V::Mask, y: &Lanes<4, V>) -> V {
        c.air((y.0[2], y.0[3])).2
    }

    #[inline(always)]
    fn reach_lanes<V: LaneReal>(y: &Lanes<4, V>) -> V {
        let x = y.0[0];
        let behind = x.lt(V::splat(0.0));
        V::select(behind, V::splat(f64::INFINITY), planar_reach_at(x))
    }
}

impl Default for SpatialConstants<f64> {
    fn default() -> Self {
        let scene = crate::model::scene::Scene::default();
        Flight3d::new(&scene, nalgebra::Vector3::zeros()).constants()
    }
}

impl LaneFlight<6> for Flight3d {
    type Constants = SpatialConstants<f64>;
    type LaneConstants<V: LaneReal> = SpatialConstants<V>;

    fn constants_of(&self) -> Self::Constants {
        self.constants()
    }

    fn gather<V: LaneReal>(each: &[Self::Constants; LANES]) -> Self::LaneConstants<V> {
        SpatialConstants {
            gravity: lanes_of(each, |c| c.gravity),
            wind: std::array::from_fn(|i| lanes_of(each, |c| c.wind[i])),
            force_per_mass: lanes_of(each, |c| c.force_per_mass),
            reynolds_per_speed: lanes_of(each, |c| c.reynolds_per_speed),
            spin_axis: std::array::from_fn(|i| lanes_of(each, |c| c.spin_axis[i])),
            drag_scale: lanes_of(each, |c| c.drag_scale),
            spin_rate: lanes_of(each, |c| c.spin_rate),
            surface_speed: lanes_of(each, |c| c.surface_speed),
            spin_decay_rate: lanes_of(each, |c| c.spin_decay_rate),
        }
    }

    fn set_lane<V: LaneReal>(lanes: &mut Self::LaneConstants<V>, j: usize, one: &Self::Constants) {
        lanes.gravity.set(j, one.gravity);
        for i in 0..3 {
            lanes.wind[i].set(j, one.wind[i]);
            lanes.spin_axis[i].set(j, one.spin_axis[i]);
        }
        lanes.force_per_mass.set(j, one.force_per_mass);
        lanes.reynolds_per_speed.set(j, one.reynolds_per_speed);
        lanes.drag_scale.set(j, one.drag_scale);
        lanes.spin_rate.set(j, one.spin_rate);
        lanes.surface_speed.set(j, one.surface_speed);
        lanes.spin_decay_rate.set(j, one.spin_decay_rate);
    }

    #[inline(always)]
    fn derivative_lanes<V: LaneReal>(
        c: &Self::LaneConstants<V>,
        (drag, lift): (&impl DragCurve, &impl LiftCurve),
        (pieces, in_wind): (Option<V>, V::Mask),
        t: V,
        y: &Lanes<6, V>,
    ) -> Lanes<6, V> {
        let [_, _, _, vx, vy, vz] = y.0;
        let [ax, ay, az] = c.acceleration(
            #[inline(always)]
            |re, spin_rate| drag_lanes(drag, pieces, re, spin_rate),
            lift,
            (t, in_wind),
            [vx, vy, vz],
        );
        Lanes([vx, vy, vz, ax, ay, az])
    }

    #[inline(always)]
    fn reynolds_lanes<V: LaneReal>(
        c: &Self::LaneConstants<V>,
        in_wind: V::Mask,
        y: &Lanes<6, V>,
    ) -> V {
        c.air(in_wind, [y.0[3], y.0[4], y.0[5]]).2
    }

    #[inline(always)]
    fn reach_lanes<V: LaneReal>(y: &Lanes<6, V>) -> V {
        spatial_reach_at(y.0[0], y.0[2])
    }
}

/// One flight for the lanes: its position in the caller's list, its
/// forces, and where it starts and how long it is followed.
pub struct LaneJob<const N: usize, D> {
    pub index: usize,
    pub flight: D,
    pub start: State<N>,
    pub time_limit: f64,
    /// How far from home plate (m) the watch starts looking (0: at once):
    /// steps that end short of it, with nothing inside them, pass unseen.
    pub watched_from: f64,
}

/// Shows a flight's step (by the flight's index) to a watcher.
pub type LaneWatch<'r, const N: usize> = &'r mut dyn FnMut(usize, &Step<N>);

/// What the caller is told: each step of a flight (if it watches), and
/// each flight's summary, by the flight's index.
pub struct LaneReports<'r, const N: usize> {
    pub watch: Option<LaneWatch<'r, N>>,
    pub done: LaneDone<'r>,
}

/// How a flight's end is told, by the flight's index.
pub enum LaneDone<'r> {
    /// Its whole summary.
    Summary(&'r mut dyn FnMut(usize, FlightSummary)),
    /// What its range needs alone: no apex is located (a step that only
    /// passes it is left unseen), and no landing speed, angle or direction
    /// worked out. The same flight, to the bit, as with its whole summary.
    Range(&'r mut dyn FnMut(usize, RangeSummary)),
}

impl LaneDone<'_> {
    /// Whether the flights' apexes are wanted.
    fn locates_apex(&self) -> bool {
        matches!(self, LaneDone::Summary(_))
    }

    /// The same, borrowed for a shorter while.
    pub fn reborrow(&mut self) -> LaneDone<'_> {
        match self {
            LaneDone::Summary(done) => LaneDone::Summary(*done),
            LaneDone::Range(done) => LaneDone::Range(*done),
        }
    }
}

/// Four flights' worth of lanes (numbers `V`), with their events, fed
/// from `jobs`.
struct FlightLanes<'r, const N: usize, V: LaneReal, D: LaneFlight<N>, Dr, L, J> {
    models: (Dr, L),
    stop_at_kinks: bool,
    /// Whether the events locate the apex ([`LaneDone::locates_apex`]).
    locates_apex: bool,
    /// Whether the lanes switch drag pieces at the kinks (else each
    /// evaluation takes the piece its Re is on).
    switching: bool,
    constants: D::LaneConstants<V>,
    /// Each lane's regime: its drag piece (a float) and whether it is in
    /// the wind (a lane mask), and what the regime bounds.
    pieces: V,
    in_wind: V::Mask,
    bounds: Bounds<V>,
    /// Each lane's [`LaneJob::watched_from`].
    watched_from: V,
    events: [Option<Events<N, D>>; LANES],
    index: [usize; LANES],
    jobs: J,
    reports: LaneReports<'r, N>,
}

impl<const N: usize, V: LaneReal, D: LaneFlight<N>, Dr, L, J> FlightLanes<'_, N, V, D, Dr, L, J> {
    /// Lane `j`'s regime from its events.
    fn set_regime(&mut self, j: usize, (regime, bounds): (Regime, Bounds<f64>)) {
        self.pieces.set(j, regime.piece.unwrap_or_default() as f64);
        V::set_mask(&mut self.in_wind, j, regime.in_wind);
        self.bounds.kink_below.set(j, bounds.kink_below);
        self.bounds.kink_above.set(j, bounds.kink_above);
        self.bounds.wind_height.set(j, bounds.wind_height);
        V::set_mask(&mut self.bounds.in_wind, j, regime.in_wind);
    }
}

impl<const N: usize, V, D, Dr, L, J> LaneSystem<N, V> for FlightLanes<'_, N, V, D, Dr, L, J>
where
    V: LaneReal,
    D: LaneFlight<N>,
    Dr: DragCurve,
    L: LiftCurve,
    J: Iterator<Item = LaneJob<N, D>>,
{
    #[inline(always)]
    fn derivative(&self, t: V, y: &Lanes<N, V>) -> Lanes<N, V> {
        let pieces = if self.switching {
            Some(self.pieces)
        } else {
            None
        };
        D::derivative_lanes(
            &self.constants,
            (&self.models.0, &self.models.1),
            (pieces, self.in_wind),
            t,
            y,
        )
    }

    fn derivative_lane(&self, lane: usize, t: f64, y: &State<N>) -> State<N> {
        match &self.events[lane] {
            Some(events) => {
                let Regime { piece, in_wind } = events.regime();
                let models = (&self.models.0, &self.models.1);
                events
                    .flight()
                    .derivative_with(models, t, y, piece, in_wind)
            }
            None => State::<N>::zeros(),
        }
    }

    fn observe(&mut self, lane: usize, step: &Step<N>) -> Control {
        let Some(events) = self.events[lane].as_mut() else {
            return Control::Stop;
        };
        let index = self.index[lane];
        let control = match self.reports.watch.as_mut() {
            Some(watch) => events.observe(step, &mut |s: &Step<N>| watch(index, s)),
            None => events.observe(step, &mut |_: &Step<N>| {}),
        };
        let regime = (events.regime(), events.bounds());
        self.set_regime(lane, regime);
        control
    }

    #[inline(always)]
    fn quiet(
        &mut self,
        accepted: V::Mask,
        (t0, t1, h): (V, V, V),
        (y0, y1): (&Lanes<N, V>, &Lanes<N, V>),
    ) -> (V::Mask, V) {
        // A watched step short of where its watch starts looking is left
        // unseen like any other, its next step's end reckoned as the
        // observer would, from the step's ends (t1 − t0, which may differ
        // from h in the last bit), so that the flight is the same to the
        // bit. Unwatched lanes keep h.
        let (unwatched, h) = if self.reports.watch.is_some() {
            let short = D::reach_lanes(y1).lt(self.watched_from);
            (short, t1 - t0)
        } else {
            (accepted, h)
        };
        let vertical_velocities = (y0.0[D::VERTICAL_VELOCITY], y1.0[D::VERTICAL_VELOCITY]);
        let apex = passes_apex(vertical_velocities);
        // Where no apex is located, a step that only passes it is unseen
        // too, its next end reckoned as its observer reckons it (from
        // t1 − t0), so that the flight is the one located apexes give.
        let (apex, h) = if self.locates_apex {
            (apex, h)
        } else {
            (V::mask_of([false; LANES]), V::select(apex, t1 - t0, h))
        };
        let reynolds = if self.switching {
            (
                D::reynolds_lanes(&self.constants, self.in_wind, y0),
                D::reynolds_lanes(&self.constants, self.in_wind, y1),
            )
        } else {
            (V::splat(0.0), V::splat(0.0))
        };
        let ends = StepEnds {
            t1,
            h,
            heights: (y0.0[D::HEIGHT], y1.0[D::HEIGHT]),
            vertical_velocities,
            reynolds,
        };
        let eventful = switches_or_lands(&ends, &self.bounds) | apex;
        let quiet = accepted & unwatched & !eventful;
        (quiet, end_next_by(&ends, &self.bounds))
    }

    fn finish(&mut self, lane: usize, outcome: Outcome, stats: Stats, end: (f64, State<N>)) {
        if let Some(mut events) = self.events[lane].take() {
            // Quiet steps were not shown to it: the flight's last point.
            events.last = end;
            let (index, landed) = (self.index[lane], outcome == Outcome::Stopped);
            match &mut self.reports.done {
                LaneDone::Summary(done) => done(index, events.summary(landed, stats)),
                LaneDone::Range(done) => done(index, events.range_summary(landed, stats)),
            }
        }
    }

    fn refill(&mut self, lane: usize) -> Option<LaneStart<N>> {
        let job = self.jobs.next()?;
        let events = Events::new(
            job.flight,
            &job.start,
            (self.stop_at_kinks, self.locates_apex),
        );
        self.set_regime(lane, (events.regime(), events.bounds()));
        self.events[lane] = Some(events);
        self.index[lane] = job.index;
        self.watched_from.set(lane, job.watched_from);
        D::set_lane(&mut self.constants, lane, &job.flight.constants_of());
        Some(LaneStart {
            t0: 0.0,
            y0: job.start,
            t_end: job.time_limit,
        })
    }
}

/// Flies `jobs` in lock-step, four at a time, every flight with the
/// models of the first (the caller groups them so), reporting to
/// `reports`: each as [`super::fly`] would fly it alone, to its tolerance.
/// Each flight starts from its neighbour's first step, or with
/// [`FirstSteps::Guessed`] from its own, as a flight alone does.
pub fn fly_lanes<const N: usize, D: LaneFlight<N>>(
    first_steps: FirstSteps,
    jobs: impl Iterator<Item = LaneJob<N, D>>,
    options: &FlightOptions,
    reports: LaneReports<'_, N>,
) {
    let mut jobs = jobs.peekable();
    let Some(first) = jobs.peek() else {
        return;
    };
    let (drag, lift) = (first.flight.drag(), first.flight.lift());
    let run = Run {
        first_steps,
        jobs,
        options: *options,
        reports,
        flight: std::marker::PhantomData,
    };
    drag.with_lift(lift, run);
}

/// [`fly_lanes`] once the models are known.
struct Run<'r, const N: usize, D, J> {
    first_steps: FirstSteps,
    jobs: J,
    options: FlightOptions,
    reports: LaneReports<'r, N>,
    flight: std::marker::PhantomData<D>,
}

impl<const N: usize, D, J> WithModels for Run<'_, N, D, J>
where
    D: LaneFlight<N>,
    J: Iterator<Item = LaneJob<N, D>>,
{
    type Output = ();

    fn run<Dr: DragCurve + Copy, L: LiftCurve + Copy>(self, drag: Dr, lift: L) {
        let none = [false; LANES];
        let mut system: FlightLanes<N, Lane, D, Dr, L, J> = FlightLanes {
            switching: self.options.stop_at_kinks && !drag.kinks().is_empty(),
            models: (drag, lift),
            stop_at_kinks: self.options.stop_at_kinks,
            locates_apex: self.reports.done.locates_apex(),
            constants: D::gather(&[D::Constants::default(); LANES]),
            pieces: Lane::splat(0.0),
            in_wind: Lane::mask_of(none),
            bounds: Bounds {
                kink_below: Lane::splat(0.0),
                kink_above: Lane::splat(0.0),
                wind_height: Lane::splat(0.0),
                in_wind: Lane::mask_of(none),
            },
            watched_from: Lane::splat(0.0),
            events: [const { None }; LANES],
            index: [0; LANES],
            jobs: self.jobs,
            reports: self.reports,
        };
        let settings = Settings::new(self.options.tolerance);
        integrate_lanes(&mut system, &settings, self.first_steps);
    }
}
