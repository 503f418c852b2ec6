//! `homerun calibrate FILE [--save NAME]`: the rows of a CSV read as
//! `fly --batch` reads them (a Savant export as it comes), each launch
//! completed as it completes them, and the factors on C_D and C_L fitted
//! to the measured distances, and hang times or apexes where measured
//! ([`crate::analysis::calibrate`]).

use std::io::{self, BufRead};
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use super::output::band_name;
use super::pieces::PIECE_ROWS;
use super::read::{MAX_RECORD_BYTES, Records};
use super::rows::{Header, Job, Row};
use super::savant_columns::{SavantColumn, Setup};
use crate::analysis::calibrate::{self, Errors, Fit, LiftFrom, Measured};
use crate::analysis::precision::Purpose;
use crate::analysis::savant;
use crate::cli::UsageError;
use crate::cli::hit::labelled;
use crate::cli::shown::Shown;
use crate::preset::{Preset, Source, escape_cut};
use crate::units::Quantity;

/// What was read: the measured rows, and the others counted.
struct Read {
    measured: Vec<Measured>,
    /// Each measured row's group (`--by`'s cell; empty without `--by`).
    groups: Vec<String>,
    /// With `--spin swing`: the measured rows launched by their solved
    /// swing's impact (the others by Nathan's relation).
    spin_from_swing: Option<usize>,
    rows: usize,
    without_distance: usize,
    /// Rows launched below [`LOWEST_FLIGHT`]: a grounder's distance is
    /// where it was fielded, not where a flight came down.
    grounders: usize,
    /// Rows with a measurement outside its plausible range, left out (each
    /// named on stderr).
    implausible: usize,
    /// Rows whose header has hit coordinates but the row none: their launch
    /// direction would be a guess, so they are left out of the fit.
    without_spray: usize,
    skipped: usize,
}

/// `--save NAME` in the presets folder `dir` (if there is one), and
/// whether `--force` was given.
pub(in crate::cli) struct Save<'a> {
    pub name: &'a str,
    pub dir: Option<&'a Path>,
    pub force: bool,
}

/// The most rows named one by one as implausible; the rest are counted.
const NAMED_IMPLAUSIBLE: usize = 20;

/// The lowest launch angle (rad) whose distance is a flight's: 10°, where
/// Statcast's own bands put the line drive (below it the ball bounces
/// before anyone fields it, and `hit_distance_sc` is where it was fielded).
/// A whole export, grounders and all, then calibrates as its balls in the
/// air do.
pub(super) const LOWEST_FLIGHT: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// Groups with fewer rows are named, not fitted.
const FEWEST_IN_GROUP: usize = 10;

/// Runs `calibrate` on `source` ("-" for stdin): the text (or JSON) to print.
pub(in crate::cli) fn run(
    setup: &Setup,
    source: &str,
    save: Option<Save>,
    lift: bool,
    json: bool,
    shown: Shown,
) -> Result<String, UsageError> {
    let failed = |message| failed(source, message);
    let read = read_source(source, save.as_ref(), |input| read(setup, input))?;
    let options = Purpose::Readout.flight_options();
    let fit = calibrate::fit(&read.measured, &options, lift).map_err(|e| failed(e.to_string()))?;

    let at_bounds: Vec<String> = fit
        .at_bounds()
        .iter()
        .map(|(key, value, (low, high))| {
            format!("{key} = {value:.4} ended at the end of [{low}, {high}] searched")
        })
        .collect();
    let refusal = (!at_bounds.is_empty()).then(|| {
        format!(
            "{}: the measurements pull {} further than the model can follow; not saved (--force to save anyway)",
            at_bounds.join(", "),
            if at_bounds.len() == 1 { "it" } else { "them" }
        )
    });
    let description = format!(
        "{}, calibrated on {} ({} rows{}): model.drag_scale = {:.4} ± {:.4}{}",
        setup.base.name,
        escape_cut(source, 80),
        fit.after.rows,
        if setup.solve_swings {
            ", each with its solved swing's spin"
        } else {
            ""
        },
        fit.drag_scale.value,
        fit.drag_scale.uncertainty,
        fit.lift_scale.map_or(String::new(), |l| format!(
            ", model.lift_scale = {:.4} ± {:.4}",
            l.value, l.uncertainty
        ))
    );
    let saved = save_fitted(save, (setup, source), refusal, description, |scene| {
        scene.drag_scale *= fit.drag_scale.value;
        if let Some(lift) = fit.lift_scale {
            scene.lift_scale *= lift.value;
        }
    })?;
    if json {
        let mut value = serde_json::json!({
            "rows": read.rows,
            "measured": read.measured.len(),
            "without_distance": read.without_distance,
            "grounders": read.grounders,
            "implausible": read.implausible,
            "without_spray": read.without_spray,
            "skipped": read.skipped,
            "spin_from_swing": read.spin_from_swing,
            "fit": fit,
            "at_bound": fit.at_bounds().iter().map(|b| b.0).collect::<Vec<_>>(),
        });
        if let Some(path) = &saved {
            value["saved"] = path.display().to_string().into();
        }
        return Ok(super::super::pretty(&value));
    }
    Ok(text(&read, &fit, &at_bounds, saved.as_deref(), shown))
}

/// `calibrate --by COLUMN`: the fit of each group of rows apart (by the
/// column's cell, or `month`: game_date's year and month), one line a
/// group, in the groups' order.
pub(in crate::cli) fn run_by(
    mut setup: Setup,
    source: &str,
    by: &str,
    lift: bool,
    json: bool,
    shown: Shown,
) -> Result<String, UsageError> {
    let failed = |message| failed(source, message);
    let month = by == "month";
    setup.keep = vec![if month { "game_date" } else { by }.to_owned()];
    let read = read_source(source, None, |input| {
        read(&setup, input).map_err(|e| e.replace("--keep", "--by"))
    })?;
    let mut groups: std::collections::BTreeMap<String, Vec<Measured>> = Default::default();
    for (measured, cell) in read.measured.iter().zip(&read.groups) {
        // Savant's dates are YYYY-MM-DD.
        let key = match month {
            true => cell.chars().take(7).collect(),
            false => cell.clone(),
        };
        groups.entry(key).or_default().push(*measured);
    }
    let options = Purpose::Readout.flight_options();
    let d = |m: f64| shown.value(Quantity::Distance, m, 1);
    let mut lines = Vec::new();
    let mut fits = Vec::new();
    for (group, measured) in &groups {
        let name = escape_cut(if group.is_empty() { "(empty)" } else { group }, 24);
        if measured.len() < FEWEST_IN_GROUP {
            lines.push(format!(
                "{name:<12} {:>6} rows: too few to fit",
                measured.len()
            ));
            fits.push(serde_json::json!({ "group": group, "rows": measured.len() }));
            continue;
        }
        let fit =
            calibrate::fit(measured, &options, lift).map_err(|e| failed(format!("{name}: {e}")))?;
        let lift = fit.lift_scale.map_or(String::new(), |l| {
            format!("  model.lift_scale = {:.4} ± {:.4}", l.value, l.uncertainty)
        });
        let signed = |m: f64| format!("{}{}", if m >= 0.0 { "+" } else { "-" }, d(m.abs()));
        lines.push(format!(
            "{name:<12} {:>6} rows  model.drag_scale = {:.4} ± {:.4}{lift}  median {} → {}, median |error| {} → {}{}",
            fit.after.rows,
            fit.drag_scale.value,
            fit.drag_scale.uncertainty,
            signed(fit.before.median),
            signed(fit.after.median),
            d(fit.before.median_absolute),
            d(fit.after.median_absolute),
            if fit.at_bounds().is_empty() { "" } else { "  (at a bound)" }
        ));
        fits.push(serde_json::json!({ "group": group, "rows": measured.len(), "fit": fit }));
    }
    if json {
        let value = serde_json::json!({ "by": by, "groups": fits, "rows": read.rows,
            "measured": read.measured.len(), "grounders": read.grounders });
        return Ok(super::super::pretty(&value));
    }
    let mut text = format!(
        "by {}: {} groups, {} of {} rows measured (launched at 10° or more, with a distance and hit coordinates)\n",
        escape_cut(by, 40),
        groups.len(),
        read.measured.len(),
        read.rows
    );
    for line in lines {
        text += &line;
        text.push('\n');
    }
    Ok(text)
}

/// Calibrating on `source` failed: `message` says why.
pub(super) fn failed(source: &str, message: String) -> UsageError {
    UsageError::Calibrate {
        input: escape_cut(source, 200),
        message,
    }
}

/// `--save NAME`: the base preset, described by `description`, with
/// `fitted` applied to its scene, saved; refused (unless forced) with
/// `refusal` where a fitted value ended at the end of its search.
pub(super) fn save_fitted(
    save: Option<Save>,
    (setup, source): (&Setup, &str),
    refusal: Option<String>,
    description: String,
    fitted: impl FnOnce(&mut crate::model::scene::Scene),
) -> Result<Option<PathBuf>, UsageError> {
    let Some(Save { name, dir, force }) = save else {
        return Ok(None);
    };
    let no_folder = || failed(source, format!("--save: {}", crate::preset::NO_FOLDER));
    let dir = dir.ok_or_else(no_folder)?;
    if let Some(message) = refusal.filter(|_| !force) {
        return Err(UsageError::CalibrateSave {
            name: escape_cut(name, 64),
            message,
        });
    }
    let mut preset = Preset {
        name: name.to_owned(),
        description,
        scene: setup.base.scene,
        fence: setup.base.fence,
        source: Source::Bundled,
    };
    fitted(&mut preset.scene);
    preset.scene.validate()?;
    Ok(Some(preset.save(dir, force)?))
}

/// Refuses a name `--save` cannot take (before the work), then reads
/// `source` ("-" for stdin) with `read`.
pub(super) fn read_source<T>(
    source: &str,
    save: Option<&Save>,
    read: impl FnOnce(Box<dyn BufRead>) -> Result<T, String>,
) -> Result<T, UsageError> {
    let failed = |message| failed(source, message);
    if let Some(Save {
        name,
        dir: Some(dir),
        force,
    }) = save
    {
        crate::preset::check_save(name, dir, *force)?;
    }
    let input: Box<dyn BufRead> = if source == "-" {
        Box::new(io::stdin().lock())
    } else {
        let file = std::fs::File::open(source).map_err(|e| failed(e.to_string()))?;
        Box::new(io::BufReader::with_capacity(MAX_RECORD_BYTES, file))
    };
    read(input).map_err(failed)
}

/// Reads every row into a measured flight, the launches completed in
/// parallel.
fn read(setup: &Setup, input: impl BufRead) -> Result<Read, String> {
    let mut records = Records::new(input);
    let mut header = match super::read_header(&mut records)? {
        Some(names) => Header::new(names).map_err(|e| format!("line 1 (the header): {e}"))?,
        None => return Err("the input is empty".to_owned()),
    };
    header.keep(&setup.keep)?;
    if setup.solve_swings {
        header
            .read_swings()
            .map_err(|e| format!("line 1 (the header): {e}"))?;
    }
    let (mut skipped, mut rows) = (0, 0);
    let mut jobs = super::parse_all(&mut records, &header, setup, |row| match row {
        None => skipped += 1,
        Some(Row::Job) => rows += 1,
        Some(Row::Bad { .. } | Row::NoLaunch) => {
            rows += 1;
            skipped += 1;
        }
    })?;
    let options = Purpose::Solve.flight_options();
    let sprayed = header.has(SavantColumn::HcX) || header.has(SavantColumn::HcY);

    // Launched as `fly --batch` launches them: a piece's solves together.
    let mut implausible = 0;
    let flies = |job: &&Job| job.scene.batted_ball().angle >= LOWEST_FLIGHT;
    let grounders = (jobs.iter())
        .filter(|job| job.statcast.is_some() && !flies(job))
        .count();
    let without_spray = (jobs.iter())
        .filter(|j| sprayed && j.statcast.is_some() && j.launch.spray.is_none() && flies(j))
        .count();
    let wanted: Vec<bool> = (jobs.iter())
        .map(|job| {
            let fit = (!sprayed || job.launch.spray.is_some()) && job.statcast.is_some();
            fit && flies(&job)
                && match plausible(job) {
                    Ok(()) => true,
                    Err(why) => {
                        implausible += 1;
                        if implausible <= NAMED_IMPLAUSIBLE {
                            eprintln!("line {}: {why}; skipped", job.line);
                        }
                        false
                    }
                }
        })
        .collect();
    // `--spin swing`: a row with a solved swing is launched as its impact
    // sends the ball (the spin, and the direction that lands on the spray),
    // as `fly --batch --spin swing` launches it; the others as above.
    if setup.solve_swings {
        let tilt = setup.tilt_prior(&header);
        (jobs.par_iter_mut().zip(&wanted))
            .filter(|(_, wanted)| **wanted)
            .for_each(|(job, _)| super::swing_columns::solve_row(job, setup.spray, tilt));
    }
    let wanted: Vec<&Job> = (jobs.iter().zip(wanted))
        .filter_map(|(job, wanted)| wanted.then_some(job))
        .collect();
    if implausible > NAMED_IMPLAUSIBLE {
        eprintln!(
            "{} more rows with a measurement outside its range; skipped",
            implausible - NAMED_IMPLAUSIBLE
        );
    }
    let launched: Vec<Option<(Measured, String, bool)>> = wanted
        .par_chunks(PIECE_ROWS)
        .flat_map_iter(|piece| {
            let rows = piece.iter().map(|job| (&job.scene, &job.launch));
            let launched = savant::launch_many(rows, setup.spray, &options);
            piece.iter().zip(launched).map(|(job, launched)| {
                // A ball fielded where no flight comes down says nothing
                // of the flight's length.
                if job.direction_from(launched.direction_from)
                    == savant::DirectionFrom::SprayUnsolved
                {
                    return None;
                }
                launched.scene.validate().ok()?;
                let measured = Measured {
                    scene: launched.scene,
                    distance: job.statcast?,
                    hang_time: job.hang_time,
                    apex: job.apex,
                };
                let group = job.kept.first().cloned().unwrap_or_default();
                Some((measured, group, job.swing_solved()))
            })
        })
        .collect();
    let without_distance = jobs.iter().filter(|j| j.statcast.is_none()).count();
    let launched: Vec<_> = launched.into_iter().flatten().collect();
    let spin_from_swing =
        (setup.solve_swings).then(|| launched.iter().filter(|(_, _, swing)| *swing).count());
    let (measured, groups): (Vec<Measured>, Vec<String>) =
        launched.into_iter().map(|(m, g, _)| (m, g)).unzip();
    skipped +=
        jobs.len() - without_distance - grounders - without_spray - implausible - measured.len();
    Ok(Read {
        measured,
        groups,
        spin_from_swing,
        rows,
        without_distance,
        grounders,
        implausible,
        without_spray,
        skipped,
    })
}

/// Refuses a row whose measurements are not plausible ([`calibrate::implausible`]):
/// the column, its value and the range accepted, in the CSV's units.
fn plausible(job: &Job) -> Result<(), String> {
    let Some(distance) = job.statcast else {
        return Ok(());
    };
    let Some((range, value)) = calibrate::implausible(distance, job.hang_time, job.apex) else {
        return Ok(());
    };
    let (column, unit, scale) = if range == calibrate::HANG_TIME {
        ("hang_time", "s", 1.0)
    } else if range == calibrate::APEX {
        ("apex", "ft", FEET_PER_METRE)
    } else {
        ("hit_distance_sc", "ft", FEET_PER_METRE)
    };
    let number = |v: f64| {
        if v.abs() >= 1e6 {
            format!("{v:.3e}")
        } else {
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

/// Savant's feet, for messages about its columns.
const FEET_PER_METRE: f64 = 1.0 / 0.3048;

fn text(
    read: &Read,
    fit: &Fit,
    at_bounds: &[String],
    saved: Option<&Path>,
    shown: Shown,
) -> String {
    let d = |m: f64| shown.value(Quantity::Distance, m, 1);
    let errors = |e: &Errors, unit: &dyn Fn(f64) -> String| {
        format!(
            "median {}{}, median |error| {}, spread {} ({} rows)",
            if e.median >= 0.0 { "+" } else { "-" },
            unit(e.median.abs()),
            unit(e.median_absolute),
            unit(e.spread),
            e.rows
        )
    };
    let seconds = |s: f64| format!("{s:.2} s");
    let mut lines = vec![(
        "rows",
        format!(
            "{} of {} read: {} without a distance, {} launched below 10° (a grounder's distance is where it was fielded), {} without hit coordinates, {}{} skipped",
            read.measured.len(),
            read.rows,
            read.without_distance,
            read.grounders,
            read.without_spray,
            if read.implausible > 0 {
                format!("{} outside the plausible ranges, ", read.implausible)
            } else {
                String::new()
            },
            read.skipped
        ),
    )];
    if let Some(from_swing) = read.spin_from_swing {
        let spin = format!(
            "the swing's impact on {from_swing} rows (solved from bat tracking), Nathan's relation on {}",
            read.measured.len() - from_swing
        );
        lines.push(("spin", spin));
    }
    lines.extend([
        (
            "drag",
            format!(
                "model.drag_scale = {:.4} ± {:.4}",
                fit.drag_scale.value, fit.drag_scale.uncertainty
            ),
        ),
        (
            "lift",
            match (fit.lift_scale, fit.lift_from) {
                (Some(l), Some(from)) => format!(
                    "model.lift_scale = {:.4} ± {:.4}, from {}; correlation with the drag {:+.2}",
                    l.value,
                    l.uncertainty,
                    match from {
                        LiftFrom::HangTime => "the hang times",
                        LiftFrom::Apex => "the apexes",
                        LiftFrom::Bands => "the distances by launch-angle band",
                    },
                    fit.correlation.unwrap_or(0.0)
                ),
                _ => format!("not fitted: {}", fit.why_no_lift.unwrap_or("--drag-only")),
            },
        ),
        ("before", format!("distance {}", errors(&fit.before, &d))),
        ("after", format!("distance {}", errors(&fit.after, &d))),
    ]);
    if let Some(bands) = &fit.bands {
        let signed = |m: f64| format!("{}{}", if m >= 0.0 { "+" } else { "-" }, d(m.abs()));
        let with_rows = bands.lower_edges.iter().enumerate();
        for (k, edge) in with_rows.filter(|(k, _)| bands.after[*k].rows > 0) {
            let name = band_name((Some(*edge), bands.lower_edges.get(k + 1).copied()));
            let (before, after) = (bands.before[k], bands.after[k]);
            lines.push((
                if lines
                    .last()
                    .is_some_and(|l| l.0 == "bands" || l.0.is_empty())
                {
                    ""
                } else {
                    "bands"
                },
                format!(
                    "{name:<7} median {} → {} ({} rows)",
                    signed(before.median),
                    signed(after.median),
                    after.rows
                ),
            ));
        }
        lines.push((
            "misfit",
            format!(
                "χ²/dof = {:.1} over the bands (about 1 for noise alone; {})",
                bands.misfit,
                if bands.misfit > 1.0 {
                    "the ± are scaled by its root"
                } else {
                    "the ± are the medians' own"
                }
            ),
        ));
    }
    if let (Some(before), Some(after)) = (fit.second_before, fit.second_after) {
        let unit: &dyn Fn(f64) -> String = if read.measured.iter().any(|m| m.hang_time.is_some()) {
            &seconds
        } else {
            &d
        };
        lines.push(("", format!("second: before {}", errors(&before, unit))));
        lines.push(("", format!("second: after {}", errors(&after, unit))));
    }
    for bound in at_bounds {
        lines.push((
            "bound",
            format!("{bound}: the measurements pull it further; check them"),
        ));
    }
    if let Some(path) = saved {
        lines.push(("saved", path.display().to_string()));
    }
    labelled(&lines)
}
