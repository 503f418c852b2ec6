//! The swing whose ball lands where it was seen to. The hit coordinates
//! are where the ball came down, not the direction it left in, and the
//! impact's sidespin curves it (3.3° apart at the median on April 2024,
//! 13° at the 90th percentile). So the impact is solved toward the launch
//! direction whose flight lands on the spray: its launch flown, the
//! direction that lands there found as `fly --batch` finds it
//! ([`savant::launch`], the impact's spin held), and the impact solved
//! again toward that direction, until the two agree. Turning the bat by
//! those few degrees moves the sidespin by ~220 rpm at the median (900 at
//! the 90th percentile), the carry by up to a few metres.

use super::{Problem, Second, SolvedSwing, SwingAnswer, TrackedSwing, Unreached, solve};
use crate::savant::{self, DirectionFrom, RowLaunch, Spray};
use model::flight::FlightOptions;
use model::scene::Scene;

/// The launch directions agree to this (rad), a fifth of what `fly
/// --batch` wants of a landing, so that the impact's own lands within it.
const AGREE: f64 = 2e-5;
/// Passes at the most (each an impact solved and a direction found); two
/// to four reach `AGREE`.
const PASSES: usize = 8;

/// [`solve`], then the launch turned until its flight, flown with `options`
/// from `base` (the row's batted-ball scene: its park and air), lands on
/// the spray; and where the launch direction came from: `Landing` once the
/// impact's direction lands on the spray, `SprayUnsolved` where no
/// direction does or the turning stopped (the last solved kept), `Scene`
/// for a row without a spray. With a measured attack direction the bat's
/// lead over it turns the launch, as the bat's direction does without.
pub fn solve_landing(
    base: &Scene,
    swing: &TrackedSwing,
    options: &FlightOptions,
) -> (SwingAnswer, DirectionFrom) {
    let mut answer = solve(base, swing);
    let Some(bearing) = swing.spray_to_solve() else {
        return (answer, DirectionFrom::Scene);
    };
    // The launch direction d is a root of aimed(d) − d: the aim turns the
    // launch, the turn moves the sidespin, and the sidespin the aim, about
    // −0.45 times back (an alternating miss), so a secant, not repeated
    // aiming, finds it in three or four passes.
    let mut previous: Option<(f64, f64)> = None;
    for _ in 0..PASSES {
        let Ok(solved) = answer.solved else { break };
        let Some(aimed) = landing_launch(base, &solved, bearing, options) else {
            break;
        };
        let (direction, miss) = (solved.launch.direction, aimed - solved.launch.direction);
        if miss.abs() < AGREE {
            return (answer, DirectionFrom::Landing);
        }
        let toward = match previous {
            Some((before, missed)) if miss != missed => {
                direction - miss * (direction - before) / (miss - missed)
            }
            _ => aimed,
        };
        previous = Some((direction, miss));
        let toward = TrackedSwing {
            spray: Some(toward),
            ..*swing
        };
        match again(base, &toward, &solved).or_else(|_| solve(base, &toward).solved) {
            Ok(turned) => answer.solved = Ok(turned),
            Err(_) => break,
        }
    }
    (answer, DirectionFrom::SprayUnsolved)
}

/// The launch direction whose flight, with the solved impact's speed,
/// angle and spin, lands on `bearing`, if one does.
fn landing_launch(
    base: &Scene,
    solved: &SolvedSwing,
    bearing: f64,
    options: &FlightOptions,
) -> Option<f64> {
    let mut scene = *base;
    scene.launch = solved.launch.given();
    let row = RowLaunch {
        spray: Some(bearing),
        side: None,
        estimate_backspin: false,
        estimate_sidespin: false,
        measured_spin: None,
    };
    let launched = savant::launch(&scene, &row, Spray::Landing, options);
    match launched.direction_from {
        DirectionFrom::Landing => launched.scene.launch.direction,
        _ => None,
    }
}

/// The impact solved again toward `toward`'s direction, by Newton's method
/// from `from` (the same kind of solve: off the sweet spot or not). A
/// swing angle solved at the sweet spot is first tried off it at the
/// prior, as [`solve`] tries it: near the edge between the two, turning the
/// bat can bring the prior's reach back over the ball's speed.
fn again(
    base: &Scene,
    toward: &TrackedSwing,
    from: &SolvedSwing,
) -> Result<SolvedSwing, Unreached> {
    let problem = Problem::new(base, toward);
    let bat = from.scene.bat;
    let newton = |problem: &Problem, second: f64| {
        problem
            .newton([bat.undercut, second, problem.third_of(&bat)])
            .map(|x| problem.solved_at(x))
    };
    let solved = match problem.second {
        // Without a measured attack angle, off the sweet spot at the prior
        // first; a swing angle solved at the sweet spot only after it.
        Second::SwingAngle => {
            newton(&problem.off_the_sweet_spot(), bat.speed).or_else(|| match from.off_sweet_spot {
                true => None,
                false => newton(&problem, bat.swing_angle),
            })
        }
        Second::ContactSpeed => newton(&problem, bat.speed),
    };
    solved.ok_or(Unreached::NoConvergence)
}
