//! The command line as clap parses it, with every refusal in one line: the
//! argument, what was given (escaped and cut) and what is accepted. `--help`
//! and `--version` print clap's own text.

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::{CommandFactory as _, Parser as _};

use super::{Cli, MAX_STEPS, UsageError, hit};
use crate::analysis::figures;
use crate::preset::escape_for_terminal;

/// What the command line asks for.
pub enum Parsed {
    Run(Cli),
    /// Help or the version: clap's text, printed as it is, status 0.
    Help(clap::Error),
    /// A refusal: one line, status 2.
    Refused(UsageError),
}

/// Parses `args` (the program's name first).
pub fn parse<I, T>(args: I) -> Parsed
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    match Cli::try_parse_from(args) {
        Ok(cli) => Parsed::Run(cli),
        Err(error) => match error.kind() {
            ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => Parsed::Help(error),
            _ => Parsed::Refused(UsageError::CommandLine(refusal(&error))),
        },
    }
}

/// A usage error as one line that is safe to print: control characters
/// escaped, and cut at 1000 characters. Every value from the user is
/// already cut to 80 where the error names it; this is the last guard.
pub fn error_line(message: &str) -> String {
    let mut out = String::new();
    for (n, c) in message.chars().enumerate() {
        if n == 999 {
            out.push('…');
            break;
        }
        // One character is never cut, only escaped if it must be.
        out.push_str(&escape_for_terminal(c.encode_utf8(&mut [0; 4])));
    }
    out
}

fn text(error: &clap::Error, kind: ContextKind) -> Option<String> {
    match error.get(kind)? {
        ContextValue::String(s) => Some(s.clone()),
        ContextValue::Strings(list) => Some(list.join(", ")),
        ContextValue::StyledStr(s) => Some(s.to_string()),
        ContextValue::StyledStrs(list) => Some(
            list.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("; "),
        ),
        _ => None,
    }
}

/// Clap's error as one line, saying which argument, what was given and what
/// is accepted where that is known.
fn refusal(error: &clap::Error) -> String {
    let arg = text(error, ContextKind::InvalidArg).unwrap_or_default();
    let value = text(error, ContextKind::InvalidValue).unwrap_or_default();
    let flag = arg.split_whitespace().next().unwrap_or_default();
    let usage = text(error, ContextKind::Usage).and_then(|u| {
        u.lines()
            .next()
            .map(|l| l.trim_start_matches("Usage: ").to_owned())
    });
    match error.kind() {
        ErrorKind::InvalidValue | ErrorKind::ValueValidation => {
            let Some(accepted) = accepted(flag) else {
                return first_line(error);
            };
            let name = match flag {
                "<NUMBER>" => "figure",
                "<KEY>" => "sweep",
                flag => flag,
            };
            if value.is_empty() {
                format!("{name}: a value is required: {accepted}")
            } else {
                format!("{name} {}: must be {accepted}", shown(&value))
            }
        }
        ErrorKind::UnknownArgument => {
            let mut line = format!("unexpected argument {}", shown(&arg));
            if let Some(suggested) = text(error, ContextKind::SuggestedArg) {
                line += &format!(" (did you mean {suggested}?)");
            }
            if let Some(tip) = text(error, ContextKind::Suggested) {
                line += &format!(" ({})", escape_for_terminal(&tip));
            }
            if let Some(takes) = usage.as_deref().and_then(arguments_of) {
                line += &format!("; {takes}");
            }
            line
        }
        ErrorKind::InvalidSubcommand => {
            let name = text(error, ContextKind::InvalidSubcommand).unwrap_or_default();
            let mut line = format!("unknown command {}", shown(&name));
            if let Some(suggested) = text(error, ContextKind::SuggestedSubcommand) {
                line += &format!(" (did you mean {suggested}?)");
            }
            let commands: Vec<String> = Cli::command()
                .get_subcommands()
                .map(|c| c.get_name().to_owned())
                .collect();
            line + &format!("; commands: {}", commands.join(", "))
        }
        ErrorKind::MissingRequiredArgument => {
            let mut line = format!("missing {arg}");
            // One missing argument: what it takes.
            if let Some(ContextValue::Strings(missing)) = error.get(ContextKind::InvalidArg)
                && let [one] = missing.as_slice()
                && let Some(accepted) = one.split_whitespace().next().and_then(accepted)
            {
                line += &format!(", {accepted}");
            }
            if let Some(usage) = usage {
                line += &format!("; usage: {usage}");
            }
            line
        }
        ErrorKind::ArgumentConflict => first_line(error) + "; give only one",
        _ => first_line(error),
    }
}

/// A value as given, escaped and cut; quoted unless it reads as a number.
pub(super) fn shown(value: &str) -> String {
    let escaped = escape_for_terminal(value);
    if value.trim().parse::<f64>().is_ok() {
        escaped
    } else {
        format!("'{escaped}'")
    }
}

/// Clap's own first line, without "error: ", escaped and cut.
fn first_line(error: &clap::Error) -> String {
    let rendered = error.to_string();
    let line = rendered.lines().next().unwrap_or_default();
    escape_for_terminal(line.trim_start_matches("error: "))
}

/// What an option or positional takes, by its name as clap gives it
/// ("--samples", "<NUMBER>").
fn accepted(flag: &str) -> Option<String> {
    Some(match flag {
        "--samples" => format!("a whole number in [2, {}]", hit::MAX_SAMPLES),
        "--steps" => format!("a whole number in [1, {MAX_STEPS}]"),
        "--from" | "--to" => {
            "a number, in the swept key's range (homerun keys lists them)".to_owned()
        }
        "<NUMBER>" => format!("a figure number, 3 to 14: {}", figures::figure_list()),
        "<KEY>" => "a key to sweep, e.g. bat.speed (homerun keys lists them)".to_owned(),
        "--set" => "KEY=VALUE, e.g. bat.speed=32 (homerun keys lists the keys)".to_owned(),
        "--preset" => {
            "a preset name (homerun presets lists them) or a path to a TOML file".to_owned()
        }
        "--presets-dir" => "a folder".to_owned(),
        "--batch" => {
            "a CSV file of launches, or - for stdin (homerun fly --help lists the columns read)"
                .to_owned()
        }
        "--units" => "si or imperial".to_owned(),
        "--grid" => "NxM, e.g. 21x17".to_owned(),
        "--undercut" => "A..B in m, e.g. 0..0.05".to_owned(),
        "--swing-angle" => "C..D in rad, e.g. -0.6..1.0".to_owned(),
        _ => return None,
    })
}

/// "homerun hit takes --preset, --set, --json, --presets-dir, --help", from
/// a usage line ("homerun hit [OPTIONS]").
fn arguments_of(usage: &str) -> Option<String> {
    let name = usage.split_whitespace().nth(1)?;
    // Built whole: a command's own arguments are added when it is built.
    let mut cli = Cli::command();
    cli.build();
    let command = cli.find_subcommand(name)?;
    // Its own, in their order; the global ones and help are named below.
    let mut names: Vec<String> = command
        .get_arguments()
        .filter(|a| !a.is_hide_set() && !a.is_global_set() && a.get_id() != "help")
        .map(|a| match a.get_long() {
            Some(long) => format!("--{long}"),
            None => format!("<{}>", a.get_id().as_str().to_uppercase()),
        })
        .collect();
    names.extend(["--presets-dir", "--units", "--help"].map(str::to_owned));
    Some(format!("homerun {name} takes {}", names.join(", ")))
}
