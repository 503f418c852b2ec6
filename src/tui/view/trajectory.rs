//! The batted flight in braille: the current swing, the optimal swing, the
//! pinned scene, the apex, the landing point and the fence, with axes in
//! the units shown (m or ft).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Chart};

use super::chart;
use crate::tui::app::App;
use crate::tui::theme::{self, title_style};

/// A round axis end at or above `value`, so that the halfway label is round too.
pub fn nice_ceiling(value: f64) -> f64 {
    if !(value.is_finite() && value > 0.0) {
        return 1.0;
    }
    let power = 10f64.powf(value.log10().floor());
    [1.0, 1.2, 1.6, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0]
        .iter()
        .map(|m| m * power)
        .find(|&v| v >= value)
        .unwrap_or(10.0 * power)
}

pub fn draw(frame: &mut Frame, area: Rect, app: &App) {
    let flight = &app.flown.flight;
    let (k, unit) = app.distance(1.0);
    let scaled = |path: &[(f64, f64)]| -> Vec<(f64, f64)> {
        path.iter().map(|&(x, y)| (k * x, k * y)).collect()
    };
    let (path, optimal_path) = (scaled(&app.path), scaled(&app.optimal_path));
    let pinned_path = app.pin.as_ref().map_or(Vec::new(), |p| scaled(&p.path));
    let (pin_range, pin_apex) = app
        .pin
        .as_ref()
        .map_or((0.0, 0.0), |p| (p.flown.flight.range, p.flown.flight.apex));
    let optimal_range = app.optimum.filter(|o| o.done).map_or(0.0, |o| o.best.range);
    let optimal_apex = app.optimal_path.iter().map(|p| p.1).fold(0.0, f64::max);
    let fence = app
        .fence
        .map_or((0.0, 0.0), |f| (k * f.distance, k * f.height));
    let x_max = nice_ceiling(1.05 * k * flight.range.max(optimal_range).max(pin_range))
        .max(nice_ceiling(1.05 * fence.0));
    // A ball carried back over the plate (a steep launch with backspin)
    // lands behind it: the axis then starts behind the plate too.
    let x_least = path
        .iter()
        .chain(&optimal_path)
        .chain(&pinned_path)
        .map(|p| p.0)
        .fold(0.0, f64::min);
    let x_min = if x_least < 0.0 {
        -nice_ceiling(-1.05 * x_least)
    } else {
        0.0
    };
    let y_max = nice_ceiling(1.1 * k * flight.apex.max(optimal_apex).max(pin_apex))
        .max(nice_ceiling(1.1 * fence.1));

    let apex = [(k * flight.apex_distance, k * flight.apex)];
    // A ball that does not land has no landing point (nor range).
    let landing = if flight.landed {
        vec![(k * flight.range, 0.0)]
    } else {
        Vec::new()
    };
    let fence_line = [(fence.0, 0.0), (fence.0, fence.1)];
    let mut datasets = Vec::new();
    if !optimal_path.is_empty() {
        datasets.push(chart::line(theme::OPTIMAL, &optimal_path).name("optimal"));
    }
    if !pinned_path.is_empty() {
        datasets.push(chart::line(theme::PINNED, &pinned_path).name("pinned"));
    }
    datasets.push(chart::line(theme::SWING, &path).name("this swing"));
    datasets.push(chart::points(Marker::Dot, theme::APEX, &apex).name("apex"));
    datasets.push(chart::points(Marker::Block, theme::LANDING, &landing).name("landing"));
    if app.fence.is_some() {
        datasets.push(chart::line(theme::FENCE, &fence_line).name("fence"));
    }
    let labels = |min: f64, max: f64| [min, 0.5 * (min + max), max].map(|v| format!("{v:.0}"));
    // The legend sits in the border, where it hides no data.
    let mut legend = vec![Span::styled("━ now ", theme::SWING)];
    if !optimal_path.is_empty() {
        legend.push(Span::styled("━ best ", theme::OPTIMAL));
    }
    if !pinned_path.is_empty() {
        legend.push(Span::styled("━ pin ", theme::PINNED));
    }
    let legend = Line::from(legend);
    let numbers = if flight.landed {
        format!(
            "{:.1} {unit}, apex {:.1} {unit} ",
            k * flight.range,
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
    let chart = Chart::new(datasets)
        .block(
            Block::bordered()
                .title(Span::styled(title, title_style()))
                .title_top(legend.right_aligned()),
        )
        .x_axis(chart::axis(
            format!("x ({unit})"),
            [x_min, x_max],
            labels(x_min, x_max),
        ))
        .y_axis(chart::axis(
            format!("y ({unit})"),
            [0.0, y_max],
            labels(0.0, y_max),
        ))
        .legend_position(None);
    frame.render_widget(chart, area);
}
