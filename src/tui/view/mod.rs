//! Drawing: pure functions from the app's state to a frame, one per pane.
//! Nothing here changes the state or computes physics.

mod heatmap;
mod impact;
mod inputs;
mod overlay;
mod readout;
mod trajectory;

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Tabs};

use super::app::{App, Mode, Tab};
use super::theme::{self, dim};
use crate::model::scene::Key;

/// The smallest screen the explorer draws on.
pub const MIN_SIZE: (u16, u16) = (60, 16);

/// Where each pane goes; `None` for a pane not shown at this size and tab.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Panes {
    pub inputs: Rect,
    pub tabs: Option<Rect>,
    pub trajectory: Option<Rect>,
    pub readout: Option<Rect>,
    pub heatmap: Option<Rect>,
    pub impact: Option<Rect>,
    pub status: Rect,
}

/// Whether everything fits at once.
pub fn is_wide(area: Rect) -> bool {
    area.width >= 140 && area.height >= 40
}

const READOUT_HEIGHT: u16 = 9;

pub fn layout(area: Rect, tab: Tab) -> Panes {
    let [body, status] = Layout::vertical([Constraint::Fill(1), Constraint::Length(1)]).areas(area);
    let inputs_width = if is_wide(area) { 44 } else { 30 };
    let [inputs, right] =
        Layout::horizontal([Constraint::Length(inputs_width), Constraint::Fill(1)]).areas(body);
    let mut panes = Panes {
        inputs,
        status,
        ..Panes::default()
    };
    if is_wide(area) {
        let [top, bottom] =
            Layout::vertical([Constraint::Percentage(50), Constraint::Fill(1)]).areas(right);
        let [trajectory, readout] =
            Layout::horizontal([Constraint::Fill(1), Constraint::Length(50)]).areas(top);
        let [heatmap, impact] =
            Layout::horizontal([Constraint::Percentage(50), Constraint::Fill(1)]).areas(bottom);
        panes.trajectory = Some(trajectory);
        panes.readout = Some(readout);
        panes.heatmap = Some(heatmap);
        panes.impact = Some(impact);
    } else {
        let [tabs, content] =
            Layout::vertical([Constraint::Length(1), Constraint::Fill(1)]).areas(right);
        panes.tabs = Some(tabs);
        match tab {
            Tab::Flight => {
                let [trajectory, readout] =
                    Layout::vertical([Constraint::Fill(1), Constraint::Length(READOUT_HEIGHT)])
                        .areas(content);
                panes.trajectory = Some(trajectory);
                panes.readout = Some(readout);
            }
            Tab::Surface => panes.heatmap = Some(content),
            Tab::Impact => panes.impact = Some(content),
        }
    }
    panes
}

/// Trajectory samples for a screen: two per braille column of the plot.
pub fn trajectory_samples(size: Rect) -> usize {
    let width = layout(size, Tab::Flight).trajectory.map_or(80, |r| r.width);
    (2 * width as usize).clamp(16, 800)
}

/// The heatmap's resolution in (columns, rows) of pixels: one column per
/// cell, two rows per line (half blocks).
pub fn heatmap_resolution(size: Rect) -> (usize, usize) {
    let area = layout(size, Tab::Surface).heatmap.unwrap_or(size);
    let plot = heatmap::plot_area(area);
    (
        (plot.width as usize).clamp(2, 200),
        (2 * plot.height as usize).clamp(2, 120),
    )
}

/// A value as the inputs pane shows it: enough digits for a thousandth of
/// the key's step, trailing zeros trimmed.
pub fn format_value(key: &Key, value: f64) -> String {
    let decimals = ((-key.step.log10()).ceil() as i32 + 3).clamp(0, 12) as usize;
    let text = format!("{value:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    };
    if text == "-0" { "0".to_owned() } else { text }
}

/// Draws the whole screen from the app's state.
pub fn draw(frame: &mut Frame, app: &App) {
    let area = frame.area();
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        let text = format!(
            "homerun needs at least {}×{} (this is {}×{}); q quits",
            MIN_SIZE.0, MIN_SIZE.1, area.width, area.height
        );
        frame.render_widget(
            Paragraph::new(text).wrap(ratatui::widgets::Wrap { trim: true }),
            area,
        );
        return;
    }
    let panes = layout(area, app.tab);
    inputs::draw(frame, panes.inputs, app);
    if let Some(tabs) = panes.tabs {
        let selected = Tab::ALL.iter().position(|t| *t == app.tab).unwrap_or(0);
        frame.render_widget(
            Tabs::new(Tab::ALL.iter().map(|t| t.title()))
                .select(selected)
                .highlight_style(theme::SELECTED)
                .divider("│"),
            tabs,
        );
    }
    if let Some(r) = panes.trajectory {
        trajectory::draw(frame, r, app);
    }
    if let Some(r) = panes.readout {
        readout::draw(frame, r, app);
    }
    if let Some(r) = panes.heatmap {
        heatmap::draw(frame, r, app);
    }
    if let Some(r) = panes.impact {
        impact::draw(frame, r, app);
    }
    status_line(frame, panes.status, app);
    match &app.mode {
        Mode::Help => overlay::help(frame, area),
        Mode::Save { text, error } => overlay::save(frame, area, app, text, error.as_deref()),
        Mode::Open {
            items,
            selected,
            error,
        } => overlay::open(frame, area, items, *selected, error.as_deref()),
        Mode::Normal | Mode::Edit { .. } => {}
    }
}

/// What is being computed and how fresh each result is.
fn status_line(frame: &mut Frame, area: Rect, app: &App) {
    let mut spans = Vec::new();
    spans.push(Span::raw("readout ✓ "));
    spans.push(match &app.optimum {
        Some(o) if o.done => Span::raw(format!("· optimum ✓ {} evals ", o.evaluations)),
        Some(o) => Span::styled(
            format!("· optimising… {} evals ", o.evaluations),
            theme::BUSY,
        ),
        None => Span::styled("· optimising… ", theme::BUSY),
    });
    spans.push(match &app.surface {
        Some(s) if s.generation != app.generation => {
            Span::styled("· surface stale, updating… ", theme::BUSY)
        }
        Some(s) if s.last => Span::raw(format!(
            "· surface ✓ {}×{} ",
            s.surface.grid.columns, s.surface.grid.rows
        )),
        Some(s) => Span::styled(
            format!(
                "· surface {}×{}, refining… ",
                s.surface.grid.columns, s.surface.grid.rows
            ),
            theme::BUSY,
        ),
        None => Span::styled("· surface… ", theme::BUSY),
    });
    spans.push(Span::styled("· ? help  q quit", dim()));
    frame.render_widget(Paragraph::new(Line::from(spans)), area);
}
