//! The range over (E, ψ) as half-block cells (two pixels per character),
//! with a colour bar, the current swing as a cursor, the optimum, and the
//! contour of the fence's distance. A cell whose ball does not land has no
//! range: it is drawn off the colour scale (hatched where a whole character
//! is such), with its own legend entry, and never sets the scale, the best
//! cell or the contour. The margin map ([`super::margin_map`]) is painted
//! by the same pieces on its own scale.

use ratatui::Frame;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

use super::pane_views::{InUnits, Surface};
use crate::layout::{HEATMAP_BAR, heatmap_plot};
use crate::shown::{swing_angle_tick, swing_angle_unit, undercut_axis, undercut_tick};
use crate::theme::{Theme, ramp};
use analysis::study::{CellOutcome, Grid};

/// The grid cell (column, row) at pixel (px, py) of a w×h picture, py from
/// the top.
pub(super) fn sample_cell(grid: &Grid, px: usize, py: usize, w: usize, h: usize) -> (usize, usize) {
    let i = (px * grid.columns / w.max(1)).min(grid.columns - 1);
    let j_from_top = (py * grid.rows / h.max(1)).min(grid.rows - 1);
    (i, grid.rows - 1 - j_from_top)
}

/// The glyph of a character whose two pixels both do not land, and its
/// legend.
pub const NOT_LANDED_GLYPH: &str = "░";
pub const NOT_LANDED_LEGEND: &str = "░░   up";
/// Without colour: the hatch (the shades use ░), its legend, and the
/// fence's contour.
pub const NOT_LANDED_PLAIN_GLYPH: &str = "╳";
pub const NOT_LANDED_PLAIN_LEGEND: &str = "╳╳   up";
const CONTOUR_GLYPH: &str = "•";

/// What a map holds at a pixel: a value, or why it has none.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Value {
    Number(f64),
    /// The ball does not land: drawn off the scale, hatched.
    NotLanded,
    /// Nothing to show (the bat misses, not flown yet, foul): blank.
    Empty,
}

/// How a map's values look: its colour ramp over [0, 1], the glyph for a
/// place on the scale without colour, and the colour of its contour.
pub(super) struct Scale {
    pub ramp: fn(f64) -> (u8, u8, u8),
    pub shade: fn(f64) -> &'static str,
    pub contour: Color,
}

pub fn draw(frame: &mut Frame, area: Rect, view: &Surface) {
    if let Some(margin) = &view.margin {
        super::margin_map::draw(frame, area, view, margin);
        return;
    }
    let level = view.fence_distance;
    let stale = if view
        .surface
        .is_some_and(|s| s.generation != view.generation)
    {
        " (stale)"
    } else {
        ""
    };
    let title = match level {
        Some(d) => {
            let (d, unit) = view.distance(d);
            format!(
                " Range over (E, ψ){stale} · {} {d:.0} {unit} (fence) ",
                contour_key(view)
            )
        }
        None => format!(" Range over (E, ψ){stale} "),
    };
    let Some(plot) = frame_and_axes(frame, area, view, title) else {
        return;
    };
    let Some(state) = view.surface else {
        frame.render_widget(
            Paragraph::new(Line::styled("computing the surface…", view.theme.dim)),
            plot,
        );
        return;
    };
    let surface = &state.surface;
    // The scale spans the landings only.
    let (min, max) = surface
        .landed_ranges()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    let value = |px: usize, py: usize, w: usize, h: usize| {
        let (i, j) = sample_cell(&surface.grid, px, py, w, h);
        match surface.outcome(i, j) {
            CellOutcome::Landed(v) => Value::Number(v),
            CellOutcome::NotLanded => Value::NotLanded,
            CellOutcome::BatMisses | CellOutcome::NotComputed => Value::Empty,
        }
    };
    let scale = Scale {
        ramp,
        shade: Theme::shade,
        contour: view.theme.contour,
    };
    paint(
        frame.buffer_mut(),
        plot,
        view,
        (&value, &|v| (v - min) / (max - min).max(1e-9), level),
        &scale,
    );
    marks(frame.buffer_mut(), plot, view);
    let (top, unit) = view.distance(max);
    let labels = [
        format!("{top:>5.0}"),
        format!("{unit:>5}"),
        format!("{:>5.0}", view.distance(min).0),
    ];
    colour_bar(
        frame.buffer_mut(),
        plot,
        view,
        (&scale, &labels),
        if surface.any_not_landed() {
            OffScale::NotLanded
        } else {
            OffScale::None
        },
    );
}

/// The pane's border and title, and the axes' labels: ψ on the left (top,
/// bottom), E along the bottom, in the units shown (rad and m, or degrees
/// and inches); the plot inside them, if it is large enough to draw.
pub(super) fn frame_and_axes(
    frame: &mut Frame,
    area: Rect,
    view: &Surface,
    title: String,
) -> Option<Rect> {
    let block = Block::bordered().title(Span::styled(title, view.theme.title));
    frame.render_widget(block, area);
    let plot = heatmap_plot(area);
    if plot.width < 4 || plot.height < 2 {
        return None;
    }
    let window = Grid::explorer_window();
    let inner = Block::bordered().inner(area);
    let psi_text = |psi: f64| swing_angle_tick(view.units, psi);
    let e_text = |e: f64| undercut_tick(view.units, e);
    let buf = frame.buffer_mut();
    buf.set_string(
        inner.x,
        plot.y,
        format!("{:>5}", psi_text(window.swing_angle.1)),
        view.theme.dim,
    );
    let middle = plot.y + plot.height / 2;
    buf.set_string(inner.x, middle, "  ψ ↑", view.theme.dim);
    // The unit under the name, where it leaves the bottom tick its row.
    if middle + 1 < plot.bottom().saturating_sub(1) {
        let unit = format!("{:>5}", swing_angle_unit(view.units));
        buf.set_string(inner.x, middle + 1, unit, view.theme.dim);
    }
    buf.set_string(
        inner.x,
        plot.bottom().saturating_sub(1),
        format!("{:>5}", psi_text(window.swing_angle.0)),
        view.theme.dim,
    );
    let bottom = plot.bottom();
    buf.set_string(plot.x, bottom, e_text(window.undercut.0), view.theme.dim);
    let e_label = format!("{} →", undercut_axis(view.units));
    buf.set_string(
        plot.x + plot.width.saturating_sub(e_label.chars().count() as u16) / 2,
        bottom,
        &e_label,
        view.theme.dim,
    );
    let right = e_text(window.undercut.1);
    buf.set_string(
        plot.right().saturating_sub(right.len() as u16),
        bottom,
        &right,
        view.theme.dim,
    );

    Some(plot)
}

/// What a map's values are for [`paint`]: the value at pixel (px, py) of a
/// w×h picture, where a value falls on the scale (0 to 1), and the level
/// whose contour is drawn.
pub(super) type Values<'a> = (
    &'a dyn Fn(usize, usize, usize, usize) -> Value,
    &'a dyn Fn(f64) -> f64,
    Option<f64>,
);

/// Paints a map's values over `plot`: in colour, half blocks on `scale`'s
/// ramp; without, a glyph per character on its shades; the contour where
/// the level lies between a pixel and its neighbour to the right or below.
pub(super) fn paint(
    buf: &mut Buffer,
    plot: Rect,
    view: &Surface,
    (value, place, level): Values,
    scale: &Scale,
) {
    let (w, h) = (plot.width as usize, 2 * plot.height as usize);
    let pixels: Vec<Value> = (0..h)
        .flat_map(|py| (0..w).map(move |px| (px, py)))
        .map(|(px, py)| value(px, py, w, h))
        .collect();
    let at = |px: usize, py: usize| pixels[py * w + px];
    let number = |v: Value| match v {
        Value::Number(n) => Some(n),
        _ => None,
    };
    let pixel = |px: usize, py: usize| -> Pixel {
        let v = at(px, py);
        if let (Some(l), Some(here)) = (level, number(v)) {
            // A pixel on the contour: the level lies between it and a
            // neighbour, both with values.
            let crosses = |there: Value| number(there).is_some_and(|t| (t >= l) != (here >= l));
            let edge =
                (px + 1 < w && crosses(at(px + 1, py))) || (py + 1 < h && crosses(at(px, py + 1)));
            if edge {
                return Pixel::Contour;
            }
        }
        match v {
            Value::Number(v) => Pixel::Landed(place(v)),
            Value::NotLanded => Pixel::NotLanded,
            Value::Empty => Pixel::NoRange,
        }
    };
    let theme = &view.theme;
    if theme.colored() {
        let colour = |px: usize, py: usize| -> Color {
            match pixel(px, py) {
                Pixel::Contour => scale.contour,
                Pixel::Landed(t) => theme.rgb((scale.ramp)(t)),
                Pixel::NotLanded => theme.not_landed,
                Pixel::NoRange => theme.no_range,
            }
        };
        draw_pixels(buf, plot, &colour, theme);
    } else {
        draw_shades(buf, plot, &pixel, scale.shade);
    }
}

/// The current swing ✚ and the optimum ★ over a map; a point outside the
/// window is pinned to its edge as ◆.
pub(super) fn marks(buf: &mut Buffer, plot: Rect, view: &Surface) {
    let window = Grid::explorer_window();
    let to_cell = |e: f64, psi: f64| -> (u16, u16, bool) {
        let fx = (e - window.undercut.0) / (window.undercut.1 - window.undercut.0);
        let fy = (psi - window.swing_angle.0) / (window.swing_angle.1 - window.swing_angle.0);
        let inside = (0.0..=1.0).contains(&fx) && (0.0..=1.0).contains(&fy);
        let (fx, fy) = (fx.clamp(0.0, 1.0), fy.clamp(0.0, 1.0));
        let x = plot.x + ((fx * (plot.width - 1) as f64).round() as u16);
        let y = plot.y + (((1.0 - fy) * (plot.height - 1) as f64).round() as u16);
        (x, y, inside)
    };
    let mark = |buf: &mut Buffer, (x, y, inside): (u16, u16, bool), symbol: &str, colour: Color| {
        let symbol = if inside { symbol } else { "◆" };
        buf[(x, y)]
            .set_symbol(symbol)
            .set_style(view.theme.mark(colour));
    };
    if let Some(o) = view.optimum.filter(|o| o.done && o.best.range.is_finite()) {
        mark(
            buf,
            to_cell(o.best.undercut, o.best.swing_angle),
            "★",
            view.theme.optimum_mark,
        );
    }
    mark(
        buf,
        to_cell(view.swing.0, view.swing.1),
        "✚",
        view.theme.swing_mark,
    );
}

/// The cells off a map's scale, for the legend under its colour bar.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum OffScale {
    None,
    /// Some balls do not land (hatched).
    NotLanded,
    /// Some swings go foul (blank: the margin map's).
    Foul,
}

/// The colour bar right of `plot`, top = 1 on the scale, with `labels` at
/// its top, middle and bottom, and under it the legend of the cells off
/// the scale, if any.
pub(super) fn colour_bar(
    buf: &mut Buffer,
    plot: Rect,
    view: &Surface,
    (scale, labels): (&Scale, &[String; 3]),
    off: OffScale,
) {
    let bar = Rect::new(plot.right() + 1, plot.y, HEATMAP_BAR - 1, plot.height);
    let [_, bar_area] = Layout::horizontal([Constraint::Length(0), Constraint::Fill(1)]).areas(bar);
    for row in 0..bar_area.height {
        let t = 1.0 - row as f64 / (bar_area.height.max(2) - 1) as f64;
        let c = view.theme.rgb((scale.ramp)(t));
        let swatch = if view.theme.colored() {
            "██"
        } else {
            &(scale.shade)(t).repeat(2)
        };
        buf.set_string(bar_area.x, bar_area.y + row, swatch, view.theme.swatch(c));
    }
    let rows = [
        bar_area.y,
        bar_area.y + bar_area.height / 2,
        bar_area.bottom().saturating_sub(1),
    ];
    for (row, label) in rows.into_iter().zip(labels) {
        buf.set_string(bar_area.x + 2, row, label, view.theme.dim);
    }
    let (x, y) = (bar_area.x, bar_area.bottom());
    match off {
        OffScale::None => {}
        OffScale::NotLanded => {
            let legend = if view.theme.colored() {
                NOT_LANDED_LEGEND
            } else {
                NOT_LANDED_PLAIN_LEGEND
            };
            buf.set_string(x, y, legend, view.theme.swatch(view.theme.not_landed));
        }
        OffScale::Foul => {
            // The blank cells' own colour, then the word.
            let swatch = Style::new().bg(view.theme.no_range);
            buf.set_string(x, y, "  ", swatch);
            buf.set_string(x + 2, y, " foul", view.theme.dim);
        }
    }
}

/// What a pixel of the map shows.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Pixel {
    /// On the level's contour.
    Contour,
    /// A value, at `t` of the colour scale (0 to 1).
    Landed(f64),
    NotLanded,
    /// No value: the bat misses the ball (or nothing to show).
    NoRange,
}

/// Fills `area` with half blocks: the upper pixel as foreground, the lower
/// as background; a character whose two pixels both do not land gets the
/// hatch glyph instead, on the no-range colour.
fn draw_pixels(
    buf: &mut Buffer,
    area: Rect,
    colour: &dyn Fn(usize, usize) -> Color,
    theme: &Theme,
) {
    for row in 0..area.height {
        for col in 0..area.width {
            let (c, r) = (col as usize, row as usize);
            let (top, bottom) = (colour(c, 2 * r), colour(c, 2 * r + 1));
            let cell = &mut buf[(area.x + col, area.y + row)];
            if top == theme.not_landed && bottom == theme.not_landed {
                cell.set_symbol(NOT_LANDED_GLYPH)
                    .set_fg(theme.not_landed)
                    .set_bg(theme.no_range);
            } else {
                cell.set_symbol("▀").set_fg(top).set_bg(bottom);
            }
        }
    }
}

/// How the legend draws the contour: a line where it is drawn in colour,
/// its dots without (NO_COLOR), as the map shows it.
pub(super) fn contour_key(view: &Surface) -> String {
    if view.theme.colored() {
        "──".to_owned()
    } else {
        CONTOUR_GLYPH.repeat(2)
    }
}

/// Fills `area` without colour, a glyph per character: the contour's dot,
/// the hatch where neither pixel lands, else the `shade` of its values'
/// mean place on the scale (blank where there is none).
fn draw_shades(
    buf: &mut Buffer,
    area: Rect,
    pixel: &dyn Fn(usize, usize) -> Pixel,
    shade: fn(f64) -> &'static str,
) {
    for row in 0..area.height {
        for col in 0..area.width {
            let (c, r) = (col as usize, row as usize);
            let pair = [pixel(c, 2 * r), pixel(c, 2 * r + 1)];
            let landed: Vec<f64> = pair
                .iter()
                .filter_map(|p| match p {
                    Pixel::Landed(t) => Some(*t),
                    _ => None,
                })
                .collect();
            let glyph = if pair.contains(&Pixel::Contour) {
                CONTOUR_GLYPH
            } else if pair == [Pixel::NotLanded; 2] {
                NOT_LANDED_PLAIN_GLYPH
            } else if landed.is_empty() {
                " "
            } else {
                shade(landed.iter().sum::<f64>() / landed.len() as f64)
            };
            buf[(area.x + col, area.y + row)].set_symbol(glyph);
        }
    }
}
