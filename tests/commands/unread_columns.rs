//! Columns no one would mean to go unread: a spray angle or a weather
//! column of its own name, with nothing that reads it, is refused with the
//! mapping to give (issue 35: never a silently wrong answer).

use super::pipeline::{run, sample, summary_of};

/// `homerun fly --batch -` with `args` after, `stdin` piped in: (stdout,
/// stderr, status).
fn fly(args: &[&str], stdin: &str) -> (String, String, i32) {
    let all: Vec<&str> = ["fly", "--batch", "-"]
        .iter()
        .chain(args)
        .copied()
        .collect();
    run(&all, stdin.as_bytes())
}

/// A spray angle kept as its own column (hc_x and hc_y dropped, or a
/// tracker's Bearing) and no direction read: every row would fly to centre
/// field, so the file is refused with the mappings to choose from. Mapped
/// as the landing bearing, each row lands on it, as on the spray its hit
/// coordinates give.
#[test]
fn a_spray_angle_no_column_reads_is_refused_until_mapped() {
    // A record's cells (the sample quotes names and descriptions).
    let cells = |line: &str| -> Vec<String> {
        let (mut cells, mut cell, mut quoted) = (Vec::new(), String::new(), false);
        for c in line.chars() {
            match c {
                '"' => quoted = !quoted,
                ',' if !quoted => cells.push(std::mem::take(&mut cell)),
                c => cell.push(c),
            }
        }
        cells.push(cell);
        cells
    };
    let text = sample();
    let mut lines = text.lines();
    let header = cells(lines.next().unwrap());
    let at = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (x, y, speed, angle, stand) = (
        at("hc_x"),
        at("hc_y"),
        at("launch_speed"),
        at("launch_angle"),
        at("stand"),
    );
    // The sample's first rows as launch, side and spray angle (°).
    let mut spray = String::from("launch_speed,launch_angle,stand,spray_angle\n");
    let mut kept = String::from("launch_speed,launch_angle,stand,hc_x,hc_y\n");
    let rows = lines.map(cells).filter(|row| row[x].parse::<f64>().is_ok());
    for row in rows.take(6) {
        let (hc_x, hc_y): (f64, f64) = (row[x].parse().unwrap(), row[y].parse().unwrap());
        let degrees = ((hc_x - 125.42) / (198.27 - hc_y)).atan().to_degrees();
        let launch = format!("{},{},{}", row[speed], row[angle], row[stand]);
        spray += &format!("{launch},{degrees}\n");
        kept += &format!("{launch},{hc_x},{hc_y}\n");
    }
    let (out, err, status) = fly(&[], &spray);
    assert_eq!(status, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains(
            "column `spray_angle` looks like a direction, but no column gives one, so every \
             row would fly to centre field: map it, --column landing_bearing=spray_angle"
        ),
        "{err}"
    );
    let args = ["--json", "--column", "landing_bearing=spray_angle"];
    let (mapped, err, status) = fly(&args, &spray);
    assert_eq!(status, 0, "{err}");
    let (from_coordinates, err, status) = fly(&["--json"], &kept);
    assert_eq!(status, 0, "{err}");
    let direction = |line: &str| {
        let row: serde_json::Value = serde_json::from_str(line).unwrap();
        assert_eq!(row["direction_from"], "landing", "{row}");
        row["flight"]["direction"].as_f64().unwrap()
    };
    for (a, b) in mapped.lines().zip(from_coordinates.lines()) {
        // The same bearing, read two ways (°, or by hit coordinates).
        assert!((direction(a) - direction(b)).abs() < 2e-4, "{a}\n{b}");
    }
    assert_eq!(mapped.lines().count(), 6);
    // A direction given for every row answers it too.
    let args = ["--set", "launch.direction=0"];
    let (_, err, status) = fly(&args, &spray);
    assert_eq!(status, 0, "{err}");
    // Both hit coordinates and a landing bearing: one too many.
    let both = "launch_speed,launch_angle,hc_x,hc_y,landing_bearing\n100,25,100,80,10\n";
    let (_, err, status) = fly(&[], both);
    assert_eq!(status, 2, "{err}");
    assert!(
        err.contains("columns hc_x/hc_y and landing_bearing both give"),
        "{err}"
    );
    let far = "launch_speed,launch_angle,landing_bearing\n100,25,200\n";
    let (_, err, status) = fly(&[], far);
    assert_eq!(status, 1, "{err}");
    assert!(
        err.contains(r#"landing_bearing = "200": expected -180 to 180° (+ toward right field)"#),
        "{err}"
    );
}

/// A weather column of its own name (`temperature`, `wind_speed`) that no
/// column reads: every row would fly in the standard air, so the file is
/// refused naming the key to map it to and the units it takes. Mapped with
/// its unit, its cells are read as that key's (a bare number in that unit,
/// a cell with its unit in it); `--column ignore=COLUMN` says it is meant
/// to go unread.
#[test]
fn a_weather_column_no_column_reads_is_refused_until_mapped_or_ignored() {
    let text = "launch_speed,launch_angle,temperature,wind_speed\n105,28,75F,0\n";
    let (out, err, status) = fly(&[], text);
    assert_eq!(status, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains(
            "column `temperature` looks like weather, but no column reads it, so every row \
             would fly in its park's standard air (or the preset's): map it to its key, \
             --column environment.temperature=temperature:UNIT with the unit of its bare \
             numbers (C, °C, F, °F, K)"
        ) && err.contains("--column ignore=temperature to fly without it"),
        "{err}"
    );
    let temperature = "environment.temperature=temperature:C";
    let (_, err, status) = fly(&["--column", temperature], text);
    assert_eq!(status, 2, "{err}");
    assert!(
        err.contains(
            "--column environment.wind=wind_speed:UNIT with the unit of its bare \
             numbers (m/s, km/h, mph, ft/s)"
        ),
        "{err}"
    );
    // Mapped: 75 °F is read as it says, and the ball carries farther than
    // in the preset's 15 °C; ignored: the preset's air. A bare 75 in a
    // column mapped as °F is that 75F, to the bit.
    let bare = text.replace("75F", "75");
    let range = |input: &str, temperature: &str, wind: &str| {
        let args = [
            "--json",
            "--column",
            temperature,
            "--column",
            wind,
            "--set",
            "environment.wind_direction=0",
        ];
        let (out, err, status) = fly(&args, input);
        assert_eq!(status, 0, "{err}");
        let row: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
        row["flight"]["range"].as_f64().unwrap()
    };
    let mapped = range(text, temperature, "environment.wind=wind_speed:mph");
    let ignored = range(text, "ignore=temperature", "ignore=wind_speed");
    assert!(mapped > ignored + 0.5, "{mapped} {ignored}");
    let in_fahrenheit = "environment.temperature=temperature:F";
    assert_eq!(
        range(&bare, in_fahrenheit, "ignore=wind_speed"),
        range(text, temperature, "ignore=wind_speed")
    );
    // A unit of another quantity, or on a column whose cells take none, is
    // one line.
    for (mapping, needle) in [
        (
            "environment.temperature=temperature:mph",
            "`mph` is no unit of a temperature; it takes",
        ),
        (
            "launch_speed=temperature:F",
            "`F` is no unit of a speed; it takes",
        ),
        (
            "stand=temperature:F",
            "a unit is given only to a key's column (`homerun keys`) or to a measurement's",
        ),
    ] {
        let (_, err, status) = fly(&["--column", mapping], &bare);
        assert_eq!(status, 2, "{err}");
        assert!(err.contains(needle), "{err}");
    }
}

/// Another column mapped to a number key of more units than one, without
/// its unit: read as SI, a 55 °F day would pass for 55 °C and a 50-mph
/// launch for 50 m/s, both in range. The mapping is refused until it says
/// the unit; with it, a bare number flies as the same number with that
/// unit in its cell.
#[test]
fn a_key_column_mapped_without_its_unit_is_refused() {
    let text = "EV,LA,temp\n50,25,55\n";
    for (mapping, needle) in [
        (
            "launch.speed=EV",
            "--column launch.speed=EV: say the unit of its bare numbers, --column \
             launch.speed=EV:UNIT with UNIT one of m/s, km/h, mph, ft/s (a bare number is read \
             in m/s only in a column named launch.speed)",
        ),
        (
            "environment.temperature=temp",
            "UNIT with UNIT one of C, °C, F, °F, K (a bare number is read in °C",
        ),
    ] {
        let mut args = vec!["--column", mapping];
        args.extend(["--column", "launch.angle=LA:deg", "--column"]);
        args.push(match mapping.starts_with("launch") {
            true => "ignore=temp",
            false => "launch.speed=EV:mph",
        });
        let (out, err, status) = fly(&args, text);
        assert_eq!(status, 2, "{err}");
        assert!(out.is_empty() && err.contains(needle), "{err}");
    }
    let flown = |input: &str, speed: &str| {
        let args = [
            "--json",
            "--column",
            speed,
            "--column",
            "launch.angle=LA:deg",
            "--column",
            "ignore=temp",
        ];
        let (out, err, status) = fly(&args, input);
        assert_eq!(status, 0, "{err}");
        let row: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
        (
            row["launch"]["speed"].as_f64().unwrap(),
            row["flight"]["range"].as_f64().unwrap(),
        )
    };
    let (speed, range) = flown(text, "launch.speed=EV:mph");
    assert_eq!(speed, 50.0 * 0.44704);
    assert_eq!(
        (speed, range),
        flown("EV,LA,temp\n50mph,25,55\n", "launch.speed=EV:mph")
    );
    // A cell with its own unit keeps it, whatever the mapping's.
    assert_eq!(
        flown("EV,LA,temp\n80.4672km/h,25,55\n", "launch.speed=EV:mph").0,
        speed
    );
}

/// A wind's speed mapped from another column with nothing saying where it
/// blows: every row's wind would blow toward centre field. Refused until a
/// column or `--set` gives the direction.
#[test]
fn a_mapped_wind_without_its_direction_is_refused() {
    let text = "launch_speed,launch_angle,wind_speed,wind_toward\n100,28,10,90\n";
    let wind = ["--column", "environment.wind=wind_speed:mph"];
    let run_with = |extra: &[&str]| {
        let mut args = vec!["--json"];
        args.extend(wind);
        args.extend(extra);
        fly(&args, text)
    };
    let (out, err, status) = run_with(&["--column", "ignore=wind_toward"]);
    assert_eq!(status, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains(
            "--column environment.wind=wind_speed:mph: no column says where that wind blows, so \
             every row's would blow toward centre field: map one, --column \
             environment.wind_direction=COLUMN:UNIT"
        ) && err.contains("--set environment.wind_direction=0 for centre field"),
        "{err}"
    );
    let direction = |(out, err, status): (String, String, i32)| {
        assert_eq!(status, 0, "{err}");
        let row: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
        row["flight"]["direction"].as_f64().unwrap()
    };
    let set = [
        "--column",
        "ignore=wind_toward",
        "--set",
        "environment.wind_direction=0",
    ];
    let mapped = ["--column", "environment.wind_direction=wind_toward:deg"];
    // Toward centre field the ball keeps its line; blowing toward right
    // field (+90°) it is carried that way.
    let (centre, right) = (direction(run_with(&set)), direction(run_with(&mapped)));
    assert!(centre.abs() < 1e-9 && right > 0.01, "{centre} {right}");
}

/// Savant's columns that look like a launch value and are something else
/// (`launch_speed_angle`, Savant's contact class 1–6; `bat_speed`;
/// `attack_angle`) are never suggested for the launch, and are refused
/// as one: mapped, every ball would fly at 1–6° or at the bat's speed.
/// A name that holds the one looked for (`exit_angle`) is suggested first.
#[test]
fn a_lookalike_column_is_never_suggested_or_read_as_the_launch() {
    let text = "EV,bat_speed,launch_speed_angle,attack_angle,exit_angle,stand\n100,70,6,10,28,R\n";
    let (out, err, status) = fly(&[], text);
    assert_eq!(status, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("did you mean `exit_angle` or `EV`? (--column NAME=COLUMN maps one)"),
        "{err}"
    );
    for (mapping, what) in [
        (
            "launch_angle=launch_speed_angle",
            "`launch_speed_angle` is Savant's contact class (1 weak to 6 barrel), not launch_angle",
        ),
        (
            "launch.speed=bat_speed:mph",
            "`bat_speed` is the bat's speed (bat tracking), not launch.speed",
        ),
        (
            "launch_angle=attack_angle",
            "`attack_angle` is the bat's path at contact (bat tracking), not launch_angle",
        ),
    ] {
        let args = ["--column", mapping];
        let (out, err, status) = fly(&args, text);
        assert_eq!(status, 2, "{err}");
        assert!(out.is_empty() && err.contains(what), "{err}");
    }
    let args = [
        "--column",
        "launch_speed=EV",
        "--column",
        "launch_angle=exit_angle",
    ];
    let (out, err, status) = fly(&args, text);
    assert_eq!(status, 0, "{err}");
    assert_eq!(out.lines().count(), 2);
}

/// A measurement's column of the table (Statcast's mph, ° and ft) mapped
/// from a file in other units says them: an exit speed in km/h and a
/// distance in metres fly and compare as the same row in Statcast's units.
#[test]
fn a_measurement_mapped_with_its_unit_is_read_in_it() {
    let statcast = "launch_speed,launch_angle,hit_distance_sc\n100,28,393.7\n";
    let metric = "EV,LA,dist\n160.9344,28,120\n";
    let flown = |text: &str, args: &[&str]| {
        let mut all = vec!["--json"];
        all.extend(args);
        let (out, err, status) = fly(&all, text);
        assert_eq!(status, 0, "{err}");
        serde_json::from_str::<serde_json::Value>(out.trim()).unwrap()
    };
    let a = flown(statcast, &[]);
    let mapped = [
        "--column",
        "launch_speed=EV:km/h",
        "--column",
        "launch_angle=LA",
        "--column",
        "hit_distance_sc=dist:m",
    ];
    let b = flown(metric, &mapped);
    let speed = |v: &serde_json::Value| v["launch"]["speed"].as_f64().unwrap();
    assert!((speed(&a) - speed(&b)).abs() < 1e-9, "{a} {b}");
    let distance = |v: &serde_json::Value| v["statcast"]["distance"].as_f64().unwrap();
    assert!((distance(&a) - 393.7 * 0.3048).abs() < 1e-9);
    assert_eq!(distance(&b), 120.0);
}

/// An exit speed past any batted ball's (130 mph; Statcast's fastest are
/// under 123) is a column in another unit, as a metric Trackman export's
/// km/h under the same `ExitSpeed`: the row is refused naming the mapping
/// that reads it, and mapped so, the file flies.
#[test]
fn an_exit_speed_past_any_batted_balls_names_the_km_h_mapping() {
    let metric = "ExitSpeed,Angle\n158.3,28\n120,20\n";
    let (out, err, status) = fly(&[], metric);
    assert_eq!(status, 1, "{err}");
    assert_eq!(out.lines().count(), 2, "{out}");
    assert!(
        err.contains(
            "line 2: ExitSpeed = \"158.3\": 158.3 mph, faster than any batted ball measured (130 \
             mph at most); a column in km/h is mapped so: --column launch_speed=ExitSpeed:km/h"
        ),
        "{err}"
    );
    let args = ["--column", "launch_speed=ExitSpeed:km/h"];
    let (out, err, status) = fly(&args, metric);
    assert_eq!(status, 0, "{err}");
    assert_eq!(out.lines().count(), 3, "{out}");
}

/// A distance column in metres read as feet (a metric Trackman export's
/// `Distance`) makes every difference wrong, while the flights are right:
/// where most balls in the air measure under half their flight, the
/// summary says so and names the mapping; mapped, the line is gone.
#[test]
fn distances_in_metres_read_as_feet_are_named() {
    let text = std::fs::read_to_string("tests/data/trackman_2024_measured_spin.csv").unwrap();
    let metric = with_column(&text, "Distance", |feet| feet * 0.3048);
    // The rows are written; the exit status says they are suspect.
    let (out, err, status) = fly(&[], &metric);
    assert_eq!((status, out.lines().count()), (1, 67), "{err}");
    assert!(
        err.contains("Distance is under half the flight's distance on")
            && err.contains("a column in metres? map it, --column hit_distance_sc=Distance:m"),
        "{err}"
    );
    let (summary, _, status) = summary_of(metric.as_bytes());
    assert_eq!(status, 1);
    let under_half = &summary["distance_under_half"];
    let (short, of) = (under_half["rows"].as_u64(), under_half["of"].as_u64());
    assert!(
        of >= Some(10) && short.zip(of).is_some_and(|(s, o)| 2 * s > o),
        "{summary}"
    );
    let args = ["--column", "hit_distance_sc=Distance:m"];
    let (_, err, status) = fly(&args, &metric);
    assert_eq!(status, 0, "{err}");
    assert!(!err.contains("under half"), "{err}");
    let (_, err, _) = fly(&[], &text);
    assert!(!err.contains("under half"), "{err}");
}

/// Launch angles in radians read as degrees: a whole file of batted balls
/// within ±1.6° (line drives alone rise 10–25°). The summary says so and
/// names the mapping; mapped, the rows fly as the file in degrees does.
#[test]
fn launch_angles_in_radians_read_as_degrees_are_named() {
    let text = sample();
    let radians = with_column(&text, "\"launch_angle\"", f64::to_radians);
    let (summary, err, status) = summary_of(radians.as_bytes());
    assert_eq!(status, 1, "{err}");
    assert!(
        err.contains(
            "lies within ±1.6°: a column in radians read as degrees? map it, --column \
             launch_angle=COLUMN:rad (exit status 1)"
        ),
        "{err}"
    );
    assert_eq!(summary["launch_angles_within_1_6_deg"], true);
    let args = ["--column", "launch_angle=launch_angle:rad"];
    let (mapped, err, status) = fly(&args, &radians);
    assert_eq!(status, 0, "{err}");
    assert!(!err.contains("radians"), "{err}");
    let (given, err, _) = fly(&[], &text);
    assert!(!err.contains("radians"), "{err}");
    // The same launches, but for the last bits of a degree's conversion.
    let angle = |out: &str| -> Vec<String> {
        out.lines()
            .skip(1)
            .map(|l| l.split(',').nth(2).unwrap().to_owned())
            .collect()
    };
    assert_eq!(angle(&mapped), angle(&given));
}

/// `text` (a CSV whose cells hold no comma) with each number of column
/// `name` (as the header writes it, quotes and all) changed by `change`.
fn with_column(text: &str, name: &str, change: impl Fn(f64) -> f64) -> String {
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let at = header.split(',').position(|c| c == name).unwrap();
    let mut changed = vec![header.to_owned()];
    for line in lines {
        let mut cells: Vec<String> = line.split(',').map(str::to_owned).collect();
        if let Ok(number) = cells[at].trim_matches('"').parse::<f64>() {
            cells[at] = format!("{}", change(number));
        }
        changed.push(cells.join(","));
    }
    changed.join("\n") + "\n"
}
