//! A piece of a batch flown: each row's launch completed (the spin
//! estimated, the direction solved: [`savant::launch`]), flown once to the
//! ground and its fences, and judged there and at every park.
//!
//! CSV rows fly at [`Purpose::Batch`], looser than the readout, and each is
//! then checked ([`settled`]): a row whose printed digits, or any of its
//! outcomes, that flight cannot settle is flown again at
//! [`Purpose::Readout`], as `fly` flies it. So the batch prints what `fly`
//! prints, digit for digit. JSON prints every digit, so it flies at the
//! readout's precision throughout.

use super::fixed;
use super::rows::Job;
use super::savant_columns::Setup;
use crate::Scene;
use crate::analysis::precision::{BATCH_GUARD, Guard, Purpose};
use crate::analysis::savant;
use crate::cli::shown::Shown;
use crate::model::clearing::{Clearing, Crossing, Landing};
use crate::model::flight::{FlightOptions, FlightSummary};
use crate::model::launch::{self, BattedBall, SceneFlight};
use crate::model::many;
use crate::model::park::{self, GivenWeather};
use crate::units::Quantity;

/// A row's flight, as the output needs it.
#[derive(Clone, Copy, Debug)]
pub(super) struct RowFlight {
    pub launch: BattedBall,
    pub flight: FlightSummary,
    /// At the row's own fence (its park's, or the generic one).
    pub clearing: Clearing,
    pub parks_cleared: usize,
    /// Where the parks cleared are marked, one flag a park, in
    /// [`Scratch::cleared`].
    pub cleared_from: usize,
    /// Flights spent solving the launch direction.
    pub flights: usize,
}

/// What flying a piece reuses from row to row.
#[derive(Default)]
pub(super) struct Scratch {
    /// Each row's crossings of its fences: its own, then each park's.
    crossings: Vec<Option<Crossing>>,
    /// The rows to fly again, the places among their verdicts of those
    /// left undecided (each row's [`Again::undecided`]), and their
    /// crossings of the fences they are judged at again.
    again: Vec<Again>,
    undecided: Vec<usize>,
    crossings_again: Vec<Option<Crossing>>,
    summaries: Vec<FlightSummary>,
    /// The row's judging: at its own fence, then at each park.
    judged: Judged,
    /// For each row flown, a flag per park: cleared.
    pub cleared: Vec<bool>,
    /// Rows flown twice (unsettled at the batch's precision).
    pub refined: usize,
}

/// A row judged: at its own fence in full (its margin is printed), at each
/// park as far as the output needs.
#[derive(Default)]
struct Judged {
    own: Option<Clearing>,
    parks: Vec<Verdict>,
}

/// A park's judging of a row, as the batch prints it.
#[derive(Clone, Copy)]
struct Verdict {
    clears: bool,
    /// The outcome stands [`BATCH_GUARD`] from each of its thresholds
    /// ([`decided`]).
    decided: bool,
}

impl Verdict {
    /// `flight` judged at `fence`. A ball that crossed no fence and came
    /// down fair or foul by more than the guard, short of the fence's
    /// nearest point by more than the guard, or of the wall in its landing
    /// direction by the fence's table ([`park::Fence::surely_short`]), is
    /// short (or foul) and decided there without looking the wall up: most
    /// rows, at most parks.
    fn of(
        fence: &park::Fence,
        crossing: Option<Crossing>,
        flight: &FlightSummary,
        landing: Landing,
    ) -> Verdict {
        let guard = BATCH_GUARD;
        let short_of = |wall: f64| flight.range.abs() < wall - guard.distance;
        let far_short = crossing.is_none()
            && flight.landed
            && (landing.direction.abs() - park::FOUL_LINE).abs() > guard.angle
            && (short_of(fence.nearest()) || short_of(fence.surely_short(landing.direction)));
        if far_short {
            return Verdict {
                clears: false,
                decided: true,
            };
        }
        let clearing = Clearing::judge_landed(fence, crossing, flight, landing);
        Verdict {
            clears: clearing.clears(),
            decided: decided(&clearing, guard),
        }
    }
}

impl Verdict {
    /// Whether the row is short at every one of `parks` (fences and the
    /// row's crossings of them) by [`Verdict::of`]'s first test, at once:
    /// it crossed none, came down fair or foul by more than the guard, and
    /// short by more than the guard of `nearest`, the nearest of all their
    /// walls. Most rows, for a batch judged at the 30 parks.
    fn short_of_all(
        (fences, crossings): (&[&park::Fence], &[Option<Crossing>]),
        nearest: f64,
        flight: &FlightSummary,
        landing: Landing,
    ) -> bool {
        let guard = BATCH_GUARD;
        debug_assert!(fences.iter().all(|f| f.nearest() >= nearest));
        flight.landed
            && flight.range.abs() < nearest - guard.distance
            && (landing.direction.abs() - park::FOUL_LINE).abs() > guard.angle
            && crossings.iter().all(Option::is_none)
    }
}

/// The nearest of the walls of `parks` (m): +∞ for none.
pub(super) fn nearest_wall(parks: &[&park::Fence]) -> f64 {
    parks
        .iter()
        .map(|f| f.nearest())
        .fold(f64::INFINITY, f64::min)
}

/// What the output prints of a row, for [`settled`].
#[derive(Clone, Copy)]
pub(super) struct Printed {
    pub shown: Shown,
    /// The `difference` column (range less Statcast's) is printed.
    pub statcast: bool,
    pub json: bool,
}

/// A row ready to fly: its launch complete and checked, and the fence it
/// is judged at (its park's, or the generic one).
pub(super) struct Ready<'f> {
    scene: Scene,
    pub flight: SceneFlight,
    launch: BattedBall,
    flights: usize,
    pub own: &'f park::Fence,
}

/// Flies `jobs` into `out`, in order (a reason where a row cannot fly), in
/// four steps: each row made ready; every row flown once ([`fly_all`],
/// in lock-step); each judged and checked; the unsettled ones flown again
/// together at the readout's precision ([`judge_again`]).
pub(super) fn fly_chunk(
    jobs: &[Job],
    setup: &Setup,
    printed: Printed,
    scratch: &mut Scratch,
    out: &mut Vec<Result<RowFlight, String>>,
) {
    out.clear();
    scratch.cleared.clear();
    scratch.refined = 0;
    let purpose = if printed.json {
        Purpose::Readout
    } else {
        Purpose::Batch
    };
    // The generic fences of the piece (one, unless rows give field.*).
    let mut generic: Vec<(crate::preset::Fence, park::Fence)> = Vec::new();
    for job in jobs.iter().filter(|j| j.park.is_none()) {
        if !generic.iter().any(|(f, _)| *f == job.fence) {
            generic.push((job.fence, job.fence.uniform()));
        }
    }
    let own = |job: &Job| match job.park {
        Some(index) => setup.fences[index],
        None => {
            &generic
                .iter()
                .find(|(f, _)| *f == job.fence)
                .expect("cached")
                .1
        }
    };
    let rows = jobs.iter().map(|job| (&job.scene, &job.launch));
    let solve = Purpose::Solve.flight_options();
    let launched = savant::launch_many(rows, setup.spray, &solve);
    let ready: Vec<Result<Ready, String>> = (jobs.iter().zip(launched))
        .map(|(job, launched)| ready(job, launched, own(job)))
        .collect();
    // With --own-air each park is judged on a flight in its own air.
    let parks: &[&park::Fence] = if setup.own_air { &[] } else { &setup.fences };
    let flying: Vec<&Ready> = ready.iter().flatten().collect();
    fly_all(
        &flying,
        parks,
        &purpose.flight_options(),
        &mut scratch.crossings,
        &mut scratch.summaries,
    );
    let parks_nearest = nearest_wall(parks);
    let width = parks.len() + 1;
    let mut flown = 0;
    let mut fences: Vec<&park::Fence> = Vec::with_capacity(width);
    scratch.again.clear();
    scratch.undecided.clear();
    for (row, (job, ready)) in jobs.iter().zip(&ready).enumerate() {
        let ready = match ready {
            Ok(ready) => ready,
            Err(reason) => {
                out.push(Err(reason.clone()));
                continue;
            }
        };
        fences.clear();
        fences.push(ready.own);
        fences.extend_from_slice(parks);
        let own_air = setup.own_air.then_some((setup, job.given));
        let crossings = &scratch.crossings[flown * width..][..width];
        let summary = scratch.summaries[flown];
        flown += 1;
        judge(
            ready,
            (&fences, parks_nearest),
            crossings,
            &summary,
            own_air,
            &purpose.flight_options(),
            &mut scratch.judged,
        );
        let settled = settled(
            &summary,
            ready.flight.is_planar(),
            &scratch.judged,
            printed,
            job,
        );
        let from = scratch.cleared.len();
        if purpose == Purpose::Batch && !settled.all {
            // Flown again below, with the piece's other such rows.
            scratch.refined += 1;
            let first = scratch.undecided.len();
            let parks = scratch.judged.parks.iter().enumerate();
            let undecided = parks.filter(|(_, v)| !v.decided).map(|(k, _)| k);
            scratch.undecided.extend(undecided);
            scratch.again.push(Again {
                row,
                own_settled: settled.own,
                undecided: first..scratch.undecided.len(),
            });
        }
        let cleared = scratch.judged.parks.iter().map(|v| v.clears);
        scratch.cleared.extend(cleared);
        out.push(Ok(RowFlight {
            launch: ready.launch,
            flight: summary,
            clearing: scratch.judged.own.expect("judged at its own fence"),
            parks_cleared: scratch.cleared[from..].iter().filter(|&&c| c).count(),
            cleared_from: from,
            flights: ready.flights,
        }));
    }
    let own_air = setup.own_air.then_some(setup);
    judge_again(jobs, &ready, (parks, own_air), scratch, out);
}

/// Flies each row once to the ground, noting where it crosses its own fence
/// and then each of `parks`: row i's crossings are `crossings[i * (parks.len()
/// + 1)..][..parks.len() + 1]`, its summary `summaries[i]`.
///
/// The one place a piece's flights are flown: the lock-step engine for many
/// flights replaces this loop. The rows are independent (each its own
/// [`SceneFlight`] and own fence, every one the same options and parks).
pub(super) fn fly_all(
    rows: &[&Ready],
    parks: &[&park::Fence],
    options: &FlightOptions,
    crossings: &mut Vec<Option<Crossing>>,
    summaries: &mut Vec<FlightSummary>,
) {
    let width = parks.len() + 1;
    crossings.clear();
    crossings.resize(rows.len() * width, None);
    // Each row's fences, its own park's then the 30: one list per own
    // fence (a chunk's rows share a few parks), not one per row.
    let mut lists: Vec<Vec<&park::Fence>> = Vec::new();
    for row in rows {
        if !lists.iter().any(|l| std::ptr::eq(l[0], row.own)) {
            lists.push(
                std::iter::once(row.own)
                    .chain(parks.iter().copied())
                    .collect(),
            );
        }
    }
    let fences_of = |row: &Ready| -> &[&park::Fence] {
        let list = lists.iter().find(|l| std::ptr::eq(l[0], row.own));
        list.map_or(&[], |l| l.as_slice())
    };
    let mut flown: Vec<Option<FlightSummary>> = vec![None; rows.len()];
    // In lock-step, four rows at a time; results come as rows finish.
    many::judge_many(
        rows.iter().map(|row| (row.flight, fences_of(row))),
        options,
        |index, summary, found| {
            flown[index] = Some(summary);
            crossings[index * width..(index + 1) * width].copy_from_slice(found);
        },
    );
    summaries.clear();
    summaries.extend(flown.into_iter().map(|f| f.expect("every row flown")));
}

/// The row's launch, completed ([`savant::launch_many`]), checked.
fn ready<'f>(
    job: &Job,
    launched: Result<savant::Launched, savant::SolveError>,
    own: &'f park::Fence,
) -> Result<Ready<'f>, String> {
    let launched = launched.map_err(|e| e.to_string())?;
    // The row was validated whole when it was read; only its launch moved,
    // if it did (a spin estimated, a direction solved).
    let moved = launched.scene.launch != job.scene.launch;
    let checked = if moved {
        launched.scene.validate_changed_launch()
    } else {
        Ok(())
    };
    checked.map_err(|e| {
        if job.launch.estimates_spin() {
            format!("{e} (the spin estimated from the launch angle)")
        } else {
            e.to_string()
        }
    })?;
    let (flight, launch, _) = launch::scene_start(&launched.scene);
    Ok(Ready {
        scene: launched.scene,
        flight,
        launch,
        flights: launched.flights,
        own,
    })
}

/// A flight judged at `fences` (the row's own, then each park's; with
/// `own_air`, its own alone, and each park on a flight of its own in its own
/// air) into `judged`.
fn judge(
    ready: &Ready,
    (fences, parks_nearest): (&[&park::Fence], f64),
    crossings: &[Option<Crossing>],
    summary: &FlightSummary,
    own_air: Option<(&Setup, GivenWeather)>,
    options: &FlightOptions,
    judged: &mut Judged,
) {
    let landing = Landing::of(summary);
    judged.own = Some(Clearing::judge_landed(
        fences[0],
        crossings[0],
        summary,
        landing,
    ));
    judged.parks.clear();
    let parks = (&fences[1..], &crossings[1..]);
    if Verdict::short_of_all(parks, parks_nearest, summary, landing) {
        // What `Verdict::of` decides at each park, without asking each.
        let short = Verdict {
            clears: false,
            decided: true,
        };
        judged.parks.resize(parks.0.len(), short);
    } else {
        judged.parks.extend(
            (parks.0.iter().zip(parks.1))
                .map(|(fence, crossing)| Verdict::of(fence, *crossing, summary, landing)),
        );
    }
    if let Some((setup, given)) = own_air {
        for park in &setup.parks.parks {
            judged
                .parks
                .push(own_air_verdict(ready, park, given, options));
        }
    }
}

/// The row judged at `park` on a flight of its own in that park's air.
fn own_air_verdict(
    ready: &Ready,
    park: &park::Park,
    given: GivenWeather,
    options: &FlightOptions,
) -> Verdict {
    let mut there = ready.scene;
    given.park_air(&mut there.environment, park.elevation);
    let (flight, _, _) = launch::scene_start(&there);
    let mut crossing = [None];
    let flown = flight.fly_to_fences(options, &[&park.fence], &mut crossing);
    let landing = Landing::of(&flown);
    Verdict::of(&park.fence, crossing[0], &flown, landing)
}

/// A row to fly again at the readout's precision: its place in the piece,
/// whether its own fence's outcome and margin were settled, and where in
/// [`Scratch::undecided`] the places of its verdicts left undecided are.
struct Again {
    row: usize,
    own_settled: bool,
    undecided: std::ops::Range<usize>,
}

/// The rows the first flight left unsettled ([`Scratch::again`]) flown
/// again at the readout's precision, as `fly` flies them, and judged again
/// where the first flight left something unsettled: at its own fence unless
/// it was settled, at each park whose verdict was not decided. What the
/// first flight settled stands (the readout's flight prints and judges it
/// alike), so only those fences watch the flight again: the watch never
/// changes the flight itself. Rows whose lanes fly as they fly alone
/// ([`many::flies_alone_alike`]) are flown in lock-step from their own
/// first steps, the others alone: the same bits.
fn judge_again(
    jobs: &[Job],
    ready: &[Result<Ready, String>],
    (parks, own_air): (&[&park::Fence], Option<&Setup>),
    scratch: &mut Scratch,
    out: &mut [Result<RowFlight, String>],
) {
    if scratch.again.is_empty() {
        return;
    }
    let readout = Purpose::Readout.flight_options();
    let ready_at = |row: usize| ready[row].as_ref().expect("a row flown is ready");
    // Each row's fences to watch again, one after another.
    let mut fences: Vec<&park::Fence> = Vec::new();
    let mut offsets = Vec::with_capacity(scratch.again.len() + 1);
    offsets.push(0);
    for again in &scratch.again {
        let own = ready_at(again.row).own;
        fences.extend((!again.own_settled).then_some(own));
        let undecided = &scratch.undecided[again.undecided.clone()];
        fences.extend(undecided.iter().filter_map(|&k| parks.get(k).copied()));
        offsets.push(fences.len());
    }
    let crossings = &mut scratch.crossings_again;
    crossings.clear();
    crossings.resize(fences.len(), None);
    let mut summaries: Vec<Option<FlightSummary>> = vec![None; scratch.again.len()];
    let (alike, alone): (Vec<usize>, Vec<usize>) = (0..scratch.again.len())
        .partition(|&m| many::flies_alone_alike(&ready_at(scratch.again[m].row).flight));
    let watched = |m: usize| &fences[offsets[m]..offsets[m + 1]];
    many::judge_many_alone(
        alike
            .iter()
            .map(|&m| (ready_at(scratch.again[m].row).flight, watched(m))),
        &readout,
        |index, summary, found| {
            let m = alike[index];
            summaries[m] = Some(summary);
            crossings[offsets[m]..offsets[m + 1]].copy_from_slice(found);
        },
    );
    for m in alone {
        let flight = ready_at(scratch.again[m].row).flight;
        let found = &mut crossings[offsets[m]..offsets[m + 1]];
        summaries[m] = Some(flight.fly_to_fences(&readout, watched(m), found));
    }
    for (m, again) in scratch.again.iter().enumerate() {
        let ready = ready_at(again.row);
        let summary = summaries[m].expect("every row flown again");
        let Ok(flown) = &mut out[again.row] else {
            continue;
        };
        let landing = Landing::of(&summary);
        let mut found = crossings[offsets[m]..offsets[m + 1]].iter().copied();
        if !again.own_settled {
            let crossing = found.next().expect("watched");
            flown.clearing = Clearing::judge_landed(ready.own, crossing, &summary, landing);
        }
        let verdicts = parks.len() + own_air.map_or(0, |setup| setup.parks.parks.len());
        let cleared = &mut scratch.cleared[flown.cleared_from..][..verdicts];
        for &k in &scratch.undecided[again.undecided.clone()] {
            let verdict = match parks.get(k) {
                Some(fence) => {
                    Verdict::of(fence, found.next().expect("watched"), &summary, landing)
                }
                // With --own-air, in that park's air (the piece's parks
                // are then none).
                None => {
                    let Some(setup) = own_air else { continue };
                    let park = &setup.parks.parks[k - parks.len()];
                    own_air_verdict(ready, park, jobs[again.row].given, &readout)
                }
            };
            cleared[k] = verdict.clears;
        }
        flown.parks_cleared = cleared.iter().filter(|&&c| c).count();
        flown.flight = summary;
    }
}

/// Whether the row prints, and judges, exactly what the readout's flight
/// would: every printed number [`BATCH_GUARD`] away from a change of its
/// last digit or its sign, every outcome as far from its threshold (a
/// margin's zero, a foul line), and the ball landed.
struct Settled {
    all: bool,
    /// The own fence's outcome and margin, as printed.
    own: bool,
}

fn settled(
    flight: &FlightSummary,
    planar: bool,
    judged: &Judged,
    printed: Printed,
    job: &Job,
) -> Settled {
    let own = judged.own.expect("judged at its own fence");
    let guard = BATCH_GUARD;
    let same = |quantity, value: f64, error: f64, decimals| {
        printed_alike(printed.shown, quantity, value, error, decimals)
    };
    let own_settled = own
        .margin
        .is_none_or(|m| same(Quantity::Distance, m, guard.distance, 3))
        && decided(&own, guard);
    let numbers = flight.landed
        && same(Quantity::Distance, flight.range, guard.distance, 3)
        // A planar flight's direction is its plane's, exactly.
        && (planar || same(Quantity::Angle, flight.direction, guard.angle, 6))
        && same(Quantity::Unchanged, flight.flight_time, guard.time, 3)
        && same(Quantity::Distance, flight.apex, guard.distance, 3)
        && same(Quantity::Angle, flight.landing_angle, guard.angle, 4)
        && (!printed.statcast
            || job.statcast.is_none_or(|measured| {
                same(
                    Quantity::Distance,
                    flight.range - measured,
                    guard.distance,
                    2,
                )
            }));
    Settled {
        all: numbers && own_settled && judged.parks.iter().all(|v| v.decided),
        own: own_settled,
    }
}

/// Whether `value` and anything within `error` of it print alike (the
/// same digits and sign) to `si_decimals` of `quantity` as `shown` prints it.
fn printed_alike(
    shown: Shown,
    quantity: Quantity,
    value: f64,
    error: f64,
    si_decimals: usize,
) -> bool {
    let decimals = shown.unit(quantity).decimals(si_decimals) as i32;
    let low = shown.convert(quantity, value - error);
    let high = shown.convert(quantity, value + error);
    let scale = 10f64.powi(decimals);
    let (low, high) = if low <= high {
        (low, high)
    } else {
        (high, low)
    };
    fixed::round(low * scale) == fixed::round(high * scale)
        && low.is_sign_negative() == high.is_sign_negative()
}

/// Whether a clearing's outcome stands `guard` from each threshold it was
/// decided at: its margin's zero, the ground at the fence, the foul lines.
fn decided(c: &Clearing, guard: Guard) -> bool {
    let margin = c.margin.is_none_or(|m| m.abs() > guard.distance);
    let height = c.height_at_fence.is_none_or(|h| h > guard.distance);
    let lines = (c.direction.abs() - park::FOUL_LINE).abs() > guard.angle;
    margin && height && lines
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::launch::scene_start;

    /// The shortcut decides a row at every park only where each park's own
    /// verdict is short and decided; and it is taken for many rows, not all.
    #[test]
    fn short_of_all_parks_is_each_parks_own_verdict() {
        let preset = crate::preset::load("fly-ball", None).unwrap();
        let parks = crate::preset::parks::all(None).unwrap();
        let fences: Vec<&park::Fence> = parks.parks.iter().map(|p| &p.fence).collect();
        let nearest = nearest_wall(&fences);
        let options = Purpose::Batch.flight_options();
        let (mut taken, mut rows) = (0, 0);
        for speed in [25.0, 35.0, 40.0, 45.0, 50.0] {
            for degrees in [-10.0, 10.0, 20.0, 30.0, 40.0, 60.0] {
                for direction in [-0.8, -0.7, -0.5, 0.0, 0.3, 0.78] {
                    let scene = preset.scene.with_launch(BattedBall {
                        speed,
                        angle: f64::to_radians(degrees),
                        spin: 200.0,
                        direction,
                        sidespin: 0.0,
                    });
                    let (flight, _, _) = scene_start(&scene);
                    let mut crossings = vec![None; fences.len()];
                    let summary = flight.fly_to_fences(&options, &fences, &mut crossings);
                    let landing = Landing::of(&summary);
                    let shortcut =
                        Verdict::short_of_all((&fences, &crossings), nearest, &summary, landing);
                    rows += 1;
                    if shortcut {
                        taken += 1;
                        for (fence, crossing) in fences.iter().zip(&crossings) {
                            let verdict = Verdict::of(fence, *crossing, &summary, landing);
                            assert!(!verdict.clears && verdict.decided, "{speed} {degrees}");
                        }
                    }
                }
            }
        }
        assert!(
            taken > rows / 4 && taken < rows * 3 / 4,
            "{taken} of {rows}"
        );
    }
}
