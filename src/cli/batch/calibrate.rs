//! `homerun calibrate FILE [--save NAME]`: the rows of a CSV read as
//! `fly --batch` reads them (a Savant export as it comes), each launch
//! completed as it completes them, and the factors on C_D (and C_L, given
//! hang times or apexes) fitted to the measured distances
//! ([`crate::analysis::calibrate`]).

use std::io::{self, BufRead};
use std::path::Path;

use rayon::prelude::*;

use super::pieces::PIECE_ROWS;
use super::records::{Fields, MAX_RECORD_BYTES, Record, Records, Stop, split_fields};
use super::rows::{Header, Job, Row, parse_row};
use super::savant_columns::{SavantColumn, Setup};
use crate::analysis::calibrate::{self, Errors, Fit, Measured};
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
    rows: usize,
    without_distance: usize,
    /// Rows whose header has hit coordinates but the row none: their launch
    /// direction would be a guess, so they are left out of the fit.
    without_spray: usize,
    skipped: usize,
}

/// Runs `calibrate` on `source` ("-" for stdin): the text (or JSON) to print.
pub(in crate::cli) fn run(
    setup: &Setup,
    source: &str,
    save: Option<(&str, Option<&Path>)>,
    json: bool,
    shown: Shown,
) -> Result<String, UsageError> {
    let failed = |message: String| UsageError::Calibrate {
        input: escape_cut(source, 200),
        message,
    };
    let read = if source == "-" {
        read(setup, io::stdin().lock())
    } else {
        let file = std::fs::File::open(source).map_err(|e| failed(e.to_string()))?;
        read(setup, io::BufReader::with_capacity(MAX_RECORD_BYTES, file))
    }
    .map_err(failed)?;
    let options = Purpose::Readout.flight_options();
    let fit = calibrate::fit(&read.measured, &options).map_err(|e| failed(e.to_string()))?;
    let saved = match save {
        Some((name, dir)) => {
            let dir = dir.ok_or_else(|| failed("--save: no presets folder".to_owned()))?;
            let mut preset = Preset {
                name: name.to_owned(),
                description: format!(
                    "{}, calibrated on {} ({} rows): model.drag_scale = {:.4} ± {:.4}{}",
                    setup.base.name,
                    escape_cut(source, 80),
                    fit.after.rows,
                    fit.drag_scale.value,
                    fit.drag_scale.uncertainty,
                    fit.lift_scale.map_or(String::new(), |l| format!(
                        ", model.lift_scale = {:.4} ± {:.4}",
                        l.value, l.uncertainty
                    ))
                ),
                scene: setup.base.scene,
                fence: setup.base.fence,
                source: Source::Bundled,
            };
            preset.scene.drag_scale *= fit.drag_scale.value;
            if let Some(lift) = fit.lift_scale {
                preset.scene.lift_scale *= lift.value;
            }
            preset.scene.validate()?;
            Some(preset.save(dir)?)
        }
        None => None,
    };
    if json {
        let mut value = serde_json::json!({
            "rows": read.rows,
            "measured": read.measured.len(),
            "without_distance": read.without_distance,
            "without_spray": read.without_spray,
            "skipped": read.skipped,
            "fit": fit,
        });
        if let Some(path) = &saved {
            value["saved"] = path.display().to_string().into();
        }
        return Ok(super::super::pretty(&value));
    }
    Ok(text(&read, &fit, saved.as_deref(), shown))
}

/// Reads every row into a measured flight, the launches completed in
/// parallel.
fn read(setup: &Setup, input: impl BufRead) -> Result<Read, String> {
    let mut records = Records::new(input);
    let header = match records.next() {
        Ok(Record::Text { text, .. }) => {
            let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
            let names = split_fields(text).map_err(|e| format!("line 1 (the header): {e}"))?;
            Header::new(names).map_err(|e| format!("line 1 (the header): {e}"))?
        }
        Ok(Record::End) => return Err("the input is empty".to_owned()),
        Ok(Record::TooLong) => return Err("line 1 (the header) is too long".to_owned()),
        Err(Stop::Binary { .. }) => return Err("binary data, not CSV text".to_owned()),
        Err(Stop::Io(e)) => return Err(e.to_string()),
    };
    records.read_past_long = true;
    let mut jobs = Vec::new();
    let mut skipped = 0;
    let mut rows = 0;
    let (mut fields, mut kept) = (Fields::default(), Fields::default());
    loop {
        match records.next() {
            Ok(Record::End) => break,
            Ok(Record::Text { line, text }) => {
                match parse_row(
                    &header,
                    setup,
                    (line, &text),
                    (&mut fields, &mut kept),
                    None,
                    &mut jobs,
                ) {
                    Row::Job => rows += 1,
                    Row::Blank => {}
                    Row::Bad { .. } | Row::NoLaunch => {
                        rows += 1;
                        skipped += 1;
                    }
                }
            }
            Ok(Record::TooLong) => skipped += 1,
            Err(Stop::Binary { line }) => {
                return Err(format!(
                    "line {line}: a NUL byte: binary data, not CSV text"
                ));
            }
            Err(Stop::Io(e)) => return Err(e.to_string()),
        }
    }
    let options = Purpose::Solve.flight_options();
    let sprayed = header.has(SavantColumn::HcX) || header.has(SavantColumn::HcY);
    let without_spray = jobs
        .iter()
        .filter(|j| sprayed && j.statcast.is_some() && j.launch.spray.is_none())
        .count();
    // Launched as `fly --batch` launches them: a piece's solves together.
    let wanted: Vec<&Job> = jobs
        .iter()
        .filter(|job| (!sprayed || job.launch.spray.is_some()) && job.statcast.is_some())
        .collect();
    let launched: Vec<Option<Measured>> = wanted
        .par_chunks(PIECE_ROWS)
        .flat_map_iter(|piece| {
            let rows = piece.iter().map(|job| (&job.scene, &job.launch));
            let launched = savant::launch_many(rows, setup.spray, &options);
            piece.iter().zip(launched).map(|(job, launched)| {
                let launched = launched.ok()?;
                launched.scene.validate().ok()?;
                Some(Measured {
                    scene: launched.scene,
                    distance: job.statcast?,
                    hang_time: job.hang_time,
                    apex: job.apex,
                })
            })
        })
        .collect();
    let without_distance = jobs.iter().filter(|j| j.statcast.is_none()).count();
    let measured: Vec<Measured> = launched.into_iter().flatten().collect();
    skipped += jobs.len() - without_distance - without_spray - measured.len();
    Ok(Read {
        measured,
        rows,
        without_distance,
        without_spray,
        skipped,
    })
}

fn text(read: &Read, fit: &Fit, saved: Option<&Path>, shown: Shown) -> String {
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
    let mut lines = vec![
        (
            "rows",
            format!(
                "{} of {} read: {} without a distance, {} without hit coordinates, {} skipped",
                read.measured.len(),
                read.rows,
                read.without_distance,
                read.without_spray,
                read.skipped
            ),
        ),
        (
            "drag",
            format!(
                "model.drag_scale = {:.4} ± {:.4}",
                fit.drag_scale.value, fit.drag_scale.uncertainty
            ),
        ),
        (
            "lift",
            match fit.lift_scale {
                Some(l) => format!("model.lift_scale = {:.4} ± {:.4}", l.value, l.uncertainty),
                None => "not fitted: no hang_time or apex column measures it".to_owned(),
            },
        ),
        ("before", format!("distance {}", errors(&fit.before, &d))),
        ("after", format!("distance {}", errors(&fit.after, &d))),
    ];
    if let (Some(before), Some(after)) = (fit.second_before, fit.second_after) {
        let unit: &dyn Fn(f64) -> String = if read.measured.iter().any(|m| m.hang_time.is_some()) {
            &seconds
        } else {
            &d
        };
        lines.push(("", format!("second: before {}", errors(&before, unit))));
        lines.push(("", format!("second: after {}", errors(&after, unit))));
    }
    if let Some(path) = saved {
        lines.push(("saved", path.display().to_string()));
    }
    labelled(&lines)
}
