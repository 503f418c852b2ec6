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
        Command::Tui { preset } => explore(&cli, preset),
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

/// Opens the explorer on `preset`, with the user's (or `--presets-dir`'s) folder.
fn explore(cli: &Cli, preset: &str) -> Result<(), cli::UsageError> {
    let dir = cli::presets_dir(cli);
    let preset = homerun::preset::load(preset, dir.as_deref())?;
    Ok(homerun::tui::run(preset, dir)?)
}
