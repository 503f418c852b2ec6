//! homerun: the physics of hitting a baseball as far as possible, after
//! Sawicki, Hubbard & Stronge, "How to hit home runs", Am. J. Phys. 71 (2003).
//!
//! Every arrow points down, and a module's folder says what it may import:
//! - [`numerics`]: the integrator, root finding and the simplex search;
//!   imports nothing of the crate.
//! - [`model`]: the paper, each equation once: [`model::scene::Scene`] →
//!   [`model::impact::Impact`] → [`model::flight`] → a summary.
//! - [`analysis`]: precision budgets, the optimal swing, the studies behind
//!   the figures, the benchmark; calls the model and the numerics.
//! - [`preset`]: scenes in TOML files.
//! - [`picture`]: figures, surfaces, trajectories and the bench as SVG text.
//! - [`units`]: SI or baseball units for text shown and typed; imports nothing.
//! - [`cli`] and [`tui`]: the frontends; nothing below imports them.

pub mod cli;

pub use analysis;
pub use batch;
pub use model;
pub use numerics;
pub use picture;
pub use preset;
pub use preset::atomic_file;
pub use tui;
pub use units;

pub use analysis::precision::Purpose;
pub use model::scene::Scene;
pub use model::{Swing, range, simulate};
