//! The summary's table by kind of ball: Savant's `bb_type`, and the home
//! runs by `events`, as docs/accuracy.md tabulates April 2024, for a
//! user's own export. Both columns are only counted: a cell that names no
//! kind leaves the row out of the table, never out of the batch.

use std::fmt::Write as _;

use serde::Serialize;

use crate::cli::shown::Shown;
use crate::units::Quantity;

// The launch angle from which a ball's distance is a flight's, as
// `calibrate` takes it: below, a grounder's distance is where it was fielded.
use super::calibrate::LOWEST_FLIGHT;
use super::output::medians;

/// A batted ball's kind, as Savant's `bb_type` names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    GroundBall,
    LineDrive,
    FlyBall,
    Popup,
}

impl Kind {
    /// Savant's names, in the table's order.
    const ALL: [(&'static str, Kind); 4] = [
        ("ground_ball", Kind::GroundBall),
        ("line_drive", Kind::LineDrive),
        ("fly_ball", Kind::FlyBall),
        ("popup", Kind::Popup),
    ];

    pub(super) fn of(text: &str) -> Option<Kind> {
        (Self::ALL.iter())
            .find(|(name, _)| name.eq_ignore_ascii_case(text))
            .map(|(_, kind)| *kind)
    }

    fn index(self) -> usize {
        Self::ALL.iter().position(|(_, k)| *k == self).unwrap_or(0)
    }
}

/// What Savant called a row: its kind, and whether it was a home run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Called {
    pub kind: Option<Kind>,
    pub home_run: bool,
}

/// The table's rows: the four kinds, then the home runs.
const ROWS: [&str; 5] = [
    "ground balls",
    "line drives",
    "fly balls",
    "popups",
    "home runs",
];

/// Model − Statcast by kind (balls launched at 10° or more), and how many
/// home runs clear the fence they are judged at.
#[derive(Clone, Debug, Default)]
pub(super) struct KindTally {
    differences: [Vec<f64>; 5],
    home_runs: usize,
    home_runs_clear: usize,
}

/// One kind's rows, median difference and median |difference| (m).
#[derive(Serialize)]
pub(super) struct KindRow {
    kind: &'static str,
    rows: usize,
    median: f64,
    median_abs: f64,
}

impl KindTally {
    pub(super) fn count(
        &mut self,
        called: Called,
        angle: f64,
        difference: Option<f64>,
        clears: bool,
    ) {
        if called.home_run {
            self.home_runs += 1;
            self.home_runs_clear += usize::from(clears);
        }
        let Some(difference) = difference.filter(|_| angle >= LOWEST_FLIGHT) else {
            return;
        };
        if let Some(kind) = called.kind {
            self.differences[kind.index()].push(difference);
        }
        if called.home_run {
            self.differences[4].push(difference);
        }
    }

    pub(super) fn add(&mut self, other: &KindTally) {
        for (mine, theirs) in self.differences.iter_mut().zip(&other.differences) {
            mine.extend_from_slice(theirs);
        }
        self.home_runs += other.home_runs;
        self.home_runs_clear += other.home_runs_clear;
    }

    /// Whether any row named its kind or was a home run.
    pub(super) fn any(&self) -> bool {
        self.home_runs > 0 || self.differences.iter().any(|d| !d.is_empty())
    }

    /// The kinds with rows, in SI.
    pub(super) fn rows(&self) -> Vec<KindRow> {
        (ROWS.iter().zip(&self.differences))
            .filter(|(_, d)| !d.is_empty())
            .map(|(kind, differences)| {
                let (median, median_abs) = medians(&mut differences.clone());
                KindRow {
                    kind,
                    rows: differences.len(),
                    median,
                    median_abs,
                }
            })
            .collect()
    }

    /// (home runs that clear, home runs), if the batch had any.
    pub(super) fn home_runs_clearing(&self) -> Option<(usize, usize)> {
        (self.home_runs > 0).then_some((self.home_runs_clear, self.home_runs))
    }

    /// The table in the units shown, and the home runs' verdict.
    pub(super) fn table(&self, shown: Shown) -> String {
        let unit = shown.unit(Quantity::Distance);
        let rows = self.rows();
        // Without distances there is no error to show, only the verdicts.
        let mut table = if rows.is_empty() {
            String::new()
        } else {
            format!(
                "by kind of ball (bb_type; home runs by events), launched at 10° or more, model − \
                 hit_distance_sc ({}):\n{:<13} {:>7} {:>8} {:>10}\n",
                unit.symbol, "kind", "rows", "median", "median |d|"
            )
        };
        for row in rows {
            let _ = writeln!(
                table,
                "{:<13} {:>7} {:>+8.1} {:>10.1}",
                row.kind,
                row.rows,
                unit.show(row.median),
                unit.show(row.median_abs)
            );
        }
        if let Some((clear, of)) = self.home_runs_clearing() {
            let _ = writeln!(
                table,
                "home runs that clear the fence they are judged at: {clear} of {of} ({:.1} %)",
                100.0 * clear as f64 / of as f64
            );
        }
        table.pop();
        table
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_are_savants_names_in_either_case_and_nothing_else() {
        assert_eq!(Kind::of("line_drive"), Some(Kind::LineDrive));
        assert_eq!(Kind::of("POPUP"), Some(Kind::Popup));
        assert_eq!(Kind::of("bunt"), None);
        assert_eq!(Kind::of(""), None);
    }

    #[test]
    fn only_balls_in_the_air_with_a_distance_are_tabulated_and_every_home_run_judged() {
        let mut tally = KindTally::default();
        let line = Called {
            kind: Some(Kind::LineDrive),
            home_run: false,
        };
        let homer = Called {
            kind: Some(Kind::FlyBall),
            home_run: true,
        };
        tally.count(line, 0.3, Some(2.0), false);
        tally.count(line, 0.3, Some(-4.0), false);
        tally.count(line, 0.1, Some(9.0), false); // 5.7°: fielded, not landed
        tally.count(line, 0.3, None, false); // no distance
        tally.count(homer, 0.5, Some(1.0), true);
        tally.count(homer, 0.5, None, false);
        let rows = tally.rows();
        let kinds: Vec<&str> = rows.iter().map(|r| r.kind).collect();
        assert_eq!(kinds, ["line drives", "fly balls", "home runs"]);
        assert_eq!(
            (rows[0].rows, rows[0].median, rows[0].median_abs),
            (2, -1.0, 3.0)
        );
        assert_eq!(tally.home_runs_clearing(), Some((1, 2)));
        // Without distances, only the verdict.
        let mut verdict = KindTally::default();
        verdict.count(homer, 0.5, None, true);
        assert_eq!(
            verdict.table(Shown(crate::units::UnitSystem::Si)),
            "home runs that clear the fence they are judged at: 1 of 1 (100.0 %)"
        );
    }
}
