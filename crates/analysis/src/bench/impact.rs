//! The 3-D swing's rows of `homerun bench`: one impact in the plane (the
//! paper's closed forms), tilted, tilted and pulled, and slipping to
//! separation (the slip integrated over the impulse); one tracked swing
//! solved as `hit --batch` solves a row; and one `optimize --park` per park
//! and hand, the work the park search costs.

use serde::Serialize;

use super::{Effort, TRAJECTORY_BATCH, time_median};
use crate::bat_tracking::{self, LEAGUE_SWING_PATH_TILT, TrackedSwing};
use crate::optimum::OptimizerSettings;
use crate::optimum::park::{Held, optimize_park};
use crate::precision::Purpose;
use model::impact::{Collision, Regime};
use model::park::{self, GivenWeather};
use model::scene::{Hand, Scene};
use model::tracked_pitch::PitchFit;

#[derive(Clone, Debug, Serialize)]
pub struct ImpactRow {
    /// What is timed: "impact, planar", "optimize --park NYY, right", …
    pub work: String,
    /// The impact's regime, or the search's flights and starts.
    pub detail: String,
    /// Flights flown (none for an impact alone).
    pub flights: u32,
    /// Median wall time (µs).
    pub time_us: f64,
    pub cpu_us: Option<f64>,
}

/// The fastball's swing with the barrel `tilt` (rad) below the hands,
/// swung toward `direction` (rad).
fn swing(tilt: f64, direction: f64, hand: Hand) -> Scene {
    let mut scene = Scene::default();
    scene.bat.tilt = tilt;
    scene.bat.direction = direction;
    scene.bat.hand = hand;
    scene
}

pub(super) fn rows(effort: Effort, quick: bool) -> Vec<ImpactRow> {
    let tilt = 30f64.to_radians();
    let pulled = (-20f64).to_radians();
    // Undercut deep with little friction, the slip outlasts the contact.
    let mut slipping = swing(tilt, pulled, Hand::Right);
    slipping.bat.undercut = 0.045;
    slipping.bat.friction = 0.1;
    let impacts = [
        ("impact, planar (the paper's)", swing(0.0, 0.0, Hand::Right)),
        ("impact, tilted 30°", swing(tilt, 0.0, Hand::Right)),
        (
            "impact, tilted 30°, pulled 20°",
            swing(tilt, pulled, Hand::Right),
        ),
        ("impact, tilted, pulled, E 45 mm, μ 0.1", slipping),
    ];
    let mut rows: Vec<ImpactRow> = impacts
        .iter()
        .map(|(work, scene)| {
            let impact = Collision::new(scene);
            let regime = match impact.regime() {
                Regime::Stick => "sticks",
                Regime::Slip => "slips to separation",
            };
            // Impacts take about a microsecond: many to a batch.
            let batch = 20 * TRAJECTORY_BATCH;
            let (time, cpu) = time_median(effort.trajectory_batches, batch, || {
                Collision::new(std::hint::black_box(scene))
            });
            ImpactRow {
                work: (*work).to_owned(),
                detail: regime.to_owned(),
                flights: 0,
                time_us: time * 1e6,
                cpu_us: cpu.map(|c| c * 1e6),
            }
        })
        .collect();
    rows.extend(swing_solves(effort));
    let searches: &[(&str, Hand)] = if quick {
        &[("NYY", Hand::Right)]
    } else {
        &[
            ("NYY", Hand::Right),
            ("NYY", Hand::Left),
            ("BOS", Hand::Right),
            ("COL", Hand::Right),
        ]
    };
    for &(code, hand) in searches {
        let park = park::find(park::bundled(), code).expect("a bundled park");
        let mut scene = swing(tilt, 0.0, hand);
        GivenWeather::default().park_air(&mut scene.environment, park.elevation);
        let search = || {
            let settings = OptimizerSettings::default();
            optimize_park(
                &scene,
                &park.fence,
                Held::default(),
                Purpose::Optimizer,
                settings,
            )
        };
        let found = search();
        let (time, cpu) = time_median(effort.optimisation_runs, 1, search);
        rows.push(ImpactRow {
            work: format!("optimize --park {code}, {}", hand.name()),
            detail: format!("{} starts, margin {:.2} m", found.starts, found.margin),
            flights: found.evaluations,
            time_us: time * 1e6,
            cpu_us: cpu.map(|c| c * 1e6),
        });
    }
    rows
}

/// One tracked swing solved as `hit --batch` solves a row without bat
/// tracking's 2025 columns (the undercut, the contact's speed and the
/// bat's direction; no flight): a ball met 20 mm under its centre by a
/// 70 mph bat 10 % off the sweet spot's speed, level and at the league's
/// tilt (where a glancing trial contact's slip has both parts and is
/// integrated), and one faster than any swing gives (the search for its
/// shortfall).
fn swing_solves(effort: Effort) -> Vec<ImpactRow> {
    let pitch = PitchFit {
        velocity: [6.0, -137.0, -5.0],
        acceleration: [-12.0, 29.0, -15.0],
    }
    .at_front_of_plate()
    .expect("a pitch that reaches the plate");
    let bat_speed = 31.3;
    let cases = [
        ("swing solve, level bat", 0.0, 1.0),
        (
            "swing solve, the league's tilt",
            LEAGUE_SWING_PATH_TILT,
            1.0,
        ),
        (
            "swing solve, too fast (shortfall)",
            LEAGUE_SWING_PATH_TILT,
            1.4,
        ),
    ];
    cases
        .iter()
        .map(|&(work, tilt, faster)| {
            let mut base = Scene::default();
            base.bat.tilt = tilt;
            let mut met = base;
            met.bat.speed = 0.9 * bat_speed;
            met.bat.undercut = 0.02;
            met.pitch.spin = -230.0;
            let impact = model::impact::Impact3d::with_pitch(&met, pitch.velocity);
            let swing = TrackedSwing {
                pitch,
                pitch_spin: Some(-230.0),
                bat_speed,
                attack_angle: None,
                attack_direction: None,
                tilt: None,
                hand: Hand::Right,
                launch_speed: faster * impact.launch_speed(),
                launch_angle: impact.launch_angle(),
                spray: Some(impact.launch_direction()),
            };
            let answer = bat_tracking::solve(&base, &swing);
            let detail = match answer.solved {
                Ok(solved) if solved.off_sweet_spot => "off the sweet spot".to_owned(),
                Ok(_) => "swing angle solved".to_owned(),
                Err(why) => why.to_string(),
            };
            let (time, cpu) = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, || {
                bat_tracking::solve(&base, std::hint::black_box(&swing))
            });
            ImpactRow {
                work: work.to_owned(),
                detail,
                flights: 0,
                time_us: time * 1e6,
                cpu_us: cpu.map(|c| c * 1e6),
            }
        })
        .collect()
}
