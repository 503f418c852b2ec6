//! Where each pane goes at a given screen size. The view draws into these
//! rectangles; the app reads them too, because what it computes follows the
//! screen (a trajectory sample per half braille column, a surface pixel per
//! half block).

use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::widgets::Block;

use analysis::study::Grid;

/// The view shown beside the inputs on a small screen (a large one shows all).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    Flight,
    Surface,
    Impact,
    /// The paper's figures for the current inputs.
    Figures,
    /// The field from above: the spray chart.
    Field,
}

impl Tab {
    pub const ALL: [Tab; 5] = [
        Tab::Flight,
        Tab::Surface,
        Tab::Impact,
        Tab::Figures,
        Tab::Field,
    ];
    /// The tab's title, `short` where the tab bar is narrow (all five fit
    /// the 50 columns right of the inputs at 80×24).
    pub fn title(self, short: bool) -> &'static str {
        match (self, short) {
            (Tab::Flight, _) => "1 Flight",
            (Tab::Surface, false) => "2 Range surface",
            (Tab::Surface, true) => "2 Surface",
            (Tab::Impact, _) => "3 Impact",
            (Tab::Figures, false) => "4 Figures",
            (Tab::Figures, true) => "4 Figs",
            (Tab::Field, _) => "5 Field",
        }
    }

    /// The tab bar's divider: the titles are unpadded.
    pub const DIVIDER: &'static str = " │ ";
    /// The divider where even the short titles do not fit with [`Tab::DIVIDER`].
    pub const NARROW_DIVIDER: &'static str = "│";

    /// The divider for a tab bar `width` columns wide: every title whole.
    pub fn divider(width: u16) -> &'static str {
        let short: usize = Tab::ALL.iter().map(|t| t.title(true).chars().count()).sum();
        if short + 3 * (Tab::ALL.len() - 1) > width as usize {
            Tab::NARROW_DIVIDER
        } else {
            Tab::DIVIDER
        }
    }

    /// Whether the titles must be short to fit `width` columns.
    pub fn short_titles(width: u16) -> bool {
        let long: usize = Tab::ALL
            .iter()
            .map(|t| t.title(false).chars().count())
            .sum();
        long + 3 * (Tab::ALL.len() - 1) > width as usize
    }

    /// The tab whose title (with the divider after it) is at column `x` of
    /// a tab bar drawn over `bar`, as the view draws it.
    pub fn at(bar: Rect, x: u16) -> Option<Tab> {
        let short = Tab::short_titles(bar.width);
        let divider = Tab::divider(bar.width).chars().count() as u16;
        let mut left = bar.x;
        for tab in Tab::ALL {
            let right = left + tab.title(short).chars().count() as u16 + divider;
            if (left..right).contains(&x) {
                return Some(tab);
            }
            left = right;
        }
        None
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
    /// The field from above (the spray chart).
    pub field: Option<Rect>,
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

/// Whether the inputs pane is wide enough for the Δopt column (46 or 58
/// columns; at 31 it has room for neither). Δopt costs ~28 ms of CPU per
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
    use model::keys::swing_keys;
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
    // Wide enough for each row's words and symbol, value and unit (the Δ
    // columns from 116 columns): a batted ball's words ("exit speed V̂_bf")
    // are the longer.
    let inputs_width = match (is_wide(area), swing) {
        (true, _) => 46,
        (false, true) => 31,
        (false, false) => 33,
    };
    let [inputs, right] =
        Layout::horizontal([Constraint::Length(inputs_width), Constraint::Fill(1)]).areas(body);
    let mut panes = Panes {
        inputs,
        status,
        ..Panes::default()
    };
    if is_wide(area) {
        // The side view beside the readout; under them the range surface
        // (a batted ball's figure) beside the field from above, which gives
        // its place to the impact (`3`) or the figures (`4`) when chosen.
        let [top, bottom] =
            Layout::vertical([Constraint::Percentage(50), Constraint::Fill(1)]).areas(right);
        let [trajectory, readout] =
            Layout::horizontal([Constraint::Fill(1), Constraint::Length(50)]).areas(top);
        let [left, other] =
            Layout::horizontal([Constraint::Percentage(50), Constraint::Fill(1)]).areas(bottom);
        panes.trajectory = Some(trajectory);
        panes.readout = Some(readout);
        if !swing {
            panes.field = Some(left);
            panes.figure = Some(other);
            return panes;
        }
        panes.heatmap = Some(left);
        match tab {
            Tab::Impact => panes.impact = Some(other),
            Tab::Figures => panes.figure = Some(other),
            Tab::Flight | Tab::Surface | Tab::Field => panes.field = Some(other),
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
            Tab::Field => panes.field = Some(content),
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
        (Tab::Field, _) => panes.field = Some(bottom),
    }
}

/// A field's width over its height in cells, about: fair territory out to
/// a fence the same all round is 1.4 times as wide as it is deep, a cell
/// twice as tall as wide, and a park's nearer foul poles make it narrower.
const FIELD_ASPECT: f64 = 2.6;

/// The field's pane width for a row of panes `height` tall: the field at
/// equal scales fills it (at most half of `width`).
fn field_width(height: u16, width: u16) -> u16 {
    let inner = f64::from(height.saturating_sub(2));
    ((2.0 + FIELD_ASPECT * inner).round() as u16).min(width / 2)
}

/// Everything at once: the inputs over the readout at the left; along the
/// top the trajectory beside the field from above (each pane about the
/// shape of what it draws: a flight is long and low, a field twice as wide
/// as deep in cells), and under them the range surface, the impact and the
/// figure; a batted ball's figure under its flight.
fn big_layout(body: Rect, status: Rect, swing: bool) -> Panes {
    let [left, right] =
        Layout::horizontal([Constraint::Length(BIG_INPUTS_WIDTH), Constraint::Fill(1)]).areas(body);
    let inputs_height = inputs_height().min(body.height.saturating_sub(BIG_READOUT_MIN));
    let [inputs, readout] =
        Layout::vertical([Constraint::Length(inputs_height), Constraint::Fill(1)]).areas(left);
    let [top, bottom] = Layout::vertical([
        Constraint::Percentage(if swing { 42 } else { 45 }),
        Constraint::Fill(1),
    ])
    .areas(right);
    let [trajectory, field] = Layout::horizontal([
        Constraint::Fill(1),
        Constraint::Length(field_width(top.height, top.width)),
    ])
    .areas(top);
    let mut panes = Panes {
        inputs,
        tabs: None,
        trajectory: Some(trajectory),
        readout: Some(readout),
        field: Some(field),
        status,
        ..Panes::default()
    };
    if !swing {
        panes.figure = Some(bottom);
        return panes;
    }
    let [heatmap, impact, figure] = Layout::horizontal([
        Constraint::Ratio(1, 3),
        Constraint::Ratio(1, 3),
        Constraint::Ratio(1, 3),
    ])
    .areas(bottom);
    panes.heatmap = Some(heatmap);
    panes.impact = Some(impact);
    panes.figure = Some(figure);
    panes
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

/// The field view's scale: the plot (the pane inside its border, which
/// ratatui's chart fills when its axes carry no labels), and the lateral
/// (z) and centre-field (x) bounds it spans, in metres, at equal scales.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldMap {
    pub plot: Rect,
    pub z: [f64; 2],
    pub x: [f64; 2],
}

impl FieldMap {
    /// The view over `pane` that shows `half` metres either side of the
    /// centre-field line and from `behind` metres behind the plate to
    /// `reach` beyond it, as large as fits at equal scales: a braille dot is
    /// half a cell wide and a quarter of a cell tall, and a cell is
    /// [`CELL_ASPECT`] times as tall as wide. The plate is at the bottom
    /// centre; room to spare goes above (centre field) or to the sides.
    pub fn new(pane: Rect, half: f64, behind: f64, reach: f64) -> FieldMap {
        let plot = Block::bordered().inner(pane);
        let (dots_z, dots_x) = (
            f64::from(2 * plot.width.max(1)) - 1.0,
            f64::from(4 * plot.height.max(1)) - 1.0,
        );
        // Metres per cell's width, from the wider need.
        let across = 2.0 * (2.0 * half) / dots_z;
        let up = 4.0 * (reach + behind) / (CELL_ASPECT * dots_x);
        let cell = across.max(up).max(f64::MIN_POSITIVE);
        let (span_z, span_x) = (cell * dots_z / 2.0, cell * CELL_ASPECT * dots_x / 4.0);
        FieldMap {
            plot,
            z: [-span_z / 2.0, span_z / 2.0],
            x: [-behind, span_x - behind],
        }
    }

    /// The point (x, z) at the centre of the cell at screen (column, row),
    /// or `None` outside the plot. A cell's centre is between its braille
    /// dots 0.5 across and 1.5 down, where the chart puts dot k at
    /// k / (dots − 1) of the span.
    pub fn point(&self, column: u16, row: u16) -> Option<(f64, f64)> {
        let plot = self.plot;
        if !plot.contains(ratatui::layout::Position { x: column, y: row }) {
            return None;
        }
        let (dots_z, dots_x) = (
            f64::from(2 * plot.width) - 1.0,
            f64::from(4 * plot.height) - 1.0,
        );
        let across = (2.0 * f64::from(column - plot.x) + 0.5) / dots_z;
        let down = (4.0 * f64::from(row - plot.y) + 1.5) / dots_x;
        Some((
            self.x[1] - down * (self.x[1] - self.x[0]),
            self.z[0] + across * (self.z[1] - self.z[0]),
        ))
    }
}
