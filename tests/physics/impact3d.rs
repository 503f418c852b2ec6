//! The impact in three dimensions (docs/swing-3d.md): it is the paper's in
//! the paper's geometry, a left-handed batter is the mirror image of a
//! right-handed one, it never makes energy, friction alone turns the ball,
//! and an independent implementation (reference/impact3d.py: rotation
//! matrices, full rigid-body vectors, DOP853 over the normal impulse, the
//! end of contact from the energetic e*) agrees with it.

use crate::common;

use common::Row;
use homerun::Scene;
use homerun::model::impact::{Collision, Impact, Impact3d, Regime};
use homerun::model::launch::{BattedBall, fly_scene};
use homerun::model::scene::Hand;
use homerun::{Purpose, simulate};
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_6;

/// The impact blocks of `homerun hit --json` for Table II's three pitches at
/// their published swings, as printed before the 3-D impact existed
/// (commit 7b09181): normal angle, restitution, p_c, p_f, p_s, then the
/// launch speed, angle and spin.
const TODAY: [(&str, [f64; 8]); 3] = [
    (
        "fastball",
        [
            0.3791292905568626,
            0.4314147916057654,
            8.621326634383582,
            12.34069446772141,
            1.6566632332488014,
            44.29906800990522,
            0.4604009372429193,
            191.8261001474417,
        ],
    ),
    (
        "knuckleball",
        [
            0.35667668228559213,
            0.44545326976155797,
            7.932029929167949,
            11.465378596962351,
            0.9604000887485779,
            44.03616825937068,
            0.45007316881010007,
            227.14925629009664,
        ],
    ),
    (
        "curveball",
        [
            0.316721191307259,
            0.4472532508943707,
            7.843649903175875,
            11.351747821248601,
            0.3250451986711853,
            44.037950633907876,
            0.4245646763605091,
            276.8781427696799,
        ],
    ),
];

fn numbers_of(impact: &Collision) -> [f64; 8] {
    [
        impact.normal_angle(),
        impact.restitution(),
        impact.compression_impulse(),
        impact.separation_impulse(),
        impact.stick_impulse().expect("Table II's swings stick"),
        impact.launch_speed(),
        impact.launch_angle(),
        impact.launch_spin(),
    ]
}

#[test]
fn the_papers_geometry_keeps_todays_numbers_bit_for_bit_and_in_3d_to_1e_12() {
    let mut worst: f64 = 0.0;
    for (name, today) in TODAY {
        let scene = common::scene(name);
        // A level square bat takes the planar path: the numbers of before.
        let planar = Collision::new(&scene);
        assert!(planar.planar().is_some(), "{name}");
        assert_eq!(numbers_of(&planar), today, "{name}");
        assert_eq!(planar.launch_direction(), 0.0);
        assert_eq!(planar.launch_sidespin(), 0.0);
        // The 3-D impact, forced on the same swing, agrees to 1e-12.
        let spatial = Collision::Spatial(Impact3d::new(&scene));
        for (k, (a, b)) in numbers_of(&spatial).iter().zip(today).enumerate() {
            let relative = (a - b).abs() / b.abs();
            worst = worst.max(relative);
            assert!(relative <= 1e-12, "{name} #{k}: {a} vs {b}");
        }
        // In the plane, with no sidespin and no gyrospin, at all.
        assert_eq!(spatial.launch_direction(), 0.0, "{name}");
        assert_eq!(spatial.launch_sidespin(), 0.0, "{name}");
        assert_eq!(spatial.launch_gyrospin(), 0.0, "{name}");
        assert_eq!(spatial.regime(), Regime::Stick);
        // Either hand: the plane is its own mirror image.
        let mut left = scene;
        left.bat.hand = Hand::Left;
        assert_eq!(Collision::new(&left), planar, "{name}");
        let left_3d = Impact3d::new(&left);
        assert_eq!(
            left_3d.after.ball_velocity,
            Impact3d::new(&scene).after.ball_velocity
        );
    }
    eprintln!("forced 3-D against today's planar numbers: {worst:.1e} relative at worst");
}

#[test]
fn the_paper_geometry_in_3d_matches_the_planar_impact_in_the_slip_regime_too() {
    // Low friction and a deep undercut: the contact slides to separation,
    // the 3-D slip's closed form in τ then stands for Eq. (21)'s second line.
    for friction in [0.0, 0.05, 0.1] {
        let mut scene = Scene::default();
        scene.bat.friction = friction;
        scene.bat.undercut = 0.045;
        let planar = Impact::new(&scene);
        let spatial = Impact3d::new(&scene);
        assert_eq!(planar.regime, Regime::Slip);
        assert_eq!(spatial.regime, Regime::Slip);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
        assert!(close(spatial.launch_speed(), planar.launch_speed()));
        assert!(close(spatial.launch_angle(), planar.launch_angle()));
        assert!(
            close(spatial.launch_spin(), planar.launch_spin()),
            "μ = {friction}"
        );
    }
}

/// `scene` with a 3-D swing.
fn swing(scene: &Scene, hand: Hand, tilt: f64, direction: f64) -> Scene {
    let mut s = *scene;
    s.bat.hand = hand;
    s.bat.tilt = tilt;
    s.bat.direction = direction;
    s
}

#[test]
fn a_left_handed_batter_is_the_mirror_image_of_a_right_handed_one() {
    for name in ["fastball", "curveball"] {
        let base = common::scene(name);
        for (tilt, direction, undercut, friction) in [
            (FRAC_PI_6, 0.349, 0.0265, 0.5),
            (FRAC_PI_6, -0.349, 0.0265, 0.5),
            (0.3, 0.0, -0.01, 0.5),
            (-0.4, 0.7, 0.05, 0.1),
            (0.9, -0.9, 0.03, 0.05),
            (0.2, 0.1, 0.02, 0.0),
        ] {
            let mut scene = base;
            scene.bat.undercut = undercut;
            scene.bat.friction = friction;
            let right = Impact3d::new(&swing(&scene, Hand::Right, tilt, direction));
            let left = Impact3d::new(&swing(&scene, Hand::Left, tilt, -direction));
            let case = format!("{name} τ {tilt} φ {direction} E {undercut} μ {friction}");
            assert_eq!(left.launch_speed(), right.launch_speed(), "{case}");
            assert_eq!(left.launch_angle(), right.launch_angle(), "{case}");
            assert_eq!(left.launch_spin(), right.launch_spin(), "{case}");
            assert_eq!(left.launch_direction(), -right.launch_direction(), "{case}");
            assert_eq!(left.launch_sidespin(), -right.launch_sidespin(), "{case}");
            assert_eq!(left.launch_gyrospin(), -right.launch_gyrospin(), "{case}");
            assert_eq!(left.regime, right.regime, "{case}");
            assert_eq!(left.stick_impulse(), right.stick_impulse(), "{case}");
            assert_eq!(left.separation_impulse, right.separation_impulse, "{case}");
            // The slip turns the other way round the bat.
            assert_eq!(left.initial_slip.x, right.initial_slip.x);
            assert_eq!(left.initial_slip.y, -right.initial_slip.y);
        }
    }
    // And so does the flight: the same range, the landing mirrored.
    let scene = common::scene("fastball");
    let right = simulate(&swing(&scene, Hand::Right, 0.5, 0.2), Purpose::Readout);
    let left = simulate(&swing(&scene, Hand::Left, 0.5, -0.2), Purpose::Readout);
    assert_eq!(left.flight.range, right.flight.range);
    assert_eq!(left.flight.direction, -right.flight.direction);
    assert!(right.flight.direction > 0.0);
}

#[test]
fn without_friction_the_spin_is_the_pitchs_to_the_last_bit() {
    for (tilt, direction, undercut) in [(0.5, 0.3, 0.03), (-0.7, -1.0, -0.05), (1.0, 0.5, 0.0)] {
        for hand in Hand::ALL {
            let mut scene = swing(&Scene::default(), hand, tilt, direction);
            scene.bat.friction = 0.0;
            scene.bat.undercut = undercut;
            scene.bat.spin = 40.0;
            let impact = Impact3d::new(&scene);
            assert_eq!(impact.after.ball_spin, impact.ball_spin_before);
            assert_eq!(impact.after.bat_roll, impact.bat_roll_before);
            assert_eq!(impact.after.slip, impact.initial_slip);
            assert_eq!(impact.regime, Regime::Slip);
            assert_eq!(impact.stick_impulse(), None);
        }
    }
}

#[test]
fn a_barrel_below_the_hands_that_undercuts_slices_toward_the_opposite_field() {
    // A knuckleball, so that no pitched spin is left over: a right-handed
    // batter's tilted bat under the ball sends it toward right field with
    // sidespin toward right field; over the ball, the other way.
    let scene = common::scene("knuckleball");
    let under = Impact3d::new(&swing(&scene, Hand::Right, 0.5, 0.0));
    assert!(under.launch_direction() > 0.0 && under.launch_sidespin() > 0.0);
    let mut over = swing(&scene, Hand::Right, 0.5, 0.0);
    over.bat.undercut = -0.01;
    let over = Impact3d::new(&over);
    assert!(over.launch_direction() < 0.0 && over.launch_sidespin() < 0.0);
    // A level bat swung toward right field sends the ball there, further
    // than the bat's direction (the pitch's speed across the bat's normal
    // stays partly in the ball).
    let late = Impact3d::new(&swing(&scene, Hand::Right, 0.0, 0.3));
    assert!(late.launch_direction() > 0.3, "{}", late.launch_direction());
}

#[test]
fn the_slip_turns_toward_the_bat_as_it_slows_and_the_step_through_shows_it() {
    let scene = swing(&common::scene("fastball"), Hand::Right, FRAC_PI_6, 0.349);
    let impact = Impact3d::new(&scene);
    assert_eq!(impact.regime, Regime::Stick);
    let turn = impact.slip_turn(11);
    assert_eq!(turn.len(), 11);
    for pair in turn.windows(2) {
        assert!(pair[1].angle > pair[0].angle, "{pair:?}");
        assert!(pair[1].speed < pair[0].speed, "{pair:?}");
    }
    let ps = impact.stick_impulse().unwrap();
    assert!(turn.last().unwrap().impulse < ps);
    // After the halt the contact sticks: no slip, no angle.
    let after = impact.at(ps * 1.001);
    assert_eq!(after.slip_angle(), None);
    assert!(impact.after.slip.norm() == 0.0);
    // The stops: as the plane's, with the halt of slip among them.
    let stops = impact.stops();
    assert!(stops.iter().any(|s| s.impulse == ps));
    assert!(stops.windows(2).all(|w| w[0].impulse <= w[1].impulse));
}

#[test]
fn a_3d_swing_flies_in_3d_and_its_batted_ball_flies_the_same() {
    let scene = swing(&common::scene("fastball"), Hand::Right, FRAC_PI_6, -0.349);
    let flown = fly_scene(&scene, Purpose::Readout);
    let impact = flown.impact.expect("a swing");
    assert!(impact.spatial().is_some());
    let launch = BattedBall::of(&impact);
    assert_eq!(flown.launch, launch);
    assert!(launch.direction != 0.0 && launch.sidespin != 0.0);
    // The same launch as a batted ball in the same air: the same flight to
    // rounding (the swing flies the impact's own velocity vector, the batted
    // ball one rebuilt from speed, angle and direction).
    let mut same_models = scene;
    same_models.choose_drag(scene.drag);
    same_models.choose_lift(scene.lift);
    let batted = fly_scene(&same_models.with_launch(launch), Purpose::Readout);
    assert!(batted.impact.is_none() && batted.flight.landed);
    let (a, b) = (flown.flight.range, batted.flight.range);
    assert!((a - b).abs() < 1e-6, "{a} vs {b}");
    assert!((flown.flight.direction - batted.flight.direction).abs() < 1e-9);
}

/// Kinetic energy of ball and bat, before and at p.
fn energies(scene: &Scene) -> (f64, Vec<f64>) {
    let impact = Impact3d::new(scene);
    let before = impact.kinetic_energy(&impact.at(0.0));
    let during = (1..=10)
        .map(|k| impact.kinetic_energy(&impact.at(impact.separation_impulse * k as f64 / 10.0)))
        .collect();
    (before, during)
}

/// Each key's accepted range.
fn range_of(name: &str) -> std::ops::RangeInclusive<f64> {
    let key = Scene::key(name).expect(name);
    let min = if key.bounds.min_exclusive {
        key.bounds.min.next_up()
    } else {
        key.bounds.min
    };
    min..=key.bounds.max
}

pub(crate) fn scenes() -> impl Strategy<Value = Scene> {
    (
        (
            range_of("bat.tilt"),
            range_of("bat.direction"),
            any::<bool>(),
        ),
        (
            -0.0715..0.0715f64,
            range_of("bat.swing_angle"),
            range_of("bat.friction"),
        ),
        (
            15.0..60.0f64,
            -600.0..600.0f64,
            10.0..50.0f64,
            range_of("bat.spin"),
        ),
        (0.3..3.0f64, 0.1..0.3f64),
    )
        .prop_map(
            |(
                (tilt, direction, left),
                swing,
                (pitch_speed, pitch_spin, bat_speed, bat_spin),
                masses,
            )| {
                let mut s = common::impact_scene(
                    (pitch_speed, pitch_spin),
                    (bat_speed, bat_spin),
                    swing,
                    masses,
                );
                s.bat.tilt = tilt;
                s.bat.direction = direction;
                s.bat.hand = if left { Hand::Left } else { Hand::Right };
                s
            },
        )
        .prop_filter("valid", |s| s.validate().is_ok())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn kinetic_energy_never_increases(scene in scenes()) {
        let (before, during) = energies(&scene);
        for (k, e) in during.iter().enumerate() {
            prop_assert!(*e <= before * (1.0 + 1e-12), "at {}/10 of p_f: {before} → {e}", k + 1);
        }
    }

    #[test]
    fn separation_reverses_the_approach_times_restitution_and_stick_ends_the_slip(scene in scenes()) {
        let impact = Impact3d::new(&scene);
        prop_assume!(impact.initial_approach < 0.0);
        let v3 = impact.after.normal_velocity;
        let expected = -impact.restitution * impact.initial_approach;
        prop_assert!((v3 - expected).abs() < 1e-9 * impact.initial_approach.abs());
        if impact.regime == Regime::Stick {
            prop_assert_eq!(impact.after.slip.norm(), 0.0);
            let ps = impact.stick_impulse().unwrap();
            prop_assert!(ps < impact.separation_impulse);
        } else if impact.friction > 0.0 {
            // Still sliding, the same way round as it started: friction
            // slows each part of the slip and never reverses it.
            let (s0, s) = (impact.initial_slip, impact.after.slip);
            prop_assert!(s.x * s0.x >= 0.0 && s.y * s0.y >= 0.0);
            prop_assert!(s.norm() < s0.norm());
        }
    }

    #[test]
    fn friction_above_what_halts_the_slip_changes_nothing(scene in scenes(), extra in 0.0..1.0f64) {
        // Once the slip halts the contact sticks (the stick coefficient is
        // 0), so any more friction leaves the launch as it is.
        let impact = Impact3d::new(&scene);
        prop_assume!(impact.regime == Regime::Stick && scene.bat.friction + extra <= 2.0);
        let mut more = scene;
        more.bat.friction += extra;
        let more = Impact3d::new(&more);
        prop_assert_eq!(more.regime, Regime::Stick);
        let d = (more.after.ball_velocity - impact.after.ball_velocity).norm();
        let w = (more.after.ball_spin - impact.after.ball_spin).norm();
        prop_assert!(d < 1e-9 && w < 1e-7, "{d} {w}");
    }
}

/// The reference fixture's rows.
fn reference_rows() -> (Vec<&'static str>, Vec<Vec<&'static str>>) {
    const TEXT: &str = include_str!("../data/impact3d_reference.csv");
    let mut lines = TEXT.lines().filter(|l| !l.starts_with('#'));
    let names: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows = lines.map(|l| l.split(',').collect()).collect();
    (names, rows)
}

#[test]
fn an_independent_implementation_agrees_on_varied_3d_impacts() {
    let (names, rows) = reference_rows();
    assert!(rows.len() >= 30, "{} rows", rows.len());
    let (mut stuck, mut slid, mut gripped, mut leading) = (0, 0, 0, 0);
    let mut worst: f64 = 0.0;
    for fields in rows {
        let row = Row {
            names: &names,
            fields,
        };
        let mut scene = Scene::default();
        for key in [
            "hand",
            "tilt",
            "direction",
            "undercut",
            "swing_angle",
            "friction",
            "lead",
        ] {
            scene
                .set_text(&format!("bat.{key}"), row.text(key))
                .unwrap();
        }
        scene.set_text("bat.speed", row.text("bat_speed")).unwrap();
        scene.set_text("bat.spin", row.text("bat_spin")).unwrap();
        scene
            .set_text("pitch.speed", row.text("pitch_speed"))
            .unwrap();
        scene
            .set_text("pitch.spin", row.text("pitch_spin"))
            .unwrap();
        scene
            .set_text(
                "bat.tangential_restitution",
                row.text("tangential_restitution"),
            )
            .unwrap();
        scene.validate().unwrap();
        let impact = Impact3d::new(&scene);
        gripped += usize::from(scene.bat.tangential_restitution > 0.0);
        leading += usize::from(scene.bat.lead != 0.0);
        let case = row.fields.join(",");
        let regime = match impact.regime {
            Regime::Stick => "stick",
            Regime::Slip => "slip",
        };
        assert_eq!(regime, row.text("regime"), "{case}");
        match impact.regime {
            Regime::Stick => stuck += 1,
            Regime::Slip => slid += 1,
        }
        // Speeds and impulses to 1e-9 of themselves; angles to 1e-9 rad;
        // spins to 1e-7 rad/s.
        let mut check = |name: &str, ours: f64, scale: f64| {
            let theirs = row.number(name);
            let error = (ours - theirs).abs() / scale;
            worst = worst.max(error);
            assert!(
                error < 1e-9,
                "{name}: {ours} vs {theirs} ({error:e})\n{case}"
            );
        };
        check(
            "launch_speed",
            impact.launch_speed(),
            row.number("launch_speed"),
        );
        check("launch_angle", impact.launch_angle(), 1.0);
        check("launch_direction", impact.launch_direction(), 1.0);
        check("backspin", impact.launch_spin(), 100.0);
        check("sidespin", impact.launch_sidespin(), 100.0);
        check("gyrospin", impact.launch_gyrospin(), 100.0);
        let pf = impact.separation_impulse;
        check("compression_impulse", impact.compression_impulse, pf);
        check("separation_impulse", pf, pf);
        if let Some(ps) = impact.stick_impulse() {
            check("stick_impulse", ps, pf);
        }
        let half = 0.5 * impact.slip_halt_impulse().min(pf);
        if let Some(angle) = impact.at(half).slip_angle() {
            check("slip_angle_half", angle, 1.0);
        }
    }
    assert!(stuck >= 10 && slid >= 5, "{stuck} stuck, {slid} slid");
    assert!(gripped >= 10, "{gripped} gripping");
    // Bats leading their path by up to ±45° (bat.lead), both hands, some
    // gripping and some slipping: the reference turns the bat by Rodrigues'
    // rotation in its plane, the core by cos λ·â + sin λ·v̂.
    assert!(leading >= 14, "{leading} leading");
    eprintln!("worst scaled disagreement with reference/impact3d.py: {worst:.1e}");
}

#[test]
fn the_hand_is_a_named_input_as_the_models_are() {
    use homerun::preset::{Preset, Source};
    let text = "[bat]\nhand = \"left\"\ntilt = 0.5\ndirection = -0.3\n";
    let preset = Preset::parse(text, "lefty", "lefty.toml", Source::Bundled).unwrap();
    assert_eq!(preset.scene.bat.hand, Hand::Left);
    assert_eq!(
        (preset.scene.bat.tilt, preset.scene.bat.direction),
        (0.5, -0.3)
    );
    // A saved preset writes the hand and reads back the same scene.
    let saved = preset.to_toml();
    assert!(saved.contains("hand = \"left\""), "{saved}");
    let again = Preset::parse(&saved, "again", "again.toml", Source::Bundled).unwrap();
    assert_eq!(again.scene, preset.scene);
    // Refusals name the key, the value and what is accepted.
    let wrong = Preset::parse("[bat]\nhand = 3\n", "w", "w.toml", Source::Bundled).unwrap_err();
    assert_eq!(
        wrong.to_string(),
        "w.toml: bat.hand = 3: expected \"right\" or \"left\" in quotes"
    );
    let mut scene = Scene::default();
    let unknown = scene.set_text("bat.hand", "up").unwrap_err();
    assert_eq!(
        unknown.to_string(),
        "bat.hand = \"up\": unknown hand; accepted: right, left"
    );
    assert_eq!(
        scene.set_text("bat.tilt", "1.1").unwrap_err().to_string(),
        "bat.tilt = 1.1: must be a finite number in [-π/3, π/3] rad (did you mean 1.1deg?)"
    );
}
