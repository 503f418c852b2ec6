//! The background work: the optimiser (warm-started, one Nelder–Mead step at
//! a time, streaming its best point), the range surface (coarse to fine) and
//! the sensitivity of the range to each input (at the current swing, then at
//! the optimum), streamed input by input.
//!
//! Plain std threads and channels, no async runtime. Every job carries a
//! generation number; the UI bumps it on each input change, the worker polls
//! it between steps and cells and abandons stale work, and the UI drops any
//! report whose generation is not the current one. The paper's figures and
//! the margin map ([`super::margin`]) have their own threads and
//! generations, so that stepping through figures or parks never cancels
//! the optimiser.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;
use std::time::{Duration, Instant};

use crate::inputs::{input_key, scene_inputs};
use crate::margin::{MarginJob, MarginReport, run_margin_job};
use analysis::figures::{self, Figure, FigureData};
use analysis::optimum::{Optimizer, OptimizerSettings, Point, Status};
use analysis::precision::Purpose;
use analysis::sensitivity;
use analysis::study::{self, Grid, Surface};
use model::launch::{SceneKind, fly_scene};
use model::scene::Scene;
use units::UnitSystem;

/// What the UI wants computed for one set of inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Job {
    pub generation: u64,
    pub scene: Scene,
    /// Where the optimiser starts: the last optimum (warm start) or the
    /// scene's own swing.
    pub start: (f64, f64),
    /// The heatmap's window over (E, ψ).
    pub window: Grid,
    /// The finest surface: the heatmap pane's pixels (columns, rows).
    pub resolution: (usize, usize),
    /// Whether to compute Δopt: only where the inputs pane shows it.
    pub optimum_gains: bool,
    /// Whether to compute the range surface: not while the heatmap shows
    /// the margin at a park instead.
    pub range_surface: bool,
    /// The units shown: a nudge, and so the Δ columns, moves by the shown
    /// unit's step.
    pub units: UnitSystem,
    pub work: Work,
}

/// How much of a job to do. A batted ball gets only its Δ column, whatever
/// is asked: it has no optimum, surface or Δopt.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Work {
    /// The surface, the optimum, Δ and Δopt.
    Everything,
    /// Only Δ and Δopt, for the optimum found already (the units changed,
    /// the inputs did not).
    Gains { optimum: Option<Point> },
    /// Only the range surface (the heatmap is back from the margin map).
    Surface,
}

/// A result, tagged with the generation it was computed for.
#[derive(Clone, Debug, PartialEq)]
pub enum Report {
    /// The optimiser's best point so far; `done` once it has stopped, and
    /// `status` why (converged, a limit, or nothing lands).
    Optimum {
        generation: u64,
        best: Point,
        evaluations: u32,
        done: bool,
        status: Status,
    },
    /// One refinement of the range surface; `last` for the finest.
    Surface {
        generation: u64,
        surface: Surface,
        last: bool,
    },
    /// The range gained (m) by one step up of input `key` (an index into
    /// `all_keys()`, see `app::input_key`), at the current swing or at the
    /// optimum; `None` where
    /// the nudge is refused, the ball does not land, or (at the optimum) the
    /// key is the swing itself.
    Sensitivity {
        generation: u64,
        gain: Gain,
        key: usize,
        value: Option<f64>,
    },
}

/// Which range a sensitivity is of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Gain {
    /// The current swing's (one flight per input).
    Swing,
    /// The optimal swing's (one warm-started optimisation per input).
    Optimum,
}

impl Report {
    pub fn generation(&self) -> u64 {
        match self {
            Report::Optimum { generation, .. }
            | Report::Surface { generation, .. }
            | Report::Sensitivity { generation, .. } => *generation,
        }
    }
}

/// One of the paper's figures to compute for the current inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureJob {
    pub generation: u64,
    pub number: u32,
    pub scene: Scene,
    pub preset_name: String,
}

/// A figure's data (or why there is none), tagged with its job's generation.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureReport {
    pub generation: u64,
    pub number: u32,
    pub figure: Result<FigureData, String>,
    /// How long it took to compute.
    pub elapsed: Duration,
}

/// Computes one figure, unless cancelled first. Every figure takes at most
/// ~20 ms (the sweeps, Figs. 8–12, run 11 warm-started optimisations), so
/// it is computed once, at full resolution, with no coarse pass.
pub fn run_figure_job(
    job: &FigureJob,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(FigureReport),
) {
    if cancelled() {
        return;
    }
    let start = Instant::now();
    let figure = match figures::figure_data(job.number, &job.scene, &job.preset_name) {
        Ok(Figure::Table(data)) => Ok(data),
        Ok(Figure::Surface(_)) => Err(format!("Fig. {} is the range surface (tab 2)", job.number)),
        Err(e) => Err(e.to_string()),
    };
    if cancelled() {
        return;
    }
    report(FigureReport {
        generation: job.generation,
        number: job.number,
        figure,
        elapsed: start.elapsed(),
    });
}

/// The optimiser's progress is reported every this many steps (and at the end).
const PROGRESS_EVERY: u32 = 8;

/// Runs one job to the end, or until `cancelled()`; each result goes to
/// `report`. The order is what the user waits for first: a coarse surface,
/// the optimum, the range gained per nudge at the current swing (~3 ms for
/// all inputs), the finer surfaces, and last the optimal range gained per
/// nudge (one warm-started optimisation per input, ~30 ms for all), so that
/// the sensitivities never delay the surface or the optimum. The same
/// function runs on the worker thread and, synchronously, in the tests.
pub fn run_job(job: &Job, cancelled: &(dyn Fn() -> bool + Sync), report: &mut dyn FnMut(Report)) {
    if job.scene.kind == SceneKind::BattedBall {
        report_range_gains(job, cancelled, report);
        return;
    }
    if let Work::Gains { optimum } = job.work {
        report_range_gains(job, cancelled, report);
        if let Some(optimum) = optimum {
            report_optimum_gains(job, optimum, cancelled, report);
        }
        return;
    }
    if job.work == Work::Surface {
        report_surfaces(job, cancelled, report);
        return;
    }
    // A first glance at the surface before the optimiser: 64 cells.
    if job.range_surface && !report_coarse_surface(job, cancelled, report) {
        return;
    }

    let mut optimizer = Optimizer::new(
        &job.scene,
        job.start,
        Purpose::Optimizer,
        OptimizerSettings::default(),
    );
    let mut steps = 0;
    loop {
        if cancelled() {
            return;
        }
        let status = optimizer.step();
        steps += 1;
        let done = status != Status::Running;
        if done || steps % PROGRESS_EVERY == 0 {
            report(Report::Optimum {
                generation: job.generation,
                best: optimizer.best(),
                evaluations: optimizer.evaluations(),
                done,
                status,
            });
        }
        if done {
            break;
        }
    }
    let optimum = optimizer.best();

    if !report_range_gains(job, cancelled, report) {
        return;
    }

    if job.range_surface && !report_finer_surfaces(job, cancelled, report) {
        return;
    }

    report_optimum_gains(job, optimum, cancelled, report);
}

/// The range surface of `job` on a grid of `columns` × `rows`, unless
/// cancelled.
fn surface_of(
    job: &Job,
    columns: usize,
    rows: usize,
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Option<Surface> {
    let grid = Grid {
        columns,
        rows,
        ..job.window
    };
    study::surface_until(&job.scene, grid, Purpose::Surface, cancelled)
}

/// The range surface alone, coarse to fine.
fn report_surfaces(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(Report),
) {
    if report_coarse_surface(job, cancelled, report) {
        report_finer_surfaces(job, cancelled, report);
    }
}

/// The range surface at 8×8 (or the pane's resolution if coarser); false
/// if cancelled.
fn report_coarse_surface(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(Report),
) -> bool {
    let (columns, rows) = (job.resolution.0.max(2), job.resolution.1.max(2));
    let Some(coarse) = surface_of(job, 8.min(columns), 8.min(rows), cancelled) else {
        return false;
    };
    report(Report::Surface {
        generation: job.generation,
        surface: coarse,
        last: columns <= 8 && rows <= 8,
    });
    true
}

/// The range surface at 32×16, then at the pane's full resolution; false
/// if cancelled.
fn report_finer_surfaces(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(Report),
) -> bool {
    let (columns, rows) = (job.resolution.0.max(2), job.resolution.1.max(2));
    let mut levels = vec![(32.min(columns), 16.min(rows))];
    if columns > 32 || rows > 16 {
        levels.push((columns, rows));
    }
    let count = levels.len();
    for (k, (c, r)) in levels.into_iter().enumerate() {
        if c <= 8 && r <= 8 {
            continue;
        }
        let Some(surface) = surface_of(job, c, r, cancelled) else {
            return false;
        };
        report(Report::Surface {
            generation: job.generation,
            surface,
            last: k + 1 == count,
        });
    }
    true
}

/// The range gained by one nudge of each input the scene shows, at the
/// current swing (or batted ball); false if cancelled.
fn report_range_gains(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(Report),
) -> bool {
    let flight = fly_scene(&job.scene, Purpose::Readout).flight;
    let range = if flight.landed {
        flight.range
    } else {
        f64::NAN
    };
    for k in scene_inputs(job.scene.kind) {
        if cancelled() {
            return false;
        }
        report(Report::Sensitivity {
            generation: job.generation,
            gain: Gain::Swing,
            key: k,
            value: sensitivity::range_gain_in(&job.scene, input_key(k), range, job.units),
        });
    }
    true
}

/// The optimal range gained by one nudge of each input, where the pane
/// shows that column.
fn report_optimum_gains(
    job: &Job,
    optimum: Point,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(Report),
) {
    if !job.optimum_gains {
        return;
    }
    for k in scene_inputs(job.scene.kind) {
        let key = input_key(k);
        let value = sensitivity::optimum_gain_in(&job.scene, key, optimum, job.units, cancelled);
        if cancelled() {
            return;
        }
        report(Report::Sensitivity {
            generation: job.generation,
            gain: Gain::Optimum,
            key: k,
            value,
        });
    }
}

/// The worker threads (the surface and optimiser; the figures; the margin
/// map) and their channels.
pub struct Worker {
    jobs: Sender<Job>,
    latest: Arc<AtomicU64>,
    pub reports: Receiver<Report>,
    figure_jobs: Sender<FigureJob>,
    latest_figure: Arc<AtomicU64>,
    pub figures: Receiver<FigureReport>,
    margin_jobs: Sender<MarginJob>,
    latest_margin: Arc<AtomicU64>,
    pub margins: Receiver<MarginReport>,
}

/// The signature of a job's work: the job, whether it is cancelled, where
/// its results go.
type Run<J, R> = fn(&J, &(dyn Fn() -> bool + Sync), &mut dyn FnMut(R));

/// A thread that runs `run` on the newest of the jobs sent to it, cancelling
/// a job as soon as a newer generation is stored in the returned counter.
fn spawn_runner<J: Send + 'static, R: Send + 'static>(
    name: &str,
    generation: fn(&J) -> u64,
    run: Run<J, R>,
) -> (Sender<J>, Arc<AtomicU64>, Receiver<R>) {
    let (jobs, job_rx) = mpsc::channel::<J>();
    let (report_tx, reports) = mpsc::channel();
    let latest = Arc::new(AtomicU64::new(0));
    let seen = Arc::clone(&latest);
    thread::Builder::new()
        .name(name.into())
        .spawn(move || {
            while let Ok(mut job) = job_rx.recv() {
                // Coalesce: only the newest inputs matter.
                while let Ok(newer) = job_rx.try_recv() {
                    job = newer;
                }
                let wanted = generation(&job);
                let cancelled = || seen.load(Ordering::Relaxed) != wanted;
                run(&job, &cancelled, &mut |r| {
                    let _ = report_tx.send(r);
                });
            }
        })
        .expect("spawn a worker thread");
    (jobs, latest, reports)
}

impl Worker {
    pub fn spawn() -> Worker {
        let (jobs, latest, reports) =
            spawn_runner("homerun-worker", |j: &Job| j.generation, run_job);
        let (figure_jobs, latest_figure, figures) = spawn_runner(
            "homerun-figures",
            |j: &FigureJob| j.generation,
            run_figure_job,
        );
        let (margin_jobs, latest_margin, margins) = spawn_runner(
            "homerun-margin",
            |j: &MarginJob| j.generation,
            run_margin_job,
        );
        Worker {
            jobs,
            latest,
            reports,
            figure_jobs,
            latest_figure,
            figures,
            margin_jobs,
            latest_margin,
            margins,
        }
    }

    /// Starts computing a margin map, cancelling the one before.
    pub fn submit_margin(&self, job: MarginJob) {
        self.cancel_margins_before(job.generation);
        let _ = self.margin_jobs.send(job);
    }

    /// Cancels any margin map for a generation other than `generation`
    /// (the map is no longer shown, or is for old inputs), whether or not
    /// a new one is wanted.
    pub fn cancel_margins_before(&self, generation: u64) {
        self.latest_margin.store(generation, Ordering::Relaxed);
    }

    /// Starts computing a figure, cancelling the one before.
    pub fn submit_figure(&self, job: FigureJob) {
        self.latest_figure.store(job.generation, Ordering::Relaxed);
        let _ = self.figure_jobs.send(job);
    }

    /// Starts `job`, cancelling whatever is running.
    pub fn submit(&self, job: Job) {
        self.latest.store(job.generation, Ordering::Relaxed);
        let _ = self.jobs.send(job);
    }
}
