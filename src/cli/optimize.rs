//! The optimum: `optimize` (one scene; with `--park`, see [`park`]) and
//! `sweep` (against one input).

mod park;
pub(super) use park::{held, park_optimum};

use super::hit::{environment_json, labelled, launch_text};
use super::progress::{self, Work};
use super::shown::Shown;
use super::table::{Align, Cell, Column, Digits, Table, Width};
use super::{Format, UsageError, pretty};
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::optimum::{OptimizerSettings, Optimum, Scan, Status, lands_at_time_limit};
use crate::analysis::paper::{Best, best_swing};
use crate::analysis::precision::Purpose;
use crate::analysis::study;
use crate::model::keys::{AIR_KEYS, ATMOSPHERE_KEYS, LAUNCH_KEYS};
use crate::model::keys::{InputError, Key};
use crate::units::{Quantity, Unit};

/// The most points a sweep takes: its work budget
/// ([`study::SWEEP_FLIGHT_STEPS`]) shared by 200 points still gives each five
/// times what the costliest ordinary point needs (~10 000 integration
/// steps), and 200 ordinary points take about 0.3 s.
pub const MAX_STEPS: usize = 200;

pub(super) fn optimum(scene: &Scene, json: bool, shown: Shown) -> String {
    let work = Work {
        what: "optimize",
        steps: None,
    };
    let Best { optimum, swing } = progress::run(work, |_| best_swing(scene));
    let impact = &swing.impact;
    // No swing landing at all, or (at the margin) the optimum not landing
    // when flown again at readout precision, as every command reports a
    // flight. Then E and ψ are still the optimiser's best, and its own range
    // is given beside, named as such.
    let unlanded = if optimum.landed {
        landing::why_not_landed(
            &swing_scene(scene, &optimum),
            &swing.flight,
            Purpose::Readout,
        )
        .map(|why| not_at_readout_precision(&optimum, &why))
    } else {
        let own = crate::simulate(scene, Purpose::Readout).flight;
        Some(
            landing::why_not_landed(scene, &own, Purpose::Readout)
                .unwrap_or_else(|| "lands only at readout precision".to_owned()),
        )
    };
    let landed = unlanded.is_none();
    // On a scene whose balls hover, the longest landing flight may be one
    // that comes down just before the flight's time limit: then the limit,
    // not the swing, sets the range.
    let at_time_limit = lands_at_time_limit(&swing_scene(scene, &optimum), &swing.flight);
    if json {
        let mut json = serde_json::json!({
            "undercut": optimum.undercut,
            "swing_angle": optimum.swing_angle,
            "range": landed.then_some(swing.flight.range),
            "launch_speed": impact.launch_speed(),
            "launch_spin": impact.launch_spin(),
            "launch_angle": impact.launch_angle(),
            "evaluations": optimum.evaluations,
            "converged": optimum.converged,
            "status": optimum.status,
            "landed": landed,
            "environment": environment_json(scene),
        });
        if let Some(scan) = optimum.scan {
            json["scanned"] = scan.flown.into();
        }
        if at_time_limit {
            json["at_time_limit"] = true.into();
        }
        if !optimum.landed {
            no_optimum(&mut json);
        }
        if optimum.landed && !landed {
            json["optimizer_range"] = optimum.range.into();
        }
        if let Some(why) = unlanded {
            json["why_not_landed"] = why.into();
        }
        return pretty(&json);
    }
    let search = (
        "search",
        format!(
            "{} range evaluations, {}",
            optimum.evaluations,
            stopped(&optimum)
        ),
    );
    // Text about a flight that did not land gives the height in the units shown.
    let unlanded = match unlanded {
        Some(_) if !shown.is_si() => {
            let (flown, flight) = if optimum.landed {
                (swing_scene(scene, &optimum), swing.flight)
            } else {
                (*scene, crate::simulate(scene, Purpose::Readout).flight)
            };
            let height = landing::end_height(&flown, Purpose::Readout);
            Some(if flight.landed {
                "lands only at readout precision".to_owned()
            } else {
                shown.not_landed(&flight, height)
            })
        }
        unlanded => unlanded,
    };
    if !optimum.landed {
        let why = unlanded.unwrap_or_default();
        return labelled(&[
            (
                "optimum",
                format!("none: {}", nothing_lands(&optimum, shown)),
            ),
            (
                "",
                format!(
                    "the swing given, E = {}, ψ = {}, {why}",
                    shown.value(Quantity::Size, scene.bat.undercut, 4),
                    shown.value(Quantity::Angle, scene.bat.swing_angle, 4)
                ),
            ),
            search,
        ]);
    }
    let range = unlanded.unwrap_or_else(|| {
        let limit = if at_time_limit {
            " (at the flight's time limit: the limit, not the swing, sets this range)"
        } else {
            ""
        };
        format!(
            "{} in {:.3} s{limit}",
            shown.value(Quantity::Distance, swing.flight.range, 4),
            swing.flight.flight_time
        )
    });
    let mut lines = vec![
        (
            "optimum",
            format!(
                "E = {}, ψ = {}",
                shown.value(Quantity::Size, optimum.undercut, 6),
                shown.angle_and_degrees(optimum.swing_angle, 5, 2)
            ),
        ),
        ("range", range),
        ("launch", launch_text(impact, shown)),
        search,
    ];
    if let Some(scan) = optimum.scan {
        lines.push((
            "start",
            format!(
                "the swing given does not land; started from the best of {} swings over {}",
                scan.flown,
                window(&scan, shown)
            ),
        ));
    }
    labelled(&lines)
}

/// Why a landing optimum has no range at readout precision: its flight,
/// flown again at readout precision, `why` (it did not land within its
/// limit). At the margin of the time limit the two precisions can disagree.
fn not_at_readout_precision(optimum: &Optimum, why: &str) -> String {
    let limit = if optimum.at_time_limit {
        ", just inside the flight's time limit"
    } else {
        ""
    };
    format!(
        "the optimiser's best does not land at readout precision ({why}); at the optimiser's own precision it lands at {:.2} m{limit}",
        optimum.range
    )
}

/// `scene` with the optimum's swing.
fn swing_scene(scene: &Scene, optimum: &Optimum) -> Scene {
    scene.with_swing(optimum.undercut, optimum.swing_angle)
}

/// The status as JSON names it ("work_limit").
fn status_name(status: Status) -> String {
    serde_json::to_value(status)
        .ok()
        .and_then(|v| v.as_str().map(str::to_owned))
        .unwrap_or_default()
}

/// How a search ended: "converged (…)" or "NOT converged: stopped at …".
fn stopped(optimum: &Optimum) -> String {
    stopped_at(optimum.status, optimum.flight_steps)
}

/// [`stopped`], given the status and the integration steps taken.
fn stopped_at(status: Status, flight_steps: u64) -> String {
    match status {
        Status::Converged => "converged (Nelder–Mead, tolerances 1e-4)".to_owned(),
        Status::OutOfWork => {
            format!("NOT converged: stopped at the work limit ({flight_steps} integration steps)")
        }
        Status::OutOfEvaluations => "NOT converged: stopped at the evaluation limit".to_owned(),
        Status::NothingLands => "nothing to converge to: no swing lands".to_owned(),
        Status::Running => "NOT converged".to_owned(),
    }
}

/// "E ∈ [0, 0.05] m, ψ ∈ [-0.6, 1] rad"
fn window(scan: &Scan, shown: Shown) -> String {
    let grid = scan.grid;
    if shown.is_si() {
        return format!(
            "E ∈ [{}, {}] m, ψ ∈ [{}, {}] rad",
            grid.undercut.0, grid.undercut.1, grid.swing_angle.0, grid.swing_angle.1
        );
    }
    let end = |quantity, si| super::shown::short(shown.convert(quantity, si));
    format!(
        "E ∈ [{}, {}] in, ψ ∈ [{}, {}]°",
        end(Quantity::Size, grid.undercut.0),
        end(Quantity::Size, grid.undercut.1),
        end(Quantity::Angle, grid.swing_angle.0),
        end(Quantity::Angle, grid.swing_angle.1)
    )
}

/// Why a search has no optimum: which swings it flew, none landing.
fn nothing_lands(optimum: &Optimum, shown: Shown) -> String {
    match optimum.scan {
        Some(scan) if scan.complete => format!(
            "none of {} swings over {} lands, nor the swing given, so there is no range to maximise",
            scan.flown,
            window(&scan, shown)
        ),
        Some(scan) => format!(
            "no swing tried lands (the swing given and {} of a scan over {}, cut short), so there is no range to maximise",
            scan.flown,
            window(&scan, shown)
        ),
        None => "no swing tried lands, so there is no range to maximise".to_owned(),
    }
}

/// A sweep's end as typed: a bare number is in the unit shown (so that
/// `--units imperial` sweeps mph, as it prints them); a number with a unit
/// of the key's quantity (`60mph`, `28deg`) is read as `--set` reads it,
/// bounds included. Returns the end in the unit shown, and in SI when a
/// unit gave it (the end itself is then swept to the last bit).
fn sweep_end(
    flag: &'static str,
    text: &str,
    (key, unit): (&'static Key, Unit),
    shown: Shown,
) -> Result<(f64, Option<f64>), UsageError> {
    if let Ok(value) = text.trim().parse::<f64>() {
        return Ok((value, None));
    }
    match key.read_with_unit(text, unit) {
        Ok(si) => Ok((unit.show(si), Some(si))),
        Err(InputError::NotANumber { .. }) => Err(UsageError::SweepEndNotANumber {
            flag,
            text: super::usage::shown(text),
            range: shown.bounds(key),
            units: crate::units::accepted(key.quantity(), key.unit),
        }),
        Err(error) => Err(UsageError::BadEnd { flag, error }),
    }
}

pub(super) fn sweep(
    scene: &Scene,
    key: &str,
    (from, to, steps): (&str, &str, usize),
    format: Format,
    shown: Shown,
) -> Result<String, UsageError> {
    if !(1..=MAX_STEPS).contains(&steps) {
        return Err(UsageError::BadSteps { steps });
    }
    // The key first (unknown, or not sweepable), then the bounds.
    let key = super::scene::checked_key(key)?;
    if let Some(launch) = LAUNCH_KEYS.iter().find(|k| k.name == key) {
        return Err(UsageError::LaunchSwept(launch.name));
    }
    study::sweep_scenes(scene, key, &[])?;
    // --from and --to are in the units shown, and checked in them.
    let swept = Scene::key(key)?;
    let unit = swept.unit_in(shown.0);
    let (from, from_si) = sweep_end("--from", from, (swept, unit), shown)?;
    let (to, to_si) = sweep_end("--to", to, (swept, unit), shown)?;
    for (flag, value) in [("--from", from), ("--to", to)] {
        let outside = !unit.is_identity() && !swept.bounds.contains(unit.read(value));
        if !value.is_finite() || outside {
            return Err(UsageError::BadBound {
                flag,
                value,
                key: swept,
                accepted: shown.bounds(swept),
            });
        }
    }
    let mut values: Vec<f64> = study::linspace(from, to, steps)
        .into_iter()
        .map(|v| if unit.is_identity() { v } else { unit.read(v) })
        .collect();
    if let (Some(first), Some(si)) = (values.first_mut(), from_si) {
        *first = si;
    }
    if let (Some(last), Some(si)) = (values.last_mut(), to_si)
        && steps > 1
    {
        *last = si;
    }
    let work = Work {
        what: "sweep",
        steps: Some((steps, "points")),
    };
    let points = progress::run(work, |p| {
        let settings = OptimizerSettings::default();
        study::sweep_observed(scene, key, &values, settings, &mut || p.tick())
    })?;
    let unit = Scene::key(key).map(|k| k.unit).unwrap_or("");
    if format == Format::Json {
        let mut json = serde_json::json!({
            "key": key,
            "unit": unit,
            "points": points,
            "environment": environment_json(scene),
        });
        // A swept ρ, ν or weather key changes the air from point to point.
        let air_swept = AIR_KEYS.contains(&key) || ATMOSPHERE_KEYS.contains(&key);
        let scenes = if air_swept {
            study::sweep_scenes(scene, key, &values)?
        } else {
            Vec::new()
        };
        for (index, (point, p)) in json["points"]
            .as_array_mut()
            .into_iter()
            .flatten()
            .zip(&points)
            .enumerate()
        {
            if !p.landed {
                no_optimum(point);
            }
            if let Some(scene) = scenes.get(index) {
                point["environment"] = environment_json(scene);
            }
        }
        return Ok(pretty(&json));
    }
    let swept = Scene::key(key).map_or(Quantity::Unchanged, |k| k.quantity());
    let swept_symbol = swept.unit(shown.0, unit).symbol;
    let label = if swept_symbol.is_empty() {
        key.to_owned()
    } else {
        format!("{key} ({swept_symbol})")
    };
    // Each column's name, heading and decimals in the units shown, the SI
    // ones as they always were.
    let column = |key: &str, si_head: &str, head: String, width, quantity: Quantity, decimals| {
        let head = if shown.is_si() {
            si_head.to_owned()
        } else {
            head
        };
        let decimals = shown.unit(quantity).decimals(decimals);
        Column::right(
            &shown.csv_key(key, quantity),
            &head,
            width,
            Digits::Fixed(decimals),
        )
    };
    let symbol = |quantity: Quantity| shown.unit(quantity).symbol;
    let table = Table {
        columns: vec![
            Column::right(&shown.csv_key(key, swept), &label, 24, Digits::Trimmed),
            column(
                "undercut",
                "E_opt (m)",
                format!("E_opt ({})", symbol(Quantity::Size)),
                10,
                Quantity::Size,
                5,
            ),
            column(
                "swing_angle",
                "ψ_opt",
                format!("ψ_opt ({})", symbol(Quantity::Angle)),
                8,
                Quantity::Angle,
                4,
            ),
            column(
                "range",
                "range (m)",
                format!("range ({})", symbol(Quantity::Distance)),
                10,
                Quantity::Distance,
                3,
            ),
            column(
                "launch_speed",
                "V_bf m/s",
                format!("V_bf {}", symbol(Quantity::Speed)),
                9,
                Quantity::Speed,
                3,
            ),
            column(
                "launch_spin",
                "ω_bf r/s",
                format!("ω_bf {}", symbol(Quantity::Spin)),
                9,
                Quantity::Spin,
                2,
            ),
            column(
                "launch_angle",
                "ζ rad",
                format!("ζ {}", symbol(Quantity::Angle)),
                8,
                Quantity::Angle,
                4,
            ),
            Column::data("evaluations"),
            Column::data("at_time_limit"),
            Column::data("converged"),
            Column::data("status"),
            Column::data("landed"),
            Column::text("", Width::AtLeast(0), Align::Left, ""),
        ],
        rows: points
            .iter()
            .map(|p| {
                let mut row: Vec<Cell> = [
                    (p.value, swept),
                    (p.undercut, Quantity::Size),
                    (p.swing_angle, Quantity::Angle),
                    (p.range, Quantity::Distance),
                    (p.launch_speed, Quantity::Speed),
                    (p.launch_spin, Quantity::Spin),
                    (p.launch_angle, Quantity::Angle),
                    (f64::from(p.evaluations), Quantity::Unchanged),
                ]
                .map(|(si, quantity)| Cell::Num(shown.convert(quantity, si)))
                .to_vec();
                row.push(Cell::Bool(p.at_time_limit));
                row.push(Cell::Text(p.converged.to_string()));
                row.push(Cell::Text(status_name(p.status)));
                row.push(Cell::Bool(p.landed));
                if !p.landed {
                    row[1..7].fill(Cell::Blank);
                }
                row.push(match (p.landed, p.status) {
                    (false, Status::NothingLands) => {
                        Cell::Text("  (no swing lands: no optimum)".to_owned())
                    }
                    (false, _) => Cell::Text("  (no swing tried lands: no optimum)".to_owned()),
                    (true, status) => limits(status, p.at_time_limit, p.lands_at_readout),
                });
                row
            })
            .collect(),
    };
    Ok(if format == Format::Csv {
        table.csv()
    } else {
        table.text()
    })
}

/// A landing optimum's notes: whether it lands only at the optimiser's
/// precision, the search's limit, if it stopped at one, and the flight's
/// time limit, if that set its range.
fn limits(status: Status, at_time_limit: bool, lands_at_readout: bool) -> Cell {
    let mut notes = Vec::new();
    if !lands_at_readout {
        notes.push("lands only at the optimiser's precision: at readout precision it does not");
    }
    match status {
        Status::OutOfWork => notes.push("not converged: work limit"),
        Status::OutOfEvaluations => notes.push("not converged: evaluation limit"),
        _ => {}
    }
    if at_time_limit {
        notes.push("time limit: the flight's limit, not the swing, sets this range");
    }
    if notes.is_empty() {
        Cell::Blank
    } else {
        Cell::Text(format!("  ({})", notes.join("; ")))
    }
}

/// The fields of an optimum, null where no swing lands: there is no
/// optimum, only where the search stopped.
const OPTIMUM_FIELDS: [&str; 6] = [
    "undercut",
    "swing_angle",
    "range",
    "launch_speed",
    "launch_spin",
    "launch_angle",
];

fn no_optimum(json: &mut serde_json::Value) {
    for field in OPTIMUM_FIELDS {
        json[field] = serde_json::Value::Null;
    }
}
