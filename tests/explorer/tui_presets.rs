//! Issue 36, item 7: a preset saved from the explorer keeps the set-up
//! (the park, its air, the units) and a description the user writes; one
//! without that set-up loads as before; `fly` flies the same ball.

use crate::common::homerun;
use crate::tui_support::*;
use homerun::preset::{self, ExplorerSetup};
use homerun::tui::app::Mode;
use homerun::units::UnitSystem;
use ratatui::crossterm::event::KeyCode;

/// Chooses the park `code` through the park list (`/`, its code, Enter).
fn choose_park(app: &mut homerun::tui::app::App, code: &str) {
    key(app, KeyCode::Char('/'));
    typed(app, code);
    key(app, KeyCode::Enter);
    settle(app);
    assert_eq!(app.chosen_park().map(|p| p.code.as_str()), Some(code));
}

/// Opens the save prompt and types `name` over the name it offers.
fn name_it(app: &mut homerun::tui::app::App, name: &str) {
    key(app, KeyCode::Char('s'));
    let Mode::Save { text, .. } = &app.mode else {
        panic!("the save prompt is open")
    };
    for _ in 0..text.lines().join("").chars().count() {
        key(app, KeyCode::Backspace);
    }
    typed(app, name);
    key(app, KeyCode::Enter);
}

#[test]
fn a_saved_preset_brings_back_its_park_air_units_and_description() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    choose_park(&mut app, "COL");
    assert!(app.in_park_air(), "a park brings its air");
    key(&mut app, KeyCode::Char('u'));
    settle(&mut app);
    let shown_range = app.flown.flight.range;
    let coors_air = app.scene.environment.air();
    name_it(&mut app, "coors-demo");
    typed(&mut app, "a fly ball at Coors, in feet");
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal), "{:?}", app.mode);

    let saved = preset::load("coors-demo", Some(dir.path())).unwrap();
    assert_eq!(saved.description, "a fly ball at Coors, in feet");
    assert_eq!(
        saved.explorer,
        Some(ExplorerSetup {
            park: Some("COL".into()),
            park_air: true,
            units: UnitSystem::Imperial,
        })
    );
    assert_eq!(saved.scene, app.scene);

    // A fresh explorer, in SI at no park, loads it as it was left.
    let mut fresh = self::app(80, 24, Some(dir.path().to_owned()));
    assert_eq!(fresh.units, UnitSystem::Si);
    fresh.load(saved.clone());
    settle(&mut fresh);
    assert_eq!(fresh.chosen_park().map(|p| p.code.as_str()), Some("COL"));
    assert!(fresh.in_park_air());
    assert_eq!(fresh.units, UnitSystem::Imperial);
    assert_eq!(fresh.scene.environment.air(), coors_air);
    assert_eq!(fresh.flown.flight.range, shown_range);
    assert_eq!(fresh.description, "a fly ball at Coors, in feet");
    let (message, error) = fresh.message.clone().unwrap();
    assert!(!error, "{message}");
    assert_eq!(
        message,
        "loaded coors-demo at COL in its air, in imperial units"
    );
    // `a` leaves the park's air for the standard air at sea level.
    key(&mut fresh, KeyCode::Char('a'));
    assert!(!fresh.in_park_air());
    let sea_level = homerun::model::scene::Scene::default().environment.air();
    assert_eq!(fresh.scene.environment.air(), sea_level);

    // Opened from the start, the explorer is as it was left too.
    let opened = app_on_preset(saved.clone(), dir.path());
    assert_eq!(opened.chosen_park().map(|p| p.code.as_str()), Some("COL"));
    assert_eq!(opened.units, UnitSystem::Imperial);

    // `fly` takes the file, and flies the ball the explorer showed (in
    // the park's air its [environment] holds).
    let out = homerun(dir.path(), &["fly", "--preset", "coors-demo"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains(&format!("range {shown_range:.3} m")),
        "{shown_range}: {text}"
    );
}

fn app_on_preset(preset: preset::Preset, dir: &std::path::Path) -> homerun::tui::app::App {
    homerun::tui::app::App::new(
        preset,
        Some(dir.to_owned()),
        homerun::tui::theme::ColorMode::Indexed,
        ratatui::layout::Rect::new(0, 0, 80, 24),
    )
}

#[test]
fn a_preset_without_the_setup_leaves_park_and_units_as_they_are() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("old.toml"),
        "description = \"from an older homerun\"\n[bat]\nspeed = 33\n",
    )
    .unwrap();
    let old = preset::load("old", Some(dir.path())).unwrap();
    assert_eq!(old.explorer, None);
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    choose_park(&mut app, "BOS");
    key(&mut app, KeyCode::Char('u'));
    app.load(old);
    settle(&mut app);
    assert_eq!(app.scene.bat.speed, 33.0);
    assert_eq!(app.description, "from an older homerun");
    assert_eq!(app.chosen_park().map(|p| p.code.as_str()), Some("BOS"));
    assert_eq!(app.units, UnitSystem::Imperial);
    // The preset brings its own air: the park's is left.
    assert!(!app.in_park_air());
    assert_eq!(app.message.clone().unwrap().0, "loaded old");
}

#[test]
fn an_empty_description_saves_the_default_one() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    choose_park(&mut app, "BOS");
    key(&mut app, KeyCode::Char('a'));
    name_it(&mut app, "fenway");
    key(&mut app, KeyCode::Enter);
    let saved = preset::load("fenway", Some(dir.path())).unwrap();
    assert_eq!(saved.description, "fastball as set in the explorer at BOS");
    let setup = saved.explorer.unwrap();
    assert_eq!(setup.park.as_deref(), Some("BOS"));
    assert!(!setup.park_air, "a: out of the park's air");
}

#[test]
fn save_prompt_80x24() {
    let dir = tempfile::tempdir().unwrap();
    // The folder is not shown at the second step, so a temporary one does.
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    settle(&mut app);
    choose_park(&mut app, "COL");
    name_it(&mut app, "coors");
    typed(&mut app, "a class at Coors");
    let shown = screen(&app);
    assert!(shown.contains("2/2 what `coors` is for"), "{shown}");
    insta::assert_snapshot!("save_prompt_80x24", shown);
}
