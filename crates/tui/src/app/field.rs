//! The field from above: its scale (what the view draws and a click reads,
//! one computation), the fence it shows, and a click that sets the launch
//! direction.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4};

use ratatui::layout::Rect;

use super::*;
use crate::format::on_step;
use crate::layout::FieldMap;
use model::frame::direction_of;
use model::many;
use model::park::{self, GivenWeather};
use preset::parks::Parks;
use preset::{escape_cut, escape_for_terminal};

/// The current flight at the parks: how many it clears, and what it does
/// at the one chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AtParks {
    pub cleared: usize,
    pub of: usize,
    pub here: Option<model::clearing::Clearing>,
}

/// The key a click on the field sets.
pub const DIRECTION: &str = "launch.direction";

/// The parks `m`/`M` go through: the 30 bundled (less any that a user's
/// park of the same code hides), then the user's own from the parks
/// folder, as `fly --park` finds them ([`preset::parks::all`]).
#[derive(Clone, Debug)]
pub struct ParkList {
    pub list: Parks,
    /// Why the user's parks could not be read: then the bundled alone.
    pub error: Option<String>,
}

impl Default for ParkList {
    /// The bundled parks alone.
    fn default() -> ParkList {
        ParkList {
            list: preset::parks::all(None).unwrap_or_default(),
            error: None,
        }
    }
}

impl App {
    /// Every ground track shown: now, the pin's, the optimal swing's.
    pub fn ground_tracks(&self) -> impl Iterator<Item = &(f64, f64)> {
        let pinned = self.pin.as_ref().map_or(&[][..], |p| &p.ground[..]);
        self.ground.iter().chain(&self.optimal_ground).chain(pinned)
    }

    /// The park chosen (`m`/`M`), if any.
    pub fn chosen_park(&self) -> Option<&park::Park> {
        self.park.and_then(|k| self.parks.list.parks.get(k))
    }

    /// The index of the park `code` names (its code, else an alias, in
    /// any case), as `--park` finds it.
    pub fn park_index(&self, code: &str) -> Option<usize> {
        let park = self.parks.list.find(code)?;
        self.parks
            .list
            .parks
            .iter()
            .position(|p| std::ptr::eq(p, park))
    }

    /// Reads the user's parks from `dir` (every `*.toml` in it) beside the
    /// bundled ones for `m`/`M`. A file that does not read leaves the
    /// bundled parks alone, and says why (a park silently missing would
    /// be a wrong answer, not a smaller list).
    pub fn load_parks(&mut self, dir: Option<&std::path::Path>) {
        let code = self.chosen_park().map(|p| p.code.clone());
        self.parks = match preset::parks::all(dir) {
            Ok(list) => {
                if let Some(note) = &list.note {
                    self.message = Some((note.clone(), false));
                }
                ParkList { list, error: None }
            }
            Err(e) => {
                let error = e.to_string();
                self.message = Some((
                    format!("your parks were not read, the 30 bundled only: {error}"),
                    true,
                ));
                ParkList {
                    error: Some(error),
                    ..ParkList::default()
                }
            }
        };
        // The park chosen stays chosen, found by its code in the new list.
        self.park = code.and_then(|code| self.park_index(&code));
        if self.park.is_none() {
            self.air_before_park = None;
        }
        self.judge_fences();
        self.refresh_margin(true);
        self.dirty = true;
    }

    /// The fence from above: the chosen park's, else the preset's generic
    /// fence, the same in every direction.
    pub fn field_fence(&self) -> Option<park::Fence> {
        if let Some(p) = self.chosen_park() {
            return Some(p.fence.clone());
        }
        self.fence
            .map(|f| park::Fence::uniform(f.distance, f.height))
    }

    /// The fence the side view draws, (distance, height) in m: the chosen
    /// park's wall where the ball's track crosses it (or toward its
    /// landing), else the preset's fence.
    pub fn side_fence(&self) -> Option<(f64, f64)> {
        if self.park.is_some() {
            let wall = self.at_parks.as_ref()?.here?.wall?;
            return Some((wall.distance, wall.height));
        }
        self.fence.map(|f| (f.distance, f.height))
    }

    /// The current flight judged at the preset's fence (`fence_height`)
    /// and at the park chosen, which may be a user's: one flight for both;
    /// and the count of the 30 bundled parks, each on a flight in its own
    /// air, as `fly --preset` counts them (the standard air at each park's
    /// elevation: the explorer gives no weather of its own to keep).
    pub(super) fn judge_fences(&mut self) {
        let parks = park::bundled();
        let generic = self
            .fence
            .map(|f| park::Fence::uniform(f.distance, f.height));
        let chosen = self.chosen_park().map(|p| &p.fence);
        let fences: Vec<&park::Fence> = generic.iter().chain(chosen).collect();
        let options = Purpose::Readout.flight_options();
        let (flight, _, _) = scene_start(&self.scene);
        let (_, mut clearings) = flight.judge(&options, &fences);
        let here = if chosen.is_some() {
            clearings.pop()
        } else {
            None
        };
        self.fence_height = if generic.is_some() {
            clearings.remove(0).height_at_fence
        } else {
            None
        };
        let in_own_air =
            many::judged_in_own_air(&self.scene, parks, GivenWeather::default(), &options);
        let cleared = in_own_air.iter().filter(|c| c.clears()).count();
        self.at_parks = Some(AtParks {
            cleared,
            of: parks.len(),
            here,
        });
    }

    /// `m`/`M`: the next or previous park (the bundled, then the user's),
    /// through "none" (the preset's fence) at either end.
    pub(super) fn cycle_park(&mut self, forward: bool) {
        let n = self.parks.list.parks.len();
        let park = match (self.park, forward) {
            (None, true) => n.checked_sub(1).map(|_| 0),
            (None, false) => n.checked_sub(1),
            (Some(k), true) => (k + 1 < n).then_some(k + 1),
            (Some(k), false) => k.checked_sub(1),
        };
        self.choose_park(park);
    }

    /// The parks (their indices) that answer to `query` as it is typed in
    /// the park list: each of its words the start of the park's code (or an
    /// alias), or of a word of its name or city; without regard to case.
    /// All of them for an empty query.
    pub fn parks_matching(&self, query: &str) -> Vec<usize> {
        let query = query.to_lowercase();
        let words: Vec<&str> = query.split_whitespace().collect();
        let starts = |text: &str, word: &str| {
            text.to_lowercase()
                .split(|c: char| c.is_whitespace() || c == '-' || c == '.')
                .any(|w| w.starts_with(word))
        };
        self.parks
            .list
            .parks
            .iter()
            .enumerate()
            .filter(|(_, p)| {
                words.iter().all(|w| {
                    p.code.to_lowercase().starts_with(w)
                        || p.aliases.iter().any(|a| a.to_lowercase().starts_with(w))
                        || starts(&p.name, w)
                        || starts(&p.city, w)
                })
            })
            .map(|(k, _)| k)
            .collect()
    }

    /// A key in the park list: typing filters it, ↑ ↓ move, Enter chooses
    /// the park, Esc closes it.
    pub(super) fn parks_key(&mut self, key: KeyEvent, mut query: String, selected: usize) {
        use ratatui::crossterm::event::{KeyCode, KeyModifiers};
        let found = self.parks_matching(&query);
        let mut at = found.iter().position(|&k| k == selected).unwrap_or(0);
        match key.code {
            KeyCode::Esc => return,
            KeyCode::Enter => {
                if let Some(&k) = found.get(at) {
                    self.choose_park(Some(k));
                    return;
                }
            }
            KeyCode::Down => at = (at + 1).min(found.len().saturating_sub(1)),
            KeyCode::Up => at = at.saturating_sub(1),
            KeyCode::Backspace => {
                query.pop();
            }
            KeyCode::Char(c) if !key.modifiers.contains(KeyModifiers::CONTROL) => query.push(c),
            _ => {}
        }
        let found_now = self.parks_matching(&query);
        // The same park stays selected while it still answers, else the first.
        let keep = found.get(at).copied().filter(|k| found_now.contains(k));
        let selected = keep.or(found_now.first().copied()).unwrap_or(selected);
        self.mode = Mode::Parks { query, selected };
    }

    /// Chooses the park `park` (an index into the list; None: the preset's
    /// fence): its fence, its verdict and (in the park's air) its air.
    fn choose_park(&mut self, park: Option<usize>) {
        let n = self.parks.list.parks.len();
        self.park = park;
        self.judge_fences();
        self.refresh_margin(true);
        self.dirty = true;
        // A park brings its air, as `fly --park` flies in it: a class at
        // Coors should not fly at sea level until it finds `a`. With no
        // park, the air from before.
        let was_in_air = self.in_park_air();
        if park.is_some() && !was_in_air {
            self.air_before_park = Some(self.scene.environment.air());
        }
        let air = self.follow_park_air();
        let mut text = match (self.chosen_park(), self.park) {
            (Some(p), Some(k)) => {
                let yours = self.parks.list.files[k]
                    .as_ref()
                    .and_then(|f| f.file_name())
                    .map_or(String::new(), |f| {
                        format!(", yours from {}", f.to_string_lossy())
                    });
                let what = match &air {
                    Some(Ok(at)) => format!("in its air at {at} (a: the air before)"),
                    _ => "its fence drawn (m/M: the next)".to_owned(),
                };
                format!(
                    "park {}/{n}: {} ({}{yours}), {what}",
                    k + 1,
                    escape_for_terminal(&p.code),
                    escape_cut(&p.name, 40)
                )
            }
            _ if was_in_air => "park: none, the preset's fence, the air before".to_owned(),
            _ => "park: none, the preset's fence (m/M: a park)".to_owned(),
        };
        if let Some(Err(error)) = &air {
            text = error.clone();
        }
        if let Some(error) = &self.parks.error {
            text.push_str(&format!("; your parks were not read: {error}"));
        }
        let error = self.parks.error.is_some() || matches!(air, Some(Err(_)));
        self.message = Some((text, error));
    }

    /// The field view's scale in `pane`: the fence and every track with a
    /// margin, as tight as they are (a park's foul poles nearer than its
    /// centre field make it narrower), so that they fill the pane as far
    /// as equal scales allow.
    pub fn field_map(&self, pane: Rect) -> FieldMap {
        // The fence's reach up the page and to either side, pole to pole
        // (sampled finely, with its own corners).
        let fence: Vec<(f64, f64)> = self.field_fence().map_or(Vec::new(), |f| {
            let n = 180;
            (0..=n)
                .map(|i| -FRAC_PI_4 + FRAC_PI_2 * f64::from(i) / f64::from(n))
                .chain(f.points().iter().map(|p| p.direction))
                .filter_map(|d| f.distance_at(d).map(|r| (r * d.cos(), r * d.sin())))
                .collect()
        });
        let points = || {
            fence
                .iter()
                .chain(self.ground_tracks())
                .filter(|p| p.0.is_finite() && p.1.is_finite())
        };
        let reach = 1.06 * points().map(|p| p.0).fold(10.0, f64::max);
        let half = 1.04 * points().map(|p| p.1.abs()).fold(0.0, f64::max);
        // Fair territory to the foul lines at least half as far as the view
        // reaches (a short pop-up's view still shows the lines part).
        let half = half.max(0.5 * FRAC_1_SQRT_2 * reach);
        let behind = points().map(|p| -p.0).fold(0.0, f64::max) + 0.03 * reach;
        FieldMap::new(pane, half, behind, reach)
    }

    /// A click at screen (x, y) on the field in `pane`: the launch toward
    /// that point, on the input's step in the unit shown and validated as
    /// a typed value is; a point behind the plate's line is refused in
    /// place. A swing's launch comes from its impact, so there the click
    /// makes it the batted ball it launches (as `b` does) toward that
    /// point: `b` returns to the swing as it was.
    pub(super) fn click_field(&mut self, pane: Rect, x: u16, y: u16) -> bool {
        let Some((along, across)) = self.field_map(pane).point(x, y) else {
            return false;
        };
        self.dirty = true;
        let Ok(key) = Scene::key(DIRECTION) else {
            return true;
        };
        let direction = direction_of(along, across);
        if direction.is_nan() || direction.abs() >= FRAC_PI_2 {
            self.message = Some((
                format!(
                    "{DIRECTION}: a click behind the plate's line gives no launch; click in front of it"
                ),
                true,
            ));
            return true;
        }
        let value = on_step(key, direction, self.units);
        let was_swing = self.is_swing();
        let mut scene = if was_swing {
            self.scene.with_launch(self.flown.launch)
        } else {
            self.scene
        };
        (key.set)(&mut scene, value);
        match scene.validate() {
            Ok(()) => {
                self.set_scene(scene);
                self.message = was_swing.then(|| {
                    (
                        "batted-ball scene: this swing's launch toward the click (b: back to the swing)"
                            .into(),
                        false,
                    )
                });
            }
            Err(error) => self.message = Some((error_text(&error, self.units), true)),
        }
        true
    }
}
