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
        // One thread: the cost per cell, start-up and output aside.
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let scene = Scene::default();
        let mut total = 0.0;
        let start = std::time::Instant::now();
        for _ in 0..count {
            let s =
                pool.install(|| study::surface(&scene, Grid::figure7(64, 64), Purpose::Surface));
            total += s.landed_ranges().sum::<f64>();
        }
        let per = start.elapsed().as_secs_f64() / count as f64;
        println!(
            "surface: 64x64 in {:.3} ms, {:.3} µs a cell ({total:.3})",
            per * 1e3,
            per * 1e6 / 4096.0
        );
        return;
    }
    if what == "cells" {
        // The surface's flights (impacts done), alone and in lock-step.
        use homerun::model::impact::Collision;
        use homerun::model::launch::SceneFlight;
        let mut scene = Scene::default();
        if let Ok(drag) = std::env::var("DRAG") {
            scene.drag = drag.parse().unwrap();
        }
        if let Ok(lift) = std::env::var("LIFT") {
            scene.lift = lift.parse().unwrap();
        }
        let grid = Grid::figure7(64, 64);
        let flights: Vec<SceneFlight> = (0..4096)
            .map(|k| (grid.undercut_at(k % 64), grid.swing_angle_at(k / 64)))
            .filter(|(e, _)| e.abs() < scene.reach())
            .map(|(e, psi)| {
                let s = scene.with_swing(e, psi);
                SceneFlight::of_impact(&s, &Collision::new(&s))
            })
            .collect();
        let mut options = Purpose::Surface.flight_options();
        options.stop_at_kinks = std::env::var_os("NOKINKS").is_none();
        let mut evaluations = 0u64;
        let start = std::time::Instant::now();
        for _ in 0..count {
            evaluations = 0;
            homerun::model::many::fly_many(flights.iter().copied(), &options, |_, f| {
                evaluations += u64::from(f.stats.evaluations)
            });
        }
        let many = start.elapsed().as_secs_f64() / count as f64;
        let start = std::time::Instant::now();
        let mut alone = 0u64;
        for _ in 0..count.min(if std::env::var_os("ALONE").is_some() {
            count
        } else {
            1
        }) {
            alone = flights
                .iter()
                .map(|f| u64::from(f.fly(&options).stats.evaluations))
                .sum();
        }
        let single = start.elapsed().as_secs_f64()
            / count.min(if std::env::var_os("ALONE").is_some() {
                count
            } else {
                1
            }) as f64;
        if std::env::var_os("ERRORS").is_some() {
            let reference = Purpose::Reference.flight_options();
            let truth: Vec<f64> = flights.iter().map(|f| f.fly(&reference).range).collect();
            let alone: Vec<f64> = flights.iter().map(|f| f.fly(&options).range).collect();
            let mut many = vec![0.0; flights.len()];
            homerun::model::many::fly_many(flights.iter().copied(), &options, |i, f| {
                many[i] = f.range
            });
            let stats = |v: &[f64]| {
                let e: Vec<f64> = v.iter().zip(&truth).map(|(a, b)| (a - b).abs()).collect();
                let rms = (e.iter().map(|x| x * x).sum::<f64>() / e.len() as f64).sqrt();
                let mut sorted = e.clone();
                sorted.sort_by(f64::total_cmp);
                (
                    rms,
                    sorted[sorted.len() / 2],
                    sorted[sorted.len() * 99 / 100],
                    sorted[sorted.len() - 1],
                )
            };
            println!(
                "errors (rms, median, 99th, max): alone {:?} many {:?}",
                stats(&alone),
                stats(&many)
            );
        }
        let n = flights.len() as f64;
        println!(
            "cells: {} flights; lock-step {:.3} µs a flight, {:.1} evaluations, {:.2} ns an evaluation; alone {:.3} µs, {:.1} evaluations, {:.2} ns",
            flights.len(),
            many * 1e6 / n,
            evaluations as f64 / n,
            many * 1e9 / evaluations as f64,
            single * 1e6 / n,
            alone as f64 / n,
            single * 1e9 / alone as f64,
        );
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
