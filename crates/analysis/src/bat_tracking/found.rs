//! What a solved swing's numbers rest on (issue 37, item 2): for each swing
//! quantity, whether tracking measured it, the solve found it, or it is the
//! prior (the scene's value, held); and Baseball Savant's own squared-up
//! beside the model's.

use super::{SolvedSwing, TrackedSwing};

/// How one swing quantity was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum How {
    /// A column of the row gave it (bat tracking).
    Measured,
    /// The solve found it, so that the impact gives the measured launch.
    Solved,
    /// Neither: the scene's value (the prior), held through the solve.
    Prior,
}

impl How {
    /// As the output writes it.
    pub fn name(self) -> &'static str {
        match self {
            How::Measured => "measured",
            How::Solved => "solved",
            How::Prior => "prior",
        }
    }
}

/// How each quantity of a solved swing was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Found {
    /// ψ: `attack_angle`; else held at the prior where the contact's speed
    /// was solved (off the sweet spot), else solved (at the sweet spot).
    pub angle: How,
    /// The bat's direction: `attack_direction`; else solved toward the
    /// spray; else the scene's.
    pub direction: How,
    /// The swing plane's tilt: `swing_path_tilt`, else the scene's (the
    /// league's 32° unless the user gave `bat.tilt`).
    pub tilt: How,
    /// The bat's speed at the contact: solved off the sweet spot (and
    /// wherever the attack angle is measured); else `bat_speed` itself.
    pub contact_speed: How,
    /// E: always solved.
    pub undercut: How,
    /// The bat's lead over its path: solved toward the spray where
    /// `attack_direction` measures the path; else the scene's (0, the
    /// square bat: without a measured path the lead and the direction
    /// turn the launch alike, and the direction is solved).
    pub lead: How,
}

impl Found {
    /// How `solved`, the answer for `swing`, was found.
    pub fn of(swing: &TrackedSwing, solved: &SolvedSwing) -> Found {
        let measured_or = |given: bool, otherwise: How| match given {
            true => How::Measured,
            false => otherwise,
        };
        Found {
            angle: measured_or(
                swing.attack_angle.is_some(),
                match solved.off_sweet_spot {
                    true => How::Prior,
                    false => How::Solved,
                },
            ),
            direction: measured_or(
                swing.attack_direction.is_some(),
                match swing.spray_to_solve() {
                    Some(_) => How::Solved,
                    None => How::Prior,
                },
            ),
            tilt: measured_or(swing.tilt.is_some(), How::Prior),
            contact_speed: match solved.off_sweet_spot {
                true => How::Solved,
                false => How::Measured,
            },
            undercut: How::Solved,
            lead: match swing.attack_direction.and(swing.spray) {
                Some(_) => How::Solved,
                None => How::Prior,
            },
        }
    }
}

/// Baseball Savant's squared-up: the exit speed over the most the swing
/// could give, taken as 1.23·`bat_speed` + 0.23·`release_speed` (the pitch
/// at release, not at the plate). Source: Baseball Savant's bat-tracking
/// glossary ("Squared-up rate": "how much exit velocity was obtained,
/// compared to the maximum possible exit velocity available, given the
/// swing speed and pitch speed"; max EV = 1.23 × bat speed + 0.23 × pitch
/// speed, Nathan's linear form EV = q·V_pitch + (1 + q)·V_bat at q = 0.23).
/// Any one unit for the three speeds.
pub fn savant_squared_up(exit_speed: f64, bat_speed: f64, release_speed: f64) -> f64 {
    exit_speed / (1.23 * bat_speed + 0.23 * release_speed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn savant_squared_up_is_ev_over_its_linear_most() {
        // 100 mph off a 70-mph bat against a 95-mph pitch: most 107.95.
        let squared = savant_squared_up(100.0, 70.0, 95.0);
        assert!((squared - 100.0 / 107.95).abs() < 1e-15, "{squared}");
        assert!((squared - 0.926355).abs() < 1e-6);
        // Units cancel: the same in m/s.
        let mph = 0.44704;
        let si = savant_squared_up(100.0 * mph, 70.0 * mph, 95.0 * mph);
        assert!((si - squared).abs() < 1e-15);
    }
}
