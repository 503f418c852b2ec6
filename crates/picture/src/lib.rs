//! Pictures as SVG text: the paper's figures, the range surface (Fig. 7), a
//! trajectory and the work–precision diagram, drawn with plotters' SVG
//! backend only. No fonts are read and no C library is linked: text goes out
//! as `<text>` for the viewer to set, its width estimated for the layout.
//!
//! UI-free and I/O-free: every function returns the SVG as a `String`; the
//! command line and the explorer write it (atomically, with
//! [`preset::atomic_file::write`]).

mod bench;
mod figure;
mod impact;
mod park;
mod surface;
mod trajectory;

pub use bench::bench_svg;
pub use figure::{figure_svg, table_figure_svg, table_figure_svg_now};
pub use impact::{ImpactPicture, impact_svg_in};
pub use park::park_svg_in;
pub use surface::{SurfacePicture, surface_svg, surface_svg_in};
pub use trajectory::{
    FlightPath, MAX_STRETCH, TrajectoryPicture, trajectory_svg, trajectory_svg_in,
};
pub use units::UnitSystem;

use units::Quantity;

/// A picture's lengths, sizes, angles and ranges in the units asked for:
/// SI (m, rad) by default, or ft, in and ° under `--units imperial`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Scale(UnitSystem);

impl Scale {
    /// A distance (m) in the unit shown.
    fn len(self, m: f64) -> f64 {
        Quantity::Distance.in_system(self.0).show(m)
    }

    /// The distance's unit: "m" or "ft".
    fn len_unit(self) -> &'static str {
        Quantity::Distance.in_system(self.0).symbol
    }

    /// An undercut (m) on the surface's axis: in m, as Table II and the
    /// figures give E (one unit for E everywhere), or in inches.
    fn undercut(self, m: f64) -> f64 {
        Quantity::Size.in_system(self.0).show(m)
    }

    /// The undercut axis' unit: "m" or "in".
    fn undercut_unit(self) -> &'static str {
        Quantity::Size.in_system(self.0).symbol
    }

    /// An angle (rad) in the unit shown.
    fn angle(self, rad: f64) -> f64 {
        Quantity::Angle.in_system(self.0).show(rad)
    }

    /// The angle's unit: "rad" or "°".
    fn angle_unit(self) -> &'static str {
        Quantity::Angle.in_system(self.0).symbol
    }
}

use plotters::chart::{ChartContext, MeshStyle, SeriesLabelPosition};
use plotters::coord::CoordTranslate;
use plotters::coord::Shift;
use plotters::coord::ranged1d::Ranged;
use plotters::prelude::{DrawingArea, DrawingBackend, FontStyle, IntoFont, Text};
use plotters::style::RGBColor;
use plotters::style::{Color, WHITE};

/// Why a picture could not be drawn (plotters' own errors; with a `String`
/// as the target there is no I/O to fail).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("drawing the picture: {0}")]
pub struct PictureError(pub String);

/// Turns any plotters error into a [`PictureError`].
fn drawn<E: std::fmt::Display>(error: E) -> PictureError {
    PictureError(error.to_string())
}

/// The font family every text asks for: the viewer's own sans-serif.
const FONT: &str = "sans-serif";

/// A line of a picture's title, in bold `size`-point type at `at` (pixels
/// from `area`'s top left).
fn draw_title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    line: &str,
    at: (i32, i32),
    size: u32,
) -> Result<(), PictureError> {
    let font = (FONT, size).into_font().style(FontStyle::Bold);
    area.draw(&Text::new(line, at, font)).map_err(drawn)
}

/// Every chart's legend alike, at `position`: a white box over the plot,
/// lightly bordered.
fn draw_legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
) -> Result<(), PictureError> {
    chart
        .configure_series_labels()
        .position(position)
        .label_font((FONT, 12))
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(180, 180, 180))
        .draw()
        .map_err(drawn)
}

/// A line in the `k`-th series' colour, named in the legend.
fn draw_named_line<'a, DB: DrawingBackend + 'a, CT: CoordTranslate<From = (f64, f64)>>(
    chart: &mut ChartContext<'a, DB, CT>,
    k: usize,
    name: &str,
    points: &[(f64, f64)],
) -> Result<(), PictureError> {
    let color = series_color(k);
    chart
        .draw_series(plotters::series::LineSeries::new(
            points.iter().copied(),
            color.stroke_width(2),
        ))
        .map_err(drawn)?
        .label(name)
        .legend(move |(x, y)| {
            plotters::element::PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
        });
    Ok(())
}

/// Every chart's axes alike: the descriptions' and labels' fonts and the
/// grid's two greys (the finer lines lighter).
fn house_style<'m, 'a, 'b, X: Ranged, Y: Ranged, DB: DrawingBackend>(
    mesh: &'m mut MeshStyle<'a, 'b, X, Y, DB>,
) -> &'m mut MeshStyle<'a, 'b, X, Y, DB> {
    mesh.axis_desc_style((FONT, 14))
        .label_style((FONT, 12))
        .light_line_style(RGBColor(240, 240, 240))
        .bold_line_style(RGBColor(215, 215, 215))
}

/// Okabe–Ito: told apart with any colour vision and in greyscale print.
const SERIES: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
];

/// The colour of the `k`-th series.
fn series_color(k: usize) -> RGBColor {
    SERIES[k % SERIES.len()]
}

/// Marked points (the paper's A, B, kinks, the optimum).
const MARK: RGBColor = RGBColor(200, 0, 0);
/// The current input's value and the current swing.
const NOW: RGBColor = RGBColor(90, 90, 90);

/// The most decimals a tick label or note gives ([`units::sig`]).
const MOST_DECIMALS: i32 = 8;

/// The smallest and largest of `values` (finite ones only), widened by
/// `pad` of the span on each side, and never empty: a flat series gets a
/// span of its own size (or 1) so that plotters has an axis to draw.
fn padded(values: impl IntoIterator<Item = f64>, pad: f64) -> (f64, f64) {
    let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.into_iter().filter(|v| v.is_finite()) {
        low = low.min(v);
        high = high.max(v);
    }
    if low > high {
        return (0.0, 1.0);
    }
    if high - low <= 1e-12 * low.abs().max(high.abs()).max(1e-300) {
        let half = 0.5 * low.abs().max(1.0);
        return (low - half, high + half);
    }
    let margin = pad * (high - low);
    (low - margin, high + margin)
}

/// Tick labels for an axis spanning `span`: as many decimals as a tenth of
/// the span needs, and no "-0".
fn tick_label(span: f64) -> impl Fn(&f64) -> String {
    let decimals = if span > 0.0 && span.is_finite() {
        (1 - span.log10().floor() as i32).clamp(0, 8) as usize
    } else {
        3
    };
    move |v: &f64| units::fixed(*v, decimals)
}

/// `text` cut into lines of at most `width` characters at spaces.
fn wrapped(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    lines.push(line);
    lines
}

/// Characters of a `size` px text that fit in `pixels` (a sans-serif
/// character is about 0.55 em wide; no font is read to measure it).
fn chars_in(pixels: u32, size: f64) -> usize {
    (f64::from(pixels) / (0.58 * size)) as usize
}

/// Labels placed one by one beside their points so that none overlaps one
/// placed before, with widths estimated as in [`chars_in`].
struct Labels {
    placed: Vec<[i32; 4]>,
}

impl Labels {
    const SIZE: f64 = 12.0;

    fn new() -> Labels {
        Labels { placed: Vec::new() }
    }

    /// Where to put `text` for a point drawn at pixel `at` inside the
    /// plotting area `area` (left, top, right, bottom): an offset from the
    /// point and whether the text ends there (right-aligned).
    fn place(&mut self, at: (i32, i32), text: &str, area: [i32; 4]) -> ((i32, i32), bool) {
        self.place_clear(at, text, area, 0)
    }

    /// Keeps later labels off a marker of `radius` pixels drawn at `at`.
    fn block(&mut self, at: (i32, i32), radius: i32) {
        self.placed
            .push([at.0 - radius, at.1 - radius, at.0 + radius, at.1 + radius]);
    }

    /// As [`Labels::place`], `clear` pixels further from the point on each
    /// side (for a big marker, so that its label does not crowd it).
    fn place_clear(
        &mut self,
        at: (i32, i32),
        text: &str,
        area: [i32; 4],
        clear: i32,
    ) -> ((i32, i32), bool) {
        let width = (text.chars().count() as f64 * 0.58 * Self::SIZE) as i32;
        let height = Self::SIZE as i32 + 2;
        let (dx, up, down) = (8 + clear, -height - 4 - clear, 6 + clear);
        let candidates = [
            (dx, up, false),
            (dx, down, false),
            (-dx, up, true),
            (-dx, down, true),
            (dx, up - height - 2, false),
            (-dx, up - height - 2, true),
            (dx, down + height + 2, false),
            (-dx, down + height + 2, true),
        ];
        let rect = |(dx, dy, right): (i32, i32, bool)| {
            let left = if right { at.0 + dx - width } else { at.0 + dx };
            [left, at.1 + dy, left + width, at.1 + dy + height]
        };
        let fits =
            |r: &[i32; 4]| r[0] >= area[0] && r[2] <= area[2] && r[1] >= area[1] && r[3] <= area[3];
        let free = |r: &[i32; 4]| {
            self.placed
                .iter()
                .all(|p| r[2] <= p[0] || p[2] <= r[0] || r[3] <= p[1] || p[3] <= r[1])
        };
        let choice = candidates
            .iter()
            .copied()
            .find(|&c| fits(&rect(c)) && free(&rect(c)))
            .or_else(|| candidates.iter().copied().find(|&c| fits(&rect(c))))
            .unwrap_or(candidates[0]);
        self.placed.push(rect(choice));
        ((choice.0, choice.1), choice.2)
    }
}

/// The corner of a plot where the fewest of `points` (pixels) fall inside a
/// box of `size`, for the legend; `area` is the plot (left, top, right,
/// bottom).
fn emptiest_corner(
    points: impl Iterator<Item = (i32, i32)>,
    area: [i32; 4],
    size: (i32, i32),
) -> plotters::chart::SeriesLabelPosition {
    use plotters::chart::SeriesLabelPosition::{LowerLeft, LowerRight, UpperLeft, UpperRight};
    let corners = [
        (
            UpperRight,
            [area[2] - size.0, area[1], area[2], area[1] + size.1],
        ),
        (
            UpperLeft,
            [area[0], area[1], area[0] + size.0, area[1] + size.1],
        ),
        (
            LowerRight,
            [area[2] - size.0, area[3] - size.1, area[2], area[3]],
        ),
        (
            LowerLeft,
            [area[0], area[3] - size.1, area[0] + size.0, area[3]],
        ),
    ];
    let mut counts = [0usize; 4];
    for (x, y) in points {
        for (k, (_, b)) in corners.iter().enumerate() {
            if x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3] {
                counts[k] += 1;
            }
        }
    }
    let best = (0..4).min_by_key(|&k| counts[k]).unwrap_or(0);
    corners[best].0.clone()
}
