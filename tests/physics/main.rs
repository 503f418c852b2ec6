//! The physics against the paper, published numbers, the independent
//! reference (reference/) and its own laws: one test binary.

mod accuracy;
mod aero;
#[path = "../common/mod.rs"]
mod common;
mod figures;
mod flight3d;
mod grip;
mod hard_cases;
mod impact3d;
mod lockstep;
mod optimizer;
mod paper_text;
mod properties;
mod savant;
mod surface_outcomes;
mod table2;
#[path = "../tui_support/mod.rs"]
mod tui_support;
