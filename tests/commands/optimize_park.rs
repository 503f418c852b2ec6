//! `optimize --park`: the swing (E, ψ, φ_B) that clears a park's wall by
//! the most (issue 17, docs/swing-3d.md "The best swing for a park").

use crate::common;
use std::f64::consts::FRAC_PI_4;

use homerun::Scene;
use homerun::analysis::optimum::OptimizerSettings;
use homerun::analysis::optimum::park::{Held, Judged, ParkOptimum, optimize_park};
use homerun::analysis::optimum::{Status, optimize};
use homerun::analysis::precision::Purpose;
use homerun::model::park::{self, Fence, FencePoint};
use homerun::model::scene::Hand;

fn search(scene: &Scene, fence: &Fence, held: Held) -> ParkOptimum {
    optimize_park(
        scene,
        fence,
        held,
        Purpose::Optimizer,
        OptimizerSettings::default(),
    )
}

/// The fastball's swing with the barrel 30° below the hands.
fn tilted(hand: Hand) -> Scene {
    let mut scene = Scene::default();
    scene.bat.tilt = 30f64.to_radians();
    scene.bat.hand = hand;
    scene
}

fn homerun(args: &[&str]) -> std::process::Output {
    let none = tempfile::tempdir().unwrap();
    common::assert_command()
        .arg("--presets-dir")
        .arg(none.path())
        .arg("--parks-dir")
        .arg(none.path())
        .args(args)
        .output()
        .unwrap()
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = homerun(args);
    assert!(out.status.success(), "{args:?}: {out:?}");
    serde_json::from_slice(&out.stdout).unwrap()
}

fn number(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} in {v}"))
}

#[test]
fn without_a_park_optimize_is_the_planar_range_search_it_was() {
    // The fastball's Table II optimum as `optimize --json` printed it before
    // the park search existed, with the same fields and no new ones.
    let v = json(&["optimize", "--json"]);
    let mut keys: Vec<&str> = v.as_object().unwrap().keys().map(|k| k.as_str()).collect();
    keys.sort_unstable();
    assert_eq!(
        keys,
        [
            "converged",
            "environment",
            "evaluations",
            "landed",
            "launch_angle",
            "launch_speed",
            "launch_spin",
            "range",
            "status",
            "swing_angle",
            "undercut"
        ]
    );
    for (key, before) in [
        ("undercut", 0.027268548273373425),
        ("swing_angle", 0.17435669249674735),
        ("range", 134.7948580516685),
        ("launch_angle", 0.4805213534716207),
    ] {
        let now = number(&v, key);
        assert!((now - before).abs() < 1e-9 * before, "{key}: {now}");
    }
    assert_eq!(number(&v, "evaluations"), 115.0);
}

#[test]
fn at_a_uniform_fence_a_level_swing_goes_straight_away() {
    // A level bat swung either way is its own mirror image, and a square
    // contact meets the pitch hardest: the best direction is centre field,
    // where the wall is as near as anywhere and the foul lines farthest.
    let scene = Scene::default();
    let fence = Fence::uniform(121.9, 3.0);
    let best = search(&scene, &fence, Held::default());
    assert_eq!(best.status, Status::Converged);
    assert!(best.swing.direction.abs() < 1e-3, "{best:?}");
    // Higher than the range optimum: over a wall 121.9 m out the margin
    // is the ball's height there, and a steeper swing trades range for it.
    assert!((best.margin - 11.386).abs() < 0.01, "{best:?}");
    let range = optimize(&scene, OptimizerSettings::default());
    assert!(
        best.swing.swing_angle > range.swing_angle + 0.05,
        "{best:?}"
    );
    let options = Purpose::Optimizer.flight_options();
    let longest = scene.with_swing(range.undercut, range.swing_angle);
    let at_longest = Judged::new(&longest, &fence, &options).score();
    assert!(at_longest < best.margin - 1.0, "{at_longest}");
}

#[test]
fn an_asymmetric_fence_draws_the_ball_to_its_short_side() {
    // 110 m down the left-field line, 95 m down the right: the same swing
    // goes toward right field, and clears by more than at 110 m all round.
    let point = |direction, distance| FencePoint {
        direction,
        distance,
        height: 3.0,
    };
    let fence = Fence::new(vec![point(-FRAC_PI_4, 110.0), point(FRAC_PI_4, 95.0)]).unwrap();
    let scene = Scene::default();
    let best = search(&scene, &fence, Held::default());
    assert!(best.swing.direction > 0.1, "{best:?}");
    let deep = search(&scene, &Fence::uniform(110.0, 3.0), Held::default());
    assert!(best.margin > deep.margin + 2.0, "{best:?} {deep:?}");
}

/// `fence` reflected in the centre-field line.
fn mirrored(fence: &Fence) -> Fence {
    let points = fence
        .points()
        .iter()
        .rev()
        .map(|p| FencePoint {
            direction: -p.direction,
            ..*p
        })
        .collect();
    Fence::new(points).unwrap()
}

#[test]
fn a_left_handed_batter_at_the_mirror_image_of_a_park_swings_the_mirror_image() {
    for code in ["BOS", "NYY"] {
        let fence = &park::find(park::bundled(), code).unwrap().fence;
        let right = search(&tilted(Hand::Right), fence, Held::default());
        let left = search(&tilted(Hand::Left), &mirrored(fence), Held::default());
        assert!(right.found && left.found);
        // The same path in the batter's frame: equal to the last bit today
        // (the mirrored fence's interpolation could round differently).
        assert!((right.swing.undercut - left.swing.undercut).abs() < 1e-15);
        assert!((right.swing.swing_angle - left.swing.swing_angle).abs() < 1e-14);
        assert!((right.swing.direction + left.swing.direction).abs() < 1e-14);
        assert!(
            (right.margin - left.margin).abs() < 1e-12,
            "{right:?} {left:?}"
        );
        assert_eq!(right.evaluations, left.evaluations);
        // At Fenway a right-handed batter pulls, over the Monster: the bat's
        // velocity heads toward left field (−0.25 rad), its barrel out in
        // front of the hands as it rises through the contact in its tilted
        // plane. (At Yankee Stadium the bat in its plane now goes the other
        // way, +0.15 rad, toward the short porch in right.)
        if code == "BOS" {
            assert!(right.swing.direction < -0.2, "{right:?}");
        }
    }
}

#[test]
fn a_held_key_keeps_the_scenes_value_exactly() {
    let at_nyy =
        |extra: &[&str]| json(&[&["optimize", "--json", "--park", "NYY"][..], extra].concat());
    let v = at_nyy(&["--set", "bat.direction=0.1", "--fix", "bat.direction"]);
    assert_eq!(number(&v, "bat_direction"), 0.1);
    assert_eq!(v["held"], serde_json::json!(["bat.direction"]));
    let v = at_nyy(&[
        "--set",
        "bat.undercut=0.031",
        "--fix",
        "bat.undercut",
        "--fix",
        "bat.swing_angle",
    ]);
    assert_eq!(number(&v, "undercut"), 0.031);
    assert_eq!(number(&v, "swing_angle"), Scene::default().bat.swing_angle);
    assert_ne!(number(&v, "bat_direction"), 0.0);
}

#[test]
fn the_margin_is_the_one_fly_gives_the_optimum_at_that_park() {
    // In the park's air (Coors: 1580 m), as `fly --park` flies.
    let v = json(&["optimize", "--json", "--park", "COL"]);
    assert_eq!(v["outcome"], "clears");
    let margin = number(&v, "margin");
    assert_eq!(
        margin,
        number(&v, "over_wall").min(number(&v, "inside_line"))
    );
    let set = |key: &str, field: &str| format!("{key}={}", number(&v, field));
    let fly = json(&[
        "fly",
        "--json",
        "--park",
        "COL",
        "--set",
        &set("bat.undercut", "undercut"),
        "--set",
        &set("bat.swing_angle", "swing_angle"),
        "--set",
        &set("bat.direction", "bat_direction"),
    ]);
    assert_eq!(number(&fly["fence"], "margin"), number(&v, "over_wall"));
    assert_eq!(number(&fly["launch"], "direction"), number(&v, "direction"));
    let elevation = number(&v["environment"]["atmosphere"], "elevation");
    assert!((elevation - 1580.0).abs() < 1.0, "{elevation}");
}

#[test]
fn imperial_text_gives_the_margin_in_feet_and_the_directions_in_degrees() {
    let v = json(&["optimize", "--json", "--park", "BOS"]);
    let out = homerun(&["optimize", "--park", "BOS", "--units", "imperial"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let feet = format!("margin   {:.2} ft ", number(&v, "margin") / 0.3048);
    assert!(text.contains(&feet), "{feet} in {text}");
    let degrees = number(&v, "bat_direction").abs().to_degrees();
    assert!(
        text.contains(&format!("bat swung {degrees:.1}° toward")),
        "{text}"
    );
}

#[test]
fn a_bad_park_or_key_to_hold_is_one_line_naming_it_and_what_is_accepted() {
    for (args, names) in [
        (
            &["optimize", "--park", "XYZ"][..],
            &["\"XYZ\"", "NYY", "BOS"][..],
        ),
        (
            &["optimize", "--park", "NYY", "--fix", "bat.speed"],
            &[
                "--fix 'bat.speed'",
                "bat.undercut, bat.swing_angle, bat.direction",
            ],
        ),
        (&["optimize", "--fix", "bat.undercut"], &["--park <CODE>"]),
    ] {
        let out = homerun(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty());
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        for name in names {
            assert!(err.contains(name), "{name} in {err}");
        }
    }
}

#[test]
fn a_swing_that_cannot_clear_says_how_far_below_the_wall_and_outside_the_line() {
    // A 5 m/s bat cannot send the fastball out: the best swing found has a
    // negative margin, and the text names each side by its sign rather
    // than printing "-14.68 m inside the foul line".
    let v = json(&[
        "optimize",
        "--json",
        "--park",
        "BOS",
        "--set",
        "bat.speed=5",
    ]);
    let (over, inside) = (number(&v, "over_wall"), number(&v, "inside_line"));
    assert!(number(&v, "margin") < 0.0, "{v}");
    let out = homerun(&["optimize", "--park", "BOS", "--set", "bat.speed=5"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let wall = if over < 0.0 {
        format!("{:.2} m below the wall's top", -over)
    } else {
        format!("{over:.2} m over the wall")
    };
    let line = if inside < 0.0 {
        format!("{:.2} m outside the foul line", -inside)
    } else {
        format!("{inside:.2} m inside the foul line")
    };
    let margin = text.lines().find(|l| l.starts_with("margin")).unwrap();
    assert_eq!(
        margin,
        format!("margin   {:.2} m: {wall}, {line}", number(&v, "margin"))
    );
}

/// Issue 28, item 14: where the two sides balance, the margin is said once.
#[test]
fn a_balanced_margin_is_one_number_once() {
    let out = homerun(&["optimize", "--park", "BOS"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let margin = text.lines().find(|l| l.starts_with("margin")).unwrap();
    assert!(
        margin.ends_with(" m over the wall and inside the foul line alike"),
        "{margin}"
    );
    assert_eq!(margin.matches(" m ").count(), 1, "{margin}");
}
