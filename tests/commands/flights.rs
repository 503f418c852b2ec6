//! Flights that do not land are never a range, and every command's work
//! is bounded.

use std::time::Instant;

use crate::{LIMIT, json, refused, text};

/// A scene whose balls hover: almost nothing lands.
const HOVER: &[&str] = &["--set", "environment.gravity=0.001"];

/// A big light ball with a large backspin in dense air and low gravity: no
/// swing over the explorer's window lands (found by flying random scenes).
const FLOAT: &[&str] = &[
    "--set",
    "ball.radius=0.074",
    "--set",
    "ball.mass=0.45",
    "--set",
    "ball.gyration_radius=0.055",
    "--set",
    "environment.air_density=3.9",
    "--set",
    "environment.gravity=0.0009",
    "--set",
    "bat.speed=50",
    "--set",
    "pitch.spin=520",
];

/// A short sweep of the bat's speed, three optimisations, for the scenes
/// above.
const SWEEP_BAT_SPEED: &[&str] = &[
    "sweep",
    "bat.speed",
    "--from",
    "40",
    "--to",
    "50",
    "--steps",
    "3",
];

fn with<'a>(args: &[&'a str], scene: &[&'a str]) -> Vec<&'a str> {
    [args, scene].concat()
}

#[test]
fn a_flight_that_does_not_land_is_never_a_range() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let hit = text(d, &with(&["hit"], HOVER));
    let flight = hit.lines().last().unwrap();
    assert!(
        flight.starts_with("flight   did not land within 600.0 s (still ")
            && flight.contains(" m up)"),
        "{hit}"
    );
    assert!(!hit.contains("range"), "{hit}");
    let v = json(d, &with(&["hit", "--json"], HOVER));
    assert_eq!(v["flight"]["landed"], false);
    assert!(v["flight"]["range"].is_null());
    assert!(v["flight"]["flight_time"].as_f64().unwrap() > 0.0);
    let why = v["flight"]["why_not_landed"].as_str().unwrap();
    assert!(flight.contains(why), "{why}");
    assert_eq!(json(d, &["hit", "--json"])["flight"]["landed"], true);

    let trajectory = text(d, &with(&["trajectory", "--samples", "3"], HOVER));
    assert!(
        trajectory.starts_with("a flight that did not land within 600.0 s"),
        "{trajectory}"
    );
    let v = json(d, &with(&["trajectory", "--json"], HOVER));
    assert!(v["range"].is_null() && v["landed"] == false, "{v}");

    // No swing of the window lands on FLOAT: there is no optimum.
    let optimum = text(d, &with(&["optimize"], FLOAT));
    assert!(
        optimum.starts_with(
            "optimum  none: none of 64 swings over E ∈ [0, 0.05] m, ψ ∈ [-0.6, 1] rad lands"
        ),
        "{optimum}"
    );
    assert!(
        optimum.contains("nothing to converge to: no swing lands"),
        "{optimum}"
    );
    assert!(!optimum.contains("\nrange"), "{optimum}");
    let v = json(d, &with(&["optimize", "--json"], FLOAT));
    assert_eq!(v["landed"], false);
    assert_eq!(v["status"], "nothing_lands");
    assert_eq!(v["scanned"], 64);
    for field in ["range", "undercut", "swing_angle", "launch_speed"] {
        assert!(v[field].is_null(), "{field}: {v}");
    }
    assert!(
        v["why_not_landed"]
            .as_str()
            .unwrap()
            .starts_with("did not land")
    );
    assert_eq!(json(d, &["optimize", "--json"])["landed"], true);
    // On HOVER the given swing does not land but others do: the search
    // starts from the best of a coarse scan and finds one.
    let optimum = text(d, &with(&["optimize"], HOVER));
    assert!(
        optimum.contains(
            "\nstart    the swing given does not land; started from the best of 64 swings over"
        ),
        "{optimum}"
    );
    let v = json(d, &with(&["optimize", "--json"], HOVER));
    assert_eq!(v["landed"], true, "{v}");
    assert!(v["range"].as_f64().unwrap() > 134.8, "{v}");

    let sweep = with(SWEEP_BAT_SPEED, FLOAT);
    let table = text(d, &sweep);
    let first = table.lines().nth(1).unwrap();
    assert!(first.ends_with("(no swing lands: no optimum)"), "{table}");
    assert!(
        !first.contains("inf") && !first.contains("0.0265"),
        "{first}"
    );
    let v = json(d, &[&sweep[..], &["--json"]].concat());
    let points = v["points"].as_array().unwrap();
    assert_eq!(points[0]["landed"], false);
    assert_eq!(points[0]["status"], "nothing_lands");
    assert!(points[0]["range"].is_null() && points[0]["undercut"].is_null());
    let v = json(
        d,
        &[
            "sweep",
            "environment.gravity",
            "--from",
            "0.001",
            "--to",
            "9.81",
            "--steps",
            "2",
            "--json",
        ],
    );
    let points = v["points"].as_array().unwrap();
    assert!(points.iter().all(|p| p["landed"] == true), "{v}");
    let csv = text(d, &[&sweep[..], &["--csv"]].concat());
    assert!(
        csv.lines()
            .next()
            .unwrap()
            .ends_with(",converged,status,landed"),
        "{csv}"
    );
    assert!(
        csv.lines()
            .nth(1)
            .unwrap()
            .ends_with(",false,nothing_lands,false"),
        "{csv}"
    );
    assert!(!csv.contains("inf"), "{csv}");

    // Figures whose rows are flights carry `landed`; a row that does not
    // land shows no range.
    for (figure, scene) in [("8", FLOAT), ("13", HOVER)] {
        let v = json(d, &with(&["figure", figure, "--json"], scene));
        let rows = v["rows"].as_array().unwrap();
        let down = rows.iter().find(|r| r["landed"] == false).expect(figure);
        assert!(down["range"].is_null(), "{down}");
        assert!(rows.iter().all(|r| r["landed"].is_boolean()), "{figure}");
    }
    let v = json(d, &["figure", "14", "--json"]);
    assert!(
        v["rows"]
            .as_array()
            .unwrap()
            .iter()
            .all(|r| r["landed"] == true)
    );
    // A surface marks the cells whose ball does not land: `up` in text with
    // its legend, `landed: false` and a null range in JSON, `false` and a
    // blank range in CSV; the bat's misses are null (blank) in both.
    let surface = ["surface", "--grid", "8x8", "--undercut", "0..0.08"];
    let table = text(d, &with(&surface, HOVER));
    assert!(
        table
            .lines()
            .next()
            .unwrap()
            .ends_with("- bat misses, up: the ball does not land"),
        "{table}"
    );
    assert!(table.contains("  up") && table.contains("   -"), "{table}");
    let v = json(d, &with(&[&surface[..], &["--json"]].concat(), HOVER));
    let (ranges, landed) = (
        v["ranges"].as_array().unwrap(),
        v["landed"].as_array().unwrap(),
    );
    let mut kinds = [0; 3];
    for (r, l) in ranges
        .iter()
        .flat_map(|r| r.as_array().unwrap())
        .zip(landed.iter().flat_map(|l| l.as_array().unwrap()))
    {
        match l.as_bool() {
            Some(true) => assert!(r.is_f64(), "{r}"),
            Some(false) => assert!(r.is_null(), "{r}"),
            None => assert!(r.is_null(), "{r}"),
        }
        kinds[match l.as_bool() {
            Some(true) => 0,
            Some(false) => 1,
            None => 2,
        }] += 1;
    }
    assert!(kinds.iter().all(|&k| k > 0), "{kinds:?}");
    let csv = text(d, &with(&[&surface[..], &["--csv"]].concat(), HOVER));
    assert_eq!(
        csv.lines().next(),
        Some("undercut,swing_angle,range,landed")
    );
    let count = |end: &str| csv.lines().filter(|l| l.ends_with(end)).count();
    assert_eq!(
        (count(",true"), count(",,false"), count(",,")),
        (kinds[0], kinds[1], kinds[2]),
        "{csv}"
    );
    let fig7 = text(d, &with(&["figure", "7"], HOVER));
    assert!(
        fig7.contains("up: the ball does not land") && fig7.contains("  up"),
        "{fig7}"
    );
}

/// The slowest scene found (a 1 cm ball of 1.5 g with a huge backspin in
/// dense air and low gravity): its flights take up to 100 000 steps.
const SLOW: &[&str] = &[
    "--set",
    "pitch.speed=99.99443730489737",
    "--set",
    "pitch.spin=-765.6436764401647",
    "--set",
    "bat.speed=50.05355219369941",
    "--set",
    "bat.spin=158.54338615836008",
    "--set",
    "bat.radius=0.02485337069975321",
    "--set",
    "bat.gyration_radius=0.005896685579324641",
    "--set",
    "ball.mass=0.0015235176564186116",
    "--set",
    "ball.radius=0.010012842236086304",
    "--set",
    "ball.gyration_radius=0.0037323270916390936",
    "--set",
    "environment.wind=14.271583750846887",
    "--set",
    "environment.air_density=4.9956808378659785",
    "--set",
    "environment.gravity=0.0006603265802640174",
    "--set",
    "environment.contact_height=1.8372523574322064",
];

/// A heavy-spun big ball in dense air: the search runs into its work limit.
const WORK: &[&str] = &[
    "--set",
    "ball.radius=0.063",
    "--set",
    "ball.mass=0.35",
    "--set",
    "ball.gyration_radius=0.046",
    "--set",
    "environment.air_density=4.4",
    "--set",
    "environment.gravity=0.021",
    "--set",
    "bat.speed=49",
    "--set",
    "pitch.spin=1000",
];

#[test]
fn work_is_bounded_on_the_slowest_scene() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let start = Instant::now();
    // SLOW's own swing hovers; the coarse scan finds swings that land.
    let optimum = text(d, &with(&["optimize"], SLOW));
    assert!(
        optimum.contains("\nstart    the swing given does not land"),
        "{optimum}"
    );
    // WORK's search stops at its work limit, and says so in text and JSON.
    let optimum = text(d, &with(&["optimize"], WORK));
    assert!(
        optimum.contains("NOT converged: stopped at the work limit ("),
        "{optimum}"
    );
    let v = json(d, &with(&["optimize", "--json"], WORK));
    assert_eq!(v["status"], "work_limit", "{v}");
    assert_eq!(v["converged"], false, "{v}");
    let sweep = text(d, &with(SWEEP_BAT_SPEED, SLOW));
    assert_eq!(sweep.lines().count(), 4, "{sweep}");
    // A big surface is refused as soon as its first cells show how much
    // work it would be, naming what fits.
    let line = refused(
        d,
        &with(&["surface", "--grid", "500x500"], SLOW),
        &[
            "--grid 500x500: about ",
            "integration steps on this scene",
            "accepted here: at most ~",
        ],
    );
    let side: usize = line
        .rsplit("--grid ")
        .next()
        .unwrap()
        .split('x')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((2..100).contains(&side), "{line}");
    text(
        d,
        &with(&["surface", "--grid", &format!("{side}x{side}")], SLOW),
    );
    assert!(start.elapsed() < LIMIT, "{:?}", start.elapsed());
    let sweep = ["sweep", "bat.speed", "--from=20", "--to=30", "--steps=201"];
    refused(d, &sweep, &["--steps 201", "[1, 200]"]);
    refused(
        d,
        &["surface", "--grid", "501x2"],
        &["--grid \"501x2\"", "[1, 500]"],
    );
}

/// A sweep says of each optimum what `optimize` says: on WORK at 49 m/s the
/// optimiser's best grazes the ground behind the plate at its own precision
/// (y dips to ~1e-4 m) but does not land when flown at readout precision.
#[test]
fn a_sweep_point_that_lands_only_at_the_optimisers_precision_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let sweep = &[
        "sweep",
        "bat.speed",
        "--from",
        "49",
        "--to",
        "49",
        "--steps",
        "1",
    ];
    let v = json(d, &with(&[sweep.as_slice(), &["--json"]].concat(), WORK));
    let point = &v["points"][0];
    assert_eq!(point["landed"], true, "{point}");
    assert_eq!(point["lands_at_readout"], false, "{point}");
    let optimum = json(d, &with(&["optimize", "--json"], WORK));
    assert_eq!(optimum["landed"], false, "{optimum}");
    let text = text(d, &with(sweep, WORK));
    assert!(
        text.contains("lands only at the optimiser's precision"),
        "{text}"
    );
}
