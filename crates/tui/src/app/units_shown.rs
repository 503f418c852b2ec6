//! Key `u`: every quantity shown and typed in the other units.

use super::{App, Work};
use units::UnitSystem;

impl App {
    /// Shows every quantity in `units` (as `u` would switch them).
    pub fn set_units(&mut self, units: UnitSystem) {
        if self.units != units {
            self.toggle_units();
        }
    }

    /// Key `u`: every quantity shown in the other units. Nothing physical
    /// changes, but a nudge now moves by the shown unit's step, so the Δ
    /// columns are recomputed; the optimum and surface stay when they are
    /// complete (else everything is, as after an input's change).
    pub(super) fn toggle_units(&mut self) {
        self.units = self.units.toggled();
        self.message = Some((
            match self.units {
                UnitSystem::Si => "SI units: m, m/s, rad, rad/s, kg, °C, hPa (u: baseball's)",
                UnitSystem::Imperial => "baseball units: ft, in, mph, °, rpm, oz, °F, inHg (u: SI)",
            }
            .into(),
            false,
        ));
        let done = self.optimum.filter(|o| o.done);
        if self.is_swing() && !(done.is_some() && self.surface_fresh()) {
            self.inputs_changed = true;
            return;
        }
        self.generation += 1;
        if let Some(surface) = &mut self.surface {
            surface.generation = self.generation;
        }
        self.job = Some(self.job_for(Work::Gains {
            optimum: done.map(|o| o.best),
        }));
    }
}
