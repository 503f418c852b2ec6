//! The explorer's state, the events it understands and `update()`: the only
//! place the state changes. Drawing only reads it.

use std::path::PathBuf;
use std::sync::Arc;

use ratatui::crossterm::event::{Event, KeyEvent, KeyEventKind};
use ratatui::layout::Rect;
use ratatui_textarea::TextArea;

mod edit;
mod export;
mod field;
pub use field::{AtParks, ParkList};
mod figures;
mod find;
mod reading;
pub use find::{Find, Pick, Searchable};
mod impact;
pub use impact::impact_stops;
mod margin;
mod park_air;
pub use margin::{MarginMap, MarginState};
mod mouse;
mod presets;
mod reports;
mod scene;
mod units_shown;

use super::format::{error_text, read_value, shown_value};
pub use super::inputs::{input_count, input_key, scene_inputs};
use super::keymap::{self, Action};
use super::layout::{Tab, heatmap_resolution, shows_optimum_gains, trajectory_samples};
use super::theme::Theme;
use super::worker::{FigureJob, Gain, Job, Report, Work};
use analysis::optimum::{Point, Status};
use analysis::precision::Purpose;
use analysis::sensitivity;
use analysis::study::{Grid, Surface};
use edit::prefilled;
use figures::FigureInputs;
pub use figures::{AERO_FIGURES, FIGURES, FigureState};
use model::aero::{DragModel, LiftModel};
use model::keys::{DRAG_KEY, HAND_KEY, LIFT_KEY, SWING_3D_KEYS};
use model::launch::{Flown, SceneKind, fly_scene, scene_start};
use model::scene::{Hand, Scene};
use preset::{self, Fence, Preset};
use scene::first_input;
use units::{Quantity, Unit, UnitSystem};

/// Points of a plotted flight: (distance, height) or, from above, (x, z).
pub type Path = Vec<(f64, f64)>;

/// One row of the inputs pane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    /// The preset's name: Enter opens the picker.
    Preset,
    /// A numeric input: an index into `all_keys()` ([`model::keys::KEYS`],
    /// then [`model::keys::EXTENDED_KEYS`], then [`model::keys::LAUNCH_KEYS`];
    /// see [`input_key`]).
    Key(usize),
    /// The drag model.
    Drag,
    /// The lift model.
    Lift,
    /// The batter's hand (`bat.hand`).
    Hand,
}

/// The inputs pane's group of the swing in three dimensions.
const SWING_3D: &str = "3-D swing";

/// The inputs pane's group of the contact beyond the paper's rigid rolling
/// (`bat.tangential_restitution`), listed last.
const GRIP: &str = "contact";

impl Field {
    /// The group it is listed under in the inputs pane.
    pub fn group(self) -> &'static str {
        match self {
            Field::Preset => "",
            // The swing beyond the paper's plane, on its own after the
            // paper's inputs (as docs/swing-3d.md describes it).
            Field::Key(k) if SWING_3D_KEYS.contains(&input_key(k).name) => SWING_3D,
            Field::Key(k) if input_key(k).name == "bat.tangential_restitution" => GRIP,
            Field::Key(k) => input_key(k).name.split('.').next().unwrap_or(""),
            Field::Drag | Field::Lift => "model",
            Field::Hand => SWING_3D,
        }
    }
}

/// Every row of the inputs pane for a scene of `kind`, top to bottom: each
/// group once (the weather after the paper's environment keys, then the
/// models, and last the swing in three dimensions).
pub fn fields(kind: SceneKind) -> Vec<Field> {
    let mut all = vec![Field::Preset];
    all.extend(scene_inputs(kind).into_iter().map(Field::Key));
    all.extend([Field::Drag, Field::Lift]);
    // A batted ball has no bat.
    if kind == SceneKind::Swing {
        all.push(Field::Hand);
    }
    let mut groups: Vec<&str> = Vec::new();
    for field in &all {
        if !groups.contains(&field.group()) {
            groups.push(field.group());
        }
    }
    // A stable sort keeps each group's own order.
    all.sort_by_key(|f| groups.iter().position(|g| *g == f.group()));
    all
}

/// One input's range gained per nudge, and the inputs it was computed for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GainCell {
    /// `None`: the nudge is refused, a ball does not land, or (at the
    /// optimum) the input is the swing itself.
    pub value: Option<f64>,
    pub generation: u64,
}

/// A preset in the picker: loadable, or broken with its error.
#[derive(Clone, Debug)]
pub struct PickItem {
    pub name: String,
    pub detail: String,
    pub preset: Option<Preset>,
}

/// What the keyboard is talking to.
#[derive(Debug)]
pub enum Mode {
    Normal,
    /// Typing a value for `field` (in the unit shown); `error` says why the
    /// last Enter was refused. `initial` is the text it started from: Enter
    /// on it unchanged keeps the value as it was, not as rounded for show.
    Edit {
        field: Field,
        text: TextArea<'static>,
        error: Option<String>,
        initial: String,
    },
    /// Typing a name to save the inputs under, then (once `named`) the
    /// preset's description. `overwrite` is the name (a bundled preset's,
    /// or one of the user's) the user was warned about: Enter on it again
    /// goes on anyway.
    Save {
        text: TextArea<'static>,
        error: Option<String>,
        overwrite: Option<String>,
        named: Option<String>,
    },
    /// Choosing a preset (or a Savant file's swing) to load; with `find`,
    /// the items are those whose name and description hold each of its
    /// words, and `find` is being typed while it is `Some`.
    Open {
        items: Vec<Pick>,
        selected: usize,
        error: Option<String>,
        find: Option<Find>,
    },
    /// The help: its keys, or (Tab) the glossary of the symbols on screen,
    /// scrolled down by `scroll` rows (j k ↑ ↓).
    Help {
        glossary: bool,
        scroll: u16,
    },
    /// The words cut short on the panes, whole (`i`): the selected input,
    /// the message, the figure's notes, the models; scrolled by `scroll`.
    Detail {
        scroll: u16,
    },
    /// Choosing a park from the list, filtered by `query` (a code, or words
    /// of a name or a city); `selected` counts in the filtered list.
    Parks {
        query: String,
        selected: usize,
    },
}

/// The optimiser's latest word for the current inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OptimumState {
    pub best: Point,
    pub evaluations: u32,
    pub done: bool,
    /// Why it stopped, once `done`.
    pub status: Status,
    /// Whether its best, flown again at readout precision (as the readout
    /// flies the swing), lands too; checked once it is done.
    pub lands_at_readout: bool,
}

/// The range surface as refined so far.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceState {
    pub surface: Surface,
    pub last: bool,
    /// The inputs it was computed for; older than the app's while the
    /// surface for new inputs is being computed.
    pub generation: u64,
}

/// A scene kept for comparison (key `p`): it stays while the inputs change,
/// and across the switch between a swing and a batted ball.
#[derive(Clone, Debug, PartialEq)]
pub struct Pin {
    pub scene: Scene,
    /// Its launch and flight at the readout's precision.
    pub flown: Flown,
    /// Its path, sampled at the plot's resolution.
    pub path: Vec<(f64, f64)>,
    /// Its ground track (x, z), from the same samples.
    pub ground: Vec<(f64, f64)>,
}

/// The explorer.
#[derive(Debug)]
pub struct App {
    pub preset_name: String,
    pub description: String,
    pub scene: Scene,
    pub fence: Option<Fence>,
    pub presets_dir: Option<PathBuf>,
    /// Swings of a Savant export (`tui --savant`), first in the picker.
    pub swings: Arc<Searchable>,
    pub fields: Vec<Field>,
    pub selected: usize,
    pub mode: Mode,
    pub tab: Tab,
    /// The last thing worth telling the user, and whether it is an error.
    pub message: Option<(String, bool)>,
    /// What `x` wrote, or why not, and whether it is an error: shown in the
    /// status line (the full width) until the next key.
    pub export_message: Option<(String, bool)>,
    /// How everything looks: the background's colours, or none.
    pub theme: Theme,
    pub size: Rect,
    /// The current scene's launch, impact (a swing's) and flight at the
    /// readout's precision.
    pub flown: Flown,
    /// The ball's height (m) where it passes the fence, if it gets there.
    pub fence_height: Option<f64>,
    /// The park chosen (`m`/`M`), an index into `parks`: its fence
    /// replaces the preset's in the field and the side view.
    pub park: Option<usize>,
    pub parks: ParkList,
    /// The air before `a` put the scene in the park's: `Some` while in it.
    pub air_before_park: Option<model::atmosphere::Air>,
    /// The current flight judged at every park, and at the one chosen.
    pub at_parks: Option<AtParks>,
    /// The heatmap's margin over the park's wall (key `c`).
    pub margin: MarginMap,
    /// The current flight's path (distance from the plate, height), sampled
    /// at the plot's resolution.
    pub path: Vec<(f64, f64)>,
    /// Its ground track (x toward centre field, z toward right field), from
    /// the same samples: the field view draws it from above.
    pub ground: Vec<(f64, f64)>,
    pub optimum: Option<OptimumState>,
    /// The optimal swing's path, once the optimiser has converged.
    pub optimal_path: Vec<(f64, f64)>,
    /// Its ground track.
    pub optimal_ground: Vec<(f64, f64)>,
    pub surface: Option<SurfaceState>,
    /// Bumped on every change of inputs; results for older ones are dropped.
    pub generation: u64,
    /// The last converged optimum, whatever the inputs: the warm start.
    pub warm_start: Option<(f64, f64)>,
    pub impact_stop: usize,
    /// Per input (as [`input_key`] counts them), the range gained by one
    /// step up at the current swing and at the optimum; a cell older than
    /// `generation` is stale and shown so until the new one arrives.
    pub swing_gains: Vec<Option<GainCell>>,
    pub optimum_gains: Vec<Option<GainCell>>,
    /// The pinned scene, if any: drawn and compared beside the current one.
    pub pin: Option<Pin>,
    /// The paper's figure chosen on the figures tab, and as computed.
    pub figure_number: u32,
    /// The figure's panel shown where not all fit (`v`), counted modulo
    /// its panels.
    pub figure_panel: usize,
    pub figure: Option<FigureState>,
    /// Bumped whenever the figure shown must change; older ones are dropped.
    pub figure_generation: u64,
    figure_for: Option<FigureInputs>,
    figure_job: Option<FigureJob>,
    /// The units every quantity is shown and typed in (key `u`); the scene
    /// stays SI.
    pub units: UnitSystem,
    pub quit: bool,
    /// Something changed since the last frame.
    pub dirty: bool,
    inputs_changed: bool,
    job: Option<Job>,
}

impl App {
    /// A distance in the units shown: (value, unit).
    pub fn distance(&self, metres: f64) -> (f64, &'static str) {
        crate::shown::distance(self.units, metres)
    }

    /// The scene's range as every pane shows it ([`crate::shown::range_text`]).
    pub fn range_text(&self, metres: f64) -> String {
        crate::shown::range_text(self.units, metres)
    }

    /// What a class should hear about a landing that is no hit to the
    /// field: a ball behind the plate (a negative range) is "backwards",
    /// one landing outside the foul lines (±45°) "foul"; None for a fair
    /// ball.
    pub fn landing_call(flight: &model::flight::FlightSummary) -> Option<&'static str> {
        if !flight.landed {
            None
        } else if flight.range < 0.0 {
            Some("backwards")
        } else if flight.direction.abs() > std::f64::consts::FRAC_PI_4 {
            Some("foul")
        } else {
            None
        }
    }

    /// The unit a quantity is shown in.
    pub fn unit(&self, quantity: Quantity) -> Unit {
        quantity.in_system(self.units)
    }

    /// Whether the swing scene is shown (pitch, bat, impact, optimum,
    /// surface) rather than a batted ball on its own.
    pub fn is_swing(&self) -> bool {
        self.scene.kind == SceneKind::Swing
    }

    /// How many sensitivities the scene shown has: one per numeric input.
    pub fn gain_count(&self) -> usize {
        scene_inputs(self.scene.kind).len()
    }

    pub fn new(
        preset: Preset,
        presets_dir: Option<PathBuf>,
        theme: impl Into<Theme>,
        size: Rect,
    ) -> App {
        let setup = preset.explorer.clone();
        let flown = fly_scene(&preset.scene, Purpose::Readout);
        let fields = fields(preset.scene.kind);
        let selected = first_input(&fields, preset.scene.kind);
        let mut app = App {
            preset_name: preset.name,
            description: preset.description,
            scene: preset.scene,
            fence: preset.fence,
            presets_dir,
            swings: Arc::default(),
            fields,
            selected,
            mode: Mode::Normal,
            tab: Tab::Flight,
            message: None,
            export_message: None,
            theme: theme.into(),
            size,
            flown,
            fence_height: None,
            park: None,
            parks: ParkList::default(),
            air_before_park: None,
            at_parks: None,
            margin: MarginMap::default(),
            path: Vec::new(),
            ground: Vec::new(),
            optimum: None,
            optimal_path: Vec::new(),
            optimal_ground: Vec::new(),
            surface: None,
            generation: 0,
            warm_start: None,
            impact_stop: 0,
            swing_gains: vec![None; input_count()],
            optimum_gains: vec![None; input_count()],
            pin: None,
            figure_number: 8,
            figure_panel: 0,
            figure: None,
            figure_generation: 0,
            figure_for: None,
            figure_job: None,
            units: UnitSystem::Si,
            quit: false,
            dirty: true,
            inputs_changed: true,
            job: None,
        };
        // A preset saved from the explorer opens as it was left (its park
        // among the bundled; `run` looks again among the user's).
        if let Some(setup) = &setup {
            app.restore_setup(setup);
            app.message = None;
        }
        app.fit_figure();
        app.flush();
        app
    }

    /// The work the background should do now, if any (taken once).
    pub fn take_job(&mut self) -> Option<Job> {
        self.job.take()
    }

    /// Whether background work for the current inputs is still under way.
    /// A batted ball has no optimum, surface nor Δopt to wait for.
    pub fn busy(&self) -> bool {
        let swing_work = !self.is_swing()
            || (self.optimum.is_some_and(|o| o.done)
                && self.heatmap_fresh()
                && self.optimum_gains_fresh());
        !(swing_work && self.gains_done(Gain::Swing) == self.gain_count() && self.figure_fresh())
    }

    /// Whether Δopt is current, or not wanted: it is computed only where
    /// the inputs pane shows it, and only for a swing.
    pub fn optimum_gains_fresh(&self) -> bool {
        !self.wants_optimum_gains() || self.gains_done(Gain::Optimum) == self.gain_count()
    }

    /// Whether Δopt is computed: a swing's, where the pane has its column.
    pub fn wants_optimum_gains(&self) -> bool {
        self.is_swing() && shows_optimum_gains(self.size)
    }

    /// The sensitivities of one kind.
    pub fn gains(&self, gain: Gain) -> &[Option<GainCell>] {
        match gain {
            Gain::Swing => &self.swing_gains,
            Gain::Optimum => &self.optimum_gains,
        }
    }

    /// How many sensitivities of one kind are for the current inputs.
    pub fn gains_done(&self, gain: Gain) -> usize {
        self.gains(gain)
            .iter()
            .filter(|c| c.is_some_and(|c| c.generation == self.generation))
            .count()
    }

    /// Whether the surface shown is the finest one for the current inputs.
    pub fn surface_fresh(&self) -> bool {
        self.surface
            .as_ref()
            .is_some_and(|s| s.last && s.generation == self.generation)
    }

    /// Recomputes what depends on the inputs, once per batch of events (so a
    /// held-down key costs one computation per frame, not per repeat).
    pub fn flush(&mut self) {
        self.flush_inputs();
        self.request_figure();
    }

    fn flush_inputs(&mut self) {
        if !self.inputs_changed {
            return;
        }
        self.inputs_changed = false;
        self.dirty = true;
        self.flown = fly_scene(&self.scene, Purpose::Readout);
        self.judge_fences();
        (self.path, self.ground) = self.plot_tracks(&self.scene);
        // The pin's scene stays; its path follows the plot's resolution.
        if let Some(pin) = self.pin.take() {
            let (path, ground) = self.plot_tracks(&pin.scene);
            self.pin = Some(Pin {
                path,
                ground,
                ..pin
            });
        }
        if let Some(impact) = &self.flown.impact {
            self.impact_stop = self.impact_stop.min(impact_stops(impact).len() - 1);
        }
        self.generation += 1;
        // A stale optimum is never shown; the old surface stays, marked
        // stale, until the new one is at least as fine (see `apply`).
        self.optimum = None;
        self.optimal_path.clear();
        self.optimal_ground.clear();
        self.job = Some(self.job_for(Work::Everything));
        self.refresh_margin(false);
    }

    /// The background work for the current inputs.
    fn job_for(&self, work: Work) -> Job {
        let start = self
            .warm_start
            .unwrap_or((self.scene.bat.undercut, self.scene.bat.swing_angle));
        Job {
            generation: self.generation,
            scene: self.scene,
            start,
            window: Grid::explorer_window(),
            resolution: heatmap_resolution(self.size),
            optimum_gains: self.wants_optimum_gains(),
            range_surface: !self.shows_margin(),
            units: self.units,
            work,
        }
    }

    /// A scene's flight sampled at the plot's resolution, flown once: its
    /// side view (distance from the plate, height) and its ground track
    /// (x, z).
    fn plot_tracks(&self, scene: &Scene) -> (Path, Path) {
        let samples = trajectory_samples(self.size, self.is_swing());
        let (_, points) = scene_start(scene)
            .0
            .trajectory(&Purpose::Plot.flight_options(), samples);
        points
            .iter()
            .map(|p| ((p.distance, p.y), (p.x, p.z)))
            .unzip()
    }

    pub fn handle(&mut self, event: &Event) {
        match event {
            Event::Key(key) if key.kind != KeyEventKind::Release => self.key(*key),
            Event::Mouse(mouse) => self.mouse(*mouse),
            Event::Resize(columns, rows) => {
                self.size = Rect::new(0, 0, *columns, *rows);
                self.dirty = true;
                // The plot and the heatmap follow the new resolution.
                self.inputs_changed = true;
            }
            _ => {}
        }
    }

    fn key(&mut self, key: KeyEvent) {
        let action = keymap::action(&key);
        if action == Some(Action::Interrupt) {
            self.quit = true;
            return;
        }
        self.dirty = true;
        match std::mem::replace(&mut self.mode, Mode::Normal) {
            Mode::Normal => {
                // A message lasts until the next key (which may set a new
                // one), save `i`, which shows it whole.
                if action != Some(Action::Detail) {
                    self.message = None;
                    self.export_message = None;
                }
                if let Some(action) = action {
                    self.act(action);
                }
            }
            Mode::Help { glossary, scroll } => self.help_key(action, glossary, scroll),
            Mode::Detail { scroll } => self.detail_key(action, scroll),
            Mode::Edit {
                field,
                text,
                error,
                initial,
            } => self.edit_key(key, action, field, text, (error, initial)),
            Mode::Save {
                text,
                error,
                overwrite,
                named,
            } => self.save_key(key, action, text, (error, overwrite), named),
            Mode::Open {
                items,
                selected,
                error,
                find,
            } => self.open_key((key, action), items, (selected, find), error),
            Mode::Parks { query, selected } => self.parks_key(key, query, selected),
        }
    }

    /// Does what a key asks for over the panes (no pop-up open).
    fn act(&mut self, action: Action) {
        match action {
            Action::Quit | Action::Interrupt => self.quit = true,
            Action::Detail => self.mode = Mode::Detail { scroll: 0 },
            Action::Help => {
                self.mode = Mode::Help {
                    glossary: false,
                    scroll: 0,
                }
            }
            Action::Down => self.selected = (self.selected + 1).min(self.fields.len() - 1),
            Action::Up => self.selected = self.selected.saturating_sub(1),
            // The first input, past the preset's row (Enter there opens
            // the picker; k reaches it).
            Action::First => {
                self.selected = self
                    .fields
                    .iter()
                    .position(|f| !matches!(f, Field::Preset))
                    .unwrap_or(0)
            }
            Action::Last => self.selected = self.fields.len() - 1,
            Action::Raise(step) => self.nudge(step.factor()),
            Action::Lower(step) => self.nudge(-step.factor()),
            Action::Confirm | Action::Edit => self.start_edit(),
            Action::Save => {
                // A name that hides no bundled preset and overwrites no file.
                let name = preset::fresh_name(&self.preset_name, self.presets_dir.as_deref());
                self.mode = Mode::Save {
                    text: prefilled(name, &self.theme),
                    error: None,
                    overwrite: None,
                    named: None,
                };
            }
            Action::Open => self.open_picker(),
            Action::ToOptimum => self.reset_to_optimum(),
            Action::Units => self.toggle_units(),
            Action::Scene => self.switch_scene(),
            Action::Pin => self.pin_scene(),
            Action::Unpin => self.pin = None,
            Action::NextPark | Action::PreviousPark => {
                self.cycle_park(action == Action::NextPark);
            }
            Action::FindPark => {
                self.mode = Mode::Parks {
                    query: String::new(),
                    selected: self.park.unwrap_or(0),
                }
            }
            Action::MarginMap => self.toggle_margin(),
            Action::ParkAir => self.toggle_park_air(),
            Action::NextTab | Action::PreviousTab => {
                let n = Tab::ALL.len();
                let k = Tab::ALL.iter().position(|t| *t == self.tab).unwrap_or(0);
                let next = if action == Action::NextTab {
                    k + 1
                } else {
                    k + n - 1
                };
                self.tab = Tab::ALL[next % n];
            }
            Action::ShowTab(tab) => self.tab = tab,
            Action::NextStop => {
                if let Some(impact) = &self.flown.impact {
                    let last = impact_stops(impact).len() - 1;
                    self.impact_stop = (self.impact_stop + 1).min(last);
                }
            }
            Action::PreviousStop => self.impact_stop = self.impact_stop.saturating_sub(1),
            Action::Export => self.export(),
            Action::NextFigure => self.step_figure(true),
            Action::NextPanel => self.figure_panel = self.figure_panel.wrapping_add(1),
            Action::PreviousFigure => self.step_figure(false),
            // The message is cleared already.
            Action::Close => {}
        }
    }

    /// The inputs list's lines: `None` for a group's header, else the field's index.
    pub fn input_lines(&self) -> Vec<Option<usize>> {
        let groups: Vec<&str> = self.fields.iter().map(|f| f.group()).collect();
        super::layout::input_lines(&groups)
    }
}

/// What the swing scene's views say in the batted-ball scene.
pub const SWING_ONLY: &str =
    "the optimum, the range surface and the impact belong to the swing scene: b switches to it";
