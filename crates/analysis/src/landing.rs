//! A flight that does not land within its limits has no range: what to say
//! instead, in one place for every command and figure.

use model::flight::{FlightOptions, FlightSummary};
use model::impact::Collision;
use model::launch::SceneFlight;
use model::scene::Scene;
use numerics::ode;
use units::Unit;

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

/// Whether the ball clears a fence `distance` away and `height` high, in
/// the same words for the command line and the explorer: "121.9 m, 3.0 m
/// high: over by 9.2 m", "…: under by 1.3 m", "…: falls short".
/// `height_at` is the ball's height where it passes the fence (`None`:
/// it never gets there); `unit` is the distances' (m or ft). The fence is
/// written as given, a round number in feet as such ([`as_given`]).
pub fn fence_text(distance: f64, height: f64, height_at: Option<f64>, unit: Unit) -> String {
    let by = |metres: f64| format!("{:.1} {}", unit.show_difference(metres), unit.symbol);
    let clearance = match height_at {
        Some(h) if h >= height => format!("over by {}", by(h - height)),
        Some(h) => format!("under by {}", by(height - h)),
        None => "falls short".to_owned(),
    };
    format!(
        "{} {unit}, {} {unit} high: {clearance}",
        as_given(distance, 1, unit),
        as_given(height, 1, unit),
        unit = unit.symbol
    )
}

/// A length given in metres to `decimals` (a preset's 121.9), in `unit`:
/// the roundest number there that names the same metres to those decimals
/// (121.9 m is 400 ft, 121.92 m; 3.0 m is 10 ft, 3.048 m), rather than the
/// conversion's own digits (399.9 ft).
pub fn as_given(metres: f64, decimals: usize, unit: Unit) -> String {
    let given = format!("{metres:.decimals$}");
    if unit.is_identity() {
        return given;
    }
    let shown = unit.show(metres);
    let finest = unit.decimals(decimals);
    (0..=finest)
        .map(|d| format!("{shown:.d$}"))
        .find(|text| {
            text.parse::<f64>()
                .is_ok_and(|v| format!("{:.decimals$}", unit.read(v)) == given)
        })
        .unwrap_or_else(|| format!("{shown:.finest$}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::precision::Purpose;
    use model;
    use units::{Quantity, UnitSystem};

    #[test]
    fn a_fence_reads_as_given_and_says_by_how_much_it_is_cleared() {
        let (m, ft) = (
            Quantity::Distance.in_system(UnitSystem::Si),
            Quantity::Distance.in_system(UnitSystem::Imperial),
        );
        assert_eq!(
            fence_text(121.9, 3.0, Some(12.2), m),
            "121.9 m, 3.0 m high: over by 9.2 m"
        );
        // 121.9 m is 399.93 ft: 400 ft names the same 121.9 m.
        assert_eq!(
            fence_text(121.9, 3.0, Some(12.2), ft),
            "400 ft, 10 ft high: over by 30.2 ft"
        );
        assert_eq!(
            fence_text(121.9, 3.0, Some(1.7), m),
            "121.9 m, 3.0 m high: under by 1.3 m"
        );
        assert_eq!(
            fence_text(121.9, 3.0, None, m),
            "121.9 m, 3.0 m high: falls short"
        );
        // 328 ft is 99.97 m, 100.0 m to a decimal; no whole foot is 100.1 m.
        assert_eq!(as_given(100.0, 1, ft), "328");
        assert_eq!(as_given(100.1, 1, ft), "328.4");
        assert_eq!(as_given(91.44, 1, ft), "300");
        assert_eq!(as_given(121.9, 1, m), "121.9");
    }

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
