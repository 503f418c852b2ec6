//! Saving the inputs as a preset and choosing one to load: the save prompt
//! and the picker's keys.

use std::path::PathBuf;
use std::sync::Arc;

use ratatui::crossterm::event::KeyEvent;
use ratatui_textarea::TextArea;

use super::edit::prefilled;
use super::{App, Find, Mode, Pick, PickItem, Searchable};
use crate::keymap::Action;
use preset::compact::CompactPresets;
use preset::{self, ExplorerSetup, Preset, PresetError, Source, escape_for_terminal};

/// The longest description a preset is saved with: a sentence or two,
/// which the picker and the preset row show.
const MAX_DESCRIPTION: usize = 300;

impl App {
    /// A key in the save prompt: its first step takes the name, its
    /// second (`named`) the description.
    pub(super) fn save_key(
        &mut self,
        key: KeyEvent,
        action: Option<Action>,
        mut text: TextArea<'static>,
        (error, overwrite): (Option<String>, Option<String>),
        named: Option<String>,
    ) {
        match (action, named) {
            (Some(Action::Close), _) => {}
            (Some(Action::Confirm), None) => self.confirm_name(text, overwrite),
            (Some(Action::Confirm), Some(name)) => self.confirm_description(text, name),
            (_, named) => {
                text.input(key);
                self.mode = Mode::Save {
                    text,
                    error,
                    overwrite,
                    named,
                };
            }
        }
    }

    /// Enter on the name: asked about if it has spaces, or would hide a
    /// bundled preset or overwrite one of the user's; else on to the
    /// description.
    fn confirm_name(&mut self, text: TextArea<'static>, overwrite: Option<String>) {
        let ask = |text, error: String, overwrite| Mode::Save {
            text,
            error: Some(error),
            overwrite,
            named: None,
        };
        // A name with spaces is asked about, never changed silently:
        // "class demo" offers class-demo in the box, which Enter then
        // saves (or the user edits it).
        let typed = text.lines().join("");
        let name = typed.split_whitespace().collect::<Vec<_>>().join("-");
        if name != typed.trim() {
            let error = format!(
                "names take no spaces: Enter takes `{}` as `{name}` (or edit it; Esc cancels)",
                typed.trim()
            );
            self.mode = ask(prefilled(name, &self.theme), error, overwrite);
            return;
        }
        // A name that cannot be saved is said now, not after the description.
        let dir = self.presets_dir.as_deref();
        if let Err(e) = dir
            .ok_or_else(|| preset::NO_FOLDER.to_owned())
            .and_then(|dir| preset::check_save(&name, dir, true).map_err(|e| e.to_string()))
        {
            self.mode = ask(text, format!("not saved: {e}"), overwrite);
            return;
        }
        // Taking a bundled name hides the bundled preset from
        // `--preset NAME` and from `o`: only when asked twice.
        // Overwriting one of the user's own: only when asked twice too.
        let asked = overwrite.as_deref() == Some(name.as_str());
        let question = if preset::user_file(&name, dir).is_some() {
            Some(format!(
                "`{name}` is one of your presets: Enter again to overwrite it"
            ))
        } else if preset::is_bundled(&name) {
            Some(format!(
                "`{name}` is bundled: your file would hide it (--preset {name} and o load yours); Enter again to save anyway"
            ))
        } else {
            None
        };
        if let Some(question) = question.filter(|_| !asked) {
            self.mode = ask(text, question, Some(name));
            return;
        }
        self.mode = Mode::Save {
            text: TextArea::default(),
            error: None,
            overwrite: None,
            named: Some(name),
        };
    }

    /// Enter on the description (empty: [`App::default_description`]):
    /// the preset is saved, or the prompt says why not.
    fn confirm_description(&mut self, text: TextArea<'static>, name: String) {
        let typed = text.lines().join(" ");
        let description = match typed.trim() {
            "" => self.default_description(),
            typed => typed.to_owned(),
        };
        if description.chars().count() > MAX_DESCRIPTION {
            self.mode = Mode::Save {
                text,
                error: Some(format!(
                    "a description is at most {MAX_DESCRIPTION} characters; this is {}",
                    description.chars().count()
                )),
                overwrite: None,
                named: Some(name),
            };
            return;
        }
        match self.save(&name, &description) {
            Ok(path) => {
                // The preset row's hint now describes the one saved.
                self.description = description;
                self.preset_name = name;
                self.message = Some((format!("saved {}", path.display()), false));
            }
            Err(error) => {
                self.mode = Mode::Save {
                    text,
                    error: Some(error),
                    overwrite: None,
                    named: Some(name),
                }
            }
        }
    }

    /// What a preset saved with no description of the user's says of
    /// itself: where it came from and the park it was set in.
    pub fn default_description(&self) -> String {
        let park = match (self.chosen_park(), self.in_park_air()) {
            (Some(park), true) => format!(" at {} in its air", escape_for_terminal(&park.code)),
            (Some(park), false) => format!(" at {}", escape_for_terminal(&park.code)),
            (None, _) => String::new(),
        };
        format!("{} as set in the explorer{park}", self.preset_name)
    }

    /// The explorer's set-up around the scene, as a preset keeps it.
    pub fn setup(&self) -> ExplorerSetup {
        let park = self.chosen_park().map(|p| p.code.clone());
        ExplorerSetup {
            park_air: park.is_some() && self.in_park_air(),
            park,
            units: self.units,
        }
    }

    fn save(&self, name: &str, description: &str) -> Result<PathBuf, String> {
        let dir = self.presets_dir.as_deref().ok_or(preset::NO_FOLDER)?;
        let preset = Preset {
            name: name.to_owned(),
            description: description.to_owned(),
            scene: self.scene,
            fence: self.fence,
            explorer: Some(self.setup()),
            source: Source::Bundled,
        };
        preset
            .save(dir, true)
            .map_err(|e| format!("not saved: {e}"))
    }

    /// Offers `swings` (a Savant export's, solved) at the top of the
    /// picker, and opens it on the first of them.
    pub fn offer_swings(&mut self, swings: Vec<Preset>) {
        self.offer_compact_swings(swings.into_iter().collect());
    }

    /// [`App::offer_swings`], for swings held compactly (`tui --savant`).
    pub fn offer_compact_swings(&mut self, swings: CompactPresets) {
        if swings.is_empty() {
            return;
        }
        self.swings = Arc::new(Searchable::swings(swings));
        self.open_picker();
        if let Mode::Open { selected, .. } = &mut self.mode {
            *selected = 0;
        }
    }

    pub(super) fn open_picker(&mut self) {
        let items = self.pick_items();
        let selected = items
            .iter()
            .position(|i| i.name(&self.swings) == self.preset_name)
            .unwrap_or(0);
        self.mode = Mode::Open {
            items,
            selected,
            error: None,
            find: None,
        };
    }

    /// Everything the picker offers: the swings, then the presets (a
    /// swing by its index: a list of thousands of swings copies none).
    fn pick_items(&self) -> Vec<Pick> {
        let mut items: Vec<Pick> = self.swings.picks().collect();
        items.extend(self.preset_items().into_iter().map(Pick::Preset));
        items
    }

    /// The presets, as the picker offers them.
    fn preset_items(&self) -> Vec<Arc<PickItem>> {
        preset::list(self.presets_dir.as_deref())
            .into_iter()
            .map(|entry| match entry {
                Ok(p) => PickItem {
                    name: p.name.clone(),
                    detail: match &p.source {
                        Source::Bundled
                            if preset::user_file(&p.name, self.presets_dir.as_deref())
                                .is_some() =>
                        {
                            format!("{} (bundled; hidden by yours of that name)", p.description)
                        }
                        Source::Bundled => format!("{} (bundled)", p.description),
                        Source::File(_) if preset::is_bundled(&p.name) => {
                            format!("{} (yours; hides the bundled one)", p.description)
                        }
                        Source::File(_) => p.description.clone(),
                    },
                    preset: Some(p),
                },
                Err(e) => PickItem {
                    name: broken_name(&e),
                    detail: format!("broken: {e}"),
                    preset: None,
                },
            })
            .map(Arc::new)
            .collect()
    }

    pub(super) fn open_key(
        &mut self,
        (key, action): (KeyEvent, Option<Action>),
        mut items: Vec<Pick>,
        (selected, find): (usize, Option<Find>),
        error: Option<String>,
    ) {
        use ratatui::crossterm::event::{KeyCode, KeyModifiers};
        // Typing a find: letters go to it, the list follows at each key.
        if let Some(mut find) = find {
            match key.code {
                KeyCode::Esc => return self.open_picker(),
                KeyCode::Enter | KeyCode::Down | KeyCode::Up => {
                    self.mode = Mode::Open {
                        items,
                        selected: 0,
                        error,
                        find: None,
                    };
                    return;
                }
                KeyCode::Backspace => find.pop(&mut items),
                KeyCode::Char(c) if !key.modifiers.contains(KeyModifiers::CONTROL) => {
                    find.push(c, &mut items)
                }
                _ => {}
            }
            self.mode = Mode::Open {
                items,
                selected: 0,
                error: None,
                find: Some(find),
            };
            return;
        }
        if key.code == KeyCode::Char('/') {
            let presets = Searchable::presets(self.preset_items());
            let (find, items) = Find::new(Arc::clone(&self.swings), presets);
            self.mode = Mode::Open {
                items,
                selected: 0,
                error: None,
                find: Some(find),
            };
            return;
        }
        let last = items.len().saturating_sub(1);
        let (selected, error) = match action {
            Some(Action::Close | Action::Quit) => return,
            Some(Action::Down) => ((selected + 1).min(last), None),
            Some(Action::Up) => (selected.saturating_sub(1), None),
            // g and G: the top and the bottom of the list, as in the inputs.
            Some(Action::First) => (0, None),
            Some(Action::Last) => (last, None),
            Some(Action::Confirm) => match items.get(selected).and_then(|i| i.preset(&self.swings))
            {
                Some(preset) => {
                    self.load(preset);
                    return;
                }
                None => (
                    selected,
                    Some(
                        items
                            .get(selected)
                            .map_or(String::new(), |i| i.detail(&self.swings).to_owned()),
                    ),
                ),
            },
            _ => (selected, error),
        };
        self.mode = Mode::Open {
            items,
            selected,
            error,
            find: None,
        };
    }
}

/// A short name for a broken preset: its file's stem, if the error has one.
fn broken_name(error: &PresetError) -> String {
    let text = error.to_string();
    let path = text.split(':').next().unwrap_or("?");
    std::path::Path::new(path)
        .file_stem()
        .map_or_else(|| path.to_owned(), |s| s.to_string_lossy().into_owned())
}
