//! homerun: the physics of hitting a baseball as far as possible, after
//! Sawicki, Hubbard & Stronge, "How to hit home runs", Am. J. Phys. 71 (2003).
//!
//! The core is pure functions over small `Copy` structs, in SI units:
//! [`model::scene::Scene`] → [`model::impact::Impact`] → [`model::flight`] →
//! a summary; [`solve::optimize`] and [`study`] call that chain and nothing else.

pub mod bench;
pub mod cli;
pub mod figures;
pub mod model;
pub mod paper;
pub mod precision;
pub mod preset;
pub mod solve;
pub mod study;
pub mod tui;

pub use model::scene::Scene;
pub use model::{Swing, range, simulate};
pub use precision::Purpose;
