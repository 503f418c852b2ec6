//! A flight that does not land within its limits has no range: what to say
//! instead, in one place for every command and figure.

use crate::model::flight::{FlightOptions, FlightSummary};
use crate::model::impact::Collision;
use crate::model::launch::SceneFlight;
use crate::model::scene::Scene;
use crate::numerics::ode;

/// The height (m) of `scene`'s ball where its flight ends: 0 on landing, or
/// where it is at its time or step limit.
pub fn end_height(scene: &Scene, options: impl Into<FlightOptions>) -> f64 {
    let impact = Collision::new(scene);
    let (_, points) = SceneFlight::of_impact(scene, &impact).trajectory(&options.into(), 2);
    points.last().map_or(0.0, |p| p.y)
}

/// Why a flight has no range, in words: "did not land within 92.0 s (still
/// 235.7 m up)", or, stopped by the integrator's step limit, "did not land
/// within 100000 integration steps (61.2 s, still 235.7 m up)". `height` is
/// where the ball was at the end ([`end_height`]).
pub fn not_landed(summary: &FlightSummary, height: f64) -> String {
    not_landed_at(summary, &format!("{height:.1} m"))
}

/// [`not_landed`] with the height already written, in whatever unit the
/// caller shows ("773.3 ft").
pub fn not_landed_at(summary: &FlightSummary, height: &str) -> String {
    let steps = summary.stats.accepted + summary.stats.rejected;
    if steps >= ode::MAX_STEPS {
        format!(
            "did not land within {} integration steps ({:.1} s, still {height} up)",
            ode::MAX_STEPS,
            summary.flight_time
        )
    } else {
        format!(
            "did not land within {:.1} s (still {height} up)",
            summary.flight_time
        )
    }
}

/// [`not_landed`] for `scene`'s own swing flown at `options`, or `None` if
/// it lands.
pub fn why_not_landed(
    scene: &Scene,
    summary: &FlightSummary,
    options: impl Into<FlightOptions>,
) -> Option<String> {
    (!summary.landed).then(|| not_landed(summary, end_height(scene, options)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::precision::Purpose;
    use crate::model;

    #[test]
    fn a_hovering_ball_is_still_up_and_says_so() {
        let mut scene = Scene::default();
        scene.environment.gravity = 0.001;
        let swing = model::simulate(&scene, Purpose::Readout);
        let why = why_not_landed(&scene, &swing.flight, Purpose::Readout).unwrap();
        let height = end_height(&scene, Purpose::Readout);
        assert!(height > 1.0, "{height}");
        assert_eq!(
            why,
            format!(
                "did not land within {:.1} s (still {height:.1} m up)",
                swing.flight.flight_time
            )
        );
        let scene = Scene::default();
        let swing = model::simulate(&scene, Purpose::Readout);
        assert_eq!(
            why_not_landed(&scene, &swing.flight, Purpose::Readout),
            None
        );
        assert_eq!(end_height(&scene, Purpose::Readout), 0.0);
    }
}
