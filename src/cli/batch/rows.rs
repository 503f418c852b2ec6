//! A batch's header and rows: which column gives which input (the keys,
//! or Statcast's own names in mph, degrees and rpm), and each row made a
//! scene to fly, or the reason it cannot be one.

use crate::Scene;
use crate::analysis::savant::RowLaunch;
use crate::model::aero::UnknownModel;
use crate::model::keys::{
    AIR_KEYS, ATMOSPHERE_KEYS, DRAG_KEY, InputBatch, InputError, Key, LAUNCH_KEYS, TEXT_KEYS,
    out_of_range_shown,
};
use crate::model::park::GivenWeather;
use crate::model::scene::UnknownHand;
use crate::preset::{FIELD_KEYS, Fence, cut, escape_cut};
use crate::units::{Quantity, UnitSystem, significant};

use super::kinds::Called;
use super::launch_columns::{LAUNCH_COLUMNS, Unit};
use super::own_launch::SwingLaunches;
use super::plural;
use super::read::Fields;
use super::savant_columns::{CONTACT_HEIGHT, ContactFrom, SavantCells, SavantColumn, Setup};
use super::swing_columns::{RowSwing, SwingCells, SwingColumn};

/// `fly --batch`'s long help: the columns read, made from
/// [`LAUNCH_COLUMNS`] and the keys, so that it cannot fall behind them.
pub(in crate::cli) fn columns_help() -> String {
    let mut launch: Vec<(&str, String)> = LAUNCH_COLUMNS
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
    launch.extend(
        [
            (
                "hc_x, hc_y",
                "Savant's hit coordinates: the spray angle (see --spray)",
            ),
            ("stand", "the batter's side, R or L (for the spin estimate)"),
            (
                "home_team",
                "the park: its fence, and the standard air at its elevation",
            ),
            (
                "hit_distance_sc",
                "Statcast's distance (ft): the output adds it and the difference",
            ),
            (
                "exit_direction",
                "the launch direction measured at the bat (°, + toward right field)",
            ),
            (
                "plate_z",
                "the pitch's height over the plate (ft): the contact height, unless \
                 environment.contact_height is given",
            ),
            (
                "bb_type, events",
                "Savant's kind of ball and the play: --summary's table by kind (home runs by events)",
            ),
            (
                "hang_time, apex",
                "measured hang time (s) and apex (ft): calibrate fits the lift on them",
            ),
        ]
        .map(|(name, meaning)| (name, meaning.to_owned())),
    );
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
         Statcast's launch_speed and launch_angle columns are read as they are, its names \
         in either case (EXIT_SPEED, LAUNCH_ANGLE, HIT_DISTANCE, HANG_TIME, as older and \
         Trackman's files write them); its \
         release_spin_rate is the pitch's spin, not the batted ball's, and is not read: a row \
         without spin gets Nathan's estimate from its angle, direction and side. \
         `null`, `NA`, `NaN` and the empty cell are missing values; a row without a launch speed \
         is skipped. Statcast's columns take a unit as --set does (`103mph`, `460ft`); a \
         distance, hang time or apex that cannot be read is missing, never a reason to skip \
         the row. \
         Other columns are ignored (named once on stderr). A launch column not given takes \
         the preset's value for every row; an empty cell of another column, the preset's \
         value; a row whose launch cells are all empty is skipped. \
         The output is in the units of --units, SI by default whatever the file: --units \
         imperial writes a Savant export in its own mph, ° and ft (columns named with their \
         unit, launch.speed_mph). One summary closes the batch on stderr (--summary: on \
         stdout): rows flown and skipped, the outcomes at the park, the error against \
         hit_distance_sc.",
        FIELD_KEYS[0].name
    );
    text
}

/// The key of [`LAUNCH_COLUMNS`]`[index]`, looked up once.
fn launch_key(index: usize) -> &'static Key {
    static KEYS: std::sync::OnceLock<[&'static Key; 3]> = std::sync::OnceLock::new();
    KEYS.get_or_init(|| LAUNCH_COLUMNS.map(|(name, _)| Scene::key(name).expect("a launch key")))
        [index]
}

/// What one input column is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Column {
    /// A launch value (index into [`LAUNCH_COLUMNS`]), in `Unit`.
    Launch(usize, Unit),
    /// Any other input key, as `--set` takes it.
    Input(&'static str),
    /// A `[field]` key (index into [`FIELD_KEYS`]).
    Field(usize),
    /// A Savant column that is no key (hit coordinates, side, park, distance).
    Savant(SavantColumn),
    /// Bat or pitch tracking, read when swings are solved.
    Swing(SwingColumn),
    /// Not an input: ignored (Statcast's other 80-odd columns).
    Ignored,
}

/// The header's columns, checked.
pub(super) struct Header {
    pub(super) names: Vec<String>,
    pub(super) columns: Vec<Column>,
    /// Each [`Column::Input`], what a row needs of its key (worked out
    /// once, not on every row).
    inputs: Vec<Option<InputKey>>,
    /// The columns `--keep` copies, by index (the first of a repeated name).
    pub(super) keep: Vec<usize>,
    /// The columns a row reads (all but the ignored), by index.
    pub(super) read: Vec<usize>,
    /// The launch columns, by index, and the launch speed's.
    launch: Vec<usize>,
    speed: Option<usize>,
    /// No column gives a row's scene anything but its launch (and its
    /// park): every row at a park then has the same swing ([`SwingLaunches`]
    /// knows it by the park).
    launch_only: bool,
    /// A column gives `launch.direction` (the hit coordinates then do not).
    direction_given: bool,
    /// A column gives a hit coordinate.
    pub(super) hit_coordinates: bool,
    /// A column gives `environment.contact_height`: `plate_z` then does not.
    contact_height_given: bool,
    /// A column gives `bat.tilt`: the league's tilt then does not
    /// ([`super::Setup::tilt_prior`]).
    pub(super) tilt_given: bool,
}

/// An input column's key as a row sets it.
#[derive(Clone, Copy, Debug)]
struct InputKey {
    name: &'static str,
    /// The key, if it is a number's (looked up once; set as `set_text`
    /// sets it), not a model's or the hand's.
    numeric: Option<&'static Key>,
    /// An air or weather key, which the row's batch and given air note; a
    /// row sets any other key at once.
    air: bool,
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
                // The hit coordinates give the launch direction.
                Column::Savant(SavantColumn::HcX | SavantColumn::HcY)
                    if names.iter().any(|n| n.trim() == "launch.direction") =>
                {
                    Some("launch.direction")
                }
                Column::Savant(SavantColumn::ExitDirection) => Some("launch.direction"),
                Column::Savant(c) => Some(c.name()),
                Column::Swing(_) | Column::Ignored => None,
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
        let inputs = columns
            .iter()
            .map(|column| match *column {
                Column::Input(name) => Some(InputKey {
                    name,
                    numeric: Some(name)
                        .filter(|name| !TEXT_KEYS.contains(name))
                        .and_then(|name| Scene::key(name).ok()),
                    air: AIR_KEYS.contains(&name) || ATMOSPHERE_KEYS.contains(&name),
                }),
                _ => None,
            })
            .collect();
        let indices = |keep: fn(&Column) -> bool| -> Vec<usize> {
            (0..columns.len()).filter(|&i| keep(&columns[i])).collect()
        };
        let read = indices(|c| !matches!(c, Column::Ignored));
        let launch = indices(|c| matches!(c, Column::Launch(..)));
        let speed = indices(|c| matches!(c, Column::Launch(0, _)))
            .first()
            .copied();
        let launch_only = columns.iter().all(|c| match c {
            Column::Input(key) => LAUNCH_KEYS.iter().any(|k| k.name == *key),
            _ => true,
        });
        let is = |column: SavantColumn| columns.contains(&Column::Savant(column));
        let hit_coordinates = is(SavantColumn::HcX) || is(SavantColumn::HcY);
        let contact_height_given = columns.contains(&Column::Input(CONTACT_HEIGHT));
        let tilt_given = columns.contains(&Column::Input("bat.tilt"));
        Ok(Header {
            direction_given: columns.contains(&Column::Input("launch.direction"))
                || columns.contains(&Column::Savant(SavantColumn::ExitDirection)),
            names,
            columns,
            inputs,
            keep: Vec::new(),
            read,
            launch,
            speed,
            launch_only,
            hit_coordinates,
            contact_height_given,
            tilt_given,
        })
    }

    /// Sets the columns `--keep` copies: each name must be a column (the
    /// first of that name, if the header repeats it, as Savant's 2019
    /// layout does `pitcher` and `fielder_2`).
    pub(super) fn keep(&mut self, names: &[String]) -> Result<(), String> {
        self.keep = names
            .iter()
            .map(|name| {
                self.names.iter().position(|n| n == name).ok_or_else(|| {
                    format!(
                        "--keep {}: no column of that name in the header",
                        escape_cut(name, 80)
                    )
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(())
    }

    /// Whether a column is `column`.
    pub(super) fn has(&self, column: SavantColumn) -> bool {
        self.columns
            .iter()
            .any(|c| matches!(c, Column::Savant(s) if *s == column))
    }

    /// The names of the columns read that are not keys of `homerun keys`:
    /// Statcast's launch columns and the Savant ones.
    pub(super) fn savant_used(&self) -> Vec<&str> {
        self.names
            .iter()
            .zip(&self.columns)
            .filter(|(_, c)| {
                matches!(
                    c,
                    Column::Savant(_) | Column::Launch(_, Unit::Mph | Unit::Degrees | Unit::Rpm)
                )
            })
            .map(|(n, _)| n.as_str())
            .collect()
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
    // Statcast's own names in either case (`LAUNCH_ANGLE`, as its search
    // and Trackman's files write them); a key only as written.
    let statcast = name.to_ascii_lowercase();
    for (index, (_, names)) in LAUNCH_COLUMNS.iter().enumerate() {
        let found =
            (names.iter()).find(|(n, unit)| *n == name || (*unit != Unit::Si && *n == statcast));
        if let Some((_, unit)) = found {
            return Column::Launch(index, *unit);
        }
    }
    if let Some(index) = FIELD_KEYS.iter().position(|f| f.name == name) {
        return Column::Field(index);
    }
    if let Some(column) = SavantColumn::of(&statcast) {
        return Column::Savant(column);
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
pub(super) struct Job {
    pub(super) line: usize,
    /// Its speed, angle and any spin and direction it gave; the rest is
    /// `launch`'s to fill in.
    pub(super) scene: Scene,
    pub(super) launch: RowLaunch,
    /// The generic fence (the preset's, or the row's `field.*`), used when
    /// the row is at no park.
    pub(super) fence: Fence,
    /// The index of the row's park, if it is at one.
    pub(super) park: Option<usize>,
    /// Statcast's distance (m).
    pub(super) statcast: Option<f64>,
    /// Measured hang time (s) and apex (m), for `calibrate`.
    pub(super) hang_time: Option<f64>,
    pub(super) apex: Option<f64>,
    /// The `--keep` cells, as read.
    pub(super) kept: Vec<String>,
    /// Its hit coordinates are the plate's: it has no spray.
    pub(super) spray_at_plate: bool,
    /// Its tracking cells, and (when swings are solved) its swing.
    pub(super) tracked: SwingCells,
    pub(super) swing: Option<RowSwing>,
    /// The air keys given, by `--set` and by the row: a park keeps them.
    pub(super) given: GivenWeather,
    /// Where its contact height came from.
    pub(super) contact: ContactFrom,
    /// What Savant called it, for the summary.
    pub(super) called: Called,
}

/// What a row turned out to be.
pub(super) enum Row {
    /// Ready to fly: pushed onto the jobs [`parse_row`] was given.
    Job,
    Bad {
        line: usize,
        reason: String,
    },
    /// Every launch column empty, or no launch speed (in a Statcast export:
    /// a pitch not put in play): skipped and counted, not a failure.
    NoLaunch,
}

/// [`InputBatch::set_key_text`], a plain decimal in the key's bounds read
/// without the general reader (units, errors): the same value, set alike.
/// A key neither of the air nor of the weather (`air` false) changes
/// nothing of the batch, and is set at once.
fn set_number(
    batch: &mut InputBatch,
    scene: &mut Scene,
    (key, air): (&'static Key, bool),
    text: &str,
) -> Result<(), InputError> {
    match text.parse::<f64>().ok() {
        Some(value) if key.bounds.contains(value) && !air => {
            (key.set)(scene, value);
            Ok(())
        }
        Some(value) if key.bounds.contains(value) => batch.set_key(scene, key, value),
        _ => batch.set_key_text(scene, key, text),
    }
}

/// A missing value: the empty cell, Savant's `null` (its 2019 layout), R's
/// `NA`, pandas' `NaN`.
fn is_missing(value: &str) -> bool {
    ["", "null", "na", "nan"]
        .iter()
        .any(|missing| value.eq_ignore_ascii_case(missing))
}

/// A measured cell of `quantity`: a bare number in the column's own unit
/// (`bare` makes it SI), or a number with a unit as `--set` takes it
/// (`103mph`, `460ft`, `140m`); `None` if it is neither, or not finite.
pub(super) fn measure(text: &str, quantity: Quantity, bare: impl Fn(f64) -> f64) -> Option<f64> {
    let reading = crate::units::read_typed(text, quantity, quantity.si_symbol()).ok()?;
    let si = match reading.unit {
        Some(_) => reading.si,
        None => bare(reading.number),
    };
    si.is_finite().then_some(si)
}

/// The row on `line`, its `fields` as read; with `swings`, the launch
/// values it leaves to its swing filled in where its swing is known (see
/// [`SwingLaunches`]). A row that flies is pushed onto `jobs`, built there
/// (a job holds a scene: moving it cost more than reading its cells).
pub(super) fn parse_row(
    header: &Header,
    setup: &Setup,
    (line, fields): (usize, Fields),
    swings: Option<&mut SwingLaunches>,
    jobs: &mut Vec<Job>,
) -> Row {
    let bad = |reason: String| Row::Bad { line, reason };
    if fields.len() != header.columns.len() {
        return bad(format!(
            "{} field{} where the header has {}",
            fields.len(),
            plural(fields.len()),
            header.columns.len()
        ));
    }
    let no_speed = header.speed.is_some_and(|i| cell(&fields, i).is_empty());
    let launch = &header.launch;
    if no_speed || (!launch.is_empty() && launch.iter().all(|&i| cell(&fields, i).is_empty())) {
        return Row::NoLaunch;
    }
    jobs.push(Job {
        line,
        scene: setup.base.scene,
        launch: RowLaunch::default(),
        fence: setup.base.fence.unwrap_or(Fence::generic()),
        park: None,
        statcast: None,
        hang_time: None,
        apex: None,
        kept: Vec::new(),
        spray_at_plate: false,
        tracked: SwingCells::default(),
        swing: None,
        given: setup.given,
        contact: ContactFrom::Given,
        called: Called::default(),
    });
    let job = jobs.last_mut().expect("a job just pushed");
    if let Err(reason) = read_cells(header, setup, &fields, swings, job) {
        jobs.pop();
        return bad(reason);
    }
    job.kept = header
        .keep
        .iter()
        .map(|&i| fields.get(i).to_owned())
        .collect();
    Row::Job
}

/// Cell `i` of a row, trimmed, "" where missing.
fn cell<'a>(fields: &Fields<'a>, i: usize) -> &'a str {
    let value = fields.get(i).trim();
    if is_missing(value) { "" } else { value }
}

/// Sets `job` (the preset's scene and fence) as the row's cells say, and
/// validates its scene; or the reason the row cannot fly.
fn read_cells(
    header: &Header,
    setup: &Setup,
    fields: &Fields,
    swings: Option<&mut SwingLaunches>,
    job: &mut Job,
) -> Result<(), String> {
    let cell = |i: usize| cell(fields, i);
    let Job {
        scene,
        fence,
        given,
        ..
    } = job;
    let mut savant = SavantCells::default();
    let mut tracked = SwingCells::default();
    let (mut spin_given, mut sidespin_given) = (setup.spin_given, setup.sidespin_given);
    // One row is one source: ρ beside the weather is refused.
    let mut batch = InputBatch::new();
    // Statcast's columns read in their units, named only if the row fails.
    let mut converted = false;
    for &i in &header.read {
        let (column, name) = (&header.columns[i], &header.names[i]);
        let value = cell(i);
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
            // No spin: the estimate's.
            Column::Launch(2, _) if value.is_empty() => Ok(()),
            Column::Launch(index, _) if value.is_empty() => {
                Err(format!("{} is empty", LAUNCH_COLUMNS[index].0))
            }
            _ if value.is_empty() => Ok(()), // the preset's value
            Column::Savant(column) => savant.read(column, value, setup),
            Column::Swing(column) => tracked.read(column, value),
            // A launch.* cell as `--set` takes it (`103mph`).
            Column::Launch(index, Unit::Si) => {
                spin_given |= index == 2;
                set_number(&mut batch, scene, (launch_key(index), false), value)
                    .map_err(|e| e.to_string())
            }
            // Statcast's own columns: a bare number in their unit, or one
            // with its unit (a launch key: nothing of the batch's, set at
            // once; checked with the scene).
            Column::Launch(index, unit) => {
                let quantity = unit.quantity().expect("Statcast's columns have units");
                let si = match measure(value, quantity, |v| unit.to_si(v)) {
                    Some(si) => Ok(si),
                    None => number().map(|v| unit.to_si(v)),
                };
                si.map(|si| {
                    converted = true;
                    spin_given |= index == 2;
                    (launch_key(index).set)(scene, si);
                })
            }
            // The whole value is parsed; only the error's copy is cut.
            Column::Input(_) => {
                let input = header.inputs[i].expect("an input column's key");
                if input.air {
                    given.note(input.name);
                }
                sidespin_given |= input.name == "launch.sidespin";
                match input.numeric {
                    Some(key) => set_number(&mut batch, scene, (key, input.air), value),
                    None => batch.set_text(scene, input.name, value),
                }
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
                .map_err(|e| e.to_string())
            }
            Column::Field(index) => {
                let key = &FIELD_KEYS[index];
                key.read(value)
                    .map(|v| (key.set)(fence, v))
                    .map_err(|e| e.to_string())
            }
        };
        done?;
    }
    if let Some(direction) = savant.direction {
        scene.launch.direction = Some(direction);
    }
    let contact = savant.start_at_pitch(
        scene,
        header.contact_height_given || setup.contact_height_given,
    );
    let park = setup.park.or(savant.park);
    if let Some(index) = park {
        super::super::ground::to_park(scene, &setup.parks.parks[index], *given);
    }
    let valid = match swings {
        Some(swings) => swings.validate(scene, header.launch_only.then_some(park)),
        None => scene.validate(),
    };
    if let Err(mut e) = valid {
        // Out of range from a column in mph, ° or rpm: shown in that unit
        // too, as `--set` shows a value typed with one.
        if let InputError::OutOfRange {
            key,
            value,
            bounds,
            unit,
            typed: None,
        } = e
            && let Some(quantity) = header.columns.iter().find_map(|column| match column {
                Column::Launch(i, unit) if LAUNCH_COLUMNS[*i].0 == key => unit.quantity(),
                _ => None,
            })
        {
            let shown = quantity.unit(UnitSystem::Imperial, unit);
            let typed = significant(shown.show(value));
            e = out_of_range_shown((key, quantity, unit, bounds), value, &typed, shown);
        }
        let from = if converted {
            let read: Vec<String> = header
                .columns
                .iter()
                .zip(&header.names)
                .enumerate()
                .filter_map(|(i, (column, name))| match column {
                    Column::Launch(_, unit) if *unit != Unit::Si && !cell(i).is_empty() => Some(
                        format!("{name} = {} {}", escape_cut(cell(i), 80), unit.name()),
                    ),
                    _ => None,
                })
                .collect();
            format!(" (from {})", read.join(", "))
        } else {
            String::new()
        };
        return Err(format!("{e}{from}"));
    }
    job.launch = RowLaunch {
        spray: savant.spray().filter(|_| !header.direction_given),
        side: savant.side,
        // A row that gives its backspin has its spin: only a row without
        // one is filled, both parts (a sidespin given is kept).
        estimate_backspin: !spin_given,
        estimate_sidespin: !spin_given && !sidespin_given,
    };
    job.park = park;
    job.contact = contact;
    job.called = savant.called;
    job.tracked = tracked;
    job.spray_at_plate = savant.at_plate() && !header.direction_given;
    (job.statcast, job.hang_time, job.apex) = (savant.distance, savant.hang_time, savant.apex);
    Ok(())
}
