//! The help: every argument says what it is for, the long `--units` text is
//! said once, `fly --help` lists the columns `--batch` reads (and the batch
//! reads each in the unit the help gives), and the `keys` table's columns
//! never run together.

use crate::common;
use assert_cmd::Command;
use clap::{CommandFactory as _, FromArgMatches as _, Parser as _};
use homerun::cli::{Cli, Parsed, UNITS_HELP, parse};
use unicode_width::UnicodeWidthStr as _;

fn homerun() -> Command {
    common::assert_command()
}

/// Every argument of `command` and its subcommands, by the path of
/// commands to it, with its help (short or long) if it has one.
fn arguments(command: &clap::Command, path: &str, out: &mut Vec<(String, Option<String>)>) {
    for arg in command.get_arguments().filter(|a| !a.is_hide_set()) {
        let help = arg
            .get_help()
            .or(arg.get_long_help())
            .map(ToString::to_string);
        out.push((format!("{path} {}", arg.get_id()), help));
    }
    for sub in command.get_subcommands() {
        arguments(sub, &format!("{path} {}", sub.get_name()), out);
    }
}

#[test]
fn every_argument_of_every_command_has_help() {
    let mut cli = Cli::command();
    cli.build(); // the global arguments and clap's own --help, in every command
    let mut found = Vec::new();
    arguments(&cli, "homerun", &mut found);
    // Options and positionals of the twelve commands and of `homerun` itself.
    assert!(found.len() > 60, "found {}", found.len());
    let without: Vec<&String> = found
        .iter()
        .filter(|(_, help)| help.as_deref().is_none_or(|h| h.trim().is_empty()))
        .map(|(path, _)| path)
        .collect();
    assert!(without.is_empty(), "arguments without help: {without:?}");
    for sub in cli.get_subcommands() {
        assert!(sub.get_about().is_some(), "{} has no about", sub.get_name());
    }
}

/// What `homerun ARGS` prints for help.
fn help(args: &[&str]) -> String {
    match parse(std::iter::once("homerun").chain(args.iter().copied())) {
        Parsed::Help(help) => help.to_string(),
        _ => panic!("homerun {args:?} is not help"),
    }
}

#[test]
fn the_units_text_is_said_once_under_homerun_help() {
    assert!(UNITS_HELP.len() > 250, "the long text: {UNITS_HELP}");
    assert_eq!(help(&["--help"]).matches(UNITS_HELP).count(), 1);
    // `-h`, the summary, has only the line.
    assert!(!help(&["-h"]).contains(UNITS_HELP));
    let cli = Cli::command();
    for sub in cli.get_subcommands().map(|s| s.get_name()) {
        if sub == "help" {
            continue;
        }
        for flag in ["--help", "-h"] {
            let text = help(&[sub, flag]);
            assert!(
                !text.contains(UNITS_HELP),
                "homerun {sub} {flag} repeats it"
            );
            // On the option's line (-h), or on the next (--help).
            let mut lines = text
                .lines()
                .skip_while(|l| !l.trim_start().starts_with("--units"));
            let line = match lines.next() {
                Some(line) if line.contains("Units") => line,
                _ => lines.next().unwrap_or_default(),
            };
            assert!(line.contains("imperial"), "homerun {sub} {flag}: {text}");
            assert!(
                line.chars().count() < 130,
                "homerun {sub} {flag}'s --units is long: {line}"
            );
        }
    }
}

/// The column lines of `fly --help`'s `--batch` entry: (column, key, unit).
fn batch_columns() -> Vec<(String, String, String)> {
    help(&["fly", "--help"])
        .lines()
        .filter_map(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            match fields.as_slice() {
                [column, key, "in", unit] if key.starts_with("launch.") => {
                    Some((column.to_string(), key.to_string(), unit.to_string()))
                }
                _ => None,
            }
        })
        .collect()
}

#[test]
fn fly_help_lists_the_columns_the_batch_reads() {
    let columns = batch_columns();
    let names: Vec<&str> = columns.iter().map(|(c, _, _)| c.as_str()).collect();
    for statcast in ["launch_speed", "launch_angle", "spin_rpm"] {
        assert!(names.contains(&statcast), "{statcast} not in {names:?}");
    }
    assert_eq!(columns.len(), 10, "{columns:?}");
    let text = help(&["fly", "--help"]);
    assert!(text.contains("any other key of `homerun keys`"), "{text}");
    // Each column is read, in the unit the help gives.
    for (column, key, unit) in &columns {
        let given = match key.as_str() {
            "launch.speed" => 30.0,
            "launch.angle" => 0.3,
            _ => 100.0,
        };
        let si_per_unit = match unit.as_str() {
            "m/s" | "rad" | "rad/s" => 1.0,
            "mph" => 0.44704,
            "°" => std::f64::consts::PI / 180.0,
            "rpm" => std::f64::consts::PI / 30.0,
            other => panic!("{column}: unit {other}"),
        };
        // The other launch value every row needs, given for every row.
        let other = match key.as_str() {
            "launch.speed" => vec!["--set", "launch.angle=0.3"],
            "launch.angle" => vec!["--set", "launch.speed=30"],
            _ => vec!["--set", "launch.angle=0.3", "--set", "launch.speed=30"],
        };
        let output = homerun()
            .args(["fly", "--preset", "fly-ball", "--batch", "-"])
            .args(&other)
            .write_stdin(format!("{column}\n{given}\n"))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(output.status.success(), "{column}: {stderr}");
        assert!(!stderr.contains("ignored"), "{column}: {stderr}");
        let stdout = String::from_utf8_lossy(&output.stdout);
        let mut lines = stdout.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let row: Vec<&str> = lines.next().unwrap().split(',').collect();
        let at = header.iter().position(|h| h == key).unwrap();
        let flown: f64 = row[at].parse().unwrap();
        // The batch prints six significant digits.
        let expected = given * si_per_unit;
        assert!(
            (flown - expected).abs() <= 1e-5 * expected,
            "{column}: {given} {unit} flew as {key} = {flown}, not {expected}"
        );
    }
}

/// Whether terminal column `at` of `line` is blank.
fn blank(line: &str, at: usize) -> bool {
    let mut column = 0;
    for c in line.chars() {
        let width = c.to_string().width();
        if column == at && width > 0 {
            return c == ' ';
        }
        if column > at {
            break;
        }
        column += width;
    }
    true // past the line's end
}

#[test]
fn the_keys_columns_never_run_together() {
    for units in ["si", "imperial"] {
        let output = homerun().args(["keys", "--units", units]).output().unwrap();
        assert!(output.status.success());
        let text = String::from_utf8(output.stdout).unwrap();
        let table: Vec<&str> = text.lines().take_while(|l| !l.is_empty()).collect();
        // The longest key names are in it.
        for key in ["environment.kinematic_viscosity", "field.fence_distance"] {
            assert!(table.iter().any(|l| l.starts_with(key)), "{key}: {text}");
        }
        let header = table[0];
        let at = |head: &str| header[..header.find(head).unwrap()].width();
        let starts = ["symbol", "unit", "accepted", "meaning"].map(at);
        // Every left-aligned column starts two blanks after the one before.
        for line in &table {
            for start in starts {
                assert!(
                    blank(line, start - 1) && blank(line, start - 2),
                    "{units}: column at {start} touches the one before in\n{line}"
                );
            }
            assert!(!blank(line, starts[3]), "{units}: no meaning in\n{line}");
            // Between the range's start and the meaning: the range (which
            // has single spaces of its own) and the value, two blanks apart.
            let middle: String = line
                .chars()
                .scan(0, |column, c| {
                    let here = *column;
                    *column += c.to_string().width();
                    Some((here, c))
                })
                .filter(|&(column, _)| column >= starts[2] && column < starts[3])
                .map(|(_, c)| c)
                .collect();
            let fields: Vec<&str> = middle
                .split("  ")
                .map(str::trim)
                .filter(|f| !f.is_empty())
                .collect();
            assert_eq!(fields.len(), 2, "{units}: {fields:?} in\n{line}");
        }
    }
}

/// A command's texts that its variant sets (none of them may come from a
/// struct it flattens).
fn command_texts(command: &clap::Command) -> [Option<String>; 6] {
    [
        command.get_about(),
        command.get_long_about(),
        command.get_before_help(),
        command.get_before_long_help(),
        command.get_after_help(),
        command.get_after_long_help(),
    ]
    .map(|text| text.map(ToString::to_string))
}

/// The commands are built lazily (`Command`'s `#[command(defer = true)]`):
/// `homerun hit --help` builds `hit` alone, after the global arguments are
/// added. Each command must read as it does in the whole tree built at once,
/// with the texts its variant gives (building may not replace its about, as
/// a flattened struct's doc comment would), and refuse as the whole does.
#[test]
fn a_command_built_alone_is_the_command_built_whole() {
    let unbuilt = Cli::command();
    let mut whole = Cli::command();
    whole.build();
    let mut asked: Vec<Vec<&str>> = vec![
        vec!["--help"],
        vec!["-h"],
        vec!["--nope"],
        vec!["flyy"],
        vec!["help", "nosuch"],
        vec!["keys", "--units", "furlongs"],
        vec!["fly", "--keep", "a"],
        vec!["fly", "--spray", "sideways", "--batch", "x.csv"],
        vec!["fly", "--one-flight", "--own-air"],
        vec!["surface", "--json", "--csv"],
        vec!["surface", "--grid"],
        vec!["trajectory", "--samples", "x"],
        vec!["figure", "x"],
        vec!["sweep", "bat.speed"],
        vec!["parks", "--svg", "f.svg"],
        vec!["tui", "--theme", "purple"],
        vec!["keys", "extra"],
    ];
    let names: Vec<&str> = unbuilt.get_subcommands().map(|c| c.get_name()).collect();
    assert_eq!(names.len(), 14, "{names:?}");
    for command in unbuilt.get_subcommands() {
        let name = command.get_name();
        let built = whole.find_subcommand(name).unwrap();
        assert_eq!(command_texts(command), command_texts(built), "{name}");
        // Its help opens with its about, as `homerun --help` lists it.
        let about = command.get_about().map(ToString::to_string);
        let short = help(&[name, "-h"]);
        assert_eq!(short.lines().next(), about.as_deref(), "{name}");
        for flag in ["--help", "-h", "--nope", "--units"] {
            asked.push(vec![name, flag]);
        }
        asked.push(vec!["help", name]);
    }
    // Clap's own answer (help, or the error our one line is made of).
    for args in asked {
        let args: Vec<&str> = std::iter::once("homerun").chain(args).collect();
        let lazily = Cli::try_parse_from(&args).unwrap_err();
        let wholly = whole
            .clone()
            .try_get_matches_from(&args)
            .and_then(|matches| Cli::from_arg_matches(&matches))
            .unwrap_err();
        assert_eq!(lazily.kind(), wholly.kind(), "{args:?}");
        assert_eq!(lazily.to_string(), wholly.to_string(), "{args:?}");
    }
}
