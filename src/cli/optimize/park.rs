//! `optimize --park CODE [--fix KEY]…`: the swing (E, ψ, φ_B) that clears
//! the park's wall by the most ([`crate::analysis::optimum::park`]), in the
//! park's air as `fly --park` flies (docs/swing-3d.md).

use super::super::fly::{air_text, batted_text};
use super::super::ground::{FlownToFence, Ground, clearing_json, clearing_text};
use super::super::hit::{environment_json, flight_json, flight_text, labelled};
use super::super::progress::{self, Work};
use super::super::shown::Shown;
use super::super::{UsageError, pretty};
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::optimum::OptimizerSettings;
use crate::analysis::optimum::park::{Held, Judged, ParkOptimum, SEARCHED_KEYS, optimize_park};
use crate::analysis::precision::Purpose;
use crate::model::clearing::Outcome;
use crate::model::park::Park;
use crate::preset::escape_cut;
use crate::units::Quantity;

/// `--fix`'s keys, checked: each one of [`SEARCHED_KEYS`].
pub(in crate::cli) fn held(fix: &[String]) -> Result<Held, UsageError> {
    let mut held = Held::default();
    for key in fix {
        if !held.hold(key.trim()) {
            return Err(UsageError::CommandLine(format!(
                "--fix '{}': not a key the park search moves; accepted: {}",
                escape_cut(key, 40),
                SEARCHED_KEYS.join(", ")
            )));
        }
    }
    Ok(held)
}

/// The best swing for `park` (`scene` already in the park's air), as text
/// or JSON.
pub(in crate::cli) fn park_optimum(
    scene: &Scene,
    park: &Park,
    held: Held,
    json: bool,
    shown: Shown,
) -> String {
    let work = Work {
        what: "optimize",
        steps: None,
    };
    let optimum = progress::run(work, |_| {
        let settings = OptimizerSettings::default();
        optimize_park(scene, &park.fence, held, Purpose::Optimizer, settings)
    });
    // The best swing flown again at readout precision, as `fly --park`
    // flies it: the margin shown is the one `fly` gives that swing.
    let best = optimum.swing.in_scene(scene);
    let flown = FlownToFence::new(&best, &park.fence, &[], None);
    let margin = Judged::of(&park.fence, flown.clearing, flown.flight).margin;
    let held_keys: Vec<&str> = SEARCHED_KEYS
        .iter()
        .zip(held.0)
        .filter(|(_, h)| *h)
        .map(|(k, _)| *k)
        .collect();
    let ground = Ground::Park(park);
    let unlanded = landing::why_not_landed(&best, &flown.flight, Purpose::Readout);
    if json {
        let launch = &flown.launch;
        let found = optimum.found;
        let margin = margin.filter(|_| found);
        let mut json = serde_json::json!({
            "park": park.code,
            "undercut": optimum.swing.undercut,
            "swing_angle": optimum.swing.swing_angle,
            "bat_direction": optimum.swing.direction,
            "margin": margin.map(|m| m.value()),
            "over_wall": margin.map(|m| m.over_wall),
            "inside_line": margin.map(|m| m.inside_line),
            "outcome": flown.clearing.outcome.name(),
            "direction": launch.direction,
            "range": flown.flight.landed.then_some(flown.flight.range),
            "launch_speed": launch.speed,
            "launch_spin": launch.spin,
            "launch_angle": launch.angle,
            "launch_sidespin": launch.sidespin,
            "fence": clearing_json(&park.code, &flown.clearing),
            "flight": flight_json(&flown.flight, unlanded),
            "held": held_keys,
            "evaluations": optimum.evaluations,
            "starts": optimum.starts,
            "converged": optimum.converged,
            "status": optimum.status,
            "found": found,
            "environment": environment_json(scene),
        });
        if let Some(scanned) = optimum.scanned {
            json["scanned"] = scanned.into();
        }
        return pretty(&json);
    }
    let air = scene.environment.air();
    let air = format!(
        "ρ = {}, ν = {:.4e} m²/s; {}",
        air_text(&air, shown),
        air.kinematic_viscosity,
        scene.models_text()
    );
    let search = ("search", search_text(&optimum, &held_keys));
    if !optimum.found {
        return labelled(&[
            (
                "optimum",
                format!(
                    "none: no swing tried lands or reaches the fence at {}",
                    park.code
                ),
            ),
            search,
            ("air", air),
        ]);
    }
    let swing = optimum.swing;
    let d = |m: f64| shown.value(Quantity::Distance, m, 2);
    let margin_text = match margin {
        Some(m) => {
            let short = if flown.clearing.outcome == Outcome::Short {
                " (continued down its landing line)"
            } else {
                ""
            };
            // Each side in words that keep its sign readable: a swing that
            // cannot clear says "below the wall's top", "outside the line".
            let wall = if m.over_wall >= 0.0 {
                "over the wall"
            } else {
                "below the wall's top"
            };
            let line = if m.inside_line >= 0.0 {
                "inside the foul line"
            } else {
                "outside the foul line"
            };
            // At the optimum the two sides often balance: one number, once.
            let (over, inside) = (d(m.over_wall.abs()), d(m.inside_line.abs()));
            if over == inside && d(m.value()) == over {
                format!("{over} {wall}{short} and {line} alike")
            } else {
                format!("{}: {over} {wall}{short}, {inside} {line}", d(m.value()))
            }
        }
        None => "none: it neither lands nor reaches the fence".to_owned(),
    };
    // In the units shown, as `fly` says it.
    let unlanded = unlanded.map(|why| {
        if shown.is_si() {
            why
        } else {
            let height = landing::end_height(&best, Purpose::Readout);
            shown.not_landed(&flown.flight, height)
        }
    });
    labelled(&[
        (
            "optimum",
            format!(
                "E = {}, ψ = {}, bat swung {}",
                shown.value(Quantity::Size, swing.undercut, 6),
                shown.angle_and_degrees(swing.swing_angle, 5, 2),
                shown.direction(swing.direction)
            ),
        ),
        ("margin", margin_text),
        ("fence", clearing_text(&ground, &flown.clearing, shown)),
        ("launch", batted_text(&flown.launch, shown)),
        (
            "flight",
            flight_text(&flown.flight, unlanded.as_deref(), shown),
        ),
        search,
        ("air", air),
    ])
}

/// "612 flights from 6 starts, converged (Nelder–Mead, tolerances 1e-4);
/// held: bat.direction"
fn search_text(optimum: &ParkOptimum, held: &[&str]) -> String {
    let starts = match optimum.starts {
        1 => "1 start".to_owned(),
        n => format!("{n} starts"),
    };
    let mut text = format!(
        "{} flights from {starts}, {}",
        optimum.evaluations,
        super::stopped_at(optimum.status, optimum.flight_steps)
    );
    if let Some(scanned) = optimum.scanned {
        text += &format!(" (no start scored: {scanned} swings scanned first)");
    }
    if !held.is_empty() {
        text += &format!("; held: {}", held.join(", "));
    }
    text
}
