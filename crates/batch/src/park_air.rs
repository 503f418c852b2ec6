//! Each park's verdict on a row in that park's own air (the standard air
//! at its elevation, the weather given kept): what `fly --park` gives the
//! row there alone. A flight a park would cost 30 flights a row. Instead
//! the row's one flight, in its own air, which crosses every park's fence
//! on the way ([`super::flights`]), settles each park where no change of
//! air as small as the one between the two can move the verdict; only the
//! rest are flown, each in its park's air, as `fly` flies it.
//!
//! A park its own flight cannot settle is flown in that park's air, to
//! every park's fence: that flight then settles the parks whose air is
//! near its own (the 29 parks but Coors Field lie within 4 % of each
//! other's density; Coors is 15–20 % thinner than any). Each round flies,
//! for every row with a park unsettled, the park farthest in density from
//! the flights it has; a round settles at least the park it flies.
//!
//! How far a flight moves with the air is bounded by measurement: every
//! row of April 2024 (22,910 balls in play, five times over) flown in each
//! of the 30 parks' air against its own (docs/parks.md, "Each park in its
//! own air, in a batch"). The bounds below are 2.4 times the largest
//! change seen, and
//! hold only where the air acts through its density alone: a drag without
//! a Reynolds number (Nathan's or a constant C_D), a launch that does not
//! come out of an impact in that air, and still air (they were measured
//! without wind). Any other row is flown in every park's air.

use analysis::precision::Purpose;
use model::aero::DragModel;
use model::atmosphere::Air;
use model::clearing::{Clearing, Landing};
use model::flight::{FlightOptions, FlightSummary};
use model::launch::{self, SceneFlight};
use model::many;
use model::park::{Fence, GivenWeather, Park};
use model::scene::{Environment, Scene, SceneKind};

/// A flight's height where it crosses a wall moves by at most this times
/// r·d·max(1, tan θ), for a relative change r in the air's density, a wall
/// d away and a ball that lands at θ below the horizontal: a steeper ball
/// meets a wall moved along its track higher or lower (seen: 0.62 at most,
/// 0.27 in the median).
const HEIGHT_PER_DENSITY: f64 = 1.5;

/// Its range moves by at most this times r·range (seen: 0.86 at most where
/// it lands past 70 m, 0.33 in the median; 1.6 for a popup).
const RANGE_PER_DENSITY: f64 = 2.0;

/// Its direction, where it crosses a wall or lands, by at most this times
/// r·hook, the hook being how far the sidespin turned it from its launch
/// direction: the Magnus force that turns it scales with the density.
const TURN_PER_DENSITY: f64 = 2.0;

/// And by no less than this (rad, 0.5°).
const LEAST_TURN: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// Each park's air for a row in its own air with its weather given:
/// worked out once for all the rows that share them (a piece's rows share
/// one a park, or a few).
#[derive(Default)]
pub(crate) struct ParkAirs {
    known: Vec<(Air, GivenWeather, Vec<Air>)>,
}

/// More airs than this known: the rows give their own weather, and the
/// list starts again.
const MOST_AIRS: usize = 64;

impl ParkAirs {
    /// Each of `parks`' air, in order, for a row in `own` air that gave
    /// the weather `given` ([`GivenWeather::park_air`]).
    pub(crate) fn of(&mut self, own: &Environment, given: GivenWeather, parks: &[Park]) -> &[Air] {
        let air = own.air();
        let found = (self.known.iter()).position(|(known, was, _)| *known == air && *was == given);
        let index = found.unwrap_or_else(|| {
            if self.known.len() == MOST_AIRS {
                self.known.clear();
            }
            let airs = parks.iter().map(|park| {
                let mut there = *own;
                given.park_air(&mut there, park.elevation);
                there.air()
            });
            self.known.push((air, given, airs.collect()));
            self.known.len() - 1
        });
        &self.known[index].2
    }
}

/// A row whose verdicts at the parks are being settled.
pub(crate) struct Pending {
    /// The row's scene, its launch complete ([`settles`]).
    pub scene: Scene,
    pub launch_direction: f64,
    /// Each park's air.
    pub airs: Vec<Air>,
    /// Where its parks' verdicts are, one a park, in the clearings.
    pub from: usize,
    /// Its flights so far: its own first.
    pub flights: Vec<Reference>,
    /// The parks its own flight settles ([`own_flight_settles`]): their
    /// verdicts are in place.
    pub settled_at: Vec<bool>,
}

/// A row's flight in one air, judged at every park.
pub(crate) struct Reference {
    pub density: f64,
    pub flight: FlightSummary,
    /// How far (m) its heights and ranges may lie from the readout's: 0
    /// for the row's own flight, [`VERDICT_SLACK`] for one flown at the
    /// solve's precision.
    pub slack: f64,
    /// At each park it was judged at (the row's own: every park).
    pub clearings: Vec<Option<Clearing>>,
}

/// The flights that settle parks are flown at [`Purpose::Verdict`]'s
/// precision (within 3.5e-4 m of the readout's in range, docs/speed.md), a
/// quarter of the readout's cost, and read as if their heights and ranges
/// could be this far (m) from the readout's: 28 times that. A verdict they
/// cannot give so is flown again at the readout's precision, so that each
/// park's is the one `fly --park` gives.
pub(crate) const VERDICT_SLACK: f64 = 0.01;

/// Settles every park of every row of `rows` in rounds (see above): each
/// park's verdict, cleared or not, into `cleared[row.from + park]`, from a
/// flight whose air settles it. `options` is the readout's precision.
pub(crate) fn settle(
    mut rows: Vec<Pending>,
    parks: &[&Fence],
    options: &FlightOptions,
    cleared: &mut [bool],
) {
    let cheap = Purpose::Verdict.flight_options();
    // The parks each row's own flight settled, read against it already.
    let mut done: Vec<bool> = (rows.iter())
        .flat_map(|row| row.settled_at.iter().copied())
        .collect();
    // How many of each row's flights each park has been read against: a
    // flight that could not settle a park cannot the next round either.
    let mut tried: Vec<u8> = vec![1; rows.len() * parks.len()];
    for round_number in 0.. {
        let last = round_number == REFERENCE_ROUNDS;
        let mut round: Vec<(usize, usize)> = Vec::new();
        // Each row's parks unsettled, for the round's flights to judge.
        let mut open: Vec<Vec<usize>> = Vec::new();
        for (index, row) in rows.iter().enumerate() {
            let done = &mut done[index * parks.len()..][..parks.len()];
            let tried = &mut tried[index * parks.len()..][..parks.len()];
            let mut farthest: Option<(usize, f64)> = None;
            for (park, fence) in parks.iter().enumerate() {
                if done[park] {
                    continue;
                }
                let density = row.airs[park].density;
                let change = |flight: &Reference| density_change(flight.density, density);
                let untried = &row.flights[usize::from(tried[park])..];
                tried[park] = row.flights.len() as u8;
                let by = untried.iter().find_map(|flight| {
                    let judged = flight.clearings[park]?;
                    let launched = (row.launch_direction, &flight.flight);
                    settled(&judged, launched, fence, (change(flight), flight.slack))
                        .then_some(judged)
                });
                let by = by.or_else(|| between(row, park, fence));
                match by {
                    Some(judged) => {
                        cleared[row.from + park] = judged.clears();
                        done[park] = true;
                    }
                    None if last => round.push((index, park)),
                    None => {
                        let nearest = row.flights.iter().map(change).fold(f64::INFINITY, f64::min);
                        if farthest.is_none_or(|(_, far)| nearest > far) {
                            farthest = Some((park, nearest));
                        }
                    }
                }
            }
            if let Some((park, _)) = farthest {
                round.push((index, park));
                open.push((0..parks.len()).filter(|&k| !done[k]).collect());
            }
        }
        if round.is_empty() {
            return;
        }
        let air_of = |&(index, park): &(usize, usize)| {
            let mut there: Scene = rows[index].scene;
            there.environment.set_air(rows[index].airs[park]);
            launch::scene_start(&there).0
        };
        if last {
            // Each park left flown in its air to its own fence alone, and
            // again at the readout's precision where that is not sure.
            let flights: Vec<_> = (round.iter())
                .map(|pair| (rows[pair.0].from + pair.1, air_of(pair)))
                .collect();
            let mut unsure = Vec::new();
            fly_each(&flights, parks, &cheap, |index, judged, summary| {
                let (slot, flight) = flights[index];
                let fence = parks[slot % parks.len()];
                let launched = (rows[round[index].0].launch_direction, summary);
                if settled(&judged, launched, fence, (0.0, VERDICT_SLACK)) {
                    cleared[slot] = judged.clears();
                } else {
                    unsure.push((slot, flight));
                }
            });
            fly_alone(&unsure, parks, options, |slot, judged| {
                cleared[slot] = judged.clears();
            });
            return;
        }
        let fences: Vec<Vec<&Fence>> = (open.iter())
            .map(|open| open.iter().map(|&k| parks[k]).collect())
            .collect();
        let flights: Vec<_> = (round.iter().zip(&fences))
            .map(|(pair, fences)| (air_of(pair), fences.as_slice()))
            .collect();
        many::judge_many(flights, &cheap, |flown, flight, crossings| {
            let (index, park) = round[flown];
            let landing = Landing::of(&flight);
            let mut judged = vec![None; parks.len()];
            for (&k, crossing) in open[flown].iter().zip(crossings) {
                judged[k] = Some(Clearing::outcome_landed(
                    parks[k], *crossing, &flight, landing,
                ));
            }
            let row = &mut rows[index];
            row.flights.push(Reference {
                density: row.airs[park].density,
                flight,
                slack: VERDICT_SLACK,
                clearings: judged,
            });
        });
    }
}

/// Flies each `(slot, flight)` to its park's fence alone (the slot's place
/// among a row's parks, which start at a multiple of their number) and
/// judges it there: `set(slot, judged)`.
pub(crate) fn fly_alone(
    flights: &[(usize, SceneFlight)],
    parks: &[&Fence],
    options: &FlightOptions,
    mut set: impl FnMut(usize, Clearing),
) {
    fly_each(flights, parks, options, |index, judged, _| {
        set(flights[index].0, judged);
    });
}

/// As [`fly_alone`], each flight's verdict and flight handed to
/// `done(index, judged, flight)`.
fn fly_each(
    flights: &[(usize, SceneFlight)],
    parks: &[&Fence],
    options: &FlightOptions,
    mut done: impl FnMut(usize, Clearing, &FlightSummary),
) {
    let fence_of = |slot: usize| std::slice::from_ref(&parks[slot % parks.len()]);
    let fenced = flights
        .iter()
        .map(|(slot, flight)| (*flight, fence_of(*slot)));
    many::judge_many(fenced, options, |index, summary, crossing| {
        let fence = fence_of(flights[index].0)[0];
        done(
            index,
            Clearing::judge(fence, crossing[0], &summary),
            &summary,
        );
    });
}

/// A park's verdict read between two of the row's flights, the nearest in
/// density either side of the park's air, both judged there: the flight in
/// the park's air lies between theirs, but for a second-order term
/// ([`read_between`]). The verdict is one of theirs.
fn between(row: &Pending, park: usize, fence: &Fence) -> Option<Clearing> {
    let density = row.airs[park].density;
    let judged = |flight: &&Reference| flight.flight.landed && flight.clearings[park].is_some();
    let nearest = |side: std::cmp::Ordering| {
        (row.flights.iter().filter(judged))
            .filter(|flight| flight.density.total_cmp(&density) == side)
            .min_by(|a, b| {
                let away = |f: &Reference| (f.density - density).abs();
                away(a).total_cmp(&away(b))
            })
    };
    let pair = [
        nearest(std::cmp::Ordering::Less)?,
        nearest(std::cmp::Ordering::Greater)?,
    ];
    let clears = read_between(pair, park, (density, row.launch_direction), fence)?;
    (pair.iter()).find_map(|flight| flight.clearings[park].filter(|c| c.clears() == clears))
}

/// Whether the row's flight in air of density `density` clears `fence`
/// (the park `park` of its flights' clearings), read between `pair`, two
/// flights in airs either side of it: `None` where the reading cannot say.
///
/// Between two airs, a flight's height at a wall, its range and its
/// direction are the straight line between theirs, off by at most
/// C·½(ρ − ρ₁)(ρ₂ − ρ)/ρ² times the wall's distance (times max(1, tan θ)),
/// the range, or the hook, C measured as the first-order bounds were
/// (docs/parks.md): a second-order term, some ten times smaller than the
/// first-order bands across the parks' airs.
fn read_between(
    [a, b]: [&Reference; 2],
    park: usize,
    (density, launch_direction): (f64, f64),
    fence: &Fence,
) -> Option<bool> {
    let (on_a, on_b) = (a.clearings[park]?, b.clearings[park]?);
    let along = (density - a.density) / (b.density - a.density);
    let between = |x: f64, y: f64| x + (y - x) * along;
    let curvature = 0.5 * (density - a.density) * (b.density - density) / (density * density);
    let slack = a.slack.max(b.slack);
    let hook = [
        on_a.direction,
        on_b.direction,
        a.flight.direction,
        b.flight.direction,
    ]
    .iter()
    .fold(0.0, |most: f64, d| most.max((d - launch_direction).abs()));
    let turn = TURN_CURVATURE * curvature * hook + slack / fence.nearest();
    let (from, to) = (
        on_a.direction.min(on_b.direction),
        on_a.direction.max(on_b.direction),
    );
    let window = Window::of(fence, from - turn, to + turn);
    let Some(fair) = window.fair else {
        // Foul in every direction the ball could take.
        return Some(false);
    };
    let steepest = a
        .flight
        .landing_angle
        .tan()
        .abs()
        .max(b.flight.landing_angle.tan().abs());
    let slope = steepest.max(1.0);
    match (on_a.height_at_fence, on_b.height_at_fence) {
        (Some(over_a), Some(over_b)) => {
            let height = between(over_a, over_b);
            let band = HEIGHT_CURVATURE * curvature * fair.farthest * slope
                + slack
                + slope * (fair.farthest - fair.nearest);
            if window.all_fair && height - band > fair.tallest {
                Some(true)
            } else {
                (height + band < fair.lowest).then_some(false)
            }
        }
        (None, None) => {
            let ranges = (a.flight.range.abs(), b.flight.range.abs());
            let reach = between(ranges.0, ranges.1)
                + RANGE_CURVATURE * curvature * ranges.0.max(ranges.1)
                + slack;
            (reach < fair.nearest).then_some(false)
        }
        _ => None,
    }
}

/// Read between two airs ([`read_between`]), a flight's height at a wall
/// lies off the straight line by at most this times ½(ρ − ρ₁)(ρ₂ − ρ)/ρ²
/// times the wall's distance and max(1, tan θ) (seen: 0.67 at most, 0.35
/// in the median, walls at 100–130 m).
const HEIGHT_CURVATURE: f64 = 1.6;

/// Its range by at most this times that and the range (seen: 0.84 at
/// most, 0.16 in the median, where it lands past 70 m).
const RANGE_CURVATURE: f64 = 2.0;

/// Its direction by at most this times that and the hook (seen: 0.76 at
/// most where the hook is over 0.3°).
const TURN_CURVATURE: f64 = 2.0;

/// Rounds of flights to every fence before the parks left are flown each
/// to its own fence.
const REFERENCE_ROUNDS: usize = 3;

/// Whether `scene`'s flight depends on its air only through the density,
/// its launch fixed whatever the air, in still air as the bounds were
/// measured: then [`settled`] may answer for it. A wind changes how much
/// the density moves a flight (a 27 mph wind blowing in moved a height at
/// a wall past the bounds: 2 verdicts of 20,000 fly balls, 21 blowing
/// out), and such a row is flown in every park's air.
pub(crate) fn settles(scene: &Scene) -> bool {
    let drag_without_reynolds = matches!(scene.drag, DragModel::Nathan | DragModel::Constant);
    let launch_given = scene.kind == SceneKind::BattedBall && scene.launch.is_complete();
    let still = scene.environment.wind == 0.0;
    drag_without_reynolds && launch_given && still
}

/// Whether a flight (in air of density `own`) comes down short of
/// `nearest_wall` (m, the nearest wall of every park) in any of `airs`:
/// then its own verdict, short, is every park's, and no park need be
/// settled one by one ([`settled`]'s first answer, for them all at once).
pub(crate) fn short_everywhere(
    flight: &FlightSummary,
    own: f64,
    airs: &[Air],
    nearest_wall: f64,
) -> bool {
    let change = (airs.iter()).fold(0.0, |most: f64, air| {
        most.max(density_change(own, air.density))
    });
    flight.landed && flight.range.abs() * (1.0 + RANGE_PER_DENSITY * change) < nearest_wall
}

/// Which parks a row's own flight (launched toward `launch_direction`, in
/// air of density `own`, judged at each of `parks` as `judged`) settles in
/// their air (`airs`, one a park), into `settled_at`: as [`settle`]'s first
/// round would find, before a row is handed to it. True where it settles
/// them all.
pub(crate) fn own_flight_settles(
    (launch_direction, flight): (f64, &FlightSummary),
    (own, airs): (f64, &[Air]),
    (parks, judged): (&[&Fence], &[Clearing]),
    settled_at: &mut Vec<bool>,
) -> bool {
    settled_at.clear();
    settled_at.extend(
        (parks.iter().zip(airs).zip(judged)).map(|((fence, air), home)| {
            let change = density_change(own, air.density);
            settled(home, (launch_direction, flight), fence, (change, 0.0))
        }),
    );
    settled_at.iter().all(|&s| s)
}

/// The relative change in density from `own` to `there` (kg/m³).
fn density_change(own: f64, there: f64) -> f64 {
    ((there - own) / own).abs()
}

/// Whether the row's own flight (launched toward `launch_direction`,
/// `flight`, judged at `fence` as `home`) gives its verdict there in an air
/// whose density differs from its own by the fraction `change`, its
/// heights and ranges known to `slack` (m): false where that air or that
/// slack could move the verdict, and the park must be flown in its own air
/// (or at the readout's precision).
fn settled(
    home: &Clearing,
    (launch_direction, flight): (f64, &FlightSummary),
    fence: &Fence,
    (change, slack): (f64, f64),
) -> bool {
    if change == 0.0 && slack == 0.0 {
        return true;
    }
    if !flight.landed {
        return false;
    }
    let reach = flight.range.abs() * (1.0 + RANGE_PER_DENSITY * change) + slack;
    if home.height_at_fence.is_none() && reach < fence.nearest() {
        // Short of every wall of the park, whatever the air.
        return true;
    }
    let hook = (home.direction - launch_direction)
        .abs()
        .max((flight.direction - launch_direction).abs());
    // In another air, the hook's share of the turn (and no less than the
    // least seen); in its own air, none. Either way, the slack's: a
    // crossing known to `slack` is known in direction to slack over its
    // distance, which is no less than the nearest wall's.
    let air_turn = if change == 0.0 {
        0.0
    } else {
        (TURN_PER_DENSITY * change * hook).max(LEAST_TURN)
    };
    let turn = air_turn + slack / fence.nearest();
    if home.height_at_fence.is_none() && reach < fence.surely_short_within(home.direction, turn) {
        // Short of the wall in every direction the ball could take (the
        // window's nearest wall, bounded without a search of its points).
        return true;
    }
    let window = Window::of(fence, home.direction - turn, home.direction + turn);
    let Some(fair) = window.fair else {
        // Foul in every direction the ball could take.
        return true;
    };
    // A flight that comes down before the wall, continued down its
    // landing line: a falling ball's track only steepens, so the line is
    // as high as it could be at the wall (and no lower than the field
    // where it has landed short: the band then starts from the ground).
    let continued = |distance: f64| -(distance - flight.range.abs()) * flight.landing_angle.tan();
    let slope = flight.landing_angle.tan().abs().max(1.0);
    let band = HEIGHT_PER_DENSITY * change * fair.farthest * slope + slack;
    match home.height_at_fence {
        None => reach < fair.nearest || continued(fair.nearest).max(0.0) + band < fair.lowest,
        Some(height) => {
            // The wall moved: the ball meets it nearer or farther, as high
            // as the track's steepest slope allows.
            let band = band + slope * (fair.farthest - fair.nearest);
            if home.clears() {
                window.all_fair && height - fair.tallest > band
            } else {
                height + band < fair.lowest
            }
        }
    }
}

/// The walls of a fence over a window of directions.
struct Window {
    /// Over its fair part, if it has one.
    fair: Option<Walls>,
    all_fair: bool,
}

#[derive(Clone, Copy)]
struct Walls {
    nearest: f64,
    farthest: f64,
    lowest: f64,
    tallest: f64,
}

impl Window {
    /// The fence from direction `from` to `to` (rad): at both ends and at
    /// every point between, where it bends (it is straight between them).
    fn of(fence: &Fence, from: f64, to: f64) -> Window {
        let ends = [fence.at(from), fence.at(to)];
        let all_fair = ends.iter().all(Option::is_some);
        // The points are in order of direction: those strictly between.
        let points = fence.points();
        let first = points.partition_point(|p| p.direction <= from);
        let past = points.partition_point(|p| p.direction < to);
        let inside = (points[first..past.max(first)].iter()).map(|p| (p.distance, p.height));
        let mut fair: Option<Walls> = None;
        for (distance, height) in ends
            .into_iter()
            .flatten()
            .map(|w| (w.distance, w.height))
            .chain(inside)
        {
            let walls = fair.get_or_insert(Walls {
                nearest: distance,
                farthest: distance,
                lowest: height,
                tallest: height,
            });
            walls.nearest = walls.nearest.min(distance);
            walls.farthest = walls.farthest.max(distance);
            walls.lowest = walls.lowest.min(height);
            walls.tallest = walls.tallest.max(height);
        }
        Window { fair, all_fair }
    }
}
