//! The pitched ball at the plate: Eq. (3)–(4).

use nalgebra::Vector2;

// Eq. (3) is built from a fit to pitch data: the release vertical velocity is
// −(V̂_bp − 36)/3.42 m/s, the ball keeps 95 % of its speed, and it falls for
// D/V̂_bp seconds over D = 18.52 m. The unrounded form is kept (not the
// printed 34.2/561/3.25 one) so that gravity stays an input.
const FIT_SPEED: f64 = 36.0; // m/s at which the release is level
const FIT_SLOPE: f64 = 3.42; // (m/s) of speed per (m/s) of release vertical speed
const SPEED_KEPT: f64 = 0.95; // V̂_b0 = 0.95 V̂_bp
const MOUND_DISTANCE: f64 = 18.52; // m

/// V̂_by0, the vertical velocity at the plate for a pitch of `speed` (Eq. 3).
/// Negative: the ball is descending.
pub fn vertical_velocity(speed: f64, gravity: f64) -> f64 {
    let a = FIT_SPEED * SPEED_KEPT;
    let c = FIT_SLOPE * SPEED_KEPT;
    let d = FIT_SLOPE * SPEED_KEPT * SPEED_KEPT * gravity * MOUND_DISTANCE;
    (-speed * speed + a * speed - d) / (c * speed)
}

/// γ, the angle of descent below the horizontal (Eq. 4), positive descending.
pub fn descent_angle(speed: f64, gravity: f64) -> f64 {
    -(vertical_velocity(speed, gravity) / speed).asin()
}

/// The pitched ball's velocity in the flight frame: toward the catcher (−x)
/// and down, V̂_b0·(−cos γ, −sin γ).
pub fn velocity(speed: f64, gravity: f64) -> Vector2<f64> {
    velocity_descending(speed, descent_angle(speed, gravity))
}

/// [`velocity`] for a pitch whose descent angle γ is known already (an
/// impact needs both: one arcsine, not two).
pub fn velocity_descending(speed: f64, gamma: f64) -> Vector2<f64> {
    Vector2::new(-speed * gamma.cos(), -speed * gamma.sin())
}

/// The slowest pitch for which Eq. (3) gives |V̂_by0| < V̂_b0 (so that Eq. 4's
/// arcsine exists). Below it the fit extrapolates to a ball falling faster
/// than it moves.
pub fn minimum_speed(gravity: f64) -> f64 {
    let a = FIT_SPEED * SPEED_KEPT;
    let c = FIT_SLOPE * SPEED_KEPT;
    let d = FIT_SLOPE * SPEED_KEPT * SPEED_KEPT * gravity * MOUND_DISTANCE;
    // V̂_by0 ≥ −V̂_b0  ⇔  (c − 1)V² + aV − d ≥ 0.
    let falling = (-a + (a * a + 4.0 * (c - 1.0) * d).sqrt()) / (2.0 * (c - 1.0));
    // V̂_by0 ≤ V̂_b0  ⇔  (c + 1)V² − aV + d ≥ 0; fails between two roots in weak gravity.
    let discriminant = a * a - 4.0 * (c + 1.0) * d;
    let rising = if discriminant > 0.0 {
        (a + discriminant.sqrt()) / (2.0 * (c + 1.0))
    } else {
        0.0
    };
    falling.max(rising)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_value_at_38_m_per_s() {
        // §III: "V̂_by0 = −5.7 m/s" for the Fig. 5 pitch of 38 m/s.
        assert!((vertical_velocity(38.0, 9.81) + 5.7116).abs() < 1e-4);
    }

    #[test]
    fn minimum_speed_is_where_the_arcsine_runs_out() {
        let v = minimum_speed(9.81);
        assert!((vertical_velocity(v, 9.81) + v).abs() < 1e-9);
        assert!(vertical_velocity(v + 0.01, 9.81).abs() < v + 0.01);
    }
}
