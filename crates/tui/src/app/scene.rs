//! Which scene is shown: a preset loaded, the switch between a swing and
//! the batted ball it launches, and the swing moved to the optimum.

use super::*;
use preset::{ExplorerSetup, escape_for_terminal};

impl App {
    /// Replaces the inputs with a preset's.
    pub fn load(&mut self, preset: Preset) {
        let mut message = format!("loaded {}", preset.name);
        // The preset brings its own air.
        self.air_before_park = None;
        self.preset_name = preset.name;
        self.description = preset.description;
        self.set_scene(preset.scene);
        self.fence = preset.fence;
        // A preset saved from the explorer brings its set-up too; one
        // without leaves the park and the units as they are.
        if let Some(setup) = &preset.explorer {
            message += &self.restore_setup(setup);
        }
        self.message = Some((message, false));
        self.dirty = true;
    }

    /// Puts back the set-up a preset was saved in: its units, its park
    /// (by code, among the parks `m`/`M` go through) and whether the
    /// scene flies in that park's air (the preset's air is that air
    /// already; `a` then brings the standard air at sea level). What
    /// the message adds about it.
    pub fn restore_setup(&mut self, setup: &ExplorerSetup) -> String {
        self.set_units(setup.units);
        let found = setup
            .park
            .as_deref()
            .map(|code| (code, self.park_index(code)));
        let (park, words) = match found {
            None => (None, String::new()),
            Some((code, Some(k))) => (Some(k), format!(" at {}", escape_for_terminal(code))),
            Some((code, None)) => (
                None,
                format!(
                    "; its park {} is not among yours: the preset's fence",
                    escape_for_terminal(code)
                ),
            ),
        };
        self.park = park;
        self.air_before_park =
            (park.is_some() && setup.park_air).then(|| Scene::default().environment.air());
        self.judge_fences();
        self.refresh_margin(true);
        let air = if self.in_park_air() {
            " in its air"
        } else {
            ""
        };
        format!("{words}{air}, in {} units", self.units)
    }

    /// Replaces the scene, and the inputs pane's rows with its kind's,
    /// keeping the selected row where the new scene has it.
    pub(super) fn set_scene(&mut self, scene: Scene) {
        let kind_changed = scene.kind != self.scene.kind;
        self.scene = scene;
        self.inputs_changed = true;
        if kind_changed {
            let selected = self.fields[self.selected];
            self.fields = fields(scene.kind);
            self.selected = self
                .fields
                .iter()
                .position(|f| *f == selected)
                .unwrap_or_else(|| first_input(&self.fields, scene.kind));
            // The old scene's results are of another kind: drop them now.
            self.optimum = None;
            self.optimal_path.clear();
            self.optimal_ground.clear();
            self.fit_figure();
        }
    }

    /// Key `b`: from a swing to the batted ball it launches (the same
    /// launch, so the same flight), or back to the swing as it was (the
    /// ball, air and models as now). The models in force go with the
    /// switch, chosen: a model left unset would otherwise become the other
    /// kind's default (the paper's for a swing, Nathan's for a batted
    /// ball), and the same launch would fly another range.
    pub(super) fn switch_scene(&mut self) {
        let (scene, message) = if self.is_swing() {
            // A swing's validation refuses a launch outside launch.*'s
            // bounds; this holds it for a swing set by a click or an optimum.
            let batted = self.scene.with_launch(self.flown.launch);
            if let Err(e) = batted.validate() {
                self.message = Some((format!("no batted ball: {e}"), true));
                return;
            }
            (
                batted,
                "batted-ball scene: this swing's launch, flown on its own (b: back to the swing)",
            )
        } else {
            (
                self.scene.as_swing(),
                "swing scene: pitch, bat, impact, optimum and surface (b: the batted ball)",
            )
        };
        let mut scene = scene;
        scene.choose_drag(self.scene.drag);
        scene.choose_lift(self.scene.lift);
        self.set_scene(scene);
        self.message = Some((message.into(), false));
    }

    /// Moves the swing to the optimum found (key `r`).
    pub(super) fn reset_to_optimum(&mut self) {
        if !self.is_swing() {
            self.message = Some((SWING_ONLY.into(), true));
            return;
        }
        if let Some(o) = self.optimum.filter(|o| o.done) {
            if o.best.range.is_finite() {
                self.scene = self.scene.with_swing(o.best.undercut, o.best.swing_angle);
                self.inputs_changed = true;
            } else {
                self.message = Some(("no swing lands: there is no optimum".into(), true));
            }
        } else {
            self.message = Some(("no optimum yet for these inputs".into(), true));
        }
    }
}

/// The row selected when a scene of `kind` opens: the input that matters
/// most (the bat's speed, the launch speed).
pub(super) fn first_input(fields: &[Field], kind: SceneKind) -> usize {
    let name = match kind {
        SceneKind::Swing => "bat.speed",
        SceneKind::BattedBall => "launch.speed",
    };
    fields
        .iter()
        .position(|f| matches!(f, Field::Key(k) if input_key(*k).name == name))
        .unwrap_or(0)
}
