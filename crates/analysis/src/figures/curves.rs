//! Which columns of a figure's table are drawn, and how: its panels (the y
//! columns of each), its curves against its x column, and the curve each of
//! the paper's marks sits on. One place for the explorer's braille chart and
//! the SVG picture, so that the two draw the same thing.

use super::{Cell, FigureData};
use model::keys::{KEYS, Key};
use model::scene::Scene;

/// The panels of figure `number`: the prefix of each panel's y columns,
/// the main one first (the explorer draws only that one). Figs. 8–12 get
/// the paper's three panels: the optimal range, E_opt and ψ_opt.
pub fn panels(number: u32) -> &'static [&'static str] {
    match number {
        3 => &["drag_coefficient"],
        4 => &["lift_coefficient"],
        5 => &["launch_spin_mu"],
        6 => &["launch_angle_mu"],
        8..=12 => &["range", "undercut", "swing_angle"],
        14 => &["drag_coefficient"],
        // Fig. 13: range against E.
        _ => &["range"],
    }
}

/// The x column of `data`: the first, but for Fig. 14 (time, one curve per
/// point A, B).
pub fn x_column(data: &FigureData) -> usize {
    let key = if data.number == 14 { "time" } else { "" };
    data.columns.iter().position(|c| c.key == key).unwrap_or(0)
}

/// One curve: its legend, its points in row order, and the row of each.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub rows: Vec<usize>,
}

fn number(row: &[Cell], k: usize) -> Option<f64> {
    match row[k] {
        Cell::Num(v) if v.is_finite() => Some(v),
        _ => None,
    }
}

/// The curves whose y column starts with `prefix`, against the x column;
/// Fig. 14's rows split into one curve per flight (A, B). Rows without both
/// numbers (a flight that did not land) are left out.
pub fn curves(data: &FigureData, prefix: &str) -> Vec<Curve> {
    let x = x_column(data);
    let split = (data.number == 14)
        .then(|| data.columns.iter().position(|c| c.key == "point"))
        .flatten();
    let mut curves: Vec<Curve> = Vec::new();
    for (k, column) in data.columns.iter().enumerate() {
        if k == x || !column.key.starts_with(prefix) {
            continue;
        }
        // The legend: what tells the curves apart (μ = 0.35), else the heading.
        let name = column
            .head
            .rsplit_once(") ")
            .map_or(column.head.clone(), |(_, rest)| rest.to_owned());
        let first = curves.len();
        for (r, row) in data.rows.iter().enumerate() {
            let (Some(px), Some(py)) = (number(row, x), number(row, k)) else {
                continue;
            };
            let label = match split.map(|s| &row[s]) {
                Some(Cell::Text(t)) => format!("{} {t}", axis_title(&column.head)),
                _ => name.clone(),
            };
            match curves[first..].iter_mut().find(|c| c.name == label) {
                Some(curve) => {
                    curve.points.push((px, py));
                    curve.rows.push(r);
                }
                None => curves.push(Curve {
                    name: label,
                    points: vec![(px, py)],
                    rows: vec![r],
                }),
            }
        }
    }
    curves
}

/// A column's heading up to its unit: `ω_bf (rad/s)`.
pub fn axis_title(head: &str) -> String {
    head.find(')')
        .map_or(head.to_owned(), |end| head[..=end].to_owned())
}

/// The heading of the y axis of the panel `prefix`: its first column's,
/// up to the unit.
pub fn y_title(data: &FigureData, prefix: &str) -> String {
    data.columns
        .iter()
        .find(|c| c.key.starts_with(prefix))
        .map_or(String::new(), |c| axis_title(&c.head))
}

/// Whether a mark's words name `curve` ("cusp μ = 0.35" names "μ=0.35" but
/// not "μ=0.3").
pub fn names(mark: &str, curve: &str) -> bool {
    // The columns write "μ=0.35", the marks "μ = 0.35".
    let (mark, curve) = (mark.replace(' ', ""), curve.replace(' ', ""));
    mark.match_indices(&curve).any(|(at, _)| {
        !mark[at + curve.len()..]
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_digit() || c == '.')
    })
}

/// One of the paper's marked points, placed on a curve.
#[derive(Clone, Debug, PartialEq)]
pub struct MarkedPoint {
    pub label: String,
    /// The index of its curve in the `curves` it was placed on.
    pub curve: usize,
    pub point: (f64, f64),
}

/// The marked rows of `data` placed on `curves`: each mark on the curves it
/// names (Fig. 5's "cusp μ = 0.35" on the μ = 0.35 curve), or on every curve
/// if it names none (Fig. 3's kinks, Fig. 13's A and B). A mark whose row
/// has no point on a curve (it did not land) is left off that curve.
pub fn marked_points(data: &FigureData, curves: &[Curve]) -> Vec<MarkedPoint> {
    let Some(m) = data.columns.iter().position(|c| c.key == "mark") else {
        return Vec::new();
    };
    let mut marked = Vec::new();
    for (row, cells) in data.rows.iter().enumerate() {
        let Cell::Text(label) = &cells[m] else {
            continue;
        };
        if label.is_empty() {
            continue;
        }
        let named: Vec<usize> = (0..curves.len())
            .filter(|&k| names(label, &curves[k].name))
            .collect();
        let on = if named.is_empty() {
            (0..curves.len()).collect()
        } else {
            named
        };
        for k in on {
            if let Some(at) = curves[k].rows.iter().position(|&r| r == row) {
                marked.push(MarkedPoint {
                    label: label.clone(),
                    curve: k,
                    point: curves[k].points[at],
                });
            }
        }
    }
    marked
}

/// The input a column sweeps, if it is one (`bat_speed`, `undercut`).
pub fn column_input(column_key: &str) -> Option<&'static Key> {
    KEYS.iter().find(|key| {
        key.name.replace('.', "_") == column_key || key.name.ends_with(&format!(".{column_key}"))
    })
}

/// The current value of the input the x column sweeps, if it is an input.
pub fn current_value(data: &FigureData, scene: &Scene) -> Option<f64> {
    column_input(&data.columns[x_column(data)].key).map(|key| (key.get)(scene))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mark_names_its_curve_and_not_a_prefix_of_it() {
        assert!(names("cusp μ = 0.35: slip halts at separation", "μ=0.35"));
        assert!(!names("cusp μ = 0.35: slip halts at separation", "μ=0.3"));
        assert!(names("1000 rad/s at μ = 0.5", "μ=0.5"));
        assert!(!names("kink", "C_D"));
    }
}
