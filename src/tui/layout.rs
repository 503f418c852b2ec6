//! Where each pane goes at a given screen size. The view draws into these
//! rectangles; the app reads them too, because what it computes follows the
//! screen (a trajectory sample per half braille column, a surface pixel per
//! half block).

use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::widgets::Block;

use crate::analysis::study::Grid;

/// The view shown beside the inputs on a small screen (a large one shows all).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    Flight,
    Surface,
    Impact,
    /// The paper's figures for the current inputs.
    Figures,
}

impl Tab {
    pub const ALL: [Tab; 4] = [Tab::Flight, Tab::Surface, Tab::Impact, Tab::Figures];
    pub fn title(self) -> &'static str {
        match self {
            Tab::Flight => "1 Flight",
            Tab::Surface => "2 Range surface",
            Tab::Impact => "3 Impact",
            Tab::Figures => "4 Figures",
        }
    }
}

/// A terminal cell's height over its width, about: what a chart drawn to
/// scale must allow for.
pub const CELL_ASPECT: f64 = 2.0;

/// The smallest screen the explorer draws on; a smaller one gets a notice.
pub const MIN_SIZE: (u16, u16) = (80, 24);

/// Where each pane goes; `None` for a pane not shown at this size and tab.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Panes {
    pub inputs: Rect,
    pub tabs: Option<Rect>,
    pub trajectory: Option<Rect>,
    pub readout: Option<Rect>,
    pub heatmap: Option<Rect>,
    pub impact: Option<Rect>,
    pub figure: Option<Rect>,
    pub status: Rect,
}

/// Whether everything but the figures fits at once.
pub fn is_wide(area: Rect) -> bool {
    area.width >= 140 && area.height >= 40
}

/// Whether the figures get a pane of their own too (e.g. 200×60): the
/// inputs (with their names and both sensitivity columns) over the readout
/// at the left, and trajectory, figure, surface and impact in a 2×2 grid.
pub fn is_big(area: Rect) -> bool {
    area.width >= 190 && area.height >= 54
}

/// Whether a second pane fits beside the flight (e.g. 120×40): the
/// trajectory and the readout side by side above the tab's pane.
pub fn is_medium(area: Rect) -> bool {
    area.width >= 116 && area.height >= 34
}

/// Whether the inputs pane is wide enough for the Δopt column (44 or 58
/// columns; at 30 it has room for Δ only). Δopt costs ~28 ms of CPU per
/// change, so it is computed only where it is shown.
pub fn shows_optimum_gains(area: Rect) -> bool {
    is_wide(area) || is_big(area)
}

const READOUT_HEIGHT: u16 = 9;
/// The inputs pane's width on a big screen: every column (see `view::inputs`).
const BIG_INPUTS_WIDTH: u16 = 58;
/// The fewest lines the readout gets under the inputs on a big screen.
const BIG_READOUT_MIN: u16 = 14;

/// The inputs pane's height for its whole list: one line per input (the
/// preset, every numeric key, the drag and lift models), one per group
/// header, the 3 lines that describe the selected input and the borders.
fn inputs_height() -> u16 {
    use crate::model::keys::swing_keys;
    let mut groups = vec!["model"];
    for key in swing_keys() {
        let group = key.name.split('.').next().unwrap_or("");
        if !groups.contains(&group) {
            groups.push(group);
        }
    }
    (1 + swing_keys().count() + 2 + groups.len() + 3 + 2) as u16
}

/// The panes at `area` for the tab chosen, for a swing (`swing`) or a
/// batted ball, which has no range surface nor impact: on a screen that
/// shows everything, the trajectory and the figure take their room.
pub fn layout(area: Rect, tab: Tab, swing: bool) -> Panes {
    let [body, status] = Layout::vertical([Constraint::Fill(1), Constraint::Length(1)]).areas(area);
    if is_big(area) {
        return big_layout(body, status, swing);
    }
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
        if !swing {
            panes.trajectory = Some(trajectory);
            panes.readout = Some(readout);
            panes.figure = Some(bottom);
            return panes;
        }
        let [heatmap, other] =
            Layout::horizontal([Constraint::Percentage(50), Constraint::Fill(1)]).areas(bottom);
        panes.trajectory = Some(trajectory);
        panes.readout = Some(readout);
        panes.heatmap = Some(heatmap);
        // The figures take the impact's place when chosen (`4`).
        if tab == Tab::Figures {
            panes.figure = Some(other);
        } else {
            panes.impact = Some(other);
        }
    } else if is_medium(area) {
        medium_layout(&mut panes, right, tab, swing);
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
            Tab::Figures => panes.figure = Some(content),
        }
    }
    panes
}

/// A second pane (e.g. 120×40): the tabs, the trajectory and the readout
/// side by side, and under them the tab's pane: the range surface for the
/// flight's tab (a batted ball's figure), the impact or the figures.
fn medium_layout(panes: &mut Panes, right: Rect, tab: Tab, swing: bool) {
    let [tabs, top, bottom] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Percentage(40),
        Constraint::Fill(1),
    ])
    .areas(right);
    let [trajectory, readout] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(50)]).areas(top);
    panes.tabs = Some(tabs);
    panes.trajectory = Some(trajectory);
    panes.readout = Some(readout);
    match (tab, swing) {
        (Tab::Flight, true) | (Tab::Surface, _) => panes.heatmap = Some(bottom),
        (Tab::Impact, _) => panes.impact = Some(bottom),
        (Tab::Flight, false) | (Tab::Figures, _) => panes.figure = Some(bottom),
    }
}

/// Everything at once: the inputs over the readout at the left, and a 2×2
/// grid of trajectory, figure, range surface and impact.
fn big_layout(body: Rect, status: Rect, swing: bool) -> Panes {
    let [left, right] =
        Layout::horizontal([Constraint::Length(BIG_INPUTS_WIDTH), Constraint::Fill(1)]).areas(body);
    let inputs_height = inputs_height().min(body.height.saturating_sub(BIG_READOUT_MIN));
    let [inputs, readout] =
        Layout::vertical([Constraint::Length(inputs_height), Constraint::Fill(1)]).areas(left);
    if !swing {
        // A batted ball: the trajectory and the aero figure, full height.
        let [trajectory, figure] =
            Layout::horizontal([Constraint::Percentage(60), Constraint::Fill(1)]).areas(right);
        return Panes {
            inputs,
            tabs: None,
            trajectory: Some(trajectory),
            readout: Some(readout),
            heatmap: None,
            impact: None,
            figure: Some(figure),
            status,
        };
    }
    let [top, bottom] =
        Layout::vertical([Constraint::Percentage(50), Constraint::Fill(1)]).areas(right);
    let [trajectory, figure] =
        Layout::horizontal([Constraint::Percentage(50), Constraint::Fill(1)]).areas(top);
    let [heatmap, impact] =
        Layout::horizontal([Constraint::Percentage(50), Constraint::Fill(1)]).areas(bottom);
    Panes {
        inputs,
        tabs: None,
        trajectory: Some(trajectory),
        readout: Some(readout),
        heatmap: Some(heatmap),
        impact: Some(impact),
        figure: Some(figure),
        status,
    }
}

/// Trajectory samples for a screen: two per braille column of the plot.
pub fn trajectory_samples(size: Rect, swing: bool) -> usize {
    let width = layout(size, Tab::Flight, swing)
        .trajectory
        .map_or(80, |r| r.width);
    (2 * width as usize).clamp(16, 800)
}

/// Columns left of the heatmap's pixels for the ψ labels.
const HEATMAP_LABELS: u16 = 6;
/// Columns right of the heatmap's pixels for the colour bar.
pub const HEATMAP_BAR: u16 = 9;

/// The part of the heatmap's pane covered by pixels.
pub fn heatmap_plot(area: Rect) -> Rect {
    let inner = Block::bordered().inner(area);
    Rect::new(
        inner.x + HEATMAP_LABELS,
        inner.y,
        inner.width.saturating_sub(HEATMAP_LABELS + HEATMAP_BAR),
        inner.height.saturating_sub(1),
    )
}

/// The heatmap's resolution in (columns, rows) of pixels: one column per
/// cell, two rows per line (half blocks).
pub fn heatmap_resolution(size: Rect) -> (usize, usize) {
    let area = layout(size, Tab::Surface, true).heatmap.unwrap_or(size);
    let plot = heatmap_plot(area);
    (
        (plot.width as usize).clamp(2, 200),
        (2 * plot.height as usize).clamp(2, 120),
    )
}

/// The inputs pane's list of rows (above the 3 lines that describe the
/// selected one).
pub fn inputs_list(area: Rect) -> Rect {
    let [list, _] = Layout::vertical([Constraint::Fill(1), Constraint::Length(3)])
        .areas(Block::bordered().inner(area));
    list
}

/// The inputs list's lines, given each field's group: a header line (`None`)
/// before each new group, then the field's index.
pub fn input_lines(groups: &[&str]) -> Vec<Option<usize>> {
    let mut lines = Vec::new();
    let mut last = "";
    for (i, group) in groups.iter().enumerate() {
        if *group != last {
            lines.push(None);
            last = group;
        }
        lines.push(Some(i));
    }
    lines
}

/// How many lines the inputs list scrolls by to keep `selected_line` in view.
pub fn input_scroll(selected_line: usize, lines: usize, height: usize) -> usize {
    (selected_line + 2)
        .saturating_sub(height)
        .min(lines.saturating_sub(height))
}

/// The swing (E, ψ) at the centre of the heatmap's character cell at screen
/// (x, y), or `None` outside its pixels. Each cell is one column of the
/// surface's grid and two of its rows (half blocks), spread over
/// [`Grid::explorer_window`] as the surface is.
pub fn heatmap_point(area: Rect, x: u16, y: u16) -> Option<(f64, f64)> {
    let plot = heatmap_plot(area);
    if !(plot.contains(ratatui::layout::Position { x, y }) && plot.width >= 2) {
        return None;
    }
    let grid = Grid {
        columns: plot.width as usize,
        rows: 2 * plot.height as usize,
        ..Grid::explorer_window()
    };
    let column = (x - plot.x) as usize;
    // The cell's two pixels, top first, are grid rows rows−1−2k and rows−2−2k.
    let top = grid.rows - 1 - 2 * (y - plot.y) as usize;
    let psi = 0.5 * (grid.swing_angle_at(top) + grid.swing_angle_at(top - 1));
    Some((grid.undercut_at(column), psi))
}
