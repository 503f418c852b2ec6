//! homerun's batch pipeline: a CSV of launches, or a Baseball Savant
//! export as it comes, read once and taken down one staged path: the
//! columns ([`columns`]: one table), the header ([`header`]), records read
//! bounded (`read`), each row made a scene (`row`) with its tracking
//! cells (`swing`), its swing solved (`swing_solve`), flown
//! (`flights`, each park in its air: `park_air`) in pieces on the thread pool
//! (`pieces`), and given to a sink: the rows as CSV or JSON and the
//! summary ([`fly_rows`]), the measured flights `calibrate` fits
//! ([`calibrate`]), the tracked swings of `calibrate --impact`, the swings
//! the explorer opens ([`swings`]). Each row's answer is its own, bit for
//! bit, whatever its neighbours.
//!
//! Arrows point down: this crate imports the core (numerics, units,
//! model, preset, analysis) and is imported by the frontends; inside it,
//! each module imports only those before it on that path, never in a loop
//! (a test reads the sources and holds it).

use std::io::{self, BufRead, Write};

use preset::escape_cut;

mod away;
pub mod calibrate;
mod cells;
pub mod columns;
mod dates;
mod flights;
pub mod header;
mod kinds;
mod output;
mod own_launch;
mod park_air;
mod pieces;
mod read;
mod row;
mod setup;
mod summary;
mod swing;
mod swing_solve;
pub mod swings;
mod tally;
mod words;

pub use analysis::shown::Shown;
pub use header::{Header, columns_help};
pub use pieces::{Outcome, rows_failed};
pub use read::{MAX_RECORD_BYTES, open};
pub use setup::{Setup, assigned_keys, quoted};
pub use summary::band_name;
pub use tally::Tally;

use pieces::Stage;
use read::{Records, read_header};
use words::plural;

/// How rows are printed.
#[derive(Clone, Copy, Debug, Default)]
pub struct Format {
    pub json: bool,
    pub shown: Shown,
}

/// Flies every row of `input` (`fly --batch`, `hit --batch`), writing each
/// row's answer to `out` in order and naming bad rows to `note`; the
/// outcome and the rows' tally for the summary. `Err` for an input that
/// cannot be a batch (its header), or output that cannot be written.
pub fn fly_rows(
    setup: &Setup,
    input: impl BufRead,
    format: Format,
    out: &mut dyn Write,
    note: &mut dyn FnMut(&str),
    tick: &(dyn Fn() + Sync),
) -> Result<(Outcome, Tally), String> {
    let mut records = Records::new(input);
    let Some(names) = read_header(&mut records)? else {
        // The header of no rows: a reader of the output still finds columns.
        let line = output::csv_header((false, false), setup, format.shown);
        if !format.json {
            let _ = out.write_all(line.as_bytes()).and_then(|()| out.flush());
        }
        note("the input is empty: no rows to fly");
        return Ok((Outcome::default(), Tally::new(setup, None)));
    };
    let header = Header::new(names, setup)?;
    let statcast = header.has(columns::SavantColumn::Distance);
    let spin_measured = header.has(columns::SavantColumn::HitSpinRate);
    let written = |r: io::Result<()>| match r {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(false),
        Err(e) => Err(format!("writing the output: {e}")),
        Ok(()) => Ok(true),
    };
    if !format.json {
        let line = output::csv_header((statcast, spin_measured), setup, format.shown);
        if !written(out.write_all(line.as_bytes()))? {
            return Ok((Outcome::default(), Tally::new(setup, Some(&header))));
        }
    }
    announce(&header, setup, note);
    let mut tally = Tally::new(setup, Some(&header));
    let printed = output::Printed {
        shown: format.shown,
        statcast,
        spin_measured,
        json: format.json,
    };
    let finish = |piece: &mut pieces::Piece<(Vec<u8>, Tally)>| {
        let (bytes, piece_tally) = &mut piece.made;
        bytes.clear();
        *piece_tally = Tally::new(setup, Some(&header));
        for (job, flown) in piece.jobs.iter().zip(&piece.flown) {
            let Ok(flown) = flown else { continue };
            output::write_row(bytes, (job, flown), &piece.scratch, setup, printed);
            piece_tally.count(job, flown);
            piece.answered += 1;
            tick();
        }
    };
    let take = |piece: &mut pieces::Piece<(Vec<u8>, Tally)>| {
        // A piece the reader did not take (`| head`) is not counted: the
        // summary is of the rows written.
        let wrote = written(out.write_all(&piece.made.0).and_then(|()| out.flush()))?;
        if wrote {
            tally.add(&piece.made.1);
        }
        Ok(wrote)
    };
    let outcome = pieces::stream(
        (setup, &header),
        &mut records,
        Stage::Flown,
        finish,
        take,
        note,
    )?;
    tally.close(&outcome, &header);
    Ok((outcome, tally))
}

/// One note for the columns ignored and the launch values the rows take
/// from elsewhere than a column.
fn announce(header: &Header, setup: &Setup, note: &mut dyn FnMut(&str)) {
    let ignored = header.ignored();
    if !ignored.is_empty() {
        let shown: Vec<String> = ignored.iter().take(8).map(|n| escape_cut(n, 40)).collect();
        let more = match ignored.len() > 8 {
            true => format!(", … ({} in all)", ignored.len()),
            false => String::new(),
        };
        note(&format!(
            "ignored {} column{} that {} no input: {}{more}",
            ignored.len(),
            plural(ignored.len()),
            if ignored.len() == 1 { "is" } else { "are" },
            shown.join(", ")
        ));
        // Bat tracking left unread is worth a word: it is what a swing's
        // spin is solved from (docs/bat-tracking.md).
        if !setup.solve_swings && ignored.contains(&"bat_speed") {
            note(
                "bat_speed (bat tracking) is not read by this run: --spin swing, or hit --batch, \
                 solves each row's swing from it",
            );
        }
    }
    let swing_columns = header.swing_columns();
    for (index, key) in columns::LAUNCH_KEYS.iter().enumerate() {
        // Without a spin column the spin is estimated (said at the end).
        if header.has_launch(index) || (index == 2 && !setup.gave(key)) {
            continue;
        }
        let source = match setup.gave(key) {
            true => format!("every row takes --set {key}"),
            false => format!(
                "each row's {key} comes from its own swing (column{} {})",
                plural(swing_columns.len()),
                swing_columns.join(", ")
            ),
        };
        note(&format!("no {key} column: {source}"));
    }
}

#[cfg(test)]
mod tests;
