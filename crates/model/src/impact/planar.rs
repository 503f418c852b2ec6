//! The paper's planar rigid-body bat–ball impact with friction: Eq. (1)–(2),
//! (5)–(23), after Stronge, solved as functions of the normal impulse p.
//! A level bat square to the pitch (`bat.tilt` = `bat.direction` = 0) takes
//! this path; [`super::Impact3d`] is the same collision in three dimensions.
//!
//! Sign conventions (derived once, from first principles, and checked against
//! all nine launch values of Table II; docs/models.md lists the paper's
//! misprints they settle):
//! - flight frame x toward centre field, y up; spins are ẑ components
//!   (counter-clockwise positive), so batted backspin and pitched topspin are
//!   positive;
//! - n3 = (cos θ, sin θ) points from the bat's axis to the ball's centre,
//!   n1 = ẑ × n3 = (−sin θ, cos θ), n2 = +ẑ;
//! - the impulse p = p1·n1 + p3·n3 acts *on the ball*, the bat gets −p.
//!   Eq. (22) prints V̂_b(p_f) = V̂_b(0) − p/M_b: that minus belongs to the
//!   opposite sign for p; with this one it is a plus, and the launch values
//!   match Table II;
//! - e* is taken from the approach speed |v3(0)| (Eq. 19 as printed would
//!   take the negative v3(0) and give e* > 0.6 for every hit).

use nalgebra::{Rotation2, Vector2};

use super::{Bodies, Regime, Stop, normal_phase, stops};
use crate::pitch;
use crate::scene::Scene;

/// The ball and bat states at some normal impulse p during contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// Normal impulse p (N·s).
    pub impulse: f64,
    /// Tangential impulse p1 on the ball (N·s).
    pub tangential_impulse: f64,
    /// Relative velocity of the contact points, tangential v1 and normal v3 (m/s).
    pub slip_velocity: f64,
    pub normal_velocity: f64,
    /// Ball centre velocity (flight frame, m/s) and spin (rad/s, ẑ).
    pub ball_velocity: Vector2<f64>,
    pub ball_spin: f64,
    /// Bat axis velocity (flight frame, m/s) and spin (rad/s, ẑ).
    pub bat_velocity: Vector2<f64>,
    pub bat_spin: f64,
}

/// Everything about one collision: its inputs in the impact frame, its phases
/// and the launch state of the ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact {
    /// θ, angle of the common normal n3 above the horizontal (Eq. 1).
    pub normal_angle: f64,
    /// γ, the pitch's descent angle (Eq. 4).
    pub descent_angle: f64,
    /// Rotation from impact-frame components (n1, n3) to flight-frame (x, y)
    /// is `frame * Vector2::new(c3, c1)` — n3 along the rotated x axis.
    pub frame: Rotation2<f64>,
    /// Masses, radii, inertias, m (Eq. 11) and β1 (Eq. 13).
    pub bodies: Bodies,
    /// μ.
    pub friction: f64,
    /// v1(0), v3(0): initial slip and approach (Eq. 16); v3(0) < 0 approaches.
    pub initial_slip: f64,
    pub initial_approach: f64,
    /// e*, energetic coefficient of restitution (Eq. 19).
    pub restitution: f64,
    /// p_c, impulse at the end of compression (Eq. 18).
    pub compression_impulse: f64,
    /// p_f = p_c(1 + e*), impulse at separation (Eq. 20).
    pub separation_impulse: f64,
    /// p_s, impulse at which slip halts (Eq. 17); infinite without friction.
    pub slip_halt_impulse: f64,
    pub regime: Regime,
    /// The tangential impulse a gripping contact gives back after the slip
    /// halts (N·s, ≥ 0): e_T times the one that halted it, no more than
    /// friction allows over the rest of the contact (`impact::release`);
    /// 0 for the paper's rolling.
    pub release_impulse: f64,
    /// Pre-impact states (flight frame).
    pub ball_velocity_before: Vector2<f64>,
    pub ball_spin_before: f64,
    pub bat_velocity_before: Vector2<f64>,
    pub bat_spin_before: f64,
    /// Ball and bat at separation.
    pub after: ContactState,
}

/// The parts of an impact that take trigonometry, each from fewer inputs
/// than the whole: the pitch's (Eq. 3–4), the undercut's (Eq. 1) and the
/// swing's direction. A surface holds the pitch over every cell, the
/// undercut down a column and the swing angle along a row, so it works each
/// out once there ([`Impact::with_angles`]), not once a cell (a sixth of a
/// cell's work outside its flight).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactAngles {
    pub pitch: PitchAngles,
    pub normal: NormalAngles,
    /// The bat's velocity before contact (flight frame, m/s).
    pub bat_velocity_before: Vector2<f64>,
}

/// γ and the pitched ball's velocity at the plate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PitchAngles {
    pub descent_angle: f64,
    pub ball_velocity_before: Vector2<f64>,
}

/// θ and the rotation from the impact frame to the flight frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalAngles {
    pub normal_angle: f64,
    pub frame: Rotation2<f64>,
}

impl ImpactAngles {
    pub fn of(scene: &Scene) -> ImpactAngles {
        ImpactAngles {
            pitch: PitchAngles::of(scene),
            normal: NormalAngles::of(scene),
            bat_velocity_before: ImpactAngles::bat_velocity(scene),
        }
    }

    /// The bat's velocity before contact: its speed along ψ.
    pub fn bat_velocity(scene: &Scene) -> Vector2<f64> {
        let bat = scene.bat;
        Vector2::new(bat.swing_angle.cos(), bat.swing_angle.sin()) * bat.speed
    }
}

impl PitchAngles {
    pub fn of(scene: &Scene) -> PitchAngles {
        let descent_angle = pitch::descent_angle(scene.pitch.speed, scene.environment.gravity);
        PitchAngles {
            descent_angle,
            ball_velocity_before: pitch::velocity_descending(scene.pitch.speed, descent_angle),
        }
    }
}

impl NormalAngles {
    pub fn of(scene: &Scene) -> NormalAngles {
        // Eq. (1); the clamp only guards rounding at a validated |E| < r_b + r_B.
        let normal_angle = (scene.bat.undercut / scene.reach()).clamp(-1.0, 1.0).asin();
        NormalAngles {
            normal_angle,
            frame: Rotation2::new(normal_angle),
        }
    }
}

impl Impact {
    /// Solves the collision for a scene (assumed validated).
    pub fn new(scene: &Scene) -> Impact {
        Impact::with_angles(scene, ImpactAngles::of(scene))
    }

    /// [`Impact::new`], given the scene's angles (`ImpactAngles::of(scene)`,
    /// perhaps worked out in parts for many scenes): the same bits.
    pub fn with_angles(scene: &Scene, angles: ImpactAngles) -> Impact {
        let ball = scene.ball;
        let bat = scene.bat;
        let PitchAngles {
            descent_angle,
            ball_velocity_before,
        } = angles.pitch;
        let NormalAngles {
            normal_angle,
            frame,
        } = angles.normal;
        let bat_velocity_before = angles.bat_velocity_before;
        let ball_spin_before = scene.pitch.spin;
        // Fig. 9's positive roll is −ẑ (see Scene::bat.spin).
        let bat_spin_before = -bat.spin;

        let bodies = Bodies::of(scene);
        let Bodies {
            pair_mass, beta1, ..
        } = bodies;

        // Eq. (16): components in the impact frame. The contact point of the
        // ball is −r_b·n3 from its centre, so ω×r adds −r_b·ω along n1; the
        // bat's is +r_B·n3, adding +r_B·ω_B along n1.
        let to_impact = frame.inverse();
        let ball_local = to_impact * ball_velocity_before; // (n3, n1) components
        let bat_local = to_impact * bat_velocity_before;
        let initial_slip = ball_local.y
            - ball.radius * ball_spin_before
            - bat_local.y
            - bat.radius * bat_spin_before;
        let initial_approach = ball_local.x - bat_local.x;

        let (restitution, compression_impulse, separation_impulse) =
            normal_phase(pair_mass, initial_approach);
        // Eq. (17) with s = sign v1(0): p_s = m|v1(0)|/(μβ1).
        let slip_halt_impulse = if initial_slip == 0.0 {
            0.0
        } else if scene.bat.friction == 0.0 {
            f64::INFINITY
        } else {
            pair_mass * initial_slip.abs() / (scene.bat.friction * beta1)
        };
        let regime = if slip_halt_impulse < separation_impulse {
            Regime::Stick
        } else {
            Regime::Slip
        };

        let release_impulse = match regime {
            // |p1(p_s)| = μ·p_s, the impulse that halted the slip.
            Regime::Stick => super::release(
                bat.tangential_restitution,
                bat.friction * slip_halt_impulse,
                bat.friction * (separation_impulse - slip_halt_impulse),
            ),
            Regime::Slip => 0.0,
        };

        let mut impact = Impact {
            normal_angle,
            descent_angle,
            frame,
            bodies,
            friction: scene.bat.friction,
            initial_slip,
            initial_approach,
            restitution,
            compression_impulse,
            separation_impulse,
            slip_halt_impulse,
            regime,
            release_impulse,
            ball_velocity_before,
            ball_spin_before,
            bat_velocity_before,
            bat_spin_before,
            after: ContactState {
                impulse: 0.0,
                tangential_impulse: 0.0,
                slip_velocity: initial_slip,
                normal_velocity: initial_approach,
                ball_velocity: ball_velocity_before,
                ball_spin: ball_spin_before,
                bat_velocity: bat_velocity_before,
                bat_spin: bat_spin_before,
            },
        };
        impact.after = impact.at(separation_impulse);
        impact
    }

    /// s of Eq. (14) for the initial slip.
    fn slip_sign(&self) -> f64 {
        if self.initial_slip > 0.0 {
            1.0
        } else if self.initial_slip < 0.0 {
            -1.0
        } else {
            0.0
        }
    }

    /// The tangential impulse p1 on the ball when the normal impulse is p
    /// (Eq. 14 integrated; Eq. 21 at p = p_f): friction −μ·s opposes the slip
    /// until p_s, after which the contact sticks and p1 stays put; a contact
    /// that grips (e_T > 0) gives its release back evenly over p_s..p_f.
    pub fn tangential_impulse(&self, impulse: f64) -> f64 {
        if self.slip_sign() == 0.0 {
            return 0.0;
        }
        let rolled = -self.friction * self.slip_sign() * impulse.min(self.slip_halt_impulse);
        if self.release_impulse > 0.0 && impulse > self.slip_halt_impulse {
            let (ps, pf) = (self.slip_halt_impulse, self.separation_impulse);
            rolled - self.slip_sign() * self.release_impulse * ((impulse - ps) / (pf - ps)).min(1.0)
        } else {
            rolled
        }
    }

    /// The state of both bodies at normal impulse p, 0 ≤ p ≤ p_f (Eq. 7–8, 15).
    pub fn at(&self, impulse: f64) -> ContactState {
        let p1 = self.tangential_impulse(impulse);
        let p3 = impulse;
        // Eq. (15) with β2 = 0, β3 = 1.
        let slip_velocity = self.initial_slip + self.bodies.beta1 * p1 / self.bodies.pair_mass;
        let normal_velocity = self.initial_approach + p3 / self.bodies.pair_mass;
        let on_ball = self.frame * Vector2::new(p3, p1); // flight-frame impulse
        // Eq. (8): r × p about ẑ is −r_b·p1 for the ball (r = −r_b n3) and,
        // for the bat, r_B n3 × (−p) = −r_B·p1 as well.
        let ball_velocity = self.ball_velocity_before + on_ball / self.bodies.ball_mass;
        let ball_spin =
            self.ball_spin_before - self.bodies.ball_radius * p1 / self.bodies.ball_inertia;
        let bat_velocity = self.bat_velocity_before - on_ball / self.bodies.bat_mass;
        let bat_spin = self.bat_spin_before - self.bodies.bat_radius * p1 / self.bodies.bat_inertia;
        ContactState {
            impulse,
            tangential_impulse: p1,
            slip_velocity,
            normal_velocity,
            ball_velocity,
            ball_spin,
            bat_velocity,
            bat_spin,
        }
    }

    /// p_s if slip halts before separation, else `None`.
    pub fn stick_impulse(&self) -> Option<f64> {
        (self.regime == Regime::Stick).then_some(self.slip_halt_impulse)
    }

    /// V̂_bf, the batted ball's speed.
    pub fn launch_speed(&self) -> f64 {
        self.after.ball_velocity.norm()
    }

    /// ω_bf, the batted ball's spin (backspin positive).
    pub fn launch_spin(&self) -> f64 {
        self.after.ball_spin
    }

    /// ζ, the launch angle above the horizontal (Eq. 23, as atan2 so that a
    /// ball leaving backwards keeps its true direction).
    pub fn launch_angle(&self) -> f64 {
        let v = self.after.ball_velocity;
        v.y.atan2(v.x)
    }

    /// Kinetic energy of ball and bat (translation of the bat's equivalent
    /// mass plus its roll), for the energy check.
    pub fn kinetic_energy(&self, state: &ContactState) -> f64 {
        0.5 * self.bodies.ball_mass * state.ball_velocity.norm_squared()
            + 0.5 * self.bodies.ball_inertia * state.ball_spin.powi(2)
            + 0.5 * self.bodies.bat_mass * state.bat_velocity.norm_squared()
            + 0.5 * self.bodies.bat_inertia * state.bat_spin.powi(2)
    }
}

impl Impact {
    /// The phases of the collision in order of impulse (paper Fig. 2).
    pub fn stops(&self) -> Vec<Stop> {
        stops(
            self.compression_impulse,
            self.separation_impulse,
            self.stick_impulse(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_two_fastball_launch() {
        let impact = Impact::new(&Scene::default());
        assert!((impact.launch_speed() - 44.30).abs() < 0.02);
        assert!((impact.launch_spin() - 191.35).abs() < 1.0);
        assert!((impact.launch_angle() - 0.4600).abs() < 0.002);
        assert_eq!(impact.regime, Regime::Stick);
        // With stick, the contact points move together at separation.
        assert!(impact.after.slip_velocity.abs() < 1e-9);
        assert!(
            (impact.after.normal_velocity + impact.restitution * impact.initial_approach).abs()
                < 1e-9
        );
    }
}
