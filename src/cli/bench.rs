//! `homerun bench`: the work–precision report (measured by
//! `analysis::bench`) as text tables, or as JSON.

use crate::analysis::bench::{self, Report};

fn or_dash(value: Option<f64>, format: impl Fn(f64) -> String) -> String {
    value.map_or("-".to_string(), format)
}

/// The report as text tables.
fn render(report: &Report) -> String {
    use std::fmt::Write;
    let mut out = String::new();
    let r = &report.reference;
    let _ = writeln!(
        out,
        "reference (Purpose::Reference, Table II fastball): range {:.6} m; reference/model.py {:.6} m; difference {:+.1e} m",
        r.range, r.python_range, r.difference
    );
    let _ = writeln!(out, "\none trajectory (Table II fastball launch)");
    let _ = writeln!(
        out,
        "{:<7} {:>9} {:>8} {:>6} {:>13} {:>11} {:>8} {:>8} {:>9} {:>8} {:>11}",
        "method",
        "tolerance",
        "absolute",
        "step",
        "stop_at_kinks",
        "evaluations",
        "accepted",
        "rejected",
        "time_us",
        "cpu_us",
        "range_error"
    );
    for row in &report.trajectory {
        let _ = writeln!(
            out,
            "{:<7} {:>9} {:>8} {:>6} {:>13} {:>11} {:>8} {:>8} {:>9.2} {:>8} {:>11.2e}",
            row.method,
            or_dash(row.tolerance, |t| format!("{t:.0e}")),
            or_dash(row.absolute, |t| format!("{t:.0e}")),
            or_dash(row.step, |h| format!("{h}")),
            row.stop_at_kinks,
            row.evaluations,
            row.accepted,
            row.rejected,
            row.time_us,
            or_dash(row.cpu_us, |c| format!("{c:.2}")),
            row.range_error
        );
    }
    let _ = writeln!(
        out,
        "\none trajectory per aero model (Table II fastball launch, dopri5 stopping at kinks; errors against Purpose::Reference for the same models)\n{:<11} {:<11} {:>10} {:>9} {:>8} {:>11} {:>8} {:>9} {:>8} {:>11}",
        "drag",
        "lift",
        "spin_decay",
        "tolerance",
        "absolute",
        "evaluations",
        "rejected",
        "time_us",
        "cpu_us",
        "range_error"
    );
    for r in &report.aero {
        let _ = writeln!(
            out,
            "{:<11} {:<11} {:>10} {:>9.0e} {:>8.0e} {:>11} {:>8} {:>9.2} {:>8} {:>11.2e}",
            r.drag,
            r.lift,
            r.spin_decay,
            r.tolerance,
            r.absolute,
            r.evaluations,
            r.rejected,
            r.time_us,
            or_dash(r.cpu_us, |c| format!("{c:.2}")),
            r.range_error
        );
    }
    let _ = writeln!(
        out,
        "\nthe fly ball in the plane and in 3-D (103 mph, 28°, 2500 rpm, Nathan's aero; dopri5; errors against Purpose::Reference for the same flight)\n{:<24} {:>9} {:>8} {:>11} {:>8} {:>9} {:>8} {:>11} {:>15}",
        "flight",
        "tolerance",
        "absolute",
        "evaluations",
        "rejected",
        "time_us",
        "cpu_us",
        "range_error",
        "direction_error"
    );
    for r in &report.spatial {
        let _ = writeln!(
            out,
            "{:<24} {:>9.0e} {:>8.0e} {:>11} {:>8} {:>9.2} {:>8} {:>11.2e} {:>15.2e}",
            r.flight,
            r.tolerance,
            r.absolute,
            r.evaluations,
            r.rejected,
            r.time_us,
            or_dash(r.cpu_us, |c| format!("{c:.2}")),
            r.range_error,
            r.direction_error
        );
    }
    let _ = writeln!(
        out,
        "\na home run judged at the parks (102 mph, 28°, Nathan's spin for a right-handed batter, landing 15° toward left field; readout precision)\n{:<28} {:>7} {:>9} {:>8}",
        "work", "flights", "time_us", "cpu_us"
    );
    for r in &report.parks {
        let _ = writeln!(
            out,
            "{:<28} {:>7} {:>9.2} {:>8}",
            r.work,
            r.flights,
            r.time_us,
            or_dash(r.cpu_us, |c| format!("{c:.2}"))
        );
    }
    impact_table(&mut out, report);
    let _ = writeln!(
        out,
        "\none optimisation per Table II pitch (errors against optimiser 1e-9, integrator 1e-12)"
    );
    let _ = writeln!(
        out,
        "{:<12} {:>19} {:>20} {:>11} {:>9} {:>7} {:>6} {:>14} {:>17} {:>11}",
        "pitch",
        "optimizer_tolerance",
        "integrator_tolerance",
        "evaluations",
        "converged",
        "time_ms",
        "cpu_ms",
        "undercut_error",
        "swing_angle_error",
        "range_error"
    );
    for row in &report.optimisation {
        let _ = writeln!(
            out,
            "{:<12} {:>19.0e} {:>20.0e} {:>11} {:>9} {:>7.2} {:>6} {:>14.1e} {:>17.1e} {:>11.1e}",
            row.pitch,
            row.optimizer_tolerance,
            row.integrator_tolerance,
            row.evaluations,
            row.converged,
            row.time_ms,
            or_dash(row.cpu_ms, |c| format!("{c:.2}")),
            row.undercut_error,
            row.swing_angle_error,
            row.range_error
        );
    }
    let _ = writeln!(
        out,
        "\none range surface over Fig. 7's window (errors against Purpose::Reference)"
    );
    let _ = writeln!(
        out,
        "{:>6} {:>20} {:>8} {:>7} {:>8} {:>8} {:>14}",
        "cells",
        "integrator_tolerance",
        "absolute",
        "threads",
        "time_ms",
        "cpu_ms",
        "max_cell_error"
    );
    for row in &report.surface {
        let _ = writeln!(
            out,
            "{:>6} {:>20.0e} {:>8.0e} {:>7} {:>8.1} {:>8} {:>14.2e}",
            row.cells,
            row.integrator_tolerance,
            row.absolute,
            row.threads,
            row.time_ms,
            or_dash(row.cpu_ms, |c| format!("{c:.1}")),
            row.max_cell_error
        );
    }
    let _ = writeln!(
        out,
        "\nthe explorer's background work for the Table II fastball (one thread; figures as `homerun figure N` computes them)"
    );
    let _ = writeln!(
        out,
        "{:<27} {:>8} {:>8}  detail",
        "work", "time_ms", "cpu_ms"
    );
    for row in &report.explorer {
        let _ = writeln!(
            out,
            "{:<27} {:>8.2} {:>8}  {}",
            row.work,
            row.time_ms,
            or_dash(row.cpu_ms, |c| format!("{c:.2}")),
            row.detail
        );
    }
    let _ = writeln!(
        out,
        "\ndefaults (crates/analysis/src/precision.rs), range error on the Table II fastball"
    );
    let _ = writeln!(
        out,
        "{:<10} {:>12} {:>9} {:>11}",
        "purpose", "range_budget", "tolerance", "range_error"
    );
    for row in &report.defaults {
        let _ = writeln!(
            out,
            "{:<10} {:>12.1e} {:>9.0e} {:>11.1e}",
            row.purpose, row.range_budget, row.tolerance, row.range_error
        );
    }
    let _ = writeln!(
        out,
        "\nfly --batch: batted balls flown as its rows are (readout precision, to the fence and the ground)\n{:>6} {:>7} {:>8} {:>8} {:>11}",
        "rows", "threads", "time_ms", "cpu_ms", "rows_per_s"
    );
    for row in &report.batch {
        let _ = writeln!(
            out,
            "{:>6} {:>7} {:>8.1} {:>8} {:>11.0}",
            row.rows,
            row.threads,
            row.time_ms,
            or_dash(row.cpu_ms, |c| format!("{c:.1}")),
            row.rows_per_second
        );
    }
    render_floor(&mut out, &report.floor);
    let _ = writeln!(
        out,
        "\n(all cores = {} threads; time = median wall clock, cpu = median CPU time summed over threads; \
         on a machine shared with other work, the wall clock counts waiting for a core)",
        report.threads
    );
    out
}

/// The floor table: each workload's evaluations times one evaluation's
/// cost, beside its measured time.
fn render_floor(out: &mut String, floor: &bench::FloorReport) {
    use std::fmt::Write;
    let _ = writeln!(
        out,
        "\none right-hand-side evaluation (ns): in a dependent chain, and with independent ones interleaved\n{:<7} {:<7} {:>9} {:>15}",
        "aero", "flight", "chain_ns", "interleaved_ns"
    );
    for c in &floor.evaluation {
        let _ = writeln!(
            out,
            "{:<7} {:<7} {:>9.2} {:>15.2}",
            c.aero, c.flight, c.chain_ns, c.interleaved_ns
        );
    }
    let _ = writeln!(
        out,
        "\nthe floor: evaluations x one evaluation's cost (the chain's for one flight, interleaved for many), on one core\n{:<50} {:<18} {:>7} {:>11} {:>7} {:>10} {:>7} {:>10} {:>10} {:>10}",
        "workload",
        "setting",
        "flights",
        "evaluations",
        "eval_ns",
        "floor_us",
        "threads",
        "time_us",
        "cpu_us",
        "over_floor"
    );
    for r in &floor.workloads {
        let _ = writeln!(
            out,
            "{:<50} {:<18} {:>7} {:>11} {:>7.2} {:>10.2} {:>7} {:>10.2} {:>10} {:>10.1}",
            r.workload,
            r.setting,
            r.flights,
            r.evaluations,
            r.evaluation_ns,
            r.floor_us,
            r.threads,
            r.time_us,
            or_dash(r.cpu_us, |c| format!("{c:.2}")),
            r.over_floor
        );
    }
}

/// The 3-D swing's table: an impact each way, and `optimize --park`.
fn impact_table(out: &mut String, report: &Report) {
    use std::fmt::Write;
    let _ = writeln!(
        out,
        "\nthe 3-D impact (the fastball's swing; each on its own) and the park search (barrel 30° below the hands, in the park's air)\n{:<38} {:>7} {:>11} {:>10}  detail",
        "work", "flights", "time_us", "cpu_us"
    );
    for r in &report.impact {
        let _ = writeln!(
            out,
            "{:<38} {:>7} {:>11.2} {:>10}  {}",
            r.work,
            r.flights,
            r.time_us,
            or_dash(r.cpu_us, |c| format!("{c:.2}")),
            r.detail
        );
    }
}

/// `homerun bench [--json] [--quick] [--svg FILE]`: with `svg`, the
/// work–precision diagram of the trajectory rows.
pub fn output(json: bool, quick: bool, svg: bool) -> Result<String, super::UsageError> {
    let report = bench::run(quick);
    Ok(if svg {
        crate::picture::bench_svg(&report.trajectory)?
    } else if json {
        serde_json::to_string_pretty(&report).expect("plain numbers") + "\n"
    } else {
        render(&report)
    })
}
