//! The launch columns a batch reads, and the units Statcast's come in.

use crate::units::{Quantity, UnitSystem};

/// How a column's values become a launch value in SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Unit {
    Si,
    /// Statcast's `launch_speed`: mph, exactly 0.44704 m/s.
    Mph,
    /// Statcast's `launch_angle`: degrees.
    Degrees,
    /// `spin_rpm`: revolutions per minute, 2π/60 rad/s.
    Rpm,
}

impl Unit {
    /// The explorer's and `--units`' conversion, so that 103 mph is the
    /// same launch to the last bit wherever it is typed.
    pub(super) fn to_si(self, value: f64) -> f64 {
        match self.quantity() {
            None => value,
            Some(quantity) => quantity.unit(UnitSystem::Imperial, "").read(value),
        }
    }

    pub(super) fn quantity(self) -> Option<Quantity> {
        match self {
            Unit::Si => None,
            Unit::Mph => Some(Quantity::Speed),
            Unit::Degrees => Some(Quantity::Angle),
            Unit::Rpm => Some(Quantity::Spin),
        }
    }

    pub(super) fn name(self) -> &'static str {
        match self {
            Unit::Si => "",
            Unit::Mph => "mph",
            Unit::Degrees => "°",
            Unit::Rpm => "rpm",
        }
    }
}

/// The launch keys and the other names their columns may have, with units.
pub(super) const LAUNCH_COLUMNS: [(&str, &[(&str, Unit)]); 3] = [
    (
        "launch.speed",
        &[
            ("launch.speed", Unit::Si),
            ("launch_speed", Unit::Mph),
            // Statcast's older and Trackman's files (the 2018 set).
            ("exit_speed", Unit::Mph),
        ],
    ),
    (
        "launch.angle",
        &[("launch.angle", Unit::Si), ("launch_angle", Unit::Degrees)],
    ),
    (
        "launch.spin",
        &[("launch.spin", Unit::Si), ("spin_rpm", Unit::Rpm)],
    ),
];
