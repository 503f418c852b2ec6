//! `fly --batch FILE` (or `-` for stdin): one launch per CSV row, flown in
//! parallel and written in input order, a chunk at a time, so that memory
//! stays bounded however long the input (a season of Statcast rows, or an
//! endless pipe). A bad row is named by its line on stderr and skipped;
//! input that is no CSV text (a NUL byte) stops the run.

use std::io::{self, BufRead, Write};

use rayon::prelude::*;

use super::UsageError;
use super::ground::{FlownToFence, clearing_json};
use super::progress::{self, Progress, Work};
use super::shown::Shown;
use crate::analysis::precision::Purpose;
use crate::analysis::savant;
use crate::model::launch::SceneKind;
use crate::preset::escape_cut;
use crate::units::Quantity;

pub(super) mod calibrate;
mod records;
mod rows;
mod savant_columns;

pub use records::MAX_RECORD_BYTES;
use records::*;
pub(super) use rows::columns_help;
use rows::*;
pub(super) use savant_columns::Setup;
use savant_columns::{SavantColumn, Summary, quoted};

/// Rows read, flown in parallel and written at a time.
const CHUNK_ROWS: usize = 2048;
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
        what: "fly --batch",
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
    records.read_past_long = false;
    let mut outcome = Outcome::default();
    let header = match records.next() {
        Ok(Record::End) => None,
        Ok(Record::Text { text, .. }) => {
            let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
            let names = split_fields(text).map_err(|e| format!("line 1 (the header): {e}"))?;
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
            Some(header)
        }
        Ok(Record::TooLong { .. }) => {
            return Err(format!(
                "line 1 (the header): longer than {} KiB: not a CSV of launches",
                MAX_RECORD_BYTES / 1024
            ));
        }
        Err(Stop::Binary { .. }) => {
            return Err("a NUL byte in line 1: binary data, not CSV text".to_owned());
        }
        Err(Stop::Io(e)) => return Err(e.to_string()),
    };
    records.read_past_long = true;
    let statcast = header
        .as_ref()
        .is_some_and(|h| h.has(SavantColumn::Distance));
    if !json {
        let mut names: Vec<String> = OUTPUT_COLUMNS
            .iter()
            .copied()
            .zip(OUTPUT_QUANTITIES)
            .chain(STATCAST_COLUMNS.into_iter().filter(|_| statcast))
            .map(|(name, quantity)| shown.csv_key(name, quantity))
            .collect();
        names.extend(setup.keep.iter().map(|n| quoted(n)));
        let _ = writeln!(sinks.out, "{}", names.join(","));
    }
    let Some(header) = header else {
        sinks.note("the input is empty: no rows to fly");
        return Ok(outcome);
    };
    announce(&header, setup, sinks);
    let mut summary = Summary::new(setup.parks.parks.len());
    let options = Purpose::Readout.flight_options();
    let mut messages = 0;
    let mut fail = |sinks: &mut Sinks, outcome: &mut Outcome, line: usize, reason: &str| {
        outcome.failed += 1;
        messages += 1;
        if messages <= MAX_ROW_MESSAGES {
            sinks.note(&format!("line {line}: {reason}; skipped"));
        } else if messages == MAX_ROW_MESSAGES + 1 {
            sinks.note("more bad rows: counted, not shown");
        }
    };
    loop {
        let mut jobs = Vec::with_capacity(CHUNK_ROWS);
        let mut ended = false;
        while jobs.len() < CHUNK_ROWS {
            let row = match records.next() {
                Ok(Record::End) => {
                    ended = true;
                    break;
                }
                Ok(Record::Text { line, text }) => parse_row(&header, setup, line, &text),
                Ok(Record::TooLong { line }) => Row::Bad {
                    line,
                    reason: format!("longer than {} KiB", MAX_RECORD_BYTES / 1024),
                },
                Err(stop) => {
                    let why = match stop {
                        Stop::Binary { line } => {
                            format!("line {line}: a NUL byte: binary data, not CSV text")
                        }
                        Stop::Io(e) => format!("reading the input: {e}"),
                    };
                    sinks.note(&format!("{why}; stopped reading"));
                    outcome.stopped = true;
                    ended = true;
                    break;
                }
            };
            match row {
                Row::Job(job) => jobs.push(job),
                Row::Bad { line, reason } => fail(sinks, &mut outcome, line, &reason),
                Row::NoLaunch => outcome.without_launch += 1,
                Row::Blank => outcome.empty += 1,
            }
        }
        let flown: Vec<Result<(FlownToFence, usize), String>> = jobs
            .par_iter()
            .map(|job| fly_job(job, setup, &options))
            .collect();
        for (job, flown) in jobs.iter().zip(flown) {
            let (flown, flights) = match flown {
                Ok(flown) => flown,
                Err(reason) => {
                    fail(sinks, &mut outcome, job.line, &reason);
                    continue;
                }
            };
            summary.count(job, &header, flights);
            let text = if json {
                json_line(job, &flown, setup)
            } else {
                csv_line(job, &flown, statcast, setup, shown)
            };
            match sinks.out.write_all(text.as_bytes()) {
                // `| head`: the reader has what it wanted.
                Err(e) if e.kind() == io::ErrorKind::BrokenPipe => return Ok(outcome),
                Err(e) => return Err(format!("writing the output: {e}")),
                Ok(()) => {}
            }
            outcome.flown += 1;
            progress.tick();
        }
        if let Err(e) = sinks.out.flush()
            && e.kind() != io::ErrorKind::BrokenPipe
        {
            return Err(format!("writing the output: {e}"));
        }
        if ended {
            break;
        }
    }
    summary.without_speed = outcome.without_launch;
    if let Some(line) = summary.line(&header.savant_used(), outcome.flown, setup) {
        sinks.note(&line);
    }
    if outcome.empty > 0 {
        let n = outcome.empty;
        sinks.note(&format!(
            "{n} empty line{} skipped",
            if n == 1 { "" } else { "s" }
        ));
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
            if ignored.len() == 1 { "" } else { "s" },
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
                if swing_columns.len() == 1 { "" } else { "s" },
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

/// The output's columns, in order: then [`STATCAST_COLUMNS`] when the input
/// has Statcast's distance, then `--keep`'s.
pub const OUTPUT_COLUMNS: [&str; 18] = [
    "line",
    "launch.speed",
    "launch.angle",
    "launch.spin",
    "launch.direction",
    "launch.sidespin",
    "range",
    "direction",
    "flight_time",
    "apex",
    "landing_angle",
    "landed",
    "clears_fence",
    "park",
    "outcome",
    "margin",
    "parks_cleared",
    "spin_estimated",
];

/// What each output column measures, for its unit outside SI.
const OUTPUT_QUANTITIES: [Quantity; 18] = [
    Quantity::Unchanged,
    Quantity::Speed,
    Quantity::Angle,
    Quantity::Spin,
    Quantity::Angle,
    Quantity::Spin,
    Quantity::Distance,
    Quantity::Angle,
    Quantity::Unchanged,
    Quantity::Distance,
    Quantity::Angle,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Unchanged,
    Quantity::Distance,
    Quantity::Unchanged,
    Quantity::Unchanged,
];

/// Statcast's distance and the model's range less it.
const STATCAST_COLUMNS: [(&str, Quantity); 2] = [
    ("statcast_distance", Quantity::Distance),
    ("difference", Quantity::Distance),
];

/// A row's launch completed (the spin estimated, the direction solved:
/// [`savant::launch`]) and flown once, judged at its park's fence (or the
/// generic one) and at every park's; and the flights the solve took.
fn fly_job(
    job: &Job,
    setup: &Setup,
    options: &crate::model::flight::FlightOptions,
) -> Result<(FlownToFence, usize), String> {
    let launched =
        savant::launch(&job.scene, &job.launch, setup.spray, options).map_err(|e| e.to_string())?;
    launched.scene.validate().map_err(|e| {
        if job.launch.estimates_spin() {
            format!("{e} (the spin estimated from the launch angle)")
        } else {
            e.to_string()
        }
    })?;
    let generic;
    let fence = match job.park {
        Some(index) => setup.fences[index],
        None => {
            generic = job.fence.uniform();
            &generic
        }
    };
    let own_air = setup.own_air.then_some((setup.parks, job.given));
    let flown = FlownToFence::new(&launched.scene, fence, &setup.fences, own_air);
    Ok((flown, launched.flights))
}

/// The row's park code, or "generic".
fn park_code<'a>(job: &Job, setup: &Setup<'a>) -> &'a str {
    job.park
        .map_or("generic", |i| setup.parks.parks[i].code.as_str())
}

/// The model's range less Statcast's distance (m), if both are known.
fn difference(job: &Job, flown: &FlownToFence) -> Option<f64> {
    let flight = &flown.flight;
    job.statcast
        .filter(|_| flight.landed)
        .map(|measured| flight.range - measured)
}

fn csv_line(
    job: &Job,
    flown: &FlownToFence,
    statcast: bool,
    setup: &Setup,
    shown: Shown,
) -> String {
    let (launch, flight) = (&flown.launch, &flown.flight);
    let distance = |m: Option<f64>, decimals| {
        m.map_or(String::new(), |m| {
            shown.number(Quantity::Distance, m, decimals)
        })
    };
    let range = distance(flight.landed.then_some(flight.range), 3);
    let mut line = format!(
        "{},{},{},{},{},{},{range},{},{:.3},{},{},{},{},{},{},{},{},{}",
        job.line,
        shown.number(Quantity::Speed, launch.speed, 4),
        shown.number(Quantity::Angle, launch.angle, 6),
        shown.number(Quantity::Spin, launch.spin, 3),
        shown.number(Quantity::Angle, launch.direction, 6),
        shown.number(Quantity::Spin, launch.sidespin, 3),
        shown.number(Quantity::Angle, flight.direction, 6),
        flight.flight_time,
        shown.number(Quantity::Distance, flight.apex, 3),
        shown.number(Quantity::Angle, flight.landing_angle, 4),
        flight.landed,
        flown.clears_fence(),
        quoted(park_code(job, setup)),
        flown.clearing.outcome.name(),
        distance(flown.clearing.margin, 3),
        flown.parks_cleared(),
        job.launch.estimates_spin(),
    );
    if statcast {
        line += &format!(
            ",{},{}",
            distance(job.statcast, 2),
            distance(difference(job, flown), 2)
        );
    }
    for kept in &job.kept {
        line.push(',');
        line += &quoted(kept);
    }
    line + "\n"
}

fn json_line(job: &Job, flown: &FlownToFence, setup: &Setup) -> String {
    let (launch, flight) = (&flown.launch, &flown.flight);
    let mut json = serde_json::json!({
        "line": job.line,
        // {speed, angle, spin, direction, sidespin}, as `fly --json`.
        "launch": launch,
        "flight": {
            "range": flight.landed.then_some(flight.range),
            "direction": flight.direction,
            "flight_time": flight.flight_time,
            "apex": flight.apex,
            "landing_angle": flight.landing_angle,
            "landed": flight.landed,
        },
        "clears_fence": flown.clears_fence(),
        "fence": clearing_json(park_code(job, setup), &flown.clearing),
        "parks": {
            "cleared": flown.parks_cleared(),
            "codes": flown.codes_cleared(setup.parks),
        },
        "spin_estimated": job.launch.estimates_spin(),
    });
    if let Some(measured) = job.statcast {
        json["statcast"] = serde_json::json!({
            "distance": measured,
            "difference": difference(job, flown),
        });
    }
    if !job.kept.is_empty() {
        json["kept"] = setup
            .keep
            .iter()
            .zip(&job.kept)
            .map(|(name, value)| (name.clone(), serde_json::Value::from(value.as_str())))
            .collect::<serde_json::Map<_, _>>()
            .into();
    }
    json.to_string() + "\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_follow_rfc_4180() {
        assert_eq!(split_fields("a,b,,c").unwrap(), ["a", "b", "", "c"]);
        assert_eq!(
            split_fields(r#"1,"x, ""y""",2"#).unwrap(),
            ["1", r#"x, "y""#, "2"]
        );
        assert!(split_fields(r#"1,"open"#).is_err());
    }

    #[test]
    fn records_end_outside_quotes_and_long_ones_are_dropped() {
        let text = "h\n\"a\nb\",1\r\nlast";
        let mut records = Records::new(text.as_bytes());
        let mut got = Vec::new();
        loop {
            match records.next() {
                Ok(Record::Text { line, text }) => got.push((line, text)),
                Ok(Record::End) => break,
                _ => panic!("unexpected"),
            }
        }
        assert_eq!(
            got,
            [
                (1, "h".to_owned()),
                (2, "\"a\nb\",1".to_owned()),
                (4, "last".to_owned())
            ]
        );
        let long = format!("{}\nnext\n", "x".repeat(MAX_RECORD_BYTES + 1));
        let mut records = Records::new(io::BufReader::with_capacity(1000, long.as_bytes()));
        assert!(matches!(records.next(), Ok(Record::TooLong { line: 1 })));
        assert!(matches!(records.next(), Ok(Record::Text { line: 2, .. })));
        let mut records = Records::new(&b"a\nb\0"[..]);
        assert!(matches!(records.next(), Ok(Record::Text { .. })));
        assert!(matches!(records.next(), Err(Stop::Binary { line: 2 })));
    }

    #[test]
    fn a_header_too_long_is_given_up_without_reading_on() {
        /// Counts the bytes handed out, of a line that never ends.
        struct Endless(usize);
        impl io::Read for Endless {
            fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
                buf.fill(b'a');
                self.0 += buf.len();
                Ok(buf.len())
            }
        }
        let mut endless = Endless(0);
        let mut sinks = Sinks {
            out: &mut Vec::new(),
            err: &mut Vec::new(),
            erase: false,
        };
        let reader = io::BufReader::with_capacity(4096, &mut endless);
        let fastball = crate::preset::load("fastball", None).unwrap();
        let parks = crate::preset::parks::all(None).unwrap();
        let setup = Setup::new(&fastball, &parks);
        let work = Work {
            what: "test",
            steps: None,
        };
        let refused = progress::run(work, |p| {
            batch(&setup, reader, false, Shown::default(), &mut sinks, p)
        });
        assert!(refused.unwrap_err().contains("longer than 64 KiB"));
        assert!(
            endless.0 <= MAX_RECORD_BYTES + 4096,
            "{} bytes read",
            endless.0
        );
    }

    #[test]
    fn statcast_units_convert_exactly() {
        assert_eq!(Unit::Mph.to_si(103.0), 103.0 * 0.44704);
        assert_eq!(Unit::Degrees.to_si(28.0), 28f64.to_radians());
        assert_eq!(
            Unit::Rpm.to_si(2500.0),
            2500.0 * (std::f64::consts::TAU / 60.0)
        );
        assert!((Unit::Degrees.to_si(28.0) - 0.488_692_190_558_412).abs() < 1e-15);
        assert!((Unit::Rpm.to_si(2500.0) - 261.799_387_799_149).abs() < 1e-12);
    }
}
