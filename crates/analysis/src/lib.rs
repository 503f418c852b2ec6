//! What is computed *from* the model: the accuracy each consumer needs
//! (`precision`), the optimal swing (`optimum`), the studies behind the
//! paper's figures (`study`), what to say of a ball that does not land
//! (`landing`), each figure's data (`figures`), the paper's own
//! numbers (`paper`: Table II, what the text states), and the benchmark
//! (`bench`). Uses `model` and `numerics`; knows nothing of the CLI or the
//! explorer.

pub mod bat_tracking;
pub mod bench;
pub mod calibrate;
pub mod figures;
pub mod landing;
pub mod optimum;
pub mod paper;
pub mod precision;
pub mod savant;
pub mod sensitivity;
pub mod shown;
pub mod study;
