//! Pop-ups over the panes: help, the save prompt and the preset picker.

use ratatui::Frame;
use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, List, ListItem, ListState, Paragraph, Wrap};
use ratatui_textarea::TextArea;

use crate::app::{App, PickItem};
use crate::keymap;
use crate::theme::Theme;
use preset::escape_text;

fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let [row] = Layout::vertical([Constraint::Length(height.min(area.height))])
        .flex(Flex::Center)
        .areas(area);
    let [cell] = Layout::horizontal([Constraint::Length(width.min(area.width))])
        .flex(Flex::Center)
        .areas(row);
    cell
}

pub fn help(frame: &mut Frame, area: Rect, theme: &Theme) {
    let lines: Vec<Line> = keymap::help()
        .into_iter()
        .map(|(keys, what)| {
            Line::from(vec![
                Span::styled(format!("{keys:<16}"), theme.key),
                Span::raw(what),
            ])
        })
        .collect();
    // The closing line on the border, so that it shows even where the keys
    // fill the screen (80×24).
    let popup = centered(area, 68, lines.len() as u16 + 2);
    frame.render_widget(Clear, popup);
    frame.render_widget(
        Paragraph::new(lines).block(
            Block::bordered()
                .title(Span::styled(" Keys ", theme.title))
                .title_bottom(Line::styled(" any key closes this help ", theme.dim)),
        ),
        popup,
    );
}

pub fn save(frame: &mut Frame, area: Rect, app: &App, text: &TextArea, error: Option<&str>) {
    let popup = centered(area, 64, 8);
    frame.render_widget(Clear, popup);
    let block = Block::bordered().title(Span::styled(" Save preset ", app.theme.title));
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [folder, input, message] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Length(1),
        Constraint::Fill(1),
    ])
    .areas(inner);
    let dir = app
        .presets_dir
        .as_ref()
        .map_or("(no folder)".to_owned(), |d| d.display().to_string());
    frame.render_widget(
        Paragraph::new(Line::styled(format!("name, into {dir}:"), app.theme.dim)),
        folder,
    );
    frame.render_widget(text, input);
    let line = match error {
        Some(e) => Paragraph::new(Line::styled(e, app.theme.error)),
        None => Paragraph::new(Line::styled(
            "letters, digits, - and _ · Enter saves · Esc cancels",
            app.theme.dim,
        )),
    };
    frame.render_widget(line.wrap(Wrap { trim: true }), message);
}

pub fn open(
    frame: &mut Frame,
    (area, theme): (Rect, &Theme),
    items: &[PickItem],
    selected: usize,
    error: Option<&str>,
) {
    let popup = centered(area, 76, items.len() as u16 + 7);
    frame.render_widget(Clear, popup);
    let block = Block::bordered().title(Span::styled(" Open preset ", theme.title));
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [list_area, message] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(3)]).areas(inner);
    // Each description fitted at words to its row ("…" where words are
    // left over); the selected one's is shown whole under the list.
    let detail_width = (list_area.width as usize).saturating_sub(2 + 14);
    let list: Vec<ListItem> = items
        .iter()
        .map(|item| {
            let style = if item.preset.is_some() {
                theme.plain
            } else {
                theme.broken
            };
            let detail = super::words::fit(
                &[Span::styled(escape_text(&item.detail), style)],
                detail_width,
                1,
            );
            let mut spans = vec![Span::styled(
                format!("{:<14}", escape_text(&item.name)),
                Theme::strong(style),
            )];
            spans.extend(detail.into_iter().flat_map(|l| l.spans));
            ListItem::new(Line::from(spans))
        })
        .collect();
    let mut state = ListState::default().with_selected(Some(selected));
    frame.render_stateful_widget(
        List::new(list)
            .highlight_style(theme.selected)
            .highlight_symbol("▶ "),
        list_area,
        &mut state,
    );
    let line = match error {
        Some(e) => Paragraph::new(Line::styled(e, theme.broken)),
        None => Paragraph::new(Line::styled(
            format!(
                "{} · Enter loads · Esc cancels",
                items.get(selected).map_or("", |i| i.detail.as_str())
            ),
            theme.dim,
        )),
    };
    frame.render_widget(line.wrap(Wrap { trim: true }), message);
}
