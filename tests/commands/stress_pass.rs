//! The eight failures a stress pass found (issue 15, F1–F8), each held by
//! a test here (F1, a preset saved onto a FIFO, is in `hostile_files.rs`).
#![allow(unsafe_code)] // libc: a child started with its stdout closed.

use crate::common;
use common::homerun;
use std::path::Path;

use homerun::Scene;
use ratatui::crossterm::event::KeyCode;

use crate::tui_support;
use homerun::preset::{Preset, Source};

/// The one line of a refusal (status 2, nothing on stdout).
fn refusal(presets: &Path, args: &[&str]) -> String {
    let output = homerun(presets, args);
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(output.stdout.is_empty(), "{args:?}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    stderr.trim_end().to_owned()
}

/// F2: a batted ball's launch values taken from its swing are held to the
/// launch.* bounds: 100 m/s of bat speed launches the fastball at
/// 106.9 m/s, which `fly --set launch.angle=0.5` flew. Refused, naming the
/// value, the bound and the swing that made it.
#[test]
fn f2_a_batted_ball_taking_a_launch_out_of_bounds_from_its_swing_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let line = refusal(
        dir.path(),
        &["fly", "--set", "bat.speed=100", "--set", "launch.angle=0.5"],
    );
    assert_eq!(
        line,
        "homerun: launch.speed = 106.906 m/s, taken from the swing (pitch.speed = 42, pitch.spin = -200, bat.speed = 100, bat.spin = 0, bat.undercut = 0.0265, bat.swing_angle = 0.1594): must be in (0, 100] m/s, as if given; give launch.speed, or change the swing"
    );
    // Given, the launch speed no longer comes from the swing.
    let output = homerun(
        dir.path(),
        &[
            "fly",
            "--set",
            "bat.speed=100",
            "--set",
            "launch.angle=0.5",
            "--set",
            "launch.speed=45",
        ],
    );
    assert!(output.status.success(), "{output:?}");
}

/// The swing of F2's second repro: its impact launches at 1518 rad/s.
fn fierce_swing() -> Preset {
    let mut preset = homerun::preset::load("fastball", None).unwrap();
    preset.name = "fierce".into();
    preset.scene.bat.speed = 100.0;
    preset.scene.bat.undercut = 0.06;
    preset.scene.pitch.spin = -1000.0;
    preset.scene.bat.spin = 200.0;
    preset
}

/// F2: the swing still flies (its inputs are the swing), but its launch,
/// outside launch.spin's bounds, becomes no batted ball: the explorer's `b`
/// refuses it, saying why, and a preset of it is not saved.
#[test]
fn f2_a_swings_launch_out_of_bounds_is_not_frozen_nor_saved() {
    use homerun::model::launch::SceneKind;
    let swing = fierce_swing();
    swing.scene.validate().unwrap();
    assert!((swing.scene.batted_ball().spin - 1518.14).abs() < 0.01);
    let mut app = homerun::tui::app::App::new(
        swing.clone(),
        None,
        homerun::tui::theme::ColorMode::Indexed,
        ratatui::layout::Rect::new(0, 0, 80, 24),
    );
    tui_support::key(&mut app, KeyCode::Char('b'));
    assert_eq!(app.scene.kind, SceneKind::Swing);
    let (message, error) = app.message.clone().unwrap();
    assert!(
        error
            && message.starts_with("no batted ball: launch.spin = ")
            && message.contains("[-1000, 1000] rad/s"),
        "{message}"
    );
    let dir = tempfile::tempdir().unwrap();
    let mut frozen = swing;
    frozen.scene = frozen.scene.with_launch(frozen.scene.batted_ball());
    let error = frozen.save(dir.path(), true).unwrap_err().to_string();
    assert!(
        error.starts_with("fierce.toml: launch.spin = ") && error.contains("[-1000, 1000] rad/s"),
        "{error}"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

/// F2's principle: whatever the program flies, it accepts back as input.
/// Over swings at the edges of every input of the impact, each batted ball
/// made from a swing (frozen whole, as `b` does, or with the angle given
/// and the rest taken from the swing, as `--set launch.angle` does) is
/// either refused before it flies, or saved and loaded back unchanged.
#[test]
fn f2_every_batted_ball_flown_loads_back_from_its_saved_preset() {
    let dir = tempfile::tempdir().unwrap();
    let (mut accepted, mut refused) = (0, 0);
    let mut preset = homerun::preset::load("fastball", None).unwrap();
    preset.name = "frozen".into();
    for bat_speed in [20.0, 60.0, 93.0, 100.0] {
        for undercut in [-0.06, 0.0, 0.03, 0.06] {
            for pitch_spin in [-1000.0, 0.0, 1000.0] {
                for bat_spin in [-200.0, 200.0] {
                    for swing_angle in [-1.0, 0.16, 1.2] {
                        let mut scene = Scene::default();
                        scene.bat.speed = bat_speed;
                        scene.bat.undercut = undercut;
                        scene.pitch.spin = pitch_spin;
                        scene.bat.spin = bat_spin;
                        scene.bat.swing_angle = swing_angle;
                        scene.validate().unwrap();
                        let mut angled = scene;
                        angled.set("launch.angle", 0.5).unwrap();
                        for batted in [scene.with_launch(scene.batted_ball()), angled] {
                            preset.scene = batted;
                            match batted.validate() {
                                Ok(()) => {
                                    accepted += 1;
                                    let path = preset.save(dir.path(), true).unwrap();
                                    assert_eq!(Preset::read(&path).unwrap().scene, batted);
                                }
                                Err(_) => {
                                    refused += 1;
                                    assert!(preset.save(dir.path(), true).is_err());
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    // Both outcomes are there: the test covers the edge it is about.
    assert!(
        accepted > 100 && refused > 50,
        "{accepted} accepted, {refused} refused"
    );
    let text = "[bat]\nspeed = 100\n\n[launch]\nangle = 0.5\n";
    assert!(Preset::parse(text, "x", "x.toml", Source::Bundled).is_err());
}

/// F3: `model.spin_decay=1e-310`, inside [0, 1000] s, "did not land within
/// 0.0 s": 1/τ overflowed and the spin was NaN at launch. A τ that small
/// decays the spin to nothing at once, so the ball flies as one launched
/// without spin, to the integrator's tolerance.
#[test]
fn f3_a_subnormal_spin_decay_time_flies_as_no_spin() {
    use homerun::analysis::precision::Purpose;
    use homerun::model::launch::{BattedBall, fly_scene};
    let fastball = Scene::default();
    let launch = fastball.batted_ball();
    let mut spinless = fastball.with_launch(BattedBall {
        spin: 0.0,
        ..launch
    });
    // The swing's (the paper's) models, which a batted ball would not fly
    // unless chosen.
    spinless.choose_drag(fastball.drag);
    spinless.choose_lift(fastball.lift);
    let without = fly_scene(&spinless, Purpose::Readout).flight;
    for tau in [1e-310, 5e-324, 1e-300, 1e-9] {
        let mut scene = fastball;
        scene.spin_decay = tau;
        scene.validate().unwrap();
        let flight = fly_scene(&scene, Purpose::Readout).flight;
        assert!(flight.landed, "τ = {tau:e}: {flight:?}");
        assert!(
            (flight.range - without.range).abs() < 1e-3,
            "τ = {tau:e}: {} m, without spin {} m",
            flight.range,
            without.range
        );
    }
    // And the spin decays as it did for an ordinary τ.
    let mut scene = fastball;
    scene.spin_decay = 40.0;
    let decayed = fly_scene(&scene, Purpose::Readout).flight.range;
    assert!(decayed > without.range + 10.0, "{decayed}");
}

/// The ends of `interval`, "(0, 223.693]", as (number, open) pairs.
fn ends(interval: &str) -> [(f64, bool); 2] {
    let (min, max) = interval[1..interval.len() - 1].split_once(", ").unwrap();
    let number = |s: &str| s.parse::<f64>().unwrap_or_else(|_| panic!("{interval}"));
    [
        (number(min), interval.starts_with('(')),
        (number(max), interval.ends_with(')')),
    ]
}

/// F4: bounds printed in imperial units were rounded outward and refused
/// themselves (`sweep pitch.speed --to 223.694 --units imperial`: "(0,
/// 223.694] mph"). For every key, in both systems, each printed end typed
/// back is what its bracket says: accepted at a closed end, refused at an
/// open one, with a value a last digit inside it accepted.
#[test]
fn f4_every_printed_bound_typed_back_is_what_its_bracket_says() {
    use homerun::model::keys::{Bounds, all_keys};
    use homerun::units::{Quantity, UnitSystem};
    let field_keys = homerun::preset::FIELD_KEYS
        .iter()
        .map(|f| (f.name, f.bounds, Quantity::Distance, f.unit));
    let keys = all_keys()
        .map(|k| (k.name, k.bounds, k.quantity(), k.unit))
        .chain(field_keys);
    let mut checked = 0;
    for (name, bounds, quantity, si_unit) in keys {
        for system in UnitSystem::ALL {
            let unit = quantity.unit(system, si_unit);
            let printed = bounds.shown_in(unit);
            if printed.contains('π') {
                continue; // SI's ±π/2, exact by name
            }
            for ((end, open), inward) in ends(&printed).into_iter().zip([1.0, -1.0]) {
                let accepted = |v: f64| Bounds::contains(&bounds, unit.read(v));
                if open {
                    assert!(!accepted(end), "{name} {system}: {printed}");
                    assert!(accepted(end + inward * 1e-3), "{name} {system}: {printed}");
                } else {
                    assert!(accepted(end), "{name} {system}: {printed}");
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "{checked}");
    // The repro: the bound the error prints is a bound the sweep takes.
    let dir = tempfile::tempdir().unwrap();
    let line = refusal(
        dir.path(),
        &[
            "sweep",
            "pitch.speed",
            "--from",
            "1",
            "--to",
            "300",
            "--units",
            "imperial",
        ],
    );
    let printed = line.split(" in ").nth(1).unwrap().trim_end_matches(" mph");
    let [_, (to, _)] = ends(printed);
    let args = [
        "sweep",
        "pitch.speed",
        "--from",
        "90",
        "--to",
        &to.to_string(),
    ];
    let args = [&args[..], &["--steps", "2", "--units", "imperial"]].concat();
    let output = homerun(dir.path(), &args);
    assert!(output.status.success(), "{args:?}: {output:?}");
}

/// The text of a command that succeeds.
fn stdout(presets: &Path, args: &[&str]) -> String {
    let output = homerun(presets, args);
    assert!(output.status.success(), "{args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}

/// F5: the surface's column headings ran together once |E| ≥ 100 mm
/// (`-400.0-325.0…`, and `-50.0-40.0` already), and a ball landing 0.4 m
/// behind the plate printed `-0`. Every heading now stands apart, over
/// its column, and a range that rounds to zero is 0.
#[test]
fn f5_surface_headings_stand_apart_and_no_cell_is_minus_zero() {
    let dir = tempfile::tempdir().unwrap();
    let big_ball = [
        "--set",
        "ball.radius=0.1",
        "--set",
        "ball.gyration_radius=0.05",
        "--set",
        "ball.mass=1",
    ];
    let surface = |window: &[&str]| {
        let args = [&["surface"][..], window, &big_ball].concat();
        stdout(dir.path(), &args)
    };
    let text = surface(&["--undercut", "-0.4..-0.1", "--grid", "5x2"]);
    let lines: Vec<&str> = text.lines().collect();
    let heads: Vec<&str> = lines[1].split_whitespace().collect();
    assert_eq!(
        heads,
        [
            "ψ", "\\", "E", "-400.0", "-325.0", "-250.0", "-175.0", "-100.0"
        ],
        "{text}"
    );
    // Each row's numbers end a mark's width (" " or "*") before their
    // headings end.
    let ends = |line: &str| -> Vec<usize> {
        let chars: Vec<char> = line.chars().collect();
        (1..=chars.len())
            .filter(|&k| chars[k - 1] != ' ' && chars.get(k).is_none_or(|c| *c == ' '))
            .collect()
    };
    for row in &lines[2..4] {
        let row = row.replace('*', " ");
        let numbers: Vec<usize> = ends(&row)[1..].iter().map(|k| k + 1).collect();
        assert_eq!(numbers, ends(lines[1])[3..], "{text}");
    }
    let text = surface(&[
        "--undercut",
        "-0.05..-0.04",
        "--swing-angle",
        "-1.2692307692307692..-1.2",
        "--grid",
        "2x2",
    ]);
    assert!(
        text.lines().nth(1).unwrap().ends_with(" -50.0 -40.0"),
        "{text}"
    );
    assert!(text.ends_with("range -0.36 m\n"), "{text}");
    assert!(!text.contains("-0 ") && !text.contains("-0*"), "{text}");
    assert!(text.contains("     0     0*"), "{text}");
}

/// F6: `hit --set pitch.speed=1e-300` was a 771-character error (its
/// vertical velocity, 1.7e302 m/s, written out in full), and 5e-324 one
/// with `-inf` in it. For every key and every extreme value, an error is
/// one short line, with the value as typed and no inf or NaN of ours.
#[test]
fn f6_errors_show_extreme_values_short_and_without_inf() {
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(
        refusal(dir.path(), &["hit", "--set", "pitch.speed=1e-300"]),
        "homerun: pitch.speed = 1e-300: Eq. (3)'s fit gives a vertical velocity of -1.72597e302 m/s, more than the speed itself; at this gravity it needs a pitch speed of at least 9.92 m/s"
    );
    assert_eq!(
        refusal(dir.path(), &["hit", "--set", "pitch.speed=5e-324"]),
        "homerun: pitch.speed = 5e-324: Eq. (3)'s fit gives an infinite vertical velocity, more than the speed itself; at this gravity it needs a pitch speed of at least 9.92 m/s"
    );
    let long = format!("0.{}1", "0".repeat(300));
    let values = [
        "1e-300",
        "-1e-300",
        "5e-324",
        "-5e-324",
        "1e300",
        "-1e300",
        "1.7976931348623157e308",
        long.as_str(),
        "0.30000000000000004",
    ];
    let mut refused = 0;
    for key in homerun::model::keys::all_keys() {
        for value in values {
            let mut scene = Scene::default();
            let Err(error) = scene
                .set_text(key.name, value)
                .and_then(|()| scene.validate())
            else {
                continue;
            };
            refused += 1;
            let message = error.to_string();
            assert!(
                message.chars().count() <= 300,
                "{}={value}: {message}",
                key.name
            );
            let words = message.split(|c: char| !c.is_alphanumeric());
            assert!(
                !words.into_iter().any(|w| w == "inf" || w == "NaN"),
                "{}={value}: {message}",
                key.name
            );
            // The value as typed, cut to 80 characters (the long one), or
            // its shortest digits (1.7976931348623157e308).
            let shown = value.chars().take(79).collect::<String>();
            let short = value.parse::<f64>().unwrap().to_string();
            let shortest = format!("{:e}", value.parse::<f64>().unwrap());
            assert!(
                message.contains(&shown) || message.contains(&short) || message.contains(&shortest),
                "{}={value}: {message}",
                key.name
            );
        }
    }
    assert!(refused > 100, "{refused}");
}

/// `fly --batch -` on `input`: (status, stdout, stderr).
fn batch(presets: &Path, input: &str) -> (Option<i32>, String, String) {
    let output = common::assert_command()
        .arg("--presets-dir")
        .arg(presets)
        .args(["fly", "--batch", "-"])
        .write_stdin(input)
        .output()
        .unwrap();
    (
        output.status.code(),
        String::from_utf8(output.stdout).unwrap(),
        String::from_utf8(output.stderr).unwrap(),
    )
}

/// F7: lines of spaces or tabs vanished from the count ("1 of 2 rows
/// failed" for four records). Each is a record of one field, named and
/// counted; a line with nothing on it is counted as skipped.
#[test]
fn f7_every_record_line_is_counted() {
    let dir = tempfile::tempdir().unwrap();
    let (status, out, err) = batch(
        dir.path(),
        "launch_speed,launch_angle\n \n\t\n\"\"\n100,30\n\n",
    );
    assert_eq!(status, Some(1), "{err}");
    assert_eq!(out.lines().count(), 2, "{out}");
    for line in 2..=4 {
        assert!(
            err.contains(&format!(
                "line {line}: 1 field where the header has 2; skipped"
            )),
            "{err}"
        );
    }
    assert!(err.contains("homerun: 1 empty line skipped\n"), "{err}");
    assert!(
        err.ends_with("homerun: 3 of 4 rows failed and were skipped (exit status 1)\n"),
        "{err}"
    );
    // With one column (the angle given for every row), a line of spaces is
    // a row whose launch is empty.
    let output = common::assert_command()
        .args(["fly", "--batch", "-", "--set", "launch.angle=0.4"])
        .write_stdin("launch_speed\n \n100\n")
        .output()
        .unwrap();
    let (status, err) = (
        output.status.code(),
        String::from_utf8(output.stderr).unwrap(),
    );
    assert_eq!(status, Some(0), "{err}");
    assert!(
        err.contains("skipped 1 row without a launch speed (not batted balls)"),
        "{err}"
    );
}

/// `homerun ARGS` with its standard output closed (`>&-`) and `input` on
/// its standard input: (status, stderr).
#[cfg(target_os = "linux")]
fn with_stdout_closed(presets: &Path, args: &[&str], input: &str) -> (Option<i32>, String) {
    use std::io::Write as _;
    use std::os::unix::process::CommandExt as _;
    let mut command = common::command();
    command
        .arg("--presets-dir")
        .arg(presets)
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped());
    // SAFETY: close is async-signal-safe and touches no memory of ours.
    unsafe {
        command.pre_exec(|| {
            libc::close(libc::STDOUT_FILENO);
            Ok(())
        });
    }
    let mut child = command.spawn().unwrap();
    // The program may exit before reading it all: a broken pipe is fine.
    let _ = child.stdin.take().unwrap().write_all(input.as_bytes());
    let output = child.wait_with_output().unwrap();
    (
        output.status.code(),
        String::from_utf8(output.stderr).unwrap(),
    )
}

/// F8: with its standard output closed, `keys` and `fly --batch` exited 0
/// having written nothing (Rust's runtime put /dev/null there). Now each
/// exits 2 with one line, the batch before reading a row.
#[cfg(target_os = "linux")]
#[test]
fn f8_a_closed_stdout_is_refused_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let closed =
        "homerun: standard output is closed: nothing could be written (give it a file or a pipe)\n";
    let rows = format!("launch_speed,des\n{}", "100,x\n".repeat(10_000));
    for (args, input) in [
        (&["keys"][..], ""),
        (&["hit", "--json"][..], ""),
        (&["fly", "--batch", "-"][..], rows.as_str()),
        (&["--help"][..], ""),
    ] {
        let (status, stderr) = with_stdout_closed(dir.path(), args, input);
        assert_eq!(status, Some(2), "{args:?}: {stderr}");
        // One line: not even the header's note on the ignored column.
        assert_eq!(stderr, closed, "{args:?}");
    }
    // A picture goes to its file, whatever stdout is.
    let svg = dir.path().join("t.svg");
    let (status, stderr) = with_stdout_closed(
        dir.path(),
        &["trajectory", "--svg", svg.to_str().unwrap()],
        "",
    );
    assert_eq!(status, Some(0), "{stderr}");
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
}

/// F8: the batch's notice said "every row takes preset fastball's
/// launch.speed" when a bat.speed column gave each row its own swing, and
/// so its own launch speed.
#[test]
fn f8_the_batch_notice_names_each_rows_own_swing_when_columns_change_it() {
    let dir = tempfile::tempdir().unwrap();
    let (status, out, err) = batch(dir.path(), "bat.speed,launch.angle\n30,0.3\n35,0.3\n");
    assert_eq!(status, Some(0), "{err}");
    assert!(
        err.contains(
            "no launch.speed column: each row's launch.speed comes from its own swing (column bat.speed)"
        ) && !err.contains("every row takes"),
        "{err}"
    );
    // And it does: the faster bat launches faster.
    let speeds: Vec<f64> = out
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(1).unwrap().parse().unwrap())
        .collect();
    assert!(speeds[1] > speeds[0] + 4.0, "{out}");
    // Without such a column every row would take the preset's one swing's
    // launch, which no one means (issue 35): refused, naming the columns.
    let (status, out, err) = batch(dir.path(), "launch.angle\n0.3\n");
    assert_eq!((status, out.as_str()), (Some(2), ""));
    assert!(
        err.contains("no launch speed column (looked for launch_speed, exit_speed"),
        "{err}"
    );
}
