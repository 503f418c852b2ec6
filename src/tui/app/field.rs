//! The field from above: its scale (what the view draws and a click reads,
//! one computation), the fence it shows, and a click that sets the launch
//! direction.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2};

use ratatui::layout::Rect;

use super::*;
use crate::model::frame::direction_of;
use crate::model::park;
use crate::tui::format::on_step;
use crate::tui::layout::FieldMap;

/// The current flight at the parks: how many it clears, and what it does
/// at the one chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AtParks {
    pub cleared: usize,
    pub of: usize,
    pub here: Option<crate::model::clearing::Clearing>,
}

/// The key a click on the field sets.
pub const DIRECTION: &str = "launch.direction";

impl App {
    /// Every ground track shown: now, the pin's, the optimal swing's.
    pub fn ground_tracks(&self) -> impl Iterator<Item = &(f64, f64)> {
        let pinned = self.pin.as_ref().map_or(&[][..], |p| &p.ground[..]);
        self.ground.iter().chain(&self.optimal_ground).chain(pinned)
    }

    /// The park chosen (`m`/`M`), if any.
    pub fn chosen_park(&self) -> Option<&park::Park> {
        self.park.and_then(|k| park::bundled().get(k))
    }

    /// The fence from above: the chosen park's, else the preset's generic
    /// fence, the same in every direction.
    pub fn field_fence(&self) -> Option<park::Fence> {
        if let Some(k) = self.park {
            return park::bundled().get(k).map(|p| p.fence.clone());
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

    /// The current flight judged at the preset's fence (`fence_height`) and
    /// at every bundled park (`at_parks`, in the scene's own air, as `fly`'s
    /// count): one flight for all of them.
    pub(super) fn judge_fences(&mut self) {
        let parks = park::bundled();
        let generic = self
            .fence
            .map(|f| park::Fence::uniform(f.distance, f.height));
        let fences: Vec<&park::Fence> = generic
            .iter()
            .chain(parks.iter().map(|p| &p.fence))
            .collect();
        let (flight, _, _) = scene_start(&self.scene);
        let (_, mut clearings) = flight.judge(&Purpose::Readout.flight_options(), &fences);
        self.fence_height = if generic.is_some() {
            clearings.remove(0).height_at_fence
        } else {
            None
        };
        self.at_parks = Some(AtParks {
            cleared: clearings.iter().filter(|c| c.clears()).count(),
            of: parks.len(),
            here: self.park.and_then(|k| clearings.get(k).copied()),
        });
    }

    /// `m`/`M`: the next or previous park, through "none" (the preset's
    /// fence) at either end.
    pub(super) fn cycle_park(&mut self, forward: bool) {
        let n = park::bundled().len();
        self.park = match (self.park, forward) {
            (None, true) => Some(0),
            (None, false) => n.checked_sub(1),
            (Some(k), true) => (k + 1 < n).then_some(k + 1),
            (Some(k), false) => k.checked_sub(1),
        };
        self.judge_fences();
        self.refresh_margin(true);
        self.dirty = true;
        let text = match self.park.and_then(|k| park::bundled().get(k)) {
            Some(p) => format!(
                "park: {} ({}), its fence drawn (m/M: the next)",
                p.code, p.name
            ),
            None => "park: none, the preset's fence (m/M: a park)".to_owned(),
        };
        self.message = Some((text, false));
    }

    /// The field view's scale in `pane`: the fence and every track with a
    /// margin, and the foul lines' fair territory at least.
    pub fn field_map(&self, pane: Rect) -> FieldMap {
        let fence = self.field_fence().map_or(0.0, |f| {
            f.points().iter().map(|p| p.distance).fold(0.0, f64::max)
        });
        let far = self
            .ground_tracks()
            .map(|&(x, z)| x.hypot(z))
            .filter(|d| d.is_finite())
            .fold(fence.max(10.0), f64::max);
        let reach = 1.06 * far;
        let half = self
            .ground_tracks()
            .map(|p| p.1.abs())
            .filter(|z| z.is_finite())
            .fold(FRAC_1_SQRT_2 * far, f64::max)
            * 1.04;
        let behind = self
            .ground_tracks()
            .map(|p| -p.0)
            .filter(|x| x.is_finite())
            .fold(0.0, f64::max)
            + 0.03 * reach;
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
