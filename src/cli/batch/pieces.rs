//! The batch's parallel work. The input is read a round at a time (whole
//! records, back to back in one buffer); each round is cut into pieces of
//! [`PIECE_ROWS`] records, and every piece is parsed, flown and written
//! into its own byte buffer on the thread pool, while the next round is
//! read. Only reading records and writing the pieces' bytes, in order,
//! stay serial.

use std::io::BufRead;
use std::ops::Range;

use rayon::prelude::*;

use super::flights::{RowFlight, Scratch, fly_chunk};
use super::output::{CsvLine, Tally, json_line};
use super::own_launch::SwingLaunches;
use super::read::{Fields, Lossy, MAX_RECORD_BYTES, Read, Records};
use super::rows::{Header, Job, Row, parse_row};
use super::savant_columns::{Setup, Summary};
use super::swing_columns::solve_row;
use crate::cli::progress::Progress;

/// Records a piece holds: small enough that a round's last pieces leave
/// no thread idle for long (a few ms of flights), large enough that
/// handing one out costs nothing.
pub(super) const PIECE_ROWS: usize = 256;
/// Records read a round, at most...
const ROUND_ROWS: usize = 8192;
/// ...and bytes (one record more at most): memory stays flat however long
/// the input...
const ROUND_BYTES: usize = 1 << 20;
/// ...and rows × fences judged (each row its own fence and every park's,
/// a crossing each): many user parks make rounds of fewer rows.
const ROUND_CROSSINGS: usize = ROUND_ROWS * 31;

/// The rows of a round and of a piece for a batch judged at `parks` parks.
pub(super) fn sizes(parks: usize) -> (usize, usize) {
    let round = (ROUND_CROSSINGS / (parks + 1)).clamp(1, ROUND_ROWS);
    (round, (round / 32).clamp(1, PIECE_ROWS))
}

/// Records read at once, and how reading stopped after them.
#[derive(Default)]
pub(super) struct Round {
    /// The records' fields, back to back, and where each field ends (from
    /// its record's start).
    bytes: Vec<u8>,
    ends: Vec<usize>,
    records: Vec<(Read, Range<usize>, Range<usize>)>,
    /// Why reading stopped early after these records (a note to say).
    pub stop: Option<String>,
    /// No records follow.
    pub ended: bool,
}

impl Round {
    /// Reads the next round of records (none once the input has ended).
    pub(super) fn read<R: BufRead>(&mut self, records: &mut Records<R>, rows: usize) {
        self.bytes.clear();
        self.ends.clear();
        self.records.clear();
        self.stop = None;
        while !self.ended && self.records.len() < rows && self.bytes.len() < ROUND_BYTES {
            let (bytes, ends) = (self.bytes.len(), self.ends.len());
            match records.next(&mut self.bytes, &mut self.ends, true) {
                Ok(Some(read)) => {
                    let places = (bytes..self.bytes.len(), ends..self.ends.len());
                    self.records.push((read, places.0, places.1));
                }
                Ok(None) => self.ended = true,
                Err(stop) => {
                    self.stop = Some(stop.to_string());
                    self.ended = true;
                }
            }
        }
    }
}

/// What the output prints of a row.
#[derive(Clone, Copy)]
pub(super) struct Printed {
    pub shown: crate::cli::shown::Shown,
    /// The `difference` column (range less Statcast's) is printed.
    pub statcast: bool,
    pub json: bool,
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
    lossy: Lossy,
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
    pub summary: Summary,
    /// The rows' outcomes and differences, for the batch's summary.
    pub tally: Tally,
}

/// Parses, flies and writes every piece of `round`, in parallel, into
/// `pieces` (grown as needed); how many it used, from the first.
pub(super) fn work(round: &Round, pieces: &mut Vec<Piece>, context: &Context) -> usize {
    let rows = sizes(context.setup.parks.parks.len()).1;
    let used = round.records.len().div_ceil(rows);
    if pieces.len() < used {
        pieces.resize_with(used, Piece::default);
    }
    round
        .records
        .par_chunks(rows)
        .zip(pieces.par_iter_mut())
        .for_each(|(records, piece)| piece.work(records, round, context));
    used
}

impl Piece {
    fn work(
        &mut self,
        records: &[(Read, Range<usize>, Range<usize>)],
        round: &Round,
        context: &Context,
    ) {
        let (header, setup) = (context.header, context.setup);
        self.out.clear();
        self.failed.clear();
        self.jobs.clear();
        (self.flown_rows, self.without_launch) = (0, 0);
        self.summary = Summary::new(setup.parks.parks.len());
        self.tally = Tally::default();
        for (read, bytes, ends) in records {
            let line = read.line;
            let row = if read.too_long {
                Row::Bad {
                    line,
                    reason: format!("longer than {} KiB", MAX_RECORD_BYTES / 1024),
                }
            } else {
                let fields = Fields::of(
                    &round.bytes[bytes.clone()],
                    &round.ends[ends.clone()],
                    &mut self.lossy,
                );
                // With --own-air each park's flight takes the launch its
                // swing gives in that park's air: left to it.
                let swings = (!setup.own_air).then_some(&mut self.swings);
                parse_row(header, setup, (line, fields), swings, &mut self.jobs)
            };
            match row {
                Row::Job => {}
                Row::Bad { line, reason } => self.failed.push((line, reason)),
                Row::NoLaunch => self.without_launch += 1,
            }
        }
        if setup.solve_swings {
            self.jobs
                .iter_mut()
                .for_each(|job| solve_row(job, setup.spray, setup.tilt_prior(header)));
        }
        fly_chunk(&self.jobs, setup, &mut self.scratch, &mut self.flown);
        let csv = CsvLine {
            setup,
            shown: context.printed.shown,
            statcast: context.printed.statcast,
        };
        for (job, flown) in self.jobs.iter().zip(&self.flown) {
            let flown = match flown {
                Ok(flown) => flown,
                Err(reason) => {
                    self.failed.push((job.line, reason.clone()));
                    continue;
                }
            };
            let parks = setup.parks.parks.len();
            let judged = if setup.all_parks {
                &self.scratch.clearings[flown.cleared_from..][..parks]
            } else {
                &[]
            };
            if context.printed.json {
                let cleared = &self.scratch.cleared[flown.cleared_from..][..parks];
                json_line(&mut self.out, job, flown, (cleared, judged), setup);
            } else {
                csv.write(&mut self.out, job, flown, judged);
            }
            self.summary
                .count(job, header, (flown.flights, flown.direction_from));
            self.tally.count(job, flown);
            self.flown_rows += 1;
            context.progress.tick();
        }
        // Parse failures came first; the messages go out in line order.
        self.failed.sort_by_key(|(line, _)| *line);
    }
}
