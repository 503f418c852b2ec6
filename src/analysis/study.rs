//! Studies over many swings: the range surface over (E, ψ) (Fig. 7), the
//! optimum as one input is swept (Figs. 8–12), a slice in E (Fig. 13), C_D
//! along a flight (Fig. 14) and the impact against E for several μ
//! (Figs. 5–6). Parallel with rayon where the points are independent. Each
//! study calls the model and nothing else.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use super::optimum::{OptimizerSettings, Status, optimize_from};
use crate::model::flight::{FlightOptions, FlightSummary, TrajectoryPoint};
use crate::model::impact::{Collision, Regime};
use crate::model::keys::{InputError, TEXT_KEYS};
use crate::model::launch::SceneFlight;
use crate::model::many::fly_many;
use crate::model::{self, scene::Scene};

/// A rectangular grid over undercut (columns) and swing angle (rows).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Grid {
    /// E from, to (m).
    pub undercut: (f64, f64),
    /// ψ from, to (rad).
    pub swing_angle: (f64, f64),
    pub columns: usize,
    pub rows: usize,
}

impl Grid {
    /// The window of the paper's Fig. 7.
    pub fn figure7(columns: usize, rows: usize) -> Grid {
        Grid {
            undercut: (0.0, 0.05),
            swing_angle: (-0.6, 1.0),
            columns,
            rows,
        }
    }

    fn at(range: (f64, f64), i: usize, n: usize) -> f64 {
        if n <= 1 {
            0.5 * (range.0 + range.1)
        } else {
            range.0 + (range.1 - range.0) * i as f64 / (n - 1) as f64
        }
    }

    /// E of column `i`.
    pub fn undercut_at(&self, i: usize) -> f64 {
        Self::at(self.undercut, i, self.columns)
    }

    /// ψ of row `j`.
    pub fn swing_angle_at(&self, j: usize) -> f64 {
        Self::at(self.swing_angle, j, self.rows)
    }
}

/// What one cell of a range surface holds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CellOutcome {
    /// The ball lands, this far from the plate (m).
    Landed(f64),
    /// The ball does not land within its flight's limits (time or
    /// integration steps): it has no range.
    NotLanded,
    /// The bat cannot reach the ball there (|E| ≥ r_b + r_B).
    BatMisses,
    /// Not flown: the surface was cancelled or is not finished.
    NotComputed,
}

impl CellOutcome {
    /// The outcome of one flight: a range only if it landed.
    pub fn of_flight(landed: bool, range: f64) -> CellOutcome {
        if landed && range.is_finite() {
            CellOutcome::Landed(range)
        } else {
            CellOutcome::NotLanded
        }
    }

    /// The range, if the ball landed.
    pub fn range(self) -> Option<f64> {
        match self {
            CellOutcome::Landed(range) => Some(range),
            _ => None,
        }
    }
}

/// The outcome at every grid point, row-major (row j = ψ, column i = E).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Surface {
    pub grid: Grid,
    cells: Vec<CellOutcome>,
}

impl Surface {
    /// A surface of given outcomes, row-major; `None` unless there is one
    /// per grid point.
    pub fn from_outcomes(grid: Grid, cells: Vec<CellOutcome>) -> Option<Surface> {
        (cells.len() == grid.columns * grid.rows).then_some(Surface { grid, cells })
    }

    /// A surface with no cell flown yet.
    pub fn not_computed(grid: Grid) -> Surface {
        Surface {
            grid,
            cells: vec![CellOutcome::NotComputed; grid.columns * grid.rows],
        }
    }

    /// The range at (column, row), if the ball lands there.
    pub fn get(&self, column: usize, row: usize) -> Option<f64> {
        self.outcome(column, row).range()
    }

    /// What happened at (column, row).
    pub fn outcome(&self, column: usize, row: usize) -> CellOutcome {
        self.cells[row * self.grid.columns + column]
    }

    /// Every cell's outcome, row-major.
    pub fn outcomes(&self) -> &[CellOutcome] {
        &self.cells
    }

    /// The ranges of the cells whose ball lands.
    pub fn landed_ranges(&self) -> impl Iterator<Item = f64> + '_ {
        self.cells.iter().filter_map(|c| c.range())
    }

    /// Whether any cell's ball does not land.
    pub fn any_not_landed(&self) -> bool {
        self.cells.contains(&CellOutcome::NotLanded)
    }

    /// The highest cell whose ball lands: (column, row, range).
    pub fn best(&self) -> Option<(usize, usize, f64)> {
        self.cells
            .iter()
            .enumerate()
            .filter_map(|(k, c)| c.range().map(|r| (k, r)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(k, r)| (k % self.grid.columns, k / self.grid.columns, r))
    }
}

/// What happens with `scene`'s swing replaced by (E, ψ).
pub fn outcome_at(
    scene: &Scene,
    undercut: f64,
    swing_angle: f64,
    options: impl Into<FlightOptions>,
) -> CellOutcome {
    if undercut.abs() >= scene.reach() {
        return CellOutcome::BatMisses;
    }
    let flight = model::simulate(&scene.with_swing(undercut, swing_angle), options).flight;
    CellOutcome::of_flight(flight.landed, flight.range)
}

/// The range of `scene` with its swing replaced by (E, ψ), if the bat
/// reaches and the ball lands.
pub fn range_at(
    scene: &Scene,
    undercut: f64,
    swing_angle: f64,
    options: impl Into<FlightOptions>,
) -> Option<f64> {
    outcome_at(scene, undercut, swing_angle, options).range()
}

/// The most integration steps a sweep's optimisations may take together
/// (about 3 s on one core), shared by its points: each point's optimiser
/// gets the smaller of an even share of what is left and its own
/// [`OptimizerSettings::max_flight_steps`], and flies at least one swing (so
/// the sweep may overrun by a flight a point). An ordinary point takes 3 000
/// to 10 000 (warm-started), so a share stays ample up to 200 points.
pub const SWEEP_FLIGHT_STEPS: u64 = 10_000_000;

/// Why [`surface_within`] gave up: the work it would take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TooMuchWork {
    /// Cells flown before giving up, and the integration steps they took.
    pub cells: usize,
    pub steps: u64,
    /// Cells in the whole grid (those the bat reaches).
    pub total: usize,
}

impl TooMuchWork {
    /// The mean integration steps of a flight so far.
    pub fn steps_per_cell(&self) -> f64 {
        self.steps as f64 / self.cells.max(1) as f64
    }
}

/// As [`surface`], within a budget of `max_steps` integration steps over all
/// its flights, reporting each cell done to `tick`. It gives up as soon as
/// the steps taken pass the budget, or, once 64 cells are done, as soon as
/// their mean says the whole grid would take twice the budget.
pub fn surface_within(
    scene: &Scene,
    grid: Grid,
    options: impl Into<FlightOptions>,
    max_steps: u64,
    tick: &(dyn Fn() + Sync),
) -> Result<Surface, TooMuchWork> {
    let each_chunk = |_: usize, _: &[CellOutcome]| ();
    surface_within_then(scene, grid, options, max_steps, tick, &each_chunk).map(|(s, _)| s)
}

/// As [`surface_within`], handing each chunk's cells to `each_chunk` on the
/// chunk's thread as soon as they are flown: `each_chunk(first, outcomes)`,
/// `outcomes[n]` being cell `first + n`'s (row-major). Its results come
/// back in the cells' order (a surface's CSV is written so, in parallel
/// pieces, while the other chunks fly).
pub fn surface_within_then<T: Send>(
    scene: &Scene,
    grid: Grid,
    options: impl Into<FlightOptions>,
    max_steps: u64,
    tick: &(dyn Fn() + Sync),
    each_chunk: &(dyn Fn(usize, &[CellOutcome]) -> T + Sync),
) -> Result<(Surface, Vec<T>), TooMuchWork> {
    let options = options.into();
    let reach = scene.reach();
    let total = (0..grid.columns)
        .filter(|&i| grid.undercut_at(i).abs() < reach)
        .count()
        * grid.rows;
    let steps = AtomicU64::new(0);
    let cells_flown = AtomicUsize::new(0);
    let over = || {
        let (steps, cells) = (
            steps.load(Ordering::Relaxed),
            cells_flown.load(Ordering::Relaxed),
        );
        steps > max_steps
            || (cells >= 64 && steps as f64 / cells as f64 * total as f64 > 2.0 * max_steps as f64)
    };
    // The chunks (the same as `surface_until`'s, so that a cell's range is
    // the same in both) in a spread-out order, so that the first ones done
    // are a fair sample of the grid's work.
    let chunks = chunks(grid.rows * grid.columns);
    let stride = spread(chunks.len());
    // Collected as a Vec of Options (each chunk's place known in advance),
    // not an Option of a Vec, which rayon gathers in lists of Vecs grown by
    // `realloc` as they fill.
    let done: Vec<Option<(usize, [CellOutcome; CHUNK], T)>> = (0..chunks.len())
        .into_par_iter()
        .map(|m| {
            if over() {
                return None;
            }
            let chunk = chunks[m * stride % chunks.len()].clone();
            let (first, count) = (chunk.start, chunk.len());
            let mut outcomes = [CellOutcome::NotComputed; CHUNK];
            let (mut taken, mut flown) = (0, 0);
            fly_cells(scene, grid, chunk, &options, |k, outcome, steps| {
                taken += steps;
                flown += usize::from(steps > 0);
                outcomes[k - first] = outcome;
            });
            // Counted once a chunk, where the budget is checked: the
            // counters' cache line moves between the cores once a chunk,
            // not three times a cell.
            steps.fetch_add(taken, Ordering::Relaxed);
            cells_flown.fetch_add(flown, Ordering::Relaxed);
            (0..count).for_each(|_| tick());
            let then = each_chunk(first, &outcomes[..count]);
            Some((first, outcomes, then))
        })
        .collect();
    let Some(mut done) = done.into_iter().collect::<Option<Vec<_>>>() else {
        return Err(TooMuchWork {
            cells: cells_flown.load(Ordering::Relaxed),
            steps: steps.load(Ordering::Relaxed),
            total,
        });
    };
    done.sort_unstable_by_key(|(first, _, _)| *first);
    let mut surface = Surface::not_computed(grid);
    let count = surface.cells.len();
    let mut thens = Vec::with_capacity(done.len());
    for (first, outcomes, then) in done {
        let last = (first + CHUNK).min(count);
        surface.cells[first..last].copy_from_slice(&outcomes[..last - first]);
        thens.push(then);
    }
    Ok((surface, thens))
}

/// Cells a chunk of a surface flies in lock-step: enough that the lanes'
/// last flights (some lanes idle) cost little, few enough that the chunks
/// spread over the cores and a cancellation is seen soon (64 cells take
/// ~50 µs).
const CHUNK: usize = 64;

/// Flights a chunk of a short list flies in lock-step ([`fly_all`]): a
/// few chunks for the cores, each a few times the lanes.
const FEW: usize = 8;

/// 0..count in chunks of [`CHUNK`].
fn chunks(count: usize) -> Vec<std::ops::Range<usize>> {
    (0..count)
        .step_by(CHUNK)
        .map(|start| start..(start + CHUNK).min(count))
        .collect()
}

/// Flies the grid's cells `cells` (row-major indices) in lock-step:
/// `done(k, outcome, steps)` for each cell k, `steps` the integration
/// steps its flight took (0 where the bat misses).
fn fly_cells(
    scene: &Scene,
    grid: Grid,
    cells: impl Iterator<Item = usize>,
    options: &FlightOptions,
    mut done: impl FnMut(usize, CellOutcome, u64),
) {
    let reach = scene.reach();
    let mut flown = Vec::with_capacity(cells.size_hint().0);
    let mut flights = Vec::with_capacity(cells.size_hint().0);
    for k in cells {
        let (i, j) = (k % grid.columns, k / grid.columns);
        let undercut = grid.undercut_at(i);
        if undercut.abs() >= reach {
            done(k, CellOutcome::BatMisses, 0);
            continue;
        }
        let swing = scene.with_swing(undercut, grid.swing_angle_at(j));
        flown.push(k);
        flights.push(SceneFlight::of_impact(&swing, &Collision::new(&swing)));
    }
    fly_many(flights, options, |index, flight| {
        let taken = u64::from(flight.stats.accepted) + u64::from(flight.stats.rejected);
        done(
            flown[index],
            CellOutcome::of_flight(flight.landed, flight.range),
            taken.max(1),
        );
    });
}

/// A step through 0..n that visits every index once (coprime with n) and
/// spreads them out: the nearest such step to n/φ.
fn spread(n: usize) -> usize {
    let gcd = |mut a: usize, mut b: usize| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut stride = ((n as f64 * 0.618_034).round() as usize).max(1);
    while gcd(stride, n) != 1 {
        stride += 1;
    }
    stride
}

/// The range surface, in parallel over chunks of cells, each flown in
/// lock-step.
pub fn surface(scene: &Scene, grid: Grid, options: impl Into<FlightOptions>) -> Surface {
    surface_until(scene, grid, options, &|| false).expect("never cancelled")
}

/// As [`surface`], giving up (`None`) as soon as `cancelled()` turns true:
/// it is polled before every chunk of [`CHUNK`] cells.
pub fn surface_until(
    scene: &Scene,
    grid: Grid,
    options: impl Into<FlightOptions>,
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Option<Surface> {
    let options = options.into();
    let chunks: Option<Vec<Vec<(usize, CellOutcome)>>> = chunks(grid.rows * grid.columns)
        .into_par_iter()
        .map(|chunk| {
            if cancelled() {
                return None;
            }
            let mut done = Vec::with_capacity(chunk.len());
            fly_cells(scene, grid, chunk, &options, |k, outcome, _| {
                done.push((k, outcome));
            });
            Some(done)
        })
        .collect();
    let mut surface = Surface::not_computed(grid);
    for (k, outcome) in chunks?.into_iter().flatten() {
        surface.cells[k] = outcome;
    }
    Some(surface)
}

/// One point of a sweep: the optimal swing with one input set to `value`
/// (Figs. 8–12), and the launch it gives.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SweepPoint {
    /// The swept input's value.
    pub value: f64,
    pub undercut: f64,
    pub swing_angle: f64,
    pub range: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub evaluations: u32,
    pub converged: bool,
    /// Why its search stopped: converged, which limit, or nothing lands.
    pub status: Status,
    /// Whether any swing tried lands; if none does, there is no optimum and
    /// `range` is −∞.
    pub landed: bool,
    /// Whether the optimum's flight lands only just inside its time limit:
    /// the limit, not the swing, sets its range.
    pub at_time_limit: bool,
    /// Whether the optimum, flown again at readout precision (as `hit` and
    /// `optimize` report a flight), lands too. A hovering or looping ball
    /// can graze the ground at one precision and miss it at another.
    pub lands_at_readout: bool,
}

/// Why a sweep was refused before any computation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    #[error(transparent)]
    Input(#[from] InputError),
    #[error(
        "{0}: the optimiser chooses this one; sweep another key (e.g. bat.speed, pitch.spin, environment.wind)"
    )]
    ControlVariable(&'static str),
    #[error("{0} is not a number and cannot be swept; run once per value with --set {0}=NAME")]
    NotNumeric(&'static str),
    #[error("sweep point {index} of {count}: {source}")]
    Point {
        index: usize,
        count: usize,
        source: InputError,
    },
}

/// The scenes of a sweep of `key` over `values`, each validated, before any
/// computation: the first bad value is an error naming the key.
pub fn sweep_scenes(scene: &Scene, key: &str, values: &[f64]) -> Result<Vec<Scene>, SweepError> {
    if let Some(text) = TEXT_KEYS.iter().find(|k| **k == key) {
        return Err(SweepError::NotNumeric(text));
    }
    let key = Scene::key(key)?;
    if key.name == "bat.undercut" || key.name == "bat.swing_angle" {
        return Err(SweepError::ControlVariable(key.name));
    }
    values
        .iter()
        .enumerate()
        .map(|(index, &value)| {
            let mut s = *scene;
            (key.set)(&mut s, value);
            s.validate().map_err(|source| SweepError::Point {
                index: index + 1,
                count: values.len(),
                source,
            })?;
            Ok(s)
        })
        .collect()
}

/// `steps` equally spaced values from `from` to `to` (both included).
pub fn linspace(from: f64, to: f64, steps: usize) -> Vec<f64> {
    match steps {
        0 => Vec::new(),
        1 => vec![from],
        n => (0..n)
            .map(|i| from + (to - from) * i as f64 / (n - 1) as f64)
            .collect(),
    }
}

/// The optimum as `key` is swept over `values` (Figs. 8–12). Each point is
/// warm-started from the previous optimum, which makes the sweep sequential
/// but about twice as cheap per point, and keeps it on one ridge. The points
/// share a work budget of [`SWEEP_FLIGHT_STEPS`].
pub fn sweep(
    scene: &Scene,
    key: &str,
    values: &[f64],
    settings: OptimizerSettings,
) -> Result<Vec<SweepPoint>, SweepError> {
    sweep_observed(scene, key, values, settings, &mut || {})
}

/// As [`sweep`], calling `tick` after each point.
pub fn sweep_observed(
    scene: &Scene,
    key: &str,
    values: &[f64],
    settings: OptimizerSettings,
    tick: &mut dyn FnMut(),
) -> Result<Vec<SweepPoint>, SweepError> {
    let scenes = sweep_scenes(scene, key, values)?;
    let mut start = (scene.bat.undercut, scene.bat.swing_angle);
    let mut remaining = SWEEP_FLIGHT_STEPS;
    let count = scenes.len() as u64;
    Ok(scenes
        .iter()
        .zip(values)
        .zip(0..)
        .map(|((s, &value), done)| {
            // An even share of what is left: a point that takes less leaves
            // more for the others.
            let settings = OptimizerSettings {
                max_flight_steps: settings.max_flight_steps.min(remaining / (count - done)),
                ..settings
            };
            let optimum = optimize_from(s, start, settings);
            remaining = remaining.saturating_sub(optimum.flight_steps);
            tick();
            // A search that found nothing landing leaves the next one
            // where it started.
            if optimum.landed {
                start = (optimum.undercut, optimum.swing_angle);
            }
            let best = s.with_swing(optimum.undercut, optimum.swing_angle);
            let impact = Collision::new(&best);
            // One flight more per point (~0.1 ms) to say the same as `optimize`.
            let lands_at_readout = optimum.landed
                && model::simulate(&best, crate::Purpose::Readout)
                    .flight
                    .landed;
            SweepPoint {
                value,
                undercut: optimum.undercut,
                swing_angle: optimum.swing_angle,
                range: optimum.range,
                launch_speed: impact.launch_speed(),
                launch_spin: impact.launch_spin(),
                launch_angle: impact.launch_angle(),
                evaluations: optimum.evaluations,
                converged: optimum.converged,
                status: optimum.status,
                landed: optimum.landed,
                at_time_limit: optimum.at_time_limit,
                lands_at_readout,
            }
        })
        .collect())
}

/// One point of a slice in E at fixed ψ (Fig. 13): launch and range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SlicePoint {
    pub undercut: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub range: f64,
    /// Whether the ball lands; if not, `range` is where it was at its limit.
    pub landed: bool,
}

/// Launch and range at each undercut in `undercuts`, the swing angle held at
/// `swing_angle` (Fig. 13), flown in lock-step. Undercuts the bat cannot reach
/// (|E| ≥ r_b + r_B) are left out.
pub fn slice(
    scene: &Scene,
    swing_angle: f64,
    undercuts: &[f64],
    options: impl Into<FlightOptions>,
) -> Vec<SlicePoint> {
    let reachable: Vec<(f64, Collision, SceneFlight)> = undercuts
        .iter()
        .filter(|e| e.abs() < scene.reach())
        .map(|&undercut| {
            let swing = scene.with_swing(undercut, swing_angle);
            let impact = Collision::new(&swing);
            (undercut, impact, SceneFlight::of_impact(&swing, &impact))
        })
        .collect();
    let flights: Vec<SceneFlight> = reachable.iter().map(|(_, _, flight)| *flight).collect();
    reachable
        .iter()
        .zip(fly_all(&flights, &options.into()))
        .map(|((undercut, impact, _), flight)| SlicePoint {
            undercut: *undercut,
            launch_speed: impact.launch_speed(),
            launch_spin: impact.launch_spin(),
            launch_angle: impact.launch_angle(),
            range: flight.range,
            landed: flight.landed,
        })
        .collect()
}

/// Flies `flights` in lock-step, in parallel chunks of [`FEW`] (the same
/// on any number of cores, so that each flight's steps are too), giving
/// their summaries in their order.
pub fn fly_all(flights: &[SceneFlight], options: &FlightOptions) -> Vec<FlightSummary> {
    flights
        .par_chunks(FEW)
        .flat_map_iter(|chunk| {
            let mut summaries = vec![None; chunk.len()];
            fly_many(chunk.iter().copied(), options, |index, summary| {
                summaries[index] = Some(summary);
            });
            summaries.into_iter().flatten()
        })
        .collect()
}

/// C_D (and the whole path) along the flight of `scene`'s own swing at
/// `samples` equal time steps (Fig. 14: C_D against time).
pub fn drag_along_flight(
    scene: &Scene,
    samples: usize,
    options: impl Into<FlightOptions>,
) -> (FlightSummary, Vec<TrajectoryPoint>) {
    let impact = Collision::new(scene);
    SceneFlight::of_impact(scene, &impact).trajectory(&options.into(), samples)
}

/// One point of Figs. 5–6: the batted spin ω_bf and launch angle ζ at an
/// undercut, and whether slip halted.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImpactPoint {
    pub undercut: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub regime: Regime,
}

/// The impact alone, against E, for one friction coefficient.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpactCurve {
    pub friction: f64,
    pub points: Vec<ImpactPoint>,
}

/// ω_bf and ζ against E for each μ in `frictions` (Figs. 5–6). Impacts are
/// closed-form and cheap, so this needs no parallelism. Undercuts the bat
/// cannot reach are left out.
pub fn impact_curves(scene: &Scene, frictions: &[f64], undercuts: &[f64]) -> Vec<ImpactCurve> {
    let reach = scene.reach();
    frictions
        .iter()
        .map(|&friction| ImpactCurve {
            friction,
            points: undercuts
                .iter()
                .filter(|e| e.abs() < reach)
                .map(|&undercut| {
                    let mut s = *scene;
                    s.bat.friction = friction;
                    let impact = Collision::new(&s.with_swing(undercut, scene.bat.swing_angle));
                    ImpactPoint {
                        undercut,
                        launch_speed: impact.launch_speed(),
                        launch_spin: impact.launch_spin(),
                        launch_angle: impact.launch_angle(),
                        regime: impact.regime(),
                    }
                })
                .collect(),
        })
        .collect()
}

impl Grid {
    /// The explorer's heatmap window: the paper's Fig. 7, E from 0 to 50 mm,
    /// ψ from −0.6 to 1.0 rad (the explorer sets the resolution per job).
    pub fn explorer_window() -> Grid {
        Grid::figure7(2, 2)
    }
}
