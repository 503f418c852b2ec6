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
