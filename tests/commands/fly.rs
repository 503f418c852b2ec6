//! The batted-ball scene and `homerun fly`: a batted ball at a swing's
//! launch flies as the swing does, the vacuum limit is the closed form, and
//! the launch keys are bounded. (`fly --batch`: fly_batch.rs.)

use crate::common;
use std::f64::consts::TAU;
use std::path::Path;

use assert_cmd::Command;
use homerun::analysis::precision::Purpose;
use homerun::model::aero::{DragModel, LiftModel};
use homerun::model::launch::{self, BattedBall, SceneKind};
use homerun::preset::{Preset, Source};
use homerun::{Scene, model};
use serde_json::Value;

pub(crate) fn homerun(presets: &Path) -> Command {
    let mut command = common::assert_command();
    command.arg("--presets-dir").arg(presets);
    command
}

pub(crate) fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The JSON a command prints, which must succeed.
fn json_of(presets: &Path, args: &[&str]) -> Value {
    let out = homerun(presets).args(args).output().unwrap();
    assert!(out.status.success(), "{args:?}: {out:?}");
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn a_batted_ball_at_the_fastballs_launch_flies_as_the_fastball() {
    let swing_scene = Scene::default();
    let swing = model::simulate(&swing_scene, Purpose::Readout);
    let mut batted_scene = swing_scene.with_launch(BattedBall::of(&swing.impact));
    assert_eq!(batted_scene.kind, SceneKind::BattedBall);
    // A batted ball flies Nathan's aero unless the models are chosen: the
    // paper's, to compare with the swing.
    assert_eq!(
        (batted_scene.drag, batted_scene.lift),
        (DragModel::Nathan, LiftModel::Nathan)
    );
    batted_scene.choose_drag(DragModel::Sawicki2003);
    batted_scene.choose_lift(LiftModel::Sawicki2003);
    let batted = launch::fly_scene(&batted_scene, Purpose::Readout);
    assert!(batted.impact.is_none());
    // Table II's fastball: 134.70 m.
    assert!((swing.flight.range - 134.699).abs() < 1e-3);
    for (a, b) in [
        (batted.flight.range, swing.flight.range),
        (batted.flight.flight_time, swing.flight.flight_time),
        (batted.flight.apex, swing.flight.apex),
        (batted.flight.landing_speed, swing.flight.landing_speed),
    ] {
        assert!(relative(a, b) < 1e-12, "{a} vs {b}");
    }
    // And a swing scene through fly_scene is simulate itself.
    let flown = launch::fly_scene(&swing_scene, Purpose::Readout);
    assert_eq!(flown.flight, swing.flight);
    assert_eq!(flown.launch, BattedBall::of(&swing.impact));
}

#[test]
fn without_air_and_lift_the_flight_is_the_vacuum_parabola() {
    let mut scene = Scene::default();
    let mut batch = model::keys::InputBatch::new();
    for (key, value) in [
        ("model.lift", "none"),
        ("environment.air_density", "0"),
        ("launch.speed", "40"),
        ("launch.angle", "0.6"),
        ("launch.spin", "300"),
    ] {
        batch.set_text(&mut scene, key, value).unwrap();
    }
    scene.validate().unwrap();
    let (v, angle, g, h) = (40.0_f64, 0.6_f64, 9.81, 1.0);
    let (vx, vy) = (v * angle.cos(), v * angle.sin());
    let time = (vy + (vy * vy + 2.0 * g * h).sqrt()) / g;
    let flight = launch::fly_scene(&scene, Purpose::Readout).flight;
    assert!(flight.landed);
    assert!(relative(flight.flight_time, time) < 1e-9, "{flight:?}");
    assert!(relative(flight.range, vx * time) < 1e-9, "{flight:?}");
    assert!(
        relative(flight.apex, h + vy * vy / (2.0 * g)) < 1e-9,
        "{flight:?}"
    );
}

#[test]
fn missing_launch_keys_come_from_the_swing_in_any_order() {
    let mut a = Scene::default();
    a.set("launch.angle", 0.5).unwrap();
    a.set("bat.speed", 32.0).unwrap();
    let mut b = Scene::default();
    b.set("bat.speed", 32.0).unwrap();
    b.set("launch.angle", 0.5).unwrap();
    assert_eq!(a, b);
    let swing = model::simulate(
        &Scene::default().with_swing(0.0265, 0.1594),
        Purpose::Readout,
    );
    let mut c = Scene::default();
    c.set("launch.angle", 0.5).unwrap();
    let launch = c.batted_ball();
    assert_eq!(launch.speed, swing.impact.launch_speed());
    assert_eq!(launch.spin, swing.impact.launch_spin());
    assert_eq!(launch.angle, 0.5);
}

/// The launch line says which values came from the swing, so that a spin
/// no one typed is not taken for one given (an analyst's 105 mph at 28°
/// flies the fastball impact's 1832 rpm, not an estimate); `--spin nathan`
/// flies the estimate a batch row without a spin takes, to the bit.
#[test]
fn the_launch_line_names_what_came_from_the_swing() {
    let first_line = |args: &[&str]| {
        let (status, out, err) = common::run_homerun(args, None);
        assert_eq!(status, Some(0), "{err}");
        out.lines().next().unwrap().to_owned()
    };
    let speed_angle = [
        "fly",
        "--set",
        "launch.speed=105mph",
        "--set",
        "launch.angle=28deg",
    ];
    let line = first_line(&speed_angle);
    assert!(
        line.ends_with("(28.0°); spin from the swing's impact (--spin nathan estimates the spin)"),
        "{line}"
    );
    // The estimate, as a batch row of the same launch and side flies it.
    let mut one = speed_angle.to_vec();
    one.extend([
        "--set",
        "launch.direction=-20deg",
        "--spin",
        "nathan",
        "--json",
    ]);
    let (status, out, err) = common::run_homerun(&one, None);
    assert_eq!(status, Some(0), "{err}");
    let one: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(one["spin_estimated"], true);
    let row = "launch_speed,launch_angle,exit_direction,stand\n105,28,-20,R\n";
    let (status, out, err) = common::run_homerun(&["fly", "--batch", "-", "--json"], Some(row));
    assert_eq!(status, Some(0), "{err}");
    let row: Value = serde_json::from_str(out.trim()).unwrap();
    for key in ["spin", "sidespin", "direction"] {
        assert_eq!(one["launch"][key], row["launch"][key], "{key}");
    }
    assert_eq!(one["flight"]["range"], row["flight"]["range"]);
    let mut text = speed_angle.to_vec();
    text.extend(["--spin", "nathan", "--set", "bat.hand=left"]);
    let line = first_line(&text);
    assert!(
        line.ends_with("; spin estimated (Nathan's relation, a left-handed batter)"),
        "{line}"
    );
    let (status, _, err) = common::run_homerun(
        &["fly", "--spin", "nathan", "--set", "launch.spin=100"],
        None,
    );
    assert_eq!(status, Some(2));
    assert!(err.contains("--spin nathan estimates the spin that --set launch.spin gives"));
    let line = first_line(&["fly", "--set", "launch.angle=0.5"]);
    assert!(
        line.ends_with(
            "; speed and spin from the swing's impact (--spin nathan estimates the spin)"
        ),
        "{line}"
    );
    // Asked for, the swing's spin needs no pointer to the estimate.
    let line = first_line(&["fly", "--set", "launch.angle=0.5", "--spin", "swing"]);
    assert!(
        line.ends_with("; speed and spin from the swing's impact"),
        "{line}"
    );
    let line = first_line(&["fly", "--preset", "fly-ball"]);
    assert!(!line.contains("from the swing"), "{line}");
    let line = first_line(&["fly"]);
    assert!(line.ends_with(" (from the swing's impact)"), "{line}");
}

#[test]
fn a_batted_ball_preset_round_trips_through_its_toml() {
    let preset = homerun::preset::load("fly-ball", None).unwrap();
    assert_eq!(preset.scene.kind, SceneKind::BattedBall);
    let launch = preset.scene.batted_ball();
    // 103 mph, 28°, 2500 rpm.
    assert!((launch.speed - 103.0 * 0.44704).abs() < 1e-12);
    assert!((launch.angle - 28f64.to_radians()).abs() < 1e-14);
    assert!((launch.spin - 2500.0 * TAU / 60.0).abs() < 1e-11);
    let again = Preset::parse(&preset.to_toml(), "again", "again.toml", Source::Bundled).unwrap();
    assert_eq!(again.scene, preset.scene);
    // A swing writes no [launch] and stays a swing.
    let fastball = homerun::preset::load("fastball", None).unwrap();
    let text = fastball.to_toml();
    assert!(!text.contains("[launch]"), "{text}");
    let again = Preset::parse(&text, "f", "f.toml", Source::Bundled).unwrap();
    assert_eq!(again.scene.kind, SceneKind::Swing);
    // One launch key given: only it is written, the rest still follow the swing.
    let mut one = fastball.clone();
    one.scene.set("launch.angle", 0.5).unwrap();
    let again = Preset::parse(&one.to_toml(), "o", "o.toml", Source::Bundled).unwrap();
    assert_eq!(again.scene, one.scene);
    assert_eq!(again.scene.launch.speed, None);
}

#[test]
fn fly_json_has_every_field_finite() {
    let dir = tempfile::tempdir().unwrap();
    let out = homerun(dir.path())
        .args(["fly", "--preset", "fly-ball", "--json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    for path in [
        "launch.speed",
        "launch.angle",
        "launch.spin",
        "flight.range",
        "flight.flight_time",
        "flight.apex",
        "flight.landing_speed",
        "flight.landing_angle",
        "environment.air_density",
        "environment.kinematic_viscosity",
    ] {
        let (head, tail) = path.split_once('.').unwrap();
        let x = v[head][tail]
            .as_f64()
            .unwrap_or_else(|| panic!("{path}: {v}"));
        assert!(x.is_finite(), "{path}: {v}");
    }
    assert_eq!(v["flight"]["landed"], true);
    assert_eq!(v["scene"], "batted_ball");
    assert_eq!(v["launch"]["speed"], 46.04512);
    assert_eq!(v["environment"]["air_density"], 1.23);
    // The weather's ρ and ν reach the JSON, here and in hit's.
    for command in ["fly", "hit"] {
        let out = homerun(dir.path())
            .args([command, "--json", "--set", "environment.elevation=1580"])
            .output()
            .unwrap();
        let v: Value = serde_json::from_slice(&out.stdout).unwrap();
        let rho = v["environment"]["air_density"].as_f64().unwrap();
        assert!(rho > 1.0 && rho < 1.05, "{command}: {v}");
        assert_eq!(v["environment"]["atmosphere"]["elevation"], 1580.0);
    }
}

#[test]
fn fly_on_the_fastball_at_another_angle_keeps_its_launch_speed_and_spin() {
    let dir = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| json_of(dir.path(), args);
    let hit = run(&["hit", "--json"]);
    let fly = run(&["fly", "--set", "launch.angle=0.5", "--json"]);
    assert_eq!(fly["launch"]["speed"], hit["impact"]["launch_speed"]);
    assert_eq!(fly["launch"]["spin"], hit["impact"]["launch_spin"]);
    assert_eq!(fly["launch"]["angle"], 0.5);
    // Without launch keys, fly flies the swing: hit's flight.
    let own = run(&["fly", "--json"]);
    assert_eq!(own["flight"]["range"], hit["flight"]["range"]);
    assert_eq!(own["scene"], "swing");
}

#[test]
fn launch_keys_out_of_range_are_refused_with_their_range() {
    let dir = tempfile::tempdir().unwrap();
    for (set, message) in [
        (
            "launch.speed=0",
            "launch.speed = 0: must be a finite number in (0, 100] m/s",
        ),
        (
            "launch.speed=-5",
            "launch.speed = -5: must be a finite number in (0, 100] m/s",
        ),
        // Straight up and down are balls Statcast records (issue 35);
        // past them the ball would leave backwards.
        (
            "launch.angle=1.58",
            "must be a finite number in [-π/2, π/2] rad",
        ),
        (
            "launch.angle=-1.58",
            "must be a finite number in [-π/2, π/2] rad",
        ),
        (
            "launch.spin=2000",
            "launch.spin = 2000: must be a finite number in [-1000, 1000] rad/s",
        ),
    ] {
        let out = homerun(dir.path())
            .args(["fly", "--set", set])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{set}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains(message), "{set}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // A batted ball has no swing: hit refuses it, naming fly.
    let out = homerun(dir.path())
        .args(["hit", "--preset", "fly-ball"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("homerun fly"), "{err}");
}

#[test]
fn fly_at_hits_launch_prints_hits_flight() {
    // The commands, not only the library: `fly` given the launch `hit`
    // reports for the fastball flies `hit`'s flight.
    let dir = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| json_of(dir.path(), args);
    let hit = run(&["hit", "--json"]);
    let launch = |k: &str| format!("{:?}", hit["impact"][k].as_f64().unwrap());
    let sets = [
        format!("launch.speed={}", launch("launch_speed")),
        format!("launch.angle={}", launch("launch_angle")),
        format!("launch.spin={}", launch("launch_spin")),
    ];
    // The paper's models, chosen: a batted ball would fly Nathan's.
    let mut args = vec![
        "fly",
        "--json",
        "--set",
        "model.drag=sawicki2003",
        "--set",
        "model.lift=sawicki2003",
    ];
    for set in &sets {
        args.extend(["--set", set.as_str()]);
    }
    let fly = run(&args);
    assert_eq!(fly["scene"], "batted_ball", "{fly}");
    for key in [
        "range",
        "flight_time",
        "apex",
        "landing_speed",
        "landing_angle",
    ] {
        let (a, b) = (
            fly["flight"][key].as_f64().unwrap(),
            hit["flight"][key].as_f64().unwrap(),
        );
        assert!(relative(a, b) < 1e-12, "{key}: fly {a} vs hit {b}");
    }
    // Table II's fastball: 134.70 m.
    assert!((fly["flight"]["range"].as_f64().unwrap() - 134.699).abs() < 1e-3);
}

#[test]
fn a_batted_balls_figure_names_its_launch_not_a_pitch_and_bat() {
    let dir = tempfile::tempdir().unwrap();
    let second_line = |args: &[&str]| {
        let out = homerun(dir.path()).args(args).output().unwrap();
        assert!(out.status.success(), "{args:?}");
        String::from_utf8(out.stdout)
            .unwrap()
            .lines()
            .nth(1)
            .unwrap()
            .to_owned()
    };
    // 103 mph, 28°, 2500 rpm: the fly-ball preset's launch in both units.
    let si = second_line(&["figure", "3", "--preset", "fly-ball"]);
    assert!(
        si.starts_with(
            "preset fly-ball: launch 46.04512 m/s, 0.488692 rad, spin 261.799388 rad/s;"
        ),
        "{si}"
    );
    let imperial = second_line(&["figure", "4", "--preset", "fly-ball", "--units", "imperial"]);
    assert!(
        imperial.starts_with("preset fly-ball: launch 103 mph, 28°, spin 2500 rpm;"),
        "{imperial}"
    );
    assert!(
        !si.contains("pitch") && !imperial.contains("bat "),
        "{si}\n{imperial}"
    );
}
