//! The pipeline's modules import one another without a loop (issue 35:
//! "no loop of imports inside it"): each stage uses only those below it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The modules each module names (`crate::m`, `super::m`, or an item the
/// crate's root re-exports from one), outside comments and tests.
fn imports() -> BTreeMap<String, BTreeSet<String>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let reexported = [("Setup", "setup"), ("Header", "header"), ("Tally", "tally")];
    let mut modules: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut files = vec![];
    for folder in ["", "output", "header"] {
        for entry in std::fs::read_dir(root.join(folder)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    for path in files {
        // The files of a folder are its module's, one unit.
        let folder = path.parent().unwrap();
        let name = match folder != root {
            true => folder.file_name().unwrap().to_str().unwrap().to_owned(),
            false => path.file_stem().unwrap().to_str().unwrap().to_owned(),
        };
        if name == "lib" || name == "tests" {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let code = text.split("#[cfg(test)]").next().unwrap();
        let mut named = BTreeSet::new();
        for line in code.lines().filter(|l| !l.trim_start().starts_with("//")) {
            for prefix in ["crate::", "super::"] {
                for (at, _) in line.match_indices(prefix) {
                    let rest = &line[at + prefix.len()..];
                    let word: String = rest
                        .chars()
                        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                        .collect();
                    let module = reexported
                        .iter()
                        .find(|(item, _)| *item == word)
                        .map_or(word.as_str(), |(_, module)| module);
                    named.insert(module.to_owned());
                }
            }
            // `crate::{A, B}`: the root's re-exports.
            for (at, _) in line.match_indices("crate::{") {
                for (item, module) in reexported {
                    if line[at..].contains(item) {
                        named.insert(module.to_owned());
                    }
                }
            }
        }
        named.remove(&name);
        let entry: &mut BTreeSet<String> = modules.entry(name).or_default();
        entry.extend(named);
    }
    let known: BTreeSet<String> = modules.keys().cloned().collect();
    for named in modules.values_mut() {
        named.retain(|m| known.contains(m));
    }
    modules
}

#[test]
fn the_pipelines_modules_import_one_another_without_a_loop() {
    let modules = imports();
    assert!(modules.len() > 15, "{modules:?}");
    // A module's place: it imports only modules placed before it.
    let mut placed: Vec<String> = Vec::new();
    while placed.len() < modules.len() {
        let next = modules.iter().find(|(name, named)| {
            !placed.contains(name) && named.iter().all(|m| placed.contains(m))
        });
        match next {
            Some((name, _)) => placed.push(name.clone()),
            None => {
                let left: BTreeMap<_, _> = (modules.iter())
                    .filter(|(name, _)| !placed.contains(name))
                    .collect();
                panic!("modules that import one another in a loop: {left:?}");
            }
        }
    }
    // The reading comes before the solving, the solving before the sinks.
    let at = |m: &str| placed.iter().position(|p| p == m).unwrap();
    assert!(
        at("columns") < at("row") && at("row") < at("flights"),
        "{placed:?}"
    );
    assert!(
        at("flights") < at("tally") && at("pieces") < at("summary"),
        "{placed:?}"
    );
}
