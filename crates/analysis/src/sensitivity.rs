//! Which input matters: the range gained by one nudge of each input, at the
//! current swing and at the optimal one. The explorer shows both beside its
//! inputs; a nudge here is exactly the explorer's arrow key (the key's step,
//! snapped, validated), so the number says what pressing it will do.

use super::optimum::{Optimizer, OptimizerSettings, Point};
use super::precision::Purpose;
use model::keys::{InputError, Key};
use model::launch::{fly_scene, scene_start};
use model::many::fly_many;
use model::scene::Scene;
use units::UnitSystem;

/// `scene` with `key` moved by `scale` of its step, snapped to a thousandth
/// of the step (so that repeated nudges do not accumulate rounding noise in
/// the display), or why that scene is refused.
pub fn nudge(scene: &Scene, key: &Key, scale: f64) -> Result<Scene, InputError> {
    nudge_in(scene, key, scale, UnitSystem::Si)
}

/// Keys whose 0 means "off", and the value a nudge up from off goes to:
/// one the quantity takes when on, not the smallest step. A baseball's spin
/// decays over 30–50 s (§II.D); 1 s, off plus a step, would stop the spin
/// early in the flight.
const FROM_OFF: [(&str, f64); 1] = [("model.spin_decay", 30.0)];

/// [`nudge`] as a person sees it in `system`: outside SI the step is the
/// key's step in the shown unit rounded to 1, 2 or 5 (`Unit::nice_step`:
/// 1 mph, 100 rpm, 0.5°). A converted value is rarely on that step's grid,
/// so the snap there only removes the conversion's rounding noise, and each
/// nudge moves by the shown step exactly. Up from off, a key of
/// `FROM_OFF` goes to its value when on.
pub fn nudge_in(
    scene: &Scene,
    key: &Key,
    scale: f64,
    system: UnitSystem,
) -> Result<Scene, InputError> {
    let mut nudged = *scene;
    let unit = key.unit_in(system);
    let on = FROM_OFF.iter().find(|(name, _)| *name == key.name);
    if let Some((_, on)) = on.filter(|_| (key.get)(scene) == 0.0 && scale > 0.0) {
        (key.set)(&mut nudged, *on);
    } else if unit.is_identity() {
        let value = (key.get)(scene) + scale * key.step;
        let quantum = key.step * 1e-3;
        (key.set)(&mut nudged, (value / quantum).round() * quantum);
    } else {
        let step = unit.nice_step(key.step);
        let shown = unit.show((key.get)(scene)) + scale * step;
        let quantum = step * 1e-9;
        (key.set)(&mut nudged, unit.read((shown / quantum).round() * quantum));
    }
    nudged.validate()?;
    Ok(nudged)
}

/// The range (m) of a scene's own flight (a swing's or a batted ball's) at
/// the readout's precision, if the ball lands.
fn landed_range(scene: &Scene) -> Option<f64> {
    let flight = fly_scene(scene, Purpose::Readout).flight;
    (flight.landed && flight.range.is_finite()).then_some(flight.range)
}

/// The range gained (m) at the current swing by one step up of `key`: one
/// impact and one flight at the readout's precision (~0.1 ms). `None` when
/// the nudge is refused or either ball does not land.
pub fn range_gain(scene: &Scene, key: &Key, range: f64) -> Option<f64> {
    range_gain_in(scene, key, range, UnitSystem::Si)
}

/// [`range_gain`] for the nudge shown in `system` ([`nudge_in`]).
pub fn range_gain_in(scene: &Scene, key: &Key, range: f64, system: UnitSystem) -> Option<f64> {
    let nudged = nudge_in(scene, key, 1.0, system).ok()?;
    Some(landed_range(&nudged)? - range).filter(|_| range.is_finite())
}

/// [`range_gain_in`] for each of `keys`: the nudged scenes' flights flown
/// in lock-step, as a column of the explorer's gains is asked at once.
pub fn range_gains_in(
    scene: &Scene,
    keys: &[&Key],
    range: f64,
    system: UnitSystem,
) -> Vec<Option<f64>> {
    let mut gains = vec![None; keys.len()];
    if !range.is_finite() {
        return gains;
    }
    let nudged: Vec<(usize, Scene)> = keys
        .iter()
        .enumerate()
        .filter_map(|(k, key)| Some((k, nudge_in(scene, key, 1.0, system).ok()?)))
        .collect();
    let flights = nudged.iter().map(|(_, s)| scene_start(s).0);
    fly_many(
        flights,
        &Purpose::Readout.flight_options(),
        |index, flight| {
            if flight.landed && flight.range.is_finite() {
                gains[nudged[index].0] = Some(flight.range - range);
            }
        },
    );
    gains
}

/// Whether the optimal range depends on `key` at all: not on the swing
/// (E, ψ) it optimises over.
pub fn moves_optimum(key: &Key) -> bool {
    !matches!(key.name, "bat.undercut" | "bat.swing_angle")
}

/// The optimal range gained (m) by one step up of `key`: the optimiser
/// rerun on the nudged scene, warm-started from `optimum` (a few tens of
/// flights, ~1 ms). Both optima stop within the optimiser's 1e-4 m, so the
/// difference is good to ~2e-4 m. `None` when the nudge is refused, the key
/// does not move the optimum, no swing lands, or `cancelled()` says stop.
pub fn optimum_gain(
    scene: &Scene,
    key: &Key,
    optimum: Point,
    cancelled: &dyn Fn() -> bool,
) -> Option<f64> {
    optimum_gain_in(scene, key, optimum, UnitSystem::Si, cancelled)
}

/// [`optimum_gain`] for the nudge shown in `system` ([`nudge_in`]).
pub fn optimum_gain_in(
    scene: &Scene,
    key: &Key,
    optimum: Point,
    system: UnitSystem,
    cancelled: &dyn Fn() -> bool,
) -> Option<f64> {
    if !moves_optimum(key) || !optimum.range.is_finite() {
        return None;
    }
    let nudged = nudge_in(scene, key, 1.0, system).ok()?;
    let mut optimizer = Optimizer::new(
        &nudged,
        (optimum.undercut, optimum.swing_angle),
        Purpose::Optimizer,
        OptimizerSettings::default(),
    );
    let best = optimizer.run(cancelled)?;
    best.range.is_finite().then_some(best.range - optimum.range)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::optimum::optimize;
    use model::keys::KEYS;

    fn key(name: &str) -> &'static Key {
        Scene::key(name).unwrap()
    }

    #[test]
    fn a_nudge_is_one_step_and_refused_past_the_bounds() {
        let scene = Scene::default();
        let faster = nudge(&scene, key("bat.speed"), 1.0).unwrap();
        assert_eq!(faster.bat.speed, 30.5);
        let mut edge = scene;
        edge.bat.friction = 2.0;
        let refused = nudge(&edge, key("bat.friction"), 1.0).unwrap_err();
        assert!(refused.to_string().starts_with("bat.friction = 2.01"));
    }

    #[test]
    fn half_a_metre_per_second_of_bat_speed_is_about_two_metres() {
        // §III: "nearly 5 m" of range per 1 m/s of bat speed near 30 m/s
        // (ours is 4.0 m at the optimum, Fig. 8): a 0.5 m/s step gains 2 m.
        let scene = Scene::default();
        let range = landed_range(&scene).unwrap();
        let gain = range_gain(&scene, key("bat.speed"), range).unwrap();
        assert!((1.7..2.3).contains(&gain), "{gain}");
        // A tail wind of 1 m/s carries the ball farther, a denser air less far.
        assert!(range_gain(&scene, key("environment.wind"), range).unwrap() > 0.5);
        assert!(range_gain(&scene, key("environment.air_density"), range).unwrap() < 0.0);
    }

    #[test]
    fn a_column_of_gains_in_lock_step_is_the_gains_one_by_one() {
        let scene = Scene::default();
        let range = landed_range(&scene).unwrap();
        let keys: Vec<&Key> = model::keys::swing_keys().collect();
        let column = range_gains_in(&scene, &keys, range, UnitSystem::Si);
        let mut compared = 0;
        for (key, gain) in keys.iter().zip(&column) {
            let alone = range_gain(&scene, key, range);
            assert_eq!(gain.is_some(), alone.is_some(), "{}", key.name);
            if let (Some(a), Some(b)) = (gain, alone) {
                // Each within the readout's budget of the truth.
                assert!((a - b).abs() < 2e-6, "{}: {a} {b}", key.name);
                compared += 1;
            }
        }
        assert!(compared >= 20, "{compared} of {}", keys.len());
        assert!(
            (1.7..2.3).contains(
                &column[keys.iter().position(|k| k.name == "bat.speed").unwrap()].unwrap()
            )
        );
    }

    #[test]
    fn the_optimum_gain_equals_two_optimisations_and_ignores_the_swing() {
        let scene = Scene::default();
        let settings = OptimizerSettings::default();
        let base = optimize(&scene, settings);
        let optimum = base.point();
        let gain = optimum_gain(&scene, key("bat.speed"), optimum, &|| false).unwrap();
        let faster = nudge(&scene, key("bat.speed"), 1.0).unwrap();
        let direct = optimize(&faster, settings).range - base.range;
        // Two searches from different starts agree to their stopping tolerance.
        assert!((gain - direct).abs() < 1e-3, "{gain} vs {direct}");
        assert!((1.7..2.3).contains(&gain), "{gain}");
        for name in ["bat.undercut", "bat.swing_angle"] {
            assert_eq!(optimum_gain(&scene, key(name), optimum, &|| false), None);
        }
        // Cancelled: nothing.
        assert_eq!(
            optimum_gain(&scene, &KEYS[0], optimum, &|| true),
            None,
            "a cancelled search reports nothing"
        );
    }
}
