//! Drawing: pure functions from the app's state to a frame, one per pane.
//! Nothing here changes the state or computes physics.

mod chart;
mod detail;
mod field;
pub mod figure;
mod figure_panels;
mod heatmap;
mod impact;
mod impact3d;
mod inputs;
mod inputs_view;
mod margin_map;
mod overlay;
pub mod pane_views;
mod paper_line;
mod phase_words;
mod readout;
mod readout_view;
mod trajectory;
mod words;

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Tabs};

use super::app::{App, Mode};
use super::layout::{MIN_SIZE, Tab, layout};
use super::theme::Theme;
use super::worker::Gain;

/// Draws the whole screen from the app's state, then takes out of every
/// cell any control, bidirectional or invisible format character
/// ([`preset::needs_escape`]) that text from a file brought: the
/// views escape the texts they know come from files, and this catches the
/// rest, so that no U+202E reorders the screen and no ESC reaches it.
pub fn draw(frame: &mut Frame, app: &App) {
    draw_panes(frame, app);
    for cell in &mut frame.buffer_mut().content {
        if cell.symbol().chars().any(preset::needs_escape) {
            let kept: String = cell
                .symbol()
                .chars()
                .filter(|c| !preset::needs_escape(*c))
                .collect();
            cell.set_symbol(if kept.is_empty() { " " } else { &kept });
        }
    }
}

fn draw_panes(frame: &mut Frame, app: &App) {
    let area = frame.area();
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        too_small(frame, area, &app.theme);
        return;
    }
    let panes = layout(area, app.tab, app.is_swing());
    inputs::draw(frame, panes.inputs, &inputs_view::Inputs::of(app));
    if let Some(tabs) = panes.tabs {
        let selected = Tab::ALL.iter().position(|t| *t == app.tab).unwrap_or(0);
        let short = Tab::short_titles(tabs.width);
        frame.render_widget(
            Tabs::new(Tab::ALL.iter().map(|t| t.title(short)))
                .select(selected)
                .highlight_style(app.theme.selected)
                .padding("", "")
                .divider(Tab::divider(tabs.width)),
            tabs,
        );
    }
    if let Some(r) = panes.trajectory {
        trajectory::draw(frame, r, &pane_views::Trajectory::of(app));
    }
    if let Some(r) = panes.readout {
        readout::draw(frame, r, &readout_view::Readout::of(app));
    }
    // A batted ball has no swing to vary nor impact to step through.
    if let Some(r) = panes.heatmap {
        if app.is_swing() {
            heatmap::draw(frame, r, &pane_views::Surface::of(app));
        } else {
            swing_only(
                frame,
                r,
                (" Range over (E, ψ) ", "The range surface"),
                &app.theme,
            );
        }
    }
    if let Some(r) = panes.impact {
        if app.is_swing() {
            impact::draw(frame, r, &pane_views::Impact::of(app));
        } else {
            swing_only(frame, r, (" Impact ", "The impact"), &app.theme);
        }
    }
    if let Some(r) = panes.figure {
        figure::draw(frame, r, &pane_views::Figure::of(app));
    }
    if let Some(r) = panes.field {
        field::draw(frame, r, &pane_views::Field::of(app, r));
    }
    status_line(frame, panes.status, app);
    match &app.mode {
        Mode::Help { glossary, scroll } => overlay::help(frame, area, app, (*glossary, *scroll)),
        Mode::Detail { scroll } => detail::draw(frame, area, app, *scroll),
        Mode::Save {
            text, error, named, ..
        } => overlay::save(frame, area, app, text, (error.as_deref(), named.as_deref())),
        Mode::Open {
            items,
            selected,
            error,
            find,
        } => overlay::open(
            frame,
            (area, &app.theme),
            (items, find.as_ref().map(|f| f.text.as_str())),
            &app.swings,
            *selected,
            error.as_deref(),
        ),
        Mode::Parks { query, selected } => overlay::parks(frame, area, app, query, *selected),
        Mode::Normal | Mode::Edit { .. } => {}
    }
}

/// In place of a layout cut to pieces: what size the explorer needs, in
/// the middle of the screen.
fn too_small(frame: &mut Frame, area: Rect, theme: &Theme) {
    let (w, h) = MIN_SIZE;
    let lines = vec![
        Line::styled(format!("terminal too small (need {w}×{h})"), theme.error),
        Line::raw(format!("this one is {}×{}", area.width, area.height)),
        Line::styled("enlarge it, or q to quit", theme.dim),
    ];
    let rows = 3.min(area.height);
    let top = area.y + area.height.saturating_sub(rows) / 2;
    frame.render_widget(
        Paragraph::new(lines)
            .centered()
            .wrap(ratatui::widgets::Wrap { trim: true }),
        Rect::new(area.x, top, area.width, area.height - (top - area.y)),
    );
}

/// A swing scene's pane in the batted-ball scene: one line saying so.
fn swing_only(frame: &mut Frame, area: Rect, (title, what): (&str, &str), theme: &Theme) {
    let text = format!("{what} belongs to the swing scene: b switches to it.");
    frame.render_widget(
        Paragraph::new(Line::styled(text, theme.dim))
            .wrap(ratatui::widgets::Wrap { trim: true })
            .block(
                ratatui::widgets::Block::bordered()
                    .title(Span::styled(title.to_owned(), theme.title)),
            ),
        area,
    );
}

/// " i: read all " on the foot of a pane whose words are cut short: `i`
/// shows them whole ([`detail`]).
pub(super) fn read_all_hint(frame: &mut Frame, pane: Rect, theme: &Theme) {
    let hint = " i: read all ";
    if pane.height == 0 || pane.width < hint.chars().count() as u16 + 2 {
        return;
    }
    let x = pane.x + pane.width - hint.chars().count() as u16 - 1;
    frame
        .buffer_mut()
        .set_string(x, pane.y + pane.height - 1, hint, theme.key);
}

/// Which scene is shown, what is being computed and how fresh each result
/// is; or, until the next key, what `x` wrote or why not.
fn status_line(frame: &mut Frame, area: Rect, app: &App) {
    if let Some((text, error)) = &app.export_message {
        let style = if *error {
            app.theme.error
        } else {
            app.theme.good
        };
        let text = fitted(text, area.width as usize);
        frame.render_widget(Paragraph::new(Line::styled(text, style)), area);
        return;
    }
    let mut spans = Vec::new();
    spans.push(Span::styled(
        if app.is_swing() {
            "swing · "
        } else {
            "batted ball · "
        },
        app.theme.title,
    ));
    spans.push(Span::raw("readout ✓ "));
    if app.is_swing() {
        swing_status(&mut spans, app);
    }
    // The sensitivities: at the current swing (quick), then at the optimum.
    let n = app.gain_count();
    let (swing, optimum) = (app.gains_done(Gain::Swing), app.gains_done(Gain::Optimum));
    spans.push(if swing < n {
        Span::styled("· Δ… ", app.theme.busy)
    } else if !app.optimum_gains_fresh() {
        Span::styled(format!("· Δopt {optimum}/{n}… "), app.theme.busy)
    } else {
        Span::raw("· Δ ✓ ")
    });
    if !app.is_swing() {
        spans.push(Span::styled("· b swing ", app.theme.dim));
    }
    spans.push(Span::styled("· ? help  q quit", app.theme.dim));
    frame.render_widget(Paragraph::new(Line::from(spans)), area);
}

/// The swing scene's background work: the optimum and the surface.
fn swing_status(spans: &mut Vec<Span<'static>>, app: &App) {
    spans.push(match &app.optimum {
        Some(o) if o.done => Span::raw(format!("· optimum ✓ {} evals ", o.evaluations)),
        Some(o) => Span::styled(
            format!("· optimising… {} evals ", o.evaluations),
            app.theme.busy,
        ),
        None => Span::styled("· optimising… ", app.theme.busy),
    });
    if app.shows_margin() {
        spans.push(margin_status(app));
        return;
    }
    spans.push(match &app.surface {
        Some(s) if s.generation != app.generation => {
            Span::styled("· surface stale, updating… ", app.theme.busy)
        }
        Some(s) if s.last => Span::raw(format!(
            "· surface ✓ {}×{} ",
            s.surface.grid.columns, s.surface.grid.rows
        )),
        Some(s) => Span::styled(
            format!(
                "· surface {}×{}, refining… ",
                s.surface.grid.columns, s.surface.grid.rows
            ),
            app.theme.busy,
        ),
        None => Span::styled("· surface… ", app.theme.busy),
    });
}

/// The margin map's progress: rows still coming, or done.
fn margin_status(app: &App) -> Span<'static> {
    let Some(state) = &app.margin.state else {
        return Span::styled("· margin… ", app.theme.busy);
    };
    if let Some(filling) = state.filling() {
        let rows = filling.done() / filling.grid.columns.max(1);
        return Span::styled(
            format!("· margin {rows}/{} rows… ", filling.grid.rows),
            app.theme.busy,
        );
    }
    if !app.margin_fresh() {
        return Span::styled("· margin stale, updating… ", app.theme.busy);
    }
    let grid = state.surface.grid;
    Span::raw(format!("· margin ✓ {}×{} ", grid.columns, grid.rows))
}

/// `text` in `width` columns: a path too long loses its start, so that the
/// file's name and the reason after it stay ("x: wrote …/dir/name.svg").
fn fitted(text: &str, width: usize) -> String {
    let chars: Vec<char> = text.chars().collect();
    if chars.len() <= width {
        return text.to_owned();
    }
    let cut_end = || chars[..width.saturating_sub(1)].iter().collect::<String>() + "…";
    // Without a path, or with no room for one, the end goes.
    let Some(keep_head) = chars.iter().position(|&c| c == '/') else {
        return cut_end();
    };
    let tail = width.saturating_sub(keep_head + 1);
    if tail == 0 {
        return cut_end();
    }
    let head: String = chars[..keep_head].iter().collect();
    let end: String = chars[chars.len() - tail..].iter().collect();
    format!("{head}…{end}")
}

#[cfg(test)]
mod tests {
    use super::fitted;

    #[test]
    fn a_long_path_loses_its_start_and_keeps_its_name() {
        assert_eq!(fitted("x: wrote /a/b.svg", 80), "x: wrote /a/b.svg");
        let long = format!("x: wrote /{}/homerun-figure8-1.svg", "d".repeat(100));
        let fit = fitted(&long, 40);
        assert_eq!(fit.chars().count(), 40);
        assert!(
            fit.starts_with("x: wrote …") && fit.ends_with("/homerun-figure8-1.svg"),
            "{fit}"
        );
        assert_eq!(fitted("x: no SVG written: a reason", 10), "x: no SVG…");
    }
}
