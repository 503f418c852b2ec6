//! The flight frame in three dimensions, and every convention that reads
//! it, in one place (`../shared/DESIGN.md`, "Three dimensions"):
//!
//! - x toward centre field, y up, z = x × y toward the right-field
//!   (first-base) side. A planar scene lives in z = 0.
//! - A direction (a launch's, a landing's, the wind's, a fence point's) is
//!   the angle in radians from the centre-field line, positive toward right
//!   field (+z): the unit vector (cos φ, 0, sin φ).
//! - Backspin is spin about the horizontal axis perpendicular to the launch
//!   direction that makes a ball moving along it rise: (−sin φ, 0, cos φ),
//!   which is +z for a launch toward centre field, as in the plane.
//! - Sidespin is spin about the axis perpendicular to the launch velocity
//!   within the launch's vertical plane, signed so that a positive sidespin
//!   curves the ball toward +z: (sin θ cos φ, −cos θ, sin θ sin φ) for a
//!   launch at angle θ above the horizontal in direction φ (pointing down
//!   for a level launch, since (0, −1, 0) × (1, 0, 0) = (0, 0, 1)).
//! - The Magnus force is along ω × v (v relative to the air): up for
//!   backspin, toward +z for positive sidespin.

use nalgebra::Vector3;

/// The horizontal unit vector of direction `direction` (rad from the
/// centre-field line, positive toward right field).
#[inline]
pub fn horizontal(direction: f64) -> Vector3<f64> {
    let (sin, cos) = direction.sin_cos();
    Vector3::new(cos, 0.0, sin)
}

/// The direction (rad from the centre-field line, positive toward right
/// field) of the horizontal point or vector (x, z).
#[inline]
pub fn direction_of(x: f64, z: f64) -> f64 {
    z.atan2(x)
}

/// The velocity of a launch at `speed` (m/s), `angle` above the horizontal
/// and `direction` (rad).
pub fn launch_velocity(speed: f64, angle: f64, direction: f64) -> Vector3<f64> {
    let (sin_angle, cos_angle) = angle.sin_cos();
    let (sin_direction, cos_direction) = direction.sin_cos();
    Vector3::new(
        cos_angle * cos_direction,
        sin_angle,
        cos_angle * sin_direction,
    ) * speed
}

/// The axis of backspin for a launch in `direction`: horizontal,
/// perpendicular to the direction, +z toward centre field.
pub fn backspin_axis(direction: f64) -> Vector3<f64> {
    let (sin, cos) = direction.sin_cos();
    Vector3::new(-sin, 0.0, cos)
}

/// The axis of sidespin for a launch at `angle` in `direction`:
/// perpendicular to the launch velocity, in its vertical plane, signed so
/// that positive sidespin curves the ball toward +z (right field).
pub fn sidespin_axis(angle: f64, direction: f64) -> Vector3<f64> {
    let (sin_angle, cos_angle) = angle.sin_cos();
    let (sin_direction, cos_direction) = direction.sin_cos();
    Vector3::new(
        sin_angle * cos_direction,
        -cos_angle,
        sin_angle * sin_direction,
    )
}

/// The spin vector (rad/s) of a launch at `angle` in `direction` with
/// `backspin` and `sidespin` (rad/s): perpendicular to the launch velocity.
pub fn spin_vector(backspin: f64, sidespin: f64, angle: f64, direction: f64) -> Vector3<f64> {
    backspin_axis(direction) * backspin + sidespin_axis(angle, direction) * sidespin
}

/// A spin vector's parts for a launch at `angle` in `direction`: its
/// backspin, sidespin and gyrospin (about the launch velocity), each the
/// vector along its axis. The inverse of [`spin_vector`], which has no
/// gyrospin.
pub fn spin_parts(spin: Vector3<f64>, angle: f64, direction: f64) -> (f64, f64, f64) {
    (
        spin.dot(&backspin_axis(direction)),
        spin.dot(&sidespin_axis(angle, direction)),
        spin.dot(&launch_velocity(1.0, angle, direction)),
    )
}

/// The wind's velocity (m/s): `speed` blowing toward `direction`.
pub fn wind_velocity(speed: f64, direction: f64) -> Vector3<f64> {
    horizontal(direction) * speed
}

/// The component of a wind of `speed` toward `wind_direction` along a
/// vertical plane of direction `plane`, if the wind lies in that plane
/// exactly (blowing along it or against it, or calm); `None` for a wind
/// with any crosswind part. Angles that differ by exactly 0 or ±π count as
/// along the plane (cos π is exactly −1 in floating point, sin π is not 0).
pub fn wind_along(speed: f64, wind_direction: f64, plane: f64) -> Option<f64> {
    let difference = wind_direction - plane;
    if speed == 0.0 || difference == 0.0 {
        Some(speed)
    } else if difference.abs() == std::f64::consts::PI {
        Some(-speed)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

    fn close(a: Vector3<f64>, b: Vector3<f64>) -> bool {
        (a - b).norm() < 1e-15
    }

    #[test]
    fn directions_are_positive_toward_right_field() {
        assert!(close(horizontal(0.0), Vector3::x()));
        assert!(close(horizontal(FRAC_PI_2), Vector3::z()));
        assert_eq!(direction_of(1.0, 1.0), FRAC_PI_4);
        assert_eq!(direction_of(1.0, -1.0), -FRAC_PI_4);
    }

    #[test]
    fn the_spin_axes_are_perpendicular_to_the_launch_and_to_each_other() {
        for (angle, direction) in [(0.0, 0.0), (0.5, 0.3), (-0.2, -0.7), (1.2, 1.0)] {
            let v = launch_velocity(1.0, angle, direction);
            let (b, s) = (backspin_axis(direction), sidespin_axis(angle, direction));
            assert!(v.dot(&b).abs() < 1e-15 && v.dot(&s).abs() < 1e-15);
            assert!(b.dot(&s).abs() < 1e-15);
            assert!((b.norm() - 1.0).abs() < 1e-15 && (s.norm() - 1.0).abs() < 1e-15);
            // Backspin lifts (ω × v has a positive y part for a climbing
            // or level ball), positive sidespin pushes toward +z seen
            // from behind the ball: ω × v along the launch's right-hand
            // horizontal (−sin φ, 0, cos φ).
            assert!(b.cross(&v).y > 0.0);
            let right = Vector3::new(-direction.sin(), 0.0, direction.cos());
            assert!((s.cross(&v) - right).norm() < 1e-15);
        }
    }

    #[test]
    fn a_spin_vector_splits_back_into_its_parts() {
        for (angle, direction) in [(0.0, 0.0), (0.5, 0.3), (-0.2, -0.7), (1.2, 1.0)] {
            let spin = spin_vector(180.0, -70.0, angle, direction);
            let (back, side, gyro) = spin_parts(spin, angle, direction);
            assert!((back - 180.0).abs() < 1e-12 && (side + 70.0).abs() < 1e-12);
            assert!(gyro.abs() < 1e-12);
            // Spin about the velocity is gyrospin alone.
            let along = launch_velocity(25.0, angle, direction);
            let (back, side, gyro) = spin_parts(along, angle, direction);
            assert!(back.abs() < 1e-12 && side.abs() < 1e-12 && (gyro - 25.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_level_launch_to_centre_field_has_the_planar_spin_axis() {
        assert!(close(backspin_axis(0.0), Vector3::z()));
        assert!(close(sidespin_axis(0.0, 0.0), -Vector3::y()));
        assert!(close(
            spin_vector(200.0, 0.0, 0.4, 0.0),
            Vector3::new(0.0, 0.0, 200.0)
        ));
    }

    #[test]
    fn a_wind_is_along_a_plane_only_exactly() {
        assert_eq!(wind_along(5.0, 0.0, 0.0), Some(5.0));
        assert_eq!(wind_along(5.0, PI, 0.0), Some(-5.0));
        assert_eq!(wind_along(5.0, -PI, 0.0), Some(-5.0));
        assert_eq!(wind_along(0.0, 1.0, 0.0), Some(0.0));
        assert_eq!(wind_along(5.0, 0.3, 0.3), Some(5.0));
        assert_eq!(wind_along(5.0, 1e-9, 0.0), None);
    }
}
