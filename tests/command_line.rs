//! The real binary on hostile or odd command lines: every refusal, clap's
//! included, is one line `homerun: …` with exit status 2 that names the
//! argument, shows what was given escaped and cut, and says what is accepted;
//! help and the version still print normally; a flight that does not land is
//! never reported as a range; and every command's work is bounded.

use std::path::Path;
use std::time::{Duration, Instant};

use assert_cmd::Command;
use serde_json::Value;

fn homerun(presets: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_homerun"));
    command.arg("--presets-dir").arg(presets).timeout(LIMIT);
    command
}

/// Longer than any command here may take, on a busy 2-core machine.
const LIMIT: Duration = Duration::from_secs(60);

/// Runs `args` and returns the one line on stderr, having checked exit
/// status 2, an empty stdout, the `homerun: ` prefix, no control character
/// and a bounded length, and every `needle` in it.
fn refused<S: AsRef<std::ffi::OsStr>>(dir: &Path, args: &[S], needles: &[&str]) -> String {
    let output = homerun(dir).args(args).output().unwrap();
    let shown: Vec<String> = args
        .iter()
        .map(|a| {
            let a = a.as_ref().to_string_lossy();
            a.chars().take(40).collect()
        })
        .collect();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(output.status.code(), Some(2), "{shown:?}: {stderr}");
    assert!(output.stdout.is_empty(), "{shown:?}");
    let line = stderr
        .strip_suffix('\n')
        .unwrap_or_else(|| panic!("{shown:?}: {stderr:?}"));
    assert!(line.starts_with("homerun: "), "{shown:?}: {line}");
    assert!(!line.chars().any(char::is_control), "{shown:?}: {line:?}");
    assert!(line.chars().count() <= 1010, "{shown:?}: {line}");
    for needle in needles {
        assert!(line.contains(needle), "{shown:?}: {needle:?} not in {line}");
    }
    line.to_owned()
}

fn json(dir: &Path, args: &[&str]) -> Value {
    let output = homerun(dir).args(args).output().unwrap();
    assert!(output.status.success(), "{args:?}: {output:?}");
    serde_json::from_slice(&output.stdout).unwrap()
}

fn text(dir: &Path, args: &[&str]) -> String {
    let output = homerun(dir).args(args).output().unwrap();
    assert!(output.status.success(), "{args:?}: {output:?}");
    // Nothing on stderr when it is not a terminal: no progress line.
    assert!(output.stderr.is_empty(), "{args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}

#[test]
fn clap_refusals_are_one_line_naming_the_argument_and_what_it_takes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: &[(&[&str], &[&str])] = &[
        (
            &["trajectory", "--samples", "-5"],
            &["--samples -5: must be a whole number in [2, 100000]"],
        ),
        (
            &["trajectory", "--samples", "many"],
            &["--samples 'many': must be a whole number in [2, 100000]"],
        ),
        (
            &["sweep", "bat.speed", "--from=1", "--to=2", "--steps=1e9"],
            &["--steps 1e9: must be a whole number in [1, 200]"],
        ),
        (
            &["sweep", "bat.speed", "--from=1", "--to=2", "--steps=-1"],
            &["--steps -1: must be a whole number in [1, 200]"],
        ),
        (
            &["figure", "abc"],
            &["figure 'abc': must be a figure number, 3 to 14"],
        ),
        (
            &["figure", "99999999999"],
            &["figure 99999999999:", "3 to 14"],
        ),
        (&["figure"], &["missing <NUMBER>, a figure number, 3 to 14"]),
        (
            &["hit", "--json", "--csv"],
            &[
                "unexpected argument '--csv'",
                "homerun hit takes --preset, --set, --json",
            ],
        ),
        (
            &["table2", "--csv"],
            &["'--csv'", "homerun table2 takes --json"],
        ),
        (&["hit", "extra"], &["unexpected argument 'extra'"]),
        (&["hit", "--jsn"], &["'--jsn' (did you mean --json?)"]),
        (
            &["sweep", "bat.speed", "--from", "1"],
            &["missing --to <TO>, a number", "usage: homerun sweep"],
        ),
        (&["sweep"], &["missing --from <FROM>, --to <TO>, <KEY>"]),
        (
            &["sweep", "bat.speed", "--from", "abc", "--to", "1"],
            &["--from 'abc': must be a number"],
        ),
        (
            &["frobnicate"],
            &["unknown command 'frobnicate'", "commands: hit, trajectory"],
        ),
        (
            &["trajectory", "--json", "--csv"],
            &["'--json' cannot be used with '--csv'"],
        ),
        (
            &["hit", "--json", "--json"],
            &["'--json' cannot be used multiple times"],
        ),
        (
            &["hit", "--set"],
            &["--set: a value is required: KEY=VALUE"],
        ),
        (
            &["hit", "--preset"],
            &["--preset: a value is required: a preset name"],
        ),
        (
            &["surface", "--grid"],
            &["--grid: a value is required: NxM"],
        ),
        (&["--presets-dir"], &["--presets-dir: a value is required"]),
    ];
    for (args, needles) in cases {
        refused(d, args, needles);
    }
    // What clap would echo is escaped and cut, never a screenful.
    let hostile = format!("\x1b[2J{}", "x".repeat(100_000));
    let line = refused(
        d,
        &["hit", &hostile],
        &["unexpected argument '\\u{1b}[2Jxxx"],
    );
    assert!(line.contains("x…'"), "{line}");
    let line = refused(
        d,
        &["trajectory", "--samples", &hostile],
        &["--samples '\\u{1b}[2J"],
    );
    assert!(line.len() < 200, "{line}");
    refused(d, &["fig\nure"], &["unknown command 'fig\\u{a}ure'"]);
}

#[cfg(unix)]
#[test]
fn an_argument_that_is_not_utf8_is_refused_in_one_line() {
    use std::os::unix::ffi::OsStringExt;
    let dir = tempfile::tempdir().unwrap();
    let bad = std::ffi::OsString::from_vec(vec![b'b', 0xff, b'x']);
    refused(dir.path(), &["sweep".into(), bad], &["UTF-8"]);
}

#[test]
fn help_and_version_print_as_usual() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["--help"][..],
        &["-h"],
        &["help"],
        &["hit", "--help"],
        &["help", "sweep"],
    ] {
        let output = homerun(dir.path()).args(args).output().unwrap();
        assert_eq!(output.status.code(), Some(0), "{args:?}");
        assert!(output.stderr.is_empty(), "{args:?}");
        let text = String::from_utf8(output.stdout).unwrap();
        assert!(text.contains("Usage: homerun"), "{args:?}: {text}");
        assert!(text.lines().count() > 5, "{args:?}: {text}");
    }
    let output = homerun(dir.path()).arg("--version").output().unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(
        String::from_utf8(output.stdout).unwrap(),
        format!("homerun {}\n", env!("CARGO_PKG_VERSION"))
    );
}

#[test]
fn what_users_typed_is_escaped_and_cut_in_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let long = "y".repeat(100_000);
    let (key, value) = (format!("{long}=3"), format!("bat.speed={long}"));
    let drag = format!("model.drag={long}");
    let (path, window) = (format!("/{long}"), format!("{long}..1"));
    let cases: &[(&[&str], &[&str])] = &[
        (
            &["hit", "--set", "bat.sp\x1b]0;pwned\x07eed=30"],
            &["unknown key `bat.sp\\u{1b}]0;pwned\\u{7}eed`"],
        ),
        (
            &["hit", "--set", "bat\nspeed=30"],
            &["unknown key `bat\\u{a}speed`"],
        ),
        (&["hit", "--set", &key], &["unknown key `yyy", "y…`"]),
        (
            &["hit", "--set", &value],
            &["bat.speed = \"yyy", "y…\": not a number"],
        ),
        (
            &["hit", "--set", "bat.speed=3\x1b[2J"],
            &["bat.speed = 3\\u{1b}[2J: unknown unit `\\u{1b}[2J`"],
        ),
        (
            &["hit", "--set", &drag],
            &["model.drag = \"yyy", "y…\": unknown drag model"],
        ),
        (
            &["hit", "--set", &long],
            &["--set \"yyy", "y…\": expected KEY=VALUE"],
        ),
        (
            &["hit", "--preset", "fast\x1b[31mball"],
            &["no preset named `fast\\u{1b}[31mball`"],
        ),
        (
            &["hit", "--preset", &long[..4000]],
            &["no preset named `yyy", "y…`;"],
        ),
        (
            &["hit", "--preset", &long],
            &["--preset \"yyy", "100000 bytes"],
        ),
        (
            &["hit", "--preset", &path],
            &[
                "--preset \"/yyy",
                "100001 bytes, longer than any path can be (4096 bytes)",
            ],
        ),
        (
            &["sweep", "bat.\u{202e}speed", "--from", "1", "--to", "2"],
            &["unknown key `bat.\\u{202e}speed`"],
        ),
        (&["surface", "--grid", &long], &["--grid \"yyy", "NxM"]),
        (&["surface", "--undercut", &window], &["--undercut \"yyy"]),
    ];
    for (args, needles) in cases {
        let line = refused(d, args, needles);
        assert!(line.len() < 1000, "{line}");
    }
    // A TOML file that echoes its bad line: escaped and cut by the reader.
    let file = d.join("bad.toml");
    std::fs::write(&file, format!("[bat]\nspeed = 3 \x1b[2J{long}\n")).unwrap();
    refused(
        d,
        &["hit", "--preset", file.to_str().unwrap()],
        &["bad.toml: malformed TOML"],
    );
}

#[test]
fn the_fence_keys_work_in_set_as_in_toml() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    text(
        d,
        &[
            "hit",
            "--set",
            "field.fence_distance=100",
            "--set",
            "field.fence_height=5",
        ],
    );
    refused(
        d,
        &["hit", "--set", "field.fence_distance=2000"],
        &["field.fence_distance = 2000: must be a finite number in (0, 1000] m"],
    );
    refused(
        d,
        &["hit", "--set", "field.fence_height=0"],
        &["field.fence_height = 0: must be a finite number in (0, 100] m"],
    );
    refused(
        d,
        &["hit", "--set", "field.fence_height=tall"],
        &["field.fence_height = \"tall\""],
    );
    refused(
        d,
        &["hit", "--set", "field.fence=3"],
        &["known keys:", "field.fence_distance"],
    );
    // The same values are accepted and refused in a preset file.
    for (key, value) in [
        ("fence_distance", "1000"),
        ("fence_distance", "1000.5"),
        ("fence_distance", "1e-9"),
        ("fence_distance", "-1"),
        ("fence_distance", "nan"),
        ("fence_height", "100"),
        ("fence_height", "100.5"),
        ("fence_height", "0"),
    ] {
        let file = d.join(format!("{key}.toml"));
        std::fs::write(&file, format!("[field]\n{key} = {value}\n")).unwrap();
        let toml = homerun(d)
            .args(["hit", "--preset"])
            .arg(&file)
            .output()
            .unwrap();
        let set = homerun(d)
            .args(["hit", "--set", &format!("field.{key}={value}")])
            .output()
            .unwrap();
        assert_eq!(toml.status.code(), set.status.code(), "{key} = {value}");
    }
    let keys = text(d, &["keys"]);
    for (key, bounds) in [
        ("field.fence_distance", "(0, 1000]"),
        ("field.fence_height", "(0, 100]"),
    ] {
        let line = keys.lines().find(|l| l.starts_with(key)).expect(key);
        assert!(line.contains(bounds), "{line}");
    }
}

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

    let sweep = [
        "sweep",
        "bat.speed",
        "--from",
        "40",
        "--to",
        "50",
        "--steps",
        "3",
    ];
    let sweep = with(&sweep, FLOAT);
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
    let sweep = text(
        d,
        &with(
            &[
                "sweep",
                "bat.speed",
                "--from",
                "40",
                "--to",
                "50",
                "--steps",
                "3",
            ],
            SLOW,
        ),
    );
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

#[test]
fn a_section_written_as_a_value_is_called_a_section() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for section in ["pitch", "field"] {
        let file = d.join(format!("{section}.toml"));
        std::fs::write(&file, format!("{section} = 5\n")).unwrap();
        refused(
            d,
            &["hit", "--preset", file.to_str().unwrap()],
            &[
                &format!("{section} = 5: a section, not a value: expected a table"),
                "[header]",
            ],
        );
    }
    // Not a section at all: an unknown key, with a suggestion.
    let file = d.join("pitchh.toml");
    std::fs::write(&file, "pitchh = 5\n").unwrap();
    refused(
        d,
        &["hit", "--preset", file.to_str().unwrap()],
        &["unknown key `pitchh`"],
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
