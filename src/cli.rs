//! The headless command line: clap commands → core → text, JSON or CSV.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use crate::figures::{self, Cell, Figure, FigureData, FigureError, SurfaceFigure, trimmed};
use crate::model::pitch;
use crate::model::scene::InputError;
use crate::model::scene::Scene;
use crate::paper::{self, Best, Table2Row, best_swing, table2_rows, tolerance};
use crate::precision::Purpose;
use crate::preset::{self, Preset, Source};
use crate::solve::optimize::OptimizerSettings;
use crate::study::SweepError;
use crate::study::{self, Grid};
use crate::tui::TuiError;

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
    /// The batted ball's path: time, x, y and C_D, sampled evenly in time.
    Trajectory {
        #[command(flatten)]
        scene: SceneArgs,
        /// How many points, launch and landing included (2 to 100000).
        #[arg(long, default_value_t = 51)]
        samples: usize,
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        #[arg(long)]
        csv: bool,
    },
    /// Every input key: symbol, unit, accepted range and the fastball's value.
    Keys,
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
    /// The data behind one of the paper's figures (3–14), to plot beside it.
    Figure {
        /// The figure's number in the paper: 3 to 14.
        number: u32,
        /// A preset name or TOML path (default: figure5 for Figs. 5–6, fastball otherwise).
        #[arg(long, short, value_name = "P")]
        preset: Option<String>,
        /// Change one input, with the same keys as the TOML (e.g. bat.speed=32).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print JSON: title, conditions, one object per row, the paper's numbers beside ours.
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// Print CSV: a header of column names, one line per row (to plot).
        #[arg(long)]
        csv: bool,
    },
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
    Input(#[from] InputError),
    #[error(transparent)]
    Sweep(#[from] SweepError),
    #[error(transparent)]
    Figure(#[from] FigureError),
    #[error(transparent)]
    Tui(#[from] TuiError),
    #[error("--set {assignment:?}: expected KEY=VALUE, e.g. bat.speed=32")]
    BadAssignment { assignment: String },
    #[error("--steps {steps}: must be an integer in [1, {max}]", max = MAX_STEPS)]
    BadSteps { steps: usize },
    #[error("--samples {samples}: must be a whole number in [2, {max}]", max = MAX_SAMPLES)]
    BadSamples { samples: usize },
    #[error(
        "{flag} {text:?}: {fault}; expected A..B with finite A < B in {accepted}, e.g. {example}"
    )]
    BadWindow {
        flag: &'static str,
        text: String,
        fault: WindowFault,
        /// The accepted interval, with its unit.
        accepted: String,
        example: &'static str,
    },
    #[error(
        "--grid {text:?}: expected NxM, columns (undercut) x rows (swing angle), each an integer in [1, {max}], e.g. 21x17",
        max = MAX_GRID
    )]
    BadGrid { text: String },
    #[error("this command opens the explorer; it is not a headless command")]
    NotHeadless,
    #[error("writing the output: {0}")]
    Output(#[source] std::io::Error),
}

/// What is wrong with an A..B window.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WindowFault {
    #[error("no `..`")]
    NoDots,
    #[error("{0:?} is not a number")]
    NotANumber(String),
    #[error("not finite")]
    NotFinite,
    #[error("A must be below B")]
    Reversed,
    #[error("out of range")]
    OutOfRange,
}

impl SceneArgs {
    /// The preset, with every `--set` applied, validated.
    pub fn resolve(&self, presets_dir: Option<&std::path::Path>) -> Result<Preset, UsageError> {
        let mut preset = preset::load(&self.preset, presets_dir)?;
        for assignment in &self.set {
            let (key, value) =
                assignment
                    .split_once('=')
                    .ok_or_else(|| UsageError::BadAssignment {
                        assignment: assignment.clone(),
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
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(UsageError::Output(e)),
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
        Command::Keys => Ok(keys()),
        Command::Trajectory {
            scene,
            samples,
            json,
            csv,
        } => trajectory(
            &scene.resolve(dir)?.scene,
            *samples,
            Format::new(*json, *csv),
        ),
        Command::Figure {
            number,
            preset,
            set,
            json,
            csv,
        } => figure(
            *number,
            preset.as_deref(),
            set,
            dir,
            Format::new(*json, *csv),
        ),
        Command::Tui { .. } => Err(UsageError::NotHeadless),
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
        return Err(UsageError::BadSteps { steps });
    }
    let values = study::linspace(from, to, steps);
    let points = study::sweep(scene, key, &values, OptimizerSettings::default())?;
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

/// Parses "A..B" (a window) for `flag`, inside `bounds`.
fn parse_window(
    flag: &'static str,
    text: &str,
    bounds: (f64, f64),
) -> Result<(f64, f64), UsageError> {
    let bad = |fault| {
        let (accepted, example) = if flag == "--undercut" {
            (format!("[{}, {}] m", bounds.0, bounds.1), "0..0.05")
        } else {
            ("[-π/2, π/2] rad".to_owned(), "-0.6..1.0")
        };
        UsageError::BadWindow {
            flag,
            text: text.to_owned(),
            fault,
            accepted,
            example,
        }
    };
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| bad(WindowFault::NoDots))?;
    let parse = |s: &str| {
        s.trim()
            .parse::<f64>()
            .map_err(|_| bad(WindowFault::NotANumber(s.trim().to_owned())))
    };
    let (a, b) = (parse(a)?, parse(b)?);
    if !(a.is_finite() && b.is_finite()) {
        return Err(bad(WindowFault::NotFinite));
    }
    if a >= b {
        return Err(bad(WindowFault::Reversed));
    }
    if a < bounds.0 || b > bounds.1 {
        return Err(bad(WindowFault::OutOfRange));
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
    let bad = || UsageError::BadGrid {
        text: grid.to_owned(),
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
    render_surface(&study::surface(scene, grid, Purpose::Surface), format)
}

fn render_surface(surface: &study::Surface, format: Format) -> String {
    let grid = surface.grid;
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

// `homerun figure N`: the data behind the paper's Figs. 3–14, from
// `crate::figures`, printed as text, CSV or JSON.

fn figure(
    number: u32,
    preset: Option<&str>,
    set: &[String],
    dir: Option<&std::path::Path>,
    format: Format,
) -> Result<String, UsageError> {
    figures::known(number)?;
    let args = SceneArgs {
        preset: preset.unwrap_or(paper::figure_preset(number)).to_owned(),
        set: set.to_vec(),
    };
    let preset = args.resolve(dir)?;
    Ok(
        match figures::figure_data(number, &preset.scene, &preset.name)? {
            Figure::Table(data) => data.render(format),
            Figure::Surface(surface) => figure7(&surface, format),
        },
    )
}

/// Fig. 7: the `surface` command's output, with the optimum O beside the paper's.
fn figure7(figure: &SurfaceFigure, format: Format) -> String {
    let body = render_surface(&figure.surface, format);
    let o = &figure.optimum;
    let (undercut, swing_angle, range) = figure.paper;
    match format {
        Format::Csv => body,
        Format::Json => {
            let surface: serde_json::Value =
                serde_json::from_str(&body).expect("the surface's own JSON");
            pretty(&serde_json::json!({
                "figure": figure.number,
                "title": figure.title,
                "conditions": figure.conditions,
                "surface": surface,
                "optimum": {
                    "undercut": o.undercut, "swing_angle": o.swing_angle, "range": o.range,
                },
                "paper": {"undercut": undercut, "swing_angle": swing_angle, "range": range},
            }))
        }
        Format::Text => {
            let mut out = format!(
                "Fig. {}: {}\n{}\n",
                figure.number, figure.title, figure.conditions
            );
            out.push_str(&body);
            let _ = writeln!(
                out,
                "optimum O (Nelder–Mead): E = {:.4} m, ψ = {:.4} rad, range {:.2} m; paper: E = {undercut:.4} m, ψ = {swing_angle:.3} rad, {range:.2} m",
                o.undercut, o.swing_angle, o.range
            );
            out
        }
    }
}

impl FigureData {
    fn render(&self, format: Format) -> String {
        match format {
            Format::Json => self.json(),
            Format::Csv => self.csv(),
            Format::Text => self.text(),
        }
    }

    fn json(&self) -> String {
        let rows: Vec<serde_json::Value> = self
            .rows
            .iter()
            .map(|row| {
                let object: serde_json::Map<String, serde_json::Value> = self
                    .columns
                    .iter()
                    .zip(row)
                    .map(|(c, cell)| {
                        let value = match cell {
                            Cell::Num(x) => serde_json::json!(x),
                            Cell::Text(t) => serde_json::json!(t),
                            Cell::Blank => serde_json::Value::Null,
                        };
                        (c.key.clone(), value)
                    })
                    .collect();
                serde_json::Value::Object(object)
            })
            .collect();
        let comparisons: Vec<serde_json::Value> = self
            .comparisons
            .iter()
            .map(|c| {
                serde_json::json!({
                    "quantity": c.what, "unit": c.unit, "paper": c.paper, "ours": c.ours,
                })
            })
            .collect();
        pretty(&serde_json::json!({
            "figure": self.number,
            "title": self.title,
            "conditions": self.conditions,
            "columns": self.columns.iter().map(|c| c.key.as_str()).collect::<Vec<_>>(),
            "rows": rows,
            "paper": comparisons,
            "notes": self.notes,
        }))
    }

    fn csv(&self) -> String {
        let mut out = String::new();
        let keys: Vec<&str> = self.columns.iter().map(|c| c.key.as_str()).collect();
        let _ = writeln!(out, "{}", keys.join(","));
        for row in &self.rows {
            let fields: Vec<String> = row
                .iter()
                .map(|cell| match cell {
                    Cell::Num(x) => x.to_string(),
                    Cell::Text(t) if t.contains([',', '"']) => {
                        format!("\"{}\"", t.replace('"', "\"\""))
                    }
                    Cell::Text(t) => t.clone(),
                    Cell::Blank => String::new(),
                })
                .collect();
            let _ = writeln!(out, "{}", fields.join(","));
        }
        out
    }

    fn text(&self) -> String {
        let cells: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|row| {
                self.columns
                    .iter()
                    .zip(row)
                    .map(|(c, cell)| match cell {
                        Cell::Num(x) if x.is_finite() => format!("{x:.*}", c.decimals),
                        Cell::Num(_) | Cell::Blank => String::new(),
                        Cell::Text(t) => t.clone(),
                    })
                    .collect()
            })
            .collect();
        let widths: Vec<usize> = self
            .columns
            .iter()
            .enumerate()
            .map(|(k, c)| {
                cells
                    .iter()
                    .map(|row| row[k].chars().count())
                    .chain([c.head.chars().count()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let numeric: Vec<bool> = (0..self.columns.len())
            .map(|k| self.rows.iter().all(|r| !matches!(r[k], Cell::Text(_))))
            .collect();
        let line = |fields: &[String]| -> String {
            let mut text = String::new();
            for (k, field) in fields.iter().enumerate() {
                let pad = widths[k].saturating_sub(field.chars().count());
                if k > 0 {
                    text.push_str("  ");
                }
                if numeric[k] {
                    text.push_str(&" ".repeat(pad));
                    text.push_str(field);
                } else {
                    text.push_str(field);
                    text.push_str(&" ".repeat(pad));
                }
            }
            text.trim_end().to_owned() + "\n"
        };
        let mut out = format!(
            "Fig. {}: {}\n{}\n",
            self.number, self.title, self.conditions
        );
        let heads: Vec<String> = self.columns.iter().map(|c| c.head.clone()).collect();
        out.push_str(&line(&heads));
        for row in &cells {
            out.push_str(&line(row));
        }
        if !self.comparisons.is_empty() {
            out.push_str("the paper (for its own conditions, the default preset's) beside ours:\n");
            let width = self
                .comparisons
                .iter()
                .map(|c| c.what.chars().count())
                .max()
                .unwrap_or(0);
            for c in &self.comparisons {
                let pad = " ".repeat(width - c.what.chars().count());
                let _ = writeln!(
                    out,
                    "  {}{pad}  paper {:<8} ours {:<10.4} {}",
                    c.what,
                    trimmed(c.paper),
                    c.ours,
                    c.unit
                );
            }
        }
        for note in &self.notes {
            let _ = writeln!(out, "{note}");
        }
        trim_lines(&out)
    }
}

/// The most points `trajectory` samples.
pub const MAX_SAMPLES: usize = 100_000;

/// The flight at readout precision, sampled from the dense output.
fn trajectory(scene: &Scene, samples: usize, format: Format) -> Result<String, UsageError> {
    if !(2..=MAX_SAMPLES).contains(&samples) {
        return Err(UsageError::BadSamples { samples });
    }
    let impact = crate::model::impact::Impact::new(scene);
    let (flight, launch) = crate::model::launch(scene, &impact);
    let options = Purpose::Readout.flight_options();
    let (summary, points) = crate::model::flight::trajectory(&flight, &launch, &options, samples);
    Ok(match format {
        Format::Json => pretty(&serde_json::json!({
            "range": summary.range,
            "flight_time": summary.flight_time,
            "landed": summary.landed,
            "points": points,
        })),
        Format::Csv => {
            let mut out = String::from("time,x,y,drag_coefficient\n");
            for p in &points {
                let _ = writeln!(out, "{},{},{},{}", p.time, p.x, p.y, p.drag_coefficient);
            }
            out
        }
        Format::Text => {
            let mut out = format!(
                "flight of {:.3} m in {:.3} s{}\n{:>8} {:>9} {:>8} {:>6}\n",
                summary.range,
                summary.flight_time,
                if summary.landed {
                    ""
                } else {
                    " (still in the air at the step limit)"
                },
                "t (s)",
                "x (m)",
                "y (m)",
                "C_D"
            );
            for p in &points {
                let _ = writeln!(
                    out,
                    "{:>8.3} {:>9.3} {:>8.3} {:>6.3}",
                    p.time, p.x, p.y, p.drag_coefficient
                );
            }
            out
        }
    })
}

/// The input keys, as `--set` and the TOML presets take them.
fn keys() -> String {
    use crate::model::scene::{DRAG_KEY, KEYS};
    let defaults = Scene::default();
    let mut out = format!(
        "{:<33} {:<6} {:<7} {:<24} {:>10}  {}\n",
        "key", "symbol", "unit", "accepted", "fastball", "meaning"
    );
    for key in KEYS {
        let _ = writeln!(
            out,
            "{:<33} {:<6} {:<7} {:<24} {:>10}  {}",
            key.name,
            key.symbol,
            key.unit,
            key.bounds.to_string(),
            (key.get)(&defaults),
            key.description
        );
    }
    let (symbol, unit, meaning) = ("C_D", "", "drag model");
    let _ = writeln!(
        out,
        "{:<33} {:<6} {:<7} {:<24} {:>10}  {}",
        DRAG_KEY,
        symbol,
        unit,
        crate::model::aero::DragModel::ALL
            .map(|m| m.name())
            .join(" | "),
        defaults.drag.name(),
        meaning
    );
    let _ = writeln!(
        out,
        "\nAlso: bat.undercut must stay below r_b + r_B in size (the bat must reach the ball), and\n\
         pitch.speed must be fast enough for Eq. (3) to hold at the chosen gravity."
    );
    out
}
