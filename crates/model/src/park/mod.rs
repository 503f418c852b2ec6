//! Ballparks: where a park is (its elevation, which way it faces) and its
//! fence. The 30 MLB parks are bundled from `data/parks.toml` (built by
//! `scripts/parks/regenerate.py`; sources, vintage and format in
//! docs/parks.md), parsed once on first use. Users' own park files are read
//! by `preset::parks` (a frontend: the model reads no files).

mod air;
mod fence;
mod home;
mod neutral;
mod parse;

use std::sync::LazyLock;

use parse::BundledEntry;

pub use air::GivenWeather;
pub use fence::{FOUL_LINE, Fence, FenceAt, FenceError, FencePoint, fair};
pub use home::{AtHome, Day, HOME_FORMS, HomeSpan, Played, at_home, spans_text};
pub use neutral::{NeutralSite, neutral_site, neutral_sites};
pub use parse::{ParkError, parse};

/// A ballpark.
#[derive(Clone, Debug, PartialEq)]
pub struct Park {
    /// Baseball Savant's `home_team` code, in capitals ("BOS").
    pub code: String,
    /// Other codes that name it ("ARI" for "AZ").
    pub aliases: Vec<String>,
    pub name: String,
    /// The city it is in ("Boston"), empty if not given.
    pub city: String,
    /// Elevation of the field above sea level (m).
    pub elevation: f64,
    /// Compass bearing from home plate to centre field, degrees clockwise
    /// from true north, in [0, 360).
    pub center_field_bearing: f64,
    /// The published foul-line and centre-field distances, if known.
    pub published: Option<ParkDimensions>,
    pub fence: Fence,
    /// When it was its team's home (none: always), [`at_home`].
    pub home: Vec<HomeSpan>,
    /// When its fence stood as given (none: always): a row at its park on
    /// another day met other walls. A park file without `walls` gives its
    /// `home` spans.
    pub walls: Vec<HomeSpan>,
    /// Other walls that stood there, each with when (a park rebuilt since:
    /// Toronto's before 2023): a row played there then is judged at them.
    pub earlier: Vec<EarlierWalls>,
}

/// Walls a park had on other days than its fence as given.
#[derive(Clone, Debug, PartialEq)]
pub struct EarlierWalls {
    /// When they stood.
    pub walls: Vec<HomeSpan>,
    pub fence: Fence,
}

/// A park's published distances (m): to the foul poles and to straightaway
/// centre field, as painted on its walls.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ParkDimensions {
    pub left_line: f64,
    pub center: f64,
    pub right_line: f64,
}

/// A wind's compass direction, degrees clockwise from true north, as a
/// weather report gives it (where it blows from) or as an arrow (where to).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CompassWind {
    From(f64),
    Toward(f64),
}

/// The bundled parks' file, compiled in.
pub const BUNDLED_TOML: &str = include_str!("../../../../data/parks.toml");

/// The bundled parks' fields, written by build.rs from data/parks.toml
/// (whose directions are rounded to 1e-5 rad: -0.7854 is the file's, not an
/// approximation of π/4 to mend).
#[allow(clippy::approx_constant)]
static BUNDLED_ENTRIES: &[BundledEntry] = include!(concat!(env!("OUT_DIR"), "/bundled_parks.rs"));

static BUNDLED: LazyLock<Vec<Park>> = LazyLock::new(|| {
    BUNDLED_ENTRIES
        .iter()
        .map(|entry| entry.checked().expect("data/parks.toml is valid (tested)"))
        .collect()
});

/// The bundled parks, in the file's order (checked on first use; equal to
/// `parse(BUNDLED_TOML)`, tested).
pub fn bundled() -> &'static [Park] {
    &BUNDLED
}

/// The park `code` names among `parks`, by its code first, then by an
/// alias; without regard to case.
pub fn find<'a>(parks: &'a [Park], code: &str) -> Option<&'a Park> {
    let code = code.trim();
    parks
        .iter()
        .find(|p| p.code.eq_ignore_ascii_case(code))
        .or_else(|| parks.iter().find(|p| p.answers_to(code)))
}

/// What a park's name, city or code given by a user matched among `parks`.
#[derive(Debug)]
pub enum Named<'a> {
    One(&'a Park),
    /// Several parks answer to it (`chicago`, `park`): these.
    Several(Vec<&'a Park>),
    None,
}

/// The park `query` names among `parks`, as a user types it: a code or an
/// alias (as [`find`]); else a park whose name or city is `query`; else one
/// whose name or city has `query` at the start of a word (`fenway`,
/// `camden`, `kansas`). Case and runs of blanks do not matter.
pub fn named<'a>(parks: &'a [Park], query: &str) -> Named<'a> {
    if let Some(park) = find(parks, query) {
        return Named::One(park);
    }
    let query = words(query);
    if query.is_empty() {
        return Named::None;
    }
    let exact: Vec<&Park> = parks
        .iter()
        .filter(|p| words(&p.name) == query || words(&p.city) == query)
        .collect();
    let matches = if exact.is_empty() {
        parks
            .iter()
            .filter(|p| {
                starts_a_word(&words(&p.name), &query) || starts_a_word(&words(&p.city), &query)
            })
            .collect()
    } else {
        exact
    };
    match matches.as_slice() {
        [] => Named::None,
        [one] => Named::One(one),
        _ => Named::Several(matches),
    }
}

/// `text` lower-cased, its words one blank apart.
fn words(text: &str) -> String {
    text.split_whitespace()
        .map(str::to_lowercase)
        .collect::<Vec<_>>()
        .join(" ")
}

/// Whether `query` stands in `text` from the start of one of its words.
fn starts_a_word(text: &str, query: &str) -> bool {
    text.match_indices(query)
        .any(|(at, _)| at == 0 || text[..at].ends_with(' '))
}

impl Park {
    /// Its code and aliases.
    pub fn codes(&self) -> impl Iterator<Item = &str> {
        std::iter::once(self.code.as_str()).chain(self.aliases.iter().map(String::as_str))
    }

    /// Whether `code` is its code or one of its aliases (any case).
    pub fn answers_to(&self, code: &str) -> bool {
        self.codes().any(|c| c.eq_ignore_ascii_case(code))
    }

    /// Whether it was its team's home when a row was `played`.
    pub fn home_on(&self, played: Played) -> AtHome {
        at_home(&self.home, played)
    }

    /// Whether its fence as given stood when a row was `played` (asked
    /// of a row played there: [`Self::home_on`] first).
    pub fn walls_on(&self, played: Played) -> AtHome {
        at_home(&self.walls, played)
    }

    /// The earlier walls (their index in `earlier`) that surely stood
    /// when a row was `played` there, where its fence as given did not.
    pub fn earlier_on(&self, played: Played) -> Option<usize> {
        (self.earlier.iter()).position(|earlier| at_home(&earlier.walls, played) == AtHome::Yes)
    }

    /// Its fence, or the earlier walls `earlier` (an index from
    /// [`Self::earlier_on`]).
    pub fn fence_of(&self, earlier: Option<usize>) -> &Fence {
        earlier.map_or(&self.fence, |k| &self.earlier[k].fence)
    }

    /// Whether it has been home, with its walls as given, every day from
    /// the first of `year` on: a row without a date is surely judged
    /// where and as it was played.
    pub fn as_given_since(&self, year: i32) -> bool {
        home::home_since(&self.home, year) && home::home_since(&self.walls, year)
    }

    /// A wind's direction in the flight frame: radians from the
    /// centre-field line, positive toward right field (which is clockwise
    /// from centre field seen from above), in (−π, π]. A wind from due
    /// south at a park facing due north blows straight out: 0.
    pub fn wind_direction(&self, wind: CompassWind) -> f64 {
        let toward = match wind {
            CompassWind::From(bearing) => bearing + 180.0,
            CompassWind::Toward(bearing) => bearing,
        };
        let relative = (toward - self.center_field_bearing).rem_euclid(360.0);
        let relative = if relative > 180.0 {
            relative - 360.0
        } else {
            relative
        };
        relative.to_radians()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn the_compiled_in_parks_are_the_files_to_the_last_bit() {
        let parsed = parse(BUNDLED_TOML).unwrap();
        assert_eq!(parsed.len(), 30);
        assert_eq!(bundled(), parsed.as_slice());
        let fenway = find(bundled(), "BOS").unwrap();
        assert_eq!(fenway.name, "Fenway Park");
    }

    fn facing(bearing: f64) -> Park {
        Park {
            code: "T".into(),
            aliases: vec![],
            name: "T".into(),
            city: String::new(),
            elevation: 0.0,
            center_field_bearing: bearing,
            published: None,
            fence: Fence::uniform(120.0, 3.0),
            home: vec![],
            walls: vec![],
            earlier: vec![],
        }
    }

    #[test]
    fn real_winds_turn_into_the_flight_frame() {
        let north = facing(0.0);
        // From the south: straight out to centre field.
        assert!(north.wind_direction(CompassWind::From(180.0)).abs() < 1e-12);
        // Toward the east: toward right field (clockwise of north).
        let east = north.wind_direction(CompassWind::Toward(90.0));
        assert!((east - FRAC_PI_2).abs() < 1e-12);
        // From centre field back in: ±π, given as +π.
        assert!((north.wind_direction(CompassWind::From(0.0)) - PI).abs() < 1e-12);
        // Fenway faces 45°: a wind from the south-west (225°) blows out.
        let fenway = facing(45.0);
        assert!(fenway.wind_direction(CompassWind::From(225.0)).abs() < 1e-12);
        // A wind toward north at a park facing 350° drifts 10° toward right field.
        let coors = facing(350.0);
        let drift = coors.wind_direction(CompassWind::Toward(0.0));
        assert!((drift - 10f64.to_radians()).abs() < 1e-12);
    }

    #[test]
    fn each_bundled_fence_stood_in_its_walls_spans_only() {
        let played = |y, m, d| Played::On(Day::new(y, m, d).unwrap());
        let walls = |code: &str, when: Played| find(bundled(), code).unwrap().walls_on(when);
        // Camden Yards' left field: back and up for 2022, part way in for 2025.
        assert_eq!(walls("BAL", played(2021, 9, 30)), AtHome::No);
        assert_eq!(walls("BAL", played(2022, 4, 11)), AtHome::Yes);
        assert_eq!(walls("BAL", played(2024, 9, 29)), AtHome::Yes);
        assert_eq!(walls("BAL", played(2025, 3, 31)), AtHome::No);
        assert_eq!(walls("BAL", Played::In(2023)), AtHome::Yes);
        assert_eq!(walls("BAL", Played::Unknown), AtHome::Undated);
        // Toronto's walls rebuilt for 2023; its outline's before, bundled
        // as its earlier walls.
        assert_eq!(walls("TOR", played(2022, 9, 1)), AtHome::No);
        assert_eq!(walls("TOR", played(2023, 4, 11)), AtHome::Yes);
        let toronto = find(bundled(), "TOR").unwrap();
        assert_eq!(toronto.earlier_on(played(2022, 9, 1)), Some(0));
        assert_eq!(toronto.earlier_on(Played::In(2019)), Some(0));
        assert_eq!(toronto.earlier_on(played(2023, 4, 11)), None);
        assert_eq!(toronto.earlier_on(Played::Unknown), None);
        assert_eq!(spans_text(&toronto.earlier[0].walls), "1989–2022");
        // The same park, a new wall: in 16 ft at right-centre (375 to 359
        // ft, at the direction the old wall was 375), the poles and
        // centre field where they were.
        let ft = |m: f64| m / 0.3048;
        let right_centre = 24.6f64.to_radians();
        let old = ft(toronto.earlier[0].fence.distance_at(right_centre).unwrap());
        let new = ft(toronto.fence.distance_at(right_centre).unwrap());
        assert!(
            (old - 375.0).abs() < 0.5 && (new - 359.0).abs() < 1.0,
            "{old} {new}"
        );
        for direction in [-FOUL_LINE, 0.0, FOUL_LINE] {
            let old = toronto.earlier[0].fence.distance_at(direction).unwrap();
            assert_eq!(toronto.fence.distance_at(direction).unwrap(), old);
        }
        // Camden Yards before its 2022 wall, Comerica Park before 2023 and
        // Oracle Park before 2020, from 2015; Marlins Park 2016–2019;
        // Kauffman Stadium 2004–2025; Rogers Centre 1989–2022; no other
        // park has any.
        let earlier_on = |code: &str, when| find(bundled(), code).unwrap().earlier_on(when);
        assert_eq!(earlier_on("BAL", played(2019, 6, 1)), Some(0));
        assert_eq!(earlier_on("BAL", played(2014, 6, 1)), None);
        assert_eq!(earlier_on("DET", Played::In(2022)), Some(0));
        assert_eq!(earlier_on("SF", played(2020, 7, 24)), None);
        assert_eq!(earlier_on("MIA", played(2015, 7, 24)), None);
        assert_eq!(earlier_on("MIA", Played::In(2016)), Some(0));
        assert_eq!(earlier_on("KC", Played::In(2025)), Some(0));
        assert_eq!(earlier_on("KC", Played::In(2003)), None);
        let with_earlier: Vec<&str> = (bundled().iter())
            .filter(|p| !p.earlier.is_empty())
            .map(|p| p.code.as_str())
            .collect();
        assert_eq!(with_earlier, ["BAL", "DET", "KC", "MIA", "SF", "TOR"]);
        // Houston's centre field without Tal's Hill, from 2017.
        assert_eq!(walls("HOU", played(2016, 9, 28)), AtHome::No);
        assert_eq!(walls("HOU", played(2017, 4, 3)), AtHome::Yes);
        // Kauffman Stadium's walls rebuilt for 2026; those of 2004–2025
        // its earlier walls.
        assert_eq!(walls("KC", Played::In(2026)), AtHome::Yes);
        assert_eq!(walls("KC", Played::In(2025)), AtHome::No);
        // A park with no change known: its walls are its home spans.
        let fenway = find(bundled(), "BOS").unwrap();
        assert_eq!(fenway.walls, fenway.home);
        assert_eq!(fenway.walls_on(played(2016, 6, 1)), AtHome::Yes);
        // A row without a date is surely judged as it was played only where
        // the park was home, with these walls, since the season asked.
        let since = |code: &str| find(bundled(), code).unwrap().as_given_since(2015);
        assert_eq!(
            [
                since("BOS"),
                since("BAL"),
                since("HOU"),
                since("MIA"),
                since("TB")
            ],
            [true, false, false, false, false]
        );
    }

    #[test]
    fn codes_and_aliases_find_parks_in_any_case() {
        let parks = bundled();
        assert_eq!(find(parks, "az").unwrap().code, "AZ");
        assert_eq!(find(parks, "ARI").unwrap().code, "AZ");
        assert_eq!(find(parks, "OAK").unwrap().code, "ATH");
        assert_eq!(find(parks, " bos ").unwrap().name, "Fenway Park");
        assert!(find(parks, "XXX").is_none());
    }
}
