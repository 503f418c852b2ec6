//! `fly --batch` and `hit --batch` from their command lines: the setup
//! each makes, then [`super::batch::run`].

use std::io::IsTerminal as _;
use std::process::ExitCode;

use super::shown::Shown;
use super::{
    Cli, Command, SceneArgs, SpinArg, UsageError, batch, checked_presets_dir, parks_dir, scene,
};
use crate::preset;

/// Runs `command` if it is a batch: `None` if it is not.
pub(super) fn run(cli: &Cli, command: &Command) -> Option<Result<ExitCode, UsageError>> {
    if let Command::Fly {
        scene,
        batch: Some(source),
        json,
        park,
        keep,
        spray,
        own_air,
        summary,
        all_parks,
        spin,
        ..
    } = command
    {
        let batch = BatchArgs::new(scene, source, (park, keep), *summary, *json);
        return Some(run_batch(cli, &batch, |setup| {
            setup.spray = (*spray).into();
            // A batch flies each row once (a season in about a second); a
            // park's own air is a flight a park, asked for.
            setup.own_air = *own_air;
            setup.all_parks = *all_parks;
            setup.solve_swings = *spin == SpinArg::Swing;
        }));
    }
    if let Command::Hit {
        scene,
        batch: Some(source),
        json,
        park,
        keep,
        summary,
    } = command
    {
        let batch = BatchArgs::new(scene, source, (park, keep), *summary, *json);
        return Some(run_batch(cli, &batch, |setup| {
            setup.solve_swings = true;
            setup.swing_columns = true;
        }));
    }
    None
}

/// What `fly --batch` and `hit --batch` share on their command lines.
struct BatchArgs<'a> {
    scene: &'a SceneArgs,
    source: &'a str,
    park: Option<&'a str>,
    keep: Option<&'a str>,
    summary: bool,
    json: bool,
}

impl<'a> BatchArgs<'a> {
    fn new(
        scene: &'a SceneArgs,
        source: &'a str,
        (park, keep): (&'a Option<String>, &'a Option<String>),
        summary: bool,
        json: bool,
    ) -> BatchArgs<'a> {
        BatchArgs {
            scene,
            source,
            park: park.as_deref(),
            keep: keep.as_deref(),
            summary,
            json,
        }
    }
}

/// Runs a batch over `batch.source`, its setup made as the command line
/// says and then as `choose` sets it.
fn run_batch(
    cli: &Cli,
    batch: &BatchArgs,
    choose: impl FnOnce(&mut batch::Setup),
) -> Result<ExitCode, UsageError> {
    let preset = batch
        .scene
        .resolve(checked_presets_dir(cli)?.as_deref(), cli.units)?;
    scene::check_path("--batch", batch.source)?;
    let parks = preset::parks::all_noted(parks_dir(cli).as_deref())?;
    let mut setup = batch::Setup::for_command(&preset, &parks, &batch.scene.set, batch.park)?;
    setup.summary_to_stdout = batch.summary;
    if let Some(keep) = batch.keep {
        setup.keep = keep
            .split(',')
            .map(|c| c.trim().to_owned())
            .filter(|c| !c.is_empty())
            .collect();
    }
    choose(&mut setup);
    let stdout = std::io::stdout().lock();
    setup.escape_kept = stdout.is_terminal();
    let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout);
    let mut err = std::io::stderr().lock();
    let erase = err.is_terminal();
    let outcome = batch::run(
        &setup,
        batch.source,
        batch.json,
        Shown(cli.units),
        &mut batch::Sinks {
            out: &mut out,
            err: &mut err,
            erase,
        },
    )?;
    Ok(ExitCode::from(outcome.exit_status()))
}
