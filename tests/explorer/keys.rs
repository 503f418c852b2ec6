//! Keys and inputs (nudges, typed values, presets, colours, units, the pin)
//! and the worker that answers them (stale results never shown, cancelling).

use std::time::Duration;

use crate::input_index;
use crate::tui_support::*;
use homerun::analysis::optimum::{OptimizerSettings, optimize, optimize_from};
use homerun::tui::app::Mode;
use homerun::tui::worker::{Report, Worker, run_job};
use ratatui::crossterm::event::{KeyCode, KeyModifiers};

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

/// Enter, the shown value erased, `text` typed, Enter.
fn retype(app: &mut homerun::tui::app::App, text: &str) {
    key(app, KeyCode::Enter);
    for _ in 0..12 {
        key(app, KeyCode::Backspace);
    }
    typed(app, text);
    key(app, KeyCode::Enter);
}

/// The reason a typed value was refused: the editor closed (so that it
/// swallows no later key), the reason shown as an error message.
fn edit_error(app: &homerun::tui::app::App) -> &str {
    assert!(
        matches!(app.mode, Mode::Normal),
        "the editor closes after a refusal, not {:?}",
        app.mode
    );
    match &app.message {
        Some((error, true)) => error,
        other => panic!("an error message, not {other:?}"),
    }
}

#[test]
fn typed_values_are_parsed_validated_and_kept_or_refused() {
    let mut app = app(80, 24, None);
    select(&mut app, "bat.speed");
    retype(&mut app, "fast");
    let error = edit_error(&app);
    assert!(error.contains("not a number"), "{error}");
    assert_eq!(app.scene.bat.speed, 30.0);
    // The next key acts on the panes: j moves down, it is not typed.
    let selected = app.selected;
    key(&mut app, KeyCode::Char('j'));
    assert_eq!(
        app.selected,
        selected + 1,
        "j after a refusal moves the selection"
    );
    key(&mut app, KeyCode::Char('k'));
    assert_eq!(app.scene.bat.speed, 30.0);
    retype(&mut app, "35");
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.scene.bat.speed, 35.0);
    // A unit may be typed with the number, as --set takes it: 70 mph is
    // 31.2928 m/s to the last bit; a unit of another quantity is refused,
    // saying what a bare number is here (mph once the explorer shows mph).
    retype(&mut app, "70mph");
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.scene.bat.speed, 70.0 * 0.44704);
    key(&mut app, KeyCode::Char('u'));
    retype(&mut app, "28deg");
    let error = edit_error(&app);
    assert!(
        error.contains("deg measures an angle") && error.contains("a bare number is mph"),
        "{error}"
    );
    assert_eq!(app.scene.bat.speed, 70.0 * 0.44704);
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
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert!(dir.path().join("quick.toml").is_file());
    assert_eq!(app.preset_name, "quick");

    // Back to the fastball through the picker, then to the saved one.
    key(&mut app, KeyCode::Char('o'));
    let Mode::Open { items, .. } = &app.mode else {
        panic!("the picker is open")
    };
    let names: Vec<&str> = items.iter().map(|i| i.name(&app.swings)).collect();
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
        broken.preset(&app.swings).is_none() && broken.detail(&app.swings).contains("bat.speed"),
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
    // Enter again (and on the description): saved, and the picker says
    // which fastball is which.
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert!(dir.path().join("fastball.toml").is_file());
    key(&mut app, KeyCode::Char('o'));
    let Mode::Open { items, .. } = &app.mode else {
        panic!("the picker is open")
    };
    let details: Vec<&str> = items
        .iter()
        .filter(|i| i.name(&app.swings) == "fastball")
        .map(|i| i.detail(&app.swings))
        .collect();
    assert_eq!(details.len(), 2);
    assert!(details[0].ends_with("(bundled; hidden by yours of that name)"));
    assert!(details[1].ends_with("(yours; hides the bundled one)"));
}

/// Issue 25 item 5: saving over one of the user's own presets asks too, as
/// `--save` refuses it without `--force`.
#[test]
fn a_save_never_overwrites_a_users_preset_unless_asked_twice() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("mine.toml"), "description = \"old\"\n").unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    key(&mut app, KeyCode::Char('s'));
    let Mode::Save { text, .. } = &app.mode else {
        panic!("the save prompt is open")
    };
    for _ in 0..text.lines().join("").chars().count() {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "mine");
    key(&mut app, KeyCode::Enter);
    match &app.mode {
        Mode::Save { error: Some(e), .. } => {
            assert!(e.contains("is one of your presets"), "{e}");
        }
        other => panic!("a warning, not {other:?}"),
    }
    let old = "description = \"old\"\n";
    assert_eq!(
        std::fs::read_to_string(dir.path().join("mine.toml")).unwrap(),
        old
    );
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Save { named: Some(_), .. }));
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert_ne!(
        std::fs::read_to_string(dir.path().join("mine.toml")).unwrap(),
        old
    );
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
    assert_eq!(
        edit_error(&app),
        "pitch.speed = 300 mph: must be a finite number in (0, 223.693] mph"
    );
    settle(&mut app);
    // Δ is in feet for the imperial nudge: what pressing l does.
    let k = input_index("pitch.speed");
    let gain = app.swing_gains[k].unwrap().value.unwrap();
    let range = app.flown.flight.range;
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.flown.flight.range - range, gain);
    let shown = screen(&app);
    // At 80×24 the inputs show words, values and units (Δ from 116
    // columns); the nudge's Δ is in feet (above).
    assert!(shown.contains("mph"), "{shown}");
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

/// Issue 27 item 5: `tui --savant FILE` offers the file's swings first in
/// the picker, open at start on the first; Enter loads one as the scene
/// (its name on the preset row), and `o` offers them again.
#[test]
fn a_savant_files_swings_open_first_in_the_picker() {
    let mut app = app(80, 24, None);
    let mut swing = homerun::preset::load("fastball", None).unwrap();
    swing.name = "Turang 04-03".to_owned();
    swing.description = "line 4, 2024-04-03: measured 78.5 mph at 32.0°".to_owned();
    swing.scene.bat.undercut = 0.0338;
    swing.scene.bat.tilt = 0.4;
    let other = homerun::preset::Preset {
        name: "Correa 04-03".to_owned(),
        ..swing.clone()
    };
    app.offer_swings(vec![swing.clone(), other]);
    let Mode::Open {
        items, selected, ..
    } = &app.mode
    else {
        panic!("the picker is open at start")
    };
    assert_eq!(*selected, 0);
    let names: Vec<&str> = items.iter().map(|i| i.name(&app.swings)).collect();
    assert_eq!(names[..3], ["Turang 04-03", "Correa 04-03", "fastball"]);
    assert!(
        items[0]
            .detail(&app.swings)
            .starts_with("line 4, 2024-04-03")
    );
    // Its title says what it offers.
    assert!(
        screen(&app).contains(" Open a swing (2) or a preset (/ finds) "),
        "{}",
        screen(&app)
    );
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.preset_name, "Turang 04-03");
    assert_eq!(app.scene, swing.scene);
    key(&mut app, KeyCode::Char('o'));
    let Mode::Open {
        items, selected, ..
    } = &app.mode
    else {
        panic!("the picker is open")
    };
    assert_eq!((items[0].name(&app.swings), *selected), ("Turang 04-03", 0));
    // No swings: nothing opens.
    let mut plain = crate::tui_support::app(80, 24, None);
    plain.offer_swings(Vec::new());
    assert!(matches!(plain.mode, Mode::Normal));
    key(&mut plain, KeyCode::Char('o'));
    assert!(screen(&plain).contains(" Open preset (/ finds) "));
}

/// `/` in the picker finds: each word typed must be in an item's name or
/// description (a Savant file's swings are thousands); Enter keeps the
/// list found for j, k and Enter; Esc gives the whole list back.
#[test]
fn slash_in_the_picker_finds_by_words() {
    let mut app = app(80, 24, None);
    let mut swing = homerun::preset::load("fastball", None).unwrap();
    let swings: Vec<homerun::preset::Preset> = ["Turang 04-03", "Correa 04-03", "Turner 04-05"]
        .iter()
        .map(|name| {
            swing.name = (*name).to_owned();
            swing.description = format!("{name}: measured 90 mph");
            swing.clone()
        })
        .collect();
    app.offer_swings(swings);
    key(&mut app, KeyCode::Char('/'));
    typed(&mut app, "tur 04-0");
    let names = |app: &homerun::tui::app::App| match &app.mode {
        Mode::Open { items, .. } => (items.iter())
            .map(|i| i.name(&app.swings).to_owned())
            .collect::<Vec<_>>(),
        other => panic!("the picker, not {other:?}"),
    };
    assert_eq!(names(&app), ["Turang 04-03", "Turner 04-05"]);
    // Words in any order, any case; none found is an empty list.
    for _ in 0..5 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, " 05 TURN");
    assert_eq!(names(&app), ["Turner 04-05"]);
    typed(&mut app, "x");
    assert!(names(&app).is_empty());
    key(&mut app, KeyCode::Esc);
    assert!(names(&app).len() > 3, "{:?}", names(&app));
    // Enter ends the find; j and Enter then pick in what was found.
    key(&mut app, KeyCode::Char('/'));
    typed(&mut app, "04-03");
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Char('j'));
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.preset_name, "Correa 04-03");
}
