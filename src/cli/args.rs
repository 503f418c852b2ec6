//! The command line's words: the global flags, the commands and their
//! arguments, as clap derives them. What each command does is in its own
//! file; [`super::run`] dispatches.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use crate::tui::theme::Background;
use crate::units::UnitSystem;

#[derive(Parser, Debug)]
#[command(
    name = "homerun",
    version,
    about = "The physics of hitting a baseball as far as possible (Sawicki, Hubbard & Stronge 2003).",
    long_about = "The physics of hitting a baseball as far as possible, after Sawicki, Hubbard & Stronge, \
                  \"How to hit home runs\", Am. J. Phys. 71 (2003).\n\n\
                  With no command, opens the explorer (a terminal app); the commands below print numbers.\n\n\
                  RAYON_NUM_THREADS sets how many threads share the work: a whole number from 0 (one per CPU, \
                  as when it is unset) to 256; any other value is refused.",
    after_long_help = UNITS_HELP
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Folder for the user's own presets (default: $XDG_CONFIG_HOME/homerun/presets).
    #[arg(long, global = true, value_name = "DIR")]
    pub presets_dir: Option<PathBuf>,
    /// Folder for the user's own parks (default: $XDG_CONFIG_HOME/homerun/parks).
    #[arg(long, global = true, value_name = "DIR")]
    pub parks_dir: Option<PathBuf>,
    /// Units printed, and of a bare number typed: si (default) or imperial (ft, mph, °, rpm).
    #[arg(
        long,
        global = true,
        value_name = "SYSTEM",
        default_value = "si",
        hide_default_value = true
    )]
    pub units: UnitSystem,
    /// The explorer's colours: dark or light, for the terminal's background
    /// (default: from COLORFGBG, else dark). NO_COLOR turns colour off.
    #[arg(long, value_name = "THEME")]
    pub theme: Option<Background>,
}

/// What `--units` does, said once, under `homerun --help` (every command
/// takes `--units`, and its own help gives one line).
pub const UNITS_HELP: &str = "Units: --units imperial prints the text, CSV and SVG pictures in ft, in, mph, °, rpm, °F, inHg and oz \
     instead of si's m, m/s, rad, rad/s, °C, hPa and kg. What you see is what you type: a bare number \
     in --set, sweep's --from/--to and surface's --undercut/--swing-angle is in the unit printed \
     (--units imperial --set launch.speed=100 is 100 mph), and a number with a unit takes its unit \
     (103mph, 28deg, 2500rpm, 400ft, 70F). JSON is always SI, and so is a bare number in a preset \
     file or a batch column named by its key (a file means what it says, whatever the flag). \
     The explorer starts in these units (its `u` switches).";

// Which preset to start from, and changes to it. (Not a doc comment: it
// would become the about of each command that flattens these; see
// [`Command`].)
#[derive(Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// A preset name (see `homerun presets`) or a path to a TOML file.
    #[arg(long, short, value_name = "P", default_value = "fastball")]
    pub preset: String,
    /// Change one input, with the same keys as the TOML (e.g. bat.speed=32).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
}

/// The commands. Each is built (its arguments made) only when the command
/// line names it: building all fourteen took ~0.15 ms of every start.
/// Building adds a command's arguments after its about and the global
/// arguments, so no struct it flattens may carry a doc comment (it would
/// replace the about); tests/help.rs holds each command, built alone, to the
/// command built in the whole tree at once.
#[derive(Subcommand, Debug)]
#[command(defer = true)]
pub enum Command {
    /// One swing: pitch, every impact quantity, flight summary; --batch solves
    /// the swing behind each tracked ball of a Savant export.
    Hit {
        #[command(flatten)]
        scene: SceneArgs,
        /// Print JSON instead of text (with --batch: one JSON object per line).
        #[arg(long)]
        json: bool,
        /// A Savant export with bat tracking (`-` for stdin): each row's undercut,
        /// bat speed at the contact (or swing angle) and bat direction solved so
        /// that the paper's impact gives its measured launch, the bat tilted by the
        /// row's swing_path_tilt or the league's 32°, then flown as `fly --batch`
        /// flies it (docs/bat-tracking.md).
        #[arg(long, value_name = "FILE")]
        batch: Option<String>,
        /// With --batch: the park every row is taken to, as `fly --park` [default:
        /// each row's home_team].
        #[arg(long, value_name = "PARK", requires = "batch")]
        park: Option<String>,
        /// With --batch: add the summary's tables to its lines on stderr.
        #[arg(long, requires = "batch")]
        summary: bool,
        /// With --batch: read the file's COLUMN as NAME (a column name that
        /// --batch --help lists, or a key of `homerun keys` with the unit of
        /// its bare numbers, COLUMN:UNIT), e.g. --column launch_speed=EV,
        /// --column launch_speed=EV:km/h or --column
        /// environment.temperature=temp:F; repeatable.
        #[arg(long, value_name = "NAME=COLUMN[:UNIT]", requires = "batch")]
        column: Vec<String>,
        /// With --batch: also write the summary as JSON to FILE (atomically),
        /// its numbers in the units of --units.
        #[arg(long, value_name = "FILE", requires = "batch")]
        summary_file: Option<PathBuf>,
        /// With --batch: copy these input columns into the output, after the others.
        #[arg(long, value_name = "COLS", requires = "batch")]
        keep: Option<String>,
    },
    /// The batted ball's path: time, x, y and C_D, sampled evenly in time.
    Trajectory {
        #[command(flatten)]
        scene: SceneArgs,
        /// How many points, launch and landing included (2 to 100000).
        #[arg(long, default_value_t = 51, allow_negative_numbers = true)]
        samples: usize,
        /// Print JSON instead of text: range, flight time, landed, the points.
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// Print CSV instead of text: a header, then one line per point.
        #[arg(long)]
        csv: bool,
        /// Write the picture as SVG to FILE instead (atomically; "wrote FILE" on stderr).
        #[arg(long, value_name = "FILE", conflicts_with_all = ["json", "csv"])]
        svg: Option<PathBuf>,
    },
    /// A batted ball's flight from its launch (launch.speed, .angle, .spin), or
    /// a swing's launch and flight; --batch flies one launch per CSV row.
    Fly {
        #[command(flatten)]
        scene: SceneArgs,
        /// A CSV of launches, one flight per row (`-` for stdin); `--help` lists the columns read.
        #[arg(long, value_name = "FILE", long_help = batch::columns_help())]
        batch: Option<String>,
        /// Print JSON instead of text (with --batch: one JSON object per line).
        #[arg(long)]
        json: bool,
        /// The park whose fence the ball meets, and whose air it flies in unless
        /// air or weather keys are given: a code (Savant's home_team), a name or a
        /// city, any case (BOS, fenway, "Fenway Park", boston; `homerun parks` lists
        /// them) [default: the generic fence, the same in every direction; with
        /// --batch: each row's home_team].
        #[arg(long, value_name = "PARK")]
        park: Option<String>,
        /// Also list every park with the outcome and margin there; with --batch
        /// two more columns a park (`<CODE>_outcome`, `<CODE>_margin`). The help
        /// is `help`'s text, where `<CODE>` is written as it is, not as HTML.
        #[arg(
            long,
            help = "Also list every park with the outcome and margin there. With --batch: two \
                    more columns a park, <CODE>_outcome and <CODE>_margin (_margin_ft with \
                    --units imperial), after the others and before --keep's; in JSON an \
                    `all_parks` list of {park, outcome, margin} (SI)"
        )]
        all_parks: bool,
        /// Each park in its own air: the default, kept so that older
        /// command lines still run.
        #[arg(long, hide = true, conflicts_with = "one_flight")]
        own_air: bool,
        /// Judge every park on the one flight, in its air (--park's, each
        /// row's park's, or the scene's), instead of each park in its own air
        /// (the standard air at its elevation, the weather given kept); the
        /// parks line and a batch's summary say so.
        #[arg(long)]
        one_flight: bool,
        /// With --batch: add the summary's tables to its lines on stderr: the
        /// error against hit_distance_sc by launch-angle band and by kind of
        /// ball, and the swings by launch angle (stdout holds only the rows).
        #[arg(long, requires = "batch")]
        summary: bool,
        /// With --batch: read the file's COLUMN as NAME (a column name that
        /// --batch --help lists, or a key of `homerun keys` with the unit of
        /// its bare numbers, COLUMN:UNIT), e.g. --column launch_speed=EV,
        /// --column launch_speed=EV:km/h or --column
        /// environment.temperature=temp:F; repeatable.
        #[arg(long, value_name = "NAME=COLUMN[:UNIT]", requires = "batch")]
        column: Vec<String>,
        /// With --batch: also write the summary as JSON to FILE (atomically),
        /// its numbers in the units of --units.
        #[arg(long, value_name = "FILE", requires = "batch")]
        summary_file: Option<PathBuf>,

        /// With --batch: copy these input columns into the output, after the
        /// others (comma-separated, e.g. player_name,game_date,events).
        #[arg(long, value_name = "COLS", requires = "batch")]
        keep: Option<String>,
        /// With --batch: what Savant's spray angle (from hc_x, hc_y) is: `landing`,
        /// where the ball came down (the launch direction is solved so that the
        /// flight lands there), or `launch`, the launch direction itself (the
        /// recipe of pybaseball's calculator).
        #[arg(
            long,
            value_name = "WHAT",
            default_value = "landing",
            requires = "batch"
        )]
        spray: SprayArg,
        /// Where the spin comes from. With --batch, each row's: `nathan`
        /// (the default), Nathan's relation from its launch angle and
        /// direction; `swing`, the impact of its swing solved from bat
        /// tracking (bat_speed and the pitch's kinematics, as `hit --batch`),
        /// and Nathan's relation where that swing is missing or not solved.
        /// One ball: `swing` (the default), the preset's swing's impact where
        /// launch.spin is not given; `nathan`, Nathan's relation at its
        /// launch angle and direction for a bat.hand batter, as a batch row
        /// without a spin flies.
        #[arg(long, value_name = "FROM")]
        spin: Option<SpinArg>,
    },
    /// Fit model.drag_scale (and model.lift_scale, given hang_time or apex
    /// columns) to the measured distances of a CSV of flights, as `fly --batch`
    /// reads them (a Savant export: hit_distance_sc).
    Calibrate {
        /// The CSV (`-` for stdin): launches and hit_distance_sc (ft); hang_time (s)
        /// or apex (ft) fit the lift, else the distances below and above the
        /// median launch angle do.
        file: String,
        #[command(flatten)]
        scene: SceneArgs,
        /// The park every row is at, by code, name or city [default: each row's home_team].
        #[arg(long, value_name = "PARK")]
        park: Option<String>,
        /// What Savant's spray angle is (as `fly --batch --spray`).
        #[arg(long, value_name = "WHAT", default_value = "landing")]
        spray: SprayArg,
        /// Fit each group of rows apart, one line a group (`month`, `season` or
        /// a column); with --save NAME, one preset a group (`NAME-<group>`).
        /// The help is `help`'s text, where `<group>` is written as it is.
        #[arg(
            long,
            value_name = "COLUMN",
            help = "Fit each group of rows apart, one line a group: by a column's value \
                    (home_team, …), `month` (game_date's year and month, from YYYY-MM-DD or \
                    M/D/YYYY) or `season` (game_year or season). With --save NAME, one preset a \
                    group: NAME-<group>"
        )]
        by: Option<String>,
        /// Read the file's COLUMN as NAME (as fly --batch --column); repeatable.
        #[arg(long, value_name = "NAME=COLUMN")]
        column: Vec<String>,
        /// Save the preset with the factors found as NAME in the presets folder.
        #[arg(long, value_name = "NAME")]
        save: Option<String>,
        /// With --save: overwrite a preset of that name, hide a bundled one,
        /// or save a factor that ended at its bound.
        #[arg(long, requires = "save")]
        force: bool,
        /// Fit the drag alone (model.drag_scale), the lift left as it is.
        #[arg(long, conflicts_with = "impact")]
        drag_only: bool,
        /// Where each row's spin comes from (as `fly --batch --spin`): the
        /// flights fitted are the ones that command flies.
        #[arg(
            long,
            value_name = "FROM",
            default_value = "nathan",
            conflicts_with = "impact"
        )]
        spin: SpinArg,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Fit the impact instead: the bat's effective mass (bat.effective_mass) for
        /// which only 1 % of the file's tracked swings beat the model's most
        /// q = (EV - V_bat)/(V_pitch + V_bat) at their own pitch and bat speed; then
        /// the two compared by approach speed (docs/bat-tracking.md).
        #[arg(long, conflicts_with = "by")]
        impact: bool,
    },
    /// Every input key: symbol, unit, accepted range and the fastball's value.
    Keys,
    /// The undercut and swing angle that maximise range (§II.E); with --park,
    /// the swing that clears that park's wall by the most.
    Optimize {
        #[command(flatten)]
        scene: SceneArgs,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Maximise the margin over this park's wall instead, searching the bat's
        /// direction too, in the park's air as `fly --park` flies (a Savant
        /// home_team code; `homerun parks` lists them).
        #[arg(long, value_name = "CODE")]
        park: Option<String>,
        /// With --park: hold KEY at the scene's value (bat.undercut,
        /// bat.swing_angle or bat.direction; repeatable).
        #[arg(long, value_name = "KEY", requires = "park")]
        fix: Vec<String>,
    },
    /// Table II: the paper's numbers beside ours, with the differences.
    Table2 {
        /// Print JSON instead of text: one object per pitch.
        #[arg(long)]
        json: bool,
    },
    /// The optimum (undercut, swing angle, range) against any numeric key.
    Sweep {
        /// The key to sweep, e.g. bat.speed.
        key: String,
        /// The first value: a bare number is in the unit shown (SI, or imperial with
        /// --units imperial); or give a unit of the key's quantity, e.g. 60mph.
        #[arg(long, allow_hyphen_values = true)]
        from: String,
        /// The last value, read as --from is.
        #[arg(long, allow_hyphen_values = true)]
        to: String,
        /// How many values, both ends included (1 to 200).
        #[arg(long, default_value_t = 11, allow_negative_numbers = true)]
        steps: usize,
        #[command(flatten)]
        scene: SceneArgs,
        /// Print JSON instead of text: the key, its unit, one object per point.
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// Print CSV instead of text: a header, then one line per point.
        #[arg(long)]
        csv: bool,
    },
    /// The range over a grid of (undercut, swing angle), as in Fig. 7.
    Surface {
        #[command(flatten)]
        scene: SceneArgs,
        /// Undercut window A..B (m; in with --units imperial) [default: 0..0.05 m].
        #[arg(long, value_name = "A..B", allow_hyphen_values = true)]
        undercut: Option<String>,
        /// Swing-angle window C..D (rad; ° with --units imperial) [default: -0.6..1.0 rad].
        #[arg(long, value_name = "C..D", allow_hyphen_values = true)]
        swing_angle: Option<String>,
        /// Columns (undercut) x rows (swing angle).
        #[arg(long, value_name = "NxM", default_value = "21x17")]
        grid: String,
        /// Print JSON instead of text: the windows, rows of ranges, which cells landed, the best.
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// Print CSV instead of text: one line per cell (undercut, swing angle, range, landed).
        #[arg(long)]
        csv: bool,
        /// Write the picture as SVG to FILE instead (atomically; "wrote FILE" on stderr).
        #[arg(long, value_name = "FILE", conflicts_with_all = ["json", "csv"])]
        svg: Option<PathBuf>,
    },
    /// The presets and what they are.
    Presets,
    /// The ballparks: code, name, elevation, distances and tallest wall; with
    /// CODE, that park's fence every 5° and at each change of wall height.
    Parks {
        /// A park: its code (Baseball Savant's home_team, e.g. BOS), name or city.
        code: Option<String>,
        /// Print JSON (SI: metres, radians from centre field, + toward right field).
        #[arg(long)]
        json: bool,
        /// Draw the park's outline with its wall heights as SVG to FILE instead
        /// (atomically; "wrote FILE" on stderr).
        #[arg(long, value_name = "FILE", requires = "code", conflicts_with = "json")]
        svg: Option<PathBuf>,
    },
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
        /// Write the picture as SVG to FILE instead (atomically; "wrote FILE" on stderr).
        #[arg(long, value_name = "FILE", conflicts_with_all = ["json", "csv"])]
        svg: Option<PathBuf>,
    },
    /// Speed against error on this machine: the work–precision tables.
    Bench {
        /// Print JSON, with the tables' field names.
        #[arg(long)]
        json: bool,
        /// A reduced version (seconds).
        #[arg(long)]
        quick: bool,
        /// Write the work–precision diagram as SVG to FILE instead (atomically; "wrote FILE" on stderr).
        #[arg(long, value_name = "FILE", conflicts_with = "json")]
        svg: Option<PathBuf>,
    },
    /// Open the explorer (the default with no command).
    Tui {
        /// The preset to start from.
        #[arg(long, short, value_name = "P", default_value = "fastball")]
        preset: String,
        /// A Savant export with bat tracking: each row's swing solved (as `hit
        /// --batch`), and a picker of them (batter, date, measured launch) to open
        /// one as the scene.
        #[arg(long, value_name = "FILE")]
        savant: Option<String>,
        /// With --savant: read the file's COLUMN as NAME, as fly --batch
        /// --column does (e.g. --column launch_speed=EV); repeatable.
        #[arg(long, value_name = "NAME=COLUMN[:UNIT]", requires = "savant")]
        column: Vec<String>,
        /// The colours: dark or light, for the terminal's background
        /// (default: from COLORFGBG, else dark). NO_COLOR turns colour off.
        #[arg(long, value_name = "THEME")]
        theme: Option<Background>,
    },
}

/// Where a batch row's spin comes from (`fly --batch --spin`).
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SpinArg {
    /// Nathan's relation from the launch angle and direction.
    #[default]
    Nathan,
    /// The impact of the row's swing, solved from bat tracking.
    Swing,
}

/// What Savant's spray angle is taken to be (`fly --batch --spray`).
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SprayArg {
    /// Where the ball came down: the launch direction is solved.
    #[default]
    Landing,
    /// The launch direction.
    Launch,
}

impl From<SprayArg> for crate::analysis::savant::Spray {
    fn from(spray: SprayArg) -> Self {
        match spray {
            SprayArg::Landing => crate::analysis::savant::Spray::Landing,
            SprayArg::Launch => crate::analysis::savant::Spray::Launch,
        }
    }
}
