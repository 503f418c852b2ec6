//! Numbers as the explorer writes them: the inputs pane shows a value this
//! way, and an edit starts from the same text.

use crate::model::keys::Key;

/// A value as the inputs pane shows it: enough digits for a thousandth of
/// the key's step, trailing zeros trimmed.
pub fn format_value(key: &Key, value: f64) -> String {
    let decimals = ((-key.step.log10()).ceil() as i32 + 3).clamp(0, 12) as usize;
    let text = format!("{value:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    };
    if text == "-0" { "0".to_owned() } else { text }
}
