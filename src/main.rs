use std::process::ExitCode;

use clap::Parser;
use homerun::cli::{self, Cli, Command};

fn main() -> ExitCode {
    let cli = Cli::parse();
    let default = Command::Tui {
        preset: "fastball".to_owned(),
    };
    let command = cli.command.as_ref().unwrap_or(&default);
    let result = match command {
        Command::Tui { .. } => Err(cli::UsageError::Other(
            "the explorer is not built yet; see `homerun --help` for the commands".into(),
        )),
        command => cli::run(&cli, command),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("homerun: {error}");
            ExitCode::from(2)
        }
    }
}
