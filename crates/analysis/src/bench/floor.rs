//! The floor under each workload of `homerun bench`: its right-hand-side
//! evaluations times what one evaluation costs, beside its measured time.
//!
//! One evaluation is timed two ways. In a dependent chain (each input the
//! previous output, as inside one flight: a step's stages wait for each
//! other) it costs its latency; with independent evaluations interleaved
//! (several flights at once) the core overlaps them and it costs about its
//! throughput. A single flight's floor is its evaluations times the chain's
//! cost; a surface's or a batch's, times the interleaved cost (on one core:
//! its CPU time is what to compare). What sits above the floor is the
//! integrator's bookkeeping, events, parsing and printing.

use serde::Serialize;

use super::{Effort, TRAJECTORY_BATCH, fastball_launch, stated_mixed, time_median};
use crate::precision::Purpose;
use crate::study::{self, Grid};
use model::aero::{DragCurve, LiftCurve, WithModels};
use model::flight::{self, Dynamics, Flight3d, FlightOptions};
use model::launch::{BattedBall, SceneFlight, height_at_distance};
use model::scene::Scene;
use model::{self, frame};
use numerics::ode::State;

/// Independent flights interleaved when timing the throughput.
const LANES: usize = 8;
/// Evaluations per timed run of a chain (about a millisecond).
const CHAIN_EVALUATIONS: usize = 65_536;
/// Euler's step along the chain (s): a flight of ~5 s in ~1000 evaluations,
/// so that the states stay those of a real flight (speed, Re, piece).
const CHAIN_STEP: f64 = 0.005;

/// What one right-hand-side evaluation costs.
#[derive(Clone, Debug, Serialize)]
pub struct EvaluationCost {
    /// "paper" (Sawicki et al.'s drag crisis and lift) or "nathan".
    pub aero: &'static str,
    /// "planar" or "3-D".
    pub flight: &'static str,
    /// In a dependent chain (ns): the latency.
    pub chain_ns: f64,
    /// With independent evaluations interleaved (ns): the throughput.
    pub interleaved_ns: f64,
}

/// One workload: its work, its floor and its measured time.
#[derive(Clone, Debug, Serialize)]
pub struct FloorRow {
    pub workload: String,
    /// How accurately it flies: a tolerance or a purpose.
    pub setting: String,
    pub flights: usize,
    pub evaluations: u64,
    /// The per-evaluation cost its floor takes (ns): the chain's for one
    /// flight, the interleaved one for many.
    pub evaluation_ns: f64,
    /// evaluations × evaluation_ns, on one core (µs).
    pub floor_us: f64,
    /// Threads of the measured run.
    pub threads: usize,
    /// Median wall time (µs).
    pub time_us: f64,
    /// Median CPU time summed over threads (µs; Unix only).
    pub cpu_us: Option<f64>,
    /// CPU time over the floor (wall time where there is no CPU clock).
    pub over_floor: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct FloorReport {
    pub evaluation: Vec<EvaluationCost>,
    pub workloads: Vec<FloorRow>,
}

/// The floor of `evaluations` at `nanoseconds` each (µs).
pub fn floor_us(evaluations: u64, nanoseconds: f64) -> f64 {
    evaluations as f64 * nanoseconds * 1e-3
}

/// Euler along `flight` from `starts` (one lane each, taken in turn), for
/// `rounds` evaluations per lane; a lane that lands starts again. With one
/// lane every evaluation waits for the one before; with several, the lanes'
/// evaluations are independent and interleave. The right-hand side is the
/// one a flight integrates: its models asked once, then used as types.
fn euler_lanes<const N: usize, D: Dynamics<N>>(
    flight: &D,
    starts: &[State<N>],
    rounds: usize,
) -> State<N> {
    flight.drag().with_lift(
        flight.lift(),
        Euler {
            flight,
            starts,
            rounds,
        },
    )
}

struct Euler<'a, const N: usize, D> {
    flight: &'a D,
    starts: &'a [State<N>],
    rounds: usize,
}

impl<const N: usize, D: Dynamics<N>> WithModels for Euler<'_, N, D> {
    type Output = State<N>;

    fn run<Dr: DragCurve + Copy, L: LiftCurve + Copy>(self, drag: Dr, lift: L) -> State<N> {
        let Euler {
            flight,
            starts,
            rounds,
        } = self;
        let mut lanes: Vec<(f64, State<N>)> = starts.iter().map(|&s| (0.0, s)).collect();
        for _ in 0..rounds {
            for (lane, start) in lanes.iter_mut().zip(starts) {
                let (t, state) = lane;
                let slope = flight.derivative_with((&drag, &lift), *t, state, None, true);
                *state += slope * CHAIN_STEP;
                *t += CHAIN_STEP;
                if state[D::HEIGHT] < 0.0 {
                    *lane = (0.0, *start);
                }
            }
        }
        lanes.iter().map(|(_, s)| s).sum()
    }
}

/// The chain's and the interleaved cost of one evaluation (ns).
fn evaluation_cost<const N: usize, D: Dynamics<N>>(
    flight: &D,
    start: State<N>,
    batches: usize,
) -> (f64, f64) {
    let per_evaluation = |lanes: usize| {
        // Launches a percent apart, so that no two lanes are the same.
        let starts: Vec<State<N>> = (0..lanes)
            .map(|i| start * (1.0 + 0.01 * i as f64))
            .collect();
        let rounds = CHAIN_EVALUATIONS / lanes;
        let (time, cpu) = time_median(batches, 1, || {
            euler_lanes(std::hint::black_box(flight), &starts, rounds)
        });
        cpu.unwrap_or(time) * 1e9 / (rounds * lanes) as f64
    };
    (per_evaluation(1), per_evaluation(LANES))
}

/// The fly-ball preset's launch (103 mph, 28°, 2500 rpm), with sidespin
/// and a direction when `spatial`.
fn fly_ball(spatial: bool) -> BattedBall {
    BattedBall {
        speed: 46.04512,
        angle: 28f64.to_radians(),
        spin: 2500.0 * std::f64::consts::TAU / 60.0,
        direction: if spatial { -0.3 } else { 0.0 },
        sidespin: if spatial {
            -1000.0 * std::f64::consts::TAU / 60.0
        } else {
            0.0
        },
    }
}

fn costs(effort: Effort) -> Vec<EvaluationCost> {
    let batches = effort.trajectory_batches;
    let mut rows = Vec::new();
    let mut push = |aero, flight, (chain_ns, interleaved_ns)| {
        rows.push(EvaluationCost {
            aero,
            flight,
            chain_ns,
            interleaved_ns,
        });
    };
    let spatial_start = |launch: &BattedBall| {
        let v = frame::launch_velocity(launch.speed, launch.angle, launch.direction);
        State::<6>::new(0.0, 1.0, 0.0, v.x, v.y, v.z)
    };
    for (aero, scene) in [
        ("paper", Scene::default()),
        ("nathan", Scene::default().with_launch(fly_ball(false))),
    ] {
        let planar = if aero == "paper" {
            fastball_launch()
        } else {
            match SceneFlight::new(&scene, &fly_ball(false)) {
                SceneFlight::Planar { flight, launch, .. } => (flight, launch),
                SceneFlight::Spatial { .. } => unreachable!("a launch in the plane"),
            }
        };
        let (flight, launch) = planar;
        let start = State::<4>::new(
            launch.position.x,
            launch.position.y,
            launch.velocity.x,
            launch.velocity.y,
        );
        push(aero, "planar", evaluation_cost(&flight, start, batches));
        let hook = fly_ball(true);
        let flight = Flight3d::new(&scene, hook.spin_vector());
        push(
            aero,
            "3-D",
            evaluation_cost(&flight, spatial_start(&hook), batches),
        );
    }
    rows
}

fn cost_of(costs: &[EvaluationCost], aero: &str, flight: &str, chain: bool) -> f64 {
    let cost = costs
        .iter()
        .find(|c| c.aero == aero && c.flight == flight)
        .expect("every aero and flight is timed");
    if chain {
        cost.chain_ns
    } else {
        cost.interleaved_ns
    }
}

/// The loosest stated tolerance (relative 10^−e, absolute 10^−(e−1),
/// stopping at kinks) whose range is within 1 mm of `Purpose::Reference`'s.
fn within_a_millimetre(fly: impl Fn(&FlightOptions) -> flight::FlightSummary) -> FlightOptions {
    let reference = fly(&Purpose::Reference.flight_options()).range;
    (3..=10)
        .map(|e| stated_mixed(e, e - 1, true))
        .find(|options| (fly(options).range - reference).abs() <= 1e-3)
        .unwrap_or_else(|| stated_mixed(10, 9, true))
}

fn setting(options: &FlightOptions) -> String {
    format!(
        "rtol {:.0e}, atol {:.0e}",
        options.tolerance.relative, options.tolerance.absolute
    )
}

/// The measured part of a row, with its floor.
#[allow(clippy::too_many_arguments)]
fn row(
    workload: &str,
    setting: String,
    flights: usize,
    evaluations: u64,
    evaluation_ns: f64,
    threads: usize,
    (time, cpu): (f64, Option<f64>),
) -> FloorRow {
    let floor = floor_us(evaluations, evaluation_ns);
    let measured = cpu.unwrap_or(time) * 1e6;
    FloorRow {
        workload: workload.to_owned(),
        setting,
        flights,
        evaluations,
        evaluation_ns,
        floor_us: floor,
        threads,
        time_us: time * 1e6,
        cpu_us: cpu.map(|c| c * 1e6),
        over_floor: measured / floor,
    }
}

/// One flight within 1 mm, timed, beside its chain's floor.
fn single_flight(
    effort: Effort,
    workload: &str,
    cost_ns: f64,
    fly: impl Fn(&FlightOptions) -> flight::FlightSummary,
) -> FloorRow {
    let options = within_a_millimetre(&fly);
    let summary = fly(&options);
    let timed = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, || {
        fly(std::hint::black_box(&options))
    });
    let evaluations = summary.stats.evaluations.into();
    row(
        workload,
        setting(&options),
        1,
        evaluations,
        cost_ns,
        1,
        timed,
    )
}

fn single_flights(effort: Effort, costs: &[EvaluationCost]) -> Vec<FloorRow> {
    let (flight, launch) = fastball_launch();
    let scene = Scene::default().with_launch(fly_ball(false));
    let fly_ball = SceneFlight::new(&scene, &fly_ball(false));
    vec![
        single_flight(
            effort,
            "one trajectory: Table II fastball, paper's aero",
            cost_of(costs, "paper", "planar", true),
            |o| flight::fly(&flight, &launch, o),
        ),
        single_flight(
            effort,
            "one trajectory: fly ball, Nathan's aero",
            cost_of(costs, "nathan", "planar", true),
            |o| fly_ball.fly(o),
        ),
    ]
}

fn surface(effort: Effort, threads: usize, costs: &[EvaluationCost]) -> FloorRow {
    let scene = Scene::default();
    let size = effort.surface_size;
    let grid = Grid::figure7(size, size);
    let purpose = Purpose::Surface;
    let evaluations: u64 = (0..size * size)
        .map(|k| {
            let at = scene.with_swing(grid.undercut_at(k % size), grid.swing_angle_at(k / size));
            u64::from(model::simulate(&at, purpose).flight.stats.evaluations)
        })
        .sum();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let timed = time_median(effort.surface_runs, 1, || {
        pool.install(|| study::surface(&scene, grid, purpose))
    });
    row(
        &format!("{size}×{size} surface, Fig. 7's window"),
        format!("Purpose::{purpose:?}"),
        size * size,
        evaluations,
        cost_of(costs, "paper", "planar", false),
        threads,
        timed,
    )
}

/// `bench`'s batch rows, and the same with a spray direction within ±40°
/// and ±1500 rpm of sidespin (3-D flights).
fn batches(effort: Effort, threads: usize, quick: bool, costs: &[EvaluationCost]) -> Vec<FloorRow> {
    use rayon::prelude::*;
    let count = if quick { 2_000 } else { 20_000 };
    let planar = super::batch_scenes(count);
    let spatial: Vec<Scene> = planar
        .iter()
        .enumerate()
        .map(|(i, scene)| {
            let f = |period: usize| (i % period) as f64 / (period - 1) as f64;
            scene.with_launch(BattedBall {
                direction: (-40.0 + 80.0 * f(7)).to_radians(),
                sidespin: (-1500.0 + 3000.0 * f(5)) * std::f64::consts::TAU / 60.0,
                ..scene.batted_ball()
            })
        })
        .collect();
    let fence = preset::FIELD_KEYS[0].default;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let fly_all = |scenes: &[Scene]| {
        scenes
            .par_iter()
            .map(|s| height_at_distance(s, fence, Purpose::Readout))
            .collect::<Vec<_>>()
    };
    [("planar", planar), ("3-D", spatial)]
        .into_iter()
        .map(|(flight, scenes)| {
            let evaluations = fly_all(&scenes)
                .iter()
                .map(|(summary, _)| u64::from(summary.stats.evaluations))
                .sum();
            let timed = time_median(effort.surface_runs, 1, || pool.install(|| fly_all(&scenes)));
            row(
                &format!("batch of {count}, Nathan's aero, {flight}, to the fence"),
                "Purpose::Readout".to_owned(),
                count,
                evaluations,
                cost_of(costs, "nathan", flight, false),
                threads,
                timed,
            )
        })
        .collect()
}

pub(super) fn report(effort: Effort, threads: usize, quick: bool) -> FloorReport {
    let evaluation = costs(effort);
    let mut workloads = single_flights(effort, &evaluation);
    workloads.push(surface(effort, threads, &evaluation));
    workloads.extend(batches(effort, threads, quick, &evaluation));
    FloorReport {
        evaluation,
        workloads,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_floor_is_evaluations_times_their_cost() {
        // The single flight: 83 evaluations at 13 ns in a chain is
        // 1.079 µs; a 64×64 surface's ~400 000 at 3.5 ns, 1.4 ms.
        assert!((floor_us(83, 13.0) - 1.079).abs() < 1e-12);
        assert!((floor_us(400_000, 3.5) - 1400.0).abs() < 1e-9);
    }

    #[test]
    fn a_chain_follows_the_flight_and_starts_again_at_the_landing() {
        let (flight, launch) = fastball_launch();
        let (p, v) = (launch.position, launch.velocity);
        let start = State::<4>::new(p.x, p.y, v.x, v.y);
        // Euler at 5 ms carries the fastball to its range (134.7 m, to
        // within its first-order error and the last step's 0.1 m) before
        // the lane starts again from the launch.
        let xs: Vec<f64> = (0..2000)
            .map(|n| euler_lanes(&flight, &[start], n)[0])
            .collect();
        let landing = xs.windows(2).position(|w| w[1] < w[0]).expect("it lands");
        assert_eq!(xs[landing + 1], 0.0);
        assert!((xs[landing] - 134.7).abs() < 1.0, "{}", xs[landing]);
        // Lanes are independent flights: together as each on its own.
        let other = start * 1.01;
        let both = euler_lanes(&flight, &[start, other], 500);
        let apart = euler_lanes(&flight, &[start], 500) + euler_lanes(&flight, &[other], 500);
        assert_eq!(both, apart);
    }
}
