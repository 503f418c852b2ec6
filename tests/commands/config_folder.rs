//! Issue 38, item 11: an unusable config folder (HOME or XDG_CONFIG_HOME a
//! file, the presets folder a link loop) is one warning on stderr, not a
//! stop: every command prints what it prints with no folder at all, from
//! the bundled presets and parks. A `--save` into it is refused, exit 2.

use std::path::Path;
use std::process::Output;

use crate::common;

const HOME_RUNS: &str = "tests/data/savant_home_runs.csv";

/// The commands that read the presets or the parks folder.
fn commands(batch: &Path) -> Vec<Vec<String>> {
    let batch = batch.to_str().unwrap().to_owned();
    [
        vec!["fly"],
        vec!["hit", "--preset", "curveball"],
        vec!["calibrate", HOME_RUNS, "--drag-only"],
        vec!["fly", "--batch", &batch],
        vec!["presets"],
        vec!["parks"],
        vec!["fly", "--park", "COL"],
    ]
    .into_iter()
    .map(|args| args.into_iter().map(str::to_owned).collect())
    .collect()
}

fn run(env: &[(&str, &Path)], args: &[String]) -> Output {
    let mut command = common::command();
    for (name, value) in env {
        command.env(name, value);
    }
    command.args(args).output().unwrap()
}

/// Each command under `env` prints exactly what it prints with no user
/// folder, and says once on stderr which folder it could not use.
fn bundled_only_with_a_warning(env: &[(&str, &Path)], folder: &Path) {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("launches.csv");
    std::fs::write(&batch, "launch_speed,launch_angle\n100,30\n").unwrap();
    for args in commands(&batch) {
        let plain = run(&[], &args);
        assert_eq!(plain.status.code(), Some(0), "{args:?}: {plain:?}");
        let output = run(env, &args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(0), "{args:?} {env:?}: {stderr}");
        assert_eq!(output.stdout, plain.stdout, "{args:?} {env:?}");
        let warnings: Vec<&str> = stderr.lines().filter(|l| l.contains("warning")).collect();
        assert!(
            !warnings.is_empty()
                && warnings
                    .iter()
                    .all(|w| w.starts_with("homerun: warning: your ")
                        && w.contains(folder.to_str().unwrap())),
            "{args:?} {env:?}: {stderr}"
        );
        // One line a folder, however many times the command reads it.
        assert!(warnings.len() <= 2, "{args:?}: {stderr}");
    }
}

#[test]
fn home_as_a_file_leaves_the_bundled_presets_and_parks() {
    let dir = tempfile::tempdir().unwrap();
    let home = dir.path().join("home");
    std::fs::write(&home, "not a folder").unwrap();
    bundled_only_with_a_warning(&[("HOME", &home)], &home);
}

#[test]
fn xdg_config_home_as_a_file_leaves_the_bundled_presets_and_parks() {
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join("config");
    std::fs::write(&config, "not a folder").unwrap();
    bundled_only_with_a_warning(&[("XDG_CONFIG_HOME", &config)], &config);
}

#[test]
fn a_presets_folder_in_a_link_loop_leaves_the_bundled_presets() {
    let dir = tempfile::tempdir().unwrap();
    let homerun = dir.path().join("homerun");
    std::fs::create_dir(&homerun).unwrap();
    let presets = homerun.join("presets");
    std::os::unix::fs::symlink(&presets, &presets).unwrap();
    bundled_only_with_a_warning(&[("XDG_CONFIG_HOME", dir.path())], &presets);
}

/// A folder that cannot be read. Root reads every folder whatever its
/// mode, so there this case cannot be made and is left to the others.
#[test]
fn an_unreadable_home_leaves_the_bundled_presets() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let home = dir.path().join("home");
    std::fs::create_dir(&home).unwrap();
    std::fs::set_permissions(&home, std::fs::Permissions::from_mode(0o000)).unwrap();
    if std::fs::read_dir(&home).is_err() {
        bundled_only_with_a_warning(&[("HOME", &home)], &home);
    }
    std::fs::set_permissions(&home, std::fs::Permissions::from_mode(0o700)).unwrap();
}

#[test]
fn a_save_into_an_unusable_folder_is_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let home = dir.path().join("home");
    std::fs::write(&home, "not a folder").unwrap();
    let args: Vec<String> = ["calibrate", HOME_RUNS, "--drag-only", "--save", "mine"]
        .map(str::to_owned)
        .to_vec();
    let output = run(&[("HOME", &home)], &args);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(output.stdout.is_empty());
    let last = stderr.lines().last().unwrap();
    assert!(
        last.starts_with("homerun: calibrate --save mine: your presets folder cannot be used (")
            && last.contains(home.to_str().unwrap())
            && last.contains("--presets-dir"),
        "{stderr}"
    );
}
