//! The keys of a preset's `[field]` section: the fence.

use super::Fence;
use model::keys::{Bounds, InputError, read_in_system, read_typed};
use units::{Quantity, UnitSystem};

/// One key of a preset's `[field]`: the fence the explorer draws, not an
/// input of the physics (so not in [`model::keys::KEYS`]). The TOML
/// reader and `--set` both take their bounds and defaults from here.
pub struct FieldKey {
    pub name: &'static str,
    pub unit: &'static str,
    pub description: &'static str,
    pub bounds: Bounds,
    /// The value taken when a preset sets only the other key.
    pub default: f64,
    pub get: fn(&Fence) -> f64,
    pub set: fn(&mut Fence, f64),
}

/// `field.fence_distance` and `field.fence_height`.
pub const FIELD_KEYS: [FieldKey; 2] = [
    FieldKey::new(
        "field.fence_distance",
        "fence distance from the plate (drawn by the explorer)",
        (1000.0, 121.9),
        |f| f.distance,
        |f, v| f.distance = v,
    ),
    FieldKey::new(
        "field.fence_height",
        "fence height (drawn by the explorer)",
        (100.0, 3.0),
        |f| f.height,
        |f, v| f.height = v,
    ),
];

impl FieldKey {
    /// A value typed for this key (`400ft`, or metres bare), in metres,
    /// checked against the bounds, as [`model::keys::Key::read`].
    pub fn read(&self, text: &str) -> Result<f64, InputError> {
        read_typed(
            (self.name, Quantity::Distance, self.unit, self.bounds),
            text,
        )
    }

    /// [`FieldKey::read`] typed under `system`: a bare number in the unit
    /// shown there (feet under imperial).
    pub fn read_in(&self, text: &str, system: UnitSystem) -> Result<f64, InputError> {
        read_in_system(
            (self.name, Quantity::Distance, self.unit, self.bounds),
            text,
            system,
        )
    }

    /// A length in metres in (0, max], `default` when not given.
    const fn new(
        name: &'static str,
        description: &'static str,
        (max, default): (f64, f64),
        get: fn(&Fence) -> f64,
        set: fn(&mut Fence, f64),
    ) -> FieldKey {
        FieldKey {
            name,
            unit: "m",
            description,
            bounds: Bounds {
                min: 0.0,
                max,
                min_exclusive: true,
                max_exclusive: false,
            },
            default,
            get,
            set,
        }
    }
}

impl Fence {
    /// The preset's fence as a park's: the same distance and height in every
    /// fair direction.
    pub fn uniform(self) -> model::park::Fence {
        model::park::Fence::uniform(self.distance, self.height)
    }

    /// The generic fence: `field.fence_distance` and `field.fence_height`'s
    /// defaults (121.9 m, 3.0 m), what a flight is measured against when no
    /// park is chosen.
    pub fn generic() -> Fence {
        Fence {
            distance: FIELD_KEYS[0].default,
            height: FIELD_KEYS[1].default,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_generic_fence_is_400_feet_out_and_3_metres_high_everywhere() {
        let fence = Fence::generic().uniform();
        for direction in [-0.785, 0.0, 0.4] {
            let at = fence.at(direction).unwrap();
            assert_eq!((at.distance, at.height), (121.9, 3.0));
        }
    }
}
