//! The user's default folders (`$XDG_CONFIG_HOME/homerun/…` or
//! `$HOME/.config/homerun/…`), used only when they can be: HOME or
//! XDG_CONFIG_HOME a file, a link loop, a folder that cannot be read are
//! one warning on stderr, and the command goes on with the bundled presets
//! and parks. A folder given with `--presets-dir` or `--parks-dir` was
//! asked for by name, and stays an error where it cannot be used.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Once;

use crate::preset::{self, PresetError, shown};

/// Which of the user's folders.
#[derive(Clone, Copy)]
pub(super) enum Folder {
    Presets,
    Parks,
}

impl Folder {
    fn default_path(self) -> Option<PathBuf> {
        match self {
            Folder::Presets => preset::user_dir(),
            Folder::Parks => preset::parks::user_dir(),
        }
    }

    fn noun(self) -> &'static str {
        match self {
            Folder::Presets => "presets",
            Folder::Parks => "parks",
        }
    }

    /// The warning is said once a run, however often the folder is asked for.
    fn warned(self) -> &'static Once {
        static PRESETS: Once = Once::new();
        static PARKS: Once = Once::new();
        match self {
            Folder::Presets => &PRESETS,
            Folder::Parks => &PARKS,
        }
    }
}

/// The default `folder`, if there is one and it can be used; else `None`,
/// having warned (once) what is wrong and where.
pub(super) fn usable(folder: Folder) -> Option<PathBuf> {
    let path = folder.default_path()?;
    match unusable_because(&path) {
        None => Some(path),
        Some(why) => {
            folder.warned().call_once(|| {
                let noun = folder.noun();
                // Never a panic where stderr cannot take it (eprintln!'s).
                let _ = writeln!(
                    std::io::stderr(),
                    "homerun: warning: your {noun} folder cannot be used ({why}); going on with the bundled {noun} only"
                );
            });
            None
        }
    }
}

/// Why the default presets folder cannot take a preset, if it cannot: what
/// `--save` says instead of saving (the bundled presets cannot be saved to).
pub(super) fn unusable_presets_folder() -> Option<String> {
    let path = Folder::Presets.default_path()?;
    unusable_because(&path).map(|why| {
        format!("your presets folder cannot be used ({why}); give one with --presets-dir DIR")
    })
}

/// What is wrong with `path` as a folder to read, or `None` if it is a
/// folder that can be listed or does not exist (it then holds nothing).
fn unusable_because(path: &Path) -> Option<String> {
    if let Err(e) = preset::check_dir(Some(path)) {
        return Some(e.to_string());
    }
    match std::fs::read_dir(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Some(
            PresetError::Io {
                path: shown(path),
                source: e,
            }
            .to_string(),
        ),
        _ => None,
    }
}
