//! What 2025's measured swings say about the bat's heading at contact
//! (issue 37; docs/swing-3d.md *The bat's heading at contact*). Where a row
//! has `attack_direction`, the bat's direction is the measured one and the
//! launch direction is no target of the solve: it is the model's
//! prediction, and the spray measures it. The model's bat, square to its
//! path in its swing plane, sends the balls to the opposite field of their
//! sprays; the real bat leads its path.

use serde_json::Value;

use crate::common::run_homerun;

/// Every 20th line of `statcast-2025-bat-tracking-three-hitters.csv` (lines
/// 20, 40, …, 1340: 67 rows of Springer, Altuve and Schwarber, as they are).
const SAMPLE: &str = "tests/data/savant_2025_every_20th.csv";

/// Statcast's spray angle (deg, + toward right field) from hc_x, hc_y.
fn spray(row: &Value) -> Option<f64> {
    let kept = |c: &str| row["kept"][c].as_str()?.parse::<f64>().ok();
    Some(
        ((kept("hc_x")? - 125.42) / (198.27 - kept("hc_y")?))
            .atan()
            .to_degrees(),
    )
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

#[test]
fn the_square_bat_sends_2025_s_balls_to_the_opposite_field_of_their_sprays() {
    let (code, out, err) = run_homerun(
        &[
            "hit",
            "--batch",
            SAMPLE,
            "--json",
            "--keep",
            "hc_x,hc_y,stand",
        ],
        None,
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("swings: solved 58 of 64 tracked"), "{err}");
    // The launch direction less the spray, toward each batter's opposite
    // field (+), for the solved rows with hit coordinates.
    let mut by_hand: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    for line in out.lines() {
        let row: Value = serde_json::from_str(line).unwrap();
        if row["solved"] != true {
            continue;
        }
        assert_eq!(row["swing"]["from"]["direction"], "measured", "{row}");
        let Some(spray) = spray(&row) else { continue };
        let launch = row["launch"]["direction"].as_f64().unwrap().to_degrees();
        let right = row["kept"]["stand"] == "R";
        let sign = if right { 1.0 } else { -1.0 };
        by_hand[usize::from(!right)].push((launch - spray) * sign);
    }
    let [right, left] = by_hand;
    assert_eq!((right.len(), left.len()), (37, 21));
    // 15.6° on the whole file's 1,180 rows; here 18.5° (the upper middle
    // value; 52 of the 58 rows on the opposite-field side), and on the
    // same side for either hand. A bat leading its path by 7–9° would put
    // it near 0.
    let all = median([right.clone(), left.clone()].concat());
    assert!((all - 18.5).abs() < 0.1, "{all}");
    for hand in [right, left] {
        let side = median(hand);
        assert!((10.0..25.0).contains(&side), "{side}");
    }
}
