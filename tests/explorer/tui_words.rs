//! Issue 28 ("Speak baseball, teach physics"): the explorer at 80×24 cuts
//! no text mid-word, and names every input in words beside its symbol.

use crate::tui_support;

use homerun::tui::app::App;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyCode;
use tui_support::*;

/// Cells that end a pane's row: a border, or the screen's edge.
fn is_edge(symbol: &str) -> bool {
    ["│", "┐", "┘", "┤", "┌", "└", "├", "┬", "┴"].contains(&symbol)
}

/// Whether the word ending before column `x` of row `y` is whole: one the
/// same state shows whole on a screen big enough for every text (`big`,
/// its words), or shown whole there by design (a preset's name or the
/// batter's hand, right-aligned in its row, or an axis' name).
fn whole_at(buffer: &Buffer, x: u16, y: u16, big: &[String]) -> bool {
    let mut word = String::new();
    let mut at = x;
    while at > 0 && {
        let s = buffer[(at - 1, y)].symbol();
        s != "│" && !s.chars().all(char::is_whitespace)
    } {
        at -= 1;
        word.insert_str(0, buffer[(at, y)].symbol());
    }
    // A word wider than a whole row (a key's name) is split, not lost.
    let split = big.iter().any(|w| {
        w.starts_with(&word)
            && w.chars().count() > word.chars().count() + 1
            && word.chars().count() > 20
    });
    // A key's name, wider than the inputs' row, is split there, not lost.
    let key = word.chars().count() > 20
        && homerun::model::keys::KEYS
            .iter()
            .chain(homerun::model::keys::EXTENDED_KEYS.iter())
            .any(|k| k.name.starts_with(&word));
    split
        || key
        || big.contains(&word)
        || homerun::preset::bundled().iter().any(|p| p.name == word)
        || ["Re", "right", "left"].contains(&word.as_str())
}

/// Whether the border at (`x`, `y`) is a box's right side (not the left
/// side of an overlay drawn over other text): the corner above it is ┐.
fn right_border(buffer: &Buffer, x: u16, y: u16) -> bool {
    (0..=y).rev().find_map(|at| match buffer[(x, at)].symbol() {
        "┐" | "┘" | "┤" | "┬" => Some(true),
        "┌" | "└" | "├" => Some(false),
        _ => None,
    }) != Some(false)
}

/// Where a row of `buffer` ends inside a word: text running up to a pane's
/// right border (or the screen's edge) and cut there. A row is cut when its
/// last two cells before the edge are letters (a word that went on), a
/// digit and a point ("+196."). (Text fitted with "…" ends at a whole
/// word: see `view::words`.)
fn cuts(buffer: &Buffer, what: &str, big: &[String]) -> Vec<String> {
    let area = buffer.area;
    let mut found = Vec::new();
    let row = |y: u16| -> String {
        (0..area.width)
            .map(|x| buffer[(x, y)].symbol())
            .collect::<String>()
    };
    for y in 0..area.height {
        for x in 2..=area.width {
            // A pane's edge, not the tab bar's divider ("Flight│2").
            let divider = x + 1 < area.width
                && buffer[(x + 1, y)]
                    .symbol()
                    .starts_with(|c: char| c.is_ascii_digit());
            let at_edge = x == area.width
                || (is_edge(buffer[(x, y)].symbol()) && !divider && right_border(buffer, x, y));
            if !at_edge || whole_at(buffer, x, y, big) {
                continue;
            }
            let last = buffer[(x - 1, y)].symbol();
            let before = buffer[(x - 2, y)].symbol();
            let letter = |s: &str| s.chars().next().is_some_and(char::is_alphabetic);
            let digit = |s: &str| s.chars().next().is_some_and(|c| c.is_ascii_digit());
            let cut = (letter(last) && letter(before) && x != area.width)
                || (last == "." && digit(before));
            if cut {
                found.push(format!("{what}: {:?}", row(y)));
            }
        }
    }
    found
}

/// The words of `app` drawn on a screen of 400×120, where no text is cut.
fn big_words(app: &App) -> Vec<String> {
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;
    let mut terminal = Terminal::new(TestBackend::new(400, 120)).unwrap();
    terminal
        .draw(|frame| homerun::tui::view::draw(frame, app))
        .unwrap();
    let text = terminal.backend().to_string();
    text.split(|c: char| c.is_whitespace() || "│┐┘┤┌└├┬┴─\"".contains(c))
        .filter(|w| !w.is_empty())
        .map(str::to_owned)
        .collect()
}

/// Every tab, overlay and picker of `app`'s scene, each as drawn.
fn walk(app: &mut App, scene: &str, found: &mut Vec<String>) {
    let mut look = |app: &mut App, what: &str| {
        settle(app);
        let big = big_words(app);
        found.extend(cuts(&buffer(app), &format!("{scene} {what}"), &big));
    };
    for (tab, name) in ['1', '2', '3', '4', '5']
        .into_iter()
        .zip(["flight", "surface", "impact", "figures", "field"])
    {
        key(app, KeyCode::Char(tab));
        look(app, name);
    }
    // The figures, each.
    key(app, KeyCode::Char('4'));
    for _ in 0..12 {
        key(app, KeyCode::Char('f'));
        let what = format!("figure {}", app.figure_number);
        look(app, &what);
    }
    // The impact, step by step.
    key(app, KeyCode::Char('3'));
    for step in 0..8 {
        key(app, KeyCode::Char('.'));
        look(app, &format!("impact step {step}"));
    }
    key(app, KeyCode::Char('1'));
    // Every input's description, selected in turn (g is the first input,
    // k the preset's row above it).
    key(app, KeyCode::Char('g'));
    key(app, KeyCode::Char('k'));
    for row in 0..app.fields.len() {
        look(app, &format!("input {row}"));
        key(app, KeyCode::Char('j'));
    }
    // The overlays: help, the preset picker, an edit, a park.
    key(app, KeyCode::Char('?'));
    look(app, "help");
    assert!(
        screen(app).contains("any other key closes"),
        "{scene}: the help's closing line"
    );
    key(app, KeyCode::Tab);
    look(app, "glossary");
    for _ in 0..40 {
        key(app, KeyCode::Char('j'));
    }
    look(app, "glossary, scrolled");
    key(app, KeyCode::Esc);
    key(app, KeyCode::Char('o'));
    look(app, "preset picker");
    for _ in 0..8 {
        key(app, KeyCode::Down);
        look(app, "preset picker, moved");
    }
    key(app, KeyCode::Esc);
    key(app, KeyCode::Char('g'));
    key(app, KeyCode::Char('j'));
    key(app, KeyCode::Enter);
    look(app, "edit");
    key(app, KeyCode::Esc);
    key(app, KeyCode::Char('/'));
    look(app, "park list");
    key(app, KeyCode::Char('s'));
    look(app, "park list, filtered");
    key(app, KeyCode::Esc);
    key(app, KeyCode::Char('m'));
    look(app, "park");
    key(app, KeyCode::Char('5'));
    look(app, "park's field");
    key(app, KeyCode::Esc);
}

#[test]
fn no_text_is_cut_mid_word_at_80x24() {
    let mut found = Vec::new();
    for preset in ["fastball", "fly-ball", "figure5", "mile-high"] {
        let mut app = app_on(preset, 80, 24, None);
        walk(&mut app, preset, &mut found);
        if app.is_swing() {
            key(&mut app, KeyCode::Char('b'));
            walk(&mut app, &format!("{preset} as a batted ball"), &mut found);
        }
    }
    found.dedup();
    assert!(
        found.is_empty(),
        "{} cut:\n{}",
        found.len(),
        found.join("\n")
    );
}

/// Words beside the symbols at every size, in the scene's language.
#[test]
fn inputs_are_named_in_words_beside_their_symbols_at_every_size() {
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        let app = app_on("fly-ball", w, h, None);
        let shown = screen(&app);
        for label in ["exit speed V̂_bf", "launch angle ζ", "backspin ω_bf"] {
            assert!(shown.contains(label), "{w}×{h}: {label}\n{shown}");
        }
        let mut app = app_on("fastball", w, h, None);
        let mut shown = String::new();
        // The whole list, scrolled through.
        for _ in 0..app.fields.len() {
            shown.push_str(&screen(&app));
            key(&mut app, KeyCode::Char('j'));
        }
        for label in [
            "speed V̂_b0",
            "undercut E",
            "swing angle ψ",
            "spin decay τ",
            "bat tilt τ_B",
            "wind aim φ_w",
            "bat aim φ_B",
            "elevation h",
            "wind base h_w",
        ] {
            assert!(shown.contains(label), "{w}×{h}: {label}");
        }
    }
}

/// Issue 28, item 10: in the picker g and G jump to the top and bottom; a
/// name with spaces is saved fixed up (spaces to '-'), and the preset row's
/// hint then describes the preset saved.
#[test]
fn the_picker_jumps_and_a_name_with_spaces_is_fixed_up() {
    use homerun::tui::app::Mode;
    let dir = tempfile::tempdir().unwrap();
    let mut app = app(80, 24, Some(dir.path().to_owned()));
    key(&mut app, KeyCode::Char('o'));
    key(&mut app, KeyCode::Char('G'));
    let Mode::Open {
        items, selected, ..
    } = &app.mode
    else {
        panic!("the picker is open");
    };
    assert_eq!(*selected, items.len() - 1);
    key(&mut app, KeyCode::Char('g'));
    assert!(matches!(app.mode, Mode::Open { selected: 0, .. }));
    key(&mut app, KeyCode::Esc);
    key(&mut app, KeyCode::Char('s'));
    for _ in 0..20 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "class demo");
    key(&mut app, KeyCode::Enter);
    // Issue 36, item 8: a name with a space is asked about, not changed
    // silently: the box offers class-demo, and nothing is saved yet.
    let Mode::Save { text, error, .. } = &app.mode else {
        panic!("the save box stays open to ask");
    };
    assert_eq!(text.lines().join(""), "class-demo");
    let question = error.clone().expect("a question");
    assert!(
        question.contains("names take no spaces: Enter takes `class demo` as `class-demo`"),
        "{question}"
    );
    assert!(homerun::preset::load("class-demo", Some(dir.path())).is_err());
    let asked = screen(&app);
    assert!(asked.contains("names take no spaces"), "{asked}");
    key(&mut app, KeyCode::Enter);
    // Then its description, which the user writes (empty: a default).
    let Mode::Save { named, .. } = &app.mode else {
        panic!("the save box asks for the description");
    };
    assert_eq!(named.as_deref(), Some("class-demo"));
    typed(&mut app, "for Tuesday's class");
    key(&mut app, KeyCode::Enter);
    assert!(
        !matches!(app.mode, Mode::Save { .. }),
        "saved once confirmed"
    );
    assert_eq!(app.preset_name, "class-demo");
    let (message, error) = app.message.clone().expect("a message");
    assert!(!error && message.starts_with("saved "), "{message}");
    let saved = homerun::preset::load("class-demo", Some(dir.path())).unwrap();
    assert_eq!(saved.description, "for Tuesday's class");
    assert_eq!(app.description, "for Tuesday's class");
}

/// Issue 28, item 10: h and l on the preset row load the previous and next
/// preset, and its hint follows the preset loaded.
#[test]
fn h_and_l_on_the_preset_row_cycle_the_presets() {
    use homerun::tui::app::Field;
    let mut app = app(80, 24, None);
    app.selected = app.fields.iter().position(|f| *f == Field::Preset).unwrap();
    let names: Vec<String> = homerun::preset::bundled()
        .into_iter()
        .map(|p| p.name)
        .collect();
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.preset_name, names[1]);
    let loaded = homerun::preset::load(&names[1], None).unwrap();
    assert_eq!(app.description, loaded.description);
    key(&mut app, KeyCode::Char('h'));
    key(&mut app, KeyCode::Char('h'));
    assert_eq!(app.preset_name, names[names.len() - 1]);
}

/// Issue 28: at 80×24, where the Δ column gives way to the words, the
/// selected input's Δ (the range a step up gains) shows in the pane's title,
/// for a swing and for a batted ball, and follows the selection; where the
/// column shows, it does not.
#[test]
fn the_selected_inputs_delta_is_shown_at_80x24() {
    for (preset, gain, next) in [
        ("fastball", "▶ Δ +2.01 m", "▶ Δ +0.16 m"),
        ("fly-ball", "▶ Δ +1.60 m", ""),
    ] {
        let mut app = app_on(preset, 80, 24, None);
        settle(&mut app);
        let top = screen(&app).lines().next().unwrap().to_owned();
        assert!(top.contains(gain), "{preset}: {top}");
        if !next.is_empty() {
            key(&mut app, KeyCode::Char('j'));
            settle(&mut app);
            let top = screen(&app).lines().next().unwrap().to_owned();
            assert!(top.contains(next), "{preset}, the next row: {top}");
        }
        let mut wide = app_on(preset, 200, 60, None);
        settle(&mut wide);
        assert!(!screen(&wide).contains("▶ Δ"), "{preset} at 200×60");
    }
}

/// Issue 28, item 8: the same ball's range at one rounding everywhere on
/// screen (the trajectory's title, the field's and the readout's), in
/// metres and in feet.
#[test]
fn the_range_has_one_rounding_on_screen() {
    for (imperial, unit) in [(false, " m"), (true, " ft")] {
        let mut app = app_on("fly-ball", 160, 48, None);
        key(&mut app, KeyCode::Char('5'));
        if imperial {
            key(&mut app, KeyCode::Char('u'));
        }
        settle(&mut app);
        let range = app.range_text(app.flown.flight.range);
        let (number, _) = range.split_once(unit).expect("the unit");
        assert_eq!(
            number.split_once('.').map(|(_, d)| d.len()),
            Some(2),
            "{range}"
        );
        let shown = screen(&app);
        assert!(shown.contains(&format!("Trajectory {range}")), "{shown}");
        assert!(shown.contains(&format!("Field {range}")), "{shown}");
        assert!(shown.contains(&format!("range {range}")), "{shown}");
    }
}

/// Issue 28, item 7: `/` opens the park list, which filters as a code, a
/// name or a city is typed; Enter chooses the park (as `m` would have), Esc
/// leaves the park as it was; `m`/`M` still cycle.
#[test]
fn the_park_list_filters_by_code_name_or_city() {
    use homerun::tui::app::Mode;
    let mut app = app_on("fly-ball", 80, 24, None);
    let typed = |app: &mut App, text: &str| {
        for c in text.chars() {
            key(app, KeyCode::Char(c));
        }
    };
    let codes = |app: &App, query: &str| -> Vec<String> {
        app.parks_matching(query)
            .into_iter()
            .map(|k| app.parks.list.parks[k].code.clone())
            .collect()
    };
    assert_eq!(codes(&app, "").len(), 30);
    assert_eq!(codes(&app, "fenway"), ["BOS"]);
    assert_eq!(codes(&app, "bos"), ["BOS"]);
    assert_eq!(codes(&app, "Fenway Park"), ["BOS"]);
    assert_eq!(codes(&app, "sea"), ["SEA"]);
    assert_eq!(codes(&app, "chicago").len(), 2);
    assert!(codes(&app, "zzz").is_empty());

    key(&mut app, KeyCode::Char('/'));
    typed(&mut app, "seattle");
    let shown = screen(&app);
    assert!(shown.contains("Parks: 1 of 30"), "{shown}");
    assert!(shown.contains("SEA"), "{shown}");
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Normal));
    assert_eq!(app.chosen_park().unwrap().code, "SEA");
    // Backspace widens the list again; Esc keeps the park chosen.
    key(&mut app, KeyCode::Char('/'));
    typed(&mut app, "fenx");
    assert!(screen(&app).contains("Parks: 0 of 30"));
    key(&mut app, KeyCode::Backspace);
    assert!(screen(&app).contains("Parks: 1 of 30"));
    key(&mut app, KeyCode::Esc);
    assert_eq!(app.chosen_park().unwrap().code, "SEA");
    // m and M still cycle.
    key(&mut app, KeyCode::Char('m'));
    assert_ne!(app.chosen_park().map(|p| p.code.as_str()), Some("SEA"));
    key(&mut app, KeyCode::Char('M'));
    assert_eq!(app.chosen_park().unwrap().code, "SEA");
}

/// Issue 28, item 11: in the impact chart the curves are named at their
/// ends (v1, v3; a 3-D swing's v2 too), not told apart by colour alone,
/// and p_f is marked inside the axis, which runs on past it.
#[test]
fn the_impact_chart_names_its_curves_and_keeps_p_f_inside() {
    for (preset, names) in [("fastball", &["v1", "v3"][..]), ("figure5", &["v3"][..])] {
        let mut app = app_on(preset, 80, 24, None);
        settle(&mut app);
        key(&mut app, KeyCode::Char('3'));
        key(&mut app, KeyCode::Char('.'));
        settle(&mut app);
        let shown = screen(&app);
        // The chart's rows: those above its x axis' labels.
        let chart: String = shown
            .lines()
            .take_while(|l| !l.contains("p (N·s)"))
            .collect();
        for name in names.iter().chain(&["p_f"]) {
            assert!(chart.contains(name), "{preset}: {name}\n{shown}");
        }
    }
}
