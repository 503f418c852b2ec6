//! The batted flight in braille: the current swing, the optimal swing, the
//! pinned scene, the apex, the landing point and the fence, with axes in
//! the units shown (m or ft).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::Block;

use super::chart::{self, AxisSpec, Ticks};
use super::pane_views::InUnits;
use super::pane_views::Trajectory;
use crate::app::App;

pub fn draw(frame: &mut Frame, area: Rect, view: &Trajectory) {
    let flight = view.flight;
    let (k, unit) = view.distance(1.0);
    let scaled = |path: &[(f64, f64)]| -> Vec<(f64, f64)> {
        path.iter().map(|&(x, y)| (k * x, k * y)).collect()
    };
    let (path, optimal_path) = (scaled(view.path), scaled(view.optimal_path));
    let pinned_path = view.pin.map_or(Vec::new(), |p| scaled(&p.path));
    let (pin_range, pin_apex) = view
        .pin
        .map_or((0.0, 0.0), |p| (p.flown.flight.range, p.flown.flight.apex));
    let optimal_range = view.optimal_range;
    let optimal_apex = view.optimal_path.iter().map(|p| p.1).fold(0.0, f64::max);
    let fence = view
        .fence
        .map_or((0.0, 0.0), |(distance, height)| (k * distance, k * height));
    // The x axis reaches past the farthest landing and the fence; a ball
    // carried back over the plate (a steep launch with backspin) lands
    // behind it, and the axis then starts behind the plate too.
    let x_most = 1.03 * (k * flight.range.max(optimal_range).max(pin_range)).max(fence.0);
    let x_least = path
        .iter()
        .chain(&optimal_path)
        .chain(&pinned_path)
        .map(|p| p.0)
        .fold(0.0, f64::min);
    let y_most = 1.05 * (k * flight.apex.max(optimal_apex).max(pin_apex)).max(fence.1);
    let apex = [(k * flight.apex_distance, k * flight.apex)];
    // A ball that does not land has no landing point (nor range).
    let landing = if flight.landed {
        vec![(k * flight.range, 0.0)]
    } else {
        Vec::new()
    };
    let fence_line = [(fence.0, 0.0), (fence.0, fence.1)];
    // Each path's marker and legend glyph: told apart by colour, or by
    // glyph where there is none.
    let (now, best, pin) = (view.theme.path(0), view.theme.path(1), view.theme.path(2));
    let mut datasets = Vec::new();
    if !optimal_path.is_empty() {
        datasets.push(chart::curve(best.0, view.theme.optimal, &optimal_path).name("optimal"));
    }
    if !pinned_path.is_empty() {
        datasets.push(chart::curve(pin.0, view.theme.pinned, &pinned_path).name("pinned"));
    }
    datasets.push(chart::curve(now.0, view.theme.swing, &path).name("this swing"));
    datasets.push(chart::points(Marker::Dot, view.theme.apex, &apex).name("apex"));
    datasets.push(chart::points(Marker::Block, view.theme.landing, &landing).name("landing"));
    if view.fence.is_some() {
        datasets.push(chart::line(view.theme.fence, &fence_line).name("fence"));
    }
    // The legend sits in the border, where it hides no data.
    let mut legend = vec![Span::styled(format!("{} now ", now.1), view.theme.swing)];
    if !optimal_path.is_empty() {
        legend.push(Span::styled(
            format!("{} best ", best.1),
            view.theme.optimal,
        ));
    }
    if !pinned_path.is_empty() {
        legend.push(Span::styled(format!("{} pin ", pin.1), view.theme.pinned));
    }
    let legend = Line::from(legend);
    let numbers = if flight.landed {
        format!(
            "{}{}, apex {:.1} {unit} ",
            view.range_text(flight.range),
            App::landing_call(flight).map_or(String::new(), |c| format!(" {c}")),
            k * flight.apex
        )
    } else {
        format!("does not land, apex {:.1} {unit} ", k * flight.apex)
    };
    // The title gives up its first word before it would run into the legend.
    let title = format!(" Trajectory {numbers}");
    let room = area.width.saturating_sub(2) as usize;
    let title = if title.chars().count() + legend.width() <= room {
        title
    } else {
        format!(" {numbers}")
    };
    let block = Block::bordered()
        .title(Span::styled(title, view.theme.title))
        .title_top(legend.right_aligned());
    let inner = block.inner(area);
    frame.render_widget(block, area);
    // Round ticks, as many as the pane has room for, the height axis to the
    // first tick over the flight's where that adds under a fifth. Not at equal scales: the pane's shape is
    // the layout's, and a true-scale flight leaves most of a tall pane
    // empty (a 27 m apex under a 75 m axis at 200×60); the ticks give the
    // scale, the title the true apex and range. (The SVG, whose shape is
    // its own, stretches the height at most picture::MAX_STRETCH times.)
    let rows = inner.height.saturating_sub(2);
    let x = Ticks::across(x_least, x_most, inner.width.saturating_sub(6));
    let y = Ticks::up(0.0, y_most, rows);
    let tidy = y.to_a_tick();
    let y = if tidy.hi <= 1.2 * y.hi { tidy } else { y };
    chart::draw(
        frame,
        inner,
        datasets,
        (
            &AxisSpec::new(format!("x ({unit})"), x),
            &AxisSpec::new(format!("y ({unit})"), y),
        ),
        view.theme.dim,
    );
}
