//! What the worker computes for each scene: the figure, the sensitivity
//! column, the keys offered, batted balls, balls that do not land.

use crate::input_index;
use crate::tui_support::*;
use homerun::analysis::precision::Purpose;
use homerun::model::aero::{DragModel, LiftModel};
use homerun::model::atmosphere::Atmosphere;
use homerun::tui::app::{Field, input_count, input_key};
use homerun::tui::worker::{Gain, Report, run_job};
use ratatui::crossterm::event::KeyCode;

#[test]
fn the_figure_shown_is_figure_data_for_the_scene_and_follows_the_inputs() {
    use homerun::analysis::figures::{Figure, figure_data};
    let mut app = app(80, 24, None);
    settle(&mut app);
    // Not computed until the figures tab shows.
    assert_eq!(app.figure, None);
    assert!(app.take_figure_job().is_none());
    key(&mut app, KeyCode::Char('4'));
    let all = homerun::tui::app::FIGURES;
    let first = all.iter().position(|&n| n == app.figure_number).unwrap();
    for k in 0..all.len() {
        let number = all[(first + k) % all.len()];
        settle(&mut app);
        let shown = app.figure.clone().unwrap();
        assert_eq!(shown.number, number);
        let Ok(Figure::Table(direct)) = figure_data(number, &app.scene, &app.preset_name) else {
            panic!("figure {number}");
        };
        assert_eq!(shown.data, Ok(direct), "figure {number}");
        println!("Fig. {number}: {:?}", shown.elapsed);
        key(&mut app, KeyCode::Char('f'));
    }
    // A nudge makes the figure stale: its job's result for the old inputs is dropped.
    settle(&mut app);
    let old = app.take_figure_job();
    assert!(old.is_none());
    let generation = app.figure_generation;
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('l'));
    assert!(app.figure_generation > generation);
    assert!(!app.figure_fresh());
    settle(&mut app);
    assert!(app.figure_fresh());
}

#[test]
fn the_sensitivity_column_is_what_a_nudge_does() {
    // At 80×24 the pane has room for Δ only, so Δopt is not computed.
    let mut small = app(80, 24, None);
    settle(&mut small);
    assert_eq!(small.gains_done(Gain::Swing), small.gain_count());
    assert_eq!(small.gains_done(Gain::Optimum), 0);
    assert!(!small.busy());

    let mut app = app(140, 40, None);
    settle(&mut app);
    assert_eq!(app.gains_done(Gain::Swing), app.gain_count());
    assert_eq!(app.gains_done(Gain::Optimum), app.gain_count());
    let k = input_index("bat.speed");
    let gain = app.swing_gains[k].unwrap().value.unwrap();
    let optimum_gain = app.optimum_gains[k].unwrap().value.unwrap();
    let (range, optimum) = (app.flown.flight.range, app.optimum.unwrap().best.range);
    // Half a metre per second of bat speed: ~2 m (the paper's "nearly 5 m"
    // per 1 m/s is 4.0 m in Fig. 8's sweep).
    assert!((1.7..2.3).contains(&gain), "{gain}");
    // The pane shows it beside the bat speed, signed.
    let row = screen(&app)
        .lines()
        .find(|l| l.contains("V̂_B0"))
        .unwrap()
        .to_owned();
    assert!(row.contains(&format!("{gain:+.2}")), "{row}");

    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('l'));
    // The same flight as the column's: exactly the range the nudge gains.
    assert_eq!(app.flown.flight.range - range, gain);
    // Until the worker reports, every cell is stale (kept, but marked).
    assert_eq!(app.gains_done(Gain::Swing), 0);
    assert!(app.swing_gains[k].is_some());
    settle(&mut app);
    // The optimum moves as the column said, within the optimiser's tolerance
    // (1e-4 m on each of the two searches).
    let moved = app.optimum.unwrap().best.range - optimum;
    assert!(
        (moved - optimum_gain).abs() < 1e-3,
        "{moved} vs {optimum_gain}"
    );
    // The swing's own inputs do not move the optimum; an input at its bound
    // has no nudge up.
    assert_eq!(
        app.optimum_gains[input_index("bat.undercut")]
            .unwrap()
            .value,
        None
    );
    select(&mut app, "bat.friction");
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Backspace);
    typed(&mut app, "2");
    key(&mut app, KeyCode::Enter);
    settle(&mut app);
    let friction = input_index("bat.friction");
    assert_eq!(app.swing_gains[friction].unwrap().value, None);
}

#[test]
fn every_key_is_offered_and_the_weather_derives_the_air() {
    let mut app = app(80, 24, None);
    // Every key but the launch, which is the batted-ball scene's.
    for k in 0..input_count() {
        let launch = input_key(k).name.starts_with("launch.");
        assert_eq!(
            app.fields.contains(&Field::Key(k)),
            !launch,
            "{}",
            input_key(k).name
        );
    }
    assert!(app.fields.contains(&Field::Drag) && app.fields.contains(&Field::Lift));
    assert!(app.fields.contains(&Field::Hand));
    // Each group is listed once, the swing beyond the paper's plane and
    // the contact beyond its rigid rolling last.
    let headers = app.input_lines().iter().filter(|l| l.is_none()).count();
    assert_eq!(
        headers, 7,
        "pitch, bat, ball, environment, model, 3-D swing, contact"
    );

    select(&mut app, "environment.temperature");
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Backspace);
    typed(&mut app, "30");
    key(&mut app, KeyCode::Enter);
    let weather = Atmosphere {
        temperature: 30.0,
        ..Atmosphere::STANDARD
    };
    assert_eq!(app.scene.environment.atmosphere(), Some(weather));
    assert_eq!(app.scene.environment.air_density, weather.air_density());
    assert_eq!(
        app.scene.environment.kinematic_viscosity,
        weather.kinematic_viscosity()
    );
    // A nudge of the elevation keeps the temperature and derives again.
    select(&mut app, "environment.elevation");
    key(&mut app, KeyCode::Char('l'));
    let higher = Atmosphere {
        elevation: 10.0,
        ..weather
    };
    assert_eq!(app.scene.environment.air_density, higher.air_density());
    // The readout says where the air comes from.
    let screen = screen(&app);
    assert!(
        screen.contains("from 30 °C, 10 m, 1013.25 hPa,") && screen.contains("50 %"),
        "{screen}"
    );
    // Given ρ replaces the weather's.
    select(&mut app, "environment.air_density");
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Backspace);
    typed(&mut app, "1.1");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.scene.environment.atmosphere(), None);
    assert_eq!(app.scene.environment.air_density, 1.1);

    // The models cycle with h and l.
    let lift = app.fields.iter().position(|f| *f == Field::Lift).unwrap();
    app.selected = lift;
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.scene.lift, LiftModel::Nathan);
    key(&mut app, KeyCode::Char('h'));
    key(&mut app, KeyCode::Char('h'));
    assert_eq!(app.scene.lift, LiftModel::None);
}

#[test]
fn a_ball_that_does_not_land_is_never_shown_as_a_range() {
    let mut app = app(80, 24, None);
    set_and_settle(&mut app, "environment.gravity", "0.001");
    assert!(!app.flown.flight.landed);
    let screen = screen(&app);
    // The readout says where the ball is instead, and the trajectory's
    // title gives no range.
    assert!(screen.contains("did not land in 600 s ("), "{screen}");
    assert!(screen.contains(" does not land, apex "), "{screen}");
    assert!(!screen.contains("range "), "{screen}");
    // The optimum found from the coarse scan lands, and is shown with its
    // range; the current swing's difference from it has none.
    let optimum = app.optimum.unwrap();
    assert!(
        optimum.done && optimum.best.range.is_finite(),
        "{optimum:?}"
    );
    assert!(
        screen.contains("you −opt ΔE") && screen.contains("  —"),
        "{screen}"
    );
    // The heatmap's best cell and scale use only landings.
    let surface = &app.surface.as_ref().unwrap().surface;
    assert!(surface.any_not_landed());
    let (i, j, best) = surface.best().unwrap();
    assert_eq!(surface.get(i, j), Some(best));
}

/// The groups of the inputs pane, top to bottom.
fn groups(app: &homerun::tui::app::App) -> Vec<&'static str> {
    let mut groups = Vec::new();
    for field in &app.fields {
        if !groups.contains(&field.group()) {
            groups.push(field.group());
        }
    }
    groups
}

#[test]
fn b_flies_the_swings_launch_on_its_own_and_back() {
    use homerun::model::launch::SceneKind;
    let mut app = app(80, 24, None);
    settle(&mut app);
    let swing = app.scene;
    let (launch, range) = (app.flown.launch, app.flown.flight.range);
    key(&mut app, KeyCode::Char('b'));
    assert_eq!(app.scene.kind, SceneKind::BattedBall);
    // The same launch under the same models (the swing's paper's, kept
    // chosen), so the same flight.
    assert_eq!(app.flown.launch, launch);
    assert_eq!(
        (app.scene.drag, app.scene.lift),
        (DragModel::Sawicki2003, LiftModel::Sawicki2003)
    );
    let flown = homerun::model::launch::fly_scene(&app.scene, Purpose::Readout);
    assert_eq!(app.flown.flight, flown.flight);
    assert!((app.flown.flight.range - range).abs() < 1e-9);
    assert!(app.flown.impact.is_none());
    // Launch, ball, air and models; no pitch and no bat.
    assert_eq!(groups(&app), ["", "launch", "ball", "environment", "model"]);
    assert!(
        matches!(app.fields[app.selected], Field::Key(k) if input_key(k).name == "launch.speed")
    );
    let shown = screen(&app);
    assert!(shown.contains("batted ball · "), "{shown}");
    assert!(
        !shown.contains("V̂_B0") && !shown.contains("optimum"),
        "{shown}"
    );
    // A launch key nudged; then back to the swing as it was.
    select(&mut app, "launch.angle");
    key(&mut app, KeyCode::Char('l'));
    assert_ne!(app.flown.flight.range, range);
    key(&mut app, KeyCode::Char('b'));
    assert_eq!(app.scene.kind, SceneKind::Swing);
    assert_eq!((app.scene.pitch, app.scene.bat), (swing.pitch, swing.bat));
    assert_eq!(app.flown.flight.range, range);
    assert_eq!(
        groups(&app),
        [
            "",
            "pitch",
            "bat",
            "ball",
            "environment",
            "model",
            "3-D swing",
            "contact"
        ]
    );
    assert!(screen(&app).contains("swing · "));
}

#[test]
fn the_fly_ball_preset_opens_as_a_batted_ball() {
    use homerun::model::launch::SceneKind;
    // From the command line (`homerun tui --preset fly-ball`) …
    let mut app = app_on("fly-ball", 80, 24, None);
    assert_eq!(app.scene.kind, SceneKind::BattedBall);
    assert_eq!(app.flown.launch.speed, 46.04512);
    assert!(
        app.fields
            .iter()
            .all(|f| !["pitch", "bat"].contains(&f.group()))
    );
    let shown = screen(&app);
    // 103 mph is 46.04512 m/s: the input shows it as the readout does
    // (issue 36), not to digits no other pane shows.
    assert!(
        shown.matches("46.05 m/s").count() == 2 && !shown.contains("46.0451"),
        "{shown}"
    );
    // … and from the picker.
    let mut fastball = app_on("fastball", 80, 24, None);
    fastball.load(homerun::preset::load("fly-ball", None).unwrap());
    fastball.flush();
    assert_eq!(fastball.scene, app.scene);
    assert_eq!(fastball.flown.flight, app.flown.flight);
    // Nudging the launch angle changes the range by what Δ said.
    settle(&mut app);
    let k = input_index("launch.angle");
    let gain = app.swing_gains[k].unwrap().value.unwrap();
    let range = app.flown.flight.range;
    select(&mut app, "launch.angle");
    key(&mut app, KeyCode::Char('l'));
    // One step of 0.01 rad, snapped to a thousandth of it.
    assert!((app.scene.launch.angle.unwrap() - (0.488692190558412 + 0.01)).abs() < 5e-6);
    assert_ne!(app.flown.flight.range, range);
    assert_eq!(app.flown.flight.range - range, gain);
}

#[test]
fn a_batted_ball_costs_the_worker_no_optimum_or_surface() {
    let mut app = app_on("fly-ball", 200, 60, None);
    let job = app.take_job().unwrap();
    let mut reports = Vec::new();
    run_job(&job, &|| false, &mut |r| reports.push(r));
    // One Δ per input shown, and nothing else (no Δopt, even with room for it).
    assert_eq!(reports.len(), app.gain_count());
    assert!(reports.iter().all(|r| matches!(
        r,
        Report::Sensitivity {
            gain: Gain::Swing,
            ..
        }
    )));
    for report in reports {
        app.apply(report);
    }
    // And the figure in view (200×60 shows it): then nothing is left to do.
    settle(&mut app);
    assert_eq!(app.optimum, None);
    assert_eq!(app.surface, None);
    assert!(!app.busy());
    // Only the aero figures apply: the pane opens on Fig. 3, f steps
    // through Figs. 3–4, and the title says the rest need a swing.
    key(&mut app, KeyCode::Char('4'));
    assert_eq!(app.figure_number, 3);
    assert_eq!(app.figure.as_ref().unwrap().number, 3);
    assert!(screen(&app).contains("the rest need a swing"));
    key(&mut app, KeyCode::Char('f'));
    assert_eq!(app.figure_number, 4);
    key(&mut app, KeyCode::Char('f'));
    assert_eq!(app.figure_number, 3);
    settle(&mut app);
    assert!(app.figure.as_ref().unwrap().data.is_ok());
    // Back in the swing, f reaches Fig. 8; the batted ball again shows Fig. 3.
    key(&mut app, KeyCode::Char('b'));
    for _ in 0..4 {
        key(&mut app, KeyCode::Char('f'));
    }
    assert_eq!(app.figure_number, 8);
    key(&mut app, KeyCode::Char('b'));
    assert_eq!(app.figure_number, 3);
    // r has no optimum to go to.
    key(&mut app, KeyCode::Char('r'));
    assert!(app.message.as_ref().unwrap().0.contains("swing scene"));
}

#[test]
fn a_batted_ball_saves_as_one_and_the_pin_compares_across_scenes() {
    use homerun::model::launch::SceneKind;
    let dir = tempfile::tempdir().unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    settle(&mut app);
    key(&mut app, KeyCode::Char('p'));
    let swing_range = app.flown.flight.range;
    key(&mut app, KeyCode::Char('b'));
    select(&mut app, "launch.speed");
    key(&mut app, KeyCode::Char('L'));
    assert_eq!(app.scene.launch.speed, Some(app.flown.launch.speed));
    // The pinned swing against the batted ball: 5 m/s more launch speed.
    let pin = app.pin.clone().unwrap();
    assert_eq!(pin.scene.kind, SceneKind::Swing);
    assert_eq!(pin.flown.flight.range, swing_range);
    let dv = app.flown.launch.speed - pin.flown.launch.speed;
    // Five steps of 0.5 m/s, snapped to a thousandth of the step.
    assert!((dv - 5.0).abs() < 5e-4, "{dv}");
    let shown = screen(&app);
    assert!(shown.contains("+5.00 m/s"), "{shown}");
    assert!(shown.contains("━ pin"), "{shown}");
    // Saved, it is a batted-ball preset.
    key(&mut app, KeyCode::Char('s'));
    for _ in 0..12 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "batted");
    key(&mut app, KeyCode::Enter);
    // The description: none, so the default.
    key(&mut app, KeyCode::Enter);
    let saved = homerun::preset::load("batted", Some(dir.path())).unwrap();
    assert_eq!(saved.scene.kind, SceneKind::BattedBall);
    assert_eq!(saved.scene.launch, app.scene.launch);
}

#[test]
fn a_ball_that_lands_behind_the_plate_is_drawn_behind_it() {
    // 85° with 2500 rpm of backspin: the lift carries the ball back over
    // the plate, to land about 15 m behind it. The x axis starts behind
    // the plate, so the path is on the chart, not clipped at x = 0.
    // Under the paper's lift, which carries it back (Nathan's saturates).
    let mut app = app_on("fly-ball", 80, 24, None);
    app.scene.choose_drag(DragModel::Sawicki2003);
    app.scene.choose_lift(LiftModel::Sawicki2003);
    set_and_settle(&mut app, "launch.angle", "1.4835");
    let range = app.flown.flight.range;
    assert!(app.flown.flight.landed && range < -5.0, "{range}");
    // The plate's tick, 0, stands well right of the axis' corner.
    let screen = screen(&app);
    let lines: Vec<Vec<char>> = screen.lines().map(|l| l.chars().collect()).collect();
    let corner_row = lines.iter().position(|l| l.contains(&'└')).unwrap();
    let corner = lines[corner_row].iter().position(|&c| c == '└').unwrap();
    let labels: String = lines[corner_row + 1][corner..].iter().collect();
    let zero = labels
        .find(" 0 ")
        .unwrap_or_else(|| panic!("no 0 tick: {screen}"));
    assert!(zero >= 3, "the axis starts at the plate: {screen}");
}

/// The readout says what `optimize` says when the optimiser's best grazes
/// the ground only at its own precision (the WORK scene of
/// tests/command_line/flights.rs: a heavy-spun big ball in dense air).
#[test]
fn an_optimum_that_lands_only_at_the_optimisers_precision_is_tagged() {
    let mut preset = homerun::preset::load("fastball", None).unwrap();
    let scene = &mut preset.scene;
    scene.ball.radius = 0.063;
    scene.ball.mass = 0.35;
    scene.ball.gyration_radius = 0.046;
    scene.environment.set_air_density(4.4);
    scene.environment.gravity = 0.021;
    scene.bat.speed = 49.0;
    scene.pitch.spin = 1000.0;
    let mut app = homerun::tui::app::App::new(
        preset,
        None,
        homerun::tui::theme::ColorMode::Indexed,
        ratatui::layout::Rect::new(0, 0, 80, 24),
    );
    settle(&mut app);
    let optimum = app.optimum.unwrap();
    assert!(
        optimum.done && optimum.best.range.is_finite(),
        "{optimum:?}"
    );
    assert!(!optimum.lands_at_readout, "{optimum:?}");
    let screen = screen(&app);
    // Wrapped at words on the 80×24 readout.
    assert!(
        screen.contains("(readout:") && screen.contains("land)"),
        "{screen}"
    );
}

#[test]
fn the_3d_swing_is_offered_and_a_left_handed_batter_mirrors_the_flight() {
    use homerun::model::scene::Hand;
    let mut app = app(80, 24, None);
    // A tilted bat swung late: the ball flies toward right field.
    set_and_settle(&mut app, "bat.tilt", "0.5");
    set_and_settle(&mut app, "bat.direction", "0.2");
    let right = app.flown.flight;
    assert!(right.direction > 0.0, "{right:?}");
    // The hand, a named input like the models, cycles with l.
    app.selected = app.fields.iter().position(|f| *f == Field::Hand).unwrap();
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.scene.bat.hand, Hand::Left);
    // A left-handed batter swinging toward −φ_B is the mirror image.
    set_and_settle(&mut app, "bat.direction", "-0.2");
    assert_eq!(app.flown.flight.range, right.range);
    assert_eq!(app.flown.flight.direction, -right.direction);
    // The impact tab steps through the 3-D collision to its last stop.
    key(&mut app, KeyCode::Char('3'));
    for _ in 0..8 {
        key(&mut app, KeyCode::Char('.'));
    }
    let shown = screen(&app);
    assert!(shown.contains("Impact: separation"), "{shown}");
    assert!(!shown.contains("NaN") && !shown.contains("inf"), "{shown}");
}

/// Issue 28, item 2: `b` keeps the range to 1e-9 m on every bundled
/// preset: from a swing to its batted ball, and from that batted ball back
/// to the swing. The models in force go with the switch.
#[test]
fn b_keeps_the_range_on_every_preset() {
    let same = |a: f64, b: f64| (a - b).abs() < 1e-9 || (a.is_nan() && b.is_nan());
    for preset in homerun::preset::bundled() {
        let name = preset.name.clone();
        let mut app = app_on(&name, 80, 24, None);
        if !app.is_swing() {
            // A batted ball's b opens the swing it holds: another launch.
            key(&mut app, KeyCode::Char('b'));
        }
        let (range, models) = (app.flown.flight.range, (app.scene.drag, app.scene.lift));
        key(&mut app, KeyCode::Char('b'));
        assert!(!app.is_swing(), "{name}");
        assert_eq!((app.scene.drag, app.scene.lift), models, "{name}");
        let there = app.flown.flight.range;
        assert!(same(there, range), "{name}: {range} then {there}");
        key(&mut app, KeyCode::Char('b'));
        assert_eq!((app.scene.drag, app.scene.lift), models, "{name}");
        let back = app.flown.flight.range;
        assert!(same(back, range), "{name}: {range} then back {back}");
    }
}

/// The contact that grips, as a teacher turns it: a nudge of `grip e_T`
/// spins the fastball more than rolling does, and the readout says so.
#[test]
fn a_nudge_of_grip_springs_the_contact_back() {
    let mut app = app(80, 24, None);
    let rolled = app.flown.launch.spin;
    assert!(screen(&app).contains(" stick "), "{}", screen(&app));
    select(&mut app, "bat.tangential_restitution");
    for _ in 0..10 {
        key(&mut app, KeyCode::Char('l'));
    }
    assert!((app.scene.bat.tangential_restitution - 0.2).abs() < 1e-12);
    // 0.2 of the spin the halting impulse gave (391.8 rad/s): +78.4 rad/s.
    let gained = app.flown.launch.spin - rolled;
    assert!((gained - 78.4).abs() < 0.1, "{gained}");
    assert!(screen(&app).contains(" grip "), "{}", screen(&app));
}
