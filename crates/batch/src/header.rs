//! A batch's header: which column gives which input ([`columns`]), checked
//! once: a column repeated, a launch that no column gives, a mapping
//! (`--column`) that names no column are refused here, before any row.

use std::io::BufRead;

use analysis::bat_tracking;
use model::keys::{AIR_KEYS, ATMOSPHERE_KEYS, Key, LAUNCH_KEYS as SCENE_LAUNCH_KEYS, TEXT_KEYS};
use model::scene::{Scene, SceneKind};
use preset::{FIELD_KEYS, Source, escape_cut};

use crate::Setup;
use crate::columns::{
    self, Column, LAUNCH_KEYS, NEEDED_FOR_SWINGS, SavantColumn, TABLE, Unit, column_of,
};
use crate::read::{Records, read_header};
use crate::setup::Priors;
use crate::words::plural;

/// `fly --batch`'s long help: the columns read, made from the table and
/// the keys, so that it cannot fall behind them.
pub fn columns_help() -> String {
    // The launch columns a name a line, with the key and unit each gives
    // (the keys themselves in SI); the others by entry.
    let mut rows: Vec<(String, String)> = Vec::new();
    for (index, key) in LAUNCH_KEYS.iter().enumerate() {
        let si = Scene::key(key).map_or("", |k| k.unit);
        rows.push(((*key).to_owned(), format!("{key} in {si}")));
        if let Some((entry, unit)) = columns::launch_entry(index) {
            let unit = unit.name();
            rows.extend(
                entry
                    .names
                    .iter()
                    .map(|n| ((*n).to_owned(), format!("{key} in {unit}"))),
            );
        }
    }
    rows.extend(
        (TABLE.iter())
            .filter(|e| !e.meaning.is_empty() && !matches!(e.becomes, columns::Becomes::Launch(..)))
            .map(|e| (e.names.join(", "), e.meaning.to_owned())),
    );
    let width = rows.iter().map(|(n, _)| n.len()).max().unwrap_or(0).min(44);
    let mut text = String::from(
        "A CSV of launches, one flight per row (`-` reads stdin; gzip read as it comes). The \
         header names the columns; these are read, in any order, their names in any case and \
         with or without spaces and underscores:\n",
    );
    for (names, meaning) in &rows {
        text += &format!("  {names:<width$}  {meaning}\n");
    }
    text += &format!(
        "  and any other key of `homerun keys` as written ({}, environment.temperature, …), that input for the row, as --set takes it.\n\
         --column NAME=COLUMN reads the file's COLUMN as NAME (any name above or key). A file \
         without a launch speed or angle column is refused, unless --set gives that key for \
         every row or its columns give each row its own swing. A column read twice is \
         refused. `null`, `NA`, `NaN` and the empty cell are missing values; a row without a \
         launch speed is skipped and counted. Statcast's columns take a unit as --set does \
         (`103mph`, `460ft`); a distance, hang time or apex that cannot be read is missing, \
         never a reason to skip the row. Savant's release_spin_rate is the pitch's spin: a row \
         without spin_rpm gets Nathan's estimate from its angle, direction and side. Other \
         columns are ignored (named once on stderr). The rows go to stdout (CSV, or JSON \
         lines with --json), in the units of --units; the summary goes to stderr, or as JSON \
         to --summary-file.",
        FIELD_KEYS[0].name
    );
    text
}

/// The key of launch value `index`, looked up once.
pub(crate) fn launch_key(index: usize) -> &'static Key {
    static KEYS: std::sync::OnceLock<[&'static Key; 3]> = std::sync::OnceLock::new();
    KEYS.get_or_init(|| LAUNCH_KEYS.map(|name| Scene::key(name).expect("a launch key")))[index]
}

/// An input column's key as a row sets it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct InputKey {
    pub name: &'static str,
    /// The key, if it is a number's (looked up once), not a model's or
    /// the hand's.
    pub numeric: Option<&'static Key>,
    /// An air or weather key, which the row's batch and given air note.
    pub air: bool,
}

/// The header's columns, checked.
pub struct Header {
    pub(crate) names: Vec<String>,
    pub(crate) columns: Vec<Column>,
    pub(crate) inputs: Vec<Option<InputKey>>,
    /// The columns `--keep` copies, by index.
    pub(crate) keep: Vec<usize>,
    /// The columns a row reads (all but the ignored), by index.
    pub(crate) read: Vec<usize>,
    /// The launch columns, by index, and the launch speed's.
    pub(crate) launch: Vec<usize>,
    pub(crate) speed: Option<usize>,
    /// No column gives a row's scene anything but its launch (and its
    /// park): every row at a park then has the same swing.
    pub(crate) launch_only: bool,
    /// A column gives `launch.direction` (the hit coordinates then do not).
    pub(crate) direction_given: bool,
    pub(crate) hit_coordinates: bool,
    /// A column gives `environment.contact_height`: `plate_z` then does not.
    pub(crate) contact_height_given: bool,
    /// A column gives `bat.tilt`: the league's tilt then does not.
    pub(crate) tilt_given: bool,
    /// "line 3 (the header)": where the header is, for its messages.
    pub(crate) line: String,
    /// The unit a mapped key column's bare numbers are in, by index
    /// (`--column KEY=COLUMN:UNIT`).
    pub(crate) cell_units: Vec<Option<String>>,
}

mod refusals;

impl Header {
    /// The header of `names` (a byte-order mark dropped), each column read
    /// as `mapping` (`--column NAME=COLUMN`) says, or as the table does.
    /// With `swings`, bat and pitch tracking's columns are read too.
    pub fn new((names, line): (Vec<String>, usize), setup: &Setup) -> Result<Header, String> {
        // Blank lines before it are counted: the header is named by its own.
        let line = format!("line {line} (the header)");
        let names: Vec<String> = names.into_iter().map(|n| n.trim().to_owned()).collect();
        // Each mapping's column, and the unit its bare numbers are in
        // (`--column environment.temperature=temp:F`), checked.
        let mapping = refusals::mappings(setup, &names)?;
        let mut columns = Vec::with_capacity(names.len());
        let mut cell_units = Vec::with_capacity(names.len());
        let mut given: Vec<(String, &str)> = Vec::new(); // (what, column name)
        for name in &names {
            let mapped = mapping.iter().find(|(_, c, _)| c == name);
            cell_units.push(mapped.and_then(|(_, _, unit)| unit.map(str::to_owned)));
            let column = match column_of(mapped.map_or(name, |(to, _, _)| to)) {
                Column::Swing(..) if !setup.solve_swings => Column::Ignored,
                column => column,
            };
            let what = match column {
                Column::Launch(i, _) => Some(LAUNCH_KEYS[i].to_owned()),
                Column::Input(key) => Some(key.to_owned()),
                Column::Field(i) => Some(FIELD_KEYS[i].name.to_owned()),
                Column::Savant(SavantColumn::ExitDirection) => Some("launch.direction".into()),
                Column::Savant(c) => Some(columns::name_of(columns::Becomes::Savant(c)).into()),
                Column::Swing(c, r) => {
                    Some(columns::name_of(columns::Becomes::Swing(c, r)).to_owned())
                }
                Column::Ignored => None,
            };
            if let Some(what) = what {
                if let Some((_, first)) = given.iter().find(|(w, _)| *w == what) {
                    return Err(format!(
                        "{line}: columns `{}` and `{}` both give {what}; keep one (or map one \
                         with --column)",
                        escape_cut(first, 80),
                        escape_cut(name, 80)
                    ));
                }
                given.push((what, name));
            }
            columns.push(column);
        }
        // The hit coordinates give the direction, unless a column does.
        let has = |c: Column| columns.contains(&c);
        let direction_given = has(Column::Input("launch.direction"))
            || has(Column::Savant(SavantColumn::ExitDirection));
        let coordinates =
            has(Column::Savant(SavantColumn::HcX)) || has(Column::Savant(SavantColumn::HcY));
        let bearing = has(Column::Savant(SavantColumn::LandingBearing));
        if coordinates && bearing {
            return Err(format!(
                "{line}: columns hc_x/hc_y and landing_bearing both give where the ball came \
                 down; keep one"
            ));
        }
        let hit_coordinates = coordinates || bearing;
        if direction_given && hit_coordinates && has(Column::Input("launch.direction")) {
            let spray = if bearing {
                "landing_bearing"
            } else {
                "hc_x/hc_y"
            };
            return Err(format!(
                "{line}: columns launch.direction and {spray} both give launch.direction; keep one"
            ));
        }
        let inputs = (columns.iter())
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
        let indices = |keep: &dyn Fn(&Column) -> bool| -> Vec<usize> {
            (0..columns.len()).filter(|&i| keep(&columns[i])).collect()
        };
        let read = indices(&|c| !matches!(c, Column::Ignored));
        let launch = indices(&|c| matches!(c, Column::Launch(..)));
        let speed = indices(&|c| matches!(c, Column::Launch(0, _)))
            .first()
            .copied();
        let launch_only = columns.iter().all(|c| match c {
            Column::Input(key) => SCENE_LAUNCH_KEYS.iter().any(|k| k.name == *key),
            _ => true,
        });
        let mut header = Header {
            contact_height_given: has(Column::Input("environment.contact_height")),
            line,
            tilt_given: has(Column::Input("bat.tilt")),
            names,
            columns,
            inputs,
            keep: Vec::new(),
            read,
            launch,
            speed,
            launch_only,
            direction_given,
            hit_coordinates,
            cell_units,
        };
        header.check(setup)?;
        header.keep = (setup.keep.iter())
            .map(|name| {
                header.position(name).ok_or_else(|| {
                    format!(
                        "--keep {}: no column of that name in the header",
                        escape_cut(name, 80)
                    )
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(header)
    }

    /// The first column named `name`.
    pub(crate) fn position(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    /// Refuses a header that would answer wrong: no column an input, no
    /// launch speed or angle that any row can have, a swing not solvable.
    fn check(&self, setup: &Setup) -> Result<(), String> {
        if !self.columns.iter().any(|c| !matches!(c, Column::Ignored)) {
            return Err(format!(
                "{}: no column is an input (launch_speed, launch_angle, launch.*, or a key \
                 of `homerun keys`); columns separated by commas? first column: `{}`; \
                 --column NAME=COLUMN maps one (--column launch_speed=EV)",
                self.line,
                escape_cut(self.names.first().map_or("", String::as_str), 80)
            ));
        }
        // A launch value no column gives comes from --set, or from each
        // row's own swing where columns change it; else every row would fly
        // the preset's, which no one means.
        let scene = &setup.base.scene;
        let given = [scene.launch.speed, scene.launch.angle];
        let from_swing = |i: usize| {
            (scene.kind != SceneKind::BattedBall || given[i].is_none())
                && !self.swing_columns().is_empty()
                && !setup.solve_swings
        };
        let missing: Vec<usize> = (0..2)
            .filter(|&i| !self.has_launch(i) && !setup.gave(LAUNCH_KEYS[i]) && !from_swing(i))
            .collect();
        if !missing.is_empty() {
            let mut looked = Vec::new();
            let mut wanted = Vec::new();
            for &i in &missing {
                let names = columns::launch_entry(i).map_or(&[][..], |(e, _)| e.names);
                looked.push(format!("{} or {}", names.join(", "), LAUNCH_KEYS[i]));
                wanted.extend(names.iter().copied());
            }
            // Names the table does not read, nearest those wanted, but for
            // those that are something else.
            let unread: Vec<String> = (self.names.iter().zip(&self.columns))
                .filter(|(n, c)| matches!(c, Column::Ignored) && columns::lookalike(n).is_none())
                .map(|(n, _)| n.clone())
                .collect();
            let near = columns::nearest(&wanted, &unread);
            let near = match near.is_empty() {
                true => String::new(),
                false => format!(
                    "; did you mean {}? (--column NAME=COLUMN maps one)",
                    (near.iter().map(|n| format!("`{}`", escape_cut(n, 40))))
                        .collect::<Vec<_>>()
                        .join(" or ")
                ),
            };
            return Err(format!(
                "{}: no launch {} column (looked for {}){near}{}",
                self.line,
                (missing.iter().map(|&i| ["speed", "angle"][i]))
                    .collect::<Vec<_>>()
                    .join(" or "),
                looked.join("; "),
                setup.or_set(
                    &format!("{}=VALUE", LAUNCH_KEYS[missing[0]]),
                    "for every row"
                )
            ));
        }
        self.check_direction(setup)?;
        self.check_weather(setup)?;
        self.check_wind(setup)?;
        if setup.solve_swings {
            let missing: Vec<&str> = (NEEDED_FOR_SWINGS.iter().copied())
                .filter(|needed| {
                    !self.columns.iter().any(|c| {
                        matches!(c, Column::Swing(s, r)
                            if columns::name_of(columns::Becomes::Swing(*s, *r)) == *needed)
                    })
                })
                .collect();
            if !missing.is_empty() {
                return Err(format!(
                    "{}: no {} column{}: a swing is solved from bat tracking (bat_speed), \
                     the pitch's kinematics (vx0, vy0, vz0, ax, ay, az) and the launch \
                     (launch_speed, launch_angle), as a Baseball Savant export since 2024 has \
                     them",
                    self.line,
                    missing.join(", "),
                    plural(missing.len())
                ));
            }
        }
        Ok(())
    }

    /// Whether a column is `column`.
    pub(crate) fn has(&self, column: SavantColumn) -> bool {
        self.columns.contains(&Column::Savant(column))
    }

    /// The names of the columns read that are not keys of `homerun keys`.
    pub(crate) fn savant_used(&self) -> Vec<&str> {
        (self.names.iter().zip(&self.columns))
            .filter(|(_, c)| {
                matches!(
                    c,
                    Column::Savant(_) | Column::Launch(_, Unit::Mph | Unit::Degrees | Unit::Rpm)
                )
            })
            .map(|(n, _)| n.as_str())
            .collect()
    }

    /// The file's name of `column`, if it has it.
    pub(crate) fn name_of(&self, column: &Column) -> Option<&str> {
        let at = self.columns.iter().position(|c| c == column)?;
        Some(&self.names[at])
    }

    pub(crate) fn has_launch(&self, index: usize) -> bool {
        (self.columns.iter()).any(|c| matches!(c, Column::Launch(i, _) if *i == index))
    }

    /// The input columns that change a row's swing, and so the launch
    /// values the row takes from it: the pitch, the bat, the ball and
    /// gravity (which bends the pitch, Eq. 3).
    pub(crate) fn swing_columns(&self) -> Vec<&str> {
        (self.names.iter().zip(&self.columns))
            .filter(|(_, c)| {
                matches!(c, Column::Input(key)
                    if ["pitch.", "bat.", "ball."].iter().any(|s| key.starts_with(s))
                        || *key == "environment.gravity")
            })
            .map(|(n, _)| n.as_str())
            .collect()
    }

    pub(crate) fn ignored(&self) -> Vec<&str> {
        (self.names.iter().zip(&self.columns))
            .filter(|(_, c)| matches!(c, Column::Ignored))
            .map(|(n, _)| n.as_str())
            .collect()
    }
}

/// What a tracked row is solved at where it does not say, from the header
/// and the command line.
impl Header {
    /// The bat's tilt a tracked row without `swing_path_tilt` is solved
    /// at: MLB's league average ([`bat_tracking::LEAGUE_SWING_PATH_TILT`]),
    /// unless `--set bat.tilt` or a `bat.tilt` column gives one (`None`:
    /// the row's scene's).
    fn tilt_prior(&self, setup: &Setup) -> Option<f64> {
        (!setup.gave("bat.tilt") && !self.tilt_given)
            .then_some(bat_tracking::LEAGUE_SWING_PATH_TILT)
    }

    /// What a tracked row is solved at where it does not say: the tilt
    /// ([`Header::tilt_prior`]), and whether its season's bat replaces the
    /// preset's. It does unless `--set` or a column gives
    /// `bat.effective_mass`, or the preset is the user's own (a file, as
    /// `calibrate --impact --save` writes): a bundled preset's bat is the
    /// paper's, of 1998.
    pub(crate) fn priors(&self, setup: &Setup) -> Priors {
        let bat_given = setup.gave("bat.effective_mass")
            || (self.columns).contains(&Column::Input("bat.effective_mass"));
        Priors {
            tilt: self.tilt_prior(setup),
            season_bats: !bat_given && setup.base.source == Source::Bundled,
        }
    }
}

/// The header of `records`, checked against `setup`; refused when empty.
pub(crate) fn header_of<R: BufRead>(
    records: &mut Records<R>,
    setup: &Setup,
) -> Result<Header, String> {
    Header::new(read_header(records)?.ok_or("the input is empty")?, setup)
}
