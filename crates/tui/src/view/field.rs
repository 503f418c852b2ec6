//! The field from above (the spray chart): home plate at the bottom
//! centre, centre field up and right field to the right, at equal scales;
//! the foul lines, faint distance rings, the fence, each ground track (now,
//! best, pin) with the landing point, and the wind as an arrow.

use std::f64::consts::FRAC_PI_4;

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Axis, Block, Chart, Dataset};

use super::chart::{self, Ticks};
use super::pane_views::Field;
use super::pane_views::InUnits;
use crate::layout::FieldMap;
use units::Quantity;

/// Points along an arc, per radian: smooth in braille at any pane size.
const ARC_POINTS: usize = 120;

pub fn draw(frame: &mut Frame, area: Rect, view: &Field) {
    let map = view.map;
    let k = view.distance(1.0).0;
    // Drawn as (z, x): across the page, then up it.
    let across =
        |track: &[(f64, f64)]| -> Vec<(f64, f64)> { track.iter().map(|&(x, z)| (z, x)).collect() };
    let (now, best) = (across(view.ground), across(view.optimal_ground));
    let pinned = view.pin_ground.map_or(Vec::new(), across);
    let reach = map.x[1].max(map.z[1] * 2f64.sqrt());
    let foul_lines: Vec<Vec<(f64, f64)>> = [-1.0, 1.0]
        .iter()
        .map(|side| vec![(0.0, 0.0), (side * reach, reach)])
        .collect();
    // Rings at round distances in the unit shown, over fair territory.
    let rings = Ticks::new(0.0, k * map.x[1], 4);
    let ring_arcs: Vec<(f64, Vec<(f64, f64)>)> = rings
        .values()
        .into_iter()
        .filter(|r| *r > 0.0)
        .map(|r| (r, arc(|_| Some(r / k), FRAC_PI_4)))
        .collect();
    // A park's wall in runs of one height band each; the preset's fence,
    // the same everywhere, in the fence's colour.
    let walls = view.wall.map(wall_runs);
    let fence = view
        .fence
        .as_ref()
        .filter(|_| walls.is_none())
        .map(|f| arc(|d| f.distance_at(d), FRAC_PI_4));
    let flight = view.flight;
    let landing = match now.last() {
        Some(&end) if flight.landed => vec![end],
        _ => Vec::new(),
    };
    let wind = wind_arrow(view, &map);

    let (now_mark, best_mark, pin_mark) =
        (view.theme.path(0), view.theme.path(1), view.theme.path(2));
    let mut datasets: Vec<Dataset> = Vec::new();
    for line in &foul_lines {
        datasets.push(chart::line(view.theme.dim, line));
    }
    for (_, ring) in &ring_arcs {
        datasets.push(chart::line(view.theme.dim, ring));
    }
    if let Some(fence) = &fence {
        datasets.push(chart::line(view.theme.fence, fence));
    }
    for (band, run) in walls.iter().flatten() {
        datasets.push(chart::curve(
            view.theme.wall_marker(*band),
            view.theme.walls[*band],
            run,
        ));
    }
    if let Some((arrow, _, _)) = &wind {
        datasets.push(chart::line(view.theme.apex, arrow));
    }
    if !best.is_empty() {
        datasets.push(chart::curve(best_mark.0, view.theme.optimal, &best));
    }
    if !pinned.is_empty() {
        datasets.push(chart::curve(pin_mark.0, view.theme.pinned, &pinned));
    }
    datasets.push(chart::curve(now_mark.0, view.theme.swing, &now));
    datasets.push(chart::points(Marker::Block, view.theme.landing, &landing));

    let block = titled_block(
        view,
        area,
        (!best.is_empty(), !pinned.is_empty()),
        walls.is_some(),
    );
    frame.render_widget(block, area);
    // No labels on either axis: the chart's graph is the whole plot.
    let chart = Chart::new(datasets)
        .x_axis(Axis::default().bounds(map.z))
        .y_axis(Axis::default().bounds(map.x))
        .legend_position(None);
    frame.render_widget(chart, map.plot);

    write_labels(frame, (&map, k), view, &ring_arcs, wind.as_ref());
}

/// The pane's border with its title ("Field 134.70 m, centre field"), the
/// paths' legend where it fits (`shown`: whether best and the pin are
/// drawn) and, under a park's wall, the wall's key.
fn titled_block(view: &Field, area: Rect, shown: (bool, bool), walls: bool) -> Block<'static> {
    let (now_mark, best_mark, pin_mark) =
        (view.theme.path(0), view.theme.path(1), view.theme.path(2));
    let mut legend = vec![Span::styled(
        format!("{} now ", now_mark.1),
        view.theme.swing,
    )];
    if shown.0 {
        legend.push(Span::styled(
            format!("{} best ", best_mark.1),
            view.theme.optimal,
        ));
    }
    if shown.1 {
        legend.push(Span::styled(
            format!("{} pin ", pin_mark.1),
            view.theme.pinned,
        ));
    }
    let legend = Line::from(legend);
    let flight = view.flight;
    let numbers = if flight.landed {
        format!(
            "{}, {} ",
            view.range_text(flight.range),
            crate::shown::direction_text(view.units, flight.direction)
        )
    } else {
        "does not land ".to_owned()
    };
    let title = format!(" Field {numbers}");
    let room = area.width.saturating_sub(2) as usize;
    let mut block = Block::bordered().title(Span::styled(title.clone(), view.theme.title));
    if title.chars().count() + legend.width() <= room {
        block = block.title_top(legend.right_aligned());
    }
    if walls {
        let key = wall_legend(view);
        if key.width() <= room {
            block = block.title_bottom(key);
        }
    }
    block
}

/// The rings' distances just left of the left-field line (`k`: the unit
/// shown per metre), the wind's speed under its arrow.
fn write_labels(
    frame: &mut Frame,
    (map, k): (&FieldMap, f64),
    view: &Field,
    ring_arcs: &[(f64, Vec<(f64, f64)>)],
    wind: Option<&WindArrow>,
) {
    let bounds = (map.z, map.x);
    let buf = frame.buffer_mut();
    let mut write = |point: (f64, f64), text: &str, style: Style, left: bool| {
        if let Some((column, row)) = chart::cell_of(map.plot, bounds, point, Marker::Braille) {
            let width = text.chars().count() as u16;
            let start = if left {
                column.checked_sub(width + 1)
            } else {
                Some(column + 1)
            };
            if let Some(start) = start.filter(|s| *s >= map.plot.x && s + width <= map.plot.right())
            {
                buf.set_string(start, row, text, style);
                return true;
            }
        }
        false
    };
    // The nearest ring says the unit ("100 ft"), as an axis would, where
    // it fits; the others their number alone.
    let unit = view.unit(Quantity::Distance).symbol;
    for (n, (r, _)) in ring_arcs.iter().enumerate() {
        let d = r / k;
        let at = (-d * FRAC_PI_4.sin(), d * FRAC_PI_4.cos());
        let bare = format!("{r:.0}");
        if !(n == 0 && write(at, &format!("{bare} {unit}"), view.theme.dim, true)) {
            write(at, &bare, view.theme.dim, true);
        }
    }
    if let Some((_, tail, label)) = wind {
        write(*tail, label, view.theme.apex, false);
    }
}

/// Points (z, x) along the curve at `distance(direction)` over
/// [−`half_angle`, `half_angle`]: a ring, or the fence (where a per-direction
/// fence has no distance, nothing is drawn).
fn arc(distance: impl Fn(f64) -> Option<f64>, half_angle: f64) -> Vec<(f64, f64)> {
    let n = ((2.0 * half_angle) * ARC_POINTS as f64).ceil() as usize;
    (0..=n)
        .filter_map(|i| {
            let direction = -half_angle + 2.0 * half_angle * i as f64 / n as f64;
            distance(direction).map(|d| (d * direction.sin(), d * direction.cos()))
        })
        .collect()
}

/// The wall heights' bands (ft): up to 8, up to 12, under 20, and 20 or
/// more (Fenway's 37 ft wall in left field, Houston's 25 ft one, the
/// 16 ft scoreboards).
const WALL_BANDS_FT: [f64; 3] = [8.0, 12.0, 20.0];

/// The band of a wall `height` (m) high: 0 to 3.
fn wall_band(height: f64) -> usize {
    let feet = height / units::METRES_PER_FOOT;
    match feet {
        f if f >= WALL_BANDS_FT[2] => 3,
        f if f > WALL_BANDS_FT[1] => 2,
        f if f > WALL_BANDS_FT[0] => 1,
        _ => 0,
    }
}

/// A park's wall from pole to pole as runs of points (z, x) of one height
/// band each; a run ends where the next begins, so the outline is whole.
fn wall_runs(fence: &model::park::Fence) -> Vec<(usize, Vec<(f64, f64)>)> {
    let n = ((2.0 * FRAC_PI_4) * ARC_POINTS as f64).ceil() as usize;
    let mut runs: Vec<(usize, Vec<(f64, f64)>)> = Vec::new();
    // The fence's own corners, where its height steps, and an even spread.
    let mut directions: Vec<f64> = (0..=n)
        .map(|i| -FRAC_PI_4 + 2.0 * FRAC_PI_4 * i as f64 / n as f64)
        .chain(fence.points().iter().map(|p| p.direction))
        .collect();
    directions.sort_by(f64::total_cmp);
    for direction in directions {
        let Some(at) = fence.at(direction) else {
            continue;
        };
        let point = (at.distance * direction.sin(), at.distance * direction.cos());
        let band = wall_band(at.height);
        match runs.last_mut() {
            Some((b, run)) if *b == band => run.push(point),
            last => {
                let joint = last.and_then(|(_, run)| run.last().copied());
                runs.push((band, joint.into_iter().chain([point]).collect()));
            }
        }
    }
    runs
}

/// "wall ≤8 ≤12 <20 ≥20 ft", each band in its own colour and glyph, in
/// the units shown (metres: ≤2.4 ≤3.7 <6.1 ≥6.1 m).
fn wall_legend(view: &Field) -> Line<'static> {
    let unit = view.unit(Quantity::Distance);
    let shown = |feet: f64| {
        let v = unit.show(feet * units::METRES_PER_FOOT);
        analysis::figures::trimmed((v * 10.0).round() / 10.0)
    };
    let [low, mid, high] = WALL_BANDS_FT.map(shown);
    let glyph = |k: usize| match view.theme.wall_marker(k) {
        Marker::Block => "█",
        Marker::HalfBlock => "▀",
        Marker::Bar => "▄",
        _ => "━",
    };
    let mut spans = vec![Span::styled(" wall ", view.theme.dim)];
    for (k, text) in [
        format!("≤{low} "),
        format!("≤{mid} "),
        format!("<{high} "),
        format!("≥{high} {}", unit.symbol),
    ]
    .into_iter()
    .enumerate()
    {
        spans.push(Span::styled(
            format!("{}{text}", glyph(k)),
            view.theme.walls[k],
        ));
    }
    spans.push(Span::raw(" "));
    Line::from(spans)
}

/// The wind's arrow (points across, up), where its label starts, the label.
type WindArrow = (Vec<(f64, f64)>, (f64, f64), String);

/// The wind as an arrow in the upper left of the field, pointing where it
/// blows, its length growing with its speed (a quarter of the view's reach
/// at 15 m/s and beyond), with its speed in the unit shown under it;
/// `None` in calm air.
fn wind_arrow(view: &Field, map: &FieldMap) -> Option<WindArrow> {
    let (speed, direction) = view.wind;
    if speed == 0.0 || !speed.is_finite() {
        return None;
    }
    let toward = direction
        + if speed < 0.0 {
            std::f64::consts::PI
        } else {
            0.0
        };
    let reach = map.x[1];
    let length = 0.25 * reach * (speed.abs() / 15.0).clamp(0.5, 1.0);
    // The arrow's middle, in foul territory clear of the fence.
    let centre = (
        map.z[0] + 0.2 * (map.z[1] - map.z[0]),
        map.x[0] + 0.8 * (map.x[1] - map.x[0]),
    );
    let (dz, dx) = (toward.sin() * length / 2.0, toward.cos() * length / 2.0);
    let tail = (centre.0 - dz, centre.1 - dx);
    let head = (centre.0 + dz, centre.1 + dx);
    let barb = |turn: f64| {
        let back = toward + std::f64::consts::PI + turn;
        (
            head.0 + 0.35 * length * back.sin(),
            head.1 + 0.35 * length * back.cos(),
        )
    };
    let arrow = vec![tail, head, barb(0.5), head, barb(-0.5)];
    // The label under the arrow, from its left end: a row's height below.
    let row = (map.x[1] - map.x[0]) / f64::from(map.plot.height.max(1));
    let under = (
        arrow.iter().map(|p| p.0).fold(f64::INFINITY, f64::min),
        arrow.iter().map(|p| p.1).fold(f64::INFINITY, f64::min) - row,
    );
    let unit = view.unit(Quantity::Speed);
    let label = format!("wind {:.0} {}", unit.show(speed.abs()), unit.symbol);
    Some((arrow, under, label))
}
