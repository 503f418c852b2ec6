//! Figs. 13 and 14: the range against E at a fixed ψ, and C_D along the
//! flights of its points A and B.

use super::{
    Cell, FigureData, LANDED, LAUNCH, MARK, columns, compare, flight_row, trimmed,
    undercut_for_spin, with_marks,
};
use crate::landing;
use crate::paper::{self, POINT_A_SPIN, POINT_B_SPIN};
use crate::precision::Purpose;
use crate::study;
use model::scene::Scene;

/// Fig. 13's A and B: the undercuts, at the scene's ψ, that give the batted
/// spins the paper states; `None` where the spin is out of reach.
fn points_a_b(scene: &Scene) -> [Option<f64>; 2] {
    let top = 0.06_f64.min(scene.reach() * (1.0 - 1e-9));
    [POINT_A_SPIN, POINT_B_SPIN]
        .map(|spin| undercut_for_spin(scene, top, scene.bat.friction, spin, 0.01))
}

/// Fig. 13: the range against E at the scene's ψ, with A, B and the highest.
pub(super) fn figure13(scene: &Scene) -> FigureData {
    let [a, b] = points_a_b(scene);
    let mut marks = Vec::new();
    marks.extend(a.map(|e| (e, format!("A ({POINT_A_SPIN} rad/s)"))));
    marks.extend(b.map(|e| (e, format!("B ({POINT_B_SPIN} rad/s)"))));
    let grid = with_marks(
        study::linspace(0.0, 0.05_f64.min(scene.reach() * 0.99), 26),
        marks,
    );
    let undercuts: Vec<f64> = grid.iter().map(|g| g.0).collect();
    let slice = study::slice(scene, scene.bat.swing_angle, &undercuts, Purpose::Readout);
    let best = slice
        .iter()
        .filter(|p| p.landed)
        .map(|p| p.range)
        .fold(f64::NEG_INFINITY, f64::max);
    let rows = slice
        .iter()
        .zip(&grid)
        .map(|(p, (_, mark))| {
            let extra = if !p.landed {
                "does not land"
            } else if p.range == best {
                "highest"
            } else {
                ""
            };
            let mark = [mark.as_str(), extra]
                .into_iter()
                .filter(|m| !m.is_empty())
                .collect::<Vec<_>>()
                .join("; ");
            let launch = [p.launch_speed, p.launch_spin, p.launch_angle];
            flight_row(
                &[&[p.undercut, p.range][..], &launch].concat(),
                1..2,
                p.landed,
                &mark,
            )
        })
        .collect();
    let mut comparisons = Vec::new();
    let find = |e: f64| slice.iter().find(|p| p.landed && p.undercut == e);
    if let (Some(pa), Some(pb)) = (a.and_then(find), b.and_then(find)) {
        comparisons.extend([
            compare(paper::POINT_A_SPEED, pa.launch_speed),
            compare(paper::POINT_A_ANGLE, pa.launch_angle),
            compare(paper::POINT_B_SPEED, pb.launch_speed),
            compare(paper::POINT_B_ANGLE, pb.launch_angle),
            compare(paper::A_TO_B_UNDERCUT, (pb.undercut - pa.undercut) * 1000.0),
            compare(paper::A_LESS_B_RANGE, pa.range - pb.range),
        ]);
    }
    let title = format!(
        "range (m) against undercut E (m) at ψ = {} rad, with launch; A and B are the E giving ω_bf = {POINT_A_SPIN} rad/s and {POINT_B_SPIN} rad/s",
        trimmed(scene.bat.swing_angle)
    );
    let mut table = columns(&[("undercut", "E (m)", 5), ("range", "range (m)", 2)]);
    table.extend(columns(&LAUNCH));
    table.extend(columns(&[LANDED, MARK]));
    FigureData {
        comparisons,
        ..FigureData::new(13, title, table, rows)
    }
}

/// Fig. 14: C_D against time along the flights of A and B, with the path.
pub(super) fn figure14(scene: &Scene) -> FigureData {
    let mut rows = Vec::new();
    let mut notes = Vec::new();
    for (name, e) in ["A", "B"].into_iter().zip(points_a_b(scene)) {
        let Some(e) = e else {
            notes.push(format!("{name}: no undercut gives its batted spin here"));
            continue;
        };
        let s = scene.with_swing(e, scene.bat.swing_angle);
        let (summary, points) = study::drag_along_flight(&s, 31, Purpose::Plot);
        rows.extend(points.iter().map(|p| {
            let mut row = vec![Cell::Text(name.to_owned())];
            row.extend([p.time, p.drag_coefficient, p.x, p.y].map(Cell::Num));
            row.push(Cell::Bool(summary.landed));
            row
        }));
        // Time at high (subcritical) drag, from a fine sampling.
        let (_, fine) = study::drag_along_flight(&s, 2001, Purpose::Plot);
        let dt = summary.flight_time / 2000.0;
        let high = fine.iter().filter(|p| p.drag_coefficient > 0.45).count() as f64 * dt;
        let flown = match points.last().filter(|_| !summary.landed) {
            Some(end) => landing::not_landed(&summary, end.y),
            None => format!(
                "range {:.2} m in {:.2} s",
                summary.range, summary.flight_time
            ),
        };
        notes.push(format!(
            "{name}: E = {e:.4} m, {flown}, {high:.2} s of it at C_D > 0.45"
        ));
    }
    notes.push(
        "paper: both pass through the drag crisis rising and stay below it descending; B spends longer at high drag."
            .to_owned(),
    );
    let title = format!(
        "drag coefficient C_D against time t (s) along the flights of Fig. 13's A and B (ψ = {} rad), with the path x, y (m)",
        trimmed(scene.bat.swing_angle)
    );
    let table = columns(&[
        ("point", "point", 0),
        ("time", "t (s)", 3),
        ("drag_coefficient", "C_D", 4),
        ("x", "x (m)", 2),
        ("y", "y (m)", 2),
        LANDED,
    ]);
    FigureData {
        notes,
        ..FigureData::new(14, title, table, rows)
    }
}
