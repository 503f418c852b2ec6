//! Why a command could not run: one line each, exit status 2.

use crate::analysis::figures::FigureError;
use crate::analysis::study::SweepError;
use crate::model::keys::{InputError, Key};
use crate::preset;
use crate::tui::TuiError;

use super::{MAX_GRID, MAX_STEPS, hit};

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
    #[error("--steps {steps}: must be a whole number in [1, {max}]", max = MAX_STEPS)]
    BadSteps { steps: usize },
    #[error("{flag} {value}: {} must be a finite number in {accepted}", .key.name)]
    BadBound {
        flag: &'static str,
        value: f64,
        key: &'static Key,
        /// The key's range in the units the value was given in.
        accepted: String,
    },
    /// A sweep's end that is no number, with or without a unit.
    #[error(
        "{flag} {text}: must be a number, in the swept key's range {range}, or one with a unit: {units}"
    )]
    SweepEndNotANumber {
        flag: &'static str,
        /// As typed, escaped, cut and quoted.
        text: String,
        range: String,
        units: String,
    },
    /// A sweep's end given with a unit (`--from 60mph`) that the key refuses.
    #[error("{flag}: {error}")]
    BadEnd {
        flag: &'static str,
        error: InputError,
    },
    /// More work than the command's budget; `detail` says how much and what fits.
    #[error("{flag} {text}: {detail}")]
    TooMuchWork {
        flag: &'static str,
        text: String,
        detail: String,
    },
    #[error("{flag} \"{text}\": {length} bytes, longer than any path can be ({max} bytes)")]
    TooLong {
        flag: &'static str,
        text: String,
        length: usize,
        max: usize,
    },
    /// A thread count (`RAYON_NUM_THREADS`) out of bounds, or no number.
    #[error(
        "{variable}={value:?}: must be a whole number from 0 (one thread per CPU, as when unset) to {max}",
        max = super::threads::MAX_THREADS
    )]
    BadThreadCount {
        variable: &'static str,
        /// As set, its first 40 characters.
        value: String,
    },
    /// A command line clap refused, in one line.
    #[error("{0}")]
    CommandLine(String),
    #[error("--samples {samples}: must be a whole number in [2, {max}]", max = hit::MAX_SAMPLES)]
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
    #[error(transparent)]
    Picture(#[from] crate::picture::PictureError),
    /// An SVG that cannot be written where asked: the path and why.
    #[error("--svg {path}: {reason}")]
    SvgFile { path: String, reason: String },
    #[error(
        "{command} needs a swing scene (pitch → impact → flight), and preset {preset} with these --set is a batted ball (it gives launch.*): fly it with `homerun fly` or `homerun trajectory`"
    )]
    NotASwing {
        command: &'static str,
        preset: String,
    },
    #[error(
        "{0}: a launch key makes a batted ball, which has no swing to optimise; to fly many launches use `homerun fly --batch`"
    )]
    LaunchSwept(&'static str),
    #[error("--batch {input}: {message}")]
    Batch { input: String, message: String },
    #[error("--column {mapping}: expected NAME=COLUMN (e.g. launch_speed=EV)")]
    Column { mapping: String },
    /// `calibrate FILE`'s file could not be read or fitted (named as given).
    #[error("calibrate {input}: {message}")]
    Calibrate { input: String, message: String },
    #[error("tui --savant {input}: {message}")]
    Savant { input: String, message: String },
    #[error("calibrate --save {name}: {message}")]
    CalibrateSave { name: String, message: String },
    #[error("no park named {code:?} (a code, a park's name or its city); the parks: {accepted}")]
    UnknownPark { code: String, accepted: String },
    #[error("park {query:?} could be {candidates}: give one of these codes")]
    AmbiguousPark { query: String, candidates: String },
    #[error("standard output is closed: nothing could be written (give it a file or a pipe)")]
    StdoutClosed,
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
