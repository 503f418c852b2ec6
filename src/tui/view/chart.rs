//! What the two charts (the trajectory and the impact) are built of.

use ratatui::style::Style;
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::{Axis, Dataset, GraphType};

use crate::tui::theme::dim;

/// A curve in braille.
pub fn line(style: Style, data: &[(f64, f64)]) -> Dataset<'_> {
    Dataset::default()
        .marker(Marker::Braille)
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

/// An axis over `bounds`, its title and labels dimmed.
pub fn axis<'a>(
    title: impl Into<String>,
    bounds: [f64; 2],
    labels: impl IntoIterator<Item = String>,
) -> Axis<'a> {
    Axis::default()
        .title(Span::styled(title.into(), dim()))
        .bounds(bounds)
        .labels(labels.into_iter().map(|l| Span::styled(l, dim())))
}
