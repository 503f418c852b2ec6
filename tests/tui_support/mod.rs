//! Drives the explorer headlessly: key events in, the worker's job run
//! synchronously (so results never race the snapshot), a TestBackend out.
#![allow(dead_code)]

use std::path::PathBuf;

use homerun::preset;
use homerun::tui::app::App;
use homerun::tui::margin::run_margin_job;
use homerun::tui::theme::ColorMode;
use homerun::tui::view;
use homerun::tui::worker::{run_figure_job, run_job};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;

pub fn app(width: u16, height: u16, presets_dir: Option<PathBuf>) -> App {
    let fastball = preset::load("fastball", None).unwrap();
    App::new(
        fastball,
        presets_dir,
        ColorMode::Indexed,
        Rect::new(0, 0, width, height),
    )
}

/// The explorer on the fastball with `theme`.
pub fn themed(theme: homerun::tui::theme::Theme, width: u16, height: u16) -> App {
    App::new(
        preset::load("fastball", None).unwrap(),
        None,
        theme,
        Rect::new(0, 0, width, height),
    )
}

pub fn key(app: &mut App, code: KeyCode) {
    key_with(app, code, KeyModifiers::NONE);
}

pub fn key_with(app: &mut App, code: KeyCode, modifiers: KeyModifiers) {
    app.handle(&Event::Key(KeyEvent::new(code, modifiers)));
    app.flush();
}

pub fn typed(app: &mut App, text: &str) {
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
}

/// Runs the pending background job to the end, here, and applies its results.
pub fn settle(app: &mut App) {
    app.flush();
    while let Some(job) = app.take_job() {
        let mut reports = Vec::new();
        run_job(&job, &|| false, &mut |r| reports.push(r));
        for report in reports {
            app.apply(report);
        }
    }
    while let Some(job) = app.take_margin_job() {
        let mut reports = Vec::new();
        run_margin_job(&job, &|| false, &mut |r| reports.push(r));
        for report in reports {
            app.apply_margin(report);
        }
    }
    while let Some(job) = app.take_figure_job() {
        let mut reports = Vec::new();
        run_figure_job(&job, &|| false, &mut |r| reports.push(r));
        for report in reports {
            app.apply_figure(report);
        }
    }
}

/// Selects the input row whose key is `name`.
pub fn select(app: &mut App, name: &str) {
    use homerun::tui::app::{Field, input_key};
    app.selected = app
        .fields
        .iter()
        .position(|f| matches!(f, Field::Key(k) if input_key(*k).name == name))
        .unwrap();
}

pub fn screen(app: &App) -> String {
    let mut terminal = Terminal::new(TestBackend::new(app.size.width, app.size.height)).unwrap();
    terminal.draw(|frame| view::draw(frame, app)).unwrap();
    // A non-breaking space (a number glued to its unit) reads as a space.
    terminal.backend().to_string().replace('\u{a0}', " ")
}

/// Types `text` into the input `name` (Enter, the text, Enter) and runs the
/// background work to the end.
pub fn set_and_settle(app: &mut App, name: &str, text: &str) {
    settle(app);
    select(app, name);
    key(app, KeyCode::Enter);
    typed(app, text);
    key(app, KeyCode::Enter);
    settle(app);
}

/// The explorer opened on the bundled preset `name`.
pub fn app_on(name: &str, width: u16, height: u16, presets_dir: Option<PathBuf>) -> App {
    App::new(
        preset::load(name, None).unwrap(),
        presets_dir,
        ColorMode::Indexed,
        Rect::new(0, 0, width, height),
    )
}

/// The screen as drawn, cell by cell.
pub fn buffer(app: &App) -> ratatui::buffer::Buffer {
    let mut terminal = Terminal::new(TestBackend::new(app.size.width, app.size.height)).unwrap();
    terminal.draw(|frame| view::draw(frame, app)).unwrap();
    terminal.backend().buffer().clone()
}

/// The text of each row of `area`, inside its borders, trimmed.
pub fn rows_in(app: &App, area: Rect) -> Vec<String> {
    let buffer = buffer(app);
    (area.y + 1..area.bottom().saturating_sub(1))
        .map(|y| {
            (area.x + 1..area.right().saturating_sub(1))
                .map(|x| buffer[(x, y)].symbol())
                .collect::<String>()
                .trim()
                .to_owned()
        })
        .collect()
}

/// `m` until the chosen park is `code`.
pub fn pick(app: &mut App, code: &str) {
    for _ in 0..=homerun::model::park::bundled().len() {
        if app.chosen_park().is_some_and(|p| p.code == code) {
            return;
        }
        key(app, KeyCode::Char('m'));
    }
    panic!("no park {code}");
}
