//! Nelder–Mead over a fixed-size vector, one iteration at a time, with
//! restarts.
//!
//! Written by hand because the explorer needs what no optimisation crate
//! offers together: one iteration at a time (`step`), so that a search can be
//! stopped between any two evaluations and its best point shown while it
//! runs; a warm start from any point; and restarts. It is cross-checked
//! against `argmin`'s Nelder–Mead in the tests.
//!
//! A long flat ridge (the range surface's, Fig. 7 of the paper) lets a simplex
//! collapse before it has found the top; after converging, the search
//! restarts from its best point with a fresh simplex, and ends only when a
//! restart no longer improves the cost.
//!
//! The cost is minimised; a point outside the feasible region should cost
//! +∞. The cost is passed to every call rather than owned, so that the caller
//! keeps its own bookkeeping (counting, cancelling) around it.

use nalgebra::SVector;

pub type Point<const N: usize> = SVector<f64, N>;

/// When to stop, in the caller's (scaled) units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// The largest distance (∞-norm) of a vertex from the best one.
    pub tolerance_x: f64,
    /// The largest spread of cost over the simplex.
    pub tolerance_cost: f64,
    /// Restarts from the best point after the first convergence.
    pub max_restarts: u32,
    /// The size of a (re)started simplex.
    pub initial_size: f64,
}

/// Where the search stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Running,
    Converged,
}

/// A point and its cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex<const N: usize> {
    pub point: Point<N>,
    pub cost: f64,
}

/// The simplex (N + 1 vertices, best first) and the restart bookkeeping.
/// `M` must be `N + 1` (checked when the search starts).
#[derive(Clone, Debug)]
pub struct NelderMead<const N: usize, const M: usize> {
    settings: Settings,
    simplex: [Vertex<N>; M],
    restarts: u32,
    /// The best cost when the current simplex was started.
    cost_at_restart: f64,
    status: Status,
}

impl<const N: usize, const M: usize> NelderMead<N, M> {
    /// Starts a search at `start`, evaluating the first simplex.
    pub fn new(
        start: Point<N>,
        settings: Settings,
        cost: &mut impl FnMut(&Point<N>) -> f64,
    ) -> NelderMead<N, M> {
        assert_eq!(M, N + 1, "a simplex in N dimensions has N + 1 vertices");
        let mut search = NelderMead {
            settings,
            simplex: [Vertex {
                point: Point::<N>::zeros(),
                cost: f64::INFINITY,
            }; M],
            restarts: 0,
            cost_at_restart: f64::INFINITY,
            status: Status::Running,
        };
        search.start_simplex(start, cost);
        search
    }

    /// A fresh simplex at `start`: each further vertex steps `initial_size`
    /// along one axis, toward zero, so that a start near a bound of a region
    /// centred on zero stays feasible.
    fn start_simplex(&mut self, start: Point<N>, cost: &mut impl FnMut(&Point<N>) -> f64) {
        let size = self.settings.initial_size;
        self.simplex[0] = vertex(start, cost);
        for axis in 0..N {
            let mut point = start;
            point[axis] += if start[axis] > 0.0 { -size } else { size };
            self.simplex[axis + 1] = vertex(point, cost);
        }
        self.sort();
        self.cost_at_restart = self.simplex[0].cost;
    }

    fn sort(&mut self) {
        self.simplex.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    }

    fn converged(&self) -> bool {
        let best = self.simplex[0];
        self.simplex[1..].iter().all(|v| {
            (v.point - best.point).amax() <= self.settings.tolerance_x
                && (v.cost - best.cost).abs() <= self.settings.tolerance_cost
        })
    }

    /// One Nelder–Mead iteration (reflect, expand, contract or shrink: one
    /// to N + 2 evaluations), or a restart once converged.
    pub fn step(&mut self, cost: &mut impl FnMut(&Point<N>) -> f64) -> Status {
        if self.status != Status::Running {
            return self.status;
        }
        if self.converged() {
            let improved =
                self.cost_at_restart - self.simplex[0].cost > self.settings.tolerance_cost;
            if self.restarts >= self.settings.max_restarts || (self.restarts > 0 && !improved) {
                self.status = Status::Converged;
                return self.status;
            }
            self.restarts += 1;
            let best = self.simplex[0].point;
            self.start_simplex(best, cost);
            return self.status;
        }

        let best = self.simplex[0];
        let next = self.simplex[M - 2];
        let worst = self.simplex[M - 1];
        let centroid = self.simplex[..M - 1]
            .iter()
            .skip(1)
            .fold(best.point, |sum, v| sum + v.point)
            / N as f64;
        let along = |t: f64| centroid + (worst.point - centroid) * t;
        let reflected = vertex(along(-1.0), cost);
        if reflected.cost < best.cost {
            let expanded = vertex(along(-2.0), cost);
            self.simplex[M - 1] = if expanded.cost < reflected.cost {
                expanded
            } else {
                reflected
            };
        } else if reflected.cost < next.cost {
            self.simplex[M - 1] = reflected;
        } else {
            let outside = reflected.cost < worst.cost;
            let contracted = vertex(along(if outside { -0.5 } else { 0.5 }), cost);
            let bound = if outside { reflected.cost } else { worst.cost };
            if contracted.cost <= bound {
                self.simplex[M - 1] = contracted;
            } else {
                // Shrink toward the best vertex.
                for i in 1..M {
                    let point = self.simplex[i].point;
                    self.simplex[i] = vertex(best.point + (point - best.point) * 0.5, cost);
                }
            }
        }
        self.sort();
        self.status
    }

    /// The best vertex found so far.
    pub fn best(&self) -> Vertex<N> {
        self.simplex[0]
    }

    pub fn status(&self) -> Status {
        self.status
    }
}

fn vertex<const N: usize>(point: Point<N>, cost: &mut impl FnMut(&Point<N>) -> f64) -> Vertex<N> {
    Vertex {
        point,
        cost: cost(&point),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings() -> Settings {
        Settings {
            tolerance_x: 1e-8,
            tolerance_cost: 1e-12,
            max_restarts: 4,
            initial_size: 0.5,
        }
    }

    fn minimise<const N: usize, const M: usize>(
        start: Point<N>,
        mut cost: impl FnMut(&Point<N>) -> f64,
    ) -> Vertex<N> {
        let mut search = NelderMead::<N, M>::new(start, settings(), &mut cost);
        for _ in 0..100_000 {
            if search.step(&mut cost) == Status::Converged {
                return search.best();
            }
        }
        panic!("no convergence");
    }

    #[test]
    fn finds_the_minimum_of_rosenbrock() {
        let rosenbrock = |p: &Point<2>| (1.0 - p[0]).powi(2) + 100.0 * (p[1] - p[0] * p[0]).powi(2);
        let best = minimise::<2, 3>(Point::<2>::new(-1.2, 1.0), rosenbrock);
        assert!(
            (best.point - Point::<2>::new(1.0, 1.0)).amax() < 1e-5,
            "{best:?}"
        );
    }

    #[test]
    fn works_in_three_dimensions_and_respects_infeasible_points() {
        // A bowl centred at (0.3, −0.2, 0.1), infeasible beyond |x| ≥ 1.
        let bowl = |p: &Point<3>| {
            if p.amax() >= 1.0 {
                f64::INFINITY
            } else {
                (p - Point::<3>::new(0.3, -0.2, 0.1)).norm_squared()
            }
        };
        let best = minimise::<3, 4>(Point::<3>::new(0.9, 0.9, -0.9), bowl);
        assert!(
            (best.point - Point::<3>::new(0.3, -0.2, 0.1)).amax() < 1e-6,
            "{best:?}"
        );
    }
}
