//! What a keypress costs on the wire: the frames it causes, drawn through
//! crossterm into memory at 120×40, counted in bytes.

use crate::tui_support;

use homerun::tui::app::App;
use homerun::tui::view;
use homerun::tui::worker::run_job;
use ratatui::Terminal;
use ratatui::backend::CrosstermBackend;
use ratatui::crossterm::event::KeyCode;
use tui_support::*;

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Counts what is written, as a terminal would receive it.
#[derive(Clone, Default)]
struct Counter(Arc<AtomicUsize>);

impl std::io::Write for Counter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.fetch_add(buf.len(), Ordering::Relaxed);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

type Wire = Terminal<CrosstermBackend<Counter>>;

fn frame(terminal: &mut Wire, counter: &Counter, app: &App) -> usize {
    let before = counter.0.load(Ordering::Relaxed);
    terminal.draw(|f| view::draw(f, app)).unwrap();
    counter.0.load(Ordering::Relaxed) - before
}

/// Bytes written for one nudge of the bat speed: the frame for the key and
/// one frame per background result that follows.
fn cost_of_a_nudge(tab: char) -> (usize, usize) {
    let mut app = app(120, 40, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char(tab));
    let counter = Counter::default();
    let backend = CrosstermBackend::new(counter.clone());
    let mut terminal = Terminal::with_options(
        backend,
        ratatui::TerminalOptions {
            viewport: ratatui::Viewport::Fixed(app.size),
        },
    )
    .unwrap();
    frame(&mut terminal, &counter, &app);
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('l'));
    let first = frame(&mut terminal, &counter, &app);
    let job = app.take_job().unwrap();
    let mut reports = Vec::new();
    run_job(&job, &|| false, &mut |r| reports.push(r));
    let mut total = first;
    for report in reports {
        app.apply(report);
        total += frame(&mut terminal, &counter, &app);
    }
    (first, total)
}

#[test]
fn a_keypress_costs_well_under_20_kb_at_120x40() {
    for tab in ['1', '2', '3'] {
        let (first, total) = cost_of_a_nudge(tab);
        eprintln!("tab {tab}: key frame {first} B, with every background result {total} B");
        assert!(first < 10_000, "tab {tab}: {first} bytes");
        assert!(total < 20_000, "tab {tab}: {total} bytes");
    }
}
