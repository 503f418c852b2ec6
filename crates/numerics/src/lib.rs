//! Domain-free numerics: the integrator, root finding on its dense output,
//! and the simplex search. Nothing here knows about baseballs; nothing here
//! imports the rest of the crate.

pub mod nelder_mead;
pub mod ode;
pub mod quadrature;
pub mod quantile;
pub mod real;
pub mod roots;
// For the tests of every crate above.
pub mod xorshift;
