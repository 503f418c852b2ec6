//! The model's ceiling for a tracked row, and `calibrate --impact`'s fit
//! of the bat's effective mass to it.

use super::{TrackedSwing, collision_efficiency};
use model::impact::Impact3d;
use model::scene::Scene;

/// The `quantile` (0 to 1) of `values` (not empty) by the nearest rank.
pub fn quantile(values: &[f64], quantile: f64) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    sorted[(quantile * (sorted.len() - 1) as f64).round() as usize]
}

/// The most the scene's bat gives this row's pitch, as a collision
/// efficiency: the bat meeting the ball centred (E = 0) and head-on, its
/// velocity straight against the pitch's (ψ = γ, the bat's direction
/// against the pitch's path), at the row's bat speed, with the row's pitch
/// spin and the scene's bodies.
pub fn ceiling_efficiency(base: &Scene, swing: &TrackedSwing) -> f64 {
    let mut scene = *base;
    scene.pitch.spin = swing.pitch_spin.unwrap_or(base.pitch.spin);
    scene.bat.speed = swing.bat_speed;
    scene.bat.hand = swing.hand;
    scene.bat.tilt = 0.0;
    scene.bat.undercut = 0.0;
    scene.bat.swing_angle = swing.pitch.descent_angle();
    scene.bat.direction = -swing.pitch.lateral_angle();
    let exit = Impact3d::with_pitch(&scene, swing.pitch.velocity).launch_speed();
    collision_efficiency(exit, swing.pitch.speed(), swing.bat_speed)
}

/// `calibrate --impact`'s fit: the bat's effective mass M_B for which a
/// row's q exceeds its own ceiling ([`ceiling_efficiency`]: its pitch, its
/// bat speed, Eq. 19's e* at its approach) on only 1 − `quantile` of the
/// rows, so that the model's ceiling is the measured one row by row.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ImpactFit {
    pub rows: usize,
    pub quantile: f64,
    /// The data's q at the quantile.
    pub data: f64,
    /// The scene's M_B (kg), the model's ceiling at the quantile with it,
    /// and the share of rows above their ceiling.
    pub effective_mass_before: f64,
    pub ceiling_before: f64,
    pub above_before: f64,
    /// The fitted M_B (kg), and the same with it.
    pub effective_mass: f64,
    pub ceiling_after: f64,
    pub above_after: f64,
    /// The same, row by row, in five groups of rows by approach speed.
    pub by_approach: [ApproachBand; APPROACH_BANDS],
}

/// How many groups of rows by approach speed [`ImpactFit`] compares.
pub const APPROACH_BANDS: usize = 5;

/// One group of rows by approach speed, V_pitch + V_bat at the plate:
/// Eq. (19)'s e*, so the model's ceiling, falls as it rises. Within a group
/// the ceiling is nearly one number, so its median against the data's q at
/// the quantile says whether the model's ceiling is the measured one at
/// that speed; over all rows the two quantiles mix different speeds
/// (docs/bat-tracking.md).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct ApproachBand {
    /// The group's approach speeds (m/s), from its slowest row to its
    /// fastest, and its rows.
    pub slowest: f64,
    pub fastest: f64,
    pub rows: usize,
    /// The data's q at the quantile, in the group.
    pub data: f64,
    /// The median ceiling in the group with the scene's M_B and with the
    /// fitted one, and the group's share of rows above their fitted
    /// ceiling.
    pub ceiling_before: f64,
    pub ceiling_after: f64,
    pub above_after: f64,
}

/// The rows' approach speeds cut into [`APPROACH_BANDS`] groups of as many
/// rows (the last takes the remainder), each compared as [`ApproachBand`]
/// says.
fn by_approach(
    swings: &[TrackedSwing],
    (data, before, after): (&[f64], &[f64], &[f64]),
    at: f64,
) -> [ApproachBand; APPROACH_BANDS] {
    let approach = |k: usize| swings[k].pitch.speed() + swings[k].bat_speed;
    let mut order: Vec<usize> = (0..swings.len()).collect();
    order.sort_by(|&a, &b| approach(a).total_cmp(&approach(b)));
    let mut bands = [ApproachBand::default(); APPROACH_BANDS];
    let size = swings.len() / APPROACH_BANDS;
    for (band, slot) in bands.iter_mut().enumerate() {
        let end = if band + 1 == APPROACH_BANDS {
            swings.len()
        } else {
            (band + 1) * size
        };
        let rows = &order[band * size..end];
        if rows.is_empty() {
            continue;
        }
        let pick = |values: &[f64]| rows.iter().map(|&k| values[k]).collect::<Vec<_>>();
        let above = rows.iter().filter(|&&k| data[k] > after[k]).count();
        *slot = ApproachBand {
            slowest: approach(rows[0]),
            fastest: approach(rows[rows.len() - 1]),
            rows: rows.len(),
            data: quantile(&pick(data), at),
            ceiling_before: quantile(&pick(before), 0.5),
            ceiling_after: quantile(&pick(after), 0.5),
            above_after: above as f64 / rows.len() as f64,
        };
    }
    bands
}

/// The range of M_B searched (kg).
pub const EFFECTIVE_MASSES: (f64, f64) = (0.2, 5.0);

/// Fits M_B by bisection (each ceiling rises with M_B: a heavier bat gives
/// back more of the ball's momentum); `None` without rows.
pub fn fit_effective_mass(base: &Scene, swings: &[TrackedSwing], at: f64) -> Option<ImpactFit> {
    if swings.is_empty() {
        return None;
    }
    let data: Vec<f64> = swings
        .iter()
        .map(|s| collision_efficiency(s.launch_speed, s.pitch.speed(), s.bat_speed))
        .collect();
    let ceilings = |mass: f64| -> Vec<f64> {
        let mut scene = *base;
        scene.bat.effective_mass = mass;
        swings
            .iter()
            .map(|s| ceiling_efficiency(&scene, s))
            .collect()
    };
    let excess =
        |ceilings: &[f64]| -> Vec<f64> { data.iter().zip(ceilings).map(|(q, c)| q - c).collect() };
    let above = |ceilings: &[f64]| {
        let above = data.iter().zip(ceilings).filter(|(q, c)| q > c).count();
        above as f64 / data.len() as f64
    };
    let (mut low, mut high) = EFFECTIVE_MASSES;
    for _ in 0..50 {
        let middle = 0.5 * (low + high);
        if quantile(&excess(&ceilings(middle)), at) > 0.0 {
            low = middle;
        } else {
            high = middle;
        }
    }
    let effective_mass = 0.5 * (low + high);
    let (before, after) = (ceilings(base.bat.effective_mass), ceilings(effective_mass));
    Some(ImpactFit {
        rows: swings.len(),
        quantile: at,
        data: quantile(&data, at),
        effective_mass_before: base.bat.effective_mass,
        ceiling_before: quantile(&before, at),
        above_before: above(&before),
        effective_mass,
        ceiling_after: quantile(&after, at),
        above_after: above(&after),
        by_approach: by_approach(swings, (&data, &before, &after), at),
    })
}
