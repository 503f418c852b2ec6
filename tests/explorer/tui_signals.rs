//! Issue 38, item 8: the real binary in a pseudo-terminal, sent signals. A
//! suspend (SIGTSTP, or Ctrl-Z) gives the shell its terminal back (main
//! screen, no mouse reporting, a visible cursor, cooked mode) and a resume
//! (SIGCONT) takes it again and redraws; every catchable signal that ends
//! the explorer restores the terminal first, and the exit status is 128 +
//! the signal.
use std::os::unix::fs::OpenOptionsExt as _;
use std::thread;
use std::time::{Duration, Instant};

use rustix::termios::LocalModes;

use crate::tui_pty::Session;

/// What the terminal looks like from the shell's side.
#[derive(Debug, PartialEq)]
struct TerminalState {
    alternate_screen: bool,
    mouse_reporting: bool,
    cursor_hidden: bool,
    /// ICANON and ECHO: keys echo and lines wait for Enter.
    cooked: bool,
}

const THE_SHELLS: TerminalState = TerminalState {
    alternate_screen: false,
    mouse_reporting: false,
    cursor_hidden: false,
    cooked: true,
};

const THE_EXPLORERS: TerminalState = TerminalState {
    alternate_screen: true,
    mouse_reporting: true,
    cursor_hidden: true,
    cooked: false,
};

fn state(session: &Session) -> TerminalState {
    // The line's modes, read on the terminal's own side (the pair shares
    // them), opened without becoming this process's controlling terminal.
    let tty = session.master.tty_name().expect("a unix pty");
    let tty = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NOCTTY)
        .open(tty)
        .unwrap();
    let local = rustix::termios::tcgetattr(&tty).unwrap().local_modes;
    let parser = session.screen.lock().unwrap();
    let screen = parser.screen();
    TerminalState {
        alternate_screen: screen.alternate_screen(),
        mouse_reporting: screen.mouse_protocol_mode() != vt100::MouseProtocolMode::None,
        cursor_hidden: screen.hide_cursor(),
        cooked: local.contains(LocalModes::ICANON | LocalModes::ECHO),
    }
}

/// Waits (within a generous bound) for the terminal to be in `expected`.
fn wait_for_state(session: &Session, expected: &TerminalState) {
    let start = Instant::now();
    while state(session) != *expected {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "the terminal stayed {:?}, not {expected:?}",
            state(session)
        );
        thread::sleep(Duration::from_millis(20));
    }
}

/// The state letter of `pid` in /proc (R, S, T for stopped, Z…).
fn process_state(pid: u32) -> char {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap();
    let (_, rest) = stat.split_once(") ").unwrap();
    rest.chars().next().unwrap()
}

fn wait_until_stopped(pid: u32) {
    let start = Instant::now();
    while process_state(pid) != 'T' {
        assert!(start.elapsed() < Duration::from_secs(30), "never stopped");
        thread::sleep(Duration::from_millis(20));
    }
}

fn send(signal: &str, pid: u32) {
    let status = std::process::Command::new("kill")
        .args([&format!("-{signal}"), &pid.to_string()])
        .status()
        .unwrap();
    assert!(status.success(), "kill -{signal}");
}

/// Suspended by SIGTSTP or Ctrl-Z: stopped, with the shell's terminal;
/// resumed by SIGCONT: the explorer's terminal, redrawn, and q (one key,
/// no Enter) quits.
#[test]
fn a_suspend_gives_the_terminal_back_and_a_resume_takes_it_again() {
    let mut session = Session::start(&[], 100, 30);
    session.wait_for("Trajectory");
    wait_for_state(&session, &THE_EXPLORERS);
    let pid = session.child.process_id().unwrap();
    for suspend in ["SIGTSTP", "Ctrl-Z"] {
        if suspend == "Ctrl-Z" {
            session.press("\u{1a}");
        } else {
            send("TSTP", pid);
        }
        wait_until_stopped(pid);
        wait_for_state(&session, &THE_SHELLS);
        assert!(!session.contents().contains("Trajectory"), "{suspend}");
        send("CONT", pid);
        wait_for_state(&session, &THE_EXPLORERS);
        // Drawn again whole on the cleared alternate screen.
        session.wait_for_all(&["Trajectory", "Inputs"]);
    }
    session.press("q");
    assert_eq!(session.exit_code(), 0);
    assert_eq!(state(&session), THE_SHELLS);
}

/// Each signal that ends the explorer restores the terminal first, and
/// the status is 128 + the signal's number.
#[test]
fn an_ending_signal_restores_the_terminal_and_exits_128_plus_it() {
    for (signal, number) in [
        ("HUP", libc::SIGHUP),
        ("INT", libc::SIGINT),
        ("QUIT", libc::SIGQUIT),
        ("TERM", libc::SIGTERM),
        ("USR1", libc::SIGUSR1),
        ("USR2", libc::SIGUSR2),
        ("ALRM", libc::SIGALRM),
    ] {
        let mut session = Session::start(&[], 80, 24);
        session.wait_for("Trajectory");
        wait_for_state(&session, &THE_EXPLORERS);
        send(signal, session.child.process_id().unwrap());
        let expected = u32::try_from(128 + number).unwrap();
        assert_eq!(session.exit_code(), expected, "SIG{signal}");
        assert_eq!(state(&session), THE_SHELLS, "SIG{signal}");
    }
}
