//! The flight and the field fill their panes at every size (issue 28,
//! item 9): at 200×60 the field once drew in the lower two thirds of a
//! tall, narrow pane.

use crate::tui_support::*;
use homerun::tui::app::App;
use homerun::tui::layout::layout;
use ratatui::crossterm::event::KeyCode;

/// The share of the field's plot (the pane inside its border) that the
/// fence and the tracks span, across and up: the box around every cell
/// drawn but in the faint colour of the foul lines and distance rings.
fn field_spans(app: &App) -> (f64, f64) {
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    let rows = rows_in(app, pane);
    let buffer = buffer(app);
    let inner = (pane.x + 1..pane.right() - 1, pane.y + 1..pane.bottom() - 1);
    let drawn: Vec<(u16, u16)> = inner
        .1
        .clone()
        .flat_map(|y| inner.0.clone().map(move |x| (x, y)))
        .filter(|&c| buffer[c].symbol() != " " && Some(buffer[c].fg) != app.theme.dim.fg)
        .collect();
    let (xs, ys): (Vec<u16>, Vec<u16>) = drawn.into_iter().unzip();
    let span = |v: &[u16]| f64::from(v.iter().max().unwrap() - v.iter().min().unwrap() + 1);
    let across = span(&xs) / f64::from(pane.width - 2);
    let up = span(&ys) / f64::from(pane.height - 2);
    assert!(!rows.is_empty());
    (across, up)
}

#[test]
fn the_field_fills_its_pane_at_every_size() {
    for (w, h) in [(80, 24), (120, 40), (160, 48), (200, 60)] {
        for (preset, park) in [
            ("fastball", None),
            ("fly-ball", None),
            ("fastball", Some("BOS")),
        ] {
            let mut app = app_on(preset, w, h, None);
            if let Some(code) = park {
                pick(&mut app, code);
            }
            settle(&mut app);
            key(&mut app, KeyCode::Char('5'));
            let (across, up) = field_spans(&app);
            // At equal scales one way is filled, and the other most of it
            // (at 120×40 the field's pane is a wide strip under the flight,
            // and the field fills its height).
            let (most, least) = (across.max(up), across.min(up));
            assert!(
                most > 0.9 && (least > 0.7 || w == 120),
                "{preset} {park:?} at {w}×{h}: {across:.2} across, {up:.2} up"
            );
        }
    }
}
