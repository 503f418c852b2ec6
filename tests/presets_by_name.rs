//! When a user's preset and a bundled one share a name, the user's wins, and
//! `presets` says so beside both; text from the user's files reaches the
//! terminal escaped.

use assert_cmd::Command;

fn presets(dir: &std::path::Path) -> String {
    let out = Command::cargo_bin("homerun")
        .unwrap()
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
    let out = Command::cargo_bin("homerun")
        .unwrap()
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
