//! Key `c`: the heatmap shows the margin over the wall of the park chosen
//! (`m`/`M`; without one, the preset's fence) instead of the range. Its own
//! generations and thread ([`crate::margin`]): a new park or new
//! inputs cancel the map being computed, never the optimiser.

use super::*;
use crate::margin::{MarginJob, MarginReport, MarginSurface};

/// The margin map's state.
#[derive(Clone, Debug, Default)]
pub struct MarginMap {
    /// Key `c`: the heatmap shows the margin rather than the range.
    pub on: bool,
    /// Bumped whenever what it shows changes (inputs, park, size); reports
    /// for older ones are dropped.
    pub generation: u64,
    pub state: Option<MarginState>,
    job: Option<MarginJob>,
}

/// The map as computed so far.
#[derive(Clone, Debug, PartialEq)]
pub struct MarginState {
    /// What is drawn under any rows still coming: the coarse map, or the
    /// last complete fine one (older than the inputs while new rows come).
    pub surface: MarginSurface,
    /// Its generation.
    pub generation: u64,
    /// The fine map being filled row by row, and its generation (drawn
    /// over `surface` where its rows are done).
    filling: Option<(MarginSurface, u64)>,
}

impl App {
    /// Whether the heatmap shows the margin: asked for (`c`), in a swing,
    /// with a fence to be judged at.
    pub fn shows_margin(&self) -> bool {
        self.margin.on && self.is_swing() && self.field_fence().is_some()
    }

    /// Whether the map shown is complete, at the pane's resolution, for
    /// the current inputs and park.
    pub fn margin_fresh(&self) -> bool {
        let (columns, rows) = heatmap_resolution(self.size);
        self.margin.state.as_ref().is_some_and(|s| {
            s.generation == self.margin.generation
                && s.filling.is_none()
                && (s.surface.grid.columns, s.surface.grid.rows) == (columns.max(2), rows.max(2))
        })
    }

    /// Whether the heatmap in force (range or margin) is complete for the
    /// current inputs.
    pub fn heatmap_fresh(&self) -> bool {
        if self.shows_margin() {
            self.margin_fresh()
        } else {
            self.surface_fresh()
        }
    }

    /// The margin job to start, if any (taken once).
    pub fn take_margin_job(&mut self) -> Option<MarginJob> {
        self.margin.job.take()
    }

    /// Key `c`: the heatmap between the range and the margin at the park.
    pub(super) fn toggle_margin(&mut self) {
        if !self.is_swing() {
            self.message = Some((SWING_ONLY.into(), true));
            return;
        }
        if self.field_fence().is_none() {
            self.message = Some((
                "c: no fence to measure a margin at (m picks a park)".into(),
                true,
            ));
            return;
        }
        self.margin.on = !self.margin.on;
        self.refresh_margin(true);
        let text = if self.margin.on {
            format!(
                "surface: the height over the wall at {} (c: the range)",
                self.margin_place()
            )
        } else {
            // The range surface was left alone while the margin showed.
            if !self.surface_fresh() {
                self.job = Some(self.job_for(Work::Surface));
            }
            "surface: the range (c: the margin over the wall)".to_owned()
        };
        self.message = Some((text, false));
    }

    /// Where the margin is taken: the park's code, or "the fence".
    pub fn margin_place(&self) -> String {
        self.chosen_park()
            .map_or_else(|| "the fence".to_owned(), |p| p.code.clone())
    }

    /// Starts the margin map over for the current inputs, park and size;
    /// `anew` drops the map shown (another park: its picture would
    /// mislead), else it stays, marked stale, as new rows stream over it.
    pub(super) fn refresh_margin(&mut self, anew: bool) {
        self.margin.generation += 1;
        self.margin.job = None;
        if anew || !self.shows_margin() {
            self.margin.state = None;
        }
        let Some(fence) = self.field_fence().filter(|_| self.shows_margin()) else {
            return;
        };
        self.margin.job = Some(MarginJob {
            generation: self.margin.generation,
            scene: self.scene,
            fence,
            window: Grid::explorer_window(),
            resolution: heatmap_resolution(self.size),
        });
        self.dirty = true;
    }

    /// Takes in rows of the margin map, unless they are for older inputs.
    /// A coarse map is drawn only over none or another coarse one: a finer
    /// map for the old inputs stays under the new rows instead.
    pub fn apply_margin(&mut self, report: MarginReport) {
        if report.generation != self.margin.generation {
            return;
        }
        self.dirty = true;
        let fine = heatmap_resolution(self.size);
        let is_fine = |grid: &Grid| (grid.columns, grid.rows) == (fine.0.max(2), fine.1.max(2));
        let state = self.margin.state.get_or_insert_with(|| MarginState {
            surface: MarginSurface::not_computed(report.grid),
            generation: report.generation,
            filling: None,
        });
        if is_fine(&report.grid) || !is_fine(&state.surface.grid) {
            state.put(&report);
        }
    }
}

impl MarginState {
    /// Puts `report`'s rows into the map being filled (a new one for a new
    /// generation or grid), which replaces the map drawn once complete.
    fn put(&mut self, report: &MarginReport) {
        let mut filling = match self.filling.take() {
            Some((f, g)) if f.grid == report.grid && g == report.generation => f,
            _ => MarginSurface::not_computed(report.grid),
        };
        filling.fill(report.first_row, &report.cells);
        if filling.complete() {
            self.surface = filling;
            self.generation = report.generation;
        } else {
            self.filling = Some((filling, report.generation));
        }
    }

    /// The rows coming in for newer inputs, drawn over `surface` where
    /// they are done.
    pub fn filling(&self) -> Option<&MarginSurface> {
        self.filling.as_ref().map(|(f, _)| f)
    }
}
