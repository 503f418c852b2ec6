//! The explorer's polish (issue 15): captions fitted at words, the figure's
//! panels, the trajectory's aspect, round ticks, the small-screen notice,
//! the spin decay's first nudge, clicks rounded to a step, the fence's
//! words, and the themes.

use crate::common;
use crate::tui_support;

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
                    // A number, or one in degrees ("6.79°", glued as everywhere).
                    || word.trim_end_matches('°').parse::<f64>().is_ok()
                    || ["paper", "ours", "·"].contains(&word)
            };
            let pane = layout(app.size, app.tab, true).figure.unwrap();
            let rows = rows_in(&app, pane);
            // The caption: the rows above the chart; the notes: those under
            // its x labels (the row after the axis' corner) and the axis'
            // title where it has a row of its own ("bat.speed (m/s)").
            let caption = rows
                .iter()
                .take_while(|r| !r.contains('│') && !r.contains('━'));
            let corner = rows.iter().rposition(|r| r.contains('└')).unwrap();
            let axis_title = |r: &&String| {
                r.split_whitespace().count() == 2 && r.contains(" (") && r.ends_with(')')
            };
            let notes = rows[corner + 2..].iter().skip_while(axis_title);
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

/// A chart's tick labels in `pane`: (x labels, y labels), read off the row
/// under the axes' corner and the column left of the y axis.
fn ticks_in(app: &homerun::tui::app::App, pane: ratatui::layout::Rect) -> (Vec<f64>, Vec<f64>) {
    let buffer = buffer(app);
    let at = |x: u16, y: u16| buffer[(x, y)].symbol().to_owned();
    let (corner_x, corner_y) = (pane.y..pane.bottom())
        .flat_map(|y| (pane.x..pane.right()).map(move |x| (x, y)))
        .find(|&(x, y)| at(x, y) == "└")
        .expect("a chart");
    let numbers = |text: String| -> Vec<f64> {
        text.split_whitespace()
            .filter_map(|w| w.parse().ok())
            .collect()
    };
    let x = numbers(
        (pane.x + 1..pane.right() - 1)
            .map(|c| at(c, corner_y + 1))
            .collect(),
    );
    let y = (pane.y + 1..corner_y)
        .flat_map(|row| numbers((pane.x + 1..corner_x).map(|c| at(c, row)).collect()))
        .collect();
    (x, y)
}

/// Whether `ticks` are round: evenly spaced by 1, 2 or 5 times a power of
/// ten (the y labels top down), each a multiple of it.
fn round(ticks: &[f64]) -> bool {
    if ticks.len() < 2 {
        return false;
    }
    let step = (ticks[1] - ticks[0]).abs();
    let decade = 10f64.powf((step.log10() + 1e-9).floor());
    let mantissa = step / decade;
    let nice = [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-6);
    let even = ticks
        .windows(2)
        .all(|w| ((w[1] - w[0]).abs() - step).abs() < 1e-9 * step);
    let multiples = ticks
        .iter()
        .all(|t| ((t / step).round() - t / step).abs() < 1e-6);
    nice && even && multiples
}

#[test]
fn axis_ticks_are_round_numbers() {
    // The trajectory, the impact and each figure, at 80×24 and 200×60.
    for (w, h) in [(80, 24), (200, 60)] {
        let mut app = app(w, h, None);
        settle(&mut app);
        let panes = layout(app.size, app.tab, true);
        let (x, y) = ticks_in(&app, panes.trajectory.unwrap());
        assert!(round(&x) && round(&y), "trajectory at {w}×{h}: {x:?} {y:?}");
        key(&mut app, KeyCode::Char('3'));
        let (x, y) = ticks_in(&app, layout(app.size, app.tab, true).impact.unwrap());
        assert!(round(&x) && round(&y), "impact at {w}×{h}: {x:?} {y:?}");
        key(&mut app, KeyCode::Char('4'));
        for number in homerun::tui::app::FIGURES {
            while app.figure_number != number {
                key(&mut app, KeyCode::Char('f'));
            }
            settle(&mut app);
            let (x, y) = ticks_in(&app, layout(app.size, app.tab, true).figure.unwrap());
            // Stacked panels each have their own y ticks: check the lowest's.
            let y: Vec<f64> = y.into_iter().rev().take(2).collect();
            assert!(
                round(&x) && round(&y),
                "Fig. {number} at {w}×{h}: {x:?} {y:?}"
            );
        }
    }
}

#[test]
fn fig_13_names_its_points_a_and_b_and_p_c_is_named_in_a_colour_that_reads_on_black() {
    let mut app = app(80, 24, None);
    key(&mut app, KeyCode::Char('4'));
    while app.figure_number != 13 {
        key(&mut app, KeyCode::Char('f'));
    }
    settle(&mut app);
    let text = rows_in(&app, layout(app.size, app.tab, true).figure.unwrap()).join("\n");
    assert!(text.contains("•A") && text.contains("•B"), "{text}");
    key(&mut app, KeyCode::Char('3'));
    let pane = layout(app.size, app.tab, true).impact.unwrap();
    let buffer = buffer(&app);
    let label = (pane.y..pane.bottom())
        .flat_map(|y| (pane.x..pane.right() - 2).map(move |x| (x, y)))
        .find(|&(x, y)| {
            (0..3)
                .map(|k| buffer[(x + k, y)].symbol())
                .collect::<String>()
                == "p_c"
        })
        .expect("p_c named on the chart");
    let colour = buffer[label].fg;
    assert!(
        ![ratatui::style::Color::Blue, ratatui::style::Color::Black].contains(&colour),
        "{colour:?}"
    );
}

#[test]
fn the_trajectory_fills_its_pane_at_every_size() {
    // The fly ball: 28°, 143 m long and 34 m high. Measured on screen: the
    // rows from the ground to the apex against those from the ground to the
    // graph's top, the columns from the plate to the landing against those
    // to the x axis' end. (At equal scales, 200×60 drew a 34 m apex under a
    // 90 m axis: 38 % of the height.)
    for (w, h) in [(80, 24), (120, 40), (160, 48), (200, 60)] {
        let mut app = app_on("fly-ball", w, h, None);
        settle(&mut app);
        let pane = layout(app.size, app.tab, false).trajectory.unwrap();
        let buffer = buffer(&app);
        let cells: Vec<(u16, u16)> = (pane.y..pane.bottom())
            .flat_map(|y| (pane.x..pane.right()).map(move |x| (x, y)))
            .collect();
        let at = |(x, y): (u16, u16)| buffer[(x, y)].symbol().to_owned();
        let braille = |c: &(u16, u16)| {
            at(*c)
                .chars()
                .all(|ch| ('\u{2801}'..='\u{28ff}').contains(&ch))
        };
        let top = cells
            .iter()
            .filter(|c| braille(c))
            .map(|c| c.1)
            .min()
            .unwrap();
        let &(corner_x, ground) = cells.iter().find(|&&c| at(c) == "└").unwrap();
        let axis_end = (corner_x..pane.right())
            .take_while(|&x| at((x, ground)) == "─" || x == corner_x)
            .last()
            .unwrap();
        let &(landing, _) = cells.iter().find(|&&c| at(c) == "█").unwrap();
        let height = f64::from(ground - top) / f64::from(ground - (pane.y + 1));
        let length = f64::from(landing - corner_x) / f64::from(axis_end - corner_x);
        assert!(
            height > 0.8 && length > 0.9,
            "{w}×{h}: the apex at {height:.2} of the height, the landing at {length:.2} of the length"
        );
        // The height axis is labelled to the apex or past it.
        let labels: Vec<f64> = (pane.y + 1..ground)
            .filter_map(|y| {
                let row: String = (pane.x + 1..corner_x).map(|x| at((x, y))).collect();
                row.trim().parse().ok()
            })
            .collect();
        let highest = labels.iter().copied().fold(0.0, f64::max);
        assert!(
            highest > 0.75 * app.flown.flight.apex,
            "{w}×{h}: {labels:?} for an apex of {:.1} m",
            app.flown.flight.apex
        );
    }
}

#[test]
fn a_120x40_screen_shows_a_second_pane_and_below_80x24_a_notice() {
    let mut wide = app(120, 40, None);
    settle(&mut wide);
    let panes = layout(wide.size, wide.tab, true);
    assert!(panes.trajectory.is_some() && panes.readout.is_some());
    assert!(
        panes.heatmap.is_some(),
        "the surface beside the flight: {panes:?}"
    );
    let shown = screen(&wide);
    for title in ["Readout", "Range over (E, ψ)", "apex 27.0 m"] {
        assert!(shown.contains(title), "{title}: {shown}");
    }
    // Tabs 3 and 4 choose the second pane; the flight stays.
    for (tab, title) in [('3', "Impact:"), ('4', "Fig. 8")] {
        key(&mut wide, KeyCode::Char(tab));
        settle(&mut wide);
        let shown = screen(&wide);
        assert!(
            shown.contains(title) && shown.contains("Readout"),
            "{shown}"
        );
    }
    // A batted ball has no surface: its figure takes the place.
    let mut batted = app_on("fly-ball", 120, 40, None);
    settle(&mut batted);
    assert!(screen(&batted).contains("Fig. 3"));

    for (w, h) in [(79, 24), (80, 23), (60, 16), (20, 5)] {
        let mut small = app(w, h, None);
        settle(&mut small);
        let shown = screen(&small);
        let text = shown
            .replace('"', " ")
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        assert!(
            text.contains("terminal too small (need 80×24)"),
            "{w}×{h}: {shown}"
        );
        assert!(!shown.contains("Inputs"), "{w}×{h}: {shown}");
    }
    let mut enough = app(80, 24, None);
    settle(&mut enough);
    assert!(!screen(&enough).contains("too small"));
}

#[test]
fn spin_decay_goes_from_off_to_a_baseballs_30_s_and_its_delta_says_so() {
    use homerun::analysis::sensitivity;
    use homerun::model::keys::all_keys;
    let mut app = app(80, 24, None);
    settle(&mut app);
    select(&mut app, "model.spin_decay");
    assert_eq!(app.scene.spin_decay, 0.0);
    // The Δ column measures this same nudge: off → 30 s.
    let tau = all_keys().find(|k| k.name == "model.spin_decay").unwrap();
    let on = sensitivity::nudge(&app.scene, tau, 1.0).unwrap();
    assert_eq!(on.spin_decay, 30.0);
    let gain = sensitivity::range_gain(&app.scene, tau, app.flown.flight.range).unwrap();
    // 30 s costs the fastball a little range (less lift late in the flight),
    // far less than the 12.9 m that 1 s cost.
    assert!(gain < 0.0 && gain > -3.0, "{gain}");
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.scene.spin_decay, 30.0);
    key(&mut app, KeyCode::Char('l'));
    assert_eq!(app.scene.spin_decay, 31.0);
    key(&mut app, KeyCode::Char('h'));
    key(&mut app, KeyCode::Char('h'));
    assert_eq!(app.scene.spin_decay, 29.0);
    // Down from off stays refused, as below any key's bound.
    let mut off = app.scene;
    off.spin_decay = 0.0;
    assert!(sensitivity::nudge(&off, tau, -1.0).is_err());
}

#[test]
fn a_click_on_the_surface_sets_values_on_the_inputs_steps() {
    use ratatui::crossterm::event::{Event, KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
    // In SI (0.5 mm, 0.01 rad) and in baseball units (0.02 in, 0.5°), over
    // cells across the surface: the inputs pane shows each value whole.
    for imperial in [false, true] {
        let mut app = app(80, 24, None);
        if imperial {
            key(&mut app, KeyCode::Char('u'));
        }
        settle(&mut app);
        key(&mut app, KeyCode::Char('2'));
        let plot =
            homerun::tui::layout::heatmap_plot(layout(app.size, app.tab, true).heatmap.unwrap());
        for (column, row) in [
            (1, 1),
            (plot.width / 3, 2 * plot.height / 3),
            (plot.width - 2, 3),
        ] {
            app.handle(&Event::Mouse(MouseEvent {
                kind: MouseEventKind::Down(MouseButton::Left),
                column: plot.x + column,
                row: plot.y + row,
                modifiers: KeyModifiers::NONE,
            }));
            app.flush();
            let (e, psi) = (app.scene.bat.undercut, app.scene.bat.swing_angle);
            let (e_step, psi_step, e_shown, psi_shown) = if imperial {
                (0.02, 0.5, e / 0.0254, psi.to_degrees())
            } else {
                (0.0005, 0.01, e, psi)
            };
            for (value, step) in [(e_shown, e_step), (psi_shown, psi_step)] {
                let steps = value / step;
                assert!((steps - steps.round()).abs() < 1e-9, "{value} by {step}");
            }
        }
    }
}

#[test]
fn the_fence_reads_the_same_in_the_cli_and_the_explorer() {
    // The fastball's flight passes the default fence 12.20 m up: over the
    // 3.0 m wall by 9.2 m; in feet the 121.9 m fence is the 400 ft it was.
    for (units, sentence) in [
        ("si", "121.9 m, 3.0 m high: over by 9.2 m"),
        ("imperial", "400 ft, 10 ft high: over by 30.2 ft"),
    ] {
        let output = common::command()
            .args(["fly", "--units", units])
            .output()
            .unwrap();
        let cli = String::from_utf8(output.stdout).unwrap();
        assert!(cli.contains(&format!("fence    {sentence}\n")), "{cli}");
        let mut app = app(80, 24, None);
        if units == "imperial" {
            key(&mut app, KeyCode::Char('u'));
        }
        settle(&mut app);
        assert!(
            screen(&app).contains(&format!("fence    {sentence}")),
            "{}",
            screen(&app)
        );
    }
}

#[test]
fn without_colour_every_cell_is_in_the_terminals_own_colours() {
    use homerun::tui::theme::{Background, ColorMode, Theme};
    use ratatui::style::{Color, Modifier};
    for (w, h) in [(80, 24), (200, 60)] {
        let mut app = themed(Theme::new(Background::Dark, ColorMode::NoColor), w, h);
        settle(&mut app);
        for tab in ['1', '2', '3', '4', '?'] {
            key(&mut app, KeyCode::Char(tab));
            settle(&mut app);
            let buffer = buffer(&app);
            for cell in buffer.content() {
                assert!(
                    cell.fg == Color::Reset && cell.bg == Color::Reset,
                    "{tab}: {cell:?}"
                );
            }
            // The selected input stands out in reverse video.
            let reversed = buffer
                .content()
                .iter()
                .any(|c| c.modifier.contains(Modifier::REVERSED));
            assert!(reversed, "{w}×{h} {tab}");
            key(&mut app, KeyCode::Esc);
        }
    }
    // The surface in shades, its contour dotted, the marks in reverse.
    let mut app = themed(Theme::new(Background::Dark, ColorMode::NoColor), 80, 24);
    settle(&mut app);
    key(&mut app, KeyCode::Char('2'));
    let shown = screen(&app);
    for glyph in ["▓", "▒", "░", "•", "✚"] {
        assert!(shown.contains(glyph), "{glyph}: {shown}");
    }
    insta::assert_snapshot!("surface_no_color_80x24", shown);
}
