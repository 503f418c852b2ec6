//! The real binary: each command's output fields, and every bad input giving
//! one clear line on stderr and exit status 2.

use crate::common;
use std::path::Path;

use assert_cmd::Command;
use serde_json::Value;

/// `homerun` with an empty user preset folder, so the machine's own
/// presets never change a result.
fn homerun(presets: &Path) -> Command {
    let mut command = common::assert_command();
    command.arg("--presets-dir").arg(presets);
    command
}

fn json(presets: &Path, args: &[&str]) -> Value {
    let output = homerun(presets).args(args).output().unwrap();
    assert!(output.status.success(), "{args:?}: {output:?}");
    serde_json::from_slice(&output.stdout).unwrap()
}

fn number(value: &Value, path: &str) -> f64 {
    let mut v = value;
    for part in path.split('.') {
        v = &v[part];
    }
    v.as_f64()
        .unwrap_or_else(|| panic!("{path} is not a number in {value}"))
}

#[test]
fn hit_reports_every_field() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(dir.path(), &["hit", "--json"]);
    for path in [
        "pitch.speed",
        "pitch.vertical_velocity",
        "pitch.angle",
        "impact.normal_angle",
        "impact.restitution",
        "impact.compression_impulse",
        "impact.separation_impulse",
        "impact.stick_impulse",
        "impact.launch_speed",
        "impact.launch_spin",
        "impact.launch_angle",
        "flight.range",
        "flight.flight_time",
        "flight.apex",
        "flight.landing_speed",
        "flight.landing_angle",
    ] {
        number(&v, path);
    }
    assert_eq!(v["impact"]["regime"], "stick");
    assert!((number(&v, "flight.range") - 134.6988).abs() < 1e-3);
    // A grazing hit slips throughout: no stick impulse.
    let v = json(
        dir.path(),
        &[
            "hit",
            "--json",
            "--set",
            "bat.undercut=0.068",
            "--set",
            "bat.friction=0.35",
        ],
    );
    assert_eq!(v["impact"]["regime"], "slip");
    assert!(v["impact"]["stick_impulse"].is_null());
    // A ball driven into the ground (ζ < 0) is still simulated and reported,
    // with finite numbers everywhere.
    let v = json(
        dir.path(),
        &["hit", "--json", "--set", "bat.undercut=-0.05"],
    );
    assert!(number(&v, "impact.launch_angle") < 0.0);
    for path in [
        "flight.range",
        "flight.flight_time",
        "flight.apex",
        "flight.landing_angle",
    ] {
        assert!(number(&v, path).is_finite(), "{path}");
    }
}

#[test]
fn optimize_reports_the_optimum_and_its_launch() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(dir.path(), &["optimize", "--json", "--preset", "curveball"]);
    assert!((number(&v, "undercut") - 0.0223).abs() < 0.001);
    assert!((number(&v, "swing_angle") - 0.1152).abs() < 0.03);
    assert!((number(&v, "range") - 138.831).abs() < 0.1);
    assert!((number(&v, "launch_speed") - 44.0).abs() < 0.1);
    assert!((number(&v, "launch_spin") - 280.0).abs() < 5.0);
    assert!((number(&v, "launch_angle") - 0.43).abs() < 0.01);
    assert!(number(&v, "evaluations") > 20.0);
    let text = homerun(dir.path()).arg("optimize").output().unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    assert!(text.contains("E = 0.0272"), "{text}");
}

#[test]
fn table2_lists_paper_and_ours() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(dir.path(), &["table2", "--json"]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 3);
    let keys = [
        "pitch_speed",
        "bat_speed",
        "pitch_spin",
        "launch_speed",
        "launch_spin",
        "launch_angle",
        "undercut",
        "swing_angle",
        "range",
    ];
    for (row, pitch) in rows.iter().zip(["fast", "knuckle", "curve"]) {
        assert_eq!(row["pitch"], pitch);
        for side in ["paper", "ours", "ours_at_paper_swing"] {
            for key in keys {
                number(&row[side], key);
            }
        }
        assert_eq!(row["within_tolerance"], true, "{row}");
    }
    assert_eq!(number(&rows[2]["paper"], "launch_speed"), 43.04);
    assert_eq!(number(&rows[2]["errata"][0], "corrected"), 44.04);
    let text = homerun(dir.path()).arg("table2").output().unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    assert_eq!(text.matches("inside the tolerances").count(), 3, "{text}");
    assert!(text.contains("43.04*") && text.contains("misprint for 44.04"));
}

#[test]
fn sweep_and_surface_in_every_format() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(
        dir.path(),
        &[
            "sweep", "bat.spin", "--from", "0", "--to", "50", "--steps", "2", "--json",
        ],
    );
    assert_eq!(v["key"], "bat.spin");
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    // Fig. 9: rolling the wrists helps a little (+1.8 m at 50–60 rad/s).
    let gain = number(&points[1], "range") - number(&points[0], "range");
    assert!((1.0..2.5).contains(&gain), "{gain}");
    for key in ["value", "undercut", "swing_angle", "range"] {
        number(&points[0], key);
    }
    let csv = homerun(dir.path())
        .args([
            "sweep",
            "environment.wind",
            "--from=-2",
            "--to",
            "2",
            "--steps",
            "3",
            "--csv",
        ])
        .output()
        .unwrap();
    let csv = String::from_utf8(csv.stdout).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 4, "{csv}");
    assert!(lines[0].starts_with("environment.wind,undercut,swing_angle,range"));
    assert!(lines[1].starts_with("-2,"));

    let v = json(
        dir.path(),
        &[
            "surface",
            "--grid",
            "3x2",
            "--undercut",
            "0.02..0.03",
            "--swing-angle=-0.1..0.3",
            "--json",
        ],
    );
    assert_eq!(v["undercuts"].as_array().unwrap().len(), 3);
    assert_eq!(v["swing_angles"].as_array().unwrap().len(), 2);
    assert_eq!(v["ranges"].as_array().unwrap().len(), 2);
    assert_eq!(v["ranges"][0].as_array().unwrap().len(), 3);
    assert!(number(&v["best"], "range") > 130.0);
    // Cells the bat cannot reach are null, not an error.
    let v = json(
        dir.path(),
        &[
            "surface",
            "--grid",
            "2x1",
            "--undercut",
            "0.05..0.08",
            "--json",
        ],
    );
    assert!(v["ranges"][0][1].is_null() && v["ranges"][0][0].is_number());
    let text = homerun(dir.path())
        .args(["surface", "--grid", "5x3"])
        .output()
        .unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    assert_eq!(text.lines().count(), 1 + 1 + 3 + 1, "{text}");
}

#[test]
fn presets_lists_bundled_and_user_presets_and_survives_a_broken_one() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("broken.toml"), "[bat\n").unwrap();
    std::fs::write(
        dir.path().join("mine.toml"),
        "description = \"my swing\"\n[bat]\nspeed = 33.0\n",
    )
    .unwrap();
    let output = homerun(dir.path()).arg("presets").output().unwrap();
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    for name in [
        "fastball",
        "knuckleball",
        "curveball",
        "figure5",
        "mine",
        "my swing",
    ] {
        assert!(text.contains(name), "{name}: {text}");
    }
    assert!(text.contains("broken.toml: malformed TOML"), "{text}");
    // The user's preset is usable by name.
    let v = json(dir.path(), &["hit", "--json", "--preset", "mine"]);
    assert!(number(&v, "flight.range") > 140.0);
}

/// Runs `args`, expecting exit status 2 and one line on stderr containing
/// every `needle`, and nothing on stdout.
fn refuses(presets: &Path, args: &[&str], needles: &[&str]) {
    let output = homerun(presets).args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(output.stdout.is_empty(), "{args:?}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    for needle in needles {
        assert!(
            stderr.contains(needle),
            "{args:?}: {needle:?} not in {stderr}"
        );
    }
    // Ours and clap's alike: exactly one line, `homerun: …`.
    assert_eq!(stderr.trim_end().lines().count(), 1, "{args:?}: {stderr}");
    assert!(stderr.starts_with("homerun: "), "{args:?}: {stderr}");
}

#[test]
fn every_bad_input_is_one_clear_line_and_status_2() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let set = |kv: &'static str| ["hit", "--set", kv];
    refuses(d, &set("bat.speed=NaN"), &["bat.speed = NaN", "(0, 100]"]);
    refuses(
        d,
        &set("pitch.speed=inf"),
        &["pitch.speed = inf", "(0, 100]"],
    );
    refuses(d, &set("pitch.spin=-inf"), &["pitch.spin = -inf"]);
    refuses(d, &set("bat.speed=0"), &["bat.speed = 0", "(0, 100]"]);
    refuses(d, &set("pitch.speed=-3"), &["pitch.speed = -3"]);
    refuses(d, &set("ball.mass=0"), &["ball.mass = 0"]);
    refuses(
        d,
        &set("bat.effective_mass=-0.8"),
        &["bat.effective_mass = -0.8"],
    );
    refuses(d, &set("ball.radius=0"), &["ball.radius = 0"]);
    refuses(d, &set("bat.radius=-0.035"), &["bat.radius = -0.035"]);
    refuses(
        d,
        &set("bat.undercut=0.0716"),
        &["bat.undercut = 0.0716", "misses", "0.0716 m"],
    );
    refuses(
        d,
        &set("bat.undercut=-0.08"),
        &["bat.undercut = -0.08", "misses"],
    );
    refuses(
        d,
        &set("bat.friction=-0.1"),
        &["bat.friction = -0.1", "[0, 2]"],
    );
    refuses(
        d,
        &set("bat.sped=30"),
        &["unknown key `bat.sped`", "bat.speed"],
    );
    refuses(
        d,
        &set("model.drag=smooth"),
        &["model.drag = \"smooth\"", "sawicki2003", "constant"],
    );
    refuses(d, &set("bat.speed"), &["--set \"bat.speed\"", "KEY=VALUE"]);
    refuses(
        d,
        &set("bat.speed=fast"),
        &["bat.speed = \"fast\"", "not a number"],
    );
    refuses(
        d,
        &["hit", "--preset", "nosuch"],
        &["no preset named `nosuch`", "fastball"],
    );
    refuses(
        d,
        &["optimize", "--set", "environment.gravity=0"],
        &["environment.gravity = 0"],
    );

    // Preset files.
    let write = |name: &str, text: &str| {
        let path = d.join(name);
        std::fs::write(&path, text).unwrap();
        path.display().to_string()
    };
    let malformed = write("malformed.toml", "[bat\nspeed = 30\n");
    refuses(
        d,
        &["hit", "--preset", &malformed],
        &["malformed.toml", "malformed TOML"],
    );
    let unknown = write("unknown.toml", "[bat]\nspeeed = 30\n");
    refuses(
        d,
        &["hit", "--preset", &unknown],
        &["unknown key `bat.speeed`"],
    );
    let section = write("section.toml", "[batt]\nspeed = 30\n");
    refuses(
        d,
        &["hit", "--preset", &section],
        &["unknown key `batt.speed`"],
    );
    let drag = write("drag.toml", "[model]\ndrag = \"smooth\"\n");
    refuses(d, &["hit", "--preset", &drag], &["model.drag = \"smooth\""]);
    let negative = write("negative.toml", "[ball]\nmass = -0.145\n");
    refuses(d, &["hit", "--preset", &negative], &["ball.mass = -0.145"]);
    let text = write("text.toml", "[bat]\nspeed = \"fast\"\n");
    refuses(
        d,
        &["hit", "--preset", &text],
        &["bat.speed", "\"fast\": not a number"],
    );
    refuses(
        d,
        &[
            "hit",
            "--preset",
            &d.join("absent.toml").display().to_string(),
        ],
        &["absent.toml"],
    );

    // Sweeps: every point is validated before any is computed.
    refuses(
        d,
        &[
            "sweep",
            "bat.speed",
            "--from",
            "20",
            "--to",
            "200",
            "--steps",
            "3",
        ],
        &["bat.speed = 110", "point 2 of 3"],
    );
    refuses(
        d,
        &["sweep", "bat.speed", "--from", "nan", "--to", "30"],
        &["--from NaN: bat.speed must be a finite number in (0, 100] m/s"],
    );
    refuses(
        d,
        &["sweep", "bat.speed", "--from", "26", "--to", "inf"],
        &["--to inf: bat.speed must be a finite number in (0, 100] m/s"],
    );
    refuses(
        d,
        &["sweep", "bat.speeed", "--from", "20", "--to", "30"],
        &["unknown key `bat.speeed`"],
    );
    refuses(
        d,
        &["sweep", "bat.undercut", "--from", "0", "--to", "0.03"],
        &["bat.undercut", "optimiser"],
    );
    refuses(
        d,
        &["sweep", "model.drag", "--from", "0", "--to", "1"],
        &["model.drag"],
    );
    refuses(
        d,
        &[
            "sweep",
            "bat.speed",
            "--from",
            "20",
            "--to",
            "30",
            "--steps",
            "0",
        ],
        &["--steps 0"],
    );

    // Surfaces.
    refuses(
        d,
        &["surface", "--undercut", "0.05"],
        &["--undercut \"0.05\"", "A..B"],
    );
    refuses(
        d,
        &["surface", "--undercut", "0.03..0.01"],
        &["--undercut", "below"],
    );
    refuses(
        d,
        &["surface", "--undercut", "x..0.01"],
        &["--undercut", "\"x\" is not a number"],
    );
    refuses(
        d,
        &["surface", "--swing-angle", "-2..1"],
        &["--swing-angle \"-2..1\"", "π/2"],
    );
    refuses(
        d,
        &["surface", "--swing-angle", "nan..1"],
        &["--swing-angle", "finite"],
    );
    refuses(d, &["surface", "--grid", "21"], &["--grid \"21\"", "NxM"]);
    refuses(d, &["surface", "--grid", "0x5"], &["--grid \"0x5\""]);
    refuses(
        d,
        &["surface", "--grid", "5x100000"],
        &["--grid \"5x100000\""],
    );

    // clap's own usage errors also exit with 2.
    refuses(
        d,
        &["sweep", "bat.speed", "--from", "abc", "--to", "1"],
        &["abc"],
    );
    refuses(d, &["table2", "--csv"], &["--csv"]);
    refuses(d, &["frobnicate"], &["frobnicate"]);
}

#[test]
fn trajectory_runs_from_the_contact_point_to_the_landing_of_hit() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let hit = json(d, &["hit", "--json"]);
    let flight = json(d, &["trajectory", "--samples", "41", "--json"]);
    let points = flight["points"].as_array().unwrap();
    assert_eq!(points.len(), 41);
    let first = &points[0];
    assert_eq!((number(first, "x"), number(first, "y")), (0.0, 1.0));
    // The swing is planar: no lateral coordinate anywhere.
    assert!(points.iter().all(|p| number(p, "z") == 0.0));
    let last = &points[40];
    // The same flight as `hit`: it lands at hit's range, on the ground.
    assert!((number(last, "x") - number(&hit, "flight.range")).abs() < 1e-9);
    assert_eq!(number(last, "y"), 0.0);
    assert!((number(last, "time") - number(&hit, "flight.flight_time")).abs() < 1e-12);
    let apex = points.iter().map(|p| number(p, "y")).fold(0.0, f64::max);
    assert!(apex <= number(&hit, "flight.apex") + 1e-9 && apex > number(&hit, "flight.apex") - 0.5);
    let csv = homerun(d)
        .args(["trajectory", "--samples", "5", "--csv"])
        .output()
        .unwrap();
    let csv = String::from_utf8(csv.stdout).unwrap();
    assert_eq!(csv.lines().next(), Some("time,x,y,z,drag_coefficient"));
    assert_eq!(csv.lines().count(), 6);
    refuses(
        d,
        &["trajectory", "--samples", "1"],
        &["--samples 1", "[2, 100000]"],
    );
}

#[test]
fn keys_lists_every_input_with_its_range() {
    let dir = tempfile::tempdir().unwrap();
    let out = homerun(dir.path()).arg("keys").output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for key in homerun::model::keys::KEYS {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("{} ", key.name)))
            .unwrap_or_else(|| panic!("{} missing", key.name));
        assert!(line.contains(&key.bounds.to_string()), "{line}");
    }
    assert!(text.contains("model.drag") && text.contains("sawicki2003 | constant"));
    assert!(text.contains("[-π/2, π/2]"));
    // Every key, the 3-D flight's among them, says why its range is what
    // it is: its reason follows its name, whole (wrapped at words).
    let why = text.split("Why each range is what it is:").nth(1).unwrap();
    let words = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    for key in homerun::model::keys::all_keys() {
        assert!(key.bounds_reason.ends_with('.'), "{}", key.name);
        let start = why
            .find(&format!("\n{} ", key.name))
            .unwrap_or_else(|| panic!("no reason for {}", key.name));
        assert!(
            words(&why[start..]).contains(&words(key.bounds_reason)),
            "{}",
            key.name
        );
    }
    assert!(why.contains("environment.wind_height") && why.contains("launch.sidespin"));
}

/// A sweep's ends take a unit as `--set` does; a bare number stays in the
/// unit shown. 60 mph is 26.8224 m/s to the last bit (60 × 0.44704), so
/// the two sweeps below are the same sweep, printed alike.
#[test]
fn a_sweeps_ends_take_units_and_a_bare_number_is_in_the_unit_shown() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let sweep = |from: &str, to: &str, more: &[&str]| {
        let mut args = vec!["sweep", "bat.speed", "--from", from, "--to", to];
        args.extend_from_slice(&["--steps", "3", "--csv"]);
        args.extend_from_slice(more);
        let output = homerun(d).args(&args).output().unwrap();
        assert!(output.status.success(), "{args:?}: {output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    let with_units = sweep("60mph", "70mph", &[]);
    assert_eq!(with_units, sweep("26.8224", "31.2928", &[]));
    assert!(with_units.lines().nth(1).unwrap().starts_with("26.8224,"));
    // Under --units imperial a bare number is mph, and a unit still reads.
    let imperial = sweep("60", "70mph", &["--units", "imperial"]);
    let first: Vec<&str> = imperial.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(first[0], "60");
    refuses(
        d,
        &["sweep", "bat.speed", "--from", "300mph", "--to", "70mph"],
        &["--from: bat.speed = 300mph (134.112 m/s): must be a finite number in (0, 100] m/s"],
    );
    refuses(
        d,
        &[
            "sweep",
            "bat.speed",
            "--from",
            "60deg",
            "--to",
            "70",
            "--units",
            "imperial",
        ],
        &[
            "--from: bat.speed = 60deg: deg measures an angle",
            "(a bare number is mph, as shown)",
        ],
    );
}

/// Issue 28, item 14: `calibrate FILE` blames the file it was given, not
/// `--batch`; an unknown key is one short line with a "did you mean".
#[test]
fn small_refusals_name_what_the_user_typed() {
    let dir = tempfile::tempdir().unwrap();
    let out = homerun(dir.path())
        .args(["calibrate", "/nope.csv"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.starts_with("homerun: calibrate /nope.csv: "), "{err}");
    assert!(!err.contains("--batch"), "{err}");
    let out = homerun(dir.path())
        .args(["fly", "--set", "launch.sped=40"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        err,
        "homerun: unknown key `launch.sped`; did you mean `launch.speed`? (`homerun keys` lists every key)\n"
    );
    assert!(err.len() < 120);
}

// Issue 27 item 5's `tui --savant FILE` (the swings solved and counted, a
// file without bat tracking refused) runs in a pseudo-terminal since issue
// 38 asks for the terminal first: tests/explorer/tui_pty.rs.
