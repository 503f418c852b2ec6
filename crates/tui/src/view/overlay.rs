//! Pop-ups over the panes: help, the save prompt, the preset picker and
//! the park list.

use ratatui::Frame;
use ratatui::layout::{Constraint, Flex, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, List, ListItem, ListState, Paragraph, Wrap};
use ratatui_textarea::TextArea;

use crate::app::{App, Pick, Searchable};
use crate::glossary::GLOSSARY;
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

/// The help: the keys, or (Tab) the glossary of the symbols on screen,
/// scrolled by `scroll` rows where it is taller than the screen.
pub fn help(frame: &mut Frame, area: Rect, app: &App, (glossary, scroll): (bool, u16)) {
    let theme = &app.theme;
    // The keys' page leaves the selected input in view at 80×24.
    let width: u16 = if glossary { 76 } else { 68 };
    let lines = if glossary {
        glossary_lines(app, width.min(area.width).saturating_sub(2))
    } else {
        keymap::help()
            .into_iter()
            .map(|(keys, what)| {
                Line::from(vec![
                    Span::styled(format!("{keys:<16}"), theme.key),
                    Span::raw(what),
                ])
            })
            .collect()
    };
    // The closing line on the border, so that it shows even where the keys
    // fill the screen (80×24).
    let popup = centered(area, width, (lines.len() as u16).saturating_add(2));
    let visible = popup.height.saturating_sub(2);
    let scroll = scroll.min((lines.len() as u16).saturating_sub(visible));
    let (title, bottom) = if glossary {
        (
            " Glossary: what each symbol means ",
            " Tab: keys · j k scroll · any other key closes ",
        )
    } else {
        (
            " Keys ",
            " Tab: glossary · j k scroll · any other key closes ",
        )
    };
    frame.render_widget(Clear, popup);
    frame.render_widget(
        Paragraph::new(lines).scroll((scroll, 0)).block(
            Block::bordered()
                .title(Span::styled(title, theme.title))
                .title_bottom(Line::styled(bottom, theme.dim)),
        ),
        popup,
    );
}

/// Column of the glossary's meanings: symbols stand left of it.
const GLOSSARY_INDENT: usize = 14;

/// Each symbol, then its meaning wrapped at words under a hanging indent,
/// with its unit in the system shown and where the paper defines it.
fn glossary_lines(app: &App, width: u16) -> Vec<Line<'static>> {
    let text_width = (width as usize).saturating_sub(GLOSSARY_INDENT).max(10);
    let mut lines = Vec::new();
    for entry in GLOSSARY {
        let unit = entry
            .quantity
            .map_or(String::new(), |q| format!(" [{}]", app.unit(q).symbol));
        let text = vec![
            Span::raw(entry.meaning),
            Span::raw(unit),
            Span::styled(format!(" ({})", entry.source), app.theme.dim),
        ];
        for (k, row) in super::words::fit(&text, text_width, 8)
            .into_iter()
            .enumerate()
        {
            let symbol = if k == 0 { entry.symbol } else { "" };
            let pad = GLOSSARY_INDENT.saturating_sub(Span::raw(symbol).width());
            let mut spans = vec![
                Span::styled(symbol, app.theme.key),
                Span::raw(" ".repeat(pad)),
            ];
            spans.extend(row.spans);
            lines.push(Line::from(spans));
        }
    }
    lines
}

/// The save prompt: the name (`named` is `None`), then the description.
pub fn save(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    text: &TextArea,
    (error, named): (Option<&str>, Option<&str>),
) {
    let popup = centered(area, 64, 9);
    frame.render_widget(Clear, popup);
    let block = Block::bordered().title(Span::styled(" Save preset ", app.theme.title));
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [asked, input, message] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Length(1),
        Constraint::Fill(1),
    ])
    .areas(inner);
    let (question, hint) = match named {
        None => {
            let dir = app
                .presets_dir
                .as_ref()
                .map_or("(no folder)".to_owned(), |d| d.display().to_string());
            (
                format!("1/2 name, into {dir}:"),
                "letters, digits, - and _ · Enter: on to the description · Esc cancels".to_owned(),
            )
        }
        Some(name) => (
            format!("2/2 what `{name}` is for (the picker shows it):"),
            format!(
                "Enter saves it with the park, its air and the units · empty: \"{}\" · Esc cancels",
                app.default_description()
            ),
        ),
    };
    frame.render_widget(Paragraph::new(Line::styled(question, app.theme.dim)), asked);
    frame.render_widget(text, input);
    let line = match error {
        Some(e) => Paragraph::new(Line::styled(e, app.theme.error)),
        None => Paragraph::new(Line::styled(hint, app.theme.dim)),
    };
    frame.render_widget(line.wrap(Wrap { trim: true }), message);
}

pub fn open(
    frame: &mut Frame,
    (area, theme): (Rect, &Theme),
    (items, find): (&[Pick], Option<&str>),
    swings: &Searchable,
    selected: usize,
    error: Option<&str>,
) {
    let popup = centered(area, 76, (items.len() as u16).saturating_add(7));
    frame.render_widget(Clear, popup);
    // While a find is typed, the title shows it (`/` starts one).
    let title = match find {
        Some(find) => format!(
            " Open: find {}▏ ({} found) ",
            escape_text(find),
            items.len()
        ),
        // `tui --savant`: the file's swings come first, then the presets.
        None if !swings.is_empty() => {
            format!(" Open a swing ({}) or a preset (/ finds) ", swings.len())
        }
        None => " Open preset (/ finds) ".to_owned(),
    };
    let block = Block::bordered().title(Span::styled(title, theme.title));
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [list_area, message] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(3)]).areas(inner);
    // Each description fitted at words to its row ("…" where words are
    // left over); the selected one's is shown whole under the list.
    let detail_width = (list_area.width as usize).saturating_sub(2 + 14);
    // Only the rows in view are made: a Savant export's swings are
    // thousands (`tui --savant`).
    let height = (list_area.height as usize).max(1);
    let offset = (selected + 1).saturating_sub(height);
    let list: Vec<ListItem> = items
        .iter()
        .skip(offset)
        .take(height)
        .map(|item| {
            let style = match item {
                Pick::Preset(item) if item.preset.is_none() => theme.broken,
                _ => theme.plain,
            };
            let detail = super::words::fit(
                &[Span::styled(escape_text(item.detail(swings)), style)],
                detail_width,
                1,
            );
            let mut spans = vec![Span::styled(
                name_cell(item.name(swings)),
                Theme::strong(style),
            )];
            spans.extend(detail.into_iter().flat_map(|l| l.spans));
            ListItem::new(Line::from(spans))
        })
        .collect();
    let mut state = ListState::default().with_selected(Some(selected - offset));
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
                items.get(selected).map_or("", |i| i.detail(swings))
            ),
            theme.dim,
        )),
    };
    frame.render_widget(line.wrap(Wrap { trim: true }), message);
}

/// A picker row's name in its 14 columns, escaped, a blank after it: a
/// longer one (a Savant row's long `game_date`) is cut with "…" rather
/// than push the description off the row.
fn name_cell(name: &str) -> String {
    use unicode_width::UnicodeWidthChar;
    const COLUMNS: usize = 14;
    let name = escape_text(name);
    let width = |c: char| c.width().unwrap_or(0);
    let mut cell = String::new();
    let mut used = 0;
    if name.chars().map(width).sum::<usize>() < COLUMNS {
        cell.push_str(&name);
        used = name.chars().map(width).sum();
    } else {
        // Room for the "…" and the blank.
        for c in name.chars() {
            if used + width(c) > COLUMNS - 2 {
                break;
            }
            cell.push(c);
            used += width(c);
        }
        cell.push('…');
        used += 1;
    }
    cell.extend(std::iter::repeat_n(' ', COLUMNS - used));
    cell
}

/// The park list (`/`): what is typed, then the parks that answer to it
/// (code, name, city), the chosen one marked; under it the keys.
pub fn parks(frame: &mut Frame, area: Rect, app: &App, query: &str, selected: usize) {
    let theme = &app.theme;
    let found = app.parks_matching(query);
    let height = (found.len() as u16 + 6).min(area.height.saturating_sub(2));
    let popup = centered(area, 60, height);
    frame.render_widget(Clear, popup);
    let title = format!(" Parks: {} of {} ", found.len(), app.parks.list.parks.len());
    let block = Block::bordered().title(Span::styled(title, theme.title));
    let inner = block.inner(popup);
    frame.render_widget(block, popup);
    let [typed, list_area, keys] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(2),
    ])
    .areas(inner);
    frame.render_widget(
        Paragraph::new(Line::from(vec![
            Span::styled("find: ", theme.dim),
            Span::styled(format!("{}▏", escape_text(query)), theme.selected),
        ])),
        typed,
    );
    let width = (list_area.width as usize).saturating_sub(2 + 5);
    let list: Vec<ListItem> = found
        .iter()
        .map(|&k| {
            let p = &app.parks.list.parks[k];
            let place = if p.city.is_empty() {
                escape_text(&p.name)
            } else {
                format!("{}, {}", escape_text(&p.name), escape_text(&p.city))
            };
            let mut spans = vec![Span::styled(
                format!("{:<5}", escape_text(&p.code)),
                Theme::strong(theme.plain),
            )];
            let place = super::words::fit(&[Span::styled(place, theme.plain)], width, 1);
            spans.extend(place.into_iter().flat_map(|l| l.spans));
            ListItem::new(Line::from(spans))
        })
        .collect();
    if list.is_empty() {
        frame.render_widget(
            Paragraph::new(Line::styled("no park answers: Backspace", theme.broken)),
            list_area,
        );
    } else {
        let at = found.iter().position(|&k| k == selected).unwrap_or(0);
        let mut state = ListState::default().with_selected(Some(at));
        frame.render_stateful_widget(
            List::new(list)
                .highlight_style(theme.selected)
                .highlight_symbol("▶ "),
            list_area,
            &mut state,
        );
    }
    frame.render_widget(
        Paragraph::new(Line::styled(
            "type a code, name or city · ↑ ↓ move · Enter chooses · Esc cancels",
            theme.dim,
        ))
        .wrap(Wrap { trim: true }),
        keys,
    );
}
