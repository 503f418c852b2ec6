//! What the explorer does with keys and background results.

mod tui_support;

use std::time::Duration;

use homerun::analysis::optimum::{OptimizerSettings, optimize, optimize_from};
use homerun::analysis::precision::Purpose;
use homerun::analysis::study::Grid;
use homerun::model::aero::{DragModel, LiftModel};
use homerun::model::atmosphere::Atmosphere;
use homerun::model::keys::KEYS;
use homerun::tui::app::Mode;
use homerun::tui::app::{Field, input_count, input_key};
use homerun::tui::layout::{CELL_ASPECT, FieldMap, heatmap_plot, layout};
use homerun::tui::worker::{Gain, Report, Worker, run_job};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{
    Event, KeyCode, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use ratatui::layout::Rect;
use tui_support::*;

#[test]
fn nudging_the_undercut_up_adds_backspin_and_range() {
    // The fastball's Table II swing has E = 26.5 mm, below the optimum 27.27
    // mm: more undercut means more backspin (Fig. 6) and, here, more range.
    let mut app = app(80, 24, None);
    select(&mut app, "bat.undercut");
    let (spin, range) = (app.flown.launch.spin, app.flown.flight.range);
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.scene.bat.undercut, 0.0265 + 0.0005);
    assert!(app.flown.launch.spin > spin + 1.0);
    assert!(app.flown.flight.range > range);
    // Down again, ten steps with Shift: less spin, less range than at the start.
    key_with(&mut app, KeyCode::Left, KeyModifiers::SHIFT);
    assert!((app.scene.bat.undercut - (0.0265 - 0.0045)).abs() < 1e-12);
    assert!(app.flown.launch.spin < spin - 10.0);
    assert!(app.flown.flight.range < range);
    // A finer nudge: a tenth of the step.
    key(&mut app, KeyCode::Char(']'));
    assert!((app.scene.bat.undercut - (0.0265 - 0.0045 + 0.00005)).abs() < 1e-12);
}

#[test]
fn a_nudge_out_of_range_is_refused_with_the_reason() {
    let mut app = app(80, 24, None);
    select(&mut app, "bat.friction");
    for _ in 0..6 {
        key_with(&mut app, KeyCode::Char('H'), KeyModifiers::SHIFT);
    }
    assert!(app.scene.bat.friction >= 0.0);
    let (message, error) = app.message.clone().unwrap();
    assert!(error && message.contains("bat.friction"), "{message}");
}

#[test]
fn typed_values_are_parsed_validated_and_kept_or_refused() {
    let mut app = app(80, 24, None);
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Enter);
    for _ in 0..4 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "fast");
    key(&mut app, KeyCode::Enter);
    match &app.mode {
        Mode::Edit {
            error: Some(error), ..
        } => assert!(error.contains("not a number"), "{error}"),
        other => panic!("still editing with an error, not {other:?}"),
    }
    assert_eq!(app.scene.bat.speed, 30.0);
    key(&mut app, KeyCode::Esc);
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.scene.bat.speed, 30.0);
    key(&mut app, KeyCode::Enter);
    for _ in 0..4 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "35");
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.scene.bat.speed, 35.0);
}

#[test]
fn settled_background_optimum_equals_optimize() {
    let mut app = app(80, 24, None);
    select(&mut app, "bat.speed");
    // Several changes in one batch: only the last inputs are worked on.
    key(&mut app, KeyCode::Char('l'));
    key(&mut app, KeyCode::Char('l'));
    settle(&mut app);
    let shown = app.optimum.unwrap();
    assert!(shown.done);
    // The first search starts from the scene's own swing, as optimize() does.
    let direct = optimize(&app.scene, OptimizerSettings::default());
    assert_eq!(shown.best.undercut, direct.undercut);
    assert_eq!(shown.best.swing_angle, direct.swing_angle);
    assert_eq!(shown.best.range, direct.range);
    assert_eq!(shown.evaluations, direct.evaluations);

    // The next search is warm-started from that optimum: the same as
    // optimize_from() there, and the same optimum as a cold search to within
    // the optimiser's tolerance on range (1e-4 m).
    let warm = (shown.best.undercut, shown.best.swing_angle);
    key(&mut app, KeyCode::Char('l'));
    settle(&mut app);
    let shown = app.optimum.unwrap();
    let direct = optimize_from(&app.scene, warm, OptimizerSettings::default());
    assert_eq!(shown.best.range, direct.range);
    assert_eq!(shown.best.undercut, direct.undercut);
    let cold = optimize(&app.scene, OptimizerSettings::default());
    assert!(
        (shown.best.range - cold.range).abs() < 2e-4,
        "{shown:?} vs {cold:?}"
    );
    assert!((shown.best.undercut - cold.undercut).abs() < 2e-4);
}

#[test]
fn a_stale_result_is_never_shown_for_new_inputs() {
    let mut app = app(80, 24, None);
    let old_job = app.take_job().unwrap();
    let mut old_reports = Vec::new();
    run_job(&old_job, &|| false, &mut |r| old_reports.push(r));
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('L'));
    assert!(app.generation > old_job.generation);
    for report in old_reports {
        app.apply(report);
    }
    assert_eq!(app.optimum, None);
    assert_eq!(app.surface, None);
    assert!(app.optimal_path.is_empty());
    // The status line says it is still working, not a stale figure.
    let screen = screen(&app);
    assert!(screen.contains("optimising…"), "{screen}");
    assert!(!screen.contains("134.79"), "{screen}");
}

#[test]
fn the_worker_thread_cancels_old_work_and_finishes_the_new() {
    let mut app = app(80, 24, None);
    let worker = Worker::spawn();
    let first = app.take_job().unwrap();
    worker.submit(first);
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('l'));
    let second = app.take_job().unwrap();
    worker.submit(second);
    // Collect reports until the new job's optimiser and finest surface are in.
    let (mut optimum_done, mut surface_done) = (false, false);
    while !(optimum_done && surface_done) {
        let report = worker
            .reports
            .recv_timeout(Duration::from_secs(120))
            .expect("the worker answers");
        match &report {
            Report::Optimum {
                generation, done, ..
            } if *generation == second.generation => optimum_done |= *done,
            Report::Surface {
                generation, last, ..
            } if *generation == second.generation => surface_done |= *last,
            _ => {}
        }
        app.apply(report);
    }
    let shown = app.optimum.unwrap();
    assert_eq!(
        shown.best.range,
        optimize(&second.scene, OptimizerSettings::default()).range
    );
    assert!(app.surface.as_ref().unwrap().last);
}

#[test]
fn typing_replaces_the_shown_value_and_end_keeps_it() {
    let mut app = app(80, 24, None);
    select(&mut app, "bat.speed");
    // The field opens with "30" selected, as in a form: typing replaces it.
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "31");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.scene.bat.speed, 31.0);
    // End drops the selection and keeps the text for editing: "31" + ".5".
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::End);
    typed(&mut app, ".5");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.scene.bat.speed, 31.5);
}

#[test]
fn presets_save_and_load_and_a_broken_file_is_listed_not_fatal() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("broken.toml"), "[bat]\nspeed = \"fast\"\n").unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('L'));
    key(&mut app, KeyCode::Char('s'));
    for _ in 0..8 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "quick");
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert!(dir.path().join("quick.toml").is_file());
    assert_eq!(app.preset_name, "quick");

    // Back to the fastball through the picker, then to the saved one.
    key(&mut app, KeyCode::Char('o'));
    let Mode::Open { items, .. } = &app.mode else {
        panic!("the picker is open")
    };
    let names: Vec<&str> = items.iter().map(|i| i.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "fastball",
            "knuckleball",
            "curveball",
            "figure5",
            "mile-high",
            "fly-ball",
            "broken",
            "quick"
        ]
    );
    let broken = &items[6];
    assert!(
        broken.preset.is_none() && broken.detail.contains("bat.speed"),
        "{broken:?}"
    );
    // Enter on the broken one: its error, and the picker stays.
    for _ in 0..10 {
        key(&mut app, KeyCode::Char('k'));
    }
    for _ in 0..6 {
        key(&mut app, KeyCode::Char('j'));
    }
    key(&mut app, KeyCode::Enter);
    match &app.mode {
        Mode::Open { error: Some(e), .. } => assert!(e.contains("broken.toml"), "{e}"),
        other => panic!("picker with the error, not {other:?}"),
    }
    assert_eq!(app.scene.bat.speed, 35.0);
    for _ in 0..6 {
        key(&mut app, KeyCode::Char('k'));
    }
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.preset_name, "fastball");
    assert_eq!(app.scene.bat.speed, 30.0);
    key(&mut app, KeyCode::Char('o'));
    key(&mut app, KeyCode::Char('G'));
    for _ in 0..10 {
        key(&mut app, KeyCode::Char('j'));
    }
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.preset_name, "quick");
    assert_eq!(app.scene.bat.speed, 35.0);
}

#[test]
fn colours_fall_back_to_the_256_colour_cube() {
    use homerun::tui::theme::ColorMode;
    use ratatui::style::Color;
    let indexed = ColorMode::Indexed;
    assert_eq!(indexed.rgb((0, 0, 0)), Color::Indexed(16));
    assert_eq!(indexed.rgb((255, 255, 255)), Color::Indexed(231));
    // The cube's levels are 0, 95, 135, 175, 215, 255: each channel goes to
    // the nearest.
    assert_eq!(
        indexed.rgb((95, 135, 175)),
        Color::Indexed(16 + 36 + 12 + 3)
    );
    assert_eq!(
        indexed.rgb((100, 130, 180)),
        Color::Indexed(16 + 36 + 12 + 3)
    );
    assert_eq!(ColorMode::TrueColor.rgb((1, 2, 3)), Color::Rgb(1, 2, 3));
}

#[test]
fn feet_are_a_display_choice() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    let range = app.flown.flight.range;
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.flown.flight.range, range, "nothing is recomputed");
    let screen = screen(&app);
    // 134.698780 m is 441.925 ft.
    assert!(screen.contains("range 441.93 ft"), "{screen}");
    assert!(screen.contains("x (ft)"), "{screen}");
}

#[test]
fn a_save_never_hides_a_bundled_preset_unless_asked_twice() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    // The proposed name hides nothing: the fastball is bundled.
    key(&mut app, KeyCode::Char('s'));
    let Mode::Save { text, .. } = &app.mode else {
        panic!("the save prompt is open")
    };
    assert_eq!(text.lines().join(""), "fastball-1");
    // Typing the bundled name warns, and saves nothing.
    typed(&mut app, "fastball");
    key(&mut app, KeyCode::Enter);
    match &app.mode {
        Mode::Save { error: Some(e), .. } => assert!(e.contains("is bundled"), "{e}"),
        other => panic!("a warning, not {other:?}"),
    }
    assert!(!dir.path().join("fastball.toml").exists());
    // Enter again: saved, and the picker says which fastball is which.
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert!(dir.path().join("fastball.toml").is_file());
    key(&mut app, KeyCode::Char('o'));
    let Mode::Open { items, .. } = &app.mode else {
        panic!("the picker is open")
    };
    let details: Vec<&str> = items
        .iter()
        .filter(|i| i.name == "fastball")
        .map(|i| i.detail.as_str())
        .collect();
    assert_eq!(details.len(), 2);
    assert!(details[0].ends_with("(bundled; hidden by yours of that name)"));
    assert!(details[1].ends_with("(yours; hides the bundled one)"));
}

#[test]
fn a_pin_survives_a_nudge_and_a_preset_load_and_p_clears_it() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('p'));
    let pin = app.pin.clone().expect("pinned");
    assert_eq!(pin.scene, app.scene);
    assert_eq!(pin.path, app.path);
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('L'));
    settle(&mut app);
    let after = app.pin.clone().expect("still pinned");
    assert_eq!(after.scene, pin.scene, "the pinned scene is unchanged");
    assert_eq!(after.flown, pin.flown);
    assert_ne!(app.scene, pin.scene);
    // The readout's now − pin is non-zero: 5 m/s more bat speed.
    let dv = app.flown.launch.speed - pin.flown.launch.speed;
    assert!(dv > 1.0, "{dv}");
    let shown = screen(&app);
    assert!(
        shown.contains(&format!("{dv:+.2} m/s")),
        "the readout shows now − pin: {shown}"
    );
    assert!(shown.contains("━ pin"), "the legend names the pin: {shown}");
    // A preset load keeps it too.
    app.load(homerun::preset::load("fastball", None).unwrap());
    app.flush();
    assert_eq!(app.pin.as_ref().map(|p| p.scene), Some(pin.scene));
    key_with(&mut app, KeyCode::Char('P'), KeyModifiers::SHIFT);
    assert_eq!(app.pin, None);
    assert!(!screen(&app).contains("now−pin"));
}

fn mouse(app: &mut homerun::tui::app::App, kind: MouseEventKind, column: u16, row: u16) {
    app.handle(&Event::Mouse(MouseEvent {
        kind,
        column,
        row,
        modifiers: KeyModifiers::NONE,
    }));
    app.flush();
}

#[test]
fn a_click_on_the_heatmap_moves_the_swing_to_that_cells_centre_on_the_steps() {
    for (w, h, tab) in [(80, 24, '2'), (200, 60, '1')] {
        let mut app = app(w, h, None);
        settle(&mut app);
        key(&mut app, KeyCode::Char(tab));
        let area = layout(app.size, app.tab, true).heatmap.unwrap();
        let plot = heatmap_plot(area);
        // A cell a third of the way across and two thirds down.
        let (column, row) = (plot.width / 3, 2 * plot.height / 3);
        let (x, y) = (plot.x + column, plot.y + row);
        mouse(&mut app, MouseEventKind::Down(MouseButton::Left), x, y);
        // One grid column per character, two grid rows (half blocks) per
        // line, the first row at the bottom, over the explorer's window.
        let window = Grid::explorer_window();
        let (columns, rows) = (plot.width as f64, 2.0 * plot.height as f64);
        let e = window.undercut.0
            + (window.undercut.1 - window.undercut.0) * column as f64 / (columns - 1.0);
        // The mean of the cell's two rows, rows − 1 − 2·row and the one below.
        let j = rows - 1.5 - 2.0 * row as f64;
        let psi =
            window.swing_angle.0 + (window.swing_angle.1 - window.swing_angle.0) * j / (rows - 1.0);
        // Rounded to the inputs' steps (0.5 mm, 0.01 rad).
        let step = |name| homerun::Scene::key(name).unwrap().step;
        let on_step = |v: f64, name| (v / step(name)).round() * step(name);
        let (e, psi) = (on_step(e, "bat.undercut"), on_step(psi, "bat.swing_angle"));
        assert!((app.scene.bat.undercut - e).abs() < 1e-12, "{w}x{h}");
        assert!((app.scene.bat.swing_angle - psi).abs() < 1e-12, "{w}x{h}");
        // The swing's mark is drawn in the cell clicked.
        let mut terminal = ratatui::Terminal::new(TestBackend::new(w, h)).unwrap();
        terminal
            .draw(|frame| homerun::tui::view::draw(frame, &app))
            .unwrap();
        assert_eq!(terminal.backend().buffer()[(x, y)].symbol(), "✚");
    }
}

#[test]
fn a_click_on_an_input_selects_it_and_the_wheel_nudges_it() {
    let mut app = app(80, 24, None);
    let screen = screen(&app);
    // The row on screen whose label is ω_B0 (the bat's roll).
    let line = screen.lines().position(|l| l.contains("ω_B0")).unwrap() as u16;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), 5, line);
    let spin = app.fields[app.selected];
    assert!(
        matches!(spin, Field::Key(k) if KEYS[k].name == "bat.spin"),
        "{spin:?}"
    );
    // The wheel over another input: that one, up a step, then down two.
    let speed = screen.lines().position(|l| l.contains("V̂_b0")).unwrap() as u16;
    mouse(&mut app, MouseEventKind::ScrollUp, 10, speed);
    assert_eq!(app.scene.pitch.speed, 42.0 + 0.5);
    mouse(&mut app, MouseEventKind::ScrollDown, 10, speed);
    mouse(&mut app, MouseEventKind::ScrollDown, 10, speed);
    assert_eq!(app.scene.pitch.speed, 42.0 - 0.5);
    assert!(matches!(app.fields[app.selected], Field::Key(k) if KEYS[k].name == "pitch.speed"));
    // A click on a group's header or outside the panes changes nothing.
    let before = (app.selected, app.scene);
    let header = screen.lines().position(|l| l.contains("─ bat")).unwrap() as u16;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), 5, header);
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), 79, 23);
    assert_eq!((app.selected, app.scene), before);
}

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

/// The index of input `name`, as the sensitivity columns count them.
fn input_index(name: &str) -> usize {
    (0..input_count())
        .find(|&k| input_key(k).name == name)
        .unwrap()
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
    // Each group is listed once, the swing beyond the paper's plane last.
    let headers = app.input_lines().iter().filter(|l| l.is_none()).count();
    assert_eq!(
        headers, 6,
        "pitch, bat, ball, environment, model, 3-D swing"
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
        screen.contains("from 30 °C, 10 m, 1013.25 hPa, 50 %"),
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
    // The same launch, flown under Nathan's aero (a batted ball's default,
    // the models not being chosen) rather than the swing's paper's.
    assert_eq!(app.flown.launch, launch);
    assert_eq!(
        (app.scene.drag, app.scene.lift),
        (DragModel::Nathan, LiftModel::Nathan)
    );
    let nathan = homerun::model::launch::fly_scene(&app.scene, Purpose::Readout);
    assert_eq!(app.flown.flight, nathan.flight);
    assert!((app.flown.flight.range - range).abs() > 1.0);
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
            "3-D swing"
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
    assert!(
        shown.contains("46.0451 m/s") && shown.contains("46.05 m/s"),
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
    let saved = homerun::preset::load("batted", Some(dir.path())).unwrap();
    assert_eq!(saved.scene.kind, SceneKind::BattedBall);
    assert_eq!(saved.scene.launch, app.scene.launch);
}

#[test]
fn u_shows_and_takes_every_value_in_baseball_units() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('u'));
    // Typed in mph: 100 mph is 44.704 m/s.
    select(&mut app, "pitch.speed");
    key(&mut app, KeyCode::Enter);
    let Mode::Edit { text, .. } = &app.mode else {
        panic!("editing")
    };
    // The edit starts from the shown text: 42 m/s is 93.951 mph, shown to
    // the 1 mph step.
    assert_eq!(text.lines().join(""), "94");
    typed(&mut app, "100");
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert!((app.scene.pitch.speed - 44.704).abs() < 1e-12);
    // A nudge is 1 mph, exactly.
    let before = app.scene.pitch.speed;
    key(&mut app, KeyCode::Char('l'));
    let step = app.scene.pitch.speed - before;
    assert!((step - 0.44704).abs() < 1e-12, "{step}");
    // Enter on the shown text unchanged keeps the value as it was.
    select(&mut app, "bat.undercut");
    let undercut = app.scene.bat.undercut;
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.scene.bat.undercut, undercut);
    // An invalid value is refused with its range in the shown unit.
    select(&mut app, "pitch.speed");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "300");
    key(&mut app, KeyCode::Enter);
    match &app.mode {
        Mode::Edit {
            error: Some(error), ..
        } => assert_eq!(
            error,
            "pitch.speed = 300 mph: must be a finite number in (0, 223.693] mph"
        ),
        other => panic!("an error, not {other:?}"),
    }
    key(&mut app, KeyCode::Esc);
    settle(&mut app);
    // Δ is in feet for the imperial nudge: what pressing l does.
    let k = input_index("pitch.speed");
    let gain = app.swing_gains[k].unwrap().value.unwrap();
    let range = app.flown.flight.range;
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.flown.flight.range - range, gain);
    let shown = screen(&app);
    assert!(shown.contains("Δ ft") && shown.contains("mph"), "{shown}");
    // Back to SI: 100 mph and two nudges of 1 mph are 45.59808 m/s.
    key(&mut app, KeyCode::Char('u'));
    assert!(screen(&app).contains("45.5981 m/s"));
}

#[test]
fn a_unit_switch_keeps_the_optimum_and_recomputes_only_the_deltas() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    let (optimum, surface) = (app.optimum, app.surface.clone().unwrap());
    let k = input_index("bat.speed");
    let si_gain = app.swing_gains[k].unwrap().value.unwrap();
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.optimum, optimum);
    assert!(app.surface_fresh());
    let job = app.take_job().unwrap();
    let mut reports = Vec::new();
    run_job(&job, &|| false, &mut |r| reports.push(r));
    assert!(
        reports
            .iter()
            .all(|r| matches!(r, Report::Sensitivity { .. }))
    );
    for report in reports {
        app.apply(report);
    }
    assert!(!app.busy());
    assert_eq!(app.surface.as_ref().unwrap().surface, surface.surface);
    // 1 mph of bat speed (0.447 m/s) gains less than 0.5 m/s did.
    let gain = app.swing_gains[k].unwrap().value.unwrap();
    assert!(gain > 0.0 && gain < si_gain, "{gain} vs {si_gain}");
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
/// tests/command_line.rs: a heavy-spun big ball in dense air).
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
    assert!(screen.contains("(readout: does not land)"), "{screen}");
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

/// The field view's geometry, computed here from the pane alone: the plot
/// is the pane inside its border, at equal scales (a braille dot is half a
/// cell wide and a quarter of a cell [`CELL_ASPECT`] times as tall as it is
/// wide), the plate at the bottom centre. So the direction of a cell's
/// centre from the plate needs no metres: only how many dots across and up.
fn clicked_direction(pane: Rect, plate_row_dots: f64, column: u16, row: u16) -> f64 {
    let plot = Rect::new(pane.x + 1, pane.y + 1, pane.width - 2, pane.height - 2);
    // Dots from the plate (at the middle of the plot's dot columns).
    let across = 2.0 * f64::from(column - plot.x) + 0.5 - (2.0 * f64::from(plot.width) - 1.0) / 2.0;
    let up = plate_row_dots - (4.0 * f64::from(row - plot.y) + 1.5);
    // A dot across is half a cell wide; one up is a quarter of a cell tall.
    (across / 2.0).atan2(up * CELL_ASPECT / 4.0)
}

#[test]
fn a_click_on_the_field_sets_the_launch_direction_on_its_step() {
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('5'));
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    let map = app.field_map(pane);
    // The plate's dot row, from the bounds the view drew (x = 0 lies
    // `behind` metres above the bottom dot row).
    let dots_x = 4.0 * f64::from(pane.height - 2) - 1.0;
    let plate_row_dots = dots_x * map.x[1] / (map.x[1] - map.x[0]);
    let (column, row) = (pane.x + 10, pane.y + 6);
    mouse(
        &mut app,
        MouseEventKind::Down(MouseButton::Left),
        column,
        row,
    );
    settle(&mut app);
    let expected = clicked_direction(pane, plate_row_dots, column, row);
    // On the input's step (0.01 rad), as typed.
    let on_step = (expected / 0.01).round() * 0.01;
    assert!(expected < -0.3, "left of centre: {expected}");
    assert_eq!(app.scene.launch.direction, Some(on_step));
    assert!((app.flown.flight.direction - on_step).abs() < 0.01);
    // In degrees the step is 0.5°.
    app.set_units(homerun::units::UnitSystem::Imperial);
    let (column, row) = (pane.right() - 12, pane.y + 8);
    mouse(
        &mut app,
        MouseEventKind::Down(MouseButton::Left),
        column,
        row,
    );
    let expected = clicked_direction(pane, plate_row_dots, column, row);
    let degrees = (expected.to_degrees() / 0.5).round() * 0.5;
    assert!(expected > 0.3, "right of centre: {expected}");
    let set = app.scene.launch.direction.unwrap();
    assert!(
        (set - degrees.to_radians()).abs() < 1e-12,
        "{set} vs {degrees}°"
    );
}

#[test]
fn a_click_on_the_field_of_a_swing_makes_it_a_batted_ball_and_b_returns() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    let swing = app.scene;
    key(&mut app, KeyCode::Char('5'));
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    mouse(
        &mut app,
        MouseEventKind::Down(MouseButton::Left),
        pane.x + pane.width / 2 + 6,
        pane.y + 4,
    );
    assert!(!app.is_swing());
    let direction = app.scene.launch.direction.unwrap();
    assert!(direction > 0.0 && direction < 0.7, "{direction}");
    // The swing's launch, turned.
    assert_eq!(app.scene.launch.speed, Some(app.flown.launch.speed));
    key(&mut app, KeyCode::Char('b'));
    assert!(app.is_swing());
    assert_eq!(app.scene.pitch, swing.pitch);
    assert_eq!(app.scene.bat, swing.bat);
}

#[test]
fn the_pinned_track_is_drawn_on_the_field() {
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('5'));
    set_and_settle(&mut app, "launch.direction", "0.3");
    key(&mut app, KeyCode::Char('p'));
    set_and_settle(&mut app, "launch.direction", "-0.3");
    let pin = app.pin.as_ref().unwrap();
    assert_eq!(pin.ground.len(), pin.path.len());
    // Its track ends toward right field, the current one toward left.
    let (pin_end, now_end) = (*pin.ground.last().unwrap(), *app.ground.last().unwrap());
    assert!(
        pin_end.1 > 30.0 && now_end.1 < -30.0,
        "{pin_end:?} {now_end:?}"
    );
    // Drawn in the pin's colour: a cell where its landing point falls.
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    let map = app.field_map(pane);
    let buffer = buffer(&app);
    let in_pin_colour = |(x, z): (f64, f64)| {
        let (column, row) = cell(&map, x, z);
        buffer[(column, row)].fg == app.theme.pinned.fg.unwrap()
    };
    let drawn = pin
        .ground
        .iter()
        .rev()
        .take(10)
        .filter(|p| in_pin_colour(**p))
        .count();
    assert!(
        drawn >= 5,
        "{drawn} of the pin's last 10 samples in its colour"
    );
    assert!(screen(&app).contains("pin"), "the legend names the pin");
}

/// The cell where the chart draws (x, z) in braille over the field's plot.
fn cell(map: &FieldMap, x: f64, z: f64) -> (u16, u16) {
    let plot = map.plot;
    let dots_z = 2.0 * f64::from(plot.width) - 1.0;
    let dots_x = 4.0 * f64::from(plot.height) - 1.0;
    let column = ((z - map.z[0]) * dots_z / (map.z[1] - map.z[0])).round() as u16 / 2;
    let row = ((map.x[1] - x) * dots_x / (map.x[1] - map.x[0])).round() as u16 / 4;
    (plot.x + column, plot.y + row)
}

/// `m` picks a ballpark: the field draws its fence, the side view its wall
/// where the ball crosses, and the readout says what the ball does there and
/// in how many parks it clears, as judging each park's fence apart does.
#[test]
fn m_picks_a_park_and_the_readout_judges_the_ball_there() {
    use homerun::model::park;
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    let (flight, _, _) = homerun::model::launch::scene_start(&app.scene);
    let options = Purpose::Readout.flight_options();
    let cleared = park::bundled()
        .iter()
        .filter(|p| flight.judge(&options, &[&p.fence]).1[0].clears())
        .count();
    let at = app.at_parks.unwrap();
    assert_eq!((at.cleared, at.of), (cleared, 30));
    assert!(screen(&app).contains(&format!("clears {cleared} of 30 parks")));
    key(&mut app, KeyCode::Char('m'));
    let first = &park::bundled()[0];
    assert_eq!(app.park, Some(0));
    assert_eq!(app.field_fence().unwrap(), first.fence);
    let here = app.at_parks.unwrap().here.unwrap();
    assert_eq!(here, flight.judge(&options, &[&first.fence]).1[0]);
    let wall = here.wall.unwrap();
    assert_eq!(app.side_fence(), Some((wall.distance, wall.height)));
    assert!(
        screen(&app).contains(&format!("{} ", first.code)),
        "{}",
        screen(&app)
    );
    // Back past the first park: none, the preset's fence again.
    key(&mut app, KeyCode::Char('M'));
    assert_eq!(app.park, None);
    assert!(app.at_parks.unwrap().here.is_none());
}
