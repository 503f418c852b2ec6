//! Figs. 3 and 4: the aerodynamic coefficients.

use super::{FigureData, MARK, columns, compare, marked_row, with_marks};
use crate::paper;
use crate::study;
use model::aero::{DragCurve, DragModel, LiftCurve, LiftModel};
use model::scene::Scene;

/// Fig. 3: C_D against Re for the scene's drag model, with its kinks and
/// Dryden's point. A spin-dependent C_D (Nathan's) is drawn at the spin the
/// scene's ball leaves the bat with (a batted ball's own, a swing's
/// impact's), the one its flight starts with. The paper's drag crisis is
/// set against the paper's model only.
pub(super) fn figure3(scene: &Scene) -> FigureData {
    let model = scene.drag;
    let spin_rate = scene.batted_ball().spin_vector().norm();
    let drag = |re: f64| model.coefficient_on(model.piece(re), re, spin_rate);
    let speed_per_re = scene.environment.kinematic_viscosity / (2.0 * scene.ball.radius);
    let papers = model == DragModel::Sawicki2003;
    let mut marks: Vec<(f64, String)> = model
        .kinks()
        .iter()
        .map(|&re| (re, "kink".to_owned()))
        .collect();
    if papers {
        marks.push((
            paper::DRYDEN_RE,
            format!("Dryden's point (paper: C_D = {})", paper::DRYDEN.value),
        ));
    }
    let rows = with_marks(study::linspace(50_000.0, 300_000.0, 26), marks)
        .into_iter()
        .map(|(re, mark)| marked_row(&[re, re * speed_per_re, drag(re)], &mark))
        .collect();
    let spin_note = if model == DragModel::Nathan {
        // In rad/s alone (one unit a title): `--units imperial` shows rpm.
        format!(
            ", at the launch spin {spin_rate:.1} rad/s: C_D = {:.3}",
            drag(paper::DRYDEN_RE)
        )
    } else {
        String::new()
    };
    let title = format!(
        "drag coefficient C_D against Reynolds number Re = 2|V_r|r_b/ν (model {}: {}{spin_note})",
        model,
        model.description()
    );
    let columns = columns(&[
        ("reynolds", "Re", 0),
        ("air_speed", "|V_r| (m/s)", 2),
        ("drag_coefficient", "C_D", 4),
        MARK,
    ]);
    let (comparisons, note) = if papers {
        (
            vec![
                compare(paper::CRISIS_FLOOR, drag(paper::CRISIS_FLOOR_RE)),
                compare(paper::DRYDEN, drag(paper::DRYDEN_RE)),
                compare(paper::DRAG_FALLS, paper::DRAG_FALLS_RE * speed_per_re),
            ],
            "The paper draws its drag curve without giving its formula; ours is read off its Fig. 3.",
        )
    } else {
        (
            Vec::new(),
            "Not the paper's drag law, so no drag crisis: set model.drag = \"sawicki2003\" for Fig. 3's.",
        )
    };
    FigureData {
        comparisons,
        notes: vec![note.to_owned()],
        ..FigureData::new(3, title, columns, rows)
    }
}

/// Fig. 4: C_L against S for the scene's lift model (the paper's is Eq. 29).
pub(super) fn figure4(scene: &Scene) -> FigureData {
    let model = scene.lift;
    let marks = if model == LiftModel::Sawicki2003 {
        vec![(0.1, "kink: 1.5S below, 0.09 + 0.6S above".to_owned())]
    } else {
        Vec::new()
    };
    let rows = with_marks(study::linspace(0.0, 1.0, 21), marks)
        .into_iter()
        .map(|(s, mark)| marked_row(&[s, model.coefficient(s)], &mark))
        .collect();
    let title = format!(
        "lift coefficient C_L against spin parameter S = r_b|ω|/|V_r| (model {}: {})",
        model,
        model.description()
    );
    let columns = columns(&[
        ("spin_parameter", "S", 3),
        ("lift_coefficient", "C_L", 4),
        MARK,
    ]);
    let note = if model == LiftModel::Sawicki2003 {
        "Eq. 29 is the paper's own formula, so ours is the paper's line; the measured points of Fig. 4 are not reproduced."
    } else {
        "Not the paper's lift law: set model.lift = \"sawicki2003\" for Eq. 29."
    };
    FigureData {
        notes: vec![note.to_owned()],
        ..FigureData::new(4, title, columns, rows)
    }
}
