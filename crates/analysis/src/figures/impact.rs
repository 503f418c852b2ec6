//! Figs. 5 and 6: the impact alone, against the undercut, for three μ.

use super::{
    Cell, Column, FigureData, MARK, bisect, column, columns, compare, impact_with, mark_cell,
    undercut_for_spin, with_marks,
};
use crate::paper::{self, FIGURE5_FRICTIONS as FRICTIONS};
use crate::study;
use model::impact::Regime;
use model::scene::Scene;

/// Figs. 5 (ω_bf) and 6 (ζ) against E for μ = 0.05, 0.35, 0.5, with the
/// cusp where slip halts exactly at separation.
pub(super) fn impact_figure(number: u32, scene: &Scene) -> FigureData {
    let spin = number == 5;
    let top = 0.07_f64.min(scene.reach() * (1.0 - 1e-9));
    let cusp = |friction: f64| {
        bisect(0.0, top, |e| {
            impact_with(scene, e, friction).regime() == Regime::Stick
        })
    };
    let cusps: Vec<Option<f64>> = FRICTIONS.iter().map(|&mu| cusp(mu)).collect();
    let mut marks: Vec<(f64, String)> = FRICTIONS
        .iter()
        .zip(&cusps)
        .filter_map(|(mu, c)| c.map(|e| (e, format!("cusp μ = {mu}: slip halts at separation"))))
        .collect();
    // Fig. 5: 1000 rad/s on the rising side (below the cusp, where spin peaks).
    let thousand =
        cusps[2].and_then(|c| undercut_for_spin(scene, c, 0.5, paper::THOUSAND_SPIN, 0.1));
    if spin {
        marks.extend(thousand.map(|e| (e, "1000 rad/s at μ = 0.5".to_owned())));
    } else {
        marks.push((paper::ZETA_UNDERCUT, "E = 0.040 m (paper's ζ)".to_owned()));
    }
    let grid = with_marks(study::linspace(0.0, top, 29), marks);
    let undercuts: Vec<f64> = grid.iter().map(|g| g.0).collect();
    let curves = study::impact_curves(scene, &FRICTIONS, &undercuts);
    let value = |p: &study::ImpactPoint| {
        if spin { p.launch_spin } else { p.launch_angle }
    };
    let rows = grid
        .iter()
        .enumerate()
        .map(|(k, (e, mark))| {
            let mut row = vec![Cell::Num(*e)];
            row.extend(curves.iter().map(|c| Cell::Num(value(&c.points[k]))));
            row.push(mark_cell(mark));
            row
        })
        .collect();
    let (what, key, decimals) = if spin {
        ("ω_bf (rad/s)", "launch_spin", 1)
    } else {
        ("ζ (rad)", "launch_angle", 4)
    };
    let mut table = vec![column("undercut", "E (m)", 5)];
    table.extend(FRICTIONS.iter().map(|mu| Column {
        key: format!("{key}_mu_{mu}"),
        head: format!("{what} μ={mu}"),
        decimals,
    }));
    table.extend(columns(&[MARK]));
    let mut comparisons = Vec::new();
    let mut notes = Vec::new();
    if let Some(c) = cusps[1] {
        let stated = if spin {
            paper::SLIP_HALTS
        } else {
            paper::SAME_ZETA
        };
        comparisons.push(compare(stated, c));
    }
    if spin {
        if let Some(e) = thousand {
            comparisons.push(compare(paper::THOUSAND_SPIN_UNDERCUT, e));
        }
        notes.push(
            "The paper prints the μ = 0.35 threshold as \"E = 0.64\", a misprint for \"0.064 m\"."
                .to_owned(),
        );
    } else {
        let zeta = |mu| impact_with(scene, paper::ZETA_UNDERCUT, mu).launch_angle();
        let (realistic, slippery) = (zeta(0.5), zeta(0.05));
        comparisons.push(compare(paper::ZETA_REALISTIC, realistic));
        comparisons.push(compare(paper::ZETA_SLIPPERY, slippery));
        comparisons.push(compare(
            paper::ZETA_DIFFERENCE,
            (slippery - realistic).to_degrees(),
        ));
    }
    for (mu, c) in FRICTIONS.iter().zip(&cusps) {
        if c.is_none() {
            let regime = impact_with(scene, 0.0, *mu).regime();
            notes.push(format!(
                "μ = {mu}: no cusp below E = {top:.4} m ({} throughout)",
                if regime == Regime::Stick {
                    "slip halts"
                } else {
                    "slips"
                }
            ));
        }
    }
    let title = if spin {
        "batted spin ω_bf (rad/s, backspin positive) against undercut E (m), impact only, for μ = 0.05, 0.35, 0.5"
    } else {
        "launch angle ζ (rad) against undercut E (m), impact only, for μ = 0.05, 0.35, 0.5"
    };
    FigureData {
        comparisons,
        notes,
        ..FigureData::new(number, title.to_owned(), table, rows)
    }
}
