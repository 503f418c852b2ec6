//! The mouse: a click on a tab shows it, one on the heatmap moves the swing there, one on the
//! field sets the launch direction, a click on an input selects it, the wheel over an input nudges it. Where things are
//! comes from `layout`, the same rectangles the views draw into.

use ratatui::crossterm::event::{MouseEvent, MouseEventKind};

use super::{App, Mode};
use crate::format::{error_text, on_step};
use crate::layout::{self, heatmap_point, input_scroll, inputs_list};
use model::scene::Scene;

/// The keys a click on the surface sets.
const UNDERCUT: &str = "bat.undercut";
const SWING_ANGLE: &str = "bat.swing_angle";

impl App {
    pub(super) fn mouse(&mut self, event: MouseEvent) {
        // Pop-ups own the keyboard; the mouse acts only on the panes.
        if !matches!(self.mode, Mode::Normal) {
            return;
        }
        let (x, y) = (event.column, event.row);
        let panes = layout::layout(self.size, self.tab, self.is_swing());
        match event.kind {
            MouseEventKind::Down(_) => {
                let on_tab = panes
                    .tabs
                    .filter(|bar| bar.contains(ratatui::layout::Position { x, y }))
                    .and_then(|bar| layout::Tab::at(bar, x));
                if let Some(tab) = on_tab {
                    self.tab = tab;
                    self.dirty = true;
                } else if let Some(field) = self.input_at(panes.inputs, x, y) {
                    self.selected = field;
                    self.message = None;
                    self.dirty = true;
                } else if panes.field.is_some_and(|pane| self.click_field(pane, x, y)) {
                    // The field set the launch's direction (or said why not).
                } else if let Some((e, psi)) = panes
                    .heatmap
                    .filter(|_| self.is_swing())
                    .and_then(|h| heatmap_point(h, x, y))
                {
                    // On the inputs' steps, as typed or nudged values are.
                    let round = |name, si| match Scene::key(name) {
                        Ok(key) => on_step(key, si, self.units),
                        Err(_) => si,
                    };
                    let (e, psi) = (round(UNDERCUT, e), round(SWING_ANGLE, psi));
                    let scene = self.scene.with_swing(e, psi);
                    self.dirty = true;
                    match scene.validate() {
                        Ok(()) => {
                            self.scene = scene;
                            self.inputs_changed = true;
                            self.message = None;
                        }
                        Err(error) => self.message = Some((error_text(&error, self.units), true)),
                    }
                }
            }
            MouseEventKind::ScrollUp | MouseEventKind::ScrollDown => {
                if let Some(field) = self.input_at(panes.inputs, x, y) {
                    self.selected = field;
                    self.dirty = true;
                    let up = event.kind == MouseEventKind::ScrollUp;
                    self.nudge(if up { 1.0 } else { -1.0 });
                }
            }
            _ => {}
        }
    }

    /// The input whose row is at screen (x, y), if any.
    fn input_at(&self, pane: ratatui::layout::Rect, x: u16, y: u16) -> Option<usize> {
        let list = inputs_list(pane);
        if !list.contains(ratatui::layout::Position { x, y }) {
            return None;
        }
        let lines = self.input_lines();
        let selected_line = lines.iter().position(|l| *l == Some(self.selected))?;
        let offset = input_scroll(selected_line, lines.len(), list.height as usize);
        lines.get(offset + (y - list.y) as usize).copied().flatten()
    }
}
