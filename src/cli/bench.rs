//! `homerun bench`: the work–precision report (measured by
//! `analysis::bench`) as text tables, or as JSON.

use crate::analysis::bench::{self, Report};

fn or_dash(value: Option<f64>, format: impl Fn(f64) -> String) -> String {
    value.map_or("-".to_string(), format)
}

/// One table: a blank line, its title, its header as printed (lined up
/// with the row's format by hand), then a line per row.
fn table<T>(out: &mut String, title: &str, header: &str, rows: &[T], line: impl Fn(&T) -> String) {
    out.push_str(&format!("\n{title}\n{header}\n"));
    for row in rows {
        out.push_str(&line(row));
        out.push('\n');
    }
}

/// The report as text tables.
fn render(report: &Report) -> String {
    let r = &report.reference;
    let mut out = format!(
        "reference (Purpose::Reference, Table II fastball): range {:.6} m; reference/model.py {:.6} m; difference {:+.1e} m\n",
        r.range, r.python_range, r.difference
    );
    table(
        &mut out,
        "one trajectory (Table II fastball launch)",
        "method  tolerance absolute   step stop_at_kinks evaluations accepted rejected   time_us   cpu_us range_error",
        &report.trajectory,
        |row| {
            format!(
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
            )
        },
    );
    table(
        &mut out,
        "one trajectory per aero model (Table II fastball launch, dopri5 stopping at kinks; errors against Purpose::Reference for the same models)",
        "drag        lift        spin_decay tolerance absolute evaluations rejected   time_us   cpu_us range_error",
        &report.aero,
        |r| {
            format!(
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
            )
        },
    );
    table(
        &mut out,
        "the fly ball in the plane and in 3-D (103 mph, 28°, 2500 rpm, Nathan's aero; dopri5; errors against Purpose::Reference for the same flight)",
        "flight                   tolerance absolute evaluations rejected   time_us   cpu_us range_error direction_error",
        &report.spatial,
        |r| {
            format!(
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
            )
        },
    );
    table(
        &mut out,
        "a home run judged at the parks (102 mph, 28°, Nathan's spin for a right-handed batter, landing 15° toward left field; readout precision)",
        "work                         flights   time_us   cpu_us",
        &report.parks,
        |r| {
            format!(
                "{:<28} {:>7} {:>9.2} {:>8}",
                r.work,
                r.flights,
                r.time_us,
                or_dash(r.cpu_us, |c| format!("{c:.2}"))
            )
        },
    );
    table(
        &mut out,
        "the 3-D impact (the fastball's swing; each on its own) and the park search (barrel 30° below the hands, in the park's air)",
        "work                                   flights     time_us     cpu_us  detail",
        &report.impact,
        |r| {
            format!(
                "{:<38} {:>7} {:>11.2} {:>10}  {}",
                r.work,
                r.flights,
                r.time_us,
                or_dash(r.cpu_us, |c| format!("{c:.2}")),
                r.detail
            )
        },
    );
    table(
        &mut out,
        "one optimisation per Table II pitch (errors against optimiser 1e-9, integrator 1e-12)",
        "pitch        optimizer_tolerance integrator_tolerance evaluations converged time_ms cpu_ms undercut_error swing_angle_error range_error",
        &report.optimisation,
        |row| {
            format!(
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
            )
        },
    );
    table(
        &mut out,
        "one range surface over Fig. 7's window (errors against Purpose::Reference)",
        " cells integrator_tolerance absolute threads  time_ms   cpu_ms max_cell_error",
        &report.surface,
        |row| {
            format!(
                "{:>6} {:>20.0e} {:>8.0e} {:>7} {:>8.1} {:>8} {:>14.2e}",
                row.cells,
                row.integrator_tolerance,
                row.absolute,
                row.threads,
                row.time_ms,
                or_dash(row.cpu_ms, |c| format!("{c:.1}")),
                row.max_cell_error
            )
        },
    );
    table(
        &mut out,
        "the explorer's background work for the Table II fastball (one thread; figures as `homerun figure N` computes them)",
        "work                         time_ms   cpu_ms  detail",
        &report.explorer,
        |row| {
            format!(
                "{:<27} {:>8.2} {:>8}  {}",
                row.work,
                row.time_ms,
                or_dash(row.cpu_ms, |c| format!("{c:.2}")),
                row.detail
            )
        },
    );
    table(
        &mut out,
        "defaults (crates/analysis/src/precision.rs), range error on the Table II fastball",
        "purpose    range_budget tolerance range_error",
        &report.defaults,
        |row| {
            format!(
                "{:<10} {:>12.1e} {:>9.0e} {:>11.1e}",
                row.purpose, row.range_budget, row.tolerance, row.range_error
            )
        },
    );
    table(
        &mut out,
        "fly --batch: batted balls flown as its rows are (readout precision, to the fence and the ground)",
        "  rows threads  time_ms   cpu_ms  rows_per_s",
        &report.batch,
        |row| {
            format!(
                "{:>6} {:>7} {:>8.1} {:>8} {:>11.0}",
                row.rows,
                row.threads,
                row.time_ms,
                or_dash(row.cpu_ms, |c| format!("{c:.1}")),
                row.rows_per_second
            )
        },
    );
    // The floor: each workload's evaluations times one evaluation's cost,
    // beside its measured time.
    table(
        &mut out,
        "one right-hand-side evaluation (ns): in a dependent chain, and with independent ones interleaved",
        "aero    flight   chain_ns  interleaved_ns",
        &report.floor.evaluation,
        |c| {
            format!(
                "{:<7} {:<7} {:>9.2} {:>15.2}",
                c.aero, c.flight, c.chain_ns, c.interleaved_ns
            )
        },
    );
    table(
        &mut out,
        "the floor: evaluations x one evaluation's cost (the chain's for one flight, interleaved for many), on one core",
        "workload                                           setting            flights evaluations eval_ns   floor_us threads    time_us     cpu_us over_floor",
        &report.floor.workloads,
        |r| {
            format!(
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
            )
        },
    );
    out.push_str(&format!(
        "\n(all cores = {} threads; time = median wall clock, cpu = median CPU time summed over threads; \
         on a machine shared with other work, the wall clock counts waiting for a core)\n",
        report.threads
    ));
    out
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
