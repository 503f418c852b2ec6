//! The launch's tests: the spray's sign, the direction solve, the
//! estimate's spin and the many rows' launches.

use super::*;
use crate::precision::Purpose;
use model::launch::BattedBall;
use model::scene::GivenLaunch;
use model::spin_estimate::Side;
use numerics::ode::Tolerance;

/// `fly --spin nathan` is a batch row's estimate: the same launch, the
/// same spin, for the batter's side as `bat.hand` gives it.
#[test]
fn one_balls_estimate_is_a_batch_rows() {
    let mut scene = Scene::default();
    scene.set("launch.speed", 46.0).unwrap();
    scene.set("launch.angle", 0.45).unwrap();
    scene.set("launch.direction", -0.3).unwrap();
    for (hand, side) in [(Hand::Right, Side::Right), (Hand::Left, Side::Left)] {
        scene.bat.hand = hand;
        let one = with_estimated_spin(&scene, false).batted_ball();
        let (backspin, sidespin) = nathan_spin(0.45, -0.3, Some(side));
        assert_eq!((one.spin, one.sidespin), (backspin, sidespin));
        assert_eq!((one.speed, one.angle, one.direction), (46.0, 0.45, -0.3));
        // A sidespin given is kept.
        scene.set("launch.sidespin", 10.0).unwrap();
        assert_eq!(
            with_estimated_spin(&scene, true).batted_ball().sidespin,
            10.0
        );
        scene.launch.sidespin = None;
    }
}

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
            let launched = launch(&scene, row, spray, &options);
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
    let base = model::scene::Scene::default().with_launch(BattedBall {
        speed: 46.0,
        angle: 0.49,
        spin: 0.0,
        direction: 0.0,
        sidespin: 0.0,
    });
    // The last: a tracker's measured spin rate, the estimate's axis.
    let cases = [
        (Side::Right, 0.3, None),
        (Side::Right, -0.4, None),
        (Side::Left, 0.1, None),
        (Side::Right, 0.35, Some(250.0)),
    ];
    for (side, bearing, measured_spin) in cases {
        let row = RowLaunch {
            spray: Some(bearing),
            side: Some(side),
            estimate_backspin: true,
            estimate_sidespin: true,
            measured_spin,
        };
        let solved = launch(&base, &row, Spray::Landing, &options);
        let ball = solved.scene.batted_ball();
        let landing = SceneFlight::new(&solved.scene, &ball)
            .fly(&options)
            .direction;
        assert!((landing - bearing).abs() < DIRECTION_TOLERANCE, "{landing}");
        assert!(solved.flights <= 5, "{}", solved.flights);
        // The spin is the estimate's at the launch direction; a
        // measured size keeps the estimate's axis.
        let (back, sidespin) = nathan_spin(0.49, ball.direction, Some(side));
        match measured_spin {
            None => assert_eq!((ball.spin, ball.sidespin), (back, sidespin)),
            Some(measured) => {
                assert!((ball.spin.hypot(ball.sidespin) - measured).abs() < 1e-9);
                assert!((ball.sidespin / ball.spin - sidespin / back).abs() < 1e-12);
                assert!(measured < back.hypot(sidespin) - 50.0, "a size of its own");
            }
        }
        // A slice (sidespin toward right field) is launched left of
        // where it lands, a hook right of it.
        assert_eq!(ball.direction < bearing, sidespin > 0.0, "{ball:?}");
        // Taken as the launch direction, the spray is where it leaves.
        let taken = launch(&base, &row, Spray::Launch, &options);
        assert_eq!(taken.scene.batted_ball().direction, bearing);
    }
}

/// The default scene under Nathan's drag and lift, which the lanes fly
/// bit for bit as a flight alone.
fn nathan_scene() -> model::scene::Scene {
    let mut nathan = model::scene::Scene::default();
    nathan.set_text("model.drag", "nathan").unwrap();
    nathan.set_text("model.lift", "nathan").unwrap();
    nathan
}

/// Many rows' solves together (in lock-step where the lanes fly as one
/// flight alone does, one by one under the paper's drag crisis) give
/// each row's [`launch`], to the bit: its scene, flights and failures.
#[test]
fn launches_together_are_each_rows_launch() {
    use std::f64::consts::FRAC_PI_2;
    let options = FlightOptions {
        tolerance: Tolerance::uniform(1e-10),
        stop_at_kinks: true,
    };
    let nathan = nathan_scene();
    let mut next = numerics::xorshift::uniform(7);
    let mut rows = Vec::new();
    for i in 0..40 {
        let base = if i % 5 == 0 {
            model::scene::Scene::default()
        } else {
            nathan
        };
        let scene = base.with_launch(BattedBall {
            speed: 30.0 + 20.0 * next(),
            // Some straight up: they never land on their bearing's side.
            angle: if i % 13 == 6 {
                FRAC_PI_2 - 1e-4
            } else {
                0.1 + 0.6 * next()
            },
            spin: 200.0,
            direction: 0.0,
            sidespin: 0.0,
        });
        let row = RowLaunch {
            spray: (i % 7 != 3).then(|| 1.4 * next() - 0.7),
            side: Some(if i % 2 == 0 { Side::Right } else { Side::Left }),
            estimate_backspin: i % 3 != 0,
            estimate_sidespin: i % 4 != 0,
            measured_spin: (i % 5 == 1).then_some(260.0),
        };
        rows.push((scene, row));
    }
    for spray in [Spray::Landing, Spray::Launch] {
        let together = launch_many(rows.iter().map(|(s, r)| (s, r)), spray, &options);
        let mut solved = 0;
        for ((scene, row), together) in rows.iter().zip(&together) {
            let alone = launch(scene, row, spray, &options);
            assert_eq!(&alone, together);
            solved += usize::from(alone.flights > 1);
        }
        // The test bites: most rows solved over several flights.
        if spray == Spray::Landing {
            assert!(solved > 20, "{solved}");
            // Straight up never lands on its bearing's side: flown
            // toward the spray, and said so.
            let unsolved = |l: &&Launched| l.direction_from == DirectionFrom::SprayUnsolved;
            let unsolved: Vec<&Launched> = together.iter().filter(unsolved).collect();
            assert!(!unsolved.is_empty());
            for launched in unsolved {
                let bearing = launched.scene.batted_ball().direction;
                let (scene, row) = rows
                    .iter()
                    .find(|(s, _)| s.launch.speed == launched.scene.launch.speed)
                    .unwrap();
                assert_eq!(Some(bearing), row.spray, "{scene:?}");
            }
        }
    }
}

/// A solve's flights land where the reference's do to well inside the
/// budget Purpose::Solve states (1e-6 rad, a hundredth of the solve's
/// own tolerance), over 3-D flights with spray and sidespin.
#[test]
fn a_solves_flight_lands_well_inside_its_budget() {
    use crate::precision::Purpose;
    let nathan = nathan_scene();
    let mut next = numerics::xorshift::uniform(11);
    let landing = landing_direction;
    let mut worst: f64 = 0.0;
    // An aiming and a confirming flight's landing point, sideways (m).
    let mut aim_worst: f64 = 0.0;
    let mut confirm_worst: f64 = 0.0;
    for i in 0..300 {
        let base = if i % 3 == 0 {
            model::scene::Scene::default()
        } else {
            nathan
        };
        let scene = base.with_launch(BattedBall {
            speed: 30.0 + 22.0 * next(),
            angle: -0.1 + 0.9 * next(),
            spin: 150.0 + 200.0 * next(),
            direction: 1.4 * next() - 0.7,
            sidespin: 200.0 * next() - 100.0,
        });
        let flight = SceneFlight::new(&scene, &scene.batted_ball());
        let solve = flight.fly(&Purpose::Solve.flight_options());
        let reference = flight.fly(&Purpose::Reference.flight_options());
        worst = worst.max((landing(&solve) - landing(&reference)).abs());
        let aim = flight.fly(&Purpose::Aim.flight_options());
        let sideways = (landing(&aim) - landing(&reference)).abs() * reference.range.abs();
        aim_worst = aim_worst.max(sideways);
        let confirm = flight.fly(&precision(Stage::Confirm, &Purpose::Solve.into()));
        let sideways = (landing(&confirm) - landing(&reference)).abs() * reference.range.abs();
        confirm_worst = confirm_worst.max(sideways);
    }
    assert!(
        confirm_worst < Stage::Confirm.lateral(),
        "{confirm_worst:e} m"
    );
    assert!(
        confirm_worst > Stage::Confirm.lateral() / 1000.0,
        "{confirm_worst:e} m"
    );
    assert!(aim_worst < Stage::Aim.lateral(), "{aim_worst:e} m");
    assert!(aim_worst > Stage::Aim.lateral() / 1000.0, "{aim_worst:e} m");
    let budget = Purpose::Solve.range_budget() / 150.0;
    assert!(worst < budget / 10.0, "{worst:e} rad");
    // And no tighter than it needs: within ~1000× of the budget.
    assert!(worst > budget / 1000.0, "{worst:e} rad");
}
