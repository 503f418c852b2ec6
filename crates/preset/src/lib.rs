//! Presets: TOML files ↔ [`Scene`], with errors that name the key, and a save
//! that never leaves a broken file (temporary file, then rename).
//!
//! The bundled presets (`presets/*.toml`) are compiled into the binary as
//! their TOML text, parsed when asked for as a user's file is, so `homerun`
//! works from any directory; a user's own presets live in their config
//! folder ([`config_dir`]: `$XDG_CONFIG_HOME/homerun/presets`, else
//! `$HOME/.config/homerun/presets`) or a folder given with `--presets-dir`.

use std::fs;
use std::path::{Path, PathBuf};

mod escape;
mod field;
mod file;
pub mod parks;
mod setup;

pub use escape::{
    cut, escape_cut, escape_for_terminal, escape_text, json_for_terminal, needs_escape,
};
pub use field::{FIELD_KEYS, FieldKey};
pub use file::shown;
pub use file::{FileKind, MAX_BYTES, check_dir, read_text};
use file::{check_save_target, preset_files, size_text, through};
pub use setup::{EXPLORER_SECTION, ExplorerSetup};

use model::aero::{DragModel, LiftModel};
use model::keys::{
    AIR_KEYS, ATMOSPHERE_KEYS, CALIBRATION_KEYS, HAND_KEY, InputBatch, InputError, Key,
    LAUNCH_KEYS, TEXT_KEYS, all_keys,
};
use model::launch::SceneKind;

/// The TOML table of a batted ball's launch: its presence makes one.
const LAUNCH_SECTION: &str = "launch";
use model::scene::Scene;

/// A fence to clear, drawn by the explorer (not part of the physics).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Fence {
    /// Horizontal distance from the plate (m).
    pub distance: f64,
    /// Height (m).
    pub height: f64,
}

/// Where a preset came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Source {
    Bundled,
    File(PathBuf),
}

/// A named set of inputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Preset {
    pub name: String,
    pub description: String,
    pub scene: Scene,
    pub fence: Option<Fence>,
    /// The explorer's set-up saved with it (`[explorer]`), if any.
    pub explorer: Option<ExplorerSetup>,
    pub source: Source,
}

/// Why a preset could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    #[error("{path}: malformed TOML: {message}")]
    Syntax { path: String, message: String },
    #[error("{path}: {source}")]
    Input { path: String, source: InputError },
    #[error("{path}: {key} = {value}: {expected}")]
    WrongType {
        path: String,
        key: String,
        value: String,
        expected: &'static str,
    },
    #[error("no preset named `{name}`; bundled: {bundled}{user}")]
    NotFound {
        name: String,
        bundled: String,
        user: String,
    },
    #[error("`{0}` is not a usable preset name: use letters, digits, '-' and '_'")]
    BadName(String),
    /// A FIFO, a device, a folder or a socket where a preset file should be:
    /// refused without reading it (a FIFO would block, `/dev/zero` never ends).
    #[error("{path}: not a regular file ({kind}{})", through(.link))]
    NotAFile {
        path: String,
        kind: FileKind,
        /// Where the symlink at `path` leads, if it is one.
        link: Option<String>,
    },
    /// Larger than [`MAX_BYTES`]: refused before parsing.
    #[error("{path}: {}, presets are at most 1 MiB", size_text(*.size))]
    TooBig {
        path: String,
        /// The size, if known (`None`: it grew past the cap while read).
        size: Option<u64>,
    },
    #[error("{path}: a symlink loop (too many levels of symbolic links)")]
    SymlinkLoop { path: String },
    #[error("{path}: a symlink to {target}, which does not exist")]
    DanglingLink { path: String, target: String },
    #[error("{path}: not a text file (a NUL byte at byte {offset})")]
    Binary { path: String, offset: usize },
    #[error("{path}: not UTF-8 text (an invalid byte at byte {offset})")]
    NotUtf8 { path: String, offset: usize },
    /// A park file that is not a list of parks (the message is one line).
    #[error("{path}: {message}")]
    Park { path: String, message: String },
    /// A save over a preset of the user's, without `--force`.
    #[error("preset `{name}` exists ({path}): --force to overwrite it")]
    Exists { name: String, path: String },
    /// A save under a bundled preset's name, without `--force`.
    #[error(
        "`{name}` is a bundled preset: yours would hide it (--preset {name} would load yours); --force to save it anyway"
    )]
    HidesBundled { name: String },
    /// The presets folder exists but is not a folder.
    #[error("{path}: not a folder ({kind}), so it cannot hold presets")]
    NotAFolder { path: String, kind: FileKind },
}

/// The presets shipped with homerun: (name, TOML text).
pub const BUNDLED: &[(&str, &str)] = &[
    ("fastball", include_str!("../../../presets/fastball.toml")),
    (
        "knuckleball",
        include_str!("../../../presets/knuckleball.toml"),
    ),
    ("curveball", include_str!("../../../presets/curveball.toml")),
    ("figure5", include_str!("../../../presets/figure5.toml")),
    ("mile-high", include_str!("../../../presets/mile-high.toml")),
    ("fly-ball", include_str!("../../../presets/fly-ball.toml")),
];

impl Preset {
    /// Parses preset text; `origin` names it in errors (a path or a name).
    /// Missing keys take the defaults of [`Scene::default`]; unknown keys,
    /// wrong types and out-of-range values are errors naming the key.
    pub fn parse(
        text: &str,
        name: &str,
        origin: &str,
        source: Source,
    ) -> Result<Preset, PresetError> {
        let table: toml::Table =
            text.parse()
                .map_err(|e: toml::de::Error| PresetError::Syntax {
                    path: origin.to_owned(),
                    message: syntax_message(&e),
                })?;
        let input = |source| PresetError::Input {
            path: origin.to_owned(),
            source,
        };
        let wrong = |key: &str, value: &toml::Value, expected| PresetError::WrongType {
            path: origin.to_owned(),
            key: escape_for_terminal(key),
            value: escape_for_terminal(&value.to_string()),
            expected,
        };
        let mut scene = Scene::default();
        // One file is one source: ρ or ν beside the weather is refused.
        let mut batch = InputBatch::new();
        let mut description = String::new();
        let mut fence_distance = None;
        let mut fence_height = None;
        let mut explorer = None;
        for (section, value) in &table {
            let section = section.as_str();
            if section == EXPLORER_SECTION {
                explorer = Some(ExplorerSetup::parse(value, origin)?);
                continue;
            }
            if section == "description" {
                description = value
                    .as_str()
                    .ok_or_else(|| wrong(section, value, "expected a string"))?
                    .to_owned();
                continue;
            }
            let Some(entries) = value.as_table() else {
                // `pitch = 5`: a section written as a value.
                let is_section = all_keys()
                    .map(|k| k.name)
                    .chain(TEXT_KEYS)
                    .chain(FIELD_KEYS.iter().map(|f| f.name))
                    .any(|name| name.split_once('.').is_some_and(|(s, _)| s == section));
                if is_section {
                    return Err(wrong(
                        section,
                        value,
                        "a section, not a value: expected a table, its keys under a [header] line of its own name",
                    ));
                }
                return Err(input(unknown(&escape_for_terminal(section))));
            };
            // A `[launch]` table makes a batted ball, even an empty one
            // (every launch value then from the swing's impact).
            if section == LAUNCH_SECTION {
                scene.set_kind(SceneKind::BattedBall);
            }
            for (name, value) in entries {
                let key = format!("{section}.{name}");
                if TEXT_KEYS.contains(&key.as_str()) {
                    let expected = if key == HAND_KEY {
                        "expected \"right\" or \"left\" in quotes"
                    } else {
                        "expected a model name in quotes"
                    };
                    let text = value.as_str().ok_or_else(|| wrong(&key, value, expected))?;
                    // A name too long to be one is shown cut (the error
                    // quotes it, escaping control characters).
                    let shown = cut(text, 80);
                    batch.set_text(&mut scene, &key, &shown).map_err(input)?;
                    continue;
                }
                // An unknown key is named escaped, as it cannot be printed.
                let named = |e| {
                    let shown = escape_for_terminal(&key);
                    input(if shown == key { e } else { unknown(&shown) })
                };
                let field = FIELD_KEYS.iter().find(|f| f.name == key);
                let number = match value {
                    toml::Value::Float(number) => *number,
                    toml::Value::Integer(number) => *number as f64,
                    // A number with its unit, "103mph", as `--set` takes it.
                    toml::Value::String(text) => match field {
                        Some(field) => field.read(text).map_err(input)?,
                        None => {
                            batch.set_text(&mut scene, &key, text).map_err(named)?;
                            continue;
                        }
                    },
                    _ => {
                        return Err(wrong(
                            &key,
                            value,
                            "expected a number, or a number and its unit in quotes (\"103mph\")",
                        ));
                    }
                };
                match key.as_str() {
                    k if k == FIELD_KEYS[0].name => fence_distance = Some(number),
                    k if k == FIELD_KEYS[1].name => fence_height = Some(number),
                    _ => batch.set(&mut scene, &key, number).map_err(named)?,
                }
            }
        }
        scene.validate().map_err(input)?;
        let fence = match (fence_distance, fence_height) {
            (None, None) => None,
            (distance, height) => {
                let fence = Fence {
                    distance: distance.unwrap_or(FIELD_KEYS[0].default),
                    height: height.unwrap_or(FIELD_KEYS[1].default),
                };
                for field in &FIELD_KEYS {
                    let value = (field.get)(&fence);
                    if !field.bounds.contains(value) {
                        return Err(PresetError::WrongType {
                            path: origin.to_owned(),
                            key: field.name.to_owned(),
                            value: value.to_string(),
                            expected: "must be a finite number in (0, 1000] m for the distance, (0, 100] m for the height",
                        });
                    }
                }
                Some(fence)
            }
        };
        Ok(Preset {
            name: name.to_owned(),
            description,
            scene,
            fence,
            explorer,
            source,
        })
    }

    /// Reads a preset file, safely (see [`read_text`]).
    pub fn read(path: &Path) -> Result<Preset, PresetError> {
        let origin = shown(path);
        let text = read_text(path)?;
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        Preset::parse(&text, &name, &origin, Source::File(path.to_owned()))
    }

    /// The TOML text of this preset: every key, with the paper's symbol and
    /// unit in a comment, so a saved file documents itself.
    pub fn to_toml(&self) -> String {
        let mut out = String::new();
        if !self.description.is_empty() {
            out += &format!(
                "description = {}\n",
                toml::Value::from(self.description.clone())
            );
        }
        // Every input, grouped by section: the weather when it set ρ and ν,
        // else ρ and ν themselves (never both: that would be refused).
        let weather = self.scene.environment.atmosphere().is_some();
        let skipped: &[&str] = if weather { &AIR_KEYS } else { &ATMOSPHERE_KEYS };
        // A swing writes no `[launch]` (it would make a batted ball); a
        // batted ball writes the launch values it gives, all of them if it
        // gives none (so that it reads back as a batted ball).
        let launch = self.scene.launch;
        let given = launch.values();
        let launch_written = |name: &str| match self.scene.kind {
            SceneKind::Swing => false,
            SceneKind::BattedBall if launch.is_empty() => true,
            SceneKind::BattedBall => LAUNCH_KEYS
                .iter()
                .zip(given)
                .any(|(k, v)| k.name == name && v.is_some()),
        };
        // A calibration factor is written only when it scales (1: as
        // published), the tangential restitution only when the contact
        // springs back (0: the paper's rolling), the bat's lead only when
        // the bat leads (0: the paper's square bat).
        let unscaled = |k: &Key| {
            let value = (k.get)(&self.scene);
            (CALIBRATION_KEYS.iter().any(|c| c.name == k.name) && value == 1.0)
                || (["bat.tangential_restitution", "bat.lead"].contains(&k.name) && value == 0.0)
        };
        let keys: Vec<&Key> = all_keys()
            .filter(|k| !skipped.contains(&k.name) && !unscaled(k))
            .filter(|k| !LAUNCH_KEYS.iter().any(|l| l.name == k.name) || launch_written(k.name))
            .collect();
        let mut sections: Vec<&str> = Vec::new();
        for key in &keys {
            let head = key.name.split_once('.').expect("keys are dotted").0;
            if !sections.contains(&head) {
                sections.push(head);
            }
        }
        for head in sections {
            out += &format!("\n[{head}]\n");
            if head == "model" {
                // A model the user chose is written; one that follows the
                // scene's kind is left to follow it (commented out).
                let (drag, lift) = (self.scene.drag, self.scene.lift);
                let chosen = self.scene.chosen;
                out += &format!(
                    "{}drag = \"{drag}\"  # {}; one of: {}\n",
                    if chosen.drag { "" } else { "# " },
                    drag.description(),
                    DragModel::ALL.map(DragModel::name).join(", ")
                );
                out += &format!(
                    "{}lift = \"{lift}\"  # {}; one of: {}\n",
                    if chosen.lift { "" } else { "# " },
                    lift.description(),
                    LiftModel::ALL.map(LiftModel::name).join(", ")
                );
            }
            if HAND_KEY
                .split_once('.')
                .is_some_and(|(section, _)| section == head)
            {
                out += &format!(
                    "hand = \"{}\"  # the batter's side: right, left\n",
                    self.scene.bat.hand
                );
            }
            for key in keys
                .iter()
                .filter(|k| k.name.starts_with(&format!("{head}.")))
            {
                let name = &key.name[head.len() + 1..];
                let unit = if key.unit.is_empty() {
                    String::new()
                } else {
                    format!(" ({})", key.unit)
                };
                out += &format!(
                    "{name} = {}  # {}{unit}: {}\n",
                    toml::Value::Float((key.get)(&self.scene)),
                    key.symbol,
                    key.description
                );
            }
        }
        if let Some(fence) = self.fence {
            out += &format!(
                "\n[field]\nfence_distance = {}  # m from the plate\nfence_height = {}  # m\n",
                toml::Value::Float(fence.distance),
                toml::Value::Float(fence.height)
            );
        }
        if let Some(setup) = &self.explorer {
            out += &setup.to_toml();
        }
        out
    }

    /// Writes the preset as `dir/name.toml`: first to a temporary file in the
    /// same folder, flushed to disk, then renamed over the target, so that a
    /// crash or a full disk never leaves a half-written preset. A target that
    /// exists and is not a regular file (a FIFO, a device, a folder) is
    /// refused, as reading refuses it; so is a scene that reading refuses,
    /// and a link that leads out of `dir` ([`crate::atomic_file::resolved`]).
    /// Without `force`, a name the user's presets already hold, or a bundled
    /// preset's (which the file would hide), is refused.
    pub fn save(&self, dir: &Path, force: bool) -> Result<PathBuf, PresetError> {
        check_name(&self.name)?;
        // Never write what `load` would refuse.
        self.scene.validate().map_err(|source| PresetError::Input {
            path: format!("{}.toml", self.name),
            source,
        })?;
        let io = |path: &Path| {
            let path = path.display().to_string();
            move |source| PresetError::Io { path, source }
        };
        fs::create_dir_all(dir).map_err(io(dir))?;
        let target = check_save(&self.name, dir, force)?;
        crate::atomic_file::replace(&target, self.to_toml().as_bytes()).map_err(io(&target))?;
        Ok(target)
    }
}

/// Whether a preset can be saved as `name` in `dir`, before any work is
/// done for it: the name is usable, the target is a regular file or a new
/// name, not a link out of `dir`, and, without `force`, neither one of the
/// user's presets nor a bundled one's name. The target's path.
pub fn check_save(name: &str, dir: &Path, force: bool) -> Result<PathBuf, PresetError> {
    check_name(name)?;
    let target = dir.join(format!("{name}.toml"));
    check_save_target(&target)?;
    if !force {
        if let Some(path) = user_file(name, Some(dir)) {
            return Err(PresetError::Exists {
                name: name.to_owned(),
                path: shown(&path),
            });
        }
        if is_bundled(name) {
            return Err(PresetError::HidesBundled {
                name: name.to_owned(),
            });
        }
    }
    crate::atomic_file::resolved(&target).map_err(|source| PresetError::Io {
        path: shown(&target),
        source,
    })?;
    Ok(target)
}

/// A TOML error on one line, as the toml crate words it, with the quoted
/// source line escaped and cut (a hostile file may hold a megabyte on one
/// line, or terminal escapes), and the caret line dropped if it was cut.
fn syntax_message(error: &toml::de::Error) -> String {
    error
        .to_string()
        .trim()
        .split('\n')
        .filter_map(|line| {
            let cut = escape_cut(line, 200);
            let pointer = |c| matches!(c, ' ' | '|' | '^' | '…');
            (cut == line || !cut.chars().all(pointer)).then_some(cut)
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The error for a key that is not an input. A quoted top-level key that
/// names one (`"bat.speed" = 3`, not a `[bat]` table) is shown quoted, as
/// written.
fn unknown(key: &str) -> InputError {
    match Scene::key(key) {
        Err(e) => e,
        Ok(_) => unknown(&format!("\"{key}\"")),
    }
}

fn check_name(name: &str) -> Result<(), PresetError> {
    let ok = !name.is_empty()
        && name.len() <= 64
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
    if ok {
        Ok(())
    } else {
        Err(PresetError::BadName(escape_for_terminal(name)))
    }
}

/// The user's preset folder: `presets` in [`config_dir`].
pub fn user_dir() -> Option<PathBuf> {
    config_dir().map(|d| d.join("presets"))
}

/// homerun's config folder, from the environment alone (no lookup of the
/// user in the system's databases, which a process of an unknown user or
/// without NSS could not do): `$XDG_CONFIG_HOME/homerun` if that is an
/// absolute path (as the XDG spec asks), else `$HOME/.config/homerun`;
/// `None` when neither is set: then there is no user folder, and every
/// command works on the bundled presets and parks.
pub fn config_dir() -> Option<PathBuf> {
    let absolute = |name| {
        let path = PathBuf::from(std::env::var_os(name)?);
        path.is_absolute().then_some(path)
    };
    let base = absolute("XDG_CONFIG_HOME").or_else(|| Some(absolute("HOME")?.join(".config")))?;
    Some(base.join("homerun"))
}

/// Why a preset cannot be saved without `--presets-dir`: one line.
pub const NO_FOLDER: &str =
    "no presets folder: neither XDG_CONFIG_HOME nor HOME is set; pass --presets-dir DIR";

/// The bundled presets, parsed.
pub fn bundled() -> Vec<Preset> {
    BUNDLED
        .iter()
        .map(|(name, _)| match bundled_preset(name) {
            Some(Ok(preset)) => preset,
            _ => panic!("bundled preset {name} is valid (tested)"),
        })
        .collect()
}

/// The bundled preset `name`, its text parsed and checked as a file's is;
/// `None` if there is none of that name.
fn bundled_preset(name: &str) -> Option<Result<Preset, PresetError>> {
    let (name, text) = BUNDLED.iter().find(|(n, _)| *n == name)?;
    let origin = format!("presets/{name}.toml");
    Some(Preset::parse(text, name, &origin, Source::Bundled))
}

/// Every preset available: bundled first, then each `*.toml` in `dir`, each
/// file read once with [`read_text`] (so nothing in the folder can block or
/// flood it). A broken file is returned as an error beside the others, not
/// fatal; so is a `dir` that exists but is not a folder (see [`check_dir`]).
/// A missing `dir` holds no presets.
pub fn list(dir: Option<&Path>) -> Vec<Result<Preset, PresetError>> {
    let mut all: Vec<_> = bundled().into_iter().map(Ok).collect();
    if let Some(dir) = dir {
        match preset_files(dir) {
            Ok(paths) => all.extend(paths.iter().map(|p| Preset::read(p))),
            Err(e) => all.push(Err(e)),
        }
    }
    all
}

/// Whether `name` is one of the bundled presets.
pub fn is_bundled(name: &str) -> bool {
    BUNDLED.iter().any(|(n, _)| *n == name)
}

/// The user's file that `load` reads for `name` in `dir`, if there is one:
/// when names collide, the user's file wins over a bundled preset (so a
/// bundled preset listed beside it is hidden from `--preset NAME`).
pub fn user_file(name: &str, dir: Option<&Path>) -> Option<PathBuf> {
    let candidate = dir?.join(format!("{name}.toml"));
    fs::symlink_metadata(&candidate)
        .is_ok()
        .then_some(candidate)
}

/// A name to save under that hides nothing and overwrites nothing: `base`
/// itself if it is neither bundled nor taken in `dir`, else `base-1`,
/// `base-2`, … (a trailing `-N` on `base` is counted on from).
pub fn fresh_name(base: &str, dir: Option<&Path>) -> String {
    let free = |name: &str| !is_bundled(name) && user_file(name, dir).is_none();
    if free(base) {
        return base.to_owned();
    }
    let (stem, first) = match base.rsplit_once('-') {
        Some((stem, n)) if !stem.is_empty() && n.parse::<u32>().is_ok() => {
            (stem, n.parse::<u32>().unwrap_or(0) + 1)
        }
        _ => (base, 1),
    };
    (first..first + 10_000)
        .map(|n| format!("{stem}-{n}"))
        .find(|name| free(name))
        .unwrap_or_else(|| format!("{stem}-new"))
}

/// Finds a preset by name (user folder first, so a user can shadow a bundled
/// one: see [`user_file`]) or, if `spec` looks like a path, reads that file. A name is looked up
/// in `dir` only if `dir` is usable ([`check_dir`]); any file there with that
/// name is read, so a broken one is reported rather than skipped.
pub fn load(spec: &str, dir: Option<&Path>) -> Result<Preset, PresetError> {
    let as_path = Path::new(spec);
    if spec.ends_with(".toml") || spec.contains(std::path::MAIN_SEPARATOR) {
        return Preset::read(as_path);
    }
    if let Some(file) = user_file(spec, check_dir(dir)?) {
        return Preset::read(&file);
    }
    if let Some(preset) = bundled_preset(spec) {
        return preset;
    }
    Err(PresetError::NotFound {
        name: escape_for_terminal(spec),
        bundled: BUNDLED
            .iter()
            .map(|(n, _)| *n)
            .collect::<Vec<_>>()
            .join(", "),
        user: dir
            .map(|d| format!("; or a file in {}", shown(d)))
            .unwrap_or_default(),
    })
}

pub mod atomic_file;
pub mod compact;
#[cfg(test)]
mod tests;
