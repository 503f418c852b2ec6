//! A 3-D swing's collision step by step: v1 (across the bat), v2 (along
//! it) and v3 against the normal impulse p, as the plane's chart, and
//! beside it the slip (v1, v2) in the tangent plane at equal scales: the
//! path of its tip from s(0) to where it halts (the contact sticks at the
//! origin) or the ball leaves, with the cursor's slip as an arrow from the
//! origin. Coulomb friction slows the slip faster across the bat than
//! along it, so the path curves: the slip's direction turns toward the bat
//! as it slows (`model::impact::slip`).

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Chart, Paragraph};

use super::impact::{Curve, impulse_line, named, phase_chart, stop_sentence};
use super::pane_views::Impact;
use super::pane_views::InUnits;
use super::{chart, words};
use crate::layout::CELL_ASPECT;
use crate::shown::{angle_text, quantity_text};
use model::impact::{Collision, Impact3d, Regime, Stop};
use units::{Quantity, UnitSystem};

/// Points along the slip's path: smooth in braille at any pane size.
const PATH_POINTS: usize = 80;

pub fn draw(
    frame: &mut Frame,
    inner: Rect,
    view: &Impact,
    (impact, spatial): (&Collision, &Impact3d),
    stop: Stop,
) {
    let speed = view.unit(Quantity::Speed);
    let (across, normal, along) = (view.theme.path(0), view.theme.path(1), view.theme.path(2));
    let s = impact.at(stop.impulse);
    let value = |v: f64| Span::raw(format!("{:+.2}  ", speed.show(v)));
    let v = s.ball_velocity;
    let lines: Vec<Line> = [
        impulse_line(view, impact, stop),
        Line::from(vec![
            Span::styled(format!("{}v1 ", named(view, across.1)), view.theme.slip),
            value(s.slip.x),
            Span::styled(
                format!("{}v2 ", named(view, along.1)),
                view.theme.slip_along,
            ),
            value(s.slip.y),
            Span::styled(format!("{}v3 ", named(view, normal.1)), view.theme.approach),
            Span::raw(format!(
                "{:+.2} {}",
                speed.show(s.normal_velocity),
                speed.symbol
            )),
        ]),
        turn_line(view, spatial, stop.impulse, inner.width),
        Line::from(vec![
            Span::styled("ball ", view.theme.dim),
            Span::raw(format!(
                "({:+.2}, {:+.2}, {:+.2}) {}  |ω| {}{}",
                speed.show(v.x),
                speed.show(v.y),
                speed.show(v.z),
                speed.symbol,
                quantity_text(view.units, Quantity::Spin, s.ball_spin.norm(), 1, false),
                spin_parts(view, impact, stop)
            )),
        ]),
    ]
    .iter()
    // Each line wrapped at words, never cut: up to two rows each; the
    // stop's sentence first, up to four.
    .flat_map(|l| words::fit(&l.spans, inner.width as usize, 2))
    .collect();
    let lines: Vec<Line> = words::fit(
        &stop_sentence(view, impact, stop).spans,
        inner.width as usize,
        4,
    )
    .into_iter()
    .chain(lines)
    .collect();
    let [charts, text_area] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(lines.len() as u16)])
            .areas(inner);
    // The slip plane beside the chart, about as wide as tall in true
    // proportion, and never more than two fifths of the pane.
    let plane_width = (charts.width * 2 / 5).min(CELL_ASPECT as u16 * charts.height + 2);
    let shows_plane = plane_width >= 12 && charts.height >= 6;
    let [chart_area, _, plane_area] = Layout::horizontal([
        Constraint::Fill(1),
        Constraint::Length(u16::from(shows_plane)),
        Constraint::Length(if shows_plane { plane_width } else { 0 }),
    ])
    .areas(charts);
    let curves = [
        Curve {
            name: "v1",
            value: |s| s.slip.x,
            style: view.theme.slip,
            marker: across.0,
        },
        Curve {
            name: "v2",
            value: |s| s.slip.y,
            style: view.theme.slip_along,
            marker: along.0,
        },
        Curve {
            name: "v3",
            value: |s| s.normal_velocity,
            style: view.theme.approach,
            marker: normal.0,
        },
    ];
    phase_chart(frame, chart_area, view, impact, stop.impulse, &curves);
    if shows_plane {
        slip_plane(frame, plane_area, view, spatial, stop.impulse);
    }

    frame.render_widget(Paragraph::new(lines), text_area);
}

/// At separation, what the launch line calls spin: |ω| is the whole spin
/// vector, the launch's backspin and sidespin are its parts about the
/// horizontal across the flight and the vertical (the rest spins about the
/// ball's path and bends nothing).
fn spin_parts(view: &Impact, impact: &Collision, stop: Stop) -> String {
    if stop.impulse < impact.separation_impulse() {
        return String::new();
    }
    // The readout's digits: a tenth of a rad/s, whole rpm.
    let spin = view.unit(Quantity::Spin);
    let decimals = spin.decimals(1);
    format!(
        " (launch: backspin\u{a0}{:.decimals$}, sidespin\u{a0}{:.decimals$})",
        spin.show(impact.launch_spin()),
        spin.show(impact.launch_sidespin())
    )
}

/// "slip 38.2° (26.3° → 74.3° at p_s, sticks)", in SI in rad: the slip's direction at the
/// cursor (0° square across the bat, 90° along it), and at the start and
/// the end of its turn: where it halts, or at separation if it never does.
fn turn_line(view: &Impact, impact: &Impact3d, cursor: f64, width: u16) -> Line<'static> {
    // To a tenth of a degree, as `hit` prints the turn.
    let slip_angle = |rad: f64| angle_text(view.units, rad, 3, false);
    let turn = impact.slip_turn(2);
    let label = Span::styled("slip ", view.theme.slip);
    let (Some(first), Some(last)) = (turn.first(), turn.last()) else {
        return Line::from(vec![label, Span::raw("none: it sticks from the start")]);
    };
    // From p_s on the contact sticks (at p_s itself the slip's last
    // trace still has a direction, which means nothing).
    let stuck = impact.regime == Regime::Stick && cursor >= impact.slip_halt_impulse();
    let grips = impact.release != nalgebra::Vector2::zeros();
    let now = match impact.at(cursor).slip_angle().filter(|_| !stuck) {
        Some(angle) => slip_angle(angle),
        None if grips && cursor > impact.slip_halt_impulse() => "springing back".to_owned(),
        None => "stuck".to_owned(),
    };
    let end = match impact.regime {
        Regime::Stick if grips => Span::styled("sticks, springs back", view.theme.stick),
        Regime::Stick => Span::styled("sticks", view.theme.stick),
        Regime::Slip => Span::raw("slips to p_f"),
    };
    let mut spans = vec![
        label,
        Span::styled(now, view.theme.cursor),
        // Where each end is, so that the last stop's 37° before the halt
        // does not read as the 74° at it.
        Span::raw(format!(
            " ({} → {} at {}, ",
            slip_angle(first.angle),
            slip_angle(last.angle),
            if impact.regime == Regime::Stick {
                "p_s"
            } else {
                "p_f"
            }
        )),
        end,
        Span::raw(")"),
    ];
    let key = match view.units {
        UnitSystem::Si => "  0 across the bat, π/2 along",
        UnitSystem::Imperial => "  0° across the bat, 90° along",
    };
    let used: usize = spans.iter().map(Span::width).sum();
    if used + key.chars().count() <= width as usize {
        spans.push(Span::styled(key, view.theme.dim));
    }
    Line::from(spans)
}

/// The slip in the tangent plane: v1 across, v2 up, equal scales; the path
/// of its tip, the stick point, and the cursor's slip as an arrow.
fn slip_plane(frame: &mut Frame, area: Rect, view: &Impact, impact: &Impact3d, cursor: f64) {
    let [title, plot] = Layout::vertical([Constraint::Length(1), Constraint::Fill(1)]).areas(area);
    frame.buffer_mut().set_string(
        title.x,
        title.y,
        fitted("slip (v1, v2)", title.width),
        view.theme.dim,
    );
    let plane = Plane::new(plot, view, impact, cursor);
    plane.draw(frame, view);
    plane.name(frame, view);
}

/// What the slip plane draws, in the speed unit shown: the path of the
/// slip's tip (ending at the origin where it sticks), the cursor's arrow,
/// and the bounds at equal scales over `plot`.
struct Plane {
    plot: Rect,
    path: Vec<(f64, f64)>,
    arrow: Option<Vec<(f64, f64)>>,
    bounds: ([f64; 2], [f64; 2]),
    sticks: bool,
}

impl Plane {
    fn new(plot: Rect, view: &Impact, impact: &Impact3d, cursor: f64) -> Plane {
        let speed = view.unit(Quantity::Speed);
        let shown = |v: nalgebra::Vector2<f64>| (speed.show(v.x), speed.show(v.y));
        let mut path: Vec<(f64, f64)> = impact
            .slip_turn(PATH_POINTS)
            .iter()
            .map(|p| {
                let (sin, cos) = p.angle.sin_cos();
                (speed.show(p.speed * cos), speed.show(p.speed * sin))
            })
            .collect();
        let sticks = impact.regime == Regime::Stick;
        if sticks {
            path.push((0.0, 0.0));
        } else {
            path.push(shown(impact.after.slip));
        }
        let stuck = sticks && cursor >= impact.slip_halt_impulse();
        let now = if stuck {
            (0.0, 0.0)
        } else {
            shown(impact.at(cursor).slip)
        };
        let bounds = equal_bounds(plot, &path);
        Plane {
            plot,
            arrow: arrow(now, bounds),
            path,
            bounds,
            sticks,
        }
    }

    /// The axes, the path, the arrow and the stick point.
    fn draw(&self, frame: &mut Frame, view: &Impact) {
        let (bx, by) = self.bounds;
        let axes = [
            vec![(bx[0], 0.0), (bx[1], 0.0)],
            vec![(0.0, by[0]), (0.0, by[1])],
        ];
        let mut datasets = vec![
            chart::line(view.theme.dim, &axes[0]),
            chart::line(view.theme.dim, &axes[1]),
            chart::curve(view.theme.path(0).0, view.theme.slip, &self.path),
        ];
        if let Some(arrow) = &self.arrow {
            // Without colour, dots tell it from the path.
            let marker = if view.theme.colored() {
                Marker::Braille
            } else {
                Marker::Dot
            };
            datasets.push(chart::curve(marker, view.theme.cursor, arrow));
        }
        if self.sticks {
            datasets.push(chart::points(Marker::Dot, view.theme.stick, &ORIGIN));
        }
        frame.render_widget(
            Chart::new(datasets)
                .x_axis(Axis::default().bounds(bx))
                .y_axis(Axis::default().bounds(by))
                .legend_position(None),
            self.plot,
        );
    }

    /// The axes' names at their ends; the start of the path and the stick
    /// each on the first place beside their point (above or below it,
    /// right or left) where every cell is blank. No word covers a cell the
    /// path, the arrow or the stick point passes through: an axis's name
    /// moves off its axis's end where the slip runs along it.
    fn name(&self, frame: &mut Frame, view: &Impact) {
        let (plot, bounds) = (self.plot, self.bounds);
        let (bx, by) = bounds;
        let mut ink = inked(plot, bounds, &self.path);
        if let Some(arrow) = &self.arrow {
            ink.extend(inked(plot, bounds, arrow));
        }
        ink.extend(inked(plot, bounds, &ORIGIN));
        let buf = frame.buffer_mut();
        let mut write =
            |point: (f64, f64), text: &str, style: Style, places: &[(bool, i16)], blank: bool| {
                let Some((column, row)) = chart::cell_of(plot, bounds, point, Marker::Braille)
                else {
                    return;
                };
                let width = text.chars().count() as u16;
                for &(left, down) in places {
                    let start = if left {
                        column.checked_sub(width)
                    } else {
                        Some(column + 1)
                    };
                    let row = row
                        .checked_add_signed(down)
                        .filter(|r| *r >= plot.y && *r < plot.bottom());
                    let (Some(start), Some(row)) = (
                        start.filter(|s| *s >= plot.x && s + width <= plot.right()),
                        row,
                    ) else {
                        continue;
                    };
                    let free = (start..start + width).all(|x| {
                        !ink.contains(&(x, row)) && (!blank || buf[(x, row)].symbol() == " ")
                    });
                    if free {
                        buf.set_string(start, row, text, style);
                        return;
                    }
                }
            };
        let ends = [(true, 0), (true, -1), (true, 1)];
        write((bx[1], 0.0), "v1", view.theme.dim, &ends, false);
        let top = [(false, 0), (true, 0), (false, 1), (true, 1)];
        write((0.0, by[1]), "v2", view.theme.dim, &top, false);
        if let Some(&start) = self.path.first() {
            let left = start.0 > 0.5 * (bx[0] + bx[1]);
            let places = [
                (left, -1),
                (left, 1),
                (!left, -1),
                (!left, 1),
                (left, 0),
                (left, -2),
                (left, 2),
            ];
            write(start, "p=0", view.theme.slip, &places, true);
        }
        if self.sticks {
            let places = [(false, 1), (true, 1), (false, -1), (true, -1)];
            write(ORIGIN[0], "p_s", view.theme.stick, &places, true);
        }
    }
}

/// The slip plane's origin: where the contact sticks.
const ORIGIN: [(f64, f64); 1] = [(0.0, 0.0)];

/// The cells a polyline through `points` passes through, drawn in braille
/// over `plot` with `bounds` (each segment sampled finer than a dot).
fn inked(
    plot: Rect,
    bounds: ([f64; 2], [f64; 2]),
    points: &[(f64, f64)],
) -> std::collections::HashSet<(u16, u16)> {
    let dots = 2 * u32::from(plot.width.max(plot.height * 2));
    let cell = |p| chart::cell_of(plot, bounds, p, Marker::Braille);
    let mut cells: std::collections::HashSet<_> = points.iter().filter_map(|&p| cell(p)).collect();
    for pair in points.windows(2) {
        let ((x0, y0), (x1, y1)) = (pair[0], pair[1]);
        for k in 1..dots {
            let t = f64::from(k) / f64::from(dots);
            cells.extend(cell((x0 + t * (x1 - x0), y0 + t * (y1 - y0))));
        }
    }
    cells
}

/// The bounds (v1, v2) that show `points` and the origin with a margin, at
/// equal scales in `plot`: a braille dot is half a cell wide and a quarter
/// of one tall, a cell [`CELL_ASPECT`] times as tall as wide.
fn equal_bounds(plot: Rect, points: &[(f64, f64)]) -> ([f64; 2], [f64; 2]) {
    let (mut x, mut y) = ([0.0f64, 0.0f64], [0.0f64, 0.0f64]);
    for &(px, py) in points.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
        x = [x[0].min(px), x[1].max(px)];
        y = [y[0].min(py), y[1].max(py)];
    }
    // The plot's width and height in braille dots' widths.
    let (dots_x, dots_y) = (
        2.0 * f64::from(plot.width.max(1)),
        4.0 * f64::from(plot.height.max(1)) * CELL_ASPECT / 2.0,
    );
    // Per dot's width, from the wider need.
    let need = |[a, b]: [f64; 2]| 1.15 * (b - a).max(1e-9);
    let per_dot = (need(x) / dots_x).max(need(y) / dots_y);
    let centred = |[a, b]: [f64; 2], dots: f64| {
        let (mid, half) = (0.5 * (a + b), 0.5 * per_dot * dots);
        [mid - half, mid + half]
    };
    (centred(x, dots_x), centred(y, dots_y))
}

/// An arrow from the origin toward `tip` with two barbs, at least a
/// quarter of the plot long so that a dying slip's direction still shows;
/// `None` once it has halted (the contact sticks).
fn arrow(tip: (f64, f64), (x, y): ([f64; 2], [f64; 2])) -> Option<Vec<(f64, f64)>> {
    let length = tip.0.hypot(tip.1);
    if length == 0.0 || !length.is_finite() {
        return None;
    }
    let shown = length.max(0.25 * (x[1] - x[0]).min(y[1] - y[0]));
    let heading = tip.1.atan2(tip.0);
    let tip = (shown * heading.cos(), shown * heading.sin());
    let barb = |turn: f64| {
        let back = heading + std::f64::consts::PI + turn;
        let reach = 0.2 * shown;
        (tip.0 + reach * back.cos(), tip.1 + reach * back.sin())
    };
    Some(vec![(0.0, 0.0), tip, barb(0.5), tip, barb(-0.5)])
}

/// `text` cut to `width` characters.
fn fitted(text: &str, width: u16) -> String {
    text.chars().take(width as usize).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::App;
    use crate::theme::ColorMode;
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;
    use ratatui::buffer::Buffer;

    fn drawn(area: Rect, draw: impl FnOnce(&mut Frame)) -> Buffer {
        let mut terminal = Terminal::new(TestBackend::new(area.width, area.height)).unwrap();
        terminal.draw(draw).unwrap();
        terminal.backend().buffer().clone()
    }

    /// Every cell that ratatui draws of the path, the arrow or the stick
    /// point (in their colours) is still theirs once the words are written:
    /// over swings that slip along the v1 axis (μ 0.05) or stick, at every
    /// sixth of the impulse, in insets small and large.
    #[test]
    fn the_slip_planes_words_never_cover_its_path_its_arrow_or_the_stick() {
        for (tilt, direction, friction) in [(0.5, 0.0, 0.05), (0.5, 0.3, 0.5), (0.2, 0.6, 0.1)] {
            let mut fastball = preset::load("fastball", None).unwrap();
            fastball.scene.bat.tilt = tilt;
            fastball.scene.bat.direction = direction;
            fastball.scene.bat.friction = friction;
            let app = App::new(fastball, None, ColorMode::Indexed, Rect::new(0, 0, 80, 24));
            let view = Impact::of(&app);
            let impact = view.impact.unwrap();
            let spatial = impact.spatial().unwrap();
            let inks = [
                view.theme.slip.fg,
                view.theme.cursor.fg,
                view.theme.stick.fg,
            ];
            for (w, h) in [(18, 16), (26, 28)] {
                let area = Rect::new(0, 0, w, h);
                for k in 0..6 {
                    let cursor = impact.separation_impulse() * f64::from(k) / 6.0;
                    let plane = Plane::new(area, &view, spatial, cursor);
                    let bare = drawn(area, |f| plane.draw(f, &view));
                    let named = drawn(area, |f| {
                        plane.draw(f, &view);
                        plane.name(f, &view);
                    });
                    let mut words = 0;
                    for (x, y) in (0..h).flat_map(|y| (0..w).map(move |x| (x, y))) {
                        let (before, after) = (&bare[(x, y)], &named[(x, y)]);
                        if before != after {
                            words += 1;
                        }
                        let inked = before.symbol() != " " && inks.contains(&Some(before.fg));
                        assert!(
                            !inked || before == after,
                            "μ {friction}, {w}×{h}, p {cursor:.2}: ({x}, {y}) {:?} became {:?}",
                            before.symbol(),
                            after.symbol()
                        );
                    }
                    // The axes' names at least are written.
                    assert!(words >= 4, "μ {friction}, {w}×{h}: {words} cells of words");
                }
            }
        }
    }
}
