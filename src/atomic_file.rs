//! Writing a file so that it is either whole or not there: first a
//! temporary file in the same folder, flushed to disk, then renamed over the
//! target (a rename within one folder is atomic). A crash, a full disk or a
//! folder that cannot be written never leaves a half-written file, and the
//! temporary is removed on failure.

use std::fs;
use std::io::{self, Write as _};
use std::path::{Path, PathBuf};

/// The temporary file beside `target`: hidden, and named by the process so
/// that two programs writing the same target do not share one.
fn temporary_for(target: &Path) -> PathBuf {
    let name = target
        .file_name()
        .map_or("file".into(), |n| n.to_string_lossy().into_owned());
    target.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

/// Writes `bytes` to `target` atomically (see the module's comment). The
/// folder must exist: it is not created.
pub fn write(target: &Path, bytes: &[u8]) -> io::Result<()> {
    let temporary = temporary_for(target);
    let written = (|| {
        let mut file = fs::File::create(&temporary)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        fs::rename(&temporary, target)
    })();
    if written.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    written
}
