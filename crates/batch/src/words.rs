//! The batch's words: what its notes and summary share.

/// "s" after a count other than one: "1 row", "2 rows".
pub(crate) fn plural(count: usize) -> &'static str {
    if count == 1 { "" } else { "s" }
}
