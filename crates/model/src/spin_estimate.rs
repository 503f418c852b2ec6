//! A batted ball's spin when nobody measured it: Alan Nathan's estimate
//! from the launch angle, the launch direction and the batter's side, as
//! his 3-D trajectory calculator fills it in (A. M. Nathan,
//! "TrajectoryCalculator-new-3D-May2021.xlsx", sheet
//! BattedBallTrajectory-1, cells G4 and G5:
//! `=-763+120*theta+21*phi*sign` and `=-sign*849-94*phi`, sign = +1 for a
//! right-handed batter, −1 for a left-handed one;
//! baseball.physics.illinois.edu/trajectory-calculator-new3D.html). Its
//! sidespin is positive toward left field; here it is turned into
//! [`super::frame`]'s sign (positive curves the ball toward right field).
//! docs/spin-estimate.md checks the signs against the physics.

use std::f64::consts::TAU;

/// rad/s per rpm.
const RAD_PER_S_PER_RPM: f64 = TAU / 60.0;

/// How fast the estimated sidespin grows with the launch direction:
/// 94 rpm per degree, in (rad/s)/rad (94·(2π/60)·(180/π) = 564).
pub const SIDESPIN_PER_DIRECTION: f64 = 94.0 * 6.0;

/// The batter's side, as Statcast's `stand` gives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    Right,
    Left,
}

impl Side {
    /// Nathan's `sign`: +1 for a right-handed batter, −1 for a left-handed
    /// one; 0 when the side is unknown, which averages the two (the
    /// relation is linear in it).
    pub fn sign(side: Option<Side>) -> f64 {
        match side {
            Some(Side::Right) => 1.0,
            Some(Side::Left) => -1.0,
            None => 0.0,
        }
    }
}

/// Backspin and sidespin (rad/s; sidespin positive curving the ball toward
/// right field) of a ball launched at `angle` above the horizontal in
/// `direction` (rad, from the centre-field line, positive toward right
/// field) by a batter on `side`:
///
///   backspin = −763 + 120·θ + 21·s·φ   rpm
///   sidespin =  849·s + 94·φ           rpm
///
/// θ and φ in degrees. A right-handed batter's ball to straightaway centre
/// slices toward right field (849 rpm); pulled 9° to left field it flies
/// straight; pulled further it hooks.
pub fn nathan_spin(angle: f64, direction: f64, side: Option<Side>) -> (f64, f64) {
    let (theta, phi, s) = (angle.to_degrees(), direction.to_degrees(), Side::sign(side));
    let backspin = -763.0 + 120.0 * theta + 21.0 * s * phi;
    let sidespin = 849.0 * s + 94.0 * phi;
    (backspin * RAD_PER_S_PER_RPM, sidespin * RAD_PER_S_PER_RPM)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rpm((back, side): (f64, f64)) -> (f64, f64) {
        (back / RAD_PER_S_PER_RPM, side / RAD_PER_S_PER_RPM)
    }

    fn close((a, b): (f64, f64), (c, d): (f64, f64)) -> bool {
        (a - c).abs() < 1e-9 && (b - d).abs() < 1e-9
    }

    #[test]
    fn the_spreadsheets_examples_in_our_sign() {
        // docs/spin-estimate.md: a right-handed batter at 28°.
        let right = Some(Side::Right);
        let at = |phi: f64| rpm(nathan_spin(28f64.to_radians(), phi.to_radians(), right));
        assert!(close(at(-30.0), (1967.0, -1971.0)), "{:?}", at(-30.0));
        assert!(close(at(0.0), (2597.0, 849.0)));
        assert!(close(at(30.0), (3227.0, 3669.0)));
        // Straight (no sidespin) pulled 849/94 = 9.03° toward left field.
        let straight = rpm(nathan_spin(0.5, (-849.0f64 / 94.0).to_radians(), right)).1;
        assert!(straight.abs() < 1e-9);
        let (_, at_0) = nathan_spin(0.5, 0.0, right);
        let (_, at_1) = nathan_spin(0.5, 1.0, right);
        assert!((at_1 - at_0 - SIDESPIN_PER_DIRECTION).abs() < 1e-9);
    }

    #[test]
    fn a_left_handed_batter_is_the_mirror_image() {
        for (angle, direction) in [(0.4, 0.3), (0.6, -0.2), (0.1, 0.0)] {
            let (back_l, side_l) = nathan_spin(angle, direction, Some(Side::Left));
            let (back_r, side_r) = nathan_spin(angle, -direction, Some(Side::Right));
            assert!((back_l - back_r).abs() < 1e-12);
            assert!((side_l + side_r).abs() < 1e-12);
            // Unknown: the average of the two.
            let (back_u, side_u) = nathan_spin(angle, direction, None);
            let (back_r, side_r) = nathan_spin(angle, direction, Some(Side::Right));
            assert!((back_u - 0.5 * (back_l + back_r)).abs() < 1e-12);
            assert!((side_u - 0.5 * (side_l + side_r)).abs() < 1e-12);
        }
    }
}
