//! A batch whose stderr is a terminal: the progress line shows after a
//! second, from a thread of its own, while the rows go to a file. The run
//! held stderr's lock until its end, the progress thread waited on that
//! lock and the run on the thread: every batch past a second hung.
//!
//! The batch lasts past the second on any machine because its rows come
//! through a pipe that stalls for two seconds halfway (a faster build once
//! ended 12,000 rows inside the second, and the line never showed).

use std::io::Read;
use std::time::{Duration, Instant};

use portable_pty::{CommandBuilder, PtySize, native_pty_system};

/// Rows in each half of the stalled stream, each flown to the 30 parks in
/// their own air (`--all-parks`).
const ROWS: usize = 2_000;

#[test]
fn a_long_batch_on_a_terminal_ends_and_shows_its_summary() {
    let dir = tempfile::tempdir().unwrap();
    let first = dir.path().join("first.csv");
    let second = dir.path().join("second.csv");
    let output = dir.path().join("out.csv");
    let mut csv = String::from("launch_speed,launch_angle,hc_x,hc_y,home_team\n");
    let teams = ["BOS", "COL", "NYY", "SF", "HOU"];
    let row = |k: usize| {
        let speed = 80.0 + (k % 35) as f64;
        let angle = 10.0 + (k % 30) as f64;
        let x = 90.0 + (k % 80) as f64;
        format!("{speed},{angle},{x},60,{}\n", teams[k % 5])
    };
    csv.extend((0..ROWS).map(row));
    std::fs::write(&first, csv).unwrap();
    std::fs::write(&second, (ROWS..2 * ROWS).map(row).collect::<String>()).unwrap();

    let pair = native_pty_system()
        .openpty(PtySize {
            rows: 24,
            cols: 200,
            pixel_width: 0,
            pixel_height: 0,
        })
        .unwrap();
    // Only stderr on the terminal: the rows to a file, as an analyst runs it.
    let mut command = CommandBuilder::new("sh");
    command.args([
        "-c",
        r#"{ cat "$1"; sleep 2; cat "$2"; } | "$0" fly --all-parks --batch - > "$3""#,
        env!("CARGO_BIN_EXE_homerun"),
        first.to_str().unwrap(),
        second.to_str().unwrap(),
        output.to_str().unwrap(),
    ]);
    command.env_remove("HOME");
    command.env_remove("XDG_CONFIG_HOME");
    let mut child = pair.slave.spawn_command(command).unwrap();
    drop(pair.slave);
    let mut reader = pair.master.try_clone_reader().unwrap();
    let seen = std::thread::spawn(move || {
        let mut all = Vec::new();
        let mut buf = [0u8; 4096];
        while let Ok(n) = reader.read(&mut buf) {
            if n == 0 {
                break;
            }
            all.extend_from_slice(&buf[..n]);
        }
        String::from_utf8_lossy(&all).into_owned()
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(120) {
            child.kill().unwrap();
            panic!("the batch hung on a terminal");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    drop(pair.master);
    let shown = seen.join().unwrap();
    assert_eq!(status.exit_code(), 0, "{shown}");
    // The progress line was drawn (and erased), then the summary.
    assert!(shown.contains("homerun: fly --batch "), "{shown}");
    assert!(shown.contains("summary: flown 4000 rows"), "{shown}");
    let rows = std::fs::read_to_string(&output).unwrap().lines().count();
    assert_eq!(rows, 2 * ROWS + 1);
}
