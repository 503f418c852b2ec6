//! Rows played away from their `home_team`'s bundled park (the park was not
//! the team's home that day: [`model::park::Park::home_on`]), or there but
//! before or after its walls as given ([`model::park::Park::walls_on`]),
//! counted and said: such a row is at no park, for a verdict at the wrong
//! park, or at walls that were not there, would be a wrong answer given as
//! right.

use std::collections::BTreeMap;

use model::park::{HomeSpan, spans_text};
use preset::cut;
use serde_json::{Value, json};

use crate::Setup;
use crate::words::plural;

/// A row whose `home_team`'s park was not home when it was played.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Away {
    /// The park's index.
    pub park: usize,
    pub season: Option<i32>,
    pub why: AwayWhy,
    /// The elevation (m) where it was played, a neutral site's or its
    /// park's when the walls were others: the row flies in its air.
    pub air_elevation: Option<f64>,
}

/// Why a row is [`Away`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum AwayWhy {
    /// The park was not home on its date, or in its season.
    NotHome,
    /// Only its season is known, and the park was home for part of it.
    Unsure,
    /// A regular-season game at a neutral site (Mexico City, London, …):
    /// its venue.
    Neutral(&'static str),
    /// Savant's `game_type` S, E or A: spring training and exhibitions
    /// (at the team's spring park, or anywhere), the All-Star Game.
    NotAtHome(GameType),
    /// Played at its park, on a day its walls as given did not stand (a
    /// 2019 row at Camden Yards, whose left field moved for 2022).
    WallsNotThen,
    /// Only its season is known, and the walls as given stood for part of
    /// it.
    WallsUnsure,
    /// No date: judged at the park as bundled, and counted.
    Undated,
}

impl AwayWhy {
    /// Whether it is about the park's walls, not where it was played.
    fn walls(self) -> bool {
        matches!(self, AwayWhy::WallsNotThen | AwayWhy::WallsUnsure)
    }
}

/// A game `game_type` says was not at the home team's park.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum GameType {
    Spring,
    Exhibition,
    AllStar,
}

impl GameType {
    /// Savant's `game_type`: `Ok(None)` for a game at the home team's park
    /// (R, and the postseason's F, D, L, W).
    pub(crate) fn of(value: &str) -> Result<Option<GameType>, String> {
        match value.to_ascii_uppercase().as_str() {
            "R" | "F" | "D" | "L" | "W" => Ok(None),
            "S" => Ok(Some(GameType::Spring)),
            "E" => Ok(Some(GameType::Exhibition)),
            "A" => Ok(Some(GameType::AllStar)),
            _ => Err(format!(
                "game_type = {:?}: expected Savant's R, F, D, L, W (at the home team's park), \
                 S, E or A (spring training, exhibition, All-Star Game)",
                cut(value, 20)
            )),
        }
    }

    pub(crate) fn name(self) -> &'static str {
        match self {
            GameType::Spring => "spring training",
            GameType::Exhibition => "exhibition",
            GameType::AllStar => "All-Star Game",
        }
    }
}

/// Rows by (park, season, why), in that order.
#[derive(Clone, Debug, Default)]
pub(crate) struct AwayRows(BTreeMap<(usize, Option<i32>, AwayWhy), usize>);

impl AwayRows {
    pub(crate) fn count(&mut self, away: &Away) {
        *self
            .0
            .entry((away.park, away.season, away.why))
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
            .filter(|((_, _, why), _)| *why != AwayWhy::Undated)
            .map(|(_, rows)| rows)
            .sum()
    }

    /// "ATH 2025 (38 rows)", the kinds `how` picks.
    fn groups(
        &self,
        setup: &Setup,
        how: impl Fn(AwayWhy) -> bool,
    ) -> (usize, Vec<String>, Vec<usize>) {
        let (mut rows, mut named, mut parks) = (0, Vec::new(), Vec::new());
        for (&(park, season, kind), &n) in self.0.iter().filter(|((_, _, k), _)| how(*k)) {
            rows += n;
            let code = &setup.parks.parks[park].code;
            let year = season.map_or(String::new(), |y| format!(" {y}"));
            let when = match kind {
                AwayWhy::Unsure | AwayWhy::WallsUnsure => format!("{year}, its date not given"),
                AwayWhy::NotAtHome(game) => format!("{year}, {}", game.name()),
                AwayWhy::Neutral(venue) => format!("{year}, at {venue}, in its air"),
                _ => year,
            };
            named.push(format!("{code}{when} ({n} row{})", plural(n)));
            let dated = !matches!(kind, AwayWhy::Neutral(_) | AwayWhy::NotAtHome(_));
            if dated && !parks.contains(&park) {
                parks.push(park);
            }
        }
        (rows, named, parks)
    }

    /// "ATH's Oakland Coliseum was home 1968–2024; BAL's Oriole Park at
    /// Camden Yards was home 1992 on, its walls as given 2022–2024, earlier
    /// walls 2015–2021".
    fn homes(setup: &Setup, parks: &[usize]) -> String {
        let always = |spans: &[HomeSpan]| match spans.is_empty() {
            true => String::from("always"),
            false => spans_text(spans),
        };
        let homes: Vec<String> = (parks.iter())
            .map(|&i| {
                let park = &setup.parks.parks[i];
                let mut walls = match park.walls == park.home {
                    true => String::new(),
                    false => format!(", its walls as given {}", always(&park.walls)),
                };
                for earlier in &park.earlier {
                    walls += &format!(", earlier walls {}", spans_text(&earlier.walls));
                }
                format!(
                    "{}'s {} was home {}{walls}",
                    park.code,
                    park.name,
                    always(&park.home)
                )
            })
            .collect();
        homes.join("; ")
    }

    /// The summary's parts: the rows at no park, and those judged at a park
    /// without the date that would say whether it was home.
    pub(crate) fn parts(&self, setup: &Setup) -> Vec<String> {
        let mut parts = Vec::new();
        let (rows, named, parks) =
            self.groups(setup, |why| why != AwayWhy::Undated && !why.walls());
        if rows > 0 {
            let homes = match parks.is_empty() {
                true => String::new(),
                false => format!(
                    " ({}; a park file with that code and its `home` judges them, \
                     docs/parks.md)",
                    Self::homes(setup, &parks)
                ),
            };
            parts.push(format!(
                "{rows} row{} played where home_team's park was not home, at no park: {}{homes}",
                plural(rows),
                named.join(", "),
            ));
        }
        let (rows, named, parks) = self.groups(setup, AwayWhy::walls);
        if rows > 0 {
            parts.push(format!(
                "{rows} row{} played at home_team's park when its walls were not those given, \
                 at no park, in its air: {} ({}; a park file with that code and its `walls` \
                 judges them, docs/parks.md)",
                plural(rows),
                named.join(", "),
                Self::homes(setup, &parks)
            ));
        }
        let (rows, named, parks) = self.groups(setup, |why| why == AwayWhy::Undated);
        if rows > 0 {
            parts.push(format!(
                "{rows} row{} without a date (game_date, game_year) judged at a park that was \
                 not always home, or not always so walled: {} ({})",
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
                    AwayWhy::NotHome => "no_park: not home then",
                    AwayWhy::Unsure => "no_park: home for part of the season, no date",
                    AwayWhy::NotAtHome(game) => game.name(),
                    AwayWhy::Neutral(venue) => venue,
                    AwayWhy::WallsNotThen => "no_park: other walls then",
                    AwayWhy::WallsUnsure => {
                        "no_park: walls as given for part of the season, no date"
                    }
                    AwayWhy::Undated => "at the park: no date",
                };
                json!({ "home_team": park.code, "park": park.name, "season": season,
                    "rows": rows, "judged": judged, "home": spans_text(&park.home),
                    "walls": spans_text(&park.walls),
                    "earlier_walls": (park.earlier.iter()).map(|e| spans_text(&e.walls)).collect::<Vec<_>>() })
            })
            .collect();
        json!(entries)
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}
