//! Flies the Table II fastball launch N times (default 10 000) at a stated
//! tolerance, for profilers: `valgrind --tool=callgrind
//! target/release/examples/flights 1000 1e-5 1e-4`.

use homerun::model::flight::{self, FlightOptions};
use homerun::model::{self, impact::Impact, scene::Scene};
use homerun::numerics::ode::Tolerance;

fn main() {
    let mut args = std::env::args().skip(1);
    let count: usize = args.next().map_or(10_000, |a| a.parse().expect("count"));
    let relative: f64 = args
        .next()
        .map_or(1e-5, |a| a.parse().expect("relative tolerance"));
    let absolute: f64 = args
        .next()
        .map_or(relative, |a| a.parse().expect("absolute tolerance"));
    let mut scene = Scene::default();
    if std::env::var_os("CONSTANT_DRAG").is_some() {
        scene.drag = homerun::model::aero::DragModel::Constant;
    }
    let (flight, launch) = model::launch(&scene, &Impact::new(&scene));
    let options = FlightOptions {
        tolerance: Tolerance { relative, absolute },
        stop_at_kinks: true,
    };
    if std::env::var_os("TRACE").is_some() {
        flight::fly_observed(&flight, &launch, &options, |step| {
            let re = |v: f64, w: f64| flight.reynolds(nalgebra::Vector2::new(v, w));
            println!(
                "{:9.6} → {:9.6}  h {:8.5}  Re {:8.0} → {:8.0}  y {:8.3}",
                step.t0,
                step.t1,
                step.t1 - step.t0,
                re(step.y0[2], step.y0[3]),
                re(step.y1[2], step.y1[3]),
                step.y1[1]
            );
        });
    }
    let mut total = 0.0;
    let mut summary = None;
    for _ in 0..count {
        let s = flight::fly(std::hint::black_box(&flight), &launch, &options);
        total += s.range;
        summary = Some(s);
    }
    let s = summary.expect("at least one flight");
    println!(
        "range {:.9} m, {} evaluations, {} accepted, {} rejected (sum {total})",
        s.range, s.stats.evaluations, s.stats.accepted, s.stats.rejected
    );
}
