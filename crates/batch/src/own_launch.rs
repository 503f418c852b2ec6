//! The launch values a batch row leaves to its swing (a planar row of
//! speed, angle and spin leaves the direction and sidespin to it), solved
//! once for every row with the same swing instead of once a call: the
//! scene asks its swing's impact each time it is asked for its launch
//! (validating it, solving the direction, estimating the spin, starting
//! the flight).
//!
//! The impact depends on the pitch, bat, ball and air, never on the launch
//! given, so a row whose scene equals (but for its launch) one already
//! validated has that scene's swing launch. Such a row is given those
//! values: its flight, every printed number and every check are what they
//! were, as they are the same numbers (tested against the rows' own). And
//! such a row's scene needs no validation past its launch, as
//! [`Scene::validate_changed_launch`] validates it.

use model::keys::{InputError, LAUNCH_KEYS};
use model::scene::Scene;
use model::scene::{GivenLaunch, SceneKind};

/// Scenes (their launch cleared) known valid, with their swing's launch
/// (`None` where some of it is out of its bounds).
/// A piece's rows share one or a few (one a park, with `home_team`).
#[derive(Default)]
pub(crate) struct SwingLaunches {
    known: Vec<(Scene, Option<[f64; 5]>)>,
    /// The same, for rows whose scene but its launch is their park's (or
    /// the preset's, at no park): known by the park, not compared whole.
    by_park: Vec<(Option<usize>, Option<[f64; 5]>)>,
}

/// More swings than this in a piece: the rows vary their swing (columns of
/// the bat, pitch or air), and each row solves its own.
const MAX_SWINGS: usize = 32;

impl SwingLaunches {
    /// `scene` (a batch row's, its launch columns set) validated as
    /// [`Scene::validate`] validates it, and, where its swing is known,
    /// given the launch values it leaves to the swing. With `by_park`, the
    /// scene but its launch is known to be the one every row at that park
    /// has (the header's columns give nothing else: [`super::rows::Header`]).
    pub(crate) fn validate(
        &mut self,
        scene: &mut Scene,
        by_park: Option<Option<usize>>,
    ) -> Result<(), InputError> {
        if scene.kind != SceneKind::BattedBall {
            return scene.validate();
        }
        let swing = || Scene {
            launch: GivenLaunch::default(),
            ..*scene
        };
        let known = match by_park {
            Some(park) => self.by_park.iter().find(|(p, _)| *p == park).map(|k| k.1),
            None => {
                let swing = swing();
                self.known.iter().find(|(s, _)| *s == swing).map(|k| k.1)
            }
        };
        let complete = scene.launch.is_complete();
        if let Some(own) = known {
            match own {
                Some(own) => fill(&mut scene.launch, &own),
                // A launch the swing cannot give, and the row needs some
                // of it: `validate` names what is out of bounds.
                None if !complete => return scene.validate(),
                None => {}
            }
            // The rest of the scene is that of one validated whole, and the
            // launch filled in lies in its bounds (checked once below):
            // what `validate` checks of a complete launch.
            return scene.validate_changed_launch();
        }
        scene.validate()?;
        // The swing's own launch, every value of it (the row's scene would
        // mix in the values it gives).
        let swing = swing();
        let own = swing.batted_ball();
        let own = [own.speed, own.angle, own.spin, own.direction, own.sidespin];
        // Out of bounds, the swing's launch is an error where it is used (a
        // row giving none of it), not one of the launch given.
        let in_bounds = LAUNCH_KEYS
            .iter()
            .zip(own)
            .all(|(k, v)| k.bounds.contains(v));
        let own = in_bounds.then_some(own);
        match by_park {
            Some(park) if self.by_park.len() < MAX_SWINGS => self.by_park.push((park, own)),
            None if self.known.len() < MAX_SWINGS => self.known.push((swing, own)),
            _ => {}
        }
        if let Some(own) = own {
            fill(&mut scene.launch, &own);
        }
        Ok(())
    }
}

/// Gives `launch` the values it lacks, from `own` (in `LAUNCH_KEYS`' order).
fn fill(launch: &mut GivenLaunch, own: &[f64; 5]) {
    let values = [
        &mut launch.speed,
        &mut launch.angle,
        &mut launch.spin,
        &mut launch.direction,
        &mut launch.sidespin,
    ];
    for (value, own) in values.into_iter().zip(own) {
        value.get_or_insert(*own);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper's swing as a batted-ball scene that gives its launch
    /// `given` (by key), the bat tilted out of the plane when `tilted`, so
    /// that the swing gives every launch value a non-zero figure.
    fn row(given: &[(&str, f64)], tilted: bool) -> Scene {
        let mut scene = Scene::default();
        if tilted {
            scene.set("bat.tilt", 0.1).unwrap();
            scene.set("bat.direction", 0.05).unwrap();
        }
        scene.set_kind(SceneKind::BattedBall);
        for (key, value) in given {
            scene.set(key, *value).unwrap();
        }
        scene
    }

    #[test]
    fn a_known_swing_gives_its_launch_as_the_rows_own_swing_would() {
        for tilted in [false, true] {
            let mut swings = SwingLaunches::default();
            let rows = [
                vec![("launch.speed", 40.0), ("launch.angle", 0.4)],
                vec![("launch.speed", 44.0), ("launch.angle", 0.2)],
                vec![("launch.speed", 30.0)],
                vec![("launch.angle", 0.6), ("launch.spin", 150.0)],
            ];
            for (k, given) in rows.iter().enumerate() {
                let alone = row(given, tilted);
                let mut filled = alone;
                assert_eq!(swings.validate(&mut filled, None), alone.validate());
                // Filled (the first row's from its own swing, solved once;
                // the others' from it), to the bit what its own swing gives.
                assert!(filled.launch.is_complete(), "{k}");
                let (a, b) = (alone.batted_ball(), filled.batted_ball());
                let bits = |l: model::launch::BattedBall| {
                    [l.speed, l.angle, l.spin, l.direction, l.sidespin].map(f64::to_bits)
                };
                assert_eq!(bits(a), bits(b), "{given:?}");
                if tilted {
                    assert!(a.direction != 0.0 && a.sidespin != 0.0, "{a:?}");
                }
            }
            assert_eq!(swings.known.len(), 1);
        }
    }

    #[test]
    fn swings_known_by_park_are_the_swings_compared_whole() {
        // Rows whose scene but the launch is their park's (in its air):
        // known by the park, each row is validated and filled as when its
        // swing is compared whole, and as alone, error for error.
        let parks = preset::parks::all(None).unwrap();
        let given = model::park::GivenWeather::default();
        let (mut by_park, mut whole) = (SwingLaunches::default(), SwingLaunches::default());
        let launches = [
            vec![("launch.speed", 40.0), ("launch.angle", 0.4)],
            vec![("launch.speed", 44.0)],
            vec![("launch.speed", 0.0), ("launch.angle", 0.2)],
            vec![("launch.angle", 0.6), ("launch.spin", 150.0)],
        ];
        for (k, park) in [None, Some(3), Some(17), Some(3), None, Some(17)]
            .into_iter()
            .cycle()
            .take(24)
            .enumerate()
        {
            let mut alone = row(&launches[k % launches.len()], false);
            if let Some(index) = park {
                given.park_air(&mut alone.environment, parks.parks[index].elevation);
            }
            let (mut a, mut b) = (alone, alone);
            let expected = alone.validate();
            assert_eq!(by_park.validate(&mut a, Some(park)), expected, "{k}");
            assert_eq!(whole.validate(&mut b, None), expected, "{k}");
            // A row refused is dropped, whatever was filled in.
            if expected.is_ok() {
                assert_eq!(a, b, "{k}");
            }
        }
        assert_eq!(by_park.known.len(), 0);
        assert!(by_park.by_park.len() >= 3);
        assert_eq!(whole.by_park.len(), 0);
    }

    #[test]
    fn another_swing_or_a_bad_launch_is_judged_as_alone() {
        let mut swings = SwingLaunches::default();
        let mut first = row(&[("launch.speed", 40.0)], false);
        swings.validate(&mut first, None).unwrap();
        // Another swing: solved for itself, and known from then on.
        let mut other = row(&[("launch.speed", 40.0), ("bat.speed", 33.0)], false);
        let alone = other;
        assert_eq!(swings.validate(&mut other, None), Ok(()));
        assert_eq!(other.batted_ball(), alone.batted_ball());
        assert_eq!(swings.known.len(), 2, "{:?}", other.batted_ball());
        // A launch value out of its bounds is named as `validate` names it.
        let mut bad = row(&[("launch.speed", 40.0)], false);
        bad.launch.angle = Some(3.0);
        let expected = bad.validate();
        assert!(expected.is_err());
        assert_eq!(swings.validate(&mut bad, None), expected);
        // A complete launch (a 3-D row): checked as `validate` checks it,
        // with or without a value out of bounds.
        let complete = [
            ("launch.speed", 40.0),
            ("launch.angle", 0.4),
            ("launch.spin", 200.0),
            ("launch.direction", 0.2),
        ];
        for sidespin in [50.0, 1e6] {
            let mut row = row(&complete, false);
            row.launch.sidespin = Some(sidespin);
            let expected = row.validate();
            assert_eq!(expected.is_ok(), sidespin < 1e3);
            let alone = row;
            assert_eq!(swings.validate(&mut row, None), expected);
            assert_eq!(row, alone);
        }
        assert_eq!(swings.known.len(), 2);
    }
}
