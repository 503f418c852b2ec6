//! Pop-ups over the panes: help, the save prompt and the preset picker.

use ratatui::Frame;
use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, List, ListItem, ListState, Paragraph, Wrap};
use ratatui_textarea::TextArea;

use crate::preset::escape_text;
use crate::tui::app::{App, PickItem};
use crate::tui::keymap;
use crate::tui::theme::Theme;

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
    let mut lines: Vec<Line> = keymap::help()
        .into_iter()
        .map(|(keys, what)| {
            Line::from(vec![
                Span::styled(format!("{keys:<16}"), theme.key),
                Span::raw(what),
            ])
        })
        .collect();
    lines.push(Line::styled("any key closes this help", theme.dim));
    let popup = centered(area, 68, lines.len() as u16 + 2);
    frame.render_widget(Clear, popup);
    frame.render_widget(
        Paragraph::new(lines).block(Block::bordered().title(Span::styled(" Keys ", theme.title))),
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
    let popup = centered(area, 76, items.len() as u16 + 6);
    frame.render_widget(Clear, popup);
    let block = Block::bordered().title(Span::styled(" Open preset ", theme.title));
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [list_area, message] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(2)]).areas(inner);
    let list: Vec<ListItem> = items
        .iter()
        .map(|item| {
            let style = if item.preset.is_some() {
                theme.plain
            } else {
                theme.broken
            };
            ListItem::new(Line::from(vec![
                Span::styled(
                    format!("{:<14}", escape_text(&item.name)),
                    Theme::strong(style),
                ),
                Span::styled(escape_text(&item.detail), style),
            ]))
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
        None => Paragraph::new(Line::styled("Enter loads · Esc cancels", theme.dim)),
    };
    frame.render_widget(line.wrap(Wrap { trim: true }), message);
}
