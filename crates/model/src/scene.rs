//! All inputs of one scene: pitch, bat, ball, environment and model choice,
//! and for a batted ball its launch. Plain data at the bottom of the model:
//! the phases that read it (`pitch`, `impact`, `flight`, `launch`) import
//! it, never the other way. Their names, bounds and validation are in
//! [`super::keys`].

use serde::{Deserialize, Serialize};

use super::aero::{DragModel, LiftModel};
use super::atmosphere::{Air, Atmosphere};

/// Which phases a scene models.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SceneKind {
    /// Pitch → impact → flight: the launch comes out of the impact.
    #[default]
    Swing,
    /// Launch → flight: the launch is given (`launch.*`); pitch and bat
    /// only supply a launch value that is not given.
    BattedBall,
}

impl SceneKind {
    /// The drag and lift a scene of this kind flies under unless the user
    /// chose others: the paper's for a swing (so Table II stands), Nathan's
    /// for a batted ball (the aero the field calibrated on Statcast).
    pub fn default_models(self) -> (DragModel, LiftModel) {
        match self {
            SceneKind::Swing => (DragModel::Sawicki2003, LiftModel::Sawicki2003),
            SceneKind::BattedBall => (DragModel::Nathan, LiftModel::Nathan),
        }
    }

    /// "swing" or "batted_ball", as JSON and presets name it.
    pub fn name(self) -> &'static str {
        match self {
            SceneKind::Swing => "swing",
            SceneKind::BattedBall => "batted_ball",
        }
    }
}

/// The launch values a batted-ball scene gives (`launch.*`); `None` takes
/// the value from the scene's own swing, so `--set launch.angle=0.5` on the
/// fastball flies the fastball's launch speed and spin at 0.5 rad whatever
/// order the other `--set`s come in. The swing is planar, so its direction
/// and sidespin are 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct GivenLaunch {
    pub speed: Option<f64>,
    pub angle: Option<f64>,
    pub spin: Option<f64>,
    #[serde(default)]
    pub direction: Option<f64>,
    #[serde(default)]
    pub sidespin: Option<f64>,
}

impl GivenLaunch {
    pub fn is_empty(&self) -> bool {
        self.values().iter().all(Option::is_none)
    }

    pub fn is_complete(&self) -> bool {
        self.values().iter().all(Option::is_some)
    }

    /// In the order of `keys::LAUNCH_KEYS`.
    pub fn values(&self) -> [Option<f64>; 5] {
        [
            self.speed,
            self.angle,
            self.spin,
            self.direction,
            self.sidespin,
        ]
    }
}

/// Which aerodynamic models the user chose: those not chosen follow the
/// scene's kind ([`SceneKind::default_models`]), so that a swing turned
/// batted ball flies Nathan's aero, while a model the user chose is never
/// changed behind their back.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct ChosenModels {
    pub drag: bool,
    pub lift: bool,
}

/// The pitched ball as it reaches the plate.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pitch {
    /// V̂_b0, speed at the plate (m/s).
    pub speed: f64,
    /// ω_b0 (rad/s): pitched topspin positive, so a fastball's backspin is negative.
    pub spin: f64,
}

/// The bat at the instant of contact, and where it meets the ball.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Bat {
    /// V̂_B0, speed of the bat's axis at the contact point (m/s).
    pub speed: f64,
    /// ω_B0, roll about the bat's own axis (rad/s), positive in the sense of
    /// the paper's Fig. 9: the surface moves down across the ball and adds
    /// backspin. That is −ẑ in the flight frame; converted once, in `impact`.
    pub spin: f64,
    /// E, undercut: ball centre height above the bat axis (m).
    pub undercut: f64,
    /// ψ, swing angle of the bat's velocity above the horizontal (rad).
    pub swing_angle: f64,
    /// μ, bat–ball coefficient of friction.
    pub friction: f64,
    /// M_B, bat mass equivalent at the centre of percussion (kg).
    pub effective_mass: f64,
    /// r_B, barrel radius (m).
    pub radius: f64,
    /// k_B2, radius of gyration about the bat's own axis (m).
    pub gyration_radius: f64,
    /// The swing plane's tilt (rad), MLB's swing path tilt: the barrel this
    /// far below the hands at the bottom of the arc (ψ = 0), less as the bat
    /// rises or falls through the contact, its velocity square to it
    /// ([`crate::impact::barrel_in_swing_plane`]); 0 is the
    /// paper's level bat (docs/swing-3d.md).
    #[serde(default)]
    pub tilt: f64,
    /// The horizontal direction of the bat's velocity at contact (rad from
    /// the centre-field line, positive toward right field, as
    /// [`super::frame`]): 0 is the paper's square contact.
    #[serde(default)]
    pub direction: f64,
    /// Which side of the plate the batter stands on.
    #[serde(default)]
    pub hand: Hand,
    /// e_T, the tangential restitution of a contact that grips: the slip it
    /// halted springs back e_T-fold before the ball leaves (Cross, Am. J.
    /// Phys. 70, 482 (2002); docs/bat-tracking.md). 0 is the paper's rigid
    /// rolling.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tangential_restitution: f64,
    /// λ, the bat's lead over its path (rad): the barrel turned this far
    /// within the swing plane ahead of square to the velocity, so the
    /// contact point moves sin λ of its speed along the bat
    /// ([`crate::impact::BatFrame::leading`]; docs/swing-3d.md). 0 is the
    /// paper's bat, square to its path.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub lead: f64,
}

fn is_zero(value: &f64) -> bool {
    *value == 0.0
}

impl Bat {
    /// Whether this swing is the paper's: a level bat square to the pitch,
    /// meeting the ball in the vertical plane toward centre field. Either
    /// hand then swings the same (the plane is its own mirror image).
    pub fn is_planar(&self) -> bool {
        self.tilt == 0.0 && self.direction == 0.0 && self.lead == 0.0
    }
}

/// The key that chooses the batter's hand (in `--set`, presets and batch
/// columns).
pub const HAND_KEY: &str = "bat.hand";

/// The batter's side: at a square contact a right-handed batter's barrel
/// points toward the first-base side (+z), a left-handed batter's toward
/// the third-base side, the mirror image in z (`../shared/DESIGN.md`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Hand {
    #[default]
    Right,
    Left,
}

impl Hand {
    pub const ALL: [Hand; 2] = [Hand::Right, Hand::Left];

    /// "right" or "left", as `bat.hand` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Hand::Right => "right",
            Hand::Left => "left",
        }
    }

    /// +1 for a right-handed batter, −1 for a left-handed one: the sign of
    /// the z component of the barrel's direction at a square contact.
    pub fn sign(self) -> f64 {
        match self {
            Hand::Right => 1.0,
            Hand::Left => -1.0,
        }
    }

    /// "right-handed" or "left-handed".
    pub fn description(self) -> &'static str {
        match self {
            Hand::Right => "right-handed",
            Hand::Left => "left-handed",
        }
    }
}

/// A `bat.hand` that is neither `right` nor `left`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{HAND_KEY} = {text:?}: unknown hand; accepted: right, left")]
pub struct UnknownHand {
    pub text: String,
}

impl std::str::FromStr for Hand {
    type Err = UnknownHand;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        Hand::ALL
            .into_iter()
            .find(|h| h.name() == text.trim())
            .ok_or_else(|| UnknownHand {
                text: text.to_owned(),
            })
    }
}

impl std::fmt::Display for Hand {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The baseball.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ball {
    /// M_b (kg).
    pub mass: f64,
    /// r_b (m).
    pub radius: f64,
    /// k_b, radius of gyration about the centre (m).
    pub gyration_radius: f64,
}

/// The air and the field.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Environment {
    /// Horizontal wind (m/s) blowing toward `wind_direction`, negative
    /// blowing the other way: with the direction 0 (the default), positive
    /// is a tailwind toward centre field and negative a headwind.
    pub wind: f64,
    /// Where the wind blows toward (rad from the centre-field line,
    /// positive toward right field: see [`super::frame`]).
    #[serde(default)]
    pub wind_direction: f64,
    /// The height above which the wind blows (m): below it the air is
    /// still, as in Nathan's calculator. 0: everywhere.
    #[serde(default)]
    pub wind_height: f64,
    /// ρ (kg/m³) in force: given, or derived from `atmosphere` (set it with
    /// [`Environment::set_air_density`] when an atmosphere may be in force).
    pub air_density: f64,
    /// ν (m²/s) in force: given, or derived from `atmosphere` (set it with
    /// [`Environment::set_kinematic_viscosity`]).
    pub kinematic_viscosity: f64,
    /// g (m/s²).
    pub gravity: f64,
    /// Height of the ball at contact, where the flight starts (m).
    pub contact_height: f64,
    /// The weather ρ and ν were derived from; `None` (the paper's presets)
    /// when they were given. Private, so that ρ and ν cannot fall out of step
    /// with it: [`Environment::set_atmosphere`] derives them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    atmosphere: Option<Atmosphere>,
}

impl Environment {
    /// The ρ and ν in force, and where they come from.
    pub fn air(&self) -> Air {
        Air {
            density: self.air_density,
            kinematic_viscosity: self.kinematic_viscosity,
            atmosphere: self.atmosphere,
        }
    }

    /// The weather ρ and ν were derived from, if they were.
    pub fn atmosphere(&self) -> Option<Atmosphere> {
        self.atmosphere
    }

    /// Derives ρ and ν from `atmosphere`: they follow it until one of them
    /// is given.
    pub fn set_atmosphere(&mut self, atmosphere: Atmosphere) {
        self.atmosphere = Some(atmosphere);
        self.air_density = atmosphere.air_density();
        self.kinematic_viscosity = atmosphere.kinematic_viscosity();
    }

    /// Takes `air` whole, as another environment's [`Environment::air`]
    /// gave it (ρ and ν with the weather they came from, if any).
    pub fn set_air(&mut self, air: Air) {
        self.atmosphere = air.atmosphere;
        self.air_density = air.density;
        self.kinematic_viscosity = air.kinematic_viscosity;
    }

    /// Gives ρ: no atmosphere derives the air any more, and ν keeps the
    /// value it had.
    pub fn set_air_density(&mut self, air_density: f64) {
        self.atmosphere = None;
        self.air_density = air_density;
    }

    /// Gives ν: no atmosphere derives the air any more, and ρ keeps the
    /// value it had.
    pub fn set_kinematic_viscosity(&mut self, kinematic_viscosity: f64) {
        self.atmosphere = None;
        self.kinematic_viscosity = kinematic_viscosity;
    }
}

/// A scale factor's default: the model as published.
fn unscaled() -> f64 {
    1.0
}

/// Everything that determines one swing's outcome.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    pub pitch: Pitch,
    pub bat: Bat,
    pub ball: Ball,
    pub environment: Environment,
    pub drag: DragModel,
    #[serde(default)]
    pub lift: LiftModel,
    /// τ (s), the spin's decay time in flight, ω(t) = ω₀·e^(−t/τ); 0 for
    /// none (the paper's constant spin).
    #[serde(default)]
    pub spin_decay: f64,
    /// Factors on C_D and C_L (1: the model as published), fitted to
    /// measured distances by `homerun calibrate`.
    #[serde(default = "unscaled")]
    pub drag_scale: f64,
    #[serde(default = "unscaled")]
    pub lift_scale: f64,
    /// A swing (the paper's scene) or a batted ball flown from `launch`.
    /// Set it with [`Scene::set_kind`], which keeps the models in step.
    #[serde(default)]
    pub kind: SceneKind,
    /// Which of `drag` and `lift` the user chose (the others follow `kind`).
    #[serde(default)]
    pub chosen: ChosenModels,
    /// The launch values a batted-ball scene gives (unused by a swing).
    #[serde(default)]
    pub launch: GivenLaunch,
}

impl Default for Scene {
    /// The paper's fastball (Table I and II), at its published optimum (E, ψ).
    ///
    /// Table I swaps the two radii of gyration: the ball's is 0.0231 m
    /// (≈ √(2/5)·r_b, a solid sphere) and the bat's about its own axis is
    /// 0.0247 m (≈ r_B/√2, a solid cylinder). With the printed values Table II's
    /// spins are off by 15–25 rad/s; with these they agree to rounding.
    fn default() -> Self {
        Scene {
            pitch: Pitch {
                speed: 42.0,
                spin: -200.0,
            },
            bat: Bat {
                speed: 30.0,
                spin: 0.0,
                undercut: 0.0265,
                swing_angle: 0.1594,
                friction: 0.5,
                effective_mass: 0.8,
                radius: 0.035,
                gyration_radius: 0.0247,
                tilt: 0.0,
                direction: 0.0,
                hand: Hand::Right,
                tangential_restitution: 0.0,
                lead: 0.0,
            },
            ball: Ball {
                mass: 0.145,
                radius: 0.0366,
                gyration_radius: 0.0231,
            },
            environment: Environment {
                wind: 0.0,
                wind_direction: 0.0,
                wind_height: 0.0,
                air_density: 1.23,
                kinematic_viscosity: 1.5e-5,
                gravity: 9.81,
                contact_height: 1.0,
                atmosphere: None,
            },
            drag: DragModel::Sawicki2003,
            lift: LiftModel::Sawicki2003,
            spin_decay: 0.0,
            drag_scale: 1.0,
            lift_scale: 1.0,
            kind: SceneKind::Swing,
            chosen: ChosenModels::default(),
            launch: GivenLaunch::default(),
        }
    }
}

impl Scene {
    /// This scene with its swing replaced by undercut E and swing angle ψ:
    /// the one change the optimiser, the surface and the studies make.
    pub fn with_swing(&self, undercut: f64, swing_angle: f64) -> Scene {
        let mut scene = *self;
        scene.bat.undercut = undercut;
        scene.bat.swing_angle = swing_angle;
        scene
    }

    /// Makes this scene a swing or a batted ball; the models the user did not
    /// choose become that kind's ([`SceneKind::default_models`]).
    pub fn set_kind(&mut self, kind: SceneKind) {
        self.kind = kind;
        let (drag, lift) = kind.default_models();
        if !self.chosen.drag {
            self.drag = drag;
        }
        if !self.chosen.lift {
            self.lift = lift;
        }
    }

    /// Chooses the drag model: it stays whatever the scene's kind.
    pub fn choose_drag(&mut self, drag: DragModel) {
        self.drag = drag;
        self.chosen.drag = true;
    }

    /// Chooses the lift model: it stays whatever the scene's kind.
    pub fn choose_lift(&mut self, lift: LiftModel) {
        self.lift = lift;
        self.chosen.lift = true;
    }

    /// "drag nathan, lift nathan (Nathan's, a batted ball's default)": the
    /// models in force, and where they come from when the user did not
    /// choose them, as the command line and the explorer say it.
    pub fn models_text(&self) -> String {
        let whose = match self.kind {
            SceneKind::Swing => "the paper's, a swing's default",
            SceneKind::BattedBall => "Nathan's, a batted ball's default",
        };
        let (drag, lift) = (self.drag, self.lift);
        let (default_drag, default_lift) = self.kind.default_models();
        // Not chosen, yet not the kind's default (a Savant swing flies
        // Nathan's): named for whose it is, never called the default.
        let named = |name: String| match name.as_str() {
            "nathan" => "Nathan's",
            "sawicki2003" => "the paper's",
            _ => "set by the scene",
        };
        let drag_source = match (self.chosen.drag, drag == default_drag) {
            (true, _) => "chosen",
            (false, true) => whose,
            (false, false) => named(drag.to_string()),
        };
        let lift_source = match (self.chosen.lift, lift == default_lift) {
            (true, _) => "chosen",
            (false, true) => whose,
            (false, false) => named(lift.to_string()),
        };
        if drag_source == lift_source {
            format!("drag {drag}, lift {lift} ({drag_source})")
        } else {
            format!("drag {drag} ({drag_source}), lift {lift} ({lift_source})")
        }
    }

    /// r_b + r_B: the centre distance at contact, so |E| must stay below it
    /// for the bat to meet the ball.
    pub fn reach(&self) -> f64 {
        self.ball.radius + self.bat.radius
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_models_are_named_for_whose_they_are() {
        let mut scene = Scene::default();
        assert_eq!(
            scene.models_text(),
            "drag sawicki2003, lift sawicki2003 (the paper's, a swing's default)"
        );
        // A Savant swing flies Nathan's aero without the user choosing it:
        // not "the paper's", nor a swing's default.
        scene.drag = DragModel::Nathan;
        scene.lift = LiftModel::Nathan;
        assert_eq!(scene.models_text(), "drag nathan, lift nathan (Nathan's)");
        scene.choose_lift(LiftModel::Sawicki2003);
        assert_eq!(
            scene.models_text(),
            "drag nathan (Nathan's), lift sawicki2003 (chosen)"
        );
    }
}
