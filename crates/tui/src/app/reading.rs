//! The pop-ups a reader scrolls: the help (keys, then the glossary) and
//! the words in full (`i`); and the pin, kept to read beside the scene.

use super::{App, Mode, Pin};
use crate::keymap::Action;

impl App {
    /// In the help: Tab (or `?`) turns between the keys and the glossary,
    /// j k ↑ ↓ scroll; any other key closes it.
    pub(super) fn help_key(&mut self, action: Option<Action>, glossary: bool, scroll: u16) {
        let (glossary, scroll) = match action {
            Some(Action::NextTab | Action::PreviousTab | Action::Help) => (!glossary, 0),
            Some(Action::Down) => (glossary, scroll.saturating_add(1)),
            Some(Action::Up) => (glossary, scroll.saturating_sub(1)),
            _ => return,
        };
        self.mode = Mode::Help { glossary, scroll };
    }

    /// In the words in full: j k ↑ ↓ scroll; any other key closes them.
    pub(super) fn detail_key(&mut self, action: Option<Action>, scroll: u16) {
        let scroll = match action {
            Some(Action::Down) => scroll.saturating_add(1),
            Some(Action::Up) => scroll.saturating_sub(1),
            _ => return,
        };
        self.mode = Mode::Detail { scroll };
    }

    /// Keeps the scene to compare with (`p`).
    pub(super) fn pin_scene(&mut self) {
        self.pin = Some(Pin {
            scene: self.scene,
            flown: self.flown,
            path: self.path.clone(),
            ground: self.ground.clone(),
        });
        self.message = Some((
            "pinned: the trajectory and readout compare with it (P clears)".into(),
            false,
        ));
    }
}
