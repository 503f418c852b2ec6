//! What is computed *from* the model: the accuracy each consumer needs
//! (`precision`), the optimal swing (`optimum`), the studies behind the
//! paper's figures (`study`), and the benchmark (`bench`). Uses `model` and
//! `numerics`; knows nothing of the CLI or the explorer.

pub mod bench;
pub mod optimum;
pub mod precision;
pub mod study;
