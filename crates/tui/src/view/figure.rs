//! One of the paper's figures for the current inputs, in braille: its main
//! curves against its x column (axes with their units), the current input's
//! value as a vertical line, the paper's marked points, and the paper's
//! stated numbers beside ours.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

use super::pane_views::Figure;
use super::{figure_panels, words};
use crate::app::{AERO_FIGURES, FIGURES};
use analysis::figures::curves::{
    Curve, axis_title, column_input, curves, marked_points, panels, x_column,
};
use analysis::figures::{Column, FigureData, shown, stated, trimmed};
use units::{Quantity, Unit};

/// The curves of `data` the explorer draws (its main panel, as
/// [`panels`] gives it), with the x column's index.
pub fn chart_curves(data: &FigureData) -> (usize, Vec<Curve>) {
    (x_column(data), curves(data, panels(data.number)[0]))
}

/// The paper's marked points as the explorer draws them: each on the curve
/// it names ([`marked_points`]).
pub fn chart_marks(data: &FigureData) -> Vec<(f64, f64)> {
    let (_, curves) = chart_curves(data);
    marked_points(data, &curves)
        .into_iter()
        .map(|m| m.point)
        .collect()
}

/// The unit a column is drawn in, and its axis title in that unit: the
/// swept input's, else what its heading's SI unit measures (a range in m
/// is a distance, ω in rad/s a spin). Dimensionless columns (Re, S, C_D)
/// and times stay as they are.
pub(super) fn column_unit(view: &Figure, column: &Column) -> (Unit, String) {
    let title = axis_title(&column.head);
    let si = title
        .rsplit_once('(')
        .map_or("", |(_, rest)| rest.trim_end_matches(')'))
        .split(',')
        .next()
        .unwrap_or("");
    let quantity = match column_input(&column.key) {
        Some(key) => key.quantity(),
        None => match si {
            "m" => Quantity::Distance,
            "m/s" => Quantity::Speed,
            "rad/s" => Quantity::Spin,
            "rad" => Quantity::Angle,
            _ => Quantity::Unchanged,
        },
    };
    let unit = quantity.unit(view.units, "");
    if unit.is_identity() {
        return (unit, title);
    }
    let name = title
        .rsplit_once(" (")
        .map_or(title.as_str(), |(name, _)| name);
    (unit, format!("{name} ({})", unit.symbol))
}

/// The most decimals a stated number on the screen gives ([`units::sig`]).
pub(super) const MOST_DECIMALS: i32 = 6;

pub fn draw(frame: &mut Frame, area: Rect, view: &Figure) {
    let k = FIGURES.iter().position(|&f| f == view.number).unwrap_or(0);
    let state = view.figure;
    let stale = state.is_none_or(|f| f.generation != view.generation);
    // A batted ball steps through the aero figures only: say so.
    let (k, count, which) = if view.swing {
        (k, FIGURES.len(), "")
    } else {
        let k = AERO_FIGURES.iter().position(|&f| f == view.number);
        (
            k.unwrap_or(0),
            AERO_FIGURES.len(),
            "; the rest need a swing",
        )
    };
    let title = format!(
        " Fig. {} ({}/{count}, f F{which}){} ",
        view.number,
        k + 1,
        if stale { " computing…" } else { "" }
    );
    let block = Block::bordered().title(Span::styled(title, view.theme.title));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    // A batted ball has no pitch or bat to sweep: only the aero applies.
    if !view.applies() {
        let text = format!(
            "Fig. {} needs a swing: b switches to the swing scene. For a batted ball, f shows Figs. {} (the aerodynamics).",
            view.number,
            AERO_FIGURES.map(|n| n.to_string()).join("–")
        );
        frame.render_widget(
            Paragraph::new(Line::styled(text, view.theme.dim))
                .wrap(ratatui::widgets::Wrap { trim: true }),
            inner,
        );
        return;
    }
    let data = match state.map(|f| &f.data) {
        None => return,
        Some(Err(e)) => {
            frame.render_widget(
                Paragraph::new(Line::styled(e.as_str(), view.theme.error))
                    .wrap(ratatui::widgets::Wrap { trim: true }),
                inner,
            );
            return;
        }
        Some(Ok(data)) => data,
    };
    // The paper's numbers beside ours, and the notes: each gets a row, and
    // rows to spare go to the first ones' further words.
    // In the units shown, as the axes are (and as `x` writes them).
    let notes: Vec<Vec<Span>> = data
        .comparisons
        .iter()
        .map(|c| stated::comparison(c, view.units))
        .map(|c| {
            // The numbers first, so that a narrow pane loses only words.
            vec![
                Span::styled(format!("paper {}", trimmed(c.paper)), view.theme.dim),
                Span::raw(format!(
                    " · ours {}",
                    stated::with_unit(&units::sig(c.ours, 3, MOST_DECIMALS), c.unit)
                )),
                // A number's groups ("208 000") wrap together.
                Span::styled(
                    format!(
                        "  {}",
                        words::non_breaking(&c.what, |next| next.is_ascii_digit())
                    ),
                    view.theme.dim,
                ),
            ]
        })
        .chain(
            data.notes
                .iter()
                .map(|n| vec![Span::styled(stated::words(n, view.units), view.theme.dim)]),
        )
        .collect();
    let width = inner.width as usize;
    let height = inner.height as usize;
    // The caption takes two rows where the pane is tall enough.
    // In the units shown, the numbers it quotes too, as `x` writes it.
    let title = shown::title(&data.title, view.units);
    let caption = [Span::styled(title.as_str(), view.theme.dim)];
    let caption = words::fit(&caption, width, if height >= 18 { 2 } else { 1 });
    // The chart keeps at least 10 rows; the notes a quarter of the pane,
    // or a row each.
    let budget = height
        .saturating_sub(10 + caption.len())
        .min((height / 4).max(notes.len()))
        .max(1);
    let rows = note_rows(&notes, width, budget);
    let below: Vec<Line> = notes
        .iter()
        .zip(&rows)
        .flat_map(|(note, &rows)| words::fit(note, width, rows))
        .collect();
    let [heading, plot, below_area] = Layout::vertical([
        Constraint::Length(caption.len() as u16),
        Constraint::Fill(1),
        Constraint::Length(below.len() as u16),
    ])
    .areas(inner);
    let caption_cut = words::rows_needed(&[Span::raw(title.as_str())], width) > caption.len();
    frame.render_widget(Paragraph::new(caption), heading);
    frame.render_widget(Paragraph::new(below), below_area);
    let notes_cut = notes
        .iter()
        .zip(&rows)
        .any(|(note, &rows)| words::rows_needed(note, width) > rows);
    if caption_cut || notes_cut {
        super::read_all_hint(frame, area, view.theme);
    }

    figure_panels::draw(frame, plot, view, data);
}

/// The rows each note gets out of `budget`: one each, in order, while they
/// last; then the rest of their words, first notes first.
fn note_rows(notes: &[Vec<Span>], width: usize, budget: usize) -> Vec<usize> {
    let mut rows: Vec<usize> = (0..notes.len()).map(|k| usize::from(k < budget)).collect();
    let mut spare = budget.saturating_sub(notes.len());
    for (note, rows) in notes.iter().zip(rows.iter_mut()) {
        let more = words::rows_needed(note, width).saturating_sub(1).min(spare);
        *rows += more;
        spare -= more;
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_get_a_row_each_then_the_rest_of_their_words() {
        let note = |text: &'static str| vec![Span::raw(text)];
        let notes = [note("one two three four"), note("five six"), note("seven")];
        // 10 cells: the first needs 2 rows.
        assert_eq!(note_rows(&notes, 10, 2), [1, 1, 0]);
        assert_eq!(note_rows(&notes, 10, 3), [1, 1, 1]);
        assert_eq!(note_rows(&notes, 10, 5), [2, 1, 1]);
    }
}
