//! One of the paper's figures as an SVG line chart: one line per curve of
//! its table (broken where a row has no number, e.g. a flight that did not
//! land), the paper's marked points as red circles with their labels, the
//! current input's value as a grey vertical line, and the paper's stated
//! numbers beside ours under the chart. Figs. 8–12 get the paper's three
//! panels: the optimal range, E_opt and ψ_opt against the swept input.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::surface::{SurfacePicture, surface_svg};
use super::{
    FONT, Labels, MARK, NOW, PictureError, chars_in, drawn, emptiest_corner, padded, series_color,
    sig, tick_label, wrapped,
};
use crate::Scene;
use crate::analysis::figures::{Cell, Figure, FigureData, trimmed};
use crate::model::keys::KEYS;

/// A figure's picture: Fig. 7 as the range surface, the others as line
/// charts. `scene` is the one it was computed for (its input's value is
/// marked); `preset` names it in the title.
pub fn figure_svg(figure: &Figure, scene: &Scene, preset: &str) -> Result<String, PictureError> {
    match figure {
        Figure::Table(data) => table_figure_svg(data, scene, preset),
        Figure::Surface(surface) => surface_svg(&SurfacePicture::figure7(surface, scene, preset)),
    }
}

/// One curve: its legend, its points in row order, and the row of each.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub rows: Vec<usize>,
}

/// The panels of figure `number`: the prefixes of each panel's y columns.
/// The x column is the first but for Fig. 14 (time, one curve per point).
fn panels(number: u32) -> &'static [&'static str] {
    match number {
        3 => &["drag_coefficient"],
        4 => &["lift_coefficient"],
        5 => &["launch_spin_mu"],
        6 => &["launch_angle_mu"],
        8..=12 => &["range", "undercut", "swing_angle"],
        14 => &["drag_coefficient"],
        // Fig. 13: range against E.
        _ => &["range"],
    }
}

/// The x column of `data`.
fn x_column(data: &FigureData) -> usize {
    let key = if data.number == 14 { "time" } else { "" };
    data.columns.iter().position(|c| c.key == key).unwrap_or(0)
}

fn number(row: &[Cell], k: usize) -> Option<f64> {
    match row[k] {
        Cell::Num(v) if v.is_finite() => Some(v),
        _ => None,
    }
}

/// The curves whose y column starts with `prefix`, against the x column;
/// Fig. 14's rows split into one curve per flight (A, B). Rows without both
/// numbers are left out.
pub fn curves(data: &FigureData, prefix: &str) -> Vec<Curve> {
    let x = x_column(data);
    let split = (data.number == 14)
        .then(|| data.columns.iter().position(|c| c.key == "point"))
        .flatten();
    let mut curves: Vec<Curve> = Vec::new();
    for (k, column) in data.columns.iter().enumerate() {
        if k == x || !column.key.starts_with(prefix) {
            continue;
        }
        // The legend: what tells the curves apart (μ = 0.35), else the heading.
        let name = column
            .head
            .rsplit_once(") ")
            .map_or(column.head.clone(), |(_, rest)| rest.to_owned());
        let first = curves.len();
        for (r, row) in data.rows.iter().enumerate() {
            let (Some(px), Some(py)) = (number(row, x), number(row, k)) else {
                continue;
            };
            let label = match split.map(|s| &row[s]) {
                Some(Cell::Text(t)) => format!("{} {t}", axis_title(&column.head)),
                _ => name.clone(),
            };
            match curves[first..].iter_mut().find(|c| c.name == label) {
                Some(curve) => {
                    curve.points.push((px, py));
                    curve.rows.push(r);
                }
                None => curves.push(Curve {
                    name: label,
                    points: vec![(px, py)],
                    rows: vec![r],
                }),
            }
        }
    }
    curves
}

/// A column's heading up to its unit: `ω_bf (rad/s)`.
fn axis_title(head: &str) -> String {
    head.find(')')
        .map_or(head.to_owned(), |end| head[..=end].to_owned())
}

/// The marked rows of `data`: (row, label).
fn marks(data: &FigureData) -> Vec<(usize, String)> {
    let Some(m) = data.columns.iter().position(|c| c.key == "mark") else {
        return Vec::new();
    };
    data.rows
        .iter()
        .enumerate()
        .filter_map(|(r, row)| match &row[m] {
            Cell::Text(t) if !t.is_empty() => Some((r, t.clone())),
            _ => None,
        })
        .collect()
}

/// Whether a mark's words name `curve` ("cusp μ = 0.35" names "μ = 0.35"
/// but not "μ = 0.3").
fn names(mark: &str, curve: &str) -> bool {
    // The columns write "μ=0.35", the marks "μ = 0.35".
    let (mark, curve) = (mark.replace(' ', ""), curve.replace(' ', ""));
    mark.match_indices(&curve).any(|(at, _)| {
        !mark[at + curve.len()..]
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_digit() || c == '.')
    })
}

/// The current value of the input the x column sweeps, if it is an input.
fn current_value(data: &FigureData, scene: &Scene) -> Option<f64> {
    let x_key = &data.columns[x_column(data)].key;
    KEYS.iter()
        .find(|key| {
            key.name.replace('.', "_") == *x_key || key.name.ends_with(&format!(".{x_key}"))
        })
        .map(|key| (key.get)(scene))
}

/// The lines under the chart: the paper's numbers beside ours, then the notes.
fn notes(data: &FigureData) -> Vec<String> {
    let mut lines: Vec<String> = data
        .comparisons
        .iter()
        .map(|c| {
            format!(
                "{}: paper {} · ours {} {}",
                c.what,
                trimmed(c.paper),
                sig(c.ours, 4),
                c.unit
            )
        })
        .collect();
    lines.extend(data.notes.iter().cloned());
    lines
}

const WIDTH: u32 = 960;
const PANEL_HEIGHT: u32 = 380;
const LINE: u32 = 18;

/// A figure with a table (every figure but 7) as an SVG line chart.
pub fn table_figure_svg(
    data: &FigureData,
    scene: &Scene,
    preset: &str,
) -> Result<String, PictureError> {
    let prefixes = panels(data.number);
    let notes = notes(data);
    let title = wrapped(
        &format!("Fig. {} (preset {preset}): {}", data.number, data.title),
        chars_in(WIDTH - 24, 17.0),
    );
    let head = (title.len() as u32 + 1) * (LINE + 4) + 12;
    let foot = LINE * notes.len() as u32 + 10;
    let height = head + PANEL_HEIGHT * prefixes.len() as u32 + foot;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, height)).into_drawing_area();
        root.fill(&WHITE).map_err(drawn)?;
        let (top, rest) = root.split_vertically(head);
        let (body, bottom) = rest.split_vertically(PANEL_HEIGHT * prefixes.len() as u32);
        let mut y = 8;
        for line in title {
            top.draw(&Text::new(
                line,
                (12, y),
                (FONT, 17).into_font().style(FontStyle::Bold),
            ))
            .map_err(drawn)?;
            y += LINE as i32 + 4;
        }
        // The conditions without the preset's name, which the line above gives.
        let conditions = data
            .conditions
            .split_once(": ")
            .map_or(data.conditions.as_str(), |(_, rest)| rest);
        top.draw(&Text::new(
            conditions.to_owned(),
            (12, y),
            (FONT, 12).into_font().color(&NOW),
        ))
        .map_err(drawn)?;
        for (k, line) in notes.iter().enumerate() {
            bottom
                .draw(&Text::new(
                    line.clone(),
                    (12, 4 + (LINE * k as u32) as i32),
                    (FONT, 13),
                ))
                .map_err(drawn)?;
        }
        let now = current_value(data, scene);
        let marks = marks(data);
        for (panel, prefix) in body.split_evenly((prefixes.len(), 1)).iter().zip(prefixes) {
            draw_panel(panel, data, prefix, now, &marks)?;
        }
        root.present().map_err(drawn)?;
    }
    Ok(svg)
}

/// One panel: the curves of `prefix` against the x column.
fn draw_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    data: &FigureData,
    prefix: &str,
    now: Option<f64>,
    marks: &[(usize, String)],
) -> Result<(), PictureError> {
    let curves = curves(data, prefix);
    let points = || curves.iter().flat_map(|c| c.points.iter());
    let (x0, x1) = padded(points().map(|p| p.0), 0.0);
    let (y0, y1) = padded(points().map(|p| p.1), 0.06);
    let x_head = axis_title(&data.columns[x_column(data)].head);
    let y_head = data
        .columns
        .iter()
        .find(|c| c.key.starts_with(prefix))
        .map_or(String::new(), |c| axis_title(&c.head));
    let mut chart = ChartBuilder::on(area)
        .margin_left(12)
        .margin_right(24)
        .margin_top(8)
        .x_label_area_size(44)
        .y_label_area_size(72)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(drawn)?;
    let x_label = tick_label(x1 - x0);
    let y_label = tick_label(y1 - y0);
    chart
        .configure_mesh()
        .x_desc(x_head)
        .y_desc(y_head)
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .axis_desc_style((FONT, 14))
        .label_style((FONT, 12))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(215, 215, 215))
        .draw()
        .map_err(drawn)?;
    for (k, curve) in curves.iter().enumerate() {
        let color = series_color(k);
        // A gap in the rows (a flight that did not land) breaks the line.
        let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
        let mut last_row = None;
        for (&point, &row) in curve.points.iter().zip(&curve.rows) {
            match pieces.last_mut() {
                Some(piece) if last_row == Some(row - 1) => piece.push(point),
                _ => pieces.push(vec![point]),
            }
            last_row = Some(row);
        }
        for (p, piece) in pieces.into_iter().enumerate() {
            let series = chart
                .draw_series(LineSeries::new(piece, color.stroke_width(2)))
                .map_err(drawn)?;
            if p == 0 && curves.len() > 1 {
                series.label(curve.name.clone()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            }
        }
    }
    if let Some(v) = now.filter(|v| (x0..=x1).contains(v)) {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(v, y0), (v, y1)],
                NOW.stroke_width(1),
            )))
            .map_err(drawn)?
            .label(format!("now: {}", sig(v, 4)))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], NOW.stroke_width(1)));
    }
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let plot = [xs.start, ys.start, xs.end, ys.end];
    let mut labels = Labels::new();
    // Each mark on the curves it names, or on every curve if it names none.
    for (row, label) in marks {
        let named: Vec<&Curve> = curves.iter().filter(|c| names(label, &c.name)).collect();
        let on = if named.is_empty() {
            curves.iter().collect()
        } else {
            named
        };
        for curve in on {
            let Some(k) = curve.rows.iter().position(|r| r == row) else {
                continue;
            };
            let point = curve.points[k];
            let (offset, right) = labels.place(chart.backend_coord(&point), label, plot);
            let style = (FONT, Labels::SIZE).into_font().color(&MARK).pos(Pos::new(
                if right { HPos::Right } else { HPos::Left },
                VPos::Top,
            ));
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(point)
                        + Circle::new((0, 0), 5, MARK.stroke_width(2))
                        + Text::new(label.clone(), offset, style),
                ))
                .map_err(drawn)?;
        }
    }
    if curves.len() > 1 || now.is_some_and(|v| (x0..=x1).contains(&v)) {
        let pixels: Vec<(i32, i32)> = points().map(|p| chart.backend_coord(p)).collect();
        let corner = emptiest_corner(
            pixels.into_iter(),
            plot,
            (220, 24 + 18 * curves.len() as i32),
        );
        chart
            .configure_series_labels()
            .position(corner)
            .label_font((FONT, 12))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .draw()
            .map_err(drawn)?;
    }
    Ok(())
}
