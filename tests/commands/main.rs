//! The real binary on hostile or odd command lines: every refusal, clap's
//! included, is one line `homerun: …` with exit status 2 that names the
//! argument, shows what was given escaped and cut, and says what is accepted;
//! help and the version still print normally; a flight that does not land is
//! never reported as a range; and every command's work is bounded.

mod bat_heading;
mod batch_on_a_terminal;
mod calibrate;
mod cli;
#[path = "../common/mod.rs"]
mod common;
mod config_folder;
mod fly;
mod fly_batch;
mod held_out;
mod help;
mod hit_batch;
mod hit_json;
mod hostile_files;
mod inf_and_no_terminal;
mod measured_spin;
mod optimize_park;
mod parks;
mod pictures;
mod pictures_explorer;
mod pipeline;
mod presets_by_name;
mod readme;
mod start_up;
mod stress_pass;
mod swing_found;
#[path = "../tui_support/mod.rs"]
mod tui_support;
mod units;
mod units_on_input;
mod unread_columns;
mod write_errors;

mod flights;
mod refusals;

use std::path::Path;
use std::time::Duration;

use assert_cmd::Command;
use serde_json::Value;

pub(crate) fn homerun(presets: &Path) -> Command {
    let mut command = common::assert_command();
    command.arg("--presets-dir").arg(presets).timeout(LIMIT);
    command
}

/// Longer than any command here may take, on a busy 2-core machine.
pub(crate) const LIMIT: Duration = Duration::from_secs(60);

/// Runs `args` and returns the one line on stderr, having checked exit
/// status 2, an empty stdout, the `homerun: ` prefix, no control character
/// and a bounded length, and every `needle` in it.
pub(crate) fn refused<S: AsRef<std::ffi::OsStr>>(
    dir: &Path,
    args: &[S],
    needles: &[&str],
) -> String {
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

pub(crate) fn json(dir: &Path, args: &[&str]) -> Value {
    let output = homerun(dir).args(args).output().unwrap();
    assert!(output.status.success(), "{args:?}: {output:?}");
    serde_json::from_slice(&output.stdout).unwrap()
}

pub(crate) fn text(dir: &Path, args: &[&str]) -> String {
    let output = homerun(dir).args(args).output().unwrap();
    assert!(output.status.success(), "{args:?}: {output:?}");
    // Nothing on stderr when it is not a terminal: no progress line.
    assert!(output.stderr.is_empty(), "{args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}
