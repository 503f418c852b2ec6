//! A command's scene: a preset with every `--set` applied, checked before
//! anything is computed. Whatever a user typed is shown escaped and cut
//! ([`escape_for_terminal`]) in the errors.

use std::path::Path;

use super::{SceneArgs, UsageError};
use crate::model::keys::{InputBatch, InputError, TEXT_KEYS};
use crate::model::launch::SceneKind;
use crate::model::scene::Scene;
use crate::preset::{self, FIELD_KEYS, Fence, Preset, cut, escape_for_terminal};
use crate::units::UnitSystem;

/// The longest path Linux opens (PATH_MAX): a longer `--preset` or
/// `--presets-dir` is refused before it is used, so that no error echoes it.
const MAX_PATH: usize = 4096;

impl SceneArgs {
    /// The preset, with every `--set` applied, validated. A bare number
    /// in `--set` is in the unit `--units` shows (`system`): what you see
    /// is what you type.
    pub fn resolve(
        &self,
        presets_dir: Option<&Path>,
        system: UnitSystem,
    ) -> Result<Preset, UsageError> {
        let mut preset = open(&self.preset, presets_dir)?;
        // The --set list is one source: ρ or ν beside the weather is refused.
        let mut batch = InputBatch::new();
        for assignment in &self.set {
            let (key, value) =
                assignment
                    .split_once('=')
                    .ok_or_else(|| UsageError::BadAssignment {
                        assignment: cut(assignment, 80),
                    })?;
            let key = checked_key(key.trim()).map_err(with_field_keys)?;
            if let Some(field) = FIELD_KEYS.iter().find(|f| f.name == key) {
                let fence = preset.fence.get_or_insert(Fence {
                    distance: FIELD_KEYS[0].default,
                    height: FIELD_KEYS[1].default,
                });
                (field.set)(fence, field.read_in(value, system)?);
                continue;
            }
            // A name (a model's, a hand's) too long to be one is shown cut; a number is
            // read whole (its error shows it cut).
            let value = if TEXT_KEYS.contains(&key) {
                cut(value, 80)
            } else {
                value.to_owned()
            };
            batch
                .set_text_in(&mut preset.scene, key, &value, system)
                .map_err(with_field_keys)?;
        }
        if let Some(fence) = &preset.fence {
            for field in &FIELD_KEYS {
                field
                    .bounds
                    .check(field.name, (field.get)(fence), field.unit)?;
            }
        }
        preset.scene.validate()?;
        Ok(preset)
    }
}

impl SceneArgs {
    /// [`SceneArgs::resolve`]'s scene, refused (naming `command`) if it is a
    /// batted ball: `command` needs the pitch, the bat and the impact.
    pub fn resolve_swing(
        &self,
        command: &'static str,
        presets_dir: Option<&Path>,
        system: UnitSystem,
    ) -> Result<Scene, UsageError> {
        let preset = self.resolve(presets_dir, system)?;
        swing_only(command, &preset)?;
        Ok(preset.scene)
    }
}

/// Refuses a batted-ball scene for a command that needs a swing.
pub(super) fn swing_only(command: &'static str, preset: &Preset) -> Result<(), UsageError> {
    match preset.scene.kind {
        SceneKind::Swing => Ok(()),
        SceneKind::BattedBall => Err(UsageError::NotASwing {
            command,
            preset: escape_for_terminal(&preset.name),
        }),
    }
}

/// `key` if it can be printed as it is; otherwise the error for an unknown
/// key, naming it escaped and cut (no key has control characters or is
/// longer than 80 characters).
pub(super) fn checked_key(key: &str) -> Result<&str, InputError> {
    let shown = escape_for_terminal(key);
    if shown == key {
        Ok(key)
    } else {
        Err(Scene::key(&shown).expect_err("no key needs escaping"))
    }
}

/// An unknown key's error, listing the `[field]` keys among the known ones.
fn with_field_keys(error: InputError) -> InputError {
    match error {
        InputError::UnknownKey { key, known } => InputError::UnknownKey {
            key,
            known: [known.as_str()]
                .into_iter()
                .chain(FIELD_KEYS.iter().map(|f| f.name))
                .collect::<Vec<_>>()
                .join(", "),
        },
        other => other,
    }
}

/// The preset named (or at the path) `spec`, refusing first a `spec` too
/// long to be either.
pub fn open(spec: &str, presets_dir: Option<&Path>) -> Result<Preset, UsageError> {
    check_path("--preset", spec)?;
    Ok(preset::load(spec, presets_dir)?)
}

/// Refuses a path too long to open, before any error can echo it.
pub(super) fn check_path(flag: &'static str, text: &str) -> Result<(), UsageError> {
    if text.len() > MAX_PATH {
        return Err(UsageError::TooLong {
            flag,
            text: escape_for_terminal(text),
            length: text.len(),
            max: MAX_PATH,
        });
    }
    Ok(())
}
