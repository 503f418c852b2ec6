//! Issue 38, item 9 and a smaller one: the picker's find (`/`) does one
//! pass over the items still found a key, whatever the query's length (it
//! searched every item for every word at each key: 19 s at 500 characters
//! on 16,000 swings), and finds what a find by words finds; a long name (a
//! Savant row's long `game_date`) no longer hides the description.

use homerun::preset::{self, Preset};
use homerun::tui::app::{App, Mode};
use ratatui::crossterm::event::KeyCode;

use crate::tui_support::{app, key, screen, typed};

// Judge's and Ohtani's text are searched as they are, ASCII case aside
// (their ° is its own lower case); Acuña's and the Greek's are lower-cased.
const BATTERS: [&str; 5] = [
    "Aaron Judge",
    "RONALD ACUÑA",
    "Shohei Ohtani",
    "Ἀλέξανδρος ΣΩΣΙΑΣ",
    "Juan Soto",
];

fn swings(count: usize) -> Vec<Preset> {
    let mut swing = preset::load("fastball", None).unwrap();
    (0..count)
        .map(|i| {
            let batter = BATTERS[i % BATTERS.len()];
            let short: String = batter.chars().take(4).collect();
            swing.name = format!("{short} 04-{:02}", 1 + i % 30);
            swing.description = format!(
                "{batter}, line {}, 2024-04-{:02}: measured {:.1} mph at {}°",
                i + 2,
                1 + i % 30,
                80.0 + (i % 300) as f64 * 0.1,
                10 + i % 40
            );
            swing.clone()
        })
        .collect()
}

/// The names the picker lists now, and the find's count of searches.
fn found(app: &App) -> (Vec<String>, u64) {
    match &app.mode {
        Mode::Open {
            items,
            find: Some(find),
            ..
        } => (
            (items.iter())
                .map(|i| i.name(&app.swings).to_owned())
                .collect(),
            find.searches(),
        ),
        other => panic!("a find in the picker, not {other:?}"),
    }
}

/// What a find by words finds: the items whose name and description, in
/// lower case, hold each word of `query` in lower case.
fn by_words(all: &[(String, String)], query: &str) -> Vec<String> {
    let lower = |t: &str| -> String { t.chars().flat_map(char::to_lowercase).collect() };
    let words: Vec<String> = query.split_whitespace().map(lower).collect();
    (all.iter())
        .filter(|(name, detail)| {
            let text = lower(&format!("{name} {detail}"));
            words.iter().all(|w| text.contains(w.as_str()))
        })
        .map(|(name, _)| name.clone())
        .collect()
}

/// The picker's whole list, as (name, description), swings first.
fn whole_list(app: &mut App) -> Vec<(String, String)> {
    key(app, KeyCode::Char('o'));
    let Mode::Open { items, .. } = &app.mode else {
        panic!("the picker is open")
    };
    let all = (items.iter())
        .map(|i| {
            (
                i.name(&app.swings).to_owned(),
                i.detail(&app.swings).to_owned(),
            )
        })
        .collect();
    key(app, KeyCode::Esc);
    all
}

#[test]
fn a_thousand_character_find_searches_each_item_at_most_once_a_key() {
    let count = 3000;
    let mut app = app(80, 24, None);
    app.offer_swings(swings(count));
    key(&mut app, KeyCode::Esc);
    let all = whole_list(&mut app);
    key(&mut app, KeyCode::Char('o'));
    key(&mut app, KeyCode::Char('/'));
    // Words every swing holds, 1000 characters: each word searched for
    // over all of them at each key made it quadratic in the query.
    let query = "mph line measured at ".repeat(48)[..1000].to_owned();
    let mut typed_so_far = String::new();
    for (n, c) in query.chars().enumerate() {
        key(&mut app, KeyCode::Char(c));
        typed_so_far.push(c);
        let (names, searches) = found(&app);
        assert!(
            searches <= (n as u64 + 1) * all.len() as u64,
            "{searches} searches after {} keys over {} items",
            n + 1,
            all.len()
        );
        if n % 97 == 0 {
            assert_eq!(names, by_words(&all, &typed_so_far), "{typed_so_far:?}");
        }
    }
    let (names, searches) = found(&app);
    assert_eq!(names.len(), count, "every swing holds those words");
    // Erasing searches nothing: each key puts back what its character took.
    for _ in 0..query.len() {
        key(&mut app, KeyCode::Backspace);
    }
    let (names_back, searches_back) = found(&app);
    assert_eq!(searches_back, searches);
    assert_eq!(names_back.len(), all.len());
    assert_eq!(names.len(), count);
}

/// Typed and erased a key at a time, in any case and with Greek (whose
/// capital sigma has two lower cases), the list is always that of a find
/// by words, in the picker's order.
#[test]
fn the_find_finds_what_a_find_by_words_finds_at_every_key() {
    let mut app = app(80, 24, None);
    app.offer_swings(swings(200));
    key(&mut app, KeyCode::Esc);
    let all = whole_list(&mut app);
    key(&mut app, KeyCode::Char('o'));
    key(&mut app, KeyCode::Char('/'));
    let mut query = String::new();
    for (typed_text, erased) in [
        ("JUDGE 04-1", 3),
        ("2 mph", 6),
        ("σωσιας 04-0", 11),
        ("ΣΩΣ fast", 20),
        ("acuñ ACUÑA 1°", 9),
        ("  ball bundled", 5),
        ("x", 40),
    ] {
        for c in typed_text.chars() {
            key(&mut app, KeyCode::Char(c));
            query.push(c);
            assert_eq!(found(&app).0, by_words(&all, &query), "{query:?}");
        }
        for _ in 0..erased {
            key(&mut app, KeyCode::Backspace);
            query.pop();
            assert_eq!(found(&app).0, by_words(&all, &query), "{query:?}");
        }
    }
    assert!(query.is_empty());
    assert_eq!(found(&app).0.len(), all.len());
}

/// A swing named with a long `game_date`: its name is cut to its column,
/// and the row still shows the description.
#[test]
fn a_long_name_leaves_the_description_in_view() {
    let mut app = app(80, 24, None);
    let mut swing = preset::load("fastball", None).unwrap();
    swing.name = format!("Turang {}", "2024-04-03".repeat(8));
    swing.description = "line 4: measured 78.5 mph at 32.0°".to_owned();
    app.offer_swings(vec![swing.clone()]);
    let shown = screen(&app);
    let row = (shown.lines())
        .find(|l| l.contains("Turang"))
        .unwrap_or_else(|| panic!("{shown}"));
    assert!(row.contains("Turang 2024-… line 4"), "{row}");
    assert!(row.contains("line 4: measured"), "{row}");
    // A find still reads the whole name.
    key(&mut app, KeyCode::Char('/'));
    typed(&mut app, "04-032024");
    assert_eq!(found(&app).0.len(), 1);
    // Loaded, the swing has its whole name and description (its picker
    // item keeps them, not a second copy in its preset).
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.preset_name, swing.name);
    assert_eq!(app.description, swing.description);
}
