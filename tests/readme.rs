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

/// One `$ homerun …` example of the README and the lines shown under it.
struct Example {
    line: usize,
    args: Vec<String>,
    tail: Option<usize>,
    shown: Vec<String>,
}

/// The README's examples that can be run as they are written: no shell
/// variables, files or pictures, which the tests of those features cover.
fn readme_examples() -> Vec<Example> {
    let readme = include_str!("../README.md");
    let mut examples: Vec<Example> = Vec::new();
    let mut in_block = false;
    let mut current: Option<Example> = None;
    for (k, line) in readme.lines().enumerate() {
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
            let runnable = !command.contains('$')
                && !command.contains('\\')
                && !command.contains(".csv")
                && !command.contains(".toml")
                && !command.contains("--svg");
            let (command, tail) = match command.split_once("| tail -") {
                Some((command, n)) => (command, n.trim().parse().ok()),
                None => (command, None),
            };
            current = runnable.then(|| Example {
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

/// What the README shows under a command is what the program prints. Both
/// streams count (the README shows refusals too).
#[test]
fn the_readme_examples_are_what_the_program_prints() {
    let examples = readme_examples();
    assert!(examples.len() > 20, "found {}", examples.len());
    let presets = tempfile::tempdir().unwrap();
    let mut wrong = Vec::new();
    for example in &examples {
        let output = assert_cmd::Command::cargo_bin("homerun")
            .unwrap()
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
                "README line {}: homerun {}\n--- README\n{}\n--- printed\n{}",
                example.line,
                example.args.join(" "),
                example.shown.join("\n"),
                printed.join("\n")
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n\n"));
}

/// The screens the README shows are the explorer's own, as the insta
/// snapshots of `tests/tui_render.rs` hold them: each picture of the
/// explorer equals one snapshot, so a change to a pane cannot leave the
/// README showing the old one.
#[test]
fn the_readme_screens_are_snapshots() {
    let snapshots: Vec<(String, Vec<String>)> = std::fs::read_dir("tests/snapshots")
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
    let readme = include_str!("../README.md");
    let screens: Vec<Vec<String>> = readme
        .split("```")
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
        .collect();
    assert!(!screens.is_empty(), "the README shows the explorer");
    for screen in &screens {
        assert!(
            snapshots.iter().any(|(_, lines)| lines == screen),
            "a README screen that no snapshot holds:\n{}",
            screen.join("\n")
        );
    }
}
