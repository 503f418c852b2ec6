use super::*;
use model::tracked_pitch::PitchFit;

/// A 94-mph-ish four-seamer tracked as Statcast gives it.
fn fastball() -> PitchAtPlate {
    PitchFit {
        velocity: [6.0, -137.0, -5.0],
        acceleration: [-12.0, 29.0, -15.0],
    }
    .at_front_of_plate()
    .unwrap()
}

/// The launch a known swing gives, as a tracked row would measure it.
fn measured(
    undercut: f64,
    swing_angle: f64,
    direction: f64,
    hand: Hand,
) -> (TrackedSwing, Impact3d) {
    let mut scene = Scene::default();
    let pitch = fastball();
    let pitch = if hand == Hand::Left {
        PitchAtPlate {
            velocity: Vector3::new(pitch.velocity.x, pitch.velocity.y, -pitch.velocity.z),
            ..pitch
        }
    } else {
        pitch
    };
    scene.bat.speed = 31.0;
    scene.bat.undercut = undercut;
    scene.bat.swing_angle = swing_angle;
    scene.bat.direction = direction;
    scene.bat.hand = hand;
    scene.pitch.spin = -230.0;
    let impact = Impact3d::with_pitch(&scene, pitch.velocity);
    let swing = TrackedSwing {
        pitch,
        pitch_spin: Some(-230.0),
        bat_speed: 31.0,
        attack_angle: None,
        attack_direction: None,
        tilt: None,
        hand,
        launch_speed: impact.launch_speed(),
        launch_angle: impact.launch_angle(),
        spray: Some(impact.launch_direction()),
    };
    (swing, impact)
}

/// A ball faster than the prior swing angle gives at the sweet spot has
/// its swing angle solved there.
#[test]
fn a_known_swing_is_found_again() {
    let (swing, impact) = measured(0.021, 0.22, -0.3, Hand::Right);
    let answer = solve(&Scene::default(), &swing);
    let solved = answer.solved.expect("solved");
    assert!(!solved.off_sweet_spot);
    let bat = solved.scene.bat;
    assert!((bat.undercut - 0.021).abs() < 1e-8, "{}", bat.undercut);
    assert!((bat.swing_angle - 0.22).abs() < 1e-7, "{}", bat.swing_angle);
    assert!((bat.direction + 0.3).abs() < 1e-7, "{}", bat.direction);
    assert!((solved.launch.spin - impact.launch_spin()).abs() < 1e-5);
    assert!((solved.launch.speed - swing.launch_speed).abs() < 1e-9);
    assert!((solved.launch.angle - swing.launch_angle).abs() < 1e-10);
    // E = 0 is not quite the most: this swing meets the pitch head-on at
    // E ≈ (r_b + r_B)·sin 0.15 ≈ 11 mm, so this ball beats it by 1.4 %.
    let squared_up = solved.squared_up();
    assert!((squared_up - 1.014).abs() < 0.001, "{squared_up}");
    let q = (swing.launch_speed - 31.0) / (swing.pitch.speed() + 31.0);
    assert_eq!(answer.collision_efficiency, q);
}

#[test]
fn a_left_handed_batter_is_the_mirror_image() {
    // Both kinds of solve: at the sweet spot (a fast ball) and off it.
    for swing_angle in [0.22, 0.12] {
        let (right, _) = measured(0.015, swing_angle, 0.25, Hand::Right);
        let (left, _) = measured(0.015, swing_angle, -0.25, Hand::Left);
        let r = solve(&Scene::default(), &right).solved.unwrap();
        let l = solve(&Scene::default(), &left).solved.unwrap();
        assert_eq!(r.off_sweet_spot, swing_angle == 0.12);
        assert_eq!(r.off_sweet_spot, l.off_sweet_spot);
        assert!((r.scene.bat.undercut - l.scene.bat.undercut).abs() < 1e-9);
        assert!((r.scene.bat.swing_angle - l.scene.bat.swing_angle).abs() < 1e-8);
        assert!((r.scene.bat.speed - l.scene.bat.speed).abs() < 1e-8);
        assert!((r.scene.bat.direction + l.scene.bat.direction).abs() < 1e-8);
        assert!((r.launch.spin - l.launch.spin).abs() < 1e-5);
        assert!((r.launch.sidespin + l.launch.sidespin).abs() < 1e-5);
        assert!((r.launch.speed - right.launch_speed).abs() < 1e-9);
        assert!((r.launch.direction - right.spray.unwrap()).abs() < 1e-9);
    }
}

#[test]
fn a_ball_faster_than_the_bat_can_hit_is_unreached_by_its_shortfall() {
    let (mut swing, _) = measured(0.0, 0.1, 0.0, Hand::Right);
    let most = swing.launch_speed;
    swing.launch_speed = most + 3.0;
    let answer = solve(&Scene::default(), &swing);
    match answer.solved {
        Err(Unreached::TooFast { shortfall }) => {
            // At E = 0, ψ = 0.1 the swing is near head-on: the most at this
            // angle is a little above it, so the shortfall a little below 3.
            assert!(shortfall > 2.0 && shortfall < 3.0, "{shortfall}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn with_a_measured_attack_angle_the_contact_speed_is_solved() {
    let (mut swing, _) = measured(0.018, 0.15, 0.0, Hand::Right);
    swing.attack_angle = Some(0.15);
    swing.attack_direction = Some(0.0);
    swing.spray = None;
    let solved = solve(&Scene::default(), &swing).solved.unwrap();
    assert!(
        (solved.scene.bat.speed - 31.0).abs() < 1e-7,
        "{}",
        solved.scene.bat.speed
    );
    assert!((solved.scene.bat.undercut - 0.018).abs() < 1e-8);
    assert_eq!(solved.scene.bat.swing_angle, 0.15);
}

#[test]
fn the_ceiling_is_the_head_on_centred_swing_and_rises_with_the_bat_s_mass() {
    let (swing, _) = measured(0.0, 0.1, 0.0, Hand::Right);
    let scene = Scene::default();
    let q = ceiling_efficiency(&scene, &swing);
    // (e* − r)/(1 + r) for a head-on collision of point masses, r = M_b/M_B,
    // e* from Eq. (19) at the approach speed; the ball's roll and the
    // pitch's spin move it little.
    let approach = swing.pitch.speed() + 31.0;
    let e = 0.540 - (approach - 26.8) / 400.0;
    let r = 0.145 / 0.8;
    assert!((q - (e - r) / (1.0 + r)).abs() < 0.005, "{q}");
    let mut heavier = scene;
    heavier.bat.effective_mass = 1.0;
    assert!(ceiling_efficiency(&heavier, &swing) > q + 0.02);
}

#[test]
fn the_fitted_mass_leaves_one_row_in_a_hundred_above_its_ceiling() {
    // 200 rows hit at q = 0.15 … 0.25 (by exit speed), from the same pitch
    // and bat: their ceiling is one number, which the fit puts at the 99th
    // percentile of the data.
    let swings: Vec<TrackedSwing> = (0..200)
        .map(|k| {
            let (mut swing, _) = measured(0.0, 0.1, 0.0, Hand::Right);
            let q = 0.15 + 0.1 * k as f64 / 199.0;
            swing.launch_speed = q * (swing.pitch.speed() + 31.0) + 31.0;
            swing
        })
        .collect();
    let fit = fit_effective_mass(&Scene::default(), &swings, 0.99).unwrap();
    assert!((fit.ceiling_after - fit.data).abs() < 1e-6, "{fit:?}");
    assert!((fit.above_after - 0.01).abs() < 0.006, "{fit:?}");
    assert!(
        fit.above_before > 0.05 && fit.effective_mass > 0.8,
        "{fit:?}"
    );
}

/// Rows at five bat speeds, each group's fastest ball exactly at its
/// ceiling with a 0.9 kg bat: the fit finds that bat, and then in each group
/// by approach speed the median ceiling is the group's 99th percentile of
/// q, though the ceilings fall by Eq. (19)'s e* from group to group.
#[test]
fn by_approach_speed_the_fitted_ceiling_is_each_group_s_top() {
    let mut heavy = Scene::default();
    heavy.bat.effective_mass = 0.9;
    let swings: Vec<TrackedSwing> = [24.0, 27.0, 30.0, 33.0, 36.0]
        .into_iter()
        .flat_map(|bat_speed| {
            let (mut swing, _) = measured(0.0, 0.1, 0.0, Hand::Right);
            swing.bat_speed = bat_speed;
            let top = ceiling_efficiency(&heavy, &swing);
            (0..100).map(move |k| {
                let q = top - 0.1 * k as f64 / 99.0;
                TrackedSwing {
                    launch_speed: q * (swing.pitch.speed() + bat_speed) + bat_speed,
                    ..swing
                }
            })
        })
        .collect();
    let fit = fit_effective_mass(&Scene::default(), &swings, 0.99).unwrap();
    assert!((fit.effective_mass - 0.9).abs() < 0.01, "{fit:?}");
    let bands = fit.by_approach;
    assert_eq!(bands.iter().map(|b| b.rows).sum::<usize>(), 500);
    for band in bands {
        assert_eq!(band.rows, 100, "{band:?}");
        assert!((band.ceiling_after - band.data).abs() < 0.002, "{band:?}");
        assert!(band.ceiling_before < band.data - 0.01, "{band:?}");
    }
    for pair in bands.windows(2) {
        assert!(pair[0].fastest < pair[1].slowest, "{pair:?}");
        assert!(
            pair[1].ceiling_after < pair[0].ceiling_after - 0.004,
            "{pair:?}"
        );
    }
}

/// A ball slower than the prior swing angle gives at the sweet spot is
/// solved off the sweet spot: a swing at 60 % of the tracked bat speed
/// (a contact toward the hands) is found again at the prior swing angle,
/// its launch given back, and marked so.
#[test]
fn a_ball_slower_than_the_sweet_spot_gives_is_solved_off_it() {
    let base = Scene::default();
    let (mut swing, _) = measured(0.015, base.bat.swing_angle, -0.2, Hand::Right);
    // The same contact with the bat 40 % slower there.
    let mut scene = base;
    scene.bat.speed = 0.6 * 31.0;
    scene.bat.undercut = 0.015;
    scene.bat.direction = -0.2;
    scene.pitch.spin = -230.0;
    let slow = Impact3d::with_pitch(&scene, swing.pitch.velocity);
    swing.launch_speed = slow.launch_speed();
    swing.launch_angle = slow.launch_angle();
    swing.spray = Some(slow.launch_direction());
    let solved = solve(&base, &swing)
        .solved
        .expect("solved off the sweet spot");
    assert!(solved.off_sweet_spot);
    assert!(
        (solved.scene.bat.speed - 0.6 * 31.0).abs() < 1e-6,
        "{}",
        solved.scene.bat.speed
    );
    assert_eq!(solved.scene.bat.swing_angle, base.bat.swing_angle);
    assert!((solved.launch.speed - swing.launch_speed).abs() < 1e-6);
    assert!((solved.launch.angle - swing.launch_angle).abs() < 1e-9);
    // The most is still the sweet spot's: q as the data's would be.
    let mut centred = solved.scene;
    (centred.bat.undercut, centred.bat.speed) = (0.0, 31.0);
    let most = Impact3d::with_pitch(&centred, swing.pitch.velocity).launch_speed();
    assert_eq!(solved.max_exit_speed, most);
}
