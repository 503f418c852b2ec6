//! Figs. 3 and 4: the aerodynamic coefficients.

use super::{FigureData, MARK, columns, compare, marked_row, with_marks};
use crate::Scene;
use crate::analysis::paper;
use crate::analysis::study;
use crate::model::aero::lift_coefficient;

/// Fig. 3: C_D against Re, with the model's kinks and Dryden's point.
pub(super) fn figure3(scene: &Scene) -> FigureData {
    let model = scene.drag;
    let speed_per_re = scene.environment.kinematic_viscosity / (2.0 * scene.ball.radius);
    let mut marks: Vec<(f64, String)> = model
        .kinks()
        .iter()
        .map(|&re| (re, "kink".to_owned()))
        .collect();
    marks.push((
        paper::DRYDEN_RE,
        format!("Dryden's point (paper: C_D = {})", paper::DRYDEN.value),
    ));
    let rows = with_marks(study::linspace(50_000.0, 300_000.0, 26), marks)
        .into_iter()
        .map(|(re, mark)| marked_row(&[re, re * speed_per_re, model.drag_coefficient(re)], &mark))
        .collect();
    let title = format!(
        "drag coefficient C_D against Reynolds number Re = 2|V_r|r_b/ν (model {}: {})",
        model,
        model.description()
    );
    let columns = columns(&[
        ("reynolds", "Re", 0),
        ("air_speed", "|V_r| (m/s)", 2),
        ("drag_coefficient", "C_D", 4),
        MARK,
    ]);
    FigureData {
        comparisons: vec![
            compare(
                paper::CRISIS_FLOOR,
                model.drag_coefficient(paper::CRISIS_FLOOR_RE),
            ),
            compare(paper::DRYDEN, model.drag_coefficient(paper::DRYDEN_RE)),
            compare(paper::DRAG_FALLS, paper::DRAG_FALLS_RE * speed_per_re),
        ],
        notes: vec![
            "The paper gives its fit only as a figure; ours is reconstructed (see DragModel)."
                .to_owned(),
        ],
        ..FigureData::new(3, title, columns, rows)
    }
}

/// Fig. 4: C_L against S, Eq. 29.
pub(super) fn figure4() -> FigureData {
    let rows = with_marks(
        study::linspace(0.0, 1.0, 21),
        vec![(0.1, "kink: 1.5S below, 0.09 + 0.6S above".to_owned())],
    )
    .into_iter()
    .map(|(s, mark)| marked_row(&[s, lift_coefficient(s)], &mark))
    .collect();
    let title =
        "lift coefficient C_L against spin parameter S = r_b|ω|/|V_r| (Eq. 29, the bilinear fit)";
    let columns = columns(&[
        ("spin_parameter", "S", 3),
        ("lift_coefficient", "C_L", 4),
        MARK,
    ]);
    FigureData {
        notes: vec![
            "Eq. 29 is the paper's own formula, so ours is the paper's line; the measured points of Fig. 4 are not reproduced."
                .to_owned(),
        ],
        ..FigureData::new(4, title.to_owned(), columns, rows)
    }
}
