//! Reading CSV records from a stream with the `csv` crate's own parser
//! (`csv-core`: RFC 4180 quoting; a line ends at `\r\n`, `\n` or a bare
//! `\r`), one bounded record at a time: a record over [`MAX_RECORD_BYTES`]
//! is read on to its end, quotes and all, and dropped. Lines are counted as
//! Python's `csv` module counts them (`reader.line_num`): each `\r\n`, `\n`
//! or `\r`, inside quotes too.

use std::io::{self, BufRead, Read as _};

/// Opens `source` (`-` for stdin) to be read as it comes: gzip (a
/// `.csv.gz`, pybaseball's cache, or gzip on stdin, known by its magic
/// bytes) decompressed on the way, a byte-order mark dropped however the
/// bytes arrive, and formats that are no CSV refused by name.
pub fn open(source: &str) -> Result<Box<dyn BufRead>, String> {
    let input: Box<dyn io::Read> = match source {
        "-" => Box::new(io::stdin().lock()),
        path => Box::new(std::fs::File::open(path).map_err(|e| e.to_string())?),
    };
    let (first, rest) = peek(input, 4)?;
    let input = Box::new(io::Cursor::new(first.clone()).chain(rest));
    let input: Box<dyn io::Read> = match first.as_slice() {
        [0x1f, 0x8b, ..] => Box::new(flate2::read::MultiGzDecoder::new(input)),
        b"PAR1" => {
            return Err(
                "a Parquet file, not CSV text: write it as CSV first (pandas: \
                        pd.read_parquet(f).to_csv(\"out.csv\", index=False))"
                    .to_owned(),
            );
        }
        [0x50, 0x4b, 3, 4] => {
            return Err("a zip archive, not CSV text: unzip it first".to_owned());
        }
        _ => input,
    };
    let (first, rest) = peek(input, 3)?;
    let input: Box<dyn io::Read> = match first.as_slice() {
        b"\xef\xbb\xbf" => rest,
        _ => Box::new(io::Cursor::new(first).chain(rest)),
    };
    Ok(Box::new(io::BufReader::with_capacity(
        MAX_RECORD_BYTES,
        input,
    )))
}

/// The first `n` bytes of `input` (fewer at its end), however few each read
/// gives (a pipe may give one at a time), and the input after them.
fn peek(mut input: Box<dyn io::Read>, n: usize) -> Result<(Vec<u8>, Box<dyn io::Read>), String> {
    let mut first = vec![0; n];
    let mut got = 0;
    while got < n {
        match input.read(&mut first[got..]) {
            Ok(0) => break,
            Ok(read) => got += read,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(format!("reading the input: {e}")),
        }
    }
    first.truncate(got);
    Ok((first, input))
}

/// The longest record read, in bytes as they come: a 90-column Statcast
/// row is ~1 KB. A longer one is skipped, read to its end without keeping
/// it.
pub const MAX_RECORD_BYTES: usize = 64 * 1024;

/// Why reading stopped before the end.
pub enum Stop {
    Io(io::Error),
    /// A NUL byte on this line: binary data, not CSV text.
    Binary(usize),
}

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            Stop::Io(e) => write!(f, "reading the input: {e}"),
            Stop::Binary(line) => {
                write!(f, "line {line}: a NUL byte: binary data, not CSV text")
            }
        }
    }
}

/// A record read: the line it starts on, and whether it was too long (its
/// fields then not kept).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Read {
    pub line: usize,
    pub too_long: bool,
}

/// Reads records, keeping at most [`MAX_RECORD_BYTES`] of one.
pub struct Records<R> {
    input: R,
    core: csv_core::Reader,
    /// Line ends read so far, and whether the last byte read was a `\r`
    /// (a `\n` after it ends no second line).
    lines: usize,
    after_cr: bool,
    /// Line ends with no record between them: empty lines.
    pub empty: usize,
    /// Whether the input's first bytes were looked at (for a byte-order
    /// mark: dropped here, as the parser would drop one read whole but
    /// take one read alone for the input's end).
    started: bool,
    /// Room for the parser's output, reused (a record's fields are copied
    /// out of it as they come).
    out: Vec<u8>,
    ends: Vec<usize>,
}

impl<R: BufRead> Records<R> {
    pub fn new(input: R) -> Self {
        Records {
            input,
            core: csv_core::Reader::new(),
            lines: 0,
            after_cr: false,
            empty: 0,
            started: false,
            out: vec![0; MAX_RECORD_BYTES + 2],
            ends: vec![0; MAX_RECORD_BYTES + 3],
        }
    }

    /// Reads the next record, appending its fields to `bytes` and where each
    /// ends (from the record's start) to `ends`; `None` at the end. With
    /// `read_past_long` false, a record too long is given up at once (the
    /// header: nothing useful follows, and a line-less input may not end).
    pub fn next(
        &mut self,
        bytes: &mut Vec<u8>,
        ends: &mut Vec<usize>,
        read_past_long: bool,
    ) -> Result<Option<Read>, Stop> {
        let (start, first_end) = (bytes.len(), ends.len());
        if !self.started {
            self.started = true;
            if fill(&mut self.input)?.starts_with(b"\xef\xbb\xbf") {
                self.input.consume(3);
            }
        }
        // The line ends before the record (the parser would skip them):
        // each an empty line, but the one after a `\r` it ended on.
        loop {
            let available = fill(&mut self.input)?;
            let skip = available
                .iter()
                .position(|b| !matches!(b, b'\r' | b'\n'))
                .unwrap_or(available.len());
            let before = self.lines;
            count(&mut self.lines, &mut self.after_cr, &available[..skip]).map_err(Stop::Binary)?;
            self.empty += self.lines - before;
            let ended = available.is_empty();
            self.input.consume(skip);
            if ended {
                return Ok(None);
            }
            if skip > 0 {
                continue;
            }
            break;
        }
        let line = self.lines + 1;
        let (mut taken, mut too_long) = (0, false);
        loop {
            let available = fill(&mut self.input)?;
            // Never more than the record may hold, and its line end: the
            // output fits `out`.
            let room = if too_long {
                self.out.len()
            } else {
                MAX_RECORD_BYTES + 2 - taken
            };
            let input = &available[..available.len().min(room)];
            let (result, read, written, ended) =
                self.core.read_record(input, &mut self.out, &mut self.ends);
            count(&mut self.lines, &mut self.after_cr, &input[..read]).map_err(Stop::Binary)?;
            // A record's size is its own: the line end it ended on is not.
            let line_end = matches!(result, csv_core::ReadRecordResult::Record)
                && input[..read]
                    .last()
                    .is_some_and(|b| matches!(b, b'\n' | b'\r'));
            self.input.consume(read);
            taken += read;
            if !too_long {
                bytes.extend_from_slice(&self.out[..written]);
                ends.extend_from_slice(&self.ends[..ended]);
                if taken - usize::from(line_end) > MAX_RECORD_BYTES {
                    too_long = true;
                    bytes.truncate(start);
                    ends.truncate(first_end);
                    if !read_past_long {
                        return Ok(Some(Read { line, too_long }));
                    }
                }
            }
            match result {
                csv_core::ReadRecordResult::Record => return Ok(Some(Read { line, too_long })),
                csv_core::ReadRecordResult::End => return Ok(None),
                _ => {}
            }
        }
    }
}

/// The input's next bytes (none at its end).
fn fill<R: BufRead>(input: &mut R) -> Result<&[u8], Stop> {
    loop {
        match input.fill_buf() {
            Ok(_) => break,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(Stop::Io(e)),
        }
    }
    input.fill_buf().map_err(Stop::Io)
}

/// Counts the line ends of `bytes` into `lines` (`after_cr`: the byte
/// before them was a `\r`); `Err` at a NUL byte.
fn count(lines: &mut usize, after_cr: &mut bool, bytes: &[u8]) -> Result<(), usize> {
    let mut at = 0;
    while let Some(i) = memchr::memchr3(b'\n', b'\r', 0, &bytes[at..]) {
        let byte = bytes[at + i];
        match byte {
            0 => return Err(*lines + 1),
            b'\n' if *after_cr && i == 0 => {}
            _ => *lines += 1,
        }
        *after_cr = byte == b'\r';
        at += i + 1;
    }
    if at < bytes.len() {
        *after_cr = false;
    }
    Ok(())
}

/// A record's fields as text: each a slice of the record where it is
/// UTF-8, else as `String::from_utf8_lossy` makes it.
#[derive(Clone, Copy)]
pub struct Fields<'a> {
    text: &'a str,
    ends: &'a [usize],
}

/// Where [`Fields::of`] rebuilds a record that is not UTF-8, reused.
#[derive(Default)]
pub struct Lossy {
    text: String,
    ends: Vec<usize>,
}

impl<'a> Fields<'a> {
    /// The fields of a record of `bytes` ending at `ends`.
    pub fn of(bytes: &'a [u8], ends: &'a [usize], lossy: &'a mut Lossy) -> Fields<'a> {
        if let Ok(text) = std::str::from_utf8(bytes)
            && ends.iter().all(|&end| text.is_char_boundary(end))
        {
            return Fields { text, ends };
        }
        lossy.text.clear();
        lossy.ends.clear();
        let mut start = 0;
        for &end in ends {
            lossy.text += &String::from_utf8_lossy(&bytes[start..end]);
            lossy.ends.push(lossy.text.len());
            start = end;
        }
        Fields {
            text: &lossy.text,
            ends: &lossy.ends,
        }
    }

    pub fn len(&self) -> usize {
        self.ends.len()
    }

    pub fn get(&self, index: usize) -> &'a str {
        let start = if index == 0 { 0 } else { self.ends[index - 1] };
        &self.text[start..self.ends[index]]
    }

    pub fn iter(&self) -> impl Iterator<Item = &'a str> + '_ {
        (0..self.len()).map(|i| self.get(i))
    }
}

/// The header's names (a byte-order mark dropped), `None` for an empty
/// input, or why the input is no CSV of launches.
pub(crate) fn read_header<R: BufRead>(
    records: &mut Records<R>,
) -> Result<Option<(Vec<String>, usize)>, String> {
    let (mut bytes, mut ends) = (Vec::new(), Vec::new());
    match records.next(&mut bytes, &mut ends, false) {
        Ok(None) => Ok(None),
        Ok(Some(read)) if read.too_long => Err(format!(
            "line {} (the header): longer than {} KiB: not a CSV of launches",
            read.line,
            MAX_RECORD_BYTES / 1024
        )),
        Ok(Some(read)) => {
            let mut lossy = Lossy::default();
            let fields = Fields::of(&bytes, &ends, &mut lossy);
            Ok(Some((
                fields.iter().map(str::to_owned).collect(),
                read.line,
            )))
        }
        Err(stop) => Err(stop.to_string()),
    }
}
