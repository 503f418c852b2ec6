//! Reading CSV records (RFC 4180) from a stream without keeping more than
//! one bounded record: a line end inside quotes continues the record, and a
//! record over [`MAX_RECORD_BYTES`] is dropped.

use std::borrow::Cow;
use std::io::{self, BufRead};

/// The longest record (line) read, in bytes: a 90-column Statcast row is
/// ~1 KB. A longer one is skipped, reading on to its end without keeping it.
pub const MAX_RECORD_BYTES: usize = 64 * 1024;

/// A CSV record's fields (RFC 4180: commas inside quotes, `""` for a quote).
pub(super) fn split_fields(text: &str) -> Result<Vec<String>, &'static str> {
    let mut fields = Fields::default();
    fields.split(text)?;
    Ok((0..fields.len())
        .map(|i| fields.get(i).to_owned())
        .collect())
}

/// One record's fields, unquoted, in one buffer reused from record to
/// record (as the csv crate's `ByteRecord`), so that a row costs no
/// allocation. Not the csv crate itself: a quote opens a field here after
/// leading spaces too (`1, "a, b"` is two fields, as hand-written files
/// mean it), where csv reads the quote as text and finds three.
#[derive(Clone, Debug, Default)]
pub(super) struct Fields {
    /// The record as read; after it, the fields that had to be rebuilt (a
    /// doubled quote, text after a closing quote).
    text: String,
    /// Where each field lies in `text`: most are a piece of the record as
    /// it is (a quoted one without its quotes), copied no further.
    spans: Vec<(usize, usize)>,
}

impl Fields {
    /// Splits `record`, replacing the fields held.
    pub(super) fn split(&mut self, record: &str) -> Result<(), &'static str> {
        self.text.clear();
        self.spans.clear();
        self.text.push_str(record);
        if self.commas_unquoted(record.as_bytes()) {
            // No quotes (a batch's plain rows): the record cut at its commas.
            return Ok(());
        }
        self.spans.clear();
        let mut next = Some(0);
        while let Some(at) = next {
            next = self.field(record, at)?;
        }
        Ok(())
    }

    /// The field of `record` that starts at byte `at`, noted; where the
    /// next one starts (`None`: this was the last).
    fn field(&mut self, record: &str, at: usize) -> Result<Option<usize>, &'static str> {
        let bytes = record.as_bytes();
        // At once: a field with no quote before its comma, or one quoted
        // whole (after any spaces) with no quote doubled inside.
        let special = match bytes.get(at) {
            Some(b'"') => Some(at),
            _ => memchr::memchr2(b'"', b',', &bytes[at..]).map(|i| at + i),
        };
        match special {
            None => {
                self.spans.push((at, bytes.len()));
                return Ok(None);
            }
            Some(comma) if bytes[comma] == b',' => {
                self.spans.push((at, comma));
                return Ok(Some(comma + 1));
            }
            Some(quote) if record[at..quote].trim().is_empty() => {
                let open = quote + 1;
                let Some(close) = memchr::memchr(b'"', &bytes[open..]).map(|i| open + i) else {
                    return Err(UNTERMINATED);
                };
                match bytes.get(close + 1) {
                    None => {
                        self.spans.push((open, close));
                        return Ok(None);
                    }
                    Some(b',') => {
                        self.spans.push((open, close));
                        return Ok(Some(close + 2));
                    }
                    // A doubled quote, or text after the closing one.
                    Some(_) => {}
                }
            }
            // A quote inside the text.
            Some(_) => {}
        }
        // Rebuilt after the record, a piece at a time: quotes and commas
        // are ASCII, so the text between them is copied whole.
        let start = self.text.len();
        let mut quoted = false;
        let mut rest = &record[at..];
        loop {
            let found = if quoted {
                memchr::memchr(b'"', rest.as_bytes())
            } else {
                memchr::memchr2(b'"', b',', rest.as_bytes())
            };
            let Some(i) = found else { break };
            self.text.push_str(&rest[..i]);
            let special = rest.as_bytes()[i];
            rest = &rest[i + 1..];
            match (quoted, special) {
                (true, _) if rest.starts_with('"') => {
                    self.text.push('"');
                    rest = &rest[1..];
                }
                (true, _) => quoted = false,
                (false, b'"') if self.text[start..].trim().is_empty() => {
                    self.text.truncate(start);
                    quoted = true;
                }
                (false, b'"') => self.text.push('"'),
                (false, _) => {
                    self.spans.push((start, self.text.len()));
                    return Ok(Some(record.len() - rest.len()));
                }
            }
        }
        if quoted {
            return Err(UNTERMINATED);
        }
        self.text.push_str(rest);
        self.spans.push((start, self.text.len()));
        Ok(None)
    }

    /// Notes where `record`'s fields lie, cut at its commas, if it has no
    /// quote (else `false`, some noted). Eight bytes at a time: a row of
    /// numbers is mostly digits.
    fn commas_unquoted(&mut self, record: &[u8]) -> bool {
        let mut words = record.chunks_exact(8);
        let (mut at, mut start) = (0, 0);
        for word in &mut words {
            let word = u64::from_le_bytes(word.try_into().expect("eight bytes"));
            if bytes_equal(word, b'"') != 0 {
                return false;
            }
            let mut commas = bytes_equal(word, b',');
            while commas != 0 {
                let comma = at + commas.trailing_zeros() as usize / 8;
                self.spans.push((start, comma));
                start = comma + 1;
                commas &= commas - 1;
            }
            at += 8;
        }
        for (i, &byte) in words.remainder().iter().enumerate() {
            match byte {
                b'"' => return false,
                b',' => {
                    self.spans.push((start, at + i));
                    start = at + i + 1;
                }
                _ => {}
            }
        }
        self.spans.push((start, record.len()));
        true
    }

    pub(super) fn len(&self) -> usize {
        self.spans.len()
    }

    /// Adds a field at the end (to keep cells of many rows in one buffer).
    pub(super) fn push(&mut self, field: &str) {
        let start = self.text.len();
        self.text.push_str(field);
        self.spans.push((start, self.text.len()));
    }

    pub(super) fn clear(&mut self) {
        self.text.clear();
        self.spans.clear();
    }

    /// Field `index`, as `str::trim` leaves it: at once where it starts
    /// and ends with a visible ASCII character (a number, mostly).
    #[inline(always)]
    pub(super) fn trimmed(&self, index: usize) -> &str {
        let field = self.get(index);
        match (field.as_bytes().first(), field.as_bytes().last()) {
            (Some(first), Some(last)) if first.is_ascii_graphic() && last.is_ascii_graphic() => {
                field
            }
            _ => field.trim(),
        }
    }

    #[inline(always)]
    pub(super) fn get(&self, index: usize) -> &str {
        let (start, end) = self.spans[index];
        &self.text[start..end]
    }
}

const UNTERMINATED: &str = "an unterminated quote";

/// The high bit of each byte of `word` (little-endian) that is `byte`, the
/// others clear: exact, as no sum carries from one byte into the next.
fn bytes_equal(word: u64, byte: u8) -> u64 {
    const LOW: u64 = 0x7f7f_7f7f_7f7f_7f7f;
    let zero_where_equal = word ^ (u64::from(byte) * 0x0101_0101_0101_0101);
    // A byte's high bit: set where the byte's low bits, or its high bit, are.
    let nonzero = ((zero_where_equal & LOW) + LOW) | zero_where_equal;
    !(nonzero | LOW)
}

/// The records of a piece as text, each as `String::from_utf8_lossy` makes
/// it: their bytes checked once for all (a valid record then being a slice
/// of them, cut where its neighbours end), not one record at a time.
pub(super) struct RecordTexts<'a> {
    bytes: &'a [u8],
    /// The piece's bytes from its first record's start, if valid UTF-8.
    valid: Option<(usize, &'a str)>,
}

impl<'a> RecordTexts<'a> {
    /// The texts of the records `spans` places in `bytes`.
    pub(super) fn new(bytes: &'a [u8], spans: &[Span]) -> Self {
        let places = spans.iter().filter_map(|span| match *span {
            Span::Text { start, end, .. } => Some((start, end)),
            _ => None,
        });
        let from = places.clone().map(|(start, _)| start).min();
        let to = places.map(|(_, end)| end).max();
        let valid = from.zip(to).and_then(|(from, to)| {
            let text = std::str::from_utf8(&bytes[from..to]).ok()?;
            Some((from, text))
        });
        RecordTexts { bytes, valid }
    }

    /// The record at `start..end` of the bytes.
    pub(super) fn get(&self, start: usize, end: usize) -> Cow<'a, str> {
        // A slice of valid text cut at character boundaries is valid text.
        let slice = self
            .valid
            .and_then(|(from, text)| text.get(start - from..end - from));
        match slice {
            Some(text) => Cow::Borrowed(text),
            // A record whose bytes are not UTF-8, or that ends inside a
            // character the next one completes.
            None => String::from_utf8_lossy(&self.bytes[start..end]),
        }
    }
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
    TooLong,
    End,
}

/// Where [`Records::next_into`] put a record.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Span {
    /// Its first line's number and its bytes' place in the buffer.
    Text {
        line: usize,
        start: usize,
        end: usize,
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
        let mut bytes = std::mem::take(&mut self.bytes);
        bytes.clear();
        let span = self.next_into(&mut bytes);
        let record = match span? {
            Span::End => Record::End,
            Span::TooLong { .. } => Record::TooLong,
            Span::Text { line, .. } => Record::Text {
                line,
                text: String::from_utf8_lossy(&bytes).into_owned(),
            },
        };
        self.bytes = bytes;
        Ok(record)
    }

    /// Appends the next record's bytes (without its line end, nor the `\r`
    /// before it) to `out`, and says where they lie: the batch gathers a
    /// round of records into one buffer this way, with no allocation each.
    pub(super) fn next_into(&mut self, out: &mut Vec<u8>) -> Result<Span, Stop> {
        let start = out.len();
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
                    return Ok(Span::End);
                }
                break;
            }
            any = true;
            let (mut used, mut ended) = (available.len(), false);
            let mut at = 0;
            while let Some(found) = memchr::memchr3(b'"', b'\n', 0, &available[at..]) {
                let i = at + found;
                at = i + 1;
                match available[i] {
                    0 => {
                        return Err(Stop::Binary {
                            line: first + newlines,
                        });
                    }
                    b'"' => quoted = !quoted,
                    // Once too long, the next line end ends it whatever the
                    // quotes say, so one stray quote cannot swallow the file.
                    _ => {
                        newlines += 1;
                        if !quoted || too_long {
                            (used, ended) = (i + 1, true);
                            break;
                        }
                    }
                }
            }
            if !too_long {
                let take = if ended { used - 1 } else { used };
                if out.len() - start + take > MAX_RECORD_BYTES {
                    too_long = true;
                    out.truncate(start);
                    if !self.read_past_long {
                        return Ok(Span::TooLong { line: first });
                    }
                } else {
                    out.extend_from_slice(&available[..take]);
                }
            }
            self.reader.consume(used);
            if ended {
                break;
            }
        }
        self.line = first + newlines.max(1);
        if too_long {
            return Ok(Span::TooLong { line: first });
        }
        if out.last() == Some(&b'\r') {
            out.pop();
        }
        Ok(Span::Text {
            line: first,
            start,
            end: out.len(),
        })
    }
}
