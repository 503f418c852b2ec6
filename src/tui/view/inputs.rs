//! The inputs pane: every key of the scene, grouped, with the selected one's
//! description (or the edit box and its error) at the bottom.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Wrap};

use crate::model::keys::KEYS;
use crate::tui::app::{App, Field, Mode};
use crate::tui::format::format_value;
use crate::tui::layout::{input_scroll, inputs_list};
use crate::tui::theme::{self, dim, title_style};

pub fn draw(frame: &mut Frame, area: Rect, app: &App) {
    let block = Block::bordered().title(Span::styled(" Inputs ", title_style()));
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let list = inputs_list(area);
    let about = Rect::new(
        inner.x,
        list.bottom(),
        inner.width,
        inner.bottom() - list.bottom(),
    );
    let wide = inner.width >= 40;
    let editing = match &app.mode {
        Mode::Edit { text, error, .. } => Some((text, error)),
        _ => None,
    };

    // Rows, with a header line before each group (as `layout` counts them,
    // so that a click lands on the row drawn); remember the selected row.
    let lines = app.input_lines();
    let mut rows: Vec<Line> = Vec::new();
    let mut selected_row = 0;
    for (line, field) in lines.iter().enumerate() {
        let Some(i) = *field else {
            let group = lines[line + 1].map_or("", |i| app.fields[i].group());
            rows.push(Line::styled(format!("─ {group}"), dim()));
            continue;
        };
        let field = &app.fields[i];
        let selected = i == app.selected;
        if selected {
            selected_row = rows.len();
        }
        let (symbol, name, value, unit) = match field {
            Field::Preset => ("", "preset", app.preset_name.clone(), ""),
            Field::Drag => ("C_D", "drag", app.scene.drag.name().to_owned(), ""),
            Field::Key(k) => {
                let key = &KEYS[*k];
                let short = key.name.split('.').nth(1).unwrap_or(key.name);
                (
                    key.symbol,
                    short,
                    format_value(key, (key.get)(&app.scene)),
                    key.unit,
                )
            }
        };
        let label = if wide {
            format!("{symbol:<5} {name:<19}")
        } else if symbol.is_empty() {
            format!("{name:<6}")
        } else {
            format!("{symbol:<6}")
        };
        let marker = if selected { "▶" } else { " " };
        let style = if selected {
            theme::SELECTED
        } else {
            theme::PLAIN
        };
        let value_width = (inner.width as usize).saturating_sub(label.chars().count() + 2 + 7);
        rows.push(Line::from(vec![
            Span::raw(marker),
            Span::styled(format!("{label} {value:>value_width$} {unit:<6}"), style),
        ]));
    }

    // Keep the selected row in view.
    let offset = input_scroll(selected_row, rows.len(), list.height as usize);
    frame.render_widget(Paragraph::new(rows).scroll((offset as u16, 0)), list);

    if let Some((text, _)) = editing {
        let row = list.y + (selected_row - offset) as u16;
        if row < list.y + list.height {
            let edit = Rect::new(list.x + 1, row, list.width.saturating_sub(1), 1);
            frame.render_widget(ratatui::widgets::Clear, edit);
            frame.render_widget(text, edit);
        }
    }

    let about_text = match editing {
        Some((_, Some(error))) => Paragraph::new(Line::styled(error.as_str(), theme::ERROR)),
        Some((_, None)) => Paragraph::new(Line::styled("Enter accepts · Esc cancels", dim())),
        None if app.message.is_some() => {
            let (message, error) = app.message.as_ref().expect("checked");
            let style = if *error { theme::ERROR } else { theme::GOOD };
            Paragraph::new(Line::styled(message.as_str(), style))
        }
        None => {
            let text = match app.fields[app.selected] {
                Field::Preset => format!("{} — Enter or o: open a preset", app.description),
                Field::Drag => format!("model.drag: {}", app.scene.drag.description()),
                Field::Key(k) => {
                    let key = &KEYS[k];
                    format!(
                        "{}: {} {}, step {}",
                        key.name, key.description, key.bounds, key.step
                    )
                }
            };
            Paragraph::new(Line::styled(text, dim()))
        }
    };
    frame.render_widget(about_text.wrap(Wrap { trim: true }), about);
}
