//! `hit --batch` says what it solved and with which bat (issue 37): each
//! solved swing quantity is `measured`, `solved`, `prior` or `given`; the
//! contact's speed sits beside `bat_speed`; Savant's squared-up beside the
//! model's; a 2024 row is solved with the 2024 bat unless the user gives
//! one.

use serde_json::Value;

use crate::common::run_homerun;

const SAMPLE: &str = "tests/data/savant_swings.csv";
const MPH: f64 = 0.44704;

fn json_lines(stdout: &str) -> Vec<Value> {
    stdout
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// The sample's header and its first row (Henderson, 2024-04-03: 94.2 mph
/// at 24° off a 77.46-mph bat, an 83.9-mph slider), with `extra` columns
/// appended to both.
fn first_row_with(extra: &[(&str, &str)]) -> String {
    let text = std::fs::read_to_string(SAMPLE).unwrap();
    let mut lines = text.lines();
    let (header, row) = (lines.next().unwrap(), lines.next().unwrap());
    let names: String = extra.iter().map(|(n, _)| format!(",{n}")).collect();
    let cells: String = extra.iter().map(|(_, c)| format!(",{c}")).collect();
    format!("{header}{names}\n{row}{cells}\n")
}

fn hit(input: &str, more: &[&str]) -> (Vec<Value>, String) {
    let args = [&["hit", "--batch", "-", "--json"][..], more].concat();
    let (code, out, err) = run_homerun(&args, Some(input));
    assert_eq!(code, Some(0), "{err}");
    (json_lines(&out), err)
}

/// 2024's exports measure no attack angle: a swing below the sweet spot's
/// reach holds ψ at the prior and solves the contact's speed; one above it
/// solves ψ at the sweet spot's measured speed. The tilt is the league's
/// prior, the direction solved from the spray, E always solved.
#[test]
fn each_solved_quantity_says_how_it_was_found() {
    let (code, out, err) = run_homerun(&["hit", "--batch", SAMPLE, "--json"], None);
    assert_eq!(code, Some(0), "{err}");
    let (mut prior, mut solved) = (0, 0);
    for line in json_lines(&out) {
        let Some(swing) = line["swing"].as_object() else {
            assert_eq!(line["solved"], false);
            continue;
        };
        let from = &swing["from"];
        assert_eq!(from["tilt"], "prior", "{line}");
        assert_eq!(from["direction"], "solved", "{line}");
        assert_eq!(from["undercut"], "solved", "{line}");
        match from["angle"].as_str().unwrap() {
            "prior" => {
                prior += 1;
                assert_eq!(from["contact_speed"], "solved");
                assert_eq!(swing["angle"], 0.1594);
                // Off the sweet spot: slower than bat_speed.
                let (contact, bat) = (swing["contact_speed"].as_f64(), swing["bat_speed"].as_f64());
                assert!(contact.unwrap() < bat.unwrap(), "{line}");
            }
            "solved" => {
                solved += 1;
                assert_eq!(from["contact_speed"], "measured");
                assert_eq!(swing["contact_speed"], swing["bat_speed"]);
            }
            other => panic!("{other}: {line}"),
        }
    }
    // 33 solved with the 2024 bat: 30 at the prior swing angle, 3 not.
    assert_eq!((prior, solved), (30, 3), "{err}");
}

/// A measured attack angle (2025's exports) is the swing's angle, said so;
/// the contact's speed is then solved. A measured attack direction and
/// tilt are measured; a tilt from `--set` is given.
#[test]
fn a_measured_attack_angle_says_measured() {
    let input = first_row_with(&[("attack_angle", "12")]);
    let (lines, err) = hit(&input, &[]);
    let swing = &lines[0]["swing"];
    assert_eq!(lines[0]["solved"], true, "{err}");
    assert_eq!(swing["from"]["angle"], "measured");
    assert_eq!(swing["from"]["contact_speed"], "solved");
    assert!((swing["angle"].as_f64().unwrap() - 12f64.to_radians()).abs() < 1e-12);
    let input = first_row_with(&[
        ("attack_angle", "12"),
        ("attack_direction", "-5"),
        ("swing_path_tilt", "30"),
    ]);
    let (lines, _) = hit(&input, &[]);
    let from = &lines[0]["swing"]["from"];
    assert_eq!(
        [&from["angle"], &from["direction"], &from["tilt"]],
        ["measured", "measured", "measured"]
    );
    // With the path measured, the bat's lead over it is what turns the
    // launch toward the spray: solved.
    assert_eq!(from["lead"], "solved");
    assert_eq!(lines[0]["direction_from"], "landing");
    let (lines, _) = hit(&first_row_with(&[]), &["--set", "bat.tilt=0.3"]);
    assert_eq!(lines[0]["swing"]["from"]["tilt"], "given");
    assert_eq!(lines[0]["swing"]["from"]["angle"], "prior");
    // CSV: the same words, under swing.from.*.
    let (_, out, _) = run_homerun(&["hit", "--batch", "-"], Some(&first_row_with(&[])));
    let mut rows = out.lines().map(|l| l.split(',').collect::<Vec<_>>());
    let names = rows.next().unwrap();
    let row = rows.next().unwrap();
    let cell = |name: &str| row[names.iter().position(|n| *n == name).unwrap()];
    assert_eq!(
        [
            "angle",
            "direction",
            "tilt",
            "contact_speed",
            "undercut",
            "lead"
        ]
        .map(|q| cell(&format!("swing.from.{q}"))),
        ["prior", "solved", "prior", "solved", "solved", "prior"]
    );
    // Without a measured path the bat is square to it: lead 0, the prior.
    assert_eq!(cell("swing.lead"), "0.000000");
    // bat_speed as measured (77.462 mph), in m/s.
    assert_eq!(cell("swing.bat_speed"), "34.6286");
}

/// Savant's squared-up is EV / (1.23 · bat_speed + 0.23 · release_speed):
/// on the first row 94.2 / (1.23 · 77.462 + 0.23 · 83.9) = 0.822166. The
/// model's uses the pitch at the plate and the bat's own most at E = 0,
/// and differs (0.8413).
#[test]
fn savant_s_squared_up_sits_beside_the_model_s() {
    let (lines, _) = hit(&first_row_with(&[]), &[]);
    let impact = &lines[0]["impact"];
    let savant = impact["squared_up_savant"].as_f64().unwrap();
    let formula = 94.2 / (1.23 * 77.46206995520637 + 0.23 * 83.9);
    assert!((savant - formula).abs() < 1e-12, "{savant} {formula}");
    assert!((savant - 0.822166).abs() < 1e-6, "{savant}");
    let ours = impact["squared_up"].as_f64().unwrap();
    assert!((ours - 0.8413).abs() < 1e-4, "{ours}");
    // Without release_speed, none.
    let text = first_row_with(&[]).replacen("release_speed", "release_speed_x", 1);
    let (lines, _) = hit(&text, &[]);
    assert_eq!(lines[0]["impact"]["squared_up_savant"], Value::Null);
    assert_eq!(lines[0]["solved"], true);
}

/// A 2024 row is solved with the 2024 bat (M_B 0.8843 kg), named in the
/// row and the summary; `--set bat.effective_mass`, a row of another
/// season, or a row without a date keeps the preset's (the paper's 0.8 kg).
#[test]
fn a_2024_row_takes_the_2024_bat_unless_one_is_given() {
    let bat = |lines: &[Value]| {
        let impact = &lines[0]["impact"];
        (
            impact["bat"].as_str().unwrap().to_owned(),
            impact["effective_mass"].as_f64().unwrap(),
        )
    };
    let (lines, err) = hit(&first_row_with(&[]), &[]);
    assert_eq!(bat(&lines), ("2024".to_owned(), 0.8843));
    assert!(
        err.contains("bat: 1 with the 2024 bat: M_B 0.884 kg, calibrate --impact on April 2024"),
        "{err}"
    );
    let (lines, err) = hit(&first_row_with(&[]), &["--set", "bat.effective_mass=0.82"]);
    assert_eq!(bat(&lines), ("preset".to_owned(), 0.82));
    assert!(
        err.contains("bat: 1 with the preset's (M_B 0.820 kg)"),
        "{err}"
    );
    let other = first_row_with(&[]).replacen("2024-04-03", "2023-04-03", 1);
    let other = other.replace(",2024,", ",2023,");
    assert_eq!(bat(&hit(&other, &[]).0), ("preset".to_owned(), 0.8));
    let undated = (first_row_with(&[]).replacen("game_date", "day", 1)).replacen(
        "game_year",
        "year_of_game",
        1,
    );
    assert_eq!(bat(&hit(&undated, &[]).0), ("preset".to_owned(), 0.8));
    // game_year alone is enough; a date that is none is named.
    let year_only = first_row_with(&[]).replacen("game_date", "day", 1);
    assert_eq!(bat(&hit(&year_only, &[]).0), ("2024".to_owned(), 0.8843));
    let bad = first_row_with(&[]).replacen("2024-04-03", "April 3", 1);
    let (code, _, err) = run_homerun(&["hit", "--batch", "-"], Some(&bad));
    assert_ne!(code, Some(0));
    assert!(
        err.contains("game_date = \"April 3\": expected a date"),
        "{err}"
    );
    // The same row's swing at the two bats: the heavier bat's ceiling is
    // higher, the same launch needs a smaller contact speed.
    let (season, _) = hit(&first_row_with(&[]), &[]);
    let (paper, _) = hit(&first_row_with(&[]), &["--set", "bat.effective_mass=0.8"]);
    let contact = |l: &[Value]| l[0]["swing"]["contact_speed"].as_f64().unwrap();
    assert!(contact(&season) < contact(&paper) - 0.1);
    let launch = |l: &[Value]| l[0]["launch"]["speed"].as_f64().unwrap();
    assert!((launch(&season) - 94.2 * MPH).abs() < 1e-6);
    assert!((launch(&paper) - 94.2 * MPH).abs() < 1e-6);
}

/// tests/data/savant_2025_popup.csv: line 16 of
/// statcast-2025-bat-tracking-three-hitters.csv (Altuve, 2025-04-02: 56.7
/// mph at 80°, attack angle 5.2°, tilt 39.5°). With the bat square to its
/// path no undercut within 0.97 of the reach and no contact speed from 0.3
/// to 2 times `bat_speed` gives more than 53° (session 18: "launch angle
/// out of reach", named so). A barrel leading its path turns the undercut
/// ball's lean forward: with the lead solved toward the spray (session 20)
/// the popup is reached, the barrel 26.0° ahead, the ball met 60.8 mm
/// below its centre and off the sweet spot (13.5 of 33.6 m/s).
#[test]
fn a_2025_popup_past_the_square_bats_reach_is_reached_by_its_lead() {
    let (code, out, err) = run_homerun(
        &[
            "hit",
            "--batch",
            "tests/data/savant_2025_popup.csv",
            "--json",
        ],
        None,
    );
    assert_eq!(code, Some(0), "{err}");
    let line = &json_lines(&out)[0];
    assert_eq!(line["solved"], true, "{err}");
    let swing = &line["swing"];
    assert_eq!(swing["from"]["lead"], "solved");
    let lead = swing["lead"].as_f64().unwrap().to_degrees();
    assert!((lead - 26.0).abs() < 0.05, "{lead}");
    let undercut = line["impact"]["undercut"].as_f64().unwrap();
    assert!((undercut - 0.0608).abs() < 1e-4, "{undercut}");
    let contact = swing["contact_speed"].as_f64().unwrap();
    assert!((contact - 13.47).abs() < 0.01, "{contact}");
    // The measured launch, to the solve's tolerance.
    let angle = line["launch"]["angle"].as_f64().unwrap();
    assert!((angle - 80f64.to_radians()).abs() < 1e-9, "{angle}");
    // A 2025 row: the preset's bat (the program knows no 2025 bat).
    assert_eq!(line["impact"]["bat"], "preset");
    assert!(err.contains("swings: solved 1 of 1 tracked"), "{err}");
}

/// What a measured attack angle changes (docs/bat-tracking.md, *What the
/// measured swing changes*): the paper's mechanism, row by row. At the same
/// measured launch, a swing rising more steeply than the prior's 9.13°
/// lifts the ball with less undercut and so spins it with less backspin; a
/// flatter one needs more of both. On the committed 2025 sample, every row
/// launched at 8–30° and solved both ways (its attack angle read, and
/// ignored) says so.
#[test]
fn a_steeper_swing_lifts_a_line_drive_with_less_undercut_and_backspin() {
    let sample = "tests/data/savant_2025_every_20th.csv";
    let solve = |more: &[&str]| {
        let mut args = vec!["hit", "--batch", sample, "--json"];
        args.extend_from_slice(more);
        let (code, out, err) = run_homerun(&args, None);
        assert_eq!(code, Some(0), "{err}");
        json_lines(&out)
    };
    let measured = solve(&[]);
    let prior = solve(&["--column", "ignore=attack_angle"]);
    assert_eq!(measured.len(), prior.len());
    let number = |row: &Value, part: &str, key: &str| row[part][key].as_f64().unwrap();
    let mut compared = (0, 0);
    for (m, p) in measured.iter().zip(&prior) {
        let angle = number(m, "launch", "angle").to_degrees();
        if m["solved"] != true || p["solved"] != true || !(8.0..30.0).contains(&angle) {
            continue;
        }
        assert_eq!(m["swing"]["from"]["angle"], "measured");
        assert_eq!(p["swing"]["from"]["angle"], "prior");
        let steeper = number(m, "swing", "angle") > number(p, "swing", "angle");
        let less_undercut = number(m, "impact", "undercut") < number(p, "impact", "undercut");
        let less_backspin = number(m, "launch", "spin") < number(p, "launch", "spin");
        assert_eq!(less_undercut, steeper, "line {}", m["line"]);
        assert_eq!(less_backspin, steeper, "line {}", m["line"]);
        match steeper {
            true => compared.0 += 1,
            false => compared.1 += 1,
        }
    }
    // Both ways are in the sample: 8 steeper than the prior, 4 flatter.
    assert_eq!(compared, (8, 4));
}
