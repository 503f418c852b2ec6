//! `model.drag_scale` and `model.lift_scale` (factors on C_D and C_L) and
//! `homerun calibrate`, which fits them to measured distances.

use crate::common;

use homerun::Scene;
use homerun::analysis::precision::Purpose;
use homerun::model::aero::LiftModel;
use homerun::model::launch::{BattedBall, fly_scene};
use serde_json::Value;

fn scene(direction: f64, sidespin: f64) -> Scene {
    Scene::default().with_launch(BattedBall {
        speed: 46.0,
        angle: 0.5,
        spin: 260.0,
        direction,
        sidespin,
    })
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn scaling_drag_and_lift_alike_is_scaling_the_air() {
    // Both forces are ρ·C·|V|²·A/2; S and Re do not hold ρ (ν is its own
    // input): C_D and C_L times k fly as ρ times k, in the plane and in 3-D.
    for (direction, sidespin) in [(0.0, 0.0), (0.3, 80.0)] {
        let mut scaled = scene(direction, sidespin);
        scaled.set("model.drag_scale", 1.1).unwrap();
        scaled.set("model.lift_scale", 1.1).unwrap();
        let mut dense = scene(direction, sidespin);
        dense.environment.set_air_density(1.23 * 1.1);
        let (a, b) = (
            fly_scene(&scaled, Purpose::Reference).flight,
            fly_scene(&dense, Purpose::Reference).flight,
        );
        assert!(relative(a.range, b.range) < 1e-9, "{a:?} {b:?}");
        assert!((a.direction - b.direction).abs() < 1e-9);
        // More drag and lift together: shorter here than unscaled.
        let unscaled = fly_scene(&scene(direction, sidespin), Purpose::Reference).flight;
        assert!(a.range < unscaled.range - 1.0);
    }
    // No lift is lift scaled by 0.
    let mut none = scene(0.3, 80.0);
    none.choose_lift(LiftModel::None);
    let mut zero = scene(0.3, 80.0);
    zero.set("model.lift_scale", 0.0).unwrap();
    let (a, b) = (
        fly_scene(&none, Purpose::Reference).flight,
        fly_scene(&zero, Purpose::Reference).flight,
    );
    assert!(relative(a.range, b.range) < 1e-12);
}

/// The binary with a presets folder of its own.
fn homerun(presets: &std::path::Path, args: &[&str]) -> (Option<i32>, String, String) {
    let dir = presets.to_str().unwrap();
    let all: Vec<&str> = ["--presets-dir", dir].iter().chain(args).copied().collect();
    common::run_homerun(&all, None)
}

#[test]
fn the_factors_are_keys_with_bounds() {
    let dir = tempfile::tempdir().unwrap();
    let (_, keys, _) = homerun(dir.path(), &["keys"]);
    assert!(
        keys.lines()
            .any(|l| l.starts_with("model.drag_scale ") && l.contains("k_D")),
        "{keys}"
    );
    assert!(
        keys.lines()
            .any(|l| l.starts_with("model.drag_scale") && l.contains("[0.3, 3]"))
    );
    assert!(
        keys.lines()
            .any(|l| l.starts_with("model.lift_scale") && l.contains("[0, 3]"))
    );
    let (status, _, err) = homerun(
        dir.path(),
        &["fly", "--preset", "fly-ball", "--set", "model.drag_scale=5"],
    );
    assert_eq!(status, Some(2));
    assert!(
        err.contains("model.drag_scale = 5: must be a finite number in [0.3, 3]"),
        "{err}"
    );
}

#[test]
fn calibrate_fits_the_sample_and_saves_a_preset_that_lands_on_the_median() {
    let dir = tempfile::tempdir().unwrap();
    let sample = "tests/data/savant_home_runs.csv";
    let (status, out, err) = homerun(
        dir.path(),
        &[
            "calibrate",
            sample,
            "--json",
            "--drag-only",
            "--save",
            "sample-2019",
        ],
    );
    assert_eq!(status, Some(0), "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["measured"], 239);
    // Every row in its park's air (home_team) but Texas's of 2019, at
    // Globe Life Park, which no bundled park is: the preset's air.
    assert_eq!(v["in_preset_air"], 8);
    let fit = &v["fit"];
    // Measured (docs/accuracy.md): 1.0069 ± 0.0059, the median error from
    // +0.4 m to 0; the lift left as it is (--drag-only).
    let drag = fit["drag_scale"]["value"].as_f64().unwrap();
    let uncertainty = fit["drag_scale"]["uncertainty"].as_f64().unwrap();
    assert!((drag - 1.0069).abs() < 0.002, "{drag}");
    assert!((0.003..0.01).contains(&uncertainty), "{uncertainty}");
    assert!(fit["before"]["median"].as_f64().unwrap() > 0.2);
    assert!(fit["after"]["median"].as_f64().unwrap().abs() < 0.01);
    assert_eq!(fit["lift_scale"], Value::Null);
    // The preset flies the sample with a median error of about 0: not
    // exactly, since `fly --batch` solves each launch direction again under
    // the scaled drag, where the fit held the launches it solved unscaled
    // (measured −0.048 m; an exact fit would re-solve every row per trial,
    // four times the work).
    let (status, out, err) = homerun(
        dir.path(),
        &[
            "fly",
            "--batch",
            sample,
            "--preset",
            "sample-2019",
            "--json",
            "--keep",
            "hc_x",
        ],
    );
    assert_eq!(status, Some(0), "{err}");
    let mut errors: Vec<f64> = out
        .lines()
        .map(|l| serde_json::from_str::<Value>(l).unwrap())
        .filter(|r| r["kept"]["hc_x"] != "null")
        .filter_map(|r| r["statcast"]["difference"].as_f64())
        .collect();
    errors.sort_by(f64::total_cmp);
    let median = 0.5 * (errors[errors.len() / 2 - 1] + errors[errors.len() / 2]);
    assert_eq!(errors.len(), 239);
    assert!(median.abs() < 0.1, "{median}");
}

/// Issue 26, item 3: `--by` fits each group apart, and each group's fit is
/// the fit of its rows alone (the committed sample's rows of May 2019,
/// written to a file of their own, give the same factor to the digit).
#[test]
fn calibrate_by_month_fits_each_month_as_its_rows_alone() {
    let dir = tempfile::tempdir().unwrap();
    let file = "tests/data/savant_home_runs.csv";
    let (status, out, err) = homerun(dir.path(), &["calibrate", file, "--by", "month", "--json"]);
    assert_eq!(status, Some(0), "{err}");
    let value: Value = serde_json::from_str(&out).unwrap();
    let groups = value["groups"].as_array().unwrap();
    let names: Vec<&str> = groups
        .iter()
        .map(|g| g["group"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        ["2019-03", "2019-04", "2019-05", "2019-06", "2019-07"]
    );
    let rows: u64 = groups.iter().map(|g| g["rows"].as_u64().unwrap()).sum();
    assert_eq!(rows, value["measured"].as_u64().unwrap());
    assert_eq!(rows, 239);
    // March's 7 rows are too few to fit: named, not fitted.
    assert!(groups[0]["fit"].is_null());
    // May alone.
    let text = std::fs::read_to_string(file).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    // Each row opens with its quoted game_date.
    assert!(header.starts_with("\"game_date\""), "{header}");
    let may: Vec<&str> = lines.filter(|l| l.starts_with("\"2019-05-")).collect();
    assert_eq!(may.len(), 67);
    let alone = dir.path().join("may.csv");
    std::fs::write(&alone, format!("{header}\n{}\n", may.join("\n"))).unwrap();
    let (status, out, err) = homerun(
        dir.path(),
        &["calibrate", alone.to_str().unwrap(), "--json"],
    );
    assert_eq!(status, Some(0), "{err}");
    let alone: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(groups[2]["fit"]["drag_scale"], alone["fit"]["drag_scale"]);
    assert_eq!(groups[2]["rows"], alone["measured"]);
    // --by with --save saves a preset a group, each fitted on its rows.
    let (status, out, err) = homerun(
        dir.path(),
        &["calibrate", file, "--by", "month", "--save", "x"],
    );
    assert_eq!(status, Some(0), "{err}");
    assert!(out.contains("saved"), "{out}");
    // A group whose name no preset may take (a date with slashes, a
    // batter's "Last, First") is fitted and named, its preset not written,
    // and the exit status says so.
    let args = [
        "calibrate",
        file,
        "--by",
        "player_name",
        "--save",
        "y",
        "--json",
    ];
    let (status, out, err) = homerun(dir.path(), &args);
    assert_eq!(status, Some(1), "{err}");
    let value: Value = serde_json::from_str(&out).unwrap();
    let unsaved: Vec<&Value> = (value["groups"].as_array().unwrap().iter())
        .filter(|g| g["not_saved"].is_string())
        .collect();
    assert!(!unsaved.is_empty(), "{out}");
    assert!(
        unsaved
            .iter()
            .all(|g| g["saved"].is_null() && g["fit"].is_object())
    );
    assert!(
        err.contains("preset not saved (named above; exit status 1)"),
        "{err}"
    );
    // A column the file lacks is named.
    let (status, _, err) = homerun(dir.path(), &["calibrate", file, "--by", "nope"]);
    assert_eq!(status, Some(2), "{err}");
    assert!(
        err.contains("--by nope: no column of that name in the header"),
        "{err}"
    );
}

/// Issue 26, item 3: where hang times are measured, `calibrate` fits the
/// lift as well as the drag. The 2018 set's columns (capitals, Statcast's
/// older names) are read as they come: the launch direction measured at
/// the bat from EXIT_DIRECTION, the distance from HIT_DISTANCE.
#[test]
fn a_trackman_file_with_hang_times_fits_drag_and_lift() {
    let dir = tempfile::tempdir().unwrap();
    let file = "tests/data/trackman_2018_sample.csv";
    let (status, out, err) = homerun(dir.path(), &["calibrate", file, "--json"]);
    assert_eq!(status, Some(0), "{err}");
    let value: Value = serde_json::from_str(&out).unwrap();
    // 40 rows, 21 of them launched below 10°.
    assert_eq!(value["rows"], 40);
    assert_eq!(value["grounders"], 21);
    assert_eq!(value["measured"], 19);
    // No home_team: every row flies in the preset's air, and the text says
    // the fit takes up that air's level.
    assert_eq!(value["in_preset_air"], 19);
    let (status, out, err) = homerun(dir.path(), &["calibrate", file]);
    assert_eq!(status, Some(0), "{err}");
    assert!(
        out.contains("air      the preset's air on 19 of 19 rows (at no park:"),
        "{out}"
    );
    let fit = &value["fit"];
    assert!(fit["lift_scale"]["value"].is_f64(), "{fit}");
    // The fit lands both medians: distance and hang time.
    assert!(
        fit["after"]["median"].as_f64().unwrap().abs() < 0.05,
        "{fit}"
    );
    assert!(
        fit["second_after"]["median"].as_f64().unwrap().abs() < 0.01,
        "{fit}"
    );
    // Each row flies in its measured direction (row 2: 38.02812° toward right field).
    let (status, out, err) = homerun(dir.path(), &["fly", "--batch", file, "--json"]);
    assert_eq!(status, Some(0), "{err}");
    let first: Value = serde_json::from_str(out.lines().next().unwrap()).unwrap();
    let direction = first["launch"]["direction"].as_f64().unwrap();
    assert_eq!(direction, 38.02812f64.to_radians());
    assert_eq!(first["direction_from"], "scene");
    assert_eq!(
        first["statcast"]["distance"].as_f64().unwrap(),
        72.895 * 0.3048
    );
}

/// `calibrate --spin swing` fits the flights `fly --batch --spin swing`
/// flies: each row with a solved swing launched by its impact, the others by
/// Nathan's relation. On the committed bat-tracking sample its count of
/// rows from the swing and its error before the fit are those of `fly`'s
/// rows in the air (10° and up, with a distance, landing on the spray).
#[test]
fn calibrating_with_the_swing_s_spin_fits_the_flights_fly_gives() {
    let dir = tempfile::tempdir().unwrap();
    let sample = "tests/data/savant_swings.csv";
    let (status, out, err) = homerun(
        dir.path(),
        &["calibrate", sample, "--spin", "swing", "--json"],
    );
    assert_eq!(status, Some(0), "{err}");
    let calibrated: Value = serde_json::from_str(&out).unwrap();
    let (status, out, err) = homerun(
        dir.path(),
        &["fly", "--batch", sample, "--spin", "swing", "--json"],
    );
    assert_eq!(status, Some(0), "{err}");
    let rows: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str::<Value>(l).unwrap())
        .filter(|r| r["launch"]["angle"].as_f64().unwrap() >= 10f64.to_radians())
        .filter(|r| r["statcast"]["difference"].is_number())
        // A ball fielded where no flight of its comes down is no flight's
        // length: left out of a fit.
        .filter(|r| r["direction_from"] != "spray_unsolved")
        .collect();
    let from_swing = rows.iter().filter(|r| r["spin_estimated"] == false).count();
    assert_eq!(calibrated["measured"], rows.len());
    assert_eq!(calibrated["spin_from_swing"], from_swing);
    assert!(from_swing > 10 && from_swing < rows.len(), "{from_swing}");
    let mut errors: Vec<f64> = (rows.iter())
        .map(|r| r["statcast"]["difference"].as_f64().unwrap())
        .collect();
    errors.sort_by(f64::total_cmp);
    let n = errors.len();
    let median = if n % 2 == 1 {
        errors[n / 2]
    } else {
        0.5 * (errors[n / 2 - 1] + errors[n / 2])
    };
    let before = calibrated["fit"]["before"]["median"].as_f64().unwrap();
    assert!((before - median).abs() < 1e-3, "{before} {median}");
    // Nathan's relation on the same file fits other flights.
    let (_, out, _) = homerun(dir.path(), &["calibrate", sample, "--json"]);
    let nathan: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(nathan["spin_from_swing"], Value::Null);
    assert_ne!(
        nathan["fit"]["before"]["median"],
        calibrated["fit"]["before"]["median"]
    );
}

/// tests/data/savant_2025_spin_past_bound.csv: line 602 of
/// statcast-2025-bat-tracking-three-hitters.csv (Schwarber, 2025-05-14, an
/// infield-fly popup at 72°). Its swing's impact spins the ball at 1006.6
/// rad/s, past the 1000 rad/s that a spin given as input may have; the
/// impact's spin is an output of the validated swing, so `fly --batch
/// --spin swing` flies it, and `calibrate --spin swing` fits it as one of
/// those flights (it failed the row, exit 1, naming `launch.spin`).
#[test]
fn a_swings_spin_past_an_inputs_bound_is_fitted_as_it_is_flown() {
    let dir = tempfile::tempdir().unwrap();
    let popup = "tests/data/savant_2025_spin_past_bound.csv";
    let (status, out, err) = homerun(
        dir.path(),
        &["fly", "--batch", popup, "--spin", "swing", "--json"],
    );
    assert_eq!(status, Some(0), "{err}");
    let row: Value = serde_json::from_str(out.trim()).unwrap();
    let spin = row["launch"]["spin"].as_f64().unwrap();
    assert!((spin - 1006.64).abs() < 0.01, "{spin}");
    assert_eq!(row["spin_estimated"], false);
    // The popup among the every-20th sample: one more row measured.
    let sample = std::fs::read_to_string("tests/data/savant_2025_every_20th.csv").unwrap();
    let extra = std::fs::read_to_string(popup).unwrap();
    let both = dir.path().join("both.csv");
    let row_line = extra.lines().nth(1).unwrap();
    std::fs::write(&both, format!("{}{row_line}\n", sample)).unwrap();
    let fit = |file: &str| {
        let (status, out, err) = homerun(
            dir.path(),
            &["calibrate", file, "--spin", "swing", "--json"],
        );
        assert_eq!(status, Some(0), "{err}");
        assert!(!err.contains("launch.spin"), "{err}");
        serde_json::from_str::<Value>(&out).unwrap()
    };
    let alone = fit("tests/data/savant_2025_every_20th.csv");
    let with = fit(both.to_str().unwrap());
    let count = |v: &Value, key: &str| v[key].as_u64().unwrap();
    assert_eq!(count(&with, "rows"), count(&alone, "rows") + 1);
    assert_eq!(count(&with, "measured"), count(&alone, "measured") + 1);
    assert_eq!(
        count(&with, "spin_from_swing"),
        count(&alone, "spin_from_swing") + 1
    );
}

/// tests/data/savant_2025_march.csv: the March rows of
/// statcast-2025-bat-tracking-three-hitters.csv (31, as they are; 16 in the
/// air with a distance). Two factors fitted to so few rows followed their
/// scatter: lift 0.03 ± 0.64, correlated +0.98 with the drag, which `--save`
/// would have written as a preset's lift. A lift the bands cannot tell
/// from half or one and a half of the model's (± 0.5 or more) is not
/// fitted; the drag alone is, and the text says why, grouped or not.
#[test]
fn a_lift_the_bands_leave_undetermined_is_not_fitted() {
    let dir = tempfile::tempdir().unwrap();
    let march = "tests/data/savant_2025_march.csv";
    let (status, out, err) = homerun(dir.path(), &["calibrate", march, "--json"]);
    assert_eq!(status, Some(0), "{err}");
    let value: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(value["measured"], 16);
    let fit = &value["fit"];
    assert_eq!(fit["lift_scale"], Value::Null);
    assert!(
        fit["why_no_lift"]
            .as_str()
            .unwrap()
            .contains("undetermined"),
        "{fit}"
    );
    // The drag alone brings the median to zero.
    let drag = fit["drag_scale"]["value"].as_f64().unwrap();
    assert!((drag - 1.209).abs() < 0.001, "{drag}");
    assert!(
        fit["after"]["median"].as_f64().unwrap().abs() < 0.05,
        "{fit}"
    );
    let (status, out, err) = homerun(dir.path(), &["calibrate", march, "--by", "month"]);
    assert_eq!(status, Some(0), "{err}");
    assert!(
        out.contains("2025-03          16 rows  model.drag_scale = 1.2090"),
        "{out}"
    );
    assert!(!out.contains("model.lift_scale"), "{out}");
    assert!(
        out.contains("lift not fitted for 2025-03: the launch-angle bands leave it undetermined"),
        "{out}"
    );
}

/// `calibrate --impact` needs the minimum every fit needs (it fitted five
/// swings a bat), and says when its 99th percentile is one swing's: on the
/// 35 of the committed sample the fit follows the most efficient.
#[test]
fn the_bats_fit_needs_every_fits_minimum_and_names_a_one_swing_percentile() {
    let dir = tempfile::tempdir().unwrap();
    let sample = std::fs::read_to_string("tests/data/savant_swings.csv").unwrap();
    let five: String = sample.lines().take(6).map(|l| format!("{l}\n")).collect();
    let few = dir.path().join("five.csv");
    std::fs::write(&few, five).unwrap();
    let (status, out, err) = homerun(
        dir.path(),
        &["calibrate", "--impact", few.to_str().unwrap()],
    );
    assert_eq!(status, Some(2), "{out}");
    assert!(
        err.contains("5 tracked swings: too few to fit (at least 10)"),
        "{err}"
    );
    let (status, out, err) = homerun(
        dir.path(),
        &["calibrate", "--impact", "tests/data/savant_swings.csv"],
    );
    assert_eq!(status, Some(0), "{err}");
    assert!(
        out.contains("(of 35 swings the 99th percentile is the most efficient one's"),
        "{out}"
    );
    // A hundred-odd swings have a percentile of their own.
    let (status, out, err) = homerun(
        dir.path(),
        &[
            "calibrate",
            "--impact",
            "tests/data/savant_2024_held_out_110.csv",
        ],
    );
    assert_eq!(status, Some(0), "{err}");
    assert!(out.starts_with("118 tracked swings"), "{out}");
    assert!(!out.contains("most efficient one's"), "{out}");
}
