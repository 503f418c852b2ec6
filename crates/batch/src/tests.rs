//! The batch's reading against Python's `csv` module, and its rows against
//! `fly` and against themselves flown alone: the same records, lines,
//! numbers and digits.

use std::io;

use super::columns::Unit;
use super::read::{Fields, Lossy, Records, Stop};
use super::*;
use analysis::precision::Purpose;
use model::clearing::Clearing;
use model::flight::FlightSummary;
use model::launch::{self, BattedBall};
use model::scene::Scene;
use numerics::xorshift::uniform;
use units::Quantity;

/// A record's line and fields (`None` if too long).
type Got = (usize, Option<Vec<String>>);

/// Every record of `text`, and the empty lines.
fn records(text: &[u8], capacity: usize) -> (Vec<Got>, usize) {
    let mut records = Records::new(io::BufReader::with_capacity(capacity, text));
    let (mut bytes, mut ends, mut lossy) = (Vec::new(), Vec::new(), Lossy::default());
    let mut got = Vec::new();
    loop {
        bytes.clear();
        ends.clear();
        match records.next(&mut bytes, &mut ends, true) {
            Ok(Some(read)) => {
                let fields = Fields::of(&bytes, &ends, &mut lossy);
                let fields = fields.iter().map(str::to_owned).collect();
                got.push((read.line, (!read.too_long).then_some(fields)));
            }
            Ok(None) => return (got, records.empty),
            Err(_) => panic!("stopped"),
        }
    }
}

fn row(line: usize, fields: &[&str]) -> Got {
    (line, Some(fields.iter().map(|f| f.to_string()).collect()))
}

/// Lines and fields as Python's `csv.reader` gives them (computed with
/// Python 3: each row's line is the `line_num` before it, plus one; its
/// empty rows are the empty lines).
#[test]
fn records_and_lines_are_pythons() {
    for capacity in [1, 3, 4096] {
        let read = |text: &str| records(text.as_bytes(), capacity);
        // Bare CR line ends.
        let want = vec![row(1, &["h"]), row(2, &["1"]), row(3, &["2"])];
        assert_eq!(read("h\r1\r2\r"), (want, 0));
        assert_eq!(
            read("a,b\r\n\"x\ny\",1\r\n\r\n3,4\n"),
            (
                vec![
                    row(1, &["a", "b"]),
                    row(2, &["x\ny", "1"]),
                    row(5, &["3", "4"])
                ],
                1
            )
        );
        // A quote inside an unquoted field is text: the next rows are rows.
        let (got, _) = read("a,b,c\n98,23,6 ft 2\" tall\n1,2,3\n4,5,6\n7,8,9\n10,11,12\n");
        assert_eq!(got.len(), 6);
        assert_eq!(got[1], row(2, &["98", "23", "6 ft 2\" tall"]));
        assert_eq!(got[5], row(6, &["10", "11", "12"]));
        assert_eq!(
            read("\n\nh\n1\r\r\n\"a\r\nb\rc\",2\n\n"),
            (
                vec![row(3, &["h"]), row(4, &["1"]), row(6, &["a\r\nb\rc", "2"])],
                4
            )
        );
        // An unterminated quote runs to the end, as Python reads it.
        assert_eq!(
            read("h\n\"open\n1\n2\n"),
            (vec![row(1, &["h"]), row(2, &["open\n1\n2\n"])], 0)
        );
        // A quote after a space is text.
        assert_eq!(
            read("h\n x, \"a, b\"\n").0[1],
            row(2, &[" x", " \"a", " b\""])
        );
        // A byte-order mark read at once is dropped (the header drops one
        // read a byte at a time).
        if capacity >= 3 {
            assert_eq!(read("\u{feff}h\n1").0, vec![row(1, &["h"]), row(2, &["1"])]);
        }
    }
}

#[test]
fn a_long_record_is_read_to_its_end_quotes_and_all() {
    // A quoted cell of line breaks longer than the cap: one record, too
    // long, named by its first line; the row after it is read.
    let cell = "x\n".repeat(MAX_RECORD_BYTES);
    let text = format!("h,i\n1,\"{cell}\"\n2,3\n");
    let (got, _) = records(text.as_bytes(), 8192);
    assert_eq!(got.len(), 3);
    assert_eq!(got[1], (2, None));
    assert_eq!(got[2], row(3 + MAX_RECORD_BYTES, &["2", "3"]));
    // Just under the cap, it is kept.
    let cell = "y".repeat(MAX_RECORD_BYTES - 10);
    let text = format!("h,i\n1,\"{cell}\"\n2,3\n");
    let (got, _) = records(text.as_bytes(), 1000);
    assert_eq!(got[1], row(2, &["1", &cell]));
    // Exactly at the cap, it is kept with a line end of either kind and
    // without one (its line end is not its own); a byte more is too long.
    let cell = "z".repeat(MAX_RECORD_BYTES);
    for end in ["\n", "\r\n", "\r", ""] {
        for capacity in [1, 4096] {
            let (got, _) = records(format!("h\n{cell}{end}").as_bytes(), capacity);
            assert_eq!(got[1], row(2, &[&cell]), "{end:?} {capacity}");
            let (got, _) = records(format!("h\n{cell}z{end}").as_bytes(), capacity);
            assert_eq!(got[1], (2, None), "{end:?} {capacity}");
        }
    }
    // A NUL byte stops reading, on its line.
    let mut records = Records::new(&b"a\nb\r\nc\0"[..]);
    let (mut bytes, mut ends) = (Vec::new(), Vec::new());
    assert!(matches!(
        records.next(&mut bytes, &mut ends, true),
        Ok(Some(_))
    ));
    assert!(matches!(
        records.next(&mut bytes, &mut ends, true),
        Ok(Some(_))
    ));
    assert!(matches!(
        records.next(&mut bytes, &mut ends, true),
        Err(Stop::Binary(3))
    ));
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
    let reader = io::BufReader::with_capacity(4096, &mut endless);
    let fastball = preset::load("fastball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&fastball, &parks);
    let refused = fly_rows(
        &setup,
        reader,
        Format::default(),
        &mut Vec::new(),
        &mut |_| {},
        &|| {},
    );
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

/// Runs the batch on `input`: (stdout, stderr, outcome).
fn run(setup: &Setup, input: &str, json: bool, shown: Shown) -> (String, String, Outcome) {
    let (out, err, outcome, _) = run_tallied(setup, input, json, shown);
    (out, err, outcome)
}

/// [`run`], and the tally its summary is made from.
fn run_tallied(
    setup: &Setup,
    input: &str,
    json: bool,
    shown: Shown,
) -> (String, String, Outcome, Tally) {
    let (mut out, mut err) = (Vec::new(), String::new());
    let mut note = |m: &str| err += &format!("homerun: {m}\n");
    let (outcome, tally) = fly_rows(
        setup,
        input.as_bytes(),
        Format { json, shown },
        &mut out,
        &mut note,
        &|| {},
    )
    .unwrap();
    for line in tally.lines(setup, shown) {
        note(&line);
    }
    (String::from_utf8(out).unwrap(), err, outcome, tally)
}

/// A row flown alone, as `fly` flies it: at the readout's precision,
/// judged at `fence`, and at every park's fence on a flight in that
/// park's air (the standard air at its elevation: no weather given).
struct Alone {
    launch: BattedBall,
    flight: FlightSummary,
    clearing: Clearing,
    parks_cleared: usize,
}

fn alone(scene: &Scene, fence: &model::park::Fence, parks: &[model::park::Park]) -> Alone {
    let options = Purpose::Readout.flight_options();
    let (flight, launch, _) = launch::scene_start(scene);
    let (summary, clearings) = flight.judge(&options, &[fence]);
    let given = model::park::GivenWeather::default();
    let at_parks = model::many::judged_in_own_air(scene, parks, given, &options);
    Alone {
        launch,
        flight: summary,
        clearing: clearings[0],
        parks_cleared: at_parks.iter().filter(|c| c.clears()).count(),
    }
}

/// A number as the batch printed it before: `format!`.
fn number(shown: Shown, quantity: Quantity, si: f64, si_decimals: usize) -> String {
    let decimals = shown.unit(quantity).decimals(si_decimals);
    format!("{:.decimals$}", shown.convert(quantity, si))
}

/// The line `fly` gives a row: its scene flown as `fly` flies it (at the
/// readout's precision, judged at `fence` and every park's), printed as
/// the batch printed it before it flew in pieces.
fn fly_line(
    line: usize,
    scene: &Scene,
    (code, fence): (&str, &model::park::Fence),
    setup: &Setup,
    shown: Shown,
    statcast: Option<f64>,
) -> String {
    use units::Quantity::*;
    let flown = alone(scene, fence, &setup.parks.parks);
    let (launch, flight) = (&flown.launch, &flown.flight);
    let distance = |m: Option<f64>, d| m.map_or(String::new(), |m| number(shown, Distance, m, d));
    let mut text = format!(
        "{line},{},{},{},{},{},{},{},{:.3},{},{},{},{},{code},{},{},{},false,scene",
        number(shown, Speed, launch.speed, 4),
        number(shown, Angle, launch.angle, 6),
        number(shown, Spin, launch.spin, 3),
        number(shown, Angle, launch.direction, 6),
        number(shown, Spin, launch.sidespin, 3),
        distance(flight.landed.then_some(flight.range), 3),
        number(shown, Angle, flight.direction, 6),
        flight.flight_time,
        number(shown, Distance, flight.apex, 3),
        number(shown, Angle, flight.landing_angle, 4),
        flight.landed,
        flown.clearing.clears(),
        flown.clearing.outcome.name(),
        distance(flown.clearing.margin, 3),
        flown.parks_cleared,
    );
    if let Some(measured) = statcast {
        let difference = flight.landed.then_some(flight.range - measured);
        text += &format!(
            ",{},{}",
            distance(Some(measured), 2),
            distance(difference, 2)
        );
    }
    if shown.is_si() {
        return text;
    }
    // Outside SI the batch writes a number as its reader wrote it: trailing
    // zeros trimmed, one decimal kept.
    let fields: Vec<String> = text
        .split(',')
        .map(|field| match field.split_once('.') {
            Some((whole, decimals)) if field.parse::<f64>().is_ok() => {
                let decimals = decimals.trim_end_matches('0');
                format!(
                    "{whole}.{}",
                    if decimals.is_empty() { "0" } else { decimals }
                )
            }
            _ => field.to_owned(),
        })
        .collect();
    fields.join(",")
}

/// Batted balls over Statcast's spread and beyond it (grounders, pop-ups,
/// hooks and slices), as `launch.*` cells (SI, every digit).
fn launches(rows: usize, spray: bool, seed: u64) -> Vec<[f64; 5]> {
    let mut next = uniform(seed);
    (0..rows)
        .map(|_| {
            let (direction, sidespin) = if spray {
                (1.5 * next() - 0.75, 300.0 * next() - 150.0)
            } else {
                (0.0, 0.0)
            };
            [
                25.0 + 30.0 * next(),
                1.8 * next() - 0.5,
                450.0 * next() - 50.0,
                direction,
                sidespin,
            ]
        })
        .collect()
}

const LAUNCH_KEYS: [&str; 5] = [
    "launch.speed",
    "launch.angle",
    "launch.spin",
    "launch.direction",
    "launch.sidespin",
];

/// `scene` with a launch, as `--set` gives it.
fn launched(scene: &Scene, launch: &[f64; 5]) -> Scene {
    let mut scene = *scene;
    let mut batch = model::keys::InputBatch::new();
    for (key, value) in LAUNCH_KEYS.iter().zip(launch) {
        batch.set_text(&mut scene, key, &value.to_string()).unwrap();
    }
    scene
}

/// Launches whose range, as `fly` flies them, lies within ~1e-9 m of a
/// rounding boundary of its printed millimetre: the launch speed moved by
/// Newton's method onto the boundary.
fn on_rounding_boundaries(base: &Scene, rows: usize) -> Vec<[f64; 5]> {
    let fence = model::park::Fence::uniform(121.92, 3.0);
    let range = |launch: &[f64; 5]| {
        let scene = launched(base, launch);
        alone(&scene, &fence, &[]).flight.range
    };
    let mut found = Vec::new();
    for mut launch in launches(rows, false, 0x5eed_0018) {
        launch[1] = launch[1].clamp(0.1, 0.8); // fly balls: smooth ranges
        let r = range(&launch);
        let target = ((r * 1e3).floor() + 0.5) / 1e3;
        let mut dv = 1e-4;
        let slope = (range(&[launch[0] + dv, launch[1], launch[2], 0.0, 0.0]) - r) / dv;
        for _ in 0..3 {
            dv = (target - range(&launch)) / slope;
            launch[0] += dv;
        }
        found.push(launch);
    }
    found
}

#[test]
fn batch_rows_print_what_fly_prints_digit_for_digit() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let mut setup = Setup::new(&preset, &parks);
    // The preset's fence given as --set gives it: rows at no park are
    // judged there, as `fly` judges them.
    setup.given(&["field.fence_distance=121.9".to_owned()]);
    let generic = preset::Fence::generic().uniform();
    let imperial = Shown(units::UnitSystem::Imperial);
    let boundary = on_rounding_boundaries(&preset.scene, 300);
    let cases = [
        (launches(1500, false, 1), Shown::default()),
        (launches(1500, true, 2), Shown::default()),
        (launches(700, true, 3), imperial),
        (boundary.clone(), Shown::default()),
    ];
    for (rows, shown) in cases {
        let mut input = LAUNCH_KEYS.join(",") + "\n";
        let mut want = String::new();
        for (i, launch) in rows.iter().enumerate() {
            let cells: Vec<String> = launch.iter().map(f64::to_string).collect();
            input += &(cells.join(",") + "\n");
            let scene = launched(&preset.scene, launch);
            want += &fly_line(i + 2, &scene, ("generic", &generic), &setup, shown, None);
            want.push('\n');
        }
        let (out, err, outcome) = run(&setup, &input, false, shown);
        assert_eq!(outcome.answered, rows.len(), "{err}");
        let got = out.split_once('\n').unwrap().1;
        for (got, want) in got.lines().zip(want.lines()) {
            assert_eq!(got, want);
        }
        assert_eq!(got, want);
    }
}

#[test]
fn savant_rows_at_their_parks_print_what_fly_prints_there() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let codes = ["BOS", "COL", "NYY", "SF", "HOU"];
    let mut input =
        String::from("launch.speed,launch.angle,launch.spin,home_team,hit_distance_sc\n");
    let mut want = String::new();
    for (i, launch) in launches(600, false, 4).iter().enumerate() {
        let code = codes[i % codes.len()];
        let measured = 300.0 + (i % 150) as f64;
        input += &format!(
            "{},{},{},{code},{measured}\n",
            launch[0], launch[1], launch[2]
        );
        let park = parks.parks.iter().find(|p| p.code == code).unwrap();
        let mut scene = launched(&preset.scene, launch);
        model::park::GivenWeather::default().park_air(&mut scene.environment, park.elevation);
        let statcast = Some(measured * 0.3048);
        want += &fly_line(
            i + 2,
            &scene,
            (code, &park.fence),
            &setup,
            Shown::default(),
            statcast,
        );
        want.push('\n');
    }
    let (out, err, _) = run(&setup, &input, false, Shown::default());
    let got = out.split_once('\n').unwrap().1;
    assert!(err.contains("5 parks from home_team"), "{err}");
    for (got, want) in got.lines().zip(want.lines()) {
        assert_eq!(got, want);
    }
    assert_eq!(got.lines().count(), 600);
}

#[test]
fn hostile_cells_fail_in_line_order_between_rows_that_fly() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let mut setup = Setup::new(&preset, &parks);
    // The preset's fence given as --set gives it: rows at no park are
    // judged there, as `fly` judges them.
    setup.given(&["field.fence_distance=121.9".to_owned()]);
    setup.keep = vec!["des".to_owned()];
    let generic = preset::Fence::generic().uniform();
    // Good rows between bad ones, across pieces (hundreds of rows).
    let bad = [
        "abc,0.5,200,x",
        "1e999,0.5,200,x",
        "40,nan,200,x",
        "40,0.5",
        "40,0.5,200,x,extra",
        "40,3,200,x",
        // A quote after a space is text, as Python reads it.
        " \"40\",0.5,200,\"a, \"\"b\"\"\"",
    ];
    let mut input = String::from("launch.speed,launch.angle,launch.spin,des\r\n");
    let mut want = String::new();
    let mut failed = Vec::new();
    for (i, launch) in launches(900, false, 5).iter().enumerate() {
        let line = i + 2;
        // (the row's cells, its launch, and its kept cell as printed)
        let (row, launch, kept) = if i % 97 == 13 {
            let row = bad[(i / 97) % bad.len()];
            input += &format!("{row}\r\n");
            failed.push(line);
            continue;
        } else {
            let des = ["\"homers, to left\"", "single"][i % 2];
            let row = format!(
                "{},{},{},\"{}\"",
                launch[0],
                launch[1],
                launch[2],
                des.trim_matches('"')
            );
            (row, *launch, des)
        };
        input += &format!("{row}\r\n");
        let scene = launched(&preset.scene, &launch);
        let at = ("generic", &generic);
        want += &fly_line(line, &scene, at, &setup, Shown::default(), None);
        want += &format!(",{kept}\n");
    }
    let (out, err, outcome) = run(&setup, &input, false, Shown::default());
    let got = out.split_once('\n').unwrap().1;
    for (got, want) in got.lines().zip(want.lines()) {
        assert_eq!(got, want);
    }
    assert_eq!(got, want);
    let named: Vec<usize> = err
        .lines()
        .filter_map(|l| {
            l.strip_prefix("homerun: line ")?
                .split(':')
                .next()?
                .parse()
                .ok()
        })
        .collect();
    assert_eq!(named, failed, "{err}");
    assert_eq!(outcome.failed, failed.len());
}

#[test]
fn a_batch_where_every_row_fails_names_no_park() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let input = "launch_speed,launch_angle\nabc,20\n";
    let (_, err, outcome) = run(&setup, input, false, Shown::default());
    assert_eq!(outcome.failed, 1);
    // Nothing was judged: neither "each row's park" nor a count of verdicts.
    let line = err.lines().find(|l| l.contains("summary: flown")).unwrap();
    assert_eq!(line, "homerun: summary: flown 0 rows, skipped 1", "{err}");
}

/// Each output line of a batch without its line number, by line: (CSV,
/// JSON).
fn outputs(setup: &Setup, input: &str) -> Vec<(usize, String, String)> {
    let (csv, err, _) = run(setup, input, false, Shown::default());
    let (json, _, _) = run(setup, input, true, Shown::default());
    let csv = csv.lines().skip(1).map(|l| {
        let (line, rest) = l.split_once(',').unwrap();
        (line.parse::<usize>().unwrap(), rest.to_owned())
    });
    let json = json.lines().map(|l| {
        let mut value: serde_json::Value = serde_json::from_str(l).unwrap();
        let line = value["line"].as_u64().unwrap() as usize;
        value["line"] = 0.into();
        (line, value.to_string())
    });
    let both: Vec<_> = csv
        .zip(json)
        .map(|((a, csv), (b, json))| {
            assert_eq!(a, b);
            (a, csv, json)
        })
        .collect();
    assert!(!both.is_empty(), "{err}");
    both
}

/// Row 4 of issue 25: every row's answer is its own. Batches of planar
/// rows, of rows with spray and sidespin, and of Savant rows (spin
/// estimated, direction solved, at their parks) are shuffled, cut and
/// given repeated rows: each row's CSV and JSON output is, bit for bit,
/// that of the same row flown alone.
#[test]
fn every_row_gives_what_it_gives_alone_whatever_its_neighbours() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let mut next = uniform(0x00c0_ffee);
    let launch = |rows: &[[f64; 5]], cells: usize| -> Vec<String> {
        let cell = |launch: &[f64; 5]| -> Vec<String> {
            launch[..cells].iter().map(f64::to_string).collect()
        };
        rows.iter().map(|l| cell(l).join(",")).collect()
    };
    let planar = launch(&launches(60, false, 7), 3);
    let spatial = launch(&launches(60, true, 8), 5);
    let codes = ["BOS", "COL", "NYY", "SF", "HOU", "nowhere"];
    let savant: Vec<String> = (0..60)
        .map(|i| {
            let (speed, angle) = (60.0 + 50.0 * next(), 50.0 * next() - 5.0);
            let (x, y) = (125.42 + 120.0 * next() - 60.0, 198.27 - 150.0 * next());
            let stand = ["R", "L", ""][i % 3];
            let code = if i % 7 == 3 { "" } else { codes[i % 5] };
            format!("{speed:.1},{angle:.0},{x:.2},{y:.2},{stand},{code},380")
        })
        .collect();
    let kinds = [
        ("launch.speed,launch.angle,launch.spin", planar),
        (&LAUNCH_KEYS.join(",")[..], spatial),
        (
            "launch_speed,launch_angle,hc_x,hc_y,stand,home_team,hit_distance_sc",
            savant,
        ),
    ];
    for (header, rows) in kinds {
        // Alone: a batch of one row each.
        let alone: Vec<(String, String)> = rows
            .iter()
            .map(|row| {
                let got = outputs(&setup, &format!("{header}\n{row}\n"));
                assert_eq!(got.len(), 1, "{row}");
                (got[0].1.clone(), got[0].2.clone())
            })
            .collect();
        // Shuffled, with some rows left out and some repeated.
        let mut order: Vec<usize> = (0..rows.len()).filter(|i| i % 5 != 2).collect();
        order.extend((0..rows.len()).filter(|i| i % 4 == 1));
        for k in (1..order.len()).rev() {
            order.swap(k, (next() * (k + 1) as f64) as usize % (k + 1));
        }
        for order in [(0..rows.len()).collect(), order] {
            let mut input = format!("{header}\n");
            for &i in &order {
                input += &format!("{}\n", rows[i]);
            }
            let got = outputs(&setup, &input);
            assert_eq!(got.len(), order.len());
            for (line, csv, json) in got {
                let i = order[line - 2];
                assert_eq!((&csv, &json), (&alone[i].0, &alone[i].1), "{}", rows[i]);
            }
        }
    }
}

/// Row 9: hit coordinates exactly at the plate give no spray; the row
/// flies toward the preset's direction, said in one line.
#[test]
fn a_spray_at_the_plate_is_named_and_the_row_flies() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let input = "launch_speed,launch_angle,hc_x,hc_y\n100,28,125.42,198.27\n100,28,100,100\n";
    let (out, err, outcome) = run(&setup, input, false, Shown::default());
    assert_eq!((outcome.answered, outcome.failed), (2, 0), "{err}");
    assert!(!err.contains("NaN") && !out.contains("NaN"), "{err}");
    assert!(err.contains("1 row with a spray at the plate"), "{err}");
}

/// Row 12: a `--keep` cell's control characters reach a terminal escaped,
/// a file or pipe as read.
#[test]
fn kept_cells_are_escaped_for_a_terminal_only() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let mut setup = Setup::new(&preset, &parks);
    setup.keep = vec!["des".to_owned()];
    let input = "launch.speed,launch.angle,des\n45,0.5,\"a\x1b[2Jb\"\n";
    let (out, _, _) = run(&setup, input, false, Shown::default());
    assert!(out.contains("a\x1b[2Jb"), "{out}");
    setup.escape_kept = true;
    let (out, _, _) = run(&setup, input, false, Shown::default());
    assert!(
        !out.contains('\x1b') && out.contains("a\\u{1b}[2Jb"),
        "{out}"
    );
}

/// Row 11: the crossings in flight (rows × fences) stay bounded however many
/// parks there are.
#[test]
fn rounds_are_sized_by_rows_and_parks() {
    assert_eq!(pieces::sizes(30), (8192, 256));
    for parks in [0, 30, 100, 6600, 100_000] {
        let (round, piece) = pieces::sizes(parks);
        assert!(round * (parks + 1) <= 8192 * 31 || round == 1, "{parks}");
        assert!(piece >= 1 && piece <= round.max(1), "{parks}");
    }
}

/// Each park in its own air: the parks settled from a row's own flight.
mod home;
mod imports;
mod own_air;
mod reading;
mod streaming;
mod walls;
