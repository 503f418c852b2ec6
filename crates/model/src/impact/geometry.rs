//! Where the bat meets the ball in three dimensions (docs/swing-3d.md):
//! the bat's axis from its tilt, its direction and the batter's hand; the
//! undercut E measured square to that axis; and the paper's impact frame
//! (n1, n2, n3) carried along with the bat.
//!
//! With b̂ = (−sin φ, 0, cos φ), the horizontal square to the bat's
//! direction φ ([`frame::backspin_axis`]), and h = ±1 the batter's hand:
//! - the bat's velocity points along ŵ = (cos φ, 0, sin φ) tipped up by ψ;
//! - its axis, from the hands to the barrel, is â = h·cos τ·b̂ − sin τ·ŷ
//!   (τ > 0: the barrel below the hands) at the bottom of the swing's arc
//!   (ψ = 0); a bat rising through the contact lies in its swing plane,
//!   square to its velocity ([`BatFrame::swung`]), or leading it by λ
//!   within that plane ([`BatFrame::leading`]);
//! - "up, square to the bat" is û = h·sin τ·b̂ + cos τ·ŷ, the unit vector
//!   square to â in the vertical plane that holds â;
//! - the ball's centre sits at (r_b + r_B)(cos θ·ŵ + sin θ·û) from the
//!   axis, so E = (r_b + r_B)·sin θ is its offset along û, as Eq. (1) has
//!   it; at τ = φ = 0, ŵ = x̂ and û = ŷ: the paper's geometry exactly.

use nalgebra::Vector3;

use crate::frame;
use crate::scene::Hand;

/// The bat at contact: three orthonormal directions in the flight frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BatFrame {
    /// â, along the bat from the hands to the barrel.
    pub axis: Vector3<f64>,
    /// û, square to the axis in its vertical plane, upward.
    pub up: Vector3<f64>,
    /// ŵ, the horizontal square to the axis (the bat's velocity's
    /// horizontal direction at the bottom of the arc, ψ = 0).
    pub forward: Vector3<f64>,
    /// The unit direction of the bat's velocity.
    pub path: Vector3<f64>,
}

/// The barrel's drop below the hands δ and the turn ε of the bat's heading
/// (rad, for a right-handed batter; a left-handed one's turn is −ε) of a
/// bat swung at `swing_angle` ψ above the horizontal within a swing plane
/// tilted `plane_tilt` T (MLB's swing path tilt), its velocity square to
/// its axis. The sweet spot moves as a point of a rigid bat turning in its
/// plane about the hands, v = ω × r, so its velocity is square to the bat
/// (the knob's own motion along the bat is left out); the plane holds both
/// the velocity v̂ and the axis â. With q̂ = −sin ψ·ŵ + cos ψ·ŷ, square to v̂
/// in its vertical plane, â = h·cos χ·b̂ − sin χ·q̂ is square to v̂ for any χ,
/// and the plane's normal v̂ × â has the vertical part cos χ·cos ψ = cos T:
/// - cos χ = cos T / cos ψ, so sin δ = −â·ŷ = sin χ·cos ψ
///   = √(sin² T − sin² ψ): the barrel drops T at the bottom of the arc
///   (ψ = 0) and less as the bat rises through the contact;
/// - where |ψ| ≥ |T| no plane of that tilt holds the velocity: the bat is
///   level (χ = 0), its plane tilted by the rise itself, as the paper's
///   level bat swung at ψ is;
/// - â's horizontal part, h·cos χ·b̂ + sin χ·sin ψ·ŵ, turns the bat's
///   heading by ε = atan2(−sin χ·sin ψ, cos χ): an upswing puts the barrel
///   out in front of the hands, as past the bottom of a tilted arc.
///
/// At T = 0, δ = ε = 0 exactly: the paper's level bat, whatever ψ.
pub fn barrel_in_swing_plane(plane_tilt: f64, swing_angle: f64) -> (f64, f64) {
    let cos_chi = plane_tilt.cos() / swing_angle.cos();
    if plane_tilt == 0.0 || cos_chi >= 1.0 {
        return (0.0, 0.0);
    }
    let sin_chi = (1.0 - cos_chi * cos_chi).sqrt().copysign(plane_tilt);
    let drop = (sin_chi * swing_angle.cos()).asin();
    let turn = (-sin_chi * swing_angle.sin()).atan2(cos_chi);
    (drop, turn)
}

/// The most a bat may lead its path (rad), either way: ±45°. sin λ is the
/// share of the contact point's speed that runs along the bat, the hands'
/// drive along it over the sweet spot's speed ([`BatFrame::leading`]); at
/// 45° the bat slides along itself as fast as it sweeps across, and beyond
/// it would slide faster than it sweeps: a bat dragged along its length,
/// which "the undercut square to the bat" of Eq. (1) does not describe, and
/// no swing (docs/swing-3d.md, *The bat's lead over its path*).
pub const MOST_LEAD: f64 = std::f64::consts::FRAC_PI_4;

impl BatFrame {
    /// The bat tilted `tilt` (barrel below the hands), swung toward
    /// `direction`, held by a batter of `hand`.
    pub fn new(tilt: f64, direction: f64, hand: Hand) -> BatFrame {
        let (sin_tilt, cos_tilt) = tilt.sin_cos();
        let square = frame::backspin_axis(direction);
        let h = hand.sign();
        let forward = frame::horizontal(direction);
        BatFrame {
            axis: square * (h * cos_tilt) - Vector3::y() * sin_tilt,
            up: square * (h * sin_tilt) + Vector3::y() * cos_tilt,
            forward,
            path: forward,
        }
    }

    /// The bat swung at `swing_angle` ψ above the horizontal, its velocity's
    /// horizontal direction `direction` φ, in a swing plane tilted
    /// `plane_tilt` (the key `bat.tilt`): the barrel's drop and heading from
    /// [`barrel_in_swing_plane`], so the velocity is square to the axis.
    /// At a level plane (the paper's) this is [`BatFrame::new`]`(0, φ, h)`
    /// with the velocity tipped up by ψ, to the bit.
    ///
    /// A bat that leads its path by `lead` λ (rad, [`BatFrame::leading`])
    /// is turned within that plane; λ = 0, the square bat, is the frame
    /// above to the bit.
    pub fn swung(
        plane_tilt: f64,
        swing_angle: f64,
        direction: f64,
        lead: f64,
        hand: Hand,
    ) -> BatFrame {
        let (drop, turn) = barrel_in_swing_plane(plane_tilt, swing_angle);
        let mut bat = BatFrame::new(drop, direction + turn * hand.sign(), hand);
        let (sin, cos) = swing_angle.sin_cos();
        bat.path = frame::horizontal(direction) * cos + Vector3::y() * sin;
        match lead == 0.0 {
            true => bat,
            false => bat.leading(lead, hand),
        }
    }

    /// This bat turned by `lead` λ within the plane that holds its axis and
    /// its path, the barrel toward the path (forward, ahead of the hands'
    /// square position), its path kept: â' = cos λ·â + sin λ·v̂, for a bat
    /// square to its path (â·v̂ = 0, as [`BatFrame::swung`] gives it).
    ///
    /// Statcast's `attack_direction` and `attack_angle` are the sweet
    /// spot's velocity v̂, not the bat's orientation. The sweet spot of a bat
    /// turning at ω whose knob moves at v_knob moves at v = v_knob + ω × r,
    /// and ω × r is square to the bat, so v·â = v_knob·â: a bat square to
    /// its sweet spot's path is one whose hands move square to it. Where the
    /// hands drive along the bat toward the barrel as it releases, the
    /// barrel leads: sin λ = v_knob·â / |v| (docs/swing-3d.md, *The bat's
    /// lead over its path*). The axis keeps its plane, so the barrel's drop
    /// and heading follow: drop δ' = asin(−â'·ŷ), heading from â''s
    /// horizontal part.
    pub fn leading(&self, lead: f64, hand: Hand) -> BatFrame {
        let (sin, cos) = lead.sin_cos();
        let axis = self.axis * cos + self.path * sin;
        let drop = (-axis.y).clamp(-1.0, 1.0).asin();
        // â = h·cos δ·b̂(φ) − sin δ·ŷ with b̂(φ) = (−sin φ, 0, cos φ).
        let h = hand.sign();
        let heading = (-h * axis.x).atan2(h * axis.z);
        BatFrame {
            path: self.path,
            ..BatFrame::new(drop, heading, hand)
        }
    }

    /// The bat's velocity (m/s): `speed` along its path.
    pub fn velocity(&self, speed: f64) -> Vector3<f64> {
        self.path * speed
    }
}

/// The impact frame of the paper's Fig. 1, in the flight frame: n3 from the
/// bat's axis to the ball's centre, n2 along the bat (+z for either hand at
/// a level square contact, as the paper's), n1 = n2 × n3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactFrame {
    pub bat: BatFrame,
    pub n1: Vector3<f64>,
    pub n2: Vector3<f64>,
    pub n3: Vector3<f64>,
}

impl ContactFrame {
    /// The frame for a normal at `normal_angle` θ (Eq. 1) from ŵ toward û.
    pub fn new(bat: BatFrame, normal_angle: f64, hand: Hand) -> ContactFrame {
        let (sin, cos) = normal_angle.sin_cos();
        let n3 = bat.forward * cos + bat.up * sin;
        // The paper's n2 is +z for a right-handed batter, whose barrel
        // points that way; a left-handed batter's points the other way, and
        // n2 along −â keeps n1 = n2 × n3 the paper's n1 at a square contact.
        let n2 = bat.axis * hand.sign();
        ContactFrame {
            bat,
            n1: n2.cross(&n3),
            n2,
            n3,
        }
    }

    /// The flight-frame vector of impact-frame components (c1, c2, c3).
    pub fn to_flight(&self, c1: f64, c2: f64, c3: f64) -> Vector3<f64> {
        self.n1 * c1 + self.n2 * c2 + self.n3 * c3
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn orthonormal(vectors: [Vector3<f64>; 3]) -> bool {
        let [a, b, c] = vectors;
        let unit = |v: Vector3<f64>| (v.norm() - 1.0).abs() < 1e-15;
        unit(a) && unit(b) && unit(c) && a.dot(&b).abs() < 1e-15 && a.dot(&c).abs() < 1e-15
    }

    #[test]
    fn a_level_square_bat_is_the_papers() {
        for hand in Hand::ALL {
            let bat = BatFrame::new(0.0, 0.0, hand);
            assert_eq!(bat.forward, Vector3::x());
            assert_eq!(bat.up, Vector3::y());
            assert_eq!(bat.axis, Vector3::z() * hand.sign());
            let theta: f64 = 0.3791;
            let f = ContactFrame::new(bat, theta, hand);
            assert_eq!(f.n3, Vector3::new(theta.cos(), theta.sin(), 0.0));
            assert_eq!(f.n2, Vector3::z());
            assert_eq!(f.n1, Vector3::new(-theta.sin(), theta.cos(), 0.0));
        }
    }

    #[test]
    fn the_frames_are_orthonormal_and_right_handed() {
        for (tilt, direction) in [(0.5, 0.3), (-0.4, -0.9), (1.0, 0.0), (0.2, 1.0)] {
            for hand in Hand::ALL {
                let bat = BatFrame::new(tilt, direction, hand);
                assert!(orthonormal([bat.axis, bat.up, bat.forward]));
                // The barrel is below the hands for a positive tilt, up is up.
                assert!((bat.axis.y + tilt.sin()).abs() < 1e-15 && bat.up.y > 0.0);
                let f = ContactFrame::new(bat, 0.4, hand);
                assert!(orthonormal([f.n1, f.n2, f.n3]));
                assert!((f.n2.cross(&f.n3) - f.n1).norm() < 1e-15);
                assert!((f.n3.cross(&f.n1) - f.n2).norm() < 1e-15);
                // E is n3's offset along û: (r_b + r_B)·sin θ.
                assert!((f.n3.dot(&bat.up) - 0.4f64.sin()).abs() < 1e-15);
                assert!(f.n3.dot(&bat.axis).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn a_swung_bat_moves_square_to_itself_in_its_tilted_plane() {
        for (tilt, swing_angle, direction) in [
            (0.5585, 0.1594, 0.0),
            (0.5585, 0.35, -0.3),
            (0.69, -0.2, 0.4),
            (-0.4, 0.3, 0.1),
            (0.3, 0.45, 0.2),
        ] {
            for hand in Hand::ALL {
                let bat = BatFrame::swung(tilt, swing_angle, direction, 0.0, hand);
                assert!(orthonormal([bat.axis, bat.up, bat.forward]));
                let path = bat.path;
                // The velocity keeps the keys' meaning: ψ above the
                // horizontal, heading φ; and it is square to the bat.
                assert!((path.y - f64::sin(swing_angle)).abs() < 1e-15);
                assert!((path.z.atan2(path.x) - direction).abs() < 1e-14);
                assert!(path.dot(&bat.axis).abs() < 1e-15);
                // The plane holding velocity and bat is tilted by the key,
                // unless the swing rises more steeply than it (a level bat).
                let normal = path.cross(&bat.axis).normalize();
                let plane = normal.y.abs().acos();
                let expected = tilt.abs().max(swing_angle.abs());
                assert!((plane - expected).abs() < 1e-12, "{plane} {expected}");
                // The barrel drops √(sin²T − sin²ψ), less than T once the bat
                // rises or falls through the contact.
                let drop = (tilt.sin().powi(2) - swing_angle.sin().powi(2))
                    .max(0.0)
                    .sqrt();
                assert!((-bat.axis.y - drop.copysign(tilt)).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn a_level_plane_is_the_papers_bat_to_the_bit() {
        for hand in Hand::ALL {
            for (swing_angle, direction) in [(0.1594, 0.0), (-0.3, 0.25), (0.7, -0.5)] {
                let bat = BatFrame::swung(0.0, swing_angle, direction, 0.0, hand);
                let level = BatFrame::new(0.0, direction, hand);
                assert_eq!(
                    (bat.axis, bat.up, bat.forward),
                    (level.axis, level.up, level.forward)
                );
                let (sin, cos) = f64::sin_cos(swing_angle);
                assert_eq!(
                    bat.velocity(30.0),
                    (level.forward * cos + Vector3::y() * sin) * 30.0
                );
            }
        }
        // At the bottom of a tilted arc the bat is `new`'s.
        let bottom = BatFrame::swung(0.5, 0.0, 0.2, 0.0, Hand::Right);
        let new = BatFrame::new(0.5, 0.2, Hand::Right);
        assert!((bottom.axis - new.axis).norm() < 1e-15);
        assert_eq!(bottom.path, new.forward);
    }

    #[test]
    fn a_leading_bat_turns_in_its_plane_toward_its_path() {
        for (tilt, swing_angle, direction, lead) in [
            (0.5585, 0.1594, 0.0, 0.15),
            (0.5585, 0.35, -0.3, -0.2),
            (0.69, -0.2, 0.4, 0.6),
            (0.0, 0.3, 0.1, 0.1),
        ] {
            for hand in Hand::ALL {
                let square = BatFrame::swung(tilt, swing_angle, direction, 0.0, hand);
                let bat = BatFrame::swung(tilt, swing_angle, direction, lead, hand);
                assert!(orthonormal([bat.axis, bat.up, bat.forward]));
                // The path is the measured one; the sweet spot now moves
                // sin λ of its speed along the bat, toward the barrel's end
                // for a positive lead.
                assert_eq!(bat.path, square.path);
                assert!((bat.axis.dot(&bat.path) - f64::sin(lead)).abs() < 1e-15);
                // Turned within the plane of the square bat and its path.
                let plane = square.path.cross(&square.axis);
                assert!(bat.axis.dot(&plane).abs() < 1e-15);
                let turned = square.axis.dot(&bat.axis).clamp(-1.0, 1.0).acos();
                assert!((turned - lead.abs()).abs() < 1e-7, "{turned} {lead}");
                // The frame is `new`'s for the new axis: up square to it in
                // its vertical plane, forward horizontal.
                assert!(bat.up.y > 0.0 && bat.forward.y == 0.0);
                assert!(bat.up.dot(&bat.axis).abs() < 1e-15);
            }
            // A left-handed batter leading by λ mirrors a right-handed one
            // swung toward −φ and leading by λ.
            let right = BatFrame::swung(tilt, swing_angle, -direction, lead, Hand::Right);
            let left = BatFrame::swung(tilt, swing_angle, direction, lead, Hand::Left);
            let mirror = |v: Vector3<f64>| Vector3::new(v.x, v.y, -v.z);
            assert!((left.axis - mirror(right.axis)).norm() < 1e-15);
            assert!((left.up - mirror(right.up)).norm() < 1e-15);
            assert!((left.path - mirror(right.path)).norm() < 1e-15);
        }
        // A positive lead puts a square, level bat's barrel out in front of
        // the hands (toward the pitcher) for either hand.
        for hand in Hand::ALL {
            let bat = BatFrame::swung(0.0, 0.0, 0.0, 0.2, hand);
            assert!((bat.axis.x - f64::sin(0.2)).abs() < 1e-15);
        }
    }

    #[test]
    fn a_right_handed_barrel_points_to_first_base_and_down() {
        let bat = BatFrame::new(0.5, 0.0, Hand::Right);
        assert!(bat.axis.z > 0.0 && bat.axis.y < 0.0 && bat.axis.x == 0.0);
        // Pulled (toward left field), the barrel is out in front of the hands.
        let pulled = BatFrame::new(0.5, -0.4, Hand::Right);
        assert!(pulled.axis.x > 0.0);
        // A left-handed batter is the mirror image in z.
        let left = BatFrame::new(0.5, 0.4, Hand::Left);
        let mirror = |v: Vector3<f64>| Vector3::new(v.x, v.y, -v.z);
        assert_eq!(left.axis, mirror(pulled.axis));
        assert_eq!(left.up, mirror(pulled.up));
        assert_eq!(left.forward, mirror(pulled.forward));
    }
}
