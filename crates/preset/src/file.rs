//! Reading preset files safely, whatever a path holds: only regular files,
//! never blocking, never more than [`MAX_BYTES`].

use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};

use super::PresetError;
use super::escape::escape_cut;

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

pub(super) fn through(link: &Option<String>) -> String {
    link.as_ref()
        .map(|target| format!(", through a symlink to {target}"))
        .unwrap_or_default()
}

pub(super) fn size_text(size: Option<u64>) -> String {
    match size {
        Some(bytes) if bytes >= 10 << 20 => format!("{} MiB", bytes >> 20),
        Some(bytes) => format!("{bytes} bytes"),
        None => "more than 1 MiB".to_owned(),
    }
}

/// The largest preset file read, in bytes: a preset is a few hundred bytes,
/// and anything larger is refused before it costs memory or parsing time.
pub const MAX_BYTES: u64 = 1 << 20;

/// A path as messages show it: escaped, never cut (the user needs all of it).
pub fn shown(path: &Path) -> String {
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
        return Err(not_a_file(path, name, metadata));
    }
    if metadata.len() > MAX_BYTES {
        return Err(PresetError::TooBig {
            path: name.to_owned(),
            size: Some(metadata.len()),
        });
    }
    Ok(())
}

/// The error for `path`, which is not a regular file (`metadata`, after
/// links): what it is, and where a symlink there leads.
fn not_a_file(path: &Path, name: &str, metadata: &fs::Metadata) -> PresetError {
    let link = path.is_symlink().then(|| {
        fs::canonicalize(path)
            .or_else(|_| fs::read_link(path))
            .map_or_else(|_| "?".to_owned(), |target| shown(&target))
    });
    PresetError::NotAFile {
        path: name.to_owned(),
        kind: FileKind::of(metadata.file_type()),
        link,
    }
}

/// Refuses to save a preset over anything but a regular file or a new
/// name: a FIFO would block the save until a reader came, a device would
/// take the text, a folder cannot be replaced.
pub(super) fn check_save_target(path: &Path) -> Result<(), PresetError> {
    match fs::metadata(path) {
        Ok(metadata) if !metadata.is_file() => Err(not_a_file(path, &shown(path), &metadata)),
        _ => Ok(()),
    }
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
pub(super) fn preset_files(dir: &Path) -> Result<Vec<PathBuf>, PresetError> {
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
