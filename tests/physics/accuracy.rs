//! Measured against reality (docs/accuracy.md): the committed sample of
//! real 2019 home runs (tests/data/savant_home_runs.csv, 248 rows) flown by
//! the default pipeline, `fly --batch` with nothing else, against
//! Statcast's hit_distance_sc; the share that clear their own park; and the
//! same model row by row against pybaseball's implementation of Nathan's
//! calculator (tests/data/savant_home_runs_pybaseball.csv) where the inputs
//! are the same.

use crate::common;
use homerun::Scene;
use homerun::analysis::calibrate::median;
use homerun::analysis::precision::Purpose;
use homerun::model::launch::{BattedBall, fly_scene};
use serde_json::Value;

const SAMPLE: &str = "tests/data/savant_home_runs.csv";
const PYBASEBALL: &str = "tests/data/savant_home_runs_pybaseball.csv";
const FOOT: f64 = 0.3048;

/// The sample's rows as the default pipeline flies them (JSON lines), with
/// the hit coordinates kept to tell which rows had them.
fn default_pipeline(args: &[&str]) -> Vec<Value> {
    let out = common::assert_command()
        .args([
            "fly",
            "--batch",
            SAMPLE,
            "--json",
            "--keep",
            "hc_x,hc_y,home_team",
        ])
        .args(args)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// A row the distance says something of: hit coordinates and a distance
/// (the anchor's 239 rows).
fn comparable(row: &Value) -> bool {
    let kept = |c: &str| row["kept"][c].as_str().is_some_and(|v| v != "null");
    kept("hc_x") && kept("hc_y") && row["statcast"]["difference"].is_f64()
}

/// Model − Statcast (ft) of the comparable rows.
fn errors(rows: &[Value]) -> Vec<f64> {
    rows.iter()
        .filter(|r| comparable(r))
        .map(|r| r["statcast"]["difference"].as_f64().unwrap() / FOOT)
        .collect()
}

#[test]
fn the_default_pipeline_lands_within_its_measured_error() {
    let rows = default_pipeline(&[]);
    assert_eq!(rows.len(), 248);
    let errors = errors(&rows);
    assert_eq!(errors.len(), 239);
    let bias = median(errors.clone());
    let absolute = median(errors.iter().map(|e| e.abs()).collect());
    // Measured (docs/accuracy.md): median +1.3 ft, median |error| 8.9 ft.
    // Either growing by more than 1.5 ft fails.
    assert!(bias.abs() <= 1.3 + 1.5, "median error {bias:+.2} ft");
    assert!(absolute <= 8.9 + 1.5, "median |error| {absolute:.2} ft");
    // The goal, with room: within 10 ft, ≤ 13 ft.
    assert!(bias.abs() < 10.0 && absolute <= 13.0);

    // Measured: 197 of the 231 judged at their park (85.3 %) clear its
    // fence; the goal is 80 %. The 30 at Camden Yards, Comerica Park,
    // Marlins Park and Oracle Park are judged at their earlier walls, those
    // of 2019 (27 clear). The other 8 are at no park: the Rangers' of 2019,
    // hit at Globe Life Park, not the bundled Globe Life Field (2020 on).
    let judged: Vec<&Value> = (rows.iter())
        .filter(|r| comparable(r) && r["fence"]["park"] != "none")
        .collect();
    assert_eq!(judged.len(), 231);
    // And one Angels' home run in Monterrey, which has no distance.
    let away: Vec<&Value> = (rows.iter())
        .filter(|r| r["fence"]["park"] == "none")
        .collect();
    assert_eq!(away.len(), 10);
    assert_eq!(
        (away.iter())
            .filter(|r| r["kept"]["home_team"] == "TEX")
            .count(),
        9
    );
    let cleared = (judged.iter())
        .filter(|r| r["fence"]["outcome"] == "clears")
        .count();
    assert!(cleared >= 195, "{cleared} of 231 clear their own park");
    assert!(cleared as f64 / 231.0 >= 0.8);
    // Each row names its own park, and the count of parks cleared is its
    // list of codes.
    for r in &rows {
        assert_ne!(r["fence"]["park"], "generic", "{r}");
        let codes = r["parks"]["codes"].as_array().unwrap();
        assert_eq!(
            r["parks"]["cleared"].as_u64().unwrap() as usize,
            codes.len()
        );
    }
}

#[test]
fn the_spray_as_launch_direction_lands_short_as_the_anchor_does() {
    // pybaseball's recipe (docs/savant-sample.md: −11.0 ft / 14.4 ft on
    // these rows with its ball, its contact point and 70 °F): short, and
    // wider than the solved direction. Measured: −13.3 ft, 15.2 ft.
    let errors = errors(&default_pipeline(&["--spray", "launch"]));
    let bias = median(errors.clone());
    let absolute = median(errors.iter().map(|e| e.abs()).collect());
    assert!((bias + 13.3).abs() < 1.5, "{bias:+.2}");
    assert!((absolute - 15.2).abs() < 1.5, "{absolute:.2}");
}

/// One row of the pybaseball reference: its inputs and its tight 3-D
/// distance (ft).
struct Reference {
    speed: f64,
    angle: f64,
    direction: f64,
    backspin_rpm: f64,
    sidespin_rpm: f64,
    elevation: f64,
    distance_ft: f64,
    bearing_deg: f64,
}

fn references() -> Vec<Reference> {
    let text = std::fs::read_to_string(PYBASEBALL).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (speed, angle, direction) = (
        column("speed_mps"),
        column("launch_angle_deg"),
        column("direction_deg"),
    );
    let (back, side, elevation) = (
        column("backspin_rpm"),
        column("sidespin_rpm"),
        column("elevation_m"),
    );
    let (distance, bearing) = (column("distance_3d_ft"), column("bearing_3d_deg"));
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|f| !f[speed].is_empty())
        .map(|f| {
            let n = |i: usize| f[i].parse::<f64>().unwrap();
            Reference {
                speed: n(speed),
                angle: n(angle).to_radians(),
                direction: n(direction).to_radians(),
                backspin_rpm: n(back),
                sidespin_rpm: n(side),
                elevation: n(elevation),
                distance_ft: n(distance),
                bearing_deg: n(bearing),
            }
        })
        .collect()
}

#[test]
fn nathans_model_agrees_with_pybaseball_row_by_row_given_its_ball_and_contact() {
    // pybaseball's calculator as the reference file ran it: 70 °F, 29.92
    // inHg, 50 %; a 5.125 oz ball of 9.125 in; g = 32.174 ft/s²; contact 3 ft
    // up and 2 ft in front of the plate; its mph → ft/s factor 1.467 (not
    // 1.4667); total spin in C_D and S, the spin fixed in space (ours too).
    let rpm = std::f64::consts::TAU / 60.0;
    let mut scene = Scene::default();
    for (key, value) in [
        ("ball.mass", 5.125 * 0.028_349_523_125),
        ("ball.radius", 9.125 * 0.0254 / std::f64::consts::TAU),
        ("environment.gravity", 32.174 * FOOT),
        ("environment.contact_height", 3.0 * FOOT),
        ("environment.temperature", (70.0 - 32.0) / 1.8),
        ("environment.pressure", 29.92 * 33.863_886_666_7),
        ("environment.humidity", 50.0),
    ] {
        scene.set(key, value).unwrap();
    }
    let rows = references();
    assert_eq!(rows.len(), 242);
    let mut worst: f64 = 0.0;
    for r in &rows {
        let mut there = scene;
        there.set("environment.elevation", r.elevation).unwrap();
        let there = there.with_launch(BattedBall {
            speed: r.speed * 1.467 / (5280.0 / 3600.0),
            angle: r.angle,
            spin: r.backspin_rpm * rpm,
            direction: r.direction,
            sidespin: r.sidespin_rpm * rpm,
        });
        let flight = fly_scene(&there, Purpose::Reference).flight;
        // From the plate: the contact point is 2 ft toward centre field.
        let (sin, cos) = flight.direction.sin_cos();
        let (x, z) = (flight.range * cos + 2.0 * FOOT, flight.range * sin);
        let distance = x.hypot(z) / FOOT;
        let difference = distance - r.distance_ft;
        assert!(difference.abs() < 0.05, "{difference} ft");
        let bearing = z.atan2(x).to_degrees();
        assert!((bearing - r.bearing_deg).abs() < 0.005, "{bearing}");
        worst = worst.max(difference.abs());
    }
    // What is left (≤ 0.03 ft) is pybaseball's τ = 10 000 s spin decay,
    // its c0 = 0.07182 (0.0718274 exactly) and the file's rounding.
    assert!(worst > 0.0 && worst < 0.05, "{worst}");
}
