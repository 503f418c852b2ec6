//! The paper's impact in three dimensions: a tilted bat, swung toward any
//! direction, by either hand (docs/swing-3d.md). The same bodies and laws
//! as Eq. (1)–(23), with the vectors of Eq. (5)–(10) in space:
//! - the ball, a sphere: mass M_b, inertia M_b·k_b² about any axis;
//! - the bat, the paper's: its point B̂ on the axis moves as a particle of
//!   the effective mass M_B in every direction, and it rolls about its own
//!   axis with inertia M_B·k_B2². Its turning about axes square to its own
//!   is what M_B already stands for (§II.A: M_B/M'_B = (1 + z²/k_B1²)⁻¹ for
//!   an impulse square to the bat); the lever r_B that a friction impulse
//!   along the bat has about those axes is left out, as that adds
//!   r_B²/k_B1² ≈ 2.6 % to the bat's inverse mass along its axis (see the
//!   docs for this and the full mass M'_B along the axis);
//! - Coulomb friction opposing the slip, which now lives in the tangent
//!   plane and turns as it slows ([`super::slip`]);
//! - the energetic restitution e*(v3(0)) of Eq. (19): the normal impulse
//!   does not couple to the tangent plane (the contact points lie on the
//!   line of centres), so p_f = p_c(1 + e*) exactly as in Eq. (20).
//!
//! With tilt and direction 0 this is the paper's geometry, and the launch
//! agrees with [`super::Impact`]'s to rounding (tests/impact3d.rs).

use nalgebra::{Vector2, Vector3};

use super::geometry::{BatFrame, ContactFrame};
use super::slip::Slip;
use super::{Bodies, Regime, Stop, normal_phase, stops};
use crate::frame;
use crate::pitch;
use crate::scene::Scene;

/// The ball and bat at normal impulse p during a 3-D contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact3d {
    /// Normal impulse p (N·s).
    pub impulse: f64,
    /// Tangential impulse on the ball, across the bat (n1) and along it
    /// (n2) (N·s).
    pub tangential_impulse: Vector2<f64>,
    /// The slip (v1, v2) of the contact points (m/s); zero once it halts.
    pub slip: Vector2<f64>,
    /// v3, the normal relative velocity (m/s), negative approaching.
    pub normal_velocity: f64,
    /// Ball centre velocity and spin (flight frame, m/s and rad/s).
    pub ball_velocity: Vector3<f64>,
    pub ball_spin: Vector3<f64>,
    /// Bat axis velocity (flight frame, m/s) and roll about n2 (rad/s).
    pub bat_velocity: Vector3<f64>,
    pub bat_roll: f64,
}

impl Contact3d {
    /// The slip's direction in the tangent plane (rad from n1 toward n2,
    /// the bat's axis), or `None` once it has halted.
    pub fn slip_angle(&self) -> Option<f64> {
        (self.slip != Vector2::zeros()).then(|| self.slip.y.atan2(self.slip.x))
    }
}

/// One point of the slip's turn: its speed and direction at an impulse.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct SlipPoint {
    /// p (N·s).
    pub impulse: f64,
    /// |s| (m/s).
    pub speed: f64,
    /// rad from n1 toward n2 (the bat's axis).
    pub angle: f64,
}

/// One 3-D collision: its geometry, its phases and the ball's launch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact3d {
    /// θ, the normal's angle from ŵ toward û, square to the bat (Eq. 1).
    pub normal_angle: f64,
    /// γ, the pitch's descent angle (Eq. 4).
    pub descent_angle: f64,
    /// n1, n2 (along the bat), n3 in the flight frame, and the bat's frame.
    pub frame: ContactFrame,
    /// Masses, radii, inertias, m (Eq. 11), β1 across the bat and β_a
    /// along it (Eq. 13 in space).
    pub bodies: Bodies,
    /// μ.
    pub friction: f64,
    /// s(0) = (v1(0), v2(0)) and v3(0) (Eq. 16 in space).
    pub initial_slip: Vector2<f64>,
    pub initial_approach: f64,
    /// e* (Eq. 19), p_c (Eq. 18) and p_f (Eq. 20).
    pub restitution: f64,
    pub compression_impulse: f64,
    pub separation_impulse: f64,
    pub regime: Regime,
    /// The tangential impulse (n1, n2) a gripping contact gives back after
    /// its slip halts, along the impulse that halted it (`impact::release`);
    /// zero for the paper's rolling.
    pub release: Vector2<f64>,
    /// p_s where a release needed it exactly (friction capped it); else
    /// worked out when a state before separation asks for it.
    release_from: Option<f64>,
    /// Pre-impact states (flight frame); the bat's roll about n2.
    pub ball_velocity_before: Vector3<f64>,
    pub ball_spin_before: Vector3<f64>,
    pub bat_velocity_before: Vector3<f64>,
    pub bat_roll_before: f64,
    /// Ball and bat at separation.
    pub after: Contact3d,
    slip: Slip,
}

impl Impact3d {
    /// Solves the collision for a scene (assumed validated), in space
    /// whatever its bat.
    pub fn new(scene: &Scene) -> Impact3d {
        let gravity = scene.environment.gravity;
        let descent_angle = pitch::descent_angle(scene.pitch.speed, gravity);
        let pitched = pitch::velocity_descending(scene.pitch.speed, descent_angle);
        Impact3d::meeting(
            scene,
            Vector3::new(pitched.x, pitched.y, 0.0),
            descent_angle,
        )
    }

    /// The collision of a scene's swing with a pitch arriving at `velocity`
    /// (flight frame, m/s) instead of the paper's pitch of Eq. (3)–(4): a
    /// tracked pitch, which may also move sideways ([`crate::tracked_pitch`]).
    /// `scene.pitch.speed` is not read; its spin is.
    pub fn with_pitch(scene: &Scene, velocity: Vector3<f64>) -> Impact3d {
        let descent_angle = (-velocity.y).atan2(velocity.x.hypot(velocity.z));
        Impact3d::meeting(scene, velocity, descent_angle)
    }

    fn meeting(scene: &Scene, ball_velocity_before: Vector3<f64>, descent_angle: f64) -> Impact3d {
        let (ball, bat) = (scene.ball, scene.bat);
        // Eq. (1), square to the bat; the clamp only guards rounding.
        let normal_angle = (bat.undercut / scene.reach()).clamp(-1.0, 1.0).asin();
        let bat_frame =
            BatFrame::swung(bat.tilt, bat.swing_angle, bat.direction, bat.lead, bat.hand);
        let frame = ContactFrame::new(bat_frame, normal_angle, bat.hand);
        let ball_spin_before = Vector3::z() * scene.pitch.spin;
        let bat_velocity_before = bat_frame.velocity(bat.speed);
        // Fig. 9's positive roll adds backspin: it turns about −n2.
        let bat_roll_before = -bat.spin;

        // Eq. (13) in space: the ball rolls under either tangential
        // impulse, the bat only under one across it.
        let bodies = Bodies::of(scene);
        let Bodies {
            pair_mass,
            beta1,
            beta_axial,
            ..
        } = bodies;

        // Eq. (9)–(10): the contact points' velocities, V̂ + ω × r.
        let to_ball_contact = frame.n3 * -ball.radius;
        let to_bat_contact = frame.n3 * bat.radius;
        let relative = ball_velocity_before + ball_spin_before.cross(&to_ball_contact)
            - bat_velocity_before
            - (frame.n2 * bat_roll_before).cross(&to_bat_contact);
        let initial_slip = Vector2::new(relative.dot(&frame.n1), relative.dot(&frame.n2));
        let initial_approach = relative.dot(&frame.n3);
        let (restitution, compression_impulse, separation_impulse) =
            normal_phase(pair_mass, initial_approach);

        let slip = Slip::new(initial_slip, (beta1, beta_axial), bat.friction, pair_mass);
        let regime = if separation_impulse > 0.0 && slip.halts_by(separation_impulse) {
            Regime::Stick
        } else {
            Regime::Slip
        };
        // The impulse that halted the slip is m·diag(β1, β_a)⁻¹·(0 − s(0)).
        let (release, release_from) = match regime {
            Regime::Stick
                if initial_slip != Vector2::zeros() && bat.tangential_restitution > 0.0 =>
            {
                let halting = Vector2::new(
                    -pair_mass * initial_slip.x / beta1,
                    -pair_mass * initial_slip.y / beta_axial,
                );
                // Friction's room over p_s..p_f, from p_s's bounds where
                // they show it does not bind (no integration), else exact.
                let wanted = bat.tangential_restitution * halting.norm();
                let room = |halt: f64| bat.friction * (separation_impulse - halt);
                let (_, latest) = slip.halt_impulse_bounds();
                let (left, from) = if wanted <= room(latest) {
                    (room(latest), None)
                } else {
                    let halt = slip.halt_impulse();
                    (room(halt), Some(halt))
                };
                let release = halting.normalize()
                    * super::release(bat.tangential_restitution, halting.norm(), left);
                (release, from)
            }
            _ => (Vector2::zeros(), None),
        };
        let before = Contact3d {
            impulse: 0.0,
            tangential_impulse: Vector2::zeros(),
            slip: initial_slip,
            normal_velocity: initial_approach,
            ball_velocity: ball_velocity_before,
            ball_spin: ball_spin_before,
            bat_velocity: bat_velocity_before,
            bat_roll: bat_roll_before,
        };
        let mut impact = Impact3d {
            normal_angle,
            descent_angle,
            frame,
            bodies,
            friction: bat.friction,
            initial_slip,
            initial_approach,
            restitution,
            compression_impulse,
            separation_impulse,
            regime,
            release,
            release_from,
            ball_velocity_before,
            ball_spin_before,
            bat_velocity_before,
            bat_roll_before,
            after: before,
            slip,
        };
        impact.after = impact.at(separation_impulse);
        impact
    }

    /// The state of both bodies at normal impulse p, 0 ≤ p ≤ p_f.
    pub fn at(&self, impulse: f64) -> Contact3d {
        let mut slip = self.slip.at(impulse);
        // ds = m⁻¹·diag(β1, β_a)·dp_t, so the tangential impulse so far is
        // read off the slip lost (exactly 0 without friction).
        let s0 = self.initial_slip;
        let m = self.bodies.pair_mass;
        let mut tangential = Vector2::new(
            m * (slip.x - s0.x) / self.bodies.beta1,
            m * (slip.y - s0.y) / self.bodies.beta_axial,
        );
        // A gripping contact's release, evenly over p_s..p_f: the slip
        // springs back, to −e_T·s(0) at separation where friction allows.
        let pf = self.separation_impulse;
        let fraction = if self.release == Vector2::zeros() {
            None
        } else if impulse >= pf {
            Some(1.0)
        } else {
            let ps = self
                .release_from
                .unwrap_or_else(|| self.slip.halt_impulse());
            (impulse > ps).then(|| (impulse - ps) / (pf - ps))
        };
        if let Some(fraction) = fraction {
            let given = self.release * fraction;
            tangential += given;
            slip += Vector2::new(
                self.bodies.beta1 * given.x / m,
                self.bodies.beta_axial * given.y / m,
            );
        }
        let (p1, p2) = (tangential.x, tangential.y);
        let f = &self.frame;
        let on_ball = f.to_flight(p1, p2, impulse);
        // Eq. (8): r × p for the ball (r = −r_b·n3) is −r_b(p1·n2 − p2·n1);
        // the bat's roll takes the n2 part of r_B·n3 × (−p), −r_B·p1. The
        // normal impulse has no moment about either centre.
        let ball_turn =
            (f.n1 * p2 - f.n2 * p1) * (self.bodies.ball_radius / self.bodies.ball_inertia);
        Contact3d {
            impulse,
            tangential_impulse: tangential,
            slip,
            normal_velocity: self.initial_approach + impulse / m,
            ball_velocity: self.ball_velocity_before + on_ball / self.bodies.ball_mass,
            ball_spin: self.ball_spin_before + ball_turn,
            bat_velocity: self.bat_velocity_before - on_ball / self.bodies.bat_mass,
            bat_roll: self.bat_roll_before - self.bodies.bat_radius * p1 / self.bodies.bat_inertia,
        }
    }

    /// p_s, the impulse at which the slip halts: 0 without slip, infinite
    /// without friction (Eq. 17 in the plane).
    pub fn slip_halt_impulse(&self) -> f64 {
        self.slip.halt_impulse()
    }

    /// p_s if slip halts before separation, else `None`.
    pub fn stick_impulse(&self) -> Option<f64> {
        (self.regime == Regime::Stick).then(|| self.slip_halt_impulse())
    }

    /// The phases of the collision in order of impulse, as the plane's.
    pub fn stops(&self) -> Vec<Stop> {
        stops(
            self.compression_impulse,
            self.separation_impulse,
            self.stick_impulse(),
        )
    }

    /// The slip's turn: `samples` points evenly in p from 0 to where it
    /// halts or the ball leaves, whichever comes first.
    pub fn slip_turn(&self, samples: usize) -> Vec<SlipPoint> {
        let end = self.slip_halt_impulse().min(self.separation_impulse);
        let samples = samples.max(2);
        (0..samples)
            .filter_map(|k| {
                // Just short of the halt, where the direction is still defined.
                let p = end * k as f64 / (samples - 1) as f64 * (1.0 - 1e-9);
                let state = self.at(p);
                state.slip_angle().map(|angle| SlipPoint {
                    impulse: p,
                    speed: state.slip.norm(),
                    angle,
                })
            })
            .collect()
    }

    /// V̂_bf, the batted ball's speed.
    pub fn launch_speed(&self) -> f64 {
        self.after.ball_velocity.norm()
    }

    /// ζ, the launch angle above the horizontal.
    pub fn launch_angle(&self) -> f64 {
        let v = self.after.ball_velocity;
        v.y.atan2(v.x.hypot(v.z))
    }

    /// The launch direction (rad from the centre-field line, positive
    /// toward right field).
    pub fn launch_direction(&self) -> f64 {
        let v = self.after.ball_velocity;
        frame::direction_of(v.x, v.z)
    }

    /// Backspin (rad/s) about [`frame::backspin_axis`] of the launch.
    pub fn launch_spin(&self) -> f64 {
        self.after
            .ball_spin
            .dot(&frame::backspin_axis(self.launch_direction()))
    }

    /// Sidespin (rad/s) about [`frame::sidespin_axis`] of the launch,
    /// positive curving the ball toward right field.
    pub fn launch_sidespin(&self) -> f64 {
        let axis = frame::sidespin_axis(self.launch_angle(), self.launch_direction());
        self.after.ball_spin.dot(&axis)
    }

    /// Spin about the launch velocity itself (rad/s), which bends no flight
    /// and which the flight, as frame.rs and Nathan's calculator, leaves out.
    pub fn launch_gyrospin(&self) -> f64 {
        let v = self.after.ball_velocity;
        let speed = v.norm();
        if speed > 0.0 {
            self.after.ball_spin.dot(&v) / speed
        } else {
            0.0
        }
    }

    /// Kinetic energy of ball and bat (the bat's effective mass and roll).
    pub fn kinetic_energy(&self, state: &Contact3d) -> f64 {
        0.5 * self.bodies.ball_mass * state.ball_velocity.norm_squared()
            + 0.5 * self.bodies.ball_inertia * state.ball_spin.norm_squared()
            + 0.5 * self.bodies.bat_mass * state.bat_velocity.norm_squared()
            + 0.5 * self.bodies.bat_inertia * state.bat_roll.powi(2)
    }
}
