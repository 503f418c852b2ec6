use std::process::ExitCode;

use homerun::cli::{self, Cli, Command, Parsed};

fn main() -> ExitCode {
    let cli = match cli::parse(std::env::args_os()) {
        Parsed::Run(cli) => cli,
        Parsed::Help(help) => {
            // Help and the version go to stdout; a closed pipe loses them.
            let _ = help.print();
            return ExitCode::SUCCESS;
        }
        Parsed::Refused(error) => return refuse(&error),
    };
    let default = Command::Tui {
        preset: "fastball".to_owned(),
        theme: None,
    };
    let command = cli.command.as_ref().unwrap_or(&default);
    let result = match command {
        Command::Tui { preset, theme } => {
            explore(&cli, preset, theme.or(cli.theme)).map(|()| ExitCode::SUCCESS)
        }
        command => cli::run(&cli, command),
    };
    match result {
        Ok(status) => status,
        Err(error) => refuse(&error),
    }
}

/// One line on stderr, `homerun: …`, and exit status 2.
fn refuse(error: &cli::UsageError) -> ExitCode {
    eprintln!("homerun: {}", cli::error_line(&error.to_string()));
    ExitCode::from(2)
}

/// Opens the explorer on `preset`, with the user's (or `--presets-dir`'s)
/// folder, in the colours for `background` (`None`: detected).
fn explore(
    cli: &Cli,
    preset: &str,
    background: Option<homerun::tui::theme::Background>,
) -> Result<(), cli::UsageError> {
    let (preset, dir) = cli::explorer_preset(cli, preset)?;
    Ok(homerun::tui::run(preset, dir, cli.units, background)?)
}
