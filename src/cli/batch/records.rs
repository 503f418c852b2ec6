//! Reading CSV records (RFC 4180) from a stream without keeping more than
//! one bounded record: a line end inside quotes continues the record, and a
//! record over [`MAX_RECORD_BYTES`] is dropped.

use std::io::{self, BufRead};

/// The longest record (line) read, in bytes: a 90-column Statcast row is
/// ~1 KB. A longer one is skipped, reading on to its end without keeping it.
pub const MAX_RECORD_BYTES: usize = 64 * 1024;

/// A CSV record's fields (RFC 4180: commas inside quotes, `""` for a quote).
pub(super) fn split_fields(text: &str) -> Result<Vec<String>, &'static str> {
    let mut fields = Vec::new();
    let mut field = String::new();
    let mut chars = text.chars().peekable();
    let mut quoted = false;
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            (true, '"') => quoted = false,
            (true, c) => field.push(c),
            (false, '"') if field.trim().is_empty() => {
                field.clear();
                quoted = true;
            }
            (false, ',') => fields.push(std::mem::take(&mut field)),
            (false, c) => field.push(c),
        }
    }
    if quoted {
        return Err("an unterminated quote");
    }
    fields.push(field);
    Ok(fields)
}

/// Why reading stopped before the end.
pub(super) enum Stop {
    Io(io::Error),
    /// A NUL byte: binary data, not CSV text.
    Binary {
        line: usize,
    },
}

/// One record of the input.
pub(super) enum Record {
    /// Its first line's number and its text (without the line end).
    Text {
        line: usize,
        text: String,
    },
    /// Longer than [`MAX_RECORD_BYTES`]: read to its end and dropped.
    TooLong {
        line: usize,
    },
    End,
}

/// Reads records, each ending at a line end outside quotes, keeping at most
/// [`MAX_RECORD_BYTES`] of one.
pub(super) struct Records<R> {
    reader: R,
    /// The line the next record starts on (1-based).
    pub(super) line: usize,
    bytes: Vec<u8>,
    /// Whether a record too long is read on to its end (a row: the next
    /// row follows) or given up at once (the header: nothing follows that
    /// could be used, and a line-less input may never end).
    pub(super) read_past_long: bool,
}

impl<R: BufRead> Records<R> {
    pub(super) fn new(reader: R) -> Self {
        Records {
            reader,
            line: 1,
            bytes: Vec::new(),
            read_past_long: true,
        }
    }

    pub(super) fn next(&mut self) -> Result<Record, Stop> {
        self.bytes.clear();
        let first = self.line;
        let (mut quoted, mut too_long, mut newlines, mut any) = (false, false, 0, false);
        loop {
            let available = match self.reader.fill_buf() {
                Ok(bytes) => bytes,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(Stop::Io(e)),
            };
            if available.is_empty() {
                if !any {
                    return Ok(Record::End);
                }
                break;
            }
            any = true;
            let (mut used, mut ended) = (available.len(), false);
            for (i, &byte) in available.iter().enumerate() {
                match byte {
                    0 => {
                        return Err(Stop::Binary {
                            line: first + newlines,
                        });
                    }
                    b'"' => quoted = !quoted,
                    // Once too long, the next line end ends it whatever the
                    // quotes say, so one stray quote cannot swallow the file.
                    b'\n' => {
                        newlines += 1;
                        if !quoted || too_long {
                            (used, ended) = (i + 1, true);
                            break;
                        }
                    }
                    _ => {}
                }
            }
            if !too_long {
                let take = if ended { used - 1 } else { used };
                if self.bytes.len() + take > MAX_RECORD_BYTES {
                    too_long = true;
                    self.bytes = Vec::new();
                    if !self.read_past_long {
                        return Ok(Record::TooLong { line: first });
                    }
                } else {
                    self.bytes.extend_from_slice(&available[..take]);
                }
            }
            self.reader.consume(used);
            if ended {
                break;
            }
        }
        self.line = first + newlines.max(1);
        if too_long {
            return Ok(Record::TooLong { line: first });
        }
        let text = String::from_utf8_lossy(&self.bytes);
        let text = text.strip_suffix('\r').unwrap_or(&text).to_owned();
        Ok(Record::Text { line: first, text })
    }
}
