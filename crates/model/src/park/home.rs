//! When a park was its team's home. A Savant row names its park only by
//! `home_team`; a team that moved (the Athletics to Sacramento in 2025,
//! the Rays to Tampa for 2025, the Blue Jays to Buffalo and Dunedin in
//! 2020–21, the Rangers and the Braves into new parks in 2020 and 2017)
//! played its home games elsewhere than its bundled park. A row of such a
//! season judged at the bundled park would be a wrong answer given as
//! right, so each park says when it was home (`home` in a park file:
//! docs/parks.md), and a row dated outside it is at no park.

use std::fmt;

/// A calendar day, ordered as days are (year, month, day).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Day {
    year: i32,
    month: u8,
    day: u8,
}

impl Day {
    /// The day, if `month` is 1–12 and `day` is in it (leap years kept).
    pub fn new(year: i32, month: u32, day: u32) -> Option<Day> {
        let leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
        let days = match month {
            2 if leap => 29,
            2 => 28,
            4 | 6 | 9 | 11 => 30,
            1..=12 => 31,
            _ => return None,
        };
        (1..=days).contains(&day).then_some(Day {
            year,
            month: month as u8,
            day: day as u8,
        })
    }

    /// `YYYY-MM-DD`, a year from 1850 to 2200.
    pub fn parse(text: &str) -> Option<Day> {
        let numbers: Vec<&str> = text.trim().split('-').collect();
        let [year, month, day] = numbers.as_slice() else {
            return None;
        };
        let year = year
            .parse::<i32>()
            .ok()
            .filter(|y| (1850..=2200).contains(y))?;
        Day::new(year, month.parse().ok()?, day.parse().ok()?)
    }

    pub fn year(self) -> i32 {
        self.year
    }

    pub fn month(self) -> u32 {
        u32::from(self.month)
    }

    fn first_of(year: i32) -> Day {
        Day {
            year,
            month: 1,
            day: 1,
        }
    }

    fn last_of(year: i32) -> Day {
        Day {
            year,
            month: 12,
            day: 31,
        }
    }
}

impl fmt::Display for Day {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:04}-{:02}-{:02}", self.year, self.month, self.day)
    }
}

/// When a row was played, as far as its columns say.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Played {
    On(Day),
    /// Only its season (`game_year`).
    In(i32),
    Unknown,
}

/// A stretch of days a park was its team's home, both ends included; an
/// open end runs on without limit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HomeSpan {
    pub from: Option<Day>,
    pub to: Option<Day>,
}

/// Whether a row was played at its team's park.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AtHome {
    Yes,
    No,
    /// Only its season is known, and the park was home for part of it.
    Unsure,
    /// Its date is not known, and the park was not always home.
    Undated,
}

/// The spans accepted, as a park file writes them.
pub const HOME_FORMS: &str =
    "YEAR..YEAR, YEAR.., ..YEAR, or with days (2021-07-30..), years from 1850 to 2200";

impl HomeSpan {
    /// `1998..2024` (the first day of 1998 to the last of 2024), `2026..`,
    /// `..2024`, or days in place of years (`2021-07-30..`).
    pub fn parse(text: &str) -> Option<HomeSpan> {
        let (from, to) = text.trim().split_once("..")?;
        let end = |text: &str, first: bool| -> Option<Option<Day>> {
            let text = text.trim();
            if text.is_empty() {
                return Some(None);
            }
            if text.contains('-') {
                return Day::parse(text).map(Some);
            }
            let year = text
                .parse::<i32>()
                .ok()
                .filter(|y| (1850..=2200).contains(y))?;
            Some(Some(if first {
                Day::first_of(year)
            } else {
                Day::last_of(year)
            }))
        };
        let span = HomeSpan {
            from: end(from, true)?,
            to: end(to, false)?,
        };
        let ordered = match (span.from, span.to) {
            (Some(from), Some(to)) => from <= to,
            _ => true,
        };
        ordered.then_some(span)
    }

    /// As a park file writes it ([`Self::parse`]'s text): "1998..2024",
    /// "2021-07-30..".
    pub fn as_written(&self) -> String {
        let (from, to) = self.ends();
        format!("{}..{}", from.unwrap_or_default(), to.unwrap_or_default())
    }

    /// Its ends as text: a year where the span takes the whole of it (from
    /// the first of January, to the last of December), else the day.
    fn ends(&self) -> (Option<String>, Option<String>) {
        let end = |day: Option<Day>, whole_year: (u8, u8)| {
            day.map(|d| match (d.month, d.day) == whole_year {
                true => d.year.to_string(),
                false => d.to_string(),
            })
        };
        (end(self.from, (1, 1)), end(self.to, (12, 31)))
    }

    pub fn contains(&self, day: Day) -> bool {
        self.from.is_none_or(|from| from <= day) && self.to.is_none_or(|to| day <= to)
    }

    /// Whether it and `other` share a day.
    pub fn overlaps(&self, other: &HomeSpan) -> bool {
        let starts_by_end = |a: &HomeSpan, b: &HomeSpan| match (a.from, b.to) {
            (Some(from), Some(to)) => from <= to,
            _ => true,
        };
        starts_by_end(self, other) && starts_by_end(other, self)
    }

    /// Whether it covers the whole of `year`, and whether any of it.
    fn covers(&self, year: i32) -> (bool, bool) {
        let whole = self.contains(Day::first_of(year)) && self.contains(Day::last_of(year));
        let any = self.from.is_none_or(|from| from.year <= year)
            && self.to.is_none_or(|to| year <= to.year);
        (whole, any)
    }
}

impl fmt::Display for HomeSpan {
    /// "1998–2024", "2026 on", "2021-07-30 on", "to 2024".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.ends() {
            (Some(from), Some(to)) if from == to => write!(f, "{from}"),
            (Some(from), Some(to)) => write!(f, "{from}–{to}"),
            (Some(from), None) => write!(f, "{from} on"),
            (None, Some(to)) => write!(f, "to {to}"),
            (None, None) => write!(f, "always"),
        }
    }
}

/// Whether a park whose home spans are `spans` (none: always home) was
/// home when a row was `played`.
pub fn at_home(spans: &[HomeSpan], played: Played) -> AtHome {
    if spans.is_empty() {
        return AtHome::Yes;
    }
    match played {
        Played::On(day) if spans.iter().any(|s| s.contains(day)) => AtHome::Yes,
        Played::On(_) => AtHome::No,
        Played::In(year) => {
            let covers = spans.iter().map(|s| s.covers(year));
            let (whole, any) = covers.fold((false, false), |(w, a), (sw, sa)| (w | sw, a | sa));
            match (whole, any) {
                (true, _) => AtHome::Yes,
                (false, true) => AtHome::Unsure,
                (false, false) => AtHome::No,
            }
        }
        Played::Unknown => AtHome::Undated,
    }
}

/// Whether a park whose home spans are `spans` (none: always home) has
/// been home every day from the first of `year` on.
pub fn home_since(spans: &[HomeSpan], year: i32) -> bool {
    let first = Day::first_of(year);
    spans.is_empty() || (spans.iter()).any(|s| s.contains(first) && s.to.is_none())
}

/// The spans as a reader says them: "1989-06-05–2019, 2021-07-30 on".
pub fn spans_text(spans: &[HomeSpan]) -> String {
    let texts: Vec<String> = spans.iter().map(HomeSpan::to_string).collect();
    texts.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn day(y: i32, m: u32, d: u32) -> Day {
        Day::new(y, m, d).unwrap()
    }

    #[test]
    fn spans_read_years_and_days_with_open_ends() {
        let span = HomeSpan::parse("1998..2024").unwrap();
        assert_eq!(span.from, Some(day(1998, 1, 1)));
        assert_eq!(span.to, Some(day(2024, 12, 31)));
        assert_eq!(span.to_string(), "1998–2024");
        let span = HomeSpan::parse(" 2021-07-30 .. ").unwrap();
        assert_eq!((span.from, span.to), (Some(day(2021, 7, 30)), None));
        assert_eq!(span.to_string(), "2021-07-30 on");
        assert_eq!(HomeSpan::parse("..2024").unwrap().to_string(), "to 2024");
        for written in ["1998..2024", "2021-07-30..", "..2019-06-30", "2026.."] {
            assert_eq!(HomeSpan::parse(written).unwrap().as_written(), written);
        }
        assert_eq!(HomeSpan::parse("2025..2025").unwrap().to_string(), "2025");
        for bad in [
            "2024",
            "2024..2020",
            "1700..",
            "2024-02-30..",
            "2024-13-01..",
            "20x4..",
            "2024-05..",
        ] {
            assert_eq!(HomeSpan::parse(bad), None, "{bad}");
        }
        assert!(Day::new(2024, 2, 29).is_some());
        assert!(Day::new(2023, 2, 29).is_none());
        assert!(Day::new(1900, 2, 29).is_none());
    }

    #[test]
    fn a_row_is_at_home_by_its_day_or_by_a_whole_season() {
        // Toronto: Rogers Centre to 2019, Buffalo and Dunedin in 2020 and
        // until 29 July 2021.
        let toronto = [
            HomeSpan::parse("1989..2019").unwrap(),
            HomeSpan::parse("2021-07-30..").unwrap(),
        ];
        assert_eq!(at_home(&toronto, Played::On(day(2019, 9, 29))), AtHome::Yes);
        assert_eq!(at_home(&toronto, Played::On(day(2020, 8, 1))), AtHome::No);
        assert_eq!(at_home(&toronto, Played::On(day(2021, 7, 29))), AtHome::No);
        assert_eq!(at_home(&toronto, Played::On(day(2021, 7, 30))), AtHome::Yes);
        assert_eq!(at_home(&toronto, Played::In(2019)), AtHome::Yes);
        assert_eq!(at_home(&toronto, Played::In(2020)), AtHome::No);
        assert_eq!(at_home(&toronto, Played::In(2021)), AtHome::Unsure);
        assert_eq!(at_home(&toronto, Played::In(2024)), AtHome::Yes);
        assert_eq!(at_home(&toronto, Played::Unknown), AtHome::Undated);
        // A park always home needs no date.
        assert_eq!(at_home(&[], Played::Unknown), AtHome::Yes);
        assert_eq!(spans_text(&toronto), "1989–2019, 2021-07-30 on");
    }
}
