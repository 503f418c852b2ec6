//! Flights in lock-step ([`homerun::model::many`]) against the single
//! flight: many random launches, planar and 3-D, under the paper's aero
//! (stopping at the drag curve's kinks) and Nathan's, with wind layers, spin
//! decay and balls that never land, each flown four at a time and alone.

use homerun::Purpose;
use homerun::model::flight::{FlightOptions, FlightSummary};
use homerun::model::launch::{BattedBall, SceneFlight};
use homerun::model::many::{fly_many, judge_many, land_many};
use homerun::model::park::{Fence, bundled};
use homerun::model::scene::Scene;

/// A small deterministic generator (no dependency for a test's dice).
struct Dice(u64);

impl Dice {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }
}

/// `count` random flights of every kind the lanes must carry.
fn random_flights(count: usize, seed: u64) -> Vec<SceneFlight> {
    let mut dice = Dice(seed);
    (0..count)
        .map(|k| {
            let mut scene = Scene::default();
            let (drag, lift) = [
                ("sawicki2003", "sawicki2003"),
                ("nathan", "nathan"),
                ("constant", "none"),
                ("nathan", "sawicki2003"),
            ][k % 4];
            scene.drag = drag.parse().unwrap();
            scene.lift = lift.parse().unwrap();
            if dice.next() < 0.3 {
                scene.spin_decay = dice.between(2.0, 40.0);
            }
            if dice.next() < 0.5 {
                scene.environment.wind = dice.between(-8.0, 8.0);
                scene.environment.wind_direction = dice.between(-1.0, 1.0);
                if dice.next() < 0.5 {
                    scene.environment.wind_height = dice.between(2.0, 20.0);
                }
            }
            if k % 23 == 5 {
                // Held up for minutes: followed to its time limit.
                scene.environment.gravity = 1e-3;
            }
            let sidespin = if dice.next() < 0.5 {
                0.0
            } else {
                dice.between(-150.0, 150.0)
            };
            let ball = BattedBall {
                speed: dice.between(15.0, 55.0),
                angle: dice.between(-0.3, 1.2),
                spin: dice.between(-200.0, 350.0),
                direction: dice.between(-0.7, 0.7),
                sidespin,
            };
            SceneFlight::new(&scene.with_launch(ball), &ball)
        })
        .collect()
}

/// Each flight alone and in lock-step.
fn both(flights: &[SceneFlight], purpose: Purpose) -> Vec<(FlightSummary, FlightSummary)> {
    let options = purpose.flight_options();
    let mut many = vec![None; flights.len()];
    fly_many(flights.iter().copied(), &options, |index, summary| {
        assert!(many[index].is_none(), "flight {index} reported twice");
        many[index] = Some(summary);
    });
    flights
        .iter()
        .zip(many)
        .map(|(flight, many)| (flight.fly(&options), many.expect("every flight reported")))
        .collect()
}

#[test]
fn lock_step_flights_agree_with_single_flights_to_their_budget() {
    let flights = random_flights(240, 18);
    let planar = flights.iter().filter(|f| f.is_planar()).count();
    assert!(planar > 40 && planar < 200, "{planar} planar of 240");
    for purpose in [Purpose::Readout, Purpose::Surface] {
        let budget = purpose.range_budget();
        let mut worst: f64 = 0.0;
        let mut worst_error: f64 = 0.0;
        let mut not_landed = 0;
        let reference = Purpose::Reference.flight_options();
        for (k, (alone, many)) in both(&flights, purpose).iter().enumerate() {
            assert_eq!(alone.landed, many.landed, "{purpose:?} flight {k}");
            if !alone.landed {
                not_landed += 1;
                // Both stop at the time limit.
                assert_eq!(alone.flight_time, many.flight_time, "flight {k}");
                continue;
            }
            let truth = flights[k].fly(&reference);
            worst_error = worst_error.max((many.range - truth.range).abs());
            let scale = alone.range.abs().max(1.0);
            for (a, b) in [
                (alone.range, many.range),
                (alone.apex, many.apex),
                (alone.apex_distance, many.apex_distance),
                (alone.landing_speed, many.landing_speed),
                (alone.flight_time * 40.0, many.flight_time * 40.0),
            ] {
                worst = worst.max((a - b).abs() / scale * 100.0);
            }
            assert!(
                (alone.direction - many.direction).abs() * alone.range.abs() <= budget,
                "{purpose:?} flight {k}: direction {} against {}",
                alone.direction,
                many.direction
            );
        }
        assert!(not_landed >= 5, "{not_landed}");
        // In metres over a 100 m flight: the two take different steps (the
        // lanes start from a neighbour's first step), each within its
        // tolerance of the truth.
        eprintln!(
            "{purpose:?}: worst difference {worst:.2e} m per 100 m, worst range error {worst_error:.2e} m"
        );
        assert!(
            worst <= budget,
            "{purpose:?}: {worst:e} m over {budget:e} m"
        );
        assert!(
            worst_error <= budget,
            "{purpose:?}: {worst_error:e} m over {budget:e} m"
        );
    }
}

#[test]
fn lock_step_flights_that_do_not_stop_at_kinks_agree_too() {
    // Each evaluation then takes the drag piece its Re is on.
    let flights = random_flights(60, 3);
    let options = FlightOptions {
        stop_at_kinks: false,
        ..Purpose::Readout.flight_options()
    };
    let mut many = vec![None; flights.len()];
    fly_many(flights.iter().copied(), &options, |index, summary| {
        many[index] = Some(summary);
    });
    for (k, (flight, many)) in flights.iter().zip(many).enumerate() {
        let (alone, many) = (flight.fly(&options), many.unwrap());
        assert_eq!(alone.landed, many.landed, "flight {k}");
        // Measured: 1.4e-9 m.
        assert!(
            (alone.range - many.range).abs() <= Purpose::Readout.range_budget(),
            "flight {k}: {} against {}",
            alone.range,
            many.range
        );
    }
}

#[test]
fn lock_step_flights_find_the_fences_the_single_flight_finds() {
    let flights = random_flights(80, 7);
    let parks = bundled();
    let fences: Vec<&Fence> = parks.iter().map(|p| &p.fence).collect();
    let options = Purpose::Readout.flight_options();
    let mut seen = 0;
    judge_many(
        flights.iter().map(|f| (*f, &fences[..])),
        &options,
        |index, summary, crossings| {
            seen += 1;
            let mut alone = vec![None; fences.len()];
            let single = flights[index].fly_to_fences(&options, &fences, &mut alone);
            assert_eq!(single.landed, summary.landed);
            for (a, b) in alone.iter().zip(crossings) {
                match (a, b) {
                    (Some(a), Some(b)) => {
                        assert!((a.height - b.height).abs() < 1e-6, "{index}: {a:?} {b:?}");
                        assert!((a.time - b.time).abs() < 1e-7, "{index}: {a:?} {b:?}");
                    }
                    (None, None) => {}
                    _ => panic!("flight {index}: {a:?} against {b:?}"),
                }
            }
        },
    );
    assert_eq!(seen, flights.len());
}

#[test]
fn flights_asked_for_their_range_alone_are_the_same_flights() {
    // Without their apexes located (a step that only passes one is left
    // unseen), each flight's range, time, work and landing are its whole
    // summary's, bit for bit: at a surface's tolerance, the
    // readout's and without the kinks.
    let flights = random_flights(240, 41);
    let no_kinks = FlightOptions {
        stop_at_kinks: false,
        ..Purpose::Readout.flight_options()
    };
    let option_sets = [
        Purpose::Surface.flight_options(),
        Purpose::Readout.flight_options(),
        no_kinks,
    ];
    for options in &option_sets {
        let mut whole = vec![None; flights.len()];
        fly_many(flights.iter().copied(), options, |index, summary| {
            whole[index] = Some(summary.range_summary());
        });
        let mut ranges = vec![None; flights.len()];
        land_many(flights.iter().copied(), options, |index, range| {
            assert!(ranges[index].is_none(), "flight {index} reported twice");
            ranges[index] = Some(range);
        });
        for (k, (whole, range)) in whole.iter().zip(&ranges).enumerate() {
            // Debug prints each number's shortest exact form.
            let whole = whole.expect("every flight reported");
            assert_eq!(
                format!("{whole:?}"),
                format!("{:?}", range.expect("every flight reported")),
                "flight {k}"
            );
        }
    }
}
