//! A piece of a batch flown: each row's launch completed (the spin
//! estimated, the direction solved: [`savant::launch_many`]), flown once at
//! the readout's precision to the ground and its fences, and judged there
//! and at every park. Every row's answer is its own ([`many::judge_many`]):
//! what `fly` gives that row alone, bit for bit, whatever its neighbours.

use crate::park_air;
use crate::row::Job;
use crate::setup::Setup;
use analysis::precision::Purpose;
use analysis::savant;
use model::clearing::{Clearing, Crossing, Landing};
use model::flight::{FlightOptions, FlightSummary};
use model::launch::{self, BattedBall, SceneFlight};
use model::many;
use model::park;
use model::scene::Scene;

/// A row's flight, as the output needs it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RowFlight {
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
    pub direction_from: savant::DirectionFrom,
}

impl RowFlight {
    /// The model's range less Statcast's distance (m), if both are known.
    pub(crate) fn difference(&self, job: &Job) -> Option<f64> {
        let flight = &self.flight;
        (job.statcast)
            .filter(|_| flight.landed)
            .map(|measured| flight.range - measured)
    }
}

/// What flying a piece reuses from row to row.
#[derive(Default)]
pub(crate) struct Scratch {
    /// Each row's crossings of its fences: its own, then each park's.
    crossings: Vec<Option<Crossing>>,
    summaries: Vec<FlightSummary>,
    /// For each row flown, a flag per park: cleared.
    pub cleared: Vec<bool>,
    /// With `--all-parks`, for each row flown, its judgement at each park
    /// (beside `cleared`: from the same `cleared_from`).
    pub clearings: Vec<Clearing>,
    /// Without it, the row being flown's verdict at each park.
    verdicts: Vec<Clearing>,
    airs: park_air::ParkAirs,
}

/// A row ready to fly: its launch complete and checked, and the fence it
/// is judged at (its park's, or the generic one).
struct Ready<'f> {
    scene: Scene,
    flight: SceneFlight,
    launch: BattedBall,
    flights: usize,
    direction_from: savant::DirectionFrom,
    own: &'f park::Fence,
}

/// Flies `jobs` into `out`, in order (a reason where a row cannot fly).
pub(crate) fn fly_chunk(
    jobs: &[Job],
    setup: &Setup,
    scratch: &mut Scratch,
    out: &mut Vec<Result<RowFlight, String>>,
) {
    out.clear();
    scratch.cleared.clear();
    scratch.clearings.clear();
    // The generic fences of the piece (one, unless rows give field.*).
    let mut generic: Vec<(preset::Fence, park::Fence)> = Vec::new();
    for job in jobs.iter().filter(|j| j.park.is_none()) {
        if !generic.iter().any(|(f, _)| *f == job.fence) {
            generic.push((job.fence, job.fence.uniform()));
        }
    }
    let own = |job: &Job| match job.park {
        // The park's fence (`setup.fences[index]`), or the earlier walls met.
        Some(index) => setup.parks.parks[index].fence_of(job.earlier),
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
    // The one flight crosses every park's fence: it is each park's
    // verdict in its own air where a change of air cannot move it
    // ([`park_air::settled`]); the other parks are flown in their air.
    let parks: &[&park::Fence] = &setup.fences;
    let options = Purpose::Readout.flight_options();
    let flying: Vec<&Ready> = ready.iter().flatten().collect();
    fly_all(
        &flying,
        parks,
        &options,
        &mut scratch.crossings,
        &mut scratch.summaries,
    );
    let width = parks.len() + 1;
    let nearest_wall =
        (parks.iter()).fold(f64::INFINITY, |least, fence| least.min(fence.nearest()));
    let mut flown = 0;
    let mut in_own_air: Vec<(usize, SceneFlight)> = Vec::new();
    let mut pending = Vec::new();
    for (job, ready) in jobs.iter().zip(&ready) {
        let ready = match ready {
            Ok(ready) => ready,
            Err(reason) => {
                out.push(Err(reason.clone()));
                continue;
            }
        };
        let crossings = &scratch.crossings[flown * width..][..width];
        let summary = scratch.summaries[flown];
        flown += 1;
        let landing = Landing::of(&summary);
        let clearing = Clearing::judge_landed(ready.own, crossings[0], &summary, landing);
        // Each row's verdicts at the parks: whole where the margins are
        // printed (`--all-parks`); else only whether each park is cleared,
        // a flag where a whole judgement is some 70 bytes.
        let from = match setup.all_parks {
            true => scratch.clearings.len(),
            false => scratch.cleared.len(),
        };
        // How each park's verdict is found: from this flight alone, from
        // flights in the parks' own air, or settled from this one (then
        // the parks' airs are kept with it).
        let mut settling = None;
        if !setup.one_flight {
            let own = &ready.scene.environment;
            let airs = scratch.airs.of(own, job.given, &setup.parks.parks);
            if setup.all_parks || !park_air::settles(&ready.scene) {
                // Flown in every park's air but its own (`--all-parks`
                // prints the margins too).
                for (k, air) in airs
                    .iter()
                    .enumerate()
                    .filter(|(_, air)| **air != own.air())
                {
                    let mut there = ready.scene;
                    there.environment.set_air(*air);
                    in_own_air.push((from + k, launch::scene_start(&there).0));
                }
            } else if !park_air::short_everywhere(&summary, own.air_density, airs, nearest_wall) {
                // Settled from this flight and as few more as it takes
                // (a row short of every wall in every park's air keeps
                // its own verdicts).
                settling = Some(airs.to_vec());
            }
        }
        let judged = parks.iter().zip(&crossings[1..]);
        if setup.all_parks {
            (scratch.clearings).extend(judged.map(|(fence, crossing)| {
                Clearing::judge_landed(fence, *crossing, &summary, landing)
            }));
        } else {
            let verdict = |(fence, crossing): (&&park::Fence, &Option<Crossing>)| {
                Clearing::outcome_landed(fence, *crossing, &summary, landing)
            };
            scratch.verdicts.clear();
            scratch.verdicts.extend(judged.map(verdict));
            (scratch.cleared).extend(scratch.verdicts.iter().map(Clearing::clears));
        }
        // A row whose own flight settles every park keeps its verdicts
        // (what the settling's first round would find, without its lists).
        let mut settled_at = Vec::new();
        let settling = settling.filter(|airs| {
            let own = (ready.scene.environment.air_density, airs.as_slice());
            let launched = (ready.launch.direction, &summary);
            let judged = (parks, scratch.verdicts.as_slice());
            !park_air::own_flight_settles(launched, own, judged, &mut settled_at)
        });
        if let Some(airs) = settling {
            pending.push(park_air::Pending {
                settled_at,
                scene: ready.scene,
                launch_direction: ready.launch.direction,
                airs,
                from,
                flights: vec![park_air::Reference {
                    density: ready.scene.environment.air_density,
                    flight: summary,
                    slack: 0.0,
                    clearings: scratch.verdicts.iter().copied().map(Some).collect(),
                }],
            });
        }
        out.push(Ok(RowFlight {
            launch: ready.launch,
            flight: summary,
            clearing,
            parks_cleared: 0,
            cleared_from: from,
            flights: ready.flights,
            direction_from: ready.direction_from,
        }));
    }
    if setup.all_parks {
        park_air::fly_alone(&in_own_air, parks, &options, |slot, judged| {
            scratch.clearings[slot] = judged;
        });
        (scratch.cleared).extend(scratch.clearings.iter().map(Clearing::clears));
    } else {
        park_air::fly_alone(&in_own_air, parks, &options, |slot, judged| {
            scratch.cleared[slot] = judged.clears();
        });
        park_air::settle(pending, parks, &options, &mut scratch.cleared);
    }
    let count = setup.parks.parks.len();
    for row in out.iter_mut().flatten() {
        let cleared = &scratch.cleared[row.cleared_from..][..count];
        row.parks_cleared = cleared.iter().filter(|&&c| c).count();
    }
}

/// Flies each row once to the ground, noting where it crosses its own fence
/// and then each of `parks`: row i's crossings are `crossings[i * (parks.len()
/// + 1)..][..parks.len() + 1]`, its summary `summaries[i]`.
fn fly_all(
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
    launched: savant::Launched,
    own: &'f park::Fence,
) -> Result<Ready<'f>, String> {
    check_launch(job, &launched.scene)?;
    let (flight, launch, _) = launch::scene_start(&launched.scene);
    Ok(Ready {
        scene: launched.scene,
        flight,
        launch,
        flights: launched.flights,
        direction_from: job.direction_from(launched.direction_from),
        own,
    })
}

/// A row's launch as [`savant::launch_many`] completed it, checked before
/// it is flown or fitted. The row was validated whole when it was read, so
/// only a launch that moved since (a spin estimated, a direction solved) is
/// checked again; a swing's impact, solved before, is an output of that
/// validated swing, not an input held to an input's bounds (a popup's spin
/// can pass 1000 rad/s).
pub(crate) fn check_launch(job: &Job, launched: &Scene) -> Result<(), String> {
    let moved = launched.launch != job.scene.launch;
    let checked = if moved {
        launched.validate_changed_launch()
    } else {
        Ok(())
    };
    checked.map_err(|e| {
        if job.launch.estimates_spin() {
            format!("{e} (the spin estimated from the launch angle)")
        } else {
            e.to_string()
        }
    })
}
