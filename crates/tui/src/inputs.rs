//! The numeric inputs, as the explorer counts them (the rows of the inputs
//! pane, the cells of the Δ columns): every key of the table, and which of
//! them each scene shows. Beneath both `app` and `worker`.

use model::keys::{EXTENDED_KEYS, KEYS, Key, LAUNCH_KEYS};
use model::launch::SceneKind;

/// The numeric input `k`: [`KEYS`], then [`EXTENDED_KEYS`], then
/// [`LAUNCH_KEYS`], as `all_keys()` and the worker's sensitivities count them.
pub fn input_key(k: usize) -> &'static Key {
    let extended = k.wrapping_sub(KEYS.len());
    KEYS.get(k)
        .or_else(|| EXTENDED_KEYS.get(extended))
        .unwrap_or_else(|| &LAUNCH_KEYS[extended - EXTENDED_KEYS.len()])
}

/// How many numeric inputs there are, in both scenes.
pub fn input_count() -> usize {
    KEYS.len() + EXTENDED_KEYS.len() + LAUNCH_KEYS.len()
}

/// The numeric inputs a scene of `kind` shows, in the pane's order: a swing
/// all but the launch; a batted ball its launch, then the ball, the air and
/// the models (no pitch, no bat: they make no launch here).
pub fn scene_inputs(kind: SceneKind) -> Vec<usize> {
    let group = |k: &usize| input_key(*k).name.split('.').next().unwrap_or("");
    let launch = |k: &usize| group(k) == "launch";
    let all = 0..input_count();
    match kind {
        SceneKind::Swing => all.filter(|k| !launch(k)).collect(),
        SceneKind::BattedBall => all
            .clone()
            .filter(launch)
            .chain(all.filter(|k| !launch(k) && !["pitch", "bat"].contains(&group(k))))
            .collect(),
    }
}

/// The input `name` in words, shown beside its symbol at every size, in
/// the scene's language: a batted ball's launch as Statcast says it (exit
/// speed, launch angle, backspin), a swing's as the paper does. The words
/// tell apart the symbols that look alike (τ spin decay and τ_B bat tilt;
/// φ, φ_w and φ_B; h and h_w).
pub fn input_words(name: &str) -> &'static str {
    match name {
        "pitch.speed" | "bat.speed" => "speed",
        "pitch.spin" | "bat.spin" => "spin",
        "bat.undercut" => "undercut",
        "bat.swing_angle" => "swing angle",
        "bat.friction" => "friction",
        "bat.effective_mass" | "ball.mass" => "mass",
        "bat.radius" | "ball.radius" => "radius",
        "bat.gyration_radius" | "ball.gyration_radius" => "gyration",
        "bat.tilt" => "bat tilt",
        "bat.direction" => "bat aim",
        "bat.tangential_restitution" => "grip",
        "environment.wind" => "wind",
        "environment.wind_direction" => "wind aim",
        "environment.wind_height" => "wind base",
        "environment.air_density" => "density",
        "environment.kinematic_viscosity" => "viscosity",
        "environment.gravity" => "gravity",
        "environment.contact_height" => "contact",
        "environment.temperature" => "temperature",
        "environment.elevation" => "elevation",
        "environment.pressure" => "pressure",
        "environment.humidity" => "humidity",
        "model.spin_decay" => "spin decay",
        "model.drag_scale" => "drag scale",
        "model.lift_scale" => "lift scale",
        "launch.speed" => "exit speed",
        "launch.angle" => "launch angle",
        "launch.spin" => "backspin",
        "launch.direction" => "spray",
        "launch.sidespin" => "sidespin",
        _ => "",
    }
}
