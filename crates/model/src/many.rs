//! Many flights at once: [`fly_many`] flies a list of scene flights in
//! lock-step, four at a time ([`super::flight::lanes`]), each as
//! [`SceneFlight::fly`] would alone, to the same tolerance; [`judge_many`]
//! also finds where each crosses its fences, as
//! [`SceneFlight::fly_to_fences`] does.
//!
//! The flights are grouped by kind (planar or 3-D) and aero models, each
//! group flown by lanes compiled for its models; within a group they are
//! flown in the list's order, a lane that finishes taking the next, with
//! the first step its neighbours found ([`judge_many`]: each from its own,
//! so that every answer is the flight's own). Results come in the order
//! the flights finish, each with its index in the list.

use super::aero::DragModel;
use super::clearing::Clearing;
use super::clearing::{Crossing, planar_reach, spatial_reach, watch_planar, watch_spatial};
use super::flight::lanes::{LaneDone, LaneJob, LaneReports, fly_lanes};
use super::flight::{FlightOptions, FlightSummary, RangeSummary, Start};
use super::launch::{self, SceneFlight};
use super::park::{Fence, GivenWeather, Park};
use super::scene::Scene;
use numerics::ode::lanes::FirstSteps;

/// Flies every flight of `flights`, calling `done(index, summary)` for
/// each as it finishes (`index` its place in `flights`).
pub fn fly_many(
    flights: impl IntoIterator<Item = SceneFlight>,
    options: &FlightOptions,
    mut done: impl FnMut(usize, FlightSummary),
) {
    fly_groups(flights, options, LaneDone::Summary(&mut done));
}

/// As [`fly_many`], telling `done(index, range)` only what each flight's
/// range needs: the same flights, bit for bit, without locating their
/// apexes or working out how they come down.
pub fn land_many(
    flights: impl IntoIterator<Item = SceneFlight>,
    options: &FlightOptions,
    mut done: impl FnMut(usize, RangeSummary),
) {
    fly_groups(flights, options, LaneDone::Range(&mut done));
}

/// [`fly_many`] and [`land_many`]: the flights in groups that fly alike,
/// each lane from its neighbour's first step, nothing watched.
fn fly_groups(
    flights: impl IntoIterator<Item = SceneFlight>,
    options: &FlightOptions,
    mut done: LaneDone<'_>,
) {
    let flights: Vec<SceneFlight> = flights.into_iter().collect();
    for group in groups(&flights) {
        let done = done.reborrow();
        fly_group(
            FirstSteps::FromNeighbours,
            &flights,
            &group,
            options,
            None,
            &[],
            done,
        );
    }
}

/// `scene` judged at each of `parks`, in order, on a flight of its own in
/// that park's air (the standard air at its elevation, the weather
/// `given` kept: [`GivenWeather::park_air`]), flown in lock-step: what
/// `fly --park` gives at each.
pub fn judged_in_own_air(
    scene: &Scene,
    parks: &[Park],
    given: GivenWeather,
    options: &FlightOptions,
) -> Vec<Clearing> {
    let fences: Vec<&Fence> = parks.iter().map(|p| &p.fence).collect();
    let flights = parks.iter().zip(&fences).map(|(park, fence)| {
        let mut there = *scene;
        given.park_air(&mut there.environment, park.elevation);
        (launch::scene_start(&there).0, std::slice::from_ref(fence))
    });
    let mut judged = vec![None; parks.len()];
    judge_many(flights, options, |k, summary, crossings| {
        judged[k] = Some(Clearing::judge(fences[k], crossings[0], &summary));
    });
    judged
        .into_iter()
        .map(|c| c.expect("every park flown"))
        .collect()
}

/// As [`fly_many`], each flight taken to its fences (`fences[k]` for the
/// k-th flight): `done(index, summary, crossings)` is told where the ball's
/// track first crossed each of its fences. Every answer is the flight's
/// own, bit for bit [`SceneFlight::fly_to_fences`]'s whatever its
/// neighbours: in lock-step from its own first step where the lanes fly it
/// alike ([`flies_alone_alike`]), else alone.
pub fn judge_many<'f>(
    flights: impl IntoIterator<Item = (SceneFlight, &'f [&'f Fence])>,
    options: &FlightOptions,
    mut done: impl FnMut(usize, FlightSummary, &[Option<Crossing>]),
) {
    let flights: Vec<(SceneFlight, &[&Fence])> = flights.into_iter().collect();
    let (alike, alone): (Vec<usize>, Vec<usize>) =
        (0..flights.len()).partition(|&k| flies_alone_alike(&flights[k].0));
    let how = (true, FirstSteps::Guessed);
    judge_many_shown(
        alike.iter().map(|&k| flights[k]),
        options,
        how,
        |i, summary, found| {
            done(alike[i], summary, found);
        },
    );
    let mut found = Vec::new();
    for k in alone {
        let (flight, fences) = flights[k];
        found.clear();
        found.resize(fences.len(), None);
        let summary = flight.fly_to_fences(options, fences, &mut found);
        done(k, summary, &found);
    }
}

/// Whether the lanes, from the flight's own first step
/// ([`judge_many`]), fly `flight` bit for bit as it flies alone: its
/// forces take no exponential (the lanes' is `real::exp_lanes`, within a
/// few ulp of libm's but not equal), so every operation of theirs is
/// exactly rounded, and alike in both: not on the paper's drag crisis,
/// nor with the spin decaying.
pub fn flies_alone_alike(flight: &SceneFlight) -> bool {
    let (drag, decays) = match flight {
        SceneFlight::Planar { flight, .. } => (flight.drag, flight.spin_decay_rate != 0.0),
        SceneFlight::Spatial { flight, .. } => (flight.drag, flight.spin_decay_rate != 0.0),
    };
    drag != DragModel::Sawicki2003 && !decays
}

/// [`judge_many`], its steps shown to the watch from where some wall may
/// be near (`shortcut`), or every one of them (as before that shortcut: a
/// test holds the two to the same bits).
fn judge_many_shown<'f>(
    flights: impl IntoIterator<Item = (SceneFlight, &'f [&'f Fence])>,
    options: &FlightOptions,
    (shortcut, first_steps): (bool, FirstSteps),
    mut done: impl FnMut(usize, FlightSummary, &[Option<Crossing>]),
) {
    let (flights, fences): (Vec<SceneFlight>, Vec<&[&Fence]>) = flights.into_iter().unzip();
    // One slot per fence per flight, each flight's at its offset.
    let mut offsets = Vec::with_capacity(fences.len() + 1);
    offsets.push(0);
    for f in &fences {
        offsets.push(offsets.last().copied().unwrap_or(0) + f.len());
    }
    let mut crossings = vec![None; offsets.last().copied().unwrap_or(0)];
    // Each flight's nearest wall: short of it, a step is short of them all
    // (most steps of most flights), and no fence need see it.
    let closest: Vec<f64> = fences
        .iter()
        .map(|list| {
            list.iter()
                .map(|f| f.nearest())
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    // Where the lanes start showing a flight's steps to the watch: its
    // nearest wall, or for a planar flight (its direction its plane's,
    // ahead of the plate) the nearest wall along its plane, by each fence's
    // table (what the watch itself checks first).
    let watched_from: Vec<f64> = flights
        .iter()
        .zip(&fences)
        .zip(&closest)
        .map(|((flight, list), &closest)| match flight {
            SceneFlight::Planar { plane, .. } => list
                .iter()
                .map(|f| f.nearest().max(f.surely_short(*plane)))
                .fold(f64::INFINITY, f64::min),
            SceneFlight::Spatial { .. } => closest,
        })
        .map(|from| if shortcut { from } else { 0.0 })
        .collect();
    for group in groups(&flights) {
        let crossings = std::cell::RefCell::new(&mut crossings);
        let mut watch = |index: usize, step: &dyn WatchedStep| {
            if step.reach() < closest[index] {
                return;
            }
            let mut all = crossings.borrow_mut();
            let mine = &mut all[offsets[index]..offsets[index + 1]];
            step.watch(&flights[index], fences[index], mine);
        };
        let mut finished = |index: usize, summary: FlightSummary| {
            let all = crossings.borrow();
            done(index, summary, &all[offsets[index]..offsets[index + 1]]);
        };
        fly_group(
            first_steps,
            &flights,
            &group,
            options,
            Some(&mut watch),
            &watched_from,
            LaneDone::Summary(&mut finished),
        );
    }
}

/// Shows a step of either kind (by its flight's index) to the fences.
type FencesWatch<'w> = &'w mut dyn FnMut(usize, &dyn WatchedStep);

/// A step of either kind of flight, for the fences' watch.
trait WatchedStep {
    fn watch(&self, flight: &SceneFlight, fences: &[&Fence], crossings: &mut [Option<Crossing>]);
    /// How far from home plate the step ends (m), never short of what the
    /// watch works out (a few ulps over).
    fn reach(&self) -> f64;
}

impl WatchedStep for numerics::ode::Step<'_, 4> {
    fn reach(&self) -> f64 {
        planar_reach(self)
    }

    fn watch(&self, flight: &SceneFlight, fences: &[&Fence], crossings: &mut [Option<Crossing>]) {
        if let SceneFlight::Planar { plane, .. } = flight {
            watch_planar(self, *plane, fences, crossings);
        }
    }
}

impl WatchedStep for numerics::ode::Step<'_, 6> {
    fn reach(&self) -> f64 {
        spatial_reach(self)
    }

    fn watch(&self, _: &SceneFlight, fences: &[&Fence], crossings: &mut [Option<Crossing>]) {
        watch_spatial(self, fences, crossings);
    }
}

/// The indices of `flights` of each kind and pair of models, in order.
fn groups(flights: &[SceneFlight]) -> Vec<Vec<usize>> {
    let key = |f: &SceneFlight| match f {
        SceneFlight::Planar { flight, .. } => (true, flight.drag, flight.lift),
        SceneFlight::Spatial { flight, .. } => (false, flight.drag, flight.lift),
    };
    let mut groups: Vec<(_, Vec<usize>)> = Vec::new();
    for (index, flight) in flights.iter().enumerate() {
        let k = key(flight);
        match groups.iter_mut().find(|(g, _)| *g == k) {
            Some((_, members)) => members.push(index),
            None => groups.push((k, vec![index])),
        }
    }
    groups.into_iter().map(|(_, members)| members).collect()
}

/// Flies one group (all planar or all 3-D, with the same models). The
/// watch, if any, looks at flight k's steps from `watched_from[k]` metres
/// from home plate on (and at any step with an event inside).
fn fly_group(
    first_steps: FirstSteps,
    flights: &[SceneFlight],
    group: &[usize],
    options: &FlightOptions,
    mut watch: Option<FencesWatch<'_>>,
    watched_from: &[f64],
    mut done: LaneDone<'_>,
) {
    let watched_from = |index: usize| watched_from.get(index).copied().unwrap_or(0.0);
    let planar = group
        .first()
        .is_some_and(|&index| flights[index].is_planar());
    if planar {
        let jobs = group.iter().filter_map(|&index| match flights[index] {
            SceneFlight::Planar { flight, launch, .. } => Some(LaneJob {
                index,
                flight,
                start: launch.state(),
                time_limit: launch.time_limit(flight.gravity),
                watched_from: watched_from(index),
            }),
            SceneFlight::Spatial { .. } => None,
        });
        let mut step_watch = watch
            .as_mut()
            .map(|w| move |index: usize, step: &numerics::ode::Step<4>| w(index, step));
        // A planar summary's direction is its plane's (a range has none).
        let mut with_plane = match done {
            LaneDone::Summary(done) => Ok(move |index: usize, summary: FlightSummary| {
                let direction = match flights[index] {
                    SceneFlight::Planar { plane, .. } => plane,
                    SceneFlight::Spatial { .. } => summary.direction,
                };
                done(
                    index,
                    FlightSummary {
                        direction,
                        ..summary
                    },
                );
            }),
            LaneDone::Range(done) => Err(done),
        };
        let done = match &mut with_plane {
            Ok(finished) => LaneDone::Summary(finished),
            Err(done) => LaneDone::Range(*done),
        };
        let reports = LaneReports {
            watch: step_watch
                .as_mut()
                .map(|w| w as &mut dyn FnMut(usize, &numerics::ode::Step<4>)),
            done,
        };
        fly_lanes(first_steps, jobs, options, reports);
    } else {
        let jobs = group.iter().filter_map(|&index| match flights[index] {
            SceneFlight::Spatial { flight, launch } => Some(LaneJob {
                index,
                flight,
                start: launch.state(),
                time_limit: launch.time_limit(flight.gravity),
                watched_from: watched_from(index),
            }),
            SceneFlight::Planar { .. } => None,
        });
        let mut step_watch = watch
            .as_mut()
            .map(|w| move |index: usize, step: &numerics::ode::Step<6>| w(index, step));
        let reports = LaneReports {
            watch: step_watch
                .as_mut()
                .map(|w| w as &mut dyn FnMut(usize, &numerics::ode::Step<6>)),
            done: done.reborrow(),
        };
        fly_lanes(first_steps, jobs, options, reports);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flight::FlightOptions;
    use crate::launch::BattedBall;
    use crate::scene::Scene;
    use numerics::ode::Tolerance;

    /// A batted ball of `scene`, its speed (m/s), angle (°) and backspin
    /// (rad/s) drawn from the ranges given; with `spray`, its direction
    /// and sidespin too.
    fn batted(
        scene: Scene,
        spray: bool,
        (speed, angle, spin): ((f64, f64), (f64, f64), (f64, f64)),
        uniform: &mut impl FnMut() -> f64,
    ) -> SceneFlight {
        let mut between = |(low, high): (f64, f64)| low + (high - low) * uniform();
        let scene = scene.with_launch(BattedBall {
            speed: between(speed),
            angle: between(angle).to_radians(),
            spin: between(spin),
            direction: if spray { between((-0.8, 0.8)) } else { 0.0 },
            sidespin: if spray { between((-100.0, 100.0)) } else { 0.0 },
        });
        SceneFlight::new(&scene, &scene.batted_ball())
    }

    /// A generic fence and the 30 bundled parks': the 31 a batch row meets.
    fn with_parks(generic: &Fence) -> Vec<&Fence> {
        std::iter::once(generic)
            .chain(crate::park::bundled().iter().map(|p| &p.fence))
            .collect()
    }

    /// Fly balls and line drives (planar and with spray and sidespin, at
    /// the bundled parks' fences and a generic one): shown to the watch
    /// only from where a wall may be near, every flight, every crossing and
    /// its summary are those of flights shown every step, to the bit.
    #[test]
    fn steps_left_unseen_change_no_bit_of_a_flight_or_a_crossing() {
        let generic = Fence::uniform(121.92, 3.0);
        let fences = with_parks(&generic);
        let mut uniform = numerics::xorshift::uniform(0x9e37_79b9_7f4a_7c15);
        let mut flights = Vec::new();
        for i in 0..160 {
            let mut scene = Scene::default();
            if i % 4 != 0 {
                scene.set_text("model.drag", "nathan").unwrap();
                scene.set_text("model.lift", "nathan").unwrap();
            }
            let ranges = ((38.0, 52.0), (5.0, 50.0), (150.0, 350.0));
            flights.push(batted(scene, i % 2 == 1, ranges, &mut uniform));
        }
        type Judged = Vec<Option<(FlightSummary, Vec<Option<Crossing>>)>>;
        let judge = |shortcut: bool, tolerance: f64| {
            let mut judged: Judged = vec![None; flights.len()];
            let rows = flights.iter().map(|f| (*f, &fences[..]));
            let options = FlightOptions {
                tolerance: Tolerance::uniform(tolerance),
                stop_at_kinks: true,
            };
            let how = (shortcut, FirstSteps::FromNeighbours);
            judge_many_shown(rows, &options, how, |index, summary, crossings| {
                judged[index] = Some((summary, crossings.to_vec()));
            });
            judged
        };
        // A loose tolerance and the readout's (analysis::precision's
        // Purpose::Readout, which model may not import).
        for tolerance in [3e-9, 1e-10] {
            let (shown, every) = (judge(true, tolerance), judge(false, tolerance));
            let mut crossed = 0;
            for (a, b) in shown.iter().zip(&every) {
                let ((a, a_at), (b, b_at)) = (a.as_ref().unwrap(), b.as_ref().unwrap());
                assert_eq!(format!("{a:?}"), format!("{b:?}"));
                assert_eq!(a_at, b_at);
                crossed += a_at.iter().flatten().count();
            }
            // Some balls cross some fences, not all.
            assert!(
                crossed > 100 && crossed < 160 * fences.len() / 2,
                "{crossed}"
            );
        }
    }

    /// Batch-like rows (Nathan's drag and lift, planar and with spray and
    /// sidespin, the spin decaying or not) at the readout's tolerance, at
    /// the generic fence and the bundled parks' (31): every summary and
    /// crossing [`judge_many`] gives is bit for bit that of the flight alone
    /// (in lock-step from its own first step where [`flies_alone_alike`]
    /// says so, the others, whose spin decays, alone).
    #[test]
    fn lanes_from_their_own_first_steps_fly_as_each_flight_alone() {
        let generic = Fence::uniform(121.92, 3.0);
        let fences = with_parks(&generic);
        assert_eq!(fences.len(), 31);
        let mut uniform = numerics::xorshift::uniform(0x2545_f491_4f6c_dd1d);
        let mut flights = Vec::new();
        for i in 0..240 {
            let mut scene = Scene::default();
            scene.set_text("model.drag", "nathan").unwrap();
            scene.set_text("model.lift", "nathan").unwrap();
            if i % 3 == 2 {
                scene.set_text("model.spin_decay", "30").unwrap();
            }
            let ranges = ((30.0, 54.0), (-5.0, 50.0), (20.0, 470.0));
            flights.push(batted(scene, i % 2 == 1, ranges, &mut uniform));
        }
        // The readout's tolerance (Purpose::Readout, which model may not
        // import).
        let options = FlightOptions {
            tolerance: Tolerance::uniform(1e-10),
            stop_at_kinks: true,
        };
        let mut lanes: Vec<Option<(FlightSummary, Vec<Option<Crossing>>)>> =
            vec![None; flights.len()];
        let rows = flights.iter().map(|f| (*f, &fences[..]));
        judge_many(rows, &options, |index, summary, crossings| {
            lanes[index] = Some((summary, crossings.to_vec()));
        });
        let (mut alike, mut crossed) = (0, 0);
        for (flight, lanes) in flights.iter().zip(&lanes) {
            let (in_lanes, lanes_at) = lanes.as_ref().unwrap();
            let mut at = vec![None; fences.len()];
            let alone = flight.fly_to_fences(&options, &fences, &mut at);
            let same = format!("{alone:?}") == format!("{in_lanes:?}") && at == *lanes_at;
            assert!(same, "{alone:?}\n{in_lanes:?}");
            alike += usize::from(flies_alone_alike(flight));
            crossed += at.iter().flatten().count();
        }
        assert_eq!(alike, 160);
        // Some balls cross some fences, not all.
        assert!(crossed > 300 && crossed < 240 * 31 / 2, "{crossed}");
    }
}
