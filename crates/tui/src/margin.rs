//! The margin map: how far over the wall of the chosen park (or the
//! preset's fence) the ball goes, [`Clearing::clearance`], over the same
//! window of swings (E, ψ) as the range surface, in place of the range
//! (key `c`). Computed off the UI thread on a thread of its own, a coarse
//! 8×8 first and then the pane's full resolution row by row from the top,
//! each block of rows sent as it is done; cancelled by a newer generation
//! (new inputs, another park) between cells.

use rayon::prelude::*;

use analysis::precision::Purpose;
use analysis::study::Grid;
use model::clearing::Clearing;
use model::flight::FlightOptions;
use model::launch::scene_start;
use model::park::Fence;
use model::scene::Scene;

/// What one swing of the map does at the fence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MarginCell {
    /// Its clearance (m): the height over the wall's top where it crosses
    /// the fence, negative under it (continued down the landing line for a
    /// ball that lands short).
    Margin(f64),
    /// It crosses the fence's line, or lands, outside the foul lines.
    Foul,
    /// It does not land within its flight's limits.
    NotLanded,
    /// The bat cannot reach the ball there.
    BatMisses,
    /// Not flown yet.
    NotComputed,
}

impl MarginCell {
    /// The margin, if there is one.
    pub fn margin(self) -> Option<f64> {
        match self {
            MarginCell::Margin(m) => Some(m),
            _ => None,
        }
    }
}

/// The margin at every grid point, row-major (row j = ψ, column i = E), as
/// [`analysis::study::Surface`] holds the range.
#[derive(Clone, Debug, PartialEq)]
pub struct MarginSurface {
    pub grid: Grid,
    pub cells: Vec<MarginCell>,
}

impl MarginSurface {
    /// A map with no cell flown yet.
    pub fn not_computed(grid: Grid) -> MarginSurface {
        MarginSurface {
            grid,
            cells: vec![MarginCell::NotComputed; grid.columns * grid.rows],
        }
    }

    /// The cell at (column, row).
    pub fn cell(&self, column: usize, row: usize) -> MarginCell {
        self.cells[row * self.grid.columns + column]
    }

    /// Puts `cells`, whole rows from `first_row` up, in place; false (and
    /// nothing changes) if they do not fit.
    pub fn fill(&mut self, first_row: usize, cells: &[MarginCell]) -> bool {
        let start = first_row * self.grid.columns;
        match self.cells.get_mut(start..start + cells.len()) {
            Some(slot) if cells.len().is_multiple_of(self.grid.columns.max(1)) => {
                slot.copy_from_slice(cells);
                true
            }
            _ => false,
        }
    }

    /// How many cells are flown.
    pub fn done(&self) -> usize {
        self.cells
            .iter()
            .filter(|c| **c != MarginCell::NotComputed)
            .count()
    }

    /// Whether every cell is flown.
    pub fn complete(&self) -> bool {
        self.done() == self.cells.len()
    }
}

/// What the margin thread computes for one set of inputs and one fence.
#[derive(Clone, Debug, PartialEq)]
pub struct MarginJob {
    pub generation: u64,
    pub scene: Scene,
    pub fence: Fence,
    /// The window over (E, ψ), and the finest grid: the heatmap's pixels.
    pub window: Grid,
    pub resolution: (usize, usize),
}

/// Rows of a map, from `first_row` up, for one generation.
#[derive(Clone, Debug, PartialEq)]
pub struct MarginReport {
    pub generation: u64,
    pub grid: Grid,
    pub first_row: usize,
    pub cells: Vec<MarginCell>,
}

/// The swing (E, ψ) of `scene` judged at `fence`: its clearance there.
pub fn margin_at(
    scene: &Scene,
    fence: &Fence,
    (undercut, swing_angle): (f64, f64),
    options: &FlightOptions,
) -> MarginCell {
    if undercut.abs() >= scene.reach() {
        return MarginCell::BatMisses;
    }
    let scene = scene.with_swing(undercut, swing_angle);
    let (flight, _, _) = scene_start(&scene);
    let (summary, clearings) = flight.judge(options, &[fence]);
    let clearance = clearings
        .first()
        .and_then(|c: &Clearing| c.clearance(&summary));
    match clearance {
        Some(m) if m.is_finite() => MarginCell::Margin(m),
        _ if !summary.landed => MarginCell::NotLanded,
        _ => MarginCell::Foul,
    }
}

/// Cells flown between two reports (about 20 ms of two cores' work).
const CELLS_PER_REPORT: usize = 256;

/// Computes the map: 8×8, then the full grid from its top row down in
/// blocks of rows, each sent as done; stops as soon as `cancelled()`.
pub fn run_margin_job(
    job: &MarginJob,
    cancelled: &(dyn Fn() -> bool + Sync),
    report: &mut dyn FnMut(MarginReport),
) {
    let options = Purpose::Surface.flight_options();
    let (columns, rows) = (job.resolution.0.max(2), job.resolution.1.max(2));
    let coarse = Grid {
        columns: 8.min(columns),
        rows: 8.min(rows),
        ..job.window
    };
    let fine = Grid {
        columns,
        rows,
        ..job.window
    };
    let levels: &[Grid] = if coarse == fine {
        &[fine]
    } else {
        &[coarse, fine]
    };
    for (level, grid) in levels.iter().enumerate() {
        // The coarse map at once; the fine one a block of rows at a time.
        let block = if level + 1 < levels.len() {
            grid.rows
        } else {
            (CELLS_PER_REPORT / grid.columns).max(1)
        };
        let mut top = grid.rows;
        while top > 0 {
            let first_row = top.saturating_sub(block);
            let cells: Option<Vec<MarginCell>> = (first_row * grid.columns..top * grid.columns)
                .into_par_iter()
                .map(|k| {
                    if cancelled() {
                        return None;
                    }
                    let (i, j) = (k % grid.columns, k / grid.columns);
                    let swing = (grid.undercut_at(i), grid.swing_angle_at(j));
                    Some(margin_at(&job.scene, &job.fence, swing, &options))
                })
                .collect();
            let Some(cells) = cells else {
                return;
            };
            report(MarginReport {
                generation: job.generation,
                grid: *grid,
                first_row,
                cells,
            });
            top = first_row;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_fill_in_place_and_a_block_that_does_not_fit_is_refused() {
        let grid = Grid {
            columns: 3,
            rows: 2,
            ..Grid::explorer_window()
        };
        let mut map = MarginSurface::not_computed(grid);
        assert!(!map.fill(1, &[MarginCell::Foul; 6]));
        assert!(!map.fill(0, &[MarginCell::Foul; 2]));
        assert!(map.fill(1, &[MarginCell::Margin(1.0); 3]));
        assert_eq!((map.done(), map.complete()), (3, false));
        assert_eq!(map.cell(2, 1), MarginCell::Margin(1.0));
        assert_eq!(map.cell(2, 0), MarginCell::NotComputed);
    }
}
