//! The paper beside ours: on a Table II preset (its pitch, bat and ball as
//! printed, any swing), the readout's "Table II" line gives the paper's
//! optimum under ours. The glossary (`?`, Tab) says why they differ.

use ratatui::text::{Line, Span};

use super::pane_views::InUnits;
use super::readout::angle;
use super::readout_view::Readout;
use crate::shown::undercut_text;
use analysis::paper::{TABLE2, TableRow, table2_scene};

/// The printed row whose scene this is, whatever its swing (E, ψ).
pub fn table2_row(view: &Readout) -> Option<TableRow> {
    let scene = &view.scene;
    TABLE2.iter().find_map(|(_, _, row)| {
        (view.is_swing() && scene.with_swing(row.undercut, row.swing_angle) == table2_scene(row))
            .then_some(*row)
    })
}

/// "Table II E 0.0265 m  ψ 0.1594 rad  134.80 m": the printed optimum, in the
/// units shown, under ours.
pub fn line(view: &Readout) -> Option<Line<'static>> {
    let row = table2_row(view)?;
    let (range, unit) = view.distance(row.range);
    Some(Line::from(vec![
        Span::styled("Table II ", view.theme.dim),
        Span::styled(
            format!(
                "E {}  ψ {}  {range:.2} {unit}",
                undercut_text(view.units, row.undercut, false),
                angle(view, row.swing_angle, false),
            ),
            view.theme.dim,
        ),
    ]))
}
