//! The swing that maximises range (§II.E): Nelder–Mead over the undercut E
//! and swing angle ψ, as the paper did with MATLAB's `fminsearch`.
//!
//! Written by hand because the explorer needs what no optimisation crate
//! offers together: one iteration at a time (`step`), a warm start from the
//! last optimum, the geometric bound |E| < r_b + r_B, and a stop on request.
//! It is cross-checked against `argmin`'s Nelder–Mead in the tests.
//!
//! The range surface has a long flat ridge along ψ (Fig. 7), on which a
//! simplex can collapse before it has found the top; after converging, the
//! search restarts from its best point with a fresh simplex, and ends only
//! when a restart no longer improves the range.

use serde::Serialize;

use crate::model::{self, scene::Scene};
use crate::precision::Purpose;

/// E and ψ are searched in scaled units, so that one unit is a comparable
/// change in range for both (Fig. 7: the ridge is ~10× longer along ψ).
const UNDERCUT_SCALE: f64 = 0.01; // m
const SWING_ANGLE_SCALE: f64 = 0.1; // rad
const MAX_SWING_ANGLE: f64 = std::f64::consts::FRAC_PI_2;

/// When to stop.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct OptimizerSettings {
    /// The simplex's size in scaled units (1e-4: 1 µm in E, 1e-5 rad in ψ,
    /// tighter than the paper's `fminsearch` TolX of 1e-4 in raw units).
    pub tolerance_x: f64,
    /// The spread of range over the simplex (m): the paper's TolFun, 1e-4.
    pub tolerance_range: f64,
    pub max_evaluations: u32,
    /// Restarts from the best point after the first convergence.
    pub max_restarts: u32,
    /// The size of a (re)started simplex, in scaled units.
    pub initial_size: f64,
}

impl Default for OptimizerSettings {
    fn default() -> Self {
        OptimizerSettings {
            tolerance_x: 1e-4,
            tolerance_range: 1e-4,
            max_evaluations: 2000,
            max_restarts: 4,
            initial_size: 0.25,
        }
    }
}

/// A swing and its range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Point {
    pub undercut: f64,
    pub swing_angle: f64,
    pub range: f64,
}

/// Where the search stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Running,
    Converged,
    /// Stopped by `max_evaluations` before converging.
    OutOfEvaluations,
}

#[derive(Clone, Copy, Debug)]
struct Vertex {
    u: [f64; 2],
    /// −range, or +∞ outside the bounds.
    cost: f64,
}

/// An incremental Nelder–Mead search for the maximum range.
#[derive(Clone, Debug)]
pub struct Optimizer {
    scene: Scene,
    purpose: Purpose,
    settings: OptimizerSettings,
    simplex: [Vertex; 3],
    evaluations: u32,
    restarts: u32,
    /// The best cost when the current simplex was started.
    cost_at_restart: f64,
    status: Status,
}

impl Optimizer {
    /// Starts a search at `start` = (E, ψ), e.g. the last optimum (warm
    /// start) or the scene's own swing. The scene must be valid.
    pub fn new(
        scene: &Scene,
        start: (f64, f64),
        purpose: Purpose,
        settings: OptimizerSettings,
    ) -> Optimizer {
        let mut optimizer = Optimizer {
            scene: *scene,
            purpose,
            settings,
            simplex: [Vertex {
                u: [0.0; 2],
                cost: f64::INFINITY,
            }; 3],
            evaluations: 0,
            restarts: 0,
            cost_at_restart: f64::INFINITY,
            status: Status::Running,
        };
        let limit = optimizer.undercut_limit();
        let start = (
            start.0.clamp(-0.99 * limit, 0.99 * limit),
            start.1.clamp(-MAX_SWING_ANGLE, MAX_SWING_ANGLE),
        );
        optimizer.start_simplex([start.0 / UNDERCUT_SCALE, start.1 / SWING_ANGLE_SCALE]);
        optimizer
    }

    fn undercut_limit(&self) -> f64 {
        self.scene.ball.radius + self.scene.bat.radius
    }

    fn cost(&mut self, u: [f64; 2]) -> f64 {
        let undercut = u[0] * UNDERCUT_SCALE;
        let swing_angle = u[1] * SWING_ANGLE_SCALE;
        if undercut.abs() >= self.undercut_limit() || swing_angle.abs() > MAX_SWING_ANGLE {
            return f64::INFINITY;
        }
        self.evaluations += 1;
        let mut scene = self.scene;
        scene.bat.undercut = undercut;
        scene.bat.swing_angle = swing_angle;
        let range = model::range(&scene, self.purpose);
        if range.is_finite() {
            -range
        } else {
            f64::INFINITY
        }
    }

    fn vertex(&mut self, u: [f64; 2]) -> Vertex {
        Vertex {
            u,
            cost: self.cost(u),
        }
    }

    fn start_simplex(&mut self, u: [f64; 2]) {
        let size = self.settings.initial_size;
        // Step toward the interior, so a start near a bound stays feasible.
        let du = if u[0] > 0.0 { -size } else { size };
        let dv = if u[1] > 0.0 { -size } else { size };
        self.simplex = [
            self.vertex(u),
            self.vertex([u[0] + du, u[1]]),
            self.vertex([u[0], u[1] + dv]),
        ];
        self.sort();
        self.cost_at_restart = self.simplex[0].cost;
    }

    fn sort(&mut self) {
        self.simplex.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    }

    fn converged(&self) -> bool {
        let best = self.simplex[0];
        self.simplex[1..].iter().all(|v| {
            (v.u[0] - best.u[0]).abs().max((v.u[1] - best.u[1]).abs()) <= self.settings.tolerance_x
                && (v.cost - best.cost).abs() <= self.settings.tolerance_range
        })
    }

    /// One Nelder–Mead iteration (reflect, expand, contract or shrink:
    /// one to four range evaluations), or a restart once converged.
    pub fn step(&mut self) -> Status {
        if self.status != Status::Running {
            return self.status;
        }
        if self.evaluations >= self.settings.max_evaluations {
            self.status = Status::OutOfEvaluations;
            return self.status;
        }
        if self.converged() {
            let improved =
                self.cost_at_restart - self.simplex[0].cost > self.settings.tolerance_range;
            if self.restarts >= self.settings.max_restarts || (self.restarts > 0 && !improved) {
                self.status = Status::Converged;
                return self.status;
            }
            self.restarts += 1;
            let best = self.simplex[0].u;
            self.start_simplex(best);
            return self.status;
        }

        let [best, next, worst] = self.simplex;
        let centroid = [0.5 * (best.u[0] + next.u[0]), 0.5 * (best.u[1] + next.u[1])];
        let along = |t: f64| {
            [
                centroid[0] + t * (worst.u[0] - centroid[0]),
                centroid[1] + t * (worst.u[1] - centroid[1]),
            ]
        };
        let reflected = self.vertex(along(-1.0));
        if reflected.cost < best.cost {
            let expanded = self.vertex(along(-2.0));
            self.simplex[2] = if expanded.cost < reflected.cost {
                expanded
            } else {
                reflected
            };
        } else if reflected.cost < next.cost {
            self.simplex[2] = reflected;
        } else {
            let outside = reflected.cost < worst.cost;
            let contracted = self.vertex(along(if outside { -0.5 } else { 0.5 }));
            let bound = if outside { reflected.cost } else { worst.cost };
            if contracted.cost <= bound {
                self.simplex[2] = contracted;
            } else {
                // Shrink toward the best vertex.
                for i in 1..3 {
                    let u = self.simplex[i].u;
                    let shrunk = [
                        best.u[0] + 0.5 * (u[0] - best.u[0]),
                        best.u[1] + 0.5 * (u[1] - best.u[1]),
                    ];
                    self.simplex[i] = self.vertex(shrunk);
                }
            }
        }
        self.sort();
        self.status
    }

    /// Steps until converged, or until `stop()` says so (then `None`).
    pub fn run(&mut self, mut stop: impl FnMut() -> bool) -> Option<Point> {
        while self.step() == Status::Running {
            if stop() {
                return None;
            }
        }
        Some(self.best())
    }

    /// The best swing found so far.
    pub fn best(&self) -> Point {
        let v = self.simplex[0];
        Point {
            undercut: v.u[0] * UNDERCUT_SCALE,
            swing_angle: v.u[1] * SWING_ANGLE_SCALE,
            range: -v.cost,
        }
    }

    pub fn evaluations(&self) -> u32 {
        self.evaluations
    }

    pub fn status(&self) -> Status {
        self.status
    }
}

/// The optimum of a finished search.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Optimum {
    pub undercut: f64,
    pub swing_angle: f64,
    pub range: f64,
    pub evaluations: u32,
    pub converged: bool,
}

/// Runs a search to the end from the scene's own (E, ψ).
pub fn optimize(scene: &Scene, settings: OptimizerSettings) -> Optimum {
    optimize_from(scene, (scene.bat.undercut, scene.bat.swing_angle), settings)
}

/// Runs a search to the end from `start`.
pub fn optimize_from(scene: &Scene, start: (f64, f64), settings: OptimizerSettings) -> Optimum {
    let mut optimizer = Optimizer::new(scene, start, Purpose::Optimizer, settings);
    let best = optimizer.run(|| false).unwrap_or_else(|| optimizer.best());
    Optimum {
        undercut: best.undercut,
        swing_angle: best.swing_angle,
        range: best.range,
        evaluations: optimizer.evaluations(),
        converged: optimizer.status() == Status::Converged,
    }
}
