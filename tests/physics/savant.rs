//! Clearing the wall at a park (`fly --park`, `--all-parks`, the count of
//! parks) and a Baseball Savant export read as it comes (`fly --batch`:
//! hit coordinates, batter's side, home team, Statcast's distance, "null",
//! repeated column names, `--keep`, `--spray`).

use crate::common;

use common::run_homerun as homerun;
use homerun::analysis::savant::spray_angle;
use homerun::model::spin_estimate::{Side, nathan_spin};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let (status, out, err) = homerun(args, None);
    assert_eq!(status, Some(0), "{err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn the_generic_fence_is_judged_by_the_same_code_as_a_parks() {
    // In vacuum the track is a parabola: at 121.9 m from a 1 m contact, a
    // launch at 46.04512 m/s and 28° is y = 1 + d·tanθ − g·d²/(2v²cos²θ) up.
    let v = json(&[
        "fly",
        "--preset",
        "fly-ball",
        "--set",
        "environment.air_density=0",
        "--json",
    ]);
    let (speed, angle, d, g) = (46.04512f64, 28f64.to_radians(), 121.9, 9.81);
    let height = 1.0 + d * angle.tan() - g * d * d / (2.0 * (speed * angle.cos()).powi(2));
    let fence = &v["fence"];
    assert_eq!(fence["park"], "generic");
    assert!((fence["height_at_fence"].as_f64().unwrap() - height).abs() < 1e-6);
    assert!((fence["margin"].as_f64().unwrap() - (height - 3.0)).abs() < 1e-6);
    assert_eq!(fence["outcome"], "clears");
    assert_eq!(fence["clears"], true);
    assert_eq!(
        (fence["distance"].as_f64(), fence["height"].as_f64()),
        (Some(121.9), Some(3.0))
    );
}

#[test]
fn a_line_drive_off_the_green_monster_clears_the_crawford_boxes() {
    // 103 mph at 0.27 rad, 34° toward left field: at Fenway it meets the
    // 11.3 m wall 96.8 m out below its top; Houston's 6.4 m wall in left is
    // no higher than the ball there.
    let args = [
        "fly",
        "--preset",
        "fly-ball",
        "--set",
        "launch.angle=0.27",
        "--set",
        "launch.direction=-0.6",
        "--park",
        "BOS",
        "--all-parks",
        "--json",
    ];
    let v = json(&args);
    let fence = &v["fence"];
    assert_eq!(fence["park"], "BOS");
    assert_eq!(fence["outcome"], "off the wall", "{fence}");
    let margin = fence["margin"].as_f64().unwrap();
    let up = fence["height_at_fence"].as_f64().unwrap();
    assert!(margin < 0.0);
    assert!((margin - (up - fence["height"].as_f64().unwrap())).abs() < 1e-12);
    // Fenway's air: the standard air at its elevation.
    let parks = json(&["parks", "--json"]);
    let fenway = parks
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["code"] == "BOS")
        .unwrap();
    assert_eq!(
        v["environment"]["atmosphere"]["elevation"],
        fenway["elevation"]
    );
    assert_eq!(v["environment"]["atmosphere"]["temperature"], 15.0);
    // Every park, the same flight: the count is the list's.
    let all = v["all_parks"].as_array().unwrap();
    assert_eq!(all.len(), 30);
    let clears: Vec<&str> = all
        .iter()
        .filter(|c| c["outcome"] == "clears")
        .map(|c| c["park"].as_str().unwrap())
        .collect();
    assert_eq!(
        v["parks"]["cleared"].as_u64().unwrap() as usize,
        clears.len()
    );
    assert_eq!(v["parks"]["codes"], serde_json::json!(clears));
    assert!(clears.contains(&"HOU") && !clears.contains(&"BOS"));
    let at = |code: &str| all.iter().find(|c| c["park"] == code).unwrap();
    assert_eq!(at("BOS")["margin"], fence["margin"]);

    // Air given stays the user's at any park.
    let given = json(&[
        "fly",
        "--preset",
        "fly-ball",
        "--park",
        "COL",
        "--set",
        "environment.air_density=1.2",
        "--json",
    ]);
    assert_eq!(given["environment"]["air_density"], 1.2);
    // A park unknown: one line, exit 2.
    let (status, _, err) = homerun(&["fly", "--park", "XYZ"], None);
    assert_eq!(status, Some(2));
    assert!(err.contains("no park named \"XYZ\""), "{err}");
}

/// A Savant export in its 2019 layout: quoted fields, "null", `pitcher`
/// twice, a pitch not put in play, an alias (OAK) and a row without hit
/// coordinates.
const EXPORT: &str = "\
\"pitcher\",\"stand\",\"home_team\",\"des\",\"hc_x\",\"hc_y\",\"hit_distance_sc\",\"launch_speed\",\"launch_angle\",\"pitcher\"
\"1\",\"R\",\"MIN\",\"Edwin Encarnacion homers (30) on a fly ball to left center field.  \",\"64.80\",\"47.78\",\"385\",\"99.9\",\"36\",\"1\"
\"2\",\"L\",\"OAK\",\"homers, to right\",\"190.2\",\"70.5\",\"null\",\"104.2\",\"27\",\"2\"
\"3\",\"R\",\"BOS\",\"ball\",\"null\",\"null\",\"null\",\"null\",\"null\",\"3\"
\"4\",\"L\",\"COL\",\"no coordinates\",\"null\",\"null\",\"410\",\"103\",\"30\",\"4\"
";

fn batch(args: &[&str]) -> (Vec<Value>, String) {
    let mut all = vec!["fly", "--batch", "-", "--json"];
    all.extend_from_slice(args);
    let (status, out, err) = homerun(&all, Some(EXPORT));
    assert_eq!(status, Some(0), "{err}");
    (
        out.lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect(),
        err,
    )
}

#[test]
fn a_savant_export_is_read_as_it_comes() {
    let (rows, err) = batch(&["--keep", "des,pitcher"]);
    // The pitch not put in play is skipped and counted, once.
    assert_eq!(rows.len(), 3);
    assert!(
        err.contains("skipped 1 row without a launch speed"),
        "{err}"
    );
    assert!(
        err.contains(
            "read stand, home_team, hc_x, hc_y, hit_distance_sc, launch_speed, launch_angle"
        ),
        "{err}"
    );
    assert!(
        err.contains("spin estimated (Nathan's relation) on 3 of 3 rows"),
        "{err}"
    );
    assert!(err.contains("1 row without hit coordinates"), "{err}");
    // Parks by home_team, aliases too.
    let parks: Vec<&str> = rows
        .iter()
        .map(|r| r["fence"]["park"].as_str().unwrap())
        .collect();
    assert_eq!(parks, ["MIN", "ATH", "COL"]);
    // The first row: its launch direction lands on the spray, with Nathan's
    // spin for that direction and a right-handed batter.
    let r = &rows[0];
    let spray = spray_angle(64.80, 47.78);
    let landing = r["flight"]["direction"].as_f64().unwrap();
    assert!((landing - spray).abs() < 1e-4, "{landing} {spray}");
    let launch = &r["launch"];
    let direction = launch["direction"].as_f64().unwrap();
    let (back, side) = nathan_spin(36f64.to_radians(), direction, Some(Side::Right));
    assert_eq!(launch["spin"].as_f64().unwrap(), back);
    assert_eq!(launch["sidespin"].as_f64().unwrap(), side);
    assert_eq!(r["spin_estimated"], true);
    // Statcast's distance, and the model's less it (m).
    let measured = r["statcast"]["distance"].as_f64().unwrap();
    assert!((measured - 385.0 * 0.3048).abs() < 1e-12);
    let range = r["flight"]["range"].as_f64().unwrap();
    assert!((r["statcast"]["difference"].as_f64().unwrap() - (range - measured)).abs() < 1e-12);
    assert_eq!(rows[1]["statcast"], Value::Null, "\"null\" is no distance");
    // The first of the repeated `pitcher` columns, and fields as read.
    assert_eq!(r["kept"]["pitcher"], "1");
    assert_eq!(
        r["kept"]["des"],
        "Edwin Encarnacion homers (30) on a fly ball to left center field.  "
    );
    // No coordinates: toward centre field (the preset's direction).
    assert_eq!(rows[2]["launch"]["direction"], 0.0);

    // Taken as the launch direction, the spray is where the ball leaves.
    let (launched, err) = batch(&["--spray", "launch"]);
    assert!(
        err.contains("spray taken as the launch direction on 2 rows"),
        "{err}"
    );
    assert_eq!(launched[0]["launch"]["direction"].as_f64().unwrap(), spray);

    // --park puts every row at that park.
    let (coors, err) = batch(&["--park", "col"]);
    assert!(coors.iter().all(|r| r["fence"]["park"] == "COL"));
    assert!(err.contains("1 park from --park"), "{err}");
}

#[test]
fn kept_columns_are_copied_into_the_csv_quoted() {
    let (status, out, err) = homerun(
        &[
            "fly", "--batch", "-", "--keep", "des", "--units", "imperial",
        ],
        Some(EXPORT),
    );
    assert_eq!(status, Some(0), "{err}");
    let mut lines = out.lines();
    let header = lines.next().unwrap();
    assert!(
        header.ends_with(
            ",park,outcome,margin_ft,parks_cleared,spin_estimated,direction_from,statcast_distance_ft,difference_ft,des"
        ),
        "{header}"
    );
    let first = lines.next().unwrap();
    // Statcast's 385 ft, then the field with its trailing spaces, quoted.
    assert!(first.contains(",385.0,"), "{first}");
    assert!(
        first.ends_with(",\"Edwin Encarnacion homers (30) on a fly ball to left center field.  \""),
        "{first}"
    );
    assert!(lines.next().unwrap().ends_with(",\"homers, to right\""));
    // A column to keep that is not there: one line, exit 2.
    let (status, _, err) = homerun(&["fly", "--batch", "-", "--keep", "nope"], Some(EXPORT));
    assert_eq!(status, Some(2));
    assert!(err.contains("--keep nope: no column of that name"), "{err}");
}
