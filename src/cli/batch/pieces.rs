//! The batch's parallel work. The input is read a round at a time (whole
//! records, back to back in one buffer); each round is cut into pieces of
//! [`PIECE_ROWS`] records, and every piece is parsed, flown and written
//! into its own byte buffer on the thread pool, while the next round is
//! read. Only reading records and writing the pieces' bytes, in order,
//! stay serial; buffers are kept from round to round, so a row costs no
//! allocation (but a failed row's message and a JSON line).

use std::io::BufRead;

use rayon::prelude::*;

use super::flights::{Printed, RowFlight, Scratch, fly_chunk};
use super::output::{CsvLine, json_line};
use super::own_launch::SwingLaunches;
use super::records::{Fields, MAX_RECORD_BYTES, RecordTexts, Records, Span, Stop};
use super::rows::{Header, Job, Row, parse_row};
use super::savant_columns::{Setup, Summary};
use crate::cli::progress::Progress;

/// Records a piece holds: small enough that a round's last pieces leave
/// no thread idle for long (a few ms of flights), large enough that
/// handing one out costs nothing.
pub(super) const PIECE_ROWS: usize = 256;
/// Records read a round, at most...
const ROUND_ROWS: usize = 8192;
/// ...and bytes (one record more at most): memory stays flat however long
/// the input.
const ROUND_BYTES: usize = 1 << 20;

/// Records read at once, and how reading stopped after them.
#[derive(Default)]
pub(super) struct Round {
    text: Vec<u8>,
    spans: Vec<Span>,
    /// Why reading stopped early after these records (a note to say).
    pub stop: Option<String>,
    /// No records follow.
    pub ended: bool,
}

impl Round {
    /// Reads the next round of records (none once the input has ended).
    pub(super) fn read<R: BufRead>(&mut self, records: &mut Records<R>) {
        self.text.clear();
        self.spans.clear();
        self.stop = None;
        while !self.ended && self.spans.len() < ROUND_ROWS && self.text.len() < ROUND_BYTES {
            match records.next_into(&mut self.text) {
                Ok(Span::End) => self.ended = true,
                Ok(span) => self.spans.push(span),
                Err(stop) => {
                    self.stop = Some(match stop {
                        Stop::Binary { line } => {
                            format!("line {line}: a NUL byte: binary data, not CSV text")
                        }
                        Stop::Io(e) => format!("reading the input: {e}"),
                    });
                    self.ended = true;
                }
            }
        }
    }
}

/// What every piece shares.
pub(super) struct Context<'a> {
    pub header: &'a Header,
    pub setup: &'a Setup<'a>,
    pub printed: Printed,
    pub progress: &'a Progress,
}

/// One piece's work and what it made.
#[derive(Default)]
pub(super) struct Piece {
    fields: Fields,
    kept: Fields,
    jobs: Vec<Job>,
    swings: SwingLaunches,
    flown: Vec<Result<RowFlight, String>>,
    scratch: Scratch,
    /// The rows' output, in order.
    pub out: Vec<u8>,
    /// The rows that failed: their line and why, in line order.
    pub failed: Vec<(usize, String)>,
    pub flown_rows: usize,
    pub without_launch: usize,
    pub empty: usize,
    /// Rows flown a second time, at the readout's precision.
    pub refined: usize,
    pub summary: Summary,
}

/// Parses, flies and writes every piece of `round`, in parallel, into
/// `pieces` (grown as needed); how many it used, from the first.
pub(super) fn work(round: &Round, pieces: &mut Vec<Piece>, context: &Context) -> usize {
    let used = round.spans.len().div_ceil(PIECE_ROWS);
    if pieces.len() < used {
        pieces.resize_with(used, Piece::default);
    }
    round
        .spans
        .par_chunks(PIECE_ROWS)
        .zip(pieces.par_iter_mut())
        .for_each(|(spans, piece)| piece.work(spans, &round.text, context));
    used
}

impl Piece {
    fn work(&mut self, spans: &[Span], text: &[u8], context: &Context) {
        let (header, setup) = (context.header, context.setup);
        self.out.clear();
        self.failed.clear();
        self.jobs.clear();
        self.kept.clear();
        (self.flown_rows, self.without_launch, self.empty) = (0, 0, 0);
        self.summary = Summary::new(setup.parks.parks.len());
        let texts = RecordTexts::new(text, spans);
        for span in spans {
            let row = match *span {
                Span::Text { line, start, end } => {
                    let record = texts.get(start, end);
                    // With --own-air each park's flight takes the launch
                    // its swing gives in that park's air: left to it.
                    let swings = (!setup.own_air).then_some(&mut self.swings);
                    parse_row(
                        header,
                        setup,
                        (line, &record),
                        (&mut self.fields, &mut self.kept),
                        swings,
                        &mut self.jobs,
                    )
                }
                Span::TooLong { line } => Row::Bad {
                    line,
                    reason: format!("longer than {} KiB", MAX_RECORD_BYTES / 1024),
                },
                Span::End => continue,
            };
            match row {
                Row::Job => {}
                Row::Bad { line, reason } => self.failed.push((line, reason)),
                Row::NoLaunch => self.without_launch += 1,
                Row::Blank => self.empty += 1,
            }
        }
        fly_chunk(
            &self.jobs,
            setup,
            context.printed,
            &mut self.scratch,
            &mut self.flown,
        );
        self.refined = self.scratch.refined;
        let csv = CsvLine {
            setup,
            shown: context.printed.shown,
            statcast: context.printed.statcast,
        };
        let mut kept: Vec<&str> = Vec::with_capacity(setup.keep.len());
        for (job, flown) in self.jobs.iter().zip(&self.flown) {
            let flown = match flown {
                Ok(flown) => flown,
                Err(reason) => {
                    self.failed.push((job.line, reason.clone()));
                    continue;
                }
            };
            kept.clear();
            kept.extend(job.kept.clone().map(|i| self.kept.get(i)));
            if context.printed.json {
                let parks = setup.parks.parks.len();
                let cleared = &self.scratch.cleared[flown.cleared_from..][..parks];
                json_line(&mut self.out, job, flown, cleared, &kept, setup);
            } else {
                csv.write(&mut self.out, job, flown, &kept);
            }
            self.summary.count(job, header, flown.flights);
            self.flown_rows += 1;
            context.progress.tick();
        }
        // Parse failures came first; the messages go out in line order.
        self.failed.sort_by_key(|(line, _)| *line);
    }
}
