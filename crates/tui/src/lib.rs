//! The explorer: a terminal app over the physics core. It builds scenes and
//! calls the core; it computes nothing of its own.
//!
//! `app` holds the state and `update`, `view` draws it, `worker` runs the
//! optimiser and the range surface in the background. Beneath both app and
//! view: `keymap` (every key, what it does and its help), `layout` (where
//! the panes go), `theme` (colours and styles) and `format` (numbers as
//! shown; `shown`, one text per quantity). Every arrow points down: `view` reads `app`,
//! and `app` never reads `view`. This file owns the terminal: set up, event
//! loop, and restoring it on every way out.

pub mod app;
pub mod format;
pub mod glossary;
pub mod inputs;
pub mod keymap;
pub mod layout;
pub mod margin;
pub mod palette;
pub mod shown;
mod signals;
pub mod theme;
pub mod view;
pub mod worker;

use std::io::{self, IsTerminal, Write};
use std::path::PathBuf;
use std::sync::mpsc::{Receiver, TryRecvError};
use std::time::Duration;

use ratatui::crossterm::event::{
    self, DisableMouseCapture, EnableMouseCapture, Event, KeyCode, KeyEventKind, KeyModifiers,
};
use ratatui::crossterm::terminal::{BeginSynchronizedUpdate, EndSynchronizedUpdate};
use ratatui::crossterm::{execute, queue};
use ratatui::layout::Rect;

use app::App;
use preset::Preset;
use preset::compact::CompactPresets;
pub use signals::Ending;
use signals::Signals;
use theme::{Background, ColorMode, Theme};
use worker::Worker;

/// Why the explorer did not run.
#[derive(Debug, thiserror::Error)]
pub enum TuiError {
    #[error(
        "the explorer needs a terminal (stdin and stdout must be a TTY); for plain numbers use the commands: see `homerun --help`"
    )]
    NoTerminal,
    #[error("the background worker stopped unexpectedly")]
    WorkerDied,
    #[error("terminal: {0}")]
    Io(#[from] io::Error),
}

/// Ends the process when the terminal goes away (a dropped SSH connection,
/// a killed tmux). SIGHUP then reaches only the session's leader, often the
/// shell, not us; and crossterm 0.29 spins forever inside `event::poll` on a
/// hung-up TTY (each read returns 0 bytes and it reads again), so the event
/// loop never comes round to notice. There is no terminal left to restore.
fn watch_for_hang_up() -> io::Result<()> {
    std::thread::Builder::new()
        .name("hang-up watch".into())
        .spawn(|| {
            loop {
                std::thread::sleep(Duration::from_millis(250));
                if terminal_hung_up() {
                    end_hung_up();
                }
            }
        })
        .map(drop)
}

/// Ends the process as a hang-up signal would (128 + SIGHUP) once its
/// terminal is gone: at once, with no destructor or at-exit handler run.
/// There is nothing left to restore, and what would try prints its failure
/// with `eprintln!` (ratatui's restore, its terminal's drop), which panics
/// on a dead terminal, in a panic hook a second panic: SIGABRT, exit 134,
/// 1 run in 25 under load (`a_terminal_that_goes_away_ends_the_explorer`).
fn end_hung_up() -> ! {
    signal_hook::low_level::exit(128 + libc::SIGHUP)
}

/// Whether standard input's terminal has hung up: Linux's `poll(2)` reports
/// POLLHUP on a TTY whose other end is gone (crossterm only reports keys,
/// and keeps polling the dead TTY).
#[cfg(unix)]
fn terminal_hung_up() -> bool {
    use rustix::event::{PollFd, PollFlags, Timespec, poll};
    use std::os::fd::AsFd as _;
    let stdin = io::stdin();
    let stdin = stdin.as_fd();
    let mut fds = [PollFd::new(&stdin, PollFlags::IN)];
    let now = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    let gone = PollFlags::HUP | PollFlags::ERR | PollFlags::NVAL;
    matches!(poll(&mut fds, Some(&now)), Ok(n) if n > 0) && fds[0].revents().intersects(gone)
}

#[cfg(not(unix))]
fn terminal_hung_up() -> bool {
    false
}

/// Restores the terminal when dropped: on quit, on error, and while
/// unwinding from a panic (ratatui's panic hook restores it too).
struct Restore;

impl Drop for Restore {
    fn drop(&mut self) {
        // Not `ratatui::restore`, which prints a failure with `eprintln!`
        // (a panic where stderr is a terminal that is gone).
        let _ = execute!(io::stdout(), DisableMouseCapture);
        let _ = ratatui::try_restore();
    }
}

/// Runs the explorer on `preset` until the user quits or a signal (TERM,
/// HUP, INT, QUIT, …: see `signals`) asks it to stop, and says which; the
/// terminal is restored either way, and given back while suspended. Its
/// colours are for `background` (else the one `COLORFGBG` names), none
/// under `NO_COLOR`. `m`/`M` go through the bundled parks and the user's
/// from `parks_dir`.
pub fn run(
    (preset, swings): (Preset, CompactPresets),
    (presets_dir, parks_dir): (Option<PathBuf>, Option<PathBuf>),
    units: units::UnitSystem,
    background: Option<Background>,
) -> Result<Ending, TuiError> {
    if !(io::stdin().is_terminal() && io::stdout().is_terminal()) {
        return Err(TuiError::NoTerminal);
    }
    let signals = Signals::catch()?;
    let first_hook = std::panic::take_hook();
    let mut terminal = ratatui::try_init()?;
    // ratatui's panic hook restores the terminal with `ratatui::restore`,
    // whose `eprintln!` would panic inside the hook on a dead terminal;
    // this one restores it quietly, then reports the panic as before.
    std::panic::set_hook(Box::new(move |info| {
        let _ = ratatui::try_restore();
        first_hook(info);
    }));
    let _restore = Restore;
    // Clicks and the wheel (see `app/mouse.rs`); Shift-drag still selects text.
    execute!(io::stdout(), EnableMouseCapture)?;
    let size = terminal.size()?;
    let theme = Theme::new(
        background.unwrap_or_else(Background::detect),
        ColorMode::detect(),
    );
    let setup = preset.explorer.clone();
    let mut app = App::new(
        preset,
        presets_dir,
        theme,
        Rect::new(0, 0, size.width, size.height),
    );
    app.load_parks(parks_dir.as_deref());
    // A preset saved from the explorer opens in its own units and park
    // (which may be one of the user's); any other in `--units`.
    match &setup {
        Some(setup) => {
            app.restore_setup(setup);
            app.message = None;
        }
        None => app.set_units(units),
    }
    app.offer_compact_swings(swings);
    let worker = Worker::spawn();
    watch_for_hang_up()?;
    let looped = event_loop(&mut app, &mut terminal, &signals, &worker);
    if looped.is_err() && terminal_hung_up() {
        // The terminal went away before the watch saw it (a write failed).
        end_hung_up();
    }
    looped
}

/// Draws, reads events and takes the worker's results until the user
/// quits or a signal asks the explorer to stop.
fn event_loop(
    app: &mut App,
    terminal: &mut ratatui::DefaultTerminal,
    signals: &Signals,
    worker: &Worker,
) -> Result<Ending, TuiError> {
    while !app.quit {
        if let Some(ending) = signals.ending() {
            return Ok(ending);
        }
        if signals.answer(terminal)? {
            app.dirty = true;
        }
        if let Some(job) = app.take_job() {
            worker.submit(job);
        }
        if let Some(job) = app.take_figure_job() {
            worker.submit_figure(job);
        }
        if let Some(job) = app.take_margin_job() {
            worker.submit_margin(job);
        }
        // A map no longer shown stops at once (its generation has moved on).
        worker.cancel_margins_before(app.margin.generation);
        if app.dirty {
            app.dirty = false;
            queue!(terminal.backend_mut(), BeginSynchronizedUpdate)?;
            terminal.draw(|frame| view::draw(frame, app))?;
            execute!(terminal.backend_mut(), EndSynchronizedUpdate)?;
            terminal.backend_mut().flush()?;
        }
        // Wait for a key, a result or a signal; poll often only while the
        // worker is busy. Waiting writes nothing to the terminal.
        let timeout = Duration::from_millis(if app.busy() { 20 } else { 200 });
        if event::poll(timeout)? {
            // Take every pending event before recomputing: a held-down key
            // costs one recomputation per frame, not one per repeat.
            loop {
                let event: Event = event::read()?;
                if is_ctrl_z(&event) {
                    signals::suspend_self()?;
                    break;
                }
                app.handle(&event);
                if app.quit || !event::poll(Duration::ZERO)? {
                    break;
                }
            }
            app.flush();
        }
        drain(&worker.reports, |report| app.apply(report))?;
        drain(&worker.figures, |report| app.apply_figure(report))?;
        drain(&worker.margins, |report| app.apply_margin(report))?;
    }
    Ok(Ending::Quit)
}

/// Ctrl-Z, which raw mode delivers as a key: it suspends, as in a shell.
fn is_ctrl_z(event: &Event) -> bool {
    matches!(event, Event::Key(key) if key.code == KeyCode::Char('z')
        && key.modifiers.contains(KeyModifiers::CONTROL)
        && key.kind == KeyEventKind::Press)
}

/// Takes in every result waiting on `reports`. A thread that is gone (it
/// panicked) stops the explorer rather than leave a screen that will never
/// update.
fn drain<R>(reports: &Receiver<R>, mut apply: impl FnMut(R)) -> Result<(), TuiError> {
    loop {
        match reports.try_recv() {
            Ok(report) => apply(report),
            Err(TryRecvError::Empty) => return Ok(()),
            Err(TryRecvError::Disconnected) => return Err(TuiError::WorkerDied),
        }
    }
}
