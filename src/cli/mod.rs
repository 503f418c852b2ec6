//! The headless command line: clap commands → core → text, JSON or CSV.
//!
//! One file per command group; every table goes through `table`.

mod args;
mod batch_run;
mod bench;
mod calibrate;
mod calibrate_impact;
mod config_folder;
mod figure;
mod fly;
mod ground;
mod hit;
mod optimize;
mod parks;
mod presets;
mod progress;
mod scene;
pub(crate) use crate::analysis::shown;
use shown::Shown;
mod surface;
mod svg_file;
mod table;
mod table2;
mod threads;
mod usage;
mod usage_error;
pub use args::{Cli, Command, SceneArgs, SpinArg, SprayArg, UNITS_HELP};
pub use usage_error::{UsageError, WindowFault};

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use crate::preset::compact::CompactPresets;
use crate::preset::{self, Preset};

pub use crate::preset::FIELD_KEYS;
pub use optimize::MAX_STEPS;
pub use surface::{MAX_GRID, SURFACE_FLIGHT_STEPS};
pub use threads::{MAX_THREADS, check_thread_count};
pub use usage::{Parsed, error_line, parse};

/// `tui --savant FILE [--column NAME=COLUMN]…`: the file's solved swings
/// as presets for the explorer's picker (from `preset`'s ball and bat),
/// its columns mapped as `fly --batch` maps them, with a note of how many
/// were solved. None solved is refused: there would be nothing to pick.
pub fn savant_swings(
    cli: &Cli,
    preset: &Preset,
    (file, column): (&str, &[String]),
) -> Result<CompactPresets, UsageError> {
    scene::check_path("--savant", file)?;
    let parks = preset::parks::all_noted(parks_dir(cli).as_deref())?;
    let mut setup = batch_run::setup(preset, &parks, (&[], None, column))?;
    setup.takes_set = false;
    let failed = |message: String| UsageError::Savant {
        input: crate::preset::escape_cut(file, 200),
        message,
    };
    let input = batch::open(file).map_err(failed)?;
    let note = &mut |m: &str| eprintln!("homerun: {m}");
    let swings =
        batch::swings::solved_swings(&mut setup, input, Shown(cli.units), note).map_err(failed)?;
    if swings.presets.is_empty() {
        return Err(failed(format!(
            "no swing solved in {} rows ({} tracked but not solved)",
            swings.rows, swings.unsolved
        )));
    }
    eprintln!(
        "homerun: {} swings solved of {} rows ({} tracked but not solved)",
        swings.presets.len(),
        swings.rows,
        swings.unsolved
    );
    Ok(swings.presets)
}

/// The user's preset folder: `--presets-dir`, or the XDG default when it
/// can be used (else a warning, and the bundled presets only).
pub fn presets_dir(cli: &Cli) -> Option<PathBuf> {
    (cli.presets_dir.clone()).or_else(|| config_folder::usable(config_folder::Folder::Presets))
}

/// The user's parks folder: `--parks-dir`, or the XDG default when it can
/// be used (else a warning, and the bundled parks only).
pub fn parks_dir(cli: &Cli) -> Option<PathBuf> {
    (cli.parks_dir.clone()).or_else(|| config_folder::usable(config_folder::Folder::Parks))
}

/// The explorer's preset and folder, checked as every command's are.
pub fn explorer_preset(cli: &Cli, spec: &str) -> Result<(Preset, Option<PathBuf>), UsageError> {
    let dir = checked_presets_dir(cli)?;
    Ok((scene::open(spec, dir.as_deref())?, dir))
}

/// [`presets_dir`], refused if it is too long to be a path.
fn checked_presets_dir(cli: &Cli) -> Result<Option<PathBuf>, UsageError> {
    let dir = presets_dir(cli);
    if let Some(dir) = &dir {
        scene::check_path("--presets-dir", &dir.to_string_lossy())?;
    }
    Ok(dir)
}

/// Runs a headless command, writing to stdout, and gives the exit status: 0,
/// or 1 when some rows of a batch (`fly --batch`, `calibrate`) failed. A closed pipe (`| head`)
/// ends the output quietly.
pub fn run(cli: &Cli, command: &Command) -> Result<ExitCode, UsageError> {
    if let Some(ran) = batch_run::run(cli, command) {
        return ran;
    }
    if let Command::Calibrate {
        file,
        scene,
        park,
        spray,
        by,
        column,
        save,
        force,
        drag_only,
        json,
        impact,
        spin,
    } = command
    {
        let dir = checked_presets_dir(cli)?;
        // A save that cannot be made is refused before the fit, not after.
        if let Some(name) = save
            && dir.is_none()
            && let Some(message) = config_folder::unusable_presets_folder()
        {
            return Err(UsageError::CalibrateSave {
                name: crate::preset::escape_cut(name, 200),
                message,
            });
        }
        let preset = scene.resolve(dir.as_deref(), cli.units)?;
        scene::check_path("calibrate", file)?;
        let parks = preset::parks::all_noted(parks_dir(cli).as_deref())?;
        let mut setup = batch_run::setup(&preset, &parks, (&scene.set, park.as_deref(), column))?;
        setup.spray = (*spray).into();
        // The impact's fit reads bat tracking, as a swing's solve does.
        setup.solve_swings = *spin == args::SpinArg::Swing || *impact;
        let save = save.as_deref().map(|name| calibrate::Save {
            name,
            dir: dir.as_deref(),
            force: *force,
        });
        let shown = Shown(cli.units);
        let (text, rows) = match impact {
            true => calibrate_impact::run(&setup, file, save, *json, shown)?,
            false => calibrate::run(
                &mut setup,
                file,
                (save, by.as_deref()),
                !drag_only,
                *json,
                shown,
            )?,
        };
        // Groups' names are the file's: to a terminal, their controls escaped.
        let text = match std::io::IsTerminal::is_terminal(&std::io::stdout()) {
            true => preset::json_for_terminal(&text).into_owned(),
            false => text,
        };
        // Written as every command's output is: a full disk or a closed
        // pipe is an error line or a quiet end, never print!'s panic.
        write_stdout(&[text])?;
        // The fit stands on the rows read; a row that failed makes the
        // exit status 1, as in `fly --batch`.
        return Ok(calibrate::exit_status(rows));
    }
    let svg = svg_target(command);
    // A folder that cannot take the file is refused before any work.
    if let Some(path) = svg {
        svg_file::check(path)?;
    }
    let pieces = render_pieces(cli, command)?;
    if let Some(path) = svg {
        svg_file::write(path, &pieces.concat())?;
        eprintln!("wrote {}", svg_file::shown(path));
        return Ok(ExitCode::SUCCESS);
    }
    write_stdout(&pieces)
}

/// Writes a command's output to stdout, one piece after another: a write
/// that fails is an error (exit 2), a closed pipe (`| head`) a quiet end.
fn write_stdout(pieces: &[String]) -> Result<ExitCode, UsageError> {
    let mut stdout = std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock());
    let written = (pieces.iter()).try_for_each(|piece| stdout.write_all(piece.as_bytes()));
    match written.and_then(|()| stdout.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(UsageError::Output(e)),
        _ => Ok(ExitCode::SUCCESS),
    }
}

/// Whether `command` writes its output to stdout (the explorer draws on
/// the terminal; `--svg FILE` writes a file and says so on stderr).
pub fn writes_stdout(command: &Command) -> bool {
    !matches!(command, Command::Tui { .. }) && svg_target(command).is_none()
}

/// Where the command writes its picture, if it was given `--svg FILE`.
fn svg_target(command: &Command) -> Option<&std::path::Path> {
    match command {
        Command::Trajectory { svg, .. }
        | Command::Surface { svg, .. }
        | Command::Figure { svg, .. }
        | Command::Bench { svg, .. }
        | Command::Parks { svg, .. } => svg.as_deref(),
        _ => None,
    }
}

/// The output of a headless command in pieces, to be written one after
/// another: one but for `surface`'s CSV, which comes in the pieces its
/// chunks of cells wrote in parallel (a 64×64 grid's 250 kB, never copied
/// into one text).
fn render_pieces(cli: &Cli, command: &Command) -> Result<Vec<String>, UsageError> {
    let Command::Surface {
        scene,
        undercut,
        swing_angle,
        grid,
        json,
        csv,
        svg,
    } = command
    else {
        return Ok(vec![render(cli, command)?]);
    };
    let dir = checked_presets_dir(cli)?;
    let shown = Shown(cli.units);
    let preset = scene.resolve(dir.as_deref(), cli.units)?;
    scene::swing_only("surface", &preset)?;
    let cells = surface::parse_grid(undercut.as_deref(), swing_angle.as_deref(), grid, shown)?;
    if svg.is_some() {
        return Ok(vec![surface::surface_svg(&preset, cells, grid, shown)?]);
    }
    surface::surface(&preset.scene, cells, grid, Format::new(*json, *csv), shown)
}

/// The output of a headless command, as text (the SVG itself with `--svg`).
pub fn render(cli: &Cli, command: &Command) -> Result<String, UsageError> {
    let dir = checked_presets_dir(cli)?;
    let dir = dir.as_deref();
    let shown = Shown(cli.units);
    match command {
        Command::Hit { scene, json, .. } => Ok(hit::hit(
            &scene.resolve_swing("hit", dir, cli.units)?,
            *json,
            shown,
        )),
        Command::Optimize {
            scene,
            json,
            park: None,
            ..
        } => Ok(optimize::optimum(
            &scene.resolve_swing("optimize", dir, cli.units)?,
            *json,
            shown,
        )),
        Command::Optimize {
            scene,
            json,
            park: Some(code),
            fix,
        } => {
            let held = optimize::held(fix)?;
            let mut preset = scene.resolve(dir, cli.units)?;
            scene::swing_only("optimize", &preset)?;
            let parks = preset::parks::all_noted(parks_dir(cli).as_deref())?;
            let park = parks::lookup(code, &parks)?;
            ground::to_park(
                &mut preset.scene,
                park,
                crate::model::park::GivenWeather::of_assignments(&scene.set),
            );
            Ok(optimize::park_optimum(
                &preset.scene,
                park,
                held,
                *json,
                shown,
            ))
        }
        Command::Fly {
            scene,
            json,
            park,
            all_parks,
            one_flight,
            spin,
            ..
        } => {
            let mut preset = scene.resolve(dir, cli.units)?;
            // `--spin nathan`: the spin a batch row without one would take.
            let gave = |key: &str| batch::assigned_keys(&scene.set).any(|k| k == key);
            let estimated = *spin == Some(args::SpinArg::Nathan);
            if estimated {
                if gave("launch.spin") {
                    return Err(UsageError::CommandLine(
                        "--spin nathan estimates the spin that --set launch.spin gives: drop one"
                            .to_owned(),
                    ));
                }
                let sidespin_given = gave("launch.sidespin");
                preset.scene =
                    crate::analysis::savant::with_estimated_spin(&preset.scene, sidespin_given);
            }
            let parks = preset::parks::all_noted(parks_dir(cli).as_deref())?;
            let generic = ground::generic_fence(&preset);
            let ground = match park {
                Some(code) => {
                    let park = parks::lookup(code, &parks)?;
                    ground::to_park(
                        &mut preset.scene,
                        park,
                        crate::model::park::GivenWeather::of_assignments(&scene.set),
                    );
                    ground::Ground::Park(park)
                }
                None => ground::Ground::Generic(&generic),
            };
            // One rule: a park's outcome is the ball in that park's own air.
            let own_air = (!*one_flight)
                .then(|| crate::model::park::GivenWeather::of_assignments(&scene.set));
            Ok(fly::fly(
                &preset,
                ground,
                &parks,
                (*all_parks, own_air),
                (*json, *spin),
                shown,
            ))
        }
        Command::Table2 { json } => Ok(elapsed("table2", || table2::table2(*json))),
        Command::Bench { json, quick, svg } => {
            elapsed("bench", || bench::output(*json, *quick, svg.is_some()))
        }
        Command::Sweep {
            key,
            from,
            to,
            steps,
            scene,
            json,
            csv,
        } => optimize::sweep(
            &scene.resolve_swing("sweep", dir, cli.units)?,
            key,
            (from, to, *steps),
            Format::new(*json, *csv),
            shown,
        ),
        Command::Surface { .. } => Ok(render_pieces(cli, command)?.concat()),
        Command::Presets => Ok(presets::presets(preset::check_dir(dir)?)),
        Command::Parks { code, json, svg } => {
            let all = preset::parks::all_noted(parks_dir(cli).as_deref())?;
            let Some(code) = code else {
                return Ok(parks::list(&all, *json, shown));
            };
            let park = parks::lookup(code, &all)?;
            if svg.is_some() {
                return Ok(crate::picture::park_svg_in(park, shown.0)?);
            }
            Ok(parks::profile(park, *json, shown))
        }
        Command::Keys => Ok(hit::keys(shown)),
        Command::Trajectory {
            scene,
            samples,
            json,
            csv,
            svg,
        } => {
            let preset = scene.resolve(dir, cli.units)?;
            if svg.is_some() {
                return hit::trajectory_svg(&preset, *samples, shown);
            }
            hit::trajectory(&preset.scene, *samples, Format::new(*json, *csv), shown)
        }
        Command::Figure {
            number,
            preset,
            set,
            json,
            csv,
            svg,
        } => figure::figure(
            *number,
            preset.as_deref(),
            set,
            dir,
            Format::new(*json, *csv),
            svg.is_some(),
            shown,
        ),
        Command::Tui { .. } => Err(UsageError::NotHeadless),
        Command::Calibrate { .. } => unreachable!("run() answers calibrate"),
    }
}

/// `job`, with a progress line giving the time it has taken once it passes a
/// second (see [`progress`]).
fn elapsed<T>(what: &str, job: impl FnOnce() -> T) -> T {
    progress::run(progress::Work { what, steps: None }, |_| job())
}

/// How a command prints: text for people, JSON or CSV for programs.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Format {
    Text,
    Json,
    Csv,
}

impl Format {
    fn new(json: bool, csv: bool) -> Format {
        if json {
            Format::Json
        } else if csv {
            Format::Csv
        } else {
            Format::Text
        }
    }
}

/// Pretty JSON, with a final newline.
fn pretty(value: &serde_json::Value) -> String {
    serde_json::to_string_pretty(value).expect("plain numbers") + "\n"
}
