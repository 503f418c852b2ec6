//! A park's outfield fence from one foul line to the other: its distance
//! from home plate and its height, by direction (DESIGN.md, "Parks").

use std::f64::consts::FRAC_PI_4;
use std::sync::atomic::{AtomicU64, Ordering};

/// The foul lines' directions: ±π/4 from the centre-field line.
pub const FOUL_LINE: f64 = FRAC_PI_4;

/// Whether `direction` (rad from the centre-field line) lies between the
/// foul lines, on them included; not NaN.
pub fn fair(direction: f64) -> bool {
    (-FOUL_LINE..=FOUL_LINE).contains(&direction)
}

/// One point of a fence.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct FencePoint {
    /// Direction from home plate (rad from the centre-field line, positive
    /// toward right field).
    pub direction: f64,
    /// Horizontal distance from home plate to the wall (m).
    pub distance: f64,
    /// The wall's height (m).
    pub height: f64,
}

/// The fence where a direction meets it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FenceAt {
    /// Horizontal distance from home plate (m).
    pub distance: f64,
    /// Height of the wall (m).
    pub height: f64,
}

/// A fence from foul line to foul line: points sorted by direction, the
/// first at −π/4 and the last at +π/4, distance and height linear between
/// them. A change of height is a step: two points at the same direction,
/// the left one's height before it, the right one's from it on.
#[derive(Clone, Debug)]
pub struct Fence {
    points: Vec<FencePoint>,
    /// The shortest distance to the wall (m): a ball nearer the plate has
    /// not reached it, whatever its direction (one comparison per step
    /// when a flight is tested against many fences).
    nearest: f64,
    /// For each of [`BUCKETS`] equal slices of fair territory, from the
    /// left-field line, the first point past the slice's start: where the
    /// search for a direction's segment begins (a batch looks up 31 fences
    /// a row; a binary search's unpredictable branches cost several times
    /// this table's one multiply and a step or two forward).
    first_past: Vec<u16>,
    /// For each slice, a distance short of the wall anywhere in it and in
    /// the slices either side ([`Fence::surely_short`]), as f64 bits: each
    /// slice worked out the first time a flight asks for it ([`UNKNOWN`]
    /// till then), since every command loads the 30 parks and one flight
    /// asks for a slice or two of each (building whole tables cost each
    /// `fly` ~0.16 ms of its ~1 ms).
    short_in: ShortSlices,
}

/// [`Fence::short_in`]: one figure a slice, each set once.
#[derive(Debug)]
struct ShortSlices(Box<[AtomicU64]>);

/// A clone keeps the slices worked out so far.
impl Clone for ShortSlices {
    fn clone(&self) -> ShortSlices {
        let bits = |slice: &AtomicU64| AtomicU64::new(slice.load(Ordering::Relaxed));
        ShortSlices(self.0.iter().map(bits).collect())
    }
}

/// A slice of [`Fence::short_in`] not worked out yet: NaN's bits, which no
/// distance has.
const UNKNOWN: u64 = u64::MAX;

/// Fences are equal when their walls are: the tables follow from them.
impl PartialEq for Fence {
    fn eq(&self, other: &Fence) -> bool {
        self.points == other.points
    }
}

/// Slices of fair territory in [`Fence::first_past`]: under 1° each, so a
/// search walks past at most the points of one slice.
const BUCKETS: usize = 128;

/// [`Fence::surely_short`]'s margin, relative: far above the interpolation's
/// rounding (ulps), far below anything that shows (0.1 µm at 100 m).
const SHORT_MARGIN: f64 = 1e-9;

/// Why a list of points is not a fence (the parser names the park and field).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FenceError {
    #[error("has {0} points; a fence needs at least 2, from -π/4 to +π/4")]
    TooFew(usize),
    #[error("has {0} points; a fence takes at most {MAX_POINTS} (one every 0.09°)")]
    TooMany(usize),
    #[error("point {index}: {field} = {value}: must be a finite number in {accepted}")]
    OutOfRange {
        index: usize,
        field: &'static str,
        value: f64,
        accepted: &'static str,
    },
    #[error(
        "point {index}: direction {direction} comes before the point ahead of it ({previous}); directions must not decrease"
    )]
    NotSorted {
        index: usize,
        direction: f64,
        previous: f64,
    },
    #[error(
        "point {index}: three points at direction {direction}; a step in height is two points at one direction"
    )]
    ThreeAtOnce { index: usize, direction: f64 },
    #[error(
        "runs from {first} to {last} rad; it must run from the left-field line (-0.7854) to the right-field line (0.7854)"
    )]
    NotFoulLineToFoulLine { first: f64, last: f64 },
}

/// The most points a fence takes: the bundled fences have at most 181 (one
/// every half degree); every flight that meets a fence looks it up, and a
/// park file of 1 MiB could otherwise hold 20,000.
pub const MAX_POINTS: usize = 1000;

/// How close to ±π/4 the end points must be (rad): the data files give
/// directions to five decimals.
const END_TOLERANCE: f64 = 1e-4;
/// Largest distance and height accepted (m), as for `field.fence_distance`.
const MAX_DISTANCE: f64 = 1000.0;
const MAX_HEIGHT: f64 = 100.0;

impl Fence {
    /// A fence from points, checked: at least two and at most
    /// `MAX_POINTS` (1000), each distance in
    /// (0, 1000] m and height in (0, 100] m, directions not decreasing (at
    /// most two at one direction) from −π/4 to +π/4. The end points are
    /// moved onto the foul lines exactly.
    pub fn new(mut points: Vec<FencePoint>) -> Result<Fence, FenceError> {
        if points.len() < 2 {
            return Err(FenceError::TooFew(points.len()));
        }
        if points.len() > MAX_POINTS {
            return Err(FenceError::TooMany(points.len()));
        }
        for (index, p) in points.iter().enumerate() {
            let check = |field, value: f64, max: f64, accepted| {
                if value.is_finite() && value > 0.0 && value <= max {
                    Ok(())
                } else {
                    Err(FenceError::OutOfRange {
                        index,
                        field,
                        value,
                        accepted,
                    })
                }
            };
            if !p.direction.is_finite() {
                return Err(FenceError::OutOfRange {
                    index,
                    field: "direction",
                    value: p.direction,
                    accepted: "[-0.7854, 0.7854] rad",
                });
            }
            check("distance", p.distance, MAX_DISTANCE, "(0, 1000] m")?;
            check("height", p.height, MAX_HEIGHT, "(0, 100] m")?;
        }
        for index in 1..points.len() {
            let (previous, direction) = (points[index - 1].direction, points[index].direction);
            if direction < previous {
                return Err(FenceError::NotSorted {
                    index,
                    direction,
                    previous,
                });
            }
            if index >= 2 && points[index - 2].direction == direction {
                return Err(FenceError::ThreeAtOnce { index, direction });
            }
        }
        let (first, last) = (points[0].direction, points[points.len() - 1].direction);
        if (first + FOUL_LINE).abs() > END_TOLERANCE || (last - FOUL_LINE).abs() > END_TOLERANCE {
            return Err(FenceError::NotFoulLineToFoulLine { first, last });
        }
        let n = points.len();
        points[0].direction = -FOUL_LINE;
        points[n - 1].direction = FOUL_LINE;
        Ok(Fence::of(points))
    }

    /// The same distance and height in every fair direction: the generic
    /// fence of a preset's `field.fence_distance` and `field.fence_height`.
    pub fn uniform(distance: f64, height: f64) -> Fence {
        let point = |direction| FencePoint {
            direction,
            distance,
            height,
        };
        Fence::of(vec![point(-FOUL_LINE), point(FOUL_LINE)])
    }

    fn of(points: Vec<FencePoint>) -> Fence {
        let nearest = points
            .iter()
            .map(|p| p.distance)
            .fold(f64::INFINITY, f64::min);
        let first_past = Fence::first_past(&points);
        Fence {
            points,
            nearest,
            first_past,
            short_in: ShortSlices((0..BUCKETS).map(|_| AtomicU64::new(UNKNOWN)).collect()),
        }
    }

    /// [`Fence::first_past`]: how many points lie at or before each
    /// slice's start, by one walk.
    fn first_past(points: &[FencePoint]) -> Vec<u16> {
        let mut count = 0;
        (0..BUCKETS)
            .map(|edge| {
                let start = Fence::bucket_start(edge);
                while count < points.len() && points[count].direction <= start {
                    count += 1;
                }
                count as u16
            })
            .collect()
    }

    /// [`Fence::short_in`]'s figure for slice `bucket`: the wall's least
    /// distance over it and the slices either side, a margin short.
    fn short_of_slice(&self, bucket: usize) -> f64 {
        let points = &self.points;
        // The points before an edge, or at or before it.
        let before = |edge: usize| {
            let start = Fence::bucket_start(edge);
            points.partition_point(|p| p.direction < start)
        };
        let up_to = |edge: usize| {
            let start = Fence::bucket_start(edge);
            points.partition_point(|p| p.direction <= start)
        };
        // The wall at an edge, between the points either side of it (as
        // `reach` finds it, but for its rounding, which SHORT_MARGIN
        // covers; at a jog on the edge both of its points are among the
        // slices' points below).
        let edge_wall = |edge: usize| match before(edge) {
            0 => points[0].distance,
            n if n == points.len() => points[n - 1].distance,
            n => {
                let (a, b) = (points[n - 1], points[n]);
                let slope = (b.distance - a.distance) / (b.direction - a.direction);
                a.distance + slope * (Fence::bucket_start(edge) - a.direction)
            }
        };
        // This slice and those either side, edges included: the wall is
        // linear between points, so its least distance over the stretch is
        // at its ends or at a point inside (sorted by direction, a run).
        let (from_edge, to_edge) = (bucket.saturating_sub(1), (bucket + 2).min(BUCKETS));
        let (first, end) = (before(from_edge), up_to(to_edge));
        let least = points[first..end.max(first)]
            .iter()
            .map(|p| p.distance)
            .chain([edge_wall(from_edge), edge_wall(to_edge)])
            .fold(f64::INFINITY, f64::min);
        least * (1.0 - SHORT_MARGIN)
    }

    /// The direction where slice `bucket` of [`Fence::first_past`] begins.
    fn bucket_start(bucket: usize) -> f64 {
        -FOUL_LINE + bucket as f64 * (2.0 * FOUL_LINE / BUCKETS as f64)
    }

    /// The shortest distance from home plate to the wall (m).
    pub fn nearest(&self) -> f64 {
        self.nearest
    }

    /// A distance (m) short of the wall in `direction`: under what
    /// [`Fence::reach`] gives there, whatever its rounding, looked up
    /// without a search (the fences' watch asks it of every fence once the
    /// ball is past their nearest points). −∞ for NaN.
    #[inline]
    pub fn surely_short(&self, direction: f64) -> f64 {
        if direction.is_nan() {
            return f64::NEG_INFINITY;
        }
        let fair = direction.clamp(-FOUL_LINE, FOUL_LINE);
        // The slice as [`Fence::segment`] finds it, or the one before (the
        // product rounds): each slice's figure covers its neighbours too.
        let slice = (fair + FOUL_LINE) * (BUCKETS as f64 / (2.0 * FOUL_LINE));
        let bucket = (slice as usize).min(BUCKETS - 1);
        // Two threads may both work a slice out: they store the same bits.
        let slot = &self.short_in.0[bucket];
        match slot.load(Ordering::Relaxed) {
            UNKNOWN => {
                let short = self.short_of_slice(bucket);
                slot.store(short.to_bits(), Ordering::Relaxed);
                short
            }
            bits => f64::from_bits(bits),
        }
    }

    /// A distance (m) short of the wall at every direction within `spread`
    /// (rad) of `direction`: [`Fence::surely_short`]'s, whose slices either
    /// side cover such a spread when it is under one slice (with room for
    /// the slice's rounding); −∞, nothing surely short, for a wider one.
    /// So a ball whose direction is known to `spread` is judged short of
    /// the wall without a search of its points.
    pub fn surely_short_within(&self, direction: f64, spread: f64) -> f64 {
        let slice = 2.0 * FOUL_LINE / BUCKETS as f64;
        if spread <= 0.9 * slice {
            self.surely_short(direction)
        } else {
            f64::NEG_INFINITY
        }
    }

    /// The wall's distance (m) in `direction` and its rate of change with
    /// the direction (m/rad), the fence continued past each foul pole at
    /// the pole's distance: a function of every direction, so that a root
    /// finder can follow a ground track that leaves fair territory (the
    /// crossing's direction then says foul). Where the distance jumps (a
    /// jog at one direction) the slope is the right-hand side's.
    pub fn reach(&self, direction: f64) -> (f64, f64) {
        let fair = direction.clamp(-FOUL_LINE, FOUL_LINE);
        let (a, b) = self.segment(fair);
        let span = b.direction - a.direction;
        if span > 0.0 {
            let slope = (b.distance - a.distance) / span;
            let distance = a.distance + slope * (fair - a.direction);
            (distance, if fair == direction { slope } else { 0.0 })
        } else {
            (b.distance, 0.0)
        }
    }

    /// The points, sorted by direction.
    pub fn points(&self) -> &[FencePoint] {
        &self.points
    }

    /// The fence in `direction` (rad from the centre-field line, + toward
    /// right field), or `None` outside the foul lines (foul) or for NaN.
    /// A binary search and one interpolation: no allocation.
    pub fn at(&self, direction: f64) -> Option<FenceAt> {
        if !fair(direction) {
            return None;
        }
        let (a, b) = self.segment(direction);
        let span = b.direction - a.direction;
        let t = if span > 0.0 {
            ((direction - a.direction) / span).clamp(0.0, 1.0)
        } else {
            1.0
        };
        Some(FenceAt {
            distance: a.distance + t * (b.distance - a.distance),
            height: a.height + t * (b.height - a.height),
        })
    }

    /// The two points around `direction` (in [−π/4, π/4]); at a step, the
    /// pair that starts there (the right-hand side).
    fn segment(&self, direction: f64) -> (FencePoint, FencePoint) {
        let points = &self.points;
        // The first point past `direction`: from the first past its
        // slice's start (NaN and directions outside fair territory fall in
        // the first or last slice), on while points are not past it.
        let slice = (direction + FOUL_LINE) * (BUCKETS as f64 / (2.0 * FOUL_LINE));
        let mut bucket = (slice as usize).min(BUCKETS - 1);
        // The product rounds, by ulps: at most one slice too far.
        if bucket > 0 && Fence::bucket_start(bucket) > direction {
            bucket -= 1;
        }
        let mut after = self.first_past[bucket] as usize;
        while after < points.len() && points[after].direction <= direction {
            after += 1;
        }
        let after = after.clamp(1, points.len() - 1);
        (points[after - 1], points[after])
    }

    /// The wall's distance from home plate in `direction` (m); `None` foul.
    pub fn distance_at(&self, direction: f64) -> Option<f64> {
        self.at(direction).map(|f| f.distance)
    }

    /// The wall's height in `direction` (m); `None` foul.
    pub fn height_at(&self, direction: f64) -> Option<f64> {
        self.at(direction).map(|f| f.height)
    }

    /// How far a point on the ground (x toward centre field, z toward right
    /// field, m from home plate) lies beyond the wall in its direction:
    /// positive past it, negative short of it; `None` if foul. Its root in a
    /// flight is where the ground track crosses the fence.
    pub fn beyond(&self, x: f64, z: f64) -> Option<f64> {
        self.distance_at(z.atan2(x)).map(|d| x.hypot(z) - d)
    }

    /// The fence at the left-field line, straightaway centre and the
    /// right-field line.
    pub fn lines_and_center(&self) -> [FenceAt; 3] {
        let at = |d| self.at(d).expect("within the foul lines");
        [at(-FOUL_LINE), at(0.0), at(FOUL_LINE)]
    }

    /// The tallest wall (m).
    pub fn tallest(&self) -> f64 {
        self.points.iter().map(|p| p.height).fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(direction: f64, distance: f64, height: f64) -> FencePoint {
        FencePoint {
            direction,
            distance,
            height,
        }
    }

    #[test]
    fn the_slice_table_finds_the_segment_a_binary_search_finds() {
        // Every bundled park and a fence with points on slice boundaries
        // and a step: at each point's direction, an ulp either side, each
        // slice's start and an ulp either side, and a fine sweep.
        let start = Fence::bucket_start;
        let mut fences: Vec<Fence> = super::super::bundled()
            .iter()
            .map(|p| p.fence.clone())
            .collect();
        let mut points = vec![point(-FOUL_LINE, 100.0, 3.0)];
        for b in [1, 2, 2, 64, 100, 127] {
            points.push(point(start(b), 110.0, if b == 2 { 5.0 } else { 3.0 }));
        }
        points.push(point(FOUL_LINE, 100.0, 3.0));
        fences.push(Fence::new(points).unwrap());
        let next = |d: f64, up: bool| {
            let bits = d.to_bits() as i64;
            let step = if (d >= 0.0) == up { 1 } else { -1 };
            if d == 0.0 {
                if up { 1e-300 } else { -1e-300 }
            } else {
                f64::from_bits((bits + step) as u64)
            }
        };
        for fence in &fences {
            let mut directions: Vec<f64> = fence.points.iter().map(|p| p.direction).collect();
            directions.extend((0..BUCKETS).map(start));
            directions.extend((0..=2000).map(|i| -FOUL_LINE + i as f64 * FOUL_LINE / 1000.0));
            for d in directions.clone() {
                directions.extend([next(d, true), next(d, false)]);
            }
            for d in directions {
                let d = d.clamp(-FOUL_LINE, FOUL_LINE);
                let searched = fence
                    .points
                    .partition_point(|p| p.direction <= d)
                    .clamp(1, fence.points.len() - 1);
                let expected = (fence.points[searched - 1], fence.points[searched]);
                assert_eq!(fence.segment(d), expected, "at {d:e}");
            }
        }
    }

    /// Every bundled fence, one with points on slice boundaries, a deep
    /// notch and a step, and a uniform one.
    fn hard_fences() -> Vec<Fence> {
        let mut fences: Vec<Fence> = super::super::bundled()
            .iter()
            .map(|p| p.fence.clone())
            .collect();
        let start = Fence::bucket_start;
        let points = vec![
            point(-FOUL_LINE, 100.0, 3.0),
            point(start(3), 90.0, 3.0),
            point(start(3), 120.0, 5.0),
            point(start(64) + 1e-4, 80.0, 3.0),
            point(start(65), 130.0, 3.0),
            point(FOUL_LINE, 100.0, 3.0),
        ];
        fences.push(Fence::new(points).unwrap());
        fences.push(Fence::uniform(121.92, 3.0));
        fences
    }

    #[test]
    fn surely_short_within_a_spread_is_short_of_the_wall_over_it() {
        let width = 2.0 * FOUL_LINE / BUCKETS as f64;
        for fence in &hard_fences() {
            // Directions at slice starts, an ulp either side, and between;
            // spreads up to the most allowed.
            let starts = (0..=BUCKETS).map(Fence::bucket_start);
            let mut directions: Vec<f64> = starts
                .flat_map(|d| [d, d.next_up(), d.next_down()])
                .collect();
            directions.extend((0..=2_000).map(|i| -0.9 + i as f64 * 9e-4));
            for d in directions {
                for spread in [0.0, 0.3 * width, 0.9 * width] {
                    let short = fence.surely_short_within(d, spread);
                    let (from, to) = (d - spread, d + spread);
                    let fair = |d: f64| d.clamp(-FOUL_LINE, FOUL_LINE);
                    let inside = (fence.points.iter())
                        .filter(|p| (fair(from)..=fair(to)).contains(&p.direction))
                        .map(|p| p.distance);
                    let ends = [fence.reach(from).0, fence.reach(to).0];
                    let least = inside.chain(ends).fold(f64::INFINITY, f64::min);
                    assert!(
                        short < least,
                        "{short} against {least} at {d:e} ± {spread:e}"
                    );
                }
                // Wider than a slice's room: nothing is surely short.
                assert_eq!(
                    fence.surely_short_within(d, 0.95 * width),
                    f64::NEG_INFINITY
                );
            }
        }
    }

    #[test]
    fn surely_short_is_short_of_the_wall_in_every_direction() {
        let fences = hard_fences();
        let start = Fence::bucket_start;
        for fence in &fences {
            let mut directions: Vec<f64> = fence.points.iter().map(|p| p.direction).collect();
            directions.extend((0..BUCKETS).map(start));
            directions.extend((0..=20_000).map(|i| -1.0 + i as f64 * 1e-4));
            for d in directions.clone() {
                directions.extend([d.next_up(), d.next_down()]);
            }
            for d in directions {
                let (short, wall) = (fence.surely_short(d), fence.reach(d).0);
                assert!(short < wall, "{short} against {wall} at {d:e}");
                // And no shorter than the wall anywhere within two slices
                // (its slice and either neighbour lie inside them).
                let width = 2.0 * FOUL_LINE / BUCKETS as f64;
                let fair = |d: f64| d.clamp(-FOUL_LINE, FOUL_LINE);
                let (from, to) = (fair(d) - 2.0 * width, fair(d) + 2.0 * width);
                let inside = fence
                    .points
                    .iter()
                    .filter(|p| (fair(from)..=fair(to)).contains(&p.direction));
                let least = inside
                    .map(|p| p.distance)
                    .chain([fence.reach(from).0, fence.reach(to).0])
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    short >= least * (1.0 - 2.0 * SHORT_MARGIN),
                    "{short} {least} at {d:e}"
                );
            }
        }
        assert_eq!(fences[0].surely_short(f64::NAN), f64::NEG_INFINITY);
    }

    #[test]
    fn interpolates_between_points_and_steps_at_a_corner() {
        let fence = Fence::new(vec![
            point(-FOUL_LINE, 100.0, 10.0),
            point(0.0, 120.0, 10.0),
            point(0.0, 120.0, 2.0),
            point(FOUL_LINE, 100.0, 2.0),
        ])
        .unwrap();
        let half_left = fence.at(-FOUL_LINE / 2.0).unwrap();
        assert!((half_left.distance - 110.0).abs() < 1e-12);
        assert_eq!(half_left.height, 10.0);
        // At the step the right-hand wall; just left of it the left one.
        assert_eq!(fence.height_at(0.0), Some(2.0));
        assert_eq!(fence.height_at(-1e-9), Some(10.0));
        assert_eq!(fence.distance_at(FOUL_LINE), Some(100.0));
        assert_eq!(fence.distance_at(FOUL_LINE + 1e-9), None);
        assert_eq!(fence.distance_at(f64::NAN), None);
        // 130 m straight to centre is 10 m past a 120 m wall.
        assert!((fence.beyond(130.0, 0.0).unwrap() - 10.0).abs() < 1e-12);
        assert_eq!(fence.beyond(10.0, -20.0), None, "foul");
    }

    #[test]
    fn uniform_fence_is_the_same_everywhere() {
        let fence = Fence::uniform(121.9, 3.0);
        for d in [-FOUL_LINE, -0.3, 0.0, 0.5, FOUL_LINE] {
            assert_eq!(
                fence.at(d),
                Some(FenceAt {
                    distance: 121.9,
                    height: 3.0
                })
            );
        }
        assert_eq!(fence.tallest(), 3.0);
    }

    #[test]
    fn refuses_what_is_not_a_fence() {
        let e = Fence::new(vec![point(-FOUL_LINE, 100.0, 3.0)]).unwrap_err();
        assert_eq!(e, FenceError::TooFew(1));
        let e =
            Fence::new(vec![point(-FOUL_LINE, 100.0, 3.0), point(0.5, 100.0, 3.0)]).unwrap_err();
        assert!(e.to_string().contains("right-field line"), "{e}");
        let e = Fence::new(vec![
            point(-FOUL_LINE, 100.0, 3.0),
            point(FOUL_LINE, -5.0, 3.0),
        ])
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "point 1: distance = -5: must be a finite number in (0, 1000] m"
        );
        let e = Fence::new(vec![
            point(-FOUL_LINE, 100.0, 3.0),
            point(0.2, 100.0, 3.0),
            point(0.1, 100.0, 3.0),
            point(FOUL_LINE, 100.0, 3.0),
        ])
        .unwrap_err();
        assert!(matches!(e, FenceError::NotSorted { index: 2, .. }), "{e}");
        let e = Fence::new(vec![
            point(-FOUL_LINE, 100.0, 3.0),
            point(0.0, 100.0, 3.0),
            point(0.0, 100.0, 4.0),
            point(0.0, 100.0, 5.0),
            point(FOUL_LINE, 100.0, 3.0),
        ])
        .unwrap_err();
        assert!(matches!(e, FenceError::ThreeAtOnce { index: 3, .. }), "{e}");
    }
}
