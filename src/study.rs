//! Studies over many swings: the range surface over (E, ψ) (Fig. 7), computed
//! in parallel with rayon. Each study calls the model and nothing else.

use rayon::prelude::*;
use serde::Serialize;

use crate::model::{self, scene::Scene};
use crate::precision::Purpose;

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

/// Range at every grid point, row-major (row j = ψ, column i = E); `None`
/// where the bat misses the ball (|E| ≥ r_b + r_B).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Surface {
    pub grid: Grid,
    pub ranges: Vec<Option<f64>>,
}

impl Surface {
    pub fn get(&self, column: usize, row: usize) -> Option<f64> {
        self.ranges[row * self.grid.columns + column]
    }

    /// The highest cell: (column, row, range).
    pub fn best(&self) -> Option<(usize, usize, f64)> {
        self.ranges
            .iter()
            .enumerate()
            .filter_map(|(k, r)| r.map(|r| (k, r)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(k, r)| (k % self.grid.columns, k / self.grid.columns, r))
    }
}

/// The range of `scene` with its swing replaced by (E, ψ), if the bat reaches.
pub fn range_at(scene: &Scene, undercut: f64, swing_angle: f64, purpose: Purpose) -> Option<f64> {
    let mut s = *scene;
    s.bat.undercut = undercut;
    s.bat.swing_angle = swing_angle;
    (undercut.abs() < s.ball.radius + s.bat.radius).then(|| model::range(&s, purpose))
}

/// The range surface, in parallel over rows.
pub fn surface(scene: &Scene, grid: Grid, purpose: Purpose) -> Surface {
    surface_until(scene, grid, purpose, &|| false).expect("never cancelled")
}

/// As [`surface`], giving up (`None`) as soon as `cancelled()` turns true:
/// it is polled before every cell.
pub fn surface_until(
    scene: &Scene,
    grid: Grid,
    purpose: Purpose,
    cancelled: &(dyn Fn() -> bool + Sync),
) -> Option<Surface> {
    let ranges: Option<Vec<Option<f64>>> = (0..grid.rows * grid.columns)
        .into_par_iter()
        .map(|k| {
            if cancelled() {
                return None;
            }
            let (i, j) = (k % grid.columns, k / grid.columns);
            Some(range_at(
                scene,
                grid.undercut_at(i),
                grid.swing_angle_at(j),
                purpose,
            ))
        })
        .collect();
    ranges.map(|ranges| Surface { grid, ranges })
}
