//! The figures tab: which of the paper's figures is shown, and asking the
//! worker for it when the inputs or the figure change, only while it shows.

use super::App;
use crate::layout::layout;
use crate::worker::{FigureJob, FigureReport};
use analysis::figures::FigureData;
use model::scene::Scene;

/// The figures the explorer draws, in order: Fig. 7 is the range surface (tab 2).
pub const FIGURES: [u32; 11] = [3, 4, 5, 6, 8, 9, 10, 11, 12, 13, 14];
/// The figures of the aerodynamics alone (C_D, C_L), the only ones that
/// apply to a batted ball; the others need a pitch and a bat.
pub const AERO_FIGURES: [u32; 2] = [3, 4];

/// A figure as computed for some inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureState {
    pub number: u32,
    pub data: Result<FigureData, String>,
    /// The figure generation it was computed for; older than the app's
    /// while the figure for new inputs is being computed.
    pub generation: u64,
    pub elapsed: std::time::Duration,
}

/// What the figure shown depends on.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct FigureInputs {
    scene: Scene,
    number: u32,
    preset_name: String,
}

impl App {
    /// Steps through [`FIGURES`] (keys `f`, `F`): a batted ball's only
    /// through those that apply to it.
    pub(super) fn step_figure(&mut self, forward: bool) {
        let all: &[u32] = if self.is_swing() {
            &FIGURES
        } else {
            &AERO_FIGURES
        };
        let n = all.len();
        self.figure_number = match all.iter().position(|&f| f == self.figure_number) {
            Some(k) => all[if forward { k + 1 } else { k + n - 1 } % n],
            None => all[if forward { 0 } else { n - 1 }],
        };
    }

    /// A batted ball shows the first figure that applies to it (the drag's)
    /// rather than one that needs a swing.
    pub(super) fn fit_figure(&mut self) {
        if !self.figure_applies() {
            self.figure_number = AERO_FIGURES[0];
        }
    }

    /// Whether the chosen figure can be drawn for this scene: a batted
    /// ball has no pitch or bat for Figs. 5–6 and 8–14.
    pub fn figure_applies(&self) -> bool {
        self.is_swing() || AERO_FIGURES.contains(&self.figure_number)
    }

    /// Whether the figure's pane is on screen.
    pub fn figure_visible(&self) -> bool {
        layout(self.size, self.tab, self.is_swing())
            .figure
            .is_some()
    }

    /// Whether the figure shown is the one for the current inputs.
    pub fn figure_fresh(&self) -> bool {
        !self.figure_visible()
            || !self.figure_applies()
            || self
                .figure
                .as_ref()
                .is_some_and(|f| f.generation == self.figure_generation)
    }

    /// Asks for the figure on screen when what it depends on has changed;
    /// cancels it when it leaves the screen.
    pub(super) fn request_figure(&mut self) {
        let wanted = (self.figure_visible() && self.figure_applies()).then(|| FigureInputs {
            scene: self.scene,
            number: self.figure_number,
            preset_name: self.preset_name.clone(),
        });
        if wanted == self.figure_for {
            return;
        }
        self.figure_generation += 1;
        self.figure_job = wanted.as_ref().map(|w| FigureJob {
            generation: self.figure_generation,
            number: w.number,
            scene: w.scene,
            preset_name: w.preset_name.clone(),
        });
        self.figure_for = wanted;
        self.dirty = true;
    }

    /// The figure the background should compute now, if any (taken once).
    pub fn take_figure_job(&mut self) -> Option<FigureJob> {
        self.figure_job.take()
    }

    /// Takes in a figure, unless it is for older inputs.
    pub fn apply_figure(&mut self, report: FigureReport) {
        if report.generation != self.figure_generation {
            return;
        }
        self.dirty = true;
        self.figure = Some(FigureState {
            number: report.number,
            data: report.figure,
            generation: report.generation,
            elapsed: report.elapsed,
        });
    }
}
