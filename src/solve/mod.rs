//! Numerical machinery: the integrator and the optimiser.

pub mod ode;
pub mod optimize;
