//! A park's air: the standard atmosphere at the park's elevation
//! ([`Atmosphere::STANDARD`]: 15 °C, 1013.25 hPa sea-level pressure, 50 %
//! humidity), with whatever weather the user gave kept. A flight taken to
//! a park flies in that park's air unless the user said what air it flies
//! in.

use crate::atmosphere::Atmosphere;
use crate::keys::{AIR_KEYS, ATMOSPHERE_KEYS};
use crate::scene::Environment;

/// Which of the air's inputs the user gave (on the command line, in a
/// row): those a park must not replace.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GivenWeather {
    /// ρ or ν given: the air is the user's, whatever the park.
    air: bool,
    /// Each of [`ATMOSPHERE_KEYS`] (temperature, elevation, pressure,
    /// humidity), in that order.
    weather: [bool; 4],
}

impl GivenWeather {
    /// Notes that `key` was given (keys other than the air's are ignored).
    pub fn note(&mut self, key: &str) {
        if AIR_KEYS.contains(&key) {
            self.air = true;
        } else if let Some(i) = ATMOSPHERE_KEYS.iter().position(|k| *k == key) {
            self.weather[i] = true;
        }
    }

    /// What `--set`'s `key=value` assignments give.
    pub fn of_assignments(assignments: &[String]) -> GivenWeather {
        let mut given = GivenWeather::default();
        for (key, _) in assignments.iter().filter_map(|a| a.split_once('=')) {
            given.note(key.trim());
        }
        given
    }

    /// Whether any air or weather key was given.
    pub fn any(&self) -> bool {
        self.air || self.weather.contains(&true)
    }

    /// Puts `environment` in the standard air at `elevation` (m), keeping
    /// the weather given (read from the environment's atmosphere, which the
    /// given keys set); if ρ or ν was given, leaves the air as it is.
    pub fn park_air(&self, environment: &mut Environment, elevation: f64) {
        if self.air {
            return;
        }
        let own = environment.atmosphere().unwrap_or(Atmosphere::STANDARD);
        let standard = Atmosphere {
            elevation,
            ..Atmosphere::STANDARD
        };
        let pick = |i: usize, own: f64, standard: f64| if self.weather[i] { own } else { standard };
        environment.set_atmosphere(Atmosphere {
            temperature: pick(0, own.temperature, standard.temperature),
            elevation: pick(1, own.elevation, standard.elevation),
            pressure: pick(2, own.pressure, standard.pressure),
            humidity: pick(3, own.humidity, standard.humidity),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    #[test]
    fn a_park_gives_its_elevation_and_keeps_the_weather_given() {
        assert_eq!(
            ATMOSPHERE_KEYS,
            [
                "environment.temperature",
                "environment.elevation",
                "environment.pressure",
                "environment.humidity"
            ]
        );
        let mut scene = Scene::default();
        GivenWeather::default().park_air(&mut scene.environment, 1580.0);
        let coors = Atmosphere {
            elevation: 1580.0,
            ..Atmosphere::STANDARD
        };
        assert_eq!(scene.environment.atmosphere(), Some(coors));
        // 1580 m up, standard air is 17.5 % thinner than at sea level:
        // e^(−1.217e−4·1580) = 0.825 (the vapour term aside).
        let ratio = coors.air_density() / Atmosphere::STANDARD.air_density();
        assert!((ratio - 0.8253).abs() < 0.002, "{ratio}");

        // A temperature given stays; the elevation is the park's.
        let mut scene = Scene::default();
        scene.set("environment.temperature", 30.0).unwrap();
        let mut given = GivenWeather::default();
        given.note("environment.temperature");
        given.park_air(&mut scene.environment, 6.0);
        let air = scene.environment.atmosphere().unwrap();
        assert_eq!((air.temperature, air.elevation), (30.0, 6.0));
        assert_eq!(air.pressure, Atmosphere::STANDARD.pressure);

        // ρ given: the air stays the user's.
        let mut scene = Scene::default();
        let mut given = GivenWeather::default();
        given.note("environment.air_density");
        let before = scene.environment;
        given.park_air(&mut scene.environment, 1580.0);
        assert_eq!(scene.environment, before);
        assert!(given.any());
    }
}
