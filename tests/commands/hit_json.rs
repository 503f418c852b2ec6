//! `homerun hit --json` over random accepted scenes (proptest): every key of
//! `KEYS` and the 3-D swing's (`bat.tilt`, `bat.direction`) drawn anywhere
//! within its bounds, the hand and the drag model, keeping the
//! scenes that `validate()` accepts. Whatever the scene, every number is
//! finite, a null stands only where it means something (no stick, no
//! landing), and a flight either lands or says why not. Rendered through the
//! library, as `homerun hit` would print it.

use std::ops::RangeInclusive;

use clap::Parser as _;
use homerun::Scene;
use homerun::cli::{self, Cli};
use homerun::model::aero::DragModel;
use homerun::model::keys::{EXTENDED_KEYS, KEYS, Key, SWING_3D_KEYS};
use proptest::prelude::*;
use serde_json::Value;

/// The keys drawn: the paper's and the 3-D swing's numbers.
fn drawn() -> impl Iterator<Item = &'static Key> {
    KEYS.iter().chain(
        EXTENDED_KEYS
            .iter()
            .filter(|k| SWING_3D_KEYS.contains(&k.name)),
    )
}

/// Each key's accepted range (an excluded minimum nudged up by one ulp).
fn bounds() -> Vec<RangeInclusive<f64>> {
    drawn()
        .map(|k| {
            let min = if k.bounds.min_exclusive {
                k.bounds.min.next_up()
            } else {
                k.bounds.min
            };
            min..=k.bounds.max
        })
        .collect()
}

/// Accepted scenes, as `--set` arguments.
fn scenes() -> impl Strategy<Value = Vec<String>> {
    (bounds(), 0..DragModel::ALL.len(), any::<bool>()).prop_filter_map(
        "not accepted by validate()",
        |(values, drag, left)| {
            let mut scene = Scene::default();
            for (key, &value) in drawn().zip(&values) {
                (key.set)(&mut scene, value);
            }
            scene.drag = DragModel::ALL[drag];
            scene.validate().ok()?;
            let mut sets: Vec<String> = drawn()
                .zip(&values)
                // `{}` is the shortest text that reads back as the same number.
                .map(|(key, value)| format!("{}={value}", key.name))
                .collect();
            sets.push(format!("model.drag={}", DragModel::ALL[drag].name()));
            sets.push(format!("bat.hand={}", if left { "left" } else { "right" }));
            Some(sets)
        },
    )
}

fn hit(sets: &[String], json: bool) -> String {
    let dir = tempfile::tempdir().unwrap();
    let mut argv = vec![
        "homerun".to_owned(),
        "--presets-dir".to_owned(),
        dir.path().display().to_string(),
        "hit".to_owned(),
    ];
    if json {
        argv.push("--json".to_owned());
    }
    for set in sets {
        argv.extend(["--set".to_owned(), set.clone()]);
    }
    let cli = Cli::try_parse_from(argv).expect("arguments parse");
    cli::render(&cli, cli.command.as_ref().expect("a command"))
        .unwrap_or_else(|e| panic!("an accepted scene was refused: {e}"))
}

/// Every leaf of `value` with its path: "flight.range".
fn leaves<'a>(value: &'a Value, path: String, out: &mut Vec<(String, &'a Value)>) {
    match value {
        Value::Object(map) => {
            for (key, v) in map {
                let path = if path.is_empty() {
                    key.clone()
                } else {
                    format!("{path}.{key}")
                };
                leaves(v, path, out);
            }
        }
        Value::Array(items) => {
            for (k, v) in items.iter().enumerate() {
                leaves(v, format!("{path}[{k}]"), out);
            }
        }
        _ => out.push((path, value)),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn every_number_is_finite_and_a_flight_lands_or_says_why(sets in scenes()) {
        let text = hit(&sets, true);
        let v: Value = serde_json::from_str(&text).unwrap();
        let landed = v["flight"]["landed"].as_bool().expect("landed is a bool");
        let slips = v["impact"]["regime"] == "slip";
        let mut all = Vec::new();
        leaves(&v, String::new(), &mut all);
        prop_assert!(all.len() >= 18, "{text}");
        for (path, value) in all {
            match value {
                // serde_json writes NaN and ±∞ as null: a null is allowed
                // only where it means something.
                Value::Null => prop_assert!(
                    (path == "flight.range" && !landed)
                        || (path == "impact.stick_impulse" && slips),
                    "{path} is null in {text}"
                ),
                Value::Number(n) => prop_assert!(n.as_f64().is_some_and(f64::is_finite), "{path}"),
                Value::String(_) | Value::Bool(_) => {}
                other => prop_assert!(false, "{path}: {other}"),
            }
        }
        prop_assert_eq!(v["flight"]["range"].is_number(), landed);
        if !landed {
            let why = v["flight"]["why_not_landed"].as_str().unwrap_or_default();
            prop_assert!(why.starts_with("did not land within "), "{text}");
        }
        let text = hit(&sets, false);
        prop_assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
        prop_assert_eq!(text.contains("did not land within "), !landed, "{}", text);
    }
}
