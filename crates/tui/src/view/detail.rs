//! `i`: the words the panes cut short, whole, in a pane that scrolls: the
//! selected input (a wind's direction runs to three rows), the message (a
//! unit refused), what `x` wrote, the figure's caption and notes, the
//! readout whole (the models in force with their descriptions too).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Wrap};

use super::inputs::about_selected;
use crate::app::App;
use crate::layout::Tab;
use analysis::figures::{stated, trimmed};
use preset::escape_text;

/// The sections shown, each a heading and its paragraphs.
fn sections(app: &App) -> Vec<(&'static str, Vec<String>)> {
    let mut sections = vec![(
        "Selected input",
        vec![about_selected(&super::inputs_view::Inputs::of(app))],
    )];
    if let Some((message, _)) = &app.message {
        sections.push(("Message", vec![escape_text(message)]));
    }
    if let Some((message, _)) = &app.export_message {
        sections.push(("Export", vec![escape_text(message)]));
    }
    let figure = app.figure.as_ref().and_then(|f| f.data.as_ref().ok());
    if let (Tab::Figures, Some(data)) = (app.tab, figure) {
        let mut words = vec![analysis::figures::shown::title(&data.title, app.units)];
        let comparisons = data
            .comparisons
            .iter()
            .map(|c| stated::comparison(c, app.units));
        words.extend(comparisons.map(|c| {
            format!(
                "paper {} · ours {}: {}",
                trimmed(c.paper),
                stated::with_unit(&units::sig(c.ours, 3, super::figure::MOST_DECIMALS), c.unit,),
                c.what
            )
        }));
        words.extend(data.notes.iter().map(|n| stated::words(n, app.units)));
        sections.push(("Figure", words));
    }
    // The readout as on a screen with room for all of it.
    let readout = super::readout::lines(
        &super::readout_view::Readout::of(app),
        Rect::new(0, 0, 200, 200),
    );
    sections.push((
        "Readout",
        readout
            .iter()
            .map(|l| {
                l.spans
                    .iter()
                    .map(|s| s.content.as_ref())
                    .collect::<String>()
            })
            .collect(),
    ));
    sections
}

/// The pop-up over the panes, scrolled down by `scroll` rows (j k).
pub fn draw(frame: &mut Frame, area: Rect, app: &App, scroll: u16) {
    let popup = Rect {
        x: area.x + 1,
        y: area.y,
        width: area.width.saturating_sub(2).min(96),
        height: area.height,
    };
    let mut lines: Vec<Line> = Vec::new();
    for (heading, paragraphs) in sections(app) {
        lines.push(Line::styled(heading, app.theme.key));
        lines.extend(paragraphs.into_iter().map(Line::raw));
        lines.push(Line::raw(""));
    }
    let paragraph = Paragraph::new(lines).wrap(Wrap { trim: true });
    let inner_width = popup.width.saturating_sub(2) as usize;
    // Where it would scroll past its end, it stops at the last row.
    let rows: usize = sections(app)
        .iter()
        .map(|(_, p)| {
            2 + p
                .iter()
                .map(|t| super::words::rows_needed(&[Span::raw(t.as_str())], inner_width))
                .sum::<usize>()
        })
        .sum();
    let visible = popup.height.saturating_sub(2) as usize;
    let scroll = scroll.min(rows.saturating_sub(visible) as u16);
    frame.render_widget(Clear, popup);
    frame.render_widget(
        paragraph.scroll((scroll, 0)).block(
            Block::bordered()
                .title(Span::styled(" In full ", app.theme.title))
                .title_bottom(Line::styled(
                    " j k scroll · any other key closes ",
                    app.theme.dim,
                )),
        ),
        popup,
    );
}
