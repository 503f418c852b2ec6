//! The range surface's cells are typed: a landing (with its range), a ball
//! that does not land within its limits, or a bat that misses. A cell that
//! does not land is never a range, and never the best cell.

use homerun::analysis::study::{self, CellOutcome, Grid};
use homerun::{Purpose, Scene, model};

/// The fastball in a hundredth of a percent of Earth's gravity: some swings
/// land, many hover past the flight's time limit.
fn hovering() -> Scene {
    let mut scene = Scene::default();
    scene.environment.gravity = 0.001;
    scene
}

/// An 8×8 grid reaching past the bat (|E| ≥ r_b + r_B = 71.6 mm).
fn grid() -> Grid {
    Grid {
        undercut: (0.0, 0.08),
        swing_angle: (-0.6, 1.0),
        columns: 8,
        rows: 8,
    }
}

#[test]
fn the_cells_that_do_not_land_are_exactly_those_whose_flight_does_not() {
    let scene = hovering();
    let grid = grid();
    let surface = study::surface(&scene, grid, Purpose::Surface);
    let mut counts = [0; 3];
    for j in 0..grid.rows {
        for i in 0..grid.columns {
            let (e, psi) = (grid.undercut_at(i), grid.swing_angle_at(j));
            let outcome = surface.outcome(i, j);
            if e >= scene.reach() {
                assert_eq!(outcome, CellOutcome::BatMisses, "E {e}");
                counts[2] += 1;
                continue;
            }
            let flight = model::simulate(&scene.with_swing(e, psi), Purpose::Surface).flight;
            if flight.landed {
                // The surface flies its cells in lock-step, with steps of
                // its own: the same landing, to the surface's budget.
                let range = surface.get(i, j).expect("a landing");
                assert_eq!(outcome, CellOutcome::Landed(range), "E {e} ψ {psi}");
                assert!(
                    (range - flight.range).abs() <= Purpose::Surface.range_budget(),
                    "E {e} ψ {psi}: {range} against {}",
                    flight.range
                );
                counts[0] += 1;
            } else {
                assert_eq!(outcome, CellOutcome::NotLanded, "E {e} ψ {psi}");
                assert_eq!(surface.get(i, j), None);
                counts[1] += 1;
            }
        }
    }
    // All three kinds are there, or the test would prove little.
    assert!(counts.iter().all(|&n| n >= 5), "{counts:?}");
    assert!(surface.any_not_landed());

    // The best cell is the longest landing, not a hovering ball's distance
    // at its limit (which here is farther than any landing).
    let (i, j, best) = surface.best().unwrap();
    assert_eq!(surface.outcome(i, j), CellOutcome::Landed(best));
    assert_eq!(best, surface.landed_ranges().fold(f64::MIN, f64::max));
    let farthest_up = (0..grid.columns * grid.rows)
        .filter(|k| surface.outcome(k % 8, k / 8) == CellOutcome::NotLanded)
        .map(|k| {
            let (e, psi) = (grid.undercut_at(k % 8), grid.swing_angle_at(k / 8));
            model::simulate(&scene.with_swing(e, psi), Purpose::Surface)
                .flight
                .range
        })
        .fold(f64::MIN, f64::max);
    assert!(farthest_up > best, "{farthest_up} {best}");

    // The budgeted surface (the CLI's) agrees cell for cell.
    let within = study::surface_within(&scene, grid, Purpose::Surface, u64::MAX, &|| {}).unwrap();
    assert_eq!(within.outcomes(), surface.outcomes());
    // A cancelled surface gives nothing; an unflown one is all NotComputed.
    assert!(study::surface_until(&scene, grid, Purpose::Surface, &|| true).is_none());
    let empty = study::Surface::not_computed(grid);
    assert!(
        empty
            .outcomes()
            .iter()
            .all(|&c| c == CellOutcome::NotComputed)
    );
    assert_eq!(empty.best(), None);
}

#[test]
fn on_earth_every_reachable_cell_of_figure7_lands() {
    let surface = study::surface(&Scene::default(), Grid::figure7(6, 5), Purpose::Surface);
    assert!(!surface.any_not_landed());
    assert_eq!(surface.landed_ranges().count(), 30);
}
