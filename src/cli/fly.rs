//! `fly`: a scene's launch and flight, whatever its kind (a batted ball
//! from `launch.*`, or a swing's launch from its impact); and `fly --batch`,
//! one launch per CSV row (see [`super::batch`]).

use super::SpinArg;
use super::ground::{
    FlownToFence, Ground, all_parks_json, all_parks_table, clearing_json, clearing_text,
    parks_json, parks_text,
};
use super::hit::{environment_json, flight_json, flight_text, labelled};
use super::pretty;
use super::shown::Shown;
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::precision::Purpose;
use crate::model::atmosphere::Air;
use crate::model::launch::{self, BattedBall, SceneKind};
use crate::model::park::{self, GivenWeather};
use crate::preset::Preset;
use crate::preset::parks::Parks;
use crate::units::Quantity;

pub(super) fn fly(
    preset: &Preset,
    ground: Ground,
    parks: &Parks,
    (all_parks, own_air): (bool, Option<GivenWeather>),
    (json, spin): (bool, Option<SpinArg>),
    shown: Shown,
) -> String {
    let scene = &preset.scene;
    let estimated = spin == Some(SpinArg::Nathan);
    let fences: Vec<&park::Fence> = parks.parks.iter().map(|p| &p.fence).collect();
    let own_air = own_air.map(|given| (parks, given));
    let flown = FlownToFence::new(scene, ground.fence(), &fences, own_air);
    let (launch, flight) = (&flown.launch, &flown.flight);
    let unlanded = (!flight.landed).then(|| landing::not_landed(flight, end_height(scene)));
    if json {
        let mut fence = clearing_json(ground.code(), &flown.clearing);
        fence["clears"] = flown.clears_fence().into();
        let mut json = serde_json::json!({
            "scene": scene.kind.name(),
            // {speed, angle, spin, direction, sidespin}: BattedBall's fields.
            "launch": launch,
            "model": model_json(scene),
            "flight": flight_json(flight, unlanded),
            "fence": fence,
            "parks": parks_json(&flown, parks),
            "environment": environment_json(scene),
        });
        if all_parks {
            json["all_parks"] = all_parks_json(&flown, parks);
        }
        if estimated {
            json["spin_estimated"] = true.into();
        }
        return pretty(&json);
    }
    // A batted ball takes what it was not given from its swing's impact:
    // say which, as a launch given whole says nothing.
    let given = scene.launch;
    let taken: Vec<&str> = [
        ("speed", given.speed),
        ("angle", given.angle),
        ("spin", given.spin),
    ]
    .into_iter()
    .filter_map(|(name, value)| value.is_none().then_some(name))
    .collect();
    let from = match scene.kind {
        _ if estimated => format!(
            "; spin estimated (Nathan's relation, a {}-handed batter)",
            scene.bat.hand.name()
        ),
        SceneKind::Swing => " (from the swing's impact)".to_owned(),
        SceneKind::BattedBall if !taken.is_empty() => format!(
            "; {} from the swing's impact{}",
            taken.join(" and "),
            // Unless the swing's spin was asked for.
            if given.spin.is_none() && spin.is_none() {
                " (--spin nathan estimates the spin)"
            } else {
                ""
            }
        ),
        SceneKind::BattedBall => String::new(),
    };
    let air = scene.environment.air();
    let unlanded = unlanded.map(|why| {
        if shown.is_si() {
            why
        } else {
            shown.not_landed(flight, end_height(scene))
        }
    });
    let mut text = labelled(&[
        ("launch", format!("{}{from}", batted_text(launch, shown))),
        ("flight", flight_text(flight, unlanded.as_deref(), shown)),
        ("fence", clearing_text(&ground, &flown.clearing, shown)),
        ("parks", parks_text(&flown, parks, own_air.is_some())),
        (
            "air",
            format!(
                "ρ = {}, ν = {:.4e} m²/s; {}",
                air_text(&air, shown),
                air.kinematic_viscosity,
                scene.models_text()
            ),
        ),
    ]);
    if all_parks {
        text.push('\n');
        text += &all_parks_table(&flown, parks, shown);
    }
    text
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
pub(super) fn air_text(air: &Air, shown: Shown) -> String {
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
