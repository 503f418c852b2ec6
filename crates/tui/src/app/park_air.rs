//! Key `a`: the scene flies in the chosen park's own air, the standard
//! atmosphere at its elevation, as `fly --park CODE --own-air` flies each
//! park (the same [`GivenWeather::park_air`]; the explorer gives no
//! weather of its own, so all four are the standard atmosphere's but the
//! elevation). A park chosen brings its air; while on, the air follows
//! the park as `m`/`M` pick another; `a`, or no park, brings back the air
//! from before, and `a` again the park's. The weather
//! inputs show the park's air, and can be typed over until the next park.

use super::*;
use model::atmosphere::Air;
use model::park::GivenWeather;
use preset::escape_for_terminal;

impl App {
    /// Whether the scene flies in the chosen park's air (key `a`).
    pub fn in_park_air(&self) -> bool {
        self.air_before_park.is_some()
    }

    /// Key `a`: into the park's air, or back to the air before.
    pub(super) fn toggle_park_air(&mut self) {
        if let Some(before) = self.air_before_park.take() {
            self.restore_air(before);
            self.message = Some((
                "air: as before the park's (a: the park's own)".into(),
                false,
            ));
            return;
        }
        let Some(park) = self.chosen_park() else {
            self.message = Some(("a: pick a park first (m/M), then its air".into(), true));
            return;
        };
        let code = escape_for_terminal(&park.code);
        self.air_before_park = Some(self.scene.environment.air());
        self.message = Some(match self.follow_park_air() {
            Some(Ok(at)) => (
                format!("air: {code}'s, the standard air at {at} (a: the air before)"),
                false,
            ),
            Some(Err(error)) => (error, true),
            None => return,
        });
    }

    /// In the park's air, a new park brings its own (`Some(Ok(its
    /// elevation, as shown))`), and no park the air from before; `None`
    /// when not in a park's air. A park's air the scene refuses (outside
    /// the inputs' bounds) ends it, and says why.
    pub(super) fn follow_park_air(&mut self) -> Option<Result<String, String>> {
        self.in_park_air().then_some(())?;
        let Some(park) = self.chosen_park() else {
            let before = self.air_before_park.take()?;
            self.restore_air(before);
            return None;
        };
        let elevation = park.elevation;
        let mut scene = self.scene;
        GivenWeather::default().park_air(&mut scene.environment, elevation);
        Some(match scene.validate() {
            Ok(()) => {
                self.set_scene(scene);
                let unit = self.unit(Quantity::Distance);
                Ok(format!("{:.0} {}", unit.show(elevation), unit.symbol))
            }
            Err(error) => {
                self.air_before_park = None;
                Err(error_text(&error, self.units))
            }
        })
    }

    /// Puts `air` back as it was: derived from its weather, or given.
    fn restore_air(&mut self, air: Air) {
        let mut scene = self.scene;
        match air.atmosphere {
            Some(weather) => scene.environment.set_atmosphere(weather),
            None => {
                scene.environment.set_air_density(air.density);
                scene
                    .environment
                    .set_kinematic_viscosity(air.kinematic_viscosity);
            }
        }
        self.set_scene(scene);
    }
}
