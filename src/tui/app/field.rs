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

/// The key a click on the field sets.
pub const DIRECTION: &str = "launch.direction";

impl App {
    /// Every ground track shown: now, the pin's, the optimal swing's.
    pub fn ground_tracks(&self) -> impl Iterator<Item = &(f64, f64)> {
        let pinned = self.pin.as_ref().map_or(&[][..], |p| &p.ground[..]);
        self.ground.iter().chain(&self.optimal_ground).chain(pinned)
    }

    /// The fence from above. Today the preset's generic fence, the same in
    /// every direction; a park's fence (per direction) fits the same place.
    pub fn field_fence(&self) -> Option<park::Fence> {
        self.fence
            .map(|f| park::Fence::uniform(f.distance, f.height))
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
