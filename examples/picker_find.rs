//! The picker's find (`/` in `tui --savant`) timed a key at a time, for
//! docs/speed.md: `cargo run --release --example picker_find -- [swings]
//! [length]`. Swings named and described as a Savant file's are, then
//! three queries typed and erased: a batter and a date; `length` (1000)
//! characters of words every swing holds (the worst case for a find that
//! tests each word against each swing); as many of one word no swing
//! holds. Each line: the slowest key's find, the slowest frame drawn after
//! a key (200×60), and the total; first, the time `/` takes.

use std::time::{Duration, Instant};

use homerun::preset::{self, Preset};
use homerun::tui::app::App;
use homerun::tui::theme::ColorMode;
use homerun::tui::view;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;

const BATTERS: [&str; 8] = [
    "Judge, Aaron",
    "Ohtani, Shohei",
    "Soto, Juan",
    "Turang, Brice",
    "Correa, Carlos",
    "Henderson, Gunnar",
    "Alvarez, Yordan",
    "Witt Jr., Bobby",
];

fn swings(count: usize) -> Vec<Preset> {
    let mut swing = preset::load("fastball", None).unwrap();
    swing.fence = Some(preset::Fence {
        distance: 120.0,
        height: 3.0,
    });
    (0..count)
        .map(|i| {
            let batter = BATTERS[i % BATTERS.len()];
            let (last, first) = batter.split_once(", ").unwrap();
            let date = format!("2024-04-{:02}", 1 + i % 30);
            swing.name = format!("{} {}", &last[..last.len().min(6)], &date[5..]);
            swing.description = format!(
                "{first} {last}, line {}, {date}: measured {:.1} mph at {:.1}°; solved E 2.71 cm, \
                 ψ 0.21 rad (12.0°), tilt 0.52 rad (30.0°), square, q 0.210; here 101.2 mph at \
                 27.9° (E for the paper's pitch path)",
                i + 2,
                80.0 + (i % 300) as f64 * 0.1,
                10.0 + (i % 40) as f64,
            );
            swing.clone()
        })
        .collect()
}

fn key(app: &mut App, code: KeyCode) {
    app.handle(&Event::Key(KeyEvent::new(code, KeyModifiers::NONE)));
    app.flush();
}

/// The slowest key's find, the slowest frame drawn after a key, and the
/// total of both.
struct Times {
    find: Duration,
    draw: Duration,
    total: Duration,
}

/// Types `query`, then erases it, a key at a time, each key with one frame
/// drawn as the event loop would.
fn timed(app: &mut App, terminal: &mut Terminal<TestBackend>, query: &str) -> Times {
    let keys = (query.chars().map(KeyCode::Char)).chain(query.chars().map(|_| KeyCode::Backspace));
    let mut times = Times {
        find: Duration::ZERO,
        draw: Duration::ZERO,
        total: Duration::ZERO,
    };
    for code in keys {
        let start = Instant::now();
        key(app, code);
        let found = start.elapsed();
        terminal.draw(|frame| view::draw(frame, app)).unwrap();
        let drawn = start.elapsed() - found;
        times.find = times.find.max(found);
        times.draw = times.draw.max(drawn);
        times.total += found + drawn;
    }
    times
}

fn main() {
    let count: usize = (std::env::args().nth(1))
        .and_then(|n| n.parse().ok())
        .unwrap_or(200_000);
    let length: usize = (std::env::args().nth(2))
        .and_then(|n| n.parse().ok())
        .unwrap_or(1000);
    let fastball = preset::load("fastball", None).unwrap();
    let mut app = App::new(fastball, None, ColorMode::Indexed, Rect::new(0, 0, 200, 60));
    app.offer_swings(swings(count));
    let mut terminal = Terminal::new(TestBackend::new(200, 60)).unwrap();
    terminal.draw(|frame| view::draw(frame, &app)).unwrap();
    let start = Instant::now();
    key(&mut app, KeyCode::Char('/'));
    println!(
        "{count} swings, `/`: {:.1} ms",
        start.elapsed().as_secs_f64() * 1e3
    );
    let every = "mph at line solved ".repeat(length / 19 + 1)[..length].to_owned();
    let none = "x".repeat(length);
    for (what, query) in [
        ("\"judge 04-1\"", "judge 04-1"),
        ("words every swing holds", every.as_str()),
        ("one word none holds", none.as_str()),
    ] {
        let times = timed(&mut app, &mut terminal, query);
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        println!(
            "{count} swings, {what}: slowest find {:.1} ms, slowest frame {:.1} ms, {} keys in {:.2} s",
            ms(times.find),
            ms(times.draw),
            2 * query.chars().count(),
            times.total.as_secs_f64()
        );
    }
}
