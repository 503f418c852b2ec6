//! A Baseball Savant (Statcast) row made a batted ball: the spray angle
//! from the hit coordinates, the spin from Nathan's estimate where the row
//! has none ([`model::spin_estimate`]), and the launch direction.
//!
//! Savant's hit coordinates mark where the ball came down: its spray angle
//! is the landing's bearing, not the launch direction. Sidespin curves a
//! batted ball 0° to 17° between the two (docs/savant-sample.md), and
//! Nathan's spin estimate wants the launch direction. So by default the
//! launch direction is solved: the one whose flight, with the spin
//! estimated from that very direction, lands on the spray's bearing (a
//! secant iteration on the landing direction, a few flights, the first ones
//! at a looser precision while they are far from it). Taking the
//! spray as the launch direction instead ([`Spray::Launch`]) is the recipe
//! of pybaseball's calculator, and lands shorter (docs/accuracy.md).

use crate::precision::{AIM_MISS, Purpose};
use model::flight::{FlightOptions, FlightSummary};
use model::frame;
use model::launch::SceneFlight;
use model::many;
use model::scene::{Hand, Scene, SceneKind};
use model::spin_estimate::{SIDESPIN_PER_DIRECTION, Side, nathan_spin};

/// Savant's hit coordinates (hc_x, hc_y) of home plate: the constants of
/// Jim Albert's and pybaseball's spray angle (pybaseball's
/// `add_spray_angle`, without its factor 0.75: docs/savant-sample.md).
pub const PLATE_HC_X: f64 = 125.42;
pub const PLATE_HC_Y: f64 = 198.27;

/// The spray angle (rad, from the centre-field line, positive toward right
/// field) of a ball Savant placed at (hc_x, hc_y): atan((hc_x − 125.42) /
/// (198.27 − hc_y)). Savant's y grows toward home plate, hence the
/// difference's order.
pub fn spray_angle(hc_x: f64, hc_y: f64) -> f64 {
    ((hc_x - PLATE_HC_X) / (PLATE_HC_Y - hc_y)).atan()
}

/// What the spray angle is taken to be.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Spray {
    /// Where the ball came down (what it is): the launch direction is
    /// solved so that the flight lands on that bearing.
    #[default]
    Landing,
    /// The launch direction itself (pybaseball's calculator's recipe).
    Launch,
}

/// What a row says of its launch besides speed and angle, and which spins
/// it leaves to the estimate.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RowLaunch {
    /// The spray angle (rad), if the row has hit coordinates and no launch
    /// direction of its own.
    pub spray: Option<f64>,
    pub side: Option<Side>,
    /// Estimate the backspin (the row and the command line give none).
    pub estimate_backspin: bool,
    /// Estimate the sidespin likewise.
    pub estimate_sidespin: bool,
    /// The spin's measured size (rad/s; a tracker's total spin rate without
    /// its axis): the estimate then gives only the axis, its backspin and
    /// sidespin scaled to this size.
    pub measured_spin: Option<f64>,
}

impl RowLaunch {
    pub fn estimates_spin(&self) -> bool {
        self.estimate_backspin || self.estimate_sidespin
    }
}

/// The landing direction is wanted to this (rad): 1.2 cm sideways at
/// 120 m, and 0.5 rpm of estimated sidespin, far below what the hit
/// coordinates resolve. The secant iteration gets there in three or four
/// flights (the miss falls ~0.1, 1e-2, 1e-4, 1e-7 rad).
const DIRECTION_TOLERANCE: f64 = 1e-4;
/// Flights the solve may take: it needs three to five (`homerun bench`), a
/// popup whose landing swings about the plate a dozen.
const MAX_FLIGHTS: usize = 16;
/// Launch directions are kept this far inside ±π/2 (`launch.direction`'s
/// open bounds).
const MAX_DIRECTION: f64 = std::f64::consts::FRAC_PI_2 - 1e-3;

/// A row's scene with its launch complete, and how it was found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Launched {
    pub scene: Scene,
    /// Flights flown to solve the direction (0 when it was not solved).
    pub flights: usize,
    pub direction_from: DirectionFrom,
}

/// Where a row's launch direction came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DirectionFrom {
    /// Solved: the flight lands on the spray's bearing.
    Landing,
    /// The spray angle, taken as the launch direction ([`Spray::Launch`]).
    Spray,
    /// The spray angle, because no launch direction lands on it: the hit
    /// coordinates of a grounder or a popup are where it was fielded,
    /// which need not be anywhere a flight comes down (a chopper fielded
    /// down the line, a popup that drifts foul).
    SprayUnsolved,
    /// The scene's own (the row has no hit coordinates).
    Scene,
}

impl DirectionFrom {
    /// The word a batch's row gives.
    pub fn name(self) -> &'static str {
        match self {
            DirectionFrom::Landing => "landing",
            DirectionFrom::Spray => "spray",
            DirectionFrom::SprayUnsolved => "spray_unsolved",
            DirectionFrom::Scene => "scene",
        }
    }
}

/// `scene` (a batted ball with its speed and angle, and any spin the row
/// gave) with the rest of its launch: the direction from the spray as
/// `spray` says, and the spin estimated where `row` asks, from that
/// direction.
pub fn launch(scene: &Scene, row: &RowLaunch, spray: Spray, options: &FlightOptions) -> Launched {
    let mut scene = *scene;
    let (flights, direction_from) = match (row.spray, spray) {
        (Some(bearing), Spray::Landing) => solve_direction(&mut scene, row, bearing, options),
        (Some(bearing), Spray::Launch) => {
            launch_toward(&mut scene, row, bearing);
            (0, DirectionFrom::Spray)
        }
        (None, _) => {
            let direction = scene.batted_ball().direction;
            launch_toward(&mut scene, row, direction);
            (0, DirectionFrom::Scene)
        }
    };
    Launched {
        scene,
        flights,
        direction_from,
    }
}

/// Whether [`launch`] leaves `scene` as it is: a batted ball whose launch
/// is complete, with no spray to take and no spin to estimate (a batch row
/// that gives its whole launch), so that a caller may skip it.
pub fn launches_as_given(scene: &Scene, row: &RowLaunch) -> bool {
    row.spray.is_none()
        && !row.estimates_spin()
        && scene.kind == SceneKind::BattedBall
        && scene.launch.is_complete()
}

/// One ball's launch with its spin estimated as a batch row without one
/// has it (`fly --spin nathan`): the scene's launch (given, or its swing's
/// impact's) as a batted ball, its backspin and, unless `sidespin_given`,
/// its sidespin from Nathan's relation at its angle and direction, for a
/// batter of the scene's `bat.hand`.
pub fn with_estimated_spin(scene: &Scene, sidespin_given: bool) -> Scene {
    let mut scene = scene.with_launch(scene.batted_ball());
    let side = match scene.bat.hand {
        Hand::Right => Side::Right,
        Hand::Left => Side::Left,
    };
    let row = RowLaunch {
        spray: None,
        side: Some(side),
        estimate_backspin: true,
        estimate_sidespin: !sidespin_given,
        measured_spin: None,
    };
    let direction = scene.batted_ball().direction;
    launch_toward(&mut scene, &row, direction);
    scene
}

/// Launches toward `direction`, with the spin the estimate gives there
/// where the row asks for it.
fn launch_toward(scene: &mut Scene, row: &RowLaunch, direction: f64) {
    scene.launch.direction = Some(direction);
    if row.estimates_spin() {
        let angle = scene.batted_ball().angle;
        let (mut backspin, mut sidespin) = nathan_spin(angle, direction, row.side);
        let size = backspin.hypot(sidespin);
        if let Some(measured) = row.measured_spin.filter(|_| size > 0.0) {
            (backspin, sidespin) = (backspin * measured / size, sidespin * measured / size);
        }
        if row.estimate_backspin {
            scene.launch.spin = Some(backspin);
        }
        if row.estimate_sidespin {
            scene.launch.sidespin = Some(sidespin);
        }
    }
}

/// Solves for the launch direction whose flight lands on `bearing`: the
/// secant method on miss(φ) = landing direction(φ) − bearing, from φ =
/// bearing and a step of one miss (the landing direction moves about as the
/// launch does). Returns the flights it took, and where the direction came
/// from (the spray itself where no direction lands on it).
fn solve_direction(
    scene: &mut Scene,
    row: &RowLaunch,
    bearing: f64,
    options: &FlightOptions,
) -> (usize, DirectionFrom) {
    let mut solve = DirectionSolve::new(*scene, row, bearing);
    loop {
        let summary = (solve.flight()).fly(&precision(solve.stage(), options));
        if let Some(ended) = solve.flown(&summary) {
            *scene = solve.scene;
            return ended;
        }
    }
}

/// A launch direction's solve under way ([`solve_direction`]), one flight
/// at a time: [`DirectionSolve::flight`] is the flight it wants flown
/// next, [`DirectionSolve::flown`] takes its outcome. So many rows' solves
/// can go on together, each round's flights flown at once
/// ([`launch_many`]).
struct DirectionSolve {
    /// The row's scene, launched toward `direction`.
    scene: Scene,
    row: RowLaunch,
    bearing: f64,
    direction: f64,
    /// The last direction flown and its miss (none before the first).
    previous: Option<(f64, f64)>,
    flights: usize,
    /// A flight came down within [`AIM_RANGE`]: the rest fly at the
    /// solve's precision.
    near: bool,
}

impl DirectionSolve {
    fn new(mut scene: Scene, row: &RowLaunch, bearing: f64) -> Self {
        launch_toward(&mut scene, row, bearing);
        DirectionSolve {
            scene,
            row: *row,
            bearing,
            direction: bearing,
            previous: None,
            flights: 0,
            near: false,
        }
    }

    /// The flight toward the direction being tried.
    fn flight(&self) -> SceneFlight {
        SceneFlight::new(&self.scene, &self.scene.batted_ball())
    }

    /// What [`Self::flight`] is flown for ([`precision`]): to aim, the
    /// first and every one after a miss over [`AIM_MISS`]; to confirm, the
    /// rest; at the solve's own precision once a flight came down within
    /// [`AIM_RANGE`].
    fn stage(&self) -> Stage {
        if self.near {
            Stage::Near
        } else if self.previous.is_none_or(|(_, miss)| miss.abs() >= AIM_MISS) {
            Stage::Aim
        } else {
            Stage::Confirm
        }
    }

    /// Takes the outcome of [`Self::flight`]: the flights taken and where
    /// the direction came from once the solve has ended, else `None` and
    /// the next direction to try.
    fn flown(&mut self, summary: &FlightSummary) -> Option<(usize, DirectionFrom)> {
        let stage = self.stage();
        self.flights += 1;
        let bearing = self.bearing;
        if !summary.landed {
            return Some(self.unsolved());
        }
        let miss = landing_direction(summary) - bearing;
        self.near |= summary.range.abs() < AIM_RANGE;
        // A flight's landing is known to its precision's budget sideways:
        // it ends the solve only as far inside the tolerance.
        let known_to = stage.lateral() / summary.range.abs();
        if miss.abs() + known_to < DIRECTION_TOLERANCE {
            return Some((self.flights, DirectionFrom::Landing));
        }
        let next = match self.previous {
            None => {
                // The first step's slope: the landing moves with the
                // launch, and with an estimated sidespin its curve grows
                // too (the estimate's sidespin rises with the direction),
                // about in proportion to the sidespin.
                let sidespin = self.scene.batted_ball().sidespin;
                let slope = if self.row.estimate_sidespin && sidespin.abs() > 1.0 {
                    1.0 + miss * SIDESPIN_PER_DIRECTION / sidespin
                } else {
                    1.0
                };
                bearing - miss / slope.max(0.5)
            }
            Some((previous, previous_miss)) => {
                if self.flights >= MAX_FLIGHTS || miss == previous_miss {
                    return Some(self.unsolved());
                }
                self.direction - miss * (self.direction - previous) / (miss - previous_miss)
            }
        };
        self.previous = Some((self.direction, miss));
        self.direction = next.clamp(-MAX_DIRECTION, MAX_DIRECTION);
        launch_toward(&mut self.scene, &self.row, self.direction);
        None
    }

    /// Gives up the solve (a flight that does not land, or no landing on
    /// the bearing within [`MAX_FLIGHTS`]): the spray taken as the launch
    /// direction.
    fn unsolved(&mut self) -> (usize, DirectionFrom) {
        let direction = self.bearing.clamp(-MAX_DIRECTION, MAX_DIRECTION);
        launch_toward(&mut self.scene, &self.row, direction);
        (self.flights, DirectionFrom::SprayUnsolved)
    }
}

/// What a solve's flight is flown for, and so at what precision
/// ([`precision`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    /// Far from the bearing: the next direction comes from the miss
    /// ([`Purpose::Aim`]).
    Aim,
    /// Near it: the flight may end the solve ([`Purpose::Verdict`], a
    /// little over half the solve's cost, its landing known to
    /// [`CONFIRM_LATERAL`]).
    Confirm,
    /// A flight came down within [`AIM_RANGE`], where a few millimetres
    /// sideways are a large angle: the solve's own precision.
    Near,
}

impl Stage {
    /// How far (m) sideways the flight's landing point may lie from the
    /// reference's: its direction is known to this over its range.
    fn lateral(self) -> f64 {
        match self {
            Stage::Aim => Purpose::Aim.range_budget(),
            Stage::Confirm => CONFIRM_LATERAL,
            Stage::Near => 0.0,
        }
    }
}

/// A confirming flight's landing point lies within this (m) of the
/// reference's, sideways: 2.7× the worst of 6,000 flights at
/// [`Purpose::Verdict`] (10–52 m/s, −30° to 90°, −500 to 1,500 rad/s of
/// backspin, ±200 of sidespin, both aeros: 1.1 mm, 0.37 mm past 50 m;
/// `Purpose::Aim` 8.2 and 2.2 mm, `Purpose::Solve` 4e-6 m). At 100 m its
/// direction is known to 3e-5 rad, inside the solve's 1e-4.
const CONFIRM_LATERAL: f64 = 3e-3;

/// A flight that comes down nearer than this (m), a popup or a grounder,
/// has its landing direction from an aiming flight unsure by more than
/// 4e-4 rad: the solve's next flights fly at its own precision.
const AIM_RANGE: f64 = 50.0;

/// The precision of a solve's flight at `stage`: [`Purpose::Aim`]'s to
/// aim, [`Purpose::Verdict`]'s to confirm, or the solve's own `options`
/// where that is looser, and near the plate.
fn precision(stage: Stage, options: &FlightOptions) -> FlightOptions {
    let purpose = match stage {
        Stage::Aim => Purpose::Aim,
        Stage::Confirm => Purpose::Verdict,
        Stage::Near => return *options,
    };
    let staged = purpose.flight_options();
    if options.tolerance.relative > staged.tolerance.relative {
        *options
    } else {
        staged
    }
}

/// Where a flight came down: the direction of its landing point (a planar
/// flight's range may be negative, behind the plate).
fn landing_direction(summary: &FlightSummary) -> f64 {
    let (sin, cos) = summary.direction.sin_cos();
    frame::direction_of(summary.range * cos, summary.range * sin)
}

/// [`launch`] for many rows (each its scene and row), in their order: the
/// direction solves go on together, a round of flights at a time, each
/// flight's answer its own ([`many::judge_many`]). So each row's launch is
/// [`launch`]'s, to the bit.
pub fn launch_many<'s>(
    rows: impl IntoIterator<Item = (&'s Scene, &'s RowLaunch)>,
    spray: Spray,
    options: &FlightOptions,
) -> Vec<Launched> {
    // Each row's launch; a row being solved has none until its solve ends.
    let mut launched: Vec<Option<Launched>> = Vec::new();
    let mut solving: Vec<(usize, DirectionSolve)> = Vec::new();
    for (index, (scene, row)) in rows.into_iter().enumerate() {
        match (row.spray, spray) {
            (Some(bearing), Spray::Landing) => {
                solving.push((index, DirectionSolve::new(*scene, row, bearing)));
                launched.push(None);
            }
            // As `launch` would give it, without its copies.
            _ if launches_as_given(scene, row) => launched.push(Some(Launched {
                scene: *scene,
                flights: 0,
                direction_from: DirectionFrom::Scene,
            })),
            _ => launched.push(Some(launch(scene, row, spray, options))),
        }
    }
    let mut summaries: Vec<Option<FlightSummary>> = Vec::new();
    while !solving.is_empty() {
        summaries.clear();
        summaries.resize(solving.len(), None);
        // The round's flights together, those of each stage at once.
        for stage in [Stage::Aim, Stage::Confirm, Stage::Near] {
            let flights: Vec<(usize, SceneFlight)> = (solving.iter().enumerate())
                .filter(|(_, (_, s))| s.stage() == stage)
                .map(|(k, (_, s))| (k, s.flight()))
                .collect();
            many::judge_many(
                flights.iter().map(|&(_, flight)| (flight, &[][..])),
                &precision(stage, options),
                |index, summary, _| summaries[flights[index].0] = Some(summary),
            );
        }
        let mut flown = summaries.iter();
        solving.retain_mut(|(index, solve)| {
            let summary = flown.next().copied().flatten().expect("every flight flown");
            match solve.flown(&summary) {
                Some((flights, direction_from)) => {
                    launched[*index] = Some(Launched {
                        scene: solve.scene,
                        flights,
                        direction_from,
                    });
                    false
                }
                None => true,
            }
        });
    }
    // Every solve ends within MAX_FLIGHTS rounds.
    (launched.into_iter())
        .map(|l| l.expect("every solve ended"))
        .collect()
}

#[cfg(test)]
mod tests;
