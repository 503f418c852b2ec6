//! The inputs pane: every key of the scene, grouped, with the range one
//! nudge gains beside each (at the current swing and, where there is room,
//! at the optimum), and the selected one's description (or the edit box and
//! its error) at the bottom.
//!
//! Columns, by priority as the pane narrows: the input in words beside its
//! symbol, value and unit always (a value is never cut, a word never
//! dropped); then Δ (the range gained by one step up at the current swing);
//! then Δopt (the optimal range gained). Where Δ does not fit as a number
//! it is shown as a sign repeated by size (+++ to +, or ·).

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Wrap};

use super::inputs_view::{Editing, Inputs};
use crate::app::{Field, GainCell, input_key};
use crate::format::{shown_bounds, shown_range, shown_step, value_and_unit};
use crate::inputs::input_words;
use crate::layout::{input_scroll, inputs_list};
use crate::worker::Gain;
use analysis::sensitivity;
use model::aero::{DragModel, LiftModel};
use model::keys::HAND_KEY;
use model::scene::Hand;
use preset::escape_text;

/// Display width of the unit column (rad/s, kg/m³).
const UNIT: usize = 5;
/// A numeric Δ column, its separating space included ("+12.34").
const GAIN: usize = 7;
/// The compact Δ column, its separating space included ("+++").
const COMPACT: usize = 4;

/// Which columns fit the pane.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Columns {
    /// Width of the label column: the longest "words symbol" shown.
    label: usize,
    /// Width of the value column: the widest value shown.
    value: usize,
    swing: Option<Sensitivity>,
    optimum: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Sensitivity {
    Numbers,
    Signs,
}

fn width(text: &str) -> usize {
    Span::raw(text).width()
}

/// `text` padded with spaces to `cells` display cells, left or right aligned.
fn pad(text: &str, cells: usize, right: bool) -> String {
    let fill = " ".repeat(cells.saturating_sub(width(text)));
    if right {
        format!("{fill}{text}")
    } else {
        format!("{text}{fill}")
    }
}

fn columns(inner: usize, label: usize, value: usize) -> Columns {
    // marker, words and symbol, space, value, space, unit
    let base = 1 + label + 1 + value + 1 + UNIT;
    let mut c = Columns {
        label,
        value,
        swing: None,
        optimum: false,
    };
    let used = base;
    if used + GAIN <= inner {
        c.swing = Some(Sensitivity::Numbers);
        if used + 2 * GAIN <= inner {
            c.optimum = true;
        }
    } else if used + COMPACT <= inner {
        c.swing = Some(Sensitivity::Signs);
    }
    c
}

/// A gain in the pane's unit, to fit 6 cells: +4.01, -0.10, +12.3, +123.
fn gain_text(value: f64) -> String {
    let a = value.abs();
    if a < 0.005 {
        // A gain that rounds to nothing has no sign worth showing: μ's at
        // the optimum is a few ulps either side of 0, and "-0.00" flips
        // with any change of the numerics.
        "+0.00".to_owned()
    } else if a < 9.995 {
        format!("{value:+.2}")
    } else if a < 99.95 {
        format!("{value:+.1}")
    } else {
        format!("{value:+.0}")
    }
}

/// A gain as signs repeated by its share of the largest: "+++" to "+", "·"
/// below a hundredth of it.
fn gain_signs(value: f64, max: f64) -> String {
    let share = value.abs() / max;
    let count = [0.01, 0.1, 0.5].iter().filter(|t| share >= **t).count();
    if count == 0 {
        "·".to_owned()
    } else {
        let sign = if value >= 0.0 { "+" } else { "-" };
        sign.repeat(count)
    }
}

/// One sensitivity cell, `cells` wide: its text and style.
fn gain_span(
    view: &Inputs,
    cell: Option<GainCell>,
    max: f64,
    form: Sensitivity,
    cells: usize,
    fixed: bool,
) -> Span<'static> {
    let (text, style) = match cell {
        None => (String::new(), view.theme.plain),
        // At the optimum, the swing's own inputs change nothing.
        Some(GainCell { value: None, .. }) if !fixed => ("—".to_owned(), view.theme.dim),
        Some(GainCell { value: None, .. }) => ("0".to_owned(), view.theme.dim),
        Some(GainCell {
            value: Some(v),
            generation,
        }) => {
            let v = view.distance(v).0;
            let text = match form {
                Sensitivity::Numbers => gain_text(v),
                Sensitivity::Signs => gain_signs(v, max),
            };
            let style = if generation != view.generation {
                view.theme.stale_gain
            } else {
                view.theme.gain(v, max)
            };
            (text, style)
        }
    };
    Span::styled(format!(" {}", pad(&text, cells - 1, true)), style)
}

/// The largest |gain| of a kind, in the pane's unit (1 if none yet).
fn largest(view: &Inputs, gain: Gain) -> f64 {
    let max = view
        .gains(gain)
        .iter()
        .filter_map(|c| c.and_then(|c| c.value))
        .map(|v| view.distance(v).0.abs())
        .fold(0.0, f64::max);
    if max > 0.0 { max } else { 1.0 }
}

/// The pane's title: "Inputs" at the left, the Δ columns' heads at the right
/// above their columns (in the busy colour while any is being computed).
fn title(view: &Inputs, c: Columns) -> (Line<'static>, Option<Line<'static>>) {
    let left = Line::from(Span::styled(" Inputs ", view.theme.title));
    let Some(form) = c.swing else {
        return (left, selected_gain(view));
    };
    let unit = view.distance(1.0).1;
    // Each head is right-aligned over its column; the border runs on to it.
    let head = |text: String, gain: Gain, cells: usize| {
        let busy = view.gains_busy(gain);
        let style = if busy {
            view.theme.busy
        } else {
            view.theme.dim
        };
        let text = format!(" {text}");
        [
            Span::raw("─".repeat(cells.saturating_sub(width(&text)))),
            Span::styled(text, style),
        ]
    };
    let mut spans = Vec::from(head(
        match form {
            Sensitivity::Numbers => format!("Δ {unit}"),
            Sensitivity::Signs => "Δ".to_owned(),
        },
        Gain::Swing,
        match form {
            Sensitivity::Numbers => GAIN - 1,
            Sensitivity::Signs => COMPACT - 1,
        },
    ));
    if c.optimum {
        spans.extend(head("Δopt".to_owned(), Gain::Optimum, GAIN));
    }
    (left, Some(Line::from(spans).right_aligned()))
}

pub fn draw(frame: &mut Frame, area: Rect, view: &Inputs) {
    let c = fitted_columns(view, Block::bordered().inner(area).width as usize);
    let (left, right) = title(view, c);
    let mut block = Block::bordered().title(left);
    if let Some(right) = right {
        block = block.title(right);
    }
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let list = inputs_list(area);
    let editing = view.editing;
    // Rows, with a header line before each group (as `layout` counts them,
    // so that a click lands on the row drawn); remember the selected row
    // and where its edit box goes (offset from the list's left, width).
    let lines = &view.lines;
    let mut rows: Vec<Line> = Vec::new();
    let (mut selected_row, mut edit_box) = (0, (0, 0));
    for (line, field) in lines.iter().enumerate() {
        let Some(i) = *field else {
            let group = lines[line + 1].map_or("", |i| view.fields[i].group());
            rows.push(Line::styled(format!("─ {group}"), view.theme.dim));
            continue;
        };
        if i == view.selected {
            selected_row = rows.len();
        }
        let (row, at) = field_row(view, i, c, editing, list);
        edit_box = at.unwrap_or(edit_box);
        rows.push(row);
    }
    // Keep the selected row in view.
    let offset = input_scroll(selected_row, rows.len(), list.height as usize);
    frame.render_widget(Paragraph::new(rows).scroll((offset as u16, 0)), list);
    if let Some((text, _)) = editing {
        let row = list.y + (selected_row - offset) as u16;
        if row < list.y + list.height {
            let (at, cells) = edit_box;
            let edit = Rect::new(list.x + at as u16, row, cells as u16, 1);
            frame.render_widget(ratatui::widgets::Clear, edit);
            frame.render_widget(text, edit);
        }
    }
    let about = Rect::new(
        inner.x,
        list.bottom(),
        inner.width,
        inner.bottom() - list.bottom(),
    );
    draw_about(frame, (area, about), view, editing);
}

/// The columns that fit a pane `inner_width` wide, for the values shown now.
fn fitted_columns(view: &Inputs, inner_width: usize) -> Columns {
    // The widest value and name of the numeric rows, as shown now.
    let value_width = view
        .fields
        .iter()
        .filter_map(|f| match f {
            Field::Key(k) => Some(input_key(*k)),
            _ => None,
        })
        .map(|key| width(&value_and_unit(key, (key.get)(view.scene), view.units).0))
        .max()
        .unwrap_or(0);
    let label_width = view
        .fields
        .iter()
        .map(|f| width(&label_text(*f)))
        .max()
        .unwrap_or(0);
    // A narrow pane gives the words their room and rounds the widest values
    // (a derived ν) to fewer decimals, rather than cut a row.
    let room = inner_width.saturating_sub(1 + label_width + 1 + 1 + UNIT);
    let value_width = value_width.min(room.max(6));
    let mut c = columns(inner_width, label_width, value_width);
    // A batted ball has no optimum, so no Δopt.
    c.optimum &= view.is_swing();
    c
}

/// The row of field `i`: its marker, words, value and unit (or the room
/// for the edit box, whose place it returns), and its Δ columns.
fn field_row(
    view: &Inputs,
    i: usize,
    c: Columns,
    editing: Editing,
    list: Rect,
) -> (Line<'static>, Option<(usize, usize)>) {
    let field = &view.fields[i];
    let selected = i == view.selected;
    let (value, unit) = match field {
        Field::Preset => (escape_text(view.preset_name), ""),
        // A model's name is a word: never cut (it takes the unit's room).
        Field::Drag => (view.scene.drag.name().to_owned(), ""),
        Field::Lift => (view.scene.lift.name().to_owned(), ""),
        Field::Hand => (view.scene.bat.hand.name().to_owned(), ""),
        Field::Key(k) => {
            let key = input_key(*k);
            let (value, unit) = value_and_unit(key, (key.get)(view.scene), view.units);
            (fitted_number(value, c.value), unit)
        }
    };
    let mut label = pad(&label_text(*field), c.label, false);
    let mut edit_box = None;
    if let (true, Some((typing, _))) = (selected, editing) {
        // The box takes the value's place; the symbol (and the name)
        // before it and the unit after it stay.
        let at = 1 + width(&label) + 1;
        let typed = width(&typing.lines().join("")) + 1;
        let (room, unit_cells) = match field {
            Field::Key(_) => (c.value.max(typed), 1 + UNIT),
            _ => ((c.value + 1 + UNIT).max(typed), 0),
        };
        let room = room.min((list.width as usize).saturating_sub(at + unit_cells));
        edit_box = Some((at, room));
        label.push_str(&" ".repeat(1 + room));
        if let Field::Key(_) = field {
            label.push_str(&format!(" {}", pad(unit, UNIT, false)));
        }
    } else {
        label.push_str(&match field {
            // A numeric value, right-aligned in its column, then the unit.
            Field::Key(_) => format!(" {} {}", pad(&value, c.value, true), pad(unit, UNIT, false)),
            // A name spans the value and unit columns, and further if long.
            _ => format!(" {}", pad(&value, c.value + 1 + UNIT, true)),
        });
    }
    let (marker, style) = if selected {
        ("▶", view.theme.selected)
    } else {
        (" ", view.theme.plain)
    };
    let mut spans = vec![Span::raw(marker), Span::styled(label, style)];
    if let (Field::Key(k), false) = (field, edit_box.is_some()) {
        spans.extend(gain_spans(view, *k, c));
    }
    (Line::from(spans), edit_box)
}

/// Input `k`'s Δ and Δopt, as the columns show them.
fn gain_spans(view: &Inputs, k: usize, c: Columns) -> Vec<Span<'static>> {
    let Some(form) = c.swing else {
        return Vec::new();
    };
    let cells = match form {
        Sensitivity::Numbers => GAIN,
        Sensitivity::Signs => COMPACT,
    };
    let max_swing = largest(view, Gain::Swing);
    let mut spans = vec![gain_span(
        view,
        view.gain(Gain::Swing, k),
        max_swing,
        form,
        cells,
        false,
    )];
    if c.optimum {
        spans.push(gain_span(
            view,
            view.gain(Gain::Optimum, k),
            largest(view, Gain::Optimum),
            Sensitivity::Numbers,
            GAIN,
            !sensitivity::moves_optimum(input_key(k)),
        ));
    }
    spans
}

/// Under the list: the edit's refusal or help, the message, or the
/// selected input's description; where its words are cut, the pane's
/// (`area`'s) foot says where the rest is (`i` shows it whole).
fn draw_about(frame: &mut Frame, (area, about): (Rect, Rect), view: &Inputs, editing: Editing) {
    let (about_words, about_style) = match editing {
        Some((_, Some(error))) => (error.clone(), view.theme.error),
        Some((_, None)) => (edit_help(view, view.fields[view.selected]), view.theme.dim),
        None => match &view.message {
            Some((message, true)) => (escape_text(message), view.theme.error),
            Some((message, false)) => (escape_text(message), view.theme.good),
            None => (about_selected(view), view.theme.dim),
        },
    };
    let cut = super::words::rows_needed(&[Span::raw(about_words.as_str())], about.width as usize)
        > about.height as usize;
    let about_text = Paragraph::new(Line::styled(about_words, about_style));
    let about_text = about_text.wrap(Wrap { trim: true });
    if cut {
        super::read_all_hint(frame, area, view.theme);
    }
    frame.render_widget(about_text, about);
}

/// What the selected input is, its range and step, in words.
pub(super) fn about_selected(view: &Inputs) -> String {
    match view.fields[view.selected] {
        Field::Preset => format!(
            "{} — h l: the previous / next preset · Enter or o: open one",
            escape_text(view.description)
        ),
        Field::Drag => format!("model.drag (h l): {}", view.scene.drag.description()),
        Field::Lift => format!("model.lift (h l): {}", view.scene.lift.description()),
        Field::Hand => format!(
            "{HAND_KEY} (h l): {} batter, right or left",
            view.scene.bat.hand.description()
        ),
        Field::Key(k) => {
            let key = input_key(k);
            format!(
                "{}: {} {}, step {}",
                key.name,
                key.description,
                shown_bounds(key, view.units),
                shown_step(key, view.units)
            )
        }
    }
}

/// Where the pane has no Δ column (80×24), the selected input's Δ at the
/// title's right, marked as the selected row is (" ▶ Δ +2.01 m "): grey
/// while it is computed, "…" before it first is, none for a model or the
/// preset.
fn selected_gain(view: &Inputs) -> Option<Line<'static>> {
    let Field::Key(k) = view.fields[view.selected] else {
        return None;
    };
    let unit = view.distance(1.0).1;
    let (text, style) = match view.gain(Gain::Swing, k) {
        Some(GainCell {
            value: Some(v),
            generation,
        }) => {
            let v = view.distance(v).0;
            let style = if generation == view.generation {
                view.theme.gain(v, largest(view, Gain::Swing))
            } else {
                view.theme.stale_gain
            };
            (format!("{} {unit}", gain_text(v)), style)
        }
        // Refused (at a bound) or not landing, as in the column.
        Some(GainCell { value: None, .. }) => ("—".to_owned(), view.theme.dim),
        None => ("…".to_owned(), view.theme.busy),
    };
    Some(
        Line::from(vec![
            Span::styled(" ▶ Δ ", view.theme.dim),
            Span::styled(text, style),
            Span::raw(" "),
        ])
        .right_aligned(),
    )
}

/// A number's text rounded to fewer decimals until it fits `cells` (its
/// whole part is never cut).
fn fitted_number(text: String, cells: usize) -> String {
    // A degree sign stays on its number, however few digits fit.
    if let Some(number) = text.strip_suffix('°') {
        let fitted = fitted_number(number.to_owned(), cells.saturating_sub(1));
        return format!("{fitted}°");
    }
    // A number in scientific notation (ν) is short already.
    if text.contains('e') {
        return text;
    }
    let Ok(value) = text.parse::<f64>() else {
        return text;
    };
    let mut decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
    let mut shown = text;
    while width(&shown) > cells && decimals > 0 {
        decimals -= 1;
        shown = format!("{value:.decimals$}");
    }
    shown
}

/// A row's label: the input in words, then its symbol ("swing angle ψ").
fn label_text(field: Field) -> String {
    let (words, symbol) = match field {
        Field::Preset => ("preset", ""),
        Field::Drag => ("drag", "C_D"),
        Field::Lift => ("lift", "C_L"),
        Field::Hand => ("batter", ""),
        Field::Key(k) => {
            let key = input_key(k);
            (input_words(key.name), key.symbol)
        }
    };
    if symbol.is_empty() {
        words.to_owned()
    } else {
        format!("{words} {symbol}")
    }
}

/// What an edit takes, under its box: the key, its unit and its accepted
/// range ("bat.speed in m/s, (0, 100]"), or a model's choices.
fn edit_help(view: &Inputs, field: Field) -> String {
    let takes = match field {
        Field::Key(k) => {
            let key = input_key(k);
            let range = shown_range(key, view.units);
            match key.unit_in(view.units).symbol {
                "" => format!("{}: {range}", key.name),
                unit => format!("{} in {unit}, {range}", key.name),
            }
        }
        Field::Drag => format!("model.drag: {}", names(&DragModel::ALL.map(|m| m.name()))),
        Field::Lift => format!("model.lift: {}", names(&LiftModel::ALL.map(|m| m.name()))),
        Field::Hand => format!("{HAND_KEY}: {}", names(&Hand::ALL.map(|h| h.name()))),
        Field::Preset => String::new(),
    };
    format!("{takes} · Enter accepts · Esc cancels")
}

/// "a, b or c".
fn names(all: &[&str]) -> String {
    match all.split_last() {
        Some((last, [])) => (*last).to_owned(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_give_way_in_order_and_never_cut_a_value() {
        // 80×24: 29 cells inside; values up to 8 wide ("0.000015"): the
        // words, never Δ.
        let narrow = columns(29, 13, 8);
        assert_eq!(narrow.swing, None);
        assert!(!narrow.optimum);
        assert_eq!(columns(33, 13, 8).swing, Some(Sensitivity::Signs));
        assert_eq!(columns(20, 13, 12).swing, None);
        // 56 inside: both Δ columns.
        let wide = columns(56, 13, 8);
        assert!(wide.optimum && wide.swing == Some(Sensitivity::Numbers));
    }

    #[test]
    fn gains_fit_six_cells_and_signs_grade_by_share() {
        for (v, text) in [
            (4.0123, "+4.01"),
            (-0.1, "-0.10"),
            (12.34, "+12.3"),
            (123.4, "+123"),
            (-1234.0, "-1234"),
            (-1e-15, "+0.00"),
            (-0.004, "+0.00"),
            (-0.006, "-0.01"),
        ] {
            assert_eq!(gain_text(v), text);
        }
        assert_eq!(gain_signs(2.0, 2.0), "+++");
        assert_eq!(gain_signs(-0.5, 2.0), "--");
        assert_eq!(gain_signs(0.1, 2.0), "+");
        assert_eq!(gain_signs(0.001, 2.0), "·");
    }
}
