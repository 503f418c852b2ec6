//! A batch's header and rows: which column gives which input (the keys,
//! or Statcast's own names in mph, degrees and rpm), and each row made a
//! scene to fly, or the reason it cannot be one.

use super::super::fly::fence_of;
use crate::Scene;
use crate::model::aero::UnknownModel;
use crate::model::keys::{DRAG_KEY, InputBatch, InputError, TEXT_KEYS};
use crate::model::scene::UnknownHand;
use crate::preset::{FIELD_KEYS, Fence, Preset, cut, escape_cut};
use crate::units::{Quantity, UnitSystem};

use super::records::*;

/// How a column's values become a launch value in SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Unit {
    Si,
    /// Statcast's `launch_speed`: mph, exactly 0.44704 m/s.
    Mph,
    /// Statcast's `launch_angle`: degrees.
    Degrees,
    /// `spin_rpm`: revolutions per minute, 2π/60 rad/s.
    Rpm,
}

impl Unit {
    /// The explorer's and `--units`' conversion, so that 103 mph is the
    /// same launch to the last bit wherever it is typed.
    pub(super) fn to_si(self, value: f64) -> f64 {
        let quantity = match self {
            Unit::Si => return value,
            Unit::Mph => Quantity::Speed,
            Unit::Degrees => Quantity::Angle,
            Unit::Rpm => Quantity::Spin,
        };
        quantity.unit(UnitSystem::Imperial, "").read(value)
    }

    pub(super) fn name(self) -> &'static str {
        match self {
            Unit::Si => "",
            Unit::Mph => "mph",
            Unit::Degrees => "°",
            Unit::Rpm => "rpm",
        }
    }
}

/// The launch keys and the other names their columns may have, with units.
pub(super) const LAUNCH_COLUMNS: [(&str, &[(&str, Unit)]); 3] = [
    (
        "launch.speed",
        &[("launch.speed", Unit::Si), ("launch_speed", Unit::Mph)],
    ),
    (
        "launch.angle",
        &[("launch.angle", Unit::Si), ("launch_angle", Unit::Degrees)],
    ),
    (
        "launch.spin",
        &[("launch.spin", Unit::Si), ("spin_rpm", Unit::Rpm)],
    ),
];

/// `fly --batch`'s long help: the columns read, made from
/// [`LAUNCH_COLUMNS`] and the keys, so that it cannot fall behind them.
pub(in crate::cli) fn columns_help() -> String {
    let launch: Vec<(&str, String)> = LAUNCH_COLUMNS
        .iter()
        .flat_map(|(key, names)| {
            names.iter().map(move |(name, unit)| {
                let unit = match unit {
                    Unit::Si => Scene::key(key).map_or("", |k| k.unit),
                    unit => unit.name(),
                };
                (*name, format!("{key} in {unit}"))
            })
        })
        .collect();
    let width = launch.iter().map(|(name, _)| name.len()).max().unwrap_or(0);
    let mut text = String::from(
        "A CSV of launches, one flight per row (`-` reads stdin). The header names the \
         columns; these are read, in any order:\n",
    );
    for (name, meaning) in &launch {
        text += &format!("  {name:<width$}  {meaning}\n");
    }
    text += &format!(
        "  and any other key of `homerun keys` ({DRAG_KEY}, environment.temperature, {}, …), \
         that input for the row, as --set takes it.\n\
         Statcast's launch_speed and launch_angle columns are read as they are; its \
         release_spin_rate is the pitch's spin, not the batted ball's, and is not read. \
         Other columns are ignored (named once on stderr). A launch column not given takes \
         the preset's value for every row; an empty cell of another column, the preset's \
         value; a row whose launch cells are all empty is skipped.",
        FIELD_KEYS[0].name
    );
    text
}

/// What one input column is.
#[derive(Clone, Copy, Debug)]
pub(super) enum Column {
    /// A launch value (index into [`LAUNCH_COLUMNS`]), in `Unit`.
    Launch(usize, Unit),
    /// Any other input key, as `--set` takes it.
    Input(&'static str),
    /// A `[field]` key (index into [`FIELD_KEYS`]).
    Field(usize),
    /// Not an input: ignored (Statcast's other 80-odd columns).
    Ignored,
}

/// The header's columns, checked.
pub(super) struct Header {
    pub(super) names: Vec<String>,
    pub(super) columns: Vec<Column>,
}

impl Header {
    pub(super) fn new(names: Vec<String>) -> Result<Header, String> {
        let names: Vec<String> = names.into_iter().map(|n| n.trim().to_owned()).collect();
        let mut columns = Vec::with_capacity(names.len());
        let mut given: Vec<(&str, &str)> = Vec::new(); // (key, column name)
        for name in &names {
            let column = column_of(name);
            let key = match column {
                Column::Launch(i, _) => Some(LAUNCH_COLUMNS[i].0),
                Column::Input(key) => Some(key),
                Column::Field(i) => Some(FIELD_KEYS[i].name),
                Column::Ignored => None,
            };
            if let Some(key) = key {
                if let Some((_, first)) = given.iter().find(|(k, _)| *k == key) {
                    return Err(format!(
                        "columns `{}` and `{}` both give {key}; keep one",
                        escape_cut(first, 80),
                        escape_cut(name, 80)
                    ));
                }
                given.push((key, name));
            }
            columns.push(column);
        }
        Ok(Header { names, columns })
    }

    /// Whether any column is an input: a header with none (a file separated
    /// by `;`, another table) would fly the preset's launch on every row.
    pub(super) fn has_input(&self) -> bool {
        self.columns.iter().any(|c| !matches!(c, Column::Ignored))
    }

    pub(super) fn has_launch(&self, index: usize) -> bool {
        self.columns
            .iter()
            .any(|c| matches!(c, Column::Launch(i, _) if *i == index))
    }

    /// The input columns that change a row's swing, and so the launch
    /// values the row takes from it: the pitch, the bat, the ball and
    /// gravity (which bends the pitch, Eq. 3).
    pub(super) fn swing_columns(&self) -> Vec<&str> {
        self.names
            .iter()
            .zip(&self.columns)
            .filter(|(_, c)| {
                matches!(c, Column::Input(key)
                    if ["pitch.", "bat.", "ball."].iter().any(|s| key.starts_with(s))
                        || *key == "environment.gravity")
            })
            .map(|(n, _)| n.as_str())
            .collect()
    }

    pub(super) fn ignored(&self) -> Vec<&str> {
        self.names
            .iter()
            .zip(&self.columns)
            .filter(|(_, c)| matches!(c, Column::Ignored))
            .map(|(n, _)| n.as_str())
            .collect()
    }
}

pub(super) fn column_of(name: &str) -> Column {
    for (index, (_, names)) in LAUNCH_COLUMNS.iter().enumerate() {
        if let Some((_, unit)) = names.iter().find(|(n, _)| *n == name) {
            return Column::Launch(index, *unit);
        }
    }
    if let Some(index) = FIELD_KEYS.iter().position(|f| f.name == name) {
        return Column::Field(index);
    }
    if let Some(key) = TEXT_KEYS.iter().find(|k| **k == name) {
        return Column::Input(key);
    }
    match Scene::key(name) {
        Ok(key) => Column::Input(key.name),
        Err(_) => Column::Ignored,
    }
}

/// One row, ready to fly.
#[derive(Clone, Copy)]
pub(super) struct Job {
    pub(super) line: usize,
    pub(super) scene: Scene,
    pub(super) fence: Fence,
}

/// What a row turned out to be. Unboxed: each is moved once, into the
/// chunk's jobs, and a box would allocate per row.
#[allow(clippy::large_enum_variant)]
pub(super) enum Row {
    Job(Job),
    Bad {
        line: usize,
        reason: String,
    },
    /// Every launch column empty (in a Statcast export: a pitch not put in
    /// play): skipped and counted, not a failure.
    NoLaunch,
    /// An empty line (not even a space): skipped and counted. A line of
    /// spaces or tabs is a record of one field, and fails or flies as one.
    Blank,
}

pub(super) fn parse_row(header: &Header, base: &Preset, line: usize, text: &str) -> Row {
    if text.is_empty() {
        return Row::Blank;
    }
    let bad = |reason: String| Row::Bad { line, reason };
    let fields = match split_fields(text) {
        Ok(fields) => fields,
        Err(reason) => return bad(reason.to_owned()),
    };
    if fields.len() != header.columns.len() {
        return bad(format!(
            "{} field{} where the header has {}",
            fields.len(),
            if fields.len() == 1 { "" } else { "s" },
            header.columns.len()
        ));
    }
    let launch_given = header
        .columns
        .iter()
        .zip(&fields)
        .filter(|(c, _)| matches!(c, Column::Launch(..)))
        .map(|(_, v)| !v.trim().is_empty())
        .collect::<Vec<_>>();
    if !launch_given.is_empty() && launch_given.iter().all(|given| !given) {
        return Row::NoLaunch;
    }
    let mut scene = base.scene;
    let mut fence = fence_of(base);
    // One row is one source: ρ beside the weather is refused.
    let mut batch = InputBatch::new();
    let mut converted = Vec::new();
    for ((column, name), value) in header.columns.iter().zip(&header.names).zip(&fields) {
        let value = value.trim();
        let shown = escape_cut(value, 80);
        let number = || {
            value.parse::<f64>().map_err(|_| {
                format!(
                    "{} = {:?}: not a number",
                    escape_cut(name, 80),
                    cut(value, 80)
                )
            })
        };
        let done = match *column {
            Column::Ignored => Ok(()),
            Column::Launch(index, _) if value.is_empty() => {
                Err(format!("{} is empty", LAUNCH_COLUMNS[index].0))
            }
            _ if value.is_empty() => Ok(()), // the preset's value
            // A launch.* cell as `--set` takes it (`103mph`).
            Column::Launch(index, Unit::Si) => batch
                .set_text(&mut scene, LAUNCH_COLUMNS[index].0, value)
                .map_err(|e| e.to_string()),
            // Statcast's own columns: a bare number in their unit.
            Column::Launch(index, unit) => number().and_then(|v| {
                converted.push(format!("{name} = {shown} {}", unit.name()));
                batch
                    .set(&mut scene, LAUNCH_COLUMNS[index].0, unit.to_si(v))
                    .map_err(|e| e.to_string())
            }),
            // The whole value is parsed; only the error's copy is cut.
            Column::Input(key) => batch
                .set_text(&mut scene, key, value)
                .map_err(|e| match e {
                    InputError::NotANumber { key, text } => InputError::NotANumber {
                        key,
                        text: cut(&text, 80),
                    },
                    InputError::UnknownModel(model) => InputError::UnknownModel(UnknownModel {
                        text: cut(&model.text, 80),
                        ..model
                    }),
                    InputError::UnknownHand(hand) => InputError::UnknownHand(UnknownHand {
                        text: cut(&hand.text, 80),
                    }),
                    e => e,
                })
                .map_err(|e| e.to_string()),
            Column::Field(index) => {
                let key = &FIELD_KEYS[index];
                key.read(value)
                    .map(|v| (key.set)(&mut fence, v))
                    .map_err(|e| e.to_string())
            }
        };
        if let Err(reason) = done {
            return bad(reason);
        }
    }
    if let Err(e) = scene.validate() {
        let from = if converted.is_empty() {
            String::new()
        } else {
            format!(" (from {})", converted.join(", "))
        };
        return bad(format!("{e}{from}"));
    }
    Row::Job(Job { line, scene, fence })
}
