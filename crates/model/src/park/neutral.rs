//! Regular-season games at neither team's park (the Mexico City, London,
//! Seoul and Tokyo series, Williamsport, the Field of Dreams): `data/
//! neutral_sites.toml`, compiled in. A Savant row of such a game still
//! names a home team, whose park is not where the ball was hit.

use std::sync::LazyLock;

use serde::Deserialize;

use super::Park;
use super::home::Day;

/// One series at a neutral site.
#[derive(Clone, Debug, PartialEq)]
pub struct NeutralSite {
    pub days: Vec<Day>,
    /// Both teams' codes: a row is matched whichever was the home team.
    pub teams: [String; 2],
    pub venue: String,
    /// The field's height above sea level (m): its standard air.
    pub elevation: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    game: Vec<Entry>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    days: Vec<String>,
    teams: [String; 2],
    venue: String,
    elevation: f64,
}

/// The file, compiled in.
const NEUTRAL_SITES_TOML: &str = include_str!("../../../../data/neutral_sites.toml");

static SITES: LazyLock<Vec<NeutralSite>> = LazyLock::new(|| {
    let file: File = toml::from_str(NEUTRAL_SITES_TOML).expect("data/neutral_sites.toml (tested)");
    (file.game.into_iter())
        .map(|game| NeutralSite {
            days: (game.days.iter())
                .map(|day| Day::parse(day).expect("a day (tested)"))
                .collect(),
            teams: game.teams,
            venue: game.venue,
            elevation: game.elevation,
        })
        .collect()
});

/// Every day some neutral site was played on, sorted: a batch asks of
/// every row, and nearly every day is none of them (one search, not a
/// look at each site's days).
static DAYS: LazyLock<Vec<Day>> = LazyLock::new(|| {
    let mut days: Vec<Day> = (SITES.iter())
        .flat_map(|site| site.days.iter().copied())
        .collect();
    days.sort_unstable();
    days
});

/// Every neutral site, in the file's order.
pub fn neutral_sites() -> &'static [NeutralSite] {
    &SITES
}

/// The neutral site where a team `park` is home to played on `day`, if any.
pub fn neutral_site(day: Day, park: &Park) -> Option<&'static NeutralSite> {
    DAYS.binary_search(&day).ok()?;
    (neutral_sites().iter())
        .find(|site| site.days.contains(&day) && site.teams.iter().any(|t| park.answers_to(t)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::park::{bundled, find};

    #[test]
    fn every_neutral_site_names_two_bundled_teams_on_real_days() {
        let sites = neutral_sites();
        assert_eq!(sites.len(), 25);
        for site in sites {
            assert!(!site.days.is_empty(), "{site:?}");
            assert!((0.0..3000.0).contains(&site.elevation), "{site:?}");
            for team in &site.teams {
                assert!(find(bundled(), team).is_some(), "{team}");
            }
            assert_ne!(
                find(bundled(), &site.teams[0]).unwrap().code,
                find(bundled(), &site.teams[1]).unwrap().code
            );
        }
        // Mexico City, 2024: Colorado's home games, and Houston's the
        // same days; not Colorado's the day after.
        let day = |y, m, d| Day::new(y, m, d).unwrap();
        let park = |code| find(bundled(), code).unwrap();
        let site = neutral_site(day(2024, 4, 27), park("COL")).unwrap();
        assert_eq!(site.venue, "Estadio Alfredo Harp Helú, Mexico City");
        assert_eq!(site.elevation, 2240.0);
        assert!(neutral_site(day(2024, 4, 28), park("HOU")).is_some());
        assert!(neutral_site(day(2024, 4, 29), park("COL")).is_none());
        assert!(neutral_site(day(2024, 4, 27), park("BOS")).is_none());
        // The 2019 Tokyo games named the Athletics OAK: ATH's alias.
        assert!(neutral_site(day(2019, 3, 20), park("ATH")).is_some());
    }
}
