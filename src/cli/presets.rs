//! `presets`: the presets, bundled and the user's, where each comes from,
//! and which one `--preset NAME` loads when names collide.

use std::fmt::Write as _;
use std::path::Path;

use crate::preset::{self, Source, escape_cut, escape_for_terminal, shown};

pub(super) fn presets(dir: Option<&Path>) -> String {
    let mut out = String::new();
    let all = preset::list(dir);
    let width = all
        .iter()
        .filter_map(|p| p.as_ref().ok().map(|p| escape_for_terminal(&p.name).len()))
        .max()
        .unwrap_or(8)
        .max(8);
    for entry in &all {
        match entry {
            Ok(p) => {
                let name = escape_for_terminal(&p.name);
                let source = match &p.source {
                    Source::Bundled => match preset::user_file(&p.name, dir) {
                        Some(file) => format!(
                            "bundled; hidden by {}, which --preset {name} loads",
                            shown(&file)
                        ),
                        None => "bundled".to_owned(),
                    },
                    Source::File(path) if preset::is_bundled(&p.name) => {
                        format!("{}; hides the bundled {name}", shown(path))
                    }
                    Source::File(path) => shown(path),
                };
                // Whole, as written, but on one line and never a screenful.
                let description = escape_cut(&p.description, 400);
                let _ = writeln!(out, "{name:<width$}  {description}");
                let _ = writeln!(out, "{:<width$}  ({source})", "");
            }
            Err(e) => {
                let _ = writeln!(out, "{:<width$}  {e}", "(broken)");
            }
        }
    }
    match dir {
        Some(dir) => {
            let _ = writeln!(
                out,
                "\nYour presets: {} (name.toml; use with --preset name; a name of yours wins over a bundled one)",
                shown(dir)
            );
        }
        None => {
            let _ = writeln!(out, "\nNo user preset folder (give one with --presets-dir)");
        }
    }
    out
}
