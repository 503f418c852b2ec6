//! The README's key table is written for people, but it may not fall behind
//! the keymap: every key the explorer's help names must be in it.

use homerun::tui::keymap::KEYMAP;

/// The code spans (`…`) in the first column of the README's key table.
fn readme_keys() -> Vec<String> {
    let readme = include_str!("../README.md");
    let table = readme
        .split("| Keys | Action |")
        .nth(1)
        .expect("the README has a key table");
    table
        .lines()
        .skip(2)
        .take_while(|line| line.starts_with('|'))
        .flat_map(|line| {
            let keys = line.split('|').nth(1).unwrap_or("");
            keys.split('`')
                .skip(1)
                .step_by(2)
                .map(str::to_owned)
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn every_key_in_the_help_is_in_the_readme_table() {
    let documented = readme_keys();
    assert!(documented.len() > 20, "parsed {documented:?}");
    let mut missing = Vec::new();
    for row in KEYMAP {
        for binding in row.keys.iter().filter(|b| b.shown) {
            // The README writes modifiers outside the code span
            // (Shift+`←`), so the key alone is what to look for.
            let name = binding.name();
            let glyph = name.rsplit(['+', '-']).next().unwrap_or(&name);
            let glyph = if name.starts_with("Ctrl-") {
                name.as_str()
            } else {
                glyph
            };
            if !documented.iter().any(|d| d == glyph || d == &name) {
                missing.push(format!("{name} ({})", row.what));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "not in the README's key table: {missing:?}"
    );
}
