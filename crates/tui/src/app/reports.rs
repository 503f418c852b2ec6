//! The background's results taken in: the optimum, the range surface and
//! the sensitivities, for the current inputs only.

use super::*;

impl App {
    /// Takes in a background result, unless it is for older inputs.
    pub fn apply(&mut self, report: Report) {
        if report.generation() != self.generation {
            return;
        }
        self.dirty = true;
        match report {
            Report::Optimum {
                best,
                evaluations,
                done,
                status,
                ..
            } => {
                let scene = self.scene.with_swing(best.undercut, best.swing_angle);
                // One flight (~0.1 ms), once: a hovering ball's best can graze
                // the ground at the optimiser's precision only.
                let lands_at_readout = !(done && best.range.is_finite())
                    || model::simulate(&scene, Purpose::Readout).flight.landed;
                self.optimum = Some(OptimumState {
                    best,
                    evaluations,
                    done,
                    status,
                    lands_at_readout,
                });
                // A search that found nothing landing has no optimum to
                // start from or to draw.
                if done && best.range.is_finite() {
                    self.warm_start = Some((best.undercut, best.swing_angle));
                    (self.optimal_path, self.optimal_ground) = self.plot_tracks(&scene);
                }
            }
            Report::Sensitivity {
                gain,
                key,
                value,
                generation,
            } => {
                let cells = match gain {
                    Gain::Swing => &mut self.swing_gains,
                    Gain::Optimum => &mut self.optimum_gains,
                };
                if let Some(cell) = cells.get_mut(key) {
                    *cell = Some(GainCell { value, generation });
                }
            }
            Report::Surface {
                surface,
                last,
                generation,
            } => {
                // A coarse surface for new inputs does not replace a finer
                // one for the old: while a key is held the map then updates
                // in place, without flashing through blocks, and a repaint
                // costs only the cells that changed.
                let cells = |s: &Surface| s.grid.columns * s.grid.rows;
                let replace = match &self.surface {
                    None => true,
                    Some(shown) => {
                        last || shown.generation == generation
                            || cells(&surface) >= cells(&shown.surface)
                    }
                };
                if replace {
                    self.surface = Some(SurfaceState {
                        surface,
                        last,
                        generation,
                    });
                }
            }
        }
    }
}
