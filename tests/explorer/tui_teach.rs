//! Issue 36, "the explorer teaches": the glossary, the impact's sentences,
//! the paper beside ours, and figures whose panels can all be seen.

use crate::tui_support;

use ratatui::crossterm::event::KeyCode;
use tui_support::*;

/// Issue 36, item 1: `?` then Tab shows the glossary, which says in words
/// what the readout's symbols are, and scrolls to its last entry at 80×24.
#[test]
fn the_help_has_a_glossary_of_the_symbols_on_screen() {
    use homerun::tui::app::Mode;
    let mut app = app(80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('?'));
    assert!(screen(&app).contains("Tab: glossary · j k scroll"));
    key(&mut app, KeyCode::Tab);
    let first = screen(&app);
    assert!(first.contains("Glossary"), "{first}");
    assert!(first.contains("pitch speed: the ball's speed"), "{first}");
    // Scrolled to its end, the last entries show; the first has gone.
    for _ in 0..200 {
        key(&mut app, KeyCode::Char('j'));
    }
    let last = screen(&app);
    assert!(last.contains("drag crisis"), "{last}");
    assert!(last.contains("the trajectory's apex"), "{last}");
    assert!(!last.contains("pitch speed: the ball's speed"), "{last}");
    // Tab back to the keys, and any other key closes.
    key(&mut app, KeyCode::Tab);
    assert!(matches!(
        app.mode,
        Mode::Help {
            glossary: false,
            scroll: 0
        }
    ));
    key(&mut app, KeyCode::Char('x'));
    assert!(matches!(app.mode, Mode::Normal));
}

/// Issue 36, item 1: each stop of the impact's step-through says what the
/// contact is doing, under the chart at 80×24.
#[test]
fn each_impact_stop_says_what_is_happening() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('3'));
    let mut seen = Vec::new();
    for _ in 0..6 {
        let text = screen(&app);
        let phase = [
            "Contact begins",
            "Slip halts",
            "Compression:",
            "Maximum compression",
            "Restitution",
            "Separation",
        ]
        .into_iter()
        .find(|p| text.contains(p));
        seen.push(phase.unwrap_or("none"));
        key(&mut app, KeyCode::Char('.'));
    }
    assert_eq!(
        seen,
        [
            "Contact begins",
            "Slip halts",
            "Compression:",
            "Maximum compression",
            "Restitution",
            "Separation"
        ]
    );
}

/// Issue 36, item 12: `g` selects the first input, as the help says, not
/// the preset's row above it.
#[test]
fn g_selects_the_first_input() {
    use homerun::tui::app::Field;
    let mut app = app(80, 24, None);
    key(&mut app, KeyCode::Char('G'));
    key(&mut app, KeyCode::Char('g'));
    assert!(matches!(app.fields[app.selected], Field::Key(_)));
    assert_eq!(app.selected, 1);
}

/// Issue 36, item 3: on a Table II preset the readout shows the paper's
/// optimum under ours (0.0265 m beside 0.0273, in the unit of Table II and
/// of the input), at 80×24 too; with the bat
/// changed the row is no longer the paper's, and the line goes.
#[test]
fn the_paper_optimum_stands_under_ours_on_table_two_presets() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    let text = screen(&app);
    assert!(
        text.contains("optimum  E 0.0273 m  ψ 0.1744 rad  134.79 m"),
        "{text}"
    );
    assert!(
        text.contains("Table II E 0.0265 m  ψ 0.1594 rad  134.80 m"),
        "{text}"
    );
    // A swing moved off the paper's (E, ψ) is still Table II's scene.
    key(&mut app, KeyCode::Char('r'));
    settle(&mut app);
    assert!(screen(&app).contains("Table II E 0.0265 m"));
    set_and_settle(&mut app, "bat.speed", "31");
    assert!(!screen(&app).contains("Table II"), "{}", screen(&app));
    // The glossary says why the two differ, and answers the curve ball's
    // "1.26 m/s higher".
    key(&mut app, KeyCode::Char('?'));
    key(&mut app, KeyCode::Tab);
    for _ in 0..40 {
        key(&mut app, KeyCode::Char('j'));
    }
    let glossary = screen(&app);
    assert!(glossary.contains("flat along a ridge"), "{glossary}");
    assert!(glossary.contains("44.30 − 43.04"), "{glossary}");
}

/// Issue 36, item 5: where Fig. 8's three panels do not fit (80×24,
/// 120×40) it says which it shows, and `v` shows the next; at 200×60 all
/// three stand stacked.
#[test]
fn a_figure_says_which_panel_it_shows_and_v_shows_the_next() {
    for (w, h) in [(80, 24), (120, 40)] {
        let mut app = app(w, h, None);
        key(&mut app, KeyCode::Char('4'));
        settle(&mut app);
        assert_eq!(app.figure_number, 8);
        let first = screen(&app);
        assert!(
            first.contains("panel 1/3: range (m) · v next"),
            "{w}×{h}\n{first}"
        );
        key(&mut app, KeyCode::Char('v'));
        let second = screen(&app);
        assert!(second.contains("panel 2/3: E_opt (m)"), "{w}×{h}\n{second}");
        key(&mut app, KeyCode::Char('v'));
        assert!(screen(&app).contains("panel 3/3: ψ_opt (rad)"));
        key(&mut app, KeyCode::Char('v'));
        assert!(screen(&app).contains("panel 1/3"));
    }
    let mut app = app(200, 60, None);
    settle(&mut app);
    let all = screen(&app);
    assert!(!all.contains("panel 1/3"), "{all}");
    for title in ["range (m)", "E_opt (m)", "ψ_opt (rad)"] {
        assert!(all.contains(title), "{title}\n{all}");
    }
}

/// Issue 36, item 12: under NO_COLOR the heatmap's legend shows the
/// contour as the map draws it (••), not as a line it never draws.
#[test]
fn the_no_colour_legend_shows_the_contours_dots() {
    use homerun::tui::theme::{Background, ColorMode, Theme};
    let mut app = themed(Theme::new(Background::Dark, ColorMode::NoColor), 80, 24);
    settle(&mut app);
    key(&mut app, KeyCode::Char('2'));
    let text = screen(&app);
    assert!(text.contains("· •• 122 m (fence)"), "{text}");
    let mut coloured = app_on("fastball", 80, 24, None);
    settle(&mut coloured);
    key(&mut coloured, KeyCode::Char('2'));
    assert!(screen(&coloured).contains("· ── 122 m (fence)"));
}

/// Issue 36, item 4: text cut short under the inputs says so ("i: read
/// all"), and `i` shows it whole: a wind's direction, a refused unit.
#[test]
fn i_shows_the_words_the_panes_cut_short() {
    use homerun::tui::app::{Field, Mode, input_key};
    let mut app = app(80, 24, None);
    settle(&mut app);
    select(&mut app, "bat.direction");
    let Field::Key(k) = app.fields[app.selected] else {
        panic!("an input");
    };
    let description = input_key(k).description;
    let text = screen(&app);
    assert!(text.contains("i: read all"), "{text}");
    // The description's last words are past the rows under the list.
    let tail: String = description
        .split_whitespace()
        .rev()
        .take(3)
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(!text.contains(&tail), "{tail}\n{text}");
    key(&mut app, KeyCode::Char('i'));
    assert!(matches!(app.mode, Mode::Detail { .. }));
    let whole = screen(&app);
    assert!(whole.contains("In full"), "{whole}");
    assert!(
        whole.split('\n').any(|row| row.contains(&tail))
            || whole.replace(" │\"\n\"│ ", " ").contains(&tail),
        "{tail}\n{whole}"
    );
    key(&mut app, KeyCode::Char('q'));
    assert!(matches!(app.mode, Mode::Normal));
    assert!(!app.quit, "a key closes the pane, not the app");

    // A unit refused under imperial: the message, whole.
    key(&mut app, KeyCode::Char('u'));
    select(&mut app, "pitch.speed");
    key(&mut app, KeyCode::Enter);
    for _ in 0..10 {
        key(&mut app, KeyCode::Backspace);
    }
    typed(&mut app, "2500rpm");
    key(&mut app, KeyCode::Enter);
    let message = app.message.clone().expect("refused").0;
    key(&mut app, KeyCode::Char('i'));
    let whole = screen(&app);
    assert!(whole.contains("Message"), "{whole}");
    let last_word = message.split_whitespace().last().unwrap();
    assert!(whole.contains(last_word), "{message}\n{whole}");
}

/// Issue 36, item 2: one unit per quantity. In SI the undercut is in m (as
/// the input, Table II and the figures give it) and every angle in rad; in
/// baseball units E in inches and angles in degrees: the readout, the
/// surface's axis and a figure's caption (with the numbers it quotes)
/// never show another.
#[test]
fn each_quantity_has_one_unit_on_every_pane() {
    use homerun::tui::layout::{Tab, layout};
    let mut app = app(200, 60, None);
    settle(&mut app);
    let readout = |app: &homerun::tui::app::App| {
        let panes = layout(app.size, app.tab, true);
        // A non-breaking space (a number glued to its unit) reads as a space.
        rows_in(app, panes.readout.unwrap())
            .join("\n")
            .replace('\u{a0}', " ")
    };
    let si = readout(&app);
    assert!(si.contains("E 0.0273 m  ψ 0.1744 rad"), "{si}");
    assert!(si.contains("0.4604 rad"), "{si}");
    assert!(!si.contains("mm") && !si.contains("° "), "{si}");
    key(&mut app, KeyCode::Char('2'));
    assert!(screen(&app).contains("E (m) →"));
    assert!(!screen(&app).contains("(mm)"));
    key(&mut app, KeyCode::Char('u'));
    settle(&mut app);
    let imperial = readout(&app);
    assert!(imperial.contains("E 1.074 in  ψ 9.99°"), "{imperial}");
    assert!(imperial.contains("26.38°"), "{imperial}");
    for si_unit in [" rad", " m ", "m/s", " mm"] {
        assert!(!imperial.contains(si_unit), "{si_unit} in {imperial}");
    }
    assert!(screen(&app).contains("E (in) →"));
    // Fig. 13's caption quotes ψ and the spins of A and B: in ° and rpm.
    key(&mut app, KeyCode::Char('4'));
    while app.figure_number != 13 {
        key(&mut app, KeyCode::Char('f'));
    }
    settle(&mut app);
    assert_eq!(app.tab, Tab::Figures);
    assert!(screen(&app).contains("range (ft) against undercut E (in) at ψ ="));
    // `i` shows the caption whole: its words, the panes' borders and the
    // curves behind it aside.
    key(&mut app, KeyCode::Char('i'));
    let words = screen(&app)
        .replace(|c: char| ('\u{2800}'..='\u{28ff}').contains(&c), " ")
        .lines()
        .flat_map(|l| l.split(['│', '"']))
        .collect::<Vec<_>>()
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(words.contains("at ψ = 9.13°"), "{words}");
    assert!(words.contains("ω_bf = 1742 rpm and 2944 rpm"), "{words}");
    assert!(
        !words.contains("rad/s") && !words.contains("E (m)"),
        "{words}"
    );
}

/// Issue 36, item 2: under baseball units Fig. 8's notes, and the paper's
/// numbers beside ours, are in ft and mph as its axes are; only the
/// paper's own words, in quotes, keep its metres. Seen at 80×24 and
/// 200×60, and whole under `i`.
#[test]
fn figure_notes_are_in_the_units_shown() {
    use homerun::tui::layout::{Tab, layout};
    for (w, h) in [(80, 24), (200, 60)] {
        let mut app = app(w, h, None);
        key(&mut app, KeyCode::Char('u'));
        key(&mut app, KeyCode::Char('4'));
        settle(&mut app);
        assert_eq!((app.tab, app.figure_number), (Tab::Figures, 8));
        insta::assert_snapshot!(format!("figure8_imperial_{w}x{h}"), screen(&app));
        let figure = layout(app.size, app.tab, true).figure.unwrap();
        let pane = rows_in(&app, figure).join(" ");
        assert!(pane.contains("paper 7.3 · ours"), "{pane}");
        // No m/s but in the paper's quoted words.
        let unquoted: String = pane.split('"').step_by(2).collect();
        assert!(!unquoted.contains("m/s"), "{pane}");
        key(&mut app, KeyCode::Char('i'));
        // The screen's rows are quoted: their words joined across rows.
        let words = screen(&app)
            .lines()
            .map(|l| l.trim_matches('"'))
            .flat_map(|l| l.split('│'))
            .collect::<Vec<_>>()
            .join(" ")
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        assert!(
            words.contains("ft: range gained per 1 mph of bat speed near 67 mph"),
            "{words}"
        );
        assert!(words.contains("paper 94 · ours"), "{words}");
        assert!(
            words.contains("ψ_opt falls to 0 at 94 mph and below it after"),
            "{words}"
        );
        // The paper's words as it printed them, in quotes.
        assert!(
            words.contains("\"increasing the bat speed by only 1 m/s"),
            "{words}"
        );
    }
}

/// Issue 36, item 2: a batted ball's exit speed and backspin, carried
/// over from the swing (`b`), show in the inputs as the readout shows them
/// (44.30 m/s, 191.8 rad/s), not to digits no pane shows; typed, as typed.
#[test]
fn the_exit_speed_shows_the_readouts_digits_until_typed() {
    let mut app = app(80, 24, None);
    key(&mut app, KeyCode::Char('b'));
    settle(&mut app);
    let shown = screen(&app);
    assert!(
        shown.contains("exit speed V̂_bf   44.30 m/s") && shown.contains("launch   44.30 m/s"),
        "{shown}"
    );
    assert!(shown.contains("backspin ω_bf     191.8 rad/s"), "{shown}");
    assert!(!shown.contains("44.2991"), "{shown}");
    set_and_settle(&mut app, "launch.speed", "44.2991");
    assert!(
        screen(&app).contains("exit speed V̂_bf 44.2991 m/s"),
        "{}",
        screen(&app)
    );
}
