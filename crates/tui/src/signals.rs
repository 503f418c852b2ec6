//! The signals the explorer answers, so that the shell gets its terminal
//! back as it lent it: a suspend (SIGTSTP, Ctrl-Z) leaves the alternate
//! screen, the mouse reporting, the hidden cursor and raw mode before the
//! process stops, and a resume (SIGCONT) takes them again and redraws;
//! every catchable signal that would end the process restores the terminal
//! first, and the explorer then exits with 128 + the signal, as shells
//! report a process a signal ended.
//!
//! The handlers only set flags (signal-hook's, async-signal-safe); the
//! event loop, which wakes at least every 200 ms, does the work.

use std::io;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use ratatui::DefaultTerminal;
use ratatui::crossterm::event::{DisableMouseCapture, EnableMouseCapture};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{
    Clear, ClearType, EnterAlternateScreen, LeaveAlternateScreen, disable_raw_mode, enable_raw_mode,
};

/// Every signal whose default action ends the process and that a handler
/// may catch. Not SIGPIPE (Rust ignores it: a write to a closed terminal
/// is an error the loop returns), nor the faults (SIGSEGV, SIGBUS, SIGILL,
/// SIGFPE, SIGABRT, SIGTRAP, SIGSYS), after which nothing can be trusted.
const ENDING: &[libc::c_int] = &[
    libc::SIGHUP,
    libc::SIGINT,
    libc::SIGQUIT,
    libc::SIGTERM,
    libc::SIGUSR1,
    libc::SIGUSR2,
    libc::SIGALRM,
    libc::SIGVTALRM,
    libc::SIGPROF,
    libc::SIGXCPU,
    libc::SIGXFSZ,
    libc::SIGIO,
    #[cfg(any(target_os = "linux", target_os = "android"))]
    libc::SIGPWR,
];

/// How the explorer ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// The user quit (q, Ctrl-C).
    Quit,
    /// A signal asked it to stop; the terminal was restored first.
    Signal(i32),
}

impl Ending {
    /// The process's exit status: 0, or 128 + the signal, as a shell
    /// reports a process that signal ended.
    pub fn exit_status(self) -> u8 {
        match self {
            Ending::Quit => 0,
            Ending::Signal(signal) => u8::try_from(128 + signal).unwrap_or(255),
        }
    }
}

/// The flags the handlers set.
pub(crate) struct Signals {
    /// The last ending signal caught, 0 for none.
    ending: Arc<AtomicUsize>,
    suspend: Arc<AtomicBool>,
    resumed: Arc<AtomicBool>,
}

impl Signals {
    /// Catches every signal in [`ENDING`], SIGTSTP and SIGCONT.
    pub(crate) fn catch() -> io::Result<Signals> {
        let signals = Signals {
            ending: Arc::new(AtomicUsize::new(0)),
            suspend: Arc::new(AtomicBool::new(false)),
            resumed: Arc::new(AtomicBool::new(false)),
        };
        for &signal in ENDING {
            let number = usize::try_from(signal).unwrap_or(0);
            signal_hook::flag::register_usize(signal, Arc::clone(&signals.ending), number)?;
        }
        signal_hook::flag::register(libc::SIGTSTP, Arc::clone(&signals.suspend))?;
        signal_hook::flag::register(libc::SIGCONT, Arc::clone(&signals.resumed))?;
        Ok(signals)
    }

    /// The signal that asks the explorer to end, if one came.
    pub(crate) fn ending(&self) -> Option<Ending> {
        match self.ending.load(Ordering::Relaxed) {
            0 => None,
            signal => Some(Ending::Signal(i32::try_from(signal).unwrap_or(i32::MAX))),
        }
    }

    /// Answers a suspend or a resume that came since the last call; true
    /// when the screen must be drawn again whole.
    pub(crate) fn answer(&self, terminal: &mut DefaultTerminal) -> io::Result<bool> {
        if self.suspend.swap(false, Ordering::Relaxed) {
            leave(terminal)?;
            // SIGSTOP, as the default action of SIGTSTP would: it cannot be
            // caught, so the process stops here until SIGCONT.
            signal_hook::low_level::raise(libc::SIGSTOP)?;
            self.resumed.store(false, Ordering::Relaxed);
            enter(terminal)?;
            return Ok(true);
        }
        // Continued after a stop that was not ours (SIGSTOP from outside):
        // the shell may have reset the terminal meanwhile.
        if self.resumed.swap(false, Ordering::Relaxed) {
            enter(terminal)?;
            return Ok(true);
        }
        Ok(false)
    }
}

/// Asks for a suspend as Ctrl-Z does in a shell: raw mode turns the key
/// into a keystroke, not the SIGTSTP the terminal would send in cooked mode.
pub(crate) fn suspend_self() -> io::Result<()> {
    signal_hook::low_level::raise(libc::SIGTSTP)
}

/// Gives the terminal back as the shell lent it.
fn leave(terminal: &mut DefaultTerminal) -> io::Result<()> {
    execute!(
        terminal.backend_mut(),
        DisableMouseCapture,
        LeaveAlternateScreen
    )?;
    terminal.show_cursor()?;
    disable_raw_mode()
}

/// Takes the terminal again, and clears it so that the next frame is
/// drawn whole. Not `Terminal::clear`, which asks the terminal where its
/// cursor is and fails where no answer comes.
fn enter(terminal: &mut DefaultTerminal) -> io::Result<()> {
    enable_raw_mode()?;
    execute!(
        terminal.backend_mut(),
        EnterAlternateScreen,
        EnableMouseCapture,
        Clear(ClearType::All)
    )?;
    terminal.hide_cursor()?;
    // Both buffers blank, as the cleared screen is: the next frame is
    // written whole rather than as its difference from the last one.
    terminal.swap_buffers();
    Ok(())
}
