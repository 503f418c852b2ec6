//! The range surface over (E, ψ) (Fig. 7): its grid, its cells, and their
//! flights, in parallel over chunks of cells, each chunk in lock-step.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use model::flight::FlightOptions;
use model::impact::{Collision, Impact, ImpactAngles, NormalAngles, PitchAngles};
use model::launch::SceneFlight;
use model::many::land_many;
use model::{self, scene::Scene};

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

/// The most integration steps a sweep's optimisations may take together
/// (about 3 s on one core), shared by its points: each point's optimiser
/// gets the smaller of an even share of what is left and its own
/// [`OptimizerSettings::max_flight_steps`](crate::optimum::OptimizerSettings::max_flight_steps), and flies at least one swing (so
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
    let keep = |first: usize, outcomes: &[CellOutcome]| {
        let mut kept = [CellOutcome::NotComputed; CHUNK];
        kept[..outcomes.len()].copy_from_slice(outcomes);
        (first, kept)
    };
    let done = surface_chunks_within(scene, grid, options, max_steps, tick, &keep)?;
    let mut surface = Surface::not_computed(grid);
    let count = surface.cells.len();
    for (first, outcomes) in done {
        let last = (first + CHUNK).min(count);
        surface.cells[first..last].copy_from_slice(&outcomes[..last - first]);
    }
    Ok(surface)
}

/// As [`surface_within`], handing each chunk's cells to `each_chunk` on
/// the chunk's thread as soon as they are flown (`each_chunk(first,
/// outcomes)`, `outcomes[n]` being cell `first + n`'s, row-major), and
/// giving back its results alone, in the cells' order: no [`Surface`] is
/// kept (a surface's CSV needs its lines, written as the chunks are flown,
/// and nothing else).
pub fn surface_chunks_within<T: Send>(
    scene: &Scene,
    grid: Grid,
    options: impl Into<FlightOptions>,
    max_steps: u64,
    tick: &(dyn Fn() + Sync),
    each_chunk: &(dyn Fn(usize, &[CellOutcome]) -> T + Sync),
) -> Result<Vec<T>, TooMuchWork> {
    let options = options.into();
    let angles = GridAngles::of(scene, grid);
    let angles = angles.as_ref();
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
    // are a fair sample of the grid's work: the m-th flown is chunk
    // m·stride mod n.
    let chunks = chunks(grid.rows * grid.columns);
    let stride = spread(chunks.len());
    // Collected as a Vec of Options (each chunk's place known in advance),
    // not an Option of a Vec, which rayon gathers in lists of Vecs grown by
    // `realloc` as they fill.
    let done: Vec<Option<T>> = (0..chunks.len())
        .into_par_iter()
        .map(|m| {
            if over() {
                return None;
            }
            let chunk = chunks[m * stride % chunks.len()].clone();
            let first = chunk.start;
            let mut outcomes = [CellOutcome::NotComputed; CHUNK];
            let count = chunk.len();
            let (mut taken, mut flown) = (0, 0);
            fly_cells(
                scene,
                grid,
                chunk,
                (&options, angles),
                |k, outcome, steps| {
                    taken += steps;
                    flown += usize::from(steps > 0);
                    outcomes[k - first] = outcome;
                },
            );
            // Counted once a chunk, where the budget is checked: the
            // counters' cache line moves between the cores once a chunk,
            // not three times a cell.
            steps.fetch_add(taken, Ordering::Relaxed);
            cells_flown.fetch_add(flown, Ordering::Relaxed);
            (0..count).for_each(|_| tick());
            Some(each_chunk(first, &outcomes[..count]))
        })
        .collect();
    let too_much = || TooMuchWork {
        cells: cells_flown.load(Ordering::Relaxed),
        steps: steps.load(Ordering::Relaxed),
        total,
    };
    if done.iter().any(Option::is_none) {
        return Err(too_much());
    }
    // In the cells' order: chunk c was the m-th flown, c = m·stride mod n.
    let n = chunks.len();
    let mut flown_as = vec![0; n];
    for m in 0..n {
        flown_as[m * stride % n] = m;
    }
    let mut done: Vec<Option<T>> = done;
    flown_as
        .into_iter()
        .map(|m| done[m].take().ok_or_else(too_much))
        .collect()
}

/// Cells a chunk of a surface flies in lock-step: enough that the lanes'
/// last flights (some lanes idle) cost little, few enough that the chunks
/// spread over the cores and a cancellation is seen soon (64 cells take
/// ~50 µs).
const CHUNK: usize = 64;

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
    (options, angles): (&FlightOptions, Option<&GridAngles>),
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
        let flight = match angles {
            // The cell's swing is all in its angles: the rest of its scene
            // is the grid's (not copied for each cell).
            Some(angles) => {
                let impact = Collision::Planar(Impact::with_angles(scene, angles.at(i, j)));
                SceneFlight::of_impact(scene, &impact)
            }
            None => {
                let swing = scene.with_swing(undercut, grid.swing_angle_at(j));
                SceneFlight::of_impact(&swing, &Collision::new(&swing))
            }
        };
        flown.push(k);
        flights.push(flight);
    }
    land_many(flights, options, |index, flight| {
        let taken = u64::from(flight.stats.accepted) + u64::from(flight.stats.rejected);
        done(
            flown[index],
            CellOutcome::of_flight(flight.landed, flight.range),
            taken.max(1),
        );
    });
}

/// A planar swing's impact angles over a grid, in parts: the pitch's once,
/// the undercut's once a column, the swing's once a row
/// ([`ImpactAngles`]). None for a 3-D bat, whose impact is another.
struct GridAngles {
    pitch: PitchAngles,
    columns: Vec<NormalAngles>,
    rows: Vec<nalgebra::Vector2<f64>>,
}

impl GridAngles {
    fn of(scene: &Scene, grid: Grid) -> Option<GridAngles> {
        if !scene.bat.is_planar() {
            return None;
        }
        let (undercut, swing_angle) = (scene.bat.undercut, scene.bat.swing_angle);
        let column = |i| NormalAngles::of(&scene.with_swing(grid.undercut_at(i), swing_angle));
        let row =
            |j| ImpactAngles::bat_velocity(&scene.with_swing(undercut, grid.swing_angle_at(j)));
        Some(GridAngles {
            pitch: PitchAngles::of(scene),
            columns: (0..grid.columns).map(column).collect(),
            rows: (0..grid.rows).map(row).collect(),
        })
    }

    fn at(&self, column: usize, row: usize) -> ImpactAngles {
        ImpactAngles {
            pitch: self.pitch,
            normal: self.columns[column],
            bat_velocity_before: self.rows[row],
        }
    }
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
/// it is polled before every chunk of `CHUNK` cells.
pub fn surface_until(
    scene: &Scene,
    grid: Grid,
    options: impl Into<FlightOptions>,
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Option<Surface> {
    let options = options.into();
    let angles = GridAngles::of(scene, grid);
    let angles = angles.as_ref();
    let chunks: Option<Vec<Vec<(usize, CellOutcome)>>> = chunks(grid.rows * grid.columns)
        .into_par_iter()
        .map(|chunk| {
            if cancelled() {
                return None;
            }
            let mut done = Vec::with_capacity(chunk.len());
            fly_cells(scene, grid, chunk, (&options, angles), |k, outcome, _| {
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

impl Grid {
    /// The explorer's heatmap window: the paper's Fig. 7, E from 0 to 50 mm,
    /// ψ from −0.6 to 1.0 rad (the explorer sets the resolution per job).
    pub fn explorer_window() -> Grid {
        Grid::figure7(2, 2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::precision::Purpose;

    #[test]
    fn a_surface_s_chunks_come_back_in_the_cells_order() {
        // 9 chunks (the last short), flown in a spread-out order: each
        // chunk's results in the cells' order, the surface's cells.
        let scene = Scene::default();
        let grid = Grid::figure7(31, 18);
        let tick = || {};
        let chunks = surface_chunks_within(
            &scene,
            grid,
            Purpose::Surface,
            u64::MAX,
            &tick,
            &|first, outcomes| (first, outcomes.to_vec()),
        )
        .expect("within the budget");
        assert_eq!(chunks.len(), 9);
        let firsts: Vec<usize> = chunks.iter().map(|(first, _)| *first).collect();
        assert_eq!(firsts, (0..9).map(|c| c * CHUNK).collect::<Vec<_>>());
        let cells: Vec<CellOutcome> = chunks.into_iter().flat_map(|(_, o)| o).collect();
        let whole = surface_within(&scene, grid, Purpose::Surface, u64::MAX, &tick)
            .expect("within the budget");
        assert_eq!(cells, whole.outcomes());
        // Over the budget, both give up alike.
        let refused = |steps| {
            let chunks =
                surface_chunks_within(&scene, grid, Purpose::Surface, steps, &tick, &|_, _| ());
            let whole = surface_within(&scene, grid, Purpose::Surface, steps, &tick);
            (chunks.err(), whole.err())
        };
        let (chunks, whole) = refused(100);
        assert!(chunks.is_some() && whole.is_some());
        assert_eq!(chunks.map(|w| w.total), Some(grid.columns * grid.rows));
    }

    #[test]
    fn a_grid_s_impact_angles_are_each_cell_s_own() {
        // Each cell's angles from its column's, its row's and the pitch's
        // parts: exactly those of its own scene, for a grid that is not
        // square (a column taken for a row would be caught).
        let mut scene = Scene::default();
        scene.pitch.speed = 35.0;
        let grid = Grid::figure7(7, 5);
        let angles = GridAngles::of(&scene, grid).expect("a level bat");
        for (i, j) in [(0, 0), (6, 0), (0, 4), (3, 2), (6, 4)] {
            let cell = scene.with_swing(grid.undercut_at(i), grid.swing_angle_at(j));
            assert_eq!(angles.at(i, j), ImpactAngles::of(&cell), "({i}, {j})");
            assert_eq!(
                Impact::with_angles(&cell, angles.at(i, j)),
                Impact::new(&cell)
            );
            // Nor does the rest of the cell's scene differ from the grid's
            // for its impact and flight (what `fly_cells` relies on).
            let impact = Collision::Planar(Impact::with_angles(&scene, angles.at(i, j)));
            assert_eq!(impact, Collision::new(&cell), "({i}, {j})");
            assert_eq!(
                SceneFlight::of_impact(&scene, &impact),
                SceneFlight::of_impact(&cell, &Collision::new(&cell))
            );
        }
        // A tilted bat's impact is the 3-D one: no planar angles.
        scene.bat.tilt = 0.3;
        assert!(GridAngles::of(&scene, grid).is_none());
    }
}
