//! `presets`: the presets, bundled and the user's, and what they are.

use std::fmt::Write as _;
use std::path::Path;

use crate::preset::{self, Source};

pub(super) fn presets(dir: Option<&Path>) -> String {
    let mut out = String::new();
    let all = preset::list(dir);
    let width = all
        .iter()
        .filter_map(|p| p.as_ref().ok().map(|p| p.name.len()))
        .max()
        .unwrap_or(8)
        .max(8);
    for entry in &all {
        match entry {
            Ok(p) => {
                let source = match &p.source {
                    Source::Bundled => "bundled".to_owned(),
                    Source::File(path) => path.display().to_string(),
                };
                let _ = writeln!(out, "{:<width$}  {}", p.name, p.description);
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
                "\nYour presets: {} (name.toml; use with --preset name)",
                dir.display()
            );
        }
        None => {
            let _ = writeln!(out, "\nNo user preset folder (give one with --presets-dir)");
        }
    }
    out
}
