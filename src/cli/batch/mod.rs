//! `fly --batch FILE` (or `-` for stdin): one launch per CSV row, parsed,
//! flown and written in parallel ([`pieces`]) and output in input order, a
//! round at a time, so that memory stays bounded however long the input (a
//! season of Statcast rows, or an endless pipe). A bad row is named by its
//! line on stderr and skipped; input that is no CSV text (a NUL byte) stops
//! the run.

use std::io::{self, BufRead, Write};

use super::UsageError;
use super::progress::{self, Progress, Work};
use super::shown::Shown;
use crate::model::launch::SceneKind;
use crate::preset::escape_cut;

pub(super) mod calibrate;
pub(super) mod calibrate_impact;
mod flights;
mod kinds;
mod launch_columns;
mod output;
mod own_launch;
mod pieces;
mod read;
mod rows;
mod savant_columns;
mod swing_bands;
mod swing_columns;
pub(super) mod swing_scenes;

use launch_columns::LAUNCH_COLUMNS;
pub use read::MAX_RECORD_BYTES;
use read::{Fields, Lossy, Records, Stop};
pub(super) use rows::columns_help;
use rows::*;
pub(super) use savant_columns::Setup;
use savant_columns::{SavantColumn, Summary};
/// Bad rows named one by one on stderr; past these only counted.
const MAX_ROW_MESSAGES: usize = 100;

/// How the batch went: the exit status follows from it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outcome {
    pub flown: usize,
    pub failed: usize,
    /// Rows with every launch column empty.
    pub without_launch: usize,
    /// Empty lines, skipped.
    pub empty: usize,
    /// Reading stopped early (binary input, a read error).
    pub stopped: bool,
}

impl Outcome {
    /// 0 when every row was flown (or skipped for having no launch), 1 when
    /// some failed or reading stopped early.
    pub fn exit_status(&self) -> u8 {
        u8::from(self.failed > 0 || self.stopped)
    }
}

/// Where rows and messages go.
pub(super) struct Sinks<'a> {
    pub out: &'a mut dyn Write,
    pub err: &'a mut dyn Write,
    /// Whether `err` is a terminal showing a progress line, which each
    /// message first erases.
    pub erase: bool,
}

impl Sinks<'_> {
    fn note(&mut self, message: &str) {
        let erase = if self.erase { "\r\x1b[K" } else { "" };
        let _ = writeln!(self.err, "{erase}homerun: {message}");
    }
}

/// Opens `source` ("-" for stdin) and flies every row, showing progress on
/// stderr when it is a terminal.
pub(super) fn run(
    setup: &Setup,
    source: &str,
    json: bool,
    shown: Shown,
    sinks: &mut Sinks,
) -> Result<Outcome, UsageError> {
    let work = Work {
        what: if setup.swing_columns {
            "hit --batch"
        } else {
            "fly --batch"
        },
        steps: Some((progress::UNCOUNTED, "rows")),
    };
    if source == "-" {
        let stdin = io::stdin().lock();
        progress::run(work, |p| batch(setup, stdin, json, shown, sinks, p))
    } else {
        let file = std::fs::File::open(source).map_err(|e| UsageError::Batch {
            input: escape_cut(source, 200),
            message: e.to_string(),
        })?;
        let reader = io::BufReader::with_capacity(MAX_RECORD_BYTES, file);
        progress::run(work, |p| batch(setup, reader, json, shown, sinks, p))
    }
    .map_err(|message| UsageError::Batch {
        input: escape_cut(source, 200),
        message,
    })
}

/// Flies every row of `input` against `base`; `Err` only for a header that
/// cannot be used (nothing was flown).
pub(super) fn batch(
    setup: &Setup,
    input: impl BufRead,
    json: bool,
    shown: Shown,
    sinks: &mut Sinks,
    progress: &Progress,
) -> Result<Outcome, String> {
    let mut records = Records::new(input);
    let mut outcome = Outcome::default();
    let header = match read_header(&mut records) {
        Ok(None) => None,
        Ok(Some(names)) => {
            let mut header = Header::new(names).map_err(|e| format!("line 1 (the header): {e}"))?;
            if !header.has_input() {
                return Err(format!(
                    "line 1 (the header): no column is an input (launch_speed, launch_angle, \
                     spin_rpm, launch.*, or a key of `homerun keys`); columns separated by \
                     commas? first column: `{}`",
                    escape_cut(&header.names[0], 80)
                ));
            }
            header.keep(&setup.keep)?;
            if setup.solve_swings {
                header
                    .read_swings()
                    .map_err(|e| format!("line 1 (the header): {e}"))?;
            }
            Some(header)
        }
        Err(e) => return Err(e),
    };
    let statcast = header
        .as_ref()
        .is_some_and(|h| h.has(SavantColumn::Distance));
    if !json {
        let _ = sinks
            .out
            .write_all(output::csv_header(statcast, setup, shown).as_bytes());
    }
    let Some(header) = header else {
        sinks.note("the input is empty: no rows to fly");
        return Ok(outcome);
    };
    announce(&header, setup, sinks);
    let mut summary = Summary::new(setup.parks.parks.len());
    let mut tally = output::Tally::default();
    let context = pieces::Context {
        header: &header,
        setup,
        printed: pieces::Printed {
            shown,
            statcast,
            json,
        },
        progress,
    };
    let mut messages = 0;
    let (mut round, mut next) = (pieces::Round::default(), pieces::Round::default());
    let mut work = Vec::new();
    let rows = pieces::sizes(setup.parks.parks.len()).0;
    round.read(&mut records, rows);
    loop {
        // The next round is read (on this thread) while this one flies (on
        // the pool).
        let mut used = 0;
        rayon::in_place_scope(|scope| {
            scope.spawn(|_| used = pieces::work(&round, &mut work, &context));
            next.read(&mut records, rows);
        });
        for piece in &work[..used] {
            for (line, reason) in &piece.failed {
                messages += 1;
                if messages <= MAX_ROW_MESSAGES {
                    sinks.note(&format!("line {line}: {reason}; skipped"));
                } else if messages == MAX_ROW_MESSAGES + 1 {
                    sinks.note("more bad rows: counted, not shown");
                }
            }
            outcome.failed += piece.failed.len();
            outcome.without_launch += piece.without_launch;
            summary.add(&piece.summary);
            tally.add(&piece.tally);
            match sinks.out.write_all(&piece.out) {
                // `| head`: the reader has what it wanted.
                Err(e) if e.kind() == io::ErrorKind::BrokenPipe => return Ok(outcome),
                Err(e) => return Err(format!("writing the output: {e}")),
                Ok(()) => outcome.flown += piece.flown_rows,
            }
        }
        if let Some(stop) = &round.stop {
            sinks.note(&format!("{stop}; stopped reading"));
            outcome.stopped = true;
        }
        if let Err(e) = sinks.out.flush()
            && e.kind() != io::ErrorKind::BrokenPipe
        {
            return Err(format!("writing the output: {e}"));
        }
        if round.ended {
            break;
        }
        std::mem::swap(&mut round, &mut next);
    }
    outcome.empty = records.empty;
    summary.without_speed = outcome.without_launch;
    if let Some(line) = summary.line(&header.savant_used(), outcome.flown, setup, shown) {
        sinks.note(&line);
    }
    if outcome.empty > 0 {
        let n = outcome.empty;
        sinks.note(&format!("{n} empty line{} skipped", plural(n)));
    }
    // One summary at the end: on stderr, or after the rows with --summary.
    let air = if setup.own_air {
        "in its own air"
    } else {
        "in the scene's air"
    };
    let at = match setup.park {
        Some(i) => format!("at {} ({air})", escape_cut(&setup.parks.parks[i].code, 20)),
        None => format!("at each row's park ({air})"),
    };
    let skipped = outcome.failed + outcome.without_launch;
    let line = tally.line(outcome.flown, skipped, &at, shown);
    if setup.summary_to_stdout {
        // On request, the error by launch-angle band too (JSON in SI).
        // And by kind of ball, where the export names them.
        let bands = !tally.differences.is_empty();
        let kinds = tally.kinds.any();
        let swing_bands = &summary.swings.bands;
        let swings = swing_bands.any();
        let line = if json {
            let mut summary = serde_json::json!({ "summary": line });
            if bands {
                summary["bands"] = serde_json::json!(tally.bands());
            }
            if kinds {
                summary["kinds"] = serde_json::json!(tally.kinds.rows());
                if let Some((clear, of)) = tally.kinds.home_runs_clearing() {
                    summary["home_runs"] = serde_json::json!({ "clear": clear, "of": of });
                }
            }
            if swings {
                summary["swings"] = serde_json::json!(swing_bands.rows());
            }
            summary.to_string()
        } else {
            let mut text = line;
            if bands {
                text = format!("{text}\n{}", tally.band_table(shown));
            }
            if kinds {
                text = format!("{text}\n{}", tally.kinds.table(shown));
            }
            if swings {
                text = format!("{text}\n{}", swing_bands.table(shown));
            }
            text
        };
        let _ = writeln!(sinks.out, "{line}");
        let _ = sinks.out.flush();
    } else {
        sinks.note(&line);
    }
    if outcome.failed > 0 {
        sinks.note(&format!(
            "{} of {} rows failed and were skipped (exit status 1)",
            outcome.failed,
            outcome.failed + outcome.flown
        ));
    }
    Ok(outcome)
}

/// "s" after a count other than one: "1 row", "2 rows".
fn plural(count: usize) -> &'static str {
    if count == 1 { "" } else { "s" }
}

/// Every remaining record of `records` parsed into jobs, as `calibrate`
/// and `tui --savant` read a file whole (no pieces, no flights); `seen` is
/// told of each row: `None` for one too long, else what it came to.
fn parse_all<R: BufRead>(
    records: &mut Records<R>,
    header: &rows::Header,
    setup: &Setup,
    mut seen: impl FnMut(Option<rows::Row>),
) -> Result<Vec<rows::Job>, String> {
    let mut jobs = Vec::new();
    let (mut bytes, mut ends, mut lossy) = (Vec::new(), Vec::new(), read::Lossy::default());
    loop {
        bytes.clear();
        ends.clear();
        match records.next(&mut bytes, &mut ends, true) {
            Ok(None) => return Ok(jobs),
            Ok(Some(read)) if read.too_long => seen(None),
            Ok(Some(read)) => {
                let fields = read::Fields::of(&bytes, &ends, &mut lossy);
                seen(Some(rows::parse_row(
                    header,
                    setup,
                    (read.line, fields),
                    None,
                    &mut jobs,
                )));
            }
            Err(stop) => return Err(stop.to_string()),
        }
    }
}

/// The header's names (a byte-order mark dropped), `None` for an empty
/// input, or why the input is no CSV of launches.
fn read_header<R: BufRead>(records: &mut Records<R>) -> Result<Option<Vec<String>>, String> {
    let (mut bytes, mut ends) = (Vec::new(), Vec::new());
    match records.next(&mut bytes, &mut ends, false) {
        Ok(None) => Ok(None),
        Ok(Some(read)) if read.too_long => Err(format!(
            "line {} (the header): longer than {} KiB: not a CSV of launches",
            read.line,
            MAX_RECORD_BYTES / 1024
        )),
        Ok(Some(_)) => {
            let mut lossy = Lossy::default();
            let fields = Fields::of(&bytes, &ends, &mut lossy);
            let mut names: Vec<String> = fields.iter().map(str::to_owned).collect();
            if names.first().is_some_and(|n| n.starts_with('\u{feff}')) {
                names[0].drain(..'\u{feff}'.len_utf8());
            }
            Ok(Some(names))
        }
        Err(Stop::Binary(line)) => Err(format!(
            "a NUL byte in line {line}: binary data, not CSV text"
        )),
        Err(Stop::Io(e)) => Err(e.to_string()),
    }
}

/// One stderr note for the columns ignored and the launch values every
/// row takes from the preset.
fn announce(header: &Header, setup: &Setup, sinks: &mut Sinks) {
    let base = setup.base;
    let ignored = header.ignored();
    if !ignored.is_empty() {
        let shown: Vec<String> = ignored.iter().take(8).map(|n| escape_cut(n, 40)).collect();
        let more = if ignored.len() > 8 {
            format!(", … ({} in all)", ignored.len())
        } else {
            String::new()
        };
        sinks.note(&format!(
            "ignored {} column{} that {} no input: {}{more}",
            ignored.len(),
            plural(ignored.len()),
            if ignored.len() == 1 { "is" } else { "are" },
            shown.join(", ")
        ));
    }
    let own = base.scene.batted_ball();
    let values = [own.speed, own.angle, own.spin];
    let given = base.scene.launch;
    let given = [given.speed, given.angle, given.spin];
    let batted = base.scene.kind == SceneKind::BattedBall;
    let swing_columns = header.swing_columns();
    for (index, (key, names)) in LAUNCH_COLUMNS.iter().enumerate() {
        // Without a spin column the spin is estimated (said at the end),
        // unless --set gave it.
        let estimated = index == 2 && !setup.spin_given;
        if header.has_launch(index) || estimated {
            continue;
        }
        let accepted: Vec<&str> = names.iter().map(|(n, _)| *n).collect();
        // A value the preset gives is every row's; one it takes from its
        // swing comes from each row's own swing when columns change it.
        let preset_gives = batted && given[index].is_some();
        let from_rows = !preset_gives && !swing_columns.is_empty();
        let source = if from_rows {
            format!(
                "each row's {key} comes from its own swing (column{} {})",
                plural(swing_columns.len()),
                swing_columns.join(", ")
            )
        } else {
            format!(
                "every row takes preset {}'s {key} = {}",
                base.name, values[index]
            )
        };
        sinks.note(&format!("no {} column: {source}", accepted.join(" or ")));
    }
}

#[cfg(test)]
mod tests;
