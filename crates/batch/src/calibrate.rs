//! `calibrate`'s sinks: the measured flights its fits take (each launch
//! completed as `fly --batch` completes it, or launched by its solved
//! swing with `--spin swing`), grouped by a column with `--by`; and the
//! tracked swings of `calibrate --impact`. Read on the one path, bad rows
//! named and counted as every command names them.

use std::io::BufRead;

use analysis::bat_tracking::TrackedSwing;
use analysis::calibrate::{self, Measured};
use analysis::precision::Purpose;
use analysis::savant;

use crate::columns::SavantColumn;
use crate::flights::check_launch;
use crate::header::header_of;
use crate::pieces::{Outcome, Piece, Stage, stream};
use crate::read::Records;
use crate::read::read_header;
use crate::row::Job;
use crate::setup::Setup;
use crate::swing_solve::solve_row;
use crate::tally::LOWEST_FLIGHT;
use crate::words::plural;

/// A group's rows fewer than this are named, not fitted: the same minimum
/// for every fit, grouped or not.
pub const FEWEST_ROWS: usize = 10;

/// What was read: the measured rows, and the others counted.
#[derive(Debug, Default)]
pub struct Measurements {
    pub measured: Vec<Measured>,
    /// Each measured row's group (`--by`'s; empty without it).
    pub groups: Vec<String>,
    /// With `--spin swing`: the rows launched by their solved swing.
    pub spin_from_swing: Option<usize>,
    pub rows: usize,
    pub without_distance: usize,
    /// Launched below `LOWEST_FLIGHT` (10°): a grounder's distance is where it
    /// was fielded.
    pub grounders: usize,
    /// With a measurement outside its plausible range (each named).
    pub implausible: usize,
    /// The header has hit coordinates but the row none.
    pub without_spray: usize,
    /// Fielded where no flight comes down (a spray no direction lands on).
    pub unlanded: usize,
    /// Measured rows at no park (no `home_team`, an unknown one, or
    /// played away) and no neutral site's elevation: flown in the preset's
    /// air, whose level the fit then takes up.
    pub in_preset_air: usize,
    pub outcome: Outcome,
}

/// What `--by` groups on: a column's cell, the month of its date, or the
/// season (`season` or `game_year`, or the year of its date).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum By {
    Column(String),
    Month,
    Season,
}

impl By {
    pub fn of(name: &str) -> By {
        match name {
            "month" => By::Month,
            "season" | "game_year" | "year" => By::Season,
            column => By::Column(column.to_owned()),
        }
    }

    /// The header column it reads, of `names`.
    fn column<'a>(&'a self, names: &[String]) -> Result<&'a str, String> {
        let candidates: &[&str] = match self {
            By::Column(name) if names.iter().any(|n| n == name) => return Ok(name),
            By::Column(name) => {
                return Err(format!(
                    "--by {}: no column of that name in the header",
                    preset::escape_cut(name, 80)
                ));
            }
            By::Month => &["game_date", "Date"],
            By::Season => &["game_year", "season", "game_date", "Date"],
        };
        (candidates.iter().copied())
            .find(|c| names.iter().any(|n| n == c))
            .ok_or_else(|| format!("--by: no column {} in the header", candidates.join(" or ")))
    }

    /// A row's group from its cell: a date as YYYY-MM (or YYYY), from ISO
    /// `2024-05-03` or US `5/3/2024`; a year as it is.
    fn group(&self, cell: &str) -> Result<String, String> {
        let cell = cell.trim();
        let date = crate::dates::year_month;
        let unreadable = || {
            format!(
                "--by: date {:?} is neither YYYY-MM-DD nor M/D/YYYY (nor M/D/YY)",
                preset::cut(cell, 40)
            )
        };
        match self {
            By::Column(_) => Ok(cell.to_owned()),
            By::Month => date(cell)
                .map(|(y, m)| format!("{y}-{m:02}"))
                .ok_or_else(unreadable),
            // A year as the rows read `game_year` ([`crate::dates::season`]).
            By::Season => match cell.parse::<f64>().map(crate::dates::season) {
                Ok(Some(year)) => Ok(year.to_string()),
                Ok(None) => Err(format!(
                    "--by season: {:?} is no year (a whole number from 1800 to 2200)",
                    preset::cut(cell, 40)
                )),
                Err(_) => date(cell).map(|(y, _)| y.to_string()).ok_or_else(|| {
                    format!(
                        "--by season: {:?} is neither a year nor a date (YYYY-MM-DD, M/D/YYYY)",
                        preset::cut(cell, 40)
                    )
                }),
            },
        }
    }
}

/// What a piece measured.
#[derive(Default)]
struct Made {
    measured: Vec<(Measured, String, bool)>,
    counts: Measurements,
    /// Rows left out for an implausible measurement: (line, why).
    implausible: Vec<(usize, String)>,
    /// Rows read whole that failed here (named with the others).
    late_failed: usize,
}

/// Reads every row of `input` into a measured flight (with `by`, its
/// group), the launches completed on the pool as `fly --batch` completes
/// them.
pub fn measured(
    setup: &mut Setup,
    input: impl BufRead,
    by: Option<&By>,
    note: &mut dyn FnMut(&str),
) -> Result<Measurements, String> {
    let mut records = Records::new(input);
    let (names, line) = read_header(&mut records)?.ok_or("the input is empty")?;
    if let Some(by) = by {
        setup.keep = vec![by.column(&names)?.to_owned()];
    }
    let header = crate::header::Header::new((names, line), setup)?;
    let sprayed = header.has(SavantColumn::HcX) || header.has(SavantColumn::HcY);
    let priors = header.priors(setup);
    let setup = &*setup;
    let options = Purpose::Solve.flight_options();
    let finish = |piece: &mut Piece<Made>| {
        let made = &mut piece.made;
        *made = Made::default();
        let mut wanted = Vec::new();
        for job in &mut piece.jobs {
            let counts = &mut made.counts;
            counts.rows += 1;
            let group = match by.map(|by| by.group(job.kept.first().map_or("", |c| c))) {
                Some(Err(why)) => {
                    piece.failed.push((job.line, why));
                    made.late_failed += 1;
                    continue;
                }
                Some(Ok(group)) => group,
                None => String::new(),
            };
            let flies = job.scene.batted_ball().angle >= LOWEST_FLIGHT;
            if job.statcast.is_none() {
                counts.without_distance += 1;
            } else if !flies {
                counts.grounders += 1;
            } else if sprayed && job.launch.spray.is_none() {
                counts.without_spray += 1;
            } else if let Err(why) = plausible(job) {
                counts.implausible += 1;
                made.implausible.push((job.line, why));
            } else {
                // `--spin swing`: launched as its impact sends the ball.
                if setup.solve_swings {
                    solve_row(job, setup.spray, priors);
                }
                wanted.push((job as &Job, group));
            }
        }
        let rows = wanted.iter().map(|(job, _)| (&job.scene, &job.launch));
        let launched = savant::launch_many(rows, setup.spray, &options);
        for ((job, group), launched) in wanted.into_iter().zip(launched) {
            // A ball fielded where no flight comes down says nothing of the
            // flight's length.
            let from = job.direction_from(launched.direction_from);
            if from == savant::DirectionFrom::SprayUnsolved {
                made.counts.unlanded += 1;
                continue;
            }
            // Checked as `fly --batch` checks it before its flight.
            if let Err(why) = check_launch(job, &launched.scene) {
                piece.failed.push((job.line, why));
                made.late_failed += 1;
                continue;
            }
            let measured = Measured {
                scene: launched.scene,
                distance: job.statcast.expect("a distance"),
                hang_time: job.hang_time,
                apex: job.apex,
            };
            let sited = job.park.is_some() || job.away.is_some_and(|a| a.air_elevation.is_some());
            made.counts.in_preset_air += usize::from(!sited);
            made.measured.push((measured, group, job.swing_solved()));
        }
        piece.answered = made.measured.len();
    };
    let mut read = Measurements::default();
    let mut implausible = Vec::new();
    let take = |piece: &mut Piece<Made>| {
        let made = &mut piece.made;
        let counts = &made.counts;
        // Every record is a row: read whole, or failed as it was read.
        read.rows += counts.rows + piece.without_launch + piece.failed.len() - made.late_failed;
        read.without_distance += counts.without_distance;
        read.grounders += counts.grounders;
        read.without_spray += counts.without_spray;
        read.implausible += counts.implausible;
        read.unlanded += counts.unlanded;
        read.in_preset_air += counts.in_preset_air;
        implausible.append(&mut made.implausible);
        for (measured, group, from_swing) in made.measured.drain(..) {
            read.measured.push(measured);
            read.groups.push(group);
            *read.spin_from_swing.get_or_insert(0) += usize::from(from_swing);
        }
        Ok(true)
    };
    read.outcome = stream(
        (setup, &header),
        &mut records,
        Stage::Parsed,
        finish,
        take,
        note,
    )?;
    for (line, why) in implausible.iter().take(NAMED_IMPLAUSIBLE) {
        note(&format!("line {line}: {why}; left out of the fit"));
    }
    if implausible.len() > NAMED_IMPLAUSIBLE {
        note(&format!(
            "{} more row{} with a measurement outside its range; left out of the fit",
            implausible.len() - NAMED_IMPLAUSIBLE,
            plural(implausible.len() - NAMED_IMPLAUSIBLE)
        ));
    }
    read.spin_from_swing = setup
        .solve_swings
        .then_some(read.spin_from_swing.unwrap_or(0));
    Ok(read)
}

/// The most rows named one by one as implausible; the rest are counted.
const NAMED_IMPLAUSIBLE: usize = 20;

/// Every row's tracked swing (`calibrate --impact`): rows without one are
/// counted, bad rows named. With them, the rows read (every record) and
/// how the batch went.
pub fn tracked_swings(
    setup: &Setup,
    input: impl BufRead,
    note: &mut dyn FnMut(&str),
) -> Result<(Vec<TrackedSwing>, usize, Outcome), String> {
    let mut records = Records::new(input);
    let header = header_of(&mut records, setup)?;
    let finish = |piece: &mut Piece<Vec<TrackedSwing>>| {
        piece.made.clear();
        let swings = piece.jobs.iter().map(|job| job.tracked_swing().ok());
        piece.made.extend(swings.flatten());
        piece.answered = piece.made.len();
    };
    let (mut swings, mut rows) = (Vec::new(), 0);
    let take = |piece: &mut Piece<Vec<TrackedSwing>>| {
        // Every record is a row: read whole, or failed as it was read.
        rows += piece.jobs.len() + piece.without_launch + piece.failed.len();
        swings.append(&mut piece.made);
        Ok(true)
    };
    let outcome = stream(
        (setup, &header),
        &mut records,
        Stage::Parsed,
        finish,
        take,
        note,
    )?;
    Ok((swings, rows, outcome))
}

/// Refuses a row whose measurements are not plausible
/// ([`calibrate::implausible`]): the column, its value and the range
/// accepted, in the CSV's units.
fn plausible(job: &Job) -> Result<(), String> {
    let Some(distance) = job.statcast else {
        return Ok(());
    };
    let Some((range, value)) = calibrate::implausible(distance, job.hang_time, job.apex) else {
        return Ok(());
    };
    // Savant's feet, for messages about its columns.
    const FEET_PER_METRE: f64 = 1.0 / 0.3048;
    let (column, unit, scale) = if range == calibrate::HANG_TIME {
        ("hang_time", "s", 1.0)
    } else if range == calibrate::APEX {
        ("apex", "ft", FEET_PER_METRE)
    } else {
        ("hit_distance_sc", "ft", FEET_PER_METRE)
    };
    let number = |v: f64| match v.abs() >= 1e6 {
        true => format!("{v:.3e}"),
        false => {
            let text = format!("{v:.2}");
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        }
    };
    Err(format!(
        "{column} = {} {unit}: outside (0, {}] {unit} ({})",
        number(value * scale),
        number((range.high * scale * 10.0).round() / 10.0),
        range.why
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn months_and_seasons_read_iso_and_us_dates_and_refuse_others() {
        assert_eq!(By::Month.group("2024-05-03").unwrap(), "2024-05");
        assert_eq!(By::Month.group("10/1/2022").unwrap(), "2022-10");
        assert_eq!(By::Month.group("5/3/2022 12:00").unwrap(), "2022-05");
        assert_eq!(By::Season.group("2025").unwrap(), "2025");
        assert_eq!(By::Season.group("4/30/2024").unwrap(), "2024");
        // A season written by pandas as a float; not a fraction of one.
        assert_eq!(By::Season.group("2019.0").unwrap(), "2019");
        assert!(By::Season.group("2019.5").unwrap_err().contains("no year"));
        assert!(By::Season.group("0000").is_err());
        assert!(
            By::Season
                .group("soon")
                .unwrap_err()
                .contains("neither a year nor a date")
        );
        // Yakkertech's two-digit year; three digits are no year.
        assert_eq!(By::Month.group("10/1/20").unwrap(), "2020-10");
        assert!(By::Month.group("10/1/202").is_err());
        assert!(
            By::Month
                .group("yesterday")
                .unwrap_err()
                .contains("\"yesterday\"")
        );
        assert_eq!(By::of("game_year"), By::Season);
    }
}
