//! `--units imperial`: the text and CSV of the real binary in mph, ft, in,
//! rpm and degrees, the same physics as in SI; JSON unchanged.

use crate::common;
use common::homerun;
use std::path::Path;

use serde_json::Value;

fn stdout(presets: &Path, args: &[&str]) -> String {
    let output = homerun(presets, args);
    assert!(output.status.success(), "{args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}

fn json(presets: &Path, args: &[&str]) -> Value {
    serde_json::from_str(&stdout(presets, args)).unwrap()
}

/// The number just before `unit` in `text` ("441.925 ft" → 441.925), and
/// how many decimals it was printed with.
fn before(text: &str, unit: &str) -> (f64, usize) {
    let at = text
        .find(unit)
        .unwrap_or_else(|| panic!("no {unit:?} in {text}"));
    let number = text[..at].trim_end().rsplit(' ').next().unwrap();
    let decimals = number.split_once('.').map_or(0, |(_, d)| d.len());
    (number.parse().unwrap(), decimals)
}

const FOOT: f64 = 0.3048;
const MPH: f64 = 0.44704;

#[test]
fn hit_in_imperial_is_the_si_flight_in_feet_mph_rpm_and_degrees() {
    let dir = tempfile::tempdir().unwrap();
    let text = stdout(dir.path(), &["hit", "--units", "imperial"]);
    let si = json(dir.path(), &["hit", "--json"]);
    let flight = text.lines().find(|l| l.starts_with("flight")).unwrap();
    // The range: 134.699 m is 441.926 ft; printed to the foot's thousandth
    // of the unrounded range.
    let range = si["flight"]["range"].as_f64().unwrap();
    assert!((range - 134.699).abs() < 5e-4, "{range}");
    let (feet, decimals) = before(flight, " ft in");
    assert_eq!(decimals, 3, "{flight}");
    assert_eq!(format!("{feet:.3}"), format!("{:.3}", range / FOOT));
    assert!((feet - 134.699 / FOOT).abs() < 2e-3, "{flight}");
    // The launch as Statcast gives it: 44.299 m/s is 99.1 mph, 191.83 rad/s
    // is 1832 rpm, 0.4604 rad is 26.4°.
    let launch = text.lines().find(|l| l.starts_with("launch")).unwrap();
    let (mph, _) = before(launch, " mph");
    let speed = si["impact"]["launch_speed"].as_f64().unwrap();
    assert!((mph - speed / MPH).abs() <= 0.05, "{launch}");
    assert!(launch.contains("99.1 mph"), "{launch}");
    let (rpm, _) = before(launch, " rpm of backspin");
    let spin = si["impact"]["launch_spin"].as_f64().unwrap();
    assert!((rpm - spin * 60.0 / (2.0 * std::f64::consts::PI)).abs() <= 0.5);
    assert_eq!(rpm, 1832.0, "{launch}");
    assert!(launch.ends_with(", 26.4°"), "{launch}");
    // Angles in degrees only: no radians anywhere in the imperial text.
    assert!(!text.contains(" rad"), "{text}");
    assert!(text.contains("ψ = 9.13°"), "{text}");
}

#[test]
fn the_fly_ball_preset_reads_back_as_its_launch() {
    let dir = tempfile::tempdir().unwrap();
    let text = stdout(
        dir.path(),
        &["fly", "--preset", "fly-ball", "--units", "imperial"],
    );
    assert!(
        text.starts_with("launch   103.0 mph, 2500 rpm of backspin, 28.0°\n"),
        "{text}"
    );
    // The default fence, 121.9 m and 3.0 m, in feet: as given, 400 ft,
    // and in the explorer's words.
    assert!(
        text.contains("fence    400 ft, 10 ft high: over by "),
        "{text}"
    );
}

#[test]
fn json_is_si_whatever_the_units() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["hit", "--json"][..],
        &["fly", "--preset", "fly-ball", "--json"],
        &["trajectory", "--samples", "5", "--json"],
        &["surface", "--grid", "3x2", "--json"],
        &["figure", "13", "--json"],
    ] {
        let mut imperial = args.to_vec();
        imperial.extend(["--units", "imperial"]);
        assert_eq!(
            stdout(dir.path(), args),
            stdout(dir.path(), &imperial),
            "{args:?}"
        );
    }
}

#[test]
fn si_is_the_default_and_prints_as_without_the_option() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["hit"][..],
        &["keys"],
        &["trajectory", "--samples", "4", "--csv"],
    ] {
        let mut si = args.to_vec();
        si.extend(["--units", "si"]);
        assert_eq!(
            stdout(dir.path(), args),
            stdout(dir.path(), &si),
            "{args:?}"
        );
    }
}

#[test]
fn an_unknown_system_is_one_line_naming_the_accepted_ones() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["hit", "--units", "furlongs"][..],
        &["--units", "furlongs", "keys"],
    ] {
        let output = homerun(dir.path(), args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(output.stdout.is_empty());
        let err = String::from_utf8(output.stderr).unwrap();
        assert_eq!(
            err, "homerun: --units 'furlongs': must be si or imperial\n",
            "{args:?}"
        );
    }
}

#[test]
fn keys_gives_ranges_and_values_in_the_units_shown() {
    let dir = tempfile::tempdir().unwrap();
    let text = stdout(dir.path(), &["keys", "--units", "imperial"]);
    let line = |key: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("{key} ")))
            .unwrap_or_else(|| panic!("no {key} in {text}"))
            .split_whitespace()
            .collect::<Vec<_>>()
    };
    // pitch.speed in (0, 100] m/s is (0, 223.693] mph (223.694 mph would be
    // 100.0003 m/s); the fastball's 42 m/s is 93.951 mph.
    let speed = line("pitch.speed");
    assert_eq!(
        speed[2..6],
        ["mph", "(0,", "223.693]", "93.951"],
        "{speed:?}"
    );
    assert!((100.0 / MPH - 223.694).abs() < 5e-4);
    assert_eq!(line("launch.angle")[2..5], ["°", "[-90,", "90]"]);
    assert_eq!(
        line("environment.temperature")[2..6],
        ["°F", "[-58,", "140]", "59"]
    );
    assert_eq!(line("field.fence_distance")[1..2], ["ft"]);
    // ρ has no imperial unit here: kg/m³ as in SI.
    assert_eq!(line("environment.air_density")[2..4], ["kg/m³", "[0,"]);
    assert!(
        text.contains("--set and presets take a bare number in"),
        "{text}"
    );
}

#[test]
fn csv_headers_carry_the_units_and_the_numbers_convert() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["trajectory", "--samples", "3", "--csv"];
    let si = stdout(dir.path(), &args);
    let imperial = stdout(dir.path(), &[&args[..], &["--units", "imperial"]].concat());
    assert!(si.starts_with("time,x,y,z,drag_coefficient\n"), "{si}");
    assert!(
        imperial.starts_with("time,x_ft,y_ft,z_ft,drag_coefficient\n"),
        "{imperial}"
    );
    let last = |csv: &str| -> Vec<f64> {
        let line = csv.lines().last().unwrap();
        line.split(',').map(|f| f.parse().unwrap()).collect()
    };
    let (m, ft) = (last(&si), last(&imperial));
    assert_eq!(m[0], ft[0]);
    assert!((ft[1] * FOOT - m[1]).abs() < 1e-9 * m[1], "{m:?} {ft:?}");

    let batch = dir.path().join("launches.csv");
    std::fs::write(&batch, "launch_speed,launch_angle,spin_rpm\n103,28,2500\n").unwrap();
    let out = stdout(
        dir.path(),
        &[
            "fly",
            "--batch",
            batch.to_str().unwrap(),
            "--units",
            "imperial",
        ],
    );
    let mut lines = out.lines();
    assert_eq!(
        lines.next().unwrap(),
        "line,launch.speed_mph,launch.angle_deg,launch.spin_rpm,launch.direction_deg,launch.sidespin_rpm,range_ft,direction_deg,flight_time,apex_ft,landing_angle_deg,landed,clears_fence,park,outcome,margin_ft,parks_cleared,spin_estimated,direction_from"
    );
    assert!(lines.next().unwrap().starts_with("2,103.0,28.0,2500.0,"));
}

#[test]
fn sweep_bounds_are_given_and_checked_in_the_units_shown() {
    let dir = tempfile::tempdir().unwrap();
    // 60 and 70 mph of bat speed: the column reads back what was typed.
    let text = stdout(
        dir.path(),
        &[
            "sweep",
            "bat.speed",
            "--from",
            "60",
            "--to",
            "70",
            "--steps",
            "2",
            "--units",
            "imperial",
        ],
    );
    let mut lines = text.lines();
    assert!(lines.next().unwrap().contains("bat.speed (mph)"), "{text}");
    let first: Vec<&str> = lines.next().unwrap().split_whitespace().collect();
    assert_eq!(first[0], "60", "{text}");
    // 300 mph is beyond the 100 m/s bound: refused in mph, before any work.
    let output = homerun(
        dir.path(),
        &[
            "sweep",
            "bat.speed",
            "--from",
            "60",
            "--to",
            "300",
            "--units",
            "imperial",
        ],
    );
    assert_eq!(output.status.code(), Some(2));
    assert_eq!(
        String::from_utf8(output.stderr).unwrap(),
        "homerun: --to 300: bat.speed must be a finite number in (0, 223.693] mph\n"
    );
}

/// Each imperial CSV heading is the command's own SI heading, with the unit
/// appended where the column converts: a figure names its columns as its
/// JSON does (`bat_speed`), a sweep names the key as typed (`bat.speed`).
#[test]
fn imperial_csv_headings_are_the_si_ones_with_their_units() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = [
        "sweep",
        "bat.speed",
        "--from",
        "60",
        "--to",
        "70",
        "--steps",
        "1",
        "--csv",
    ];
    for (args, swept) in [
        (&["figure", "8", "--csv"][..], "bat_speed"),
        (&sweep[..], "bat.speed"),
    ] {
        let heading = |units: &str| -> Vec<String> {
            let csv = stdout(dir.path(), &[args, &["--units", units]].concat());
            let line = csv.lines().next().unwrap().to_owned();
            line.split(',').map(str::to_owned).collect()
        };
        let (si, imperial) = (heading("si"), heading("imperial"));
        assert_eq!(si[0], swept, "{args:?}");
        assert_eq!(imperial[0], format!("{swept}_mph"), "{args:?}");
        assert_eq!(si.len(), imperial.len(), "{si:?} {imperial:?}");
        for (si, imperial) in si.iter().zip(&imperial) {
            let unit = imperial.strip_prefix(si.as_str()).unwrap_or("?");
            assert!(
                ["", "_ft", "_in", "_mph", "_rpm", "_deg"].contains(&unit),
                "{args:?}: {si} became {imperial}"
            );
        }
    }
}

/// Issue 28, item 12: a Savant export's batch in the file's units reads as
/// the file wrote them (99.9 mph, not 99.9000), its keys carrying their
/// unit; and one summary closes the batch, on stderr or with --summary
/// after the rows: rows flown and skipped, outcomes at the park, the
/// error against hit_distance_sc.
#[test]
fn a_savant_batch_prints_its_units_and_one_summary() {
    let run = |args: &[&str]| {
        let out = common::assert_command().args(args).output().unwrap();
        assert!(out.status.success(), "{args:?}: {out:?}");
        (
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        )
    };
    let file = "tests/data/savant_home_runs.csv";
    let (out, err) = run(&[
        "fly", "--units", "imperial", "--park", "BOS", "--batch", file,
    ]);
    let mut lines = out.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[1], "launch.speed_mph");
    let first: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!((first[1], first[2]), ("99.9", "36.0"));
    let summary: Vec<&str> = err.lines().filter(|l| l.contains("summary:")).collect();
    assert_eq!(summary.len(), 1, "{err}");
    assert!(
        summary[0].starts_with(
            "homerun: summary: flown 248 rows, skipped 0; at BOS (in its air; parks_cleared: each park in its own air): 169 clear, 39 off the wall, 37 short, 3 foul; against hit_distance_sc (245 rows): median difference "
        ),
        "{}",
        summary[0]
    );
    // At --park the difference is another park's air against where each
    // ball was hit (13 at Coors among them), and says so.
    assert!(
        summary[0].ends_with(" ft (flown in BOS's air, hit_distance_sc where each ball was hit)"),
        "{}",
        summary[0]
    );
    // stdout holds the rows alone; the summary and its tables go to stderr.
    let (out, err) = run(&["fly", "--park", "BOS", "--summary", "--batch", file]);
    assert!(!out.contains("summary:"), "{out}");
    let rows_out: Vec<&str> = out.lines().collect();
    let lines: Vec<&str> = err.lines().collect();
    let summary = lines.iter().find(|l| l.contains("summary: flown")).unwrap();
    assert!(
        summary.starts_with("homerun: summary: flown 248 rows"),
        "{summary}"
    );
    assert!(
        summary.ends_with(" m (flown in BOS's air, hit_distance_sc where each ball was hit)"),
        "{summary}"
    );
    // Issue 26, item 4: then the error by launch-angle band, each band's
    // median the median of its rows' `difference`.
    let at = (lines.iter())
        .position(|l| *l == "by launch angle, model − hit_distance_sc (m):")
        .unwrap()
        - 1;
    let header: Vec<&str> = rows_out[0].split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (angle, difference) = (column("launch.angle"), column("difference"));
    let rows: Vec<(f64, f64)> = (rows_out[1..].iter())
        .map(|l| l.split(',').collect::<Vec<&str>>())
        .filter(|cells| !cells[difference].is_empty())
        .map(|cells| {
            // The file's whole degrees, through the printed radians' 6 decimals.
            let radians: f64 = cells[angle].parse().unwrap();
            let degrees = (radians.to_degrees() * 1e3).round() / 1e3;
            (degrees, cells[difference].parse().unwrap())
        })
        .collect();
    // Rows and median ("-" for none) of a band's line.
    let band = |line: &str| -> (usize, Option<f64>) {
        let cells: Vec<&str> = line.split_whitespace().collect();
        (
            cells[cells.len() - 3].parse().unwrap(),
            cells[cells.len() - 2].parse().ok(),
        )
    };
    let mut in_25_to_30: Vec<f64> = (rows.iter())
        .filter(|(a, _)| (25.0..30.0).contains(a))
        .map(|r| r.1)
        .collect();
    in_25_to_30.sort_by(f64::total_cmp);
    let n = in_25_to_30.len();
    let median = (in_25_to_30[(n - 1) / 2] + in_25_to_30[n / 2]) / 2.0;
    let row = lines.iter().find(|l| l.starts_with("25–30°")).unwrap();
    assert_eq!(band(row).0, n);
    // The table's one decimal against the rows' two.
    assert!(
        (band(row).1.unwrap() - median).abs() <= 0.06,
        "{row}: {median}"
    );
    let kinds = at
        + lines[at..]
            .iter()
            .position(|l| l.starts_with("by kind"))
            .unwrap();
    let counted: usize = lines[at + 3..kinds].iter().map(|l| band(l).0).sum();
    assert_eq!(counted, rows.len());
    assert_eq!(rows.len(), 245);
    // Issue 26's table by kind: every row of this file is a home run, so
    // its home-run line holds every row at 10° and up, and its verdict is
    // the summary's 169 that clear.
    let mut homers: Vec<f64> = (rows.iter().filter(|(a, _)| *a >= 10.0))
        .map(|r| r.1)
        .collect();
    homers.sort_by(f64::total_cmp);
    let n = homers.len();
    let median = (homers[(n - 1) / 2] + homers[n / 2]) / 2.0;
    let row = lines[kinds..]
        .iter()
        .find(|l| l.starts_with("home runs "))
        .unwrap();
    assert_eq!(band(row).0, n);
    assert!(
        (band(row).1.unwrap() - median).abs() <= 0.06,
        "{row}: {median}"
    );
    assert_eq!(
        lines.last().unwrap(),
        &"home runs that clear the fence they are judged at: 169 of 248 (68.1 %)"
    );
}
