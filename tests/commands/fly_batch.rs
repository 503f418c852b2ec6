//! `homerun fly --batch`: a batch keeps its order, every ball in play with a
//! launch speed flies, a row gives what the same launch gives alone, bad
//! rows are named by their line, Statcast's units are converted, and a row
//! flies from its pitch's height. (The single ball: fly.rs.)

use std::f64::consts::TAU;
use std::path::Path;

use serde_json::Value;

use crate::fly::{homerun, relative};

/// `fly --batch` on `input` (through stdin), with extra arguments.
fn batch(dir: &Path, input: &str, args: &[&str]) -> (Option<i32>, String, String) {
    let out = homerun(dir)
        .args(["fly", "--batch", "-"])
        .args(args)
        .write_stdin(input)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn a_batch_keeps_the_input_order_across_chunks() {
    let dir = tempfile::tempdir().unwrap();
    // 9000 rows: two rounds of reading, 36 pieces flown in parallel.
    let mut input = String::from("launch.speed,launch.angle,launch.spin\n");
    for i in 0..9000 {
        input += &format!("{},0.5,200\n", 20.0 + f64::from(i) * 0.003);
    }
    let (status, out, err) = batch(dir.path(), &input, &[]);
    assert_eq!(status, Some(0), "{err}");
    let rows: Vec<&str> = out.lines().collect();
    assert_eq!(
        rows[0],
        "line,launch.speed,launch.angle,launch.spin,launch.direction,launch.sidespin,range,direction,flight_time,apex,landing_angle,landed,clears_fence,park,outcome,margin,parks_cleared,spin_estimated,direction_from"
    );
    assert_eq!(rows.len(), 9001);
    let mut last_range = 0.0;
    for (i, row) in rows[1..].iter().enumerate() {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells[0], (i + 2).to_string());
        assert_eq!(cells[1], format!("{:.4}", 20.0 + i as f64 * 0.003));
        // Faster launches carry farther at these speeds.
        let range: f64 = cells[6].parse().unwrap();
        assert!(range > last_range, "{row}");
        last_range = range;
    }
}

/// Rows of April 2024 that were once refused (`../shared/data/`, lines 84,
/// 251 and 2 of the export): a foul popup whose spray (71°) no flight
/// lands on, a chopper at −81° whose estimated topspin (10,500 rpm) was
/// past the batch's 1000 rad/s, and a grounder to the left side.
#[test]
fn every_ball_in_play_with_a_launch_speed_flies() {
    let dir = tempfile::tempdir().unwrap();
    let input = "stand,home_team,hc_x,hc_y,hit_distance_sc,launch_speed,launch_angle,bb_type\n\
                 L,SEA,110.95,203.29,12,88.7,82,popup\n\
                 R,HOU,124.74,175.93,0,55.4,-81,ground_ball\n\
                 R,KC,109.13,157.39,5,100.2,-22,ground_ball\n\
                 R,KC,109.13,157.39,5,NA,-22,ground_ball\n";
    let (status, out, err) = batch(dir.path(), input, &["--json"]);
    assert_eq!(status, Some(0), "{err}");
    let rows: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 3, "{out}");
    let from: Vec<&str> = rows
        .iter()
        .map(|r| r["direction_from"].as_str().unwrap())
        .collect();
    assert_eq!(from, ["spray_unsolved", "landing", "landing"]);
    // The popup flies toward its spray: atan((110.95 − 125.42)/(198.27 − 203.29)).
    let spray = ((110.95f64 - 125.42) / (198.27 - 203.29)).atan();
    assert_eq!(rows[0]["launch"]["direction"].as_f64(), Some(spray));
    // The chopper's spin is the estimate held at −10°: √(1963² + 849²) rpm
    // of topspin and slice, far inside the batch's bounds.
    let spin = rows[1]["launch"]["spin"].as_f64().unwrap();
    let sidespin = rows[1]["launch"]["sidespin"].as_f64().unwrap();
    let rpm = spin.hypot(sidespin) * 60.0 / std::f64::consts::TAU;
    assert!((rpm - 1963f64.hypot(849.0)).abs() < 60.0, "{rpm}");
    assert!(
        err.contains("1 row whose spray no flight lands on"),
        "{err}"
    );
    assert!(
        err.contains("skipped 1 row without a launch speed"),
        "{err}"
    );
}

#[test]
fn fly_and_the_same_launch_in_a_batch_print_the_same_numbers() {
    // Batch rows fly looser and are flown again where a printed digit is
    // in doubt (src/cli/batch/tests.rs tries thousands, hundreds of them on
    // rounding boundaries); here the two commands themselves.
    let dir = tempfile::tempdir().unwrap();
    let keys = ["speed", "angle", "spin", "direction", "sidespin"];
    let launches = [
        [44.7, 0.47, 250.0, 0.0, 0.0],
        [38.2, 0.91, 120.0, -0.3, 80.0],
        [46.1, 0.33, 190.0, 0.52, -120.0],
        [30.0, -0.2, 50.0, 0.1, 10.0],
        [49.0, 0.6, 160.0, -0.2, 0.0],
    ];
    let mut input = keys.map(|k| format!("launch.{k}")).join(",") + "\n";
    for launch in &launches {
        input += &(launch.map(|v| v.to_string()).join(",") + "\n");
    }
    // At no park a batch row is judged only at a fence given (the preset's
    // [field] is the explorer's), here the one `fly` judges at.
    let fence = [
        "--set",
        "field.fence_distance=121.9",
        "--set",
        "field.fence_height=3",
    ];
    let mut args = vec!["--preset", "fly-ball"];
    args.extend(fence);
    let (status, out, err) = batch(dir.path(), &input, &args);
    assert_eq!(status, Some(0), "{err}");
    for (launch, row) in launches.iter().zip(out.lines().skip(1)) {
        let sets: Vec<String> = keys
            .iter()
            .zip(launch)
            .flat_map(|(k, v)| ["--set".to_owned(), format!("launch.{k}={v}")])
            .collect();
        let fly = homerun(dir.path())
            // A batch judges each park in its own air, as a lone fly does.
            .args(["fly", "--preset", "fly-ball", "--json"])
            .args(&sets)
            .output()
            .unwrap();
        let fly: Value = serde_json::from_slice(&fly.stdout).unwrap();
        let number = |v: &Value, decimals: usize| format!("{:.decimals$}", v.as_f64().unwrap());
        let flight = &fly["flight"];
        let cells: Vec<&str> = row.split(',').collect();
        let want = [
            (6, number(&flight["range"], 3)),
            (7, number(&flight["direction"], 6)),
            (8, number(&flight["flight_time"], 3)),
            (9, number(&flight["apex"], 3)),
            (10, number(&flight["landing_angle"], 4)),
            (14, fly["fence"]["outcome"].as_str().unwrap().to_owned()),
            (15, number(&fly["fence"]["margin"], 3)),
            (16, fly["parks"]["cleared"].to_string()),
        ];
        for (column, text) in want {
            assert_eq!(cells[column], text, "column {column} of {row}");
        }
    }
}

#[test]
fn a_bad_row_is_named_by_its_line_and_skipped_with_status_1() {
    let dir = tempfile::tempdir().unwrap();
    let input = "launch.speed,launch.angle,launch.spin\n\
                 40,0.5,200\n\
                 -3,0.5,200\n\
                 45,abc,100\n\
                 \n\
                 41,0.5\n\
                 42,0.5,200\n";
    let (status, out, err) = batch(dir.path(), input, &["--json"]);
    assert_eq!(status, Some(1), "{err}");
    let lines: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let numbers: Vec<u64> = lines.iter().map(|v| v["line"].as_u64().unwrap()).collect();
    assert_eq!(numbers, [2, 7]);
    assert_eq!(lines[1]["launch"]["speed"], 42.0);
    assert!(lines[1]["flight"]["range"].as_f64().unwrap() > 100.0);
    assert!(
        err.contains("line 3: launch.speed = -3: must be a finite number in (0, 100] m/s; skipped"),
        "{err}"
    );
    assert!(
        err.contains("line 4: launch.angle = \"abc\": not a number"),
        "{err}"
    );
    assert!(
        err.contains("line 6: 2 fields where the header has 3"),
        "{err}"
    );
    assert!(err.contains("3 of 5 rows failed"), "{err}");
}

#[test]
fn statcast_columns_are_converted_and_other_columns_ignored() {
    let dir = tempfile::tempdir().unwrap();
    let statcast = "pitch_type,launch_speed,launch_angle,des,spin_rpm\n\
                    FF,103,28,\"homers, to left \"\"deep\"\"\",2500\n\
                    SL,,,ball,\n";
    let (status, out, err) = batch(dir.path(), statcast, &["--json"]);
    assert_eq!(status, Some(0), "{err}");
    assert!(
        err.contains("ignored 2 columns that are no input: pitch_type, des"),
        "{err}"
    );
    assert!(
        err.contains("skipped 1 row without a launch speed"),
        "{err}"
    );
    let statcast: Value = serde_json::from_str(out.trim()).unwrap();
    // The same launch in SI, as the conversions give it exactly.
    let si = format!(
        "launch.speed,launch.angle,launch.spin\n{},{},{}\n",
        103.0 * 0.44704,
        28f64.to_radians(),
        2500.0 * (TAU / 60.0)
    );
    let (status, out, _) = batch(dir.path(), &si, &["--json"]);
    assert_eq!(status, Some(0));
    let si: Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(statcast["launch"], si["launch"]);
    assert_eq!(statcast["flight"], si["flight"]);
    // At no park and no fence given: no verdict but a foul call.
    assert_eq!(statcast["clears_fence"], Value::Null);
    assert_eq!(statcast["fence"]["outcome"], "no_park");
    // Any other key as a column: no air, no lift, a vacuum parabola's carry.
    let input = "launch.speed,launch.angle,launch.spin,environment.air_density,model.lift\n\
                 40,0.6,300,0,none\n";
    let (_, out, err) = batch(dir.path(), input, &["--json"]);
    let v: Value = serde_json::from_str(out.trim()).unwrap_or_else(|e| panic!("{e}: {err}"));
    let (vx, vy) = (40.0 * 0.6f64.cos(), 40.0 * 0.6f64.sin());
    let carry = vx * (vy + (vy * vy + 2.0 * 9.81).sqrt()) / 9.81;
    assert!(relative(v["flight"]["range"].as_f64().unwrap(), carry) < 1e-9);
}

#[test]
fn an_empty_input_a_file_and_hostile_input() {
    let dir = tempfile::tempdir().unwrap();
    // Empty: no rows, the header of none, status 0.
    let (status, out, err) = batch(dir.path(), "", &[]);
    assert_eq!(status, Some(0), "{err}");
    assert_eq!(out.lines().count(), 1);
    assert!(err.contains("the input is empty"), "{err}");
    // A file, as well as stdin.
    let file = dir.path().join("launches.csv");
    std::fs::write(&file, "launch_speed,launch_angle\n100,25\n").unwrap();
    let out = homerun(dir.path())
        .args(["fly", "--batch"])
        .arg(&file)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    assert_eq!(String::from_utf8(out.stdout).unwrap().lines().count(), 2);
    // A missing file, binary data: one line, status 2.
    let out = homerun(dir.path())
        .args(["fly", "--batch", "/nonexistent/launches.csv"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let (status, _, err) = batch(dir.path(), "\0\x01\x02binary", &[]);
    assert_eq!(status, Some(2));
    assert!(err.contains("binary data, not CSV text"), "{err}");
    // A row longer than 64 KiB is skipped; the next one is flown.
    let input = format!(
        "launch.speed,launch.angle,launch.spin\n{}\n40,0.5,200\n",
        "9".repeat(70_000)
    );
    let (status, out, err) = batch(dir.path(), &input, &[]);
    assert_eq!(status, Some(1));
    assert!(err.contains("line 2: longer than 64 KiB; skipped"), "{err}");
    assert!(
        out.lines().nth(1).unwrap().starts_with("3,40.0000"),
        "{out}"
    );
}

#[test]
fn a_header_without_inputs_is_refused_and_long_values_are_read_whole() {
    let dir = tempfile::tempdir().unwrap();
    // Separated by `;`: no column is an input, so every row would have
    // flown the preset's launch. Refused before any row, status 2.
    let (status, out, err) = batch(dir.path(), "launch_speed;launch_angle\n103;28\n", &[]);
    assert_eq!(status, Some(2), "{err}");
    assert!(out.is_empty(), "{out}");
    assert!(
        err.contains("line 1 (the header): no column is an input")
            && err.contains("`launch_speed;launch_angle`")
            && err.contains("--column NAME=COLUMN maps one"),
        "{err}"
    );
    // A key's value longer than an error's quote is parsed whole: 15 °C
    // written with 100 zeros flies as 15 °C, and a bad one is quoted cut.
    let long = format!("15.{}", "0".repeat(100));
    let input = format!(
        "launch.speed,launch.angle,launch.spin,environment.temperature\n\
         40,0.5,200,{long}\n40,0.5,200,15\n40,0.5,200,{long}x\n40,0.5\n"
    );
    let (status, out, err) = batch(dir.path(), &input, &[]);
    assert_eq!(status, Some(1), "{err}");
    let rows: Vec<&str> = out.lines().skip(1).collect();
    assert_eq!(rows.len(), 2, "{out}\n{err}");
    assert_eq!(
        rows[0].split_once(',').unwrap().1,
        rows[1].split_once(',').unwrap().1
    );
    assert!(
        err.contains("line 4: environment.temperature = 15.000"),
        "{err}"
    );
    assert!(err.contains("…: unknown unit `x`"), "{err}");
    assert!(
        err.contains("line 5: 2 fields where the header has 4"),
        "{err}"
    );
    let (_, _, err) = batch(dir.path(), "launch.speed,launch.angle\n40\n", &[]);
    assert!(
        err.contains("line 2: 1 field where the header has 2"),
        "{err}"
    );
}

/// A Statcast row's flight starts where the bat met the pitch: at its
/// height over the plate (`plate_z`, ft), exactly as that height given as
/// the contact height. `--set environment.contact_height` holds for every
/// row instead, and a `plate_z` no ball can be hit at leaves the preset's
/// height and says so.
#[test]
fn a_row_flies_from_its_pitchs_height_at_the_plate() {
    let dir = tempfile::tempdir().unwrap();
    let head = "stand,home_team,hc_x,hc_y,launch_speed,launch_angle";
    let rows = ["R,KC,109.13,107.39,100.2,14", "L,SEA,140.95,103.29,95.0,28"];
    let heights_ft = [1.5, 3.1];
    let table = |column: &str, cells: [String; 2]| {
        format!(
            "{head},{column}\n{},{}\n{},{}\n",
            rows[0], cells[0], rows[1], cells[1]
        )
    };
    let ranges = |input: &str, args: &[&str]| -> (Vec<f64>, String) {
        let (status, out, err) = batch(dir.path(), input, &[&["--json"], args].concat());
        assert_eq!(status, Some(0), "{err}");
        let ranges = out
            .lines()
            .map(|l| {
                serde_json::from_str::<Value>(l).unwrap()["flight"]["range"]
                    .as_f64()
                    .unwrap()
            })
            .collect();
        (ranges, err)
    };
    let (from_pitch, err) = ranges(&table("plate_z", heights_ft.map(|h| h.to_string())), &[]);
    assert!(err.contains("(plate_z) on 2 rows"), "{err}");
    let metres = heights_ft.map(|h| (h * 0.3048).to_string());
    let (given, _) = ranges(&table("environment.contact_height", metres), &[]);
    assert_eq!(from_pitch, given);
    // The preset's 1 m (3.28 ft): the low pitch's ball, hit 1.78 ft lower,
    // comes down sooner; the high one's, 0.18 ft lower, a little sooner.
    let no_plate = format!("{head}\n{}\n{}\n", rows[0], rows[1]);
    let (preset, _) = ranges(&no_plate, &[]);
    assert!(from_pitch[0] < preset[0] - 0.5, "{from_pitch:?} {preset:?}");
    assert!(from_pitch[1] < preset[1] && from_pitch[1] > preset[1] - 0.5);
    let set = ["--set", "environment.contact_height=1.2"];
    let (over, err) = ranges(&table("plate_z", heights_ft.map(|h| h.to_string())), &set);
    assert_eq!(over, ranges(&no_plate, &set).0);
    assert!(!err.contains("plate_z) on"), "{err}");
    let unusable = table("plate_z", ["-0.4".into(), "high".into()]);
    let (ranges_unusable, err) = ranges(&unusable, &[]);
    assert_eq!(ranges_unusable, preset);
    assert!(
        err.contains("2 rows whose plate_z is no contact height"),
        "{err}"
    );
}

/// A ball fouled back over the catcher (Trackman's direction past ±90°,
/// 88 rows of the 2018 set) flies, and lands foul, behind the plate.
#[test]
fn a_ball_fouled_back_flies_and_lands_foul() {
    let dir = tempfile::tempdir().unwrap();
    let input = "LAUNCH_ANGLE,EXIT_SPEED,EXIT_DIRECTION\n60.6,64.5,107.7\n4.1,59.1,162.2\n";
    let (status, out, err) = batch(dir.path(), input, &["--json"]);
    assert_eq!(status, Some(0), "{err}");
    for line in out.lines() {
        let row: Value = serde_json::from_str(line).unwrap();
        assert_eq!(row["fence"]["outcome"], "foul", "{line}");
        let bearing = row["flight"]["direction"].as_f64().unwrap();
        assert!(bearing.abs() > std::f64::consts::FRAC_PI_2, "{line}");
    }
    assert_eq!(out.lines().count(), 2);
}

/// A file with bat tracking flown with Nathan's spin says what reads it:
/// `--spin swing` (or `hit --batch`) solves each row's swing from
/// `bat_speed`; with it, the word is not needed.
#[test]
fn bat_tracking_left_unread_is_named_with_what_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    let sample = "tests/data/savant_swings.csv";
    let line = "bat_speed (bat tracking) is not read by this run: --spin swing, or hit --batch";
    let out = homerun(dir.path())
        .args(["fly", "--batch", sample])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stderr).contains(line));
    let out = homerun(dir.path())
        .args(["fly", "--batch", sample, "--spin", "swing"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(!String::from_utf8_lossy(&out.stderr).contains("bat_speed (bat tracking)"));
}
