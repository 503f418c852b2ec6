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

/// The launch angles (°) over which measured spins follow the relation;
/// outside them it is held at the nearer end. Measured on 5,344 balls of
/// April 2018 with Trackman's spin (`../shared/data/`, docs/accuracy.md):
/// the median spin rises as the relation does up to the 40–50° band
/// (4,565 rpm, the relation 4,637 at 45°) and then stays flat (4,758,
/// 4,822 and 4,685 rpm at 50–60°, 60–70° and 70–90°), where the relation
/// would go on to 9,917 rpm at 89°: past a glancing contact the bat's
/// friction gives no more spin. Below −10° there are no measured spins
/// (1 ball); the relation is not extended into them.
pub const MEASURED_ANGLES: (f64, f64) = (-10.0, 45.0);

/// The launch directions (°) the relation was made for: fair territory.
/// A ball fielded foul or behind the plate keeps the sidespin of the
/// nearer foul line.
pub const FAIR_DIRECTIONS: f64 = 45.0;

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
/// θ and φ in degrees, θ held within [`MEASURED_ANGLES`] and φ within
/// [`FAIR_DIRECTIONS`]. A right-handed batter's ball to straightaway
/// centre slices toward right field (849 rpm); pulled 9° to left field it
/// flies straight; pulled further it hooks.
pub fn nathan_spin(angle: f64, direction: f64, side: Option<Side>) -> (f64, f64) {
    let theta = angle
        .to_degrees()
        .clamp(MEASURED_ANGLES.0, MEASURED_ANGLES.1);
    let phi = direction
        .to_degrees()
        .clamp(-FAIR_DIRECTIONS, FAIR_DIRECTIONS);
    let s = Side::sign(side);
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
        let (_, at_half) = nathan_spin(0.5, 0.5, right);
        assert!((at_half - at_0 - 0.5 * SIDESPIN_PER_DIRECTION).abs() < 1e-9);
    }

    #[test]
    fn the_estimate_is_held_where_measured_spins_stop_following_it() {
        let right = Some(Side::Right);
        let at =
            |theta: f64, phi: f64| rpm(nathan_spin(theta.to_radians(), phi.to_radians(), right));
        // 45°: −763 + 120·45 = 4637 rpm of backspin, and no more above it
        // (measured spins stay near 4,700 rpm up to 90°).
        assert!(close(at(45.0, 0.0), (4637.0, 849.0)));
        assert!(close(at(80.0, 0.0), at(45.0, 0.0)));
        // −10°: 1963 rpm of topspin, held below (a chopper at −88° was
        // 9,600 rpm of topspin, past any spin a batted ball has shown).
        assert!(close(at(-10.0, 0.0), (-1963.0, 849.0)));
        assert!(close(at(-88.0, 0.0), at(-10.0, 0.0)));
        // A ball fielded foul keeps the foul line's sidespin: 849 + 94·45.
        assert!(close(at(20.0, 84.0), at(20.0, 45.0)));
        assert!(close(at(20.0, 84.0), (-763.0 + 2400.0 + 945.0, 5079.0)));
        // The largest estimate anywhere: under the 1000 rad/s a batch takes.
        let (back, side) = nathan_spin(1.5, 1.5, right);
        assert!(back.hypot(side) < 800.0, "{}", back.hypot(side));
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
