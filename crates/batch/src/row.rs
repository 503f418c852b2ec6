//! A batch's row made a scene to fly, or the reason it cannot be one:
//! each cell read as its column says ([`crate::columns`]).

use analysis::savant::RowLaunch;
use model::aero::UnknownModel;
use model::keys::{InputBatch, InputError, Key, out_of_range_shown};
use model::park::GivenWeather;
use model::scene::{Scene, UnknownHand};
use preset::{FIELD_KEYS, Fence, cut, escape_cut};
use units::{UnitSystem, significant};

use crate::Setup;
use crate::away::Away;
use crate::cells::{CONTACT_HEIGHT, ContactFrom, SavantCells, measure, unit_unknown};
use crate::columns::{Column, LAUNCH_KEYS, SavantColumn, Unit};
use crate::header::{Header, launch_key};
use crate::kinds::Called;
use crate::own_launch::SwingLaunches;
use crate::read::Fields;
use crate::swing::{RowSwing, SwingCells};
use crate::words::plural;

/// One row, ready to fly.
pub(crate) struct Job {
    pub(crate) line: usize,
    /// Its speed, angle and any spin and direction it gave; the rest is
    /// `launch`'s to fill in.
    pub(crate) scene: Scene,
    pub(crate) launch: RowLaunch,
    /// The generic fence (the preset's, or the row's `field.*`), used when
    /// the row is at no park.
    pub(crate) fence: Fence,
    /// The index of the row's park, if it is at one.
    pub(crate) park: Option<usize>,
    /// The park's earlier walls it met ([`model::park::Park::earlier_on`]), if not its
    /// fence as given.
    pub(crate) earlier: Option<usize>,
    /// Its `home_team`, where no park answers to it (a college or summer
    /// league's team in a Trackman file): the row is at no park, and the
    /// summary names the code, where the row was refused before.
    pub(crate) unknown_park: Option<String>,
    /// Its first tracking cell outside its range, named: the ball flies,
    /// its swing is not solved.
    pub(crate) swing_note: Option<String>,
    /// Its `home_team`'s park, where the row was played elsewhere (the
    /// park was not home on its date, or not for all its season): the row
    /// is at no park, and the summary names the park and the season.
    pub(crate) away: Option<Away>,
    /// Its season: `game_year` (or `season`), else its date's year.
    pub(crate) season: Option<i32>,
    /// Its spin was estimated without its batter's side (no `stand`, or a
    /// side not recorded): either side's average.
    pub(crate) side_unknown: bool,
    /// A fence was given (the preset's `[field]`, `field.*` by --set or a
    /// column): a row at no park is judged there.
    pub(crate) fence_given: bool,
    /// Statcast's distance (m).
    pub(crate) statcast: Option<f64>,
    /// Measured hang time (s) and apex (m), for `calibrate`.
    pub(crate) hang_time: Option<f64>,
    pub(crate) apex: Option<f64>,
    /// The `--keep` cells, as read.
    pub(crate) kept: Vec<String>,
    /// Its hit coordinates are the plate's: it has no spray.
    pub(crate) spray_at_plate: bool,
    /// Its tracking cells, and (when swings are solved) its swing.
    pub(crate) tracked: SwingCells,
    pub(crate) swing: Option<RowSwing>,
    /// The air keys given, by `--set` and by the row: a park keeps them.
    pub(crate) given: GivenWeather,
    /// Where its contact height came from.
    pub(crate) contact: ContactFrom,
    /// What Savant called it, for the summary.
    pub(crate) called: Called,
    /// What a tracker measured of its spin, and took.
    pub(crate) spin_measured: SpinMeasured,
}

/// What a row's tracker measured of its spin (`hit_spin_rate`,
/// `hit_spin_axis`), and so what of it is flown.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum SpinMeasured {
    /// Nothing (no column, an empty cell, or a spin given otherwise).
    #[default]
    No,
    /// A rate of 0, the tracker's "none measured": the spin is estimated.
    Zero,
    /// Its size, about the estimate's axis (no axis measured).
    Size,
    /// Its size and axis: its backspin and sidespin.
    Whole,
}

impl SpinMeasured {
    /// Whether the row flew a measured spin.
    pub(crate) fn taken(self) -> bool {
        matches!(self, SpinMeasured::Size | SpinMeasured::Whole)
    }
}

impl Job {
    /// Whether the row has a fence to be judged at: its park's, or one
    /// given. Else only a foul ball is called (no generic wall stands in).
    pub(crate) fn fence_known(&self) -> bool {
        self.park.is_some() || self.fence_given
    }

    /// Whether Nathan's relation gave the row's spin (its size: a measured
    /// size about the estimate's axis is measured).
    pub(crate) fn spin_estimated(&self) -> bool {
        self.launch.estimates_spin() && self.spin_measured != SpinMeasured::Size
    }
}

/// What a row turned out to be.
pub(crate) enum Row {
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

/// The row on `line`, its `fields` as read, the launch values it leaves
/// to its swing filled in where its swing is known (see [`SwingLaunches`]:
/// its swing in the row's own air, where it was hit, as its measured
/// values were; each park then flies that launch in the park's air). A row that flies is pushed onto `jobs`, built there
/// (a job holds a scene: moving it cost more than reading its cells).
pub(crate) fn parse_row(
    header: &Header,
    setup: &Setup,
    (line, fields): (usize, Fields),
    swings: &mut SwingLaunches,
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
        earlier: None,
        unknown_park: None,
        swing_note: None,
        away: None,
        season: None,
        side_unknown: false,
        // The presets' [field] is the explorer's drawing, no park's wall.
        fence_given: FIELD_KEYS.iter().any(|k| setup.gave(k.name)),
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
        spin_measured: SpinMeasured::No,
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
    swings: &mut SwingLaunches,
    job: &mut Job,
) -> Result<(), String> {
    let cell = |i: usize| cell(fields, i);
    let Job {
        scene,
        fence,
        given,
        fence_given,
        unknown_park,
        swing_note,
        ..
    } = job;
    let mut savant = SavantCells::default();
    let mut tracked = SwingCells::default();
    let (mut spin_given, mut sidespin_given) =
        (setup.gave("launch.spin"), setup.gave("launch.sidespin"));
    // One row is one source: ρ beside the weather is refused.
    let mut batch = InputBatch::new();
    // Statcast's columns read in their units, named only if the row fails.
    let mut converted = false;
    for &i in &header.read {
        let (column, name) = (&header.columns[i], &header.names[i]);
        // A bare number in the unit its mapping gave the column (only a
        // key's column is given one).
        let with_unit = match &header.cell_units[i] {
            Some(unit) if cell(i).parse::<f64>().is_ok() => Some(format!("{}{unit}", cell(i))),
            _ => None,
        };
        let value = with_unit.as_deref().unwrap_or(cell(i));
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
                Err(format!("{} is empty", LAUNCH_KEYS[index]))
            }
            _ if value.is_empty() => Ok(()), // the preset's value
            Column::Savant(column) => savant.read(column, value, setup).map(|()| {
                if column == SavantColumn::HomeTeam && savant.park.is_none() {
                    *unknown_park = Some(cut(value, 20));
                }
            }),
            // A tracking cell no swing takes (a measurement's glitch, as
            // an attack direction of -145°): the ball still flies from its
            // launch, the swing is not solved, and the cell is named.
            Column::Swing(column, range) => {
                if let Err(why) = tracked.read((column, range), value)
                    && swing_note.is_none()
                {
                    *swing_note = Some(why);
                }
                Ok(())
            }
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
                    None => number()
                        .map(|v| unit.to_si(v))
                        .map_err(|e| unit_unknown(name, value, (quantity, unit)).unwrap_or(e)),
                };
                // A measured exit speed past any batted ball's is a column in
                // another unit (a metric Trackman file's km/h), not a ball.
                let si = si.and_then(|si| {
                    let mph = Unit::Mph.from_si(si);
                    match index == 0 && mph > FASTEST_BATTED_BALL_MPH {
                        true => Err(too_fast(name, value, mph, header.cell_units[i].is_some())),
                        false => Ok(si),
                    }
                });
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
                *fence_given = true;
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
    // A tracker's measured spin, where nothing else gives the spin: whole
    // with its axis or vector ([`SavantCells::measured_spin`]), else its
    // size about the estimate's axis. A rate of 0 is none measured: the
    // estimate's, counted.
    let mut measured_spin = None;
    let own_direction = header.direction_given || setup.gave("launch.direction");
    let launch = (
        scene.launch.angle,
        scene.launch.direction.filter(|_| own_direction),
    );
    job.spin_measured = match savant.spin_rate {
        _ if spin_given || sidespin_given => SpinMeasured::No,
        None => SpinMeasured::No,
        Some(0.0) => SpinMeasured::Zero,
        Some(rate) => match savant.measured_spin(rate, launch) {
            Some((backspin, sidespin)) => {
                scene.launch.spin = Some(backspin);
                scene.launch.sidespin = Some(sidespin);
                (spin_given, sidespin_given) = (true, true);
                SpinMeasured::Whole
            }
            None => {
                measured_spin = Some(rate);
                SpinMeasured::Size
            }
        },
    };
    let contact = savant.start_at_pitch(
        scene,
        header.contact_height_given || setup.gave(CONTACT_HEIGHT),
    );
    let ((park, earlier), away) = match (setup.park, savant.park) {
        (Some(park), _) => ((Some(park), None), None),
        (None, Some(park)) => savant.at_home(park, setup),
        (None, None) => ((None, None), None),
    };
    if let Some(index) = park {
        given.park_air(&mut scene.environment, setup.parks.parks[index].elevation);
    }
    // The air where it was played, though no fence here stands for it: a
    // neutral site's, or its park's in a season of other walls.
    if let Some(elevation) = away.and_then(|away| away.air_elevation) {
        given.park_air(&mut scene.environment, elevation);
    }
    let valid = swings.validate(scene, header.launch_only.then_some(park));
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
                Column::Launch(i, unit) if LAUNCH_KEYS[*i] == key => unit.quantity(),
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
        measured_spin,
    };
    (job.park, job.earlier) = (park, earlier);
    (job.away, job.season) = (away, savant.season());
    job.contact = contact;
    job.called = savant.called;
    // The side moves the estimate (Nathan's ±849 rpm of sidespin): a row
    // estimated without one, no `stand` or a side not recorded, is counted.
    job.side_unknown = job.launch.estimates_spin() && savant.side.is_none();
    job.tracked = tracked;
    job.spray_at_plate = savant.at_plate() && !header.direction_given;
    (job.statcast, job.hang_time, job.apex) = (savant.distance, savant.hang_time, savant.apex);
    Ok(())
}

/// The fastest a measured batted ball may be (mph), with room above
/// Statcast's fastest since 2015, all under 123 mph (Oneil Cruz's and
/// Giancarlo Stanton's; MLB.com's exit velocity leaderboards).
const FASTEST_BATTED_BALL_MPH: f64 = 130.0;

/// Why an exit speed of `mph`, past [`FASTEST_BATTED_BALL_MPH`], is
/// refused, with the mapping that reads a column of km/h where the
/// column's unit was taken.
fn too_fast(name: &str, value: &str, mph: f64, unit_mapped: bool) -> String {
    let hint = match unit_mapped {
        true => String::new(),
        false => format!(
            "; a column in km/h is mapped so: --column launch_speed={}:km/h",
            escape_cut(name, 40)
        ),
    };
    format!(
        "{} = {:?}: {mph:.1} mph, faster than any batted ball measured \
         ({FASTEST_BATTED_BALL_MPH} mph at most){hint}",
        escape_cut(name, 80),
        cut(value, 80),
    )
}
