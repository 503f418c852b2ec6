//! What the trajectory, impact and field panes read of the explorer, and
//! nothing more: each pane draws from its view alone, so that it can be
//! built, changed and tested without an [`App`] (ratatui's demo2: a widget
//! over a small view of the state), as the readout and the inputs are.

use crate::app::{App, FigureState, MarginMap, OptimumState, Pin, SurfaceState};
use crate::layout::FieldMap;
use crate::theme::Theme;
use model::flight::FlightSummary;
use model::impact::Collision;
use model::park;
use model::scene::Scene;
use ratatui::layout::Rect;
use units::{Quantity, Unit, UnitSystem};

/// A pane's view in the units shown: each quantity in one unit, as every
/// other pane shows it ([`crate::shown`]).
pub trait InUnits {
    /// The units shown (`u`).
    fn units(&self) -> UnitSystem;

    /// The unit a quantity is shown in.
    fn unit(&self, quantity: Quantity) -> Unit {
        quantity.in_system(self.units())
    }

    /// A distance in the units shown: (value, unit).
    fn distance(&self, metres: f64) -> (f64, &'static str) {
        crate::shown::distance(self.units(), metres)
    }

    /// The range as every pane shows it ([`crate::shown::range_text`]).
    fn range_text(&self, metres: f64) -> String {
        crate::shown::range_text(self.units(), metres)
    }
}

macro_rules! in_units {
    ($($view:ident),*) => {$(
        impl InUnits for $view<'_> {
            fn units(&self) -> UnitSystem {
                self.units
            }
        }
    )*};
}
in_units!(Trajectory, Impact, Field, Surface, Figure);
impl InUnits for super::readout_view::Readout<'_> {
    fn units(&self) -> UnitSystem {
        self.units
    }
}

/// The trajectory pane's view: the flight from the side.
#[derive(Clone, Copy, Debug)]
pub struct Trajectory<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    pub flight: &'a FlightSummary,
    /// The paths (x, y) in m: this swing's, the optimum's (empty until
    /// found) and the pin's.
    pub path: &'a [(f64, f64)],
    pub optimal_path: &'a [(f64, f64)],
    pub pin: Option<&'a Pin>,
    /// The optimum's range once it is found, else 0.
    pub optimal_range: f64,
    /// The fence drawn, (distance, height) in m.
    pub fence: Option<(f64, f64)>,
}

impl<'a> Trajectory<'a> {
    pub fn of(app: &'a App) -> Trajectory<'a> {
        Trajectory {
            theme: &app.theme,
            units: app.units,
            flight: &app.flown.flight,
            path: &app.path,
            optimal_path: &app.optimal_path,
            pin: app.pin.as_ref(),
            optimal_range: app.optimum.filter(|o| o.done).map_or(0.0, |o| o.best.range),
            fence: app.side_fence(),
        }
    }
}

/// The impact pane's view: the swing's collision and the step shown.
#[derive(Clone, Copy, Debug)]
pub struct Impact<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    /// `None` for a batted ball, which has no impact.
    pub impact: Option<&'a Collision>,
    /// The step-through's stop (`,` `.`), from 0.
    pub stop: usize,
}

impl<'a> Impact<'a> {
    pub fn of(app: &'a App) -> Impact<'a> {
        Impact {
            theme: &app.theme,
            units: app.units,
            impact: app.flown.impact.as_ref(),
            stop: app.impact_stop,
        }
    }
}

/// The field pane's view: the ground tracks from above, the fence and the
/// wind, over a map of the pane it is drawn in.
#[derive(Clone, Debug)]
pub struct Field<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    /// The pane's scale (`App::field_map`).
    pub map: FieldMap,
    pub flight: &'a FlightSummary,
    /// The ground tracks (x, z) in m: this swing's, the optimum's, the pin's.
    pub ground: &'a [(f64, f64)],
    pub optimal_ground: &'a [(f64, f64)],
    pub pin_ground: Option<&'a [(f64, f64)]>,
    /// The chosen park's wall, drawn by its heights; else `fence`, the
    /// preset's, one height all round.
    pub wall: Option<&'a park::Fence>,
    pub fence: Option<park::Fence>,
    /// The wind (m/s, tailwind positive) and where it blows from centre
    /// field (rad).
    pub wind: (f64, f64),
}

impl<'a> Field<'a> {
    /// The field's view of `app`, drawn in `pane`.
    pub fn of(app: &'a App, pane: Rect) -> Field<'a> {
        let environment = &app.scene.environment;
        Field {
            theme: &app.theme,
            units: app.units,
            map: app.field_map(pane),
            flight: &app.flown.flight,
            ground: &app.ground,
            optimal_ground: &app.optimal_ground,
            pin_ground: app.pin.as_ref().map(|p| p.ground.as_slice()),
            wall: app.chosen_park().map(|p| &p.fence),
            fence: app.field_fence(),
            wind: (environment.wind, environment.wind_direction),
        }
    }
}

/// The surface pane's view: the range over (E, ψ), or (`c`) the margin
/// over the fence, with the optimum and the swing marked.
#[derive(Clone, Debug)]
pub struct Surface<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    /// The range surface so far, and the inputs' generation: older is stale.
    pub surface: Option<&'a SurfaceState>,
    pub generation: u64,
    /// The preset's fence distance (m): the contour drawn.
    pub fence_distance: Option<f64>,
    pub optimum: Option<OptimumState>,
    /// The swing's (E, ψ), in m and rad.
    pub swing: (f64, f64),
    /// The margin map, when it is the one shown, and where it is judged
    /// ("the fence" or a park's code).
    pub margin: Option<(&'a MarginMap, String)>,
}

impl<'a> Surface<'a> {
    pub fn of(app: &'a App) -> Surface<'a> {
        Surface {
            theme: &app.theme,
            units: app.units,
            surface: app.surface.as_ref(),
            generation: app.generation,
            fence_distance: app.fence.map(|f| f.distance),
            optimum: app.optimum,
            swing: (app.scene.bat.undercut, app.scene.bat.swing_angle),
            margin: app
                .shows_margin()
                .then(|| (&app.margin, app.margin_place())),
        }
    }
}

/// The figures pane's view: the paper's figure chosen (`f` `F`), as far as
/// it is computed, and the panel shown (`v`).
#[derive(Clone, Copy, Debug)]
pub struct Figure<'a> {
    pub theme: &'a Theme,
    pub units: UnitSystem,
    /// The figure's number, and its table once computed for `generation`
    /// (older is being recomputed).
    pub number: u32,
    pub figure: Option<&'a FigureState>,
    pub generation: u64,
    /// The panel drawn first (`v`), counted over the figure's panels.
    pub panel: usize,
    /// The scene, for the current input's value on the x axis.
    pub scene: &'a Scene,
    /// Whether the scene is a swing: a batted ball has the aero figures only.
    pub swing: bool,
}

impl<'a> Figure<'a> {
    pub fn of(app: &'a App) -> Figure<'a> {
        Figure {
            theme: &app.theme,
            units: app.units,
            number: app.figure_number,
            figure: app.figure.as_ref(),
            generation: app.figure_generation,
            panel: app.figure_panel,
            scene: &app.scene,
            swing: app.is_swing(),
        }
    }

    /// Whether the figure can be drawn for the scene
    /// ([`App::figure_applies`]).
    pub fn applies(&self) -> bool {
        self.swing || crate::app::AERO_FIGURES.contains(&self.number)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theme::ColorMode;
    use analysis::precision::Purpose;
    use model::launch::{Flown, fly_scene};
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;

    /// The bundled preset `name`'s flight at the readout's precision.
    fn flown(name: &str) -> Flown {
        fly_scene(&preset::load(name, None).unwrap().scene, Purpose::Readout)
    }

    /// What `draw` puts on a `width` × `height` screen, row by row.
    fn screen(width: u16, height: u16, draw: impl FnOnce(&mut ratatui::Frame)) -> String {
        let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
        terminal.draw(draw).unwrap();
        let buffer = terminal.backend().buffer();
        (0..height)
            .map(|y| {
                (0..width)
                    .map(|x| buffer[(x, y)].symbol())
                    .collect::<String>()
            })
            .collect::<Vec<_>>()
            .join("\n")
    }

    /// A straight path to `range` m, rising to 20 m: enough to draw.
    fn path_to(range: f64) -> Vec<(f64, f64)> {
        (0..=20)
            .map(|k| {
                let t = f64::from(k) / 20.0;
                (range * t, 80.0 * t * (1.0 - t))
            })
            .collect()
    }

    #[test]
    fn the_trajectory_draws_from_its_view_alone() {
        let theme = Theme::from(ColorMode::Indexed);
        let flown = flown("fastball");
        let path = path_to(flown.flight.range);
        let mut view = Trajectory {
            theme: &theme,
            units: UnitSystem::Si,
            flight: &flown.flight,
            path: &path,
            optimal_path: &[],
            pin: None,
            optimal_range: 0.0,
            fence: None,
        };
        let si = screen(60, 16, |f| {
            super::super::trajectory::draw(f, f.area(), &view)
        });
        assert!(si.contains("Trajectory 134.70 m, apex 27.0 m"), "{si}");
        assert!(si.contains("x (m)") && !si.contains("best"), "{si}");
        view.units = UnitSystem::Imperial;
        let optimal = path_to(140.0);
        view.optimal_path = &optimal;
        let imperial = screen(60, 16, |f| {
            super::super::trajectory::draw(f, f.area(), &view)
        });
        assert!(imperial.contains("441.93 ft, apex 88.7 ft"), "{imperial}");
        assert!(
            imperial.contains("x (ft)") && imperial.contains("best"),
            "{imperial}"
        );
        // A ball hit back over the plate is called so in the title.
        let mut backwards = flown.flight;
        backwards.range = -41.74;
        view.flight = &backwards;
        view.units = UnitSystem::Si;
        let called = screen(60, 16, |f| {
            super::super::trajectory::draw(f, f.area(), &view)
        });
        assert!(called.contains("-41.74 m backwards"), "{called}");
    }

    #[test]
    fn the_impact_draws_from_its_view_alone() {
        let theme = Theme::from(ColorMode::Indexed);
        let flown = flown("fastball");
        let mut view = Impact {
            theme: &theme,
            units: UnitSystem::Si,
            impact: flown.impact.as_ref(),
            stop: 0,
        };
        let first = screen(48, 24, |f| super::super::impact::draw(f, f.area(), &view));
        assert!(first.contains("Impact: approach (1/6)"), "{first}");
        assert!(first.contains("Contact begins"), "{first}");
        assert!(first.contains("m/s") && !first.contains("mph"), "{first}");
        // Past the last stop, the last; in baseball units.
        view.stop = 99;
        view.units = UnitSystem::Imperial;
        let last = screen(48, 24, |f| super::super::impact::draw(f, f.area(), &view));
        assert!(
            last.contains("(6/6)") && last.contains("Separation"),
            "{last}"
        );
        assert!(last.contains("mph") && !last.contains("m/s"), "{last}");
        // A batted ball has no impact: nothing is drawn.
        view.impact = None;
        let none = screen(48, 24, |f| super::super::impact::draw(f, f.area(), &view));
        assert!(none.trim().is_empty(), "{none}");
    }

    #[test]
    fn the_field_draws_from_its_view_alone() {
        let theme = Theme::from(ColorMode::Indexed);
        let flown = flown("fastball");
        let ground: Vec<(f64, f64)> = (0..=10)
            .map(|k| (flown.flight.range * f64::from(k) / 10.0, 0.0))
            .collect();
        let pane = Rect::new(0, 0, 60, 24);
        let mut view = Field {
            theme: &theme,
            units: UnitSystem::Si,
            map: FieldMap::new(pane, 100.0, 5.0, 140.0),
            flight: &flown.flight,
            ground: &ground,
            optimal_ground: &[],
            pin_ground: None,
            wall: None,
            fence: Some(park::Fence::uniform(121.92, 3.048)),
            wind: (0.0, 0.0),
        };
        let calm = screen(60, 24, |f| super::super::field::draw(f, pane, &view));
        assert!(calm.contains("Field 134.70 m, centre field"), "{calm}");
        assert!(!calm.contains("wind"), "{calm}");
        view.units = UnitSystem::Imperial;
        view.wind = (10.0, 0.0);
        let windy = screen(60, 24, |f| super::super::field::draw(f, pane, &view));
        assert!(windy.contains("Field 441.93 ft"), "{windy}");
        assert!(windy.contains("wind 22 mph"), "{windy}");
        // A park's wall brings its key of heights, in the units shown.
        let wall = park::Fence::uniform(121.92, 3.048);
        view.wall = Some(&wall);
        let walled = screen(60, 24, |f| super::super::field::draw(f, pane, &view));
        assert!(walled.contains("wall") && walled.contains("ft"), "{walled}");
    }

    #[test]
    fn the_surface_draws_from_its_view_alone() {
        let theme = Theme::from(ColorMode::Indexed);
        let mut view = Surface {
            theme: &theme,
            units: UnitSystem::Si,
            surface: None,
            generation: 0,
            fence_distance: Some(121.92),
            optimum: None,
            swing: (0.0265, 0.1594),
            margin: None,
        };
        let draw =
            |view: &Surface| screen(60, 20, |f| super::super::heatmap::draw(f, f.area(), view));
        let si = draw(&view);
        assert!(
            si.contains("Range over (E, ψ)") && si.contains("122 m (fence)"),
            "{si}"
        );
        assert!(
            si.contains("computing the surface…") && si.contains("E (m)"),
            "{si}"
        );
        view.units = UnitSystem::Imperial;
        view.fence_distance = None;
        let imperial = draw(&view);
        assert!(
            imperial.contains("E (in)") && !imperial.contains("fence"),
            "{imperial}"
        );
        // The margin map in its place, judged at a park.
        let margin = MarginMap::default();
        view.margin = Some((&margin, "COL".to_owned()));
        let margin = draw(&view);
        assert!(
            margin.contains("COL") && margin.contains("computing the margin…"),
            "{margin}"
        );
    }

    #[test]
    fn a_figure_draws_from_its_view_alone() {
        let theme = Theme::from(ColorMode::Indexed);
        let scene = preset::load("fastball", None).unwrap().scene;
        let analysis::figures::Figure::Table(data) =
            analysis::figures::figure_data(5, &scene, "fastball").unwrap()
        else {
            panic!("Fig. 5 is a table");
        };
        let state = FigureState {
            number: 5,
            data: Ok(data),
            generation: 1,
            elapsed: std::time::Duration::ZERO,
        };
        let mut view = Figure {
            theme: &theme,
            units: UnitSystem::Imperial,
            number: 5,
            figure: Some(&state),
            generation: 1,
            panel: 0,
            scene: &scene,
            swing: true,
        };
        let draw =
            |view: &Figure| screen(100, 40, |f| super::super::figure::draw(f, f.area(), view));
        let shown = draw(&view);
        assert!(shown.contains("Fig. 5 (3/11, f F)"), "{shown}");
        // The paper's 0.064 m beside ours, in inches as the axis is.
        assert!(
            shown.contains("paper 2.5 · ours") && shown.contains("E (in)"),
            "{shown}"
        );
        assert!(!shown.contains("computing"), "{shown}");
        // Newer inputs: the figure is being recomputed.
        view.generation = 2;
        assert!(draw(&view).contains("computing…"));
        // A batted ball has no impact to draw.
        view.swing = false;
        assert!(draw(&view).contains("Fig. 5 needs a swing"));
    }
}
