//! What a header refuses before any row: a mapping (`--column`) that names
//! nothing, maps a lookalike to the launch or leaves a unit unsaid, and a
//! column left unread that would make every answer wrong (a spray angle,
//! the weather, a wind without its direction).

use model::keys::{Key, TEXT_KEYS};
use model::scene::Scene;
use preset::{FIELD_KEYS, escape_cut};

use super::Header;
use crate::Setup;
use crate::columns::{self, Column, LAUNCH_KEYS, SavantColumn, Unit, column_of};
use units::Quantity;

/// Every name a column may be mapped to: the table's and the keys.
fn readable_names() -> Vec<String> {
    let table = columns::TABLE.iter().flat_map(|e| e.names.iter().copied());
    let keys = model::keys::all_keys().map(|k| k.name);
    let fields = FIELD_KEYS.iter().map(|f| f.name);
    (table
        .chain(keys)
        .chain(fields)
        .chain(TEXT_KEYS.iter().copied()))
    .map(str::to_owned)
    .collect()
}

/// `--column ignore=COLUMN`: the column is meant to go unread.
const IGNORE: &str = "ignore";

/// Column names (folded: [`columns::folded`]) that say a direction the
/// table does not read.
const DIRECTION_LIKE: [&str; 9] = [
    "sprayangle",
    "spray",
    "bearing",
    "direction",
    "spraydirection",
    "hitdirection",
    "launchdirection",
    "horizontalangle",
    "horizontallaunchangle",
];

/// Column names (folded) that say the weather, with the key each would be.
const WEATHER_LIKE: [(&str, &str); 17] = [
    ("temperature", "environment.temperature"),
    ("temp", "environment.temperature"),
    ("tempf", "environment.temperature"),
    ("tempc", "environment.temperature"),
    ("airtemperature", "environment.temperature"),
    ("airtemp", "environment.temperature"),
    ("wind", "environment.wind"),
    ("windspeed", "environment.wind"),
    ("winddirection", "environment.wind_direction"),
    ("winddir", "environment.wind_direction"),
    ("humidity", "environment.humidity"),
    ("relativehumidity", "environment.humidity"),
    ("pressure", "environment.pressure"),
    ("barometricpressure", "environment.pressure"),
    ("elevation", "environment.elevation"),
    ("altitude", "environment.elevation"),
    ("airdensity", "environment.air_density"),
];

/// The number key a column named `name` gives, as `homerun keys` has it
/// (`launch.speed`, `environment.temperature`): `None` for the table's
/// columns, which have their own units, and for text keys.
fn number_key(name: &str) -> Option<&'static Key> {
    match column_of(name) {
        Column::Input(key) => Scene::key(key).ok(),
        Column::Launch(index, Unit::Si) => Scene::key(LAUNCH_KEYS[index]).ok(),
        _ => None,
    }
}

/// Refuses a unit on a mapping (`--column NAME=COLUMN:UNIT`) that is not
/// a number key's, or not a unit of its quantity.
fn check_unit(name: &str, column: &str, unit: &str) -> Result<(), String> {
    let mapping = format!(
        "--column {}={}:{}",
        escape_cut(name, 40),
        escape_cut(column, 40),
        escape_cut(unit, 20)
    );
    // A key's quantity, or that of a table column whose cells may carry
    // a unit (Statcast's in mph, ° and ft: a file's exit speeds in km/h,
    // its distances in metres).
    let quantity = match (number_key(name), column_of(name)) {
        (Some(key), _) => Some(key.quantity()),
        (None, Column::Launch(_, unit)) => unit.quantity(),
        (None, Column::Savant(SavantColumn::Distance | SavantColumn::Apex)) => {
            Some(Quantity::Distance)
        }
        (None, Column::Savant(SavantColumn::HitSpinRate)) => Some(Quantity::Spin),
        _ => None,
    };
    let Some(quantity) = quantity else {
        return Err(format!(
            "{mapping}: a unit is given only to a key's column (`homerun keys`) or to a \
             measurement's (launch_speed, launch_angle, spin_rpm, hit_distance_sc, apex, \
             hit_spin_rate); this column's cells are read as they are"
        ));
    };
    match units::read_typed(&format!("1{unit}"), quantity, quantity.si_symbol()) {
        Ok(reading) if reading.unit.is_some() => Ok(()),
        _ => Err(format!(
            "{mapping}: `{}` is no unit of {}; it takes {}",
            escape_cut(unit, 20),
            quantity.noun(),
            units::accepted(quantity, quantity.si_symbol())
        )),
    }
}

/// Refuses a mapping of another column to a number key whose quantity has
/// more units than one (`--column environment.temperature=temp`) where
/// the mapping does not say which its bare numbers are in: read as SI, a
/// 55 °F day would pass for 55 °C and 10 mph for 10 m/s, in range.
fn check_unit_said(name: &str, column: &str) -> Result<(), String> {
    let Some(key) = number_key(name) else {
        return Ok(());
    };
    let quantity = key.quantity();
    if quantity.typed_units().len() < 2 {
        return Ok(());
    }
    let (name, column) = (escape_cut(name, 40), escape_cut(column, 40));
    Err(format!(
        "--column {name}={column}: say the unit of its bare numbers, --column \
         {name}={column}:UNIT with UNIT one of {} (a bare number is read in {} only in a \
         column named {name})",
        units::accepted(quantity, quantity.si_symbol()),
        quantity.si_symbol()
    ))
}

/// A column's name as a message shows it, and as the shell takes it.
fn shown_and_typed(name: &str) -> (String, String) {
    let shown = escape_cut(name, 40);
    let typed = match name.contains(' ') {
        true => format!("'{shown}'"),
        false => shown.clone(),
    };
    (shown, typed)
}

/// One `--column NAME=COLUMN[:UNIT]`: the name, the column and the unit
/// of its bare numbers.
pub(super) type Mapping<'a> = (&'a str, &'a str, Option<&'a str>);

/// Each `--column NAME=COLUMN[:UNIT]` of `setup` against the header's
/// `names`, or why it is refused.
pub(super) fn mappings<'a>(setup: &'a Setup, names: &[String]) -> Result<Vec<Mapping<'a>>, String> {
    let mut mapping = Vec::new();
    for (name, column) in &setup.mapping {
        // A name nothing reads would leave the column unread, quietly
        // (`ignore` says that is meant).
        if matches!(column_of(name), Column::Ignored) && name != IGNORE {
            let readable = readable_names();
            let near = columns::nearest(&[name.as_str()], &readable);
            let near = match near.first() {
                Some(near) => format!("; did you mean {near}?"),
                None => String::new(),
            };
            return Err(format!(
                "--column {}={}: `{}` is no column name or key homerun reads (`homerun fly \
                 --help` lists the columns, `homerun keys` the keys){near}",
                escape_cut(name, 40),
                escape_cut(column, 40),
                escape_cut(name, 40)
            ));
        }
        let unit_after = column.rsplit_once(':');
        let (column, unit) = match unit_after {
            Some((before, unit)) if !names.iter().any(|n| n == column) => (before, Some(unit)),
            _ => (column.as_str(), None),
        };
        let launch_value = match column_of(name) {
            Column::Input(key) => key.starts_with("launch."),
            other => matches!(other, Column::Launch(..)),
        };
        if let Some(what) = columns::lookalike(column).filter(|_| launch_value) {
            return Err(format!(
                "--column {}={}: `{}` is {what}, not {}",
                escape_cut(name, 40),
                escape_cut(column, 40),
                escape_cut(column, 40),
                escape_cut(name, 40)
            ));
        }
        match unit {
            Some(unit) => check_unit(name, column, unit)?,
            None if column != name => check_unit_said(name, column)?,
            None => {}
        }
        mapping.push((name.as_str(), column, unit));
        if !names.iter().any(|n| n == column) {
            return Err(format!(
                "--column {}={}: no column `{}` in the header",
                escape_cut(name, 40),
                escape_cut(column, 40),
                escape_cut(column, 40)
            ));
        }
    }
    Ok(mapping)
}

impl Header {
    /// Refuses a header with a column that looks like a direction (a spray
    /// angle, a bearing) and none that gives one: every row would fly to
    /// centre field, which whoever kept that column does not mean. Its
    /// sign and what it measures (where the ball came down, or where it
    /// left the bat) follow no one convention, so it is mapped, not
    /// guessed.
    pub(super) fn check_direction(&self, setup: &Setup) -> Result<(), String> {
        if self.direction_given || self.hit_coordinates || setup.gave("launch.direction") {
            return Ok(());
        }
        let direction_like = |folded: &str| DIRECTION_LIKE.contains(&folded).then_some(());
        let Some((name, ())) = self.unread_like(setup, direction_like) else {
            return Ok(());
        };
        let (shown, typed) = shown_and_typed(name);
        Err(format!(
            "{}: column `{shown}` looks like a direction, but no column gives one, so every row \
             would fly to centre field: map it, --column landing_bearing={typed} (where the ball \
             came down, ° + toward right field) or --column exit_direction={typed} (where it \
             left the bat){}",
            self.line,
            setup.or_set("launch.direction=0", "flies every row to centre field")
        ))
    }

    /// Refuses a header with a column that looks like weather (a
    /// temperature, a wind) that no column reads: every row would fly in
    /// its park's standard air, or the preset's, where whoever kept that
    /// column means the day's. Its unit (°F or °C, mph or m/s) is not
    /// guessed: mapped to its key, a bare number is SI and a cell may
    /// carry its unit.
    pub(super) fn check_weather(&self, setup: &Setup) -> Result<(), String> {
        let key_of = |folded: &str| {
            (WEATHER_LIKE.iter())
                .find(|(name, _)| *name == folded)
                .map(|(_, key)| *key)
        };
        let Some((name, key)) = self.unread_like(setup, key_of) else {
            return Ok(());
        };
        let (shown, typed) = shown_and_typed(name);
        let mapped = match Scene::key(key).map(|k| k.quantity()) {
            Ok(quantity) if quantity.typed_units().len() > 1 => format!(
                "--column {key}={typed}:UNIT with the unit of its bare numbers ({})",
                units::accepted(quantity, quantity.si_symbol())
            ),
            _ => format!(
                "--column {key}={typed} (bare numbers in {})",
                Scene::key(key).map_or("", |k| k.unit)
            ),
        };
        Err(format!(
            "{}: column `{shown}` looks like weather, but no column reads it, so every row \
             would fly in its park's standard air (or the preset's): map it to its key, \
             {mapped}, or --column {IGNORE}={typed} to fly without it",
            self.line
        ))
    }

    /// Refuses another column mapped to the wind's speed with no
    /// direction for it (no column and no `--set`): every row's wind would
    /// blow toward centre field. A file's own `environment.wind` column
    /// keeps the key's documented default.
    pub(super) fn check_wind(&self, setup: &Setup) -> Result<(), String> {
        const WIND: &str = "environment.wind";
        const TOWARD: &str = "environment.wind_direction";
        let Some((_, column)) = (setup.mapping.iter()).find(|(n, c)| n == WIND && c != WIND) else {
            return Ok(());
        };
        if self.columns.contains(&Column::Input(TOWARD)) || setup.gave(TOWARD) {
            return Ok(());
        }
        Err(format!(
            "--column {WIND}={}: no column says where that wind blows, so every row's would \
             blow toward centre field: map one, --column {TOWARD}=COLUMN:UNIT (where it blows \
             toward, 0 centre field, + toward right field; a compass bearing it blows from is \
             not that){}",
            escape_cut(column, 40),
            setup.or_set(&format!("{TOWARD}=0"), "for centre field")
        ))
    }

    /// The first column unread (and neither mapped to [`IGNORE`] nor kept)
    /// whose folded name `like` knows, with what `like` says of it.
    fn unread_like<T>(
        &self,
        setup: &Setup,
        like: impl Fn(&str) -> Option<T>,
    ) -> Option<(&String, T)> {
        // A column mapped, or kept (`--keep`, `calibrate --by`), is known
        // to its user.
        let mapped = |name: &String| {
            setup.mapping.iter().any(|(_, column)| column == name) || setup.keep.contains(name)
        };
        (self.names.iter().zip(&self.columns))
            .filter(|(name, c)| matches!(c, Column::Ignored) && !mapped(name))
            .find_map(|(name, _)| like(&columns::folded(name)).map(|with| (name, with)))
    }
}
