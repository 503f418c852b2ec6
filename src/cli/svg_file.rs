//! `--svg FILE`: the folder checked before any work, the file written
//! atomically, and every failure one line naming the path and the reason.

use std::path::Path;

use super::UsageError;
use crate::preset::escape_cut;

/// The path as the user wrote it, escaped and cut to 80 characters.
pub(super) fn shown(path: &Path) -> String {
    escape_cut(&path.to_string_lossy(), 80)
}

fn refused(path: &Path, reason: String) -> UsageError {
    UsageError::SvgFile {
        path: shown(path),
        reason,
    }
}

/// The folder `path` goes in ("." for a bare name).
fn folder(path: &Path) -> &Path {
    path.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// Whether `path` can be written: its folder exists, is a folder and takes
/// a new file (tried with a temporary file, removed at once), and `path`
/// is not itself a folder.
pub(super) fn check(path: &Path) -> Result<(), UsageError> {
    if path.is_dir() {
        return Err(refused(path, "is a folder; give a file name".into()));
    }
    // `/dev/stdout`, a named pipe: written to in place, no folder needed.
    if crate::atomic_file::is_special(path) {
        return Ok(());
    }
    // Through a link, the file replaced is the one it points to.
    let resolved = crate::atomic_file::resolved(path).map_err(|e| refused(path, e.to_string()))?;
    let dir = folder(&resolved);
    if !dir.exists() {
        return Err(refused(
            path,
            format!("the folder {} does not exist", shown(dir)),
        ));
    }
    if !dir.is_dir() {
        return Err(refused(path, format!("{} is not a folder", shown(dir))));
    }
    crate::atomic_file::probe(&resolved).map_err(|e| {
        refused(
            path,
            format!("cannot write in the folder {}: {e}", shown(dir)),
        )
    })
}

/// Writes `svg` to `path` atomically: the whole file or none.
pub(super) fn write(path: &Path, svg: &str) -> Result<(), UsageError> {
    crate::atomic_file::write(path, svg.as_bytes())
        .map_err(|e| refused(path, format!("cannot write it: {e}")))
}
