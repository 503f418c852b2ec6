//! Writing a file so that it is either whole or not there: first a
//! temporary file in the same folder, flushed to disk, then renamed over the
//! target (a rename within one folder is atomic). A crash, a full disk or a
//! folder that cannot be written never leaves a half-written file, and the
//! temporary is removed on failure.
//!
//! The temporary is created new (`O_EXCL`: never through a link, never a
//! file that is already there) under a name no other process can guess, so
//! that a link planted where a temporary will be cannot redirect the bytes.
//!
//! Two targets are not renamed over: a symbolic link to a file in the same
//! folder stays a link (the file it points to is replaced), and, for
//! pictures ([`write`](fn@write)), a device, FIFO or socket (`/dev/null`,
//! `/dev/stdout`, a named pipe), or any path in `/dev` or `/proc` (the
//! system's own links: `/dev/stdout` when stdout is a file), is written to
//! in place, since a rename would replace the device node itself with a
//! file. A link that leads out of its folder is never written through: the
//! write is refused, naming where it leads. Files that are read back
//! ([`replace`]) are never written into a device.

use std::fs;
use std::io::{self, Write as _};
use std::path::{Path, PathBuf};

/// How many names are tried for a temporary before giving up: another
/// file at a random name is already unlikely once.
const TEMPORARY_TRIES: usize = 8;

/// A number no other process can guess: std's per-process random hash keys
/// (from the OS's random source), mixed with the time, the process and a
/// count.
fn unpredictable() -> u64 {
    use std::hash::{BuildHasher as _, Hasher as _};
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNT: AtomicU64 = AtomicU64::new(0);
    let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    hasher.write_u128(now);
    hasher.write_u32(std::process::id());
    hasher.write_u64(COUNT.fetch_add(1, Ordering::Relaxed));
    hasher.finish()
}

/// Creates a new temporary file beside `target`: hidden, at a random name,
/// opened with `create_new` (never following a link, never reusing a file;
/// another name is tried if one is taken). Its path and the open file.
fn create_temporary(target: &Path) -> io::Result<(PathBuf, fs::File)> {
    let name = target
        .file_name()
        .map_or("file".into(), |n| n.to_string_lossy().into_owned());
    // Room for the suffix within a file name's 255 bytes.
    let mut end = name.len().min(200);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    let mut last = io::Error::from(io::ErrorKind::AlreadyExists);
    for _ in 0..TEMPORARY_TRIES {
        let path = target.with_file_name(format!(".{}.{:016x}.tmp", &name[..end], unpredictable()));
        match fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
        {
            Ok(file) => return Ok((path, file)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = e,
            Err(e) => return Err(e),
        }
    }
    Err(last)
}

/// Whether a picture to `target` is written in place: it exists and is
/// neither a file nor a folder (after links: a device, a FIFO or a socket),
/// or it is a link in `/dev` or `/proc`, which are the system's
/// (`/dev/stdout` leads to whatever stdout is, a file included).
pub fn is_special(target: &Path) -> bool {
    let system = (target.starts_with("/dev") || target.starts_with("/proc")) && target.is_symlink();
    fs::metadata(target).is_ok_and(|m| !m.is_dir() && (system || !m.is_file()))
}

/// Whether a new file can be made beside `target`: a temporary is created
/// there as a write would create it, and removed at once.
pub fn probe(target: &Path) -> io::Result<()> {
    let (temporary, _) = create_temporary(target)?;
    fs::remove_file(temporary)
}

/// The folder `path` is in ("." for a bare name).
fn folder(path: &Path) -> &Path {
    path.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// The path the bytes for `target` replace: the file a symbolic link points
/// to if it is in the link's own folder (so that the link stays), else
/// `target` itself (not a link, or one that points nowhere). A link that
/// leads out of its folder is an error naming where it leads: writing
/// through it could replace any file the user can write.
pub fn resolved(target: &Path) -> io::Result<PathBuf> {
    let is_link = target.is_symlink();
    if !is_link {
        return Ok(target.to_path_buf());
    }
    let Ok(file) = fs::canonicalize(target) else {
        // A link that points nowhere: replaced by the file.
        return Ok(target.to_path_buf());
    };
    let here = fs::canonicalize(folder(target))?;
    if file.parent() == Some(here.as_path()) {
        Ok(file)
    } else {
        Err(io::Error::other(format!(
            "a symbolic link to {}, outside its folder: not written through (remove the link or give the file's own path)",
            crate::escape_cut(&file.to_string_lossy(), 200)
        )))
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
    let target = resolved(target)?;
    let (temporary, mut file) = create_temporary(&target)?;
    let written = (|| {
        file.write_all(bytes)?;
        file.sync_all()?;
        fs::rename(&temporary, &target)
    })();
    if written.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    written
}

/// Writes `bytes` as a new file at `target`, whole or not at all, and
/// never over anything already there, even a file made meanwhile: the
/// temporary is linked to `target` (which fails if the name is taken)
/// rather than renamed over it. `AlreadyExists` if it is taken. On a file
/// system without hard links, renamed if the name is still free.
pub fn write_new(target: &Path, bytes: &[u8]) -> io::Result<()> {
    let (temporary, mut file) = create_temporary(target)?;
    let written = (|| {
        file.write_all(bytes)?;
        file.sync_all()?;
        match fs::hard_link(&temporary, target) {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => Err(e),
            Err(_) if fs::symlink_metadata(target).is_err() => fs::rename(&temporary, target),
            Err(e) => Err(e),
        }
    })();
    let _ = fs::remove_file(&temporary);
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
        assert!(link.is_symlink());
        assert_eq!(fs::read_to_string(&file).unwrap(), "new");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2, "no temporary");
    }

    #[test]
    fn a_link_planted_at_the_old_temporary_name_is_not_followed() {
        // Issue 25 row 5: `.out.svg.PID.tmp` was predictable and opened with
        // `File::create`, which follows links.
        let (dir, elsewhere) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
        let victim = elsewhere.path().join("victim");
        fs::write(&victim, "keep me").unwrap();
        let planted = dir
            .path()
            .join(format!(".out.svg.{}.tmp", std::process::id()));
        std::os::unix::fs::symlink(&victim, &planted).unwrap();
        write(&dir.path().join("out.svg"), b"<svg/>").unwrap();
        assert_eq!(fs::read_to_string(&victim).unwrap(), "keep me");
        assert_eq!(fs::read(dir.path().join("out.svg")).unwrap(), b"<svg/>");
        assert!(planted.is_symlink());
        // The temporary's names are not guessable: two in a row differ.
        let (a, _) = create_temporary(&dir.path().join("out.svg")).unwrap();
        let (b, _) = create_temporary(&dir.path().join("out.svg")).unwrap();
        assert_ne!(a, b);
    }

    #[test]
    fn a_temporary_is_never_an_existing_file() {
        let dir = tempfile::tempdir().unwrap();
        let (path, _) = create_temporary(&dir.path().join("p.toml")).unwrap();
        // Taken: `create_new` refuses it rather than reusing it.
        let again = fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path);
        assert_eq!(again.unwrap_err().kind(), io::ErrorKind::AlreadyExists);
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            name.starts_with(".p.toml.") && name.ends_with(".tmp"),
            "{name}"
        );
    }

    #[test]
    fn a_new_file_never_replaces_one_already_there() {
        let dir = tempfile::tempdir().unwrap();
        let (taken, free) = (dir.path().join("taken.svg"), dir.path().join("free.svg"));
        fs::write(&taken, "old").unwrap();
        let e = write_new(&taken, b"new").unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
        assert_eq!(fs::read_to_string(&taken).unwrap(), "old");
        write_new(&free, b"new").unwrap();
        assert_eq!(fs::read_to_string(&free).unwrap(), "new");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2, "no temporary");
    }

    #[test]
    fn a_link_out_of_its_folder_is_not_written_through() {
        let (dir, elsewhere) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
        let victim = elsewhere.path().join("victim.toml");
        fs::write(&victim, "keep me").unwrap();
        let link = dir.path().join("x.toml");
        std::os::unix::fs::symlink(&victim, &link).unwrap();
        for result in [write(&link, b"new"), replace(&link, b"new")] {
            let message = result.unwrap_err().to_string();
            assert!(message.contains("outside its folder"), "{message}");
        }
        assert_eq!(fs::read_to_string(&victim).unwrap(), "keep me");
        assert!(link.is_symlink());
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1, "no temporary");
    }

    #[test]
    #[allow(unsafe_code)] // std makes no FIFO.
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
