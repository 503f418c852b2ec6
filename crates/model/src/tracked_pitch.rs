//! A tracked pitch at the plate: Statcast's (PITCHf/x's) nine-parameter
//! fit, read at the front of the plate, where the bat meets it.
//!
//! Statcast gives each pitch as a constant-acceleration fit (Nathan, "The
//! PITCHf/x coordinate system", and Baseball Savant's CSV documentation):
//! its velocity (vx0, vy0, vz0, ft/s) and acceleration (ax, ay, az, ft/s²)
//! when it passes y = 50 ft, in a frame with its origin at the back tip of
//! home plate, x toward the catcher's right (the first-base side), y toward
//! the pitcher, z up. Then y(t) = 50 + vy0·t + ½·ay·t², and the ball
//! reaches the front of the plate, y = 17/12 ft, when
//! ½·ay·t² + vy0·t + (50 − 17/12) = 0 (the earlier root: vy0 < 0), with
//! velocity v0 + a·t there.
//!
//! The flight frame (`../shared/DESIGN.md`) has x toward centre field, y up,
//! z toward the first-base side: Statcast's (x, y, z) are the flight
//! frame's (z, x, y), a cyclic relabelling (both frames right-handed).

use nalgebra::Vector3;

/// Exactly 0.3048 m to the foot.
const METRES_PER_FOOT: f64 = 0.3048;
/// Where the fit is anchored: y = 50 ft from the back tip of the plate.
pub const FIT_DISTANCE_FT: f64 = 50.0;
/// The front of home plate, 17 in from its back tip (Official Baseball
/// Rules 2.02): where the bat meets the pitch.
pub const FRONT_OF_PLATE_FT: f64 = 17.0 / 12.0;

/// Statcast's fit of one pitch, in its own units and frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PitchFit {
    /// (vx0, vy0, vz0) at y = 50 ft (ft/s).
    pub velocity: [f64; 3],
    /// (ax, ay, az), constant (ft/s²).
    pub acceleration: [f64; 3],
}

/// The pitch where the bat meets it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PitchAtPlate {
    /// The ball's velocity in the flight frame (m/s): x negative, toward
    /// the catcher.
    pub velocity: Vector3<f64>,
    /// Seconds from y = 50 ft to the front of the plate.
    pub time: f64,
}

impl PitchAtPlate {
    /// V̂_b0, the speed at the front of the plate (m/s).
    pub fn speed(&self) -> f64 {
        self.velocity.norm()
    }

    /// γ, the angle of descent below the horizontal (rad, positive
    /// descending), as Eq. (4) defines it for the paper's pitch.
    pub fn descent_angle(&self) -> f64 {
        let v = self.velocity;
        (-v.y).atan2(v.x.hypot(v.z))
    }

    /// The horizontal angle of the pitch's path (rad): positive when it
    /// moves toward the first-base side (+z) as it comes in.
    pub fn lateral_angle(&self) -> f64 {
        let v = self.velocity;
        v.z.atan2(-v.x)
    }
}

impl PitchFit {
    /// The pitch at the front of the plate; `None` if the fit never
    /// reaches it (a ball not moving toward the plate, or not finite).
    pub fn at_front_of_plate(&self) -> Option<PitchAtPlate> {
        let [vx, vy, vz] = self.velocity;
        let [ax, ay, az] = self.acceleration;
        let distance = FIT_DISTANCE_FT - FRONT_OF_PLATE_FT;
        // ½·ay·t² + vy·t + distance = 0, its earlier root written as
        // 2c/(−b + √(b² − 4ac)), which stays exact as ay → 0.
        let discriminant = vy * vy - 2.0 * ay * distance;
        if !(vy < 0.0 && discriminant >= 0.0) {
            return None;
        }
        let time = 2.0 * distance / (-vy + discriminant.sqrt());
        let at = |v: f64, a: f64| (v + a * time) * METRES_PER_FOOT;
        let velocity = Vector3::new(at(vy, ay), at(vz, az), at(vx, ax));
        (time.is_finite() && velocity.iter().all(|c| c.is_finite()))
            .then_some(PitchAtPlate { velocity, time })
    }
}

/// ω_b0 (rad/s, pitched topspin positive, as `pitch.spin`) from Statcast's
/// `release_spin_rate` (rpm) and `spin_axis` (degrees; 180 is pure
/// backspin, 0 pure topspin, seen from behind the pitcher's plane of
/// motion): the part of the spin about the horizontal axis square to the
/// pitch, rate·cos(axis). The rest (about the vertical, and any gyro
/// spin) is left out: the model's pitch spins about that one axis.
pub fn topspin(rate_rpm: f64, axis_degrees: f64) -> f64 {
    rate_rpm * std::f64::consts::TAU / 60.0 * axis_degrees.to_radians().cos()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fastball worked by hand: vy0 = −130 ft/s, ay = 26 ft/s²,
    /// vz0 = −5 ft/s, az = −16 ft/s², vx0 = 6 ft/s, ax = −10 ft/s².
    /// The plate is 50 − 17/12 = 48.583 333 ft away:
    /// 13 t² − 130 t + 48.583 333 = 0, b² − 4ac = 16 900 − 2 526.333 =
    /// 14 373.667, √ = 119.890 228, t = (130 − 119.890 228)/26 = 0.388 837 s.
    /// Then vy = −130 + 26 t = −119.890 228, vz = −5 − 16 t = −11.221 398,
    /// vx = 6 − 10 t = 2.111 626 ft/s; speed √(…) = 120.432 742 ft/s =
    /// 36.707 900 m/s; descent atan(11.221 398/√(119.890 228² + 2.111 626²))
    /// = 5.3463°.
    #[test]
    fn a_fastball_worked_by_hand() {
        let fit = PitchFit {
            velocity: [6.0, -130.0, -5.0],
            acceleration: [-10.0, 26.0, -16.0],
        };
        let plate = fit.at_front_of_plate().expect("it reaches the plate");
        assert!((plate.time - 0.388_837).abs() < 1e-6, "{}", plate.time);
        let ft = plate.velocity / METRES_PER_FOOT;
        assert!((ft.x + 119.890_228).abs() < 1e-5, "{ft:?}");
        assert!((ft.y + 11.221_398).abs() < 1e-5, "{ft:?}");
        assert!((ft.z - 2.111_626).abs() < 1e-5, "{ft:?}");
        assert!((plate.speed() - 36.707_900).abs() < 1e-5);
        assert!((plate.descent_angle().to_degrees() - 5.3463).abs() < 1e-4);
        assert!(plate.lateral_angle() > 0.0);
    }

    /// No acceleration: the ball covers 48.583 ft at 100 ft/s in 0.485 833 s.
    #[test]
    fn without_acceleration_the_time_is_distance_over_speed() {
        let fit = PitchFit {
            velocity: [0.0, -100.0, 0.0],
            acceleration: [0.0; 3],
        };
        let plate = fit.at_front_of_plate().unwrap();
        assert!((plate.time - 0.485_833_333_333).abs() < 1e-12);
        assert_eq!(plate.descent_angle(), 0.0);
        assert!((plate.speed() - 30.48).abs() < 1e-12);
    }

    #[test]
    fn a_ball_moving_away_never_arrives() {
        let away = PitchFit {
            velocity: [0.0, 10.0, 0.0],
            acceleration: [0.0; 3],
        };
        assert_eq!(away.at_front_of_plate(), None);
        // Slowing so hard that it stops short.
        let stops = PitchFit {
            velocity: [0.0, -20.0, 0.0],
            acceleration: [0.0, 50.0, 0.0],
        };
        assert_eq!(stops.at_front_of_plate(), None);
    }

    #[test]
    fn spin_axis_180_is_backspin() {
        assert!((topspin(2400.0, 180.0) + 2400.0 * TAU_PER_MINUTE).abs() < 1e-9);
        assert!((topspin(2400.0, 0.0) - 2400.0 * TAU_PER_MINUTE).abs() < 1e-9);
        assert!(topspin(2400.0, 90.0).abs() < 1e-9);
    }

    const TAU_PER_MINUTE: f64 = std::f64::consts::TAU / 60.0;
}
