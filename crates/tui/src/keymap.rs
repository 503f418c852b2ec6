//! Every key of the explorer, once: the action it asks for and the line of
//! help that explains it. The app looks keys up here ([`action`]) and the
//! help overlay lists this table ([`help`]).

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::layout::Tab;
use Action::*;
use KeyCode::{BackTab, End, Enter, Esc, Home, Left, Right};

/// How far a nudge moves an input, in steps of its key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    Tenth,
    One,
    Ten,
}

impl Step {
    pub fn factor(self) -> f64 {
        match self {
            Step::Tenth => 0.1,
            Step::One => 1.0,
            Step::Ten => 10.0,
        }
    }
}

/// What a key asks for. All of them act on the panes; a prompt reads only
/// `Confirm` and `Close` (every other key is typed), the preset picker only
/// `Down`, `Up`, `Confirm`, `Close` and `Quit` (which closes it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// The next input (or preset).
    Down,
    /// The previous input (or preset).
    Up,
    First,
    Last,
    /// The input up by a step.
    Raise(Step),
    /// The input down by a step.
    Lower(Step),
    /// Type a value; in a prompt, accept it.
    Confirm,
    /// Type a value.
    Edit,
    /// Close a pop-up (with the panes: only clear the message).
    Close,
    ToOptimum,
    Units,
    /// Switch between the swing scene and the batted-ball scene.
    Scene,
    /// Keep the current scene to compare with.
    Pin,
    Unpin,
    /// The next / previous park: its fence in the field and the side view,
    /// its verdict in the readout.
    NextPark,
    PreviousPark,
    /// The park list: filtered as a code, name or city is typed.
    FindPark,
    /// The heatmap: the range, or the margin over the park's wall.
    MarginMap,
    /// The scene in the park's own air, or back to the air before.
    ParkAir,
    NextTab,
    PreviousTab,
    ShowTab(Tab),
    NextStop,
    PreviousStop,
    NextFigure,
    PreviousFigure,
    /// The figure's next panel, where not all fit (Figs. 8–12 at 80×24).
    NextPanel,
    Save,
    Open,
    /// Write the chart in view as SVG.
    Export,
    /// The words cut short on screen, whole, in a pane that scrolls.
    Detail,
    Help,
    Quit,
    /// Ctrl-C: quits from anywhere, even a prompt.
    Interrupt,
}

/// A key and what it does. A binding with modifiers wants at least those
/// held; one without takes the key with any (so Ctrl-j still moves down).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Binding {
    pub code: KeyCode,
    pub modifiers: KeyModifiers,
    pub action: Action,
    /// Whether the help names it; the others are aliases (Home for `g`,
    /// `>` for `.`, Alt+l for Alt+→).
    pub shown: bool,
}

impl Binding {
    const fn with(self, modifiers: KeyModifiers) -> Binding {
        Binding { modifiers, ..self }
    }

    const fn alias(self) -> Binding {
        Binding {
            shown: false,
            ..self
        }
    }

    /// How the help writes the key: `j`, `←`, `Enter`, `Shift+←`, `Ctrl-C`.
    pub fn name(&self) -> String {
        self.prefix() + &self.glyph()
    }

    fn prefix(&self) -> String {
        let mut prefix = String::new();
        for (modifier, name) in [
            (KeyModifiers::CONTROL, "Ctrl-"),
            (KeyModifiers::ALT, "Alt+"),
            (KeyModifiers::SHIFT, "Shift+"),
        ] {
            if self.modifiers.contains(modifier) {
                prefix.push_str(name);
            }
        }
        prefix
    }

    fn glyph(&self) -> String {
        match self.code {
            // Control keys are written in capitals: Ctrl-C.
            KeyCode::Char(c) if self.modifiers.contains(KeyModifiers::CONTROL) => {
                c.to_uppercase().to_string()
            }
            KeyCode::Char(c) => c.to_string(),
            KeyCode::Up => "↑".into(),
            KeyCode::Down => "↓".into(),
            KeyCode::Left => "←".into(),
            KeyCode::Right => "→".into(),
            // Named here, not by crossterm, which writes Enter as "Return"
            // on macOS.
            KeyCode::Enter => "Enter".into(),
            KeyCode::Tab => "Tab".into(),
            KeyCode::BackTab => "Shift+Tab".into(),
            KeyCode::Esc => "Esc".into(),
            KeyCode::Home => "Home".into(),
            KeyCode::End => "End".into(),
            code => code.to_string(),
        }
    }
}

const fn key(code: KeyCode, action: Action) -> Binding {
    Binding {
        code,
        modifiers: KeyModifiers::NONE,
        action,
        shown: true,
    }
}

const fn ch(c: char, action: Action) -> Binding {
    key(KeyCode::Char(c), action)
}

/// A nudge by `step`: its own keys (down, up), then ← → with `held`, and
/// h l with `held` (unnamed).
const fn nudges([down, up]: [char; 2], held: KeyModifiers, step: Step) -> [Binding; 6] {
    [
        ch(down, Lower(step)),
        ch(up, Raise(step)),
        key(Left, Lower(step)).with(held),
        key(Right, Raise(step)).with(held),
        ch('h', Lower(step)).with(held).alias(),
        ch('l', Raise(step)).with(held).alias(),
    ]
}

/// One line of the help: its keys, in the order it names them, and what
/// they do.
#[derive(Debug)]
pub struct Row {
    pub keys: &'static [Binding],
    pub what: &'static str,
}

const fn row(keys: &'static [Binding], what: &'static str) -> Row {
    Row { keys, what }
}

const SHIFT: KeyModifiers = KeyModifiers::SHIFT;
const ALT: KeyModifiers = KeyModifiers::ALT;

/// Every key, in the order the help shows them.
pub const KEYMAP: &[Row] = &[
    row(
        &[
            ch('j', Down),
            ch('k', Up),
            key(KeyCode::Up, Up),
            key(KeyCode::Down, Down),
        ],
        "move between inputs",
    ),
    row(
        &[
            ch('h', Lower(Step::One)),
            ch('l', Raise(Step::One)),
            key(Left, Lower(Step::One)),
            key(Right, Raise(Step::One)),
        ],
        "nudge by a step (Δ beside it: the range gained)",
    ),
    row(&nudges(['H', 'L'], SHIFT, Step::Ten), "nudge ×10"),
    row(&nudges(['[', ']'], ALT, Step::Tenth), "nudge ×0.1"),
    row(
        &[key(Enter, Confirm), ch('e', Edit)],
        "type a value (Enter accepts, Esc cancels)",
    ),
    row(
        &[
            ch('g', First),
            ch('G', Last),
            key(Home, First).alias(),
            key(End, Last).alias(),
        ],
        "first / last input",
    ),
    row(
        &[ch('b', Scene)],
        "swing scene / batted-ball scene (the same launch)",
    ),
    row(
        &[ch('r', ToOptimum)],
        "move the swing (E, ψ) to the optimum",
    ),
    row(
        &[ch('u', Units)],
        "all units: SI / baseball (mph, ft, in, rpm…)",
    ),
    row(
        &[ch('p', Pin), ch('P', Unpin)],
        "pin the scene to compare with / clear the pin",
    ),
    row(
        &[
            ch('m', NextPark),
            ch('M', PreviousPark),
            ch('/', FindPark),
            ch('c', MarginMap),
            ch('a', ParkAir),
        ],
        "park: next / previous / find / margin map / air",
    ),
    row(
        &[
            key(KeyCode::Tab, NextTab),
            key(BackTab, PreviousTab).alias(),
            ch('1', ShowTab(Tab::Flight)),
            ch('2', ShowTab(Tab::Surface)),
            ch('3', ShowTab(Tab::Impact)),
            ch('4', ShowTab(Tab::Figures)),
            ch('5', ShowTab(Tab::Field)),
        ],
        "flight / surface / impact / figures / field",
    ),
    row(
        &[
            ch('f', NextFigure),
            ch('F', PreviousFigure),
            ch('v', NextPanel),
        ],
        "next / prev. figure (3–6, 8–14) / next panel",
    ),
    row(
        &[
            ch(',', PreviousStop),
            ch('.', NextStop),
            ch('<', PreviousStop).alias(),
            ch('>', NextStop).alias(),
        ],
        "step the impact through its phases",
    ),
    row(
        &[ch('s', Save), ch('o', Open)],
        "save inputs and set-up as a preset / open one",
    ),
    row(
        &[ch('x', Export)],
        "write the chart in view to ./homerun-*-N.svg",
    ),
    row(
        &[ch('i', Detail)],
        "the input, message, figure notes in full",
    ),
    row(&[key(Esc, Close)], "close a pop-up, clear the message"),
    row(&[ch('?', Help)], "this help"),
    row(
        &[
            ch('q', Quit),
            ch('c', Interrupt).with(KeyModifiers::CONTROL),
        ],
        "quit",
    ),
];

/// What the mouse does, for the help (the app handles it in `app/mouse.rs`).
pub const MOUSE: &[(&str, &str)] = &[
    (
        "click",
        "tab · surface: (E, ψ) · field: aim · input: select",
    ),
    ("wheel", "over an input: nudge it (up raises)"),
    (
        "Shift-drag",
        "select text (mouse capture is on; in tmux too)",
    ),
];

fn bindings() -> impl Iterator<Item = &'static Binding> {
    KEYMAP.iter().flat_map(|row| row.keys)
}

/// What `key` asks for, if anything: of the bindings it satisfies, the one
/// that wants the most modifiers (Shift+→ over →), the first on a tie
/// (Shift over Alt when both are held).
pub fn action(key: &KeyEvent) -> Option<Action> {
    let wanted = |b: &Binding| b.modifiers.bits().count_ones();
    bindings()
        .filter(|b| b.code == key.code && key.modifiers.contains(b.modifiers))
        .fold(None, |best: Option<&Binding>, b| match best {
            Some(best) if wanted(best) >= wanted(b) => Some(best),
            _ => Some(b),
        })
        .map(|b| b.action)
}

/// A row's keys as the help writes them: single characters a space apart,
/// anything longer set off by two; keys sharing a modifier share its name
/// (`H L  Shift+← →`, `Tab  1 2 3`, `q  Ctrl-C`).
pub fn keys_text(row: &Row) -> String {
    let mut words: Vec<(String, String)> = Vec::new();
    for b in row.keys.iter().filter(|b| b.shown) {
        match words.last_mut() {
            Some((prefix, glyphs)) if !prefix.is_empty() && *prefix == b.prefix() => {
                glyphs.push(' ');
                glyphs.push_str(&b.glyph());
            }
            _ => words.push((b.prefix(), b.glyph())),
        }
    }
    let words: Vec<String> = words.into_iter().map(|(p, g)| p + &g).collect();
    let mut text = String::new();
    for (k, word) in words.iter().enumerate() {
        if k > 0 {
            let short = |w: &String| w.chars().count() == 1;
            text.push_str(if short(&words[k - 1]) && short(word) {
                " "
            } else {
                "  "
            });
        }
        text.push_str(word);
    }
    text
}

/// The help's lines: (keys, what they do), then the mouse's.
pub fn help() -> Vec<(String, &'static str)> {
    KEYMAP
        .iter()
        .map(|row| (keys_text(row), row.what))
        .chain(MOUSE.iter().map(|&(how, what)| (how.to_owned(), what)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_help_lists_every_action_in_the_keymap() {
        let help = help();
        // Named in the help: one of its keys stands on its row's line.
        let listed = |action| {
            KEYMAP
                .iter()
                .zip(&help[..KEYMAP.len()])
                .any(|(row, (keys, _))| {
                    row.keys
                        .iter()
                        .filter(|b| b.shown && b.action == action)
                        .any(|b| keys.contains(&b.name()) || keys.contains(&b.glyph()))
                })
        };
        let mut unlisted: Vec<Action> = bindings()
            .map(|b| b.action)
            .filter(|&a| !listed(a))
            .collect();
        unlisted.dedup();
        // Shift+Tab (the tabs backwards) has never been in the help; it
        // stands with Tab on its line, unnamed. Nothing else may hide.
        assert_eq!(unlisted, [PreviousTab], "{help:?}");
    }

    #[test]
    fn every_key_means_one_thing() {
        let all: Vec<&Binding> = bindings().collect();
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert!(
                    (a.code, a.modifiers) != (b.code, b.modifiers),
                    "{a:?} and {b:?}"
                );
            }
        }
    }

    #[test]
    fn the_help_writes_keys_as_before() {
        let help = help();
        let keys: Vec<&str> = help.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(
            keys,
            [
                "j k ↑ ↓",
                "h l ← →",
                "H L  Shift+← →",
                "[ ]  Alt+← →",
                "Enter  e",
                "g G",
                "b",
                "r",
                "u",
                "p P",
                "m M / c a",
                "Tab  1 2 3 4 5",
                "f F v",
                ", .",
                "s o",
                "x",
                "i",
                "Esc",
                "?",
                "q  Ctrl-C",
                "click",
                "wheel",
                "Shift-drag",
            ]
        );
    }

    #[test]
    fn modifiers_choose_the_step() {
        let at = |code, modifiers| action(&KeyEvent::new(code, modifiers));
        let none = KeyModifiers::NONE;
        assert_eq!(at(Right, none), Some(Raise(Step::One)));
        assert_eq!(at(Right, SHIFT), Some(Raise(Step::Ten)));
        assert_eq!(at(Left, ALT), Some(Lower(Step::Tenth)));
        // Shift wins when both are held; Ctrl changes nothing.
        assert_eq!(at(Right, SHIFT | ALT), Some(Raise(Step::Ten)));
        assert_eq!(at(Right, KeyModifiers::CONTROL), Some(Raise(Step::One)));
        assert_eq!(at(KeyCode::Char('l'), ALT), Some(Raise(Step::Tenth)));
        assert_eq!(at(KeyCode::Char('j'), KeyModifiers::CONTROL), Some(Down));
        // Ctrl-C quits; c alone switches the heatmap.
        let ctrl = KeyModifiers::CONTROL;
        assert_eq!(at(KeyCode::Char('c'), ctrl), Some(Interrupt));
        assert_eq!(at(KeyCode::Char('c'), none), Some(MarginMap));
    }
}
