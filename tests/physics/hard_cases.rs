//! Inputs where a careless implementation breaks: each must give a finite,
//! physically sensible result and, where the physics is continuous, a
//! continuous one. No test here is timed; every flight's work is bounded.

use homerun::analysis::optimum::{OptimizerSettings, optimize_from};
use homerun::analysis::paper::table_two;
use homerun::model::flight::{self, Flight, FlightOptions, FlightSummary, Launch};
use homerun::model::impact::Impact;
use homerun::model::{self, aero::DragModel};
use homerun::numerics::ode::Tolerance;
use homerun::{Purpose, Scene};
use nalgebra::Vector2;

use crate::tui_support;

fn with_swing(scene: &Scene, undercut: f64, swing_angle: f64) -> Scene {
    scene.with_swing(undercut, swing_angle)
}

/// Finite everywhere, landed, and the work bounded.
fn assert_sane(summary: &FlightSummary, what: &str) {
    let numbers = [
        summary.range,
        summary.flight_time,
        summary.apex,
        summary.apex_distance,
        summary.landing_speed,
        summary.landing_angle,
    ];
    assert!(numbers.iter().all(|x| x.is_finite()), "{what}: {summary:?}");
    assert!(summary.landed, "{what}: never landed: {summary:?}");
    assert!(summary.flight_time >= 0.0, "{what}: {summary:?}");
    assert!(summary.landing_speed >= 0.0, "{what}: {summary:?}");
    assert!(
        summary.stats.accepted + summary.stats.rejected < 20_000,
        "{what}: {:?}",
        summary.stats
    );
    // No ball hit at ≤ 60 m/s with ordinary spin carries 300 m, either way
    // (a 50 m/s headwind carries one back ~190 m).
    assert!(
        summary.range > -300.0 && summary.range < 300.0,
        "{what}: {summary:?}"
    );
}

fn fly(scene: &Scene, purpose: impl Into<FlightOptions>) -> homerun::Swing {
    let swing = model::simulate(scene, purpose);
    assert!(
        swing.impact.launch_speed().is_finite()
            && swing.impact.launch_spin().is_finite()
            && swing.impact.launch_angle().is_finite(),
        "{:?}",
        swing.impact
    );
    swing
}

fn readout_range(scene: &Scene) -> f64 {
    let swing = fly(scene, Purpose::Readout);
    assert_sane(&swing.flight, "readout");
    swing.flight.range
}

/// A launch of the Table II fastball's flight, with its velocity replaced.
fn launch_with(velocity: Vector2<f64>, height: f64) -> (Flight, Launch) {
    let scene = Scene::default();
    let (flight, mut launch) = model::launch(&scene, &Impact::new(&scene));
    launch.velocity = velocity;
    launch.position.y = height;
    (flight, launch)
}

fn fly_launch(flight: &Flight, launch: &Launch) -> FlightSummary {
    let summary = flight::fly(flight, launch, &Purpose::Readout.flight_options());
    assert_sane(&summary, "launch");
    summary
}

#[test]
fn grazing_contact_is_finite_and_continuous() {
    let scene = Scene::default();
    let limit = scene.reach();
    for sign in [1.0, -1.0] {
        let ranges: Vec<f64> = [1e-4, 1e-7, 1e-10, 1e-13]
            .iter()
            .map(|gap| readout_range(&with_swing(&scene, sign * limit * (1.0 - gap), 0.2)))
            .collect();
        // A grazing bat barely deflects the pitch: the ball goes on toward
        // the catcher and lands behind the plate.
        assert!(ranges.iter().all(|&r| r < 0.0), "{ranges:?}");
        // The impulse vanishes like √gap, so the range converges like √gap:
        // each thousandfold smaller gap, a ~30× smaller change.
        let changes: Vec<f64> = ranges.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        for pair in changes.windows(2) {
            assert!(pair[1] <= pair[0] / 10.0, "{ranges:?}");
        }
        assert!(changes[2] < 1e-2, "{ranges:?}");
    }
}

#[test]
fn head_on_hit_is_continuous_in_undercut() {
    let scene = Scene::default();
    let at = |e: f64| readout_range(&with_swing(&scene, e, 0.1594));
    // Head on, a slightly rising swing meets a descending pitch: the ball
    // leaves below the horizontal and lands a few metres out.
    let zero = at(0.0);
    assert!(zero > 0.0 && zero < 30.0, "{zero}");
    let swing = fly(&with_swing(&scene, 0.0, 0.1594), Purpose::Readout);
    assert!(swing.impact.launch_angle() < 0.0);
    for e in [1e-9, -1e-9] {
        assert!((at(e) - zero).abs() < 1e-5, "{e}: {} vs {zero}", at(e));
    }
}

#[test]
fn an_overcut_gives_topspin_and_a_shorter_flight() {
    let scene = Scene::default();
    let over = fly(&with_swing(&scene, -0.02, 0.1594), Purpose::Readout);
    let under = fly(&with_swing(&scene, 0.02, 0.1594), Purpose::Readout);
    assert_sane(&over.flight, "overcut");
    assert!(
        over.impact.launch_spin() < 0.0,
        "{}",
        over.impact.launch_spin()
    );
    assert!(under.impact.launch_spin() > 0.0);
    assert!(over.impact.launch_angle() < 0.0);
    assert!(over.flight.range < under.flight.range);
}

#[test]
fn zero_batted_spin_has_no_lift_and_is_continuous() {
    // The undercut that zeroes the batted spin, by bisection (the spin rises
    // with E through zero between an overcut and the Table II undercut).
    let scene = Scene::default();
    let spin = |e: f64| Impact::new(&with_swing(&scene, e, 0.1594)).launch_spin();
    let (mut lo, mut hi) = (-0.03, 0.0265);
    assert!(spin(lo) < 0.0 && spin(hi) > 0.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if spin(mid) < 0.0 { lo = mid } else { hi = mid }
    }
    let e0 = 0.5 * (lo + hi);
    assert!(spin(e0).abs() < 1e-6, "{}", spin(e0));
    let at = |e: f64| readout_range(&with_swing(&scene, e, 0.1594));
    let r0 = at(e0);
    let slope = (at(e0 + 1e-6) - at(e0 - 1e-6)) / 2e-6;
    for de in [1e-9, -1e-9] {
        let expected = r0 + slope * de;
        assert!((at(e0 + de) - expected).abs() < 1e-6);
    }

    // And exactly zero spin, set on the flight directly: the lift is zero,
    // not 0/0, and the limit of small spins of either sign.
    let (_, launch) = launch_with(Vector2::new(40.0, 15.0), 1.0);
    let range_with_spin = |spin: f64| fly_launch(&Flight::new(&scene, spin), &launch).range;
    let none = range_with_spin(0.0);
    let lift = Flight::new(&scene, 0.0).acceleration(Vector2::new(40.0, 15.0));
    assert!(lift.x.is_finite() && lift.y.is_finite());
    for spin in [1e-9, -1e-9] {
        assert!((range_with_spin(spin) - none).abs() < 1e-6);
    }
    assert!(range_with_spin(-100.0) < none && none < range_with_spin(100.0));
}

#[test]
fn enormous_spin_is_finite_and_bounded() {
    let scene = Scene::default();
    let (_, launch) = launch_with(Vector2::new(40.0, 15.0), 1.0);
    // S = r_b|ω|/|V| ≈ 1.7: lift far above gravity; the ball climbs, loops
    // and still lands, far out.
    let high = fly_launch(&Flight::new(&scene, 2000.0), &launch);
    assert!(high.range > fly_launch(&Flight::new(&scene, 200.0), &launch).range);
    // S ≈ 85: the lift turns the ball in tight circles that drift under
    // gravity (as a charge drifts in crossed fields) and it never comes
    // down; the flight must stop at its step bound with finite numbers,
    // saying it has not landed.
    for spin in [1e5, -1e5] {
        let flight = Flight::new(&scene, spin);
        let summary = flight::fly(&flight, &launch, &Purpose::Readout.flight_options());
        assert!(summary.range.is_finite() && summary.flight_time.is_finite());
        assert!(summary.apex.is_finite() && summary.landing_speed.is_finite());
        assert!(summary.stats.accepted + summary.stats.rejected <= 100_000);
        if summary.landed {
            assert_sane(&summary, "enormous spin");
        }
    }
    // Through the scene, at the largest pitch spin the inputs accept.
    let mut s = Scene::default();
    s.pitch.spin = -1000.0;
    s.validate().unwrap();
    readout_range(&s);
}

#[test]
fn launch_exactly_at_each_kink_is_continuous_in_speed() {
    let scene = Scene::default();
    let flight = Flight::new(&scene, 150.0);
    for &kink in DragModel::Sawicki2003.kinks() {
        let speed = kink / flight.reynolds_per_speed;
        let direction = Vector2::new(0.8, 0.6);
        let at = |v: f64| fly_launch(&flight, &launch_with(direction * v, 1.0).1).range;
        let exact = at(speed);
        assert!(exact > 10.0, "{kink}: {exact}");
        for factor in [1.0 - 1e-12, 1.0 + 1e-12] {
            assert!((at(speed * factor) - exact).abs() < 1e-6, "{kink}");
        }
        // And a launch that starts on the kink moving into either piece
        // (horizontal: drag slows it; straight down: gravity speeds it).
        for direction in [Vector2::new(1.0, 0.0), Vector2::new(0.0, -1.0)] {
            fly_launch(&flight, &launch_with(direction * speed, 20.0).1);
        }
    }
}

/// How often the drag piece changes along a flight, and the flight.
fn kink_crossings(
    flight: &Flight,
    launch: &Launch,
    options: &flight::FlightOptions,
) -> (usize, FlightSummary) {
    let mut crossings = 0;
    let mut last_piece = None;
    let summary = flight::fly_observed(flight, launch, options, |step| {
        for t in [step.t0, step.t1] {
            let s = step.at(t);
            let piece = flight.drag.piece(flight.reynolds(Vector2::new(s[2], s[3])));
            if last_piece.is_some_and(|p| p != piece) {
                crossings += 1;
            }
            last_piece = Some(piece);
        }
    });
    (crossings, summary)
}

#[test]
fn flights_through_the_kinks_match_flights_that_ignore_them() {
    // A strong headwind: the air speed falls through all three kinks. A
    // huge spin: the ball loops and its air speed crosses them again.
    let mut headwind = Scene::default();
    headwind.environment.wind = -20.0;
    let (flight, launch) = model::launch(&headwind, &Impact::new(&headwind));
    let (_, looping_launch) = launch_with(Vector2::new(40.0, 15.0), 1.0);
    let looping = Flight::new(&headwind, 2.0e4);
    let options = Purpose::Reference.flight_options();
    let mut ignoring = options;
    ignoring.stop_at_kinks = false;
    for (flight, launch, at_least) in [(flight, launch, 3), (looping, looping_launch, 5)] {
        let (crossings, on) = kink_crossings(&flight, &launch, &options);
        assert!(crossings >= at_least, "{crossings}");
        let off = flight::fly(&flight, &launch, &ignoring);
        assert!(on.range.is_finite() && off.range.is_finite());
        if on.landed {
            assert_sane(&on, "through the kinks");
            assert!(
                (on.range - off.range).abs() < 1e-6,
                "{} vs {}",
                on.range,
                off.range
            );
        }
    }
    // Continuous in the wind.
    let at = |wind: f64| {
        let mut s = headwind;
        s.environment.wind = wind;
        readout_range(&s)
    };
    let slope = (at(-20.0 + 1e-4) - at(-20.0 - 1e-4)) / 2e-4;
    assert!(slope > 0.0);
    assert!((at(-20.0 + 1e-8) - at(-20.0) - slope * 1e-8).abs() < 1e-6);
}

#[test]
fn a_ball_landing_almost_tangentially() {
    let scene = Scene::default();
    let flight = Flight::new(&scene, 0.0);
    // Launched level from a millimetre up: it meets the ground at a grazing angle.
    let ranges: Vec<f64> = [1e-3, 1e-6, 1e-9]
        .iter()
        .map(|&h| {
            let summary = fly_launch(&flight, &launch_with(Vector2::new(40.0, 0.0), h).1);
            assert!(summary.landing_angle >= 0.0 && summary.landing_angle < 0.02);
            summary.range
        })
        .collect();
    assert!(ranges.iter().all(|r| (0.0..1.0).contains(r)), "{ranges:?}");
    assert!(ranges[1] > ranges[2] && ranges[0] > ranges[1], "{ranges:?}");
}

#[test]
fn straight_down_and_backwards() {
    let scene = Scene::default();
    let flight = Flight::new(&scene, 0.0);
    let down = fly_launch(&flight, &launch_with(Vector2::new(0.0, -40.0), 1.0).1);
    assert!(down.range.abs() < 1e-9, "{down:?}");
    assert!((down.flight_time - 1.0 / 40.0).abs() < 1e-3);
    assert!((down.landing_angle - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
    let back = fly_launch(&flight, &launch_with(Vector2::new(-40.0, 15.0), 1.0).1);
    assert!(back.range < -50.0, "{back:?}");
    // From the ground up: the flight starts at y = 0.
    let from_ground = fly_launch(&flight, &launch_with(Vector2::new(30.0, 10.0), 0.0).1);
    assert!(from_ground.range > 20.0, "{from_ground:?}");
    // A swing that drives the ball into the ground.
    let s = with_swing(&scene, -0.06, -1.5);
    s.validate().unwrap();
    let swing = fly(&s, Purpose::Readout);
    assert_sane(&swing.flight, "into the ground");
}

#[test]
fn a_headwind_carries_the_ball_back_behind_the_plate() {
    // The Table II hit into the strongest headwind the inputs accept.
    let mut scene = Scene::default();
    scene.environment.wind = -50.0;
    scene.validate().unwrap();
    let back = readout_range(&scene);
    assert!(back < -50.0, "{back}");
    // Continuous through the wind at which it lands on the plate.
    let at = |wind: f64| {
        let mut s = scene;
        s.environment.wind = wind;
        readout_range(&s)
    };
    let ranges: Vec<f64> = (0..=40).map(|k| at(-50.0 + k as f64 * 0.5)).collect();
    assert!(
        ranges.windows(2).all(|w| w[1] > w[0] && w[1] - w[0] < 10.0),
        "{ranges:?}"
    );
    assert!(ranges[40] > 0.0);
}

#[test]
fn extreme_tolerances_end_with_bounded_work() {
    let scene = Scene::default();
    let grid = homerun::analysis::study::Grid::figure7(6, 6);
    for (exponent, max_steps) in [(2, 60), (13, 4000)] {
        let purpose = FlightOptions {
            tolerance: Tolerance::uniform(10f64.powi(-exponent)),
            stop_at_kinks: true,
        };
        for i in 0..grid.columns {
            for j in 0..grid.rows {
                let s = with_swing(&scene, grid.undercut_at(i), grid.swing_angle_at(j));
                let summary = fly(&s, purpose).flight;
                assert_sane(&summary, "tolerance");
                let steps = summary.stats.accepted + summary.stats.rejected;
                assert!(steps < max_steps, "1e-{exponent}: {:?}", summary.stats);
                assert!(
                    summary.stats.rejected <= summary.stats.accepted,
                    "{:?}",
                    summary.stats
                );
            }
        }
    }
}

/// The number of sign changes of the finite differences of `values`.
fn sign_changes(values: &[f64]) -> usize {
    let differences: Vec<f64> = values.windows(2).map(|w| w[1] - w[0]).collect();
    differences
        .windows(2)
        .filter(|d| (d[0] > 0.0) != (d[1] > 0.0))
        .count()
}

#[test]
fn range_has_no_sawtooth_near_the_optimum() {
    // Ours (= scipy's) optima.
    let optima = [
        (0.027269, 0.17439),
        (0.025324, 0.15221),
        (0.022495, 0.11181),
    ];
    for ((name, scene), (e, psi)) in table_two().into_iter().zip(optima) {
        let range =
            |e: f64, psi: f64| model::range(&with_swing(&scene, e, psi), Purpose::Optimizer);
        let along_e: Vec<f64> = (-40..=40)
            .map(|k| range(e + k as f64 * 5e-5, psi))
            .collect();
        let along_psi: Vec<f64> = (-40..=40)
            .map(|k| range(e, psi + k as f64 * 1e-3))
            .collect();
        assert_eq!(sign_changes(&along_e), 1, "{name} along E: {along_e:?}");
        assert_eq!(sign_changes(&along_psi), 1, "{name} along ψ: {along_psi:?}");
    }
}

#[test]
fn the_optimiser_agrees_from_far_starts() {
    let starts = [(0.0, -0.5), (0.06, 1.0), (-0.03, 0.6), (0.05, -0.4)];
    for (name, scene) in table_two() {
        let home = optimize_from(
            &scene,
            (scene.bat.undercut, scene.bat.swing_angle),
            OptimizerSettings::default(),
        );
        for start in starts {
            let found = optimize_from(&scene, start, OptimizerSettings::default());
            assert!(found.converged, "{name} from {start:?}");
            assert!(
                (found.range - home.range).abs() < 3e-4,
                "{name} from {start:?}: {found:?} vs {home:?}"
            );
            assert!(
                (found.undercut - home.undercut).abs() < 1e-4,
                "{name} {start:?}"
            );
            assert!(
                (found.swing_angle - home.swing_angle).abs() < 0.01,
                "{name} {start:?}"
            );
        }
    }
}

#[test]
fn random_valid_scenes_give_finite_numbers() {
    // Every input drawn anywhere in its accepted range (half of them left at
    // the fastball's values), deterministic (xorshift). Balloons, gales and
    // feather-light bats included: the numbers must stay finite and the
    // work bounded, landed or not.
    use homerun::model::keys::KEYS;
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut uniform = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut checked = 0;
    while checked < 300 {
        let mut scene = Scene::default();
        for key in KEYS.iter() {
            if uniform() < 0.5 {
                continue;
            }
            let (lo, hi) = (key.bounds.min.max(-1e3), key.bounds.max.min(1e3));
            let _ = scene.set(key.name, lo + (hi - lo) * uniform());
        }
        if scene.validate().is_err() {
            continue;
        }
        checked += 1;
        let swing = model::simulate(&scene, Purpose::Surface);
        let f = swing.flight;
        let numbers = [
            f.range,
            f.flight_time,
            f.apex,
            f.landing_speed,
            f.landing_angle,
        ];
        assert!(numbers.iter().all(|x| x.is_finite()), "{scene:?}: {f:?}");
        assert!(f.stats.accepted + f.stats.rejected <= 100_000);
    }
}

#[test]
fn the_explorers_optimum_line_says_when_the_time_limit_sets_the_range() {
    use homerun::analysis::optimum::{Point, Status};
    use homerun::tui::worker::Report;
    for (w, h) in [(80, 24), (200, 60)] {
        let mut app = tui_support::app(w, h, None);
        tui_support::settle(&mut app);
        let optimum = |at_time_limit| Report::Optimum {
            generation: app.generation,
            best: Point {
                undercut: 0.01028,
                swing_angle: 0.1161,
                range: 668.15,
                at_time_limit,
            },
            evaluations: 834,
            done: true,
            status: Status::Converged,
        };
        let (plain, limited) = (optimum(false), optimum(true));
        app.apply(plain);
        let screen = tui_support::screen(&app);
        assert!(!screen.contains("(time limit)"), "{screen}");
        app.apply(limited);
        let screen = tui_support::screen(&app);
        // On one line where it fits, else on a line of its own, never cut.
        let together = screen.contains("668.15 m (time limit)");
        let apart = screen.lines().any(|l| l.contains("668.15 m  "))
            && screen.lines().any(|l| l.contains("│         (time limit)"));
        assert!(together != apart, "{screen}");
        assert_eq!(together, w == 200, "{screen}");
        // The fence still shows.
        assert!(screen.contains("fence    121.9 m"), "{screen}");
    }
}
