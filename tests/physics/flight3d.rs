//! The batted ball in three dimensions, checked from outside the flight:
//! against an independent reference (reference/flight3d.py), by the mirror
//! symmetry of the frame, by the limits whose sign the conventions fix, by
//! the planar flight it must reduce to, and by the vacuum parabola.

use crate::common;

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use common::Row;
use homerun::Purpose;
use homerun::model::flight::{self, Flight, Flight3d, FlightSummary, Launch, Launch3d, Regime};
use homerun::model::keys::InputBatch;
use homerun::model::launch::{self, SceneFlight};
use homerun::model::{self, frame, scene::Scene};
use nalgebra::{Vector2, Vector3};

/// A scene made by the keys, as `--set` makes it.
fn scene_with(settings: &[(&str, String)]) -> Scene {
    let mut scene = Scene::default();
    let mut batch = InputBatch::new();
    for (key, value) in settings {
        batch
            .set_text(&mut scene, key, value)
            .unwrap_or_else(|e| panic!("{key} = {value}: {e}"));
    }
    scene.validate().unwrap();
    scene
}

/// The inputs of one batted ball, by key (angles in rad, spins in rad/s).
#[derive(Clone, Copy, Debug)]
struct Ball {
    drag: &'static str,
    lift: &'static str,
    speed: f64,
    angle: f64,
    direction: f64,
    spin: f64,
    sidespin: f64,
    wind: f64,
    wind_direction: f64,
    wind_height: f64,
    spin_decay: f64,
}

/// 103 mph, 28°, 2500 rpm toward centre field, calm: the fly-ball preset's
/// launch, under Nathan's models.
const FLY_BALL: Ball = Ball {
    drag: "nathan",
    lift: "nathan",
    speed: 46.04,
    angle: 28.0 * PI / 180.0,
    direction: 0.0,
    spin: 2500.0 * 2.0 * PI / 60.0,
    sidespin: 0.0,
    wind: 0.0,
    wind_direction: 0.0,
    wind_height: 0.0,
    spin_decay: 0.0,
};

impl Ball {
    fn settings(&self) -> Settings {
        vec![
            ("model.drag", self.drag.to_owned()),
            ("model.lift", self.lift.to_owned()),
            ("model.spin_decay", self.spin_decay.to_string()),
            ("environment.wind", self.wind.to_string()),
            (
                "environment.wind_direction",
                self.wind_direction.to_string(),
            ),
            ("environment.wind_height", self.wind_height.to_string()),
            ("launch.speed", self.speed.to_string()),
            ("launch.angle", self.angle.to_string()),
            ("launch.direction", self.direction.to_string()),
            ("launch.spin", self.spin.to_string()),
            ("launch.sidespin", self.sidespin.to_string()),
        ]
    }

    fn scene(&self) -> Scene {
        scene_with(&self.settings())
    }

    fn fly(&self) -> FlightSummary {
        let flight = launch::fly_scene(&self.scene(), Purpose::Reference).flight;
        assert!(flight.landed, "{self:?}");
        flight
    }
}

/// Settings by key, as `--set` gives them.
type Settings = Vec<(&'static str, String)>;
/// A reference row's numbers, by column name.
type Numbers = Vec<(&'static str, f64)>;

/// The reference's launches: their settings and numbers.
fn reference_rows() -> Vec<(Settings, Numbers)> {
    let csv = include_str!("../data/aero3d_reference.csv");
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let names: Vec<&str> = lines.next().unwrap().split(',').collect();
    let mut rows = Vec::new();
    for line in lines {
        let row = Row {
            names: &names,
            fields: line.split(',').collect(),
        };
        let mut settings: Settings = [
            ("model.drag", "drag"),
            ("model.lift", "lift"),
            ("model.spin_decay", "spin_decay"),
            ("environment.wind", "wind"),
            ("environment.wind_direction", "wind_direction"),
            ("environment.wind_height", "wind_height"),
            ("launch.speed", "speed"),
            ("launch.angle", "angle"),
            ("launch.direction", "direction"),
            ("launch.spin", "spin"),
            ("launch.sidespin", "sidespin"),
        ]
        .into_iter()
        .map(|(key, column)| (key, row.text(column).to_owned()))
        .collect();
        if !row.text("temperature").is_empty() {
            for column in ["temperature", "elevation", "pressure", "humidity"] {
                let key = match column {
                    "temperature" => "environment.temperature",
                    "elevation" => "environment.elevation",
                    "pressure" => "environment.pressure",
                    _ => "environment.humidity",
                };
                settings.push((key, row.text(column).to_owned()));
            }
        }
        let numbers = [
            "air_density",
            "kinematic_viscosity",
            "range",
            "landing_direction",
            "flight_time",
            "apex",
            "apex_distance",
            "landing_speed",
            "landing_angle",
            "layer_crossings",
            "drag_kink_crossings",
            "lift_kink_crossings",
        ]
        .map(|name| (name, row.number(name)))
        .to_vec();
        rows.push((settings, numbers));
    }
    rows
}

fn value(numbers: &[(&str, f64)], name: &str) -> f64 {
    numbers.iter().find(|(n, _)| *n == name).expect(name).1
}

#[test]
fn the_3d_flight_matches_the_independent_reference() {
    // reference/flight3d.py: plain formulas, scipy's DOP853 at 1e-12, every
    // wind layer and drag or lift kink an event; it agrees with itself under
    // Radau to 8e-13 (1.4e-11 relative in a direction of 0.0009 rad).
    let rows = reference_rows();
    assert!(rows.len() >= 40, "{} launches", rows.len());
    let (mut spatial, mut up_and_down, mut down_only, mut lift_kinks) = (0, 0, 0, 0);
    // The worst difference in each output (relative, angles in rad), and
    // where: apart for the flights whose C_L(S) turns its corner at S = 0.1
    // (the paper's lift at low spin), which the Rust flight steps across
    // (it ends its steps on the drag curve's kinks only).
    let mut worst: Vec<(bool, &str, f64, String)> = Vec::new();
    for (settings, numbers) in &rows {
        let scene = scene_with(settings);
        let air = scene.environment.air();
        for (ours, theirs) in [
            (air.density, value(numbers, "air_density")),
            (
                air.kinematic_viscosity,
                value(numbers, "kinematic_viscosity"),
            ),
        ] {
            assert!((ours / theirs - 1.0).abs() < 1e-14, "{ours} vs {theirs}");
        }
        let (scene_flight, _, _) = launch::scene_start(&scene);
        spatial += usize::from(!scene_flight.is_planar());
        match value(numbers, "layer_crossings") as i32 {
            2 => up_and_down += 1,
            1 => down_only += 1,
            _ => {}
        }
        let lift_kink = value(numbers, "lift_kink_crossings") > 0.0;
        lift_kinks += usize::from(lift_kink);
        let flight = launch::fly_scene(&scene, Purpose::Reference).flight;
        assert!(flight.landed, "{settings:?}");
        let (range, time) = (value(numbers, "range"), value(numbers, "flight_time"));
        let (apex, speed) = (value(numbers, "apex"), value(numbers, "landing_speed"));
        let direction = value(numbers, "landing_direction");
        let apex_distance = value(numbers, "apex_distance");
        let angle = value(numbers, "landing_angle");
        for (what, difference) in [
            ("range", flight.range / range - 1.0),
            ("direction", flight.direction - direction),
            ("flight_time", flight.flight_time / time - 1.0),
            ("apex", flight.apex / apex - 1.0),
            (
                "apex_distance",
                (flight.apex_distance - apex_distance) / range,
            ),
            ("landing_speed", flight.landing_speed / speed - 1.0),
            ("landing_angle", flight.landing_angle - angle),
        ] {
            let line = format!("{settings:?}");
            let entry = worst.iter_mut().find(|w| (w.0, w.1) == (lift_kink, what));
            match entry {
                Some(w) if difference.abs() > w.2 => (w.2, w.3) = (difference.abs(), line),
                Some(_) => {}
                None => worst.push((lift_kink, what, difference.abs(), line)),
            }
        }
    }
    // The fixture covers what it claims to.
    assert!(spatial >= 40 && up_and_down >= 10 && down_only >= 2 && lift_kinks >= 2);
    for (lift_kink, what, difference, line) in &worst {
        let class = if *lift_kink {
            "across S = 0.1"
        } else {
            "smooth lift"
        };
        eprintln!("{class}: worst {what} {difference:.1e} ({line})");
    }
    for (lift_kink, what, difference, line) in &worst {
        // Measured: 7.8e-13 at worst (apex), about the reference's own spread
        // between DOP853 and Radau; across the lift's corner 2.3e-11 (apex),
        // where the Rust flight at a tolerance of 1e-14 instead of 1e-13
        // comes within 1e-13 of the reference (so the difference is the
        // Rust step across the corner, under a nanometre in range).
        let bound = if *lift_kink { 5e-11 } else { 2e-12 };
        assert!(*difference < bound, "{what}: {difference:e}: {line}");
    }
}

#[test]
fn negating_direction_sidespin_and_wind_direction_mirrors_the_landing_exactly() {
    // The frame is mirror-symmetric in z: every sign flip is exact in
    // floating point, so the mirrored flight is the same flight bit for bit.
    let rows = reference_rows();
    for (settings, _) in &rows {
        let mirrored: Settings = settings
            .iter()
            .map(|(key, text)| {
                let text = match *key {
                    "launch.direction" | "launch.sidespin" | "environment.wind_direction" => {
                        (-text.parse::<f64>().unwrap()).to_string()
                    }
                    _ => text.clone(),
                };
                (*key, text)
            })
            .collect();
        let a = launch::fly_scene(&scene_with(settings), Purpose::Reference).flight;
        let b = launch::fly_scene(&scene_with(&mirrored), Purpose::Reference).flight;
        assert_eq!(a.range, b.range, "{settings:?}");
        assert_eq!(a.direction, -b.direction, "{settings:?}");
        assert_eq!(
            (
                a.flight_time,
                a.apex,
                a.apex_distance,
                a.landing_speed,
                a.landing_angle
            ),
            (
                b.flight_time,
                b.apex,
                b.apex_distance,
                b.landing_speed,
                b.landing_angle
            ),
            "{settings:?}"
        );
    }
}

#[test]
fn sidespin_curves_the_ball_the_way_the_convention_says() {
    for (drag, lift) in [("nathan", "nathan"), ("sawicki2003", "sawicki2003")] {
        for direction in [-0.6, 0.0, 0.4] {
            for backspin in [0.0, FLY_BALL.spin] {
                let ball = |sidespin| Ball {
                    drag,
                    lift,
                    direction,
                    spin: backspin,
                    sidespin,
                    ..FLY_BALL
                };
                let straight = ball(0.0).fly();
                assert_eq!(straight.direction, direction);
                let right = ball(150.0).fly();
                let left = ball(-150.0).fly();
                // Positive sidespin curves toward right field (+z), from the
                // launch direction; by more than a degree at this spin.
                assert!(right.direction > direction + 0.02, "{drag}: {right:?}");
                assert!(left.direction < direction - 0.02, "{drag}: {left:?}");
            }
        }
    }
}

#[test]
fn a_crosswind_pushes_the_ball_downwind_and_a_tailwind_carries_it() {
    for direction in [-0.5, 0.0, 0.3] {
        let calm = Ball {
            direction,
            ..FLY_BALL
        }
        .fly();
        let windy = |wind: f64, toward: f64| {
            Ball {
                direction,
                wind,
                wind_direction: toward,
                ..FLY_BALL
            }
            .fly()
        };
        // Across the launch, toward its right (+z side) and its left.
        let right = windy(5.0, direction + FRAC_PI_2);
        let left = windy(5.0, direction - FRAC_PI_2);
        assert!(right.direction > direction + 0.02, "{right:?}");
        assert!(left.direction < direction - 0.02, "{left:?}");
        // The same wind signed the other way is the other crosswind.
        let negated = windy(-5.0, direction + FRAC_PI_2).direction;
        assert!((negated - left.direction).abs() < 1e-12);
        // Along the launch: a tailwind carries it further, a headwind less.
        let tail = windy(5.0, direction);
        let head = windy(
            5.0,
            direction + PI - if direction > 0.0 { 2.0 * PI } else { 0.0 },
        );
        assert!(tail.range > calm.range + 5.0, "{tail:?} {calm:?}");
        assert!(head.range < calm.range - 5.0, "{head:?} {calm:?}");
        // A wind quartering from behind on the right both carries and pushes.
        let quartering = windy(5.0, direction + FRAC_PI_4);
        assert!(quartering.range > calm.range && quartering.direction > direction);
    }
}

#[test]
fn a_wind_above_the_apex_is_no_wind() {
    // The ball never enters the layer: the forces are the calm flight's at
    // every instant, so the numbers are the calm flight's. Not necessarily
    // bit for bit: the flight watches for the layer (it may end a step near
    // a predicted crossing), and without sidespin the calm flight is the
    // planar one. Measured: identical with sidespin (both 3-D), 5e-15
    // relative in range without (3-D against planar).
    for sidespin in [0.0, 80.0] {
        let calm = Ball {
            sidespin,
            ..FLY_BALL
        };
        let aloft = Ball {
            wind: 20.0,
            wind_direction: 1.0,
            wind_height: 40.0,
            ..calm
        };
        let (a, b) = (calm.fly(), aloft.fly());
        eprintln!(
            "wind above the apex, sidespin {sidespin}: range {} vs calm {} ({:.1e})",
            b.range,
            a.range,
            b.range / a.range - 1.0
        );
        assert!(a.apex < 35.0, "the layer is above the apex: {a:?}");
        for (what, x, y) in [
            ("range", a.range, b.range),
            ("time", a.flight_time, b.flight_time),
            ("apex", a.apex, b.apex),
        ] {
            assert!((x / y - 1.0).abs() < 1e-12, "{what}: {x} vs {y}");
        }
        assert!((a.direction - b.direction).abs() < 1e-12);
        // …and a layer just under the apex is felt.
        let felt = Ball {
            wind_height: a.apex - 1.0,
            ..aloft
        }
        .fly();
        assert!((felt.range - a.range).abs() > 0.1, "{felt:?}");
    }
}

/// The planar flight's pieces for `scene`'s batted ball, built as the
/// paper's flight is (not through the scene's choice of flight).
fn planar_pieces(scene: &Scene) -> (Flight, Launch) {
    let ball = scene.batted_ball();
    let env = scene.environment;
    let mut planar = Flight::new(scene, ball.spin);
    planar.wind = frame::wind_along(env.wind, env.wind_direction, ball.direction).unwrap();
    let (sin, cos) = ball.angle.sin_cos();
    let launch = Launch {
        position: Vector2::new(0.0, scene.environment.contact_height),
        velocity: Vector2::new(cos, sin) * ball.speed,
    };
    (planar, launch)
}

/// Planar launches: every model pair, turned planes, winds along the plane,
/// spin decay, topspin.
fn planar_balls() -> Vec<Ball> {
    let mut balls = Vec::new();
    for drag in ["nathan", "sawicki2003", "constant"] {
        for lift in ["nathan", "sawicki2003", "none"] {
            balls.push(Ball {
                drag,
                lift,
                ..FLY_BALL
            });
        }
    }
    for (direction, wind, wind_direction, decay) in [
        (0.3, 0.0, 0.0, 0.0),
        (-0.7, 6.0, -0.7, 0.0),
        (0.5, -4.0, 0.5, 20.0),
        (0.0, -7.0, 0.0, 0.0),
        (-0.2, 5.0, -0.2, 3.0),
    ] {
        for (drag, lift) in [("nathan", "nathan"), ("sawicki2003", "sawicki2003")] {
            balls.push(Ball {
                drag,
                lift,
                direction,
                wind,
                wind_direction,
                spin_decay: decay,
                ..FLY_BALL
            });
        }
    }
    balls.push(Ball {
        speed: 40.0,
        angle: 0.15,
        spin: -120.0,
        ..FLY_BALL
    });
    balls
}

#[test]
fn the_3d_flight_of_a_planar_scene_is_the_planar_flight() {
    let options = Purpose::Reference.flight_options();
    let mut worst = 0.0f64;
    for ball in planar_balls() {
        let scene = ball.scene();
        let (planar, start) = planar_pieces(&scene);
        let a = flight::fly(&planar, &start, &options);
        // The same launch flown in 3-D, built directly.
        let spatial = Flight3d::new(
            &scene,
            frame::spin_vector(ball.spin, 0.0, ball.angle, ball.direction),
        );
        let start3d = Launch3d {
            position: Vector3::new(0.0, scene.environment.contact_height, 0.0),
            velocity: frame::launch_velocity(ball.speed, ball.angle, ball.direction),
        };
        let b = flight::fly(&spatial, &start3d, &options);
        // …and through the keys, a sidespin of 1e-300 rad/s forcing 3-D.
        let forced = Ball {
            sidespin: 1e-300,
            ..ball
        };
        let (forced_flight, _, _) = launch::scene_start(&forced.scene());
        assert!(!forced_flight.is_planar());
        let c = forced_flight.fly(&options);
        for other in [b, c] {
            for (ours, theirs) in [
                (a.range, other.range),
                (a.flight_time, other.flight_time),
                (a.apex, other.apex),
                (a.apex_distance, other.apex_distance),
                (a.landing_speed, other.landing_speed),
            ] {
                worst = worst.max((ours / theirs - 1.0).abs());
            }
            worst = worst.max((a.landing_angle - other.landing_angle).abs());
            assert!(
                (other.direction - ball.direction).abs() < 1e-13,
                "{ball:?}: {}",
                other.direction
            );
        }
    }
    eprintln!("planar vs 3-D, worst relative difference: {worst:.1e}");
    // Measured: 4.3e-12, a landing angle (rad; ranges 1.2e-12), with the
    // controller's rough powers (6.3e-13 with libm's): the two flights'
    // error norms differ (over 4 components or 6), so they take different
    // steps, and a landing is read off the 4th-order extension. At 1e-13
    // that is rounding noise, far below either flight's own error.
    assert!(worst < 1e-11, "{worst:e}");
}

#[test]
fn a_planar_scene_flies_the_planar_flight_bit_for_bit() {
    // A batted ball with nothing out of its plane: fly_scene takes the
    // planar flight, and gives exactly the paper's flight's numbers (the
    // step statistics included, so the very same steps).
    for purpose in [Purpose::Readout, Purpose::Reference] {
        for ball in planar_balls() {
            let scene = ball.scene();
            let (planar, start) = planar_pieces(&scene);
            let direct = flight::fly(&planar, &start, &purpose.flight_options());
            let flown = launch::fly_scene(&scene, purpose).flight;
            assert_eq!(
                flown,
                FlightSummary {
                    direction: ball.direction,
                    ..direct
                },
                "{ball:?}"
            );
            // The old entry for a launch toward centre field, too.
            if ball.direction == 0.0 {
                assert_eq!(
                    model::fly_launch(&scene, ball.speed, ball.angle, ball.spin, purpose),
                    flown
                );
            }
        }
    }
    // The paper's swings: the impact's launch, flown as model::launch builds
    // it (the planar flight of the paper, toward centre field).
    for name in ["fastball", "knuckleball", "curveball", "fly-ball"] {
        let scene = common::scene(name);
        for purpose in [Purpose::Readout, Purpose::Reference] {
            let flown = launch::fly_scene(&scene, purpose);
            if let Some(impact) = flown.impact {
                let impact = impact.planar().expect("the paper's swings are planar");
                let (planar, start) = model::launch(&scene, impact);
                let direct = flight::fly(&planar, &start, &purpose.flight_options());
                assert_eq!(flown.flight, direct, "{name}");
                assert_eq!(model::simulate(&scene, purpose).flight, direct, "{name}");
            } else {
                // The fly-ball preset is a batted ball toward centre field.
                let (planar, start) = planar_pieces(&scene);
                let direct = flight::fly(&planar, &start, &purpose.flight_options());
                assert_eq!(flown.flight, direct, "{name}");
            }
        }
    }
}

#[test]
fn without_air_the_3d_flight_is_the_vacuum_parabola_in_any_direction() {
    for direction in [-1.2, -0.5, 0.0, 0.3, 1.0] {
        let ball = Ball {
            direction,
            sidespin: 120.0,
            wind: 8.0,
            wind_direction: 2.0,
            ..FLY_BALL
        };
        let mut settings = ball.settings();
        settings.push(("environment.air_density", "0".to_owned()));
        let scene = scene_with(&settings);
        let (scene_flight, _, _) = launch::scene_start(&scene);
        let SceneFlight::Spatial {
            flight: spatial,
            launch: start,
        } = scene_flight
        else {
            panic!("a sidespun ball in a crosswind flies in 3-D");
        };
        let (g, h) = (scene.environment.gravity, scene.environment.contact_height);
        let energy = |s: &nalgebra::SVector<f64, 6>| {
            0.5 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]) + g * s[1]
        };
        let initial = 0.5 * ball.speed * ball.speed + g * h;
        let mut drift = 0.0f64;
        let summary = flight::fly_observed(
            &spatial,
            &start,
            &Purpose::Reference.flight_options(),
            |step| drift = drift.max((energy(&step.y1) / initial - 1.0).abs()),
        );
        eprintln!("vacuum, direction {direction}: energy drift {drift:.1e}");
        // Measured: 4e-16 (a Runge–Kutta step integrates a parabola exactly).
        assert!(drift < 1e-12, "energy drifts by {drift:e}");
        let (vh, vy) = (ball.speed * ball.angle.cos(), ball.speed * ball.angle.sin());
        let time = (vy + (vy * vy + 2.0 * g * h).sqrt()) / g;
        for (what, ours, exact) in [
            ("time", summary.flight_time, time),
            ("range", summary.range, vh * time),
            ("apex", summary.apex, h + vy * vy / (2.0 * g)),
            ("apex distance", summary.apex_distance, vh * vy / g),
            (
                "landing speed",
                summary.landing_speed,
                (ball.speed * ball.speed + 2.0 * g * h).sqrt(),
            ),
        ] {
            assert!(
                (ours / exact - 1.0).abs() < 1e-12,
                "{direction}: {what}: {ours} vs {exact}"
            );
        }
        assert!((summary.direction - direction).abs() < 1e-13);
    }
}

#[test]
fn lift_does_no_work_on_the_ball_relative_to_the_air() {
    // The power of the aerodynamic force against the velocity relative to
    // the air is the drag's alone: −k·C_D·|V_r|³, whatever the spin vector
    // (lift ⟂ V_r), in calm air and in a wind.
    for (drag, lift) in [("nathan", "nathan"), ("sawicki2003", "sawicki2003")] {
        for (wind, toward) in [(0.0, 0.0), (6.0, 1.1), (-4.0, -2.5)] {
            let ball = Ball {
                drag,
                lift,
                wind,
                wind_direction: toward,
                sidespin: 90.0,
                direction: 0.2,
                ..FLY_BALL
            };
            let scene = ball.scene();
            let spin = frame::spin_vector(ball.spin, ball.sidespin, ball.angle, ball.direction);
            let spatial = Flight3d::new(&scene, spin);
            let regime = Regime {
                piece: None,
                in_wind: true,
            };
            for velocity in [
                Vector3::new(40.0, 20.0, 5.0),
                Vector3::new(30.0, -10.0, -8.0),
                Vector3::new(12.0, 2.0, 20.0),
            ] {
                let relative = spatial.wind - velocity;
                let aero = spatial.acceleration_at(0.7, velocity, regime)
                    + Vector3::new(0.0, scene.environment.gravity, 0.0);
                let c_d = spatial.drag_coefficient_at(0.7, velocity, true);
                let drag_power = spatial.force_per_mass * c_d * relative.norm().powi(3);
                let power = aero.dot(&relative);
                assert!(
                    (power / drag_power - 1.0).abs() < 1e-13,
                    "{drag} × {lift}: {power} vs {drag_power}"
                );
                // And the lift is there: the force is not along V_r.
                assert!(aero.cross(&relative).norm() > 1e-3 * aero.norm() * relative.norm());
            }
        }
    }
}
