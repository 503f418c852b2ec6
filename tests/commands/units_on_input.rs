//! Units on input: `--set KEY=VALUE`, preset strings and `fly --batch`
//! cells take a number with a unit of the key's quantity (`103mph`, `28°`,
//! `70F`, `29.92inHg`), read by the exact definitions; a bare number stays
//! SI; a unit of another quantity is refused naming the units accepted; a
//! bare number out of range suggests the unit that would bring it in.

use crate::common;
use std::f64::consts::PI;
use std::path::Path;

use homerun::Scene;
use homerun::preset::{Preset, Source};

/// The SI value `text` gives `key`, through `Scene::set_text` (`--set`).
fn typed(key: &str, text: &str) -> f64 {
    let mut scene = Scene::default();
    scene
        .set_text(key, text)
        .unwrap_or_else(|e| panic!("{key}={text}: {e}"));
    scene.get(key).unwrap()
}

fn refused(key: &str, text: &str) -> String {
    let mut scene = Scene::default();
    match scene.set_text(key, text) {
        Err(e) => e.to_string(),
        Ok(()) => panic!("{key}={text} accepted"),
    }
}

#[test]
fn every_suffix_sets_its_key_by_the_exact_definition() {
    let cases: &[(&str, &str, f64)] = &[
        ("launch.speed", "103mph", 103.0 * 0.44704),
        ("launch.speed", "103 mph", 103.0 * 0.44704),
        ("bat.speed", "100km/h", 100.0 * 5.0 / 18.0),
        ("pitch.speed", "100ft/s", 100.0 * 0.3048),
        ("pitch.speed", "42m/s", 42.0),
        ("launch.angle", "28deg", 28.0 * PI / 180.0),
        ("launch.angle", "28°", 28.0 * PI / 180.0),
        ("bat.swing_angle", "0.2rad", 0.2),
        ("launch.spin", "2500rpm", 2500.0 * (2.0 * PI / 60.0)),
        ("pitch.spin", "-200rad/s", -200.0),
        ("environment.elevation", "1580m", 1580.0),
        ("environment.elevation", "5184ft", 5184.0 * 0.3048),
        ("environment.elevation", "1.58km", 1.58 * 1000.0),
        ("environment.contact_height", "100cm", 100.0 / 100.0),
        ("ball.radius", "1.44in", 1.44 * 0.0254),
        ("ball.radius", "36.6mm", 36.6 / 1000.0),
        ("bat.radius", "3.5cm", 3.5 / 100.0),
        ("bat.undercut", "1in", 0.0254),
        ("ball.mass", "5.1oz", 5.1 * 0.028_349_523_125),
        ("ball.mass", "145g", 145.0 / 1000.0),
        ("ball.mass", "0.145kg", 0.145),
        ("bat.effective_mass", "2lb", 2.0 * 0.453_592_37),
        ("environment.temperature", "70F", 190.0 / 9.0),
        ("environment.temperature", "70°F", 190.0 / 9.0),
        ("environment.temperature", "21C", 21.0),
        ("environment.temperature", "21°C", 21.0),
        ("environment.temperature", "294.15K", 294.15 - 273.15),
        (
            "environment.pressure",
            "29.92inHg",
            29.92 * 33.863_886_666_7,
        ),
        ("environment.pressure", "1013.25hPa", 1013.25),
        ("environment.pressure", "1013.25mbar", 1013.25),
        ("environment.pressure", "101325Pa", 1013.25),
        ("environment.pressure", "101.325kPa", 101.325 * 10.0),
        ("environment.gravity", "9.81m/s²", 9.81),
        ("environment.gravity", "32.174ft/s2", 32.174 * 0.3048),
        // Keys with no table of units take their own symbol.
        ("model.spin_decay", "40s", 40.0),
        ("environment.humidity", "50%", 50.0),
        ("environment.air_density", "1.2kg/m³", 1.2),
        ("environment.kinematic_viscosity", "1.5e-5 m2/s", 1.5e-5),
        // A bare number is SI, as always.
        ("launch.speed", "46.04512", 46.04512),
    ];
    for &(key, text, expected) in cases {
        assert_eq!(typed(key, text), expected, "{key}={text}");
    }
    // The numbers as quoted: 103 mph is 46.04512 m/s, 70 °F is 21.111 °C,
    // 29.92 inHg is 1013.2075 hPa, 5.1 oz is 0.14458 kg.
    assert_eq!(typed("launch.speed", "103mph"), 46.045_12);
    assert!((typed("environment.temperature", "70F") - 21.111_111_111_111).abs() < 1e-12);
    assert!((typed("environment.pressure", "29.92inHg") - 1_013.207_489_067_664).abs() < 1e-9);
    assert!((typed("ball.mass", "5.1oz") - 0.144_582_567_937_5).abs() < 1e-15);
}

#[test]
fn a_unit_of_another_quantity_is_refused_naming_the_accepted_ones() {
    assert_eq!(
        refused("bat.speed", "28deg"),
        "bat.speed = 28deg: deg measures an angle, not a speed; bat.speed takes m/s, km/h, mph, ft/s (a bare number is m/s)"
    );
    assert_eq!(
        refused("launch.angle", "28 furlongs"),
        "launch.angle = 28 furlongs: unknown unit `furlongs`; launch.angle takes rad, deg, ° (a bare number is rad)"
    );
    assert_eq!(
        refused("bat.friction", "0.5mph"),
        "bat.friction = 0.5mph: mph measures a speed; bat.friction takes a plain number"
    );
    assert_eq!(
        refused("bat.speed", "fast"),
        "bat.speed = \"fast\": not a number"
    );
    // A value typed with a unit and out of range shows its SI value.
    assert_eq!(
        refused("launch.speed", "300mph"),
        "launch.speed = 300mph (134.112 m/s): must be a finite number in (0, 100] m/s"
    );
}

#[test]
fn a_bare_number_out_of_range_suggests_the_unit_it_was_likely_meant_in() {
    assert_eq!(
        refused("launch.speed", "103"),
        "launch.speed = 103: must be a finite number in (0, 100] m/s (did you mean 103mph or 103km/h?)"
    );
    assert!(refused("launch.angle", "28").ends_with("(did you mean 28deg?)"));
    assert!(refused("launch.spin", "2500").ends_with("(did you mean 2500rpm?)"));
    assert!(refused("environment.temperature", "70").ends_with("(did you mean 70F?)"));
    assert!(refused("environment.pressure", "29.92").ends_with("(did you mean 29.92inHg?)"));
    assert!(refused("environment.elevation", "5280").ends_with("(did you mean 5280ft?)"));
    assert!(refused("bat.effective_mass", "32").ends_with("(did you mean 32oz?)"));
    assert!(refused("ball.radius", "1.45").ends_with("(did you mean 1.45in?)"));
    assert!(refused("ball.radius", "36.6").ends_with("(did you mean 36.6mm?)"));
    // No unit brings these in: no suggestion.
    for (key, text) in [
        ("launch.angle", "95"),
        ("launch.speed", "-3"),
        ("launch.speed", "300mph"),
    ] {
        assert!(!refused(key, text).contains("did you mean"), "{key}={text}");
    }
}

#[test]
fn preset_strings_take_units_as_set_does() {
    let text = "[launch]\nspeed = \"103mph\"\nangle = \"28°\"\nspin = \"2500 rpm\"\n\n[environment]\ntemperature = \"70F\"\npressure = \"29.92inHg\"\nelevation = \"1580m\"\n\n[field]\nfence_distance = \"400ft\"\n";
    let preset = Preset::parse(text, "typed", "typed.toml", Source::Bundled).unwrap();
    let launch = preset.scene.batted_ball();
    assert_eq!(launch.speed, 103.0 * 0.44704);
    assert_eq!(launch.angle, 28.0 * PI / 180.0);
    assert_eq!(launch.spin, 2500.0 * (2.0 * PI / 60.0));
    assert_eq!(
        preset.scene.get("environment.temperature").unwrap(),
        190.0 / 9.0
    );
    assert_eq!(preset.fence.unwrap().distance, 400.0 * 0.3048);
    let error = Preset::parse("[bat]\nspeed = \"28deg\"\n", "x", "x.toml", Source::Bundled)
        .unwrap_err()
        .to_string();
    assert!(
        error.starts_with("x.toml: bat.speed = 28deg: deg measures an angle"),
        "{error}"
    );
}

fn homerun(presets: &Path, args: &[&str], stdin: &str) -> std::process::Output {
    common::assert_command()
        .arg("--presets-dir")
        .arg(presets)
        .args(args)
        .write_stdin(stdin)
        .output()
        .unwrap()
}

#[test]
fn set_on_the_command_line_flies_the_same_launch_as_si() {
    let dir = tempfile::tempdir().unwrap();
    let with_units = homerun(
        dir.path(),
        &[
            "fly",
            "--json",
            "--set",
            "launch.speed=103mph",
            "--set",
            "launch.angle=28deg",
            "--set",
            "launch.spin=2500rpm",
            "--set",
            "field.fence_distance=400ft",
        ],
        "",
    );
    assert!(with_units.status.success(), "{with_units:?}");
    let json: serde_json::Value = serde_json::from_slice(&with_units.stdout).unwrap();
    assert_eq!(json["launch"]["speed"].as_f64(), Some(46.045_12));
    let refused = homerun(dir.path(), &["fly", "--set", "launch.speed=103"], "");
    assert_eq!(refused.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&refused.stderr),
        "homerun: launch.speed = 103: must be a finite number in (0, 100] m/s (did you mean 103mph or 103km/h?)\n"
    );
}

#[test]
fn batch_cells_take_units_and_statcast_columns_keep_theirs() {
    let dir = tempfile::tempdir().unwrap();
    let flown = |csv: &str| {
        let output = homerun(dir.path(), &["fly", "--batch", "-"], csv);
        assert!(output.status.success(), "{output:?}");
        // The rows without their line numbers.
        String::from_utf8(output.stdout)
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| l.split_once(',').unwrap().1.to_owned())
            .collect::<Vec<_>>()
    };
    let typed = flown("launch.speed,launch.angle,spin_rpm\n103mph,28deg,2500\n95 mph,0.3,2000\n");
    let statcast =
        flown("launch_speed,launch_angle,spin_rpm\n103,28,2500\n95,17.188733853924695,2000\n");
    assert_eq!(typed[0], statcast[0]);
    assert!(
        typed[0].starts_with("46.0451,0.488692,261.799,"),
        "{typed:?}"
    );
    // A Statcast column is mph when bare, and takes a unit as --set does
    // (issue 26): the same launch either way; a word is still no number.
    let units = flown("launch_speed,launch_angle,spin_rpm\n103mph,28deg,2500rpm\n");
    assert_eq!(units[0], statcast[0]);
    let output = homerun(
        dir.path(),
        &["fly", "--batch", "-"],
        "launch_speed,launch_angle\nfast,30\n",
    );
    assert_eq!(output.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("launch_speed = \"fast\": not a number"),
        "{output:?}"
    );
    // Out of range, a Statcast column's value and range are in its unit.
    let output = homerun(
        dir.path(),
        &["fly", "--batch", "-"],
        "launch_speed,launch_angle\n98,95\n",
    );
    assert!(
        String::from_utf8_lossy(&output.stderr).contains(
            "line 2: launch.angle = 95 ° (1.65806 rad): must be a finite number in [-π/2, π/2] rad, \
             that is [-90, 90] ° (from launch_speed = 98 mph, launch_angle = 95 °)"
        ),
        "{output:?}"
    );
}

/// Issue 28, item 1: what you see is what you type. Under imperial a bare
/// number is in the unit each key is shown in, so it is the same double as
/// the number typed with that unit's symbol, for every key with a unit.
#[test]
fn an_imperial_bare_number_is_the_unit_shown_for_every_key() {
    use homerun::model::keys::all_keys;
    use homerun::units::UnitSystem;
    let mut checked = 0;
    for key in all_keys() {
        let unit = key.unit_in(UnitSystem::Imperial);
        if unit.is_identity() {
            continue;
        }
        // The default value as shown, to three decimals, nudged inside.
        let default = (key.get)(&Scene::default());
        let mut shown = (unit.show(default) * 1000.0).round() / 1000.0;
        if !key.bounds.contains(unit.read(shown)) {
            shown = (unit.show(key.bounds.min.max(-1e3) + key.step) * 1000.0).round() / 1000.0;
        }
        let bare = shown.to_string();
        let mut imperial = Scene::default();
        imperial
            .set_text_in(key.name, &bare, UnitSystem::Imperial)
            .unwrap_or_else(|e| panic!("{}={bare}: {e}", key.name));
        let suffixed = format!("{bare}{}", unit.symbol);
        assert_eq!(
            imperial.get(key.name).unwrap(),
            typed(key.name, &suffixed),
            "{} = {bare} under imperial against {suffixed}",
            key.name
        );
        // And never as SI, unless the two units agree there.
        if unit.read(shown) != shown {
            assert_ne!(imperial.get(key.name).unwrap(), shown, "{}", key.name);
        }
        checked += 1;
    }
    assert!(checked >= 20, "{checked} keys with an imperial unit");
}

#[test]
fn set_under_units_imperial_reads_a_bare_number_as_shown() {
    let dir = tempfile::tempdir().unwrap();
    let fly = |args: &[&str]| {
        let mut all = vec!["fly", "--json"];
        all.extend_from_slice(args);
        let out = homerun(dir.path(), &all, "");
        assert!(out.status.success(), "{out:?}");
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let bare = fly(&[
        "--units",
        "imperial",
        "--set",
        "launch.speed=100",
        "--set",
        "launch.angle=25",
        "--set",
        "launch.spin=2000",
        "--set",
        "field.fence_distance=400",
    ]);
    let suffixed = fly(&[
        "--set",
        "launch.speed=100mph",
        "--set",
        "launch.angle=25deg",
        "--set",
        "launch.spin=2000rpm",
        "--set",
        "field.fence_distance=400ft",
    ]);
    assert_eq!(bare, suffixed);
    assert_eq!(bare["launch"]["speed"].as_f64(), Some(44.704));
    // Out of range, the refusal names the unit it was read in and the range in it.
    let refused = homerun(
        dir.path(),
        &["fly", "--units", "imperial", "--set", "launch.speed=300"],
        "",
    );
    assert_eq!(refused.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&refused.stderr),
        "homerun: launch.speed = 300 mph (134.112 m/s): must be a finite number in (0, 100] m/s, that is (0, 223.693] mph\n"
    );
}
