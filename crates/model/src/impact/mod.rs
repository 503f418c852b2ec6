//! The bat–ball impact (Eq. 1–23): the paper's planar collision
//! ([`Impact`]) and the same collision in three dimensions ([`Impact3d`]),
//! for a bat tilted, swung toward any direction, by either hand
//! (docs/swing-3d.md). [`Collision`] is a scene's: the planar one for the
//! paper's level, square bat (so its numbers stay the paper's to the last
//! bit), the 3-D one otherwise.
//!
//! Shared here, once: the pair's mass (Eq. 11), the normal phase
//! (Eq. 18–20) and the phases of the step-through.

mod geometry;
mod planar;
mod slip;
mod spatial;

pub use geometry::{BatFrame, ContactFrame, MOST_LEAD, barrel_in_swing_plane};
pub use planar::{ContactState, Impact, ImpactAngles, NormalAngles, PitchAngles};
pub use spatial::{Contact3d, Impact3d, SlipPoint};

use crate::scene::Scene;

/// How the tangential slip ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Regime {
    /// Slip halts before separation (p_s < p_f) and the contact then sticks:
    /// for this geometry the stick coefficient μ̄ = β2/β1 = 0 ≤ μ (in 3-D
    /// too: the normal impulse does not couple to the tangent plane, so
    /// holding the slip at zero takes no friction at all).
    Stick,
    /// The contact slips until separation (p_s ≥ p_f).
    Slip,
}

impl Regime {
    /// "stick" or "slip", as JSON has it.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Stick => "stick",
            Regime::Slip => "slip",
        }
    }
}

/// The two bodies as the impact sees them: the ball, and the bat at the
/// contact (its effective mass and its roll about its own axis), with the
/// constants of Eq. (11) and (13).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bodies {
    pub ball_mass: f64,
    pub ball_radius: f64,
    /// M_b·k_b².
    pub ball_inertia: f64,
    /// M_B.
    pub bat_mass: f64,
    pub bat_radius: f64,
    /// M_B·k_B2², about the bat's own axis.
    pub bat_inertia: f64,
    /// m = M_b·M_B/(M_b + M_B) (Eq. 11).
    pub pair_mass: f64,
    /// β1 of Eq. (13) with r_b = −r_b·n3, r_B = r_B·n3: across the bat
    /// both bodies roll (β2 = 0 and β3 = 1, the contact points lying on the
    /// line of centres).
    pub beta1: f64,
    /// The same along the bat (3-D only), where the bat cannot roll: only
    /// the ball's term.
    pub beta_axial: f64,
}

impl Bodies {
    pub fn of(scene: &Scene) -> Bodies {
        let (ball, bat) = (scene.ball, scene.bat);
        let ball_inertia = ball.mass * ball.gyration_radius.powi(2);
        let bat_inertia = bat.effective_mass * bat.gyration_radius.powi(2);
        let pair_mass = ball.mass * bat.effective_mass / (ball.mass + bat.effective_mass);
        let ball_roll = pair_mass * ball.radius.powi(2) / ball_inertia;
        Bodies {
            ball_mass: ball.mass,
            ball_radius: ball.radius,
            ball_inertia,
            bat_mass: bat.effective_mass,
            bat_radius: bat.radius,
            bat_inertia,
            pair_mass,
            beta1: 1.0 + ball_roll + pair_mass * bat.radius.powi(2) / bat_inertia,
            beta_axial: 1.0 + ball_roll,
        }
    }
}

/// The normal phase from the approach v3(0): e* (Eq. 19, in the approach
/// speed |v3(0)|; as printed it would take the negative v3(0) and give
/// e* > 0.6 for every hit), p_c = −m·v3(0) (Eq. 18) and p_f = p_c(1 + e*)
/// (Eq. 20). A swing that does not approach the ball (v3(0) ≥ 0)
/// exchanges no impulse: the pitch flies on.
fn normal_phase(pair_mass: f64, approach: f64) -> (f64, f64, f64) {
    let restitution = 0.540 - (approach.abs() - 26.8) / 400.0;
    let compression = (-pair_mass * approach).max(0.0);
    (restitution, compression, compression * (1.0 + restitution))
}

/// The tangential impulse a contact that grips gives back once its slip
/// has halted (N·s): e_T times the `halting` impulse, as a tangentially
/// compliant ball springs back (R. Cross, "Grip-slip behavior of a bouncing
/// ball", Am. J. Phys. 70, 1093 (2002); its tangential coefficient of
/// restitution: the contact's slip leaves reversed, −e_T·s(0)), but no more
/// than friction can pass over the rest of the contact, μ·(p_f − p_s) =
/// `friction_left`. Spread evenly over p_s..p_f, the friction it needs
/// never exceeds μ·dp. 0 without grip (e_T = 0): the paper's rolling, to
/// the bit.
fn release(tangential_restitution: f64, halting: f64, friction_left: f64) -> f64 {
    if tangential_restitution > 0.0 {
        (tangential_restitution * halting)
            .min(friction_left)
            .max(0.0)
    } else {
        0.0
    }
}

/// A stop of the collision step by step: a phase's name and its normal
/// impulse p.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    pub name: &'static str,
    pub impulse: f64,
}

/// The phases in order of impulse (paper Fig. 2): approach, compression,
/// maximum compression (p_c), restitution and separation (p_f), with the
/// halt of slip (p_s) where the contact sticks.
fn stops(compression: f64, separation: f64, stick: Option<f64>) -> Vec<Stop> {
    let (pc, pf) = (compression, separation);
    let stop = |name, impulse| Stop { name, impulse };
    let mut stops = vec![
        stop("approach", 0.0),
        stop("compression", 0.5 * pc),
        stop("max compression", pc),
        stop("restitution", 0.5 * (pc + pf)),
        stop("separation", pf),
    ];
    if let Some(ps) = stick {
        stops.push(stop("slip halts, stick", ps));
    }
    stops.sort_by(|a, b| a.impulse.total_cmp(&b.impulse));
    stops
}

/// The launch a collision gives: what [`crate::launch::BattedBall`]
/// is made of.
pub trait Launches {
    /// V̂_bf (m/s).
    fn launch_speed(&self) -> f64;
    /// ζ above the horizontal (rad).
    fn launch_angle(&self) -> f64;
    /// Backspin (rad/s).
    fn launch_spin(&self) -> f64;
    /// rad from the centre-field line, positive toward right field.
    fn launch_direction(&self) -> f64;
    /// rad/s, positive curving toward right field.
    fn launch_sidespin(&self) -> f64;
}

impl Launches for Impact {
    fn launch_speed(&self) -> f64 {
        Impact::launch_speed(self)
    }
    fn launch_angle(&self) -> f64 {
        Impact::launch_angle(self)
    }
    fn launch_spin(&self) -> f64 {
        Impact::launch_spin(self)
    }
    /// The plane toward centre field.
    fn launch_direction(&self) -> f64 {
        0.0
    }
    fn launch_sidespin(&self) -> f64 {
        0.0
    }
}

/// [`Launches`] from a type's own methods of the same names.
macro_rules! launches_by_its_own_methods {
    ($type:ty) => {
        impl Launches for $type {
            fn launch_speed(&self) -> f64 {
                <$type>::launch_speed(self)
            }
            fn launch_angle(&self) -> f64 {
                <$type>::launch_angle(self)
            }
            fn launch_spin(&self) -> f64 {
                <$type>::launch_spin(self)
            }
            fn launch_direction(&self) -> f64 {
                <$type>::launch_direction(self)
            }
            fn launch_sidespin(&self) -> f64 {
                <$type>::launch_sidespin(self)
            }
        }
    };
}

launches_by_its_own_methods!(Impact3d);
launches_by_its_own_methods!(Collision);

/// A scene's collision: the paper's planar one for a level bat square to
/// the pitch (bit for bit the paper's numbers), the 3-D one otherwise.
// Unboxed, and so Copy: one is made per swing, in the optimiser's loop too,
// where a box would allocate each time; 584 bytes on the stack cost less.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Collision {
    Planar(Impact),
    Spatial(Impact3d),
}

/// `$impact.$call` for either kind.
macro_rules! either {
    ($self:expr, $impact:ident => $body:expr) => {
        match $self {
            Collision::Planar($impact) => $body,
            Collision::Spatial($impact) => $body,
        }
    };
}

impl Collision {
    /// Solves the collision of a (validated) scene.
    pub fn new(scene: &Scene) -> Collision {
        if scene.bat.is_planar() {
            Collision::Planar(Impact::new(scene))
        } else {
            Collision::Spatial(Impact3d::new(scene))
        }
    }

    /// The planar impact, if this is one.
    pub fn planar(&self) -> Option<&Impact> {
        match self {
            Collision::Planar(impact) => Some(impact),
            Collision::Spatial(_) => None,
        }
    }

    /// The 3-D impact, if this is one.
    pub fn spatial(&self) -> Option<&Impact3d> {
        match self {
            Collision::Planar(_) => None,
            Collision::Spatial(impact) => Some(impact),
        }
    }

    /// θ (Eq. 1): from the horizontal in the plane, from ŵ square to the
    /// bat in 3-D.
    pub fn normal_angle(&self) -> f64 {
        either!(self, i => i.normal_angle)
    }
    /// γ (Eq. 4).
    pub fn descent_angle(&self) -> f64 {
        either!(self, i => i.descent_angle)
    }
    /// e* (Eq. 19).
    pub fn restitution(&self) -> f64 {
        either!(self, i => i.restitution)
    }
    pub fn regime(&self) -> Regime {
        either!(self, i => i.regime)
    }
    /// v3(0) (m/s), negative approaching.
    pub fn initial_approach(&self) -> f64 {
        either!(self, i => i.initial_approach)
    }
    /// p_c (Eq. 18).
    pub fn compression_impulse(&self) -> f64 {
        either!(self, i => i.compression_impulse)
    }
    /// p_f (Eq. 20).
    pub fn separation_impulse(&self) -> f64 {
        either!(self, i => i.separation_impulse)
    }
    /// p_s if slip halts before separation.
    pub fn stick_impulse(&self) -> Option<f64> {
        either!(self, i => i.stick_impulse())
    }
    /// The tangential impulse a gripping contact gives back after p_s (N·s;
    /// 0 for the paper's rolling).
    pub fn release_impulse(&self) -> f64 {
        match self {
            Collision::Planar(i) => i.release_impulse,
            Collision::Spatial(i) => i.release.norm(),
        }
    }
    pub fn stops(&self) -> Vec<Stop> {
        either!(self, i => i.stops())
    }
    pub fn launch_speed(&self) -> f64 {
        either!(self, i => i.launch_speed())
    }
    pub fn launch_angle(&self) -> f64 {
        either!(self, i => i.launch_angle())
    }
    pub fn launch_spin(&self) -> f64 {
        either!(self, i => i.launch_spin())
    }
    pub fn launch_direction(&self) -> f64 {
        either!(self, i => Launches::launch_direction(i))
    }
    pub fn launch_sidespin(&self) -> f64 {
        either!(self, i => Launches::launch_sidespin(i))
    }
    /// Spin about the launch velocity (rad/s): 0 in the plane.
    pub fn launch_gyrospin(&self) -> f64 {
        match self {
            Collision::Planar(_) => 0.0,
            Collision::Spatial(i) => i.launch_gyrospin(),
        }
    }
    /// Both bodies at normal impulse p (0 ≤ p ≤ p_f), as the step-through
    /// shows them.
    pub fn at(&self, impulse: f64) -> Moment {
        match self {
            Collision::Planar(i) => {
                let s = i.at(impulse);
                let v = s.ball_velocity;
                Moment {
                    impulse,
                    slip: nalgebra::Vector2::new(s.slip_velocity, 0.0),
                    normal_velocity: s.normal_velocity,
                    ball_velocity: nalgebra::Vector3::new(v.x, v.y, 0.0),
                    ball_spin: nalgebra::Vector3::new(0.0, 0.0, s.ball_spin),
                }
            }
            Collision::Spatial(i) => {
                let s = i.at(impulse);
                Moment {
                    impulse,
                    slip: s.slip,
                    normal_velocity: s.normal_velocity,
                    ball_velocity: s.ball_velocity,
                    ball_spin: s.ball_spin,
                }
            }
        }
    }

    /// The ball's velocity at separation, in the flight frame (z = 0 in
    /// the plane).
    pub fn launch_velocity(&self) -> nalgebra::Vector3<f64> {
        match self {
            Collision::Planar(i) => {
                let v = i.after.ball_velocity;
                nalgebra::Vector3::new(v.x, v.y, 0.0)
            }
            Collision::Spatial(i) => i.after.ball_velocity,
        }
    }
}

/// One moment of either collision, for the step-through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moment {
    /// p (N·s).
    pub impulse: f64,
    /// (v1, v2): the slip across the bat and along it (v2 = 0 in the
    /// plane) (m/s).
    pub slip: nalgebra::Vector2<f64>,
    /// v3 (m/s).
    pub normal_velocity: f64,
    /// The ball's velocity and spin in the flight frame (the plane's spin
    /// is its z component).
    pub ball_velocity: nalgebra::Vector3<f64>,
    pub ball_spin: nalgebra::Vector3<f64>,
}

impl From<Impact> for Collision {
    fn from(impact: Impact) -> Collision {
        Collision::Planar(impact)
    }
}

impl From<Impact3d> for Collision {
    fn from(impact: Impact3d) -> Collision {
        Collision::Spatial(impact)
    }
}
