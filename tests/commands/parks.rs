//! The bundled parks against what is measured and published of them, the
//! shape every fence must have, and `homerun parks` as a user meets it.

use crate::common;
use std::f64::consts::FRAC_PI_4;

use homerun::model::park::{self, CompassWind, Park};

const FOOT: f64 = 0.3048;

/// Baseball Savant's `home_team` codes, one per park.
const SAVANT_CODES: [&str; 30] = [
    "AZ", "ATL", "BAL", "BOS", "CHC", "CWS", "CIN", "CLE", "COL", "DET", "HOU", "KC", "LAA", "LAD",
    "MIA", "MIL", "MIN", "NYM", "NYY", "ATH", "PHI", "PIT", "SD", "SF", "SEA", "STL", "TB", "TEX",
    "TOR", "WSH",
];

fn park(code: &str) -> &'static Park {
    park::find(park::bundled(), code).unwrap_or_else(|| panic!("no park {code}"))
}

/// The fence's wall height (ft) at `degrees` from centre field.
fn wall_ft(code: &str, degrees: f64) -> f64 {
    park(code).fence.height_at(degrees.to_radians()).unwrap() / FOOT
}

/// The fence's distance (ft) at `degrees` from centre field.
fn distance_ft(code: &str, degrees: f64) -> f64 {
    park(code).fence.distance_at(degrees.to_radians()).unwrap() / FOOT
}

#[test]
fn every_savant_code_names_its_own_park_and_the_aliases_too() {
    assert_eq!(park::bundled().len(), 30);
    for code in SAVANT_CODES {
        assert_eq!(park(code).code, code);
    }
    assert_eq!(park("ARI").code, "AZ");
    assert_eq!(park("oak").code, "ATH");
    assert_eq!(park("WSN").code, "WSH");
}

#[test]
fn fences_run_foul_line_to_foul_line_every_five_degrees_or_closer() {
    for p in park::bundled() {
        let points = p.fence.points();
        assert_eq!(points[0].direction, -FRAC_PI_4, "{}", p.code);
        assert_eq!(points[points.len() - 1].direction, FRAC_PI_4, "{}", p.code);
        for pair in points.windows(2) {
            let gap = (pair[1].direction - pair[0].direction).to_degrees();
            assert!(
                (0.0..=5.0 + 1e-9).contains(&gap),
                "{}: a {gap}° gap",
                p.code
            );
        }
        for point in points {
            // A wall between 2 ft and 40 ft high, 290 ft to 440 ft out.
            let (d, h) = (point.distance / FOOT, point.height / FOOT);
            assert!((290.0..440.0).contains(&d), "{}: {d} ft", p.code);
            assert!((2.0..40.0).contains(&h), "{}: {h} ft high", p.code);
        }
    }
}

#[test]
fn fences_meet_the_published_lines_and_centre_within_six_feet() {
    for p in park::bundled() {
        let published = p.published.unwrap_or_else(|| panic!("{}", p.code));
        let [left, center, right] = p.fence.lines_and_center();
        for (got, want, where_) in [
            (left.distance, published.left_line, "left-field line"),
            (center.distance, published.center, "centre"),
            (right.distance, published.right_line, "right-field line"),
        ] {
            let off = (got - want) / FOOT;
            assert!(off.abs() <= 6.0, "{} {where_}: {off:+.1} ft", p.code);
            // Anchored there (docs/parks.md): met to the data's millimetre.
            assert!(off.abs() <= 0.01, "{} {where_}: {off:+.3} ft", p.code);
        }
    }
    // The published distances themselves, as painted on famous walls.
    let lines = |code: &str| (distance_ft(code, -45.0), distance_ft(code, 45.0));
    let near = |got: f64, want: f64| (got - want).abs() <= 6.0;
    let (yankee_left, yankee_right) = lines("NYY");
    assert!(
        near(yankee_right, 314.0) && near(yankee_left, 318.0),
        "the short porch"
    );
    let (fenway_left, fenway_right) = lines("BOS");
    assert!(
        near(fenway_left, 310.0) && near(fenway_right, 302.0),
        "the Pesky pole"
    );
    assert!(near(distance_ft("CHC", 0.0), 400.0));
    assert!(near(distance_ft("COL", 0.0), 415.0));
    assert!(near(lines("SF").1, 309.0));
}

#[test]
fn famous_walls_stand_as_high_as_they_are_known_to() {
    let within = |got: f64, low: f64, high: f64| (low - 2.0..=high + 2.0).contains(&got);
    // The Green Monster, 37 ft, from the left-field pole to left-centre.
    for degrees in [-44.0, -30.0, -15.0] {
        assert!(within(wall_ft("BOS", degrees), 37.0, 37.0), "{degrees}°");
    }
    assert!(wall_ft("BOS", 30.0) < 6.0, "Fenway's low right-field wall");
    // Houston's Crawford Boxes in left field, 19 to 21 ft.
    assert!(within(wall_ft("HOU", -35.0), 19.0, 21.0));
    // Oracle Park's right-field brick wall, 24 to 25 ft.
    assert!(within(wall_ft("SF", 35.0), 24.0, 25.0));
    // The Clemente wall in Pittsburgh's right field, 21 ft.
    assert!(within(wall_ft("PIT", 35.0), 21.0, 21.0));
    // The Baggie's successor: Target Field's right-field wall, 23 ft.
    assert!(within(wall_ft("MIN", 35.0), 23.0, 23.0));
}

#[test]
fn coors_field_is_a_mile_high_and_parks_face_their_own_way() {
    let coors = park("COL");
    assert!(
        (coors.elevation / FOOT - 5200.0).abs() < 50.0,
        "{}",
        coors.elevation
    );
    assert!((coors.elevation - 1580.0).abs() < 15.0);
    for p in park::bundled() {
        assert!((-10.0..2200.0).contains(&p.elevation), "{}", p.code);
        assert!((0.0..360.0).contains(&p.center_field_bearing), "{}", p.code);
    }
    // Fenway faces north-east (MLB gives 45°): a south-west wind blows out.
    let out = park("BOS").wind_direction(CompassWind::From(225.0));
    assert!(out.abs() < 1e-12, "{out}");
}

fn homerun(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    common::assert_command()
        .arg("--parks-dir")
        .arg(dir)
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn the_json_list_reads_back_as_the_bundled_parks() {
    let none = tempfile::tempdir().unwrap();
    let out = homerun(none.path(), &["parks", "--json"]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let listed = json.as_array().unwrap();
    assert_eq!(listed.len(), 30);
    for (entry, p) in listed.iter().zip(park::bundled()) {
        assert_eq!(entry["code"], p.code.as_str());
        assert_eq!(entry["elevation"].as_f64(), Some(p.elevation));
        // When its walls stood, as a park file writes it: Camden Yards'
        // left field of 2022–2024; a park without a change, its home.
        let walls: Vec<String> = p.walls.iter().map(|w| w.as_written()).collect();
        assert_eq!(entry["walls"], serde_json::json!(walls));
        let fence = entry["fence"].as_array().unwrap();
        assert_eq!(fence.len(), p.fence.points().len());
        for (point, want) in fence.iter().zip(p.fence.points()) {
            assert_eq!(point["direction"].as_f64(), Some(want.direction));
            assert_eq!(point["distance"].as_f64(), Some(want.distance));
            assert_eq!(point["height"].as_f64(), Some(want.height));
        }
    }
}

#[test]
fn one_parks_profile_in_feet_steps_at_the_monster() {
    let none = tempfile::tempdir().unwrap();
    let out = homerun(none.path(), &["parks", "bos", "--units", "imperial"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("BOS Fenway Park\n"), "{text}");
    // Fenway's walls stood all its home years: no line for them.
    assert!(!text.contains("walls"), "{text}");
    let camden = homerun(none.path(), &["parks", "BAL"]);
    let camden = String::from_utf8(camden.stdout).unwrap();
    assert!(
        camden.contains(
            "its walls as given stood 2022–2024 (a batch row at BAL dated otherwise is judged \
             at its walls then, below, or else at no park)"
        ),
        "{camden}"
    );
    // Its walls before 2022, in a table of their own: 333 ft at the pole,
    // 7 ft 4 in high (the 2022 wall: 13 ft).
    let walls_then = "its walls 2015–2021 (a batch row at BAL then is judged at them):";
    let before = camden.split(walls_then).nth(1).expect(&camden);
    let pole = before
        .lines()
        .find(|l| l.trim_start().starts_with("-45.0"))
        .unwrap();
    let pole: Vec<&str> = pole.split_whitespace().collect();
    assert_eq!(pole, ["-45.0", "101.50", "2.23"], "{camden}");
    let json = homerun(none.path(), &["parks", "BAL", "--json"]);
    let json: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(json["walls"], serde_json::json!(["2022..2024"]));
    assert_eq!(
        json["earlier"][0]["walls"],
        serde_json::json!(["2015..2021"])
    );
    assert_eq!(json["earlier"].as_array().unwrap().len(), 1);
    assert!(
        text.contains("direction (°)  distance (ft)  height (ft)"),
        "{text}"
    );
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip_while(|l| !l.starts_with("direction"))
        .filter_map(|l| {
            let v: Vec<f64> = l
                .split_whitespace()
                .filter_map(|w| w.parse().ok())
                .collect();
            (v.len() == 3).then_some(v)
        })
        .collect();
    assert_eq!(rows[0][0], -45.0);
    assert!((rows[0][1] - 310.0).abs() < 0.1 && (rows[0][2] - 37.0).abs() < 0.1);
    assert_eq!(rows.last().unwrap()[0], 45.0);
    // The step off the Monster: two rows at one direction, 37 ft then lower.
    let step = rows.windows(2).find(|w| w[0][0] == w[1][0]).unwrap();
    assert!(
        (step[0][2] - 37.0).abs() < 0.1 && step[1][2] < 20.0,
        "{step:?}"
    );
}

#[test]
fn an_unknown_code_is_one_line_naming_it_and_the_codes() {
    let none = tempfile::tempdir().unwrap();
    let out = homerun(none.path(), &["parks", "XYZ"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("\"XYZ\"") && err.contains("AZ (ARI)") && err.contains("WSH"),
        "{err}"
    );
}

const MY_PARK: &str = r#"
[[park]]
code = "BOS"
name = "Backyard"
elevation = 10
center_field_bearing = 90
fence = [
  { direction = -0.7854, distance = 60, height = 2 },
  { direction = 0, distance = 70, height = 2 },
  { direction = 0.7854, distance = 60, height = 2 },
]
"#;

#[test]
fn a_users_park_file_hides_the_bundled_park_of_its_code() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("backyard.toml"), MY_PARK).unwrap();
    let out = homerun(dir.path(), &["parks", "BOS", "--json"]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["name"], "Backyard");
    assert_eq!(json["fence"][1]["distance"].as_f64(), Some(70.0));
    let list = String::from_utf8(homerun(dir.path(), &["parks"]).stdout).unwrap();
    assert!(
        list.contains("Backyard") && !list.contains("Fenway"),
        "{list}"
    );
    assert!(list.contains("Yours: BOS from"), "{list}");
}

#[test]
fn a_bad_users_park_file_is_one_clear_line() {
    let dir = tempfile::tempdir().unwrap();
    let bad = MY_PARK.replace("elevation = 10", "elevation = \"high\"");
    std::fs::write(dir.path().join("backyard.toml"), bad).unwrap();
    let out = homerun(dir.path(), &["parks"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("backyard.toml: malformed park file"), "{err}");
    let bad = MY_PARK.replace("{ direction = 0.7854", "{ direction = 0.5");
    std::fs::write(dir.path().join("backyard.toml"), bad).unwrap();
    let err = String::from_utf8(homerun(dir.path(), &["parks"]).stderr).unwrap();
    assert!(
        err.contains("backyard.toml: park BOS: fence runs from -0.7854 to 0.5 rad"),
        "{err}"
    );
}

#[test]
fn the_outline_is_an_svg_with_every_wall_height_in_its_legend() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("fenway.svg");
    let out = homerun(
        dir.path(),
        &["parks", "BOS", "--svg", file.to_str().unwrap()],
    );
    assert!(out.status.success(), "{out:?}");
    let svg = std::fs::read_to_string(&file).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let texts: Vec<&str> = doc
        .descendants()
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect();
    assert!(
        texts.iter().any(|t| t.starts_with("Fenway Park (BOS)")),
        "{texts:?}"
    );
    for wall in ["wall 1.5 m high", "wall 5.5 m high", "wall 11.3 m high"] {
        assert!(texts.contains(&wall), "{wall}: {texts:?}");
    }
    // --svg needs a park.
    assert_eq!(
        homerun(dir.path(), &["parks", "--svg", "x.svg"])
            .status
            .code(),
        Some(2)
    );
}

/// Issue 28, item 7: a park by its code, name or city, any case, wherever
/// the command line takes one; a name that fits several lists them in one
/// line.
#[test]
fn a_park_is_found_by_code_name_or_city() {
    use homerun::model::park::Named;
    for query in [
        "BOS",
        "bos",
        "fenway",
        "Fenway Park",
        "FENWAY  park",
        "boston",
    ] {
        match park::named(park::bundled(), query) {
            Named::One(p) => assert_eq!(p.code, "BOS", "{query}"),
            other => panic!("{query}: {other:?}"),
        }
    }
    for (query, code) in [("coors", "COL"), ("Kansas City", "KC"), ("camden", "BAL")] {
        match park::named(park::bundled(), query) {
            Named::One(p) => assert_eq!(p.code, code, "{query}"),
            other => panic!("{query}: {other:?}"),
        }
    }
    match park::named(park::bundled(), "chicago") {
        Named::Several(several) => {
            let codes: Vec<&str> = several.iter().map(|p| p.code.as_str()).collect();
            assert_eq!(codes, ["CHC", "CWS"]);
        }
        other => panic!("chicago: {other:?}"),
    }
    assert!(matches!(park::named(park::bundled(), "xyz"), Named::None));
    let homerun = |args: &[&str]| common::command().args(args).output().unwrap();
    for args in [
        &["fly", "--preset", "fly-ball", "--park", "Fenway Park"][..],
        &["parks", "fenway"],
        &[
            "optimize",
            "--park",
            "boston",
            "--fix",
            "bat.direction",
            "--fix",
            "bat.undercut",
        ],
    ] {
        let out = homerun(args);
        assert!(out.status.success(), "{args:?}: {out:?}");
        assert!(
            String::from_utf8_lossy(&out.stdout).contains("Fenway Park"),
            "{args:?}"
        );
    }
    let out = homerun(&["fly", "--park", "new york"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "homerun: park \"new york\" could be NYM (Citi Field, New York), NYY (Yankee Stadium, New York): give one of these codes\n"
    );
}

/// Issue 28, item 4: one rule for a park's air. "Does it clear Fenway" has
/// one answer: `fly --park BOS`, the BOS row of `--all-parks` (with or
/// without `--park`) and the batch's margin at BOS all fly the ball in
/// Fenway's own air; `--one-flight` says it is on one flight.
#[test]
fn a_park_is_judged_in_its_own_air_everywhere() {
    let run = |args: &[&str], stdin: &str| {
        let out = common::assert_command()
            .args(args)
            .write_stdin(stdin)
            .output()
            .unwrap();
        assert!(out.status.success(), "{args:?}: {out:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    let json =
        |args: &[&str]| -> serde_json::Value { serde_json::from_str(&run(args, "")).unwrap() };
    let at_park = json(&["fly", "--json", "--preset", "fly-ball", "--park", "BOS"]);
    let margin = at_park["fence"]["margin"].as_f64().unwrap();
    for args in [
        &["fly", "--json", "--preset", "fly-ball", "--all-parks"][..],
        &[
            "fly",
            "--json",
            "--preset",
            "fly-ball",
            "--all-parks",
            "--park",
            "COL",
        ],
    ] {
        let all = json(args);
        let bos = all["all_parks"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["park"] == "BOS")
            .unwrap();
        assert_eq!(bos["margin"].as_f64().unwrap(), margin, "{args:?}");
    }
    let batch = run(
        &[
            "fly", "--preset", "fly-ball", "--park", "BOS", "--batch", "-",
        ],
        "launch.speed,launch.angle,launch.spin\n46.04512,0.48869219,261.79939\n",
    );
    let mut lines = batch.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = header.iter().position(|h| *h == "margin").unwrap();
    let printed: f64 = row[column].parse().unwrap();
    assert!(
        (printed - margin).abs() < 1e-3,
        "{printed} against {margin}"
    );
    let text = run(&["fly", "--preset", "fly-ball"], "");
    assert!(text.contains("parks (each in its own air)"), "{text}");
    let text = run(&["fly", "--preset", "fly-ball", "--one-flight"], "");
    assert!(
        text.contains("parks (on this one flight, in its air)"),
        "{text}"
    );
}

/// Issue 28, item 12: `fly --batch --all-parks` gives each row's outcome
/// and margin at every park: two CSV columns a park (the margin's unit in
/// its name outside SI), or a JSON `all_parks` list. Each park is judged
/// in its own air, and the columns count to `parks_cleared` (issue 35,
/// item 4); `--one-flight` judges every park on the row's one flight.
#[test]
fn a_batch_with_all_parks_gives_each_parks_outcome_and_margin() {
    let run = |args: &[&str]| {
        let out = common::assert_command().args(args).output().unwrap();
        assert!(out.status.success(), "{args:?}: {out:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    let file = "tests/data/savant_home_runs.csv";
    let csv = run(&["fly", "--all-parks", "--batch", file]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = |name: &str| header.iter().position(|h| *h == name).unwrap();
    for code in SAVANT_CODES {
        assert_eq!(
            at(&format!("{code}_margin")),
            at(&format!("{code}_outcome")) + 1
        );
    }
    assert_eq!(header.len(), 21 + 2 * 30);
    let (mut rows, mut away, mut earlier) = (0, 0, 0);
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), header.len(), "{line}");
        let cleared = SAVANT_CODES
            .iter()
            .filter(|code| cells[at(&format!("{code}_outcome"))] == "clears")
            .count();
        assert_eq!(cleared.to_string(), cells[at("parks_cleared")], "{line}");
        // The row's own park's columns are its outcome and margin. The
        // Rangers' 2019 home runs were hit at Globe Life Park, not the
        // bundled Globe Life Field (2020 on), one Angels' in Monterrey, and
        // none at a park whose walls of 2019 are not bundled:
        // at no park, though `--all-parks` judges them at every park.
        let park = cells[at("park")];
        if park == "none" {
            assert_eq!(cells[at("outcome")], "no_park", "{line}");
            away += 1;
            rows += 1;
            continue;
        }
        rows += 1;
        // The rows at Toronto (14), Camden Yards (15), Comerica Park (4),
        // Kauffman Stadium (7), Marlins Park (5) and Oracle Park (6) met
        // the walls of 2019, bundled as earlier ones; `--all-parks` judges
        // the walls as given (2022 on and the like).
        if ["TOR", "BAL", "DET", "KC", "MIA", "SF"].contains(&park) {
            earlier += 1;
            continue;
        }
        assert_eq!(cells[at(&format!("{park}_outcome"))], cells[at("outcome")]);
        assert_eq!(cells[at(&format!("{park}_margin"))], cells[at("margin")]);
    }
    assert_eq!((rows, away, earlier), (248, 10, 51));
    // Imperial: the margins in feet, named so.
    let imperial = run(&["fly", "--units", "imperial", "--all-parks", "--batch", file]);
    let header = imperial.lines().next().unwrap();
    assert!(header.contains(",BOS_outcome,BOS_margin_ft,"), "{header}");
    // JSON: a list of {park, outcome, margin} in the parks' order, SI.
    let json = run(&["fly", "--json", "--all-parks", "--batch", file]);
    let first: serde_json::Value = serde_json::from_str(json.lines().next().unwrap()).unwrap();
    let list = first["all_parks"].as_array().unwrap();
    assert_eq!(list.len(), 30);
    assert_eq!(list[0]["park"], "AZ");
    let mine = list
        .iter()
        .find(|p| p["park"] == first["fence"]["park"])
        .unwrap();
    assert_eq!(mine["outcome"], first["fence"]["outcome"]);
    assert_eq!(mine["margin"], first["fence"]["margin"]);
    // Without --all-parks, no such key or columns.
    let plain = run(&["fly", "--json", "--batch", file]);
    assert!(!plain.contains("all_parks"));
    // --one-flight: every park on the row's one flight, in its park's air.
    let one = run(&["fly", "--all-parks", "--one-flight", "--batch", file]);
    let header: Vec<&str> = one.lines().next().unwrap().split(',').collect();
    let first: Vec<&str> = one.lines().nth(1).unwrap().split(',').collect();
    let bos = header.iter().position(|h| *h == "BOS_margin").unwrap();
    let own: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
    assert_ne!(first[bos], own[bos], "Fenway's own air moves the margin");
    // The count without --all-parks, settled mostly from the one flight,
    // is the count of every park flown.
    let plain = run(&["fly", "--batch", file]);
    let count = |text: &str| -> Vec<String> {
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let at = header.iter().position(|h| *h == "parks_cleared").unwrap();
        lines
            .map(|l| l.split(',').nth(at).unwrap().to_owned())
            .collect()
    };
    assert_eq!(count(&plain), count(&csv));
    assert_ne!(count(&one), count(&csv), "the air moves some counts");
}
