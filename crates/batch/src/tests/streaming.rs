//! The pieces' streaming: a reader that closes early, a batch inside the
//! pool, a piece that panics.

use super::*;

/// A reader that takes `room` bytes and then closes the pipe (`| head`).
struct Closing {
    room: usize,
}

impl io::Write for Closing {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        if self.room < bytes.len() {
            return Err(io::ErrorKind::BrokenPipe.into());
        }
        self.room -= bytes.len();
        Ok(bytes.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// Rows of launches enough for several pieces: `rows` balls, each its own.
fn many_rows(rows: usize) -> String {
    let mut input = String::from("launch_speed,launch_angle\n");
    for i in 0..rows {
        input += &format!("{},{}\n", 80 + i % 30, 5 + i % 40);
    }
    input
}

/// A reader that closes the pipe early ends the batch with exit status 0,
/// and the summary counts the rows written, not those flown for pieces it
/// never took: every count agrees with "flown N rows".
#[test]
fn a_reader_that_closes_early_gets_a_summary_of_what_was_written() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let input = many_rows(2000);
    let mut out = Closing { room: 40_000 };
    let (outcome, tally) = fly_rows(
        &setup,
        input.as_bytes(),
        Format::default(),
        &mut out,
        &mut |_| {},
        &|| {},
    )
    .unwrap();
    assert_eq!(outcome.exit_status(), 0);
    assert!(
        outcome.answered > 0 && outcome.answered < 2000,
        "{outcome:?}"
    );
    // Every row estimates its spin: the count is of the rows written.
    assert_eq!(tally.estimated, outcome.answered);
    assert_eq!(tally.answered, outcome.answered);
}

/// The batch run from inside the thread pool (a pool of one thread, the
/// batch on it) neither waits on itself nor changes an answer.
#[test]
fn a_batch_inside_a_pool_of_one_thread_finishes() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let input = many_rows(700);
    let (outside, _, _) = run(&setup, &input, false, Shown::default());
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let (inside, _, outcome) = pool.install(|| run(&setup, &input, false, Shown::default()));
    assert_eq!(outcome.answered, 700);
    assert_eq!(inside, outside);
}

/// A piece whose work panics ends the batch with that panic, where the
/// pieces' reader would otherwise wait for it forever.
#[test]
fn a_piece_that_panics_ends_the_batch_with_its_panic() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let input = many_rows(700);
    let mut records = Records::new(input.as_bytes());
    let names = read::read_header(&mut records).unwrap().unwrap();
    let header = Header::new(names, &setup).unwrap();
    let streamed = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        pieces::stream::<_, ()>(
            (&setup, &header),
            &mut records,
            pieces::Stage::Parsed,
            |piece| {
                if piece.jobs.iter().any(|job| job.line == 300) {
                    panic!("a piece's panic");
                }
            },
            |_| Ok(true),
            &mut |_| {},
        )
    }));
    let panic = streamed.expect_err("the panic, come back");
    assert_eq!(panic.downcast_ref::<&str>(), Some(&"a piece's panic"));
}
