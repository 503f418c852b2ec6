//! `parks`: the parks (bundled and the user's), or one park's fence every
//! 5° and at each change of height, as text, JSON or an SVG outline.

use std::fmt::Write as _;

use serde_json::{Value, json};

use super::shown::Shown;
use super::table::{Align, Cell, Column, Digits, Table, Width};
use super::{UsageError, pretty};
use crate::model::park::{FOUL_LINE, Fence, FencePoint, Named, Park};
use crate::preset::parks::Parks;
use crate::preset::{escape_cut, escape_for_terminal, shown as shown_path};
use crate::units::Quantity;

/// Degrees between the rows of a park's profile.
const STEP_DEGREES: i32 = 5;

/// `homerun parks [--json]`: one line per park.
pub(super) fn list(parks: &Parks, json: bool, shown: Shown) -> String {
    if json {
        return pretty(&Value::Array(parks.parks.iter().map(park_json).collect()));
    }
    let distance = |head: &str| {
        Column::right(
            head,
            &shown.head(head, Quantity::Distance, "m"),
            7,
            Digits::Fixed(1),
        )
    };
    let columns = vec![
        Column::text("code", Width::Fit, Align::Left, ""),
        Column::text("name", Width::Fit, Align::Left, "  "),
        Column::right(
            "elevation",
            &shown.head("elevation", Quantity::Distance, "m"),
            9,
            Digits::Fixed(0),
        )
        .after("  "),
        distance("LF").after("  "),
        distance("CF"),
        distance("RF"),
        Column::right(
            "wall",
            &shown.head("tallest wall", Quantity::Distance, "m"),
            8,
            Digits::Fixed(1),
        )
        .after("  "),
    ];
    let rows = parks
        .parks
        .iter()
        .map(|p| {
            let [l, c, r] = p.fence.lines_and_center();
            let d = |si| Cell::Num(shown.convert(Quantity::Distance, si));
            vec![
                Cell::Text(escape_for_terminal(&p.code)),
                Cell::Text(escape_cut(&p.name, 40)),
                d(p.elevation),
                d(l.distance),
                d(c.distance),
                d(r.distance),
                d(p.fence.tallest()),
            ]
        })
        .collect();
    let mut out = Table { columns, rows }.text();
    let yours: Vec<String> = parks
        .parks
        .iter()
        .zip(&parks.files)
        .filter_map(|(p, file)| {
            file.as_ref()
                .map(|f| format!("{} from {}", escape_for_terminal(&p.code), shown_path(f)))
        })
        .collect();
    if !yours.is_empty() {
        let _ = writeln!(out, "\nYours: {}", yours.join("; "));
    }
    out
}

/// `homerun parks CODE [--json]`: the park's fence.
pub(super) fn profile(park: &Park, json: bool, shown: Shown) -> String {
    if json {
        return pretty(&park_json(park));
    }
    let d = |si| shown.value(Quantity::Distance, si, 1);
    let mut out = format!(
        "{} {}\nelevation {}; centre field bears {:.1}° (clockwise from true north)\n",
        escape_for_terminal(&park.code),
        escape_cut(&park.name, 80),
        d(park.elevation),
        park.center_field_bearing
    );
    if !park.aliases.is_empty() {
        let _ = writeln!(
            out,
            "also named {}",
            escape_cut(&park.aliases.join(", "), 80)
        );
    }
    if !park.home.is_empty() {
        let _ = writeln!(
            out,
            "home of {} {} (a batch row dated otherwise is at no park)",
            escape_for_terminal(&park.code),
            model::park::spans_text(&park.home)
        );
    }
    if !park.walls.is_empty() && park.walls != park.home {
        let otherwise = match park.earlier.is_empty() {
            true => "is at no park",
            false => "is judged at its walls then, below, or else at no park",
        };
        let _ = writeln!(
            out,
            "its walls as given stood {} (a batch row at {} dated otherwise {otherwise})",
            model::park::spans_text(&park.walls),
            escape_for_terminal(&park.code),
        );
    }
    if let Some(p) = park.published {
        let _ = writeln!(
            out,
            "published: left-field line {}, centre {}, right-field line {}",
            d(p.left_line),
            d(p.center),
            d(p.right_line)
        );
    }
    let columns = vec![
        Column::right("direction", "direction (°)", 13, Digits::Fixed(1)),
        Column::right(
            "distance",
            &shown.head("distance", Quantity::Distance, "m"),
            13,
            Digits::Fixed(shown.unit(Quantity::Distance).decimals(2)),
        )
        .after("  "),
        Column::right(
            "height",
            &shown.head("height", Quantity::Distance, "m"),
            11,
            Digits::Fixed(shown.unit(Quantity::Distance).decimals(2)),
        )
        .after("  "),
    ];
    let table = |fence: &Fence| {
        let rows = (profile_points(fence).into_iter())
            .map(|p| {
                vec![
                    Cell::Num(p.direction.to_degrees()),
                    Cell::Num(shown.convert(Quantity::Distance, p.distance)),
                    Cell::Num(shown.convert(Quantity::Distance, p.height)),
                ]
            })
            .collect();
        let columns = columns.clone();
        Table { columns, rows }.text()
    };
    out.push('\n');
    out += &table(&park.fence);
    for earlier in &park.earlier {
        let _ = writeln!(
            out,
            "\nits walls {} (a batch row at {} then is judged at them):\n",
            model::park::spans_text(&earlier.walls),
            escape_for_terminal(&park.code),
        );
        out += &table(&earlier.fence);
    }
    out
}

/// The fence every 5° from the left-field line to the right-field line,
/// and both sides of each change of height.
fn profile_points(fence: &Fence) -> Vec<FencePoint> {
    let n = 90 / STEP_DEGREES;
    let mut points: Vec<FencePoint> = (0..=n)
        .map(|k| {
            let direction = f64::from(k * STEP_DEGREES).to_radians() - FOUL_LINE;
            let at = fence.at(direction.clamp(-FOUL_LINE, FOUL_LINE));
            let at = at.expect("within the foul lines");
            FencePoint {
                direction,
                distance: at.distance,
                height: at.height,
            }
        })
        .collect();
    for pair in fence.points().windows(2) {
        if pair[0].direction == pair[1].direction && pair[0].height != pair[1].height {
            points.retain(|p| (p.direction - pair[0].direction).abs() > 1e-9);
            points.extend_from_slice(pair);
        }
    }
    points.sort_by(|a, b| a.direction.total_cmp(&b.direction));
    points
}

/// A park in JSON, SI: `code`, `aliases`, `name`, `elevation` (m),
/// `center_field_bearing` (° from true north), `published` (m, or null),
/// `home` (its spans as a park file writes them, "1998..2024"), `walls`
/// (when its fence stood, the same way), `fence`, its points as
/// `{direction (rad), distance (m), height (m)}`, and `earlier`, its other
/// walls: `{walls, fence}` each.
pub(super) fn park_json(park: &Park) -> Value {
    json!({
        "code": park.code,
        "aliases": park.aliases,
        "name": park.name,
        "elevation": park.elevation,
        "center_field_bearing": park.center_field_bearing,
        "published": park.published,
        "home": park.home.iter().map(model::park::HomeSpan::as_written).collect::<Vec<_>>(),
        "walls": park.walls.iter().map(model::park::HomeSpan::as_written).collect::<Vec<_>>(),
        "fence": park.fence.points(),
        "earlier": (park.earlier.iter()).map(|earlier| json!({
            "walls": earlier.walls.iter().map(model::park::HomeSpan::as_written).collect::<Vec<_>>(),
            "fence": earlier.fence.points(),
        })).collect::<Vec<_>>(),
    })
}

/// `parks CODE` for a code no park answers to: one line naming the code
/// and every code accepted.
/// The park `query` names (`BOS`, `fenway`, `"Fenway Park"`, `boston`, any
/// case), or one line saying there is none, or which several it names.
pub(super) fn lookup<'p>(query: &str, parks: &'p Parks) -> Result<&'p Park, UsageError> {
    match parks.named(query) {
        Named::One(park) => Ok(park),
        Named::None => Err(unknown(query, parks)),
        Named::Several(several) => Err(UsageError::AmbiguousPark {
            query: escape_cut(query, 40),
            candidates: several
                .iter()
                .map(|p| {
                    let city = if p.city.is_empty() {
                        String::new()
                    } else {
                        format!(", {}", escape_cut(&p.city, 40))
                    };
                    format!(
                        "{} ({}{city})",
                        escape_for_terminal(&p.code),
                        escape_cut(&p.name, 40)
                    )
                })
                .collect::<Vec<_>>()
                .join(", "),
        }),
    }
}

pub(super) fn unknown(code: &str, parks: &Parks) -> UsageError {
    UsageError::UnknownPark {
        code: escape_cut(code, 20),
        accepted: parks.codes(),
    }
}
