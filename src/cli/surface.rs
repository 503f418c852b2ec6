//! `surface`: the range over a grid of (E, ψ), as in Fig. 7, within a work
//! budget; also the renderer Fig. 7 shares.

use std::fmt::Write as _;

use super::progress::{self, Work};
use super::shown::Shown;
use super::table::{Cell, Column, Digits, Table};
use super::{Format, UsageError, WindowFault, pretty};
use crate::Scene;
use crate::analysis::optimum::{OptimizerSettings, optimize};
use crate::analysis::precision::Purpose;
use crate::analysis::study::{self, CellOutcome, Grid, Surface, TooMuchWork};
use crate::model::keys::Key;
use crate::picture::{self, SurfacePicture};
use crate::preset::{Preset, cut};
use crate::units::Quantity;

/// The most cells a side of the grid takes: 500×500 cells of an ordinary
/// scene take about 0.5 s on 2 cores.
pub const MAX_GRID: usize = 500;

/// The most integration steps a surface's flights may take together: about
/// 3 s on 2 cores (0.3 µs a step on one). An ordinary cell takes about 12,
/// so every ordinary grid up to 500×500 fits several times over; a scene
/// whose balls hover takes 4 000 to 70 000 a cell, and gets a smaller grid.
pub const SURFACE_FLIGHT_STEPS: u64 = 20_000_000;

/// The window a surface covers unless told: E ∈ [0, 0.05] m, ψ ∈ [−0.6, 1] rad.
const DEFAULT_UNDERCUT: (f64, f64) = (0.0, 0.05);
const DEFAULT_SWING_ANGLE: (f64, f64) = (-0.6, 1.0);

/// Parses "A..B" (a window) for `flag`, inside `key`'s bounds, in the units
/// shown, giving it in SI.
fn parse_window(
    flag: &'static str,
    text: &str,
    key: &'static Key,
    shown: Shown,
) -> Result<(f64, f64), UsageError> {
    let unit = key.unit_in(shown.0);
    let bad = |fault| {
        let (accepted, example) = match (flag, shown.is_si()) {
            ("--undercut", true) => (
                format!("[{}, {}] m", key.bounds.min, key.bounds.max),
                "0..0.05",
            ),
            (_, true) => ("[-π/2, π/2] rad".to_owned(), "-0.6..1.0"),
            ("--undercut", false) => (shown.bounds(key), "0..2"),
            (_, false) => (shown.bounds(key), "-30..60"),
        };
        UsageError::BadWindow {
            flag,
            text: cut(text, 80),
            fault,
            accepted,
            example,
        }
    };
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| bad(WindowFault::NoDots))?;
    let parse = |s: &str| {
        s.trim()
            .parse::<f64>()
            .map_err(|_| bad(WindowFault::NotANumber(cut(s.trim(), 80))))
    };
    let (a, b) = (parse(a)?, parse(b)?);
    if !(a.is_finite() && b.is_finite()) {
        return Err(bad(WindowFault::NotFinite));
    }
    if a >= b {
        return Err(bad(WindowFault::Reversed));
    }
    let (a, b) = if unit.is_identity() {
        (a, b)
    } else {
        (unit.read(a), unit.read(b))
    };
    if a < key.bounds.min || b > key.bounds.max {
        return Err(bad(WindowFault::OutOfRange));
    }
    Ok((a, b))
}

/// Parses the surface's window and "NxM" grid.
pub(super) fn parse_grid(
    undercut: Option<&str>,
    swing_angle: Option<&str>,
    grid: &str,
    shown: Shown,
) -> Result<Grid, UsageError> {
    let window = |flag, text: Option<&str>, name, default: (f64, f64)| match text {
        Some(text) => parse_window(flag, text, Scene::key(name).expect("a known key"), shown),
        None => Ok(default),
    };
    let undercut = window("--undercut", undercut, "bat.undercut", DEFAULT_UNDERCUT)?;
    let swing_angle = window(
        "--swing-angle",
        swing_angle,
        "bat.swing_angle",
        DEFAULT_SWING_ANGLE,
    )?;
    let bad = || UsageError::BadGrid {
        text: cut(grid, 80),
    };
    let (columns, rows) = grid
        .to_ascii_lowercase()
        .split_once('x')
        .map(|(n, m)| (n.trim().parse::<usize>(), m.trim().parse::<usize>()))
        .ok_or_else(bad)?;
    let (columns, rows) = (columns.map_err(|_| bad())?, rows.map_err(|_| bad())?);
    if !(1..=MAX_GRID).contains(&columns) || !(1..=MAX_GRID).contains(&rows) {
        return Err(bad());
    }
    Ok(Grid {
        undercut,
        swing_angle,
        columns,
        rows,
    })
}

/// `surface`'s output, in pieces to be written one after another: its CSV
/// comes in the pieces the chunks of cells wrote as they were flown (in
/// parallel), never copied into one text.
pub(super) fn surface(
    scene: &Scene,
    grid: Grid,
    text: &str,
    format: Format,
    shown: Shown,
) -> Result<Vec<String>, UsageError> {
    if format == Format::Csv {
        let undercuts = undercut_texts(grid, shown);
        let lines = |first: usize, outcomes: &[CellOutcome]| {
            csv_lines(grid, shown, &undercuts, first, outcomes)
        };
        let lines = computed_chunks(scene, grid, text, &lines)?;
        // The pieces moved, not copied (a slice's `concat` clones them: the
        // whole CSV once more, on one thread, after the flights).
        let mut pieces = Vec::with_capacity(1 + lines.len());
        pieces.push(csv_header(shown));
        pieces.extend(lines);
        return Ok(pieces);
    }
    let surface = computed(scene, grid, text)?;
    if format == Format::Json {
        let mut json = surface_json(&surface);
        json["environment"] = super::hit::environment_json(scene);
        return Ok(vec![pretty(&json)]);
    }
    Ok(vec![render_surface(&surface, format, shown)])
}

/// The surface within its work budget, with a progress line.
fn computed(scene: &Scene, grid: Grid, text: &str) -> Result<Surface, UsageError> {
    within_budget(grid, text, |tick| {
        study::surface_within(scene, grid, Purpose::Surface, SURFACE_FLIGHT_STEPS, tick)
    })
}

/// As [`computed`], giving only `each_chunk`'s results, in the cells' order
/// (see [`study::surface_chunks_within`]).
fn computed_chunks<T: Send>(
    scene: &Scene,
    grid: Grid,
    text: &str,
    each_chunk: &(dyn Fn(usize, &[CellOutcome]) -> T + Sync),
) -> Result<Vec<T>, UsageError> {
    within_budget(grid, text, |tick| {
        study::surface_chunks_within(
            scene,
            grid,
            Purpose::Surface,
            SURFACE_FLIGHT_STEPS,
            tick,
            each_chunk,
        )
    })
}

/// `fly(tick)` with a progress line of the grid's cells, on the pool's
/// threads; its giving up as the budget's refusal.
fn within_budget<T>(
    grid: Grid,
    text: &str,
    fly: impl FnOnce(&(dyn Fn() + Sync)) -> Result<T, TooMuchWork>,
) -> Result<T, UsageError> {
    let work = Work {
        what: "surface",
        steps: Some((grid.columns * grid.rows, "cells")),
    };
    progress::run(work, |p| fly(&|| p.tick())).map_err(|work| too_much(text, work))
}

/// `surface --svg`: the heatmap with the optimum, the current swing and, if
/// the preset has a fence, the outline of the cells that reach its distance.
pub(super) fn surface_svg(
    preset: &Preset,
    grid: Grid,
    text: &str,
    shown: Shown,
) -> Result<String, UsageError> {
    let scene = &preset.scene;
    let surface = computed(scene, grid, text)?;
    let o = optimize(scene, OptimizerSettings::default());
    let picture = SurfacePicture {
        surface: &surface,
        title: format!("Range over (E, ψ) — preset {}", preset.name),
        conditions: crate::analysis::figures::shown::conditions(&preset.name, scene, shown.0)
            .split_once(": ")
            .map_or(String::new(), |(_, rest)| rest.to_owned()),
        now: Some((scene.bat.undercut, scene.bat.swing_angle)),
        optimum: o.landed.then_some((o.undercut, o.swing_angle, o.range)),
        paper: None,
        level: preset.fence.map(|f| f.distance),
    };
    Ok(picture::surface_svg_in(&picture, shown.0)?)
}

/// "--grid 500x500: about 2.7e9 integration steps on this scene …"
fn too_much(text: &str, work: TooMuchWork) -> UsageError {
    let per_cell = work.steps_per_cell();
    // Half what the mean says, for the cells it has not seen.
    let cells = (0.5 * SURFACE_FLIGHT_STEPS as f64 / per_cell)
        .floor()
        .max(1.0);
    let side = cells.sqrt().floor().max(1.0);
    UsageError::TooMuchWork {
        flag: "--grid",
        text: text.to_owned(),
        detail: format!(
            "about {:.1e} integration steps on this scene ({per_cell:.0} a flight, where an ordinary one takes ~12), more than the {:.0e} a surface may take (~3 s); accepted here: at most ~{cells} cells, e.g. --grid {side}x{side}",
            per_cell * work.total as f64,
            SURFACE_FLIGHT_STEPS as f64,
        ),
    }
}

/// A range surface as JSON, as CSV (one line per cell) or as a grid of
/// whole metres with ψ growing upward (as in Fig. 7).
pub(super) fn render_surface(surface: &Surface, format: Format, shown: Shown) -> String {
    match format {
        Format::Json => pretty(&surface_json(surface)),
        Format::Csv => surface_csv(surface, shown),
        Format::Text => surface_text(surface, shown),
    }
}

fn axes(surface: &Surface) -> (Vec<f64>, Vec<f64>) {
    let grid = surface.grid;
    (
        (0..grid.columns).map(|i| grid.undercut_at(i)).collect(),
        (0..grid.rows).map(|j| grid.swing_angle_at(j)).collect(),
    )
}

/// Whether a cell's ball lands, as `hit --json` says it: true or false, and
/// null where there is no flight (the bat misses, or the cell was not flown).
fn landed(outcome: CellOutcome) -> Option<bool> {
    match outcome {
        CellOutcome::Landed(_) => Some(true),
        CellOutcome::NotLanded => Some(false),
        CellOutcome::BatMisses | CellOutcome::NotComputed => None,
    }
}

/// The surface's axes, row by row its ranges (null where the ball does not
/// land or the bat misses) and whether each cell's ball lands (null where
/// the bat misses), and its best cell.
pub(super) fn surface_json(surface: &Surface) -> serde_json::Value {
    let (undercuts, swing_angles) = axes(surface);
    let rows = |f: &dyn Fn(CellOutcome) -> serde_json::Value| -> Vec<Vec<serde_json::Value>> {
        surface
            .outcomes()
            .chunks(surface.grid.columns)
            .map(|row| row.iter().map(|&c| f(c)).collect())
            .collect()
    };
    serde_json::json!({
        "undercuts": undercuts,
        "swing_angles": swing_angles,
        "ranges": rows(&|c| serde_json::json!(c.range())),
        "landed": rows(&|c| serde_json::json!(landed(c))),
        "best": surface.best().map(|(i, j, range)| serde_json::json!({
            "undercut": undercuts[i], "swing_angle": swing_angles[j], "range": range,
        })),
    })
}

/// One line per cell: E, ψ, the range (blank where the ball does not land
/// or the bat misses) and whether the ball lands (blank where the bat
/// misses); its header first.
fn surface_csv(surface: &Surface, shown: Shown) -> String {
    use rayon::prelude::*;
    let undercuts = undercut_texts(surface.grid, shown);
    let pieces: Vec<String> = surface
        .outcomes()
        .par_chunks(64)
        .enumerate()
        .map(|(n, outcomes)| csv_lines(surface.grid, shown, &undercuts, 64 * n, outcomes))
        .collect();
    csv_header(shown) + &pieces.concat()
}

/// The surface's CSV header: its keys, in the units shown.
fn csv_header(shown: Shown) -> String {
    let columns = [
        ("undercut", Quantity::Size),
        ("swing_angle", Quantity::Angle),
        ("range", Quantity::Distance),
        ("landed", Quantity::Unchanged),
    ];
    columns
        .map(|(key, quantity)| shown.csv_key(key, quantity))
        .join(",")
        + "\n"
}

/// Each column's E as the CSV prints it, with the comma after it (printed
/// once, not once a cell).
fn undercut_texts(grid: Grid, shown: Shown) -> Vec<String> {
    (0..grid.columns)
        .map(|i| format!("{},", shown.convert(Quantity::Size, grid.undercut_at(i))))
        .collect()
}

/// The CSV lines of cells `first`, `first + 1`, … (row-major), whose
/// outcomes are `outcomes`: written straight into text, a row's ψ printed
/// once (a 64×64 grid is 4096 lines; through a [`Table`], each took a row
/// of cells and three numbers printed).
fn csv_lines(
    grid: Grid,
    shown: Shown,
    undercuts: &[String],
    first: usize,
    outcomes: &[CellOutcome],
) -> String {
    // Room for the lines as they usually are (the longest E, and 48
    // characters for ψ, the range, "false" and the separators): no
    // `realloc` as they are written, and no more memory touched than they
    // take (room for 82 characters a line cost 40 more page faults).
    let longest = undercuts.iter().map(String::len).max().unwrap_or(0);
    let mut text = String::with_capacity(outcomes.len() * (longest + 48));
    // Each piece with its separators: "E," (the column's), "ψ," (the
    // row's), the range, ",true\n".
    let mut row = (usize::MAX, String::new());
    for (k, &outcome) in (first..).zip(outcomes) {
        let (i, j) = (k % grid.columns, k / grid.columns);
        if row.0 != j {
            let swing_angle = shown.convert(Quantity::Angle, grid.swing_angle_at(j));
            row = (j, format!("{swing_angle},"));
        }
        text.push_str(&undercuts[i]);
        text.push_str(&row.1);
        if let Some(range) = outcome.range() {
            let _ = write!(text, "{}", shown.convert(Quantity::Distance, range));
        }
        text.push_str(match landed(outcome) {
            Some(true) => ",true\n",
            Some(false) => ",false\n",
            None => ",\n",
        });
    }
    text
}

fn surface_text(surface: &Surface, shown: Shown) -> String {
    let (undercuts, swing_angles) = axes(surface);
    let best = surface.best();
    // Columns of E in mm (SI) or in (hundredths), rows of ψ in rad or degrees.
    let (psi_decimals, column_head): (usize, &dyn Fn(f64) -> String) = if shown.is_si() {
        (3, &|e: f64| format!("{:.1}", e * 1000.0))
    } else {
        (1, &|e: f64| {
            format!("{:.2}", shown.convert(Quantity::Size, e))
        })
    };
    let mut columns = vec![Column::right("", "ψ \\ E", 7, Digits::Fixed(psi_decimals))];
    columns.extend(undercuts.iter().enumerate().map(|(i, e)| {
        // A cell is five characters ("  71*"); a longer heading ("-400.0")
        // widens its column by a space before it, so headings never touch.
        let head = column_head(*e);
        let width = (head.chars().count() + 1).max(5);
        let column = Column::right("", &head, width, Digits::Shortest);
        column.after(if i == 0 { " " } else { "" })
    }));
    // ψ grows upward, as in Fig. 7.
    let rows = (0..swing_angles.len())
        .rev()
        .map(|j| {
            let mut row = vec![Cell::Num(shown.convert(Quantity::Angle, swing_angles[j]))];
            row.extend((0..undercuts.len()).map(|i| {
                let mark = if best.is_some_and(|b| (b.0, b.1) == (i, j)) {
                    "*"
                } else {
                    " "
                };
                let text = match surface.outcome(i, j) {
                    CellOutcome::Landed(r) => {
                        // Rounded first, so that -0.4 m is 0, not "-0".
                        let r = shown.convert(Quantity::Distance, r).round() + 0.0;
                        return Cell::Text(format!("{r:>4.0}{mark}"));
                    }
                    CellOutcome::NotLanded => "up",
                    CellOutcome::BatMisses => "-",
                    CellOutcome::NotComputed => "?",
                };
                Cell::Text(format!("{text:>4}{mark}"))
            }));
            row
        })
        .collect();
    let mut out = if shown.is_si() {
        String::from(
            "range (m) over undercut E (columns, mm) and swing angle ψ (rows, rad); * best cell, - bat misses\n",
        )
    } else {
        String::from(
            "range (ft) over undercut E (columns, in) and swing angle ψ (rows, °); * best cell, - bat misses\n",
        )
    };
    if surface.any_not_landed() {
        out.insert_str(out.len() - 1, ", up: the ball does not land");
    }
    out.push_str(&Table { columns, rows }.text());
    if let Some((i, j, range)) = best {
        let _ = writeln!(
            out,
            "best cell: E = {}, ψ = {}, range {}",
            shown.value(Quantity::Size, undercuts[i], 4),
            shown.value(Quantity::Angle, swing_angles[j], 4),
            shown.value(Quantity::Distance, range, 2)
        );
    }
    out
}
