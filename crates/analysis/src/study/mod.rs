//! Studies over many swings: the range surface over (E, ψ) (Fig. 7), the
//! optimum as one input is swept (Figs. 8–12), a slice in E (Fig. 13), C_D
//! along a flight (Fig. 14) and the impact against E for several μ
//! (Figs. 5–6). Parallel with rayon where the points are independent. Each
//! study calls the model and nothing else.

use rayon::prelude::*;
use serde::Serialize;

use super::optimum::{OptimizerSettings, Status, optimize_from};
use model::flight::{FlightOptions, FlightSummary, RangeSummary, TrajectoryPoint};
use model::impact::{Collision, Regime};
use model::keys::{InputError, TEXT_KEYS};
use model::launch::SceneFlight;
use model::many::land_many;
use model::{self, scene::Scene};

mod surface;
pub use surface::*;

/// One point of a sweep: the optimal swing with one input set to `value`
/// (Figs. 8–12), and the launch it gives.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SweepPoint {
    /// The swept input's value.
    pub value: f64,
    pub undercut: f64,
    pub swing_angle: f64,
    pub range: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub evaluations: u32,
    pub converged: bool,
    /// Why its search stopped: converged, which limit, or nothing lands.
    pub status: Status,
    /// Whether any swing tried lands; if none does, there is no optimum and
    /// `range` is −∞.
    pub landed: bool,
    /// Whether the optimum's flight lands only just inside its time limit:
    /// the limit, not the swing, sets its range.
    pub at_time_limit: bool,
    /// Whether the optimum, flown again at readout precision (as `hit` and
    /// `optimize` report a flight), lands too. A hovering or looping ball
    /// can graze the ground at one precision and miss it at another.
    pub lands_at_readout: bool,
}

/// Why a sweep was refused before any computation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    #[error(transparent)]
    Input(#[from] InputError),
    #[error(
        "{0}: the optimiser chooses this one; sweep another key (e.g. bat.speed, pitch.spin, environment.wind)"
    )]
    ControlVariable(&'static str),
    #[error("{0} is not a number and cannot be swept; run once per value with --set {0}=NAME")]
    NotNumeric(&'static str),
    #[error("sweep point {index} of {count}: {source}")]
    Point {
        index: usize,
        count: usize,
        source: InputError,
    },
}

/// The scenes of a sweep of `key` over `values`, each validated, before any
/// computation: the first bad value is an error naming the key.
pub fn sweep_scenes(scene: &Scene, key: &str, values: &[f64]) -> Result<Vec<Scene>, SweepError> {
    if let Some(text) = TEXT_KEYS.iter().find(|k| **k == key) {
        return Err(SweepError::NotNumeric(text));
    }
    let key = Scene::key(key)?;
    if key.name == "bat.undercut" || key.name == "bat.swing_angle" {
        return Err(SweepError::ControlVariable(key.name));
    }
    values
        .iter()
        .enumerate()
        .map(|(index, &value)| {
            let mut s = *scene;
            (key.set)(&mut s, value);
            s.validate().map_err(|source| SweepError::Point {
                index: index + 1,
                count: values.len(),
                source,
            })?;
            Ok(s)
        })
        .collect()
}

/// `steps` equally spaced values from `from` to `to` (both included).
pub fn linspace(from: f64, to: f64, steps: usize) -> Vec<f64> {
    match steps {
        0 => Vec::new(),
        1 => vec![from],
        n => (0..n)
            .map(|i| from + (to - from) * i as f64 / (n - 1) as f64)
            .collect(),
    }
}

/// The optimum as `key` is swept over `values` (Figs. 8–12). Each point is
/// warm-started from the previous optimum, which makes the sweep sequential
/// but about twice as cheap per point, and keeps it on one ridge. The points
/// share a work budget of [`SWEEP_FLIGHT_STEPS`].
pub fn sweep(
    scene: &Scene,
    key: &str,
    values: &[f64],
    settings: OptimizerSettings,
) -> Result<Vec<SweepPoint>, SweepError> {
    sweep_observed(scene, key, values, settings, &mut || {})
}

/// As [`sweep`], calling `tick` after each point.
pub fn sweep_observed(
    scene: &Scene,
    key: &str,
    values: &[f64],
    settings: OptimizerSettings,
    tick: &mut dyn FnMut(),
) -> Result<Vec<SweepPoint>, SweepError> {
    let scenes = sweep_scenes(scene, key, values)?;
    let mut start = (scene.bat.undercut, scene.bat.swing_angle);
    let mut remaining = SWEEP_FLIGHT_STEPS;
    let count = scenes.len() as u64;
    Ok(scenes
        .iter()
        .zip(values)
        .zip(0..)
        .map(|((s, &value), done)| {
            // An even share of what is left: a point that takes less leaves
            // more for the others.
            let settings = OptimizerSettings {
                max_flight_steps: settings.max_flight_steps.min(remaining / (count - done)),
                ..settings
            };
            let optimum = optimize_from(s, start, settings);
            remaining = remaining.saturating_sub(optimum.flight_steps);
            tick();
            // A search that found nothing landing leaves the next one
            // where it started.
            if optimum.landed {
                start = (optimum.undercut, optimum.swing_angle);
            }
            let best = s.with_swing(optimum.undercut, optimum.swing_angle);
            let impact = Collision::new(&best);
            // One flight more per point (~0.1 ms) to say the same as `optimize`.
            let lands_at_readout = optimum.landed
                && model::simulate(&best, crate::precision::Purpose::Readout)
                    .flight
                    .landed;
            SweepPoint {
                value,
                undercut: optimum.undercut,
                swing_angle: optimum.swing_angle,
                range: optimum.range,
                launch_speed: impact.launch_speed(),
                launch_spin: impact.launch_spin(),
                launch_angle: impact.launch_angle(),
                evaluations: optimum.evaluations,
                converged: optimum.converged,
                status: optimum.status,
                landed: optimum.landed,
                at_time_limit: optimum.at_time_limit,
                lands_at_readout,
            }
        })
        .collect())
}

/// One point of a slice in E at fixed ψ (Fig. 13): launch and range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SlicePoint {
    pub undercut: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub range: f64,
    /// Whether the ball lands; if not, `range` is where it was at its limit.
    pub landed: bool,
}

/// Launch and range at each undercut in `undercuts`, the swing angle held at
/// `swing_angle` (Fig. 13), flown in lock-step. Undercuts the bat cannot reach
/// (|E| ≥ r_b + r_B) are left out.
pub fn slice(
    scene: &Scene,
    swing_angle: f64,
    undercuts: &[f64],
    options: impl Into<FlightOptions>,
) -> Vec<SlicePoint> {
    let reachable: Vec<(f64, Collision, SceneFlight)> = undercuts
        .iter()
        .filter(|e| e.abs() < scene.reach())
        .map(|&undercut| {
            let swing = scene.with_swing(undercut, swing_angle);
            let impact = Collision::new(&swing);
            (undercut, impact, SceneFlight::of_impact(&swing, &impact))
        })
        .collect();
    let flights: Vec<SceneFlight> = reachable.iter().map(|(_, _, flight)| *flight).collect();
    reachable
        .iter()
        .zip(land_all(&flights, &options.into()))
        .map(|((undercut, impact, _), flight)| SlicePoint {
            undercut: *undercut,
            launch_speed: impact.launch_speed(),
            launch_spin: impact.launch_spin(),
            launch_angle: impact.launch_angle(),
            range: flight.range,
            landed: flight.landed,
        })
        .collect()
}

/// Flights a chunk of a short list flies in lock-step ([`land_all`]): a
/// few chunks for the cores, each a few times the lanes.
const FEW: usize = 8;

/// Flies `flights` in lock-step, in parallel chunks of `FEW` (the same
/// on any number of cores, so that each flight's steps are too), giving
/// what their ranges need ([`land_many`]), in their order.
pub fn land_all(flights: &[SceneFlight], options: &FlightOptions) -> Vec<RangeSummary> {
    flights
        .par_chunks(FEW)
        .flat_map_iter(|chunk| {
            let mut summaries = vec![None; chunk.len()];
            land_many(chunk.iter().copied(), options, |index, summary| {
                summaries[index] = Some(summary);
            });
            summaries.into_iter().flatten()
        })
        .collect()
}

/// C_D (and the whole path) along the flight of `scene`'s own swing at
/// `samples` equal time steps (Fig. 14: C_D against time).
pub fn drag_along_flight(
    scene: &Scene,
    samples: usize,
    options: impl Into<FlightOptions>,
) -> (FlightSummary, Vec<TrajectoryPoint>) {
    let impact = Collision::new(scene);
    SceneFlight::of_impact(scene, &impact).trajectory(&options.into(), samples)
}

/// One point of Figs. 5–6: the batted spin ω_bf and launch angle ζ at an
/// undercut, and whether slip halted.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImpactPoint {
    pub undercut: f64,
    pub launch_speed: f64,
    pub launch_spin: f64,
    pub launch_angle: f64,
    pub regime: Regime,
}

/// The impact alone, against E, for one friction coefficient.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpactCurve {
    pub friction: f64,
    pub points: Vec<ImpactPoint>,
}

/// ω_bf and ζ against E for each μ in `frictions` (Figs. 5–6). Impacts are
/// closed-form and cheap, so this needs no parallelism. Undercuts the bat
/// cannot reach are left out.
pub fn impact_curves(scene: &Scene, frictions: &[f64], undercuts: &[f64]) -> Vec<ImpactCurve> {
    let reach = scene.reach();
    frictions
        .iter()
        .map(|&friction| ImpactCurve {
            friction,
            points: undercuts
                .iter()
                .filter(|e| e.abs() < reach)
                .map(|&undercut| {
                    let mut s = *scene;
                    s.bat.friction = friction;
                    let impact = Collision::new(&s.with_swing(undercut, scene.bat.swing_angle));
                    ImpactPoint {
                        undercut,
                        launch_speed: impact.launch_speed(),
                        launch_spin: impact.launch_spin(),
                        launch_angle: impact.launch_angle(),
                        regime: impact.regime(),
                    }
                })
                .collect(),
        })
        .collect()
}
