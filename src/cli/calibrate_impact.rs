//! `homerun calibrate --impact FILE [--save NAME]`: a Savant export's
//! tracked swings read as `hit --batch` reads them, and the bat's effective
//! mass fitted so that the model's ceiling q at the 99th percentile of the
//! rows is the data's ([`bat_tracking::fit_effective_mass`];
//! docs/bat-tracking.md).

use super::calibrate::{Rows, Save, failed, read_source, save_fitted};
use crate::analysis::bat_tracking::{self, ImpactFit};
use crate::cli::UsageError;
use crate::preset::escape_cut;
use crate::units::Quantity;
use batch::calibrate::FEWEST_ROWS;
use batch::{Setup, Shown};

/// The quantile of q matched.
const QUANTILE: f64 = 0.99;

/// Runs the fit on `source` ("-" for stdin): the text (or JSON) to print,
/// and the rows read.
pub(super) fn run(
    setup: &Setup,
    source: &str,
    save: Option<Save>,
    json: bool,
    shown: Shown,
) -> Result<(String, Rows), UsageError> {
    let (swings, rows, outcome) = read_source(source, save.as_ref(), |input| {
        batch::calibrate::tracked_swings(setup, input, &mut |m| eprintln!("homerun: {m}"))
    })?;
    // The same minimum as every fit (five swings fitted a bat before).
    if !swings.is_empty() && swings.len() < FEWEST_ROWS {
        let message = format!(
            "{} tracked swings: too few to fit (at least {FEWEST_ROWS})",
            swings.len()
        );
        return Err(failed(source, message));
    }
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
        let mut value = serde_json::json!({ "impact": fit, "at_bound": at_bound,
            "failed": outcome.failed, "without_launch": outcome.without_launch });
        if let Some(path) = &saved {
            value["saved"] = path.display().to_string().into();
        }
        return Ok((super::pretty(&value), (rows, outcome, 0)));
    }
    let mut text = text(&fit, saved.as_deref(), shown);
    if outcome.failed + outcome.without_launch > 0 {
        text += &format!(
            "skipped {} row{}: {} failed (named above), {} without a launch speed\n",
            outcome.failed + outcome.without_launch,
            if outcome.failed + outcome.without_launch == 1 {
                ""
            } else {
                "s"
            },
            outcome.failed,
            outcome.without_launch
        );
    }
    Ok((text, (rows, outcome, 0)))
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
    // With few rows the quantile by the nearest rank is the top row's.
    let last = fit.rows.saturating_sub(1);
    if (fit.quantile * last as f64).round() as usize == last {
        text += &format!(
            "(of {} swings the {:.0}th percentile is the most efficient one's: the fit follows that swing)\n",
            fit.rows,
            percent(fit.quantile)
        );
    }
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
