//! `homerun bench`: speed against error, measured on this machine.
//!
//! Five tables: one trajectory per integrator setting, the same launch per
//! aero model (drag × lift, spin decay), one optimisation per
//! Table II pitch per tolerance pair, one 64×64 range surface per
//! tolerance on one thread and on all cores, and the explorer's background
//! work beside the surface (each figure's data, the sensitivity columns). Every error is measured against
//! a solve at the tightest setting; times are medians over repeated runs.
//! The JSON output uses the tables' field names.

mod floor;
mod impact;
mod parks;
mod spatial;

use std::time::Instant;

use serde::Serialize;

use super::optimum::{Optimizer, OptimizerSettings, Status};
use super::paper::table_two;
use super::precision::Purpose;
use super::study::{self, Grid};
pub use floor::{EvaluationCost, FloorReport, FloorRow};
pub use impact::ImpactRow;
use model::flight::{self, Flight, FlightOptions, Launch};
use model::impact::Impact;
use model::{self, scene::Scene};
use numerics::ode::Tolerance;
pub use parks::ParksRow;
pub use spatial::SpatialRow;

/// reference/model.py's range for the Table II fastball launch (m).
pub const PYTHON_REFERENCE_RANGE: f64 = 134.698780;

/// Flights per timed batch (so that reading the CPU clock costs nothing).
const TRAJECTORY_BATCH: usize = 50;

/// How much to measure.
#[derive(Clone, Copy, Debug)]
struct Effort {
    /// Batches of `TRAJECTORY_BATCH` flights.
    trajectory_batches: usize,
    optimisation_runs: usize,
    surface_runs: usize,
    surface_size: usize,
}

impl Effort {
    fn new(quick: bool) -> Effort {
        if quick {
            Effort {
                trajectory_batches: 5,
                optimisation_runs: 1,
                surface_runs: 1,
                surface_size: 64,
            }
        } else {
            Effort {
                trajectory_batches: 41,
                optimisation_runs: 7,
                surface_runs: 5,
                surface_size: 64,
            }
        }
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// Threads "all cores" used.
    pub threads: usize,
    pub quick: bool,
    pub reference: ReferenceCheck,
    pub trajectory: Vec<TrajectoryRow>,
    pub aero: Vec<AeroRow>,
    /// The fly ball in the plane and in 3-D: what leaving the plane costs.
    pub spatial: Vec<SpatialRow>,
    pub optimisation: Vec<OptimisationRow>,
    pub surface: Vec<SurfaceRow>,
    /// The explorer's other background work, on the fastball.
    pub explorer: Vec<ExplorerRow>,
    /// The tolerances each consumer uses now (src/precision.rs).
    pub defaults: Vec<DefaultRow>,
    /// `fly --batch`'s flights: rows per second on one thread and on all.
    pub batch: Vec<BatchRow>,
    /// A flight judged at the parks, and a Savant row's whole work.
    pub parks: Vec<ParksRow>,
    /// Each workload's floor: evaluations × one evaluation's cost.
    pub floor: FloorReport,
    /// The 3-D impact, and `optimize --park`.
    pub impact: Vec<ImpactRow>,
}

/// A batch of batted balls, each flown as a `fly --batch` row is (readout
/// precision, with its height at the fence), in parallel.
#[derive(Clone, Debug, Serialize)]
pub struct BatchRow {
    pub rows: usize,
    pub threads: usize,
    /// Median wall time for the whole batch.
    pub time_ms: f64,
    pub cpu_ms: Option<f64>,
    pub rows_per_second: f64,
}

/// The reference solve checked against reference/model.py.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ReferenceCheck {
    pub range: f64,
    pub python_range: f64,
    pub difference: f64,
}

/// One trajectory (the Table II fastball launch) at one integrator setting.
#[derive(Clone, Debug, Serialize)]
pub struct TrajectoryRow {
    pub method: &'static str,
    /// Relative tolerance (adaptive methods).
    pub tolerance: Option<f64>,
    /// Absolute tolerance (adaptive methods).
    pub absolute: Option<f64>,
    /// Step size (s) (fixed-step methods).
    pub step: Option<f64>,
    pub stop_at_kinks: bool,
    pub evaluations: u32,
    pub accepted: u32,
    pub rejected: u32,
    /// Median wall time per trajectory.
    pub time_us: f64,
    /// Median CPU time per trajectory (Unix only).
    pub cpu_us: Option<f64>,
    pub range_error: f64,
}

impl TrajectoryRow {
    /// The row's measured part (work, time, error); the caller names the
    /// method and its setting.
    fn measured(
        stop_at_kinks: bool,
        summary: &flight::FlightSummary,
        (time, cpu): (f64, Option<f64>),
        reference: f64,
    ) -> TrajectoryRow {
        TrajectoryRow {
            method: "",
            tolerance: None,
            absolute: None,
            step: None,
            stop_at_kinks,
            evaluations: summary.stats.evaluations,
            accepted: summary.stats.accepted,
            rejected: summary.stats.rejected,
            time_us: time * 1e6,
            cpu_us: cpu.map(|c| c * 1e6),
            range_error: summary.range - reference,
        }
    }
}

/// The Table II fastball launch under one drag × lift pair (and spin decay
/// time, 0 for none) at one tolerance (dopri5, stopping at kinks), its error
/// against Purpose::Reference for the same models.
#[derive(Clone, Debug, Serialize)]
pub struct AeroRow {
    pub drag: &'static str,
    pub lift: &'static str,
    pub spin_decay: f64,
    pub tolerance: f64,
    pub absolute: f64,
    pub evaluations: u32,
    pub rejected: u32,
    pub time_us: f64,
    pub cpu_us: Option<f64>,
    pub range_error: f64,
}

/// One optimisation of one Table II pitch at one tolerance pair.
#[derive(Clone, Debug, Serialize)]
pub struct OptimisationRow {
    pub pitch: String,
    /// The optimiser's stopping tolerance on range (m) (and, in scaled units, on the simplex size).
    pub optimizer_tolerance: f64,
    pub integrator_tolerance: f64,
    pub evaluations: u32,
    pub converged: bool,
    /// Median wall time.
    pub time_ms: f64,
    /// Median CPU time (Unix only).
    pub cpu_ms: Option<f64>,
    pub undercut_error: f64,
    pub swing_angle_error: f64,
    pub range_error: f64,
}

/// One range surface over Fig. 7's window.
#[derive(Clone, Debug, Serialize)]
pub struct SurfaceRow {
    pub cells: usize,
    /// Relative tolerance.
    pub integrator_tolerance: f64,
    /// Absolute tolerance.
    pub absolute: f64,
    pub threads: usize,
    /// Median wall time.
    pub time_ms: f64,
    /// Median CPU time summed over the threads (Unix only): on an idle
    /// machine, the wall time is about this divided by `threads`.
    pub cpu_ms: Option<f64>,
    pub max_cell_error: f64,
}

/// A consumer's budget and tolerance.
/// One piece of the explorer's background work, as it computes it.
#[derive(Clone, Debug, Serialize)]
pub struct ExplorerRow {
    /// "figure 8", "sensitivity at the swing", …
    pub work: String,
    /// What it takes: flights, optimisations.
    pub detail: String,
    pub time_ms: f64,
    pub cpu_ms: Option<f64>,
}

#[derive(Clone, Debug, Serialize)]
pub struct DefaultRow {
    pub purpose: String,
    pub range_budget: f64,
    pub tolerance: f64,
    pub range_error: f64,
}

fn median(mut samples: Vec<f64>) -> f64 {
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

/// Time on a CPU (ns) of all this process's threads (POSIX
/// `CLOCK_PROCESS_CPUTIME_ID`); `None` where that is unavailable. Unlike the
/// wall clock, it does not count time spent waiting for a core that other
/// programs hold, so it measures the code on a shared machine.
#[cfg(unix)]
fn cpu_ns() -> Option<u64> {
    // std has no process CPU clock; rustix asks it without unsafe code.
    let now = rustix::time::clock_gettime(rustix::time::ClockId::ProcessCPUTime);
    let ns = u64::try_from(now.tv_sec).ok()? * 1_000_000_000;
    Some(ns + u64::try_from(now.tv_nsec).ok()?)
}

#[cfg(not(unix))]
fn cpu_ns() -> Option<u64> {
    None
}

/// Per call of `work`: the median wall time (s) and the median CPU time (s,
/// summed over threads) over `batches` batches of `batch` calls, after one
/// warm-up call.
fn time_median<T>(batches: usize, batch: usize, mut work: impl FnMut() -> T) -> (f64, Option<f64>) {
    std::hint::black_box(work());
    let batch = batch.max(1);
    let mut wall = Vec::new();
    let mut cpu = Vec::new();
    for _ in 0..batches.max(1) {
        let cpu_start = cpu_ns();
        let start = Instant::now();
        for _ in 0..batch {
            std::hint::black_box(work());
        }
        wall.push(start.elapsed().as_secs_f64() / batch as f64);
        if let (Some(a), Some(b)) = (cpu_start, cpu_ns()) {
            cpu.push(b.saturating_sub(a) as f64 * 1e-9 / batch as f64);
        }
    }
    let cpu = (!cpu.is_empty()).then(|| median(cpu));
    (median(wall), cpu)
}

/// Relative and absolute tolerance 10^−exponent: a stated tolerance for the
/// work–precision tables, not a consumer's (those are in `precision`).
fn stated(exponent: i32, stop_at_kinks: bool) -> FlightOptions {
    stated_mixed(exponent, exponent, stop_at_kinks)
}

fn stated_mixed(
    relative_exponent: i32,
    absolute_exponent: i32,
    stop_at_kinks: bool,
) -> FlightOptions {
    FlightOptions {
        tolerance: Tolerance {
            relative: 10f64.powi(-relative_exponent),
            absolute: 10f64.powi(-absolute_exponent),
        },
        stop_at_kinks,
    }
}

fn fastball_launch() -> (Flight, Launch) {
    let scene = Scene::default();
    model::launch(&scene, &Impact::new(&scene))
}

fn trajectories(effort: Effort, reference: f64) -> Vec<TrajectoryRow> {
    let (flight, launch) = fastball_launch();
    let mut rows = Vec::new();
    // (relative exponent, absolute exponent, stop at kinks): uniform
    // tolerances with and without kinks, then an absolute tolerance ten
    // times the relative one (positions ~100 m and speeds ~40 m/s need no
    // finer absolute floor than a relative one gives them).
    let mut settings: Vec<(i32, i32, bool)> = Vec::new();
    for stop_at_kinks in [false, true] {
        settings.extend((3..=12).map(|e| (e, e, stop_at_kinks)));
    }
    settings.extend((3..=10).map(|e| (e, e - 1, true)));
    for (relative, absolute, stop_at_kinks) in settings {
        let options = stated_mixed(relative, absolute, stop_at_kinks);
        let summary = flight::fly(&flight, &launch, &options);
        let (time, cpu) = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, || {
            flight::fly(std::hint::black_box(&flight), &launch, &options)
        });
        rows.push(TrajectoryRow {
            method: "dopri5",
            tolerance: Some(options.tolerance.relative),
            absolute: Some(options.tolerance.absolute),
            step: None,
            ..TrajectoryRow::measured(stop_at_kinks, &summary, (time, cpu), reference)
        });
    }
    for stop_at_kinks in [false, true] {
        for step in [0.2, 0.1, 0.05, 0.02, 0.01] {
            let summary = flight::fly_fixed_step(&flight, &launch, step, stop_at_kinks);
            let (time, cpu) = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, || {
                flight::fly_fixed_step(std::hint::black_box(&flight), &launch, step, stop_at_kinks)
            });
            rows.push(TrajectoryRow {
                method: "rk4",
                tolerance: None,
                absolute: None,
                step: Some(step),
                ..TrajectoryRow::measured(stop_at_kinks, &summary, (time, cpu), reference)
            });
        }
    }
    rows
}

fn aero_trajectories(effort: Effort, quick: bool) -> Vec<AeroRow> {
    use model::aero::{DragModel as D, LiftModel as L};
    let (_, launch) = fastball_launch();
    let spin = Impact::new(&Scene::default()).launch_spin();
    let models = [
        (D::Sawicki2003, L::Sawicki2003, 0.0),
        (D::Constant, L::Sawicki2003, 0.0),
        (D::Nathan, L::Nathan, 0.0),
        (D::Nathan, L::Nathan, 25.0),
        (D::Nathan, L::Sawicki2003, 0.0),
        (D::Sawicki2003, L::Nathan, 0.0),
        (D::Nathan, L::None, 0.0),
    ];
    let exponents: &[i32] = if quick { &[5, 8] } else { &[4, 5, 6, 7, 8, 10] };
    let mut rows = Vec::new();
    for (drag, lift, spin_decay) in models {
        let scene = Scene {
            drag,
            lift,
            spin_decay,
            ..Scene::default()
        };
        let flight = Flight::new(&scene, spin);
        let reference = flight::fly(&flight, &launch, &Purpose::Reference.flight_options());
        for &e in exponents {
            let options = stated_mixed(e, e - 1, true);
            let summary = flight::fly(&flight, &launch, &options);
            let (time, cpu) = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, || {
                flight::fly(std::hint::black_box(&flight), &launch, &options)
            });
            rows.push(AeroRow {
                drag: drag.name(),
                lift: lift.name(),
                spin_decay,
                tolerance: options.tolerance.relative,
                absolute: options.tolerance.absolute,
                evaluations: summary.stats.evaluations,
                rejected: summary.stats.rejected,
                time_us: time * 1e6,
                cpu_us: cpu.map(|c| c * 1e6),
                range_error: summary.range - reference.range,
            });
        }
    }
    rows
}

/// The optimiser's settings for a stopping tolerance on range (m): the
/// simplex size in scaled units follows it (1e-4 m ↔ 1e-4, the default).
fn optimizer_settings(tolerance: f64) -> OptimizerSettings {
    OptimizerSettings {
        tolerance_x: tolerance,
        tolerance_range: tolerance,
        max_evaluations: 10_000,
        ..OptimizerSettings::default()
    }
}

fn optimise(
    scene: &Scene,
    options: FlightOptions,
    settings: OptimizerSettings,
) -> (f64, f64, f64, u32, bool) {
    let start = (scene.bat.undercut, scene.bat.swing_angle);
    let mut optimizer = Optimizer::new(scene, start, options, settings);
    let best = optimizer.run(|| false).unwrap_or_else(|| optimizer.best());
    // The range at the optimum, re-solved tightly: what a user is shown.
    let at = scene.with_swing(best.undercut, best.swing_angle);
    (
        best.undercut,
        best.swing_angle,
        model::range(&at, Purpose::Reference),
        optimizer.evaluations(),
        optimizer.status() == Status::Converged,
    )
}

/// (optimiser stopping tolerance on range, integrator tolerance exponent).
fn optimisation_pairs(quick: bool) -> Vec<(f64, i32)> {
    if quick {
        vec![(1e-3, 6), (1e-4, 6), (1e-4, 8)]
    } else {
        vec![
            (1e-3, 5),
            (1e-3, 6),
            (1e-4, 6),
            (1e-4, 7),
            (1e-4, 8),
            (1e-4, 10),
            (1e-5, 8),
            (1e-6, 10),
        ]
    }
}

fn optimisations(effort: Effort, quick: bool) -> Vec<OptimisationRow> {
    let mut rows = Vec::new();
    for (pitch, scene) in table_two() {
        let (e_ref, psi_ref, range_ref, _, _) =
            optimise(&scene, stated(12, true), optimizer_settings(1e-9));
        for (tolerance, exponent) in optimisation_pairs(quick) {
            let purpose = stated(exponent, true);
            let settings = optimizer_settings(tolerance);
            let (e, psi, range, evaluations, converged) = optimise(&scene, purpose, settings);
            let (time, cpu) = time_median(effort.optimisation_runs, 1, || {
                let mut optimizer = Optimizer::new(
                    &scene,
                    (scene.bat.undercut, scene.bat.swing_angle),
                    purpose,
                    settings,
                );
                optimizer.run(|| false)
            });
            rows.push(OptimisationRow {
                pitch: pitch.to_owned(),
                optimizer_tolerance: tolerance,
                integrator_tolerance: 10f64.powi(-exponent),
                evaluations,
                converged,
                time_ms: time * 1e3,
                cpu_ms: cpu.map(|c| c * 1e3),
                undercut_error: e - e_ref,
                swing_angle_error: psi - psi_ref,
                range_error: range - range_ref,
            });
        }
    }
    rows
}

fn max_difference(a: &study::Surface, b: &study::Surface) -> f64 {
    a.outcomes()
        .iter()
        .zip(b.outcomes())
        .map(|(a, b)| match (a.range(), b.range()) {
            (Some(a), Some(b)) => (a - b).abs(),
            _ if a == b => 0.0,
            _ => f64::INFINITY,
        })
        .fold(0.0, f64::max)
}

fn surfaces(effort: Effort, threads: usize, quick: bool) -> Vec<SurfaceRow> {
    let scene = Scene::default();
    let grid = Grid::figure7(effort.surface_size, effort.surface_size);
    let tight = study::surface(&scene, grid, Purpose::Reference);
    let settings: &[(i32, i32)] = if quick {
        &[(3, 3), (5, 5), (5, 4)]
    } else {
        &[
            (2, 2),
            (3, 3),
            (4, 4),
            (5, 5),
            (6, 6),
            (8, 8),
            (4, 3),
            (5, 4),
        ]
    };
    let mut rows = Vec::new();
    for &(relative, absolute) in settings {
        let purpose = stated_mixed(relative, absolute, true);
        let cheap = study::surface(&scene, grid, purpose);
        let error = max_difference(&cheap, &tight);
        let mut counts = vec![1, threads];
        counts.dedup();
        for n in counts {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .expect("a thread pool");
            let (time, cpu) = time_median(effort.surface_runs, 1, || {
                pool.install(|| study::surface(&scene, grid, purpose))
            });
            rows.push(SurfaceRow {
                cells: grid.columns * grid.rows,
                integrator_tolerance: 10f64.powi(-relative),
                absolute: 10f64.powi(-absolute),
                threads: n,
                time_ms: time * 1e3,
                cpu_ms: cpu.map(|c| c * 1e3),
                max_cell_error: error,
            });
        }
    }
    rows
}

/// The figures the explorer draws (Fig. 7 is its range surface).
const EXPLORER_FIGURES: [u32; 11] = [3, 4, 5, 6, 8, 9, 10, 11, 12, 13, 14];

/// Each figure's data for the fastball, as the explorer's figures pane asks
/// for it (the same call as `homerun figure N`), and the two sensitivity
/// columns of its inputs pane, for all inputs.
fn explorer(effort: Effort) -> Vec<ExplorerRow> {
    use super::figures::{figure_data, work_steps};
    use super::sensitivity;
    use model::keys::swing_keys;
    let scene = Scene::default();
    let runs = effort.surface_runs;
    let mut rows = Vec::new();
    for number in EXPLORER_FIGURES {
        let (time, cpu) = time_median(runs, 1, || figure_data(number, &scene, "fastball"));
        rows.push(ExplorerRow {
            work: format!("figure {number}"),
            detail: work_steps(number).map_or(
                "curves over the model, no optimisation".into(),
                |(n, what)| format!("{n} {what}, one optimisation each"),
            ),
            time_ms: time * 1e3,
            cpu_ms: cpu.map(|c| c * 1e3),
        });
    }
    let inputs = swing_keys().count();
    let range = model::range(&scene, Purpose::Readout);
    let keys: Vec<_> = swing_keys().collect();
    let (time, cpu) = time_median(runs, 1, || {
        sensitivity::range_gains_in(&scene, &keys, range, units::UnitSystem::Si)
    });
    rows.push(ExplorerRow {
        work: "sensitivity at the swing".into(),
        detail: format!("{inputs} inputs, one flight each, in lock-step"),
        time_ms: time * 1e3,
        cpu_ms: cpu.map(|c| c * 1e3),
    });
    let best = super::optimum::optimize(&scene, OptimizerSettings::default());
    let optimum = best.point();
    let moving = swing_keys()
        .filter(|k| sensitivity::moves_optimum(k))
        .count();
    let (time, cpu) = time_median(runs, 1, || {
        swing_keys()
            .map(|key| sensitivity::optimum_gain(&scene, key, optimum, &|| false))
            .collect::<Vec<_>>()
    });
    rows.push(ExplorerRow {
        work: "sensitivity at the optimum".into(),
        detail: format!("{moving} inputs, one warm-started optimisation each"),
        time_ms: time * 1e3,
        cpu_ms: cpu.map(|c| c * 1e3),
    });
    rows
}

fn defaults(reference: f64) -> Vec<DefaultRow> {
    let scene = Scene::default();
    Purpose::CONSUMERS
        .iter()
        .map(|&purpose| DefaultRow {
            purpose: format!("{purpose:?}"),
            range_budget: purpose.range_budget(),
            tolerance: purpose.tolerance().relative,
            range_error: model::range(&scene, purpose) - reference,
        })
        .collect()
}

/// Measures everything (`quick`: a reduced version, seconds in release).
pub fn run(quick: bool) -> Report {
    let effort = Effort::new(quick);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let reference = model::range(&Scene::default(), Purpose::Reference);
    Report {
        threads,
        quick,
        reference: ReferenceCheck {
            range: reference,
            python_range: PYTHON_REFERENCE_RANGE,
            difference: reference - PYTHON_REFERENCE_RANGE,
        },
        trajectory: trajectories(effort, reference),
        aero: aero_trajectories(effort, quick),
        spatial: spatial::rows(effort, quick),
        optimisation: optimisations(effort, quick),
        surface: surfaces(effort, threads, quick),
        explorer: explorer(effort),
        defaults: defaults(reference),
        batch: batch(effort, threads, quick),
        parks: parks::rows(effort),
        floor: floor::report(effort, threads, quick),
        impact: impact::rows(effort, quick),
    }
}

/// Typical Statcast fly balls and line drives: 30–50 m/s (67–112 mph),
/// 5–45°, 1000–3000 rpm, spread over a grid.
fn batch_scenes(rows: usize) -> Vec<Scene> {
    (0..rows)
        .map(|i| {
            let f = |period: usize| (i % period) as f64 / (period - 1) as f64;
            Scene::default().with_launch(model::launch::BattedBall {
                speed: 30.0 + 20.0 * f(17),
                angle: (5.0 + 40.0 * f(13)).to_radians(),
                spin: (1000.0 + 2000.0 * f(11)) * std::f64::consts::TAU / 60.0,
                direction: 0.0,
                sidespin: 0.0,
            })
        })
        .collect()
}

/// `fly --batch`'s work apart from reading and writing the text (a few
/// percent of it): every row's flight to the fence and the ground.
fn batch(effort: Effort, threads: usize, quick: bool) -> Vec<BatchRow> {
    use rayon::prelude::*;
    let rows = if quick { 2_000 } else { 20_000 };
    let scenes = batch_scenes(rows);
    let fence = preset::FIELD_KEYS[0].default;
    let mut counts = vec![1, threads];
    counts.dedup();
    counts
        .into_iter()
        .map(|n| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .expect("a thread pool");
            let (time, cpu) = time_median(effort.surface_runs, 1, || {
                pool.install(|| {
                    scenes
                        .par_iter()
                        .map(|s| model::launch::height_at_distance(s, fence, Purpose::Readout))
                        .collect::<Vec<_>>()
                })
            });
            BatchRow {
                rows,
                threads: n,
                time_ms: time * 1e3,
                cpu_ms: cpu.map(|c| c * 1e3),
                rows_per_second: rows as f64 / time,
            }
        })
        .collect()
}
