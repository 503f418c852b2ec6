//! Rows played away from their `home_team`'s bundled park (the park was not
//! the team's home that day: [`model::park::Park::home_on`]), counted and
//! said: such a row is at no park, for a verdict at the wrong park would be
//! a wrong answer given as right.

use std::collections::BTreeMap;

use model::park::{AtHome, spans_text};
use serde_json::{Value, json};

use crate::Setup;
use crate::row::Away;
use crate::words::plural;

/// Rows by (park, season, how the row stood), in that order.
#[derive(Clone, Debug, Default)]
pub(crate) struct AwayRows(BTreeMap<(usize, Option<i32>, u8), usize>);

fn order(at_home: AtHome) -> u8 {
    match at_home {
        AtHome::No => 0,
        AtHome::Unsure => 1,
        AtHome::Undated => 2,
        AtHome::Yes => 3,
    }
}

impl AwayRows {
    pub(crate) fn count(&mut self, away: &Away) {
        *self
            .0
            .entry((away.park, away.season, order(away.at_home)))
            .or_default() += 1;
    }

    pub(crate) fn add(&mut self, other: &AwayRows) {
        for (key, rows) in &other.0 {
            *self.0.entry(*key).or_default() += rows;
        }
    }

    /// Rows at no park because of it.
    pub(crate) fn at_no_park(&self) -> usize {
        (self.0.iter())
            .filter(|((_, _, how), _)| *how < 2)
            .map(|(_, rows)| rows)
            .sum()
    }

    /// "ATH 2025 (38 rows)", the kinds `how` picks.
    fn groups(&self, setup: &Setup, how: impl Fn(u8) -> bool) -> (usize, Vec<String>, Vec<usize>) {
        let (mut rows, mut named, mut parks) = (0, Vec::new(), Vec::new());
        for (&(park, season, kind), &n) in self.0.iter().filter(|((_, _, k), _)| how(*k)) {
            rows += n;
            let code = &setup.parks.parks[park].code;
            let when = match (season, kind) {
                (Some(year), 1) => format!(" {year}, its date not given"),
                (Some(year), _) => format!(" {year}"),
                (None, _) => String::new(),
            };
            named.push(format!("{code}{when} ({n} row{})", plural(n)));
            if !parks.contains(&park) {
                parks.push(park);
            }
        }
        (rows, named, parks)
    }

    /// "Oakland Coliseum was home 1968–2024; …".
    fn homes(setup: &Setup, parks: &[usize]) -> String {
        let homes: Vec<String> = (parks.iter())
            .map(|&i| {
                let park = &setup.parks.parks[i];
                format!(
                    "{}'s {} was home {}",
                    park.code,
                    park.name,
                    spans_text(&park.home)
                )
            })
            .collect();
        homes.join("; ")
    }

    /// The summary's parts: the rows at no park, and those judged at a park
    /// without the date that would say whether it was home.
    pub(crate) fn parts(&self, setup: &Setup) -> Vec<String> {
        let mut parts = Vec::new();
        let (rows, named, parks) = self.groups(setup, |kind| kind < 2);
        if rows > 0 {
            parts.push(format!(
                "{rows} row{} played where home_team's park was not home, at no park: {} \
                 ({}; a park file with that code and its `home` judges them, \
                 docs/parks.md)",
                plural(rows),
                named.join(", "),
                Self::homes(setup, &parks)
            ));
        }
        let (rows, named, parks) = self.groups(setup, |kind| kind == 2);
        if rows > 0 {
            parts.push(format!(
                "{rows} row{} without a date (game_date, game_year) judged at a park that was \
                 not always home: {} ({})",
                plural(rows),
                named.join(", "),
                Self::homes(setup, &parks)
            ));
        }
        parts
    }

    /// As JSON: one entry a park and season.
    pub(crate) fn json(&self, setup: &Setup) -> Value {
        let entries: Vec<Value> = (self.0.iter())
            .map(|(&(park, season, kind), &rows)| {
                let park = &setup.parks.parks[park];
                let judged = match kind {
                    0 => "no_park: not home then",
                    1 => "no_park: home for part of the season, no date",
                    _ => "at the park: no date",
                };
                json!({ "home_team": park.code, "park": park.name, "season": season,
                    "rows": rows, "judged": judged, "home": spans_text(&park.home) })
            })
            .collect();
        json!(entries)
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}
