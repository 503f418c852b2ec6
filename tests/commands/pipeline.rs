//! The Savant pipeline never answers silently wrong (issue 35): a launch
//! no column gives is refused with the names nearest, `--column` maps a
//! column, stdout holds rows only, JSON follows --units, a row at no park
//! gets no verdict, dates of either form group by month, gzip and Parquet
//! are told by their bytes, and a repeated column is refused.

use std::io::Write as _;
use std::process::Stdio;

use super::common::command;

/// The committed sample of 2019 home runs (real Savant rows).
const HOME_RUNS: &str = "tests/data/savant_home_runs.csv";

/// Runs `homerun args` with `stdin` piped in: (stdout, stderr, status).
pub(super) fn run(args: &[&str], stdin: &[u8]) -> (String, String, i32) {
    let (status, out, err) = super::common::run_with_stdin(args, Some(stdin));
    (out, err, status.unwrap_or(-1))
}

/// `fly --batch -` of `stdin` with `--summary-file`: its summary, the
/// run's stderr and its exit status.
pub(super) fn summary_of(stdin: &[u8]) -> (serde_json::Value, String, i32) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("summary.json");
    let args = [
        "fly",
        "--batch",
        "-",
        "--summary-file",
        file.to_str().unwrap(),
    ];
    let (_, err, status) = run(&args, stdin);
    let text = std::fs::read_to_string(&file).unwrap();
    (serde_json::from_str(&text).unwrap(), err, status)
}

pub(super) fn sample() -> String {
    std::fs::read_to_string(HOME_RUNS).unwrap()
}

#[test]
fn a_file_without_a_launch_column_is_refused_with_the_names_nearest() {
    for renamed in ["exit_velo", "ExitVelo", "EV"] {
        let text = sample().replacen("\"launch_speed\"", &format!("\"{renamed}\""), 1);
        let (out, err, status) = run(&["fly", "--batch", "-"], text.as_bytes());
        assert_eq!(status, 2, "{err}");
        assert!(out.is_empty(), "{out}");
        assert!(err.contains("no launch speed column"), "{err}");
        assert!(err.contains("launch_speed"), "{err}");
        assert!(
            err.contains("did you mean") && err.contains(&format!("`{renamed}`")),
            "{err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
        // Mapped, the same rows fly as the original file's.
        let mapped = format!("launch_speed={renamed}");
        let (out, _, status) = run(
            &["fly", "--batch", "-", "--column", &mapped],
            text.as_bytes(),
        );
        let (want, _, _) = run(&["fly", "--batch", HOME_RUNS], b"");
        assert_eq!((status, out), (0, want));
    }
    // Names in another case or spacing are the same column.
    let text = sample().replacen("\"launch_speed\"", "\"Launch Speed\"", 1);
    let (out, _, status) = run(&["fly", "--batch", "-"], text.as_bytes());
    assert_eq!(
        (status, out),
        (0, run(&["fly", "--batch", HOME_RUNS], b"").0)
    );
    // --set gives the key for every row: taken.
    let text = "launch_speed\n100\n101\n";
    let (_, err, status) = run(&["fly", "--batch", "-"], text.as_bytes());
    assert_eq!(status, 2, "{err}");
    let (out, err, status) = run(
        &["fly", "--batch", "-", "--set", "launch.angle=30deg"],
        text.as_bytes(),
    );
    assert_eq!(status, 0, "{err}");
    assert_eq!(out.lines().count(), 3);
    // A mapping that names no column is one line.
    let (_, err, status) = run(
        &["fly", "--batch", HOME_RUNS, "--column", "launch_speed=EV"],
        b"",
    );
    assert_eq!(status, 2);
    assert!(err.contains("no column `EV`"), "{err}");
    // A mapping to a name nothing reads would leave its column unread:
    // refused, with the nearest name.
    let text = "launch_speed,launch_angle,temp\n100,25,20\n";
    let args = [
        "fly",
        "--batch",
        "-",
        "--column",
        "environment.temprature=temp",
    ];
    let (out, err, status) = run(&args, text.as_bytes());
    assert_eq!(status, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains(
            "--column environment.temprature=temp: `environment.temprature` is no column name \
             or key homerun reads"
        ) && err.contains("did you mean environment.temperature?"),
        "{err}"
    );
    let args = [
        "fly",
        "--batch",
        "-",
        "--json",
        "--column",
        "environment.temperature=temp:C",
    ];
    let (out, err, status) = run(&args, text.as_bytes());
    assert_eq!(status, 0, "{err}");
    assert_eq!(out.lines().count(), 1);
}

#[test]
fn a_repeated_column_of_any_kind_is_refused_naming_both() {
    let header = "launch_speed,launch_angle,bat_speed,vx0,vy0,vz0,ax,ay,az,bat_speed\n";
    let (_, err, status) = run(&["hit", "--batch", "-"], header.as_bytes());
    assert_eq!(status, 2, "{err}");
    assert!(
        err.contains("`bat_speed` and `bat_speed` both give bat_speed"),
        "{err}"
    );
    let (_, err, status) = run(
        &["fly", "--batch", "-"],
        b"launch_speed,exit_speed,launch_angle\n",
    );
    assert_eq!(status, 2);
    assert!(err.contains("`launch_speed` and `exit_speed`"), "{err}");
}

#[test]
fn stdout_holds_rows_only_and_the_summary_goes_to_stderr_or_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("summary.json");
    let args = [
        "fly",
        "--batch",
        HOME_RUNS,
        "--summary",
        "--units",
        "imperial",
    ];
    let mut with_file: Vec<&str> = args.to_vec();
    with_file.extend(["--summary-file", file.to_str().unwrap()]);
    let (out, err, status) = run(&with_file, b"");
    assert_eq!(status, 0, "{err}");
    let rows: Vec<&str> = out.lines().collect();
    // A header, then one row a line, each numbered: nothing else.
    assert!(rows[0].starts_with("line,"));
    assert!(
        rows[1..]
            .iter()
            .all(|r| r.split(',').next().unwrap().parse::<usize>().is_ok())
    );
    assert!(
        err.contains("by launch angle, model − hit_distance_sc (ft)"),
        "{err}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(summary["rows"].as_u64().unwrap() as usize, rows.len() - 1);
    // Its numbers in feet, named so.
    let median = summary["difference"]["median_ft"].as_f64().unwrap();
    assert!(
        err.contains(&format!("median difference {median:+.1} ft")),
        "{err}"
    );
    // At each row's park the difference is the model's error there; at
    // --park, that park's air against where each ball was hit, and said.
    assert!(summary["difference"].get("flown_in_air_of").is_none());
    with_file.extend(["--park", "COL"]);
    let (_, err, status) = run(&with_file, b"");
    assert_eq!(status, 0, "{err}");
    let at_coors: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(at_coors["difference"]["flown_in_air_of"], "COL");
    let thinner = at_coors["difference"]["median_ft"].as_f64().unwrap();
    assert!(thinner > median + 10.0, "{thinner} against {median}");
    assert!(
        err.contains("ft (flown in COL's air, hit_distance_sc where each ball was hit)"),
        "{err}"
    );
    // JSON rows too.
    let (out, _, _) = run(&["fly", "--batch", HOME_RUNS, "--json", "--summary"], b"");
    assert!(out.lines().all(|l| {
        let row: serde_json::Value = serde_json::from_str(l).unwrap();
        row.get("line").is_some()
    }));
}

#[test]
fn json_follows_units_with_the_unit_in_each_key() {
    let (si, _, _) = run(&["fly", "--batch", HOME_RUNS, "--json"], b"");
    let (imperial, _, _) = run(
        &["fly", "--batch", HOME_RUNS, "--json", "--units", "imperial"],
        b"",
    );
    let first = |text: &str| -> serde_json::Value {
        serde_json::from_str(text.lines().next().unwrap()).unwrap()
    };
    let (si, imperial) = (first(&si), first(&imperial));
    let range = si["flight"]["range"].as_f64().unwrap();
    let feet = imperial["flight"]["range_ft"].as_f64().unwrap();
    // The same number, converted (to the last bit or two).
    assert!((feet - range / 0.3048).abs() < 1e-12 * feet, "{feet}");
    let speed = si["launch"]["speed"].as_f64().unwrap();
    let mph = imperial["launch"]["speed_mph"].as_f64().unwrap();
    assert!((mph - speed / 0.44704).abs() < 1e-9, "{mph}");
    assert!(imperial["flight"].get("range").is_none());
    assert_eq!(imperial["line"], si["line"]);
}

#[test]
fn a_row_at_no_park_gets_no_verdict_and_the_summary_says_so() {
    // The second row lands foul (hc_x, hc_y: 60° right of centre): called
    // foul at no park, and counted so.
    let text = "launch_speed,launch_angle,hc_x,hc_y\n110,28,,\n90,40,225.42,140.54\n";
    let (out, err, status) = run(&["fly", "--batch", "-"], text.as_bytes());
    assert_eq!(status, 0, "{err}");
    let header: Vec<&str> = out.lines().next().unwrap().split(',').collect();
    let row: Vec<&str> = out.lines().nth(1).unwrap().split(',').collect();
    let cell = |name: &str| row[header.iter().position(|h| *h == name).unwrap()];
    assert_eq!(
        (
            cell("clears_fence"),
            cell("park"),
            cell("outcome"),
            cell("margin")
        ),
        ("", "none", "no_park", "")
    );
    let foul: Vec<&str> = out.lines().nth(2).unwrap().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();
    assert_eq!((foul[at("park")], foul[at("outcome")]), ("none", "foul"));
    assert!(
        err.contains("0 clear, 0 off the wall, 0 short, 1 foul, 1 at no park"),
        "{err}"
    );
    // With --park the same row is judged there.
    let (out, _, _) = run(&["fly", "--batch", "-", "--park", "COL"], text.as_bytes());
    assert!(out.lines().nth(1).unwrap().contains(",COL,"), "{out}");
}

#[test]
fn a_kept_column_named_as_an_output_column_is_not_repeated() {
    let text = "line,launch_speed,launch_angle\nfirst,100,30\n";
    let (out, _, status) = run(&["fly", "--batch", "-", "--keep", "line"], text.as_bytes());
    assert_eq!(status, 0);
    let header: Vec<&str> = out.lines().next().unwrap().split(',').collect();
    assert_eq!(header.iter().filter(|h| **h == "line").count(), 1);
    assert_eq!(header.last(), Some(&"kept.line"));
    assert!(out.lines().nth(1).unwrap().ends_with(",first"));
}

#[test]
fn gzip_reads_as_it_comes_and_parquet_is_named() {
    let text = sample();
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(text.as_bytes()).unwrap();
    let gz = gz.finish().unwrap();
    let (out, err, status) = run(&["fly", "--batch", "-"], &gz);
    assert_eq!(status, 0, "{err}");
    assert_eq!(out, run(&["fly", "--batch", HOME_RUNS], b"").0);
    let (out, err, status) = run(&["fly", "--batch", "-"], b"PAR1\x15\x04\x15\x10");
    assert_eq!((status, out.as_str()), (2, ""));
    assert!(err.contains("a Parquet file, not CSV text"), "{err}");
}

#[test]
fn a_byte_order_mark_split_across_reads_is_dropped_whole() {
    // The BOM's first byte alone, then the rest with a quoted first name.
    let mut child = command()
        .args(["fly", "--batch", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    input.write_all(b"\xef").unwrap();
    input.flush().unwrap();
    std::thread::sleep(std::time::Duration::from_millis(200));
    input
        .write_all(b"\xbb\xbf\"launch_speed\",launch_angle\n100,30\n")
        .unwrap();
    drop(input);
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(!err.contains("ignored"), "{err}");
    let row = String::from_utf8_lossy(&out.stdout);
    // 100 mph, as launch_speed gives it.
    assert!(
        row.lines().nth(1).unwrap().starts_with("2,44.7040,"),
        "{row}"
    );
}

#[test]
fn calibrate_by_month_reads_either_date_and_saves_a_preset_a_group() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().to_str().unwrap();
    // The sample's ISO dates written as M/D/YYYY.
    let us: Vec<String> = (sample().lines())
        .map(|line| match line.split_once("\",") {
            Some((date, rest)) if date.starts_with("\"20") => {
                let parts: Vec<u32> = date[1..].split('-').map(|p| p.parse().unwrap()).collect();
                format!("\"{}/{}/{}\",{rest}", parts[1], parts[2], parts[0])
            }
            _ => line.to_owned(),
        })
        .collect();
    let us = us.join("\n");
    assert!(us.contains("\"7/24/2019\""));
    let file = dir.path().join("us.csv");
    std::fs::write(&file, &us).unwrap();
    let out = command()
        .args([
            "--presets-dir",
            presets,
            "calibrate",
            file.to_str().unwrap(),
        ])
        .args(["--by", "month", "--drag-only", "--save", "hr"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Each month a group, each fitted one saved as a preset of its own; a
    // month too small is named, and the others still fitted.
    let fitted: Vec<&str> = (text.lines().skip(1))
        .filter(|l| l.contains("saved"))
        .map(|l| l.split_whitespace().next().unwrap())
        .collect();
    assert!(fitted.len() >= 3, "{text}");
    for month in &fitted {
        assert!(month.starts_with("2019-"), "{text}");
        assert!(
            dir.path().join(format!("hr-{month}.toml")).exists(),
            "{text}"
        );
    }
    // A date in neither form is named.
    std::fs::write(&file, us.replacen("\"7/24/2019\"", "\"yesterday\"", 1)).unwrap();
    let out = command()
        .args(["calibrate", file.to_str().unwrap(), "--by", "month"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("game_date = \"yesterday\": expected a date, YYYY-MM-DD or M/D/YYYY"),
        "{err}"
    );
    assert!(err.contains("line 2: game_date"), "{err}");
}

/// `calibrate`, in every mode, follows `fly --batch`'s rule: a row that
/// fails (a `game_date` that is no date, a `game_year` no season) is
/// named with why and skipped, the others are fitted and printed, and the
/// exit status is 1. A row merely without a launch is counted: status 0.
#[test]
fn calibrate_fits_the_other_rows_and_exits_1_when_a_row_failed() {
    let no_date = sample().replacen("\"2019-07-24\"", "\"2019-02-30\"", 1);
    let date_named =
        "line 2: game_date = \"2019-02-30\": expected a date, YYYY-MM-DD or M/D/YYYY; skipped";
    let no_season = sample().replacen("\"fly_ball\",2019,", "\"fly_ball\",2019.5,", 1);
    let season_named = "line 2: game_year = \"2019.5\": expected a whole year from 1800 to 2200";
    let modes: [(&[&str], &str, &str); 6] = [
        (&[], &no_date, date_named),
        (&["--drag-only", "--json"], &no_date, date_named),
        (&["--by", "month"], &no_date, date_named),
        (&["--by", "home_team", "--json"], &no_date, date_named),
        (&["--by", "season"], &no_season, season_named),
        (&["--by", "season", "--json"], &no_season, season_named),
    ];
    for (mode, text, named) in modes {
        let args = [&["calibrate", "-"][..], mode].concat();
        let (out, err, status) = run(&args, text.as_bytes());
        assert_eq!(status, 1, "{mode:?}: {err}");
        assert!(err.contains(named), "{mode:?}: {err}");
        assert!(
            err.contains("1 of 248 rows failed and were skipped (exit status 1)"),
            "{mode:?}: {err}"
        );
        assert!(out.contains("drag_scale"), "{mode:?}: {out}");
    }
    // The bat's fit too.
    let swings = std::fs::read_to_string("tests/data/savant_swings.csv").unwrap();
    let no_date = swings.replacen(",2024-04-03,", ",2024-02-30,", 1);
    let (out, err, status) = run(&["calibrate", "--impact", "-"], no_date.as_bytes());
    assert_eq!(status, 1, "{err}");
    assert!(err.contains("line 2: game_date = \"2024-02-30\""), "{err}");
    assert!(out.contains("(fitted: bat.effective_mass)"), "{out}");
    // A row without a launch (a pitch not put in play) is no failure.
    let pitch = format!("{}\"2019-07-24\"{}\n", sample(), ",".repeat(16));
    for mode in [&["--by", "month"][..], &[]] {
        let args = [&["calibrate", "-"][..], mode].concat();
        let (out, err, status) = run(&args, pitch.as_bytes());
        assert_eq!(status, 0, "{mode:?}: {err}");
        assert!(!err.contains("failed"), "{mode:?}: {err}");
        assert!(out.contains("1 skipped"), "{mode:?}: {out}");
    }
}

#[test]
fn a_fit_needs_ten_rows_grouped_or_not() {
    let text: String = sample().lines().take(6).collect::<Vec<_>>().join("\n");
    let (_, err, status) = run(&["calibrate", "-"], text.as_bytes());
    assert_eq!(status, 2);
    assert!(err.contains("too few to fit (at least 10"), "{err}");
}

/// Rows in range never give inf or NaN (issue 38, item 6): a swing as steep
/// as its tilt (attack_angle = swing_path_tilt = −60°) is told unsolved
/// without an infinite shortfall, and a pitch barely moving (vy0 =
/// −1e-300 ft/s) is refused with its range, not taken at 98,933 m/s.
#[test]
fn in_range_rows_give_no_inf_or_nan() {
    let text = std::fs::read_to_string("tests/data/savant_swings.csv").unwrap();
    let mut lines = text.lines();
    let mut steep = format!("{},attack_angle,swing_path_tilt\n", lines.next().unwrap());
    for line in lines {
        steep += &format!("{line},-60,-60\n");
    }
    let (out, err, status) = run(&["hit", "--batch", "-", "--json"], steep.as_bytes());
    assert_eq!(status, 0, "{err}");
    for line in out.lines() {
        let row: serde_json::Value = serde_json::from_str(line).unwrap();
        assert!(row["solved"].is_boolean(), "{row}");
        if let Some(shortfall) = row.get("shortfall") {
            assert!(shortfall.as_f64().is_some_and(f64::is_finite), "{row}");
        }
        assert!(!line.contains("inf") && !line.contains("NaN"), "{line}");
    }
    // The row's own vy0 renamed away, a new one at the end.
    let header = text
        .lines()
        .next()
        .unwrap()
        .replacen(",vy0,", ",vy0_measured,", 1);
    let row = text.lines().nth(1).unwrap();
    let input = format!("{header},vy0\n{row},-1e-300\n");
    let (out, err, status) = run(&["hit", "--batch", "-"], input.as_bytes());
    assert_eq!(status, 0, "{err}");
    assert_eq!(out.lines().count(), 2, "{out}");
    assert!(
        err.contains("vy0 = \"-1e-300\": expected a number from -250 to -20; its swing not solved"),
        "{err}"
    );
}

/// Every ball in play with a launch speed and angle gets an answer (issue
/// 35, item 7): Statcast's straight up and straight down (±90°, three rows
/// of June–September 2024) fly, land near the plate, and the run exits 0.
#[test]
fn straight_up_and_straight_down_are_answered() {
    let text = "launch_speed,launch_angle,hc_x,hc_y,stand,home_team\n\
                80,90,120,190,R,BOS\n70,-90,,,L,NYY\n80,89.99,120,190,R,BOS\n";
    let (out, err, status) = run(&["fly", "--batch", "-", "--json"], text.as_bytes());
    assert_eq!(status, 0, "{err}");
    let rows: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 3);
    for row in &rows {
        assert_eq!(row["flight"]["landed"], true, "{row}");
        assert_eq!(row["fence"]["outcome"], "foul", "{row}");
    }
    let range = |k: usize| rows[k]["flight"]["range"].as_f64().unwrap();
    // Straight down it meets the ground at once; straight up it comes down
    // as 89.99° does, a stride away.
    assert!(range(1) < 0.01, "{}", range(1));
    assert!(
        (range(0) - range(2)).abs() < 0.1,
        "{} {}",
        range(0),
        range(2)
    );
}

/// A header after blank lines is named by its own line, and a distance no
/// field has (1e308 ft) is missing, never 309 digits (issue 38).
#[test]
fn the_header_is_named_by_its_line_and_an_absurd_distance_is_missing() {
    let (_, err, status) = run(&["fly", "--batch", "-"], b"\n\nlaunch_speed,pitch\n100,3\n");
    assert_eq!(status, 2);
    assert!(
        err.contains("line 3 (the header): no launch angle column"),
        "{err}"
    );
    let text = "launch_speed,launch_angle,hit_distance_sc\n100,30,1e308\n";
    let (out, err, status) = run(&["fly", "--batch", "-"], text.as_bytes());
    assert_eq!(status, 0, "{err}");
    let row = out.lines().nth(1).unwrap();
    assert!(row.ends_with(",,") && row.len() < 200, "{row}");
}

/// `calibrate --impact` names and counts the rows it skips, as every
/// command does (issue 38, item 5): a row too short, a cell no number.
#[test]
fn calibrate_impact_names_the_rows_it_skips() {
    let mut text = std::fs::read_to_string("tests/data/savant_swings.csv").unwrap();
    let rows = text.lines().count();
    text += "1,2,3\n";
    let (out, err, status) = run(&["calibrate", "--impact", "-"], text.as_bytes());
    // The fit stands on the other rows; the one failed makes the status 1.
    assert_eq!(status, 1, "{err}");
    assert!(
        err.contains(&format!(
            "1 of {rows} rows failed and were skipped (exit status 1)"
        )),
        "{err}"
    );
    let line = rows + 1;
    assert!(
        err.contains(&format!("line {line}: 3 fields where the header has")),
        "{err}"
    );
    assert!(
        out.contains("skipped 1 row: 1 failed (named above)"),
        "{out}"
    );
}

/// A Trackman or Yakkertech file names a college or summer team in
/// HomeTeam and "Undefined" in BatterSide: each such ball is answered (at
/// no park, its spin estimated as either side's average), counted and
/// named in the summary, where every such row was refused before and the
/// whole file gave nothing (exit 1). A side that is no side at all is
/// still refused, naming it.
#[test]
fn a_league_team_and_an_undefined_side_are_answered_at_no_park() {
    let text = "ExitSpeed,Angle,Direction,BatterSide,HomeTeam\n\
                95,28,10,Right,LIN_POT\n\
                95,28,10,Undefined,LIN_POT\n\
                95,28,10,Left,BOS\n";
    let (out, err, status) = run(&["fly", "--batch", "-"], text.as_bytes());
    assert_eq!(status, 0, "{err}");
    let rows: Vec<Vec<&str>> = out.lines().map(|l| l.split(',').collect()).collect();
    let column = |name: &str| rows[0].iter().position(|c| *c == name).unwrap();
    let (park, outcome) = (column("park"), column("outcome"));
    let shown: Vec<(&str, &str)> = rows[1..].iter().map(|r| (r[park], r[outcome])).collect();
    assert_eq!(shown[..2], [("none", "no_park"), ("none", "no_park")]);
    assert_eq!(shown[2].0, "BOS");
    // The undefined side averages the two: its sidespin lies halfway.
    let sidespin = column("launch.sidespin");
    let spins: Vec<f64> = rows[1..]
        .iter()
        .map(|r| r[sidespin].parse().unwrap())
        .collect();
    assert!(spins[0] > spins[2] + 100.0, "{spins:?}");
    assert!(
        (spins[1] - 0.5 * (spins[0] + spins[2])).abs() < 0.01,
        "{spins:?}"
    );
    assert!(
        err.contains("1 row whose batter's side is not known (no stand, or Undefined or Switch)"),
        "{err}"
    );
    assert!(
        err.contains("2 rows whose home_team no park answers to (LIN_POT) at no park"),
        "{err}"
    );
    // The summary file counts them as the text does.
    let (summary, err, status) = summary_of(text.as_bytes());
    assert_eq!(status, 0, "{err}");
    assert_eq!(summary["side_unknown"], 1);
    assert_eq!(summary["at_unknown_park"], 2);
    assert!(summary.get("spray_unsolved").is_none());
    // No side at all is the same average, counted; a row that gives its
    // spin estimates none and is not.
    let no_side = "launch_speed,launch_angle,spin_rpm\n95,28,\n95,28,2500\n";
    let (_, err, status) = run(&["fly", "--batch", "-"], no_side.as_bytes());
    assert_eq!(status, 0, "{err}");
    assert!(
        err.contains("1 row whose batter's side is not known"),
        "{err}"
    );
    let nonsense = text.replace("Undefined", "X9");
    let (_, err, status) = run(&["fly", "--batch", "-"], nonsense.as_bytes());
    assert_eq!(status, 1, "{err}");
    assert!(err.contains("stand = \"X9\": expected R or L"), "{err}");
}

/// The summary compares against the distance column the file has, by the
/// file's name for it (Trackman's `Distance`), not Savant's.
#[test]
fn the_summary_names_the_files_distance_column() {
    let text = "ExitSpeed,Angle,Direction,Distance\n95,28,10,120\n100,30,-5,130\n";
    let (_, err, status) = run(&["fly", "--batch", "-", "--summary"], text.as_bytes());
    assert_eq!(status, 0, "{err}");
    assert!(err.contains("; against Distance (2 rows): median"), "{err}");
    assert!(
        err.contains("by launch angle, model − Distance (m):"),
        "{err}"
    );
    assert!(!err.contains("hit_distance_sc"), "{err}");
}
