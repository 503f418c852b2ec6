//! The hand-written Nelder–Mead against argmin's, a coarse grid and other
//! starting points.

use crate::common;

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

/// A heavy-spun big ball in dense air (the `WORK` scene of
/// tests/command_line/flights.rs): the search runs into its work limit, and its best
/// swing lands at the optimiser's precision but not at the readout's.
fn work() -> Scene {
    let mut scene = Scene::default();
    for (key, value) in [
        ("ball.radius", 0.063),
        ("ball.mass", 0.35),
        ("ball.gyration_radius", 0.046),
        ("environment.air_density", 4.4),
        ("environment.gravity", 0.021),
        ("bat.speed", 49.0),
        ("pitch.spin", 1000.0),
    ] {
        scene.set(key, value).unwrap();
    }
    scene.validate().unwrap();
    scene
}

/// `homerun ARGS…` through the library, with an empty preset folder.
fn homerun(args: &[&str]) -> String {
    use clap::Parser as _;
    use homerun::cli::{self, Cli};
    let dir = tempfile::tempdir().unwrap();
    let mut argv = vec!["homerun", "--presets-dir", dir.path().to_str().unwrap()];
    argv.extend_from_slice(args);
    let cli = Cli::try_parse_from(argv).expect("arguments parse");
    cli::render(&cli, cli.command.as_ref().expect("a command"))
        .unwrap_or_else(|e| panic!("{args:?}: {e}"))
}

#[test]
fn an_optimum_set_by_the_flights_time_limit_says_so() {
    // In 0.001 m/s² of gravity the best swing is the one whose ball comes
    // down just before the 600 s limit: the limit sets its range.
    let scene = hovering();
    let found = optimize(&scene, OptimizerSettings::default());
    assert!(found.landed && found.at_time_limit, "{found:?}");
    assert!(found.point().at_time_limit);
    let flight = homerun::simulate(
        &scene.with_swing(found.undercut, found.swing_angle),
        Purpose::Optimizer,
    )
    .flight;
    assert!(flight.landed && flight.flight_time > 594.0, "{flight:?}");
    assert_eq!(flight.range, found.range);
    // The fastball's optimum lands in 5.6 s: no limit in sight.
    let fastball = optimize(&Scene::default(), OptimizerSettings::default());
    assert!(!fastball.at_time_limit && !fastball.point().at_time_limit);

    // A sweep labels each such row, in text, CSV and JSON.
    let sweep = [
        "sweep",
        "environment.gravity",
        "--from",
        "0.001",
        "--to",
        "9.81",
        "--steps",
        "2",
    ];
    let text = homerun(&sweep);
    let rows: Vec<&str> = text.lines().skip(1).collect();
    let label = "(time limit: the flight's limit, not the swing, sets this range)";
    assert!(rows[0].ends_with(label), "{text}");
    assert!(!rows[1].contains("time limit"), "{text}");
    let csv = homerun(&[&sweep[..], &["--csv"]].concat());
    let head: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let k = head
        .iter()
        .position(|h| *h == "at_time_limit")
        .expect("a column");
    let column: Vec<&str> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(k).unwrap())
        .collect();
    assert_eq!(column, ["true", "false"], "{csv}");
    let json: serde_json::Value =
        serde_json::from_str(&homerun(&[&sweep[..], &["--json"]].concat())).unwrap();
    let points = json["points"].as_array().unwrap();
    assert_eq!(points[0]["at_time_limit"], true);
    assert_eq!(points[1]["at_time_limit"], false);
    assert!(points[0]["range"].as_f64().unwrap() > 600.0, "{json}");
}

#[test]
fn an_optimum_that_lands_only_at_optimiser_precision_is_no_range() {
    // Reported as every flight is, at readout precision: no range; E and ψ
    // are still the optimiser's best, and its own range is named as such.
    let json: serde_json::Value = serde_json::from_str(&homerun(
        &[&["optimize", "--json"][..], &work_args()].concat(),
    ))
    .unwrap();
    assert_eq!(json["status"], "work_limit", "{json}");
    assert_eq!(json["landed"], false, "{json}");
    assert!(json["range"].is_null(), "{json}");
    let number = |key: &str| {
        json[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key}: {json}"))
    };
    let (undercut, swing_angle) = (number("undercut"), number("swing_angle"));
    // The same swing, flown at the two precisions: only the optimiser's lands.
    let swing = work().with_swing(undercut, swing_angle);
    let coarse = homerun::simulate(&swing, Purpose::Optimizer).flight;
    assert!(coarse.landed, "{coarse:?}");
    assert_eq!(number("optimizer_range"), coarse.range);
    assert!(!homerun::simulate(&swing, Purpose::Readout).flight.landed);
    let found = coarse;
    let why = json["why_not_landed"].as_str().unwrap();
    assert!(
        why.starts_with(
            "the optimiser's best does not land at readout precision (did not land within 600.0 s"
        ),
        "{why}"
    );
    assert!(
        why.ends_with(&format!(
            "at the optimiser's own precision it lands at {:.2} m",
            found.range
        )),
        "{why}"
    );
    let text = homerun(&[&["optimize"][..], &work_args()].concat());
    let range = text.lines().find(|l| l.starts_with("range")).unwrap();
    assert_eq!(range, format!("range    {why}"), "{text}");
    // A landing optimum has no such field.
    let fastball: serde_json::Value =
        serde_json::from_str(&homerun(&["optimize", "--json"])).unwrap();
    assert!(fastball.get("optimizer_range").is_none(), "{fastball}");
}

/// [`work`] as `--set` arguments.
fn work_args() -> Vec<&'static str> {
    [
        "ball.radius=0.063",
        "ball.mass=0.35",
        "ball.gyration_radius=0.046",
        "environment.air_density=4.4",
        "environment.gravity=0.021",
        "bat.speed=49",
        "pitch.spin=1000",
    ]
    .into_iter()
    .flat_map(|set| ["--set", set])
    .collect()
}
