//! The summary's table by kind of ball: Savant's `bb_type`, and the home
//! runs by `events`, as docs/accuracy.md tabulates April 2024, for a
//! user's own export. Both columns are only counted: a cell that names no
//! kind leaves the row out of the table, never out of the batch.

/// A batted ball's kind, as Savant's `bb_type` names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
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

    pub(crate) fn of(text: &str) -> Option<Kind> {
        (Self::ALL.iter())
            .find(|(name, _)| name.eq_ignore_ascii_case(text))
            .map(|(_, kind)| *kind)
    }

    pub(crate) fn index(self) -> usize {
        Self::ALL.iter().position(|(_, k)| *k == self).unwrap_or(0)
    }
}

/// What Savant called a row: its kind, and whether it was a home run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Called {
    pub kind: Option<Kind>,
    pub home_run: bool,
}

/// How many kinds there are.
pub(crate) const KINDS: usize = Kind::ALL.len();

/// The summary's rows: the four kinds, then the home runs.
pub(crate) const KIND_NAMES: [&str; KINDS + 1] = [
    "ground balls",
    "line drives",
    "fly balls",
    "popups",
    "home runs",
];

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
}
