//! Drag and lift from distances alone (issue 26). Drag and lift shorten a
//! flight in different proportions at different launch angles, so the
//! distances' errors by launch-angle band part them: the bands of balls in
//! the air that `fly --batch --summary` prints (10–20°, 20–25°, 25–30°,
//! 30–35°, 35–50°, 50°+). The factors minimise χ² = Σ (median_b / σ_b)²,
//! each band's median error weighted by its own standard error
//! (Nelder–Mead from the drag fitted alone and the lift as it is).
//!
//! Where two factors cannot flatten the bands, χ² per degree of freedom
//! is far above 1: the misfit is the model's, not noise. The
//! uncertainties are then scaled by √(χ²/dof) (the Birge ratio), and the
//! bands left after the fit show the shape no factor on C_D and C_L
//! removes.

use rayon::prelude::*;

use super::{DRAG_RANGE, Errors, Estimate, Fit, FitError, LIFT_RANGE, LiftFrom, Measured, flown};
use model::flight::FlightOptions;
use numerics::nelder_mead::{NelderMead, Point, Settings, Status};

/// The bands' lower edges (degrees); the last band is open above. Below
/// 10° a distance is where the ball was fielded, and no row is used.
pub const BAND_EDGES: [f64; 6] = [10.0, 20.0, 25.0, 30.0, 35.0, 50.0];

/// Why the lift was not fitted from too few bands.
const FEW_BANDS: &str = "the distances fill fewer than three launch-angle bands that part drag \
     from lift (a hang_time or apex column would fit it)";

/// Why the lift was not fitted where the bands leave it undetermined.
const UNDETERMINED: &str = "the launch-angle bands leave it undetermined (past ± 0.5: half the \
     lift as likely as one and a half; more rows, or a hang_time or apex column, would fit it)";

/// The lift factor's uncertainty past which the bands are taken not to
/// determine it: at one standard deviation they could not tell half the
/// model's lift from one and a half, and a fit there follows the few rows'
/// scatter (a month of 16 rows fitted 0.03 ± 0.64), which `--save` would
/// write as a preset's lift.
const UNDETERMINED_LIFT: f64 = 0.5;

/// The distance errors (m) in each band, before and after the fit.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Bands {
    pub lower_edges: [f64; 6],
    pub before: [Errors; 6],
    pub after: [Errors; 6],
    /// χ² per degree of freedom at the fit (the bands with rows, less two).
    pub misfit: f64,
}

/// The band of a launch angle (rad), if it is one of the balls in the air.
/// To a millionth of a degree: an export's whole degrees come back from
/// radians an ulp off (30° as 29.999…).
pub fn band_of(angle: f64) -> Option<usize> {
    let degrees = (angle.to_degrees() * 1e6).round() / 1e6;
    BAND_EDGES.iter().rposition(|&edge| degrees >= edge)
}

/// Each band's distance errors at factors (k_D, k_L).
fn by_band(rows: &[Measured], k: (f64, f64), options: &FlightOptions) -> [Errors; 6] {
    let flown: Vec<Option<(usize, f64)>> = rows
        .par_iter()
        .map(|row| {
            let band = band_of(row.scene.launch.angle?)?;
            Some((band, flown(row, k, options)?.range - row.distance))
        })
        .collect();
    std::array::from_fn(|band| {
        let errors: Vec<f64> = (flown.iter().flatten())
            .filter(|(b, _)| *b == band)
            .map(|(_, e)| *e)
            .collect();
        Errors::of(&errors)
    })
}

/// The weighted residuals median_b / σ_b of the bands weighed (those with
/// rows).
fn residuals(bands: &[Errors; 6], weights: &[f64; 6]) -> Vec<f64> {
    (bands.iter().zip(weights))
        .filter(|(_, w)| **w > 0.0)
        .map(|(b, w)| b.median * w)
        .collect()
}

/// Fits both factors to the bands, from `drag_only` (the drag fitted
/// alone, whose distance errors it keeps as "before").
pub(super) fn fit(
    rows: &[Measured],
    options: &FlightOptions,
    drag_only: Fit,
) -> Result<Fit, FitError> {
    let mut trials = drag_only.trials;
    let mut at = |k: (f64, f64)| {
        trials += 1;
        by_band(rows, k, options)
    };
    let before = at((1.0, 1.0));
    // The weights are the bands' standard errors where the drag alone
    // fits, held through the iteration so that χ² is one function.
    let start = at((drag_only.drag_scale.value, 1.0));
    let weights: [f64; 6] = std::array::from_fn(|b| match start[b].standard_error() {
        se if se > 0.0 => 1.0 / se,
        _ => 0.0,
    });
    // Two factors need three bands at least, one left to judge the fit.
    if weights.iter().filter(|w| **w > 0.0).count() < 3 {
        return Ok(Fit {
            why_no_lift: Some(FEW_BANDS),
            ..drag_only
        });
    }
    let chi2 = |k: (f64, f64), at: &mut dyn FnMut((f64, f64)) -> [Errors; 6]| {
        residuals(&at(k), &weights)
            .iter()
            .map(|r| r * r)
            .sum::<f64>()
    };
    // Nelder–Mead, not Newton's method: a median moves in steps as rows
    // cross it, so slopes by differences are noise at small steps (the
    // same file five times over gave another answer).
    let within = |p: &Point<2>| {
        (DRAG_RANGE.0..=DRAG_RANGE.1).contains(&p[0])
            && (LIFT_RANGE.0..=LIFT_RANGE.1).contains(&p[1])
    };
    let mut cost = |p: &Point<2>| match within(p) {
        true => chi2((p[0], p[1]), &mut at),
        false => f64::INFINITY,
    };
    // To 1e-3 in each factor, a twentieth of what the bands determine,
    // and 0.1 in χ² (its misfit is tens to hundreds a band).
    let settings = Settings {
        tolerance_x: 1e-3,
        tolerance_cost: 0.1,
        max_restarts: 1,
        initial_size: 0.03,
    };
    let start = Point::<2>::new(drag_only.drag_scale.value, 1.0);
    let mut search = NelderMead::<2, 3>::new(start, settings, &mut cost);
    for _ in 0..200 {
        if search.step(&mut cost) == Status::Converged {
            break;
        }
    }
    let best = search.best().point;
    let k = (best[0], best[1]);
    // The slopes by central differences over 1 %, wide enough to average
    // over the medians' steps.
    let h = 0.01;
    let slope = |dk: (f64, f64), at: &mut dyn FnMut((f64, f64)) -> [Errors; 6]| {
        let up = residuals(&at((k.0 + dk.0, k.1 + dk.1)), &weights);
        let down = residuals(&at((k.0 - dk.0, k.1 - dk.1)), &weights);
        (up.iter().zip(&down))
            .map(|(u, d)| (u - d) / (2.0 * h))
            .collect::<Vec<f64>>()
    };
    let (by_drag, by_lift) = (slope((h, 0.0), &mut at), slope((0.0, h), &mut at));
    let jacobian: Vec<[f64; 2]> = by_drag
        .iter()
        .zip(&by_lift)
        .map(|(d, l)| [*d, *l])
        .collect();
    let after = at(k);
    let here = residuals(&after, &weights);
    let degrees_of_freedom = here.len().saturating_sub(2).max(1);
    let misfit = here.iter().map(|r| r * r).sum::<f64>() / degrees_of_freedom as f64;
    // The covariance (JᵀJ)⁻¹, scaled by the misfit where it exceeds 1.
    let (a, b, c) = normal(&jacobian);
    let det = a * c - b * b;
    let scale = misfit.max(1.0);
    let (drag_variance, lift_variance) = (scale * c / det, scale * a / det);
    if !(det > 0.0 && drag_variance.is_finite() && lift_variance.is_finite()) {
        return Ok(Fit {
            why_no_lift: Some(FEW_BANDS),
            ..drag_only
        });
    }
    if lift_variance.sqrt() > UNDETERMINED_LIFT {
        return Ok(Fit {
            why_no_lift: Some(UNDETERMINED),
            ..drag_only
        });
    }
    let distance_errors = super::errors(rows, k, None, options).0;
    Ok(Fit {
        drag_scale: Estimate {
            value: k.0,
            uncertainty: drag_variance.sqrt(),
        },
        lift_scale: Some(Estimate {
            value: k.1,
            uncertainty: lift_variance.sqrt(),
        }),
        lift_from: Some(LiftFrom::Bands),
        correlation: Some(-b / (a * c).sqrt()),
        bands: Some(Bands {
            lower_edges: BAND_EDGES,
            before,
            after,
            misfit,
        }),
        before: drag_only.before,
        after: Errors::of(&distance_errors),
        second_before: None,
        second_after: None,
        why_no_lift: None,
        trials: trials + 1,
    })
}

/// JᵀJ of a two-column Jacobian: (a, b, c) for [[a, b], [b, c]].
fn normal(jacobian: &[[f64; 2]]) -> (f64, f64, f64) {
    jacobian.iter().fold((0.0, 0.0, 0.0), |(a, b, c), j| {
        (a + j[0] * j[0], b + j[0] * j[1], c + j[1] * j[1])
    })
}
