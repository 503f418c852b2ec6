//! Issue 38's smaller ones: an infinite value typed is shown as `inf`, not
//! `infe`; `tui --savant -` without a terminal is refused before it reads
//! (and solves) all of stdin.

use std::process::Stdio;
use std::time::{Duration, Instant};

use crate::common;

#[test]
fn an_infinite_speed_is_refused_and_shown_as_inf() {
    let output = common::command()
        .args(["--units", "imperial", "fly", "--set", "launch.speed=inf"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("launch.speed = inf mph (inf m/s): must be a finite number"),
        "{stderr}"
    );
    assert!(!stderr.contains("infe"), "{stderr}");
}

/// Stdin is a pipe left open with nothing in it: reading it would wait
/// for ever, so a prompt refusal shows the terminal was asked for first.
#[test]
fn tui_savant_from_a_pipe_is_refused_before_reading_it() {
    for args in [
        &["tui", "--savant", "-"][..],
        &["tui", "--savant", "tests/data/savant_swings.csv"],
    ] {
        let mut child = common::command()
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let _open_pipe = child.stdin.take();
        let start = Instant::now();
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break status;
            }
            if start.elapsed() > Duration::from_secs(20) {
                let _ = child.kill();
                panic!("{args:?}: still reading stdin after 20 s");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let output = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains("needs a terminal"), "{args:?}: {stderr}");
        // Nothing solved: the count of swings is never said.
        assert!(!stderr.contains("swings solved"), "{args:?}: {stderr}");
    }
}
