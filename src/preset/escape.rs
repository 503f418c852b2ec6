//! Text from users' files and arguments, made safe to print.

/// `text` made safe to print on one terminal line: control characters (ESC,
/// newline, C1 codes such as U+009B), bidirectional overrides and other
/// invisible format characters are written as `\u{1b}`-style escapes, and
/// anything longer than 80 characters is cut with "…".
pub fn escape_for_terminal(text: &str) -> String {
    escape_cut(text, 80)
}

/// Escapes like [`escape_for_terminal`], cutting at `max` characters (the
/// "…" included), never inside an escape.
pub fn escape_cut(text: &str, max: usize) -> String {
    let mut out = String::new();
    let mut count = 0;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let piece = if needs_escape(c) {
            c.escape_unicode().to_string()
        } else {
            c.to_string()
        };
        let len = piece.chars().count();
        let last = chars.peek().is_none();
        // Room for this piece, and for the "…" if more follows.
        if max.saturating_sub(count) < len + usize::from(!last) {
            out.push('…');
            return out;
        }
        out += &piece;
        count += len;
    }
    out
}

fn needs_escape(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{61c}'
                | '\u{200b}'..='\u{200f}'
                | '\u{2028}'..='\u{202e}'
                | '\u{2060}'..='\u{2069}'
                | '\u{feff}'
        )
}
