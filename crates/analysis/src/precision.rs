//! Accuracy budgets: each consumer states what it can show and gets the
//! cheapest computation that meets it. Every tolerance in the program is
//! chosen here, and only here. The numbers behind each choice are in the
//! work–precision tables of docs/speed.md (`homerun bench`).
//!
//! A budget is the largest error in range (m) the consumer can accept; the
//! tolerance is the loosest one whose measured range error stays well inside
//! it (tested below and in `tests/hard_cases.rs`).

use model::flight::FlightOptions;
use numerics::ode::Tolerance;

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
    /// A flight of a launch direction's solve (`analysis::savant`), which
    /// wants the landing direction to 1e-4 rad: its flights need it to a
    /// hundredth of that, 1e-6 rad, ~1.5e-4 m sideways at 150 m.
    Solve,
    /// A flight of that solve while its miss is still large (over
    /// [`AIM_MISS`] rad): the next direction comes from the miss, so the
    /// landing point is wanted to 2 cm, a thousandth of that miss at 200 m
    /// (nearer the plate the solve reads it as less sure).
    Aim,
    /// A flight of a batch row in another park's air, whose verdict there
    /// is read with a slack of 1 cm (`batch::park_air`): a tenth of it.
    /// Also a direction solve's flights once they are near the bearing,
    /// their landing read as known to 3 mm sideways (`savant`).
    Verdict,
    /// The reference for the benchmarks and tests: as tight as f64 allows.
    Reference,
}

impl Purpose {
    /// The consumers, each with a budget.
    pub const CONSUMERS: [Purpose; 7] = [
        Purpose::Readout,
        Purpose::Optimizer,
        Purpose::Surface,
        Purpose::Plot,
        Purpose::Solve,
        Purpose::Aim,
        Purpose::Verdict,
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
            // A hundredth of the solve's 1e-4 rad, at 150 m.
            Purpose::Solve => 1e-6 * 150.0,
            Purpose::Aim => 0.02,
            Purpose::Verdict => 1e-3,
            Purpose::Reference => 1e-8,
        }
    }

    /// The loosest tolerance that keeps the range error well inside the
    /// budget, from `homerun bench` (Table II fastball; errors against
    /// Purpose::Reference). What each costs is in the bench's tables and in
    /// docs/speed.md, not here, where it would go stale.
    pub fn tolerance(self) -> Tolerance {
        match self {
            // 9e-8 m, 11× inside the budget. 1e-10 (5e-8 m) took 1.4× the
            // evaluations (515 against 371 on Table II, 1.5× with Nathan's
            // aero) for digits no reader sees, and a batch flies every row
            // at this precision.
            Purpose::Readout => Tolerance::uniform(1e-9),
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
            // 3e-5 m on Table II; the landing direction of Statcast-like
            // 3-D flights within 8.4e-9 rad of the reference's (worst of
            // 400), 120× inside the budget, in 92 evaluations against the
            // readout's 296. 1e-6 (67) leaves under 10×.
            Purpose::Solve => Tolerance::uniform(1e-7),
            // The landing point of 20,000 3-D flights (10–52 m/s, −30° to
            // 90°, ±2,000 rpm of sidespin, Nathan's aero) within 1.4 cm of
            // the reference's sideways, 2 mm past 50 m (7.4e-6 rad of
            // Statcast-like ones), 1.6e-3 m in range on Table II, in 39
            // evaluations against the solve's 92; 1e-5 (1.1e-6 rad) takes 50.
            Purpose::Aim => Tolerance::uniform(1e-4),
            // 3.5e-4 m in range at worst of those 2,000 flights, 2.1e-4 m on
            // Table II, in 50 evaluations against the solve's 92 (Nathan's
            // aero); 1e-4 (2e-3 m) leaves under 5× to the slack.
            Purpose::Verdict => Tolerance::uniform(1e-5),
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

/// A launch direction's solve flies at [`Purpose::Aim`] while its last miss
/// is over this (rad): its next miss then falls to ~1e-4 (a secant step),
/// and the flights that end it fly at [`Purpose::Solve`].
pub const AIM_MISS: f64 = 1e-2;

impl From<Purpose> for FlightOptions {
    fn from(purpose: Purpose) -> FlightOptions {
        purpose.flight_options()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::{self, Grid};
    use model::{self, scene::Scene};

    fn table_two() -> [Scene; 3] {
        crate::paper::table_two().map(|(_, scene)| scene)
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
        use model::flight::trajectory;
        for scene in table_two() {
            let impact = model::impact::Impact::new(&scene);
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
}
