//! The swing that maximises range (§II.E): Nelder–Mead over the undercut E
//! and swing angle ψ, as the paper did with MATLAB's `fminsearch`, through
//! [`numerics::nelder_mead`], with the range as the (negated) cost and
//! the geometric bound |E| < r_b + r_B as an infeasible region. [`park`]
//! searches E, ψ and the bat's direction for the margin over a park's wall.

pub mod park;

use serde::Serialize;

use super::precision::Purpose;
use super::study::Grid;
use model::flight::{FlightOptions, FlightSummary};
use model::impact::Collision;
use model::{self, scene::Scene};
use numerics::nelder_mead::{self, NelderMead};

/// E and ψ are searched in scaled units, so that one unit is a comparable
/// change in range for both (Fig. 7: the ridge is ~10× longer along ψ).
const UNDERCUT_SCALE: f64 = 0.01; // m
const SWING_ANGLE_SCALE: f64 = 0.1; // rad
const MAX_SWING_ANGLE: f64 = std::f64::consts::FRAC_PI_2;

/// The coarse scan that seeds a search whose start does not land: this many
/// columns (E) and rows (ψ) over [`Grid::explorer_window`], 64 flights, the
/// explorer's first glance at the surface.
pub const SCAN_SIDE: usize = 8;

/// The default [`OptimizerSettings::max_flight_steps`]: about 1.5 s of
/// integration at the optimiser's tolerance, 200× what the Table II optima
/// take (3 500 to 6 000 steps).
pub const DEFAULT_MAX_FLIGHT_STEPS: u64 = 5_000_000;

/// When to stop.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct OptimizerSettings {
    /// The simplex's size in scaled units (1e-4: 1 µm in E, 1e-5 rad in ψ,
    /// tighter than the paper's `fminsearch` TolX of 1e-4 in raw units).
    pub tolerance_x: f64,
    /// The spread of range over the simplex (m): the paper's TolFun, 1e-4.
    pub tolerance_range: f64,
    pub max_evaluations: u32,
    /// The most integration steps all its flights may take together: a bound
    /// on the work, whatever the scene. An ordinary optimum takes a few
    /// thousand; a scene whose balls hover (a light ball with a large spin,
    /// low gravity) takes up to 100 000 a flight, and would otherwise run its
    /// `max_evaluations` for a minute.
    pub max_flight_steps: u64,
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
            max_flight_steps: DEFAULT_MAX_FLIGHT_STEPS,
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
    /// Whether its flight lands only just inside its time limit
    /// ([`lands_at_time_limit`]): then the limit, not the swing, sets the
    /// range.
    pub at_time_limit: bool,
}

/// The share of a flight's time limit after which a landing counts as set
/// by the limit: a ball that comes down in its last 1 % was hovering.
const TIME_LIMIT_SHARE: f64 = 0.99;

/// Whether `flight`, flown from `scene` (its swing included), lands just
/// before its time limit ([`model::flight::Launch::time_limit`]).
/// On a scene whose balls hover, the longest landing flight is one that
/// comes down just before the limit: the limit, not the swing, then sets
/// the range, and a longer limit would give a longer one.
pub fn lands_at_time_limit(scene: &Scene, flight: &FlightSummary) -> bool {
    if !flight.landed {
        return false;
    }
    let env = scene.environment;
    let speed = Collision::new(scene).launch_speed();
    let limit = model::flight::time_limit(speed, env.contact_height, env.gravity);
    flight.flight_time >= TIME_LIMIT_SHARE * limit
}

/// Where the search stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Status {
    #[serde(rename = "running")]
    Running,
    #[serde(rename = "converged")]
    Converged,
    /// Stopped by `max_evaluations` before converging.
    #[serde(rename = "evaluation_limit")]
    OutOfEvaluations,
    /// Stopped by `max_flight_steps` before converging.
    #[serde(rename = "work_limit")]
    OutOfWork,
    /// Neither the start nor any swing of the coarse scan lands: there is
    /// nothing to maximise.
    #[serde(rename = "nothing_lands")]
    NothingLands,
}

/// The coarse scan of [`Grid::explorer_window`] that seeds a search whose
/// start does not land.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Scan {
    pub grid: Grid,
    /// Swings of the grid flown so far (those the bat reaches).
    pub flown: u32,
    /// Whether the whole grid was flown (not cut short by the work limit).
    pub complete: bool,
}

/// What the search is doing: scanning for a landing swing, cell by cell, or
/// climbing by Nelder–Mead.
#[derive(Clone, Copy, Debug)]
enum Phase {
    Search,
    Scan {
        /// The next cell, row-major.
        next: usize,
        /// The best cell so far (scaled point, cost).
        best: Option<(nelder_mead::Point<2>, f64)>,
    },
}

/// An incremental search for the maximum range.
#[derive(Clone, Debug)]
pub struct Optimizer {
    objective: Objective,
    settings: OptimizerSettings,
    search: NelderMead<2, 3>,
    phase: Phase,
    scan: Option<Scan>,
    status: Status,
}

/// The range as a cost over scaled (E, ψ), counting the flights it flies.
#[derive(Clone, Copy, Debug)]
struct Objective {
    scene: Scene,
    options: FlightOptions,
    evaluations: u32,
    /// Integration steps taken by all its flights, accepted and rejected.
    flight_steps: u64,
    max_flight_steps: u64,
    /// The lowest-cost swing flown so far, and whether it landed at its
    /// time limit: the simplex's best vertex is always the lowest cost
    /// flown, so this is what [`Optimizer::best`] reports.
    lowest: Option<(nelder_mead::Point<2>, f64, bool)>,
}

/// A point of the search in its scaled units.
fn scaled(undercut: f64, swing_angle: f64) -> nelder_mead::Point<2> {
    nelder_mead::Point::<2>::new(undercut / UNDERCUT_SCALE, swing_angle / SWING_ANGLE_SCALE)
}

impl Objective {
    fn cost(&mut self, u: &nelder_mead::Point<2>) -> f64 {
        let undercut = u[0] * UNDERCUT_SCALE;
        let swing_angle = u[1] * SWING_ANGLE_SCALE;
        if undercut.abs() >= self.scene.reach() || swing_angle.abs() > MAX_SWING_ANGLE {
            return f64::INFINITY;
        }
        // Past the work limit nothing more is flown (the first swing always
        // is): the search stops at its next step.
        if self.evaluations > 0 && self.flight_steps >= self.max_flight_steps {
            return f64::INFINITY;
        }
        self.evaluations += 1;
        let scene = self.scene.with_swing(undercut, swing_angle);
        let flight = model::simulate(&scene, self.options).flight;
        self.flight_steps += u64::from(flight.stats.accepted) + u64::from(flight.stats.rejected);
        // A ball that never lands has no range: that swing is infeasible.
        let cost = if flight.landed && flight.range.is_finite() {
            -flight.range
        } else {
            f64::INFINITY
        };
        if cost < self.lowest.map_or(f64::INFINITY, |l| l.1) {
            self.lowest = Some((*u, cost, lands_at_time_limit(&scene, &flight)));
        }
        cost
    }
}

impl Optimizer {
    /// Starts a search at `start` = (E, ψ), e.g. the last optimum (warm
    /// start) or the scene's own swing, flying each swing as precisely as
    /// `options` says (normally `Purpose::Optimizer`). The scene must be valid.
    /// If no swing of the first simplex lands, the search first scans
    /// [`Grid::explorer_window`] coarsely ([`SCAN_SIDE`]²) and restarts at the
    /// best landing swing there; a start that lands costs nothing more.
    pub fn new(
        scene: &Scene,
        start: (f64, f64),
        options: impl Into<FlightOptions>,
        settings: OptimizerSettings,
    ) -> Optimizer {
        let mut objective = Objective {
            scene: *scene,
            options: options.into(),
            evaluations: 0,
            flight_steps: 0,
            max_flight_steps: settings.max_flight_steps,
            lowest: None,
        };
        let limit = scene.reach();
        let start = scaled(
            start.0.clamp(-0.99 * limit, 0.99 * limit),
            start.1.clamp(-MAX_SWING_ANGLE, MAX_SWING_ANGLE),
        );
        let search = NelderMead::new(start, Self::simplex(settings), &mut |u| objective.cost(u));
        let lands = search.best().cost.is_finite();
        Optimizer {
            objective,
            settings,
            search,
            phase: if lands {
                Phase::Search
            } else {
                Phase::Scan {
                    next: 0,
                    best: None,
                }
            },
            scan: (!lands).then_some(Scan {
                grid: Self::scan_grid(),
                flown: 0,
                complete: false,
            }),
            status: Status::Running,
        }
    }

    fn simplex(settings: OptimizerSettings) -> nelder_mead::Settings {
        nelder_mead::Settings {
            tolerance_x: settings.tolerance_x,
            tolerance_cost: settings.tolerance_range,
            max_restarts: settings.max_restarts,
            initial_size: settings.initial_size,
        }
    }

    fn scan_grid() -> Grid {
        Grid {
            columns: SCAN_SIDE,
            rows: SCAN_SIDE,
            ..Grid::explorer_window()
        }
    }

    /// One Nelder–Mead iteration (reflect, expand, contract or shrink:
    /// one to four range evaluations), or a restart once converged; while
    /// scanning, one swing of the scan.
    pub fn step(&mut self) -> Status {
        if self.status != Status::Running {
            return self.status;
        }
        if self.objective.evaluations >= self.settings.max_evaluations {
            self.status = Status::OutOfEvaluations;
            return self.status;
        }
        if self.objective.flight_steps >= self.objective.max_flight_steps {
            self.status = Status::OutOfWork;
            return self.status;
        }
        if let Phase::Scan { next, best } = self.phase {
            self.scan_step(next, best);
            return self.status;
        }
        let objective = &mut self.objective;
        if self.search.step(&mut |u| objective.cost(u)) == nelder_mead::Status::Converged {
            self.status = Status::Converged;
        }
        self.status
    }

    /// Flies cell `next` of the scan; after the last, starts the simplex at
    /// the best landing cell, or gives up if none lands.
    fn scan_step(&mut self, next: usize, mut best: Option<(nelder_mead::Point<2>, f64)>) {
        let grid = Self::scan_grid();
        let (i, j) = (next % grid.columns, next / grid.columns);
        let point = scaled(grid.undercut_at(i), grid.swing_angle_at(j));
        let before = self.objective.evaluations;
        let cost = self.objective.cost(&point);
        let scan = self.scan.as_mut().expect("a scan while scanning");
        scan.flown += self.objective.evaluations - before;
        if cost < best.map_or(f64::INFINITY, |b| b.1) {
            best = Some((point, cost));
        }
        if next + 1 < grid.columns * grid.rows {
            self.phase = Phase::Scan {
                next: next + 1,
                best,
            };
            return;
        }
        scan.complete = true;
        self.phase = Phase::Search;
        match best {
            Some((point, _)) => {
                let objective = &mut self.objective;
                self.search = NelderMead::new(point, Self::simplex(self.settings), &mut |u| {
                    objective.cost(u)
                });
            }
            None => self.status = Status::NothingLands,
        }
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
        let v = self.search.best();
        Point {
            undercut: v.point[0] * UNDERCUT_SCALE,
            swing_angle: v.point[1] * SWING_ANGLE_SCALE,
            range: -v.cost,
            at_time_limit: self
                .objective
                .lowest
                .is_some_and(|(u, cost, at_limit)| u == v.point && cost == v.cost && at_limit),
        }
    }

    pub fn evaluations(&self) -> u32 {
        self.objective.evaluations
    }

    /// Integration steps taken so far by all the flights.
    pub fn flight_steps(&self) -> u64 {
        self.objective.flight_steps
    }

    pub fn status(&self) -> Status {
        self.status
    }

    /// The coarse scan, if the start did not land.
    pub fn scan(&self) -> Option<Scan> {
        self.scan
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
    /// Whether any swing tried lands. If none does, there is no optimum:
    /// `range` is −∞ and (E, ψ) is where the search started.
    pub landed: bool,
    /// Integration steps taken by all the flights.
    pub flight_steps: u64,
    /// Why it stopped: converged, which limit, or nothing lands.
    pub status: Status,
    /// The coarse scan, if the start did not land.
    pub scan: Option<Scan>,
    /// Whether its flight lands only just inside its time limit: the limit,
    /// not the swing, sets the range ([`lands_at_time_limit`]).
    pub at_time_limit: bool,
}

impl Optimum {
    /// Its swing and range.
    pub fn point(&self) -> Point {
        Point {
            undercut: self.undercut,
            swing_angle: self.swing_angle,
            range: self.range,
            at_time_limit: self.at_time_limit,
        }
    }
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
        // A swing that does not land costs +∞ (range −∞).
        landed: best.range.is_finite(),
        flight_steps: optimizer.flight_steps(),
        status: optimizer.status(),
        scan: optimizer.scan(),
        at_time_limit: best.at_time_limit,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_search_stops_at_its_work_limit_and_says_so() {
        let scene = Scene::default();
        let whole = optimize(&scene, OptimizerSettings::default());
        assert_eq!(whole.status, Status::Converged);
        assert!(whole.landed);
        // A Table II optimum takes a few thousand steps: far inside the default.
        assert!(
            (1_000..20_000).contains(&whole.flight_steps),
            "{}",
            whole.flight_steps
        );
        let settings = OptimizerSettings {
            max_flight_steps: 1_000,
            ..OptimizerSettings::default()
        };
        let cut = optimize(&scene, settings);
        assert_eq!(cut.status, Status::OutOfWork);
        assert!(!cut.converged && cut.landed);
        // No flight starts past the limit: at most one flight over it.
        assert!(
            (1_000..1_100).contains(&cut.flight_steps),
            "{}",
            cut.flight_steps
        );
    }

    #[test]
    fn a_start_that_does_not_land_scans_then_searches() {
        let mut scene = Scene::default();
        scene.environment.gravity = 0.001;
        let mut optimizer = Optimizer::new(
            &scene,
            (scene.bat.undercut, scene.bat.swing_angle),
            Purpose::Optimizer,
            OptimizerSettings::default(),
        );
        // The start's simplex, then one flight of the scan a step.
        assert_eq!(optimizer.evaluations(), 3);
        assert_eq!(optimizer.best().range, f64::NEG_INFINITY);
        for n in 1..=64 {
            assert_eq!(optimizer.step(), Status::Running);
            assert_eq!(optimizer.scan().unwrap().flown, n);
        }
        // The last scan step started the simplex at the best cell.
        assert!(optimizer.scan().unwrap().complete);
        assert_eq!(optimizer.evaluations(), 3 + 64 + 3);
        assert!(optimizer.best().range.is_finite());
    }
}
