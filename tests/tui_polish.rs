//! The explorer's polish (issue 15): captions fitted at words, the figure's
//! panels, the trajectory's aspect, round ticks, the small-screen notice,
//! the spin decay's first nudge, clicks rounded to a step, the fence's
//! words, and the themes.

mod tui_support;

use homerun::tui::layout::layout;
use ratatui::crossterm::event::KeyCode;
use tui_support::*;

#[test]
fn figure_captions_and_notes_are_never_cut_mid_word() {
    for (w, h) in [(80, 24), (120, 40)] {
        let mut app = app(w, h, None);
        key(&mut app, KeyCode::Char('4'));
        for number in homerun::tui::app::FIGURES {
            while app.figure_number != number {
                key(&mut app, KeyCode::Char('f'));
            }
            settle(&mut app);
            let Some(Ok(data)) = app.figure.as_ref().map(|f| f.data.clone()) else {
                panic!("Fig. {number}");
            };
            // Every word the caption and the notes may show.
            let mut words: Vec<String> = Vec::new();
            let texts = [data.title.clone()]
                .into_iter()
                .chain(data.notes.iter().cloned())
                .chain(
                    data.comparisons
                        .iter()
                        .map(|c| format!("{} {}", c.what, c.unit)),
                );
            for text in texts {
                words.extend(text.split(' ').map(str::to_owned));
            }
            let known = |word: &str| {
                words.iter().any(|w| w == word)
                    || word.parse::<f64>().is_ok()
                    || ["paper", "ours", "·"].contains(&word)
            };
            let pane = layout(app.size, app.tab, true).figure.unwrap();
            let rows = rows_in(&app, pane);
            // The caption: the rows above the chart; the notes: those under
            // its x labels (the row after the axis' corner).
            let caption = rows
                .iter()
                .take_while(|r| !r.contains('│') && !r.contains('━'));
            let corner = rows.iter().rposition(|r| r.contains('└')).unwrap();
            let notes = rows[corner + 2..].iter();
            let mut shown = 0;
            for row in caption.chain(notes) {
                for word in row.trim_end_matches('…').split_whitespace() {
                    assert!(known(word), "Fig. {number} at {w}×{h}: {word:?} in {row:?}");
                    shown += 1;
                }
            }
            assert!(shown > 3, "Fig. {number}: {rows:#?}");
        }
    }
}

#[test]
fn figures_8_to_12_show_their_three_panels_where_there_is_room() {
    for number in [8, 9, 10, 11, 12] {
        for ((w, h), all) in [((200, 60), true), ((80, 24), false)] {
            let mut app = app(w, h, None);
            key(&mut app, KeyCode::Char('4'));
            while app.figure_number != number {
                key(&mut app, KeyCode::Char('f'));
            }
            settle(&mut app);
            let pane = layout(app.size, app.tab, true).figure.unwrap();
            let text = rows_in(&app, pane).join("\n");
            // The caption names all three; the axes only those drawn.
            let axes: String = text.lines().skip(2).collect::<Vec<_>>().join("\n");
            for title in ["range (", "E_opt (", "ψ_opt ("] {
                let drawn = axes.contains(&format!("│{title}"));
                let expected = all || title == "range (";
                assert_eq!(
                    drawn, expected,
                    "Fig. {number} at {w}×{h}, {title}:\n{text}"
                );
            }
        }
    }
}
