//! The headless command line: clap commands → core → text, JSON or CSV.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use rayon::prelude::*;
use serde::Serialize;

use crate::model::pitch;
use crate::model::scene::Scene;
use crate::precision::Purpose;
use crate::preset::{self, Preset, Source};
use crate::solve::optimize::{self, OptimizerSettings, Optimum};
use crate::study::{self, Grid};

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

/// Runs a headless command, writing to stdout. A closed pipe (`| head`)
/// ends the output quietly.
pub fn run(cli: &Cli, command: &Command) -> Result<(), UsageError> {
    let text = render(cli, command)?;
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(UsageError::Other(format!("writing the output: {e}")))
        }
        _ => Ok(()),
    }
}

/// The output of a headless command, as text.
pub fn render(cli: &Cli, command: &Command) -> Result<String, UsageError> {
    let dir = presets_dir(cli);
    let dir = dir.as_deref();
    match command {
        Command::Hit { scene, json } => Ok(hit(&scene.resolve(dir)?.scene, *json)),
        Command::Optimize { scene, json } => Ok(optimum(&scene.resolve(dir)?.scene, *json)),
        Command::Table2 { json } => Ok(table2(*json)),
        Command::Bench { json, quick } => Ok(crate::bench::output(*json, *quick)),
        Command::Sweep {
            key,
            from,
            to,
            steps,
            scene,
            json,
            csv,
        } => sweep(
            &scene.resolve(dir)?.scene,
            key,
            (*from, *to, *steps),
            Format::new(*json, *csv),
        ),
        Command::Surface {
            scene,
            undercut,
            swing_angle,
            grid,
            json,
            csv,
        } => {
            let scene = scene.resolve(dir)?.scene;
            let grid = parse_grid(undercut, swing_angle, grid)?;
            Ok(surface(&scene, grid, Format::new(*json, *csv)))
        }
        Command::Presets => Ok(presets(dir)),
        // The explorer, and any command that is not headless.
        #[allow(unreachable_patterns)]
        _ => Err(UsageError::Other(
            "this command opens the explorer; it is not a headless command".into(),
        )),
    }
}

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

fn pretty(value: &serde_json::Value) -> String {
    serde_json::to_string_pretty(value).expect("plain numbers") + "\n"
}

fn hit(scene: &Scene, json: bool) -> String {
    let swing = crate::simulate(scene, Purpose::Readout);
    let impact = &swing.impact;
    let flight = &swing.flight;
    let vertical = pitch::vertical_velocity(scene.pitch.speed, scene.environment.gravity);
    if json {
        return pretty(&serde_json::json!({
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
        }));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "pitch    {:.2} m/s at the plate, vertical velocity {:.3} m/s, descending at {:.4} rad ({:.1}°)",
        scene.pitch.speed,
        vertical,
        impact.descent_angle,
        impact.descent_angle.to_degrees()
    );
    let _ = writeln!(
        out,
        "swing    E = {:.4} m, ψ = {:.4} rad, bat {:.2} m/s, μ = {}",
        scene.bat.undercut, scene.bat.swing_angle, scene.bat.speed, scene.bat.friction
    );
    let _ = writeln!(
        out,
        "impact   θ = {:.4} rad, v1(0) = {:.3} m/s, v3(0) = {:.3} m/s, e* = {:.4}",
        impact.normal_angle, impact.initial_slip, impact.initial_approach, impact.restitution
    );
    let _ = writeln!(
        out,
        "         p_c = {:.4} N·s, p_f = {:.4} N·s, {}",
        impact.compression_impulse,
        impact.separation_impulse,
        match impact.stick_impulse() {
            Some(p) => format!("slip halts at p_s = {p:.4} N·s (stick)"),
            None => "slips until separation".to_owned(),
        }
    );
    let _ = writeln!(out, "{}", launch_line(impact));
    let _ = writeln!(
        out,
        "flight   range {:.3} m in {:.3} s, apex {:.2} m, lands at {:.2} m/s, {:.3} rad below horizontal{}",
        flight.range,
        flight.flight_time,
        flight.apex,
        flight.landing_speed,
        flight.landing_angle,
        if flight.landed {
            ""
        } else {
            " (still in the air at the time limit)"
        }
    );
    out
}

/// A batted spin in words: backspin is positive.
/// "launch   44.299 m/s, 191.83 rad/s of backspin, 0.4604 rad (26.4°)"
fn launch_line(impact: &crate::model::impact::Impact) -> String {
    format!(
        "launch   {:.3} m/s, {}, {:.4} rad ({:.1}°)",
        impact.launch_speed(),
        spin_text(impact.launch_spin()),
        impact.launch_angle(),
        impact.launch_angle().to_degrees()
    )
}

fn spin_text(spin: f64) -> String {
    if spin < 0.0 {
        format!("{:.2} rad/s of topspin", -spin)
    } else {
        format!("{spin:.2} rad/s of backspin")
    }
}

/// The optimum and the launch it gives, at readout precision.
struct Best {
    optimum: Optimum,
    swing: crate::Swing,
}

fn best_swing(scene: &Scene) -> Best {
    let optimum = optimize::optimize(scene, OptimizerSettings::default());
    let mut at = *scene;
    at.bat.undercut = optimum.undercut;
    at.bat.swing_angle = optimum.swing_angle;
    Best {
        optimum,
        swing: crate::simulate(&at, Purpose::Readout),
    }
}

fn optimum(scene: &Scene, json: bool) -> String {
    let Best { optimum, swing } = best_swing(scene);
    let impact = &swing.impact;
    if json {
        return pretty(&serde_json::json!({
            "undercut": optimum.undercut,
            "swing_angle": optimum.swing_angle,
            "range": swing.flight.range,
            "launch_speed": impact.launch_speed(),
            "launch_spin": impact.launch_spin(),
            "launch_angle": impact.launch_angle(),
            "evaluations": optimum.evaluations,
            "converged": optimum.converged,
        }));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "optimum  E = {:.6} m, ψ = {:.5} rad ({:.2}°)",
        optimum.undercut,
        optimum.swing_angle,
        optimum.swing_angle.to_degrees()
    );
    let _ = writeln!(
        out,
        "range    {:.4} m in {:.3} s",
        swing.flight.range, swing.flight.flight_time
    );
    let _ = writeln!(out, "{}", launch_line(impact));
    let _ = writeln!(
        out,
        "search   {} range evaluations, {}",
        optimum.evaluations,
        if optimum.converged {
            "converged (Nelder–Mead, tolerances 1e-4)"
        } else {
            "NOT converged: stopped at the evaluation limit"
        }
    );
    out
}

/// One row of Table II, or ours in the same columns.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TableRow {
    pub pitch_speed: f64,
    pub bat_speed: f64,
    pub pitch_spin: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub undercut: f64,
    pub swing_angle: f64,
    pub range: f64,
}

/// The paper's Table II as printed: (pitch, bundled preset, row).
pub const TABLE2: [(&str, &str, TableRow); 3] = [
    (
        "fast",
        "fastball",
        TableRow {
            pitch_speed: 42.0,
            bat_speed: 30.0,
            pitch_spin: -200.0,
            launch_speed: 44.30,
            launch_spin: 191.35,
            launch_angle: 0.4600,
            undercut: 0.0265,
            swing_angle: 0.1594,
            range: 134.798,
        },
    ),
    (
        "knuckle",
        "knuckleball",
        TableRow {
            pitch_speed: 36.0,
            bat_speed: 30.0,
            pitch_spin: 0.0,
            launch_speed: 44.04,
            launch_spin: 226.87,
            launch_angle: 0.4499,
            undercut: 0.0250,
            swing_angle: 0.1549,
            range: 135.771,
        },
    ),
    (
        "curve",
        "curveball",
        TableRow {
            pitch_speed: 35.0,
            bat_speed: 30.0,
            pitch_spin: 200.0,
            // A misprint for 44.04: the spin and launch angle beside it match
            // ours to rounding, and so does 44.04. See `CURVE_LAUNCH_SPEED`.
            launch_speed: 43.04,
            launch_spin: 276.78,
            launch_angle: 0.4245,
            undercut: 0.0223,
            swing_angle: 0.1152,
            range: 138.831,
        },
    ),
];

/// Table II's curve-ball launch speed, corrected (printed as 43.04).
pub const CURVE_LAUNCH_SPEED: f64 = 44.04;

/// How close ours must be to the paper's (the tests hold the same numbers).
pub mod tolerance {
    /// At the paper's (E, ψ): launch speed (m/s), spin (rad/s), angle (rad).
    pub const LAUNCH_SPEED: f64 = 0.02;
    pub const LAUNCH_SPIN: f64 = 1.0;
    pub const LAUNCH_ANGLE: f64 = 0.002;
    /// The optimum: E (m), ψ (rad), range (m). ψ is loose because the
    /// optimum lies on a flat ridge along ψ (the paper calls ψ its least
    /// accurate output).
    pub const UNDERCUT: f64 = 0.001;
    pub const SWING_ANGLE: f64 = 0.03;
    pub const RANGE: f64 = 0.1;
}

/// One pitch of Table II, ours beside the paper's.
#[derive(Clone, Debug, Serialize)]
pub struct Table2Row {
    pub pitch: &'static str,
    /// As printed.
    pub paper: TableRow,
    /// Our optimum and the launch at it.
    pub ours: TableRow,
    /// Ours at the paper's own (E, ψ): the launch to compare with the
    /// printed launch columns.
    pub ours_at_paper_swing: TableRow,
    /// Misprints in the paper's row: (column, printed, corrected).
    pub errata: Vec<(&'static str, f64, f64)>,
    /// Whether every compared column is inside [`tolerance`].
    pub within_tolerance: bool,
}

fn row_of(scene: &Scene, swing: &crate::Swing) -> TableRow {
    TableRow {
        pitch_speed: scene.pitch.speed,
        bat_speed: scene.bat.speed,
        pitch_spin: scene.pitch.spin,
        launch_speed: swing.impact.launch_speed(),
        launch_spin: swing.impact.launch_spin(),
        launch_angle: swing.impact.launch_angle(),
        undercut: scene.bat.undercut,
        swing_angle: scene.bat.swing_angle,
        range: swing.flight.range,
    }
}

/// Table II recomputed: the three optimisations run in parallel.
pub fn table2_rows() -> Vec<Table2Row> {
    TABLE2
        .par_iter()
        .map(|&(pitch, preset_name, paper)| {
            let mut scene = preset::load(preset_name, None)
                .expect("bundled presets load")
                .scene;
            scene.bat.undercut = paper.undercut;
            scene.bat.swing_angle = paper.swing_angle;
            let ours_at_paper_swing = row_of(&scene, &crate::simulate(&scene, Purpose::Readout));
            let best = best_swing(&scene);
            scene.bat.undercut = best.optimum.undercut;
            scene.bat.swing_angle = best.optimum.swing_angle;
            let ours = row_of(&scene, &best.swing);
            let errata = if pitch == "curve" {
                vec![("launch_speed", paper.launch_speed, CURVE_LAUNCH_SPEED)]
            } else {
                Vec::new()
            };
            let corrected_speed = errata.first().map_or(paper.launch_speed, |e| e.2);
            let within_tolerance = (ours_at_paper_swing.launch_speed - corrected_speed).abs()
                <= tolerance::LAUNCH_SPEED
                && (ours_at_paper_swing.launch_spin - paper.launch_spin).abs()
                    <= tolerance::LAUNCH_SPIN
                && (ours_at_paper_swing.launch_angle - paper.launch_angle).abs()
                    <= tolerance::LAUNCH_ANGLE
                && (ours.undercut - paper.undercut).abs() <= tolerance::UNDERCUT
                && (ours.swing_angle - paper.swing_angle).abs() <= tolerance::SWING_ANGLE
                && (ours.range - paper.range).abs() <= tolerance::RANGE;
            Table2Row {
                pitch,
                paper,
                ours,
                ours_at_paper_swing,
                errata,
                within_tolerance,
            }
        })
        .collect()
}

fn table2(json: bool) -> String {
    let rows = table2_rows();
    if json {
        let list: Vec<serde_json::Value> = rows
            .iter()
            .map(|r| {
                serde_json::json!({
                    "pitch": r.pitch,
                    "paper": r.paper,
                    "ours": r.ours,
                    "ours_at_paper_swing": r.ours_at_paper_swing,
                    "errata": r.errata.iter().map(|(column, printed, corrected)| serde_json::json!({
                        "column": column, "printed": printed, "corrected": corrected,
                    })).collect::<Vec<_>>(),
                    "within_tolerance": r.within_tolerance,
                })
            })
            .collect();
        return pretty(&serde_json::Value::Array(list));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Table II of Sawicki, Hubbard & Stronge (2003) beside homerun (bat 30 m/s, μ = 0.5, no wind)\n"
    );
    let header = format!(
        "  {:<22}{:>9}{:>10}{:>9}{:>10}{:>9}{:>11}",
        "", "V_bf m/s", "ω_bf r/s", "ζ rad", "E_opt m", "ψ_opt", "range m"
    );
    for r in &rows {
        let erratum = r.errata.first();
        let _ = writeln!(
            out,
            "{}: pitch {:.2} m/s, {}",
            r.pitch,
            r.paper.pitch_speed,
            match r.pitch_spin_kind() {
                "" => "no spin".to_owned(),
                kind => format!("{:.0} rad/s of {kind}", r.paper.pitch_spin.abs()),
            }
        );
        let _ = writeln!(out, "{header}");
        let mark = if erratum.is_some() { "*" } else { " " };
        let _ = writeln!(
            out,
            "  {:<22}{:>8.2}{mark}{:>10.2}{:>9.4}{:>10.4}{:>9.4}{:>11.3}",
            "paper",
            r.paper.launch_speed,
            r.paper.launch_spin,
            r.paper.launch_angle,
            r.paper.undercut,
            r.paper.swing_angle,
            r.paper.range
        );
        let at = &r.ours_at_paper_swing;
        let _ = writeln!(
            out,
            "  {:<22}{:>9.3}{:>10.2}{:>9.4}{:>10}{:>9}{:>11.3}",
            "ours at paper's E, ψ",
            at.launch_speed,
            at.launch_spin,
            at.launch_angle,
            "same",
            "same",
            at.range
        );
        let speed = erratum.map_or(r.paper.launch_speed, |e| e.2);
        let _ = writeln!(
            out,
            "  {:<22}{:>+9.3}{:>+10.2}{:>+9.4}{:>10}{:>9}{:>11}",
            "  difference",
            at.launch_speed - speed,
            at.launch_spin - r.paper.launch_spin,
            at.launch_angle - r.paper.launch_angle,
            "",
            "",
            ""
        );
        let _ = writeln!(
            out,
            "  {:<22}{:>9.3}{:>10.2}{:>9.4}{:>10.5}{:>9.4}{:>11.3}",
            "ours, optimum",
            r.ours.launch_speed,
            r.ours.launch_spin,
            r.ours.launch_angle,
            r.ours.undercut,
            r.ours.swing_angle,
            r.ours.range
        );
        let _ = writeln!(
            out,
            "  {:<22}{:>9}{:>10}{:>9}{:>+10.5}{:>+9.4}{:>+11.3}",
            "  difference",
            "",
            "",
            "",
            r.ours.undercut - r.paper.undercut,
            r.ours.swing_angle - r.paper.swing_angle,
            r.ours.range - r.paper.range
        );
        if let Some((_, printed, corrected)) = erratum {
            let _ = writeln!(
                out,
                "  * printed {printed:.2}, a misprint for {corrected:.2}: the difference is against {corrected:.2}"
            );
        }
        let _ = writeln!(
            out,
            "  {}\n",
            if r.within_tolerance {
                "inside the tolerances"
            } else {
                "OUTSIDE the tolerances"
            }
        );
    }
    let _ = writeln!(
        out,
        "Tolerances: launch at the paper's (E, ψ) within {} m/s, {} rad/s, {} rad;\n\
         optimum within {} m in E, {} rad in ψ (a flat ridge), {} m in range.",
        tolerance::LAUNCH_SPEED,
        tolerance::LAUNCH_SPIN,
        tolerance::LAUNCH_ANGLE,
        tolerance::UNDERCUT,
        tolerance::SWING_ANGLE,
        tolerance::RANGE
    );
    trim_lines(&out)
}

/// Text without the padding that empty columns leave at line ends.
fn trim_lines(text: &str) -> String {
    text.lines()
        .map(|l| l.trim_end().to_owned() + "\n")
        .collect()
}

impl Table2Row {
    fn pitch_spin_kind(&self) -> &'static str {
        match self.paper.pitch_spin {
            s if s < 0.0 => "backspin",
            s if s > 0.0 => "topspin",
            _ => "",
        }
    }
}

/// The largest sweep (points) and grid side (cells) accepted.
pub const MAX_STEPS: usize = 1000;
pub const MAX_GRID: usize = 500;

fn sweep(
    scene: &Scene,
    key: &str,
    (from, to, steps): (f64, f64, usize),
    format: Format,
) -> Result<String, UsageError> {
    if !(1..=MAX_STEPS).contains(&steps) {
        return Err(UsageError::Other(format!(
            "--steps {steps}: must be an integer in [1, {MAX_STEPS}]"
        )));
    }
    let values = study::linspace(from, to, steps);
    let points = study::sweep(scene, key, &values, OptimizerSettings::default())
        .map_err(|e| UsageError::Other(e.to_string()))?;
    let unit = Scene::key(key).map(|k| k.unit).unwrap_or("");
    let mut out = String::new();
    match format {
        Format::Json => {
            return Ok(pretty(&serde_json::json!({
                "key": key,
                "unit": unit,
                "points": points,
            })));
        }
        Format::Csv => {
            let _ = writeln!(
                out,
                "{key},undercut,swing_angle,range,launch_speed,launch_spin,launch_angle,evaluations,converged"
            );
            for p in &points {
                let _ = writeln!(
                    out,
                    "{},{},{},{},{},{},{},{},{}",
                    p.value,
                    p.undercut,
                    p.swing_angle,
                    p.range,
                    p.launch_speed,
                    p.launch_spin,
                    p.launch_angle,
                    p.evaluations,
                    p.converged
                );
            }
        }
        Format::Text => {
            let label = if unit.is_empty() {
                key.to_owned()
            } else {
                format!("{key} ({unit})")
            };
            let _ = writeln!(
                out,
                "{label:>24} {:>10} {:>8} {:>10} {:>9} {:>9} {:>8}",
                "E_opt (m)", "ψ_opt", "range (m)", "V_bf m/s", "ω_bf r/s", "ζ rad"
            );
            for p in &points {
                let _ = writeln!(
                    out,
                    "{:>24} {:>10.5} {:>8.4} {:>10.3} {:>9.3} {:>9.2} {:>8.4}{}",
                    trimmed(p.value),
                    p.undercut,
                    p.swing_angle,
                    p.range,
                    p.launch_speed,
                    p.launch_spin,
                    p.launch_angle,
                    if p.converged { "" } else { "  (not converged)" }
                );
            }
        }
    }
    Ok(out)
}

/// A swept value to six decimals, without trailing zeros.
fn trimmed(value: f64) -> String {
    let text = format!("{value:.6}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// Parses "A..B" (a window) for `flag`, inside `bounds`.
fn parse_window(flag: &str, text: &str, bounds: (f64, f64)) -> Result<(f64, f64), UsageError> {
    let bad = |why: &str| {
        let (accepted, example) = if flag == "--undercut" {
            (format!("[{}, {}] m", bounds.0, bounds.1), "0..0.05")
        } else {
            ("[-π/2, π/2] rad".to_owned(), "-0.6..1.0")
        };
        UsageError::Other(format!(
            "{flag} {text:?}: {why}; expected A..B with finite A < B in {accepted}, e.g. {example}"
        ))
    };
    let (a, b) = text.split_once("..").ok_or_else(|| bad("no `..`"))?;
    let parse = |s: &str| {
        s.trim()
            .parse::<f64>()
            .map_err(|_| bad(&format!("{:?} is not a number", s.trim())))
    };
    let (a, b) = (parse(a)?, parse(b)?);
    if !(a.is_finite() && b.is_finite()) {
        return Err(bad("not finite"));
    }
    if a >= b {
        return Err(bad("A must be below B"));
    }
    if a < bounds.0 || b > bounds.1 {
        return Err(bad("out of range"));
    }
    Ok((a, b))
}

/// Parses the surface's window and "NxM" grid.
fn parse_grid(undercut: &str, swing_angle: &str, grid: &str) -> Result<Grid, UsageError> {
    let key_bounds = |name| {
        let key = Scene::key(name).expect("a known key");
        (key.bounds.min, key.bounds.max)
    };
    let undercut = parse_window("--undercut", undercut, key_bounds("bat.undercut"))?;
    let swing_angle = parse_window("--swing-angle", swing_angle, key_bounds("bat.swing_angle"))?;
    let bad = || {
        UsageError::Other(format!(
            "--grid {grid:?}: expected NxM, columns (undercut) x rows (swing angle), each an integer in [1, {MAX_GRID}], e.g. 21x17"
        ))
    };
    let (columns, rows) = grid
        .to_ascii_lowercase()
        .split_once('x')
        .map(|(n, m)| (n.trim().parse::<usize>(), m.trim().parse::<usize>()))
        .ok_or_else(bad)?;
    let (columns, rows) = (columns.map_err(|_| bad())?, rows.map_err(|_| bad())?);
    if !(1..=MAX_GRID).contains(&columns) || !(1..=MAX_GRID).contains(&rows) {
        return Err(bad());
    }
    Ok(Grid {
        undercut,
        swing_angle,
        columns,
        rows,
    })
}

fn surface(scene: &Scene, grid: Grid, format: Format) -> String {
    let surface = study::surface(scene, grid, Purpose::Surface);
    let undercuts: Vec<f64> = (0..grid.columns).map(|i| grid.undercut_at(i)).collect();
    let swing_angles: Vec<f64> = (0..grid.rows).map(|j| grid.swing_angle_at(j)).collect();
    let best = surface.best();
    let mut out = String::new();
    match format {
        Format::Json => {
            let rows: Vec<&[Option<f64>]> = surface.ranges.chunks(grid.columns).collect();
            return pretty(&serde_json::json!({
                "undercuts": undercuts,
                "swing_angles": swing_angles,
                "ranges": rows,
                "best": best.map(|(i, j, range)| serde_json::json!({
                    "undercut": undercuts[i], "swing_angle": swing_angles[j], "range": range,
                })),
            }));
        }
        Format::Csv => {
            let _ = writeln!(out, "undercut,swing_angle,range");
            for (j, psi) in swing_angles.iter().enumerate() {
                for (i, e) in undercuts.iter().enumerate() {
                    let range = surface.get(i, j).map_or(String::new(), |r| r.to_string());
                    let _ = writeln!(out, "{e},{psi},{range}");
                }
            }
        }
        Format::Text => {
            let _ = writeln!(
                out,
                "range (m) over undercut E (columns, mm) and swing angle ψ (rows, rad); * best cell, - bat misses"
            );
            let _ = write!(out, "{:>7} ", "ψ \\ E");
            for e in &undercuts {
                let _ = write!(out, "{:>5.1}", e * 1000.0);
            }
            out.push('\n');
            // ψ grows upward, as in Fig. 7.
            for j in (0..grid.rows).rev() {
                let _ = write!(out, "{:>7.3} ", swing_angles[j]);
                for i in 0..grid.columns {
                    let mark = if best.is_some_and(|b| (b.0, b.1) == (i, j)) {
                        "*"
                    } else {
                        " "
                    };
                    match surface.get(i, j) {
                        Some(r) => {
                            let _ = write!(out, "{:>4.0}{mark}", r);
                        }
                        None => {
                            let _ = write!(out, "{:>4}{mark}", "-");
                        }
                    }
                }
                out.push('\n');
            }
            if let Some((i, j, range)) = best {
                let _ = writeln!(
                    out,
                    "best cell: E = {:.4} m, ψ = {:.4} rad, range {:.2} m",
                    undercuts[i], swing_angles[j], range
                );
            }
            return trim_lines(&out);
        }
    }
    out
}

fn presets(dir: Option<&std::path::Path>) -> String {
    let mut out = String::new();
    let all = preset::list(dir);
    let width = all
        .iter()
        .filter_map(|p| p.as_ref().ok().map(|p| p.name.len()))
        .max()
        .unwrap_or(8)
        .max(8);
    for entry in &all {
        match entry {
            Ok(p) => {
                let source = match &p.source {
                    Source::Bundled => "bundled".to_owned(),
                    Source::File(path) => path.display().to_string(),
                };
                let _ = writeln!(out, "{:<width$}  {}", p.name, p.description);
                let _ = writeln!(out, "{:<width$}  ({source})", "");
            }
            Err(e) => {
                let _ = writeln!(out, "{:<width$}  {e}", "(broken)");
            }
        }
    }
    match dir {
        Some(dir) => {
            let _ = writeln!(
                out,
                "\nYour presets: {} (name.toml; use with --preset name)",
                dir.display()
            );
        }
        None => {
            let _ = writeln!(out, "\nNo user preset folder (give one with --presets-dir)");
        }
    }
    out
}
