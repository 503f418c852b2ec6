//! The collision as the paper's Fig. 2 draws it: the contact points'
//! velocities (the slip v1, for a 3-D swing v2 too, and the approach v3)
//! against the normal impulse p, with p_s, p_c and p_f marked.

use plotters::prelude::*;

use super::{
    FONT, MARK, NOW, PictureError, UnitSystem, draw_legend, draw_named_line, draw_title, drawn,
    house_style, padded, tick_label,
};
use units::Quantity;

/// What to draw: curves of a velocity (m/s) against the normal impulse
/// (N·s), and the impulses to mark.
#[derive(Clone, Debug, PartialEq)]
pub struct ImpactPicture {
    /// The preset's name, for the title.
    pub preset: String,
    /// Each curve's name ("v1", "v3") and its points (p, velocity).
    pub curves: Vec<(String, Vec<(f64, f64)>)>,
    /// The impulses marked by a vertical line: ("p_s", 1.66), ("p_c", …).
    pub marks: Vec<(String, f64)>,
    /// The step-through's cursor (an impulse), if one is to be drawn.
    pub cursor: Option<f64>,
}

const WIDTH: u32 = 960;
const HEIGHT: u32 = 600;

/// The collision as SVG, its velocities in `system`'s unit (m/s or mph);
/// impulses stay N·s in both.
pub fn impact_svg_in(picture: &ImpactPicture, system: UnitSystem) -> Result<String, PictureError> {
    let speed = Quantity::Speed.in_system(system);
    let curves: Vec<(&str, Vec<(f64, f64)>)> = picture
        .curves
        .iter()
        .map(|(name, points)| {
            let shown = points.iter().map(|&(p, v)| (p, speed.show(v))).collect();
            (name.as_str(), shown)
        })
        .collect();
    let p_end = picture
        .marks
        .iter()
        .map(|m| m.1)
        .chain(curves.iter().flat_map(|c| c.1.iter().map(|p| p.0)))
        .fold(0.0_f64, f64::max);
    let (p0, p1) = (0.0, p_end * 1.04);
    let (v0, v1) = padded(
        curves
            .iter()
            .flat_map(|c| c.1.iter().map(|p| p.1))
            .chain([0.0]),
        0.06,
    );
    let names: Vec<&str> = curves.iter().map(|c| c.0).collect();
    let title = format!(
        "Impact — preset {}: {} of the contact points against the normal impulse p (the paper's Fig. 2)",
        picture.preset,
        names.join(", ")
    );
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(drawn)?;
        let (top, body) = root.split_vertically(40);
        draw_title(&top, &title, (12, 12), 15)?;
        let mut chart = ChartBuilder::on(&body)
            .margin(12)
            .x_label_area_size(44)
            .y_label_area_size(64)
            .build_cartesian_2d(p0..p1, v0..v1)
            .map_err(drawn)?;
        let (x_label, y_label) = (tick_label(p1 - p0), tick_label(v1 - v0));
        house_style(
            chart
                .configure_mesh()
                .x_desc("normal impulse p (N·s)")
                .y_desc(format!("velocity of the contact points ({})", speed.symbol))
                .x_label_formatter(&x_label)
                .y_label_formatter(&y_label),
        )
        .draw()
        .map_err(drawn)?;
        chart
            .draw_series(LineSeries::new([(p0, 0.0), (p1, 0.0)], BLACK.mix(0.4)))
            .map_err(drawn)?;
        let font = (FONT, 13).into_font();
        for (name, p) in &picture.marks {
            chart
                .draw_series(LineSeries::new([(*p, v0), (*p, v1)], MARK.mix(0.7)))
                .map_err(drawn)?;
            chart
                .draw_series([Text::new(name.clone(), (*p, v1), font.clone())])
                .map_err(drawn)?;
        }
        if let Some(p) = picture.cursor {
            chart
                .draw_series(DashedLineSeries::new(
                    [(p, v0), (p, v1)],
                    6,
                    4,
                    NOW.stroke_width(1),
                ))
                .map_err(drawn)?;
        }
        for (k, (name, points)) in curves.iter().enumerate() {
            draw_named_line(&mut chart, k, name, points)?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::LowerRight)?;
        root.present().map_err(drawn)?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture() -> ImpactPicture {
        ImpactPicture {
            preset: "fastball".into(),
            curves: vec![
                ("v1".into(), vec![(0.0, -2.0), (1.66, 0.0), (12.3, 0.0)]),
                ("v3".into(), vec![(0.0, -70.0), (8.6, 0.0), (12.3, 30.0)]),
            ],
            marks: vec![
                ("p_s".into(), 1.66),
                ("p_c".into(), 8.6),
                ("p_f".into(), 12.3),
            ],
            cursor: Some(8.6),
        }
    }

    #[test]
    fn the_chart_names_its_curves_marks_and_units() {
        let svg = impact_svg_in(&picture(), UnitSystem::Si).unwrap();
        for text in [
            "v1", "v3", "p_s", "p_c", "p_f", "(m/s)", "p (N·s)", "Fig. 2",
        ] {
            assert!(svg.contains(text), "{text}");
        }
        let imperial = impact_svg_in(&picture(), UnitSystem::Imperial).unwrap();
        assert!(imperial.contains("(mph)") && !imperial.contains("m/s"));
    }
}
