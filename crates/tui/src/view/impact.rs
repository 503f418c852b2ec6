//! The collision step by step (paper Fig. 2): the tangential slip v1 and the
//! normal approach v3 of the contact points against the normal impulse p,
//! with p_s, p_c and p_f marked, and the ball's state at the cursor. A 3-D
//! swing's collision is drawn by [`super::impact3d`], over the same chart.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

use super::chart::{self, AxisSpec, Ticks};
use super::impact3d;
use super::pane_views::Impact;
use super::pane_views::InUnits;
use super::words;
use crate::app::impact_stops;
use model::impact::{Collision, Stop};
use units::Quantity;

pub fn draw(frame: &mut Frame, area: Rect, view: &Impact) {
    // Drawn for a swing only: a batted ball has no impact.
    let Some(impact) = view.impact else {
        return;
    };
    let stops = impact_stops(impact);
    // A view past the last stop shows the last (the app keeps it in range).
    let at = view.stop.min(stops.len() - 1);
    let stop = stops[at];
    let block = Block::bordered().title(Span::styled(
        format!(
            " Impact: {} ({}/{}) · , . step ",
            stop.name,
            at + 1,
            stops.len()
        ),
        view.theme.title,
    ));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    match impact.spatial() {
        Some(spatial) => impact3d::draw(frame, inner, view, (impact, spatial), stop),
        None => planar(frame, inner, view, impact, stop),
    }
}

/// The paper's collision: v1 and v3 against p.
fn planar(frame: &mut Frame, inner: Rect, view: &Impact, impact: &Collision, stop: Stop) {
    // Speeds in the units shown (m/s or mph); impulses stay N·s.
    let (slip_path, normal_path) = (view.theme.path(0), view.theme.path(1));
    let lines = planar_text(view, impact, stop, (slip_path.1, normal_path.1));
    // Each line wrapped at words, never cut: up to two rows each, and the
    // stop's sentence first, up to four.
    let width = inner.width as usize;
    let lines: Vec<Line> = words::fit(&stop_sentence(view, impact, stop).spans, width, 4)
        .into_iter()
        .chain(lines.iter().flat_map(|l| words::fit(&l.spans, width, 2)))
        .collect();
    let [chart_area, text_area] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(lines.len() as u16)])
            .areas(inner);
    let curves = [
        Curve {
            name: "v1",
            value: |s| s.slip.x,
            style: view.theme.slip,
            marker: slip_path.0,
        },
        Curve {
            name: "v3",
            value: |s| s.normal_velocity,
            style: view.theme.approach,
            marker: normal_path.0,
        },
    ];
    phase_chart(frame, chart_area, view, impact, stop.impulse, &curves);

    frame.render_widget(Paragraph::new(lines), text_area);
}

/// The impact's state at the cursor, in words: the impulses, v1 and v3,
/// and the ball's velocity and spin.
fn planar_text(
    view: &Impact,
    impact: &Collision,
    stop: Stop,
    glyphs: (&str, &str),
) -> Vec<Line<'static>> {
    let speed = view.unit(Quantity::Speed);
    let s = impact.at(stop.impulse);
    // The spin to the readout's digits: 191.8 rad/s, 1832 rpm.
    let spin = crate::shown::quantity_text(view.units, Quantity::Spin, s.ball_spin.z, 1, true);
    vec![
        impulse_line(view, impact, stop),
        Line::from(vec![
            Span::styled(
                format!("{}v1 slip ", named(view, glyphs.0)),
                view.theme.slip,
            ),
            Span::raw(format!("{:+.2}  ", speed.show(s.slip.x))),
            Span::styled(
                format!("{}v3 normal ", named(view, glyphs.1)),
                view.theme.approach,
            ),
            Span::raw(format!(
                "{:+.2} {}",
                speed.show(s.normal_velocity),
                speed.symbol
            )),
        ]),
        Line::from(vec![
            Span::styled("ball ", view.theme.dim),
            Span::raw(format!(
                "({:+.2}, {:+.2}) {}  |v| {:.2}  spin {spin}",
                speed.show(s.ball_velocity.x),
                speed.show(s.ball_velocity.y),
                speed.symbol,
                speed.show(s.ball_velocity.norm()),
            )),
        ]),
    ]
}

/// What is happening at the stop, in a sentence (dim, under the chart).
pub(super) fn stop_sentence(view: &Impact, impact: &Collision, stop: Stop) -> Line<'static> {
    Line::styled(super::phase_words::sentence(impact, stop), view.theme.dim)
}

/// A curve of the chart against p: what it plots of a moment (m/s), and
/// how it is drawn.
pub(super) struct Curve {
    /// Its name, written at its end ("v1"): the curves told apart by more
    /// than colour.
    pub name: &'static str,
    pub value: fn(&model::impact::Moment) -> f64,
    pub style: Style,
    pub marker: Marker,
}

/// Without colour, a curve's name carries its glyph.
pub(super) fn named(view: &Impact, glyph: &str) -> String {
    if view.theme.colored() {
        String::new()
    } else {
        format!("{glyph} ")
    }
}

/// "p 4.311 N·s  p_s 1.657  p_c 8.621  p_f 12.341": the cursor and the
/// phases' impulses.
pub(super) fn impulse_line(view: &Impact, impact: &Collision, stop: Stop) -> Line<'static> {
    Line::from(vec![
        Span::styled("p ", view.theme.cursor),
        Span::raw(format!("{:.3} N·s  ", stop.impulse)),
        Span::styled("p_s ", view.theme.stick),
        Span::raw(
            impact
                .stick_impulse()
                .map_or("— (slips) ".to_owned(), |p| format!("{p:.3}  ")),
        ),
        Span::styled("p_c ", view.theme.compression),
        Span::raw(format!("{:.3}  ", impact.compression_impulse())),
        Span::styled("p_f ", view.theme.dim),
        Span::raw(format!("{:.3}", impact.separation_impulse())),
    ])
}

/// The impulse axis's title.
const P_AXIS: &str = "p (N·s)";

/// `curves` against the normal impulse p from 0 to p_f, in the speed unit
/// shown, with p_c, p_s (where the contact sticks) and the cursor at
/// `cursor` as vertical lines, and the names of p_c and p_s at their tops.
pub(super) fn phase_chart(
    frame: &mut Frame,
    chart_area: Rect,
    view: &Impact,
    impact: &Collision,
    cursor: f64,
    curves: &[Curve],
) {
    let speed = view.unit(Quantity::Speed);
    let pf = impact.separation_impulse();
    let samples = (2 * chart_area.width as usize).clamp(8, 400);
    let states: Vec<_> = (0..samples)
        .map(|k| impact.at(pf * k as f64 / (samples - 1) as f64))
        .collect();
    let points: Vec<Vec<(f64, f64)>> = curves
        .iter()
        .map(|c| {
            states
                .iter()
                .map(|s| (s.impulse, speed.show((c.value)(s))))
                .collect()
        })
        .collect();
    let (lo, hi) = points
        .iter()
        .flatten()
        .fold((0.0f64, 0.0f64), |(a, b), p| (a.min(p.1), b.max(p.1)));
    // The axis runs on to a tick at or past p_f, so that p_f lies inside
    // its labels (12.3 on an axis labelled to 14, not past its 10).
    let x = Ticks::across_past(0.0, pf, chart_area.width.saturating_sub(6));
    let pad = 0.05 * (hi - lo);
    let y = Ticks::up(lo - pad, hi + pad, chart_area.height.saturating_sub(2));
    let vertical = |p: f64| [(p, y.lo), (p, y.hi)];
    let pc_line = vertical(impact.compression_impulse());
    let pf_line = vertical(pf);
    let ps_line = impact.stick_impulse().map(vertical);
    let cursor = vertical(cursor);
    let zero = [(0.0, 0.0), (x.hi, 0.0)];
    let mut datasets = vec![
        chart::line(view.theme.dim, &zero),
        chart::line(view.theme.compression, &pc_line),
        chart::line(view.theme.dim, &pf_line),
    ];
    if let Some(ps) = &ps_line {
        datasets.push(chart::line(view.theme.stick, ps));
    }
    datasets.push(chart::line(view.theme.cursor, &cursor));
    for (curve, points) in curves.iter().zip(&points) {
        datasets.push(chart::curve(curve.marker, curve.style, points));
    }
    let graph = chart::draw(
        frame,
        chart_area,
        datasets,
        (&AxisSpec::new(P_AXIS, x), &AxisSpec::new(speed.symbol, y)),
        view.theme.dim,
    );
    // Each line's name at its top, where the chart leaves room.
    let label = |frame: &mut Frame, at: (f64, f64), name: &str, style: Style| {
        chart::labels(
            frame,
            graph,
            (&x, &y),
            Marker::Braille,
            &[(at, name)],
            style,
        );
    };
    let compression = impact.compression_impulse();
    label(frame, (compression, y.hi), "p_c", view.theme.compression);
    if let Some(ps) = impact.stick_impulse() {
        label(frame, (ps, y.hi), "p_s", view.theme.stick);
    }
    // At the foot of its line: the curves end at its top.
    label(frame, (pf, y.lo), "p_f", view.theme.dim);
    // Each curve's name at its end, in its colour.
    for (curve, points) in curves.iter().zip(&points) {
        if let Some(&end) = points.last() {
            label(frame, end, curve.name, curve.style);
        }
    }
}
