//! The work–precision diagram of `homerun bench` as SVG: the range error of
//! one trajectory against the time it takes, both on log scales, one line
//! per method and setting (dopri5 with and without stopping at the drag
//! kinks, with an absolute tolerance equal to or ten times the relative
//! one; rk4 with and without kinks), each point one tolerance or step.

use plotters::prelude::*;

use super::{
    FONT, PictureError, draw_legend, draw_named_line, draw_title, drawn, house_style, series_color,
};
use analysis::bench::TrajectoryRow;

/// The smallest error drawn (m): a row that hit the reference exactly is
/// drawn here, at the floor of the axis, rather than lost off a log scale.
pub const ERROR_FLOOR: f64 = 1e-13;

/// The line a row belongs to.
pub fn setting(row: &TrajectoryRow) -> String {
    let kinks = if row.stop_at_kinks {
        ", stopping at kinks"
    } else {
        ""
    };
    match (row.tolerance, row.absolute) {
        (Some(rtol), Some(atol)) if (atol / rtol - 1.0).abs() > 1e-9 => {
            format!(
                "{}, atol = {} rtol{kinks}",
                row.method,
                (atol / rtol).round()
            )
        }
        (Some(_), _) => format!("{}, atol = rtol{kinks}", row.method),
        _ => format!("{}, fixed step{kinks}", row.method),
    }
}

/// One line per setting, in the order the rows first show it: its name and
/// its (time µs, |error| m) points, fastest first.
pub fn bench_lines(rows: &[TrajectoryRow], cpu: bool) -> Vec<(String, Vec<(f64, f64)>)> {
    let mut lines: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for row in rows {
        let time = if cpu {
            row.cpu_us.unwrap_or(row.time_us)
        } else {
            row.time_us
        };
        let point = (time.max(1e-3), row.range_error.abs().max(ERROR_FLOOR));
        let name = setting(row);
        match lines.iter_mut().find(|(n, _)| *n == name) {
            Some((_, points)) => points.push(point),
            None => lines.push((name, vec![point])),
        }
    }
    for (_, points) in &mut lines {
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    lines
}

/// The trajectory rows of a bench report as a log–log work–precision diagram.
pub fn bench_svg(rows: &[TrajectoryRow]) -> Result<String, PictureError> {
    // CPU time where every row has it: on a shared machine the wall clock
    // counts the wait for a core.
    let cpu = !rows.is_empty() && rows.iter().all(|r| r.cpu_us.is_some());
    let lines = bench_lines(rows, cpu);
    let points = || lines.iter().flat_map(|(_, p)| p.iter());
    let decade_span = |values: Vec<f64>| {
        let low = values.iter().copied().fold(f64::INFINITY, f64::min);
        let high = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if low > high {
            (1.0, 10.0)
        } else {
            (
                10f64.powf(low.log10().floor()),
                10f64.powf(high.log10().ceil().max(low.log10().floor() + 1.0)),
            )
        }
    };
    let (t0, t1) = decade_span(points().map(|p| p.0).collect());
    let (e0, e1) = decade_span(points().map(|p| p.1).collect());
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (960, 640)).into_drawing_area();
        root.fill(&WHITE).map_err(drawn)?;
        let (top, body) = root.split_vertically(52);
        draw_title(
            &top,
            "Work–precision: one trajectory (the Table II fastball's launch)",
            (12, 8),
            17,
        )?;
        top.draw(&Text::new(
            format!(
                "range error against Purpose::Reference; each point one tolerance or step; errors below {ERROR_FLOOR:.0e} m drawn at {ERROR_FLOOR:.0e} m"
            ),
            (12, 30),
            (FONT, 12).into_font().color(&RGBColor(90, 90, 90)),
        ))
        .map_err(drawn)?;
        let mut chart = ChartBuilder::on(&body)
            .margin(12)
            .margin_right(24)
            .x_label_area_size(44)
            .y_label_area_size(72)
            .build_cartesian_2d((t0..t1).log_scale(), (e0..e1).log_scale())
            .map_err(drawn)?;
        let label = |v: &f64| format!("{v:.0e}");
        house_style(
            chart
                .configure_mesh()
                .x_desc(if cpu {
                    "CPU time per trajectory (µs)"
                } else {
                    "wall time per trajectory (µs)"
                })
                .y_desc("|range error| (m)")
                .x_label_formatter(&label)
                .y_label_formatter(&label),
        )
        .draw()
        .map_err(drawn)?;
        for (k, (name, points)) in lines.iter().enumerate() {
            let color = series_color(k);
            draw_named_line(&mut chart, k, name, points)?;
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))
                .map_err(drawn)?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperRight)?;
        root.present().map_err(drawn)?;
    }
    Ok(svg)
}
