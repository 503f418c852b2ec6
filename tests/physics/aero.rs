//! The models beyond the paper: Nathan's drag and lift, no lift, spin decay,
//! the air from the weather, and flights from a launch given directly.

use crate::common;

use common::Row;
use homerun::Purpose;
use homerun::model::aero::{DragModel, LiftModel};
use homerun::model::impact::Impact;
use homerun::model::keys::{InputBatch, InputError};
use homerun::model::{self, scene::Scene};

/// 103 mph, 28°, 2500 rpm: a typical home-run launch.
const FLY_BALL: (f64, f64, f64) = (
    46.04,
    28.0 * std::f64::consts::PI / 180.0,
    261.799_387_799_149_4,
);

fn scene_with(settings: &[(&str, &str)]) -> Scene {
    let mut scene = Scene::default();
    let mut batch = InputBatch::new();
    for (key, value) in settings {
        batch.set_text(&mut scene, key, value).unwrap();
    }
    scene.validate().unwrap();
    scene
}

fn fly_ball(scene: &Scene) -> model::flight::FlightSummary {
    let (speed, angle, spin) = FLY_BALL;
    model::fly_launch(scene, speed, angle, spin, Purpose::Reference)
}

#[test]
fn nathan_models_spin_decay_and_weather_match_the_independent_reference() {
    // reference/aero.py: plain formulas, scipy's DOP853 at 1e-12.
    let csv = include_str!("../data/aero_reference.csv");
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let names: Vec<&str> = lines.next().unwrap().split(',').collect();
    let mut worst = (0.0f64, String::new());
    let mut launches = 0;
    for line in lines {
        let row = Row {
            names: &names,
            fields: line.split(',').collect(),
        };
        let mut settings = vec![
            ("model.drag", row.text("drag")),
            ("model.lift", row.text("lift")),
            ("model.spin_decay", row.text("spin_decay")),
            ("environment.wind", row.text("wind")),
        ];
        let weather = !row.text("temperature").is_empty();
        if weather {
            for key in ["temperature", "elevation", "pressure", "humidity"] {
                settings.push((
                    match key {
                        "temperature" => "environment.temperature",
                        "elevation" => "environment.elevation",
                        "pressure" => "environment.pressure",
                        _ => "environment.humidity",
                    },
                    row.text(key),
                ));
            }
        }
        let scene = scene_with(&settings);
        let air = scene.environment.air();
        assert_eq!(air.atmosphere.is_some(), weather);
        for (ours, theirs) in [
            (air.density, row.number("air_density")),
            (air.kinematic_viscosity, row.number("kinematic_viscosity")),
        ] {
            assert!(
                (ours / theirs - 1.0).abs() < 1e-14,
                "{line}: {ours} vs {theirs}"
            );
        }
        let flight = model::fly_launch(
            &scene,
            row.number("speed"),
            row.number("angle"),
            row.number("spin"),
            Purpose::Reference,
        );
        assert!(flight.landed, "{line}");
        for (what, ours) in [
            ("range", flight.range),
            ("flight_time", flight.flight_time),
            ("apex", flight.apex),
        ] {
            let theirs = row.number(what);
            let relative = (ours / theirs - 1.0).abs();
            if relative > worst.0 {
                worst = (relative, format!("{what} {ours} vs {theirs} in {line}"));
            }
        }
        launches += 1;
    }
    assert!(launches >= 20, "{launches} launches");
    eprintln!(
        "worst relative difference from reference/aero.py: {:.1e} ({})",
        worst.0, worst.1
    );
    assert!(worst.0 < 1e-10, "{}: {}", worst.0, worst.1);
}

#[test]
fn standard_dry_air_is_the_standard_atmosphere() {
    let scene = scene_with(&[("environment.humidity", "0")]);
    let air = scene.environment.air();
    // ISA: 1.2250 kg/m³; the formula's 1.2929·273.15/288.15 = 1.22560, 0.05 % above.
    assert!((air.density / 1.2250 - 1.0).abs() < 6e-4, "{air}");
    let atmosphere = air.atmosphere.unwrap();
    assert_eq!(atmosphere.temperature, 15.0);
    assert_eq!(atmosphere.pressure, 1013.25);
    assert_eq!(atmosphere.elevation, 0.0);
}

#[test]
fn a_derived_scene_flies_as_the_explicit_scene_with_the_same_air() {
    for (drag, lift) in [("sawicki2003", "sawicki2003"), ("nathan", "nathan")] {
        let derived = scene_with(&[
            ("model.drag", drag),
            ("model.lift", lift),
            ("environment.temperature", "30"),
            ("environment.elevation", "1580"),
        ]);
        let air = derived.environment.air();
        let mut explicit = Scene {
            drag: derived.drag,
            lift: derived.lift,
            ..Scene::default()
        };
        explicit
            .set("environment.air_density", air.density)
            .unwrap();
        explicit
            .set("environment.kinematic_viscosity", air.kinematic_viscosity)
            .unwrap();
        assert!(explicit.environment.atmosphere().is_none());
        assert_ne!(derived, explicit, "they differ in where the air comes from");
        let (a, b) = (
            model::simulate(&derived, Purpose::Readout),
            model::simulate(&explicit, Purpose::Readout),
        );
        assert_eq!(a, b, "{drag} × {lift}");
        assert_eq!(fly_ball(&derived), fly_ball(&explicit));
    }
}

#[test]
fn without_air_the_flight_is_the_vacuum_parabola() {
    let scene = scene_with(&[
        ("model.drag", "constant"),
        ("model.lift", "none"),
        ("environment.air_density", "0"),
    ]);
    let (speed, angle, _) = FLY_BALL;
    let flight = fly_ball(&scene);
    let (g, h) = (scene.environment.gravity, scene.environment.contact_height);
    let (vx, vy) = (speed * angle.cos(), speed * angle.sin());
    let time = (vy + (vy * vy + 2.0 * g * h).sqrt()) / g;
    for (what, ours, exact) in [
        ("time", flight.flight_time, time),
        ("range", flight.range, vx * time),
        ("apex", flight.apex, h + vy * vy / (2.0 * g)),
        ("apex distance", flight.apex_distance, vx * vy / g),
        (
            "landing speed",
            flight.landing_speed,
            (speed * speed + 2.0 * g * h).sqrt(),
        ),
    ] {
        assert!(
            (ours / exact - 1.0).abs() < 1e-12,
            "{what}: {ours} vs {exact}"
        );
    }
}

#[test]
fn every_drag_and_lift_pair_flies() {
    for drag in DragModel::ALL {
        for lift in LiftModel::ALL {
            for decay in ["0", "20"] {
                let scene = scene_with(&[
                    ("model.drag", drag.name()),
                    ("model.lift", lift.name()),
                    ("model.spin_decay", decay),
                ]);
                for flight in [
                    model::simulate(&scene, Purpose::Readout).flight,
                    fly_ball(&scene),
                ] {
                    assert!(flight.landed, "{drag} × {lift}, τ {decay}");
                    assert!(
                        flight.range.is_finite() && flight.range > 50.0 && flight.range < 200.0,
                        "{drag} × {lift}, τ {decay}: {flight:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_slow_decay_is_no_decay() {
    let mut scene = scene_with(&[("model.drag", "nathan"), ("model.lift", "nathan")]);
    let constant = fly_ball(&scene);
    let mut previous = f64::INFINITY;
    for tau in [1e3, 1e6, 1e9, 1e12] {
        scene.spin_decay = tau;
        let decaying = fly_ball(&scene);
        let difference = (decaying.range / constant.range - 1.0).abs();
        assert!(difference < previous, "τ = {tau}: {difference}");
        previous = difference;
    }
    assert!(previous < 1e-9, "{previous}");
    // A fast decay shortens a backspun fly ball (less lift); it stays finite.
    scene.spin_decay = 1e-3;
    let spun_down = fly_ball(&scene);
    assert!(spun_down.landed && spun_down.range < constant.range);
}

#[test]
fn a_launch_flown_directly_is_the_swing_s_flight() {
    for name in ["fastball", "knuckleball", "curveball"] {
        let scene = common::scene(name);
        let impact = Impact::new(&scene);
        let direct = model::fly_launch(
            &scene,
            impact.launch_speed(),
            impact.launch_angle(),
            impact.launch_spin(),
            Purpose::Readout,
        );
        let swing = model::simulate(&scene, Purpose::Readout).flight;
        for (what, a, b) in [
            ("range", direct.range, swing.range),
            ("time", direct.flight_time, swing.flight_time),
            ("apex", direct.apex, swing.apex),
        ] {
            assert!((a - b).abs() < 1e-9 * b.abs(), "{name} {what}: {a} vs {b}");
        }
    }
}

#[test]
fn the_lift_model_is_a_key_and_unknown_names_list_the_accepted_ones() {
    let mut scene = Scene::default();
    scene.set_text("model.lift", "nathan").unwrap();
    assert_eq!(scene.lift, LiftModel::Nathan);
    let message = scene
        .set_text("model.lift", "magnus")
        .unwrap_err()
        .to_string();
    assert_eq!(
        message,
        "model.lift = \"magnus\": unknown lift model; accepted: sawicki2003, nathan, none"
    );
    let message = scene
        .set_text("model.drag", "smooth")
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("sawicki2003, constant, nathan"),
        "{message}"
    );
    // The paper's presets load with the paper's lift and constant spin.
    let fastball = common::scene("fastball");
    assert_eq!(
        (fastball.lift, fastball.spin_decay),
        (LiftModel::Sawicki2003, 0.0)
    );
    assert!(fastball.environment.atmosphere().is_none());
}

#[test]
fn a_scene_saved_without_the_new_fields_still_loads() {
    let text = toml::to_string(&Scene::default()).unwrap();
    // The scene's own `lift` and `spin_decay`, above its first table (the
    // [chosen] table has a `lift` of its own).
    let top = text.find("\n[").unwrap();
    let old: String = text[..top]
        .lines()
        .filter(|l| !l.starts_with("lift") && !l.starts_with("spin_decay"))
        .map(|l| format!("{l}\n"))
        .collect::<String>()
        + &text[top..];
    assert_ne!(old, text);
    assert_eq!(toml::from_str::<Scene>(&old).unwrap(), Scene::default());
}

#[test]
fn one_source_may_not_give_the_air_and_the_weather() {
    for (first, second) in [
        ("environment.air_density", "environment.temperature"),
        ("environment.humidity", "environment.kinematic_viscosity"),
    ] {
        let mut scene = Scene::default();
        let mut batch = InputBatch::new();
        batch.set_text(&mut scene, first, "1.0").unwrap();
        let before = scene;
        let error = batch.set_text(&mut scene, second, "20").unwrap_err();
        assert!(matches!(error, InputError::AirGivenTwice { .. }));
        let message = error.to_string();
        assert!(
            message.contains(first) && message.contains(second),
            "{message}"
        );
        assert_eq!(scene, before, "a refused key changes nothing");
    }
    // Weather keys together, and ρ with ν, are fine.
    scene_with(&[
        ("environment.temperature", "30"),
        ("environment.pressure", "1000"),
    ]);
    scene_with(&[
        ("environment.air_density", "1.1"),
        ("environment.kinematic_viscosity", "1.6e-5"),
    ]);
}

#[test]
fn a_later_source_overrides_an_earlier_one() {
    // A paper preset gives ρ and ν; --set gives the weather: it derives them.
    let mut scene = common::scene("fastball");
    InputBatch::new()
        .set_text(&mut scene, "environment.temperature", "30")
        .unwrap();
    let derived = scene.environment.air();
    assert_eq!(derived.atmosphere.unwrap().temperature, 30.0);
    assert_eq!(derived.atmosphere.unwrap().humidity, 50.0);
    assert!(derived.density < 1.2);
    // Then a ρ: it replaces the derived one, and ν stays what it was.
    InputBatch::new()
        .set(&mut scene, "environment.air_density", 1.1)
        .unwrap();
    let given = scene.environment.air();
    assert_eq!(given.atmosphere, None);
    assert_eq!(given.density, 1.1);
    assert_eq!(given.kinematic_viscosity, derived.kinematic_viscosity);
    assert_eq!(given.to_string(), "1.1 kg/m³ as given");
}

#[test]
fn new_keys_are_bounded_and_named_in_errors() {
    for (key, bad) in [
        ("environment.humidity", 101.0),
        ("environment.temperature", -51.0),
        ("environment.temperature", f64::NAN),
        ("environment.elevation", 6000.0),
        ("environment.pressure", 500.0),
        ("model.spin_decay", -1.0),
    ] {
        let mut scene = Scene::default();
        scene.set(key, bad).unwrap();
        let message = scene.validate().unwrap_err().to_string();
        assert!(message.starts_with(key), "{key} = {bad}: {message}");
    }
    // The extremes of the weather keep ρ and ν inside their own bounds.
    for (t, h, p, rh) in [(-50.0, -500.0, 1085.0, 0.0), (60.0, 5000.0, 870.0, 100.0)] {
        let mut scene = Scene::default();
        for (key, value) in [
            ("environment.temperature", t),
            ("environment.elevation", h),
            ("environment.pressure", p),
            ("environment.humidity", rh),
        ] {
            scene.set(key, value).unwrap();
        }
        scene.validate().unwrap();
        assert!(model::simulate(&scene, Purpose::Readout).flight.landed);
    }
}

#[test]
fn the_fly_ball_at_sea_level_and_at_altitude() {
    // Printed with --nocapture for the record. Under Nathan's models thin air
    // only carries further; under the paper's drag crisis it also moves the
    // crisis (ν rises with the heat and the height, so Re falls), and the two
    // nearly cancel for this launch.
    for (drag, lift) in [("sawicki2003", "sawicki2003"), ("nathan", "nathan")] {
        let sea = scene_with(&[("model.drag", drag), ("model.lift", lift)]);
        let standard = scene_with(&[
            ("model.drag", drag),
            ("model.lift", lift),
            ("environment.temperature", "15"),
        ]);
        let denver = scene_with(&[
            ("model.drag", drag),
            ("model.lift", lift),
            ("environment.temperature", "30"),
            ("environment.elevation", "1580"),
        ]);
        let [a, b, c] = [&sea, &standard, &denver].map(|s| fly_ball(s).range);
        eprintln!(
            "{drag} × {lift}: paper air {a:.2} m, {} → {b:.2} m, {} → {c:.2} m",
            standard.environment.air(),
            denver.environment.air()
        );
        if drag == "nathan" {
            assert!(c > a.max(b) + 5.0, "thin air carries further");
        }
    }
}

#[test]
fn the_air_thins_with_heat_height_and_humidity() {
    use homerun::model::atmosphere::Atmosphere;
    // Across each key's accepted range, the others at standard values and
    // at both ends of theirs: ρ falls as T, h or RH rises (warm air expands,
    // the pressure falls with height, water vapour is lighter than dry air).
    let corners = [
        Atmosphere::STANDARD,
        Atmosphere {
            temperature: -50.0,
            elevation: -500.0,
            pressure: 1085.0,
            humidity: 0.0,
        },
        Atmosphere {
            temperature: 60.0,
            elevation: 5000.0,
            pressure: 870.0,
            humidity: 100.0,
        },
    ];
    type Setter = fn(&mut Atmosphere, f64);
    let keys: [(&str, f64, f64, Setter); 3] = [
        ("temperature", -50.0, 60.0, |a, v| a.temperature = v),
        ("elevation", -500.0, 5000.0, |a, v| a.elevation = v),
        ("humidity", 0.0, 100.0, |a, v| a.humidity = v),
    ];
    for base in corners {
        for (name, from, to, set) in keys {
            let densities: Vec<f64> = (0..=100)
                .map(|i| {
                    let mut air = base;
                    set(&mut air, from + (to - from) * f64::from(i) / 100.0);
                    air.air_density()
                })
                .collect();
            assert!(
                densities.windows(2).all(|w| w[1] < w[0]),
                "ρ not falling in {name} from {base:?}: {densities:?}"
            );
        }
    }
}
