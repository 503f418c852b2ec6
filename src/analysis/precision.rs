//! Accuracy budgets: each consumer states what it can show and gets the
//! cheapest computation that meets it. Every tolerance in the program is
//! chosen here, and only here. The numbers behind each choice are in the
//! work–precision tables of docs/speed.md (`homerun bench`).
//!
//! A budget is the largest error in range (m) the consumer can accept; the
//! tolerance is the loosest one whose measured range error stays well inside
//! it (tested below and in `tests/hard_cases.rs`).

use crate::model::flight::FlightOptions;
use crate::numerics::ode::Tolerance;

/// Who is asking for a flight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    /// Numbers printed to the user (CLI, readout): full precision, range good
    /// to ~1 µm, three orders below the last printed digit (1 mm).
    Readout,
    /// The optimiser's objective: a tenth of its own stopping tolerance
    /// (1e-4 m in range), so the simplex never compares noise.
    Optimizer,
    /// One heatmap cell: a quarter of a colour step.
    Surface,
    /// A drawn trajectory: a braille dot is ~0.5 m at the smallest zoom; the
    /// points are sampled from the dense output at the plot's resolution.
    Plot,
    /// A `fly --batch` row printed as CSV (to 1 mm, 1 ms, 1e-4 rad; the
    /// direction to 1e-6 rad): flown looser than the readout, then flown
    /// again at [`Purpose::Readout`] unless every printed digit and every
    /// outcome stands [`BATCH_GUARD`] away from where it would change, so
    /// that the batch prints exactly what `fly` prints.
    Batch,
    /// A flight of a launch direction's solve (`analysis::savant`), which
    /// wants the landing direction to 1e-4 rad: its flights need it to a
    /// hundredth of that, 1e-6 rad, ~1.5e-4 m sideways at 150 m.
    Solve,
    /// The reference for the benchmarks and tests: as tight as f64 allows.
    Reference,
}

/// How far (SI) a [`Purpose::Batch`] flight's numbers may be from the
/// readout's: a printed digit, a margin's sign or a foul line this close
/// to a change sends the row to the readout's flight. Each is ~10× the
/// worst difference from the readout's over 200 000 Statcast-like rows,
/// planar and with spray and sidespin (`scripts/batch_rows.py`'s spread):
/// 9.3e-7 m in range (pop-ups at 75°), 6.3e-8 s, 5.7e-9 rad. So ~4 % of
/// planar rows and ~13 % of 3-D ones (the direction, printed to 1e-6 rad)
/// are flown twice, and the rest once at ~55 % of the readout's cost.
pub const BATCH_GUARD: Guard = Guard {
    distance: 1e-5,
    time: 1e-6,
    angle: 5e-8,
};

/// Bounds on the difference between two precisions' numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Guard {
    /// Ranges, heights, margins (m).
    pub distance: f64,
    /// Flight times (s).
    pub time: f64,
    /// Directions and landing angles (rad).
    pub angle: f64,
}

impl Purpose {
    /// The consumers, each with a budget.
    pub const CONSUMERS: [Purpose; 6] = [
        Purpose::Readout,
        Purpose::Optimizer,
        Purpose::Surface,
        Purpose::Plot,
        Purpose::Batch,
        Purpose::Solve,
    ];

    /// The largest range error (m) this purpose can accept.
    pub fn range_budget(self) -> f64 {
        match self {
            Purpose::Readout => 1e-6,
            // A tenth of the optimiser's TolFun of 1e-4 m: the simplex
            // compares ranges that differ by ~TolFun when it stops.
            Purpose::Optimizer => 1e-5,
            // A quarter of one colour step of a surface drawn in at most 16
            // colours over a 40 m span (Fig. 7's window spans ~40 m between
            // its lowest contour of interest and the optimum):
            // 40 m / 16 / 4 = 0.625 m.
            Purpose::Surface => 0.25 * 40.0 / 16.0,
            // A quarter of a braille dot at the smallest zoom.
            Purpose::Plot => 0.1,
            // Well inside the guard, which must bound its distance from
            // the readout's numbers (tested over many rows below).
            Purpose::Batch => BATCH_GUARD.distance / 4.0,
            // A hundredth of the solve's 1e-4 rad, at 150 m.
            Purpose::Solve => 1e-6 * 150.0,
            Purpose::Reference => 1e-8,
        }
    }

    /// The loosest tolerance that keeps the range error well inside the
    /// budget, from `homerun bench` (Table II fastball; errors against
    /// Purpose::Reference). What each costs is in the bench's tables and in
    /// docs/speed.md, not here, where it would go stale.
    pub fn tolerance(self) -> Tolerance {
        match self {
            // 5e-8 m, 20× inside the budget: one solve per keystroke can
            // afford it.
            Purpose::Readout => Tolerance::uniform(1e-10),
            // ≤ 4e-6 m near the optimum, inside TolFun/10; 1e-7 gives 3e-5 m
            // (over it). The optima it finds equal those at 1e-10 to 1e-7 m in
            // E and 2e-6 rad in ψ.
            Purpose::Optimizer => Tolerance::uniform(1e-8),
            // Worst of 64×64 Fig. 7 cells: 0.0072 m flown in lock-step (0.0054
            // alone), 85× inside a quarter colour step; 1e-4 leaves under 3×
            // (0.23 m) to save ~10 % of time.
            Purpose::Surface => Tolerance::uniform(1e-5),
            // ≤ 5e-5 m at every one of 300 points read off the dense output
            // (Table II): far inside a braille dot.
            Purpose::Plot => Tolerance::uniform(1e-6),
            // Statcast-like rows: 119 evaluations a row against the
            // readout's 213 (Nathan's model), worst 9.3e-7 m off it over
            // 200 000 rows. 1e-8 (98) is 2.9e-6 m off, and its guard would
            // send ~45 % of 3-D rows to a second flight; 1e-9 (143) leaves
            // too little to gain.
            Purpose::Batch => Tolerance::uniform(3e-9),
            // 3e-5 m on Table II; the landing direction of Statcast-like
            // 3-D flights within 8.4e-9 rad of the reference's (worst of
            // 400), 120× inside the budget, in 92 evaluations against the
            // readout's 296. 1e-6 (67) leaves under 10×.
            Purpose::Solve => Tolerance::uniform(1e-7),
            Purpose::Reference => Tolerance::uniform(1e-13),
        }
    }

    pub fn flight_options(self) -> FlightOptions {
        FlightOptions {
            tolerance: self.tolerance(),
            stop_at_kinks: true,
        }
    }
}

impl From<Purpose> for FlightOptions {
    fn from(purpose: Purpose) -> FlightOptions {
        purpose.flight_options()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::study::{self, Grid};
    use crate::model::{self, scene::Scene};

    fn table_two() -> [Scene; 3] {
        crate::analysis::paper::table_two().map(|(_, scene)| scene)
    }

    #[test]
    fn every_consumer_meets_its_budget_on_table_two() {
        for scene in table_two() {
            let reference = model::range(&scene, Purpose::Reference);
            for purpose in Purpose::CONSUMERS {
                let error = (model::range(&scene, purpose) - reference).abs();
                assert!(
                    error <= purpose.range_budget(),
                    "{purpose:?}: {error:e} m over {:e} m",
                    purpose.range_budget()
                );
            }
        }
    }

    #[test]
    fn optimizer_range_error_is_far_below_its_stopping_tolerance() {
        // Near the optimum and across the ridge the simplex walks.
        let mut worst: f64 = 0.0;
        for scene in table_two() {
            for (de, dpsi) in [(0.0, 0.0), (0.002, 0.05), (-0.003, -0.1), (0.004, 0.2)] {
                let mut s = scene;
                s.bat.undercut += de;
                s.bat.swing_angle += dpsi;
                let error = (model::range(&s, Purpose::Optimizer)
                    - model::range(&s, Purpose::Reference))
                .abs();
                worst = worst.max(error);
            }
        }
        assert!(worst <= Purpose::Optimizer.range_budget(), "{worst:e}");
        assert!(Purpose::Optimizer.range_budget() <= 1e-4 / 10.0);
    }

    #[test]
    fn a_plotted_trajectory_stays_within_its_budget_between_steps() {
        use crate::model::flight::trajectory;
        for scene in table_two() {
            let impact = crate::model::impact::Impact::new(&scene);
            let (flight, launch) = model::launch(&scene, &impact);
            let plot =
                |purpose: Purpose| trajectory(&flight, &launch, &purpose.flight_options(), 300).1;
            let (drawn, tight) = (plot(Purpose::Plot), plot(Purpose::Reference));
            assert_eq!(drawn.len(), 300);
            let worst = drawn
                .iter()
                .zip(&tight)
                .map(|(a, b)| (a.x - b.x).abs().max((a.y - b.y).abs()))
                .fold(0.0, f64::max);
            assert!(worst <= Purpose::Plot.range_budget(), "{worst}");
        }
    }

    #[test]
    fn surface_cells_stay_within_a_quarter_colour_step() {
        let grid = Grid::figure7(17, 17);
        let scene = Scene::default();
        let cheap = study::surface(&scene, grid, Purpose::Surface);
        let tight = study::surface(&scene, grid, Purpose::Reference);
        let mut worst: f64 = 0.0;
        for (a, b) in cheap.outcomes().iter().zip(tight.outcomes()) {
            assert_eq!(a.range().is_some(), b.range().is_some());
            if let (Some(a), Some(b)) = (a.range(), b.range()) {
                worst = worst.max((a - b).abs());
            }
        }
        assert!(worst <= Purpose::Surface.range_budget(), "{worst}");
    }

    /// Statcast-like batted balls (~88 ± 14 mph, ~12 ± 25°, backspin
    /// rising with the angle; with `spray`, directions to ±44° and
    /// sidespin ~100 rad/s) under Nathan's model and the paper's.
    fn statcast_like(rows: usize, spray: bool) -> Vec<Scene> {
        let mut uniform = crate::numerics::xorshift::uniform(0x9e37_79b9_7f4a_7c15);
        let gauss = |u: &mut dyn FnMut() -> f64| {
            let (a, b) = (u().max(1e-300), u());
            (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
        };
        (0..rows)
            .map(|i| {
                let speed = (88.0 + 14.0 * gauss(&mut uniform)).clamp(30.0, 120.0);
                let angle = (12.0 + 25.0 * gauss(&mut uniform)).clamp(-60.0, 75.0);
                let rpm = -763.0 + 120.0 * f64::max(angle, 5.0) + 400.0 * gauss(&mut uniform);
                let (direction, sidespin) = if spray {
                    (
                        (88.0 * uniform() - 44.0).to_radians(),
                        100.0 * gauss(&mut uniform),
                    )
                } else {
                    (0.0, 0.0)
                };
                let mut scene = Scene::default();
                if i % 2 == 0 {
                    scene.set_text("model.drag", "nathan").unwrap();
                    scene.set_text("model.lift", "nathan").unwrap();
                }
                scene.with_launch(crate::model::launch::BattedBall {
                    speed: speed * 0.44704,
                    angle: angle.to_radians(),
                    spin: rpm.clamp(200.0, 4500.0) * std::f64::consts::TAU / 60.0,
                    direction,
                    sidespin,
                })
            })
            .collect()
    }

    #[test]
    fn a_batch_flight_stays_well_inside_its_guard_of_the_readout() {
        use crate::model::launch::scene_start;
        use crate::model::park::Fence;
        // The generic fence and a deep one: margins over and under walls.
        let (near, deep) = (Fence::uniform(121.92, 3.0), Fence::uniform(135.0, 11.3));
        let fences = [&near, &deep];
        let mut worst = [0.0_f64; 3];
        for spray in [false, true] {
            for scene in statcast_like(3000, spray) {
                let (flight, _, _) = scene_start(&scene);
                let judge = |purpose: Purpose| flight.judge(&purpose.flight_options(), &fences);
                let ((batch, batch_at), (readout, readout_at)) =
                    (judge(Purpose::Batch), judge(Purpose::Readout));
                assert_eq!(batch.landed, readout.landed);
                let margins = batch_at.iter().zip(&readout_at).map(|(a, b)| {
                    assert_eq!(a.outcome, b.outcome, "{scene:?}");
                    match (a.margin, b.margin) {
                        (Some(a), Some(b)) => (a - b).abs(),
                        _ => 0.0,
                    }
                });
                let distance = margins
                    .chain([batch.range - readout.range, batch.apex - readout.apex])
                    .fold(0.0_f64, |w, e| w.max(e.abs()));
                let time = (batch.flight_time - readout.flight_time).abs();
                let angle = (batch.landing_angle - readout.landing_angle)
                    .abs()
                    .max((batch.direction - readout.direction).abs());
                for (w, e) in worst.iter_mut().zip([distance, time, angle]) {
                    *w = w.max(e);
                }
            }
        }
        // A quarter of the guard at most: the guard is ~10× the worst of
        // 200 000 rows, these 6000 must stay well inside it.
        let guard = [BATCH_GUARD.distance, BATCH_GUARD.time, BATCH_GUARD.angle];
        for ((w, g), what) in worst.iter().zip(guard).zip(["m", "s", "rad"]) {
            assert!(*w <= g / 4.0, "{w:e} {what} against a guard of {g:e}");
        }
        // And the batch's tolerance is no tighter than it needs to be: the
        // worst is within ~100× of the guard (1e-9 would be ~5× tighter).
        assert!(worst[0] > BATCH_GUARD.distance / 100.0, "{worst:?}");
    }
}
