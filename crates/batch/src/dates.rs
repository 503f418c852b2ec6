//! A row's date as Savant and Trackman write it: ISO `2024-05-03` (a time
//! after it allowed, or `/` between), US `5/3/2024`, or Yakkertech's
//! `5/3/24` (a two-digit year is 20YY, and one past 69 is refused: no ball
//! was tracked before 2000, and POSIX reads 69–99 as 19YY).
//! `calibrate --by month|season` groups on it; a row's park is its team's
//! home only on some days ([`model::park::Day`]); a tracked swing's season
//! picks its bat ([`analysis::bat_tracking::season_bat`]).

use model::park::Day;

/// The day `cell` names, if it is a date of one of those forms with a
/// year from 1800 to 2200.
pub(crate) fn day(cell: &str) -> Option<Day> {
    let cell = cell.trim();
    let date = cell.split([' ', 'T']).next()?;
    let numbers: Vec<&str> = date.split(['-', '/']).collect();
    if numbers.len() != 3 {
        return None;
    }
    let number = |i: usize| numbers[i].parse::<u32>().ok();
    let (year, month, day) = match numbers[0].len() {
        4 => (number(0)?, number(1)?, number(2)?),
        _ => {
            let year = match numbers[2].len() {
                2 => Some(2000 + number(2)?).filter(|&y| y < 2070)?,
                4 => number(2)?,
                _ => return None,
            };
            (year, number(0)?, number(1)?)
        }
    };
    if !(1800..=2200).contains(&year) {
        return None;
    }
    Day::new(i32::try_from(year).ok()?, month, day)
}

/// A season's year as a number: a whole year from 1800 to 2200, `2019.0`
/// included (pandas writes an integer column with a gap as floats), not a
/// fraction of one. `game_year` in a row and `calibrate --by season`.
pub(crate) fn season(year: f64) -> Option<i32> {
    ((1800.0..=2200.0).contains(&year) && year.fract() == 0.0).then_some(year as i32)
}

/// The year and month of `cell` ([`day`]).
pub(crate) fn year_month(cell: &str) -> Option<(u32, u32)> {
    day(cell).map(|d| (d.year().unsigned_abs(), d.month()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn iso_and_us_dates_give_their_year_and_month() {
        assert_eq!(year_month("2024-04-03"), Some((2024, 4)));
        assert_eq!(year_month(" 2025-10-01T19:05:00 "), Some((2025, 10)));
        assert_eq!(year_month("2025-10-01 19:05:00"), Some((2025, 10)));
        assert_eq!(year_month("2024/04/30"), Some((2024, 4)));
        assert_eq!(year_month("4/30/2024"), Some((2024, 4)));
        assert_eq!(year_month("06/24/2025"), Some((2025, 6)));
        // Yakkertech's short year.
        assert_eq!(year_month("6/3/25"), Some((2025, 6)));
        assert_eq!(year_month("6/3/99"), None);
        assert_eq!(year_month("2024"), None);
        assert_eq!(year_month("13/1/2024"), None);
        assert_eq!(year_month("2/30/2024"), None);
        assert_eq!(year_month("1/1/1700"), None);
        assert_eq!(year_month("1/1/202"), None);
        assert_eq!(day("2021-07-30"), Day::new(2021, 7, 30));
    }
}
