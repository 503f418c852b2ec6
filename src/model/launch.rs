//! What a scene models: a swing (pitch → impact → flight, the paper's
//! scene) or a batted ball (launch → flight, no pitch and no impact, as
//! Statcast and the trajectory calculators start). One function,
//! [`fly_scene`], gives either kind's launch and flight.

use nalgebra::Vector2;
use serde::{Deserialize, Serialize};

use super::flight::{self, Flight, FlightOptions, FlightSummary, Launch};
use super::impact::Impact;
use super::keys::{InputError, LAUNCH_KEYS};
use super::scene::Scene;
use crate::units::significant;

/// Which phases a scene models.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SceneKind {
    /// Pitch → impact → flight: the launch comes out of the impact.
    #[default]
    Swing,
    /// Launch → flight: the launch is given (`launch.*`); pitch and bat
    /// only supply a launch value that is not given.
    BattedBall,
}

/// A batted ball as it leaves the bat.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BattedBall {
    /// V̂_bf (m/s).
    pub speed: f64,
    /// ζ, above the horizontal (rad).
    pub angle: f64,
    /// ω_bf (rad/s), backspin positive.
    pub spin: f64,
}

impl BattedBall {
    /// The launch of `impact`.
    pub fn of(impact: &Impact) -> BattedBall {
        BattedBall {
            speed: impact.launch_speed(),
            angle: impact.launch_angle(),
            spin: impact.launch_spin(),
        }
    }
}

/// The launch values a batted-ball scene gives (`launch.speed`,
/// `launch.angle`, `launch.spin`); `None` takes the value from the scene's
/// own swing, so `--set launch.angle=0.5` on the fastball flies the
/// fastball's launch speed and spin at 0.5 rad whatever order the other
/// `--set`s come in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct GivenLaunch {
    pub speed: Option<f64>,
    pub angle: Option<f64>,
    pub spin: Option<f64>,
}

impl GivenLaunch {
    pub fn is_empty(&self) -> bool {
        self.speed.is_none() && self.angle.is_none() && self.spin.is_none()
    }

    pub fn is_complete(&self) -> bool {
        self.speed.is_some() && self.angle.is_some() && self.spin.is_some()
    }
}

/// A scene's launch and its flight, whatever the scene's kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flown {
    pub launch: BattedBall,
    /// The impact, for a swing scene (`None` for a batted ball).
    pub impact: Option<Impact>,
    pub flight: FlightSummary,
}

impl Scene {
    /// The launch of this scene: the impact's for a swing; for a batted
    /// ball the given values, each one not given taken from the impact of
    /// the scene's own swing (computed only then).
    pub fn batted_ball(&self) -> BattedBall {
        let given = self.launch;
        if self.kind == SceneKind::BattedBall && given.is_complete() {
            return BattedBall {
                speed: given.speed.unwrap_or_default(),
                angle: given.angle.unwrap_or_default(),
                spin: given.spin.unwrap_or_default(),
            };
        }
        let own = BattedBall::of(&Impact::new(self));
        if self.kind == SceneKind::Swing {
            return own;
        }
        BattedBall {
            speed: given.speed.unwrap_or(own.speed),
            angle: given.angle.unwrap_or(own.angle),
            spin: given.spin.unwrap_or(own.spin),
        }
    }

    /// This scene as a batted ball launched as `launch`: every launch value
    /// given, so pitch and bat no longer matter (the explorer's switch to
    /// the batted-ball scene freezes the swing's launch with it).
    pub fn with_launch(&self, launch: BattedBall) -> Scene {
        let mut scene = *self;
        scene.kind = SceneKind::BattedBall;
        scene.launch = GivenLaunch {
            speed: Some(launch.speed),
            angle: Some(launch.angle),
            spin: Some(launch.spin),
        };
        scene
    }

    /// This scene as the swing it holds (the launch values are kept, unused,
    /// for a switch back).
    pub fn as_swing(&self) -> Scene {
        Scene {
            kind: SceneKind::Swing,
            ..*self
        }
    }
}

/// The inputs of a swing that make its launch, as an error names them.
const SWING_KEYS: [&str; 6] = [
    "pitch.speed",
    "pitch.spin",
    "bat.speed",
    "bat.spin",
    "bat.undercut",
    "bat.swing_angle",
];

impl Scene {
    /// Refuses a batted ball that would fly a launch value taken from its
    /// swing outside that `launch.*` key's bounds (`--set bat.speed=100
    /// --set launch.angle=0.5` would fly the swing's 106.9 m/s): what a
    /// batted ball flies must be a launch that could be given, so that the
    /// preset saved from it loads. A swing scene flies whatever its impact
    /// gives (a foul tip backwards, the spins of Fig. 5's cusps): its inputs
    /// are the swing, and its launch becomes a batted ball only through
    /// [`Scene::with_launch`], whose scene this validation then refuses.
    pub(super) fn check_swing_launch(&self) -> Result<(), InputError> {
        let given = self.launch;
        if self.kind == SceneKind::Swing || given.is_complete() {
            return Ok(());
        }
        let own = BattedBall::of(&Impact::new(self));
        let values = [
            (given.speed, own.speed),
            (given.angle, own.angle),
            (given.spin, own.spin),
        ];
        for (key, (given, value)) in LAUNCH_KEYS.iter().zip(values) {
            if given.is_none() && !key.bounds.contains(value) {
                let swing = SWING_KEYS
                    .iter()
                    .map(|name| {
                        let value = self.get(name).unwrap_or(f64::NAN);
                        format!("{name} = {}", significant(value))
                    })
                    .collect::<Vec<_>>()
                    .join(", ");
                return Err(InputError::SwingLaunch {
                    key: key.name,
                    value,
                    bounds: key.bounds,
                    unit: key.unit,
                    swing,
                });
            }
        }
        Ok(())
    }
}

/// The forces and the starting point of `launch`'s flight in `scene`'s air,
/// from the contact height.
pub fn start(scene: &Scene, launch: &BattedBall) -> (Flight, Launch) {
    (
        Flight::new(scene, launch.spin),
        Launch {
            position: Vector2::new(0.0, scene.environment.contact_height),
            velocity: Vector2::new(launch.angle.cos(), launch.angle.sin()) * launch.speed,
        },
    )
}

/// The forces and starting point of a (validated) scene's flight, whatever
/// its kind: a swing's launch velocity is the impact's own (not rebuilt
/// from speed and angle), so a swing scene flies exactly as `simulate`.
pub fn scene_start(scene: &Scene) -> (Flight, Launch, BattedBall, Option<Impact>) {
    match scene.kind {
        SceneKind::Swing => {
            let impact = Impact::new(scene);
            let (flight, launch) = super::launch(scene, &impact);
            (flight, launch, BattedBall::of(&impact), Some(impact))
        }
        SceneKind::BattedBall => {
            let batted = scene.batted_ball();
            let (flight, launch) = start(scene, &batted);
            (flight, launch, batted, None)
        }
    }
}

/// Flies a (validated) scene's launch as precisely as `options` says: the
/// one call the CLI and the explorer make for "this scene's flight".
pub fn fly_scene(scene: &Scene, options: impl Into<FlightOptions>) -> Flown {
    let (flight, start, launch, impact) = scene_start(scene);
    Flown {
        launch,
        impact,
        flight: flight::fly(&flight, &start, &options.into()),
    }
}

/// The ball's height (m) where it passes `distance` (m) from the plate, the
/// first time it does, read off the integrator's continuous extension; and
/// the flight. `None` if it never gets that far.
pub fn height_at_distance(
    scene: &Scene,
    distance: f64,
    options: impl Into<FlightOptions>,
) -> (FlightSummary, Option<f64>) {
    let (flight, start, _, _) = scene_start(scene);
    let mut height = None;
    let summary = flight::fly_observed(&flight, &start, &options.into(), |step| {
        if height.is_some() {
            return;
        }
        let (x0, x1) = (step.y0[0], step.y1[0]);
        if !(x0 < distance && distance <= x1) {
            return;
        }
        // Bisection on x(t) = distance: x rises through the step (it did at
        // both ends; a ball that turns back within one step is no home run).
        let (mut low, mut high) = (step.t0, step.t1);
        for _ in 0..60 {
            let middle = 0.5 * (low + high);
            if step.at(middle)[0] < distance {
                low = middle;
            } else {
                high = middle;
            }
        }
        height = Some(step.at(high)[1]);
    });
    // A step may carry the dense output past the landing: only a crossing
    // above the ground counts.
    (summary, height.filter(|&h| h >= 0.0))
}
