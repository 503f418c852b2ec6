//! The range surface (Fig. 7) as an SVG heatmap: range over (E, ψ) in
//! [`STEPS`] colour steps with their scale beside it, cells where the bat
//! misses or the ball does not land in their own greys, the optimum O, the
//! paper's O and the current swing marked, and the boundary of the cells
//! that reach the fence's distance.

use plotters::prelude::*;

use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{
    FONT, Labels, MARK, MOST_DECIMALS, NOW, PictureError, Scale, UnitSystem, draw_title, drawn,
    house_style, tick_label,
};
use analysis::figures::SurfaceFigure;
use analysis::study::{CellOutcome, Surface};
use model::scene::Scene;

/// Colour steps of the scale: each is 1/STEPS of the surface's span (about
/// 4 m on Fig. 7's window), fine enough to read and coarse enough that a
/// row's cells of one step are drawn as one rectangle.
pub const STEPS: usize = 32;

/// Where the bat misses the ball (|E| ≥ r_b + r_B): no flight at all.
const MISSES: RGBColor = RGBColor(255, 255, 255);
/// Where the ball does not land within its limit: no range.
const UP: RGBColor = RGBColor(150, 150, 150);
const CONTOUR: RGBColor = RGBColor(255, 255, 255);

/// What to draw over the surface.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfacePicture<'a> {
    pub surface: &'a Surface,
    /// First line: what it is and the preset's name.
    pub title: String,
    /// Second line: the inputs it was computed with.
    pub conditions: String,
    /// The current swing (E, ψ).
    pub now: Option<(f64, f64)>,
    /// The optimiser's optimum O: E, ψ, range.
    pub optimum: Option<(f64, f64, f64)>,
    /// The paper's O (Fig. 7): E, ψ, range.
    pub paper: Option<(f64, f64, f64)>,
    /// A range to outline (the fence's distance, m).
    pub level: Option<f64>,
}

impl<'a> SurfacePicture<'a> {
    /// Fig. 7 as `homerun figure 7` computes it.
    pub fn figure7(figure: &'a SurfaceFigure, scene: &Scene, preset: &str) -> SurfacePicture<'a> {
        let o = &figure.optimum;
        SurfacePicture {
            surface: &figure.surface,
            title: format!("Fig. {}: {} — preset {preset}", figure.number, figure.title),
            conditions: figure
                .conditions
                .split_once(": ")
                .map_or(figure.conditions.clone(), |(_, rest)| rest.to_owned()),
            now: Some((scene.bat.undercut, scene.bat.swing_angle)),
            optimum: o.landed.then_some((o.undercut, o.swing_angle, o.range)),
            paper: Some(figure.paper),
            level: None,
        }
    }
}

/// Viridis at nine stops, linearly between them: light for far, dark for
/// short, readable in greyscale.
const VIRIDIS: [(u8, u8, u8); 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];

/// The colour of step `k` of [`STEPS`].
fn step_color(k: usize) -> RGBColor {
    let t = (k as f64 + 0.5) / STEPS as f64 * (VIRIDIS.len() - 1) as f64;
    let i = (t.floor() as usize).min(VIRIDIS.len() - 2);
    let f = t - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// What a cell shows: a colour step, "does not land" or "bat misses".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shade {
    Step(usize),
    Up,
    Misses,
}

impl Shade {
    fn color(self) -> RGBColor {
        match self {
            Shade::Step(k) => step_color(k),
            Shade::Up => UP,
            Shade::Misses => MISSES,
        }
    }
}

/// The span of the landed ranges, if any landed.
fn span(surface: &Surface) -> Option<(f64, f64)> {
    let (low, high) = surface
        .landed_ranges()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| {
            (lo.min(r), hi.max(r))
        });
    (low <= high).then(|| (low, high.max(low + 1e-9)))
}

fn shade(outcome: CellOutcome, (low, high): (f64, f64)) -> Shade {
    match outcome {
        // Nothing produces an uncomputed cell in a finished surface; it has
        // no range either way.
        CellOutcome::BatMisses | CellOutcome::NotComputed => Shade::Misses,
        CellOutcome::NotLanded => Shade::Up,
        CellOutcome::Landed(r) => {
            Shade::Step((((r - low) / (high - low) * STEPS as f64) as usize).min(STEPS - 1))
        }
    }
}

/// The cell's edges (a grid point is a cell's centre).
fn edges(window: (f64, f64), n: usize, i: usize) -> (f64, f64) {
    if n <= 1 {
        return window;
    }
    let step = (window.1 - window.0) / (n - 1) as f64;
    let centre = window.0 + step * i as f64;
    (centre - 0.5 * step, centre + 0.5 * step)
}

const WIDTH: u32 = 960;
const HEIGHT: u32 = 680;
const SCALE_WIDTH: u32 = 130;

/// The range surface as an SVG heatmap, E in m, ψ in rad, ranges in m.
pub fn surface_svg(picture: &SurfacePicture) -> Result<String, PictureError> {
    surface_svg_in(picture, UnitSystem::Si)
}

/// The range surface as an SVG heatmap with its axes, marks and scale in
/// `system`'s units (E in in, ψ in °, ranges in ft under imperial); the
/// title and conditions are the caller's, as given.
pub fn surface_svg_in(
    picture: &SurfacePicture,
    system: UnitSystem,
) -> Result<String, PictureError> {
    let scale = Scale(system);
    let (ex, py) = (|e: f64| scale.undercut(e), |p: f64| scale.angle(p));
    let unit = scale.len_unit();
    let surface = picture.surface;
    let grid = surface.grid;
    let span = span(surface).unwrap_or((0.0, 1.0));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(drawn)?;
        let (top, body) = root.split_vertically(52);
        draw_title(&top, &picture.title, (12, 8), 17)?;
        top.draw(&Text::new(
            picture.conditions.clone(),
            (12, 30),
            (FONT, 12).into_font().color(&NOW),
        ))
        .map_err(drawn)?;
        let (main, colours) = body.split_horizontally(WIDTH - SCALE_WIDTH);
        let (e0, e1) = (
            ex(edges(grid.undercut, grid.columns, 0).0),
            ex(edges(grid.undercut, grid.columns, grid.columns - 1).1),
        );
        let (p0, p1) = (
            py(edges(grid.swing_angle, grid.rows, 0).0),
            py(edges(grid.swing_angle, grid.rows, grid.rows - 1).1),
        );
        // E in m on the axis, as Table II and the figures give it.
        let mut chart = ChartBuilder::on(&main)
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d(e0..e1, p0..p1)
            .map_err(drawn)?;
        let x_label = tick_label(e1 - e0);
        let y_label = tick_label(p1 - p0);
        house_style(
            chart
                .configure_mesh()
                .disable_mesh()
                .x_desc(format!("undercut E ({})", scale.undercut_unit()))
                .y_desc(format!("swing angle ψ ({})", scale.angle_unit()))
                .x_label_formatter(&x_label)
                .y_label_formatter(&y_label),
        )
        .draw()
        .map_err(drawn)?;
        // A row's run of cells of one shade is one rectangle.
        let mut cells = Vec::new();
        for j in 0..grid.rows {
            let (y0, y1) = edges(grid.swing_angle, grid.rows, j);
            let (y0, y1) = (py(y0), py(y1));
            let mut i = 0;
            while i < grid.columns {
                let here = shade(surface.outcome(i, j), span);
                let mut end = i + 1;
                while end < grid.columns && shade(surface.outcome(end, j), span) == here {
                    end += 1;
                }
                let x0 = ex(edges(grid.undercut, grid.columns, i).0);
                let x1 = ex(edges(grid.undercut, grid.columns, end - 1).1);
                cells.push(Rectangle::new([(x0, y0), (x1, y1)], here.color().filled()));
                i = end;
            }
        }
        chart.draw_series(cells).map_err(drawn)?;
        if let Some(level) = picture.level {
            chart
                .draw_series(contour(surface, level).into_iter().map(|segment| {
                    PathElement::new(
                        segment.map(|(e, p)| (ex(e), py(p))).to_vec(),
                        CONTOUR.stroke_width(2),
                    )
                }))
                .map_err(drawn)?;
        }
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let plot = [xs.start, ys.start, xs.end, ys.end];
        let mut labels = Labels::new();
        // Labels stand clear of both markers, each of about this radius.
        const MARKER: i32 = 9;
        let markers = [
            picture.now,
            picture.optimum.map(|(e, psi, _)| (e, psi)),
            picture.paper.map(|(e, psi, _)| (e, psi)),
        ];
        for (e, psi) in markers.into_iter().flatten() {
            labels.block(chart.backend_coord(&(ex(e), py(psi))), MARKER);
        }
        let inside = |e: f64, psi: f64| (e0..=e1).contains(&ex(e)) && (p0..=p1).contains(&py(psi));
        // The current swing as the explorer's ✚, O as a red ring, the paper's O as a triangle.
        if let Some((e, psi)) = picture.now.filter(|&(e, psi)| inside(e, psi)) {
            let at = (ex(e), py(psi));
            let (offset, right) = labels.place_clear(chart.backend_coord(&at), "now", plot, MARKER);
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(at)
                        + Cross::new((0, 0), 6, BLACK.stroke_width(2))
                        + Text::new("now", offset, anchored(BLACK, right)),
                ))
                .map_err(drawn)?;
        }
        if let Some((e, psi, range)) = picture.optimum.filter(|&(e, psi, _)| inside(e, psi)) {
            let at = (ex(e), py(psi));
            let text = format!(
                "O {} {unit}",
                units::sig(scale.len(range), 5, MOST_DECIMALS)
            );
            let (offset, right) = labels.place_clear(chart.backend_coord(&at), &text, plot, MARKER);
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(at)
                        + Circle::new((0, 0), 7, MARK.stroke_width(3))
                        + Text::new(text, offset, anchored(MARK, right)),
                ))
                .map_err(drawn)?;
        }
        if let Some((e, psi, range)) = picture.paper.filter(|&(e, psi, _)| inside(e, psi)) {
            let at = (ex(e), py(psi));
            let text = format!(
                "paper's O {} {unit}",
                units::sig(scale.len(range), 5, MOST_DECIMALS)
            );
            let (offset, right) = labels.place_clear(chart.backend_coord(&at), &text, plot, MARKER);
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(at)
                        + TriangleMarker::new((0, 0), 7, BLACK.stroke_width(2))
                        + Text::new(text, offset, anchored(BLACK, right)),
                ))
                .map_err(drawn)?;
        }
        draw_scale(&colours, surface, span, picture.level, scale)?;
        root.present().map_err(drawn)?;
    }
    Ok(svg)
}

/// A label's style: ending at its point if `right`, else starting there.
fn anchored(color: RGBColor, right: bool) -> TextStyle<'static> {
    (FONT, Labels::SIZE + 1.0)
        .into_font()
        .color(&color)
        .pos(Pos::new(
            if right { HPos::Right } else { HPos::Left },
            VPos::Top,
        ))
}

/// The colour scale: one box per step with its lower range, then the greys.
fn draw_scale(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    surface: &Surface,
    (low, high): (f64, f64),
    level: Option<f64>,
    scale: Scale,
) -> Result<(), PictureError> {
    let (top, box_height, x) = (24, 14, 10);
    let unit = scale.len_unit();
    area.draw(&Text::new(format!("range ({unit})"), (x, 4), (FONT, 13)))
        .map_err(drawn)?;
    let (low, high) = (scale.len(low), scale.len(high));
    let mut y = top;
    // Far at the top, as ψ grows upward.
    for k in (0..STEPS).rev() {
        let from = low + (high - low) * k as f64 / STEPS as f64;
        area.draw(&Rectangle::new(
            [(x, y), (x + 22, y + box_height)],
            step_color(k).filled(),
        ))
        .map_err(drawn)?;
        if k % 4 == 0 || k == STEPS - 1 {
            let text = if k == STEPS - 1 {
                format!("{from:.1}–{high:.1}")
            } else {
                format!("{from:.1}")
            };
            area.draw(&Text::new(text, (x + 28, y + 3), (FONT, 11)))
                .map_err(drawn)?;
        }
        y += box_height;
    }
    let mut extra: Vec<(RGBColor, &str)> = Vec::new();
    if surface.any_not_landed() {
        extra.push((UP, "does not land"));
    }
    if surface
        .outcomes()
        .iter()
        .any(|c| matches!(c, CellOutcome::BatMisses | CellOutcome::NotComputed))
    {
        extra.push((MISSES, "bat misses"));
    }
    y += 10;
    for (color, what) in extra {
        area.draw(&Rectangle::new(
            [(x, y), (x + 22, y + box_height)],
            color.filled(),
        ))
        .map_err(drawn)?;
        area.draw(&Rectangle::new(
            [(x, y), (x + 22, y + box_height)],
            RGBColor(120, 120, 120),
        ))
        .map_err(drawn)?;
        area.draw(&Text::new(what, (x + 28, y + 3), (FONT, 11)))
            .map_err(drawn)?;
        y += box_height + 4;
    }
    if let Some(level) = level {
        area.draw(&Text::new(
            format!(
                "white: {} {unit} (fence)",
                units::sig(scale.len(level), 4, MOST_DECIMALS)
            ),
            (x, y + 6),
            (FONT, 11),
        ))
        .map_err(drawn)?;
    }
    Ok(())
}

/// The boundary between cells that reach `level` and landed cells that do
/// not, along the cells' edges: each segment in (E, ψ), in m and rad.
fn contour(surface: &Surface, level: f64) -> Vec<[(f64, f64); 2]> {
    let grid = surface.grid;
    // Landed cells only: a missing or unlanded neighbour draws no boundary.
    let reaches = |i: usize, j: usize| surface.get(i, j).map(|r| r >= level);
    let mut segments = Vec::new();
    for j in 0..grid.rows {
        let (y0, y1) = edges(grid.swing_angle, grid.rows, j);
        for i in 0..grid.columns {
            let (x0, x1) = edges(grid.undercut, grid.columns, i);
            let Some(here) = reaches(i, j) else { continue };
            if i + 1 < grid.columns && reaches(i + 1, j).is_some_and(|r| r != here) {
                segments.push([(x1, y0), (x1, y1)]);
            }
            if j + 1 < grid.rows && reaches(i, j + 1).is_some_and(|r| r != here) {
                segments.push([(x0, y1), (x1, y1)]);
            }
        }
    }
    segments
}
