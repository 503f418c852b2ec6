//! Inputs from one source, set key by key.

use super::table::{AIR_KEYS, ATMOSPHERE_KEYS, TEXT_KEYS};
use super::{InputError, Key, Scene};
use units::UnitSystem;

/// Sets keys one by one from one source of inputs (one preset file, one
/// command line's `--set` list), refusing a source that both gives ρ or ν
/// and sets the weather that would derive them, whichever comes first.
/// Sources applied one after another override: a preset's ρ, then
/// `--set environment.temperature=30`, derives ρ and ν from the weather.
///
/// One batch per source, every key of the source through it, then
/// [`Scene::validate`]:
///
/// ```
/// use homerun_model::keys::{InputBatch, InputError};
/// use homerun_model::scene::Scene;
///
/// let mut scene = Scene::default(); // or the preset's scene, for --set
/// let mut batch = InputBatch::new();
/// batch.set(&mut scene, "environment.temperature", 30.0)?; // numbers
/// batch.set_text(&mut scene, "model.lift", "nathan")?; // text, or model names
/// let refused = batch.set(&mut scene, "environment.air_density", 1.2);
/// assert!(matches!(refused, Err(InputError::AirGivenTwice { .. })));
/// scene.validate()?;
/// # Ok::<(), InputError>(())
/// ```
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

    /// [`Scene::set`], refusing a key that contradicts one set before (and
    /// then changing neither the scene nor the batch).
    pub fn set(&mut self, scene: &mut Scene, name: &str, value: f64) -> Result<(), InputError> {
        let key = Scene::key(name)?;
        let next = self.with(key.name)?;
        (key.set)(scene, value);
        *self = next;
        Ok(())
    }

    /// [`InputBatch::set`] for a key already looked up (a batch's column,
    /// set on every row: the lookup by name cost more than the rest).
    pub fn set_key(
        &mut self,
        scene: &mut Scene,
        key: &'static Key,
        value: f64,
    ) -> Result<(), InputError> {
        *self = self.with(key.name)?;
        (key.set)(scene, value);
        Ok(())
    }

    /// [`InputBatch::set_text`] for a numeric key already looked up.
    pub fn set_key_text(
        &mut self,
        scene: &mut Scene,
        key: &'static Key,
        text: &str,
    ) -> Result<(), InputError> {
        let next = self.with(key.name)?;
        (key.set)(scene, key.read(text)?);
        *self = next;
        Ok(())
    }

    /// [`Scene::set_text`], refusing a key that contradicts one set before.
    pub fn set_text(
        &mut self,
        scene: &mut Scene,
        name: &str,
        text: &str,
    ) -> Result<(), InputError> {
        self.set_text_in(scene, name, text, UnitSystem::Si)
    }

    /// [`InputBatch::set_text`] typed under `system` ([`Scene::set_text_in`]).
    pub fn set_text_in(
        &mut self,
        scene: &mut Scene,
        name: &str,
        text: &str,
        system: UnitSystem,
    ) -> Result<(), InputError> {
        let next = if TEXT_KEYS.contains(&name) {
            *self
        } else {
            self.with(Scene::key(name)?.name)?
        };
        scene.set_text_in(name, text, system)?;
        *self = next;
        Ok(())
    }

    /// This batch with key `name` given, or the contradiction it makes.
    fn with(&self, name: &'static str) -> Result<InputBatch, InputError> {
        let mut next = *self;
        if AIR_KEYS.contains(&name) {
            next.given_air.get_or_insert(name);
        } else if ATMOSPHERE_KEYS.contains(&name) {
            next.weather.get_or_insert(name);
        }
        match (next.given_air, next.weather) {
            (Some(given), Some(weather)) => Err(InputError::AirGivenTwice { given, weather }),
            _ => Ok(next),
        }
    }
}
