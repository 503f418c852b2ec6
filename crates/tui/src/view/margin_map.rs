//! The margin map (key `c`): over the same window of swings (E, ψ) as the
//! range surface, how far over the wall of the chosen park the ball goes
//! (its [`model::clearing::Clearing::clearance`]), on a diverging
//! scale around the wall's top: green over it, magenta under it, its
//! contour at 0; without colour, shades over the wall and lines under it.
//! Each half has its own span (up to the best margin; down to the depth
//! of most misses), so that both read.
//! New rows stream in over the map for the old inputs, marked stale.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use super::heatmap::{
    OffScale, Scale, Value, colour_bar, frame_and_axes, marks, paint, sample_cell,
};
use super::pane_views::{InUnits, Surface};
use crate::app::MarginMap;
use crate::margin::{MarginCell, MarginSurface};
use crate::theme::{diverging, margin_shade};

/// Where the smallest margin either side of the wall falls from the
/// middle of the scale: a tint, so that clearing and not clearing always
/// look different, however close to the wall.
const NEAREST: f64 = 0.15;

/// The least span of either half of the scale (m): a map a few
/// centimetres either side of the wall is not painted as if it were metres.
const LEAST_REACH: f64 = 1.0;

/// Which share of the misses the lower half of the scale spans: the rest,
/// deeper, share its end. A pop-up's landing line continued to the wall
/// runs hundreds of metres under it, and would wash out the swings that
/// matter.
const MISSES_SPANNED: f64 = 0.8;

/// The scale's two halves (m): over the wall up to the best margin, under
/// it down to the depth of [`MISSES_SPANNED`] of the misses; each at least
/// [`LEAST_REACH`].
fn scale_reach(margins: impl Iterator<Item = f64>) -> (f64, f64) {
    let mut over = 0.0f64;
    let mut under: Vec<f64> = Vec::new();
    for m in margins.filter(|m| m.is_finite()) {
        if m > 0.0 {
            over = over.max(m);
        } else {
            under.push(-m);
        }
    }
    let deep = if under.is_empty() {
        0.0
    } else {
        let k = ((MISSES_SPANNED * under.len() as f64) as usize).min(under.len() - 1);
        *under.select_nth_unstable_by(k, f64::total_cmp).1
    };
    (over.max(LEAST_REACH), deep.max(LEAST_REACH))
}

pub fn draw(frame: &mut Frame, area: Rect, view: &Surface, (margin, place): &(&MarginMap, String)) {
    let state = margin.state.as_ref();
    let stale = if state.is_some_and(|s| s.generation != margin.generation) {
        " (stale)"
    } else {
        ""
    };
    let unit = view.distance(1.0).1;
    let title = format!(
        " Margin at {} (E, ψ){stale} · {} 0 {unit} ",
        place,
        super::heatmap::contour_key(view)
    );
    let Some(plot) = frame_and_axes(frame, area, view, title) else {
        return;
    };
    let Some(state) = state else {
        frame.render_widget(
            Paragraph::new(Line::styled("computing the margin…", view.theme.dim)),
            plot,
        );
        return;
    };
    let cell = |map: &MarginSurface, (px, py, w, h): (usize, usize, usize, usize)| {
        let (i, j) = sample_cell(&map.grid, px, py, w, h);
        map.cell(i, j)
    };
    // The new rows where they are done, else the map under them.
    let shown = |at| {
        state
            .filling()
            .map(|f| cell(f, at))
            .filter(|c| *c != MarginCell::NotComputed)
            .unwrap_or_else(|| cell(&state.surface, at))
    };
    let value = |px, py, w, h| match shown((px, py, w, h)) {
        MarginCell::Margin(m) => Value::Number(m),
        MarginCell::NotLanded => Value::NotLanded,
        MarginCell::Foul | MarginCell::BatMisses | MarginCell::NotComputed => Value::Empty,
    };
    let cells = || {
        state
            .surface
            .cells
            .iter()
            .chain(state.filling().map_or(&[][..], |f| &f.cells[..]))
    };
    let margins = || cells().filter_map(|c| c.margin());
    let (over, under) = scale_reach(margins());
    let saturated = margins().any(|m| m < -under);
    let place = |m: f64| {
        let half = if m > 0.0 { over } else { under };
        if m == 0.0 {
            0.5
        } else {
            0.5 + 0.5 * m.signum() * (NEAREST + (1.0 - NEAREST) * (m.abs() / half).min(1.0))
        }
    };
    let scale = Scale {
        ramp: diverging,
        shade: margin_shade,
        contour: view.theme.zero_contour,
    };
    paint(
        frame.buffer_mut(),
        plot,
        view,
        (&value, &place, Some(0.0)),
        &scale,
    );
    marks(frame.buffer_mut(), plot, view);
    // "≤" where the scale stops short of the deepest.
    let end = |metres: f64| {
        let shown = view.distance(metres).0;
        format!("{shown:+.0$}", usize::from(shown.abs() < 10.0))
    };
    let bottom = end(-under);
    let labels = [
        format!("{:>5}", end(over)),
        format!("{:>5}", format!("0 {unit}")),
        format!(
            "{:>5}",
            if saturated {
                format!("≤{bottom}")
            } else {
                bottom
            }
        ),
    ];
    let off = if cells().any(|c| *c == MarginCell::NotLanded) {
        OffScale::NotLanded
    } else if cells().any(|c| *c == MarginCell::Foul) {
        OffScale::Foul
    } else {
        OffScale::None
    };
    colour_bar(frame.buffer_mut(), plot, view, (&scale, &labels), off);
}
