//! `fly --batch` and `hit --batch` from their command lines: the setup
//! each makes, the input opened, the rows to stdout and the summary to
//! stderr (and `--summary-file`), on the pipeline of [`batch`].

use std::io::{IsTerminal as _, Write as _};
use std::path::PathBuf;
use std::process::ExitCode;

use super::progress::{self, Work};
use super::{Cli, Command, SceneArgs, SpinArg, UsageError, checked_presets_dir, parks_dir, scene};
use crate::preset::{self, escape_cut};
use batch::{Format, Setup, Shown};

/// Runs `command` if it is a batch: `None` if it is not.
pub(super) fn run(cli: &Cli, command: &Command) -> Option<Result<ExitCode, UsageError>> {
    match command {
        Command::Fly {
            scene,
            batch: Some(source),
            json,
            park,
            keep,
            spray,
            one_flight,
            summary,
            all_parks,
            spin,
            column,
            summary_file,
            ..
        } => {
            let args = BatchArgs {
                scene,
                source,
                park: park.as_deref(),
                keep: keep.as_deref(),
                column,
                summary: (*summary, summary_file.as_ref()),
                json: *json,
            };
            Some(run_batch(cli, &args, |setup| {
                setup.spray = (*spray).into();
                setup.one_flight = *one_flight;
                setup.all_parks = *all_parks;
                setup.solve_swings = *spin == Some(SpinArg::Swing);
            }))
        }
        Command::Hit {
            scene,
            batch: Some(source),
            json,
            park,
            keep,
            summary,
            column,
            summary_file,
        } => {
            let args = BatchArgs {
                scene,
                source,
                park: park.as_deref(),
                keep: keep.as_deref(),
                column,
                summary: (*summary, summary_file.as_ref()),
                json: *json,
            };
            Some(run_batch(cli, &args, |setup| {
                setup.solve_swings = true;
                setup.swing_columns = true;
            }))
        }
        _ => None,
    }
}

/// What `fly --batch` and `hit --batch` share on their command lines.
struct BatchArgs<'a> {
    scene: &'a SceneArgs,
    source: &'a str,
    park: Option<&'a str>,
    keep: Option<&'a str>,
    column: &'a [String],
    /// `--summary` (the tables too) and `--summary-file`.
    summary: (bool, Option<&'a PathBuf>),
    json: bool,
}

/// The setup a command line gives: `--set`'s keys, `--park`'s park and
/// `--column`'s mapping.
pub(super) fn setup<'a>(
    preset: &'a preset::Preset,
    parks: &'a preset::parks::Parks,
    (set, park, column): (&[String], Option<&str>, &[String]),
) -> Result<Setup<'a>, UsageError> {
    let mut setup = Setup::new(preset, parks);
    setup.given(set);
    if let Some(code) = park {
        let named = super::parks::lookup(code, parks)?;
        setup.park = parks.parks.iter().position(|p| std::ptr::eq(p, named));
    }
    for mapping in column {
        let Some((name, column)) = mapping.split_once('=') else {
            return Err(UsageError::Column {
                mapping: escape_cut(mapping, 80),
            });
        };
        setup
            .mapping
            .push((name.trim().to_owned(), column.trim().to_owned()));
    }
    Ok(setup)
}

/// `message` about `source`, as a batch's refusal.
fn refused(source: &str, message: String) -> UsageError {
    UsageError::Batch {
        input: escape_cut(source, 200),
        message,
    }
}

/// Runs a batch over `args.source`, its setup made as the command line
/// says and then as `choose` sets it.
fn run_batch(
    cli: &Cli,
    args: &BatchArgs,
    choose: impl FnOnce(&mut Setup),
) -> Result<ExitCode, UsageError> {
    let preset = args
        .scene
        .resolve(checked_presets_dir(cli)?.as_deref(), cli.units)?;
    scene::check_path("--batch", args.source)?;
    if let Some(path) = args.summary.1 {
        super::svg_file::check(path)?;
    }
    let parks = preset::parks::all_noted(parks_dir(cli).as_deref())?;
    let mut setup = setup(&preset, &parks, (&args.scene.set, args.park, args.column))?;
    if let Some(keep) = args.keep {
        setup.keep = (keep.split(',').map(|c| c.trim().to_owned()))
            .filter(|c| !c.is_empty())
            .collect();
    }
    choose(&mut setup);
    let stdout = std::io::stdout().lock();
    setup.escape_kept = stdout.is_terminal();
    let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout);
    // stderr is locked for each line only: the progress line's thread
    // writes there too, and the run waits for it (held across the run, the
    // lock hung every batch on a terminal that lasted past a second).
    let erase = std::io::stderr().is_terminal();
    let mut note = |message: &str| {
        let erase = if erase { "\r\x1b[K" } else { "" };
        let _ = writeln!(std::io::stderr().lock(), "{erase}homerun: {message}");
    };
    let input = batch::open(args.source).map_err(|e| refused(args.source, e))?;
    let shown = Shown(cli.units);
    let format = Format {
        json: args.json,
        shown,
    };
    let work = Work {
        what: if setup.swing_columns {
            "hit --batch"
        } else {
            "fly --batch"
        },
        steps: Some((progress::UNCOUNTED, "rows")),
    };
    let (outcome, tally) = progress::run(work, |p| {
        let tick = || p.tick();
        batch::fly_rows(&setup, input, format, &mut out, &mut note, &tick)
    })
    .map_err(|e| refused(args.source, e))?;
    for line in tally.lines(&setup, shown) {
        note(&line);
    }
    if args.summary.0 {
        for table in tally.tables(&setup, shown) {
            let _ = writeln!(std::io::stderr(), "{table}");
        }
    }
    if let Some(path) = args.summary.1 {
        let text = super::pretty(&tally.json(&setup, shown));
        crate::preset::atomic_file::write(path, text.as_bytes())
            .map_err(|e| refused(&path.display().to_string(), e.to_string()))?;
    }
    // A column read in the wrong unit (named above) makes every row suspect.
    let suspect = u8::from(tally.suspect());
    Ok(ExitCode::from(outcome.exit_status().max(suspect)))
}
