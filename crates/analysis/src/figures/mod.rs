//! The data behind the paper's Figs. 3–14, computed from a [`Scene`] by the
//! model and the studies: plain typed tables (numeric columns to plot, marks,
//! the paper's stated numbers beside ours), and for Fig. 7 a range surface.
//!
//! UI-free: the command line renders these as text, CSV or JSON, and the
//! explorer can draw them from the same data.

mod aero;
pub mod curves;
mod flight;
mod impact;
mod optimum;
pub mod shown;
pub mod stated;

use crate::optimum::Optimum;
use crate::paper::{FIGURES, Stated};
use crate::study::{self, SweepError};
use model::impact::Collision;
use model::launch::SceneKind;
use model::scene::Scene;

/// One table cell: a number, a label, a yes or no (`landed`), or nothing
/// (null in JSON).
#[derive(Clone, Debug, PartialEq)]
pub enum Cell {
    Num(f64),
    Text(String),
    Bool(bool),
    Blank,
}

/// One column of a figure's table.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// Name in JSON and CSV (a series' name).
    pub key: String,
    /// Heading in the text table, with the unit.
    pub head: String,
    /// Decimals in the text table (JSON and CSV keep every digit).
    pub decimals: usize,
}

/// A number the paper states about the figure, beside ours.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    pub what: String,
    pub unit: &'static str,
    pub paper: f64,
    pub ours: f64,
}

/// A figure as a table: one row per point, the x column first.
#[derive(Clone, Debug, PartialEq)]
pub struct FigureData {
    pub number: u32,
    pub title: String,
    /// The inputs it was computed with, in one line.
    pub conditions: String,
    pub columns: Vec<Column>,
    /// One cell per column.
    pub rows: Vec<Vec<Cell>>,
    pub comparisons: Vec<Comparison>,
    pub notes: Vec<String>,
}

impl FigureData {
    /// A table with no comparisons or notes yet; [`figure_data`] fills in
    /// the conditions.
    fn new(number: u32, title: String, columns: Vec<Column>, rows: Vec<Vec<Cell>>) -> FigureData {
        FigureData {
            number,
            title,
            conditions: String::new(),
            columns,
            rows,
            comparisons: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// The column named `key` as numbers (`None` for a label or a blank), to
    /// plot; `None` if there is no such column.
    pub fn series(&self, key: &str) -> Option<Vec<Option<f64>>> {
        let k = self.columns.iter().position(|c| c.key == key)?;
        Some(
            self.rows
                .iter()
                .map(|row| match row[k] {
                    Cell::Num(x) => Some(x),
                    _ => None,
                })
                .collect(),
        )
    }
}

/// Fig. 7: the range over a grid of (E, ψ), with the optimiser's optimum O.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceFigure {
    pub number: u32,
    pub title: String,
    pub conditions: String,
    pub surface: study::Surface,
    /// Point O, found by the optimiser.
    pub optimum: Optimum,
    /// Point O as the paper gives it: E (m), ψ (rad), range (m).
    pub paper: (f64, f64, f64),
}

/// One of the paper's figures.
#[derive(Clone, Debug, PartialEq)]
pub enum Figure {
    Table(FigureData),
    Surface(SurfaceFigure),
}

/// Why a figure could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FigureError {
    #[error("figure {number}: no such figure; accepted 3 to 14: {}", figure_list())]
    NoSuchFigure { number: u32 },
    #[error(transparent)]
    Sweep(#[from] SweepError),
}

/// "3 C_D against Re, 4 C_L against S, …": every figure we compute.
pub fn figure_list() -> String {
    let list: Vec<String> = FIGURES
        .iter()
        .map(|(n, what)| format!("{n} {what}"))
        .collect();
    list.join(", ")
}

/// Whether the paper has figure `number` among those we compute.
pub fn known(number: u32) -> Result<(), FigureError> {
    if FIGURES.iter().any(|(n, _)| *n == number) {
        Ok(())
    } else {
        Err(FigureError::NoSuchFigure { number })
    }
}

/// The data of figure `number` for `scene` (loaded from the preset `preset_name`).
pub fn figure_data(number: u32, scene: &Scene, preset_name: &str) -> Result<Figure, FigureError> {
    figure_data_observed(number, scene, preset_name, &|| {})
}

/// The steps of work [`figure_data_observed`] reports for figure `number`,
/// and what they are: its sweep's points (Figs. 8–12) or its surface's
/// cells (Fig. 7); `None` for the figures whose work is not counted.
pub fn work_steps(number: u32) -> Option<(usize, &'static str)> {
    match number {
        7 => Some((optimum::FIGURE7_GRID.0 * optimum::FIGURE7_GRID.1, "cells")),
        8..=12 => Some((optimum::SWEEP_POINTS, "points")),
        _ => None,
    }
}

/// As [`figure_data`], calling `tick` after each step of [`work_steps`].
pub fn figure_data_observed(
    number: u32,
    scene: &Scene,
    preset_name: &str,
    tick: &(dyn Fn() + Sync),
) -> Result<Figure, FigureError> {
    known(number)?;
    let conditions = conditions(preset_name, scene);
    let data = match number {
        3 => aero::figure3(scene),
        4 => aero::figure4(scene),
        5 | 6 => impact::impact_figure(number, scene),
        7 => {
            return Ok(Figure::Surface(SurfaceFigure {
                conditions,
                ..optimum::figure7(scene, tick)
            }));
        }
        8..=12 => optimum::sweep_figure(number, scene, tick)?,
        13 => flight::figure13(scene),
        _ => flight::figure14(scene),
    };
    Ok(Figure::Table(FigureData { conditions, ..data }))
}

/// The inputs a figure was computed with, in one line.
pub fn conditions(name: &str, s: &Scene) -> String {
    // A batted ball has no pitch or bat: its launch is what it was flown with.
    if s.kind == SceneKind::BattedBall {
        let launch = s.batted_ball();
        return format!(
            "preset {name}: launch {} m/s, {} rad, spin {} rad/s; wind {} m/s; ρ {} kg/m³; drag {}, lift {}",
            trimmed(launch.speed),
            trimmed(launch.angle),
            trimmed(launch.spin),
            trimmed(s.environment.wind),
            trimmed(s.environment.air_density),
            s.drag,
            s.lift
        );
    }
    format!(
        "preset {name}: pitch {} m/s, spin {} rad/s; bat {} m/s, roll {} rad/s, E {} m, ψ {} rad, μ {}; wind {} m/s; ρ {} kg/m³; drag {}, lift {}",
        trimmed(s.pitch.speed),
        trimmed(s.pitch.spin),
        trimmed(s.bat.speed),
        trimmed(s.bat.spin),
        trimmed(s.bat.undercut),
        trimmed(s.bat.swing_angle),
        trimmed(s.bat.friction),
        trimmed(s.environment.wind),
        trimmed(s.environment.air_density),
        s.drag,
        s.lift
    )
}

/// A value to three decimals, without trailing zeros nor a "-0": "1.5",
/// "223.694", "0".
pub fn short(value: f64) -> String {
    let text = format!("{value:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}

/// A value to six decimals, without trailing zeros.
pub fn trimmed(value: f64) -> String {
    let text = format!("{value:.6}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

fn column(key: &str, head: &str, decimals: usize) -> Column {
    Column {
        key: key.to_owned(),
        head: head.to_owned(),
        decimals,
    }
}

/// Columns from (key, heading, decimals).
fn columns(specs: &[(&str, &str, usize)]) -> Vec<Column> {
    specs
        .iter()
        .map(|&(key, head, decimals)| column(key, head, decimals))
        .collect()
}

/// The launch's columns: V_bf, ω_bf, ζ.
const LAUNCH: [(&str, &str, usize); 3] = [
    ("launch_speed", "V_bf (m/s)", 2),
    ("launch_spin", "ω_bf (rad/s)", 1),
    ("launch_angle", "ζ (rad)", 4),
];

/// The column of labels on marked points.
const MARK: (&str, &str, usize) = ("mark", "", 0);

/// A row: the numbers, then the mark.
fn marked_row(numbers: &[f64], mark: &str) -> Vec<Cell> {
    let mut row: Vec<Cell> = numbers.iter().copied().map(Cell::Num).collect();
    row.push(mark_cell(mark));
    row
}

/// The row of a flight: its numbers with those in `unknown` (the range, or
/// the whole optimum) left blank if it did not land, then `landed`, then the
/// mark.
fn flight_row(
    numbers: &[f64],
    unknown: std::ops::Range<usize>,
    landed: bool,
    mark: &str,
) -> Vec<Cell> {
    let mut row = marked_row(numbers, mark);
    if !landed {
        row[unknown].fill(Cell::Blank);
    }
    row.insert(numbers.len(), Cell::Bool(landed));
    row
}

/// The column saying whether a row's flight landed (JSON and CSV).
const LANDED: (&str, &str, usize) = ("landed", "landed", 0);

/// The paper's `stated` number beside `ours`.
fn compare(stated: Stated, ours: f64) -> Comparison {
    Comparison {
        what: stated.what.to_owned(),
        unit: stated.unit,
        paper: stated.value,
        ours,
    }
}

fn mark_cell(label: &str) -> Cell {
    if label.is_empty() {
        Cell::Blank
    } else {
        Cell::Text(label.to_owned())
    }
}

/// Where `f` changes value in [lo, hi], to well below a micrometre in E;
/// `None` if it has the same value at both ends.
fn bisect(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> bool) -> Option<f64> {
    let at_lo = f(lo);
    if at_lo == f(hi) {
        return None;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if f(mid) == at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The grid `base` with the marked points added, sorted; a mark that falls
/// on a grid point labels it.
fn with_marks(base: Vec<f64>, marks: Vec<(f64, String)>) -> Vec<(f64, String)> {
    let mut all: Vec<(f64, String)> = base.into_iter().map(|x| (x, String::new())).collect();
    for (x, label) in marks {
        match all
            .iter_mut()
            .find(|(y, _)| (x - *y).abs() <= 1e-9 * x.abs().max(1e-6))
        {
            Some((_, existing)) if existing.is_empty() => *existing = label,
            Some((_, existing)) => *existing = format!("{existing}; {label}"),
            None => all.push((x, label)),
        }
    }
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    all
}

/// The impact of `scene` with its undercut set to `undercut` and μ to `friction`.
fn impact_with(scene: &Scene, undercut: f64, friction: f64) -> Collision {
    let mut s = scene.with_swing(undercut, scene.bat.swing_angle);
    s.bat.friction = friction;
    Collision::new(&s)
}

/// The undercut in [0, `top`] (and short of the bat's reach) at which the
/// batted spin at μ = `friction` crosses `spin`, if it does so continuously.
fn undercut_for_spin(
    scene: &Scene,
    top: f64,
    friction: f64,
    spin: f64,
    within: f64,
) -> Option<f64> {
    let spin_at = |e| impact_with(scene, e, friction).launch_spin();
    bisect(0.0, top, |e| spin_at(e) > spin)
        // A jump across the spin is not a crossing.
        .filter(|&e| (spin_at(e) - spin).abs() < within)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_reads_a_column() {
        let Figure::Table(data) = figure_data(4, &Scene::default(), "fastball").unwrap() else {
            panic!("Fig. 4 is a table");
        };
        let s = data.series("spin_parameter").unwrap();
        assert_eq!(s.len(), data.rows.len());
        assert!(s.iter().all(Option::is_some));
        assert!(data.series("mark").unwrap().iter().any(Option::is_none));
        assert!(data.series("nothing").is_none());
        assert!(matches!(
            figure_data(2, &Scene::default(), "fastball"),
            Err(FigureError::NoSuchFigure { number: 2 })
        ));
    }
}
