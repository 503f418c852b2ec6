//! The one path every batch command takes. The input is read a round at a
//! time (whole records, back to back in one buffer); each round is cut
//! into pieces of at most [`PIECE_ROWS`] records, and every piece is
//! parsed, solved, flown and finished (written, measured) on the thread
//! pool, while the next round is read. Only reading records and taking
//! the pieces, in order, stay serial: memory stays flat however long the
//! input.

use std::io::BufRead;
use std::ops::Range;

use rayon::prelude::*;

use crate::flights::{RowFlight, Scratch, fly_chunk};
use crate::header::Header;
use crate::own_launch::SwingLaunches;
use crate::read::{Fields, Lossy, MAX_RECORD_BYTES, Read, Records};
use crate::row::{Job, Row, parse_row};
use crate::setup::Setup;
use crate::swing_solve::solve_row;

/// Records a piece holds: small enough that a round's last pieces leave
/// no thread idle for long (a few ms of flights), large enough that
/// handing one out costs nothing.
pub(crate) const PIECE_ROWS: usize = 256;
/// Records read a round, at most...
const ROUND_ROWS: usize = 8192;
/// ...and bytes (one record more at most)...
const ROUND_BYTES: usize = 1 << 20;
/// ...and rows × fences judged (each row its own fence and every park's,
/// a crossing each): many user parks make rounds of fewer rows.
const ROUND_CROSSINGS: usize = ROUND_ROWS * 31;

/// The rows of a round and of a piece for a batch judged at `parks` parks.
pub(crate) fn sizes(parks: usize) -> (usize, usize) {
    let round = (ROUND_CROSSINGS / (parks + 1)).clamp(1, ROUND_ROWS);
    (round, (round / 32).clamp(1, PIECE_ROWS))
}

/// How far each row goes before its piece is finished.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Stage {
    /// Its cells read into a scene.
    Parsed,
    /// Its swing solved too, when the setup solves swings.
    Solved,
    /// Flown to the ground and judged at its fences.
    Flown,
}

/// Records read at once, and how reading stopped after them.
#[derive(Default)]
struct Round {
    bytes: Vec<u8>,
    ends: Vec<usize>,
    records: Vec<(Read, Range<usize>, Range<usize>)>,
    /// Why reading stopped early after these records.
    stop: Option<String>,
    ended: bool,
}

impl Round {
    fn read<R: BufRead>(&mut self, records: &mut Records<R>, rows: usize) {
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

/// One piece's rows and what became of them.
#[derive(Default)]
pub(crate) struct Piece<T> {
    lossy: Lossy,
    swings: SwingLaunches,
    pub scratch: Scratch,
    pub jobs: Vec<Job>,
    /// With [`Stage::Flown`], each job's flight (or why it has none).
    pub flown: Vec<Result<RowFlight, String>>,
    /// The rows that failed: their line and why, in line order.
    pub failed: Vec<(usize, String)>,
    /// Rows answered (each given its answer by the finish).
    pub answered: usize,
    pub without_launch: usize,
    /// What the command's finish made of the piece.
    pub made: T,
}

/// How a batch went: the exit status follows from it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outcome {
    /// Rows answered (flown, measured, solved: what the command gives).
    pub answered: usize,
    pub failed: usize,
    /// Rows without a launch speed (a pitch not put in play): counted.
    pub without_launch: usize,
    /// Empty lines, skipped.
    pub empty: usize,
    /// Reading stopped early (binary input, a read error).
    pub stopped: bool,
}

impl Outcome {
    /// 0 when every row was answered (or skipped for having no launch), 1
    /// when some failed or reading stopped early.
    pub fn exit_status(&self) -> u8 {
        u8::from(self.failed > 0 || self.stopped)
    }
}

/// Bad rows named one by one; past these only counted.
const MAX_ROW_MESSAGES: usize = 100;

/// Streams every record of `records` through the pieces: each parsed and
/// taken to `stage`, then `finish`ed on the pool; `take` gets each piece
/// in order, on this thread. Bad rows are named by `note` (the first
/// hundred) and counted. `Err` where taking a piece fails (a write).
pub(crate) fn stream<R: BufRead, T: Default + Send>(
    (setup, header): (&Setup, &Header),
    records: &mut Records<R>,
    stage: Stage,
    finish: impl Fn(&mut Piece<T>) + Sync,
    mut take: impl FnMut(&mut Piece<T>) -> Result<bool, String>,
    note: &mut dyn FnMut(&str),
) -> Result<Outcome, String> {
    let mut outcome = Outcome::default();
    let (mut round, mut next) = (Round::default(), Round::default());
    let mut pieces: Vec<Piece<T>> = Vec::new();
    let (rows, piece_rows) = sizes(setup.parks.parks.len());
    round.read(records, rows);
    loop {
        // The next round is read (on this thread) while this one is worked
        // (on the pool).
        let used = round.records.len().div_ceil(piece_rows);
        if pieces.len() < used {
            pieces.resize_with(used, Piece::default);
        }
        rayon::in_place_scope(|scope| {
            scope.spawn(|_| {
                (round.records.par_chunks(piece_rows))
                    .zip(pieces.par_iter_mut())
                    .for_each(|(records, piece)| {
                        piece.work(records, &round, (setup, header), stage);
                        finish(piece);
                        // Parse failures came first; the messages go out in
                        // line order.
                        piece.failed.sort_by_key(|(line, _)| *line);
                    });
            });
            next.read(records, rows);
        });
        for piece in &mut pieces[..used] {
            for (line, reason) in &piece.failed {
                outcome.failed += 1;
                if outcome.failed <= MAX_ROW_MESSAGES {
                    note(&format!("line {line}: {reason}; skipped"));
                } else if outcome.failed == MAX_ROW_MESSAGES + 1 {
                    note("more bad rows: counted, not named");
                }
            }
            outcome.without_launch += piece.without_launch;
            if !take(piece)? {
                // The reader has what it wanted (`| head`).
                return Ok(outcome);
            }
            outcome.answered += piece.answered;
        }
        if let Some(stop) = &round.stop {
            note(&format!("{stop}; stopped reading"));
            outcome.stopped = true;
        }
        if round.ended {
            break;
        }
        std::mem::swap(&mut round, &mut next);
    }
    outcome.empty = records.empty;
    Ok(outcome)
}

impl<T> Piece<T> {
    fn work(
        &mut self,
        records: &[(Read, Range<usize>, Range<usize>)],
        round: &Round,
        (setup, header): (&Setup, &Header),
        stage: Stage,
    ) {
        self.failed.clear();
        self.jobs.clear();
        self.flown.clear();
        (self.answered, self.without_launch) = (0, 0);
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
                parse_row(
                    header,
                    setup,
                    (line, fields),
                    &mut self.swings,
                    &mut self.jobs,
                )
            };
            match row {
                Row::Job => {}
                Row::Bad { line, reason } => self.failed.push((line, reason)),
                Row::NoLaunch => self.without_launch += 1,
            }
        }
        if stage >= Stage::Solved && setup.solve_swings {
            let priors = header.priors(setup);
            (self.jobs.iter_mut()).for_each(|job| solve_row(job, setup.spray, priors));
        }
        if stage == Stage::Flown {
            fly_chunk(&self.jobs, setup, &mut self.scratch, &mut self.flown);
            for (job, flown) in self.jobs.iter().zip(&self.flown) {
                if let Err(reason) = flown {
                    self.failed.push((job.line, reason.clone()));
                }
            }
        }
    }
}
