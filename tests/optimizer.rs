//! The hand-written Nelder–Mead against argmin's, a coarse grid and other
//! starting points.

mod common;

use argmin::core::{CostFunction, Error, Executor, State};
use argmin::solver::neldermead::NelderMead;
use homerun::Scene;
use homerun::analysis::optimum::{Optimizer, OptimizerSettings, Status, optimize, optimize_from};
use homerun::analysis::study::{self, Grid};
use homerun::{Purpose, range};

/// −range over (E, ψ), as our optimiser sees it (Optimizer precision).
struct NegativeRange(Scene);

impl CostFunction for NegativeRange {
    type Param = Vec<f64>;
    type Output = f64;
    fn cost(&self, p: &Vec<f64>) -> Result<f64, Error> {
        Ok(-range(
            &common::with_swing(&self.0, p[0], p[1]),
            Purpose::Optimizer,
        ))
    }
}

#[test]
fn agrees_with_argmin() {
    for preset in ["fastball", "curveball"] {
        let scene = common::scene(preset);
        let ours = optimize(&scene, OptimizerSettings::default());
        let start = [0.025, 0.15];
        let simplex = vec![
            start.to_vec(),
            vec![start[0] + 0.0025, start[1]],
            vec![start[0], start[1] + 0.025],
        ];
        let solver = NelderMead::new(simplex).with_sd_tolerance(1e-9).unwrap();
        let result = Executor::new(NegativeRange(scene), solver)
            .configure(|state| state.max_iters(1000))
            .run()
            .unwrap();
        let best = result.state().get_best_param().unwrap().clone();
        let theirs = -result.state().get_best_cost();
        assert!(
            (ours.undercut - best[0]).abs() < 5e-5,
            "{preset}: E {} vs {}",
            ours.undercut,
            best[0]
        );
        assert!(
            (ours.swing_angle - best[1]).abs() < 0.01,
            "{preset}: ψ {} vs {}",
            ours.swing_angle,
            best[1]
        );
        // Ours is at least as high (within the paper's TolFun of 1e-4 m).
        assert!(
            ours.range > theirs - 1e-4,
            "{preset}: {} vs {theirs}",
            ours.range
        );
    }
}

#[test]
fn no_cell_of_a_grid_around_it_is_higher() {
    let scene = common::scene("fastball");
    let optimum = optimize(&scene, OptimizerSettings::default());
    let grid = Grid {
        undercut: (optimum.undercut - 0.002, optimum.undercut + 0.002),
        swing_angle: (optimum.swing_angle - 0.16, optimum.swing_angle + 0.16),
        columns: 21,
        rows: 17,
    };
    let surface = study::surface(&scene, grid, Purpose::Optimizer);
    let (i, j, best) = surface.best().unwrap();
    assert!(
        optimum.range >= best - 1e-6,
        "cell ({i}, {j}) reaches {best} > {}",
        optimum.range
    );
    // The grid is fine enough to see the ridge: its best cell is near.
    assert!(optimum.range - best < 0.05, "{} vs {best}", optimum.range);
}

#[test]
fn several_starting_points_agree() {
    let scene = common::scene("fastball");
    let reference = optimize(&scene, OptimizerSettings::default());
    for start in [
        (0.02, 0.0),
        (0.035, 0.5),
        (0.015, -0.3),
        (0.03, 0.3),
        (0.0, 0.0),
    ] {
        let other = optimize_from(&scene, start, OptimizerSettings::default());
        assert!(other.converged, "{start:?}");
        assert!(
            (other.range - reference.range).abs() < 1e-3,
            "{start:?}: {} vs {}",
            other.range,
            reference.range
        );
        assert!(
            (other.undercut - reference.undercut).abs() < 1e-4,
            "{start:?}"
        );
        assert!(
            (other.swing_angle - reference.swing_angle).abs() < 0.02,
            "{start:?}"
        );
    }
}

#[test]
fn stepping_and_stopping_give_the_same_optimum() {
    let scene = common::scene("knuckleball");
    let whole = optimize(&scene, OptimizerSettings::default());
    let mut stepped = Optimizer::new(
        &scene,
        (scene.bat.undercut, scene.bat.swing_angle),
        Purpose::Optimizer,
        OptimizerSettings::default(),
    );
    let mut steps = 0;
    let mut last = f64::NEG_INFINITY;
    while stepped.step() == Status::Running {
        steps += 1;
        // The best range never gets worse from one step to the next.
        assert!(stepped.best().range >= last);
        last = stepped.best().range;
    }
    assert!(steps > 10);
    assert_eq!(stepped.best().range, whole.range);
    // A stop on request returns None, with the best-so-far still readable.
    let mut stopped = Optimizer::new(
        &scene,
        (0.02, 0.0),
        Purpose::Optimizer,
        OptimizerSettings::default(),
    );
    let mut calls = 0;
    assert!(
        stopped
            .run(|| {
                calls += 1;
                calls > 3
            })
            .is_none()
    );
    assert!(stopped.best().range.is_finite());
}

#[test]
fn sweep_warm_starts_and_follows_figure8() {
    // Fig. 8: bat speed is the most important factor — nearly 5 m of range
    // per m/s at 30 m/s; the optimum undercut moves by only millimetres and
    // the swing angle falls as the bat speeds up.
    let scene = common::scene("fastball");
    let points = study::sweep(
        &scene,
        "bat.speed",
        &[29.0, 30.0, 31.0],
        OptimizerSettings::default(),
    )
    .unwrap();
    assert_eq!(points.len(), 3);
    let alone = optimize(&scene, OptimizerSettings::default());
    assert!((points[1].range - alone.range).abs() < 1e-3);
    let slope = (points[2].range - points[0].range) / 2.0;
    assert!((3.5..5.0).contains(&slope), "{slope} m per m/s");
    assert!(points.iter().all(|p| p.converged));
    assert!((points[2].undercut - points[0].undercut).abs() < 0.002);
    assert!(points[2].swing_angle < points[0].swing_angle);
    // A bad value anywhere is refused before anything is computed.
    let error = study::sweep(
        &scene,
        "bat.speed",
        &[30.0, -1.0],
        OptimizerSettings::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(error.contains("bat.speed = -1"), "{error}");
    assert!(
        study::sweep(
            &scene,
            "bat.undercut",
            &[0.02],
            OptimizerSettings::default()
        )
        .is_err()
    );
}

/// The fastball in 0.001 m/s² of gravity: its own swing hovers past the
/// flight's limit, but swings of small undercut land.
fn hovering() -> Scene {
    let mut scene = Scene::default();
    scene.environment.gravity = 0.001;
    scene
}

/// A big light ball with a large backspin in dense air and low gravity: no
/// swing of the explorer's window lands.
fn floating() -> Scene {
    let mut scene = Scene::default();
    scene.ball.radius = 0.074;
    scene.ball.mass = 0.45;
    scene.ball.gyration_radius = 0.055;
    scene.environment.air_density = 3.9;
    scene.environment.gravity = 0.0009;
    scene.bat.speed = 50.0;
    scene.pitch.spin = 520.0;
    scene
}

#[test]
fn a_start_that_does_not_land_is_seeded_from_a_coarse_scan() {
    let scene = hovering();
    assert!(!homerun::simulate(&scene, Purpose::Optimizer).flight.landed);
    let found = optimize(&scene, OptimizerSettings::default());
    assert!(found.landed, "{found:?}");
    let scan = found.scan.expect("a scan");
    assert!(scan.complete && scan.flown == 64, "{scan:?}");
    // At least as far as the best landing cell of the same 8×8 scan.
    let grid = Grid {
        columns: 8,
        rows: 8,
        ..Grid::explorer_window()
    };
    let coarse = study::surface(&scene, grid, Purpose::Optimizer);
    let (_, _, best_cell) = coarse.best().unwrap();
    assert!(found.range >= best_cell, "{} {best_cell}", found.range);
    let optimum = homerun::simulate(
        &scene.with_swing(found.undercut, found.swing_angle),
        Purpose::Optimizer,
    );
    assert!(optimum.flight.landed);
    assert_eq!(optimum.flight.range, found.range);

    // A start that lands scans nothing: the normal case costs what it did.
    let fastball = optimize(&Scene::default(), OptimizerSettings::default());
    assert_eq!(fastball.scan, None);
    assert_eq!(fastball.status, Status::Converged);
}

#[test]
fn with_no_swing_of_the_scan_landing_there_is_no_optimum() {
    let scene = floating();
    let none = optimize(&scene, OptimizerSettings::default());
    assert!(!none.landed && !none.converged, "{none:?}");
    assert_eq!(none.status, Status::NothingLands);
    assert_eq!(none.range, f64::NEG_INFINITY);
    let scan = none.scan.unwrap();
    assert!(scan.complete && scan.flown == 64, "{scan:?}");
    // The start's simplex (3) and the scan (64).
    assert_eq!(none.evaluations, 67);
    // The same scan, cut short by the work limit: it says so.
    let settings = OptimizerSettings {
        max_flight_steps: 200_000,
        ..OptimizerSettings::default()
    };
    let cut = optimize(&scene, settings);
    assert_eq!(cut.status, Status::OutOfWork);
    let scan = cut.scan.unwrap();
    assert!(!cut.landed && !scan.complete && scan.flown < 64, "{cut:?}");
}
