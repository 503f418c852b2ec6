//! Calibrating the aerodynamics on measured flights: the factors on C_D
//! and C_L (`model.drag_scale`, `model.lift_scale`) that make the model's
//! distances, and where they are measured its hang times or apexes, right
//! on the median.
//!
//! The median, not the mean: exports hold rows that say nothing of the
//! model (fill-in speeds and angles, inside-the-park home runs, balls that
//! hit a façade), and a median of errors is not dragged by a few of them.
//! The drag factor is the root of median(model − measured distance) = 0 in
//! k_D (monotone: more drag, shorter); with a second measured quantity the
//! two factors solve the two medians together (Newton's method, its
//! Jacobian by differences). Without one, the distances by launch angle
//! fit both (`bands`). Each trial flies every row (in parallel).
//!
//! The uncertainty is the median's own: its standard error, 1.2533·σ/√n
//! with σ = 1.4826·(median absolute deviation) (both exact for normal
//! errors), carried to the factors through the slopes of the medians
//! (each the mean rate of the rows about its median, `median_slope`).

mod bands;

pub use bands::{BAND_EDGES, band_of};

use rayon::prelude::*;

use model::flight::{FlightOptions, FlightSummary};
use model::launch::SceneFlight;
use model::scene::Scene;

/// One measured flight: its scene (the launch complete, the air and models
/// in force, unscaled or not) and what was measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    pub scene: Scene,
    /// Horizontal distance to the landing at field level (m).
    pub distance: f64,
    /// Time from contact to the landing (s).
    pub hang_time: Option<f64>,
    /// Highest point above the field (m).
    pub apex: Option<f64>,
}

/// A measured quantity's plausible range, (0, `high`], and why: a row
/// with a measurement outside is left out of the fit, since one absurd
/// number (a hang time of 0, an apex of 10⁹ ft) drags the medians and
/// pins a factor at its bound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plausible {
    /// The upper end (m or s); the lower is 0, excluded: no flight.
    pub high: f64,
    pub why: &'static str,
}

impl Plausible {
    pub fn holds(&self, value: f64) -> bool {
        value > 0.0 && value <= self.high
    }
}

/// Distance (m): the longest home runs measured are about 154 m (Statcast's
/// longest, 505 ft); 200 m leaves room for wind and thin air.
pub const DISTANCE: Plausible = Plausible {
    high: 200.0,
    why: "the longest home runs measured are about 154 m, 505 ft",
};
/// Hang time (s): a ball hit straight up at 70 m/s (157 mph, past any exit
/// speed measured) is back down in 10.0 s against the paper's drag
/// (`fly --set launch.speed=70 --set launch.angle=1.5 --set launch.spin=0`);
/// the longest pop-ups measured hang about 7 s.
pub const HANG_TIME: Plausible = Plausible {
    high: 12.0,
    why: "a ball hit straight up at 157 mph is back down in about 10 s",
};
/// Apex (m): the same ball rises 122 m (250 m in a vacuum); the highest
/// pop-ups measured are near 50 m.
pub const APEX: Plausible = Plausible {
    high: 150.0,
    why: "a ball hit straight up at 157 mph rises about 122 m",
};

/// The first of a row's measurements outside its plausible range: which
/// range (one of [`DISTANCE`], [`HANG_TIME`], [`APEX`]) and the value.
pub fn implausible(
    distance: f64,
    hang_time: Option<f64>,
    apex: Option<f64>,
) -> Option<(Plausible, f64)> {
    [
        (DISTANCE, Some(distance)),
        (HANG_TIME, hang_time),
        (APEX, apex),
    ]
    .into_iter()
    .find_map(|(range, value)| value.filter(|v| !range.holds(*v)).map(|v| (range, v)))
}

/// A fitted factor and its standard error.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Estimate {
    pub value: f64,
    pub uncertainty: f64,
}

/// The errors' summary: median, median |error| and spread (the median of
/// |error − median|), in the measured quantity's unit, and how many.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Errors {
    pub rows: usize,
    pub median: f64,
    pub median_absolute: f64,
    pub spread: f64,
}

impl Errors {
    pub fn of(errors: &[f64]) -> Errors {
        if errors.is_empty() {
            return Errors::default();
        }
        let median = median(errors.to_vec());
        Errors {
            rows: errors.len(),
            median,
            median_absolute: self::median(errors.iter().map(|e| e.abs()).collect()),
            spread: self::median(errors.iter().map(|e| (e - median).abs()).collect()),
        }
    }

    /// The median's standard error, 1.2533·1.4826·spread/√n.
    pub(crate) fn standard_error(&self) -> f64 {
        1.2533 * 1.4826 * self.spread / (self.rows.max(1) as f64).sqrt()
    }
}

/// What the fit found.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Fit {
    pub drag_scale: Estimate,
    /// `None`: lift was not fitted (left as it was).
    pub lift_scale: Option<Estimate>,
    /// What fitted the lift beside the distances.
    pub lift_from: Option<LiftFrom>,
    /// The correlation of the two factors' errors (−1 to 1): near ±1 the
    /// measurements fix a combination of them rather than each.
    pub correlation: Option<f64>,
    /// Fitted by launch-angle band: each band's distance errors.
    pub bands: Option<bands::Bands>,
    /// Why the lift was not fitted, when it was not.
    pub why_no_lift: Option<&'static str>,
    /// Distance errors (m) before (at the scenes' own factors) and after.
    pub before: Errors,
    pub after: Errors,
    /// The second quantity's errors (s or m), when fitted.
    pub second_before: Option<Errors>,
    pub second_after: Option<Errors>,
    /// Trials flown (each flies every row once).
    pub trials: usize,
}

impl Fit {
    /// The factors that ended at an end of the range searched (the key,
    /// its value, the range): the medians pull them further, which the
    /// model's physics cannot follow, and points to measurements that do
    /// not describe flights.
    pub fn at_bounds(&self) -> Vec<(&'static str, f64, (f64, f64))> {
        let ended = |value: f64, (low, high): (f64, f64)| {
            (value - low).abs() < 10.0 * TOLERANCE || (value - high).abs() < 10.0 * TOLERANCE
        };
        let mut out = Vec::new();
        if ended(self.drag_scale.value, DRAG_RANGE) {
            out.push(("model.drag_scale", self.drag_scale.value, DRAG_RANGE));
        }
        if let Some(lift) = self.lift_scale.filter(|l| ended(l.value, LIFT_RANGE)) {
            out.push(("model.lift_scale", lift.value, LIFT_RANGE));
        }
        out
    }
}

/// Why no fit.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum FitError {
    #[error("no row has a measured distance and a launch that lands")]
    NoRows,
    #[error(
        "no drag factor in [{low}, {high}] brings the median distance error to 0 (it stays {median:+.2} m)"
    )]
    OutOfRange { low: f64, high: f64, median: f64 },
}

/// The factors are searched within `model.drag_scale`'s and
/// `model.lift_scale`'s bounds.
const DRAG_RANGE: (f64, f64) = (0.3, 3.0);
const LIFT_RANGE: (f64, f64) = (0.0, 3.0);
/// The factors are wanted to this: far inside their uncertainty.
const TOLERANCE: f64 = 1e-5;

/// What fits the lift beside the distances' median.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LiftFrom {
    HangTime,
    Apex,
    /// The distances' medians by launch-angle band (`bands`).
    Bands,
}

/// The row flown at factors (k_D, k_L) on its scene's own, if it lands.
fn flown(
    row: &Measured,
    (drag, lift): (f64, f64),
    options: &FlightOptions,
) -> Option<FlightSummary> {
    let mut scene = row.scene;
    scene.drag_scale *= drag;
    scene.lift_scale *= lift;
    let summary = SceneFlight::new(&scene, &scene.batted_ball()).fly(options);
    summary.landed.then_some(summary)
}

/// The model's errors at factors (k_D, k_L) (each scene's own factors
/// multiplied by them): distances, and the second quantity's.
fn errors(
    rows: &[Measured],
    (drag, lift): (f64, f64),
    second: Option<LiftFrom>,
    options: &FlightOptions,
) -> (Vec<f64>, Vec<f64>) {
    let flown: Vec<(Option<f64>, Option<f64>)> = rows
        .par_iter()
        .map(|row| {
            let Some(summary) = flown(row, (drag, lift), options) else {
                return (None, None);
            };
            let measured = match second {
                Some(LiftFrom::HangTime) => row.hang_time.map(|t| summary.flight_time - t),
                Some(LiftFrom::Apex) => row.apex.map(|a| summary.apex - a),
                Some(LiftFrom::Bands) | None => None,
            };
            (Some(summary.range - row.distance), measured)
        })
        .collect();
    (
        flown.iter().filter_map(|f| f.0).collect(),
        flown.iter().filter_map(|f| f.1).collect(),
    )
}

/// The median (0 of none).
pub fn median(mut values: Vec<f64>) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}

/// How fast the median of `base` moves as each row moves to `moved` over a
/// step `h` of a factor: the mean rate of the rows in the middle fifth of
/// `base` (the median follows the rows about it). The difference of the two
/// medians would be the rate of the one row that happens to be the median,
/// which a row more or less changes by tens of per cent. Rows paired by
/// index; if a row lands at one factor and not the other, the medians'
/// difference.
fn median_slope(base: &[f64], moved: &[f64], h: f64) -> f64 {
    if base.len() != moved.len() || base.is_empty() {
        return (median(moved.to_vec()) - median(base.to_vec())) / h;
    }
    let mut order: Vec<usize> = (0..base.len()).collect();
    order.sort_by(|&a, &b| base[a].total_cmp(&base[b]));
    let n = order.len();
    let middle = &order[2 * n / 5..(3 * n).div_ceil(5).max(2 * n / 5 + 1)];
    middle
        .iter()
        .map(|&i| (moved[i] - base[i]) / h)
        .sum::<f64>()
        / middle.len() as f64
}

/// Fits `model.drag_scale` to the distances, and with `lift`
/// `model.lift_scale` too: from the hang times where at least a third of
/// the rows measure them (else the apexes), else from the distances by
/// launch-angle band. The factors found multiply each scene's own.
pub fn fit(rows: &[Measured], options: &FlightOptions, lift: bool) -> Result<Fit, FitError> {
    let count = |f: fn(&Measured) -> bool| rows.iter().filter(|r| f(r)).count();
    let second = if !lift || rows.is_empty() {
        None
    } else if 3 * count(|r| r.hang_time.is_some()) >= rows.len() {
        Some(LiftFrom::HangTime)
    } else if 3 * count(|r| r.apex.is_some()) >= rows.len() {
        Some(LiftFrom::Apex)
    } else {
        let drag_only = fit(rows, options, false)?;
        return bands::fit(rows, options, drag_only);
    };
    let mut trials = 0;
    let mut at = |k: (f64, f64)| {
        trials += 1;
        errors(rows, k, second, options)
    };
    let (before, second_before) = at((1.0, 1.0));
    if before.is_empty() {
        return Err(FitError::NoRows);
    }
    let before = Errors::of(&before);
    let second_before = second.map(|_| Errors::of(&second_before));
    // The drag factor alone: a bracketed secant (Illinois) on the median.
    let median_at = |k: f64, lift: f64, at: &mut dyn FnMut((f64, f64)) -> (Vec<f64>, Vec<f64>)| {
        median(at((k, lift)).0)
    };
    let solve_drag = |lift: f64, at: &mut dyn FnMut((f64, f64)) -> (Vec<f64>, Vec<f64>)| {
        let (mut a, mut b) = DRAG_RANGE;
        let (mut fa, mut fb) = (median_at(a, lift, at), median_at(b, lift, at));
        if fa.signum() == fb.signum() {
            return Err(FitError::OutOfRange {
                low: a,
                high: b,
                median: fb,
            });
        }
        let mut side = 0;
        for _ in 0..60 {
            let c = (a * fb - b * fa) / (fb - fa);
            let fc = median_at(c, lift, at);
            if fc == 0.0 || (b - a).abs() < TOLERANCE {
                return Ok(c);
            }
            if fc.signum() == fa.signum() {
                (a, fa) = (c, fc);
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            } else {
                (b, fb) = (c, fc);
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            }
        }
        Ok(0.5 * (a + b))
    };
    let (drag, lift) = match second {
        None => (solve_drag(1.0, &mut at)?, 1.0),
        Some(_) => {
            // Newton on the two medians, from (k_D at k_L = 1, 1).
            let mut k = (solve_drag(1.0, &mut at)?, 1.0);
            for _ in 0..8 {
                let f = |e: (Vec<f64>, Vec<f64>)| (median(e.0), median(e.1));
                let h = 1e-3;
                let f0 = f(at(k));
                let fd = f(at((k.0 + h, k.1)));
                let fl = f(at((k.0, k.1 + h)));
                let j = [
                    [(fd.0 - f0.0) / h, (fl.0 - f0.0) / h],
                    [(fd.1 - f0.1) / h, (fl.1 - f0.1) / h],
                ];
                let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
                if det == 0.0 {
                    break;
                }
                let step = (
                    (j[1][1] * f0.0 - j[0][1] * f0.1) / det,
                    (j[0][0] * f0.1 - j[1][0] * f0.0) / det,
                );
                k = (
                    (k.0 - step.0).clamp(DRAG_RANGE.0, DRAG_RANGE.1),
                    (k.1 - step.1).clamp(LIFT_RANGE.0, LIFT_RANGE.1),
                );
                if step.0.abs() < TOLERANCE && step.1.abs() < TOLERANCE {
                    break;
                }
            }
            k
        }
    };
    let (after, second_after) = at((drag, lift));
    let after = Errors::of(&after);
    let second_after = second.map(|_| Errors::of(&second_after));
    // How the medians move with the factors, at the fit.
    let h = 1e-3;
    let (base, base_second) = at((drag, lift));
    let (moved, moved_second) = at((drag + h, lift));
    let distance_per_drag = median_slope(&base, &moved, h);
    let mut correlation = None;
    let (drag_scale, lift_scale) = match (second, second_after) {
        (Some(_), Some(second_after)) => {
            let (lifted, lifted_second) = at((drag, lift + h));
            let j = [
                [distance_per_drag, median_slope(&base, &lifted, h)],
                [
                    median_slope(&base_second, &moved_second, h),
                    median_slope(&base_second, &lifted_second, h),
                ],
            ];
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            let (s1, s2) = (after.standard_error(), second_after.standard_error());
            // The inverse Jacobian's rows, each measured median's error
            // independent of the other's.
            let drag_se = (j[1][1] * s1).hypot(j[0][1] * s2) / det.abs();
            let lift_se = (j[1][0] * s1).hypot(j[0][0] * s2) / det.abs();
            let covariance =
                -(j[1][1] * j[1][0] * s1 * s1 + j[0][1] * j[0][0] * s2 * s2) / (det * det);
            correlation = Some(covariance / (drag_se * lift_se));
            (
                Estimate {
                    value: drag,
                    uncertainty: drag_se,
                },
                Some(Estimate {
                    value: lift,
                    uncertainty: lift_se,
                }),
            )
        }
        _ => (
            Estimate {
                value: drag,
                uncertainty: after.standard_error() / distance_per_drag.abs(),
            },
            None,
        ),
    };
    Ok(Fit {
        drag_scale,
        lift_scale,
        lift_from: second,
        correlation,
        bands: None,
        why_no_lift: second.is_none().then_some("--drag-only"),
        before,
        after,
        second_before,
        second_after,
        trials,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use model::launch::BattedBall;
    use numerics::ode::Tolerance;

    fn options() -> FlightOptions {
        FlightOptions {
            tolerance: Tolerance::uniform(1e-9),
            stop_at_kinks: true,
        }
    }

    /// Flights made with known factors are fitted back to them.
    fn made_with(drag: f64, lift: f64) -> Vec<Measured> {
        (0..24)
            .map(|i| {
                let f = f64::from(i);
                let scene = Scene::default().with_launch(BattedBall {
                    speed: 40.0 + 0.4 * f,
                    angle: (20.0 + f).to_radians(),
                    spin: 150.0 + 8.0 * f,
                    direction: 0.0,
                    sidespin: 0.0,
                });
                let mut truth = scene;
                truth.drag_scale = drag;
                truth.lift_scale = lift;
                let flown = SceneFlight::new(&truth, &truth.batted_ball()).fly(&options());
                Measured {
                    scene,
                    distance: flown.range,
                    hang_time: Some(flown.flight_time),
                    apex: None,
                }
            })
            .collect()
    }

    #[test]
    fn the_medians_slope_is_its_neighbours_not_one_rows() {
        // 101 rows each moving at rate 1 but the median row, at 50: the
        // median's own difference follows that one row, the slope the rows
        // about it (the middle fifth, rows 40 to 60: (20 + 50)/21).
        let h = 1e-3;
        let base: Vec<f64> = (0..101).map(f64::from).collect();
        let moved: Vec<f64> = (0..101)
            .map(|i| f64::from(i) + h * if i == 50 { 50.0 } else { 1.0 })
            .collect();
        let one_row = (median(moved.clone()) - median(base.clone())) / h;
        assert!((one_row - 50.0).abs() < 1e-6, "{one_row}");
        let slope = median_slope(&base, &moved, h);
        assert!((slope - 70.0 / 21.0).abs() < 1e-6, "{slope}");
        // Rows lost between the two: the medians' difference.
        assert_eq!(
            median_slope(&base, &moved[1..], h),
            (median(moved[1..].to_vec()) - 50.0) / h
        );
    }

    #[test]
    fn the_drag_factor_of_flights_made_with_it_is_found() {
        let mut rows = made_with(1.07, 1.0);
        for row in &mut rows {
            row.hang_time = None;
        }
        let fit = fit(&rows, &options(), false).unwrap();
        assert!((fit.drag_scale.value - 1.07).abs() < 1e-4, "{fit:?}");
        assert!(fit.lift_scale.is_none());
        assert!(fit.before.median > 0.0, "unscaled flies further");
        assert!(fit.after.median.abs() < 1e-3);
    }

    #[test]
    fn drag_and_lift_are_found_together_from_hang_times() {
        let fit = fit(&made_with(0.95, 1.1), &options(), true).unwrap();
        assert!((fit.drag_scale.value - 0.95).abs() < 1e-3, "{fit:?}");
        let lift = fit.lift_scale.unwrap();
        assert!((lift.value - 1.1).abs() < 1e-3, "{fit:?}");
        assert!(fit.after.median.abs() < 1e-3);
        assert!(fit.second_after.unwrap().median.abs() < 1e-3);
    }

    /// Without hang times, the distances by launch-angle band find both
    /// (the 24 flights span four bands, 20° to 43°), and no misfit is left.
    #[test]
    fn drag_and_lift_are_found_together_from_distances_by_band() {
        let mut rows = made_with(0.95, 1.1);
        for row in &mut rows {
            row.hang_time = None;
        }
        let fit = fit(&rows, &options(), true).unwrap();
        assert_eq!(fit.lift_from, Some(LiftFrom::Bands));
        assert!((fit.drag_scale.value - 0.95).abs() < 1e-3, "{fit:?}");
        assert!(
            (fit.lift_scale.unwrap().value - 1.1).abs() < 1e-3,
            "{fit:?}"
        );
        let bands = fit.bands.unwrap();
        assert_eq!(bands.after.iter().filter(|b| b.rows > 0).count(), 4);
        assert!(
            bands.after.iter().all(|b| b.median.abs() < 0.01),
            "{bands:?}"
        );
        assert!(bands.misfit < 0.1, "{bands:?}");
        // The same rows three times over are the same measurement.
        let thrice: Vec<Measured> = rows.iter().cycle().take(3 * rows.len()).copied().collect();
        let again = super::fit(&thrice, &options(), true).unwrap();
        assert!((again.drag_scale.value - fit.drag_scale.value).abs() < 1e-3);
        let lifts = (
            again.lift_scale.unwrap().value,
            fit.lift_scale.unwrap().value,
        );
        assert!((lifts.0 - lifts.1).abs() < 2e-3, "{lifts:?}");
        // A band is from its edge up: 30° (an ulp off in radians) is 30–35°.
        assert_eq!(band_of(30f64.to_radians()), Some(3));
        assert_eq!(band_of(9.99f64.to_radians()), None);
        assert_eq!(band_of(80f64.to_radians()), Some(5));
        // Within one band the distances cannot part the two: the drag
        // alone, and why.
        let one_band: Vec<Measured> = (rows.into_iter())
            .filter(|r| band_of(r.scene.launch.angle.unwrap()) == Some(2))
            .collect();
        let alone = super::fit(&one_band, &options(), true).unwrap();
        assert!(alone.lift_scale.is_none() && alone.drag_scale.uncertainty.is_finite());
        assert!(alone.why_no_lift.unwrap().contains("fewer than three"));
    }
}
