//! A batted flight as SVG: the side view (height against the horizontal
//! distance from the plate), metres on both axes at nearly the same scale
//! (the height is stretched at most [`MAX_STRETCH`]× so that a low liner
//! still shows its shape), with the fence and any other paths (the optimal
//! swing's, a pinned one) beside it; and under it the top view, the field
//! from above at equal scales: foul lines, the fence, each ground track.

use plotters::prelude::*;

use super::{
    FONT, NOW, PictureError, Scale, UnitSystem, draw_legend, draw_title, drawn, emptiest_corner,
    house_style, series_color, tick_label,
};
use analysis::figures::trimmed;
use preset::Fence;

/// A fence's number as the legend gives it: as typed in metres (`trimmed`),
/// to 0.1 in feet (a converted number has no short form of its own).
fn trimmed_to(v: f64, unit: &str) -> String {
    if unit == "m" {
        trimmed(v)
    } else {
        format!("{v:.1}")
    }
}

/// How much taller than true a metre of height may be drawn.
pub const MAX_STRETCH: f64 = 2.0;

/// One path: its legend, its side view's points (horizontal distance from
/// the plate, height) and its ground track's (x toward centre field, z
/// toward right field), in metres. An empty ground track is not drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct FlightPath {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub ground: Vec<(f64, f64)>,
}

/// What to draw: the first path is the flight the title describes.
#[derive(Clone, Debug, PartialEq)]
pub struct TrajectoryPicture {
    /// The preset's name, for the title.
    pub preset: String,
    pub paths: Vec<FlightPath>,
    /// The first path's range, `None` if it did not land.
    pub range: Option<f64>,
    pub apex: f64,
    /// Why there is no range ("did not land within 600.0 s …"), if none.
    pub not_landed: Option<String>,
    pub fence: Option<Fence>,
    /// A park chosen instead of the generic fence: its code and its wall
    /// from pole to pole as (direction from centre field in rad, distance
    /// in m). The side view's `fence` is then its wall where the ball
    /// crosses it, and the view from above draws the wall, not an arc.
    pub park: Option<(String, Vec<(f64, f64)>)>,
}

const WIDTH: u32 = 960;
/// The top view's height (pixels): half the width, as the fair territory
/// out to the fence is half as deep as it is wide.
const TOP_VIEW: u32 = 520;
/// Pixels around the plot: the title, the axes' labels, the margins.
const TITLE: u32 = 40;
const X_LABELS: u32 = 44;
const Y_LABELS: u32 = 56;
const MARGIN: u32 = 12;

/// The trajectory as SVG, in metres.
pub fn trajectory_svg(picture: &TrajectoryPicture) -> Result<String, PictureError> {
    trajectory_svg_in(picture, UnitSystem::Si)
}

/// The trajectory as SVG with its distances in `system`'s unit (m or ft);
/// the paths' names are the caller's, as given.
pub fn trajectory_svg_in(
    picture: &TrajectoryPicture,
    system: UnitSystem,
) -> Result<String, PictureError> {
    let scale = Scale(system);
    let l = |v: f64| scale.len(v);
    let shown = TrajectoryPicture {
        paths: picture
            .paths
            .iter()
            .map(|p| FlightPath {
                name: p.name.clone(),
                points: p.points.iter().map(|&(a, b)| (l(a), l(b))).collect(),
                ground: p.ground.iter().map(|&(a, b)| (l(a), l(b))).collect(),
            })
            .collect(),
        range: picture.range.map(l),
        apex: l(picture.apex),
        fence: picture.fence.map(|f| Fence {
            distance: l(f.distance),
            height: l(f.height),
        }),
        park: picture
            .park
            .as_ref()
            .map(|(code, wall)| (code.clone(), wall.iter().map(|&(d, r)| (d, l(r))).collect())),
        ..picture.clone()
    };
    drawn_in(&shown, scale.len_unit())
}

/// The trajectory as SVG, its numbers already in `unit`.
fn drawn_in(picture: &TrajectoryPicture, unit: &str) -> Result<String, PictureError> {
    let points = || picture.paths.iter().flat_map(|p| p.points.iter());
    let fence = picture.fence;
    let x_max = points()
        .map(|p| p.0)
        .chain(fence.map(|f| f.distance))
        .filter(|v| v.is_finite())
        .fold(1.0_f64, f64::max)
        * 1.04;
    let x_min = points()
        .map(|p| p.0)
        .filter(|v| v.is_finite())
        .fold(0.0_f64, f64::min);
    let y_max = points()
        .map(|p| p.1)
        .chain(fence.map(|f| f.height))
        .filter(|v| v.is_finite())
        .fold(1.0_f64, f64::max)
        * 1.12;
    // Equal scales, unless that leaves the height too flat to read.
    let plot_width = f64::from(WIDTH - Y_LABELS - 2 * MARGIN);
    let metre = plot_width / (x_max - x_min);
    let true_height = y_max * metre;
    let plot_height = true_height
        .max((true_height * MAX_STRETCH).min(180.0))
        .min(640.0);
    let side_height = TITLE + X_LABELS + 2 * MARGIN + plot_height.round() as u32;
    let tracked = picture.paths.iter().any(|p| !p.ground.is_empty());
    let height = side_height + if tracked { TOP_VIEW } else { 0 };
    let title = match (picture.range, &picture.not_landed) {
        (Some(range), _) => format!(
            "Trajectory — preset {}: range {range:.2} {unit}, apex {:.2} {unit}",
            picture.preset, picture.apex
        ),
        (None, why) => format!(
            "Trajectory — preset {}: no range, the ball {}; apex {:.2} {unit}",
            picture.preset,
            why.as_deref().unwrap_or("did not land"),
            picture.apex
        ),
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, height)).into_drawing_area();
        root.fill(&WHITE).map_err(drawn)?;
        let (side, below) = root.split_vertically(side_height);
        if tracked {
            top_view(&below, picture, unit)?;
        }
        let (top, body) = side.split_vertically(TITLE);
        draw_title(&top, &title, (12, 12), 17)?;
        let mut chart = ChartBuilder::on(&body)
            .margin(MARGIN)
            .x_label_area_size(X_LABELS)
            .y_label_area_size(Y_LABELS)
            .build_cartesian_2d(x_min..x_max, 0.0..y_max)
            .map_err(drawn)?;
        let x_label = tick_label(x_max - x_min);
        let y_label = tick_label(y_max);
        house_style(
            chart
                .configure_mesh()
                .x_desc(format!("distance from the plate ({unit})"))
                .y_desc(format!("y ({unit})"))
                .x_label_formatter(&x_label)
                .y_label_formatter(&y_label),
        )
        .draw()
        .map_err(drawn)?;
        for (k, path) in picture.paths.iter().enumerate() {
            let color = series_color(k);
            chart
                .draw_series(LineSeries::new(
                    path.points.iter().copied(),
                    color.stroke_width(2),
                ))
                .map_err(drawn)?
                .label(path.name.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        if let Some(f) = fence {
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(f.distance, 0.0), (f.distance, f.height)],
                    NOW.stroke_width(4),
                )))
                .map_err(drawn)?
                .label(format!(
                    "{}: {} {unit} out, {} {unit} high",
                    picture
                        .park
                        .as_ref()
                        .map_or("fence".to_owned(), |(code, _)| format!(
                            "{code}'s wall where the ball crosses it"
                        )),
                    trimmed_to(f.distance, unit),
                    trimmed_to(f.height, unit)
                ))
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], NOW.stroke_width(4)));
        }
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let pixels: Vec<(i32, i32)> = points().map(|p| chart.backend_coord(p)).collect();
        let corner = emptiest_corner(
            pixels.into_iter(),
            [xs.start, ys.start, xs.end, ys.end],
            (260, 24 + 18 * (picture.paths.len() as i32 + 1)),
        );
        draw_legend(&mut chart, corner)?;
        root.present().map_err(drawn)?;
    }
    Ok(svg)
}

/// The field from above: x up the page toward centre field, z across it
/// toward right field, at equal scales; the foul lines, the fence (an arc at
/// its distance) and each path's ground track with its landing point.
fn top_view<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    picture: &TrajectoryPicture,
    unit: &str,
) -> Result<(), PictureError> {
    let tracks = || picture.paths.iter().flat_map(|p| p.ground.iter());
    let reach = tracks()
        .map(|&(x, z)| x.hypot(z))
        .chain(picture.fence.map(|f| f.distance))
        .chain(picture.park.iter().flat_map(|(_, w)| w.iter().map(|p| p.1)))
        .filter(|v| v.is_finite())
        .fold(1.0_f64, f64::max)
        * 1.06;
    let behind = tracks().map(|p| p.0).fold(0.0_f64, f64::min) - 0.03 * reach;
    let (title, body) = area.split_vertically(28);
    title
        .draw(&Text::new(
            format!("From above: x toward centre field, z toward right field ({unit})"),
            (12, 6),
            (FONT, 14).into_font(),
        ))
        .map_err(drawn)?;
    // Equal scales: the plot's pixel height over its width is the depth
    // over the width in metres.
    let (width, height) = body.dim_in_pixel();
    let depth = reach - behind;
    let half_width = (depth * f64::from(width) / f64::from(height.max(1)) / 2.0).max(reach * 0.75);
    let mut chart = ChartBuilder::on(&body)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS - 8)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(-half_width..half_width, behind..reach)
        .map_err(drawn)?;
    let label = tick_label(reach);
    house_style(
        chart
            .configure_mesh()
            .x_desc(format!("z ({unit})"))
            .y_desc(format!("x ({unit})"))
            .x_label_formatter(&label)
            .y_label_formatter(&label),
    )
    .draw()
    .map_err(drawn)?;
    // The foul lines, to the edge of the view.
    let line = reach / std::f64::consts::SQRT_2;
    for side in [-1.0, 1.0] {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(0.0, 0.0), (side * line, line)],
                BLACK.mix(0.5).stroke_width(1),
            )))
            .map_err(drawn)?;
    }
    // A park's wall as it stands, else the generic fence's arc.
    let wall: Option<Vec<(f64, f64)>> = match (&picture.park, picture.fence) {
        (Some((_, wall)), _) => Some(wall.clone()),
        (None, Some(f)) => Some(
            (0..=90)
                .map(|k| ((f64::from(k) - 45.0).to_radians(), f.distance))
                .collect(),
        ),
        (None, None) => None,
    };
    if let Some(wall) = wall {
        let arc: Vec<(f64, f64)> = wall
            .iter()
            .map(|&(direction, distance)| (distance * direction.sin(), distance * direction.cos()))
            .collect();
        chart
            .draw_series(std::iter::once(PathElement::new(arc, NOW.stroke_width(3))))
            .map_err(drawn)?;
    }
    for (k, path) in picture.paths.iter().enumerate() {
        let color = series_color(k);
        // Drawn as (z, x): across, then up the page.
        let track: Vec<(f64, f64)> = path.ground.iter().map(|&(x, z)| (z, x)).collect();
        chart
            .draw_series(LineSeries::new(
                track.iter().copied(),
                color.stroke_width(2),
            ))
            .map_err(drawn)?;
        if let Some(&end) = track.last() {
            chart
                .draw_series(std::iter::once(Circle::new(end, 4, color.filled())))
                .map_err(drawn)?;
        }
    }
    Ok(())
}
