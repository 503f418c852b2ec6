//! `hit --batch --summary` (and `fly --batch --spin swing --summary`): what
//! the solved swings did, by the measured launch angle, as
//! docs/bat-tracking.md tabulates April 2024 (where the bat met the ball
//! sets the launch angle, more than the swing's angle does).

use std::fmt::Write;

use serde::Serialize;

use super::output::{BANDS, band_bounds, band_index, band_name, median};
use super::swing_columns::RowSwing;
use crate::cli::shown::Shown;
use crate::units::Quantity;

/// One solved swing, as the table needs it.
#[derive(Clone, Copy, Debug)]
struct Solved {
    band: usize,
    /// E (m).
    undercut: f64,
    squared_up: f64,
    /// The bat's speed at the contact over the sweet spot's (`bat_speed`).
    contact_speed: f64,
    /// The impact's whole spin (rad/s): back, side and gyro together, as a
    /// tracker measures it.
    spin: f64,
}

/// The tracked rows by band, and the solved ones.
#[derive(Clone, Debug, Default)]
pub(super) struct SwingBands {
    tracked: [usize; BANDS],
    solved: Vec<Solved>,
}

/// One band of the table (SI in JSON: m, rad/s).
#[derive(Debug, PartialEq, Serialize)]
pub(super) struct SwingBand {
    /// From this launch angle (°, none for the lowest band) up to `to`.
    from: Option<f64>,
    to: Option<f64>,
    tracked: usize,
    solved: usize,
    /// Medians over the solved swings (none without one).
    undercut: Option<f64>,
    squared_up: Option<f64>,
    contact_speed: Option<f64>,
    spin: Option<f64>,
}

impl SwingBands {
    pub(super) fn count(&mut self, swing: &RowSwing) {
        let Ok(tracked) = &swing.tracked else { return };
        let band = band_index(tracked.launch_angle);
        self.tracked[band] += 1;
        if let Some(solved) = swing.solved() {
            let launch = solved.launch;
            self.solved.push(Solved {
                band,
                undercut: solved.scene.bat.undercut,
                squared_up: solved.squared_up(),
                contact_speed: solved.scene.bat.speed / tracked.bat_speed,
                spin: (launch.spin.powi(2) + launch.sidespin.powi(2) + launch.gyrospin.powi(2))
                    .sqrt(),
            });
        }
    }

    pub(super) fn add(&mut self, other: &SwingBands) {
        for (total, n) in self.tracked.iter_mut().zip(other.tracked) {
            *total += n;
        }
        self.solved.extend_from_slice(&other.solved);
    }

    pub(super) fn any(&self) -> bool {
        self.tracked.iter().any(|&n| n > 0)
    }

    pub(super) fn rows(&self) -> Vec<SwingBand> {
        (0..BANDS)
            .map(|band| {
                let solved: Vec<&Solved> = self.solved.iter().filter(|s| s.band == band).collect();
                let middle = |part: fn(&Solved) -> f64| {
                    let mut values: Vec<f64> = solved.iter().map(|s| part(s)).collect();
                    (!values.is_empty()).then(|| median(&mut values))
                };
                let (from, to) = band_bounds(band);
                SwingBand {
                    from,
                    to,
                    tracked: self.tracked[band],
                    solved: solved.len(),
                    undercut: middle(|s| s.undercut),
                    squared_up: middle(|s| s.squared_up),
                    contact_speed: middle(|s| s.contact_speed),
                    spin: middle(|s| s.spin),
                }
            })
            .collect()
    }

    /// The bands as a small table, in the units shown (the undercut in mm
    /// or in, the spin in rad/s or rpm).
    pub(super) fn table(&self, shown: Shown) -> String {
        let (size, spin) = (shown.unit(Quantity::Size), shown.unit(Quantity::Spin));
        let (size_scale, size_symbol, size_decimals) = match shown.is_si() {
            true => (1e3, "mm", 1),
            false => (1.0, size.symbol, 2),
        };
        let mut table = format!(
            "swings by launch angle, medians of the solved (contact: its speed / bat_speed):\n\
             {:<8} {:>7} {:>7} {:>13} {:>10} {:>8} {:>12}\n",
            "angle",
            "tracked",
            "solved",
            format!("undercut ({size_symbol})"),
            "squared up",
            "contact",
            format!("spin ({})", spin.symbol),
        );
        for band in self.rows().iter().filter(|b| b.tracked > 0) {
            let name = band_name((band.from, band.to));
            let show =
                |value: Option<f64>, text: &dyn Fn(f64) -> String| value.map_or("-".into(), text);
            let _ = writeln!(
                table,
                "{name:<8} {:>7} {:>6.1}% {:>13} {:>10} {:>8} {:>12}",
                band.tracked,
                100.0 * band.solved as f64 / band.tracked as f64,
                show(band.undercut, &|e| format!(
                    "{:+.size_decimals$}",
                    size.show(e) * size_scale
                )),
                show(band.squared_up, &|q| format!("{q:.3}")),
                show(band.contact_speed, &|c| format!("{c:.3}")),
                show(band.spin, &|w| format!("{:.0}", spin.show(w))),
            );
        }
        // The summary puts the line breaks between its tables.
        table.pop();
        table
    }
}
