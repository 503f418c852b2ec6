//! Changing one input: a nudge by its step (the same nudge the Δ column
//! measures), or a typed value in the unit shown, refused with the
//! reason shown under the list and the old value kept.

use ratatui::crossterm::event::KeyEvent;
use ratatui_textarea::TextArea;

use super::*;
use crate::theme::Theme;

impl App {
    /// Moves the selected input by `scale` of its step, if the result is valid.
    pub(super) fn nudge(&mut self, scale: f64) {
        match self.fields[self.selected] {
            // The next or previous preset that loads, as the picker lists them.
            Field::Preset => {
                let presets: Vec<_> = preset::list(self.presets_dir.as_deref())
                    .into_iter()
                    .filter_map(Result::ok)
                    .collect();
                if presets.is_empty() {
                    return;
                }
                let at = presets.iter().position(|p| p.name == self.preset_name);
                let n = presets.len();
                let next = match at {
                    Some(i) if scale > 0.0 => (i + 1) % n,
                    Some(i) => (i + n - 1) % n,
                    None => 0,
                };
                self.load(presets[next].clone());
            }
            Field::Drag => {
                self.scene
                    .choose_drag(cycle(&DragModel::ALL, self.scene.drag, scale));
                self.inputs_changed = true;
            }
            Field::Lift => {
                self.scene
                    .choose_lift(cycle(&LiftModel::ALL, self.scene.lift, scale));
                self.inputs_changed = true;
            }
            Field::Hand => {
                self.scene.bat.hand = cycle(&Hand::ALL, self.scene.bat.hand, scale);
                self.inputs_changed = true;
            }
            // The same nudge as the sensitivity column's, so that its number
            // says what this key does.
            Field::Key(k) => {
                match sensitivity::nudge_in(&self.scene, input_key(k), scale, self.units) {
                    Ok(scene) => {
                        self.scene = scene;
                        self.inputs_changed = true;
                        self.message = None;
                    }
                    Err(error) => self.message = Some((error_text(&error, self.units), true)),
                }
            }
        }
    }

    pub(super) fn start_edit(&mut self) {
        let field = self.fields[self.selected];
        let current = match field {
            Field::Preset => return self.open_picker(),
            Field::Drag => self.scene.drag.name().to_owned(),
            Field::Lift => self.scene.lift.name().to_owned(),
            Field::Hand => self.scene.bat.hand.name().to_owned(),
            Field::Key(k) => shown_value(input_key(k), (input_key(k).get)(&self.scene), self.units),
        };
        self.mode = Mode::Edit {
            field,
            text: prefilled(current.clone(), &self.theme),
            error: None,
            initial: current,
        };
    }

    pub(super) fn edit_key(
        &mut self,
        key: KeyEvent,
        action: Option<Action>,
        field: Field,
        mut text: TextArea<'static>,
        (error, initial): (Option<String>, String),
    ) {
        match action {
            Some(Action::Close) => {}
            // The value as it was, not as rounded for show.
            Some(Action::Confirm) if text.lines().join("") == initial => {}
            Some(Action::Confirm) => {
                let typed = text.lines().join("");
                let mut scene = self.scene;
                let set = match field {
                    // In the unit shown; the scene stays SI.
                    Field::Key(k) => {
                        let key = input_key(k);
                        read_value(key, &typed, self.units).map(|v| (key.set)(&mut scene, v))
                    }
                    Field::Drag => scene.set_text(DRAG_KEY, &typed),
                    Field::Lift => scene.set_text(LIFT_KEY, &typed),
                    Field::Hand => scene.set_text(HAND_KEY, &typed),
                    Field::Preset => return,
                };
                match set.and_then(|()| scene.validate()) {
                    Ok(()) => {
                        self.scene = scene;
                        self.inputs_changed = true;
                        self.message = None;
                    }
                    // The box closes, so that the next keys act on the
                    // panes again (an open box swallowed them); the
                    // reason stays under the list until the next key.
                    Err(e) => self.message = Some((error_text(&e, self.units), true)),
                }
            }
            _ => {
                text.input(key);
                self.mode = Mode::Edit {
                    field,
                    text,
                    error,
                    initial,
                };
            }
        }
    }
}

/// The choice `by` places after `current` in `all`, going round.
pub(super) fn cycle<T: Copy + PartialEq>(all: &[T], current: T, by: f64) -> T {
    let k = all.iter().position(|c| *c == current).unwrap_or(0);
    let n = all.len() as isize;
    all[(k as isize + by.signum() as isize).rem_euclid(n) as usize]
}

/// A one-line text field holding `value`, all of it selected: typing
/// replaces it (as in a form), while ← → or End keep and edit it. The
/// selection is reversed, as the selected row is (the crate's light blue
/// is a colour, and hides light text).
pub(super) fn prefilled(value: String, theme: &Theme) -> TextArea<'static> {
    let mut text = TextArea::new(vec![value]);
    text.set_selection_style(theme.selected);
    text.select_all();
    text
}
