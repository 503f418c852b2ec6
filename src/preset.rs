//! Presets: TOML files ↔ [`Scene`], with errors that name the key, and a save
//! that never leaves a broken file (temporary file, then rename).
//!
//! The bundled presets (`presets/*.toml`) are compiled into the binary, so
//! `homerun` works from any directory; a user's own presets live in their
//! config folder (`$XDG_CONFIG_HOME/homerun/presets`) or a folder given with
//! `--presets-dir`.

use std::fs;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use crate::model::aero::{DragModel, UnknownModel};
use crate::model::keys::{DRAG_KEY, InputError, KEYS};
use crate::model::scene::Scene;

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
    /// The presets folder exists but is not a folder.
    #[error("{path}: not a folder ({kind}), so it cannot hold presets")]
    NotAFolder { path: String, kind: FileKind },
}

/// What a path is, for messages: "not a regular file (a FIFO)".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    File,
    Folder,
    Fifo,
    CharDevice,
    BlockDevice,
    Socket,
    Other,
}

impl FileKind {
    /// The kind of `file_type` (of metadata that followed symlinks).
    pub fn of(file_type: fs::FileType) -> FileKind {
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if file_type.is_fifo() {
                return FileKind::Fifo;
            }
            if file_type.is_char_device() {
                return FileKind::CharDevice;
            }
            if file_type.is_block_device() {
                return FileKind::BlockDevice;
            }
            if file_type.is_socket() {
                return FileKind::Socket;
            }
        }
        if file_type.is_file() {
            FileKind::File
        } else if file_type.is_dir() {
            FileKind::Folder
        } else {
            FileKind::Other
        }
    }
}

impl std::fmt::Display for FileKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FileKind::File => "a regular file",
            FileKind::Folder => "a folder",
            FileKind::Fifo => "a FIFO",
            FileKind::CharDevice => "a character device",
            FileKind::BlockDevice => "a block device",
            FileKind::Socket => "a socket",
            FileKind::Other => "an unknown kind of file",
        })
    }
}

fn through(link: &Option<String>) -> String {
    link.as_ref()
        .map(|target| format!(", through a symlink to {target}"))
        .unwrap_or_default()
}

fn size_text(size: Option<u64>) -> String {
    match size {
        Some(bytes) if bytes >= 10 << 20 => format!("{} MiB", bytes >> 20),
        Some(bytes) => format!("{bytes} bytes"),
        None => "more than 1 MiB".to_owned(),
    }
}

/// The largest preset file read, in bytes: a preset is a few hundred bytes,
/// and anything larger is refused before it costs memory or parsing time.
pub const MAX_BYTES: u64 = 1 << 20;

/// The presets shipped with homerun: (name, TOML text).
pub const BUNDLED: &[(&str, &str)] = &[
    ("fastball", include_str!("../presets/fastball.toml")),
    ("knuckleball", include_str!("../presets/knuckleball.toml")),
    ("curveball", include_str!("../presets/curveball.toml")),
    ("figure5", include_str!("../presets/figure5.toml")),
];

const FENCE_DISTANCE: &str = "field.fence_distance";
const FENCE_HEIGHT: &str = "field.fence_height";

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
        let mut description = String::new();
        let mut fence_distance = None;
        let mut fence_height = None;
        for (section, value) in &table {
            if section == "description" {
                description = value
                    .as_str()
                    .ok_or_else(|| wrong(section, value, "expected a string"))?
                    .to_owned();
                continue;
            }
            let Some(entries) = value.as_table() else {
                return Err(input(unknown(&escape_for_terminal(section))));
            };
            for (name, value) in entries {
                let key = format!("{section}.{name}");
                if key == DRAG_KEY {
                    let text = value.as_str().ok_or_else(|| {
                        wrong(&key, value, "expected a drag model name in quotes")
                    })?;
                    // A name too long to be one is shown cut (the error
                    // quotes it, escaping control characters).
                    let shown: String = if text.chars().count() > 80 {
                        text.chars().take(79).chain(['…']).collect()
                    } else {
                        text.to_owned()
                    };
                    scene.drag = shown.parse().map_err(|e: UnknownModel| input(e.into()))?;
                    continue;
                }
                let number = match value {
                    toml::Value::Float(f) => *f,
                    toml::Value::Integer(i) => *i as f64,
                    _ => return Err(wrong(&key, value, "expected a number")),
                };
                match key.as_str() {
                    FENCE_DISTANCE => fence_distance = Some(number),
                    FENCE_HEIGHT => fence_height = Some(number),
                    _ => scene.set(&key, number).map_err(|e| {
                        let shown = escape_for_terminal(&key);
                        input(if shown == key { e } else { unknown(&shown) })
                    })?,
                }
            }
        }
        scene.validate().map_err(input)?;
        let fence = match (fence_distance, fence_height) {
            (None, None) => None,
            (distance, height) => {
                let fence = Fence {
                    distance: distance.unwrap_or(121.9),
                    height: height.unwrap_or(3.0),
                };
                for (key, value, max) in [
                    (FENCE_DISTANCE, fence.distance, 1000.0),
                    (FENCE_HEIGHT, fence.height, 100.0),
                ] {
                    if !(value.is_finite() && value > 0.0 && value <= max) {
                        return Err(PresetError::WrongType {
                            path: origin.to_owned(),
                            key: key.to_owned(),
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
        let mut section = "";
        for key in KEYS {
            let (head, name) = key.name.split_once('.').expect("keys are dotted");
            if head != section {
                out += &format!("\n[{head}]\n");
                section = head;
            }
            let value = (key.get)(&self.scene);
            let unit = if key.unit.is_empty() {
                String::new()
            } else {
                format!(" ({})", key.unit)
            };
            out += &format!(
                "{name} = {}  # {}{unit}: {}\n",
                toml::Value::Float(value),
                key.symbol,
                key.description
            );
        }
        out += &format!(
            "\n[model]\ndrag = \"{}\"  # {}; one of: {}\n",
            self.scene.drag,
            self.scene.drag.description(),
            DragModel::ALL.map(DragModel::name).join(", ")
        );
        if let Some(fence) = self.fence {
            out += &format!(
                "\n[field]\nfence_distance = {}  # m from the plate\nfence_height = {}  # m\n",
                toml::Value::Float(fence.distance),
                toml::Value::Float(fence.height)
            );
        }
        out
    }

    /// Writes the preset as `dir/name.toml`: first to a temporary file in the
    /// same folder, flushed to disk, then renamed over the target, so that a
    /// crash or a full disk never leaves a half-written preset.
    pub fn save(&self, dir: &Path) -> Result<PathBuf, PresetError> {
        check_name(&self.name)?;
        let io = |path: &Path| {
            let path = path.display().to_string();
            move |source| PresetError::Io { path, source }
        };
        fs::create_dir_all(dir).map_err(io(dir))?;
        let target = dir.join(format!("{}.toml", self.name));
        let temporary = dir.join(format!(".{}.toml.{}.tmp", self.name, std::process::id()));
        let written = (|| {
            let mut file = fs::File::create(&temporary)?;
            file.write_all(self.to_toml().as_bytes())?;
            file.sync_all()?;
            fs::rename(&temporary, &target)
        })();
        if let Err(source) = written {
            let _ = fs::remove_file(&temporary);
            return Err(io(&target)(source));
        }
        Ok(target)
    }
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

/// `text` made safe to print on one terminal line: control characters (ESC,
/// newline, C1 codes such as U+009B), bidirectional overrides and other
/// invisible format characters are written as `\u{1b}`-style escapes, and
/// anything longer than 80 characters is cut with "…".
pub fn escape_for_terminal(text: &str) -> String {
    escape_cut(text, 80)
}

/// Escapes like [`escape_for_terminal`], cutting at `max` characters (the
/// "…" included), never inside an escape.
fn escape_cut(text: &str, max: usize) -> String {
    let mut out = String::new();
    let mut count = 0;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let piece = if needs_escape(c) {
            c.escape_unicode().to_string()
        } else {
            c.to_string()
        };
        let len = piece.chars().count();
        let last = chars.peek().is_none();
        // Room for this piece, and for the "…" if more follows.
        if max.saturating_sub(count) < len + usize::from(!last) {
            out.push('…');
            return out;
        }
        out += &piece;
        count += len;
    }
    out
}

fn needs_escape(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{61c}'
                | '\u{200b}'..='\u{200f}'
                | '\u{2028}'..='\u{202e}'
                | '\u{2060}'..='\u{2069}'
                | '\u{feff}'
        )
}

/// A path as messages show it: escaped, never cut (the user needs all of it).
fn shown(path: &Path) -> String {
    escape_cut(&path.display().to_string(), usize::MAX)
}

/// Reads a preset file's text, safely whatever the path holds: symlinks are
/// followed, anything but a regular file (a FIFO, a device such as
/// `/dev/zero`, a folder, a socket) is refused from its metadata without
/// being opened, the file is opened without blocking and checked again once
/// open (it may have been swapped), at most [`MAX_BYTES`] + 1 bytes are read,
/// and the text must be UTF-8 without NUL bytes. Every refusal is a
/// [`PresetError`] naming the file.
pub fn read_text(path: &Path) -> Result<String, PresetError> {
    let name = shown(path);
    let io = |source| PresetError::Io {
        path: name.clone(),
        source,
    };
    let metadata = fs::metadata(path).map_err(|e| stat_error(path, &name, e))?;
    check_file(path, &name, &metadata)?;
    let mut file = open_nonblocking(path).map_err(|e| stat_error(path, &name, e))?;
    let metadata = file.metadata().map_err(io)?;
    check_file(path, &name, &metadata)?;
    let mut bytes = Vec::with_capacity(metadata.len() as usize + 1);
    (&mut file)
        .take(MAX_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_BYTES {
        return Err(PresetError::TooBig {
            path: name,
            size: None,
        });
    }
    if let Some(offset) = bytes.iter().position(|&b| b == 0) {
        return Err(PresetError::Binary { path: name, offset });
    }
    String::from_utf8(bytes).map_err(|e| PresetError::NotUtf8 {
        path: name,
        offset: e.utf8_error().valid_up_to(),
    })
}

/// Opens `path` for reading without ever blocking: `O_NONBLOCK` makes
/// opening a FIFO return at once (and is harmless for a regular file), and
/// `O_NOCTTY` keeps a terminal device from becoming ours.
fn open_nonblocking(path: &Path) -> std::io::Result<fs::File> {
    let mut options = fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY);
    }
    options.open(path)
}

/// Refuses anything but a regular file of at most [`MAX_BYTES`].
fn check_file(path: &Path, name: &str, metadata: &fs::Metadata) -> Result<(), PresetError> {
    if !metadata.is_file() {
        let link = fs::symlink_metadata(path)
            .is_ok_and(|m| m.file_type().is_symlink())
            .then(|| {
                fs::canonicalize(path)
                    .or_else(|_| fs::read_link(path))
                    .map_or_else(|_| "?".to_owned(), |target| shown(&target))
            });
        return Err(PresetError::NotAFile {
            path: name.to_owned(),
            kind: FileKind::of(metadata.file_type()),
            link,
        });
    }
    if metadata.len() > MAX_BYTES {
        return Err(PresetError::TooBig {
            path: name.to_owned(),
            size: Some(metadata.len()),
        });
    }
    Ok(())
}

/// The error for a path whose metadata cannot be read: a symlink loop and a
/// dangling symlink are named as such.
fn stat_error(path: &Path, name: &str, source: std::io::Error) -> PresetError {
    #[cfg(unix)]
    if source.raw_os_error() == Some(libc::ELOOP) {
        return PresetError::SymlinkLoop {
            path: name.to_owned(),
        };
    }
    if source.kind() == std::io::ErrorKind::NotFound
        && let Ok(target) = fs::read_link(path)
    {
        return PresetError::DanglingLink {
            path: name.to_owned(),
            target: shown(&target),
        };
    }
    PresetError::Io {
        path: name.to_owned(),
        source,
    }
}

/// Checks that a presets folder is usable: `Ok` if it is a folder or does
/// not exist (a missing folder simply holds no presets), an error if it is
/// something else (a file, a FIFO…) or cannot be looked at. Returns `dir`,
/// to be used inline.
pub fn check_dir(dir: Option<&Path>) -> Result<Option<&Path>, PresetError> {
    let Some(path) = dir else {
        return Ok(None);
    };
    let name = shown(path);
    match fs::metadata(path) {
        Ok(metadata) if metadata.is_dir() => Ok(dir),
        Ok(metadata) => Err(PresetError::NotAFolder {
            path: name,
            kind: FileKind::of(metadata.file_type()),
        }),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound && fs::read_link(path).is_err() => {
            Ok(dir)
        }
        Err(e) => Err(stat_error(path, &name, e)),
    }
}

/// The `*.toml` files in a presets folder (not hidden ones), sorted; none if
/// the folder does not exist.
fn preset_files(dir: &Path) -> Result<Vec<PathBuf>, PresetError> {
    check_dir(Some(dir))?;
    let entries = match fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(source) => {
            return Err(PresetError::Io {
                path: shown(dir),
                source,
            });
        }
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.extension().is_some_and(|x| x == "toml")
                && !p
                    .file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    paths.sort();
    Ok(paths)
}

/// The user's preset folder: `$XDG_CONFIG_HOME/homerun/presets` (or the
/// platform's config folder).
pub fn user_dir() -> Option<PathBuf> {
    dirs::config_dir().map(|d| d.join("homerun").join("presets"))
}

/// The bundled presets, parsed.
pub fn bundled() -> Vec<Preset> {
    BUNDLED
        .iter()
        .map(|(name, text)| {
            Preset::parse(text, name, &format!("presets/{name}.toml"), Source::Bundled)
                .expect("bundled presets are valid (tested)")
        })
        .collect()
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

/// Finds a preset by name (user folder first, so a user can shadow a bundled
/// one) or, if `spec` looks like a path, reads that file. A name is looked up
/// in `dir` only if `dir` is usable ([`check_dir`]); any file there with that
/// name is read, so a broken one is reported rather than skipped.
pub fn load(spec: &str, dir: Option<&Path>) -> Result<Preset, PresetError> {
    let as_path = Path::new(spec);
    if spec.ends_with(".toml") || spec.contains(std::path::MAIN_SEPARATOR) {
        return Preset::read(as_path);
    }
    if let Some(dir) = check_dir(dir)? {
        let candidate = dir.join(format!("{spec}.toml"));
        if fs::symlink_metadata(&candidate).is_ok() {
            return Preset::read(&candidate);
        }
    }
    if let Some((name, text)) = BUNDLED.iter().find(|(name, _)| *name == spec) {
        return Preset::parse(text, name, &format!("presets/{name}.toml"), Source::Bundled);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bundled_presets_parse_and_round_trip() {
        for preset in bundled() {
            let text = preset.to_toml();
            let again = Preset::parse(&text, &preset.name, "again", Source::Bundled).unwrap();
            assert_eq!(again.scene, preset.scene, "{}", preset.name);
            assert_eq!(again.fence, preset.fence);
            assert_eq!(again.description, preset.description);
        }
    }

    #[test]
    fn errors_name_the_key() {
        let e = Preset::parse("[bat]\nspeeed = 3", "x", "x.toml", Source::Bundled).unwrap_err();
        assert!(e.to_string().contains("unknown key `bat.speeed`"), "{e}");
        let e = Preset::parse("[bat]\nspeed = -3", "x", "x.toml", Source::Bundled).unwrap_err();
        assert!(e.to_string().contains("bat.speed = -3"), "{e}");
        let e =
            Preset::parse("[bat]\nspeed = \"fast\"", "x", "x.toml", Source::Bundled).unwrap_err();
        assert!(e.to_string().contains("bat.speed"), "{e}");
        let e = Preset::parse("[model]\ndrag = \"smooth\"", "x", "x.toml", Source::Bundled)
            .unwrap_err();
        assert!(e.to_string().contains("sawicki2003"), "{e}");
        let e = Preset::parse("[bat\n", "x", "x.toml", Source::Bundled).unwrap_err();
        assert!(e.to_string().contains("malformed TOML"), "{e}");
    }

    #[test]
    fn save_is_atomic_and_reloads() {
        let dir = tempfile::tempdir().unwrap();
        let mut preset = bundled().remove(0);
        preset.name = "mine".into();
        preset.scene.bat.speed = 33.5;
        let path = preset.save(dir.path()).unwrap();
        let back = Preset::read(&path).unwrap();
        assert_eq!(back.scene, preset.scene);
        let names: Vec<_> = fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names.len(), 1, "no temporary file left: {names:?}");
        preset.name = "../escape".into();
        assert!(matches!(
            preset.save(dir.path()),
            Err(PresetError::BadName(_))
        ));
    }

    #[test]
    fn escape_for_terminal_escapes_control_characters_and_cuts() {
        assert_eq!(escape_for_terminal("fastball.toml"), "fastball.toml");
        assert_eq!(
            escape_for_terminal("a\x1b[2J\nb\u{9b}c\u{202e}d\té"),
            "a\\u{1b}[2J\\u{a}b\\u{9b}c\\u{202e}d\\u{9}é"
        );
        let long = "x".repeat(81);
        let cut = escape_for_terminal(&long);
        assert_eq!(cut.chars().count(), 80);
        assert!(cut.ends_with("x…"), "{cut}");
        assert_eq!(escape_for_terminal(&long[..80]), long[..80]);
        // Never cut inside an escape.
        let cut = escape_for_terminal(&format!("{}\x1b", "x".repeat(77)));
        assert_eq!(cut, format!("{}…", "x".repeat(77)));
    }

    #[cfg(unix)]
    #[test]
    fn read_text_refuses_what_is_not_a_small_text_file() {
        let dir = tempfile::tempdir().unwrap();
        let at = |name: &str| dir.path().join(name);
        assert!(matches!(
            read_text(Path::new("/dev/zero")),
            Err(PresetError::NotAFile {
                kind: FileKind::CharDevice,
                link: None,
                ..
            })
        ));
        assert!(matches!(
            read_text(dir.path()),
            Err(PresetError::NotAFile {
                kind: FileKind::Folder,
                ..
            })
        ));
        std::os::unix::fs::symlink("/dev/zero", at("zero.toml")).unwrap();
        let e = read_text(&at("zero.toml")).unwrap_err();
        assert!(
            e.to_string().ends_with(
                "zero.toml: not a regular file (a character device, through a symlink to /dev/zero)"
            ),
            "{e}"
        );
        std::os::unix::fs::symlink(at("loop.toml"), at("loop.toml")).unwrap();
        assert!(matches!(
            read_text(&at("loop.toml")),
            Err(PresetError::SymlinkLoop { .. })
        ));
        fs::write(at("big.toml"), vec![b'#'; MAX_BYTES as usize + 1]).unwrap();
        assert!(matches!(
            read_text(&at("big.toml")),
            Err(PresetError::TooBig {
                size: Some(1_048_577),
                ..
            })
        ));
        fs::write(at("nul.toml"), b"a = 1\0").unwrap();
        assert!(matches!(
            read_text(&at("nul.toml")),
            Err(PresetError::Binary { offset: 5, .. })
        ));
        fs::write(at("ok.toml"), "a = 1\n").unwrap();
        assert_eq!(read_text(&at("ok.toml")).unwrap(), "a = 1\n");
        let e = read_text(&at("absent.toml")).unwrap_err();
        assert!(matches!(e, PresetError::Io { .. }), "{e}");
    }

    #[test]
    fn check_dir_accepts_a_folder_or_nothing_and_refuses_a_file() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("file");
        fs::write(&file, "").unwrap();
        assert!(check_dir(None).unwrap().is_none());
        assert!(check_dir(Some(dir.path())).is_ok());
        assert!(check_dir(Some(&dir.path().join("missing"))).is_ok());
        assert!(matches!(
            check_dir(Some(&file)),
            Err(PresetError::NotAFolder {
                kind: FileKind::File,
                ..
            })
        ));
        // Listing shows a bad folder as a broken entry, after the bundled.
        let all = list(Some(&file));
        assert_eq!(all.len(), BUNDLED.len() + 1);
        assert!(matches!(
            all.last(),
            Some(Err(PresetError::NotAFolder { .. }))
        ));
    }

    #[test]
    fn a_quoted_top_level_key_naming_an_input_is_an_error_not_a_panic() {
        let e = Preset::parse("\"bat.speed\" = 3", "x", "x.toml", Source::Bundled).unwrap_err();
        assert!(e.to_string().contains("unknown key `\"bat.speed\"`"), "{e}");
    }
}
