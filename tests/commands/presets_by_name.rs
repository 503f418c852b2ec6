//! When a user's preset and a bundled one share a name, the user's wins, and
//! `presets` says so beside both; text from the user's files reaches the
//! terminal escaped.

use crate::common;

fn presets(dir: &std::path::Path) -> String {
    let out = common::assert_command()
        .arg("--presets-dir")
        .arg(dir)
        .arg("presets")
        .output()
        .unwrap();
    assert!(out.status.success());
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn a_users_preset_wins_a_name_and_both_entries_say_so() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("fastball.toml"), "[bat]\nspeed = 33\n").unwrap();
    let listing = presets(dir.path());
    let file = dir.path().join("fastball.toml");
    assert!(
        listing.contains(&format!(
            "(bundled; hidden by {}, which --preset fastball loads)",
            file.display()
        )),
        "{listing}"
    );
    assert!(
        listing.contains(&format!("({}; hides the bundled fastball)", file.display())),
        "{listing}"
    );
    // And `--preset fastball` loads the user's file: a 33 m/s bat, not the
    // bundled 30, launches faster than Table II's 44.30 m/s.
    let out = common::assert_command()
        .arg("--presets-dir")
        .arg(dir.path())
        .args(["hit", "--preset", "fastball", "--json"])
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let speed = json["impact"]["launch_speed"].as_f64().unwrap();
    assert!(speed > 45.5, "{json}");
}

#[test]
fn descriptions_and_names_are_escaped() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("evil.toml"),
        "description = \"evil \\u001b]0;pwned\\u0007\\u001b[2J\"\n",
    )
    .unwrap();
    let listing = presets(dir.path());
    assert!(
        !listing.contains('\u{1b}') && !listing.contains('\u{7}'),
        "{listing:?}"
    );
    assert!(
        listing.contains(r"evil \u{1b}]0;pwned\u{7}\u{1b}[2J"),
        "{listing}"
    );
}

/// The user's folders come from XDG_CONFIG_HOME or HOME alone (no lookup of
/// the user, which crashed a static glibc under an unknown uid); with
/// neither, every command works on the bundled presets and parks, and only
/// a save says it has no folder.
#[test]
fn the_user_folders_come_from_the_environment_alone() {
    let run = |env: &[(&str, &std::path::Path)], args: &[&str]| {
        let mut command = common::assert_command();
        command.env_clear().args(args);
        for (name, value) in env {
            command.env(name, value);
        }
        command.output().unwrap()
    };
    let data = tempfile::tempdir().unwrap();
    let rows = data.path().join("rows.csv");
    std::fs::write(
        &rows,
        "launch_speed,launch_angle,hit_distance_sc\n105,28,400\n104,30,395\n106,27,405\n\
         101,25,380\n99,31,370\n108,26,420\n103,29,398\n100,33,385\n107,24,404\n102,27,392\n",
    )
    .unwrap();
    let rows = rows.to_str().unwrap();
    // Neither variable set.
    for args in [
        &["keys"][..],
        &["fly", "--preset", "fly-ball"],
        &["parks", "BOS"],
        &["optimize", "--park", "BOS"],
        &["fly", "--batch", rows, "--preset", "fly-ball"],
        &["calibrate", rows],
    ] {
        let out = run(&[], args);
        assert!(out.status.success(), "{args:?}: {out:?}");
        assert!(!out.stdout.is_empty(), "{args:?}");
    }
    let listing = String::from_utf8(run(&[], &["presets"]).stdout).unwrap();
    assert!(listing.contains("No user preset folder"), "{listing}");
    let out = run(&[], &["calibrate", rows, "--save", "mine"]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains(homerun::preset::NO_FOLDER), "{stderr}");
    // HOME alone: ~/.config/homerun; XDG_CONFIG_HOME first when absolute.
    let home = tempfile::tempdir().unwrap();
    let xdg = tempfile::tempdir().unwrap();
    let saved = |env: &[(&str, &std::path::Path)]| {
        let out = run(env, &["calibrate", rows, "--save", "mine"]);
        assert!(out.status.success(), "{env:?}: {out:?}");
    };
    saved(&[("HOME", home.path())]);
    assert!(
        home.path()
            .join(".config/homerun/presets/mine.toml")
            .is_file()
    );
    saved(&[("HOME", home.path()), ("XDG_CONFIG_HOME", xdg.path())]);
    assert!(xdg.path().join("homerun/presets/mine.toml").is_file());
    let relative = std::path::Path::new("relative");
    let listing = run(
        &[("HOME", home.path()), ("XDG_CONFIG_HOME", relative)],
        &["presets"],
    );
    let listing = String::from_utf8(listing.stdout).unwrap();
    let folder = home.path().join(".config/homerun/presets");
    assert!(
        listing.contains(&format!("Your presets: {}", folder.display())),
        "{listing}"
    );
}
