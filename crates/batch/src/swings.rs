//! `tui --savant FILE`: the swings of a Savant export with bat tracking,
//! each solved as `hit --batch` solves it (`solve_row`) and made a scene
//! the explorer opens, so that a teacher can step through the impact of a
//! real swing.

use std::io::BufRead;

use crate::header::Header;
use crate::pieces::{Piece, Stage, stream};
use crate::read::Records;
use crate::row::Job;
use crate::setup::Setup;
use analysis::shown::Shown;
use model::launch::scene_start;
use model::scene::{GivenLaunch, Scene, SceneKind};
use preset::compact::CompactPresets;
use preset::{Preset, Source, escape_cut};
use units::Quantity;

/// The columns that name a swing in the picker, where the file has them.
const NAMING: [&str; 2] = ["player_name", "game_date"];

/// What `solved_swings` found: the solved swings as presets, in the
/// file's order (held compactly: a million fit in a few hundred MB), and
/// how many tracked rows were not solved.
pub struct Swings {
    pub presets: CompactPresets,
    pub rows: usize,
    pub unsolved: usize,
}

/// Reads `input` and solves each row's swing: the solved ones as presets
/// for the explorer, bad rows named to `note`.
pub fn solved_swings(
    setup: &mut Setup,
    input: impl BufRead,
    shown: Shown,
    note: &mut dyn FnMut(&str),
) -> Result<Swings, String> {
    // Each preset made compact as it comes: a million swings held whole
    // would pass 1 GB.
    let mut presets = CompactPresets::new();
    let (rows, tracked) = each_solved_swing(setup, input, (shown, note), &mut |p| presets.push(p))?;
    // Held while the explorer runs: no room past the swings.
    presets.shrink_to_fit();
    Ok(Swings {
        unsolved: tracked - presets.len(),
        presets,
        rows,
    })
}

/// Reads `input` and solves each row's swing, giving each solved one to
/// `take` as a preset, in the file's order; bad rows named to `note`. The
/// rows read and how many had a tracked swing.
fn each_solved_swing(
    setup: &mut Setup,
    input: impl BufRead,
    (shown, note): (Shown, &mut dyn FnMut(&str)),
    take: &mut dyn FnMut(&Preset),
) -> Result<(usize, usize), String> {
    setup.solve_swings = true;
    let mut records = Records::new(input);
    let (names, line) = crate::read::read_header(&mut records)?.ok_or("the input is empty")?;
    setup.keep = (NAMING.iter())
        .filter(|n| names.iter().any(|m| m.trim() == **n))
        .map(|n| (*n).to_owned())
        .collect();
    let header = Header::new((names, line), setup)?;
    let setup = &*setup;
    let finish = |piece: &mut Piece<(Vec<Preset>, usize)>| {
        let (presets, tracked) = &mut piece.made;
        presets.clear();
        *tracked = (piece.jobs.iter())
            .filter(|j| j.swing.is_some_and(|s| s.tracked.is_ok()))
            .count();
        presets.extend((piece.jobs.iter()).filter_map(|job| swing_preset(job, &setup.keep, shown)));
        piece.answered = piece.jobs.len();
    };
    let mut tracked = 0;
    let take_piece = |piece: &mut Piece<(Vec<Preset>, usize)>| {
        piece.made.0.iter().for_each(&mut *take);
        tracked += piece.made.1;
        Ok(true)
    };
    let outcome = stream(
        (setup, &header),
        &mut records,
        Stage::Solved,
        finish,
        take_piece,
        note,
    )?;
    let rows = outcome.answered + outcome.failed + outcome.without_launch;
    Ok((rows, tracked))
}

/// A solved row as a preset: its swing scene (the launch left to the
/// impact), named by batter and date, described by what was measured and
/// what the explorer's impact gives.
fn swing_preset(job: &Job, kept: &[String], shown: Shown) -> Option<Preset> {
    let swing = job.swing?;
    let solved = swing.solved()?;
    let tracked = swing.tracked.ok()?;
    let mut scene = solved.scene;
    scene.kind = SceneKind::Swing;
    scene.launch = GivenLaunch::default();
    // The explorer's pitch comes down the paper's path (Eq. 3) at the
    // tracked speed, not the tracked pitch's own (up to 4° steeper or
    // flatter): the undercut is solved again so that its launch angle is
    // the measured one; the exit speed then differs a little, and the
    // description says by how much.
    fit_launch_angle(&mut scene, tracked.launch_angle);
    let (_, here, _) = scene_start(&scene);
    // The cell of a kept column (`kept` names them, in order), if any.
    let cell = |name: &str| {
        let at = kept.iter().position(|k| k == name)?;
        job.kept.get(at).filter(|c| !c.is_empty())
    };
    let batter = cell("player_name").map_or("row", |n| n.split(',').next().unwrap_or(n));
    let date = cell("game_date").map_or(String::new(), |d| d.chars().skip(5).collect());
    let speed = |v: f64| shown.value(Quantity::Speed, v, 1);
    let angle = |a: f64| shown.angle_and_degrees(a, 3, 1);
    let size = |e: f64| shown.value_to(Quantity::Size, e, if shown.is_si() { 4 } else { 2 });
    // Off the sweet spot, the bat's speed where it met the ball.
    let contact = match solved.off_sweet_spot {
        true => format!(
            ", bat {} of {} at the contact",
            speed(solved.scene.bat.speed),
            speed(tracked.bat_speed)
        ),
        false => String::new(),
    };
    // The bat's lead over its measured path, where solved (a 2025 row).
    let lead = solved.scene.bat.lead;
    let lead = match lead == 0.0 {
        true => String::new(),
        false => format!(", lead {}", angle(lead)),
    };
    let description = format!(
        "{}, line {}{}: measured {} at {}; solved E {}, ψ {}, tilt {}{lead}{contact}, {}, q {:.3}, \
         {}; here {} at {} (E for the paper's pitch path)",
        // "Ohtani, Shohei" as "Shohei Ohtani": found by either name.
        cell("player_name").map_or(String::from("?"), |n| match n.split_once(", ") {
            Some((last, first)) => format!("{first} {last}"),
            None => n.clone(),
        }),
        job.line,
        cell("game_date").map_or(String::new(), |d| format!(", {d}")),
        speed(tracked.launch_speed),
        angle(tracked.launch_angle),
        size(scene.bat.undercut),
        angle(solved.scene.bat.swing_angle),
        // The row's swing_path_tilt, or the league's.
        angle(solved.scene.bat.tilt),
        solved.regime.name(),
        analysis::bat_tracking::collision_efficiency(
            tracked.launch_speed,
            tracked.pitch.speed(),
            tracked.bat_speed
        ),
        // The bat solved with: its season's, or the preset's.
        match swing.bat {
            Some(bat) => format!(
                "the {} bat (M_B {:.3} kg)",
                bat.season, swing.effective_mass
            ),
            None => format!("the preset's bat (M_B {:.3} kg)", swing.effective_mass),
        },
        speed(here.speed),
        angle(here.angle),
    );
    Some(Preset {
        // The picker gives a name 14 columns, a space after it: the date
        // kept whole, the batter cut.
        name: format!(
            "{} {date}",
            escape_cut(batter, 12usize.saturating_sub(date.chars().count()))
        )
        .trim_end()
        .to_owned(),
        description,
        scene,
        fence: Some(job.fence),
        explorer: None,
        source: Source::Bundled,
    })
}

/// Moves `scene`'s undercut until its impact launches at `angle` (rad):
/// the secant method from the undercut it has (the launch angle rises
/// about 1.3° a millimetre), to 1e-9 rad; left where it got to if it
/// does not (a row near the edge of what any undercut gives).
fn fit_launch_angle(scene: &mut Scene, angle: f64) {
    let miss = |scene: &Scene| scene_start(scene).1.angle - angle;
    let mut previous = (scene.bat.undercut, miss(scene));
    let mut undercut = previous.0 + 1e-3;
    for _ in 0..30 {
        let mut trial = *scene;
        trial.bat.undercut = undercut;
        if trial.validate().is_err() {
            return;
        }
        let now = miss(&trial);
        *scene = trial;
        if now.abs() < 1e-9 || now == previous.1 {
            return;
        }
        let next = undercut - now * (undercut - previous.0) / (now - previous.1);
        previous = (undercut, now);
        undercut = next;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The committed sample's swings (tests/data/savant_swings.csv, 35 real
    /// rows of April 2024): each solved one a swing scene named by batter
    /// and date, whose impact in the explorer (the paper's pitch path at the
    /// tracked speed) launches close to what Statcast measured.
    #[test]
    fn a_savant_files_swings_open_as_scenes_near_their_measured_launch() {
        let preset = preset::load("fastball", None).unwrap();
        let parks = preset::parks::all(None).unwrap();
        let mut setup = Setup::new(&preset, &parks);
        let swings = solved_swings(
            &mut setup,
            crate::open("../../tests/data/savant_swings.csv").unwrap(),
            Shown::default(),
            &mut |_| {},
        )
        .unwrap();
        // With the 2024 bat (M_B 0.8843 kg) two of the three too fast for
        // the paper's bat are solved; the bunt too slow and one still too
        // fast are not.
        assert_eq!(
            (swings.rows, swings.presets.len(), swings.unsolved),
            (35, 33, 2)
        );
        let presets: Vec<Preset> = (0..swings.presets.len())
            .map(|i| swings.presets.preset(i))
            .collect();
        assert!(
            (presets[0].description).contains("the 2024 bat (M_B 0.884 kg)"),
            "{}",
            presets[0].description
        );
        assert_eq!(presets[0].scene.bat.effective_mass, 0.8843);
        let first = &presets[0];
        assert_eq!(first.name, "Hender… 04-03");
        assert!(
            first
                .description
                .starts_with("Gunnar Henderson, line 2, 2024-04-03: measured 42.1 m/s"),
            "{}",
            first.description
        );
        let mut worst = (0.0f64, 0.0f64);
        for preset in &presets {
            assert_eq!(preset.scene.kind, SceneKind::Swing);
            assert!(preset.name.chars().count() <= 13, "{}", preset.name);
            preset.scene.validate().unwrap();
            let (_, here, _) = scene_start(&preset.scene);
            // The measured launch, from the description's "measured … at …".
            let measured: Vec<f64> = (preset.description.split("measured ").nth(1).unwrap())
                .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
                .filter_map(|t| t.parse().ok())
                .take(2)
                .collect();
            let off = (here.angle - measured[1]).abs().to_degrees();
            // A popup near 90° may lie past the paper's pitch path's
            // reach (Outman's 83°: 69.6° at the most with the bat in its
            // tilted swing plane, 79.6° before); it opens at the steepest
            // the explorer's impact gives, and says so.
            if measured[1] > 1.3 {
                assert!(off < 15.0, "{}", preset.description);
                continue;
            }
            worst.0 = worst.0.max((here.speed - measured[0]).abs());
            worst.1 = worst.1.max(off);
        }
        // The angle as measured (to the description's 3 decimals of a
        // radian); the speed within 1.5 m/s: the pitch's path is the
        // paper's, not the tracked one's.
        assert!(worst.0 < 1.5 && worst.1 < 0.03, "{worst:?}");
    }

    /// The batter is named from `player_name` whatever other naming column
    /// the file lacks (here its `game_date`, renamed away).
    #[test]
    fn a_swing_is_named_by_its_batter_without_a_date() {
        let text = std::fs::read_to_string("../../tests/data/savant_swings.csv").unwrap();
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no-date.csv");
        std::fs::write(&path, text.replacen("game_date", "day", 1)).unwrap();
        let preset = preset::load("fastball", None).unwrap();
        let parks = preset::parks::all(None).unwrap();
        let mut setup = Setup::new(&preset, &parks);
        let input = crate::open(path.to_str().unwrap()).unwrap();
        let swings = solved_swings(&mut setup, input, Shown::default(), &mut |_| {}).unwrap();
        assert_eq!(swings.presets.name(0), "Henderson");
        assert!(
            swings
                .presets
                .description(0)
                .starts_with("Gunnar Henderson, line 2: measured")
        );
    }

    /// Each swing held compactly opens as the preset its row made, bit for
    /// bit (scene, fence, name and description): the committed sample's,
    /// and those of April 2024's bat-tracking file where it is at hand.
    #[test]
    fn a_compact_swing_opens_bit_for_bit_as_its_row_made_it() {
        let april = "../../../shared/data/statcast-2024-04-balls-in-play.csv";
        let leading = "../../tests/data/savant_2025_every_20th.csv";
        for file in ["../../tests/data/savant_swings.csv", leading, april] {
            let Ok(input) = crate::open(file) else {
                assert_eq!(file, april, "the committed sample opens");
                continue;
            };
            let preset = preset::load("fastball", None).unwrap();
            let parks = preset::parks::all(None).unwrap();
            let mut setup = Setup::new(&preset, &parks);
            let mut whole = Vec::new();
            let mut quiet = |_: &str| {};
            let shown: (Shown, &mut dyn FnMut(&str)) = (Shown::default(), &mut quiet);
            each_solved_swing(&mut setup, input, shown, &mut |p| whole.push(p.clone())).unwrap();
            let swings = solved_swings(
                &mut setup,
                crate::open(file).unwrap(),
                Shown::default(),
                &mut |_| {},
            )
            .unwrap();
            assert_eq!(swings.presets.len(), whole.len());
            assert!(whole.len() >= 33, "{file}: {}", whole.len());
            // 2025's rows measure the bat's path: each swing carries its
            // solved lead, in its scene and its description.
            if file == leading {
                assert!(
                    whole
                        .iter()
                        .all(|p| p.scene.bat.lead != 0.0 && p.description.contains(", lead "))
                );
            }
            for (i, made) in whole.iter().enumerate() {
                let opened = swings.presets.preset(i);
                assert_eq!(
                    format!("{opened:?}"),
                    format!("{made:?}"),
                    "{file} swing {i}"
                );
                assert_eq!(
                    opened.scene.bat.undercut.to_bits(),
                    made.scene.bat.undercut.to_bits()
                );
            }
            // Shared by parks, hands and seasons' bats: a few dozen at most.
            assert!(
                swings.presets.backgrounds() <= 200,
                "{}",
                swings.presets.backgrounds()
            );
        }
    }
}
