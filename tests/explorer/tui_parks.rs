//! The explorer at the ballparks: the margin over a park's wall as a map
//! over the swings (`c`), the field shaded by wall height, the user's own
//! parks in the picker, and a park's own air.

use crate::tui_support;

use homerun::analysis::precision::Purpose;
use homerun::model::clearing::Outcome;
use homerun::model::park;
use homerun::tui::margin::{MarginCell, margin_at};
use homerun::tui::theme::{Background, ColorMode, Theme};
use ratatui::crossterm::event::KeyCode;
use tui_support::*;

#[test]
fn c_shows_the_margin_over_the_wall_and_c_again_the_range() {
    let mut app = app(80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('2'));
    assert!(!app.shows_margin());
    // No park: the preset's fence, the same in every direction.
    key(&mut app, KeyCode::Char('c'));
    settle(&mut app);
    assert!(app.shows_margin() && app.margin_fresh());
    let shown = screen(&app);
    assert!(
        shown.contains("Margin at the fence (E, ψ) · ── 0 m"),
        "{shown}"
    );
    assert!(shown.contains("margin ✓ 32×38"), "{shown}");
    // A park: its wall.
    pick(&mut app, "BOS");
    settle(&mut app);
    assert!(screen(&app).contains("Margin at BOS (E, ψ)"));
    // New inputs while the margin shows: the range surface is not computed.
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('l'));
    settle(&mut app);
    assert!(app.margin_fresh() && !app.surface_fresh());
    assert!(!app.busy(), "the margin map is what the heatmap waits for");
    // Back to the range: computed now, for these inputs.
    key(&mut app, KeyCode::Char('c'));
    assert!(!app.shows_margin() && app.busy());
    settle(&mut app);
    assert!(app.surface_fresh() && !app.busy());
    assert!(screen(&app).contains("Range over (E, ψ)"));
}

#[test]
fn a_batted_ball_has_no_margin_map() {
    let mut app = app_on("fly-ball", 80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('c'));
    assert!(!app.shows_margin() && app.take_margin_job().is_none());
    assert!(
        app.message
            .as_ref()
            .is_some_and(|(m, error)| *error && m.contains("swing scene"))
    );
}

/// The map's margin is the clearance of `Clearing`: over the wall (> 0)
/// where the readout says the ball clears, under it where it does not,
/// and the map's cell at the swing agrees.
#[test]
fn the_margin_is_positive_where_the_ball_clears_and_negative_where_it_does_not() {
    // The fastball's swing 2 m/s slower: 125 m, out of some parks only.
    let mut app = app(80, 24, None);
    set_and_settle(&mut app, "bat.speed", "28");
    let options = Purpose::Readout.flight_options();
    let swing = (app.scene.bat.undercut, app.scene.bat.swing_angle);
    let mut margins = Vec::new();
    for p in park::bundled() {
        pick(&mut app, &p.code);
        let here = app.at_parks.unwrap().here.unwrap();
        let MarginCell::Margin(m) = margin_at(&app.scene, &p.fence, swing, &options) else {
            panic!("{}: no margin", p.code);
        };
        // The readout's verdict, from the same flight at the same precision.
        let clearance = here.clearance(&app.flown.flight).unwrap();
        assert!(
            (m - clearance).abs() < 1e-9,
            "{}: {m} vs {clearance}",
            p.code
        );
        assert_eq!(m > 0.0, here.outcome == Outcome::Clears, "{}: {m}", p.code);
        margins.push((m, p.code.as_str()));
    }
    margins.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (lowest, highest) = (margins[0], margins[margins.len() - 1]);
    assert!(lowest.0 < -2.0 && highest.0 > 2.0, "{margins:?}");

    // On the map: the cell nearest the swing, at the park it clears by
    // most and at the one it misses by most.
    for (code, over) in [(highest.1, true), (lowest.1, false)] {
        pick(&mut app, code);
        if !app.shows_margin() {
            key(&mut app, KeyCode::Char('c'));
        }
        settle(&mut app);
        let state = app.margin.state.as_ref().unwrap();
        let grid = state.surface.grid;
        let nearest = |from: f64, to: f64, n: usize, v: f64| {
            (((v - from) / (to - from) * (n - 1) as f64).round() as usize).min(n - 1)
        };
        let i = nearest(grid.undercut.0, grid.undercut.1, grid.columns, swing.0);
        let j = nearest(grid.swing_angle.0, grid.swing_angle.1, grid.rows, swing.1);
        let cell = state.surface.cell(i, j).margin().unwrap();
        assert_eq!(cell > 0.0, over, "{code}: the map's {cell} at the swing");
    }
}

/// Without colour the map is in glyphs: shades over the wall, lines
/// under it, its contour dotted.
#[test]
fn the_margin_map_without_colour() {
    let mut app = themed(Theme::new(Background::Dark, ColorMode::NoColor), 80, 24);
    settle(&mut app);
    pick(&mut app, "AZ");
    key(&mut app, KeyCode::Char('2'));
    key(&mut app, KeyCode::Char('c'));
    settle(&mut app);
    let shown = screen(&app);
    for glyph in ["▓", "░", "·", "-", "=", "•", "✚"] {
        assert!(shown.contains(glyph), "{glyph}: {shown}");
    }
    insta::assert_snapshot!("margin_no_color_80x24", shown);
}

/// The field from above draws a park's wall shaded by its height: at
/// Fenway the 37 ft wall in left field in the tallest band's colour and
/// full blocks, left of the plate only; a legend names the bands.
#[test]
fn the_field_shades_the_wall_by_its_height_and_the_monster_stands_out() {
    for (w, h) in [(80, 24), (160, 48)] {
        let mut app = app(w, h, None);
        settle(&mut app);
        key(&mut app, KeyCode::Char('5'));
        pick(&mut app, "BOS");
        settle(&mut app);
        let pane = homerun::tui::layout::layout(app.size, app.tab, true)
            .field
            .unwrap();
        let buffer = buffer(&app);
        let tallest = app.theme.walls[3].fg;
        let plate = pane.x + pane.width / 2;
        let monster: Vec<u16> = (pane.y + 1..pane.bottom() - 1)
            .flat_map(|y| (pane.x + 1..pane.right() - 1).map(move |x| (x, y)))
            .filter(|&(x, y)| {
                buffer[(x, y)].symbol() == "█" && buffer[(x, y)].fg == tallest.unwrap()
            })
            .map(|(x, _)| x)
            .collect();
        assert!(monster.len() >= 5, "{w}×{h}: {monster:?}");
        assert!(monster.iter().all(|&x| x < plate), "{w}×{h}: {monster:?}");
        let shown = screen(&app);
        assert!(shown.contains("wall ━≤2.4 ━≤3.7 ▀<6.1 █≥6.1 m"), "{shown}");
        insta::assert_snapshot!(format!("field_bos_{w}x{h}"), shown);
    }
    // Without a park, the preset's fence in one colour and no legend.
    let mut app = app(80, 24, None);
    settle(&mut app);
    key(&mut app, KeyCode::Char('5'));
    assert!(!screen(&app).contains("wall "));
    // In feet: the bands' own numbers.
    pick(&mut app, "BOS");
    key(&mut app, KeyCode::Char('u'));
    assert!(screen(&app).contains("wall ━≤8 ━≤12 ▀<20 █≥20 ft"));
}

/// A park of the user's own (`data/parks.toml`'s format) in the parks
/// folder is among the parks `m`/`M` go through, after the bundled 30: its
/// fence is drawn and judged. "N of 30" still counts the bundled parks.
#[test]
fn a_users_park_is_in_the_picker_after_the_bundled_ones() {
    let dir = tempfile::tempdir().unwrap();
    // A short porch: 80 m to the wall everywhere, 2 m high.
    let mine = "[[park]]\ncode = \"MYP\"\nname = \"My Porch\"\nelevation = 10\ncenter_field_bearing = 45\nfence = [\n  { direction = -0.7854, distance = 80, height = 2 },\n  { direction = 0.7854, distance = 80, height = 2 },\n]\n";
    std::fs::write(dir.path().join("porch.toml"), mine).unwrap();
    let mut app = app(80, 24, None);
    settle(&mut app);
    let counted = app.at_parks.unwrap();
    app.load_parks(Some(dir.path()));
    assert_eq!(app.parks.list.parks.len(), 31);
    // M from none: the last, the user's.
    key(&mut app, KeyCode::Char('M'));
    let park = app.chosen_park().unwrap();
    assert_eq!(
        (park.code.as_str(), park.name.as_str()),
        ("MYP", "My Porch")
    );
    let (message, error) = app.message.clone().unwrap();
    assert!(
        !error && message.contains("park 31/31: MYP (My Porch, yours from porch.toml)"),
        "{message}"
    );
    // Judged at its wall: the fastball (134.7 m) clears an 80 m porch.
    let here = app.at_parks.unwrap().here.unwrap();
    assert!(here.clears(), "{here:?}");
    assert_eq!(here.wall.unwrap().distance, 80.0);
    assert_eq!(
        (app.at_parks.unwrap().cleared, app.at_parks.unwrap().of),
        (counted.cleared, 30)
    );
    assert!(screen(&app).contains("MYP clears by"), "{}", screen(&app));
    // On the field, its fence (80 m) in the lowest band: a legend, no
    // other park's wall.
    key(&mut app, KeyCode::Char('5'));
    assert!(screen(&app).contains("wall ━≤2.4"));
    // m past it: none again; then the first bundled park.
    key(&mut app, KeyCode::Char('m'));
    assert!(app.chosen_park().is_none());
    key(&mut app, KeyCode::Char('m'));
    assert_eq!(app.chosen_park().unwrap().code, "AZ");
}

#[test]
fn a_broken_park_file_leaves_the_bundled_parks_and_says_why() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.toml"), "[[park]]\ncode = 3\n").unwrap();
    let mut app = app(80, 24, None);
    app.load_parks(Some(dir.path()));
    assert_eq!(app.parks.list.parks.len(), 30);
    let (message, error) = app.message.clone().unwrap();
    assert!(error && message.contains("bad.toml"), "{message}");
    key(&mut app, KeyCode::Char('m'));
    let (message, error) = app.message.clone().unwrap();
    assert!(
        error && message.contains("your parks were not read"),
        "{message}"
    );
    assert_eq!(app.chosen_park().unwrap().code, "AZ");
}

/// `a`: the scene in the chosen park's own air, the standard atmosphere at
/// its elevation (as `fly --own-air` flies each park); the air follows the
/// park; `a` again brings back the air from before.
#[test]
fn a_flies_the_scene_in_the_parks_own_air_and_a_again_brings_back_the_air_before() {
    use homerun::model::atmosphere::Atmosphere;
    let mut app = app(80, 24, None);
    settle(&mut app);
    let before = app.scene.environment.air();
    let at_sea_level = app.flown.flight.range;
    // No park yet: refused, nothing changes.
    key(&mut app, KeyCode::Char('a'));
    assert!(!app.in_park_air() && app.scene.environment.air() == before);
    assert!(
        app.message
            .as_ref()
            .is_some_and(|(m, error)| *error && m.contains("pick a park"))
    );

    // Choosing a park brings its air (as `fly --park` flies in it), and
    // says so; `a` goes back to the air before, and `a` again to the park's.
    pick(&mut app, "COL");
    settle(&mut app);
    assert!(app.in_park_air());
    let (message, error) = app.message.clone().unwrap();
    assert!(
        !error && message.contains("COL") && message.contains("in its air at 1580 m"),
        "{message}"
    );
    key(&mut app, KeyCode::Char('a'));
    settle(&mut app);
    assert!(!app.in_park_air());
    assert_eq!(app.scene.environment.air(), before);
    key(&mut app, KeyCode::Char('a'));
    settle(&mut app);
    let coors = park::find(park::bundled(), "COL").unwrap().elevation;
    let air = app.scene.environment.atmosphere().unwrap();
    assert_eq!(
        air,
        Atmosphere {
            elevation: coors,
            ..Atmosphere::STANDARD
        }
    );
    // A mile up the air is about 17 % thinner than the preset's 1.23 kg/m³
    // (e^(−1.217e−4·1580) = 0.825 of sea level's standard 1.2250), and the
    // ball flies further.
    let ratio = app.scene.environment.air_density / Atmosphere::STANDARD.air_density();
    assert!((ratio - 0.8253).abs() < 0.002, "{ratio}");
    assert!(
        app.flown.flight.range > at_sea_level + 1.0,
        "{} vs {at_sea_level}",
        app.flown.flight.range
    );
    let shown = screen(&app);
    assert!(shown.contains("COL's standard air at 1579.8 m"), "{shown}");
    assert!(
        shown.contains("parks    COL clears by"),
        "the verdict stays in view: {shown}"
    );
    insta::assert_snapshot!("park_air_80x24", shown);

    // The next park brings its own air.
    key(&mut app, KeyCode::Char('m'));
    let next = app.chosen_park().unwrap().clone();
    assert_eq!(
        app.scene.environment.atmosphere().unwrap().elevation,
        next.elevation
    );
    assert!(app.message.as_ref().unwrap().0.contains("in its air at"));
    // a: the air from before, exactly (the preset's ρ and ν, given).
    key(&mut app, KeyCode::Char('a'));
    settle(&mut app);
    assert!(!app.in_park_air());
    assert_eq!(app.scene.environment.air(), before);
    assert_eq!(app.flown.flight.range, at_sea_level);
    // In a park's air, no park at all: the air from before too.
    key(&mut app, KeyCode::Char('a'));
    for _ in 0..=park::bundled().len() {
        if app.chosen_park().is_none() {
            break;
        }
        key(&mut app, KeyCode::Char('m'));
    }
    assert!(!app.in_park_air());
    assert_eq!(app.scene.environment.air(), before);
}

/// The new panes at odd and tiny sizes: a 3-D swing's impact, the margin
/// map, a park's wall and its air, on every tab.
#[test]
fn the_park_views_never_panic_at_odd_sizes() {
    for (w, h) in [
        (1, 1),
        (20, 5),
        (61, 16),
        (80, 24),
        (116, 34),
        (139, 40),
        (190, 54),
        (300, 100),
    ] {
        let mut app = app(w, h, None);
        set_and_settle(&mut app, "bat.tilt", "0.5");
        set_and_settle(&mut app, "bat.direction", "-0.3");
        // The park brings its air.
        pick(&mut app, "HOU");
        key(&mut app, KeyCode::Char('c'));
        settle(&mut app);
        for tab in ['1', '2', '3', '4', '5'] {
            key(&mut app, KeyCode::Char(tab));
            for _ in 0..9 {
                key(&mut app, KeyCode::Char('.'));
                let _ = screen(&app);
            }
        }
    }
}

/// The margin thread: a map for a newer generation cancels the older one
/// between cells, and the newer one is finished, row blocks and all; a
/// map no longer shown stops without a new one.
#[test]
fn the_margin_thread_cancels_old_maps_and_finishes_the_new() {
    use homerun::tui::worker::Worker;
    use std::time::Duration;
    let mut app = app(200, 60, None);
    settle(&mut app);
    pick(&mut app, "BOS");
    key(&mut app, KeyCode::Char('c'));
    let worker = Worker::spawn();
    let first = app.take_margin_job().unwrap();
    worker.submit_margin(first.clone());
    select(&mut app, "bat.speed");
    key(&mut app, KeyCode::Char('l'));
    let second = app.take_margin_job().unwrap();
    assert!(second.generation > first.generation);
    worker.submit_margin(second.clone());
    while !app.margin_fresh() {
        let report = worker
            .margins
            .recv_timeout(Duration::from_secs(120))
            .expect("the margin thread answers");
        app.apply_margin(report);
    }
    let map = app.margin.state.as_ref().unwrap().surface.clone();
    assert_eq!(map.grid.columns * map.grid.rows, map.done());
    assert!(map.grid.columns > 8, "{:?}", map.grid);

    // c: no map shown; the one under way stops at its next cell.
    key(&mut app, KeyCode::Char('L'));
    let third = app.take_margin_job().unwrap();
    worker.submit_margin(third);
    key(&mut app, KeyCode::Char('c'));
    assert!(app.take_margin_job().is_none());
    worker.cancel_margins_before(app.margin.generation);
    let blocks = map.grid.rows.div_ceil((256 / map.grid.columns).max(1));
    let mut sent = 0;
    while worker
        .margins
        .recv_timeout(Duration::from_millis(500))
        .is_ok()
    {
        sent += 1;
    }
    assert!(
        sent < blocks,
        "{sent} of {blocks} blocks sent after the cancel"
    );
}

/// Issue 25 row 12: a preset's description (and name) or a park's name
/// holding U+202E (right-to-left override) was printed raw, reversing the
/// rest of the line on the terminal. Every text from a file is escaped,
/// and no bidirectional or control character reaches a cell.
#[test]
fn bidi_controls_from_files_never_reach_the_screen() {
    let presets = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string("presets/fly-ball.toml").unwrap();
    let description = text
        .lines()
        .find(|l| l.starts_with("description"))
        .unwrap()
        .to_owned();
    let evil = text.replace(
        &description,
        "description = \"harmless\u{202e}txt.exe \u{2066}x\u{2069} \\u001b[2J\"",
    );
    std::fs::write(presets.path().join("evil.toml"), evil).unwrap();
    let parks = tempfile::tempdir().unwrap();
    let park = "[[park]]\ncode = \"RLO\"\nname = \"Left\u{202e}Right\"\nelevation = 10\ncenter_field_bearing = 45\nfence = [\n  { direction = -0.7854, distance = 80, height = 2 },\n  { direction = 0.7854, distance = 80, height = 2 },\n]\n";
    std::fs::write(parks.path().join("rlo.toml"), park).unwrap();
    let mut app = app(120, 40, Some(presets.path().to_owned()));
    settle(&mut app);
    app.load_parks(Some(parks.path()));
    let clean = |screen: &str| {
        !screen
            .chars()
            .any(|c| homerun::preset::needs_escape(c) && c != '\n')
    };
    // The picker shows the description escaped.
    key(&mut app, KeyCode::Char('o'));
    let shown = screen(&app);
    assert!(clean(&shown), "{shown:?}");
    assert!(shown.contains("harmless\\u{202e}txt.exe"), "{shown}");
    // Loaded: its description under the inputs, escaped.
    for _ in 0..20 {
        let homerun::tui::app::Mode::Open {
            items, selected, ..
        } = &app.mode
        else {
            panic!("the picker is open")
        };
        if items[*selected].name(&app.swings) == "evil" {
            key(&mut app, KeyCode::Enter);
            break;
        }
        key(&mut app, KeyCode::Down);
    }
    assert_eq!(app.preset_name, "evil");
    settle(&mut app);
    let shown = screen(&app);
    assert!(clean(&shown), "{shown:?}");
    // The user's park, chosen: its name escaped wherever it shows.
    key(&mut app, KeyCode::Char('M'));
    key(&mut app, KeyCode::Char('5'));
    settle(&mut app);
    let shown = screen(&app);
    assert!(clean(&shown), "{shown:?}");
    assert!(shown.contains("RLO"), "{shown}");
}
