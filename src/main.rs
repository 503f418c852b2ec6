use std::io::IsTerminal;
use std::process::ExitCode;

use homerun::cli::{self, Cli, Command, Parsed};

fn main() -> ExitCode {
    let cli = match cli::parse(std::env::args_os()) {
        Parsed::Run(cli) => cli,
        Parsed::Help(_) if stdout_at_start::closed() => {
            return refuse(&cli::UsageError::StdoutClosed);
        }
        Parsed::Help(help) => {
            // Help and the version go to stdout; a closed pipe loses them.
            let _ = help.print();
            return ExitCode::SUCCESS;
        }
        Parsed::Refused(error) => return refuse(&error),
    };
    let default = Command::Tui {
        preset: "fastball".to_owned(),
        savant: None,
        column: Vec::new(),
        theme: None,
    };
    let command = cli.command.as_ref().unwrap_or(&default);
    if let Err(error) = cli::check_thread_count() {
        return refuse(&error);
    }
    // Refused before any work: a batch would fly every row for nothing.
    if stdout_at_start::closed() && cli::writes_stdout(command) {
        return refuse(&cli::UsageError::StdoutClosed);
    }
    let result = match command {
        Command::Tui {
            preset,
            savant,
            column,
            theme,
        } => explore(
            &cli,
            (preset, savant.as_deref(), column),
            theme.or(cli.theme),
        )
        .map(|ending| ExitCode::from(ending.exit_status())),
        command => cli::run(&cli, command),
    };
    match result {
        Ok(status) => status,
        Err(error) => refuse(&error),
    }
}

/// One line on stderr, `homerun: …`, and exit status 2 (said even where
/// stderr cannot take the line: eprintln! would panic, exit 101).
fn refuse(error: &cli::UsageError) -> ExitCode {
    use std::io::Write as _;
    let line = format!("homerun: {}\n", cli::error_line(&error.to_string()));
    let _ = std::io::stderr().write_all(line.as_bytes());
    ExitCode::from(2)
}

/// Opens the explorer on `preset` (and with `--savant FILE`, a picker of
/// that file's solved swings), with the user's (or `--presets-dir`'s)
/// folder and parks (or `--parks-dir`'s), in the colours for `background`
/// (`None`: detected).
fn explore(
    cli: &Cli,
    (preset, savant, column): (&str, Option<&str>, &[String]),
    background: Option<homerun::tui::theme::Background>,
) -> Result<homerun::tui::Ending, cli::UsageError> {
    let (preset, dir) = cli::explorer_preset(cli, preset)?;
    // Before the file's swings are read and solved, which can take long:
    // without a terminal they would be for nothing (`tui --savant -` with
    // the file piped in has its terminal taken by the file).
    if !(std::io::stdin().is_terminal() && std::io::stdout().is_terminal()) {
        return Err(homerun::tui::TuiError::NoTerminal.into());
    }
    let swings = match savant {
        Some(file) => cli::savant_swings(cli, &preset, (file, column))?,
        None => homerun::preset::compact::CompactPresets::new(),
    };
    let parks = cli::parks_dir(cli);
    Ok(homerun::tui::run(
        (preset, swings),
        (dir, parks),
        cli.units,
        background,
    )?)
}

/// Whether standard output was closed when the process started (`homerun
/// keys >&-`). Rust's runtime opens /dev/null on a closed standard stream
/// before `main`, where the output would vanish and the exit status say
/// all went well; so fd 1 is looked at before it, by the C runtime's
/// initialisers (`.init_array`), as the `ctor` crate does.
#[cfg(target_os = "linux")]
#[allow(unsafe_code)] // Before main: no safe way to run there.
mod stdout_at_start {
    use std::sync::atomic::{AtomicBool, Ordering};

    static CLOSED: AtomicBool = AtomicBool::new(false);

    extern "C" fn record() {
        // SAFETY: F_GETFD only reads the process's table of descriptors.
        let closed = unsafe { libc::fcntl(libc::STDOUT_FILENO, libc::F_GETFD) } == -1;
        CLOSED.store(closed, Ordering::Relaxed);
    }

    #[used]
    #[unsafe(link_section = ".init_array")]
    static RECORD: extern "C" fn() = record;

    pub fn closed() -> bool {
        CLOSED.load(Ordering::Relaxed)
    }
}

/// Elsewhere the runtime's own handling of a closed stream stands.
#[cfg(not(target_os = "linux"))]
mod stdout_at_start {
    pub fn closed() -> bool {
        false
    }
}
