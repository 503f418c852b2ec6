//! What every row of a batch shares: the preset, the parks, and what the
//! command line chose.

use analysis::savant::Spray;
use model::park::{self, GivenWeather};
use preset::Preset;
use preset::parks::Parks;

/// What every row of a batch shares.
pub struct Setup<'a> {
    pub base: &'a Preset,
    /// Every park: a row's `home_team` is looked up here, and every flight
    /// is judged at each of their fences.
    pub parks: &'a Parks,
    /// The parks' fences, in `parks`' order.
    pub fences: Vec<&'a park::Fence>,
    /// `--park`: the index of the park every row is taken to.
    pub park: Option<usize>,
    /// The keys `--set` gave (the one record of "was this given?" for the
    /// command line; a row's own columns are the header's).
    pub given_keys: Vec<String>,
    /// The air keys among them: a park does not replace them.
    pub given: GivenWeather,
    /// `--column NAME=COLUMN`: the file's COLUMN read as NAME.
    pub mapping: Vec<(String, String)>,
    pub spray: Spray,
    /// `--one-flight`: every park judged on the row's one flight, in its
    /// own air, instead of each park in the park's air.
    pub one_flight: bool,
    /// `--all-parks`: each park's outcome and margin on every row.
    pub all_parks: bool,
    /// `--keep`'s column names.
    pub keep: Vec<String>,
    /// Solve each row's swing from bat tracking and fly the impact's
    /// launch where it is solved (`hit --batch`, `--spin swing`).
    pub solve_swings: bool,
    /// Print the swing's columns (`hit --batch`).
    pub swing_columns: bool,
    /// Whether the output goes to a terminal: the kept cells' control
    /// characters are then escaped, in CSV and JSON alike.
    pub escape_kept: bool,
    /// Each park's code as a CSV field, for every row's `park` column.
    pub(crate) code_fields: Vec<String>,
    /// The command takes `--set` (the explorer's `tui --savant` does not):
    /// only then do refusals offer it.
    pub takes_set: bool,
}

impl<'a> Setup<'a> {
    pub fn new(base: &'a Preset, parks: &'a Parks) -> Setup<'a> {
        Setup {
            base,
            parks,
            fences: parks.parks.iter().map(|p| &p.fence).collect(),
            park: None,
            given_keys: Vec::new(),
            given: GivenWeather::default(),
            mapping: Vec::new(),
            spray: Spray::Landing,
            one_flight: false,
            all_parks: false,
            keep: Vec::new(),
            solve_swings: false,
            swing_columns: false,
            escape_kept: false,
            code_fields: parks.parks.iter().map(|p| quoted(&p.code)).collect(),
            takes_set: true,
        }
    }

    /// "; or --set KEY=VALUE {what}" where the command takes `--set`.
    pub(crate) fn or_set(&self, assignment: &str, what: &str) -> String {
        match self.takes_set {
            true => format!("; or --set {assignment} {what}"),
            false => String::new(),
        }
    }

    /// Notes `--set`'s assignments: their keys, and the air among them.
    pub fn given(&mut self, assignments: &[String]) {
        self.given = GivenWeather::of_assignments(assignments);
        self.given_keys = assigned_keys(assignments).map(str::to_owned).collect();
    }

    /// Whether `--set` gave `key`.
    pub(crate) fn gave(&self, key: &str) -> bool {
        self.given_keys.iter().any(|k| k == key)
    }

    /// The index of the first park that answers to `code` (any case).
    pub(crate) fn park_of(&self, code: &str) -> Option<usize> {
        self.parks.parks.iter().position(|p| p.answers_to(code))
    }
}

/// A tracked row's priors ([`Setup::priors`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Priors {
    /// The bat's tilt where the row measured none (`None`: the scene's).
    pub tilt: Option<f64>,
    /// The row's season picks its bat where the program knows one.
    pub season_bats: bool,
}

/// A field for CSV output, quoted as RFC 4180 asks when it holds a comma, a
/// quote or a line break (and when it starts or ends with a space, which
/// some readers would trim).
pub fn quoted(field: &str) -> String {
    let special = field.contains([',', '"', '\n', '\r']);
    if special || field.starts_with(' ') || field.ends_with(' ') {
        format!("\"{}\"", field.replace('"', "\"\""))
    } else {
        field.to_owned()
    }
}

/// The keys `--set`'s `key=value` assignments give, trimmed.
pub fn assigned_keys(assignments: &[String]) -> impl Iterator<Item = &str> {
    (assignments.iter())
        .filter_map(|a| a.split_once('='))
        .map(|(key, _)| key.trim())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kept_fields_are_quoted_as_rfc_4180_asks() {
        assert_eq!(quoted("Target Field"), "Target Field");
        assert_eq!(quoted("homers, to left"), "\"homers, to left\"");
        assert_eq!(quoted("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(quoted("two\nlines"), "\"two\nlines\"");
        assert_eq!(quoted("trailing "), "\"trailing \"");
        assert_eq!(quoted(""), "");
    }
}
