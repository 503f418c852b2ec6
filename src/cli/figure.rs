//! `figure N`: the data behind one of the paper's figures, from
//! [`crate::analysis::figures`], printed as text, CSV or JSON.

use std::fmt::Write as _;
use std::path::Path;

use super::hit::environment_json;
use super::progress::{self, Work};
use super::shown::Shown;
use super::surface::{render_surface, surface_json};
use super::table::{Align, Cell, Column, Digits, Table, Width, trim_lines};
use super::{Format, SceneArgs, UsageError, pretty};
use crate::analysis::figures::shown as units;
use crate::analysis::figures::{self, Figure, FigureData, SurfaceFigure};
use crate::analysis::paper;
use crate::units::Quantity;

pub(super) fn figure(
    number: u32,
    preset: Option<&str>,
    set: &[String],
    dir: Option<&Path>,
    format: Format,
    svg: bool,
    shown: Shown,
) -> Result<String, UsageError> {
    // An unknown figure is reported before any preset error.
    figures::known(number)?;
    let args = SceneArgs {
        preset: preset.unwrap_or(paper::figure_preset(number)).to_owned(),
        set: set.to_vec(),
    };
    let preset = args.resolve(dir, shown.0)?;
    // Figs. 3–4 are the aerodynamic curves; the others need a swing.
    if number >= 5 {
        super::scene::swing_only("figure", &preset)?;
    }
    let what = format!("figure {number}");
    let work = Work {
        what: &what,
        steps: figures::work_steps(number),
    };
    let figure = progress::run(work, |p| {
        figures::figure_data_observed(number, &preset.scene, &preset.name, &|| p.tick())
    })?;
    if svg {
        return figure_svg(figure, &preset.scene, &preset.name, shown);
    }
    let environment = environment_json(&preset.scene);
    // JSON is SI whatever the units shown.
    let shown = if format == Format::Json {
        Shown::default()
    } else {
        shown
    };
    let conditions = units::conditions(&preset.name, &preset.scene, shown.0);
    Ok(match figure {
        Figure::Table(data) => {
            let data = units::converted(data, shown.0);
            render(&FigureData { conditions, ..data }, format, environment)
        }
        Figure::Surface(surface) => render_figure7(
            &SurfaceFigure {
                conditions,
                title: units::title(&surface.title, shown.0),
                ..surface
            },
            format,
            environment,
            shown,
        ),
    })
}

/// `figure N --svg`: the picture in the units shown (its axes, headings,
/// title and conditions; marks and the paper's numbers keep their SI words).
fn figure_svg(
    figure: Figure,
    scene: &crate::Scene,
    name: &str,
    shown: Shown,
) -> Result<String, UsageError> {
    let conditions = units::conditions(name, scene, shown.0);
    Ok(match figure {
        Figure::Table(data) => {
            let now = units::now(&data, scene, shown.0);
            let data = units::converted(data, shown.0);
            crate::picture::table_figure_svg_now(&FigureData { conditions, ..data }, now, name)?
        }
        Figure::Surface(surface) => {
            let surface = SurfaceFigure {
                conditions,
                title: units::title(&surface.title, shown.0),
                ..surface
            };
            crate::picture::surface_svg_in(
                &crate::picture::SurfacePicture::figure7(&surface, scene, name),
                shown.0,
            )?
        }
    })
}

/// Fig. 7: the `surface` command's output, with the optimum O beside the paper's.
fn render_figure7(
    figure: &SurfaceFigure,
    format: Format,
    environment: serde_json::Value,
    shown: Shown,
) -> String {
    let o = &figure.optimum;
    let (undercut, swing_angle, range) = figure.paper;
    match format {
        Format::Csv => render_surface(&figure.surface, format, shown),
        Format::Json => pretty(&serde_json::json!({
            "figure": figure.number,
            "title": figure.title,
            "conditions": figure.conditions,
            "surface": reparsed(&surface_json(&figure.surface)),
            "optimum": if o.landed {
                serde_json::json!({
                    "undercut": o.undercut, "swing_angle": o.swing_angle, "range": o.range,
                    "landed": true,
                })
            } else {
                serde_json::json!({
                    "undercut": null, "swing_angle": null, "range": null, "landed": false,
                })
            },
            "paper": {"undercut": undercut, "swing_angle": swing_angle, "range": range},
            "environment": environment,
        })),
        Format::Text => {
            let mut out = heading(figure.number, &figure.title, &figure.conditions);
            out.push_str(&render_surface(&figure.surface, format, shown));
            let ours = if o.landed {
                format!(
                    "E = {}, ψ = {}, range {}",
                    shown.value(Quantity::Size, o.undercut, 4),
                    shown.value(Quantity::Angle, o.swing_angle, 4),
                    shown.value(Quantity::Distance, o.range, 2)
                )
            } else {
                "none, no swing tried lands".to_owned()
            };
            let _ = writeln!(
                out,
                "optimum O (Nelder–Mead): {ours}; paper: E = {}, ψ = {}, {}",
                shown.value(Quantity::Size, undercut, 4),
                shown.value(Quantity::Angle, swing_angle, 3),
                shown.value(Quantity::Distance, range, 2)
            );
            out
        }
    }
}

/// `value` printed and read back, as Fig. 7 has always embedded the surface:
/// serde_json's default parser may move a number by an ulp, so this keeps
/// those digits (they differ from `surface --json`'s in the last place).
fn reparsed(value: &serde_json::Value) -> serde_json::Value {
    serde_json::from_str(&value.to_string()).expect("our own JSON")
}

fn heading(number: u32, title: &str, conditions: &str) -> String {
    format!("Fig. {number}: {title}\n{conditions}\n")
}

/// A figure's table: a column of numbers is right-aligned, one with labels left.
fn table(data: &FigureData) -> Table {
    let columns = data
        .columns
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let numeric = data.rows.iter().all(|r| !matches!(r[k], Cell::Text(_)));
            // `landed` is for programs: in text a flight that did not land
            // shows no range, and its mark says so.
            let yes_no = data.rows.iter().all(|r| matches!(r[k], Cell::Bool(_)));
            Column {
                key: Some(c.key.clone()),
                head: (!yes_no || data.rows.is_empty()).then(|| c.head.clone()),
                digits: Digits::Fixed(c.decimals),
                align: if numeric { Align::Right } else { Align::Left },
                width: Width::Fit,
                gap: "  ",
            }
        })
        .collect();
    Table {
        columns,
        rows: data.rows.clone(),
    }
}

fn render(data: &FigureData, format: Format, environment: serde_json::Value) -> String {
    let table = table(data);
    match format {
        Format::Json => json(data, &table, environment),
        Format::Csv => table.csv(),
        Format::Text => text(data, table),
    }
}

fn json(data: &FigureData, table: &Table, environment: serde_json::Value) -> String {
    let comparisons: Vec<serde_json::Value> = data
        .comparisons
        .iter()
        .map(|c| {
            serde_json::json!({
                "quantity": c.what, "unit": c.unit, "paper": c.paper, "ours": c.ours,
            })
        })
        .collect();
    pretty(&serde_json::json!({
        "figure": data.number,
        "title": data.title,
        "conditions": data.conditions,
        "columns": data.columns.iter().map(|c| c.key.as_str()).collect::<Vec<_>>(),
        "rows": table.json_rows(),
        "paper": comparisons,
        "notes": data.notes,
        "environment": environment,
    }))
}

fn text(data: &FigureData, mut table: Table) -> String {
    // A number that is not finite shows as a gap.
    for cell in table.rows.iter_mut().flatten() {
        if matches!(cell, Cell::Num(x) if !x.is_finite()) {
            *cell = Cell::Blank;
        }
    }
    let mut out = heading(data.number, &data.title, &data.conditions);
    out.push_str(&table.text());
    if !data.comparisons.is_empty() {
        out.push_str("the paper (for its own conditions, the default preset's) beside ours:\n");
        out.push_str(&comparisons(data).text_rows());
    }
    for note in &data.notes {
        let _ = writeln!(out, "{note}");
    }
    trim_lines(&out)
}

/// The paper's numbers beside ours, one line each.
fn comparisons(data: &FigureData) -> Table {
    let word = |w: &str, gap| Column::text(w, Width::AtLeast(0), Align::Left, gap);
    let number = |width, digits| Column {
        digits,
        ..Column::text("", Width::AtLeast(width), Align::Left, " ")
    };
    Table {
        columns: vec![
            Column::text("", Width::Fit, Align::Left, ""),
            word("", "  "),
            number(8, Digits::Trimmed),
            word("", " "),
            number(10, Digits::Fixed(4)),
            word("", " "),
        ],
        rows: data
            .comparisons
            .iter()
            .map(|c| {
                vec![
                    Cell::Text(format!("  {}", c.what)),
                    Cell::Text("paper".to_owned()),
                    Cell::Num(c.paper),
                    Cell::Text("ours".to_owned()),
                    Cell::Num(c.ours),
                    Cell::Text(c.unit.to_owned()),
                ]
            })
            .collect(),
    }
}
