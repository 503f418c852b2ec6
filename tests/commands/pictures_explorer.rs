//! `x` in the explorer: the pictures of what is on screen, written as fresh
//! SVG files (never over an old one), in the scene's units. (The pictures
//! themselves: pictures.rs.)

use crate::pictures::{lines, texts};
use crate::tui_support;

#[test]
fn explorer_x_writes_fresh_files_and_never_overwrites() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = tui_support::app(80, 24, None);
    app.flush();
    let first = app.export_to(dir.path()).unwrap();
    let second = app.export_to(dir.path()).unwrap();
    assert!(first.ends_with("homerun-trajectory-1.svg"), "{first:?}");
    assert!(second.ends_with("homerun-trajectory-2.svg"), "{second:?}");
    let svg = std::fs::read_to_string(&first).unwrap();
    // The side view and the ground track from above, one vertex a sample.
    let samples = app.path.len();
    assert_eq!(lines(&svg).iter().filter(|&&n| n == samples).count(), 2);
    // Into a folder that is not there: refused with the path, nothing written.
    let gone = dir.path().join("gone");
    let err = app.export_to(&gone).unwrap_err();
    assert!(err.contains("gone"), "{err}");

    // `x` says where it wrote, or why not, in the status line, until the
    // next key; the inputs' message area keeps the key's description.
    let status = |app: &homerun::tui::app::App| {
        let screen = tui_support::screen(app);
        let last = screen
            .lines()
            .last()
            .unwrap()
            .trim_matches('"')
            .trim_end()
            .to_owned();
        (screen, last)
    };
    app.export_in(dir.path());
    let (screen, last) = status(&app);
    assert_eq!(
        last,
        format!(
            "x: wrote {}",
            dir.path().join("homerun-trajectory-3.svg").display()
        ),
        "{screen}"
    );
    assert!(!screen.contains("│x: "), "{screen}");
    app.export_in(&gone);
    let (screen, last) = status(&app);
    assert!(last.starts_with("x: no SVG written: "), "{screen}");
    assert!(last.contains("gone"), "{screen}");
    assert!(
        last.ends_with(&format!("no such folder: {}", gone.display())),
        "{screen}"
    );
    // Three SVGs, nothing else: no temporary left behind.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);
    tui_support::key(&mut app, ratatui::crossterm::event::KeyCode::Char('j'));
    let (screen, last) = status(&app);
    assert!(last.starts_with("swing · readout ✓"), "{screen}");
    // In the batted-ball scene the surface's tab has no chart: the reason,
    // and the key that helps, fit the status line whole at 80 columns.
    use ratatui::crossterm::event::KeyCode;
    tui_support::key(&mut app, KeyCode::Char('b'));
    tui_support::key(&mut app, KeyCode::Char('2'));
    app.export_in(dir.path());
    let (screen, last) = status(&app);
    assert_eq!(
        last, "x: no SVG written: the range surface needs a swing (b switches scenes)",
        "{screen}"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);
}

#[test]
fn explorer_x_on_the_field_writes_both_views_with_every_ground_sample() {
    use ratatui::crossterm::event::KeyCode;
    let dir = tempfile::tempdir().unwrap();
    let mut app = tui_support::app_on("fly-ball", 80, 24, None);
    tui_support::set_and_settle(&mut app, "launch.direction", "-0.35");
    tui_support::key(&mut app, KeyCode::Char('5'));
    let path = app.export_to(dir.path()).unwrap();
    assert!(path.ends_with("homerun-trajectory-1.svg"), "{path:?}");
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(texts(&svg).contains("From above"), "the top view is drawn");
    // The side view's path and the ground track, one vertex per sample.
    let samples = app.ground.len();
    assert!(samples > 20 && samples == app.path.len());
    let drawn = lines(&svg);
    assert_eq!(
        drawn.iter().filter(|&&n| n == samples).count(),
        2,
        "{drawn:?} vs {samples}"
    );
    // The track leaves toward left field.
    assert!(app.ground.last().unwrap().1 < -30.0);
}

#[test]
fn explorer_x_in_an_imperial_scene_draws_in_its_units() {
    use ratatui::crossterm::event::KeyCode;
    let dir = tempfile::tempdir().unwrap();
    let mut app = tui_support::app(80, 24, None);
    app.set_units(homerun::units::UnitSystem::Imperial);
    tui_support::settle(&mut app);
    let svg = |app: &homerun::tui::app::App| {
        let path = app.export_to(dir.path()).unwrap();
        texts(&std::fs::read_to_string(path).unwrap())
    };
    // The trajectory (tab 1): the fastball's 134.70 m is 441.93 ft.
    let trajectory = svg(&app);
    for label in ["y (ft)", "x (ft)", "range 441.93 ft"] {
        assert!(trajectory.contains(label), "{label}: {trajectory}");
    }
    assert!(!trajectory.contains("(m)"), "{trajectory}");
    // The range surface (tab 2): E in inches, ψ in degrees, ranges in ft.
    tui_support::key(&mut app, KeyCode::Char('2'));
    tui_support::settle(&mut app);
    let surface = svg(&app);
    for label in ["undercut E (in)", "swing angle ψ (°)", "range (ft)"] {
        assert!(surface.contains(label), "{label}: {surface}");
    }
    assert!(!surface.contains("(mm)"), "{surface}");
    // The figure (tab 4, Fig. 8): its axes, title and conditions in mph,
    // in, ft (the paper's stated numbers keep their SI words).
    tui_support::key(&mut app, KeyCode::Char('4'));
    tui_support::settle(&mut app);
    let figure = svg(&app);
    for label in ["range (ft)", "(mph)", "bat 67.11 mph"] {
        assert!(figure.contains(label), "{label}: {figure}");
    }
    assert!(
        !figure.contains("range (m)") && !figure.contains("bat 30 m/s"),
        "{figure}"
    );
    // Back in SI, SI again.
    app.set_units(homerun::units::UnitSystem::Si);
    tui_support::settle(&mut app);
    let si = svg(&app);
    assert!(
        si.contains("range (m)") && si.contains("bat 30 m/s"),
        "{si}"
    );
}

/// Issue 36, item 7: `x` writes what is on screen. On the impact tab the
/// impact chart (the paper's Fig. 2: v1 and v3 against p, p_s, p_c and p_f
/// marked), not the trajectory; with a park chosen its wall, from the side
/// where the ball crosses it and from above pole to pole, not the generic
/// fence; each in the units shown.
#[test]
fn explorer_x_writes_the_impact_chart_and_the_chosen_parks_wall() {
    use ratatui::crossterm::event::KeyCode;
    let dir = tempfile::tempdir().unwrap();
    let mut app = tui_support::app(80, 24, None);
    tui_support::settle(&mut app);
    tui_support::key(&mut app, KeyCode::Char('3'));
    let path = app.export_to(dir.path()).unwrap();
    assert!(path.ends_with("homerun-impact-1.svg"), "{path:?}");
    let svg = std::fs::read_to_string(&path).unwrap();
    let text = texts(&svg);
    for label in [
        "v1", "v3", "p_s", "p_c", "p_f", "(m/s)", "p (N·s)", "Fig. 2",
    ] {
        assert!(text.contains(label), "{label}: {text}");
    }
    assert!(!text.contains("Trajectory"), "{text}");
    // v1 and v3, one vertex a sample.
    assert_eq!(lines(&svg).iter().filter(|&&n| n == 401).count(), 2);
    tui_support::key(&mut app, KeyCode::Char('u'));
    let text = texts(&std::fs::read_to_string(app.export_to(dir.path()).unwrap()).unwrap());
    assert!(text.contains("(mph)") && !text.contains("m/s"), "{text}");

    tui_support::key(&mut app, KeyCode::Char('1'));
    tui_support::pick(&mut app, "COL");
    tui_support::settle(&mut app);
    let svg = std::fs::read_to_string(app.export_to(dir.path()).unwrap()).unwrap();
    let text = texts(&svg);
    assert!(
        text.contains("COL's wall where the ball crosses it: ") && text.contains(" ft high"),
        "{text}"
    );
    assert!(!text.contains("fence: 400 ft out"), "{text}");
    // From above, Coors' wall point by point, not the generic arc's 91.
    let wall = app.chosen_park().unwrap().fence.points().len();
    assert_ne!(wall, 91);
    assert!(lines(&svg).contains(&wall), "{:?} vs {wall}", lines(&svg));
}
