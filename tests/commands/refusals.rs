//! Refusals: clap's and ours, one line each, escaped and cut; help and the
//! version; the fence keys and sections as `--set` takes them.

use crate::{homerun, refused, text};

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
        &["unknown key `field.fence`; did you mean `field.fence_"],
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

#[test]
fn a_thread_count_out_of_bounds_is_refused_at_once_in_one_line() {
    // rayon would start 100000 threads (still starting after 30 s), or
    // take a word for its own count without a word said.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let batch = d.join("rows.csv");
    std::fs::write(&batch, "launch_speed,launch_angle\n40,30\n45,25\n").unwrap();
    let batch = batch.to_str().unwrap();
    let run = |variable: &str, value: &str| {
        let start = std::time::Instant::now();
        let output = homerun(d)
            .env_remove("RAYON_NUM_THREADS")
            .env_remove("RAYON_RS_NUM_CPUS")
            .env(variable, value)
            .args(["fly", "--batch", batch])
            .output()
            .unwrap();
        assert!(start.elapsed().as_secs() < 10, "{variable}={value}");
        output
    };
    let max = homerun::cli::MAX_THREADS;
    for (variable, value) in [
        ("RAYON_NUM_THREADS", "100000"),
        ("RAYON_NUM_THREADS", &(max + 1).to_string()),
        ("RAYON_NUM_THREADS", "-1"),
        ("RAYON_NUM_THREADS", "many"),
        ("RAYON_NUM_THREADS", ""),
        ("RAYON_NUM_THREADS", "4\u{1b}[2J"),
        ("RAYON_RS_NUM_CPUS", "100000"),
    ] {
        let output = run(variable, value);
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert_eq!(
            output.status.code(),
            Some(2),
            "{variable}={value}: {stderr}"
        );
        assert!(output.stdout.is_empty());
        let line = stderr.strip_suffix('\n').unwrap();
        assert!(!line.chars().any(char::is_control), "{line:?}");
        let expected =
            format!("must be a whole number from 0 (one thread per CPU, as when unset) to {max}");
        assert!(line.starts_with(&format!("homerun: {variable}=")), "{line}");
        assert!(line.ends_with(&expected), "{line}");
    }
    // Within bounds, the same rows whatever the count.
    let plain = homerun(d).args(["fly", "--batch", batch]).output().unwrap();
    assert!(plain.status.success());
    for value in ["0", "1", "3"] {
        let output = run("RAYON_NUM_THREADS", value);
        assert!(output.status.success(), "{value}: {output:?}");
        assert_eq!(output.stdout, plain.stdout, "RAYON_NUM_THREADS={value}");
    }
    // --help says so.
    let help = text(d, &["--help"]);
    assert!(
        help.contains("RAYON_NUM_THREADS sets how many threads"),
        "{help}"
    );
    assert!(
        help.contains(&format!("to {max}; any other value is refused")),
        "{help}"
    );
}
