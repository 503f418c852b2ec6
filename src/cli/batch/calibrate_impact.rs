//! `homerun calibrate --impact FILE [--save NAME]`: a Savant export's
//! tracked swings read as `hit --batch` reads them, and the bat's effective
//! mass fitted so that the model's ceiling q at the 99th percentile of the
//! rows is the data's ([`bat_tracking::fit_effective_mass`];
//! docs/bat-tracking.md).

use std::io::BufRead;

use super::calibrate::{Save, failed, read_source, save_fitted};
use super::read::{Fields, Lossy, Records};
use super::rows::{Header, Row, parse_row};
use super::savant_columns::Setup;
use crate::analysis::bat_tracking::{self, ImpactFit, TrackedSwing};
use crate::cli::UsageError;
use crate::cli::shown::Shown;
use crate::preset::escape_cut;
use crate::units::Quantity;

/// The quantile of q matched.
const QUANTILE: f64 = 0.99;

/// Runs the fit on `source` ("-" for stdin): the text (or JSON) to print.
pub(in crate::cli) fn run(
    setup: &Setup,
    source: &str,
    save: Option<Save>,
    json: bool,
    shown: Shown,
) -> Result<String, UsageError> {
    let swings = read_source(source, save.as_ref(), |input| read(setup, input))?;
    let base = &setup.base.scene;
    let fit = bat_tracking::fit_effective_mass(base, &swings, QUANTILE).ok_or_else(|| {
        let message = "no row has a tracked swing (bat_speed and the pitch's kinematics)";
        failed(source, message.to_owned())
    })?;
    let (low, high) = bat_tracking::EFFECTIVE_MASSES;
    let at_bound = (fit.effective_mass - low).min(high - fit.effective_mass) < 1e-6;
    let refusal = at_bound.then(|| {
        format!(
            "bat.effective_mass = {:.4} ended at the end of [{low}, {high}] searched; not saved (--force to save anyway)",
            fit.effective_mass
        )
    });
    let description = format!(
        "{}, its bat's effective mass fitted on {} ({} swings): bat.effective_mass = {:.4} kg",
        setup.base.name,
        escape_cut(source, 80),
        fit.rows,
        fit.effective_mass
    );
    let saved = save_fitted(save, (setup, source), refusal, description, |scene| {
        scene.bat.effective_mass = fit.effective_mass;
    })?;
    if json {
        let mut value = serde_json::json!({ "impact": fit, "at_bound": at_bound });
        if let Some(path) = &saved {
            value["saved"] = path.display().to_string().into();
        }
        return Ok(super::super::pretty(&value));
    }
    Ok(text(&fit, saved.as_deref(), shown))
}

fn text(fit: &ImpactFit, saved: Option<&std::path::Path>, shown: Shown) -> String {
    let percent = |share: f64| share * 100.0;
    let mut text = format!(
        "{} tracked swings; q = (EV - V_bat)/(V_pitch + V_bat), {:.0}th percentile {:.4} (data)\n\
         the model's ceiling (E = 0, the bat head-on to the pitch), row by row:\n\
         M_B = {:.4} kg   {:.1} % of rows above it, its {:.0}th percentile {:.4}\n\
         M_B = {:.4} kg   {:.1} % of rows above it, its {:.0}th percentile {:.4}  (fitted: bat.effective_mass)\n",
        fit.rows,
        percent(fit.quantile),
        fit.data,
        fit.effective_mass_before,
        percent(fit.above_before),
        percent(fit.quantile),
        fit.ceiling_before,
        fit.effective_mass,
        percent(fit.above_after),
        percent(fit.quantile),
        fit.ceiling_after,
    );
    text += &format!(
        "by approach speed (V_pitch + V_bat), the data's q at its {:.0}th percentile against the\n\
         model's median ceiling, each in a fifth of the rows:\n\
         {:>20}  {:>6}  {:>6}  {:>10}  {:>10}  {:>7}\n",
        percent(fit.quantile),
        shown.head("approach", Quantity::Speed, "m/s"),
        "rows",
        "data",
        format!("{:.4} kg", fit.effective_mass_before),
        format!("{:.4} kg", fit.effective_mass),
        "above",
    );
    for band in fit.by_approach.iter().filter(|band| band.rows > 0) {
        let speed = |si: f64| format!("{:.1}", shown.convert(Quantity::Speed, si));
        text += &format!(
            "{:>20}  {:>6}  {:>6.4}  {:>10.4}  {:>10.4}  {:>5.1} %\n",
            format!("{} to {}", speed(band.slowest), speed(band.fastest)),
            band.rows,
            band.data,
            band.ceiling_before,
            band.ceiling_after,
            percent(band.above_after),
        );
    }
    if let Some(path) = saved {
        text += &format!("saved {}\n", path.display());
    }
    text
}

/// Every row's tracked swing (rows without one, or bad, are left out).
fn read(setup: &Setup, input: impl BufRead) -> Result<Vec<TrackedSwing>, String> {
    let mut records = Records::new(input);
    let (mut bytes, mut ends) = (Vec::new(), Vec::new());
    let mut lossy = Lossy::default();
    let mut header = match records.next(&mut bytes, &mut ends, false) {
        Ok(Some(_)) => {
            let names = Fields::of(&bytes, &ends, &mut lossy)
                .iter()
                .map(|n| n.trim_start_matches('\u{feff}').to_owned())
                .collect();
            Header::new(names).map_err(|e| format!("line 1 (the header): {e}"))?
        }
        Ok(None) => return Err("the input is empty".to_owned()),
        Err(stop) => return Err(stop.to_string()),
    };
    header
        .read_swings()
        .map_err(|e| format!("line 1 (the header): {e}"))?;
    let mut jobs = Vec::new();
    let mut swings = Vec::new();
    loop {
        bytes.clear();
        ends.clear();
        let read = match records.next(&mut bytes, &mut ends, true) {
            Ok(Some(read)) => read,
            Ok(None) => break,
            Err(stop) => return Err(stop.to_string()),
        };
        if read.too_long {
            continue;
        }
        let fields = Fields::of(&bytes, &ends, &mut lossy);
        jobs.clear();
        if let Row::Job = parse_row(&header, setup, (read.line, fields), None, &mut jobs) {
            let job = &jobs[0];
            let launch = job.scene.launch;
            let measured = (
                launch.speed.unwrap_or(f64::NAN),
                launch.angle.unwrap_or(f64::NAN),
            );
            if let Ok(swing) = job
                .tracked
                .swing(measured, job.launch.spray, job.launch.side)
            {
                swings.push(swing);
            }
        }
    }
    Ok(swings)
}
