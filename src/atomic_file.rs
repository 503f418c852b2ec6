//! Writing a file so that it is either whole or not there: first a
//! temporary file in the same folder, flushed to disk, then renamed over the
//! target (a rename within one folder is atomic). A crash, a full disk or a
//! folder that cannot be written never leaves a half-written file, and the
//! temporary is removed on failure.
//!
//! Two targets are not renamed over: a symbolic link stays a link (the file
//! it points to is replaced, in that file's folder), and, for pictures
//! ([`write`]), a device, FIFO or socket (`/dev/null`, `/dev/stdout`, a named
//! pipe) is written to in place, since a rename would replace the device
//! node itself with a file. Files that are read back ([`replace`]) are
//! never written into one.

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

/// Whether `target` exists and is neither a file nor a folder (after links):
/// a device, a FIFO or a socket, written to in place.
pub fn is_special(target: &Path) -> bool {
    fs::metadata(target).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// The path the bytes for `target` replace: the file a symbolic link points
/// to (so that the link stays), else `target` itself.
pub fn resolved(target: &Path) -> PathBuf {
    let is_link = fs::symlink_metadata(target).is_ok_and(|m| m.file_type().is_symlink());
    match is_link.then(|| fs::canonicalize(target)) {
        Some(Ok(file)) => file,
        // Not a link, or one that points nowhere: the link's own path.
        _ => target.to_path_buf(),
    }
}

/// Writes `bytes` to `target` atomically (see the module's comment), or in
/// place into a device, FIFO or socket: for pictures, which may go to
/// `/dev/stdout`. The folder must exist: it is not created.
pub fn write(target: &Path, bytes: &[u8]) -> io::Result<()> {
    if is_special(target) {
        return fs::OpenOptions::new()
            .write(true)
            .open(target)?
            .write_all(bytes);
    }
    replace(target, bytes)
}

/// Writes `bytes` as a regular file at `target`, atomically, never into a
/// device or FIFO: for files read back (presets), whose caller refuses any
/// target but a regular file or a new name. A FIFO that appears at `target`
/// meanwhile is replaced by the file, not written into (which would block
/// until a reader came).
pub fn replace(target: &Path, bytes: &[u8]) -> io::Result<()> {
    let target = resolved(target);
    let temporary = temporary_for(&target);
    let written = (|| {
        let mut file = fs::File::create(&temporary)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        fs::rename(&temporary, &target)
    })();
    if written.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    written
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn a_link_stays_a_link_and_its_file_is_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let (file, link) = (dir.path().join("real.svg"), dir.path().join("link.svg"));
        fs::write(&file, "old").unwrap();
        std::os::unix::fs::symlink(&file, &link).unwrap();
        write(&link, b"new").unwrap();
        assert!(
            fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(fs::read_to_string(&file).unwrap(), "new");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2, "no temporary");
    }

    #[test]
    fn a_fifo_is_written_to_and_stays_a_fifo() {
        // As `/dev/null` or `/dev/stdout` would be, without touching them.
        use std::os::unix::fs::FileTypeExt as _;
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("pipe.svg");
        let name = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o600) }, 0);
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || fs::read(fifo).unwrap())
        };
        write(&fifo, b"<svg/>").unwrap();
        assert_eq!(reader.join().unwrap(), b"<svg/>");
        assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    }
}
