//! The mouse on the panes: the heatmap, the inputs, the field view.

use crate::mouse;
use crate::tui_support::*;
use homerun::analysis::precision::Purpose;
use homerun::analysis::study::Grid;
use homerun::model::keys::KEYS;
use homerun::tui::app::Field;
use homerun::tui::layout::{CELL_ASPECT, FieldMap, heatmap_plot, layout};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, MouseButton, MouseEventKind};
use ratatui::layout::Rect;

#[test]
fn a_click_on_the_heatmap_moves_the_swing_to_that_cells_centre_on_the_steps() {
    for (w, h, tab) in [(80, 24, '2'), (200, 60, '1')] {
        let mut app = app(w, h, None);
        settle(&mut app);
        key(&mut app, KeyCode::Char(tab));
        let area = layout(app.size, app.tab, true).heatmap.unwrap();
        let plot = heatmap_plot(area);
        // A cell a third of the way across and two thirds down.
        let (column, row) = (plot.width / 3, 2 * plot.height / 3);
        let (x, y) = (plot.x + column, plot.y + row);
        mouse(&mut app, MouseEventKind::Down(MouseButton::Left), x, y);
        // One grid column per character, two grid rows (half blocks) per
        // line, the first row at the bottom, over the explorer's window.
        let window = Grid::explorer_window();
        let (columns, rows) = (plot.width as f64, 2.0 * plot.height as f64);
        let e = window.undercut.0
            + (window.undercut.1 - window.undercut.0) * column as f64 / (columns - 1.0);
        // The mean of the cell's two rows, rows − 1 − 2·row and the one below.
        let j = rows - 1.5 - 2.0 * row as f64;
        let psi =
            window.swing_angle.0 + (window.swing_angle.1 - window.swing_angle.0) * j / (rows - 1.0);
        // Rounded to the inputs' steps (0.5 mm, 0.01 rad).
        let step = |name| homerun::Scene::key(name).unwrap().step;
        let on_step = |v: f64, name| (v / step(name)).round() * step(name);
        let (e, psi) = (on_step(e, "bat.undercut"), on_step(psi, "bat.swing_angle"));
        assert!((app.scene.bat.undercut - e).abs() < 1e-12, "{w}x{h}");
        assert!((app.scene.bat.swing_angle - psi).abs() < 1e-12, "{w}x{h}");
        // The swing's mark is drawn in the cell clicked.
        let mut terminal = ratatui::Terminal::new(TestBackend::new(w, h)).unwrap();
        terminal
            .draw(|frame| homerun::tui::view::draw(frame, &app))
            .unwrap();
        assert_eq!(terminal.backend().buffer()[(x, y)].symbol(), "✚");
    }
}

#[test]
fn a_click_on_an_input_selects_it_and_the_wheel_nudges_it() {
    let mut app = app(80, 24, None);
    let screen = screen(&app);
    // The row on screen whose label is ω_B0 (the bat's roll).
    let line = screen.lines().position(|l| l.contains("ω_B0")).unwrap() as u16;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), 5, line);
    let spin = app.fields[app.selected];
    assert!(
        matches!(spin, Field::Key(k) if KEYS[k].name == "bat.spin"),
        "{spin:?}"
    );
    // The wheel over another input: that one, up a step, then down two.
    let speed = screen.lines().position(|l| l.contains("V̂_b0")).unwrap() as u16;
    mouse(&mut app, MouseEventKind::ScrollUp, 10, speed);
    assert_eq!(app.scene.pitch.speed, 42.0 + 0.5);
    mouse(&mut app, MouseEventKind::ScrollDown, 10, speed);
    mouse(&mut app, MouseEventKind::ScrollDown, 10, speed);
    assert_eq!(app.scene.pitch.speed, 42.0 - 0.5);
    assert!(matches!(app.fields[app.selected], Field::Key(k) if KEYS[k].name == "pitch.speed"));
    // A click on a group's header or outside the panes changes nothing.
    let before = (app.selected, app.scene);
    let header = screen.lines().position(|l| l.contains("─ bat")).unwrap() as u16;
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), 5, header);
    mouse(&mut app, MouseEventKind::Down(MouseButton::Left), 79, 23);
    assert_eq!((app.selected, app.scene), before);
}

/// The field view's geometry, computed here from the pane alone: the plot
/// is the pane inside its border, at equal scales (a braille dot is half a
/// cell wide and a quarter of a cell [`CELL_ASPECT`] times as tall as it is
/// wide), the plate at the bottom centre. So the direction of a cell's
/// centre from the plate needs no metres: only how many dots across and up.
fn clicked_direction(pane: Rect, plate_row_dots: f64, column: u16, row: u16) -> f64 {
    let plot = Rect::new(pane.x + 1, pane.y + 1, pane.width - 2, pane.height - 2);
    // Dots from the plate (at the middle of the plot's dot columns).
    let across = 2.0 * f64::from(column - plot.x) + 0.5 - (2.0 * f64::from(plot.width) - 1.0) / 2.0;
    let up = plate_row_dots - (4.0 * f64::from(row - plot.y) + 1.5);
    // A dot across is half a cell wide; one up is a quarter of a cell tall.
    (across / 2.0).atan2(up * CELL_ASPECT / 4.0)
}

#[test]
fn a_click_on_the_field_sets_the_launch_direction_on_its_step() {
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('5'));
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    let map = app.field_map(pane);
    // The plate's dot row, from the bounds the view drew (x = 0 lies
    // `behind` metres above the bottom dot row).
    let dots_x = 4.0 * f64::from(pane.height - 2) - 1.0;
    let plate_row_dots = dots_x * map.x[1] / (map.x[1] - map.x[0]);
    let (column, row) = (pane.x + 10, pane.y + 6);
    mouse(
        &mut app,
        MouseEventKind::Down(MouseButton::Left),
        column,
        row,
    );
    settle(&mut app);
    let expected = clicked_direction(pane, plate_row_dots, column, row);
    // On the input's step (0.01 rad), as typed.
    let on_step = (expected / 0.01).round() * 0.01;
    assert!(expected < -0.3, "left of centre: {expected}");
    assert_eq!(app.scene.launch.direction, Some(on_step));
    assert!((app.flown.flight.direction - on_step).abs() < 0.01);
    // In degrees the step is 0.5°.
    app.set_units(homerun::units::UnitSystem::Imperial);
    let (column, row) = (pane.right() - 12, pane.y + 8);
    mouse(
        &mut app,
        MouseEventKind::Down(MouseButton::Left),
        column,
        row,
    );
    let expected = clicked_direction(pane, plate_row_dots, column, row);
    let degrees = (expected.to_degrees() / 0.5).round() * 0.5;
    assert!(expected > 0.3, "right of centre: {expected}");
    let set = app.scene.launch.direction.unwrap();
    assert!(
        (set - degrees.to_radians()).abs() < 1e-12,
        "{set} vs {degrees}°"
    );
}

#[test]
fn a_click_on_the_field_of_a_swing_makes_it_a_batted_ball_and_b_returns() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    let swing = app.scene;
    key(&mut app, KeyCode::Char('5'));
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    mouse(
        &mut app,
        MouseEventKind::Down(MouseButton::Left),
        pane.x + pane.width / 2 + 6,
        pane.y + 4,
    );
    assert!(!app.is_swing());
    let direction = app.scene.launch.direction.unwrap();
    assert!(direction > 0.0 && direction < 0.7, "{direction}");
    // The swing's launch, turned.
    assert_eq!(app.scene.launch.speed, Some(app.flown.launch.speed));
    key(&mut app, KeyCode::Char('b'));
    assert!(app.is_swing());
    assert_eq!(app.scene.pitch, swing.pitch);
    assert_eq!(app.scene.bat, swing.bat);
}

#[test]
fn the_pinned_track_is_drawn_on_the_field() {
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('5'));
    set_and_settle(&mut app, "launch.direction", "0.3");
    key(&mut app, KeyCode::Char('p'));
    set_and_settle(&mut app, "launch.direction", "-0.3");
    let pin = app.pin.as_ref().unwrap();
    assert_eq!(pin.ground.len(), pin.path.len());
    // Its track ends toward right field, the current one toward left.
    let (pin_end, now_end) = (*pin.ground.last().unwrap(), *app.ground.last().unwrap());
    assert!(
        pin_end.1 > 30.0 && now_end.1 < -30.0,
        "{pin_end:?} {now_end:?}"
    );
    // Drawn in the pin's colour: a cell where its landing point falls.
    let pane = layout(app.size, app.tab, app.is_swing()).field.unwrap();
    let map = app.field_map(pane);
    let buffer = buffer(&app);
    let in_pin_colour = |(x, z): (f64, f64)| {
        let (column, row) = cell(&map, x, z);
        buffer[(column, row)].fg == app.theme.pinned.fg.unwrap()
    };
    let drawn = pin
        .ground
        .iter()
        .rev()
        .take(10)
        .filter(|p| in_pin_colour(**p))
        .count();
    assert!(
        drawn >= 5,
        "{drawn} of the pin's last 10 samples in its colour"
    );
    assert!(screen(&app).contains("pin"), "the legend names the pin");
}

/// The cell where the chart draws (x, z) in braille over the field's plot.
fn cell(map: &FieldMap, x: f64, z: f64) -> (u16, u16) {
    let plot = map.plot;
    let dots_z = 2.0 * f64::from(plot.width) - 1.0;
    let dots_x = 4.0 * f64::from(plot.height) - 1.0;
    let column = ((z - map.z[0]) * dots_z / (map.z[1] - map.z[0])).round() as u16 / 2;
    let row = ((map.x[1] - x) * dots_x / (map.x[1] - map.x[0])).round() as u16 / 4;
    (plot.x + column, plot.y + row)
}

/// `m` picks a ballpark: the field draws its fence, the side view its wall
/// where the ball crosses, and the readout says what the ball does there and
/// in how many parks it clears, each flown in its own air as `fly` counts.
#[test]
fn m_picks_a_park_and_the_readout_judges_the_ball_there() {
    use homerun::model::park;
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    let (flight, _, _) = homerun::model::launch::scene_start(&app.scene);
    let options = Purpose::Readout.flight_options();
    let in_own_air = |p: &park::Park| {
        let mut there = app.scene;
        park::GivenWeather::default().park_air(&mut there.environment, p.elevation);
        let (flight, _, _) = homerun::model::launch::scene_start(&there);
        flight.judge(&options, &[&p.fence]).1[0].clears()
    };
    let cleared = park::bundled().iter().filter(|p| in_own_air(p)).count();
    let at = app.at_parks.unwrap();
    assert_eq!((at.cleared, at.of), (cleared, 30));
    assert!(screen(&app).contains(&format!("clears {cleared} of 30 parks")));
    key(&mut app, KeyCode::Char('m'));
    // The park brings its air; `a` takes the air before, in which `flight`
    // above flew.
    assert!(app.in_park_air());
    key(&mut app, KeyCode::Char('a'));
    settle(&mut app);
    assert!(!app.in_park_air());
    let first = &park::bundled()[0];
    assert_eq!(app.park, Some(0));
    assert_eq!(app.field_fence().unwrap(), first.fence);
    let here = app.at_parks.unwrap().here.unwrap();
    assert_eq!(here, flight.judge(&options, &[&first.fence]).1[0]);
    let wall = here.wall.unwrap();
    assert_eq!(app.side_fence(), Some((wall.distance, wall.height)));
    assert!(
        screen(&app).contains(&format!("{} ", first.code)),
        "{}",
        screen(&app)
    );
    // Back past the first park: none, the preset's fence again.
    key(&mut app, KeyCode::Char('M'));
    assert_eq!(app.park, None);
    assert!(app.at_parks.unwrap().here.is_none());
}

/// Issue 36, item 12: a click on a tab's title shows that tab, at 80×24
/// (short titles) and 200×60 (where the big layout has no tab bar, nothing
/// to click).
#[test]
fn a_click_on_a_tabs_title_shows_it() {
    use homerun::tui::layout::Tab;
    let mut app = app(80, 24, None);
    let bar = layout(app.size, app.tab, true).tabs.unwrap();
    let text = screen(&app);
    // The screen's rows as the test backend writes them, each in quotes.
    let line = text
        .lines()
        .nth(bar.y as usize)
        .unwrap()
        .trim_start_matches('"');
    for (tab, title) in [
        (Tab::Impact, "3 Impact"),
        (Tab::Field, "5 Field"),
        (Tab::Flight, "1 Flight"),
        (Tab::Surface, "2 Surface"),
    ] {
        // The title's middle, where the screen shows it.
        let at = line.find(title).unwrap();
        let column = line[..at].chars().count() + title.chars().count() / 2;
        mouse(
            &mut app,
            MouseEventKind::Down(MouseButton::Left),
            column as u16,
            bar.y,
        );
        assert_eq!(app.tab, tab, "{title} at column {column}");
    }
}
