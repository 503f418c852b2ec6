//! One flight, many times, for `perf stat` and `valgrind --tool=callgrind`:
//! `cargo run --release --example flight_cost -- [paper|nathan|surface] [count]`.
//! The Table II fastball's launch at rel 1e-4 / abs 1e-3 (the bench's row),
//! under the paper's aero (stopping at the drag curve's kinks) or Nathan's;
//! or a 64×64 Fig. 7 surface at Purpose::Surface.

use homerun::analysis::precision::Purpose;
use homerun::analysis::study::{self, Grid};
use homerun::model::aero::{DragModel, LiftModel};
use homerun::model::flight::{self, Flight, FlightOptions};
use homerun::model::impact::Impact;
use homerun::model::{self, scene::Scene};
use homerun::numerics::ode::Tolerance;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let what = args.get(1).map_or("paper", String::as_str);
    let count: usize = args.get(2).and_then(|n| n.parse().ok()).unwrap_or(100_000);
    if what == "surface" {
        let scene = Scene::default();
        let mut total = 0.0;
        for _ in 0..count {
            let s = study::surface(&scene, Grid::figure7(64, 64), Purpose::Surface);
            total += s.landed_ranges().sum::<f64>();
        }
        println!("{total}");
        return;
    }
    let mut scene = Scene::default();
    if what == "nathan" {
        scene.drag = DragModel::Nathan;
        scene.lift = LiftModel::Nathan;
    }
    let spin = Impact::new(&Scene::default()).launch_spin();
    let (_, launch) = model::launch(&Scene::default(), &Impact::new(&Scene::default()));
    let flight = Flight::new(&scene, spin);
    let options = FlightOptions {
        tolerance: Tolerance {
            relative: 1e-4,
            absolute: 1e-3,
        },
        stop_at_kinks: true,
    };
    let one = flight::fly(&flight, &launch, &options);
    let mut total = 0.0;
    let start = std::time::Instant::now();
    for _ in 0..count {
        total += flight::fly(std::hint::black_box(&flight), &launch, &options).range;
    }
    let per = start.elapsed().as_secs_f64() / count as f64;
    println!(
        "{what}: range {:.9} m, {} evaluations, {:.3} µs a flight ({total:.3})",
        one.range,
        one.stats.evaluations,
        per * 1e6
    );
}
