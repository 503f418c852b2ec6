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
use preset::{self, Preset, PresetError, Source};

impl App {
    pub(super) fn save_key(
        &mut self,
        key: KeyEvent,
        action: Option<Action>,
        mut text: TextArea<'static>,
        error: Option<String>,
        overwrite: Option<String>,
    ) {
        match action {
            Some(Action::Close) => {}
            Some(Action::Confirm) => {
                // A name with spaces is asked about, never changed silently:
                // "class demo" offers class-demo in the box, which Enter then
                // saves (or the user edits it).
                let typed = text.lines().join("");
                let name = typed.split_whitespace().collect::<Vec<_>>().join("-");
                if name != typed.trim() {
                    self.mode = Mode::Save {
                        text: prefilled(name.clone(), &self.theme),
                        error: Some(format!(
                            "names take no spaces: Enter saves `{}` as `{name}` (or edit it; Esc cancels)",
                            typed.trim()
                        )),
                        overwrite,
                    };
                    return;
                }
                // Taking a bundled name hides the bundled preset from
                // `--preset NAME` and from `o`: only when asked twice.
                // Overwriting one of the user's own: only when asked twice too.
                let asked = overwrite.as_deref() == Some(name.as_str());
                let question = if preset::user_file(&name, self.presets_dir.as_deref()).is_some() {
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
                    self.mode = Mode::Save {
                        text,
                        error: Some(question),
                        overwrite: Some(name),
                    };
                    return;
                }
                match self.save(&name) {
                    Ok(path) => {
                        // The preset row's hint now describes the one saved.
                        self.description = self.saved_description();
                        self.preset_name = name;
                        self.message = Some((format!("saved {}", path.display()), false));
                    }
                    Err(e) => {
                        self.mode = Mode::Save {
                            text,
                            error: Some(e),
                            overwrite,
                        }
                    }
                }
            }
            _ => {
                text.input(key);
                self.mode = Mode::Save {
                    text,
                    error,
                    overwrite,
                };
            }
        }
    }

    /// What a preset saved now says of itself.
    fn saved_description(&self) -> String {
        format!("saved from the explorer (from {})", self.preset_name)
    }

    fn save(&self, name: &str) -> Result<PathBuf, String> {
        let dir = self.presets_dir.as_deref().ok_or(preset::NO_FOLDER)?;
        let preset = Preset {
            name: name.to_owned(),
            description: self.saved_description(),
            scene: self.scene,
            fence: self.fence,
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
