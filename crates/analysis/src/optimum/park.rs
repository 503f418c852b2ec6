//! The swing that clears a park's wall by the most (issue 17): Nelder–Mead
//! over the undercut E, the swing angle ψ and the bat's direction φ_B, any
//! of them held, maximising the [`Margin`] at one fence (docs/swing-3d.md,
//! "The best swing for a park").
//!
//! A home run passes through the fence's "window": above the wall's top
//! and between the foul poles. The margin is how far inside it the ball
//! passes: the smaller of its height over the wall where its track crosses
//! the fence ([`Clearing::clearance`], continued down the landing line for
//! a ball that falls short) and its room inside the nearer foul line
//! there. It is what decides a home run, the same measure in every park,
//! and continuous across short, off the wall, clears and foul, so that a
//! simplex can climb it. Height alone would put every optimum on a foul
//! line, where the wall is nearest, fair by a hair. A ball that neither
//! lands nor reaches the fence is infeasible (+∞), as in the range search.
//!
//! The margin has a hill toward each stretch of near or low wall, so the
//! search climbs from the scene's own swing and from [`START_DIRECTIONS`],
//! and keeps the best. The bat's direction is searched in the batter's own
//! frame, h·φ_B (h = +1 right-handed, −1 left-handed): a left-handed batter
//! at the mirror image of a park takes the mirror image of a right-handed
//! batter's path.

use serde::Serialize;

use super::{MAX_SWING_ANGLE, Optimizer, OptimizerSettings, SCAN_SIDE, Status};
use super::{SWING_ANGLE_SCALE, UNDERCUT_SCALE};
use crate::study::Grid;
use model::clearing::{Clearing, Outcome};
use model::flight::{FlightOptions, FlightSummary};
use model::launch;
use model::park::{FOUL_LINE, Fence};
use model::scene::Scene;
use numerics::nelder_mead::{self, NelderMead};

/// The keys the search moves, in its order; `--fix` holds any of them.
pub const SEARCHED_KEYS: [&str; 3] = ["bat.undercut", "bat.swing_angle", "bat.direction"];

/// φ_B is searched in units of this (rad), as ψ is: a tenth of a radian
/// of either moves the margin by a comparable amount.
const DIRECTION_SCALE: f64 = 0.1;

/// The bat directions the searches start from, in the batter's frame
/// (h·φ_B, rad; negative pulls), besides the scene's own: centre, the
/// alleys and the lines' side of them, where the margin's hills are.
pub const START_DIRECTIONS: [f64; 5] = [-0.6, -0.3, 0.0, 0.3, 0.6];

/// A swing as the park search moves it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Swing {
    /// E (m).
    pub undercut: f64,
    /// ψ (rad).
    pub swing_angle: f64,
    /// φ_B, `bat.direction` (rad).
    pub direction: f64,
}

impl Swing {
    /// The scene's own swing.
    pub fn of(scene: &Scene) -> Swing {
        Swing {
            undercut: scene.bat.undercut,
            swing_angle: scene.bat.swing_angle,
            direction: scene.bat.direction,
        }
    }

    /// `scene` with this swing.
    pub fn in_scene(&self, scene: &Scene) -> Scene {
        let mut scene = scene.with_swing(self.undercut, self.swing_angle);
        scene.bat.direction = self.direction;
        scene
    }

    fn get(&self, axis: usize) -> f64 {
        [self.undercut, self.swing_angle, self.direction][axis]
    }

    fn set(&mut self, axis: usize, value: f64) {
        *[
            &mut self.undercut,
            &mut self.swing_angle,
            &mut self.direction,
        ][axis] = value;
    }
}

/// Which of [`SEARCHED_KEYS`] are held at the scene's value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Held(pub [bool; 3]);

impl Held {
    /// Holds `key` (one of [`SEARCHED_KEYS`]); false if it is not one.
    pub fn hold(&mut self, key: &str) -> bool {
        match SEARCHED_KEYS.iter().position(|k| *k == key) {
            Some(axis) => {
                self.0[axis] = true;
                true
            }
            None => false,
        }
    }

    /// The axes searched, in order.
    fn free(&self) -> Vec<usize> {
        (0..3).filter(|&axis| !self.0[axis]).collect()
    }
}

/// How far the ball passes inside the home-run window where it meets the
/// fence (m): the window is the fence's face above the wall's top and
/// between the foul poles, and a home run passes through it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Margin {
    /// [`Clearing::clearance`]: the height over the wall's top where the
    /// track crosses the fence, continued down the landing line for a ball
    /// that falls short (for a foul ball, against the wall at the pole).
    pub over_wall: f64,
    /// The room inside the foul line: the arc, at the distance where the
    /// ball crosses the fence's line (or lands, if short), from its
    /// direction to the nearer foul line; negative foul.
    pub inside_line: f64,
}

impl Margin {
    /// The nearer edge: how far the ball could have passed lower, or
    /// nearer the line, and still gone out. What the search maximises.
    pub fn value(&self) -> f64 {
        self.over_wall.min(self.inside_line)
    }
}

/// One swing's flight judged at one fence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Judged {
    pub flight: FlightSummary,
    pub clearing: Clearing,
    /// None when the ball neither lands nor reaches the fence.
    pub margin: Option<Margin>,
}

impl Judged {
    /// Flies `scene` (a swing or a batted ball) as precisely as `options`
    /// says and judges it at `fence`.
    pub fn new(scene: &Scene, fence: &Fence, options: &FlightOptions) -> Judged {
        let (flight, _, _) = launch::scene_start(scene);
        let mut crossing = [None];
        let summary = flight.fly_to_fences(options, &[fence], &mut crossing);
        Judged::of(
            fence,
            Clearing::judge(fence, crossing[0], &summary),
            summary,
        )
    }

    /// `clearing`, of `flight` at `fence`, with its margin.
    pub fn of(fence: &Fence, clearing: Clearing, flight: FlightSummary) -> Judged {
        Judged {
            margin: margin(fence, &clearing, &flight),
            flight,
            clearing,
        }
    }

    /// What the search maximises (m): [`Margin::value`], or −∞ for a ball
    /// that neither lands nor reaches the fence.
    pub fn score(&self) -> f64 {
        self.margin.map_or(f64::NEG_INFINITY, |m| m.value())
    }
}

/// The margin of `flight`, judged `clearing` at `fence`. A foul ball is
/// measured as a fair one at the nearer pole (the fence continued past it,
/// as the crossing is found), so that the margin runs on continuously
/// across the line, negative, and a simplex that strays foul climbs back.
fn margin(fence: &Fence, clearing: &Clearing, flight: &FlightSummary) -> Option<Margin> {
    let crossed = clearing.height_at_fence.is_some();
    let over_wall = match clearing.clearance(flight) {
        Some(clearance) => clearance,
        None if clearing.outcome == Outcome::Foul => {
            let pole = fence.at(FOUL_LINE.copysign(clearing.direction))?;
            let at_pole = Clearing {
                outcome: if crossed {
                    Outcome::OffTheWall
                } else {
                    Outcome::Short
                },
                margin: clearing.height_at_fence.map(|h| h - pole.height),
                wall: Some(pole),
                ..*clearing
            };
            at_pole.clearance(flight)?
        }
        None => return None,
    };
    let distance = if crossed {
        fence.reach(clearing.direction).0
    } else {
        flight.range.abs()
    };
    Some(Margin {
        over_wall,
        inside_line: distance * (FOUL_LINE - clearing.direction.abs()),
    })
}

/// The best swing found for a park.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ParkOptimum {
    pub swing: Swing,
    /// Its margin ([`Margin::value`]) at the optimiser's precision (m);
    /// −∞ if no swing tried has one.
    pub margin: f64,
    /// What the best swing does at the fence, if any swing was flown.
    pub outcome: Option<Outcome>,
    /// Whether some swing tried has a margin (it lands or reaches the
    /// fence): otherwise there is no optimum, and `swing` is where the
    /// search started.
    pub found: bool,
    /// Flights flown.
    pub evaluations: u32,
    pub flight_steps: u64,
    /// Searches climbed (one per start that has a score).
    pub starts: u32,
    /// Swings of the coarse scan flown, if no start scored.
    pub scanned: Option<u32>,
    /// The best search's end: converged, or the limit it met.
    pub status: Status,
    pub converged: bool,
}

/// The margin as a cost over the free axes in scaled units, counting the
/// flights, keeping the best swing flown.
struct Objective<'a> {
    scene: Scene,
    fence: &'a Fence,
    options: FlightOptions,
    held: Held,
    /// h: the batter's side, the direction axis's sign.
    hand: f64,
    /// bat.direction's bounds.
    directions: (f64, f64),
    evaluations: u32,
    flight_steps: u64,
    max_flight_steps: u64,
    /// The best swing flown, its cost and outcome.
    best: Option<(Swing, f64, Outcome)>,
}

impl Objective<'_> {
    /// The swing at scaled `point` on the `free` axes, the held ones the
    /// scene's, exactly.
    fn swing(&self, free: &[usize], point: &[f64]) -> Swing {
        let mut swing = Swing::of(&self.scene);
        for (&axis, &u) in free.iter().zip(point) {
            swing.set(axis, u * self.scale(axis));
        }
        swing
    }

    /// One scaled unit of `axis`, in its own unit (the direction's in the
    /// batter's frame).
    fn scale(&self, axis: usize) -> f64 {
        [
            UNDERCUT_SCALE,
            SWING_ANGLE_SCALE,
            self.hand * DIRECTION_SCALE,
        ][axis]
    }

    fn scaled(&self, swing: &Swing, free: &[usize]) -> Vec<f64> {
        free.iter()
            .map(|&axis| swing.get(axis) / self.scale(axis))
            .collect()
    }

    fn cost(&mut self, swing: Swing) -> f64 {
        let (low, high) = self.directions;
        let outside = swing.undercut.abs() >= self.scene.reach()
            || swing.swing_angle.abs() > MAX_SWING_ANGLE
            || !(low..=high).contains(&swing.direction);
        if outside || (self.evaluations > 0 && self.flight_steps >= self.max_flight_steps) {
            return f64::INFINITY;
        }
        self.evaluations += 1;
        let judged = Judged::new(&swing.in_scene(&self.scene), self.fence, &self.options);
        let stats = judged.flight.stats;
        self.flight_steps += u64::from(stats.accepted) + u64::from(stats.rejected);
        let cost = -judged.score();
        if cost < self.best.map_or(f64::INFINITY, |b| b.1) {
            self.best = Some((swing, cost, judged.clearing.outcome));
        }
        cost
    }
}

/// Searches `scene`'s swing for the largest margin at `fence`, the `held`
/// keys at the scene's values, each flight as precisely as `options` says
/// (normally `Purpose::Optimizer`). The scene must be a valid swing.
pub fn optimize_park(
    scene: &Scene,
    fence: &Fence,
    held: Held,
    options: impl Into<FlightOptions>,
    settings: OptimizerSettings,
) -> ParkOptimum {
    let key = Scene::key("bat.direction").expect("a key");
    let mut objective = Objective {
        scene: *scene,
        fence,
        options: options.into(),
        held,
        hand: scene.bat.hand.sign(),
        directions: (key.bounds.min, key.bounds.max),
        evaluations: 0,
        flight_steps: 0,
        max_flight_steps: settings.max_flight_steps,
        best: None,
    };
    let free = held.free();
    let starts = start_swings(scene, held, objective.directions);
    let mut climbed = 0;
    let mut status = Status::Converged;
    let mut best_status = Status::Converged;
    let mut climb_from = |objective: &mut Objective, start: Swing| {
        let before = objective.best.map(|b| b.1);
        let end = climb(objective, &free, start, settings);
        if objective.best.map(|b| b.1) != before {
            best_status = end;
        }
        if end == Status::OutOfWork {
            status = end;
        }
        end
    };
    for start in &starts {
        if objective.cost(*start).is_finite() {
            climbed += 1;
            climb_from(&mut objective, *start);
        }
    }
    let mut scanned = None;
    if objective.best.is_none_or(|b| !b.1.is_finite()) && !(held.0[0] && held.0[1]) {
        let (flown, found) = scan(&mut objective, &starts);
        scanned = Some(flown);
        if let Some(start) = found {
            climbed += 1;
            climb_from(&mut objective, start);
        }
    }
    let status = match (objective.best, status) {
        (None, _) => Status::NothingLands,
        (Some(b), _) if !b.1.is_finite() => Status::NothingLands,
        (_, Status::OutOfWork) => Status::OutOfWork,
        _ => best_status,
    };
    let (swing, cost, outcome) = match objective.best {
        Some((swing, cost, outcome)) => (swing, cost, Some(outcome)),
        None => (starts[0], f64::INFINITY, None),
    };
    let found = cost.is_finite();
    ParkOptimum {
        swing: if found { swing } else { starts[0] },
        margin: -cost,
        outcome,
        found,
        evaluations: objective.evaluations,
        flight_steps: objective.flight_steps,
        starts: climbed,
        scanned,
        status,
        converged: status == Status::Converged,
    }
}

/// Where the searches start: the scene's own swing, clamped into the
/// feasible region; then, with the direction free, the same E and ψ at
/// each of [`START_DIRECTIONS`] other than the scene's.
fn start_swings(scene: &Scene, held: Held, (low, high): (f64, f64)) -> Vec<Swing> {
    let limit = 0.99 * scene.reach();
    let own = Swing {
        undercut: scene.bat.undercut.clamp(-limit, limit),
        swing_angle: scene
            .bat
            .swing_angle
            .clamp(-MAX_SWING_ANGLE, MAX_SWING_ANGLE),
        direction: scene.bat.direction,
    };
    let mut starts = vec![own];
    if !held.0[2] {
        let hand = scene.bat.hand.sign();
        starts.extend(
            START_DIRECTIONS
                .iter()
                .map(|d| Swing {
                    direction: (hand * d).clamp(low, high),
                    ..own
                })
                .filter(|s| s.direction != own.direction),
        );
    }
    starts
}

/// Climbs from `start` over the `free` axes until converged or a limit.
fn climb(
    objective: &mut Objective,
    free: &[usize],
    start: Swing,
    settings: OptimizerSettings,
) -> Status {
    match *free {
        [a, b, c] => climb_in::<3, 4>(objective, [a, b, c], start, settings),
        [a, b] => climb_in::<2, 3>(objective, [a, b], start, settings),
        [a] => climb_in::<1, 2>(objective, [a], start, settings),
        _ => Status::Converged,
    }
}

fn climb_in<const N: usize, const M: usize>(
    objective: &mut Objective,
    free: [usize; N],
    start: Swing,
    settings: OptimizerSettings,
) -> Status {
    let first = objective.evaluations;
    let start = nelder_mead::Point::<N>::from_iterator(objective.scaled(&start, &free));
    let cost = |objective: &mut Objective, u: &nelder_mead::Point<N>| {
        let swing = objective.swing(&free, u.as_slice());
        objective.cost(swing)
    };
    let simplex = Optimizer::simplex(settings);
    let mut search = NelderMead::<N, M>::new(start, simplex, &mut |u| cost(objective, u));
    loop {
        if search.step(&mut |u| cost(objective, u)) == nelder_mead::Status::Converged {
            return Status::Converged;
        }
        if objective.flight_steps >= objective.max_flight_steps {
            return Status::OutOfWork;
        }
        if objective.evaluations - first >= settings.max_evaluations {
            return Status::OutOfEvaluations;
        }
    }
}

/// No start scores: flies [`SCAN_SIDE`]² swings over
/// [`Grid::explorer_window`] (its free axes of E and ψ) at each start's
/// direction, and gives how many it flew and the best that scores.
fn scan(objective: &mut Objective, starts: &[Swing]) -> (u32, Option<Swing>) {
    let grid = Grid {
        columns: SCAN_SIDE,
        rows: SCAN_SIDE,
        ..Grid::explorer_window()
    };
    let [hold_undercut, hold_swing_angle, _] = objective.held.0;
    let columns = if hold_undercut { 1 } else { grid.columns };
    let rows = if hold_swing_angle { 1 } else { grid.rows };
    let before = objective.evaluations;
    let mut best: Option<(Swing, f64)> = None;
    for start in starts {
        for j in 0..rows {
            for i in 0..columns {
                let mut swing = *start;
                if !hold_undercut {
                    swing.undercut = grid.undercut_at(i);
                }
                if !hold_swing_angle {
                    swing.swing_angle = grid.swing_angle_at(j);
                }
                let cost = objective.cost(swing);
                if cost < best.map_or(f64::INFINITY, |b| b.1) {
                    best = Some((swing, cost));
                }
            }
        }
    }
    (objective.evaluations - before, best.map(|b| b.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use model::launch::BattedBall;

    /// A batted ball in vacuum toward `direction`: a straight ground track.
    fn judged(speed: f64, direction: f64) -> Judged {
        let mut scene = Scene::default();
        scene.environment.set_air_density(0.0);
        let scene = scene.with_launch(BattedBall {
            speed,
            angle: 0.5,
            spin: 200.0,
            direction,
            sidespin: 0.0,
        });
        let options = crate::precision::Purpose::Readout.flight_options();
        Judged::new(&scene, &Fence::uniform(100.0, 3.0), &options)
    }

    #[test]
    fn the_margin_runs_on_across_the_foul_line() {
        // 40 m/s reaches the wall 100 m out; 25 m/s lands short of it.
        for speed in [40.0, 25.0] {
            let fair = judged(speed, FOUL_LINE - 1e-4);
            let foul = judged(speed, FOUL_LINE + 1e-4);
            assert_eq!(foul.clearing.outcome, Outcome::Foul);
            assert_ne!(fair.clearing.outcome, Outcome::Foul);
            let (a, b) = (fair.margin.unwrap(), foul.margin.unwrap());
            // The arc to the line at the crossing (100 m) or the landing.
            let distance = if speed > 30.0 {
                100.0
            } else {
                fair.flight.range
            };
            assert!((a.inside_line - distance * 1e-4).abs() < 1e-9, "{a:?}");
            assert!((b.inside_line + distance * 1e-4).abs() < 1e-6, "{b:?}");
            assert!((a.over_wall - b.over_wall).abs() < 1e-9, "{a:?} {b:?}");
            // Near the line the room beside a ball that clears decides;
            // a short one's height below the wall's top.
            let nearer = if speed > 30.0 {
                a.inside_line
            } else {
                a.over_wall
            };
            assert_eq!(a.value(), nearer, "{a:?}");
            // Continuous: the two scores differ by the room either side.
            assert!(b.value() < 0.0 && fair.score() >= foul.score());
            assert!(fair.score() - foul.score() <= 2e-4 * distance + 1e-9);
        }
    }

    #[test]
    fn only_the_searched_keys_can_be_held() {
        let mut held = Held::default();
        assert!(held.hold("bat.direction") && held.hold("bat.undercut"));
        assert!(!held.hold("bat.speed"));
        assert_eq!(held.0, [true, false, true]);
        assert_eq!(held.free(), [1]);
    }
}
