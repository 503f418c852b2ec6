//! A contact that grips (`bat.tangential_restitution`, e_T): once the slip
//! halts, the ball springs back and gives e_T times the halting impulse
//! back, so the contact's slip leaves reversed, −e_T·s(0) (Cross's
//! tangential restitution), unless friction cannot pass that much over the
//! rest of the contact. It never makes energy, never asks more of friction
//! than μ, is the same in the plane and in space, and at one e_T makes the
//! ball's spin forget the pitch's, as Nathan et al. measured for a ball on
//! a fixed cylinder ("Spin of a batted baseball", Procedia Eng. 34, 182
//! (2012): "the scattered spin is nearly independent of the incident
//! spin").

use crate::impact3d;

use homerun::Scene;
use homerun::model::impact::{Impact, Impact3d, Regime};
use proptest::prelude::*;

/// The 3-D impact's random scenes (tests/physics/impact3d.rs), each with a
/// grip drawn from 0 to 1.
fn scenes() -> impl Strategy<Value = Scene> {
    (impact3d::scenes(), 0.0..=1.0f64).prop_map(|(mut scene, grip)| {
        scene.bat.tangential_restitution = grip;
        scene
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn a_gripping_contact_never_makes_energy_nor_outpulls_friction(scene in scenes()) {
        let impact = Impact3d::new(&scene);
        let pf = impact.separation_impulse;
        let before = impact.kinetic_energy(&impact.at(0.0));
        let mut last = impact.at(0.0);
        for k in 1..=40 {
            let now = impact.at(pf * k as f64 / 40.0);
            let energy = impact.kinetic_energy(&now);
            prop_assert!(energy <= before * (1.0 + 1e-12), "{before} → {energy}");
            let pulled = (now.tangential_impulse - last.tangential_impulse).norm();
            let allowed = impact.friction * (now.impulse - last.impulse);
            prop_assert!(pulled <= allowed * (1.0 + 1e-9) + 1e-12, "{pulled} > {allowed}");
            last = now;
        }
    }

    #[test]
    fn the_slip_leaves_reversed_e_t_fold_unless_friction_runs_out(scene in scenes()) {
        let impact = Impact3d::new(&scene);
        prop_assume!(impact.regime == Regime::Stick && impact.initial_slip.norm() > 1e-6);
        let (s0, s) = (impact.initial_slip, impact.after.slip);
        let grip = scene.bat.tangential_restitution;
        // The impulse that halted the slip, and the part given back.
        let halting = impact.after.tangential_impulse - impact.release;
        if impact.release.norm() >= grip * halting.norm() * (1.0 - 1e-12) {
            prop_assert!((s + s0 * grip).norm() <= 1e-9 * s0.norm(), "{s:?} vs −{grip}·{s0:?}");
        } else {
            // Friction passed all it could: the slip springs back less.
            prop_assert!(s.norm() <= grip * s0.norm() * (1.0 + 1e-9));
        }
    }

    #[test]
    fn the_plane_and_space_grip_alike(scene in scenes()) {
        let mut square = scene;
        square.bat.tilt = 0.0;
        square.bat.direction = 0.0;
        let (plane, space) = (Impact::new(&square), Impact3d::new(&square));
        let (v, w) = (plane.after.ball_velocity, plane.after.ball_spin);
        let (v3, w3) = (space.after.ball_velocity, space.after.ball_spin);
        let speed = v.norm().max(1.0);
        prop_assert!((v.x - v3.x).abs() < 1e-9 * speed && (v.y - v3.y).abs() < 1e-9 * speed);
        prop_assert!((w - w3.z).abs() < 1e-7 * w.abs().max(1.0), "{w} vs {}", w3.z);
        // And halfway through the release, as the step-through shows it.
        let p = 0.5 * (plane.slip_halt_impulse.min(plane.separation_impulse) + plane.separation_impulse);
        let (a, b) = (plane.at(p), space.at(p));
        prop_assert!((a.slip_velocity - b.slip.x).abs() < 1e-9 * speed);
    }
}

/// The outgoing spin against the pitch's spin, at a sticking contact:
/// ∂ω_f/∂ω_0 = 1 − (1 + e_T)·m·r_b²/(β1·I_b), which vanishes at
/// e_T = β1·I_b/(m·r_b²) − 1 (0.40 for a free ball on a fixed cylinder,
/// k_b²/r_b²; 0.62 for the paper's ball and bat, whose finite mass and roll
/// take a share).
#[test]
fn at_one_grip_the_batted_spin_forgets_the_pitchs() {
    let spin_for = |grip: f64, pitch_spin: f64| {
        let mut scene = Scene::default();
        scene.bat.tangential_restitution = grip;
        scene.pitch.spin = pitch_spin;
        let impact = Impact::new(&scene);
        assert_eq!(impact.regime, Regime::Stick);
        impact.after.ball_spin
    };
    let b = homerun::model::impact::Bodies::of(&Scene::default());
    let roll = b.pair_mass * b.ball_radius.powi(2) / (b.beta1 * b.ball_inertia);
    for grip in [0.0, 0.3] {
        let slope = (spin_for(grip, -100.0) - spin_for(grip, -200.0)) / 100.0;
        let expected = 1.0 - (1.0 + grip) * roll;
        assert!(
            (slope - expected).abs() < 1e-9,
            "e_T {grip}: {slope} vs {expected}"
        );
    }
    let forgetting = 1.0 / roll - 1.0;
    assert!((forgetting - 0.6155).abs() < 5e-4, "{forgetting}");
    let slope = (spin_for(forgetting, -100.0) - spin_for(forgetting, -200.0)) / 100.0;
    assert!(slope.abs() < 1e-9, "{slope}");
    // A free ball on a fixed cylinder: β1 = 1 + r_b²/k_b², so e_T = k_b²/r_b².
    let sphere = 0.0231f64.powi(2) / 0.0366f64.powi(2);
    assert!((sphere - 0.398).abs() < 1e-3, "{sphere}");
}
