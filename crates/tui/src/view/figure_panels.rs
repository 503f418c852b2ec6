//! A figure's chart: its panels stacked over one x axis (Figs. 8–12 have
//! three, the optimal range, E_opt and ψ_opt, shown where the pane has
//! room, else one at a time, `v` to the next; the others one), with the current input's value as a vertical
//! line and the paper's marked points on the first.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use super::chart::{self, AxisSpec, Ticks};
use super::figure::column_unit;
use super::pane_views::Figure;
use crate::theme::Theme;
use analysis::figures::FigureData;
use analysis::figures::curves::{Curve, current_value, curves, marked_points, panels, x_column};
use units::{Quantity, Unit};

/// The fewest rows a panel's graph gets; a panel that would get fewer is
/// left out (the first always shows).
const PANEL_ROWS: u16 = 5;

/// One panel: its y axis title and its curves, in the units shown.
struct Panel {
    title: String,
    y_unit: Unit,
    curves: Vec<Curve>,
}

/// How many of `count` panels to draw in `height` rows: all of them if,
/// after a row for the legend and two for the x axis, each gets
/// [`PANEL_ROWS`]; else only the first (two of three would hide one
/// half-heartedly).
fn panels_that_fit(height: u16, count: usize) -> usize {
    let rows = (height.saturating_sub(3) / PANEL_ROWS) as usize;
    if rows >= count { count.max(1) } else { 1 }
}

/// The panel of `data` whose y columns start with `prefix`, in the units
/// shown, against the x column in `x_unit`.
fn panel(view: &Figure, data: &FigureData, prefix: &str, x_unit: Unit) -> Panel {
    let (y_unit, title) = data
        .columns
        .iter()
        .find(|c| c.key.starts_with(prefix))
        .map_or(
            (Quantity::Unchanged.unit(view.units, ""), String::new()),
            |c| column_unit(view, c),
        );
    let curves = curves(data, prefix)
        .into_iter()
        .map(|curve| Curve {
            points: curve
                .points
                .iter()
                .map(|&(x, y)| (x_unit.show(x), y_unit.show(y)))
                .collect(),
            ..curve
        })
        .collect::<Vec<_>>();
    let title = if curves.is_empty() {
        String::new()
    } else {
        title
    };
    Panel {
        title,
        y_unit,
        curves,
    }
}

/// The least and greatest of `values`, if they are any.
fn span(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |range, v| match range {
        None => Some((v, v)),
        Some((a, b)) => Some((v.min(a), v.max(b))),
    })
}

pub fn draw(frame: &mut Frame, area: Rect, view: &Figure, data: &FigureData) {
    let x = x_column(data);
    let (x_unit, x_title) = column_unit(view, &data.columns[x]);
    let all = panels(data.number);
    let count = panels_that_fit(area.height, all.len());
    // Where not all fit, one at a time: the one `v` has reached.
    let first = if count < all.len() {
        view.panel % all.len()
    } else {
        0
    };
    let shown: Vec<Panel> = all[first..first + count]
        .iter()
        .map(|prefix| panel(view, data, prefix, x_unit))
        .collect();
    let Some((x0, x1)) = span(
        shown
            .iter()
            .flat_map(|p| p.curves.iter().flat_map(|c| c.points.iter().map(|p| p.0))),
    )
    .filter(|(a, b)| a < b) else {
        return;
    };
    // The paper's marked points (A, B, Dryden's point…), each on its curve
    // of the first panel, with a word where a short one names it.
    let on_first = |k: usize| first + k == 0;
    let marks: Vec<((f64, f64), String)> = marked_points(data, &curves(data, all[0]))
        .into_iter()
        .filter(|_| on_first(0))
        .map(|m| {
            let point = (x_unit.show(m.point.0), shown[0].y_unit.show(m.point.1));
            (point, short_label(&m.label))
        })
        .collect();
    let mark_points: Vec<(f64, f64)> = marks.iter().map(|m| m.0).collect();
    // Dots, or blocks where the second curve is in dots.
    let mark_marker = if view.theme.colored() {
        Marker::Dot
    } else {
        Marker::Block
    };
    // The current input's value, where the x column is an input.
    let now = current_value(data, view.scene)
        .map(|v| x_unit.show(v))
        .filter(|v| (x0..=x1).contains(v));

    let [legend_row, stack] =
        Layout::vertical([Constraint::Length(1), Constraint::Fill(1)]).areas(area);
    let which = (count < all.len()).then_some((first, all.len()));
    legend_line(frame, legend_row, view, (which, &shown[0]), now.is_some());

    let rows = (stack.height.saturating_sub(2) / count as u16).max(1);
    let x_ticks = Ticks::across(x0, x1, stack.width.saturating_sub(8));
    let (y_ticks, width) = y_axes(&shown, rows, &x_ticks);
    let constraints = (0..count).map(|k| {
        if k + 1 < count {
            Constraint::Length(rows)
        } else {
            Constraint::Fill(1)
        }
    });
    let areas = Layout::vertical(constraints).split(stack);
    for (k, (panel, y)) in shown.iter().zip(&y_ticks).enumerate() {
        let now_line = now.map_or(Vec::new(), |v| vec![(v, y.lo), (v, y.hi)]);
        let mut datasets: Vec<_> = panel
            .curves
            .iter()
            .enumerate()
            .map(|(c, curve)| {
                let marker = view.theme.path(c).0;
                chart::curve(marker, curve_style(view.theme, c), &curve.points)
            })
            .collect();
        if !now_line.is_empty() {
            datasets.push(chart::line(view.theme.swing, &now_line));
        }
        if on_first(k) {
            datasets.push(chart::points(mark_marker, view.theme.apex, &mark_points));
        }
        // Only the lowest panel has the x axis and its title (each is given
        // the title, so that each graph leaves it the same room).
        let x = AxisSpec {
            labelled: k + 1 == count,
            ..AxisSpec::new(x_title.as_str(), x_ticks)
        };
        let y_axis = AxisSpec {
            width,
            ..AxisSpec::new(panel.title.clone(), *y)
        };
        let graph = chart::draw(frame, areas[k], datasets, (&x, &y_axis), view.theme.dim);
        if on_first(k) {
            let named: Vec<((f64, f64), &str)> = marks
                .iter()
                .filter(|(_, text)| !text.is_empty())
                .map(|(point, text)| (*point, text.as_str()))
                .collect();
            let ticks = (&x_ticks, y);
            chart::labels(frame, graph, ticks, mark_marker, &named, view.theme.apex);
        }
    }
}

/// The row over the panels: which panel this is where not all fit
/// (`which`: the first shown and how many there are) and the key to the
/// others, the main panel's curves by name, and the current value's line.
fn legend_line(
    frame: &mut Frame,
    row: Rect,
    view: &Figure,
    (which, main): (Option<(usize, usize)>, &Panel),
    now: bool,
) {
    let mut legend = Vec::new();
    if let Some((first, all)) = which {
        legend.push(Span::styled(
            format!("panel {}/{all}: {} · v next ", first + 1, main.title),
            view.theme.key,
        ));
    }
    if main.curves.len() > 1 {
        for (k, curve) in main.curves.iter().enumerate() {
            let glyph = view.theme.path(k).1;
            let style = curve_style(view.theme, k);
            legend.push(Span::styled(format!("{glyph} {} ", curve.name), style));
        }
    }
    if now {
        legend.push(Span::styled("│ now ", view.theme.swing));
    }
    frame.render_widget(Paragraph::new(Line::from(legend).right_aligned()), row);
}

/// Each panel's y ticks over `rows`, and the width every panel's y labels
/// take, so that the graphs line up over the one x axis (whose first label
/// may reach left of it too).
fn y_axes(shown: &[Panel], rows: u16, x_ticks: &Ticks) -> (Vec<Ticks>, usize) {
    let y_ticks: Vec<Ticks> = shown
        .iter()
        .map(|p| {
            let (y0, y1) = span(p.curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)))
                .unwrap_or((0.0, 1.0));
            let pad = 0.05 * (y1 - y0);
            Ticks::up(y0 - pad, y1 + pad, rows)
        })
        .collect();
    let width = y_ticks
        .iter()
        .flat_map(|t| t.labels())
        .map(|l| l.chars().count())
        .chain([x_ticks.labels()[0].chars().count().saturating_sub(1)])
        .max()
        .unwrap_or(0);
    (y_ticks, width)
}

/// A mark's name on the chart: its words before any "(" or ":", if short
/// ("A", "highest", "kink"); longer names stay in the caption and notes.
fn short_label(label: &str) -> String {
    let name = label.split_once(" (").map_or(label, |(name, _)| name);
    let name = name.split(':').next().unwrap_or(name).trim();
    if name.chars().count() <= 8 {
        name.to_owned()
    } else {
        String::new()
    }
}

/// A figure's curve `k`'s style.
fn curve_style(theme: &Theme, k: usize) -> ratatui::style::Style {
    theme.figure_curves[k % theme.figure_curves.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_names_label_their_marks_and_long_ones_do_not() {
        assert_eq!(short_label("A (182.4 rad/s)"), "A");
        assert_eq!(short_label("highest"), "highest");
        assert_eq!(short_label("kink"), "kink");
        assert_eq!(short_label("cusp μ = 0.35: slip halts at separation"), "");
        assert_eq!(short_label("Dryden's point (paper: C_D = 0.3)"), "");
    }

    #[test]
    fn all_three_panels_or_the_first() {
        assert_eq!(panels_that_fit(18, 3), 3);
        assert_eq!(panels_that_fit(17, 3), 1);
        assert_eq!(panels_that_fit(40, 1), 1);
        assert_eq!(panels_that_fit(0, 3), 1);
    }
}
