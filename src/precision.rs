//! Accuracy budgets: each consumer states what it can show and gets the
//! cheapest computation that meets it. Every tolerance in the program is
//! chosen here, and only here. The numbers behind each choice are in the
//! README's work–precision table (`homerun bench`).

use crate::model::flight::FlightOptions;
use crate::solve::ode::Tolerance;

/// Who is asking for a flight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    /// Numbers printed to the user (CLI, readout): range good to ~1 µm.
    Readout,
    /// The optimiser's objective: smooth in (E, ψ) and far below its own
    /// stopping tolerance (1e-4 m in range).
    Optimizer,
    /// One heatmap cell: a quarter of a colour step is several centimetres.
    Surface,
    /// A drawn trajectory: a braille dot is ~0.5 m at the smallest zoom.
    Plot,
    /// The reference for the benchmarks and tests: as tight as f64 allows.
    Reference,
}

impl Purpose {
    pub fn tolerance(self) -> Tolerance {
        match self {
            Purpose::Readout => Tolerance::uniform(1e-10),
            Purpose::Optimizer => Tolerance::uniform(1e-8),
            Purpose::Surface => Tolerance::uniform(1e-5),
            Purpose::Plot => Tolerance::uniform(1e-6),
            Purpose::Reference => Tolerance::uniform(1e-13),
        }
    }

    pub fn flight_options(self) -> FlightOptions {
        FlightOptions {
            tolerance: self.tolerance(),
            stop_at_kinks: true,
        }
    }
}
