//! The one path every batch command takes. The input is read a piece at
//! a time (at most [`PIECE_ROWS`] whole records, back to back in the
//! piece's own buffer), and each piece is parsed, solved, flown and
//! finished (written, measured) on the thread pool as soon as it is read,
//! while the reading goes on; the pieces are taken, in order, as they
//! come back. Only reading records and taking the pieces stay serial, and
//! no thread waits for another's last piece: memory stays flat however
//! long the input (a bounded number of pieces in flight).

use std::collections::BTreeMap;
use std::io::BufRead;
use std::ops::Range;
use std::panic::{self, AssertUnwindSafe};
use std::sync::mpsc;

use crate::flights::{RowFlight, Scratch, fly_chunk};
use crate::header::Header;
use crate::own_launch::SwingLaunches;
use crate::read::{Fields, Lossy, MAX_RECORD_BYTES, Read, Records};
use crate::row::{Job, Row, parse_row};
use crate::setup::Setup;
use crate::swing_solve::solve_row;

/// Records a piece holds: small enough that the last pieces leave no
/// thread idle for long (a few ms of flights), large enough that handing
/// one out costs nothing.
pub(crate) const PIECE_ROWS: usize = 256;
/// Records in flight at once, at most...
const IN_FLIGHT_ROWS: usize = 8192;
/// ...and bytes a piece reads (one record more at most)...
const PIECE_BYTES: usize = 1 << 18;
/// ...and rows × fences judged (each row its own fence and every park's,
/// a crossing each): many user parks make fewer rows in flight.
const IN_FLIGHT_CROSSINGS: usize = IN_FLIGHT_ROWS * 31;

/// The rows in flight at most, and a piece's, for a batch judged at
/// `parks` parks.
pub(crate) fn sizes(parks: usize) -> (usize, usize) {
    let rows = (IN_FLIGHT_CROSSINGS / (parks + 1)).clamp(1, IN_FLIGHT_ROWS);
    (rows, (rows / 32).clamp(1, PIECE_ROWS))
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

/// A piece's records as read, and how reading stopped after them.
#[derive(Default)]
struct Input {
    bytes: Vec<u8>,
    ends: Vec<usize>,
    records: Vec<(Read, Range<usize>, Range<usize>)>,
    /// Why reading stopped early after these records.
    stop: Option<String>,
    /// The input ended with these records (or stopped).
    ended: bool,
}

impl Input {
    fn read<R: BufRead>(&mut self, records: &mut Records<R>, rows: usize) {
        self.bytes.clear();
        self.ends.clear();
        self.records.clear();
        (self.stop, self.ended) = (None, false);
        while !self.ended && self.records.len() < rows && self.bytes.len() < PIECE_BYTES {
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
    input: Input,
    lossy: Lossy,
    swings: SwingLaunches,
    pub scratch: Scratch,
    pub jobs: Vec<Job>,
    /// With [`Stage::Flown`], each job's flight (or why it has none).
    pub flown: Vec<Result<RowFlight, String>>,
    /// The rows that failed: their line and why, in line order.
    pub failed: Vec<(usize, String)>,
    /// Rows answered with a cell left out, named: their line and why.
    pub noted: Vec<(usize, String)>,
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

/// "3 of 248 rows failed and were skipped (exit status 1)": the closing
/// word on `failed` rows of `rows`, every command's.
pub fn rows_failed(failed: usize, rows: usize) -> String {
    format!(
        "{failed} of {rows} row{} failed and were skipped (exit status 1)",
        crate::words::plural(rows)
    )
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
    let (rows, piece_rows) = sizes(setup.parks.parks.len());
    let most_in_flight = rows.div_ceil(piece_rows);
    // Pieces come back as they are done; each is taken in its turn.
    let (done, back) = mpsc::channel::<(usize, Worked<T>)>();
    let mut spare: Vec<Box<Piece<T>>> = Vec::new();
    let mut waiting: BTreeMap<usize, Box<Piece<T>>> = BTreeMap::new();
    let (mut sent, mut taken, mut noted) = (0, 0, 0);
    let mut ended = false;
    let finish = &finish;
    let taking = rayon::in_place_scope(|scope| -> Result<(), String> {
        loop {
            if !ended && sent - taken < most_in_flight {
                // Read the next piece (on this thread) and send it to the pool.
                let mut piece = spare.pop().unwrap_or_default();
                piece.input.read(records, piece_rows);
                ended = piece.input.ended;
                let (done, number) = (done.clone(), sent);
                sent += 1;
                scope.spawn(move |_| {
                    // A panic comes back as the piece's answer, so that
                    // no one waits for it (and it goes on from there).
                    let worked = panic::catch_unwind(AssertUnwindSafe(move || {
                        piece.work((setup, header), stage);
                        finish(&mut piece);
                        // Parse failures came first; the messages go out
                        // in line order.
                        piece.failed.sort_by_key(|(line, _)| *line);
                        piece
                    }));
                    let _ = done.send((number, worked));
                });
            } else if taken == sent {
                return Ok(());
            } else {
                let (number, worked) = wait(&back)?;
                waiting.insert(number, worked.unwrap_or_else(|p| panic::resume_unwind(p)));
            }
            while let Ok((number, worked)) = back.try_recv() {
                waiting.insert(number, worked.unwrap_or_else(|p| panic::resume_unwind(p)));
            }
            while let Some(mut piece) = waiting.remove(&taken) {
                taken += 1;
                for (line, reason) in &piece.failed {
                    outcome.failed += 1;
                    if outcome.failed <= MAX_ROW_MESSAGES {
                        note(&format!("line {line}: {reason}; skipped"));
                    } else if outcome.failed == MAX_ROW_MESSAGES + 1 {
                        note("more bad rows: counted, not named");
                    }
                }
                for (line, reason) in &piece.noted {
                    noted += 1;
                    if noted <= MAX_ROW_MESSAGES {
                        note(&format!("line {line}: {reason}; its swing not solved"));
                    } else if noted == MAX_ROW_MESSAGES + 1 {
                        note("more tracking cells outside their range: counted, not named");
                    }
                }
                outcome.without_launch += piece.without_launch;
                if !take(&mut piece)? {
                    // The reader has what it wanted (`| head`): the
                    // pieces in flight end unread.
                    return Ok(());
                }
                outcome.answered += piece.answered;
                if let Some(stop) = &piece.input.stop {
                    note(&format!("{stop}; stopped reading"));
                    outcome.stopped = true;
                }
                spare.push(piece);
            }
        }
    });
    taking?;
    outcome.empty = records.empty;
    Ok(outcome)
}

/// A piece worked on the pool, or the panic that stopped it.
type Worked<T> = std::thread::Result<Box<Piece<T>>>;

/// The next piece to come back. On one of the pool's own threads (a
/// batch run from inside the pool), the pool's pending work is done
/// meanwhile, so that a pool of one thread cannot wait on itself.
fn wait<P>(back: &mpsc::Receiver<P>) -> Result<P, String> {
    loop {
        if let Ok(piece) = back.try_recv() {
            return Ok(piece);
        }
        if rayon::yield_now() != Some(rayon::Yield::Executed) {
            // Nothing pending: every piece out is on another thread.
            return back.recv().map_err(|e| e.to_string());
        }
    }
}

impl<T> Piece<T> {
    fn work(&mut self, (setup, header): (&Setup, &Header), stage: Stage) {
        self.failed.clear();
        self.noted.clear();
        self.jobs.clear();
        self.flown.clear();
        (self.answered, self.without_launch) = (0, 0);
        let input = &self.input;
        for (read, bytes, ends) in &input.records {
            let line = read.line;
            let row = if read.too_long {
                Row::Bad {
                    line,
                    reason: format!("longer than {} KiB", MAX_RECORD_BYTES / 1024),
                }
            } else {
                let fields = Fields::of(
                    &input.bytes[bytes.clone()],
                    &input.ends[ends.clone()],
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
                Row::Job => {
                    let job = self.jobs.last().expect("the row's job");
                    if let Some(why) = &job.swing_note {
                        self.noted.push((line, why.clone()));
                    }
                }
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
