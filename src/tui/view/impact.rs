//! The collision step by step (paper Fig. 2): the tangential slip v1 and the
//! normal approach v3 of the contact points against the normal impulse p,
//! with p_s, p_c and p_f marked, and the ball's state at the cursor.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

use super::chart::{self, AxisSpec, Ticks};
use crate::tui::app::App;
use crate::units::Quantity;

pub fn draw(frame: &mut Frame, area: Rect, app: &App) {
    // Drawn for a swing only: a batted ball has no impact.
    let Some(impact) = &app.flown.impact else {
        return;
    };
    // Speeds in the units shown (m/s or mph); impulses stay N·s.
    let (speed, spin) = (app.unit(Quantity::Speed), app.unit(Quantity::Spin));
    let stops = impact.stops();
    let stop = stops[app.impact_stop.min(stops.len() - 1)];
    let block = Block::bordered().title(Span::styled(
        format!(
            " Impact: {} ({}/{}) · , . step ",
            stop.name,
            app.impact_stop + 1,
            stops.len()
        ),
        app.theme.title,
    ));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let [chart_area, text_area] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(3)]).areas(inner);

    let pf = impact.separation_impulse();
    let samples = (2 * chart_area.width as usize).clamp(8, 400);
    let states: Vec<_> = (0..samples)
        .map(|k| impact.at(pf * k as f64 / (samples - 1) as f64))
        .collect();
    let slip: Vec<(f64, f64)> = states
        .iter()
        .map(|s| (s.impulse, speed.show(s.slip.x)))
        .collect();
    let normal: Vec<(f64, f64)> = states
        .iter()
        .map(|s| (s.impulse, speed.show(s.normal_velocity)))
        .collect();
    let (lo, hi) = slip
        .iter()
        .chain(&normal)
        .fold((0.0f64, 0.0f64), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let x = Ticks::across(0.0, pf, chart_area.width.saturating_sub(6));
    let pad = 0.05 * (hi - lo);
    let y = Ticks::up(lo - pad, hi + pad, chart_area.height.saturating_sub(2));
    let vertical = |p: f64| [(p, y.lo), (p, y.hi)];
    let pc_line = vertical(impact.compression_impulse());
    let ps_line = impact.stick_impulse().map(vertical);
    let cursor = vertical(stop.impulse);
    let zero = [(0.0, 0.0), (x.hi, 0.0)];
    let mut datasets = vec![
        chart::line(app.theme.dim, &zero),
        chart::line(app.theme.compression, &pc_line),
    ];
    if let Some(ps) = &ps_line {
        datasets.push(chart::line(app.theme.stick, ps));
    }
    datasets.push(chart::line(app.theme.cursor, &cursor));
    let (slip_path, normal_path) = (app.theme.path(0), app.theme.path(1));
    datasets.push(chart::curve(slip_path.0, app.theme.slip, &slip));
    datasets.push(chart::curve(normal_path.0, app.theme.approach, &normal));
    let graph = chart::draw(
        frame,
        chart_area,
        datasets,
        (
            &AxisSpec::new("p (N·s)", x),
            &AxisSpec::new(speed.symbol, y),
        ),
        app.theme.dim,
    );
    // Each line's name at its top, where the chart leaves room.
    let top = |p: f64| (p, y.hi);
    let at = |p: f64, name| [(top(p), name)];
    chart::labels(
        frame,
        graph,
        (&x, &y),
        Marker::Braille,
        &at(impact.compression_impulse(), "p_c"),
        app.theme.compression,
    );
    if let Some(ps) = impact.stick_impulse() {
        let marker = Marker::Braille;
        chart::labels(
            frame,
            graph,
            (&x, &y),
            marker,
            &at(ps, "p_s"),
            app.theme.stick,
        );
    }

    let s = impact.at(stop.impulse);
    // Without colour, the curves' names carry their glyphs.
    let named = |glyph: &str| {
        if app.theme.colored() {
            String::new()
        } else {
            format!("{glyph} ")
        }
    };
    let lines = vec![
        Line::from(vec![
            Span::styled("p ", app.theme.cursor),
            Span::raw(format!("{:.3} N·s  ", stop.impulse)),
            Span::styled("p_s ", app.theme.stick),
            Span::raw(
                impact
                    .stick_impulse()
                    .map_or("— (slips) ".to_owned(), |p| format!("{p:.3}  ")),
            ),
            Span::styled("p_c ", app.theme.compression),
            Span::raw(format!("{:.3}  ", impact.compression_impulse())),
            Span::styled("p_f ", app.theme.dim),
            Span::raw(format!("{pf:.3}")),
        ]),
        Line::from(vec![
            Span::styled(format!("{}v1 slip ", named(slip_path.1)), app.theme.slip),
            Span::raw(format!("{:+.2}  ", speed.show(s.slip.x))),
            Span::styled(
                format!("{}v3 normal ", named(normal_path.1)),
                app.theme.approach,
            ),
            Span::raw(format!(
                "{:+.2} {}",
                speed.show(s.normal_velocity),
                speed.symbol
            )),
        ]),
        Line::from(vec![
            Span::styled("ball ", app.theme.dim),
            Span::raw(format!(
                "({:+.2}, {:+.2}) {}  |v| {:.2}  spin {:+.1} {}",
                speed.show(s.ball_velocity.x),
                speed.show(s.ball_velocity.y),
                speed.symbol,
                speed.show(s.ball_velocity.norm()),
                spin.show(s.ball_spin.z),
                spin.symbol
            )),
        ]),
    ];
    frame.render_widget(Paragraph::new(lines), text_area);
}
