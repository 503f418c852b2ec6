//! What a scene flies: a swing's launch (pitch → impact, the paper's scene)
//! or a batted ball's (given, as Statcast and the trajectory calculators
//! start), in the plane or in three dimensions. [`SceneFlight`] picks the
//! cheaper flight that is exact for the scene: the planar one whenever
//! nothing leaves the launch's vertical plane. [`fly_scene`] gives either
//! kind's launch and flight.

use nalgebra::{Vector2, Vector3};
use serde::Serialize;

use super::flight::{
    self, Flight, Flight3d, FlightOptions, FlightSummary, Launch, Launch3d, TrajectoryPoint,
};
use super::frame;
use super::impact::{Collision, Launches};
use super::keys::{InputError, LAUNCH_KEYS};
use super::park::Fence;
use super::scene::Scene;
use units::significant;

pub use super::scene::{GivenLaunch, SceneKind};

/// A batted ball as it leaves the bat.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BattedBall {
    /// V̂_bf (m/s).
    pub speed: f64,
    /// ζ, above the horizontal (rad).
    pub angle: f64,
    /// ω_bf (rad/s), backspin positive.
    pub spin: f64,
    /// Horizontal direction (rad from the centre-field line, positive
    /// toward right field).
    pub direction: f64,
    /// Sidespin (rad/s), positive curving the ball toward right field
    /// ([`frame::sidespin_axis`]).
    pub sidespin: f64,
}

impl BattedBall {
    /// The launch of `impact`: the paper's planar swing leaves toward centre
    /// field with backspin only; a 3-D swing in any direction with
    /// sidespin too (its spin about the launch velocity, which bends no
    /// flight, is left out, as frame.rs has it).
    pub fn of(impact: &impl Launches) -> BattedBall {
        BattedBall {
            speed: impact.launch_speed(),
            angle: impact.launch_angle(),
            spin: impact.launch_spin(),
            direction: impact.launch_direction(),
            sidespin: impact.launch_sidespin(),
        }
    }

    /// The spin vector (rad/s) in the flight frame.
    pub fn spin_vector(&self) -> Vector3<f64> {
        frame::spin_vector(self.spin, self.sidespin, self.angle, self.direction)
    }
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
                direction: given.direction.unwrap_or_default(),
                sidespin: given.sidespin.unwrap_or_default(),
            };
        }
        let own = BattedBall::of(&Collision::new(self));
        if self.kind == SceneKind::Swing {
            return own;
        }
        BattedBall {
            speed: given.speed.unwrap_or(own.speed),
            angle: given.angle.unwrap_or(own.angle),
            spin: given.spin.unwrap_or(own.spin),
            direction: given.direction.unwrap_or(own.direction),
            sidespin: given.sidespin.unwrap_or(own.sidespin),
        }
    }

    /// This scene as a batted ball launched as `launch`: every launch value
    /// given, so pitch and bat no longer matter (the explorer's switch to
    /// the batted-ball scene freezes the swing's launch with it). Models the
    /// user did not choose become the batted ball's.
    pub fn with_launch(&self, launch: BattedBall) -> Scene {
        let mut scene = *self;
        scene.set_kind(SceneKind::BattedBall);
        scene.launch = GivenLaunch {
            speed: Some(launch.speed),
            angle: Some(launch.angle),
            spin: Some(launch.spin),
            direction: Some(launch.direction),
            sidespin: Some(launch.sidespin),
        };
        scene
    }

    /// This scene as the swing it holds (the launch values are kept, unused,
    /// for a switch back; models the user did not choose become the swing's).
    pub fn as_swing(&self) -> Scene {
        let mut scene = *self;
        scene.set_kind(SceneKind::Swing);
        scene
    }
}

/// The 3-D swing's numbers beyond those.
const SWING_3D_KEYS: [&str; 2] = ["bat.tilt", "bat.direction"];

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
        let own = BattedBall::of(&Collision::new(self));
        let own = [own.speed, own.angle, own.spin, own.direction, own.sidespin];
        // A swing out of the paper's plane names its tilt and direction too.
        let out_of_plane: &[&str] = if self.bat.is_planar() {
            &[]
        } else {
            &SWING_3D_KEYS
        };
        for (key, (given, value)) in LAUNCH_KEYS.iter().zip(given.values().into_iter().zip(own)) {
            if given.is_none() && !key.bounds.contains(value) {
                let swing = SWING_KEYS
                    .iter()
                    .chain(out_of_plane)
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

/// A scene's flight, ready to fly: planar when nothing leaves the launch's
/// vertical plane, else in three dimensions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SceneFlight {
    /// In the vertical plane of direction `plane` (rad): the paper's flight,
    /// its x along the plane.
    Planar {
        flight: Flight,
        launch: Launch,
        plane: f64,
    },
    Spatial {
        flight: Flight3d,
        launch: Launch3d,
    },
}

impl SceneFlight {
    /// The flight of `launch` in `scene`'s air, from the contact height. It
    /// stays planar when the ball has no sidespin and the wind blows along
    /// the launch's plane, everywhere (a calm, or a wind with no crosswind
    /// part and no height below which it stops).
    pub fn new(scene: &Scene, launch: &BattedBall) -> SceneFlight {
        if launch.sidespin == 0.0
            && let Some(wind) = Self::wind_in_plane(scene, launch.direction)
        {
            let (sin, cos) = launch.angle.sin_cos();
            let velocity = Vector2::new(cos, sin) * launch.speed;
            return Self::planar(scene, (launch.spin, launch.direction), wind, velocity);
        }
        let env = scene.environment;
        SceneFlight::Spatial {
            flight: Flight3d::new(scene, launch.spin_vector()),
            launch: Launch3d {
                position: Vector3::new(0.0, env.contact_height, 0.0),
                velocity: frame::launch_velocity(launch.speed, launch.angle, launch.direction),
            },
        }
    }

    /// The wind along the plane of `direction` if it blows only along it,
    /// everywhere (see [`SceneFlight::new`]); `None` if the flight leaves it.
    fn wind_in_plane(scene: &Scene, direction: f64) -> Option<f64> {
        let env = scene.environment;
        frame::wind_along(env.wind, env.wind_direction, direction)
            .filter(|_| env.wind == 0.0 || env.wind_height <= 0.0)
    }

    /// The planar flight with backspin `spin` in the plane of `direction`,
    /// launched from the contact height at `velocity` (in the plane).
    fn planar(
        scene: &Scene,
        (spin, direction): (f64, f64),
        wind: f64,
        velocity: Vector2<f64>,
    ) -> SceneFlight {
        let mut flight = Flight::new(scene, spin);
        flight.wind = wind;
        SceneFlight::Planar {
            flight,
            launch: Launch {
                position: Vector2::new(0.0, scene.environment.contact_height),
                velocity,
            },
            plane: direction,
        }
    }

    /// The flight after `impact`, whose launch velocity is the impact's own
    /// (not rebuilt from speed, angle and direction), so a planar swing
    /// flies exactly as the paper's [`super::launch`](fn@super::launch) does.
    pub fn of_impact(scene: &Scene, impact: &Collision) -> SceneFlight {
        // A planar impact flown in its plane needs no launch angle (an
        // arctangent, and a sine and cosine to undo it: a sixth of a
        // surface cell's work outside its flight).
        if let Collision::Planar(planar) = impact {
            let direction = planar.launch_direction();
            if let Some(wind) = Self::wind_in_plane(scene, direction) {
                let spin = (planar.launch_spin(), direction);
                return Self::planar(scene, spin, wind, planar.after.ball_velocity);
            }
        }
        let mut flight = SceneFlight::new(scene, &BattedBall::of(impact));
        match (&mut flight, impact) {
            (SceneFlight::Planar { launch, .. }, Collision::Planar(impact)) => {
                launch.velocity = impact.after.ball_velocity;
            }
            (SceneFlight::Spatial { launch, .. }, Collision::Spatial(impact)) => {
                launch.velocity = impact.after.ball_velocity;
            }
            // A 3-D swing whose ball leaves in a vertical plane without
            // sidespin, or a planar one into a crosswind: from the launch.
            _ => {}
        }
        flight
    }

    pub fn is_planar(&self) -> bool {
        matches!(self, SceneFlight::Planar { .. })
    }

    /// Flies to the landing as precisely as `options` says. A planar
    /// flight's landing lies in its plane's direction.
    pub fn fly(&self, options: &FlightOptions) -> FlightSummary {
        match self {
            SceneFlight::Planar {
                flight,
                launch,
                plane,
            } => FlightSummary {
                direction: *plane,
                ..flight::fly(flight, launch, options)
            },
            SceneFlight::Spatial { flight, launch } => flight::fly(flight, launch, options),
        }
    }

    /// The flight sampled at `samples` equal times (see
    /// [`flight::trajectory`]), in the flight frame.
    pub fn trajectory(
        &self,
        options: &FlightOptions,
        samples: usize,
    ) -> (FlightSummary, Vec<TrajectoryPoint>) {
        match self {
            SceneFlight::Planar {
                flight,
                launch,
                plane,
            } => {
                let (summary, mut points) = flight::trajectory(flight, launch, options, samples);
                if *plane != 0.0 {
                    let (sin, cos) = plane.sin_cos();
                    for p in &mut points {
                        (p.x, p.z) = (p.x * cos, p.x * sin);
                    }
                }
                (
                    FlightSummary {
                        direction: *plane,
                        ..summary
                    },
                    points,
                )
            }
            SceneFlight::Spatial { flight, launch } => {
                flight::trajectory(flight, launch, options, samples)
            }
        }
    }

    /// The ball's height (m) where it first gets `distance` (m) from the
    /// plate, horizontally, read off the integrator's continuous extension;
    /// and the flight. `None` if it never gets that far above the field.
    /// The crossing of a fence the same distance away in every direction
    /// ([`SceneFlight::fly_to_fences`]).
    pub fn height_at_distance(
        &self,
        distance: f64,
        options: &FlightOptions,
    ) -> (FlightSummary, Option<f64>) {
        let circle = Fence::uniform(distance, 1.0);
        let mut crossing = [None];
        let summary = self.fly_to_fences(options, &[&circle], &mut crossing);
        (summary, crossing[0].map(|c| c.height))
    }
}

/// A scene's launch and its flight, whatever the scene's kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flown {
    pub launch: BattedBall,
    /// The impact, for a swing scene (`None` for a batted ball).
    pub impact: Option<Collision>,
    pub flight: FlightSummary,
}

/// The flight, launch and impact (for a swing) of a (validated) scene,
/// whatever its kind.
pub fn scene_start(scene: &Scene) -> (SceneFlight, BattedBall, Option<Collision>) {
    match scene.kind {
        SceneKind::Swing => {
            let impact = Collision::new(scene);
            (
                SceneFlight::of_impact(scene, &impact),
                BattedBall::of(&impact),
                Some(impact),
            )
        }
        SceneKind::BattedBall => {
            let batted = scene.batted_ball();
            (SceneFlight::new(scene, &batted), batted, None)
        }
    }
}

/// Flies a (validated) scene's launch as precisely as `options` says: the
/// one call the CLI and the explorer make for "this scene's flight".
pub fn fly_scene(scene: &Scene, options: impl Into<FlightOptions>) -> Flown {
    let (flight, launch, impact) = scene_start(scene);
    Flown {
        launch,
        impact,
        flight: flight.fly(&options.into()),
    }
}

/// The ball's height (m) where it first gets `distance` (m) from the plate
/// (see [`SceneFlight::height_at_distance`]), and the flight.
pub fn height_at_distance(
    scene: &Scene,
    distance: f64,
    options: impl Into<FlightOptions>,
) -> (FlightSummary, Option<f64>) {
    scene_start(scene)
        .0
        .height_at_distance(distance, &options.into())
}
