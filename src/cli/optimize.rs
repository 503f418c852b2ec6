//! The optimum: `optimize` (one scene), `sweep` (against one input) and
//! `surface` (the range over a grid of (E, ψ), as in Fig. 7).

use std::fmt::Write as _;

use super::hit::{labelled, launch_text};
use super::table::{Align, Cell, Column, Digits, Table, Width};
use super::{Format, UsageError, WindowFault, pretty};
use crate::Scene;
use crate::analysis::optimum::OptimizerSettings;
use crate::analysis::paper::{Best, best_swing};
use crate::analysis::precision::Purpose;
use crate::analysis::study::{self, Grid, Surface};

/// The largest sweep (points) and grid side (cells) accepted.
pub const MAX_STEPS: usize = 1000;
pub const MAX_GRID: usize = 500;

pub(super) fn optimum(scene: &Scene, json: bool) -> String {
    let Best { optimum, swing } = best_swing(scene);
    let impact = &swing.impact;
    if json {
        return pretty(&serde_json::json!({
            "undercut": optimum.undercut,
            "swing_angle": optimum.swing_angle,
            "range": swing.flight.range,
            "launch_speed": impact.launch_speed(),
            "launch_spin": impact.launch_spin(),
            "launch_angle": impact.launch_angle(),
            "evaluations": optimum.evaluations,
            "converged": optimum.converged,
        }));
    }
    let search = if optimum.converged {
        "converged (Nelder–Mead, tolerances 1e-4)"
    } else {
        "NOT converged: stopped at the evaluation limit"
    };
    labelled(&[
        (
            "optimum",
            format!(
                "E = {:.6} m, ψ = {:.5} rad ({:.2}°)",
                optimum.undercut,
                optimum.swing_angle,
                optimum.swing_angle.to_degrees()
            ),
        ),
        (
            "range",
            format!(
                "{:.4} m in {:.3} s",
                swing.flight.range, swing.flight.flight_time
            ),
        ),
        ("launch", launch_text(impact)),
        (
            "search",
            format!("{} range evaluations, {search}", optimum.evaluations),
        ),
    ])
}

pub(super) fn sweep(
    scene: &Scene,
    key: &str,
    (from, to, steps): (f64, f64, usize),
    format: Format,
) -> Result<String, UsageError> {
    if !(1..=MAX_STEPS).contains(&steps) {
        return Err(UsageError::BadSteps { steps });
    }
    let values = study::linspace(from, to, steps);
    let points = study::sweep(scene, key, &values, OptimizerSettings::default())?;
    let unit = Scene::key(key).map(|k| k.unit).unwrap_or("");
    if format == Format::Json {
        return Ok(pretty(&serde_json::json!({
            "key": key,
            "unit": unit,
            "points": points,
        })));
    }
    let label = if unit.is_empty() {
        key.to_owned()
    } else {
        format!("{key} ({unit})")
    };
    let table = Table {
        columns: vec![
            Column::right(key, &label, 24, Digits::Trimmed),
            Column::right("undercut", "E_opt (m)", 10, Digits::Fixed(5)),
            Column::right("swing_angle", "ψ_opt", 8, Digits::Fixed(4)),
            Column::right("range", "range (m)", 10, Digits::Fixed(3)),
            Column::right("launch_speed", "V_bf m/s", 9, Digits::Fixed(3)),
            Column::right("launch_spin", "ω_bf r/s", 9, Digits::Fixed(2)),
            Column::right("launch_angle", "ζ rad", 8, Digits::Fixed(4)),
            Column::data("evaluations"),
            Column::data("converged"),
            Column::text("", Width::AtLeast(0), Align::Left, ""),
        ],
        rows: points
            .iter()
            .map(|p| {
                let mut row: Vec<Cell> = [
                    p.value,
                    p.undercut,
                    p.swing_angle,
                    p.range,
                    p.launch_speed,
                    p.launch_spin,
                    p.launch_angle,
                    f64::from(p.evaluations),
                ]
                .map(Cell::Num)
                .to_vec();
                row.push(Cell::Text(p.converged.to_string()));
                row.push(if p.converged {
                    Cell::Blank
                } else {
                    Cell::Text("  (not converged)".to_owned())
                });
                row
            })
            .collect(),
    };
    Ok(if format == Format::Csv {
        table.csv()
    } else {
        table.text()
    })
}

/// Parses "A..B" (a window) for `flag`, inside `bounds`.
fn parse_window(
    flag: &'static str,
    text: &str,
    bounds: (f64, f64),
) -> Result<(f64, f64), UsageError> {
    let bad = |fault| {
        let (accepted, example) = if flag == "--undercut" {
            (format!("[{}, {}] m", bounds.0, bounds.1), "0..0.05")
        } else {
            ("[-π/2, π/2] rad".to_owned(), "-0.6..1.0")
        };
        UsageError::BadWindow {
            flag,
            text: text.to_owned(),
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
            .map_err(|_| bad(WindowFault::NotANumber(s.trim().to_owned())))
    };
    let (a, b) = (parse(a)?, parse(b)?);
    if !(a.is_finite() && b.is_finite()) {
        return Err(bad(WindowFault::NotFinite));
    }
    if a >= b {
        return Err(bad(WindowFault::Reversed));
    }
    if a < bounds.0 || b > bounds.1 {
        return Err(bad(WindowFault::OutOfRange));
    }
    Ok((a, b))
}

/// Parses the surface's window and "NxM" grid.
pub(super) fn parse_grid(
    undercut: &str,
    swing_angle: &str,
    grid: &str,
) -> Result<Grid, UsageError> {
    let key_bounds = |name| {
        let key = Scene::key(name).expect("a known key");
        (key.bounds.min, key.bounds.max)
    };
    let undercut = parse_window("--undercut", undercut, key_bounds("bat.undercut"))?;
    let swing_angle = parse_window("--swing-angle", swing_angle, key_bounds("bat.swing_angle"))?;
    let bad = || UsageError::BadGrid {
        text: grid.to_owned(),
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

pub(super) fn surface(scene: &Scene, grid: Grid, format: Format) -> String {
    render_surface(&study::surface(scene, grid, Purpose::Surface), format)
}

/// A range surface as JSON, as CSV (one line per cell) or as a grid of
/// whole metres with ψ growing upward (as in Fig. 7).
pub(super) fn render_surface(surface: &Surface, format: Format) -> String {
    match format {
        Format::Json => pretty(&surface_json(surface)),
        Format::Csv => surface_cells(surface).csv(),
        Format::Text => surface_text(surface),
    }
}

fn axes(surface: &Surface) -> (Vec<f64>, Vec<f64>) {
    let grid = surface.grid;
    (
        (0..grid.columns).map(|i| grid.undercut_at(i)).collect(),
        (0..grid.rows).map(|j| grid.swing_angle_at(j)).collect(),
    )
}

/// The surface's axes, its ranges row by row (null where the bat misses) and its best cell.
pub(super) fn surface_json(surface: &Surface) -> serde_json::Value {
    let (undercuts, swing_angles) = axes(surface);
    let rows: Vec<&[Option<f64>]> = surface.ranges.chunks(surface.grid.columns).collect();
    serde_json::json!({
        "undercuts": undercuts,
        "swing_angles": swing_angles,
        "ranges": rows,
        "best": surface.best().map(|(i, j, range)| serde_json::json!({
            "undercut": undercuts[i], "swing_angle": swing_angles[j], "range": range,
        })),
    })
}

/// One row per cell: E, ψ and the range (blank where the bat misses).
fn surface_cells(surface: &Surface) -> Table {
    let (undercuts, swing_angles) = axes(surface);
    let mut rows = Vec::new();
    for (j, psi) in swing_angles.iter().enumerate() {
        for (i, e) in undercuts.iter().enumerate() {
            let range = surface.get(i, j).map_or(Cell::Blank, Cell::Num);
            rows.push(vec![Cell::Num(*e), Cell::Num(*psi), range]);
        }
    }
    Table {
        columns: ["undercut", "swing_angle", "range"]
            .map(Column::data)
            .to_vec(),
        rows,
    }
}

fn surface_text(surface: &Surface) -> String {
    let (undercuts, swing_angles) = axes(surface);
    let best = surface.best();
    let mut columns = vec![Column::right("", "ψ \\ E", 7, Digits::Fixed(3))];
    columns.extend(undercuts.iter().enumerate().map(|(i, e)| {
        let column = Column::right("", &format!("{:.1}", e * 1000.0), 5, Digits::Shortest);
        column.after(if i == 0 { " " } else { "" })
    }));
    // ψ grows upward, as in Fig. 7.
    let rows = (0..swing_angles.len())
        .rev()
        .map(|j| {
            let mut row = vec![Cell::Num(swing_angles[j])];
            row.extend((0..undercuts.len()).map(|i| {
                let mark = if best.is_some_and(|b| (b.0, b.1) == (i, j)) {
                    "*"
                } else {
                    " "
                };
                Cell::Text(match surface.get(i, j) {
                    Some(r) => format!("{r:>4.0}{mark}"),
                    None => format!("{:>4}{mark}", "-"),
                })
            }));
            row
        })
        .collect();
    let mut out = String::from(
        "range (m) over undercut E (columns, mm) and swing angle ψ (rows, rad); * best cell, - bat misses\n",
    );
    out.push_str(&Table { columns, rows }.text());
    if let Some((i, j, range)) = best {
        let _ = writeln!(
            out,
            "best cell: E = {:.4} m, ψ = {:.4} rad, range {:.2} m",
            undercuts[i], swing_angles[j], range
        );
    }
    out
}
