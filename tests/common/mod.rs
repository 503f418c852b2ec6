//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::Path;
use std::process::Output;

use homerun::Scene;
use homerun::preset;

/// The binary as every test starts it: with neither `HOME` nor
/// `XDG_CONFIG_HOME`, so that it has no user folder and the developer's own
/// presets and parks never reach a test (a test that wants a folder of
/// presets or parks passes its own, with `--presets-dir` or `--parks-dir`).
pub fn command() -> std::process::Command {
    let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_homerun"));
    command.env_remove("HOME").env_remove("XDG_CONFIG_HOME");
    command
}

/// [`command`], for assert_cmd's checks.
pub fn assert_command() -> assert_cmd::Command {
    assert_cmd::Command::from_std(command())
}

/// `homerun` with `presets` as the user's preset folder (an empty one, so
/// that the machine's own presets never change a result), and neither HOME
/// nor XDG_CONFIG_HOME (so that its parks never do either).
pub fn homerun(presets: &Path, args: &[&str]) -> Output {
    command()
        .arg("--presets-dir")
        .arg(presets)
        .args(args)
        .output()
        .unwrap()
}

/// A bundled preset's scene.
pub fn scene(name: &str) -> Scene {
    preset::load(name, None).expect("bundled preset").scene
}

/// The fastball with every input that matters to the impact replaced:
/// the pitch (speed, spin), the bat (speed, roll), the swing (E, ψ, μ) and
/// the masses (bat, ball), for the property tests' random scenes.
pub fn impact_scene(
    (pitch_speed, pitch_spin): (f64, f64),
    (bat_speed, bat_spin): (f64, f64),
    (undercut, swing_angle, friction): (f64, f64, f64),
    (bat_mass, ball_mass): (f64, f64),
) -> Scene {
    let mut s = Scene::default();
    s.pitch.speed = pitch_speed;
    s.pitch.spin = pitch_spin;
    s.bat.speed = bat_speed;
    s.bat.spin = bat_spin;
    s.bat.undercut = undercut;
    s.bat.swing_angle = swing_angle;
    s.bat.friction = friction;
    s.bat.effective_mass = bat_mass;
    s.ball.mass = ball_mass;
    s
}

/// `scene` with its swing replaced by (E, ψ).
pub fn with_swing(scene: &Scene, undercut: f64, swing_angle: f64) -> Scene {
    scene.with_swing(undercut, swing_angle)
}

/// The point in [lo, hi] where the predicate `f` changes value, found by
/// bisection to well below a micrometre. `f(lo)` and `f(hi)` must differ.
pub fn bisect(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> bool) -> f64 {
    let at_lo = f(lo);
    assert_ne!(at_lo, f(hi), "no change of the predicate in [{lo}, {hi}]");
    while hi - lo > 1e-10 {
        let mid = 0.5 * (lo + hi);
        if f(mid) == at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// One row of a reference fixture (tests/data/*_reference.csv), by column
/// name.
pub struct Row<'a> {
    pub names: &'a [&'a str],
    pub fields: Vec<&'a str>,
}

impl Row<'_> {
    pub fn text(&self, name: &str) -> &str {
        let i = self.names.iter().position(|n| *n == name).expect(name);
        self.fields[i]
    }
    pub fn number(&self, name: &str) -> f64 {
        self.text(name).parse().expect(name)
    }
}

/// Runs the binary with `args` (and `input` on stdin): exit status, stdout
/// and stderr.
pub fn run_homerun(args: &[&str], input: Option<&str>) -> (Option<i32>, String, String) {
    run_with_stdin(args, input.map(str::as_bytes))
}

/// [`run_homerun`] with any bytes on stdin (gzip, a BOM, binary data).
pub fn run_with_stdin(args: &[&str], input: Option<&[u8]>) -> (Option<i32>, String, String) {
    let mut command = assert_command();
    command.args(args);
    if let Some(input) = input {
        command.write_stdin(input);
    }
    let out = command.output().unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}
