//! Numbers quoted in the paper's text (§II–III), recomputed.

use crate::common;

use homerun::Purpose;
use homerun::analysis::study;
use homerun::model::impact::{Impact, Regime};
use homerun::model::pitch;

#[test]
fn vertical_velocity_at_38_m_per_s() {
    // §III: V̂_by0 = −5.71 m/s for the 38 m/s pitch of Figs. 5–6.
    let v = pitch::vertical_velocity(38.0, 9.81);
    assert!((v + 5.71).abs() < 0.005, "{v}");
}

fn figure5_impact(undercut: f64, friction: f64) -> Impact {
    let mut scene = common::scene("figure5");
    scene.bat.undercut = undercut;
    scene.bat.friction = friction;
    Impact::new(&scene)
}

#[test]
fn slip_halts_below_0_0638_m_with_aluminium() {
    // §III: "for μ = 0.35 (aluminum), the slip halts during impact for
    // undercuts less than E = 0.64" — a misprint for 0.064 m; the threshold
    // is where p_s = p_f.
    let threshold = common::bisect(0.0, 0.0715, |e| {
        figure5_impact(e, 0.35).regime == Regime::Stick
    });
    assert!((threshold - 0.0638).abs() < 0.0005, "{threshold}");
    // Stick below it, slip above it, all the way to the edge of the bat.
    for e in [0.0, 0.02, 0.04, 0.06, 0.063] {
        assert_eq!(figure5_impact(e, 0.35).regime, Regime::Stick, "E = {e}");
    }
    for e in [0.065, 0.068, 0.071] {
        assert_eq!(figure5_impact(e, 0.35).regime, Regime::Slip, "E = {e}");
    }
}

#[test]
fn a_thousand_rad_per_s_of_backspin_needs_0_0675_m() {
    // §III: 1000 rad/s "requires an undercut of E = 0.068 m" at μ = 0.5. The
    // spin peaks near E = 0.068 m (where slip starts to last to separation),
    // so the search runs on the rising side.
    let spin = |e| figure5_impact(e, 0.5).launch_spin();
    assert!(spin(0.06) < 1000.0 && spin(0.068) > 1000.0);
    let undercut = common::bisect(0.05, 0.068, |e| spin(e) > 1000.0);
    assert!((undercut - 0.0675).abs() < 0.001, "{undercut}");
}

#[test]
fn wood_and_aluminium_give_the_same_spin_while_slip_halts() {
    // Figs. 5–6: μ = 0.35 and 0.5 give the same ω_bf and ζ up to E ≈ 0.064 m.
    let scene = common::scene("figure5");
    let undercuts: Vec<f64> = (0..=70).map(|i| i as f64 * 0.001).collect();
    let curves = study::impact_curves(&scene, &[0.35, 0.5], &undercuts);
    assert_eq!(curves.len(), 2);
    assert_eq!(curves[0].points.len(), 71);
    for (a, b) in curves[0].points.iter().zip(&curves[1].points) {
        assert_eq!(a.undercut, b.undercut);
        if a.undercut < 0.063 {
            assert!((a.launch_spin - b.launch_spin).abs() < 1e-9, "{a:?} {b:?}");
            assert!(
                (a.launch_angle - b.launch_angle).abs() < 1e-12,
                "{a:?} {b:?}"
            );
        }
        if a.undercut > 0.065 {
            assert_eq!(a.regime, Regime::Slip);
            assert!(b.launch_spin > a.launch_spin + 10.0, "{a:?} {b:?}");
        }
    }
}

/// The undercut at which the fastball swung at ψ = 0.1594 leaves with `spin`.
fn fastball_undercut_for_spin(spin: f64) -> (f64, Impact) {
    let scene = common::scene("fastball");
    let at = |e: f64| Impact::new(&common::with_swing(&scene, e, 0.1594));
    let e = common::bisect(0.0, 0.06, |e| at(e).launch_spin() > spin);
    (e, at(e))
}

#[test]
fn figure13_points_a_and_b() {
    // Fig. 13: A (44.34 m/s, 182.4 rad/s, 0.448 rad) and B (43.63 m/s,
    // 308.3 rad/s, 0.615 rad) "differ only in undercut by 6.5 mm".
    let (e_a, a) = fastball_undercut_for_spin(182.4);
    let (e_b, b) = fastball_undercut_for_spin(308.3);
    assert!(
        (a.launch_speed() - 44.34).abs() < 0.05,
        "{}",
        a.launch_speed()
    );
    assert!(
        (a.launch_angle() - 0.448).abs() < 0.005,
        "{}",
        a.launch_angle()
    );
    assert!(
        (b.launch_speed() - 43.63).abs() < 0.05,
        "{}",
        b.launch_speed()
    );
    assert!(
        (b.launch_angle() - 0.615).abs() < 0.005,
        "{}",
        b.launch_angle()
    );
    let apart = e_b - e_a;
    assert!((apart - 0.0065).abs() < 0.001, "{apart}");
}

#[test]
fn figure13_slice_peaks_at_the_optimal_undercut() {
    let scene = common::scene("fastball");
    let undercuts: Vec<f64> = (0..=60).map(|i| 0.01 + i as f64 * 0.0005).collect();
    let slice = study::slice(&scene, 0.1594, &undercuts, Purpose::Surface);
    assert_eq!(slice.len(), undercuts.len());
    let best = slice
        .iter()
        .max_by(|a, b| a.range.total_cmp(&b.range))
        .unwrap();
    // Fig. 13 peaks near 135 m at E ≈ 0.027 m (the optimum at this ψ).
    assert!((best.undercut - 0.0272).abs() <= 0.0005, "{best:?}");
    assert!((best.range - 134.77).abs() < 0.1, "{best:?}");
    // §III on Fig. 7: more than 120 m needs 0.020 < E < 0.036 m.
    for p in &slice {
        if (0.0205..=0.0355).contains(&p.undercut) {
            assert!(p.range > 120.0, "{p:?}");
        }
        if !(0.0195..=0.0365).contains(&p.undercut) {
            assert!(p.range < 120.0, "{p:?}");
        }
    }
}

#[test]
fn figure14_both_flights_go_through_the_drag_crisis() {
    // Fig. 14: both trajectories pass through the drag crisis while rising
    // and stay below it (high drag) while descending; B spends longer there.
    let scene = common::scene("fastball");
    let mut high_drag_time = Vec::new();
    for spin in [182.4, 308.3] {
        let (e, _) = fastball_undercut_for_spin(spin);
        let (summary, points) =
            study::drag_along_flight(&common::with_swing(&scene, e, 0.1594), 401, Purpose::Plot);
        assert_eq!(points.len(), 401);
        assert!((points.last().unwrap().time - summary.flight_time).abs() < 1e-12);
        let first = points[0].drag_coefficient;
        let floor = points
            .iter()
            .position(|p| p.drag_coefficient <= 0.15 + 1e-12)
            .expect("reaches the crisis floor");
        let high = points
            .iter()
            .position(|p| p.drag_coefficient > 0.45)
            .expect("reaches subcritical drag");
        assert!(first > 0.25, "starts supercritical: {first}");
        assert!(floor < high, "crisis before subcritical drag");
        // Once subcritical, it stays subcritical to the landing.
        assert!(points[high..].iter().all(|p| p.drag_coefficient > 0.3));
        let dt = points[1].time - points[0].time;
        high_drag_time
            .push(points.iter().filter(|p| p.drag_coefficient > 0.45).count() as f64 * dt);
    }
    assert!(
        high_drag_time[1] > high_drag_time[0] + 0.3,
        "{high_drag_time:?}"
    );
}
