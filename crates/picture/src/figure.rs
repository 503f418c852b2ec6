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
    FONT, Labels, MARK, MOST_DECIMALS, NOW, PictureError, chars_in, draw_legend, draw_title, drawn,
    emptiest_corner, house_style, padded, series_color, tick_label, wrapped,
};
use analysis::figures::curves::{
    self, axis_title, current_value, marked_points, panels, x_column, y_title,
};
use analysis::figures::{Figure, FigureData, stated, trimmed};
use model::scene::Scene;

/// A figure's picture: Fig. 7 as the range surface, the others as line
/// charts. `scene` is the one it was computed for (its input's value is
/// marked); `preset` names it in the title.
pub fn figure_svg(figure: &Figure, scene: &Scene, preset: &str) -> Result<String, PictureError> {
    match figure {
        Figure::Table(data) => table_figure_svg(data, scene, preset),
        Figure::Surface(surface) => surface_svg(&SurfacePicture::figure7(surface, scene, preset)),
    }
}

/// A mark's label longer than this is drawn as its number beside the
/// point and written out under the chart, so that no long text runs across
/// the curves or into another mark's.
const SHORT_MARK: usize = 16;

/// The long marks' labels, each once, in the order of the rows: the mark
/// numbered `k + 1` beside its point is the `k`-th.
fn long_marks(data: &FigureData) -> Vec<String> {
    let Some(m) = data.columns.iter().position(|c| c.key == "mark") else {
        return Vec::new();
    };
    let mut long: Vec<String> = Vec::new();
    for row in &data.rows {
        if let analysis::figures::Cell::Text(label) = &row[m]
            && label.chars().count() > SHORT_MARK
            && !long.contains(label)
        {
            long.push(label.clone());
        }
    }
    long
}

/// What to write beside a mark's point: its label, or its number among
/// `long` marks.
fn mark_text(label: &str, long: &[String]) -> String {
    long.iter()
        .position(|l| l == label)
        .map_or(label.to_owned(), |k| format!("{}", k + 1))
}

/// The lines under the chart: the long marks by number, the paper's
/// numbers beside ours, then the notes; each wrapped to the picture's width.
fn notes(data: &FigureData) -> Vec<String> {
    let marks = long_marks(data)
        .into_iter()
        .enumerate()
        .map(|(k, label)| format!("{}: {label}", k + 1));
    marks
        .chain(notes_unwrapped(data))
        .flat_map(|line| wrapped(&line, chars_in(WIDTH - 24, 13.0)))
        .collect()
}

fn notes_unwrapped(data: &FigureData) -> Vec<String> {
    let mut lines: Vec<String> = data
        .comparisons
        .iter()
        .map(|c| {
            format!(
                "{}: paper {} · ours {}",
                c.what,
                trimmed(c.paper),
                stated::with_unit(&units::sig(c.ours, 4, MOST_DECIMALS), c.unit)
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
    table_figure_svg_now(data, current_value(data, scene), preset)
}

/// As [`table_figure_svg`], with the current input's value `now` given in
/// the units of `data`'s x column: for a table already converted to the
/// units shown (its headings, title and numbers), as `--units imperial` asks.
pub fn table_figure_svg_now(
    data: &FigureData,
    now: Option<f64>,
    preset: &str,
) -> Result<String, PictureError> {
    let prefixes = panels(data.number);
    let notes = notes(data);
    let long = long_marks(data);
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
            draw_title(&top, &line, (12, y), 17)?;
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
        for (panel, prefix) in body.split_evenly((prefixes.len(), 1)).iter().zip(prefixes) {
            draw_panel(panel, data, prefix, now, &long)?;
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
    long: &[String],
) -> Result<(), PictureError> {
    let curves = curves::curves(data, prefix);
    let points = || curves.iter().flat_map(|c| c.points.iter());
    let (x0, x1) = padded(points().map(|p| p.0), 0.0);
    let (y0, y1) = padded(points().map(|p| p.1), 0.06);
    let x_head = axis_title(&data.columns[x_column(data)].head);
    let y_head = y_title(data, prefix);
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
    house_style(
        chart
            .configure_mesh()
            .x_desc(x_head.as_str())
            .y_desc(y_head)
            .x_label_formatter(&x_label)
            .y_label_formatter(&y_label),
    )
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
        // Dashed and 2 px wide, so that it shows on the axis too (a value at
        // the window's edge) and its legend swatch is a line one sees.
        let (name, unit) = x_head
            .split_once(" (")
            .map_or((x_head.as_str(), ""), |(n, u)| (n, u.trim_end_matches(')')));
        let gap = if unit == "°" || unit.is_empty() {
            ""
        } else {
            " "
        };
        chart
            .draw_series((0..40).step_by(2).map(|k| {
                let at = |k: i32| y0 + (y1 - y0) * f64::from(k) / 40.0;
                PathElement::new(vec![(v, at(k)), (v, at(k + 1))], NOW.stroke_width(2))
            }))
            .map_err(drawn)?
            .label(format!(
                "now: {name} = {}{gap}{unit}",
                units::sig(v, 4, MOST_DECIMALS)
            ))
            .legend(|(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (6, 0)], NOW.stroke_width(2))
                    + PathElement::new(vec![(10, 0), (16, 0)], NOW.stroke_width(2))
                    + PathElement::new(vec![(20, 0), (22, 0)], NOW.stroke_width(2))
            });
    }
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let plot = [xs.start, ys.start, xs.end, ys.end];
    let mut labels = Labels::new();
    // Each mark on the curve it names, or on every curve if it names none.
    for mark in marked_points(data, &curves) {
        let text = mark_text(&mark.label, long);
        let (offset, right) = labels.place(chart.backend_coord(&mark.point), &text, plot);
        let style = (FONT, Labels::SIZE).into_font().color(&MARK).pos(Pos::new(
            if right { HPos::Right } else { HPos::Left },
            VPos::Top,
        ));
        chart
            .draw_series(std::iter::once(
                EmptyElement::at(mark.point)
                    + Circle::new((0, 0), 5, MARK.stroke_width(2))
                    + Text::new(text, offset, style),
            ))
            .map_err(drawn)?;
    }
    if curves.len() > 1 || now.is_some_and(|v| (x0..=x1).contains(&v)) {
        let pixels: Vec<(i32, i32)> = points().map(|p| chart.backend_coord(p)).collect();
        let corner = emptiest_corner(
            pixels.into_iter(),
            plot,
            (220, 24 + 18 * curves.len() as i32),
        );
        draw_legend(&mut chart, corner)?;
    }
    Ok(())
}
