//! The figures tab: which of the paper's figures is shown, and asking the
//! worker for it when the inputs or the figure change, only while it shows.

use super::App;
use crate::analysis::figures::FigureData;
use crate::model::scene::Scene;
use crate::tui::layout::layout;
use crate::tui::worker::{FigureJob, FigureReport};

/// The figures the explorer draws, in order: Fig. 7 is the range surface (tab 2).
pub const FIGURES: [u32; 11] = [3, 4, 5, 6, 8, 9, 10, 11, 12, 13, 14];

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
    /// Steps through [`FIGURES`] (keys `f`, `F`).
    pub(super) fn step_figure(&mut self, forward: bool) {
        let n = FIGURES.len();
        let k = FIGURES
            .iter()
            .position(|&f| f == self.figure_number)
            .unwrap_or(0);
        self.figure_number = FIGURES[if forward { k + 1 } else { k + n - 1 } % n];
    }

    /// Whether the figure's pane is on screen.
    pub fn figure_visible(&self) -> bool {
        layout(self.size, self.tab).figure.is_some()
    }

    /// Whether the figure shown is the one for the current inputs.
    pub fn figure_fresh(&self) -> bool {
        !self.figure_visible()
            || self
                .figure
                .as_ref()
                .is_some_and(|f| f.generation == self.figure_generation)
    }

    /// Asks for the figure on screen when what it depends on has changed;
    /// cancels it when it leaves the screen.
    pub(super) fn request_figure(&mut self) {
        let wanted = self.figure_visible().then(|| FigureInputs {
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
