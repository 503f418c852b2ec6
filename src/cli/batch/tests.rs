//! The batch against the path it replaced and against `fly`: the same
//! records, fields, numbers and digits.

use super::*;
use crate::Scene;
use crate::analysis::precision::Purpose;
use crate::units::Quantity;

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
    assert!(matches!(records.next(), Ok(Record::TooLong)));
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

/// The splitter the batch had before [`Fields`]: the reference.
fn split_fields_before(text: &str) -> Result<Vec<String>, &'static str> {
    let mut fields = Vec::new();
    let mut field = String::new();
    let mut chars = text.chars().peekable();
    let mut quoted = false;
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            (true, '"') => quoted = false,
            (true, c) => field.push(c),
            (false, '"') if field.trim().is_empty() => {
                field.clear();
                quoted = true;
            }
            (false, ',') => fields.push(std::mem::take(&mut field)),
            (false, c) => field.push(c),
        }
    }
    if quoted {
        return Err("an unterminated quote");
    }
    fields.push(field);
    Ok(fields)
}

use crate::numerics::xorshift::uniform;

#[test]
fn fields_split_as_the_splitter_before_them() {
    // Spaces of Unicode's too (no-break, em): `trimmed` is `trim`.
    let alphabet = [
        'a', ' ', ',', '"', 'é', '\t', '\r', '\n', '1', '\u{a0}', '\u{2003}',
    ];
    let mut next = uniform(0x1234_5678_9abc_def1);
    let mut fields = Fields::default();
    for _ in 0..50_000 {
        let len = (next() * 14.0) as usize;
        let text: String = (0..len)
            .map(|_| alphabet[(next() * alphabet.len() as f64) as usize])
            .collect();
        let now = fields.split(&text).map(|()| {
            (0..fields.len())
                .map(|i| fields.get(i).to_owned())
                .collect()
        });
        assert_eq!(now, split_fields_before(&text), "{text:?}");
        for i in 0..fields.len() {
            assert_eq!(fields.trimmed(i), fields.get(i).trim(), "{text:?}");
        }
    }
    // A quote after leading spaces opens a quoted field (csv's reader would
    // take it as text and find three fields here).
    fields.split(r#"1, "a, b""#).unwrap();
    assert_eq!((fields.len(), fields.get(1)), (2, "a, b"));
}

#[test]
fn record_texts_are_each_records_own() {
    // Valid text; a byte that is no UTF-8; a character cut between two
    // records (valid together, not apart); a long record between.
    let pieces: [&[u8]; 6] = [b"a,1", "é,ü".as_bytes(), b"x\xff", b"y\xc3", b"\xa9z", b""];
    for skip in 0..pieces.len() {
        let records: Vec<&[u8]> = (0..pieces.len())
            .filter(|&k| k != skip)
            .map(|k| pieces[k])
            .collect();
        let mut bytes = b"ignored".to_vec();
        let mut spans = vec![Span::TooLong { line: 1 }];
        for (k, record) in records.iter().enumerate() {
            let start = bytes.len();
            bytes.extend_from_slice(record);
            spans.push(Span::Text {
                line: k + 2,
                start,
                end: bytes.len(),
            });
        }
        let texts = RecordTexts::new(&bytes, &spans);
        for span in &spans {
            if let Span::Text { start, end, .. } = *span {
                let own = String::from_utf8_lossy(&bytes[start..end]);
                assert_eq!(texts.get(start, end), own, "{skip}: {own:?}");
            }
        }
    }
}

#[test]
fn records_gathered_into_one_buffer_keep_their_lines() {
    let long = "x".repeat(MAX_RECORD_BYTES + 1);
    let text = format!("h\n\"a\nb\",1\r\n{long}\n\nlast\r\n");
    let mut records = Records::new(io::BufReader::with_capacity(1000, text.as_bytes()));
    let mut buffer = Vec::new();
    let mut spans = Vec::new();
    loop {
        match records.next_into(&mut buffer) {
            Ok(Span::End) => break,
            Ok(span) => spans.push(span),
            Err(_) => panic!("unexpected"),
        }
    }
    let text_of = |span: &Span| match *span {
        Span::Text { line, start, end } => (line, String::from_utf8_lossy(&buffer[start..end])),
        Span::TooLong { line } => (line, "too long".into()),
        Span::End => unreachable!(),
    };
    let got: Vec<_> = spans.iter().map(text_of).collect();
    let want = [
        (1, "h"),
        (2, "\"a\nb\",1"),
        (4, "too long"),
        (5, ""),
        (6, "last"),
    ];
    assert_eq!(got.len(), want.len());
    for ((line, text), (want_line, want_text)) in got.iter().zip(want) {
        assert_eq!((*line, text.as_ref()), (want_line, want_text));
    }
}

/// Runs the batch on `input`: (stdout, stderr, outcome).
fn run(setup: &Setup, input: &str, json: bool, shown: Shown) -> (String, String, Outcome) {
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let mut sinks = Sinks {
        out: &mut out,
        err: &mut err,
        erase: false,
    };
    let work = Work {
        what: "test",
        steps: None,
    };
    let outcome = progress::run(work, |p| {
        batch(setup, input.as_bytes(), json, shown, &mut sinks, p)
    })
    .unwrap();
    (
        String::from_utf8(out).unwrap(),
        String::from_utf8(err).unwrap(),
        outcome,
    )
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
    (code, fence): (&str, &crate::model::park::Fence),
    setup: &Setup,
    shown: Shown,
    statcast: Option<f64>,
) -> String {
    use crate::units::Quantity::*;
    let flown = super::super::ground::FlownToFence::new(scene, fence, &setup.fences, None);
    let (launch, flight) = (&flown.launch, &flown.flight);
    let distance = |m: Option<f64>, d| m.map_or(String::new(), |m| number(shown, Distance, m, d));
    let mut text = format!(
        "{line},{},{},{},{},{},{},{},{:.3},{},{},{},{},{code},{},{},{},false",
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
        flown.clears_fence(),
        flown.clearing.outcome.name(),
        distance(flown.clearing.margin, 3),
        flown.parks_cleared(),
    );
    if let Some(measured) = statcast {
        let difference = flight.landed.then_some(flight.range - measured);
        text += &format!(
            ",{},{}",
            distance(Some(measured), 2),
            distance(difference, 2)
        );
    }
    text
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
    let mut batch = crate::model::keys::InputBatch::new();
    for (key, value) in LAUNCH_KEYS.iter().zip(launch) {
        batch.set_text(&mut scene, key, &value.to_string()).unwrap();
    }
    scene
}

/// Launches whose range, as `fly` flies them, lies within ~1e-9 m of a
/// rounding boundary of its printed millimetre: the launch speed moved by
/// Newton's method onto the boundary.
fn on_rounding_boundaries(base: &Scene, rows: usize, setup: &Setup) -> Vec<[f64; 5]> {
    let fence = crate::model::park::Fence::uniform(121.92, 3.0);
    let range = |launch: &[f64; 5]| {
        let scene = launched(base, launch);
        super::super::ground::FlownToFence::new(&scene, &fence, &setup.fences, None)
            .flight
            .range
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
    let preset = crate::preset::load("fly-ball", None).unwrap();
    let parks = crate::preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let generic = crate::preset::Fence::generic().uniform();
    let imperial = Shown(crate::units::UnitSystem::Imperial);
    let boundary = on_rounding_boundaries(&preset.scene, 300, &setup);
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
        assert_eq!(outcome.flown, rows.len(), "{err}");
        let got = out.split_once('\n').unwrap().1;
        for (got, want) in got.lines().zip(want.lines()) {
            assert_eq!(got, want);
        }
        assert_eq!(got, want);
    }
    // The test bites: flown once at the batch's tolerance, without the
    // readout's second flight, many boundary rows print another millimetre.
    let batch = Purpose::Batch.flight_options();
    let unguarded = boundary
        .iter()
        .filter(|launch| {
            let scene = launched(&preset.scene, launch);
            let (flight, _, _) = crate::model::launch::scene_start(&scene);
            let loose = flight.judge(&batch, &[&generic]).0.range;
            let fly = super::super::ground::FlownToFence::new(&scene, &generic, &[], None);
            format!("{loose:.3}") != format!("{:.3}", fly.flight.range)
        })
        .count();
    assert!(
        unguarded >= boundary.len() / 10,
        "{unguarded} of {}",
        boundary.len()
    );
}

#[test]
fn savant_rows_at_their_parks_print_what_fly_prints_there() {
    let preset = crate::preset::load("fly-ball", None).unwrap();
    let parks = crate::preset::parks::all(None).unwrap();
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
        super::super::ground::to_park(&mut scene, park, Default::default());
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
    let preset = crate::preset::load("fly-ball", None).unwrap();
    let parks = crate::preset::parks::all(None).unwrap();
    let mut setup = Setup::new(&preset, &parks);
    setup.keep = vec!["des".to_owned()];
    let generic = crate::preset::Fence::generic().uniform();
    // Good rows between bad ones, across pieces (hundreds of rows).
    let bad = [
        "abc,0.5,200,x",
        "1e999,0.5,200,x",
        "40,nan,200,x",
        "40,0.5",
        "40,0.5,200,x,extra",
        "40,3,200,x",
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
            if !row.starts_with(' ') {
                input += &format!("{row}\r\n");
                failed.push(line);
                continue;
            }
            // A quote after a space opens the field: this row flies.
            let launch = [40.0, 0.5, 200.0, 0.0, 0.0];
            (row.to_owned(), launch, "\"a, \"\"b\"\"\"")
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
