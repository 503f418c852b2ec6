//! Text fitted to a pane at word boundaries: wrapped to at most so many
//! rows, the last ending in "…" when words are left over. A word is cut
//! only when it is wider than a whole row.

use ratatui::style::Style;
use ratatui::text::{Line, Span};

/// One word: its pieces of text, each with its style, and how many spaces
/// stood before it.
#[derive(Clone, Debug)]
struct Word {
    gap: usize,
    pieces: Vec<(String, Style)>,
}

impl Word {
    fn width(&self) -> usize {
        self.pieces.iter().map(|(t, _)| cells(t)).sum()
    }
}

fn cells(text: &str) -> usize {
    Span::raw(text).width()
}

/// The words of `spans`, split at spaces; a word keeps the style of each
/// of its pieces.
fn words(spans: &[Span]) -> Vec<Word> {
    let mut words: Vec<Word> = Vec::new();
    let mut gap = 0;
    let mut open = false;
    for span in spans {
        for c in span.content.chars() {
            if c == ' ' {
                gap += 1;
                open = false;
                continue;
            }
            if !open {
                words.push(Word {
                    gap,
                    pieces: Vec::new(),
                });
                gap = 0;
                open = true;
            }
            let word = words.last_mut().expect("pushed");
            match word.pieces.last_mut() {
                Some((text, style)) if *style == span.style => text.push(c),
                _ => word.pieces.push((c.to_string(), span.style)),
            }
        }
    }
    words
}

/// A word wider than `width`, cut into rows of `width` cells.
fn split(word: Word, width: usize) -> Vec<Word> {
    let mut parts = vec![Word {
        gap: word.gap,
        pieces: Vec::new(),
    }];
    for (text, style) in word.pieces {
        for c in text.chars() {
            let part = parts.last_mut().expect("one");
            if part.width() + cells(&c.to_string()) > width && part.width() > 0 {
                parts.push(Word {
                    gap: 0,
                    pieces: Vec::new(),
                });
            }
            let part = parts.last_mut().expect("one");
            match part.pieces.last_mut() {
                Some((t, s)) if *s == style => t.push(c),
                _ => part.pieces.push((c.to_string(), style)),
            }
        }
    }
    parts
}

/// The rows `spans` wraps into at `width`: words, greedily.
fn wrap(spans: &[Span], width: usize) -> Vec<Vec<Word>> {
    let width = width.max(1);
    let mut rows: Vec<Vec<Word>> = vec![Vec::new()];
    let mut used = 0;
    for word in words(spans) {
        let pieces = if word.width() > width {
            split(word, width)
        } else {
            vec![word]
        };
        for word in pieces {
            let needed = if used == 0 {
                word.width()
            } else {
                used + word.gap + word.width()
            };
            if needed > width && used > 0 {
                rows.push(Vec::new());
                used = word.width();
            } else {
                used = needed;
            }
            rows.last_mut().expect("one").push(word);
        }
    }
    rows
}

/// How many rows `spans` takes wrapped at `width`.
pub fn rows_needed(spans: &[Span], width: usize) -> usize {
    wrap(spans, width).len()
}

/// `spans` wrapped at words into at most `rows` rows of `width` cells; if
/// words are left over, the last row ends in "…" after its last whole word.
pub fn fit(spans: &[Span], width: usize, rows: usize) -> Vec<Line<'static>> {
    let mut wrapped = wrap(spans, width);
    if rows == 0 {
        return Vec::new();
    }
    let cut = wrapped.len() > rows;
    wrapped.truncate(rows);
    let mut lines: Vec<Line<'static>> = Vec::new();
    let last = wrapped.len() - 1;
    for (k, mut row) in wrapped.into_iter().enumerate() {
        let ellipsis = cut && k == last;
        if ellipsis {
            // Drop words until "…" fits after the last one kept; a lone
            // word loses its end instead.
            let used = |row: &[Word]| {
                row.iter()
                    .enumerate()
                    .map(|(i, w)| if i == 0 { 0 } else { w.gap } + w.width())
                    .sum::<usize>()
            };
            while row.len() > 1 && used(&row) + 1 > width {
                row.pop();
            }
            if used(&row) + 1 > width
                && let Some(word) = row.first_mut()
            {
                let keep = width.saturating_sub(1);
                *word = split(word.clone(), keep.max(1)).swap_remove(0);
            }
        }
        let mut spans: Vec<Span<'static>> = Vec::new();
        for (i, word) in row.into_iter().enumerate() {
            if i > 0 {
                spans.push(Span::raw(" ".repeat(word.gap)));
            }
            spans.extend(word.pieces.into_iter().map(|(t, s)| Span::styled(t, s)));
        }
        if ellipsis {
            let style = spans.last().map_or(Style::new(), |s| s.style);
            spans.push(Span::styled("…", style));
        }
        lines.push(Line::from(spans));
    }
    lines
}

/// `text` with each space after a digit and before a character `joins`
/// takes made non-breaking: a number's groups ("208 000"), or a number and
/// its unit ("27.3 m"), then wrap together.
pub fn non_breaking(text: &str, joins: fn(char) -> bool) -> String {
    let chars: Vec<char> = text.chars().collect();
    chars
        .iter()
        .enumerate()
        .map(|(i, &c)| {
            let glue = c == ' '
                && i > 0
                && chars[i - 1].is_ascii_digit()
                && chars.get(i + 1).is_some_and(|&n| joins(n));
            if glue { '\u{a0}' } else { c }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(lines: &[Line]) -> Vec<String> {
        lines.iter().map(|l| l.to_string()).collect()
    }

    #[test]
    fn text_wraps_at_words_and_ends_in_an_ellipsis_when_cut() {
        let caption = [Span::raw("drag coefficient C_D against Reynolds number")];
        assert_eq!(
            text(&fit(&caption, 20, 3)),
            ["drag coefficient C_D", "against Reynolds", "number"]
        );
        // Two rows: the second ends after its last whole word.
        assert_eq!(
            text(&fit(&caption, 20, 2)),
            ["drag coefficient C_D", "against Reynolds…"]
        );
        assert_eq!(text(&fit(&caption, 20, 1)), ["drag coefficient…"]);
        assert_eq!(rows_needed(&caption, 20), 3);
        // Every row is within the width and no word is cut (the longest,
        // "coefficient", and "…" fit in 12).
        for width in 12..50 {
            for rows in 1..4 {
                for line in text(&fit(&caption, width, rows)) {
                    assert!(cells(&line) <= width, "{line:?} in {width}");
                    for word in line.trim_end_matches('…').split(' ') {
                        assert!(caption[0].content.split(' ').any(|w| w == word));
                    }
                }
            }
        }
    }

    #[test]
    fn styles_and_gaps_stay_and_a_word_wider_than_a_row_is_split() {
        let dim = Style::new().add_modifier(ratatui::style::Modifier::DIM);
        let note = [
            Span::styled("paper 5", dim),
            Span::raw(" · ours 4.01 m"),
            Span::styled("  range gained", dim),
        ];
        let lines = fit(&note, 40, 1);
        assert_eq!(text(&lines), ["paper 5 · ours 4.01 m  range gained"]);
        assert_eq!(lines[0].spans[0].style, dim);
        assert_eq!(text(&fit(&note, 12, 2)), ["paper 5 ·", "ours 4.01 m…"]);
        let long = [Span::raw("abcdefghijkl")];
        assert_eq!(text(&fit(&long, 5, 3)), ["abcde", "fghij", "kl"]);
        assert_eq!(text(&fit(&long, 5, 1)), ["abcd…"]);
    }
}
