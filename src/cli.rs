//! The headless command line: clap commands → core → text, JSON or CSV.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use crate::model::scene::Scene;
use crate::preset::{self, Preset};

#[derive(Parser, Debug)]
#[command(
    name = "homerun",
    version,
    about = "The physics of hitting a baseball as far as possible (Sawicki, Hubbard & Stronge 2003).",
    long_about = "The physics of hitting a baseball as far as possible, after Sawicki, Hubbard & Stronge, \
                  \"How to hit home runs\", Am. J. Phys. 71 (2003).\n\n\
                  With no command, opens the explorer (a terminal app); the commands below print numbers."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Folder for the user's own presets (default: $XDG_CONFIG_HOME/homerun/presets).
    #[arg(long, global = true, value_name = "DIR")]
    pub presets_dir: Option<PathBuf>,
}

/// Which preset to start from, and changes to it.
#[derive(Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// A preset name (see `homerun presets`) or a path to a TOML file.
    #[arg(long, short, value_name = "P", default_value = "fastball")]
    pub preset: String,
    /// Change one input, with the same keys as the TOML (e.g. bat.speed=32).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// One swing: pitch, every impact quantity, flight summary.
    Hit {
        #[command(flatten)]
        scene: SceneArgs,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
    /// The undercut and swing angle that maximise range (§II.E).
    Optimize {
        #[command(flatten)]
        scene: SceneArgs,
        #[arg(long)]
        json: bool,
    },
    /// Table II: the paper's numbers beside ours, with the differences.
    Table2 {
        #[arg(long)]
        json: bool,
    },
    /// The optimum (undercut, swing angle, range) against any numeric key.
    Sweep {
        /// The key to sweep, e.g. bat.speed.
        key: String,
        #[arg(long, allow_hyphen_values = true)]
        from: f64,
        #[arg(long, allow_hyphen_values = true)]
        to: f64,
        #[arg(long, default_value_t = 11)]
        steps: usize,
        #[command(flatten)]
        scene: SceneArgs,
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        #[arg(long)]
        csv: bool,
    },
    /// The range over a grid of (undercut, swing angle), as in Fig. 7.
    Surface {
        #[command(flatten)]
        scene: SceneArgs,
        /// Undercut window A..B (m).
        #[arg(
            long,
            value_name = "A..B",
            default_value = "0..0.05",
            allow_hyphen_values = true
        )]
        undercut: String,
        /// Swing-angle window C..D (rad).
        #[arg(
            long,
            value_name = "C..D",
            default_value = "-0.6..1.0",
            allow_hyphen_values = true
        )]
        swing_angle: String,
        /// Columns (undercut) x rows (swing angle).
        #[arg(long, value_name = "NxM", default_value = "21x17")]
        grid: String,
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        #[arg(long)]
        csv: bool,
    },
    /// The presets and what they are.
    Presets,
    /// Speed against error on this machine: the work–precision tables.
    Bench {
        /// Print JSON, with the tables' field names.
        #[arg(long)]
        json: bool,
        /// A reduced version (seconds).
        #[arg(long)]
        quick: bool,
    },
    /// Open the explorer (the default with no command).
    Tui {
        /// The preset to start from.
        #[arg(long, short, value_name = "P", default_value = "fastball")]
        preset: String,
    },
}

/// A failure the user can fix: printed as one line, exit status 2.
#[derive(Debug, thiserror::Error)]
pub enum UsageError {
    #[error(transparent)]
    Preset(#[from] preset::PresetError),
    #[error(transparent)]
    Input(#[from] crate::model::scene::InputError),
    #[error("{0}")]
    Other(String),
}

impl SceneArgs {
    /// The preset, with every `--set` applied, validated.
    pub fn resolve(&self, presets_dir: Option<&std::path::Path>) -> Result<Preset, UsageError> {
        let mut preset = preset::load(&self.preset, presets_dir)?;
        for assignment in &self.set {
            let (key, value) = assignment.split_once('=').ok_or_else(|| {
                UsageError::Other(format!(
                    "--set {assignment:?}: expected KEY=VALUE, e.g. bat.speed=32"
                ))
            })?;
            preset.scene.set_text(key.trim(), value)?;
        }
        preset.scene.validate()?;
        Ok(preset)
    }
}

/// The user's preset folder: `--presets-dir` or the XDG default.
pub fn presets_dir(cli: &Cli) -> Option<PathBuf> {
    cli.presets_dir.clone().or_else(preset::user_dir)
}

/// Runs a headless command, writing to stdout.
pub fn run(cli: &Cli, command: &Command) -> Result<(), UsageError> {
    let dir = presets_dir(cli);
    let dir = dir.as_deref();
    match command {
        Command::Hit { scene, json } => hit(&scene.resolve(dir)?.scene, *json),
        Command::Bench { json, quick } => crate::bench::print(*json, *quick),
        _ => Err(UsageError::Other("not implemented yet".into())),
    }
}

fn hit(scene: &Scene, json: bool) -> Result<(), UsageError> {
    let swing = crate::simulate(scene, crate::Purpose::Readout);
    let impact = &swing.impact;
    let flight = &swing.flight;
    let vertical =
        crate::model::pitch::vertical_velocity(scene.pitch.speed, scene.environment.gravity);
    if json {
        let value = serde_json::json!({
            "pitch": {
                "speed": scene.pitch.speed,
                "vertical_velocity": vertical,
                "angle": impact.descent_angle,
            },
            "impact": {
                "normal_angle": impact.normal_angle,
                "restitution": impact.restitution,
                "regime": impact.regime,
                "compression_impulse": impact.compression_impulse,
                "separation_impulse": impact.separation_impulse,
                "stick_impulse": impact.stick_impulse(),
                "launch_speed": impact.launch_speed(),
                "launch_spin": impact.launch_spin(),
                "launch_angle": impact.launch_angle(),
            },
            "flight": {
                "range": flight.range,
                "flight_time": flight.flight_time,
                "apex": flight.apex,
                "landing_speed": flight.landing_speed,
                "landing_angle": flight.landing_angle,
            },
        });
        println!(
            "{}",
            serde_json::to_string_pretty(&value).expect("plain numbers")
        );
    } else {
        println!(
            "pitch    speed {:.2} m/s, vertical {:.3} m/s, descending at {:.4} rad",
            scene.pitch.speed, vertical, impact.descent_angle
        );
        println!(
            "impact   θ {:.4} rad, e* {:.4}, {:?}; p_c {:.4} N·s, p_f {:.4} N·s, p_s {}",
            impact.normal_angle,
            impact.restitution,
            impact.regime,
            impact.compression_impulse,
            impact.separation_impulse,
            impact
                .stick_impulse()
                .map_or("never (slips throughout)".to_string(), |p| format!(
                    "{p:.4} N·s"
                ))
        );
        println!(
            "launch   {:.3} m/s, {:.2} rad/s backspin, {:.4} rad",
            impact.launch_speed(),
            impact.launch_spin(),
            impact.launch_angle()
        );
        println!(
            "flight   range {:.3} m, time {:.3} s, apex {:.2} m, lands at {:.2} m/s, {:.3} rad",
            flight.range,
            flight.flight_time,
            flight.apex,
            flight.landing_speed,
            flight.landing_angle
        );
    }
    Ok(())
}
