//! The paper's model, one file per phase: pitch (Eq. 3–4) → impact
//! (Eq. 1–2, 5–23, in the plane or, for a tilted or turned bat, in 3-D) →
//! flight (Eq. 25–29, in the plane or in 3-D), with the
//! aerodynamic models in `aero`, the air from the weather in `atmosphere`
//! and the 3-D frame's conventions in `frame`; a batted ball flown from its
//! launch alone, and which flight a scene needs, in `launch`; the inputs in
//! `scene` and their names, bounds and validation in `keys`. It knows
//! nothing of who asks or how precisely: callers pass [`FlightOptions`] (or
//! anything that becomes them, such as `analysis::precision::Purpose`).
//!
//! The arrows point one way: `aero`, `atmosphere` and `frame` at the
//! bottom; `scene` (plain data) above them; the phases `pitch`, `impact`,
//! `flight` and `launch` above the scene; `keys` (names, bounds and
//! accessors of the inputs) on top.

pub mod aero;
pub mod atmosphere;
pub mod clearing;
pub mod flight;
pub mod frame;
pub mod impact;
pub mod keys;
pub mod launch;
pub mod many;
pub mod park;
pub mod pitch;
pub mod scene;
pub mod spin_estimate;
pub mod tracked_pitch;

use nalgebra::Vector2;

use flight::{Flight, FlightOptions, FlightSummary, Launch};
use impact::{Collision, Impact};
use scene::Scene;

/// One swing, start to finish.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Swing {
    pub impact: Collision,
    pub flight: FlightSummary,
}

/// The planar flight's forces and starting point after the planar
/// `impact`, in the plane toward centre field: the paper's flight, for
/// callers that study the paper's scene (with the wind along centre field). A scene in general
/// flies through [`launch::SceneFlight`], as [`simulate`] does.
pub fn launch(scene: &Scene, impact: &Impact) -> (Flight, Launch) {
    (
        Flight::new(scene, impact.launch_spin()),
        Launch {
            position: Vector2::new(0.0, scene.environment.contact_height),
            velocity: impact.after.ball_velocity,
        },
    )
}

/// Simulates a (validated) scene as precisely as `options` says.
pub fn simulate(scene: &Scene, options: impl Into<FlightOptions>) -> Swing {
    let impact = Collision::new(scene);
    Swing {
        impact,
        flight: launch::SceneFlight::of_impact(scene, &impact).fly(&options.into()),
    }
}

/// Flies a batted ball from a launch given directly (speed in m/s, angle
/// above the horizontal in rad, spin in rad/s with backspin positive), from
/// the scene's contact height, with no pitch and no impact: the scene gives
/// only the ball, the air, the field and the aerodynamic models.
pub fn fly_launch(
    scene: &Scene,
    launch_speed: f64,
    launch_angle: f64,
    launch_spin: f64,
    options: impl Into<FlightOptions>,
) -> FlightSummary {
    let batted = launch::BattedBall {
        speed: launch_speed,
        angle: launch_angle,
        spin: launch_spin,
        direction: 0.0,
        sidespin: 0.0,
    };
    launch::SceneFlight::new(scene, &batted).fly(&options.into())
}

/// Just the range: what the optimiser and the heatmap need.
pub fn range(scene: &Scene, options: impl Into<FlightOptions>) -> f64 {
    simulate(scene, options).flight.range
}
