//! The one table renderer: a [`Table`] as aligned text, as CSV, or as JSON
//! objects (one per row). Every command that prints a table goes through it.

pub use crate::analysis::figures::Cell;

/// Where a field sits in its column, in text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    Left,
    Right,
}

/// How wide a column is, in text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Width {
    /// As wide as its widest field or heading: the column lines up.
    Fit,
    /// Each field padded to at least this many characters on its own line.
    AtLeast(usize),
}

/// How a number is written in text (CSV and JSON keep every digit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Digits {
    /// This many decimals.
    Fixed(usize),
    /// The shortest text that reads back as the same number.
    Shortest,
    /// Six decimals without trailing zeros.
    Trimmed,
}

/// One column: its name for CSV and JSON, its heading and layout for text.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// The CSV header and JSON field; `None`: text only.
    pub key: Option<String>,
    /// The text heading; `None`: CSV and JSON only.
    pub head: Option<String>,
    pub digits: Digits,
    pub align: Align,
    pub width: Width,
    /// What stands between this column and the one before it, in text.
    pub gap: &'static str,
}

impl Column {
    /// A column in every format, at least `width` wide and right-aligned in text.
    pub fn right(key: &str, head: &str, width: usize, digits: Digits) -> Column {
        Column {
            key: Some(key.to_owned()),
            head: Some(head.to_owned()),
            digits,
            align: Align::Right,
            width: Width::AtLeast(width),
            gap: " ",
        }
    }

    /// A column in text only.
    pub fn text(head: &str, width: Width, align: Align, gap: &'static str) -> Column {
        Column {
            key: None,
            head: Some(head.to_owned()),
            digits: Digits::Shortest,
            align,
            width,
            gap,
        }
    }

    /// A column in CSV and JSON only.
    pub fn data(key: &str) -> Column {
        Column {
            key: Some(key.to_owned()),
            head: None,
            digits: Digits::Shortest,
            align: Align::Right,
            width: Width::AtLeast(0),
            gap: "",
        }
    }

    /// With `gap` before it in text.
    pub fn after(self, gap: &'static str) -> Column {
        Column { gap, ..self }
    }

    fn field(&self, cell: &Cell) -> String {
        match cell {
            Cell::Num(x) => match self.digits {
                Digits::Fixed(decimals) => format!("{x:.decimals$}"),
                Digits::Shortest => x.to_string(),
                Digits::Trimmed => crate::analysis::figures::trimmed(*x),
            },
            Cell::Text(t) => t.clone(),
            Cell::Bool(b) => b.to_string(),
            Cell::Blank => String::new(),
        }
    }
}

/// The columns a text takes on a terminal: a combining mark (the hat of
/// V̂) takes none, so counting characters would misalign the column.
fn shown_width(text: &str) -> usize {
    unicode_width::UnicodeWidthStr::width(text)
}

/// Rows of CSV written as one piece (in parallel, piece by piece, when
/// there are more).
const CSV_PIECE: usize = 256;

/// Rows of cells under columns: one cell per column, in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    pub columns: Vec<Column>,
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// The headings and the rows, aligned; no line ends in spaces.
    pub fn text(&self) -> String {
        self.lines(true)
    }

    /// The rows alone, aligned as in [`Table::text`].
    pub fn text_rows(&self) -> String {
        self.lines(false)
    }

    fn lines(&self, headings: bool) -> String {
        let shown: Vec<usize> = (0..self.columns.len())
            .filter(|&k| self.columns[k].head.is_some())
            .collect();
        let heads: Vec<String> = shown
            .iter()
            .map(|&k| self.columns[k].head.clone().unwrap_or_default())
            .collect();
        let cells: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|row| {
                shown
                    .iter()
                    .map(|&k| self.columns[k].field(&row[k]))
                    .collect()
            })
            .collect();
        let widths: Vec<usize> = shown
            .iter()
            .enumerate()
            .map(|(n, &k)| match self.columns[k].width {
                Width::AtLeast(width) => width,
                Width::Fit => cells
                    .iter()
                    .map(|row| shown_width(&row[n]))
                    .chain(headings.then(|| shown_width(&heads[n])))
                    .max()
                    .unwrap_or(0),
            })
            .collect();
        let line = |fields: &[String]| -> String {
            let mut text = String::new();
            for (n, field) in fields.iter().enumerate() {
                let column = &self.columns[shown[n]];
                let pad = " ".repeat(widths[n].saturating_sub(shown_width(field)));
                if n > 0 {
                    text.push_str(column.gap);
                }
                match column.align {
                    Align::Right => text.push_str(&(pad + field)),
                    Align::Left => text.push_str(&(field.clone() + &pad)),
                }
            }
            text.trim_end().to_owned() + "\n"
        };
        let mut out = if headings {
            line(&heads)
        } else {
            String::new()
        };
        for row in &cells {
            out.push_str(&line(row));
        }
        out
    }

    /// A header of keys, then one line per row; a label with a comma or a
    /// quote is quoted.
    pub fn csv(&self) -> String {
        let keyed: Vec<usize> = (0..self.columns.len())
            .filter(|&k| self.columns[k].key.is_some())
            .collect();
        let line = |fields: Vec<String>| fields.join(",") + "\n";
        let mut out = line(
            keyed
                .iter()
                .map(|&k| self.columns[k].key.clone().unwrap_or_default())
                .collect(),
        );
        // Rows written straight into one text per piece, the pieces in
        // parallel and joined in order: a 64×64 surface's 4096 rows of
        // shortest-form numbers, a field at a time through a String each,
        // took a quarter of `homerun surface --csv`.
        let piece = |rows: &[Vec<Cell>]| {
            use std::fmt::Write;
            let mut text = String::with_capacity(rows.len() * 16 * keyed.len());
            for row in rows {
                for (i, &k) in keyed.iter().enumerate() {
                    if i > 0 {
                        text.push(',');
                    }
                    match &row[k] {
                        Cell::Num(x) => {
                            let _ = write!(text, "{x}");
                        }
                        Cell::Text(t) if t.contains([',', '"']) => {
                            text.push('"');
                            text.push_str(&t.replace('"', "\"\""));
                            text.push('"');
                        }
                        Cell::Text(t) => text.push_str(t),
                        Cell::Bool(b) => {
                            let _ = write!(text, "{b}");
                        }
                        Cell::Blank => {}
                    }
                }
                text.push('\n');
            }
            text
        };
        // One piece is written here: the first parallel call starts
        // rayon's threads, which cost a short table more than its rows.
        if self.rows.len() <= CSV_PIECE {
            return out + &piece(&self.rows);
        }
        use rayon::prelude::*;
        let pieces: Vec<String> = self.rows.par_chunks(CSV_PIECE).map(piece).collect();
        for text in pieces {
            out.push_str(&text);
        }
        out
    }

    /// One JSON object per row, keyed by the columns' keys; a blank is null.
    pub fn json_rows(&self) -> Vec<serde_json::Value> {
        self.rows
            .iter()
            .map(|row| {
                let object: serde_json::Map<String, serde_json::Value> = self
                    .columns
                    .iter()
                    .zip(row)
                    .filter_map(|(c, cell)| {
                        let value = match cell {
                            Cell::Num(x) => serde_json::json!(x),
                            Cell::Text(t) => serde_json::json!(t),
                            Cell::Bool(b) => serde_json::json!(b),
                            Cell::Blank => serde_json::Value::Null,
                        };
                        Some((c.key.clone()?, value))
                    })
                    .collect();
                serde_json::Value::Object(object)
            })
            .collect()
    }
}

/// Text without the padding that empty columns leave at line ends.
pub fn trim_lines(text: &str) -> String {
    text.lines()
        .map(|l| l.trim_end().to_owned() + "\n")
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fitted_and_fixed_columns() {
        let table = Table {
            columns: vec![
                Column {
                    align: Align::Left,
                    ..Column::right("x", "x", 0, Digits::Fixed(1))
                },
                Column::right("y", "why", 5, Digits::Trimmed),
                Column::data("z"),
                Column::text("", Width::Fit, Align::Left, " "),
            ],
            rows: vec![
                vec![
                    Cell::Num(1.24),
                    Cell::Num(0.5),
                    Cell::Num(3.0),
                    Cell::Text("a,\"b\"".into()),
                ],
                vec![Cell::Num(10.0), Cell::Num(2.0), Cell::Blank, Cell::Blank],
            ],
        };
        assert_eq!(table.text(), "x   why\n1.2   0.5 a,\"b\"\n10.0     2\n");
        assert_eq!(table.csv(), "x,y,z\n1.24,0.5,3\n10,2,\n");
        assert_eq!(
            serde_json::Value::Array(table.json_rows()).to_string(),
            r#"[{"x":1.24,"y":0.5,"z":3.0},{"x":10.0,"y":2.0,"z":null}]"#
        );
    }

    /// Fitted columns line up by what a terminal shows (V̂ is one column
    /// wide, two characters), and a field longer than any before (a key
    /// name of 60 characters) widens its column instead of touching the next.
    #[test]
    fn fitted_columns_keep_their_gap_whatever_their_width() {
        let column = |head| Column::text(head, Width::Fit, Align::Left, "  ");
        let long = "environment.".repeat(5);
        let table = Table {
            columns: vec![column("key"), column("symbol"), column("unit")],
            rows: vec![
                vec![
                    Cell::Text(long.clone()),
                    Cell::Text("V̂_b0".into()),
                    Cell::Text("m/s".into()),
                ],
                vec![
                    Cell::Text("x".into()),
                    Cell::Text("ω_b0".into()),
                    Cell::Text("rad/s".into()),
                ],
            ],
        };
        let pad = " ".repeat(long.len() - 3);
        assert_eq!(
            table.text(),
            format!(
                "key{pad}  symbol  unit\n{long}  V̂_b0    m/s\nx{}  ω_b0    rad/s\n",
                " ".repeat(long.len() - 1)
            )
        );
    }
}
