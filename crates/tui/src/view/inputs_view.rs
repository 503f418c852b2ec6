//! What the inputs pane reads of the explorer, and nothing more: the pane
//! draws from an [`Inputs`] alone, so that it can be built, changed and
//! tested without an [`App`].

use crate::app::{App, Field, GainCell, Mode};
use crate::theme::Theme;
use crate::worker::Gain;
use model::scene::Scene;
use units::UnitSystem;

/// The edit box's text and its refusal, while a value is typed.
pub type Editing<'a> = Option<(&'a ratatui_textarea::TextArea<'static>, &'a Option<String>)>;

/// The inputs pane's view of the explorer's state.
#[derive(Clone, Debug)]
pub struct Inputs<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    pub scene: &'a Scene,
    pub preset_name: &'a str,
    /// What the preset says of itself (the preset row's hint).
    pub description: &'a str,
    pub fields: &'a [Field],
    pub selected: usize,
    /// The list's lines: `None` for a group's header, else a field's index.
    pub lines: Vec<Option<usize>>,
    pub editing: Editing<'a>,
    /// The last word to the user, and whether it is an error.
    pub message: Option<&'a (String, bool)>,
    pub swing_gains: &'a [Option<GainCell>],
    pub optimum_gains: &'a [Option<GainCell>],
    /// The inputs' generation: a gain of an older one is stale.
    pub generation: u64,
    /// Whether each kind of gain is still being computed for it.
    pub swing_gains_busy: bool,
    pub optimum_gains_busy: bool,
}

impl<'a> Inputs<'a> {
    /// The inputs pane's view of `app`.
    pub fn of(app: &'a App) -> Inputs<'a> {
        let busy = |gain| app.gains_done(gain) < app.gain_count();
        Inputs {
            theme: &app.theme,
            units: app.units,
            scene: &app.scene,
            preset_name: &app.preset_name,
            description: &app.description,
            fields: &app.fields,
            selected: app.selected,
            lines: app.input_lines(),
            editing: match &app.mode {
                Mode::Edit { text, error, .. } => Some((text, error)),
                _ => None,
            },
            message: app.message.as_ref(),
            swing_gains: &app.swing_gains,
            optimum_gains: &app.optimum_gains,
            generation: app.generation,
            swing_gains_busy: busy(Gain::Swing),
            optimum_gains_busy: busy(Gain::Optimum),
        }
    }

    /// A distance in the units shown: (value, unit).
    pub fn distance(&self, metres: f64) -> (f64, &'static str) {
        crate::shown::distance(self.units, metres)
    }

    /// Whether the scene is a swing (not a batted ball on its own).
    pub fn is_swing(&self) -> bool {
        self.scene.kind == model::launch::SceneKind::Swing
    }

    /// The sensitivities of one kind.
    pub fn gains(&self, gain: Gain) -> &'a [Option<GainCell>] {
        match gain {
            Gain::Swing => self.swing_gains,
            Gain::Optimum => self.optimum_gains,
        }
    }

    /// Input `k`'s gain of one kind, if computed (none for a row past
    /// the list's end).
    pub fn gain(&self, gain: Gain, k: usize) -> Option<GainCell> {
        self.gains(gain).get(k).copied().flatten()
    }

    /// Whether the gains of one kind are still being computed.
    pub fn gains_busy(&self, gain: Gain) -> bool {
        match gain {
            Gain::Swing => self.swing_gains_busy,
            Gain::Optimum => self.optimum_gains_busy,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::{fields, input_count, input_key};
    use crate::theme::ColorMode;
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;
    use ratatui::layout::Rect;

    /// The pane alone, `width` × `height`, drawn from `view`: its rows.
    fn drawn(view: &Inputs, width: u16, height: u16) -> Vec<String> {
        let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
        terminal
            .draw(|frame| super::super::inputs::draw(frame, Rect::new(0, 0, width, height), view))
            .unwrap();
        let buffer = terminal.backend().buffer().clone();
        (0..height)
            .map(|y| {
                let row: String = (0..width).map(|x| buffer[(x, y)].symbol()).collect();
                row.replace('\u{a0}', " ")
            })
            .collect()
    }

    /// The fastball's inputs in baseball units, ψ selected, no gain yet.
    fn fastball<'a>(theme: &'a Theme, scene: &'a Scene, rows: &'a [Field]) -> Inputs<'a> {
        let groups: Vec<&str> = rows.iter().map(|f| f.group()).collect();
        let selected = rows
            .iter()
            .position(|f| matches!(f, Field::Key(k) if input_key(*k).name == "bat.swing_angle"))
            .unwrap();
        Inputs {
            theme,
            units: UnitSystem::Imperial,
            scene,
            preset_name: "fastball",
            description: "the paper's fastball",
            fields: rows,
            selected,
            lines: crate::layout::input_lines(&groups),
            editing: None,
            message: None,
            swing_gains: &[],
            optimum_gains: &[],
            generation: 3,
            swing_gains_busy: true,
            optimum_gains_busy: true,
        }
    }

    #[test]
    fn the_inputs_pane_draws_from_its_view_alone() {
        let theme = Theme::from(ColorMode::Indexed);
        let scene = preset::load("fastball", None).unwrap().scene;
        let rows = fields(scene.kind);
        let mut gains = vec![None; input_count()];
        let mut view = fastball(&theme, &scene, &rows);
        let Field::Key(k) = rows[view.selected] else {
            panic!("ψ is a key")
        };
        gains[k] = Some(GainCell {
            value: Some(2.01),
            generation: 3,
        });
        view.swing_gains = &gains;
        let shown = drawn(&view, 31, 22);
        // ψ as the readout writes it, selected; its gain in feet in the
        // title (no room for a Δ column at this width).
        let psi = shown.iter().find(|r| r.contains("swing angle ψ")).unwrap();
        assert!(
            psi.starts_with("│▶swing angle ψ") && psi.contains(" 9.13° "),
            "{psi}"
        );
        assert!(shown[0].contains("▶ Δ +6.59 ft"), "{}", shown[0]);
        assert!(
            shown.iter().any(|r| r.contains("undercut E     1.043 in")),
            "{shown:#?}"
        );
        // Under the list, what ψ is, in degrees.
        let about = shown[shown.len() - 4..].join("");
        assert!(about.contains("bat.swing_angle: swing angle"), "{about}");
    }

    #[test]
    fn a_message_takes_the_place_of_the_description() {
        let theme = Theme::from(ColorMode::Indexed);
        let scene = preset::load("fastball", None).unwrap().scene;
        let rows = fields(scene.kind);
        let message = ("loaded fastball".to_owned(), false);
        let mut view = fastball(&theme, &scene, &rows);
        view.message = Some(&message);
        view.units = UnitSystem::Si;
        let shown = drawn(&view, 31, 22);
        let about = shown[shown.len() - 4..].join("");
        assert!(about.contains("loaded fastball"), "{about}");
        assert!(!about.contains("bat.swing_angle"), "{about}");
        assert!(shown.iter().any(|r| r.contains("0.1594 rad")), "{shown:#?}");
        // No gain yet: the selected one's is on its way.
        assert!(shown[0].contains("▶ Δ …"), "{}", shown[0]);
    }
}
