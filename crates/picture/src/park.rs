//! A park seen from above: the foul lines, the fence from pole to pole
//! drawn in one colour per wall height (thicker for taller walls), and the
//! distances down the lines and to centre, in metres on equal axes.

use plotters::prelude::*;

use super::{
    FONT, NOW, PictureError, Scale, UnitSystem, draw_legend, draw_title, drawn, house_style,
    series_color, tick_label,
};
use model::park::{FOUL_LINE, Park};

const SIZE: u32 = 820;
const TITLE: u32 = 40;
const LABELS: u32 = 48;
const MARGIN: u32 = 14;

/// The park's outline as SVG, its distances and walls in `system`'s unit
/// (m or ft).
pub fn park_svg_in(park: &Park, system: UnitSystem) -> Result<String, PictureError> {
    let scale = Scale(system);
    let (l, unit) = (|m: f64| scale.len(m), scale.len_unit());
    let points = park.fence.points();
    // Ground coordinates: across (toward right field) and out (toward centre).
    let ground = |direction: f64, distance: f64| {
        (l(distance) * direction.sin(), l(distance) * direction.cos())
    };
    let reach = l(points.iter().map(|p| p.distance).fold(1.0, f64::max)) * 1.06;
    let half = reach * FOUL_LINE.sin();
    let (x_range, y_range) = (-half..half, -0.08 * reach..reach);
    let mut heights: Vec<f64> = points.iter().map(|p| p.height).collect();
    heights.sort_by(f64::total_cmp);
    heights.dedup();
    let [left, center, right] = park.fence.lines_and_center();
    let title = format!(
        "{} ({}): {:.1} {unit} down the left-field line, {:.1} {unit} to centre, {:.1} {unit} down the right",
        park.name,
        park.code,
        l(left.distance),
        l(center.distance),
        l(right.distance)
    );
    let mut svg = String::new();
    {
        let plot = SIZE - LABELS - 2 * MARGIN;
        let height = TITLE
            + LABELS
            + 2 * MARGIN
            + (f64::from(plot) * (y_range.end - y_range.start) / (2.0 * half)).round() as u32;
        let root = SVGBackend::with_string(&mut svg, (SIZE, height)).into_drawing_area();
        root.fill(&WHITE).map_err(drawn)?;
        let (top, body) = root.split_vertically(TITLE);
        draw_title(&top, &title, (12, 12), 16)?;
        let mut chart = ChartBuilder::on(&body)
            .margin(MARGIN)
            .x_label_area_size(LABELS)
            .y_label_area_size(LABELS)
            .build_cartesian_2d(x_range.clone(), y_range.clone())
            .map_err(drawn)?;
        let label = tick_label(2.0 * half);
        house_style(
            chart
                .configure_mesh()
                .x_desc(format!("toward right field ({unit})"))
                .y_desc(format!("toward centre field ({unit})"))
                .x_label_formatter(&label)
                .y_label_formatter(&label),
        )
        .draw()
        .map_err(drawn)?;
        let poles = [
            ground(-FOUL_LINE, left.distance),
            ground(FOUL_LINE, right.distance),
        ];
        chart
            .draw_series(
                poles
                    .iter()
                    .map(|&pole| PathElement::new(vec![(0.0, 0.0), pole], NOW.stroke_width(1))),
            )
            .map_err(drawn)?;
        for (k, &wall) in heights.iter().enumerate() {
            let color = series_color(k);
            let width = 2 + (wall * 0.6).round() as u32;
            let segments = points
                .windows(2)
                .filter(|w| w[0].height == wall && w[1].direction > w[0].direction)
                .map(move |w| {
                    PathElement::new(
                        vec![
                            ground(w[0].direction, w[0].distance),
                            ground(w[1].direction, w[1].distance),
                        ],
                        color.stroke_width(width),
                    )
                });
            chart
                .draw_series(segments)
                .map_err(drawn)?
                .label(format!("wall {:.1} {unit} high", l(wall)))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(width))
                });
        }
        let marks = [
            (-FOUL_LINE, left.distance),
            (0.0, center.distance),
            (FOUL_LINE, right.distance),
        ];
        chart
            .draw_series(marks.iter().map(|&(d, r)| {
                let dx = if d < 0.0 {
                    6
                } else if d > 0.0 {
                    -70
                } else {
                    -24
                };
                EmptyElement::at(ground(d, r))
                    + Text::new(
                        format!("{:.1} {unit}", l(r)),
                        (dx, 8),
                        (FONT, 13).into_font(),
                    )
            }))
            .map_err(drawn)?;
        draw_legend(&mut chart, plotters::chart::SeriesLabelPosition::LowerRight)?;
        root.present().map_err(drawn)?;
    }
    Ok(svg)
}
