//! End to end: the real binary in a pseudo-terminal, keys in, screen out.
#![allow(unsafe_code)] // libc: reads of the pseudo-terminal's own descriptor.

use crate::common;
use std::io::{Read, Write};
use std::num::NonZeroU16;
use std::sync::{Arc, Mutex};
use std::thread;
use std::time::{Duration, Instant};

use portable_pty::{CommandBuilder, PtySize, native_pty_system};

/// How long a wait for the screen lasts at most: far past what a loaded
/// machine takes (the explorer's work on two busy cores), so that a test
/// fails with the screen it saw rather than hangs when the text never
/// comes. Every wait here polls for its condition; none sleeps a fixed time
/// and hopes.
const PATIENCE: Duration = Duration::from_secs(60);
/// A wait's poll.
const POLL: Duration = Duration::from_millis(20);
/// How long the explorer writes nothing before its screen counts as drawn
/// whole: a frame read half (the terminal reads while the explorer writes)
/// can show a new value above a status line not yet rewritten.
const QUIET: Duration = Duration::from_millis(600);

pub(crate) struct Session {
    pub(crate) screen: Arc<Mutex<vt100::Parser>>,
    /// Everything the explorer wrote.
    bytes: Arc<Mutex<Vec<u8>>>,
    reader: Option<thread::JoinHandle<()>>,
    writer: Box<dyn Write + Send>,
    pub(crate) child: Box<dyn portable_pty::Child + Send + Sync>,
    pub(crate) master: Box<dyn portable_pty::MasterPty + Send>,
}

impl Session {
    pub(crate) fn start(args: &[&str], cols: u16, rows: u16) -> Session {
        Session::start_with(args, cols, rows, &[])
    }

    /// [`Session::start`] with `env` set too.
    fn start_with(args: &[&str], cols: u16, rows: u16, env: &[(&str, &str)]) -> Session {
        let pair = native_pty_system()
            .openpty(PtySize {
                rows,
                cols,
                pixel_width: 0,
                pixel_height: 0,
            })
            .unwrap();
        let mut command = CommandBuilder::new(env!("CARGO_BIN_EXE_homerun"));
        command.args(args);
        command.env("TERM", "xterm-256color");
        command.env_remove("HOME");
        command.env_remove("XDG_CONFIG_HOME");
        command.env_remove("COLORTERM");
        command.env_remove("NO_COLOR");
        command.env_remove("COLORFGBG");
        for (name, value) in env {
            command.env(name, value);
        }
        let child = pair.slave.spawn_command(command).unwrap();
        drop(pair.slave);
        let mut reader = pair.master.try_clone_reader().unwrap();
        let writer = pair.master.take_writer().unwrap();
        let screen = Arc::new(Mutex::new(vt100::Parser::new(
            NonZeroU16::new(rows).unwrap(),
            NonZeroU16::new(cols).unwrap(),
            0,
        )));
        let bytes = Arc::new(Mutex::new(Vec::new()));
        let (s, b) = (Arc::clone(&screen), Arc::clone(&bytes));
        let reader = thread::spawn(move || {
            let mut buf = [0u8; 8192];
            while let Ok(n) = reader.read(&mut buf) {
                if n == 0 {
                    break;
                }
                s.lock().unwrap().process(&buf[..n]);
                b.lock().unwrap().extend_from_slice(&buf[..n]);
            }
        });
        Session {
            screen,
            bytes,
            reader: Some(reader),
            writer,
            child,
            master: pair.master,
        }
    }

    pub(crate) fn contents(&self) -> String {
        self.screen.lock().unwrap().screen().contents()
    }

    /// Waits (up to a generous bound, so a broken build fails rather than
    /// hangs) until the screen shows `text`.
    pub(crate) fn wait_for(&self, text: &str) -> String {
        self.wait_for_all(&[text])
    }

    /// The first screen that shows every one of `texts` at once: a frame
    /// caught half written (the terminal reads while the explorer draws)
    /// can show one and not yet another.
    pub(crate) fn wait_for_all(&self, texts: &[&str]) -> String {
        self.wait_until(&format!("all of {texts:?}"), |contents| {
            texts.iter().all(|text| contents.contains(text))
        })
    }

    /// Waits until the screen no longer shows `text` (a popup closed).
    pub(crate) fn wait_for_gone(&self, text: &str) -> String {
        self.wait_until(&format!("{text:?} gone"), |contents| {
            !contents.contains(text)
        })
    }

    /// The first screen `done` holds for, polled (up to [`PATIENCE`]; past
    /// it the test fails, naming `what` and the screen).
    fn wait_until(&self, what: &str, done: impl Fn(&str) -> bool) -> String {
        self.wait_within(PATIENCE, what, done)
    }

    fn wait_within(&self, patience: Duration, what: &str, done: impl Fn(&str) -> bool) -> String {
        let start = Instant::now();
        loop {
            let contents = self.contents();
            if done(&contents) {
                return contents;
            }
            assert!(
                start.elapsed() < patience,
                "never saw {what} in {patience:?}; screen:\n{contents}"
            );
            thread::sleep(POLL);
        }
    }

    /// Waits until the explorer has written nothing for [`QUIET`] and its
    /// screen, so drawn whole, shows every one of `texts`: its work done.
    /// The bytes written in that quiet stretch are none.
    fn wait_until_settled(&self, texts: &[&str]) -> String {
        let start = Instant::now();
        loop {
            self.wait_for_all(texts);
            let (mut written, mut since) = (self.bytes.lock().unwrap().len(), Instant::now());
            while since.elapsed() < QUIET {
                assert!(
                    start.elapsed() < PATIENCE,
                    "never quiet for {QUIET:?} in {PATIENCE:?}; screen:\n{}",
                    self.contents()
                );
                thread::sleep(POLL);
                let now = self.bytes.lock().unwrap().len();
                if now != written {
                    (written, since) = (now, Instant::now());
                }
            }
            let contents = self.contents();
            if texts.iter().all(|text| contents.contains(text)) {
                return contents;
            }
        }
    }

    pub(crate) fn press(&mut self, keys: &str) {
        self.writer.write_all(keys.as_bytes()).unwrap();
        self.writer.flush().unwrap();
    }

    pub(crate) fn exit_code(&mut self) -> u32 {
        let start = Instant::now();
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                // The reader ends when the terminal closes: all output is in.
                if let Some(reader) = self.reader.take() {
                    reader.join().unwrap();
                }
                return status.exit_code();
            }
            assert!(start.elapsed() < PATIENCE, "did not exit");
            thread::sleep(POLL);
        }
    }
}

#[test]
fn the_explorer_runs_in_a_terminal_takes_keys_saves_and_quits() {
    let dir = tempfile::tempdir().unwrap();
    let dir_arg = dir.path().to_str().unwrap();
    let mut session = Session::start(&["--presets-dir", dir_arg], 80, 24);
    session.wait_for("Trajectory");
    session.wait_for("optimum ✓");
    // The bat speed is selected: nudge it up by 10 steps (5 m/s).
    session.press("L");
    let screen = session.wait_for("35 m/s");
    assert!(
        screen.contains("V̂_B0") || screen.contains("V_B0"),
        "{screen}"
    );
    // The optimum, the surface and the sensitivity at the optimum (last) for
    // the new speed: on a screen drawn whole, not one with the new value
    // above the old status line.
    session.wait_until_settled(&["35 m/s", "optimum ✓", "surface ✓", "Δ ✓"]);
    // An idle explorer writes nothing: not in the quiet stretch just waited
    // for, nor in as long again.
    let before = session.bytes.lock().unwrap().len();
    thread::sleep(QUIET);
    let after = session.bytes.lock().unwrap().clone();
    // On failure, what was written and onto which screen, to find the cause.
    assert_eq!(
        after.len(),
        before,
        "idle output {:?} onto\n{}",
        String::from_utf8_lossy(&after[before..]),
        session.contents()
    );
    // Help, then save under a new name.
    session.press("?");
    session.wait_for("this help");
    session.press("x");
    session.press("s");
    session.wait_for("Save preset");
    session.press("\u{7f}\u{7f}\u{7f}\u{7f}\u{7f}\u{7f}\u{7f}\u{7f}fast35\r");
    session.wait_for("2/2 what `fast35` is for");
    session.press("faster bat\r");
    session.wait_for("saved ");
    let saved = std::fs::read_to_string(dir.path().join("fast35.toml")).unwrap();
    assert!(
        saved.starts_with("description = \"faster bat\"\n"),
        "{saved}"
    );
    session.press("q");
    assert_eq!(session.exit_code(), 0);
    // Every frame is wrapped in a synchronized update (DEC mode 2026).
    let count = |pattern: &[u8]| {
        let bytes = session.bytes.lock().unwrap();
        bytes
            .windows(pattern.len())
            .filter(|w| *w == pattern)
            .count()
    };
    let (begun, ended) = (count(b"\x1b[?2026h"), count(b"\x1b[?2026l"));
    assert!(
        begun >= 5 && begun == ended,
        "synchronized frames {begun}/{ended}"
    );

    // Reopen on the saved preset: the bat speed is back.
    let mut session = Session::start(
        &["--presets-dir", dir_arg, "tui", "--preset", "fast35"],
        80,
        24,
    );
    session.wait_for_all(&["Trajectory", "fast35", "35 m/s"]);
    session.press("\u{3}"); // Ctrl-C
    assert_eq!(session.exit_code(), 0);
}

/// A wait for text that never comes fails, with the screen it saw, once its
/// patience is out (here 2 s, not [`PATIENCE`]).
#[test]
#[should_panic(expected = "never saw all of [\"no such text\"] in 2s; screen:")]
fn a_wait_for_text_that_never_comes_fails() {
    let session = Session::start(&[], 80, 24);
    session.wait_for("Trajectory");
    session.wait_within(Duration::from_secs(2), "all of [\"no such text\"]", |s| {
        s.contains("no such text")
    });
}

#[test]
fn sigterm_restores_the_terminal_and_exits_143() {
    let mut session = Session::start(&[], 100, 30);
    session.wait_for("Trajectory");
    let pid = session.child.process_id().unwrap();
    let status = std::process::Command::new("kill")
        .args(["-TERM", &pid.to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    // 128 + 15, as a shell reports a process SIGTERM ended.
    assert_eq!(session.exit_code(), 143);
    // The alternate screen is left: the normal screen is back (empty here).
    let screen = session.contents();
    assert!(!screen.contains("Trajectory"), "{screen}");
}

#[test]
fn without_a_terminal_it_points_at_the_cli() {
    let output = common::command()
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("needs a terminal") && stderr.contains("homerun --help"),
        "{stderr}"
    );
    assert!(output.stdout.is_empty());
}

/// A terminal that goes away (a dropped SSH connection, a killed tmux) under
/// a shell: the shell, not the explorer, leads the session and gets SIGHUP,
/// and the explorer must still notice and end instead of spinning on the dead
/// TTY (crossterm 0.29 loops forever there), with 129 (128 + SIGHUP), as if
/// the signal had reached it: its status is written by a subshell that
/// ignores the hang-up.
#[cfg(target_os = "linux")]
#[test]
fn a_terminal_that_goes_away_ends_the_explorer() {
    let pair = native_pty_system()
        .openpty(PtySize {
            rows: 24,
            cols: 80,
            pixel_width: 0,
            pixel_height: 0,
        })
        .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let status = dir.path().join("status");
    let mut command = CommandBuilder::new("sh");
    // Not `exec`: the shell stays the session's leader, as in tmux or ssh.
    command.args([
        "-c",
        "( trap '' HUP; \"$0\"; echo $? > \"$1\" ); echo after",
        env!("CARGO_BIN_EXE_homerun"),
        status.to_str().unwrap(),
    ]);
    command.env("TERM", "xterm-256color");
    let mut shell = pair.slave.spawn_command(command).unwrap();
    drop(pair.slave);
    // Read the screen without cloning the master (a clone would keep the
    // terminal open): non-blocking reads on the master's own descriptor.
    let fd = pair.master.as_raw_fd().unwrap();
    // SAFETY: fcntl and read on a descriptor the master owns for this scope.
    unsafe {
        let flags = libc::fcntl(fd, libc::F_GETFL);
        libc::fcntl(fd, libc::F_SETFL, flags | libc::O_NONBLOCK);
    }
    let mut seen = Vec::new();
    let start = Instant::now();
    while !String::from_utf8_lossy(&seen).contains("Trajectory") {
        assert!(start.elapsed() < PATIENCE, "never started");
        let mut buf = [0u8; 8192];
        let n = unsafe { libc::read(fd, buf.as_mut_ptr().cast(), buf.len()) };
        if n > 0 {
            seen.extend_from_slice(&buf[..n as usize]);
        } else {
            thread::sleep(POLL);
        }
    }
    let subshell = child_named(shell.process_id().unwrap(), "sh").expect("the subshell runs");
    let explorer = child_named(subshell, "homerun").expect("the explorer runs");
    drop(pair.master); // the terminal goes away
    let start = Instant::now();
    while running(explorer) {
        if start.elapsed() > PATIENCE {
            // Leave no spinning process behind a failed run.
            let _ = std::process::Command::new("kill")
                .args(["-KILL", &explorer.to_string()])
                .status();
            panic!("the explorer outlived its terminal");
        }
        thread::sleep(POLL);
    }
    let _ = shell.wait();
    let start = Instant::now();
    let written = loop {
        match std::fs::read_to_string(&status) {
            Ok(text) if text.ends_with('\n') => break text,
            _ if start.elapsed() > PATIENCE => panic!("no status written"),
            _ => thread::sleep(POLL),
        }
    };
    assert_eq!(written, "129\n");
}

/// A child of `parent` whose command name is `name`, from /proc.
#[cfg(target_os = "linux")]
fn child_named(parent: u32, name: &str) -> Option<u32> {
    std::fs::read_dir("/proc").ok()?.find_map(|entry| {
        let pid: u32 = entry.ok()?.file_name().to_str()?.parse().ok()?;
        let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
        // "pid (comm) state ppid ..."
        let (comm, rest) = stat.split_once(") ")?;
        let ppid: u32 = rest.split(' ').nth(1)?.parse().ok()?;
        (ppid == parent && comm.ends_with(&format!("({name}"))).then_some(pid)
    })
}

/// Whether `pid` is alive and not a zombie awaiting its reaper.
#[cfg(target_os = "linux")]
fn running(pid: u32) -> bool {
    std::fs::read_to_string(format!("/proc/{pid}/stat"))
        .ok()
        .and_then(|stat| {
            stat.split_once(") ")
                .map(|(_, rest)| !rest.starts_with('Z'))
        })
        .unwrap_or(false)
}

/// Issue 27 item 5: `tui --savant FILE` solves the file's swings before
/// the explorer opens and says how many; a file without bat tracking is
/// refused in one line naming it. In a terminal: without one, issue 38
/// refuses before the file is read.
#[test]
fn tui_savant_solves_the_files_swings_and_refuses_a_file_without_them() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/");
    let swings = format!("{data}savant_swings.csv");
    let mut session = Session::start(&["tui", "--savant", &swings], 100, 30);
    // 33 of the 35 with the 2024 bat (the rows' season; 31 with the
    // paper's).
    session.wait_for("Open a swing (33)");
    session.press("\u{1b}");
    // Apart from the Esc (read once the picker is gone), or the two read as
    // Alt-q.
    session.wait_for_gone("Open a swing (33)");
    session.press("q");
    assert_eq!(session.exit_code(), 0);
    let written = String::from_utf8_lossy(&session.bytes.lock().unwrap()).into_owned();
    assert!(
        written.contains("homerun: 33 swings solved of 35 rows (2 tracked but not solved)"),
        "{written}"
    );
    let home_runs = format!("{data}savant_home_runs.csv");
    let mut session = Session::start(&["tui", "--savant", &home_runs], 100, 30);
    assert_eq!(session.exit_code(), 2);
    let written = String::from_utf8_lossy(&session.bytes.lock().unwrap()).into_owned();
    let expected = format!("homerun: tui --savant {home_runs}: line 1 (the header): no bat_speed");
    assert!(written.starts_with(&expected), "{written}");
    assert_eq!(written.lines().count(), 1, "{written}");
}

/// `tui --savant FILE --column NAME=COLUMN` maps a renamed column as `fly
/// --batch` does: a file whose exit speed is `EV` is refused naming it,
/// and opens its swings once mapped.
#[test]
fn tui_savant_maps_a_renamed_column() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/");
    let text = std::fs::read_to_string(format!("{data}savant_swings.csv")).unwrap();
    let (header, rows) = text.split_once('\n').unwrap();
    let header: Vec<&str> = (header.split(','))
        .map(|c| if c == "launch_speed" { "EV" } else { c })
        .collect();
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("renamed.csv");
    std::fs::write(&file, format!("{}\n{rows}", header.join(","))).unwrap();
    let file = file.to_str().unwrap();
    let mut session = Session::start(&["tui", "--savant", file], 100, 30);
    assert_eq!(session.exit_code(), 2);
    let written = String::from_utf8_lossy(&session.bytes.lock().unwrap()).into_owned();
    assert!(
        written.contains("no launch speed column") && written.contains("did you mean `EV`?"),
        "{written}"
    );
    // The explorer takes no --set: its refusals offer none.
    assert!(!written.contains("--set"), "{written}");
    let args = ["tui", "--savant", file, "--column", "launch_speed=EV"];
    let mut session = Session::start(&args, 100, 30);
    session.wait_for("Open a swing (33)");
    session.press("\u{1b}");
    session.wait_for_gone("Open a swing (33)");
    session.press("q");
    assert_eq!(session.exit_code(), 0);
}

#[test]
fn a_fifo_among_the_presets_leaves_the_picker_and_q_working() {
    // Reading a FIFO would block until a writer came: the picker must list
    // it as broken at once, and q must still quit.
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("fifo.toml");
    let path = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: a plain libc call on a NUL-terminated path we own.
    assert_eq!(unsafe { libc::mkfifo(path.as_ptr(), 0o644) }, 0);
    let mut session = Session::start(&["--presets-dir", dir.path().to_str().unwrap()], 100, 30);
    session.wait_for("Trajectory");
    session.press("o");
    session.wait_for("fifo.toml: not a regular file");
    session.press("\u{1b}");
    // Apart from the Esc (read once the picker is gone), or the two read as
    // Alt-q.
    session.wait_for_gone("Open preset");
    session.press("q");
    assert_eq!(session.exit_code(), 0);
}

#[test]
fn mouse_capture_is_on_while_running_and_off_after_quitting() {
    let mut session = Session::start(&[], 100, 30);
    session.wait_for("Trajectory");
    // An SGR click (as xterm and tmux with `mouse on` send it) on the first
    // input's row, 1-based: the preset row is the screen's second line.
    session.press("\x1b[<0;5;2M\x1b[<0;5;2m");
    session.wait_for("▶preset");
    session.press("q");
    assert_eq!(session.exit_code(), 0);
    let bytes = String::from_utf8_lossy(&session.bytes.lock().unwrap()).into_owned();
    let on = bytes.find("\x1b[?1000h").expect("mouse capture enabled");
    let off = bytes.rfind("\x1b[?1000l").expect("mouse capture disabled");
    assert!(on < off);
}

/// Every SGR parameter the explorer wrote, as numbers (`38;5;4` gives 38,
/// 5 and 4).
fn sgr_codes(bytes: &[u8]) -> Vec<Vec<u16>> {
    let text = String::from_utf8_lossy(bytes);
    let mut codes = Vec::new();
    for (at, _) in text.match_indices("\x1b[") {
        let rest = &text[at + 2..];
        let Some(end) = rest.find(|c: char| !(c.is_ascii_digit() || c == ';')) else {
            continue;
        };
        if rest[end..].starts_with('m') {
            codes.push(
                rest[..end]
                    .split(';')
                    .map(|p| p.parse().unwrap_or(0))
                    .collect(),
            );
        }
    }
    codes
}

/// Whether an SGR sequence sets a colour (the terminal's own, 39 and 49,
/// only resets one).
fn sets_colour(codes: &[u16]) -> bool {
    codes
        .iter()
        .any(|&c| matches!(c, 30..=38 | 40..=48 | 58 | 90..=97 | 100..=107))
}

#[test]
fn no_color_writes_no_colour_and_stays_usable() {
    let mut session = Session::start_with(&[], 80, 24, &[("NO_COLOR", "1")]);
    session.wait_for("optimum ✓");
    // The surface reads without colour: in shades (crossterm alone drops
    // the colour escapes, which left it a block of blank half blocks).
    session.press("2");
    session.wait_for("surface ✓");
    // The status line said ✓ before the key (the surface is worked out
    // behind the first tab), so wait for the whole surface, not its first
    // shade: a frame caught mid-draw showed ▓ and no ✚ yet.
    session.wait_for_all(&["▓", "░", "✚"]);
    // The other tabs, the help and an edit.
    for (key, shown) in [("3", "Impact:"), ("4", "Fig. 8"), ("1", "Trajectory")] {
        session.press(key);
        session.wait_for(shown);
    }
    session.press("?");
    session.wait_for("this help");
    session.press("x");
    session.press("\r");
    session.wait_for("Enter accepts");
    session.press("\x1b");
    // Esc and q at once would read as Alt-q: wait for the edit to close.
    session.wait_until("the edit closed", |s| {
        !s.contains("Enter accepts") && s.contains("step 0.5")
    });
    session.press("q");
    assert_eq!(session.exit_code(), 0);
    let codes = sgr_codes(&session.bytes.lock().unwrap());
    assert!(codes.len() > 10, "{codes:?}");
    let coloured: Vec<_> = codes.iter().filter(|c| sets_colour(c)).collect();
    assert!(coloured.is_empty(), "{coloured:?}");
    // The selected row and tab still stand out: in reverse video.
    assert!(codes.iter().any(|c| c.contains(&7)), "{codes:?}");
}

#[test]
fn a_light_background_gets_colours_that_read_on_white() {
    // Detected from COLORFGBG (black on white), and asked for with --theme
    // (which wins over a dark COLORFGBG).
    for (args, colorfgbg) in [(&[][..], "0;15"), (&["--theme", "light"][..], "15;0")] {
        let mut session = Session::start_with(args, 80, 24, &[("COLORFGBG", colorfgbg)]);
        session.wait_for("optimum ✓");
        session.wait_for("Δ ✓");
        session.press("q");
        assert_eq!(session.exit_code(), 0);
        let codes = sgr_codes(&session.bytes.lock().unwrap());
        // The current swing in blue (xterm 4); no yellow (3, 11), cyan (6)
        // or white (7, 15) text, which a white background hides.
        let fg = |c: &Vec<u16>| (c.len() >= 3 && c[0] == 38 && c[1] == 5).then(|| c[2]);
        let colours: Vec<u16> = codes.iter().filter_map(fg).collect();
        assert!(colours.contains(&4), "{args:?}: {colours:?}");
        for hidden in [3, 6, 7, 11, 15] {
            assert!(
                !colours.contains(&hidden),
                "{args:?}: {hidden} in {colours:?}"
            );
        }
    }
    // The dark theme does use them.
    let mut session = Session::start_with(&[], 80, 24, &[("COLORFGBG", "15;0")]);
    session.wait_for("optimum ✓");
    session.press("q");
    assert_eq!(session.exit_code(), 0);
    let codes = sgr_codes(&session.bytes.lock().unwrap());
    assert!(
        codes.iter().any(|c| c.starts_with(&[38, 5, 6])),
        "{codes:?}"
    );
}
