//! What judging a flight at the parks costs (`homerun bench`): one flight
//! alone, with the generic fence, with the 30 parks' fences (one flight
//! serves them all), and a Savant row's whole work (the launch direction
//! solved so that the ball lands on its spray, then the flight judged at 31
//! fences), at readout precision.

use serde::Serialize;

use super::{Effort, TRAJECTORY_BATCH, time_median};
use crate::precision::Purpose;
use crate::savant::{self, RowLaunch, Spray};
use model::launch::{BattedBall, SceneFlight};
use model::park::{Fence, bundled};
use model::scene::Scene;
use model::spin_estimate::{Side, nathan_spin};

#[derive(Clone, Debug, Serialize)]
pub struct ParksRow {
    /// What one row's work is.
    pub work: &'static str,
    /// Flights it takes.
    pub flights: usize,
    pub time_us: f64,
    pub cpu_us: Option<f64>,
}

/// A right-handed batter's home run to left-centre (102 mph, 28°, landing
/// 15° toward left field), with Nathan's spin for its launch.
fn home_run() -> (Scene, RowLaunch) {
    let (angle, bearing) = (28f64.to_radians(), -15f64.to_radians());
    let (spin, sidespin) = nathan_spin(angle, bearing, Some(Side::Right));
    let scene = Scene::default().with_launch(BattedBall {
        speed: 102.0 * 0.44704,
        angle,
        spin,
        direction: bearing,
        sidespin,
    });
    let row = RowLaunch {
        spray: Some(bearing),
        side: Some(Side::Right),
        estimate_backspin: true,
        estimate_sidespin: true,
        measured_spin: None,
    };
    (scene, row)
}

pub(super) fn rows(effort: Effort) -> Vec<ParksRow> {
    let options = Purpose::Readout.flight_options();
    let (scene, row) = home_run();
    let flight = SceneFlight::new(&scene, &scene.batted_ball());
    let generic = Fence::uniform(121.9, 3.0);
    let parks: Vec<&Fence> = bundled().iter().map(|p| &p.fence).collect();
    let mut all = vec![&generic];
    all.extend_from_slice(&parks);
    let solved = savant::launch(&scene, &row, Spray::Landing, &options);
    let measure = |work, flights, job: &mut dyn FnMut()| {
        let (time, cpu) = time_median(effort.trajectory_batches, TRAJECTORY_BATCH, job);
        ParksRow {
            work,
            flights,
            time_us: time * 1e6,
            cpu_us: cpu.map(|c| c * 1e6),
        }
    };
    let judge = |fences: &[&Fence]| {
        std::hint::black_box(std::hint::black_box(&flight).judge(&options, fences));
    };
    vec![
        measure("flight", 1, &mut || {
            std::hint::black_box(std::hint::black_box(&flight).fly(&options));
        }),
        measure("flight, generic fence", 1, &mut || judge(&all[..1])),
        measure("flight, generic + 30 parks", 1, &mut || judge(&all)),
        measure("spray solved, then that", solved.flights + 1, &mut || {
            let solved = savant::launch(&scene, &row, Spray::Landing, &options);
            let s = solved.scene;
            std::hint::black_box(SceneFlight::new(&s, &s.batted_ball()).judge(&options, &all));
        }),
    ]
}
