//! The SVG pictures: each parses as XML and draws what its data holds (one
//! line per curve with one point per row, one marker per marked point), and
//! `--svg` writes a whole file or none. Cheap: no sweep, no bench run.

use crate::common;

use assert_cmd::Command;
use homerun::Scene;
use homerun::analysis::bench::TrajectoryRow;
use homerun::analysis::figures::{self, Figure, FigureData};
use homerun::analysis::study::{CellOutcome, Grid, Surface};
use homerun::picture::{
    self, FlightPath, SurfacePicture, TrajectoryPicture, bench_svg, table_figure_svg,
};
use homerun::preset::Fence;

/// The number of points of every `<polyline>` with more than two (axes,
/// ticks, legend swatches and the "now" line have two).
pub(crate) fn lines(svg: &str) -> Vec<usize> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses as XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .map(|n| {
            n.attribute("points")
                .unwrap_or("")
                .split_whitespace()
                .count()
        })
        .filter(|&n| n > 2)
        .collect()
}

fn count(svg: &str, tag: &str) -> usize {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses as XML");
    doc.descendants().filter(|n| n.has_tag_name(tag)).count()
}

pub(crate) fn texts(svg: &str) -> String {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses as XML");
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .collect::<Vec<_>>()
        .join("\n")
}

fn table(number: u32, scene: &Scene, preset: &str) -> FigureData {
    match figures::figure_data(number, scene, preset).unwrap() {
        Figure::Table(data) => data,
        Figure::Surface(_) => panic!("figure {number} has a table"),
    }
}

fn marked_rows(data: &FigureData) -> usize {
    let m = data.columns.iter().position(|c| c.key == "mark").unwrap();
    data.rows
        .iter()
        .filter(|r| matches!(&r[m], figures::Cell::Text(t) if !t.is_empty()))
        .count()
}

#[test]
fn figure_4_draws_one_curve_with_every_row_and_its_kink() {
    let scene = Scene::default();
    let data = table(4, &scene, "fastball");
    let svg = table_figure_svg(&data, &scene, "fastball").unwrap();
    assert_eq!(
        lines(&svg),
        vec![data.rows.len()],
        "one curve, a point per row"
    );
    // The kink at S = 0.1 (Eq. 29), and nothing else.
    assert_eq!(marked_rows(&data), 1);
    assert_eq!(count(&svg, "circle"), 1);
    let text = texts(&svg);
    assert!(text.contains("preset fastball"), "{text}");
    assert!(text.contains("C_L") && text.contains("S"), "axes: {text}");
    assert!(text.contains("kink"), "the mark's label: {text}");
}

#[test]
fn figure_5_draws_three_curves_and_each_mark_on_the_curve_it_names() {
    let preset = homerun::preset::load("figure5", None).unwrap();
    let data = table(5, &preset.scene, "figure5");
    let svg = table_figure_svg(&data, &preset.scene, "figure5").unwrap();
    // One curve per μ (0.05, 0.35, 0.5), each with every row.
    assert_eq!(lines(&svg), vec![data.rows.len(); 3]);
    // Each cusp, and 1000 rad/s, names one μ: one circle each.
    assert_eq!(count(&svg, "circle"), marked_rows(&data));
    assert_eq!(marked_rows(&data), 4);
    let text = texts(&svg);
    assert!(
        text.contains("ω_bf (rad/s)") && text.contains("E (m)"),
        "{text}"
    );
    // The paper's stated numbers beside ours.
    assert!(text.contains("paper 0.064"), "{text}");
}

/// Every `<text>`: its x, y, anchor and words.
fn placed_texts(svg: &str) -> Vec<(f64, f64, String, String)> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| {
            let num = |a: &str| n.attribute(a).unwrap_or("0").parse::<f64>().unwrap();
            (
                num("x"),
                num("y"),
                n.attribute("text-anchor").unwrap_or("start").to_owned(),
                n.text().unwrap_or("").trim().to_owned(),
            )
        })
        .collect()
}

#[test]
fn figure_5_notes_stay_off_the_curves_and_now_has_its_line() {
    let preset = homerun::preset::load("figure5", None).unwrap();
    let data = table(5, &preset.scene, "figure5");
    let svg = table_figure_svg(&data, &preset.scene, "figure5").unwrap();
    let height: f64 = roxmltree::Document::parse(&svg)
        .unwrap()
        .root_element()
        .attribute("height")
        .unwrap()
        .parse()
        .unwrap();
    let placed = placed_texts(&svg);
    // The marks' long words are written out under the chart, by number;
    // beside the points only their numbers.
    let red: Vec<String> = roxmltree::Document::parse(&svg)
        .unwrap()
        .descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("fill") == Some("#C80000"))
        .map(|n| n.text().unwrap_or("").trim().to_owned())
        .collect();
    assert_eq!(red, ["1", "2", "3", "4"]);
    let notes: Vec<_> = placed
        .iter()
        .filter(|t| t.3.starts_with("1: cusp") || t.3.starts_with("paper") || t.3.contains("paper"))
        .collect();
    assert!(!notes.is_empty(), "{placed:?}");
    assert!(
        texts(&svg).contains("1: cusp μ = 0.05: slip halts at separation"),
        "{placed:?}"
    );
    // The notes under the chart: one line each, 18 px apart, none past the
    // picture's width (a 13 px character is about 7.5 px) or its foot.
    let mut under: Vec<_> = placed
        .iter()
        .filter(|t| t.0 == 12.0 && t.1 > height - 140.0)
        .collect();
    under.sort_by(|a, b| a.1.total_cmp(&b.1));
    assert!(under.len() >= 5, "{under:?}");
    for pair in under.windows(2) {
        assert!(pair[1].1 - pair[0].1 >= 18.0, "{pair:?}");
    }
    for t in &under {
        assert!(12.0 + 7.6 * t.3.chars().count() as f64 <= 960.0, "{t:?}");
        assert!(t.1 + 14.0 <= height, "{t:?}");
    }
    // "now: E = 0 m" in the legend with its swatch: dashes 2 px wide in the
    // now-line's grey, beside the legend's words.
    let now = placed
        .iter()
        .find(|t| t.3 == "now: E = 0 m")
        .expect("the legend names now with its unit");
    let swatch = roxmltree::Document::parse(&svg)
        .unwrap()
        .descendants()
        .filter(|n| {
            n.has_tag_name("polyline")
                && n.attribute("stroke") == Some("#5A5A5A")
                && n.attribute("stroke-width") == Some("2")
        })
        .filter(|n| {
            let points: Vec<f64> = n
                .attribute("points")
                .unwrap()
                .split([' ', ','])
                .filter(|p| !p.is_empty())
                .map(|p| p.parse().unwrap())
                .collect();
            points[0] < now.0 && now.0 - points[0] < 40.0 && (points[1] - now.1).abs() < 12.0
        })
        .count();
    assert!(swatch >= 2, "the now entry's swatch: {swatch} dashes");
}

#[test]
fn surface_labels_stand_clear_of_the_markers() {
    let grid = Grid {
        undercut: (0.0, 0.04),
        swing_angle: (0.0, 0.4),
        columns: 3,
        rows: 2,
    };
    let surface = Surface::from_outcomes(grid, vec![CellOutcome::Landed(100.0); 6]).unwrap();
    // The current swing and the optimum side by side.
    let picture = SurfacePicture {
        surface: &surface,
        title: "test".into(),
        conditions: String::new(),
        now: Some((0.02, 0.2)),
        optimum: Some((0.021, 0.21, 130.0)),
        paper: None,
        level: None,
    };
    let svg = picture::surface_svg(&picture).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let ring = doc
        .descendants()
        .find(|n| n.has_tag_name("circle"))
        .expect("O's ring");
    let at = |a: &str| ring.attribute(a).unwrap().parse::<f64>().unwrap();
    let (cx, cy) = (at("cx"), at("cy"));
    // Each label's box (12–13 px text, about 7.5 px a character) keeps at
    // least 9 px from both markers, which are within a few pixels of (cx, cy).
    for (x, y, anchor, words) in placed_texts(&svg) {
        if words != "now" && !words.starts_with("O ") {
            continue;
        }
        let width = 7.6 * words.chars().count() as f64;
        let (left, right) = if anchor == "end" {
            (x - width, x)
        } else {
            (x, x + width)
        };
        let (top, bottom) = (y, y + 14.0);
        let dx = (left - cx).max(cx - right).max(0.0);
        let dy = (top - cy).max(cy - bottom).max(0.0);
        assert!(
            dx.max(dy) >= 9.0,
            "{words:?} at ({x}, {y}) crowds ({cx}, {cy})"
        );
    }
}

#[test]
fn a_surface_shows_its_scale_its_gaps_and_its_marks() {
    // 3×2 cells: one where the bat misses, one that does not land.
    let grid = Grid {
        undercut: (0.0, 0.04),
        swing_angle: (0.0, 0.4),
        columns: 3,
        rows: 2,
    };
    let surface = Surface::from_outcomes(
        grid,
        vec![
            CellOutcome::Landed(100.0),
            CellOutcome::Landed(130.0),
            CellOutcome::BatMisses,
            CellOutcome::NotLanded,
            CellOutcome::Landed(120.0),
            CellOutcome::Landed(90.0),
        ],
    )
    .unwrap();
    let picture = SurfacePicture {
        surface: &surface,
        title: "Range over (E, ψ) — preset test".into(),
        conditions: String::new(),
        now: Some((0.02, 0.2)),
        optimum: Some((0.02, 0.0, 130.0)),
        paper: None,
        level: Some(110.0),
    };
    let svg = picture::surface_svg(&picture).unwrap();
    let text = texts(&svg);
    for words in [
        "preset test",
        "does not land",
        "bat misses",
        "O 130.00 m",
        "now",
        "range (m)",
    ] {
        assert!(text.contains(words), "{words:?} in {text}");
    }
    // The background, 6 cells (no two alike side by side), the scale's 32
    // steps and its 2 grey boxes drawn twice (fill and edge).
    assert_eq!(count(&svg, "rect"), 1 + 6 + 32 + 4);
    // The 110 m outline: 100|130 in the first row and 120|90 in the second;
    // a neighbour that was missed or did not land draws none.
    let outline = roxmltree::Document::parse(&svg)
        .unwrap()
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#FFFFFF"))
        .count();
    assert_eq!(outline, 2);
}

#[test]
fn a_trajectory_draws_every_path_point_and_the_fence() {
    let points: Vec<(f64, f64)> = (0..=40)
        .map(|k| {
            let x = f64::from(k) * 3.0;
            (x, 1.0 + x * (120.0 - x) / 130.0)
        })
        .collect();
    let picture = TrajectoryPicture {
        park: None,
        preset: "fastball".into(),
        paths: vec![FlightPath {
            name: "now".into(),
            points: points.clone(),
            ground: Vec::new(),
        }],
        range: Some(120.0),
        apex: 28.69,
        not_landed: None,
        fence: Some(Fence {
            distance: 100.0,
            height: 3.0,
        }),
    };
    let svg = picture::trajectory_svg(&picture).unwrap();
    assert_eq!(lines(&svg), vec![points.len()]);
    let text = texts(&svg);
    assert!(text.contains("range 120.00 m, apex 28.69 m"), "{text}");
    assert!(text.contains("fence: 100 m out"), "{text}");
    assert!(
        text.contains("distance from the plate (m)") && text.contains("y (m)"),
        "{text}"
    );
    // No ground track given: no top view.
    assert!(!text.contains("From above"), "{text}");
}

#[test]
fn a_trajectory_with_a_ground_track_draws_the_field_from_above() {
    // A ball pulled 20° toward left field, curving further: its track, the
    // fence's arc (91 points) and the two foul lines (2 points each, not
    // counted by `lines`).
    let ground: Vec<(f64, f64)> = (0..=30)
        .map(|k| {
            let r = f64::from(k) * 4.0;
            let direction = -0.35 - 0.001 * r;
            (r * direction.cos(), r * direction.sin())
        })
        .collect();
    let side: Vec<(f64, f64)> = ground
        .iter()
        .map(|&(x, z)| (x.hypot(z), 1.0 + x.hypot(z) * (120.0 - x.hypot(z)) / 130.0))
        .collect();
    let picture = TrajectoryPicture {
        park: None,
        preset: "fly-ball".into(),
        paths: vec![FlightPath {
            name: "now".into(),
            points: side.clone(),
            ground: ground.clone(),
        }],
        range: Some(120.0),
        apex: 28.69,
        not_landed: None,
        fence: Some(Fence {
            distance: 100.0,
            height: 3.0,
        }),
    };
    let svg = picture::trajectory_svg(&picture).unwrap();
    let mut drawn = lines(&svg);
    drawn.sort_unstable();
    assert_eq!(drawn, vec![side.len(), ground.len(), 91]);
    let text = texts(&svg);
    assert!(
        text.contains("From above") && text.contains("z (m)"),
        "{text}"
    );
}

fn row(method: &'static str, tolerance: Option<f64>, time_us: f64, error: f64) -> TrajectoryRow {
    TrajectoryRow {
        method,
        tolerance,
        absolute: tolerance,
        step: tolerance.is_none().then_some(0.1),
        stop_at_kinks: true,
        evaluations: 100,
        accepted: 10,
        rejected: 1,
        time_us,
        cpu_us: Some(time_us),
        range_error: error,
    }
}

#[test]
fn the_work_precision_diagram_has_a_line_per_setting_and_a_dot_per_row() {
    let rows = vec![
        row("dopri5", Some(1e-4), 10.0, 1e-2),
        row("dopri5", Some(1e-6), 20.0, -1e-5),
        row("dopri5", Some(1e-8), 40.0, 1e-8),
        row("rk4", None, 30.0, 1e-1),
        row("rk4", None, 60.0, 1e-3),
        row("rk4", None, 120.0, 1e-5),
        // An error of exactly 0 is drawn at the floor, not lost.
        row("rk4", None, 240.0, 0.0),
    ];
    let svg = bench_svg(&rows).unwrap();
    let mut drawn = lines(&svg);
    drawn.sort_unstable();
    assert_eq!(drawn, vec![3, 4]);
    assert_eq!(count(&svg, "circle"), rows.len());
    let text = texts(&svg);
    assert!(
        text.contains("dopri5, atol = rtol, stopping at kinks"),
        "{text}"
    );
    assert!(
        text.contains("rk4, fixed step, stopping at kinks"),
        "{text}"
    );
    assert!(
        text.contains("|range error| (m)") && text.contains("CPU time"),
        "{text}"
    );
}

fn homerun() -> Command {
    common::assert_command()
}

#[test]
fn svg_to_a_missing_folder_is_one_line_exit_2_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("nowhere").join("t.svg");
    let out = homerun()
        .args(["trajectory", "--svg"])
        .arg(&target)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("does not exist") && err.contains("nowhere"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    assert!(!target.exists());
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn svg_writes_the_file_says_so_on_stderr_and_leaves_no_temporary() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("t.svg");
    let out = homerun()
        .args(["trajectory", "--samples", "30", "--svg"])
        .arg(&target)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.trim(), format!("wrote {}", target.display()));
    let svg = std::fs::read_to_string(&target).unwrap();
    // The side view's 30 points, the ground track's 30 and the fence's arc.
    let mut drawn = lines(&svg);
    drawn.sort_unstable();
    assert_eq!(drawn, vec![30, 30, 91]);
    assert!(texts(&svg).contains("range 134.70 m, apex 27.03 m"));
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(names.len(), 1, "no temporary left: {names:?}");
}

/// The SVG `homerun --units imperial ARGS --svg FILE` writes.
fn imperial_svg(args: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("t.svg");
    let out = homerun()
        .args(["--units", "imperial"])
        .args(args)
        .arg("--svg")
        .arg(&target)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    std::fs::read_to_string(&target).unwrap()
}

#[test]
fn svgs_follow_units_imperial_on_every_axis_and_label() {
    let trajectory = texts(&imperial_svg(&["trajectory", "--samples", "30"]));
    for label in [
        "distance from the plate (ft)",
        "y (ft)",
        "x (ft)",
        "z (ft)",
        "range 441.93 ft, apex 88.69 ft",
        "E = 1.04 in, ψ = 9.13°",
    ] {
        assert!(trajectory.contains(label), "{label}: {trajectory}");
    }
    assert!(!trajectory.contains("(m)"), "{trajectory}");
    let figure = texts(&imperial_svg(&["figure", "5"]));
    for label in ["E (in)", "ω_bf (rpm)", "mph"] {
        assert!(figure.contains(label), "{label}: {figure}");
    }
    assert!(!figure.contains("E (m)"), "{figure}");
    // The paper's numbers beside ours in the same units (issue 36): its
    // 0.064 m is 2.5 in; its own words, quoted, as printed.
    let lines = figure.replace('\n', " ");
    assert!(lines.contains("paper 2.5 · ours"), "{figure}");
    assert!(lines.contains("a misprint for \"0.064 m\""), "{figure}");
    let surface = texts(&imperial_svg(&["surface", "--grid", "6x6"]));
    for label in ["undercut E (in)", "swing angle ψ (°)", "range (ft)", " ft"] {
        assert!(surface.contains(label), "{label}: {surface}");
    }
    assert!(
        !surface.contains("(mm)") && !surface.contains("(rad)"),
        "{surface}"
    );
    let park = texts(&imperial_svg(&["parks", "BOS"]));
    for label in [
        "310.0 ft down the left-field line",
        "toward centre field (ft)",
        "wall 37.0 ft high",
    ] {
        assert!(park.contains(label), "{label}: {park}");
    }
    // SI stays the default.
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("t.svg");
    homerun()
        .args(["surface", "--grid", "6x6", "--svg"])
        .arg(&target)
        .assert()
        .success();
    let si = texts(&std::fs::read_to_string(&target).unwrap());
    assert!(
        si.contains("undercut E (m)") && si.contains("range (m)"),
        "{si}"
    );
}
