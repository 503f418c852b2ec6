//! What the explorer does with keys, the mouse and background results:
//! keys and inputs (keys.rs), the mouse on the panes (mouse.rs), and what
//! the worker computes for each kind of scene (work.rs). One test binary.

#[path = "../common/mod.rs"]
mod common;
mod tui_fit;
mod tui_output;
mod tui_parks;
mod tui_polish;
mod tui_presets;
mod tui_pty;
mod tui_render;
mod tui_signals;
mod tui_teach;
mod tui_words;

#[path = "../tui_support/mod.rs"]
mod tui_support;

mod keys;
mod mouse;
mod picker_find;
mod work;

use homerun::tui::app::{input_count, input_key};
use ratatui::crossterm::event::{Event, KeyModifiers, MouseEvent, MouseEventKind};

pub(crate) fn mouse(app: &mut homerun::tui::app::App, kind: MouseEventKind, column: u16, row: u16) {
    app.handle(&Event::Mouse(MouseEvent {
        kind,
        column,
        row,
        modifiers: KeyModifiers::NONE,
    }));
    app.flush();
}

/// The index of input `name`, as the sensitivity columns count them.
pub(crate) fn input_index(name: &str) -> usize {
    (0..input_count())
        .find(|&k| input_key(k).name == name)
        .unwrap()
}
