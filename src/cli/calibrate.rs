//! `homerun calibrate FILE [--save NAME]`: the rows of a CSV read as
//! `fly --batch` reads them (a Savant export as it comes), each launch
//! completed as it completes them, and the factors on C_D and C_L fitted
//! to the measured distances, and hang times or apexes where measured
//! ([`analysis::calibrate`]).

use std::collections::BTreeMap;
use std::io::BufRead;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use batch::calibrate::{By, FEWEST_ROWS, Measurements};
use batch::{Outcome, Setup, Shown};
use serde_json::json;

use crate::analysis::calibrate::{self, Errors, Fit, LiftFrom, Measured};
use crate::analysis::precision::Purpose;
use crate::cli::UsageError;
use crate::cli::hit::labelled;
use crate::preset::{Preset, Source, escape_cut};
use crate::units::Quantity;

/// `--save NAME` in the presets folder `dir` (if there is one), and
/// whether `--force` was given.
#[derive(Clone, Copy)]
pub struct Save<'a> {
    pub name: &'a str,
    pub dir: Option<&'a Path>,
    pub force: bool,
}

/// The rows a calibration read (every record) and how its batch went:
/// what its exit status follows from ([`exit_status`]).
/// The third: the groups' presets `--save` could not write (each named).
pub(super) type Rows = (usize, Outcome, usize);

/// Runs `calibrate` on `source` ("-" for stdin), with `--by` each group
/// apart: the text (or JSON) to print, and the rows read.
pub fn run(
    setup: &mut Setup,
    source: &str,
    (save, by): (Option<Save>, Option<&str>),
    lift: bool,
    json: bool,
    shown: Shown,
) -> Result<(String, Rows), UsageError> {
    let grouped = by.map(By::of);
    let read = read_source(source, save.as_ref(), |input| {
        batch::calibrate::measured(setup, input, grouped.as_ref(), &mut note)
    })?;
    let mut rows = (read.rows, read.outcome, 0);
    let Some(by) = by else {
        let text = run_one(setup, source, (save, read), lift, json, shown)?;
        return Ok((text, rows));
    };
    let mut groups: BTreeMap<&str, Vec<Measured>> = BTreeMap::new();
    for (measured, group) in read.measured.iter().zip(&read.groups) {
        groups.entry(group).or_default().push(*measured);
    }
    let options = Purpose::Readout.flight_options();
    let d = |m: f64| shown.value(Quantity::Distance, m, 1);
    let (mut lines, mut fits) = (Vec::new(), Vec::new());
    // The groups fitted without the lift asked for, by why.
    let mut without_lift: BTreeMap<&str, Vec<String>> = BTreeMap::new();
    for (group, measured) in &groups {
        let name = escape_cut(if group.is_empty() { "(empty)" } else { group }, 24);
        let fit = match measured.len() {
            n if n < FEWEST_ROWS => Err(format!("too few to fit (at least {FEWEST_ROWS})")),
            _ => calibrate::fit(measured, &options, lift).map_err(|e| e.to_string()),
        };
        let fit = match fit {
            Ok(fit) => fit,
            // One group that cannot be fitted is named; the rest are fitted.
            Err(why) => {
                lines.push(format!(
                    "{name:<12} {:>6} rows: not fitted: {why}",
                    measured.len()
                ));
                fits.push(json!({ "group": group, "rows": measured.len(), "error": why }));
                continue;
            }
        };
        let saved = match &save {
            Some(save) => {
                let description = description(setup, source, &fit, Some(group));
                let named = format!("{}-{}", save.name, group);
                let save = Save {
                    name: &named,
                    ..*save
                };
                match save_fitted(
                    Some(save),
                    (setup, source),
                    refusal(&fit),
                    description,
                    |s| apply(&fit, s),
                ) {
                    Ok(path) => path.map(|p| Ok(p.display().to_string())),
                    Err(e) => {
                        rows.2 += 1;
                        Some(Err(format!("not saved: {e}")))
                    }
                }
            }
            None => None,
        };
        if let (true, None, Some(why)) = (lift, fit.lift_scale, fit.why_no_lift) {
            without_lift.entry(why).or_default().push(name.clone());
        }
        let lift = fit.lift_scale.map_or(String::new(), |l| {
            format!("  model.lift_scale = {:.4} ± {:.4}", l.value, l.uncertainty)
        });
        let signed = |m: f64| format!("{}{}", if m >= 0.0 { "+" } else { "-" }, d(m.abs()));
        lines.push(format!(
            "{name:<12} {:>6} rows  model.drag_scale = {:.4} ± {:.4}{lift}  median {} → {}, median |error| {} → {}{}{}",
            fit.after.rows,
            fit.drag_scale.value,
            fit.drag_scale.uncertainty,
            signed(fit.before.median),
            signed(fit.after.median),
            d(fit.before.median_absolute),
            d(fit.after.median_absolute),
            if fit.at_bounds().is_empty() { "" } else { "  (at a bound)" },
            match &saved {
                Some(Ok(path)) => format!("  saved {path}"),
                Some(Err(why)) => format!("  {why}"),
                None => String::new(),
            }
        ));
        let mut value = json!({ "group": group, "rows": measured.len(), "fit": fit });
        match saved {
            Some(Ok(path)) => value["saved"] = path.into(),
            Some(Err(why)) => value["not_saved"] = why.into(),
            None => {}
        }
        fits.push(value);
    }
    if json {
        let value = json!({ "by": by, "groups": fits, "rows": read.rows,
            "measured": read.measured.len(), "grounders": read.grounders,
            "in_preset_air": read.in_preset_air, "skipped": skipped(&read) });
        return Ok((super::pretty(&value), rows));
    }
    let mut text = format!(
        "by {}: {} group{}, {} of {} rows measured (launched at 10° or more, with a distance and hit coordinates; {} skipped)\n",
        escape_cut(by, 40),
        groups.len(),
        if groups.len() == 1 { "" } else { "s" },
        read.measured.len(),
        read.rows,
        skipped(&read)
    );
    if let Some(air) = preset_air(&read) {
        text += &format!("air: {air}\n");
    }
    for line in lines {
        text += &line;
        text.push('\n');
    }
    for (why, names) in without_lift {
        text += &format!("lift not fitted for {}: {why}\n", names.join(", "));
    }
    Ok((text, rows))
}

/// The exit status once the fit is out, as `fly --batch` gives it: 1 where
/// a row failed (each named as it was read; the fit is of the others) or
/// reading stopped early, 0 otherwise. Rows without a launch, grounders
/// and rows left out of the fit are counted, not failed.
pub(super) fn exit_status((rows, outcome, unsaved): Rows) -> ExitCode {
    if outcome.failed > 0 {
        note(&batch::rows_failed(outcome.failed, rows));
    }
    if unsaved > 0 {
        note(&format!(
            "{unsaved} group{}'s preset not saved (named above; exit status 1)",
            if unsaved == 1 { "" } else { "s" }
        ));
        return ExitCode::from(1);
    }
    ExitCode::from(outcome.exit_status())
}

/// Rows read but neither measured nor counted otherwise: failed, without a
/// launch speed, or fielded where no flight lands.
fn skipped(read: &Measurements) -> usize {
    read.outcome.failed + read.outcome.without_launch + read.unlanded
}

/// A bad row's note on stderr.
fn note(message: &str) {
    eprintln!("homerun: {message}");
}

/// The fitted factors applied to a scene.
fn apply(fit: &Fit, scene: &mut model::scene::Scene) {
    scene.drag_scale *= fit.drag_scale.value;
    if let Some(lift) = fit.lift_scale {
        scene.lift_scale *= lift.value;
    }
}

/// Why a fit is not saved unforced: a factor ended at its bound.
fn refusal(fit: &Fit) -> Option<String> {
    let at_bounds = at_bounds(fit);
    (!at_bounds.is_empty()).then(|| {
        format!(
            "{}: the measurements pull {} further than the model can follow; not saved (--force to save anyway)",
            at_bounds.join(", "),
            if at_bounds.len() == 1 { "it" } else { "them" }
        )
    })
}

fn at_bounds(fit: &Fit) -> Vec<String> {
    (fit.at_bounds().iter())
        .map(|(key, value, (low, high))| {
            format!("{key} = {value:.4} ended at the end of [{low}, {high}] searched")
        })
        .collect()
}

/// A saved preset's description.
fn description(setup: &Setup, source: &str, fit: &Fit, group: Option<&str>) -> String {
    format!(
        "{}, calibrated on {}{} ({} rows{}): model.drag_scale = {:.4} ± {:.4}{}",
        setup.base.name,
        escape_cut(source, 80),
        group.map_or(String::new(), |g| format!(", group {}", escape_cut(g, 40))),
        fit.after.rows,
        match setup.solve_swings {
            true => ", each with its solved swing's spin",
            false => "",
        },
        fit.drag_scale.value,
        fit.drag_scale.uncertainty,
        fit.lift_scale.map_or(String::new(), |l| format!(
            ", model.lift_scale = {:.4} ± {:.4}",
            l.value, l.uncertainty
        ))
    )
}

/// The whole file's fit.
fn run_one(
    setup: &Setup,
    source: &str,
    (save, read): (Option<Save>, Measurements),
    lift: bool,
    json: bool,
    shown: Shown,
) -> Result<String, UsageError> {
    let failed = |message| failed(source, message);
    if read.measured.len() < FEWEST_ROWS {
        return Err(failed(format!(
            "{} rows measured: too few to fit (at least {FEWEST_ROWS}, launched at 10° or more \
             with a distance)",
            read.measured.len()
        )));
    }
    let options = Purpose::Readout.flight_options();
    let fit = calibrate::fit(&read.measured, &options, lift).map_err(|e| failed(e.to_string()))?;
    let description = description(setup, source, &fit, None);
    let saved = save_fitted(save, (setup, source), refusal(&fit), description, |s| {
        apply(&fit, s)
    })?;
    if json {
        let mut value = json!({
            "rows": read.rows,
            "measured": read.measured.len(),
            "without_distance": read.without_distance,
            "grounders": read.grounders,
            "implausible": read.implausible,
            "without_spray": read.without_spray,
            "in_preset_air": read.in_preset_air,
            "skipped": skipped(&read),
            "spin_from_swing": read.spin_from_swing,
            "fit": fit,
            "at_bound": fit.at_bounds().iter().map(|b| b.0).collect::<Vec<_>>(),
        });
        if let Some(path) = &saved {
            value["saved"] = path.display().to_string().into();
        }
        return Ok(super::pretty(&value));
    }
    Ok(text(&read, &fit, &at_bounds(&fit), saved.as_deref(), shown))
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
    let no_folder = || failed(source, format!("--save: {}", preset::NO_FOLDER));
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
        explorer: None,
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
        preset::check_save(name, dir, *force)?;
    }
    let input = batch::open(source).map_err(failed)?;
    read(input).map_err(failed)
}

/// "the preset's air on 226 of 226 rows (at no park: …)", where rows flew
/// in no park's air: the fit takes up that air's level with the ball's.
fn preset_air(read: &Measurements) -> Option<String> {
    (read.in_preset_air > 0).then(|| {
        format!(
            "the preset's air on {} of {} rows (at no park: no home_team or --park, a team no \
             park answers to, or played away), whose level the fit takes up with the ball's",
            read.in_preset_air,
            read.measured.len()
        )
    })
}

fn text(
    read: &Measurements,
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
            skipped(read)
        ),
    )];
    if let Some(air) = preset_air(read) {
        lines.push(("air", air));
    }
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
                    "model.lift_scale = {:.4} ± {:.4}, from {}; correlation with the drag {}",
                    l.value,
                    l.uncertainty,
                    match from {
                        LiftFrom::HangTime => "the hang times",
                        LiftFrom::Apex => "the apexes",
                        LiftFrom::Bands => "the distances by launch-angle band",
                    },
                    // Rows that do not vary leave it undefined (0/0).
                    match fit.correlation.filter(|c| c.is_finite()) {
                        Some(c) => format!("{c:+.2}"),
                        None => String::from("undefined (the rows do not vary)"),
                    }
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
            let name = batch::band_name((Some(*edge), bands.lower_edges.get(k + 1).copied()));
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
