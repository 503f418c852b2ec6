//! Figs. 7–12: the range over (E, ψ), and the optimum against one input.

use super::{
    FigureData, LANDED, LAUNCH, MARK, SurfaceFigure, column, columns, compare, flight_row,
};
use crate::optimum::{self, OptimizerSettings};
use crate::paper;
use crate::precision::Purpose;
use crate::study::{self, Grid, SweepError};
use model::scene::Scene;

/// Fig. 7's grid: columns (E) × rows (ψ).
pub(super) const FIGURE7_GRID: (usize, usize) = (21, 17);
/// The points of each of Figs. 8–12.
pub(super) const SWEEP_POINTS: usize = 11;

/// Fig. 7: the range surface over the paper's window, with the optimiser's
/// optimum (point O); `tick` after each cell.
pub(super) fn figure7(scene: &Scene, tick: &(dyn Fn() + Sync)) -> SurfaceFigure {
    let (columns, rows) = FIGURE7_GRID;
    SurfaceFigure {
        number: 7,
        title: "range (m) over undercut E (m) and swing angle ψ (rad), the window of Fig. 7"
            .to_owned(),
        conditions: String::new(),
        // At most 357 flights of 100 000 steps: no budget needed.
        surface: study::surface_within(
            scene,
            Grid::figure7(columns, rows),
            Purpose::Surface,
            u64::MAX,
            tick,
        )
        .expect("an unlimited budget"),
        optimum: optimum::optimize(scene, OptimizerSettings::default()),
        paper: (
            paper::FIGURE7_UNDERCUT,
            paper::FIGURE7_SWING_ANGLE,
            paper::FIGURE7_RANGE,
        ),
    }
}

/// The input Fig. `number` (8–12) sweeps: (key, from, to, what it is).
fn sweep_axis(number: u32) -> (&'static str, f64, f64, &'static str) {
    match number {
        8 => ("bat.speed", 20.0, 45.0, "bat speed V_B0 (m/s)"),
        9 => ("bat.spin", 0.0, 60.0, "bat roll ω_B0 (rad/s)"),
        10 => ("pitch.speed", 35.0, 45.0, "pitch speed V_b0 (m/s)"),
        11 => (
            "pitch.spin",
            -200.0,
            200.0,
            "pitch spin ω_b0 (rad/s, topspin positive)",
        ),
        _ => (
            "environment.wind",
            -10.0,
            10.0,
            "wind V_w (m/s, tailwind positive)",
        ),
    }
}

/// Figs. 8–12: the optimum against one input, as the paper varied it;
/// `tick` after each point.
pub(super) fn sweep_figure(
    number: u32,
    scene: &Scene,
    tick: &(dyn Fn() + Sync),
) -> Result<FigureData, SweepError> {
    let (key, from, to, what) = sweep_axis(number);
    let values = study::linspace(from, to, SWEEP_POINTS);
    let settings = OptimizerSettings::default();
    let points = study::sweep_observed(scene, key, &values, settings, &mut || tick())?;
    let current = Scene::key(key).map(|k| (k.get)(scene)).ok();
    let rows = points
        .iter()
        .map(|p| {
            let mut mark = Vec::new();
            if current.is_some_and(|c| (c - p.value).abs() < 1e-9) {
                mark.push("the preset's value");
            }
            if !p.landed {
                mark.push("no swing tried lands");
            } else if !p.converged {
                mark.push("not converged");
            }
            if p.at_time_limit {
                mark.push("lands at the flight's time limit");
            }
            if p.landed && !p.lands_at_readout {
                mark.push("lands only at the optimiser's precision");
            }
            let numbers = [p.value, p.undercut, p.swing_angle, p.range];
            // Without a landing swing there is no optimum: only the value.
            let row = [&numbers[..], &launch(p)].concat();
            flight_row(&row, 1..row.len(), p.landed, &mark.join("; "))
        })
        .collect();
    let at = |value: f64| {
        points
            .iter()
            .find(|p| p.landed && (p.value - value).abs() < 1e-9)
    };
    let gain = |a: f64, b: f64| at(b).zip(at(a)).map(|(b, a)| b.range - a.range);
    let mut comparisons = Vec::new();
    let mut notes = Vec::new();
    match number {
        8 => {
            if let Some(g) = gain(27.5, 32.5) {
                comparisons.push(compare(paper::BAT_SPEED_GAIN, g / 5.0));
            }
            let level = points.windows(2).find_map(|w| {
                let crossing = w[0].swing_angle > 0.0 && w[1].swing_angle <= 0.0;
                (w[0].landed && w[1].landed && crossing).then(|| {
                    w[0].value
                        + (w[1].value - w[0].value) * w[0].swing_angle
                            / (w[0].swing_angle - w[1].swing_angle)
                })
            });
            if let Some(v) = level {
                comparisons.push(compare(paper::LEVEL_SWING, v));
            }
            notes.push(
                "paper: ψ_opt falls to 0 at 42 m/s and below it after (\"increasing the bat speed by only 1 m/s increases the optimal range by nearly 5 m\")."
                    .to_owned(),
            );
        }
        9 => {
            if let Some(g) = gain(0.0, 60.0) {
                comparisons.push(compare(paper::ROLL_GAIN, g));
            }
        }
        10 => {
            if let Some(g) = gain(35.0, 45.0) {
                comparisons.push(compare(paper::PITCH_SPEED_GAIN, g));
            }
        }
        11 => {
            if let Some(g) = gain(-200.0, 200.0) {
                comparisons.push(compare(paper::PITCH_SPIN_GAIN, g));
            }
            notes.push("paper: E_opt and ψ_opt both fall as pitched topspin grows.".to_owned());
        }
        _ => {
            if let (Some(head), Some(tail)) = (at(-10.0), at(10.0)) {
                notes.push(format!(
                    "paper: with a tailwind the optimum undercuts more; ours: E_opt {:.5} m at −10 m/s, {:.5} m at +10 m/s",
                    head.undercut, tail.undercut
                ));
            }
        }
    }
    let unit = Scene::key(key).map(|k| k.unit).unwrap_or("");
    let title = format!("the optimum (E_opt m, ψ_opt rad, range m) and its launch against {what}");
    let mut table = vec![column(
        &key.replace('.', "_"),
        &format!("{key} ({unit})"),
        2,
    )];
    table.extend(columns(&[
        ("undercut", "E_opt (m)", 5),
        ("swing_angle", "ψ_opt (rad)", 4),
        ("range", "range (m)", 2),
    ]));
    table.extend(columns(&LAUNCH));
    table.extend(columns(&[LANDED, MARK]));
    Ok(FigureData {
        comparisons,
        notes,
        ..FigureData::new(number, title, table, rows)
    })
}

/// V_bf, ω_bf and ζ at a point of a sweep.
fn launch(p: &study::SweepPoint) -> [f64; 3] {
    [p.launch_speed, p.launch_spin, p.launch_angle]
}
