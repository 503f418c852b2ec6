//! The README and the guides in docs/ are written for people, but they may
//! not fall behind the program: every `$ homerun …` example is what it
//! prints, every screen of the explorer is one of its snapshots, the key
//! table names every key of the keymap, and every link between them leads
//! somewhere.

use crate::common;
use homerun::tui::keymap::KEYMAP;

/// The README and every guide in docs/, by path, as they are on disk.
fn documents() -> Vec<(String, String)> {
    let mut paths: Vec<std::path::PathBuf> = std::fs::read_dir("docs")
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "md"))
        .collect();
    paths.sort();
    paths.insert(0, "README.md".into());
    paths
        .into_iter()
        .map(|path| {
            let text = std::fs::read_to_string(&path).unwrap();
            (path.display().to_string(), text)
        })
        .collect()
}

#[test]
fn the_guides_are_there() {
    let names: Vec<String> = documents().into_iter().map(|(name, _)| name).collect();
    for guide in ["explorer", "cli", "models", "speed", "limits", "layout"] {
        assert!(
            names.contains(&format!("docs/{guide}.md")),
            "docs/{guide}.md is missing: {names:?}"
        );
    }
}

/// The code spans (`…`) in the first column of the key table, which one
/// document holds.
fn readme_keys() -> Vec<String> {
    let tables: Vec<String> = documents()
        .into_iter()
        .filter_map(|(_, text)| text.split("| Keys | Action |").nth(1).map(str::to_owned))
        .collect();
    assert_eq!(tables.len(), 1, "one key table in the README and docs/");
    let table = &tables[0];
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
        "not in the key table (docs/explorer.md): {missing:?}"
    );
}

/// One `$ homerun …` example of a document and the lines shown under it.
struct Example {
    document: String,
    line: usize,
    args: Vec<String>,
    tail: Option<usize>,
    shown: Vec<String>,
}

/// The examples of the README and the guides that can be run as they are
/// written: no shell variables, pictures or files but the repository's own
/// samples (tests/data/), which the tests of those features cover.
fn readme_examples() -> Vec<Example> {
    let mut examples: Vec<Example> = Vec::new();
    for (document, text) in documents() {
        examples.extend(examples_in(&document, &text));
    }
    examples
}

fn examples_in(document: &str, text: &str) -> Vec<Example> {
    let mut examples: Vec<Example> = Vec::new();
    let mut in_block = false;
    let mut current: Option<Example> = None;
    for (k, line) in text.lines().enumerate() {
        if line.starts_with("```") {
            in_block = !in_block;
            examples.extend(current.take());
            continue;
        }
        if !in_block {
            continue;
        }
        if let Some(command) = line.strip_prefix("$ homerun") {
            examples.extend(current.take());
            // A file of the repository's own (tests/data/) runs as written.
            let committed = |word: &str| !word.contains(".csv") || word.starts_with("tests/data/");
            let runnable = !command.contains('$')
                && !command.contains('\\')
                && command.split_whitespace().all(committed)
                && !command.contains(".toml")
                && !command.contains("--svg");
            let (command, tail) = match command.split_once("| tail -") {
                Some((command, n)) => (command, n.trim().parse().ok()),
                None => (command, None),
            };
            current = runnable.then(|| Example {
                document: document.to_owned(),
                line: k + 1,
                args: command.split_whitespace().map(str::to_owned).collect(),
                tail,
                shown: Vec::new(),
            });
        } else if let Some(example) = current.as_mut() {
            example.shown.push(line.trim_end().to_owned());
        }
    }
    examples
}

/// Whether the lines the README shows are those `printed`: each the same,
/// or its beginning where the README cuts a long line with "…"; a line of
/// "…" alone stands for the rest. A user's folder is the machine's, so a
/// line naming one only has to be there.
fn agrees(shown: &[String], printed: &[&str]) -> bool {
    let mut printed = printed.iter();
    for line in shown {
        if line == "…" {
            return true;
        }
        let Some(p) = printed.next() else {
            return false;
        };
        let same = match line.strip_suffix('…') {
            Some(start) => p.starts_with(start.trim_end()),
            None => p == line,
        };
        let a_users_folder = line.contains("/.config/homerun") && !p.is_empty();
        if !(same || a_users_folder) {
            return false;
        }
    }
    printed.next().is_none()
}

/// What the README and the guides show under a command is what the program
/// prints. Both streams count (they show refusals too).
#[test]
fn the_readme_examples_are_what_the_program_prints() {
    let examples = readme_examples();
    assert!(examples.len() > 25, "found {}", examples.len());
    assert!(
        examples
            .iter()
            .filter(|e| e.document == "README.md")
            .count()
            >= 4,
        "the README's quick start is checked too"
    );
    let presets = tempfile::tempdir().unwrap();
    let mut wrong = Vec::new();
    for example in &examples {
        let output = common::assert_command()
            .args(&example.args)
            .env("XDG_CONFIG_HOME", presets.path())
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&output.stdout).into_owned()
            + &String::from_utf8_lossy(&output.stderr);
        let mut printed: Vec<&str> = text.lines().map(str::trim_end).collect();
        if let Some(n) = example.tail {
            printed = printed.split_off(printed.len().saturating_sub(n));
        }
        let agrees = agrees(&example.shown, &printed);
        if !agrees {
            wrong.push(format!(
                "{} line {}: homerun {}\n--- shown\n{}\n--- printed\n{}",
                example.document,
                example.line,
                example.args.join(" "),
                example.shown.join("\n"),
                printed.join("\n")
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n\n"));
}

/// The screens the README and the guides show are the explorer's own, as
/// the insta snapshots of `tests/tui_render.rs` hold them: each picture of
/// the explorer equals one snapshot, so a change to a pane cannot leave a
/// document showing the old one.
#[test]
fn the_readme_screens_are_snapshots() {
    let snapshots: Vec<(String, Vec<String>)> = std::fs::read_dir("tests/explorer/snapshots")
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "snap"))
        .map(|path| {
            let text = std::fs::read_to_string(&path).unwrap();
            let body = text.splitn(3, "---\n").nth(2).unwrap_or("");
            let lines = body
                .lines()
                .map(|l| l.trim_matches('"').trim_end().to_owned())
                .collect();
            (path.display().to_string(), lines)
        })
        .collect();
    let documents = documents();
    let screens: Vec<(&str, Vec<String>)> = documents
        .iter()
        .flat_map(|(name, text)| {
            screens_in(text)
                .into_iter()
                .map(move |s| (name.as_str(), s))
        })
        .collect();
    assert!(
        screens.iter().any(|(name, _)| *name == "README.md"),
        "the README shows the explorer"
    );
    assert!(screens.len() >= 4, "found {} screens", screens.len());
    for (name, screen) in &screens {
        assert!(
            snapshots.iter().any(|(_, lines)| lines == screen),
            "a screen in {name} that no snapshot holds:\n{}",
            screen.join("\n")
        );
    }
}

/// The pictures of the explorer in a document's code blocks.
fn screens_in(text: &str) -> Vec<Vec<String>> {
    text.split("```")
        .skip(1)
        .step_by(2)
        .map(|block| {
            block
                .lines()
                .skip(1)
                .map(|l| l.trim_end().to_owned())
                .collect::<Vec<_>>()
        })
        .filter(|lines: &Vec<String>| lines.first().is_some_and(|l| l.starts_with("┌ Inputs")))
        .collect()
}

/// The targets of a document's inline links, `[text](target)`, outside
/// code (blocks and spans), with the line each is on.
fn links(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    let mut in_block = false;
    for (k, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            in_block = !in_block;
            continue;
        }
        if in_block {
            continue;
        }
        // Code spans are the odd pieces between backquotes.
        let prose: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        let mut rest = prose.as_str();
        while let Some(at) = rest.find("](") {
            rest = &rest[at + 2..];
            let Some(end) = rest.find(')') else { break };
            found.push((k + 1, rest[..end].to_owned()));
            rest = &rest[end..];
        }
    }
    found
}

/// A heading's anchor as GitHub makes it: lower case, punctuation other
/// than `-` and `_` dropped, each space a `-`.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '_'))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a document's headings, outside code blocks.
fn anchors(text: &str) -> Vec<String> {
    let mut in_block = false;
    let mut found = Vec::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_block = !in_block;
        } else if !in_block && line.starts_with('#') {
            found.push(anchor(line.trim_start_matches('#')));
        }
    }
    found
}

/// Every relative link of the README and the guides leads to a file that
/// exists, and a `#part` of one to a heading of it; links to the web are
/// left to the reader.
#[test]
fn every_link_between_the_documents_resolves() {
    let documents = documents();
    let mut checked = 0;
    let mut broken = Vec::new();
    for (name, text) in &documents {
        let folder = std::path::Path::new(name).parent().unwrap();
        for (line, target) in links(text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            checked += 1;
            let (file, part) = match target.split_once('#') {
                Some((file, part)) => (file, Some(part)),
                None => (target.as_str(), None),
            };
            let path = if file.is_empty() {
                std::path::PathBuf::from(name)
            } else {
                folder.join(file)
            };
            if !path.exists() {
                broken.push(format!(
                    "{name}:{line}: {target}: no file {}",
                    path.display()
                ));
                continue;
            }
            if let Some(part) = part {
                let text = std::fs::read_to_string(&path).unwrap_or_default();
                if !anchors(&text).iter().any(|a| a == part) {
                    broken.push(format!("{name}:{line}: {target}: no heading #{part}"));
                }
            }
        }
    }
    assert!(checked > 20, "checked {checked} links");
    assert!(
        broken.is_empty(),
        "links that lead nowhere:\n{}",
        broken.join("\n")
    );
}

#[test]
fn anchors_are_made_as_github_makes_them() {
    assert_eq!(anchor(" Pictures: `--svg FILE`"), "pictures---svg-file");
    assert_eq!(
        anchor(" `homerun surface`: range over (E, ψ)"),
        "homerun-surface-range-over-e-ψ"
    );
    assert_eq!(anchor(" The explorer's budget"), "the-explorers-budget");
    assert_eq!(
        links("see [a](b.md#c) and `[not](a link)`, [d](e.svg)"),
        vec![(1, "b.md#c".to_owned()), (1, "e.svg".to_owned())]
    );
}

/// Issue 28, item 15: the README installs with the lock file, gives the
/// batch (an analyst's first command) its own section before the quick
/// starts, and says how to run the examples without `homerun` on PATH.
#[test]
fn the_readme_serves_a_new_user() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    assert!(readme.contains("cargo install --path . --locked"));
    let batch = readme
        .find("## A Statcast export")
        .expect("a batch section");
    let quick = readme.find("## Quick start for baseball").unwrap();
    assert!(batch < quick);
    assert!(readme[batch..quick].contains("--batch tests/data/savant_home_runs.csv"));
    assert!(readme.contains("cargo run --release -- fly"));
    assert!(readme.contains("target/release/homerun fly"));
}
