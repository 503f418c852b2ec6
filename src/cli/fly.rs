//! `fly`: a scene's launch and flight, whatever its kind (a batted ball
//! from `launch.*`, or a swing's launch from its impact); and `fly --batch`,
//! one launch per CSV row (see [`super::batch`]).

use super::hit::{environment_json, flight_json, flight_text, labelled};
use super::pretty;
use super::shown::Shown;
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::precision::Purpose;
use crate::model::atmosphere::Air;
use crate::model::flight::FlightSummary;
use crate::model::launch::{self, BattedBall, SceneKind};
use crate::preset::{FIELD_KEYS, Fence, Preset};
use crate::units::Quantity;

/// The fence a preset draws, or the default one (121.9 m, 3.0 m).
pub(super) fn fence_of(preset: &Preset) -> Fence {
    preset.fence.unwrap_or(Fence {
        distance: FIELD_KEYS[0].default,
        height: FIELD_KEYS[1].default,
    })
}

/// One scene's flight, at readout precision, with the fence it clears or not.
pub(super) struct FlownToFence {
    pub launch: BattedBall,
    pub flight: FlightSummary,
    /// The ball's height where it passes the fence's distance, if it gets there.
    pub height_at_fence: Option<f64>,
    pub fence: Fence,
}

impl FlownToFence {
    pub fn new(scene: &Scene, fence: Fence) -> FlownToFence {
        let (flight, height_at_fence) =
            launch::height_at_distance(scene, fence.distance, Purpose::Readout);
        FlownToFence {
            launch: scene.batted_ball(),
            flight,
            height_at_fence,
            fence,
        }
    }

    pub fn clears_fence(&self) -> bool {
        self.height_at_fence.is_some_and(|h| h >= self.fence.height)
    }
}

pub(super) fn fly(preset: &Preset, json: bool, shown: Shown) -> String {
    let scene = &preset.scene;
    let flown = FlownToFence::new(scene, fence_of(preset));
    let (launch, flight, fence) = (&flown.launch, &flown.flight, &flown.fence);
    let unlanded = (!flight.landed).then(|| landing::not_landed(flight, end_height(scene)));
    if json {
        return pretty(&serde_json::json!({
            "scene": scene.kind.name(),
            // {speed, angle, spin, direction, sidespin}: BattedBall's fields.
            "launch": launch,
            "model": model_json(scene),
            "flight": flight_json(flight, unlanded),
            "fence": {
                "distance": fence.distance,
                "height": fence.height,
                "height_at_fence": flown.height_at_fence,
                "clears": flown.clears_fence(),
            },
            "environment": environment_json(scene),
        }));
    }
    let from = match scene.kind {
        SceneKind::Swing => " (from the swing's impact)",
        SceneKind::BattedBall => "",
    };
    // The explorer's words (analysis::landing::fence_text).
    let fence_line = landing::fence_text(
        fence.distance,
        fence.height,
        flown.height_at_fence,
        shown.unit(Quantity::Distance),
    );
    let air = scene.environment.air();
    let unlanded = unlanded.map(|why| {
        if shown.is_si() {
            why
        } else {
            shown.not_landed(flight, end_height(scene))
        }
    });
    labelled(&[
        ("launch", format!("{}{from}", batted_text(launch, shown))),
        ("flight", flight_text(flight, unlanded.as_deref(), shown)),
        ("fence", fence_line),
        (
            "air",
            format!(
                "ρ = {}, ν = {:.4e} m²/s; {}",
                air_text(&air, shown),
                air.kinematic_viscosity,
                scene.models_text()
            ),
        ),
    ])
}

/// The models in force and whether the user chose them, as JSON.
pub(super) fn model_json(scene: &Scene) -> serde_json::Value {
    serde_json::json!({
        "drag": scene.drag.name(),
        "lift": scene.lift.name(),
        "chosen": {"drag": scene.chosen.drag, "lift": scene.chosen.lift},
    })
}

/// "1.194 kg/m³ from 21 °C, 5 m, 1013 hPa, 50 %" ([`Air`]'s own words in
/// SI), with the weather in °F, ft and inHg otherwise; ρ is kg/m³ in both.
fn air_text(air: &Air, shown: Shown) -> String {
    match air.atmosphere {
        Some(weather) if !shown.is_si() => format!(
            "{:.3} kg/m³ from {}, {}, {}, {} %",
            air.density,
            shown.value_to(Quantity::Temperature, weather.temperature, 1),
            shown.value_to(Quantity::Distance, weather.elevation, 0),
            shown.value_to(Quantity::Pressure, weather.pressure, 2),
            weather.humidity
        ),
        _ => air.to_string(),
    }
}

/// Where a flight that did not land ended (m above the ground).
fn end_height(scene: &Scene) -> f64 {
    let options = Purpose::Readout.flight_options();
    let (_, points) = launch::scene_start(scene).0.trajectory(&options, 2);
    points.last().map_or(0.0, |p| p.y)
}

/// "46.045 m/s, 261.80 rad/s of backspin, 0.4887 rad (28.0°)", or
/// "103.000 mph, 2500 rpm of backspin, 28.0°"
pub(super) fn batted_text(launch: &BattedBall, shown: Shown) -> String {
    let mut text = shown.launch(launch.speed, launch.spin, launch.angle);
    if launch.direction != 0.0 {
        text += &format!(", {}", shown.direction(launch.direction));
    }
    if launch.sidespin != 0.0 {
        text += &format!(", {}", shown.sidespin(launch.sidespin));
    }
    text
}
