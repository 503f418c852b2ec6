//! The keys of a preset's `[field]` section: the fence.

use super::Fence;
use crate::model::keys::{Bounds, InputError, read_typed};
use crate::units::Quantity;

/// One key of a preset's `[field]`: the fence the explorer draws, not an
/// input of the physics (so not in [`crate::model::keys::KEYS`]). The TOML
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
    /// checked against the bounds, as [`crate::model::keys::Key::read`].
    pub fn read(&self, text: &str) -> Result<f64, InputError> {
        read_typed(
            (self.name, Quantity::Distance, self.unit, self.bounds),
            text,
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
