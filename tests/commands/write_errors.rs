//! Issue 38, item 1: every command's output is written fallibly. A full
//! disk (`> /dev/full`) is one line on stderr and exit 2; a pipe closed
//! before the output (`| true`) ends it quietly; neither is a panic (exit
//! 101, a backtrace), in any mode of `calibrate` and with `--save` too.

use std::process::{Output, Stdio};

use crate::common;

const HOME_RUNS: &str = "tests/data/savant_home_runs.csv";
const SWINGS: &str = "tests/data/savant_swings.csv";

/// Each command that prints, `calibrate` in every mode.
fn commands() -> Vec<Vec<&'static str>> {
    vec![
        vec!["calibrate", HOME_RUNS],
        vec!["calibrate", HOME_RUNS, "--json"],
        vec!["calibrate", HOME_RUNS, "--drag-only"],
        vec!["calibrate", HOME_RUNS, "--by", "month"],
        vec!["calibrate", HOME_RUNS, "--by", "month", "--json"],
        vec!["calibrate", "--impact", SWINGS],
        vec!["calibrate", "--impact", SWINGS, "--json"],
        vec!["hit"],
        vec!["keys"],
        vec!["presets"],
        vec!["parks"],
    ]
}

fn run_into(dir: &std::path::Path, args: &[&str], stdout: Stdio) -> Output {
    common::command()
        .arg("--presets-dir")
        .arg(dir)
        .args(args)
        .stdout(stdout)
        .output()
        .unwrap()
}

#[test]
fn a_full_disk_is_one_line_and_exit_2_in_every_command() {
    let dir = tempfile::tempdir().unwrap();
    for args in commands() {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let output = run_into(dir.path(), &args, Stdio::from(full));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        let last = stderr.lines().last().unwrap_or_default();
        assert!(
            last.starts_with("homerun: writing the output: ") && !stderr.contains("panicked"),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn a_closed_pipe_ends_every_command_quietly() {
    let dir = tempfile::tempdir().unwrap();
    for args in commands() {
        // The reading end is gone before the command starts: its first
        // write meets EPIPE, as `homerun calibrate x.csv | true` can.
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let output = run_into(dir.path(), &args, Stdio::from(writer));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(0), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
}

/// With `--save`, the preset is written before the output fails; the
/// failure is still reported, and the preset stays.
#[test]
fn calibrate_save_then_a_full_disk_keeps_the_preset_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let args = ["calibrate", HOME_RUNS, "--drag-only", "--save", "fitted"];
    let output = run_into(dir.path(), &args, Stdio::from(full));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("writing the output"), "{stderr}");
    assert!(dir.path().join("fitted.toml").is_file());
}

/// A refusal where stderr cannot take its line: still exit 2, not a
/// panic's 101.
#[test]
fn a_refusal_into_a_full_stderr_is_still_exit_2() {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let output = common::command()
        .args(["fly", "--set", "launch.sped=40"])
        .stderr(Stdio::from(full))
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
}
