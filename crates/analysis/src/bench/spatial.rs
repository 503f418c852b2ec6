//! The 3-D flight's rows of `homerun bench`: what a flight out of the
//! plane costs against the planar one, at the same tolerances.

use serde::Serialize;

use super::{Effort, TRAJECTORY_BATCH, stated_mixed, time_median};
use crate::precision::Purpose;
use model::flight::{self, Flight3d, FlightOptions, FlightSummary, Launch3d};
use model::frame;
use model::launch::{BattedBall, SceneFlight};
use model::scene::{Scene, SceneKind};

/// One flight of the fly-ball launch (103 mph, 28°, 2500 rpm, Nathan's aero)
/// at one tolerance (dopri5, relative 10^−e, absolute 10^−(e−1)), its error
/// against the same flight at `Purpose::Reference`.
#[derive(Clone, Debug, Serialize)]
pub struct SpatialRow {
    /// Which flight: "planar", "3-D in the plane", "3-D sidespin, crosswind",
    /// "3-D wind above 10 m".
    pub flight: &'static str,
    pub tolerance: f64,
    pub absolute: f64,
    pub evaluations: u32,
    pub rejected: u32,
    pub time_us: f64,
    pub cpu_us: Option<f64>,
    pub range_error: f64,
    /// Error of the landing's direction (rad).
    pub direction_error: f64,
}

/// The fly-ball preset's launch, optionally pulled with sidespin.
fn fly_ball(direction: f64, sidespin: f64) -> BattedBall {
    BattedBall {
        speed: 46.04512,
        angle: 28f64.to_radians(),
        spin: 2500.0 * std::f64::consts::TAU / 60.0,
        direction,
        sidespin,
    }
}

/// The flights compared: the planar fly ball, the same ball forced through
/// the 3-D flight, and two that need it.
fn cases() -> Vec<(&'static str, Scene, BattedBall, bool)> {
    let mut batted = Scene::default();
    batted.set_kind(SceneKind::BattedBall);
    let mut crosswind = batted;
    crosswind.environment.wind = 5.0;
    crosswind.environment.wind_direction = 1.2;
    let mut layered = batted;
    layered.environment.wind = 5.0;
    layered.environment.wind_direction = 0.5;
    layered.environment.wind_height = 10.0;
    // −1000 rpm of sidespin on a ball pulled 17° to left field: a hook.
    let hook = fly_ball(-0.3, -1000.0 * std::f64::consts::TAU / 60.0);
    vec![
        ("planar", batted, fly_ball(0.0, 0.0), false),
        ("3-D in the plane", batted, fly_ball(0.0, 0.0), true),
        ("3-D sidespin, crosswind", crosswind, hook, true),
        ("3-D wind above 10 m", layered, hook, true),
    ]
}

/// One case's flight: the scene's own choice, or forced into 3-D.
fn flight_of(scene: &Scene, launch: &BattedBall, spatial: bool) -> SceneFlight {
    if !spatial {
        return SceneFlight::new(scene, launch);
    }
    SceneFlight::Spatial {
        flight: Flight3d::new(scene, launch.spin_vector()),
        launch: Launch3d {
            position: nalgebra::Vector3::new(0.0, scene.environment.contact_height, 0.0),
            velocity: frame::launch_velocity(launch.speed, launch.angle, launch.direction),
        },
    }
}

fn fly(flight: &SceneFlight, options: &FlightOptions) -> FlightSummary {
    match flight {
        SceneFlight::Spatial { flight, launch } => flight::fly(flight, launch, options),
        planar => planar.fly(options),
    }
}

pub(super) fn rows(effort: Effort, quick: bool) -> Vec<SpatialRow> {
    let exponents: &[i32] = if quick { &[5, 8] } else { &[4, 5, 6, 7, 8, 10] };
    let mut rows = Vec::new();
    for (name, scene, launch, spatial) in cases() {
        let flight = flight_of(&scene, &launch, spatial);
        let reference = fly(&flight, &Purpose::Reference.flight_options());
        for &e in exponents {
            let options = stated_mixed(e, e - 1, true);
            let summary = fly(&flight, &options);
            let (time, cpu) = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, || {
                fly(std::hint::black_box(&flight), &options)
            });
            rows.push(SpatialRow {
                flight: name,
                tolerance: options.tolerance.relative,
                absolute: options.tolerance.absolute,
                evaluations: summary.stats.evaluations,
                rejected: summary.stats.rejected,
                time_us: time * 1e6,
                cpu_us: cpu.map(|c| c * 1e6),
                range_error: summary.range - reference.range,
                direction_error: summary.direction - reference.direction,
            });
        }
    }
    rows
}
