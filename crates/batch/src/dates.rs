//! A row's date as Savant and Trackman write it: ISO `2024-05-03` (a time
//! after it allowed) or US `5/3/2024`. `calibrate --by month|season` groups
//! on it; a tracked swing's season picks its bat
//! ([`analysis::bat_tracking::season_bat`]).

/// The year and month of `cell`, if it is a date of either form with a
/// year from 1800 to 2200.
pub(crate) fn year_month(cell: &str) -> Option<(u32, u32)> {
    let cell = cell.trim();
    let numbers: Vec<&str> = cell.split(['-', '/', ' ', 'T']).collect();
    let number = |i: usize| numbers.get(i)?.parse::<u32>().ok();
    let (year, month) = match cell.contains('-') {
        true => (number(0)?, number(1)?),
        false => (number(2)?, number(0)?),
    };
    ((1800..=2200).contains(&year) && (1..=12).contains(&month)).then_some((year, month))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn iso_and_us_dates_give_their_year_and_month() {
        assert_eq!(year_month("2024-04-03"), Some((2024, 4)));
        assert_eq!(year_month(" 2025-10-01T19:05:00 "), Some((2025, 10)));
        assert_eq!(year_month("4/30/2024"), Some((2024, 4)));
        assert_eq!(year_month("2024"), None);
        assert_eq!(year_month("13/1/2024"), None);
        assert_eq!(year_month("1/1/1700"), None);
    }
}
