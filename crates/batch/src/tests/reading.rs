//! Issue 26's reading: `NA`, `NaN`, `null` and the empty cell are missing;
//! a distance only compared never rejects a row; Statcast's columns take
//! units as `--set` does.

use super::*;

#[test]
fn missing_values_units_and_compared_columns() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let input = "launch_speed,launch_angle,hc_x,hc_y,hit_distance_sc\n\
                 100,28,NA,NaN,400\n\
                 100mph,28deg,null,,460ft\n\
                 NA,28,,,400\n\
                 100,28,,,far\n\
                 44.704m/s,28,,,140m\n";
    let (out, err, outcome) = run(&setup, input, false, Shown::default());
    assert_eq!(
        (outcome.answered, outcome.failed, outcome.without_launch),
        (4, 0, 1),
        "{err}"
    );
    let rows: Vec<Vec<&str>> = out
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    // 100 mph however written, the same launch to the bit.
    assert_eq!(rows[0][1..6], rows[1][1..6]);
    assert_eq!(rows[0][1..6], rows[3][1..6]);
    // 460 ft and 140 m in the distance column; `far` is missing.
    assert_eq!(rows[1][19], "140.21");
    assert_eq!(rows[2][19], "");
    assert_eq!(rows[3][19], "140.00");
    // A unit the column does not take is named, with those it does.
    let input = "launch_speed,launch_angle\n45kph,28\n100,28rpm\n";
    let (_, err, outcome) = run(&setup, input, false, Shown::default());
    assert_eq!(outcome.failed, 2);
    assert!(
        err.contains(
            "launch_speed = \"45kph\": unknown unit `kph`; it takes m/s, km/h, mph, ft/s \
             (a bare number is mph)"
        ),
        "{err}"
    );
    assert!(
        err.contains("launch_angle = \"28rpm\": `rpm` measures a spin rate, not an angle"),
        "{err}"
    );
}
