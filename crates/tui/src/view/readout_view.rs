//! What the readout reads of the explorer, and nothing more: the pane
//! draws from a [`Readout`] alone, so that it can be built, changed and
//! tested without an [`App`] (ratatui's demo2: a widget over a small view
//! of the state).

use crate::app::{App, AtParks, OptimumState, Pin};
use crate::theme::Theme;
use model::launch::Flown;
use model::park::Park;
use model::scene::Scene;
use preset::Fence;
use units::UnitSystem;

/// The readout's view of the explorer's state.
#[derive(Clone, Copy, Debug)]
pub struct Readout<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    pub scene: &'a Scene,
    /// The scene's launch, impact and flight at the readout's precision.
    pub flown: &'a Flown,
    /// Where the drawn path ends (m above the ground): where a ball that
    /// does not land is instead.
    pub path_end_height: f64,
    pub optimum: Option<OptimumState>,
    pub pin: Option<&'a Pin>,
    /// The preset's fence, and the ball's height where it passes it.
    pub fence: Option<Fence>,
    pub fence_height: Option<f64>,
    /// The park chosen (`m`/`M`), and whether the scene is in its air.
    pub park: Option<&'a Park>,
    pub in_park_air: bool,
    pub at_parks: Option<AtParks>,
}

impl<'a> Readout<'a> {
    /// The readout's view of `app`.
    pub fn of(app: &'a App) -> Readout<'a> {
        Readout {
            theme: &app.theme,
            units: app.units,
            scene: &app.scene,
            flown: &app.flown,
            path_end_height: app.path.last().map_or(0.0, |p| p.1),
            optimum: app.optimum,
            pin: app.pin.as_ref(),
            fence: app.fence,
            fence_height: app.fence_height,
            park: app.chosen_park(),
            in_park_air: app.in_park_air(),
            at_parks: app.at_parks,
        }
    }

    /// Whether the scene is a swing (not a batted ball on its own).
    pub fn is_swing(&self) -> bool {
        self.scene.kind == model::launch::SceneKind::Swing
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theme::ColorMode;
    use analysis::precision::Purpose;
    use model::launch::fly_scene;
    use ratatui::layout::Rect;

    /// The readout's lines for `view` in a pane `width` × `height`, as text.
    fn shown(view: &Readout, width: u16, height: u16) -> Vec<String> {
        super::super::readout::lines(view, Rect::new(0, 0, width, height))
            .iter()
            .map(|line| {
                let text: String = line.spans.iter().map(|s| s.content.as_ref()).collect();
                // A number glued to its unit reads as spaced.
                text.replace('\u{a0}', " ")
            })
            .collect()
    }

    /// The bundled preset `name`'s scene, flown at the readout's precision.
    fn flown(name: &str) -> (Scene, Flown) {
        let scene = preset::load(name, None).unwrap().scene;
        let flown = fly_scene(&scene, Purpose::Readout);
        (scene, flown)
    }

    /// A scene's readout, built with no explorer around it: no optimum,
    /// pin, fence nor park.
    fn alone<'a>(theme: &'a Theme, scene: &'a Scene, flown: &'a Flown) -> Readout<'a> {
        Readout {
            theme,
            units: UnitSystem::Si,
            scene,
            flown,
            path_end_height: 0.0,
            optimum: None,
            pin: None,
            fence: None,
            fence_height: None,
            park: None,
            in_park_air: false,
            at_parks: None,
        }
    }

    #[test]
    fn the_readout_draws_from_its_view_alone_in_the_units_shown() {
        let theme = Theme::from(ColorMode::Indexed);
        let (scene, flown) = flown("fastball");
        let mut view = alone(&theme, &scene, &flown);
        let lines = shown(&view, 48, 12);
        assert_eq!(lines[0], "launch   44.30 m/s  191.8 rad/s  0.4604 rad");
        assert!(
            lines[1].starts_with("flight   range 134.70 m  5.55 s"),
            "{lines:?}"
        );
        assert!(
            lines[2].starts_with("impact   e* 0.4314  stick  θ 0.3791 rad"),
            "{lines:?}"
        );
        // No optimum yet: the swing's is being searched for.
        assert!(
            lines.iter().any(|l| l == "optimum  searching…"),
            "{lines:?}"
        );
        view.units = UnitSystem::Imperial;
        let lines = shown(&view, 48, 12);
        assert_eq!(lines[0], "launch   99.09 mph  1832 rpm  26.38°");
        assert!(
            lines[1].starts_with("flight   range 441.93 ft"),
            "{lines:?}"
        );
    }

    #[test]
    fn a_batted_ball_has_no_impact_nor_optimum_and_a_fence_its_verdict() {
        let theme = Theme::from(ColorMode::Indexed);
        let (scene, flown) = flown("fly-ball");
        let mut view = alone(&theme, &scene, &flown);
        view.fence = Some(Fence::generic());
        view.fence_height = Some(6.0);
        let lines = shown(&view, 48, 12);
        assert!(!view.is_swing());
        assert!(lines.iter().all(|l| !l.starts_with("impact")), "{lines:?}");
        assert!(lines.iter().all(|l| !l.starts_with("optimum")), "{lines:?}");
        let fence = lines.iter().find(|l| l.starts_with("fence")).unwrap();
        // 6 m up where it passes a 3 m wall.
        assert_eq!(fence, "fence    121.9 m, 3.0 m high: over by 3.0 m");
    }
}
