//! Hostile preset files: whatever a path given as a preset (or found in the
//! presets folder) holds, `homerun` answers at once, with one line naming the
//! file and why, and never blocks or floods its memory. Every run has a time
//! limit and a memory limit, so a regression fails here instead of hanging
//! or eating the machine.
#![cfg(unix)]

use std::ffi::CString;
use std::os::unix::ffi::OsStrExt;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::Output;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use assert_cmd::Command;

const LIMIT: Duration = Duration::from_secs(10);

/// `homerun ARGS`, with `--presets-dir dir` (the machine's own presets never
/// count), at most [`LIMIT`] of time and 1 GiB of address space.
fn run(dir: &Path, args: &[&str]) -> Output {
    let mut std = std::process::Command::new(env!("CARGO_BIN_EXE_homerun"));
    std.env_remove("HOME")
        .env_remove("XDG_CONFIG_HOME")
        .arg("--presets-dir")
        .arg(dir)
        .args(args);
    // SAFETY: `setrlimit` is async-signal-safe and touches no memory of ours.
    unsafe {
        std.pre_exec(|| {
            let limit = libc::rlimit {
                rlim_cur: 1 << 30,
                rlim_max: 1 << 30,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let start = Instant::now();
    let output = Command::from_std(std).timeout(LIMIT).output().unwrap();
    assert!(
        output.status.code().is_some() && start.elapsed() < LIMIT,
        "{args:?} did not finish by itself in {LIMIT:?}: {:?}",
        output.status
    );
    output
}

/// Runs `args`, expecting exit status 2, nothing on stdout, and exactly one
/// line on stderr, `homerun: …`, containing every needle and no control
/// character; returns that line.
fn refused(dir: &Path, args: &[&str], needles: &[&str]) -> String {
    let output = run(dir, args);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(output.stdout.is_empty(), "{args:?}: {output:?}");
    one_line(&stderr, args);
    assert!(stderr.starts_with("homerun: "), "{args:?}: {stderr}");
    for needle in needles {
        assert!(
            stderr.contains(needle),
            "{args:?}: {needle:?} not in {stderr}"
        );
    }
    stderr
}

/// `text` is exactly one line, with no control character in it.
fn one_line(text: &str, args: &[&str]) {
    let line = text.strip_suffix('\n').unwrap_or(text);
    assert!(!line.is_empty(), "{args:?}: empty");
    assert!(
        !line.chars().any(char::is_control),
        "{args:?}: more than one line, or a control character: {text:?}"
    );
}

/// `homerun presets`, expecting it to list everything (status 0, nothing on
/// stderr) with exactly one `(broken)` line containing every needle.
fn listed_broken(dir: &Path, needles: &[&str]) {
    let output = run(dir, &["presets"]);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert!(output.stderr.is_empty(), "{output:?}");
    assert!(stdout.contains("fastball"), "{stdout}");
    let broken: Vec<_> = stdout
        .lines()
        .filter(|l| l.starts_with("(broken)"))
        .collect();
    assert_eq!(broken.len(), 1, "{stdout}");
    one_line(broken[0], &["presets"]);
    for needle in needles {
        assert!(broken[0].contains(needle), "{needle:?} not in {stdout}");
    }
}

fn mkfifo(path: &Path) {
    let c = CString::new(path.as_os_str().as_bytes()).unwrap();
    // SAFETY: a valid NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0, "{path:?}");
}

fn text(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// A temporary folder (the presets folder) and a path inside it.
fn folder() -> (tempfile::TempDir, impl Fn(&str) -> PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path().to_owned();
    (dir, move |name: &str| root.join(name))
}

#[test]
fn dev_zero_as_preset() {
    let (dir, _) = folder();
    refused(
        dir.path(),
        &["hit", "--preset", "/dev/zero"],
        &["/dev/zero: not a regular file (a character device)"],
    );
}

#[test]
fn fifo_as_preset_path() {
    let (dir, at) = folder();
    mkfifo(&at("f.toml"));
    refused(
        dir.path(),
        &["hit", "--preset", text(&at("f.toml"))],
        &["f.toml: not a regular file (a FIFO)"],
    );
}

#[test]
fn fifo_in_the_presets_folder() {
    let (dir, at) = folder();
    mkfifo(&at("fifo.toml"));
    listed_broken(dir.path(), &["fifo.toml: not a regular file (a FIFO)"]);
    refused(
        dir.path(),
        &["hit", "--preset", "fifo"],
        &["fifo.toml: not a regular file (a FIFO)"],
    );
}

#[test]
fn symlink_to_dev_zero_in_the_presets_folder() {
    let (dir, at) = folder();
    std::os::unix::fs::symlink("/dev/zero", at("zero.toml")).unwrap();
    let why = "zero.toml: not a regular file (a character device, through a symlink to /dev/zero)";
    listed_broken(dir.path(), &[why]);
    refused(dir.path(), &["hit", "--preset", "zero"], &[why]);
}

#[test]
fn symlink_loop() {
    let (dir, at) = folder();
    std::os::unix::fs::symlink(at("loop.toml"), at("loop.toml")).unwrap();
    let why = "loop.toml: a symlink loop";
    listed_broken(dir.path(), &[why]);
    refused(dir.path(), &["hit", "--preset", "loop"], &[why]);
    refused(
        dir.path(),
        &["hit", "--preset", text(&at("loop.toml"))],
        &[why],
    );
}

#[test]
fn dangling_symlink() {
    let (dir, at) = folder();
    std::os::unix::fs::symlink(at("nowhere"), at("gone.toml")).unwrap();
    let why = "gone.toml: a symlink to ";
    listed_broken(dir.path(), &[why, "which does not exist"]);
    refused(dir.path(), &["hit", "--preset", "gone"], &[why]);
}

#[test]
fn folder_named_like_a_preset() {
    let (dir, at) = folder();
    std::fs::create_dir(at("x.toml")).unwrap();
    let why = "x.toml: not a regular file (a folder)";
    listed_broken(dir.path(), &[why]);
    refused(dir.path(), &["hit", "--preset", "x"], &[why]);
    refused(
        dir.path(),
        &["hit", "--preset", text(&at("x.toml"))],
        &[why],
    );
}

#[test]
fn millions_of_tiny_tables_are_refused_by_size() {
    let (dir, at) = folder();
    // 5 million tiny tables, as the tester's file: "[t0]\n[t1]\n…" (~54 MB).
    let mut tables = Vec::with_capacity(54 << 20);
    for i in 0..5_000_000 {
        use std::io::Write;
        writeln!(tables, "[t{i}]").unwrap();
    }
    std::fs::write(at("big.toml"), &tables).unwrap();
    drop(tables);
    refused(
        dir.path(),
        &["hit", "--preset", text(&at("big.toml"))],
        &["big.toml: 51 MiB, presets are at most 1 MiB"],
    );
    listed_broken(dir.path(), &["big.toml: 51 MiB"]);
    // One byte over the cap is refused; the cap itself is allowed.
    std::fs::remove_file(at("big.toml")).unwrap();
    std::fs::write(at("over.toml"), "#".repeat((1 << 20) + 1)).unwrap();
    refused(
        dir.path(),
        &["hit", "--preset", "over"],
        &["over.toml: 1048577 bytes, presets are at most 1 MiB"],
    );
    std::fs::write(at("over.toml"), "#".repeat(1 << 20)).unwrap();
    assert_eq!(
        run(dir.path(), &["hit", "--preset", "over"]).status.code(),
        Some(0)
    );
}

#[test]
fn a_megabyte_of_nesting_or_of_one_line_errors_fast_and_short() {
    let (dir, at) = folder();
    let half = (1 << 20) / 2 - 8;
    for (name, text, why) in [
        (
            "arrays",
            format!("a = {}{}", "[".repeat(half), "]".repeat(half)),
            "recursion",
        ),
        (
            "tables",
            format!("a = {}{}", "{b=".repeat(half / 2), "}".repeat(half / 2)),
            "recursion",
        ),
        ("dotted", format!("a{} = 1", ".a".repeat(half)), "recursion"),
        (
            "line",
            format!("a = \"{}", "x".repeat(2 * half)),
            "expected `\"`",
        ),
    ] {
        std::fs::write(at(&format!("{name}.toml")), text).unwrap();
        let line = refused(dir.path(), &["hit", "--preset", name], &[why]);
        assert!(line.len() < 1000, "{name}: {} bytes", line.len());
    }
}

#[test]
fn binary_garbage() {
    let (dir, at) = folder();
    let garbage: Vec<u8> = (0..4096u32)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 13) as u8)
        .collect();
    std::fs::write(at("garbage.toml"), garbage).unwrap();
    refused(
        dir.path(),
        &["hit", "--preset", "garbage"],
        &["garbage.toml: not a text file (a NUL byte at byte "],
    );
    std::fs::write(at("garbage.toml"), b"description = \"caf\xe9\"\n").unwrap();
    refused(
        dir.path(),
        &["hit", "--preset", "garbage"],
        &["garbage.toml: not UTF-8 text (an invalid byte at byte 18)"],
    );
    listed_broken(dir.path(), &["garbage.toml: not UTF-8 text"]);
}

#[test]
fn terminal_escapes_in_the_file_and_in_its_name() {
    let (dir, at) = folder();
    // Raw escapes are not valid TOML: refused, the quoted line escaped.
    std::fs::write(
        at("raw.toml"),
        "description = \"\x1b[31mred\x1b]0;title\x07\"\n",
    )
    .unwrap();
    refused(
        dir.path(),
        &["hit", "--preset", "raw"],
        &["raw.toml: malformed TOML", "\\u{1b}[31mred"],
    );
    // Escaped in TOML, they are a valid description: loaded without panic
    // (how the listing prints them is the CLI's business).
    std::fs::remove_file(at("raw.toml")).unwrap();
    std::fs::write(
        at("quoted.toml"),
        "description = \"\\u001b[31mred\\u001b]0;title\\u0007\"\n",
    )
    .unwrap();
    assert_eq!(
        run(dir.path(), &["hit", "--preset", "quoted"])
            .status
            .code(),
        Some(0)
    );
    assert_eq!(run(dir.path(), &["presets"]).status.code(), Some(0));
    // A key full of escapes, and a file name with ESC and a newline.
    std::fs::write(at("quoted.toml"), "[bat]\n\"\\u001b[2J\" = 1\n").unwrap();
    refused(
        dir.path(),
        &["hit", "--preset", "quoted"],
        &["unknown key `bat.\\u{1b}[2J`"],
    );
    std::fs::remove_file(at("quoted.toml")).unwrap();
    let name = at("a\x1b[2J\nb.toml");
    mkfifo(&name);
    let why = "a\\u{1b}[2J\\u{a}b.toml: not a regular file (a FIFO)";
    refused(dir.path(), &["hit", "--preset", text(&name)], &[why]);
    listed_broken(dir.path(), &[why]);
}

#[test]
fn a_file_as_the_presets_folder() {
    let (_dir, at) = folder();
    std::fs::write(at("file"), "").unwrap();
    let why = "file: not a folder (a regular file), so it cannot hold presets";
    refused(&at("file"), &["presets"], &[why]);
    // Looking a name up in it is refused too.
    refused(&at("file"), &["hit", "--preset", "fastball"], &[why]);
    refused(
        Path::new("/etc/passwd"),
        &["presets"],
        &["/etc/passwd: not a folder (a regular file)"],
    );
    mkfifo(&at("fifo"));
    refused(&at("fifo"), &["presets"], &["fifo: not a folder (a FIFO)"]);
    // A missing folder holds no presets, as before.
    let output = run(&at("missing"), &["presets"]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert!(output.stderr.is_empty());
}

/// The explorer's picker (`o`) lists the folder with `preset::list`, on its
/// UI thread: it must return at once whatever the folder holds.
#[test]
fn listing_a_hostile_folder_returns_at_once() {
    let (dir, at) = folder();
    mkfifo(&at("fifo.toml"));
    std::os::unix::fs::symlink("/dev/zero", at("zero.toml")).unwrap();
    std::os::unix::fs::symlink(at("loop.toml"), at("loop.toml")).unwrap();
    std::fs::create_dir(at("dir.toml")).unwrap();
    std::fs::write(at("ok.toml"), "[bat]\nspeed = 31\n").unwrap();
    let root = dir.path().to_owned();
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || send.send(homerun::preset::list(Some(&root))));
    let all = receive.recv_timeout(LIMIT).expect("list returned");
    let broken: Vec<String> = all
        .iter()
        .filter_map(|p| p.as_ref().err().map(ToString::to_string))
        .collect();
    assert_eq!(broken.len(), 4, "{broken:?}");
    assert!(all.iter().any(|p| p.as_ref().is_ok_and(|p| p.name == "ok")));
}

/// F1: saving a preset onto a FIFO (the explorer's `s`, name `pipe`) once
/// froze the explorer, writing into the pipe until a reader came. A save
/// refuses anything but a regular file or a new name, at once.
#[test]
fn saving_a_preset_onto_a_fifo_or_a_device_is_refused_at_once() {
    let (dir, at) = folder();
    mkfifo(&at("pipe.toml"));
    std::os::unix::fs::symlink("/dev/null", at("null.toml")).unwrap();
    std::fs::create_dir(at("dir.toml")).unwrap();
    let root = dir.path().to_owned();
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let mut preset = homerun::preset::load("fastball", None).unwrap();
        let mut results = Vec::new();
        for name in ["pipe", "null", "dir", "new"] {
            preset.name = name.to_owned();
            results.push(preset.save(&root, false).map_err(|e| e.to_string()));
        }
        send.send(results).unwrap();
    });
    let results = receive.recv_timeout(LIMIT).expect("the saves returned");
    let why = |i: usize| results[i].as_ref().unwrap_err().clone();
    assert!(
        why(0).ends_with("pipe.toml: not a regular file (a FIFO)"),
        "{results:?}"
    );
    assert!(
        why(1).ends_with(
            "null.toml: not a regular file (a character device, through a symlink to /dev/null)"
        ),
        "{results:?}"
    );
    assert!(why(2).ends_with("dir.toml: not a regular file (a folder)"));
    // The FIFO is still one; a new name is saved and reads back.
    use std::os::unix::fs::FileTypeExt as _;
    let kind = std::fs::symlink_metadata(at("pipe.toml"))
        .unwrap()
        .file_type();
    assert!(kind.is_fifo());
    let saved = results[3].as_ref().unwrap();
    assert_eq!(
        homerun::preset::Preset::read(saved).unwrap().scene,
        homerun::preset::load("fastball", None).unwrap().scene
    );
}

/// A CSV `calibrate` fits: home runs' launches (mph, °) and distances (ft),
/// with `extra` columns after them (the header's, then each row's cells).
fn calibration_csv(dir: &Path, extra: (&str, &[String])) -> PathBuf {
    let mut text = format!("launch_speed,launch_angle,hit_distance_sc{}\n", extra.0);
    for i in 0..12 {
        let (speed, angle) = (98 + i, 24 + i % 8);
        let distance = 380 + 6 * i;
        let cells = extra.1.get(i as usize).map_or("", String::as_str);
        text += &format!("{speed},{angle},{distance}{cells}\n");
    }
    let path = dir.join("flights.csv");
    std::fs::write(&path, text).unwrap();
    path
}

/// Issue 25 row 5: `--svg out.svg` wrote its bytes to `.out.svg.PID.tmp`
/// with `File::create`, which follows a link planted there. The temporary
/// is now created new, at a name nobody can guess: links planted at every
/// PID the run may have are left alone.
#[test]
fn svg_never_writes_through_a_link_planted_at_a_temporary_name() {
    let (dir, elsewhere) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let victim = elsewhere.path().join("victim");
    std::fs::write(&victim, "keep me").unwrap();
    let read = |file: &str| {
        std::fs::read_to_string(file)
            .ok()
            .and_then(|t| t.trim().parse::<u32>().ok())
    };
    let last = read("/proc/sys/kernel/ns_last_pid").unwrap_or_else(std::process::id);
    let max = read("/proc/sys/kernel/pid_max").unwrap_or(u32::MAX);
    for next in last + 1..=last + 3000 {
        // Past the largest PID, Linux starts again from 300.
        let pid = if next > max { next - max + 300 } else { next };
        let planted = dir.path().join(format!(".out.svg.{pid}.tmp"));
        std::os::unix::fs::symlink(&victim, planted).unwrap();
    }
    let out = dir.path().join("out.svg");
    let output = run(dir.path(), &["trajectory", "--svg", out.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");
    assert!(std::fs::symlink_metadata(&out).unwrap().is_file());
    assert!(std::fs::read_to_string(&out).unwrap().contains("<svg"));
    // A link out of the folder at the target itself is not written through.
    let link = dir.path().join("link.svg");
    std::os::unix::fs::symlink(&victim, &link).unwrap();
    refused(
        dir.path(),
        &["trajectory", "--svg", link.to_str().unwrap()],
        &["link.svg", "outside its folder"],
    );
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");
}

/// Issue 25 row 6: `calibrate --save x` wrote through `x.toml`, a link out
/// of the presets folder, and silently overwrote a user's preset or hid a
/// bundled one. Each is refused, before the fit, in one line (exit 2);
/// `--force` overwrites and hides, never writes through the link.
#[test]
fn calibrate_save_refuses_links_out_and_overwrites_without_force() {
    let (dir, elsewhere) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let parks = elsewhere.path().join("parks");
    let parks = ["--parks-dir", parks.to_str().unwrap()];
    let csv = calibration_csv(elsewhere.path(), ("", &[]));
    let csv = csv.to_str().unwrap();
    let victim = elsewhere.path().join("victim.toml");
    std::fs::write(&victim, "keep me").unwrap();
    std::os::unix::fs::symlink(&victim, dir.path().join("x.toml")).unwrap();
    let save = |name: &str, force: bool| {
        let mut args = parks.to_vec();
        args.extend(["calibrate", csv, "--save", name]);
        if force {
            args.push("--force");
        }
        args.into_iter().map(str::to_owned).collect::<Vec<_>>()
    };
    fn args(v: &[String]) -> Vec<&str> {
        v.iter().map(String::as_str).collect()
    }
    let x = save("x", false);
    refused(dir.path(), &args(&x), &["preset `x` exists", "--force"]);
    let x = save("x", true);
    refused(dir.path(), &args(&x), &["x.toml", "outside its folder"]);
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");
    let fastball = save("fastball", false);
    refused(
        dir.path(),
        &args(&fastball),
        &["`fastball` is a bundled preset", "--force"],
    );
    assert!(!dir.path().join("fastball.toml").exists());
    // A new name is saved; again, it is refused; with --force, replaced.
    let mine = save("mine", false);
    assert_eq!(run(dir.path(), &args(&mine)).status.code(), Some(0));
    refused(dir.path(), &args(&mine), &["preset `mine` exists"]);
    let mine = save("mine", true);
    assert_eq!(run(dir.path(), &args(&mine)).status.code(), Some(0));
    let fastball = save("fastball", true);
    assert_eq!(run(dir.path(), &args(&fastball)).status.code(), Some(0));
    assert!(dir.path().join("fastball.toml").is_file());
}

/// Issue 25 row 10: rows with a hang time of 0 or an apex of 10⁹ ft were
/// fitted, pinning the factors at their bounds. Each is named (column,
/// value, range) and left out; the rest are fitted.
#[test]
fn calibrate_leaves_out_implausible_measurements_naming_each() {
    let dir = tempfile::tempdir().unwrap();
    let mut cells: Vec<String> = (0..12).map(|_| ",5.6,110".to_owned()).collect();
    cells[3] = ",0,110".into();
    cells[7] = ",5.6,1000000000".into();
    let csv = calibration_csv(dir.path(), (",hang_time,apex", &cells));
    let parks = dir.path().join("parks");
    let output = run(
        dir.path(),
        &[
            "--parks-dir",
            parks.to_str().unwrap(),
            "calibrate",
            csv.to_str().unwrap(),
            "--json",
        ],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("line 5: hang_time = 0 s: outside (0, 12] s"),
        "{stderr}"
    );
    assert!(
        stderr.contains("line 9: apex = 1.000e9 ft: outside (0, 492.1] ft"),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 2, "{stderr}");
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["implausible"], 2);
    assert_eq!(json["measured"], 10);
}

/// A fit that ends at a bound of its search says so, and is not saved
/// without --force: hang times of 11.5 s for 400 ft flies ask more lift
/// than model.lift_scale's 3.
#[test]
fn calibrate_says_when_a_factor_ends_at_its_bound_and_saves_it_only_forced() {
    let dir = tempfile::tempdir().unwrap();
    let cells: Vec<String> = (0..12).map(|_| ",11.5".to_owned()).collect();
    let csv = calibration_csv(dir.path(), (",hang_time", &cells));
    let parks = dir.path().join("parks");
    let (parks, csv) = (parks.to_str().unwrap(), csv.to_str().unwrap());
    let output = run(dir.path(), &["--parks-dir", parks, "calibrate", csv]);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert!(
        stdout.contains("model.lift_scale = 3.0000 ended at the end of [0, 3] searched"),
        "{stdout}"
    );
    let save = ["--parks-dir", parks, "calibrate", csv, "--save", "pinned"];
    refused(
        dir.path(),
        &save,
        &[
            "calibrate --save pinned: ",
            "model.lift_scale = 3.0000 ended at the end of [0, 3] searched",
            "not saved (--force",
        ],
    );
    assert!(!dir.path().join("pinned.toml").exists());
    let forced = [&save[..], &["--force"]].concat();
    assert_eq!(run(dir.path(), &forced).status.code(), Some(0));
    assert!(dir.path().join("pinned.toml").is_file());
}

/// Issue 25 row 11: 6,600 user parks took 2.35 GB over a batch. At most
/// 200 are read, with one note; a fence of more than 1000 points is refused.
#[test]
fn user_parks_are_capped_with_one_note() {
    let (dir, parks) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let park = |code: &str, points: usize| {
        let step = std::f64::consts::FRAC_PI_2 / (points - 1) as f64;
        let fence: String = (0..points)
            .map(|i| {
                let direction = -std::f64::consts::FRAC_PI_4 + step * i as f64;
                format!("  {{ direction = {direction:.6}, distance = 100, height = 3 }},\n")
            })
            .collect();
        format!(
            "[[park]]\ncode = \"{code}\"\nname = \"Park {code}\"\nelevation = 10\ncenter_field_bearing = 45\nfence = [\n{fence}]\n"
        )
    };
    for i in 0..260 {
        let code = format!("Q{i:03}");
        std::fs::write(parks.path().join(format!("{code}.toml")), park(&code, 3)).unwrap();
    }
    let list = ["--parks-dir", parks.path().to_str().unwrap(), "parks"];
    let output = run(dir.path(), &list);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    one_line(&stderr, &list);
    assert!(
        stderr.contains("more than 200 parks or files (260 files); only the first 200 parks"),
        "{stderr}"
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        stdout.contains("Q199") && !stdout.contains("Q200"),
        "{stdout}"
    );
    // A fence of 1001 points: the file is refused, naming it.
    for i in 0..260 {
        std::fs::remove_file(parks.path().join(format!("Q{i:03}.toml"))).unwrap();
    }
    std::fs::write(parks.path().join("dense.toml"), park("DNS", 1001)).unwrap();
    refused(
        dir.path(),
        &list,
        &["dense.toml", "has 1001 points; a fence takes at most 1000"],
    );
}
