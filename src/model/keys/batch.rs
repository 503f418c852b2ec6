//! Inputs from one source, set key by key.

use super::table::{AIR_KEYS, ATMOSPHERE_KEYS, DRAG_KEY, LIFT_KEY};
use super::{InputError, Scene};

/// Sets keys one by one from one source of inputs (one preset file, one
/// command line's `--set` list), refusing a source that both gives ρ or ν
/// and sets the weather that would derive them, whichever comes first.
/// Sources applied one after another override: a preset's ρ, then
/// `--set environment.temperature=30`, derives ρ and ν from the weather.
#[derive(Clone, Copy, Debug, Default)]
pub struct InputBatch {
    /// The first ρ or ν key this source gave.
    given_air: Option<&'static str>,
    /// The first weather key this source gave.
    weather: Option<&'static str>,
}

impl InputBatch {
    pub fn new() -> Self {
        InputBatch::default()
    }

    /// [`Scene::set`], refusing a key that contradicts one set before.
    pub fn set(&mut self, scene: &mut Scene, name: &str, value: f64) -> Result<(), InputError> {
        let key = Scene::key(name)?;
        self.note(key.name)?;
        (key.set)(scene, value);
        Ok(())
    }

    /// [`Scene::set_text`], refusing a key that contradicts one set before.
    pub fn set_text(
        &mut self,
        scene: &mut Scene,
        name: &str,
        text: &str,
    ) -> Result<(), InputError> {
        if name != DRAG_KEY && name != LIFT_KEY {
            self.note(Scene::key(name)?.name)?;
        }
        scene.set_text(name, text)
    }

    fn note(&mut self, name: &'static str) -> Result<(), InputError> {
        if AIR_KEYS.contains(&name) {
            self.given_air.get_or_insert(name);
        } else if ATMOSPHERE_KEYS.contains(&name) {
            self.weather.get_or_insert(name);
        }
        match (self.given_air, self.weather) {
            (Some(given), Some(weather)) => Err(InputError::AirGivenTwice { given, weather }),
            _ => Ok(()),
        }
    }
}
