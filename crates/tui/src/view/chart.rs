//! What the charts (the trajectory, the figures, the impact) are built of:
//! curves in braille, axes over round ticks, and words at points.
//!
//! ratatui's `Chart` spreads more than three x labels by its own spacing,
//! not at their values, and cannot write a word at a point. So [`draw`]
//! gives it only the end labels and writes the others, and any point
//! labels, itself, where its canvas puts those values ([`graph_area`]
//! mirrors the chart's layout; a test holds the two together).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::{Axis, Chart, Dataset, GraphType};

/// A curve in braille.
pub fn line(style: Style, data: &[(f64, f64)]) -> Dataset<'_> {
    curve(Marker::Braille, style, data)
}

/// A curve drawn in `marker` (braille, or dots and blocks where colour
/// does not tell curves apart).
pub fn curve(marker: Marker, style: Style, data: &[(f64, f64)]) -> Dataset<'_> {
    Dataset::default()
        .marker(marker)
        .graph_type(GraphType::Line)
        .style(style)
        .data(data)
}

/// Points, each drawn as `marker`.
pub fn points(marker: Marker, style: Style, data: &[(f64, f64)]) -> Dataset<'_> {
    Dataset::default()
        .marker(marker)
        .graph_type(GraphType::Scatter)
        .style(style)
        .data(data)
}

/// An axis from `lo` to `hi` with round ticks: every multiple of `step`
/// between them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ticks {
    pub lo: f64,
    pub hi: f64,
    pub step: f64,
}

impl Ticks {
    /// The axis [`lo`, `hi`] with a step of 1, 2 or 5 times a power of
    /// ten, the finest that puts at most `intervals` + 1 ticks on it.
    pub fn new(lo: f64, hi: f64, intervals: usize) -> Ticks {
        let (lo, hi) = if lo.is_finite() && hi.is_finite() {
            (lo.min(hi), lo.max(hi))
        } else {
            (0.0, 1.0)
        };
        // A single value gets an axis around it.
        let (lo, hi) = if hi - lo > 1e-12 * hi.abs().max(lo.abs()) {
            (lo, hi)
        } else {
            let half = 0.5 * lo.abs().max(1.0);
            (lo - half, hi + half)
        };
        let most = intervals.max(1) + 1;
        let mut decade = 10f64.powf(((hi - lo) / most as f64).log10().floor() - 1.0);
        let mut finer = None;
        loop {
            for mantissa in [1.0, 2.0, 5.0] {
                let ticks = Ticks {
                    lo,
                    hi,
                    step: mantissa * decade,
                };
                match ticks.values().len() {
                    // One tick says nothing of the scale: one more than
                    // asked for is better.
                    n if n < 2 => return finer.unwrap_or(ticks),
                    n if n <= most => return ticks,
                    _ => finer = Some(ticks),
                }
            }
            decade *= 10.0;
        }
    }

    /// The ticks' values, lo to hi.
    pub fn values(&self) -> Vec<f64> {
        let tolerance = 1e-9 * self.step;
        let first = ((self.lo - tolerance) / self.step).ceil() as i64;
        let last = ((self.hi + tolerance) / self.step).floor() as i64;
        (first..=last).map(|k| k as f64 * self.step).collect()
    }

    /// The ticks as written: the step's decimals, no "-0".
    pub fn labels(&self) -> Vec<String> {
        let decimals = (-self.step.log10().floor()).max(0.0) as usize;
        self.values()
            .into_iter()
            .map(|v| {
                let text = format!("{v:.decimals$}");
                let zero = text
                    .trim_start_matches('-')
                    .chars()
                    .all(|c| "0.".contains(c));
                if zero { text.replace('-', "") } else { text }
            })
            .collect()
    }

    /// The axis run on to its first tick at or past `hi`.
    pub fn to_a_tick(self) -> Ticks {
        let end = (self.hi / self.step - 1e-9).ceil() * self.step;
        Ticks {
            hi: end.max(self.hi),
            ..self
        }
    }

    pub fn bounds(&self) -> [f64; 2] {
        [self.lo, self.hi]
    }

    /// The axis [`lo`, `hi`] with ticks whose labels, each with two cells
    /// of room, fit `cells` across.
    pub fn across(lo: f64, hi: f64, cells: u16) -> Ticks {
        let mut intervals = (cells / 6).clamp(1, 10) as usize;
        loop {
            let ticks = Ticks::new(lo, hi, intervals);
            let labels = ticks.labels();
            let widest = labels.iter().map(|l| l.len()).max().unwrap_or(1);
            if intervals == 1 || labels.len() * (widest + 2) <= cells as usize {
                return ticks;
            }
            intervals -= 1;
        }
    }

    /// As [`Ticks::across`], the axis then run on to the first tick at or
    /// past `hi` (12.3 on an axis to 14 by 2s), the step kept where its
    /// labels still fit.
    pub fn across_past(lo: f64, hi: f64, cells: u16) -> Ticks {
        let mut intervals = (cells / 6).clamp(1, 10) as usize;
        loop {
            let ticks = Ticks::new(lo, hi, intervals).to_a_tick();
            let labels = ticks.labels();
            let widest = labels.iter().map(|l| l.len()).max().unwrap_or(1);
            if intervals == 1 || labels.len() * (widest + 2) <= cells as usize {
                return ticks;
            }
            intervals -= 1;
        }
    }

    /// The axis [`lo`, `hi`] with ticks a row or more apart on an axis
    /// `rows` tall (at most 6 steps).
    pub fn up(lo: f64, hi: f64, rows: u16) -> Ticks {
        Ticks::new(lo, hi, (rows.saturating_sub(1) / 2).clamp(1, 6) as usize)
    }
}

/// One axis of a chart: its title, its ticks, and whether its labels show
/// (a panel stacked over another has no x labels of its own).
#[derive(Clone, Debug)]
pub struct AxisSpec {
    pub title: String,
    pub ticks: Ticks,
    pub labelled: bool,
    /// The fewest cells the y labels take (panels stacked over one x axis
    /// line up by giving each the widest's).
    pub width: usize,
}

impl AxisSpec {
    pub fn new(title: impl Into<String>, ticks: Ticks) -> AxisSpec {
        AxisSpec {
            title: title.into(),
            ticks,
            labelled: true,
            width: 0,
        }
    }
}

/// Where a chart in `area` draws its curves: right of the y labels
/// (`y_label` cells, or the first x label's width less one if wider, at
/// most a third of the area) and the y axis, above the x axis and its
/// labels (if `x_labelled`). As ratatui's `Chart::layout` places them.
pub fn graph_area(area: Rect, y_label: u16, first_x_label: u16, x_labelled: bool) -> Rect {
    let left = if x_labelled {
        y_label.max(first_x_label.saturating_sub(1))
    } else {
        y_label
    }
    .min(area.width / 3);
    let below = if x_labelled {
        2.min(area.height.saturating_sub(1))
    } else {
        0
    };
    let x = area.x + left + u16::from(left + 1 < area.width);
    Rect::new(
        x,
        area.y,
        area.right().saturating_sub(x),
        area.height.saturating_sub(below),
    )
}

/// The cell where a chart over `graph` with bounds `x`, `y` draws the
/// point (px, py) in `marker`, as its canvas does (braille has 2×4 dots a
/// cell, the others one); `None` outside the bounds.
pub fn cell_of(
    graph: Rect,
    (x, y): ([f64; 2], [f64; 2]),
    (px, py): (f64, f64),
    marker: Marker,
) -> Option<(u16, u16)> {
    let inside = |v: f64, [a, b]: [f64; 2]| v >= a && v <= b && a < b;
    if !(inside(px, x) && inside(py, y)) || graph.width == 0 || graph.height == 0 {
        return None;
    }
    let (across, down) = if marker == Marker::Braille {
        (2, 4)
    } else {
        (1, 1)
    };
    let dots_x = f64::from(graph.width * across) - 1.0;
    let dots_y = f64::from(graph.height * down) - 1.0;
    let column = ((px - x[0]) * dots_x / (x[1] - x[0])).round() as u16 / across;
    let row = ((y[1] - py) * dots_y / (y[1] - y[0])).round() as u16 / down;
    Some((graph.x + column, graph.y + row))
}

/// Where the x axis's title goes so that its last label shows whole: at
/// the end of the labels' row, the graph leaving `Some(n)` blank columns at
/// its right (0 where the label shows anyway; at most a quarter of the
/// area); else (`None`) on a row of its own under the labels. The same for
/// every panel stacked over one x axis, labelled or not, so that their
/// graphs line up.
pub fn title_room(area: Rect, y_width: u16, x: &AxisSpec) -> Option<u16> {
    let title = x.title.chars().count() as u16;
    let (Some(last), Some(text)) = (x.ticks.values().pop(), x.ticks.labels().pop()) else {
        return Some(0);
    };
    if title == 0 {
        return Some(0);
    }
    let width = text.chars().count() as u16;
    let title_at = area.right().saturating_sub(title);
    let bounds = (x.ticks.bounds(), [0.0, 1.0]);
    (0..=area.width / 4).find(|&room| {
        let narrowed = Rect {
            width: area.width - room,
            ..area
        };
        let graph = graph_area(narrowed, y_width, 1, true);
        cell_of(graph, bounds, (last, 0.0), Marker::Braille)
            .is_some_and(|(column, _)| column.saturating_sub(width / 2) + width < title_at)
    })
}

/// Draws `datasets` in `area` over the axes `x` and `y`, each tick
/// labelled at its value; returns the graph's area (for [`labels`]).
pub fn draw(
    frame: &mut Frame,
    area: Rect,
    datasets: Vec<Dataset>,
    (x, y): (&AxisSpec, &AxisSpec),
    dim: Style,
) -> Rect {
    let y_labels = y.ticks.labels();
    let y_width = y_labels
        .iter()
        .map(|l| l.chars().count())
        .max()
        .unwrap_or(0)
        .max(y.width);
    // The chart gets blank labels, which keep its axes and their room;
    // the ticks' own are written below, each at its value.
    let blank = |cells: usize| Span::raw(" ".repeat(cells));
    let x_blanks = if x.labelled {
        vec![blank(1), blank(1)]
    } else {
        Vec::new()
    };
    let chart = Chart::new(datasets)
        .x_axis(Axis::default().bounds(x.ticks.bounds()).labels(x_blanks))
        .y_axis(
            Axis::default()
                .title(Span::styled(y.title.clone(), dim))
                .bounds(y.ticks.bounds())
                .labels([blank(y_width), blank(y_width)]),
        )
        .legend_position(None);
    // The graph stops short of the x title where its last label needs it,
    // or leaves the title a row of its own.
    let room = title_room(area, y_width as u16, x);
    let own_row = x.labelled && room.is_none() && area.height > 4;
    let narrowed = Rect {
        width: area.width - room.unwrap_or(0),
        height: area.height - u16::from(own_row),
        ..area
    };
    frame.render_widget(chart, narrowed);
    let graph = graph_area(narrowed, y_width as u16, 1, x.labelled);
    let buf = frame.buffer_mut();
    // y: right-aligned left of the axis, on the row of its value.
    if graph.x >= area.x + 2 {
        let bounds = ([0.0, 1.0], y.ticks.bounds());
        for (value, text) in y.ticks.values().iter().zip(&y_labels) {
            if let Some((_, row)) = cell_of(graph, bounds, (0.0, *value), Marker::Braille) {
                let width = graph.x - 1 - area.x;
                buf.set_string(area.x, row, format!("{text:>0$}", width as usize), dim);
            }
        }
    }
    // x: the title at the right of the labels' row (in the graph it would
    // hide the data's end: the landing point) or under it, then each label
    // centred under its column, where it clears its neighbours and the title.
    if x.labelled && area.height > 2 {
        let row = narrowed.bottom() - 1;
        let title = x.title.chars().count() as u16;
        let title_at = area.right().saturating_sub(title);
        let titled = title > 0 && title_at > graph.x + 4;
        let end = if titled && !own_row {
            buf.set_string(title_at, row, &x.title, dim);
            title_at - 1
        } else {
            if titled {
                buf.set_string(title_at, area.bottom() - 1, &x.title, dim);
            }
            area.right()
        };
        let bounds = (x.ticks.bounds(), [0.0, 1.0]);
        let mut free_from = area.x;
        for (value, text) in x.ticks.values().iter().zip(x.ticks.labels()) {
            let Some((column, _)) = cell_of(graph, bounds, (*value, 0.0), Marker::Braille) else {
                continue;
            };
            let width = text.chars().count() as u16;
            let start = column
                .saturating_sub(width / 2)
                .min(area.right().saturating_sub(width));
            if start >= free_from && start + width <= end {
                buf.set_string(start, row, &text, dim);
                free_from = start + width + 1;
            }
        }
    }
    graph
}

/// Writes each (point, text) of `labels` just right of its point on a
/// chart drawn by [`draw`] over `graph` in `marker`, else just left of it;
/// a word that would cover another's point or word, or run off the
/// chart, is left out.
pub fn labels(
    frame: &mut Frame,
    graph: Rect,
    (x, y): (&Ticks, &Ticks),
    marker: Marker,
    labels: &[((f64, f64), &str)],
    style: Style,
) {
    let bounds = (x.bounds(), y.bounds());
    let cells: Vec<Option<(u16, u16)>> = labels
        .iter()
        .map(|(point, _)| cell_of(graph, bounds, *point, marker))
        .collect();
    // Taken: every labelled point's cell, then each word placed.
    let mut taken: Vec<(u16, u16, u16)> = cells.iter().flatten().map(|&(c, r)| (c, r, 1)).collect();
    let clear = |taken: &[(u16, u16, u16)], start: u16, row: u16, width: u16| {
        taken
            .iter()
            .all(|&(c, r, w)| r != row || c + w <= start || start + width <= c)
    };
    for ((_, text), cell) in labels.iter().zip(cells) {
        let Some((column, row)) = cell else {
            continue;
        };
        let width = text.chars().count() as u16;
        let right = column + 1;
        let left = column.checked_sub(width).filter(|&l| l >= graph.x);
        let start = [Some(right).filter(|&r| r + width <= graph.right()), left]
            .into_iter()
            .flatten()
            .find(|&start| clear(&taken, start, row, width));
        if let Some(start) = start {
            frame.buffer_mut().set_string(start, row, text, style);
            taken.push((start, row, width));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;

    #[test]
    fn ticks_are_round_numbers_inside_the_axis() {
        let t = Ticks::new(81.2, 189.0, 4);
        assert_eq!((t.lo, t.hi, t.step), (81.2, 189.0, 20.0));
        assert_eq!(t.labels(), ["100", "120", "140", "160", "180"]);
        assert_eq!(Ticks::new(81.2, 189.0, 2).labels(), ["100", "150"]);
        assert_eq!(
            Ticks::new(0.0, 138.7, 7).labels(),
            ["0", "20", "40", "60", "80", "100", "120"]
        );
        assert_eq!(Ticks::new(0.0, 138.7, 3).labels(), ["0", "50", "100"]);
        assert_eq!(
            Ticks::new(-0.09, 0.41, 5).labels(),
            ["0.0", "0.1", "0.2", "0.3", "0.4"]
        );
        // Two ticks at least where one coarser step would leave one.
        assert_eq!(Ticks::new(-0.09, 0.41, 1).labels(), ["0.0", "0.2", "0.4"]);
        assert_eq!(Ticks::new(0.0215, 0.0311, 3).labels(), ["0.025", "0.030"]);
        assert_eq!(
            Ticks::new(-75.2, 35.1, 4).labels(),
            ["-60", "-40", "-20", "0", "20"]
        );
        assert_eq!(Ticks::new(0.0, 12.34, 3).labels(), ["0", "5", "10"]);
        assert_eq!(
            Ticks::new(0.0, 12.34, 6).labels(),
            ["0", "2", "4", "6", "8", "10", "12"]
        );
        // One value: an axis around it.
        let t = Ticks::new(5.0, 5.0, 2);
        assert!(t.lo < 5.0 && t.hi > 5.0 && t.values().len() >= 2);
        // Labels fit their room: 48 cells for 0 to 300 000.
        let t = Ticks::across(50_000.0, 300_000.0, 40);
        assert_eq!(t.labels(), ["100000", "200000", "300000"]);
    }

    #[test]
    fn the_graph_area_is_where_ratatuis_chart_draws() {
        for (w, h, top) in [(40, 12, 100.0), (40, 12, 10.0), (30, 8, 100_000.0)] {
            let area = Rect::new(2, 1, w, h);
            let mut terminal = Terminal::new(TestBackend::new(50, 20)).unwrap();
            let y = AxisSpec::new("", Ticks::new(0.0, top, 1));
            let x = AxisSpec::new("", Ticks::new(-1000.0, 1000.0, 2));
            let mut graph = Rect::default();
            terminal
                .draw(|frame| graph = draw(frame, area, vec![], (&x, &y), Style::new()))
                .unwrap();
            let buffer = terminal.backend().buffer();
            // The axes' corner is left of the graph's first column, under
            // its last row; the top label is on the top row, right of it.
            assert_eq!(
                buffer[(graph.x - 1, graph.bottom())].symbol(),
                "└",
                "{graph:?}"
            );
            assert_eq!(graph.right(), area.right());
            let top_label = format!("{top}");
            let at = graph.x - 1 - top_label.len() as u16;
            let row: String = (at..graph.x - 1)
                .map(|c| buffer[(c, area.y)].symbol())
                .collect();
            assert_eq!(row, top_label);
            // The x labels: -1000 at the left, 0 mid-way, 1000 at the right.
            let labels: String = (area.x..area.right())
                .map(|c| buffer[(c, area.bottom() - 1)].symbol())
                .collect();
            assert!(labels.trim_end().ends_with("1000"), "{labels:?}");
            let zero = labels.find(" 0 ").unwrap() as u16 + 1 + area.x;
            assert!(
                zero.abs_diff(graph.x + graph.width / 2) <= 1,
                "{labels:?} {graph:?}"
            );
        }
    }

    /// The last two rows of a chart drawn in `width` columns.
    fn x_rows(width: u16, x: &AxisSpec) -> (String, String) {
        let area = Rect::new(0, 0, width, 12);
        let mut terminal = Terminal::new(TestBackend::new(width, 12)).unwrap();
        let y = AxisSpec::new("", Ticks::new(0.0, 100.0, 3));
        terminal
            .draw(|frame| {
                draw(frame, area, vec![], (x, &y), Style::new());
            })
            .unwrap();
        let buffer = terminal.backend().buffer();
        let row = |r: u16| -> String { (0..width).map(|c| buffer[(c, r)].symbol()).collect() };
        (row(10), row(11))
    }

    #[test]
    fn the_last_x_label_shows_beside_or_over_the_axis_title() {
        // p_f = 12.34 on an axis run on to a tick past it: 14 by 2s.
        let p = Ticks::across_past(0.0, 12.34, 34);
        assert!(p.hi >= 12.34 && p.values().last() == Some(&p.hi), "{p:?}");
        assert_eq!(Ticks::across_past(0.0, 12.34, 60).hi, 14.0);
        // The impact's axis at 80×24 (47 columns): "15" before the title.
        let impact = AxisSpec::new("p (N·s)", Ticks::new(0.0, 15.0, 3));
        let (axis, labels) = x_rows(47, &impact);
        assert!(
            labels.trim_end().ends_with("10         15 p (N·s)"),
            "{labels:?}"
        );
        assert!(axis.trim_end().ends_with('─'), "{axis:?}");
        // A long title the graph cannot make room for gets the row under
        // the labels, which run to the axis's end.
        let sweep = AxisSpec::new("bat.speed (m/s)", Ticks::new(20.0, 45.0, 5));
        let (labels, under) = x_rows(45, &sweep);
        assert!(labels.trim_end().ends_with("40      45"), "{labels:?}");
        assert_eq!(under.trim(), "bat.speed (m/s)");
        // Where the last label clears the title, the graph keeps its width.
        let room = AxisSpec::new("x (m)", Ticks::new(0.0, 139.0, 6));
        assert_eq!(title_room(Rect::new(0, 0, 60, 12), 3, &room), Some(0));
        let (_, labels) = x_rows(60, &room);
        assert!(
            labels.trim_end().ends_with("100     120 x (m)"),
            "{labels:?}"
        );
    }
}
