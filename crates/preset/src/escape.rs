//! Text from users' files and arguments, made safe to print.

/// `text` made safe to print on one terminal line: control characters (ESC,
/// newline, C1 codes such as U+009B), bidirectional overrides and other
/// invisible format characters are written as `\u{1b}`-style escapes, and
/// anything longer than 80 characters is cut with "…".
pub fn escape_for_terminal(text: &str) -> String {
    escape_cut(text, 80)
}

/// Escapes like [`escape_for_terminal`], never cutting: for text a screen
/// lays out itself (the explorer's preset names and descriptions).
pub fn escape_text(text: &str) -> String {
    escape_cut(text, usize::MAX)
}

/// Escapes like [`escape_for_terminal`], cutting at `max` characters (the
/// "…" included), never inside an escape.
pub fn escape_cut(text: &str, max: usize) -> String {
    cut_pieces(text, max, needs_escape)
}

/// `text` cut at `max` characters (the "…" included), nothing escaped: for
/// text that an error then quotes with Rust's own escapes (`{:?}`), which
/// would otherwise escape the backslashes of [`escape_cut`]'s.
pub fn cut(text: &str, max: usize) -> String {
    cut_pieces(text, max, |_| false)
}

/// The one cut: `text`, each character escaped where `escape` says, cut at
/// `max` characters with "…", never inside an escape.
fn cut_pieces(text: &str, max: usize, escape: fn(char) -> bool) -> String {
    let mut out = String::new();
    let mut count = 0;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let piece = if escape(c) {
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

/// JSON text for a terminal: each character [`needs_escape`] names, which
/// serde_json writes as it is (DEL, C1, bidi and zero-width controls; C0
/// it escapes already), written as its `\uXXXX` escape instead, which
/// JSON reads back as the same character: the value is unchanged.
pub fn json_for_terminal(json: &str) -> std::borrow::Cow<'_, str> {
    if !json.chars().any(needs_escape) {
        return json.into();
    }
    let mut out = String::with_capacity(json.len() + 16);
    for c in json.chars() {
        match needs_escape(c) && c != '\n' {
            // Every such character lies in the Basic Multilingual Plane.
            true => out += &format!("\\u{:04x}", c as u32),
            false => out.push(c),
        }
    }
    out.into()
}

/// Whether `c` is escaped: a control character (C0, DEL, C1), a
/// bidirectional control (U+061C, U+200E/F, U+202A–E, U+2066–9), a line or
/// paragraph separator, or an invisible format character (zero-width
/// spaces and joiners, word joiner, BOM).
pub fn needs_escape(c: char) -> bool {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cut_keeps_80_characters_and_marks_the_rest() {
        let long = "é".repeat(81);
        assert_eq!(cut(&long, 80), format!("{}…", "é".repeat(79)));
        assert_eq!(cut(&long[..160], 80), long[..160]);
        // Nothing escaped: the caller quotes it with its own escapes.
        assert_eq!(cut("a\x1bb", 80), "a\x1bb");
        assert_eq!(escape_cut("a\x1bb", 80), "a\\u{1b}b");
    }

    #[test]
    fn json_for_a_terminal_escapes_what_it_must_and_reads_back_the_same() {
        let json = "{\"a\":\"x\u{9b}31m\u{202e}\u{7f}\u{200b}y\"}\n";
        let escaped = json_for_terminal(json);
        assert_eq!(escaped, "{\"a\":\"x\\u009b31m\\u202e\\u007f\\u200by\"}\n");
        assert!(!escaped.chars().any(|c| needs_escape(c) && c != '\n'));
        assert_eq!(json_for_terminal("{\"a\":1}"), "{\"a\":1}");
    }

    #[test]
    fn every_bidi_control_is_escaped() {
        for c in [
            '\u{61c}', '\u{200e}', '\u{200f}', '\u{202a}', '\u{202b}', '\u{202c}', '\u{202d}',
            '\u{202e}', '\u{2066}', '\u{2067}', '\u{2068}', '\u{2069}',
        ] {
            assert!(needs_escape(c), "{c:?}");
            let shown = escape_text(&format!("a{c}b"));
            assert!(!shown.contains(c) && shown.starts_with("a\\u{"), "{shown}");
        }
        assert_eq!(escape_text("Fenway é"), "Fenway é");
    }
}
