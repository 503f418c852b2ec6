//! A Baseball Savant (Statcast) row made a batted ball: the spray angle
//! from the hit coordinates, the spin from Nathan's estimate where the row
//! has none ([`crate::model::spin_estimate`]), and the launch direction.
//!
//! Savant's hit coordinates mark where the ball came down: its spray angle
//! is the landing's bearing, not the launch direction. Sidespin curves a
//! batted ball 0° to 17° between the two (docs/savant-sample.md), and
//! Nathan's spin estimate wants the launch direction. So by default the
//! launch direction is solved: the one whose flight, with the spin
//! estimated from that very direction, lands on the spray's bearing (a
//! secant iteration on the landing direction, a few flights). Taking the
//! spray as the launch direction instead ([`Spray::Launch`]) is the recipe
//! of pybaseball's calculator, and lands shorter (docs/accuracy.md).

use crate::model::flight::FlightOptions;
use crate::model::frame;
use crate::model::launch::SceneFlight;
use crate::model::scene::{Scene, SceneKind};
use crate::model::spin_estimate::{SIDESPIN_PER_DIRECTION, Side, nathan_spin};

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
/// Flights the solve may take: it needs three to five (`homerun bench`).
const MAX_FLIGHTS: usize = 12;
/// Launch directions are kept this far inside ±π/2 (`launch.direction`'s
/// open bounds).
const MAX_DIRECTION: f64 = std::f64::consts::FRAC_PI_2 - 1e-3;

/// A row's scene with its launch complete, and how it was found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Launched {
    pub scene: Scene,
    /// Flights flown to solve the direction (0 when it was not solved).
    pub flights: usize,
}

/// Why no launch direction lands on the spray.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SolveError {
    #[error("no launch direction lands on the spray angle {spray:.4} rad: a flight did not land")]
    NotLanded { spray: f64 },
    #[error(
        "no launch direction lands on the spray angle {spray:.4} rad within {MAX_FLIGHTS} flights (last miss {miss:.2e} rad)"
    )]
    NotConverged { spray: f64, miss: f64 },
}

/// `scene` (a batted ball with its speed and angle, and any spin the row
/// gave) with the rest of its launch: the direction from the spray as
/// `spray` says, and the spin estimated where `row` asks, from that
/// direction.
pub fn launch(
    scene: &Scene,
    row: &RowLaunch,
    spray: Spray,
    options: &FlightOptions,
) -> Result<Launched, SolveError> {
    let mut scene = *scene;
    match (row.spray, spray) {
        (Some(bearing), Spray::Landing) => {
            let flights = solve_direction(&mut scene, row, bearing, options)?;
            Ok(Launched { scene, flights })
        }
        (Some(bearing), Spray::Launch) => {
            launch_toward(&mut scene, row, bearing);
            Ok(Launched { scene, flights: 0 })
        }
        (None, _) => {
            let direction = scene.batted_ball().direction;
            launch_toward(&mut scene, row, direction);
            Ok(Launched { scene, flights: 0 })
        }
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

/// Launches toward `direction`, with the spin the estimate gives there
/// where the row asks for it.
fn launch_toward(scene: &mut Scene, row: &RowLaunch, direction: f64) {
    scene.launch.direction = Some(direction);
    if row.estimates_spin() {
        let angle = scene.batted_ball().angle;
        let (backspin, sidespin) = nathan_spin(angle, direction, row.side);
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
/// launch does). Returns the flights it took.
fn solve_direction(
    scene: &mut Scene,
    row: &RowLaunch,
    bearing: f64,
    options: &FlightOptions,
) -> Result<usize, SolveError> {
    let miss = |scene: &mut Scene, direction: f64| {
        launch_toward(scene, row, direction);
        let summary = SceneFlight::new(scene, &scene.batted_ball()).fly(options);
        let (sin, cos) = summary.direction.sin_cos();
        let landing = frame::direction_of(summary.range * cos, summary.range * sin);
        summary
            .landed
            .then_some(landing - bearing)
            .ok_or(SolveError::NotLanded { spray: bearing })
    };
    let clamp = |d: f64| d.clamp(-MAX_DIRECTION, MAX_DIRECTION);
    let (mut previous, mut previous_miss) = (bearing, miss(scene, bearing)?);
    if previous_miss.abs() < DIRECTION_TOLERANCE {
        return Ok(1);
    }
    // The first step's slope: the landing moves with the launch, and with
    // an estimated sidespin its curve grows too (the estimate's sidespin
    // rises with the direction), about in proportion to the sidespin.
    let sidespin = scene.batted_ball().sidespin;
    let slope = if row.estimate_sidespin && sidespin.abs() > 1.0 {
        1.0 + previous_miss * SIDESPIN_PER_DIRECTION / sidespin
    } else {
        1.0
    };
    let mut direction = clamp(bearing - previous_miss / slope.max(0.5));
    let mut flights = 1;
    loop {
        let now = miss(scene, direction)?;
        flights += 1;
        if now.abs() < DIRECTION_TOLERANCE {
            break;
        }
        if flights >= MAX_FLIGHTS || now == previous_miss {
            return Err(SolveError::NotConverged {
                spray: bearing,
                miss: now,
            });
        }
        let next = direction - now * (direction - previous) / (now - previous_miss);
        (previous, previous_miss) = (direction, now);
        direction = clamp(next);
    }
    Ok(flights)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::precision::Purpose;
    use crate::model::launch::BattedBall;
    use crate::model::scene::GivenLaunch;
    use crate::model::spin_estimate::Side;
    use crate::numerics::ode::Tolerance;

    #[test]
    fn the_spray_angle_is_positive_toward_right_field() {
        // Straight out from the plate, along the plate's hc_x.
        assert_eq!(spray_angle(PLATE_HC_X, 50.0), 0.0);
        // Up and to the right in Savant's picture: right field, 45°.
        let right = spray_angle(PLATE_HC_X + 100.0, PLATE_HC_Y - 100.0);
        assert!((right - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        // The committed sample's first row (Encarnación, to left-centre).
        let left = spray_angle(64.80, 47.78).to_degrees();
        assert!((left + 21.94).abs() < 0.01, "{left}");
    }

    #[test]
    fn a_launch_taken_as_given_is_what_launch_leaves() {
        let options = Purpose::Readout.flight_options();
        let mut complete = Scene::default();
        complete.set_kind(SceneKind::BattedBall);
        complete.launch = GivenLaunch {
            speed: Some(44.0),
            angle: Some(0.45),
            spin: Some(-0.0),
            direction: Some(-0.2),
            sidespin: Some(35.0),
        };
        let mut partial = complete;
        partial.launch.sidespin = None;
        let plain = RowLaunch::default();
        let rows = [
            plain,
            RowLaunch {
                spray: Some(0.1),
                ..plain
            },
            RowLaunch {
                estimate_sidespin: true,
                ..plain
            },
            RowLaunch {
                side: Some(Side::Left),
                ..plain
            },
        ];
        let mut given = 0;
        for scene in [complete, partial, Scene::default()] {
            for (row, spray) in rows
                .iter()
                .flat_map(|r| [(r, Spray::Launch), (r, Spray::Landing)])
            {
                if row.spray.is_some() && spray == Spray::Landing {
                    continue; // solved: never taken as given
                }
                let launched = launch(&scene, row, spray, &options).unwrap();
                if launches_as_given(&scene, row) {
                    given += 1;
                    // To the bit: the scene, and no flight spent.
                    let bits = |s: &Scene| s.launch.values().map(|v| v.map(f64::to_bits));
                    assert_eq!(bits(&launched.scene), bits(&scene));
                    assert_eq!((launched.scene, launched.flights), (scene, 0));
                } else {
                    assert!(row.spray.is_some() || row.estimates_spin() || scene != complete);
                }
            }
        }
        assert_eq!(given, 4);
    }

    #[test]
    fn the_solved_launch_lands_on_the_spray() {
        let options = FlightOptions {
            tolerance: Tolerance::uniform(1e-9),
            stop_at_kinks: true,
        };
        let base = crate::Scene::default().with_launch(BattedBall {
            speed: 46.0,
            angle: 0.49,
            spin: 0.0,
            direction: 0.0,
            sidespin: 0.0,
        });
        for (side, bearing) in [(Side::Right, 0.3), (Side::Right, -0.4), (Side::Left, 0.1)] {
            let row = RowLaunch {
                spray: Some(bearing),
                side: Some(side),
                estimate_backspin: true,
                estimate_sidespin: true,
            };
            let solved = launch(&base, &row, Spray::Landing, &options).unwrap();
            let ball = solved.scene.batted_ball();
            let landing = SceneFlight::new(&solved.scene, &ball)
                .fly(&options)
                .direction;
            assert!((landing - bearing).abs() < DIRECTION_TOLERANCE, "{landing}");
            assert!(solved.flights <= 5, "{}", solved.flights);
            // The spin is the estimate's at the launch direction.
            let (back, sidespin) = nathan_spin(0.49, ball.direction, Some(side));
            assert_eq!((ball.spin, ball.sidespin), (back, sidespin));
            // A slice (sidespin toward right field) is launched left of
            // where it lands, a hook right of it.
            assert_eq!(ball.direction < bearing, sidespin > 0.0, "{ball:?}");
            // Taken as the launch direction, the spray is where it leaves.
            let taken = launch(&base, &row, Spray::Launch, &options).unwrap();
            assert_eq!(taken.scene.batted_ball().direction, bearing);
        }
    }
}
