//! The air from the weather: density ρ and kinematic viscosity ν from
//! temperature, elevation, barometric pressure and humidity, as Alan
//! Nathan's trajectory calculator computes them (A. M. Nathan, "Trajectory
//! calculator", baseball.physics.illinois.edu), with the viscosity by
//! Sutherland's law. Pure functions of an [`Atmosphere`]; the scene keeps ρ
//! and ν in step with it (see `Environment` in [`super::scene`]).

use serde::{Deserialize, Serialize};

use units::significant;

/// The weather at the ballpark.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Atmosphere {
    /// Air temperature T (°C).
    pub temperature: f64,
    /// Elevation h of the field above sea level (m).
    pub elevation: f64,
    /// Barometric pressure corrected to sea level (hPa), as weather reports
    /// give it; the elevation is what lowers the pressure at the field.
    pub pressure: f64,
    /// Relative humidity RH (%).
    pub humidity: f64,
}

impl Atmosphere {
    /// The standard values a key left unset takes: 15 °C at sea level,
    /// 1013.25 hPa, 50 % humidity.
    pub const STANDARD: Atmosphere = Atmosphere {
        temperature: 15.0,
        elevation: 0.0,
        pressure: STANDARD_PRESSURE_HPA,
        humidity: 50.0,
    };

    /// ρ (kg/m³), Nathan's calculator:
    /// ρ = 1.2929 · 273.15/(T + 273.15) · (p·e^(−βh) − 0.3783·(RH/100)·SVP)/760,
    /// p and SVP in mmHg, T in °C. 1.2929 kg/m³ is dry air at 0 °C and 760
    /// mmHg; the ideal gas scales it by temperature and by the partial
    /// pressures, water vapour weighing 0.622 of dry air (1 − 0.622 = 0.378).
    pub fn air_density(&self) -> f64 {
        let pressure_mmhg = self.pressure * MMHG_PER_HPA;
        let field_pressure = pressure_mmhg * (-ELEVATION_DECAY * self.elevation).exp();
        let vapour =
            0.3783 * (self.humidity / 100.0) * saturation_vapour_pressure(self.temperature);
        DRY_AIR_DENSITY_AT_0C
            * (ZERO_CELSIUS / (self.temperature + ZERO_CELSIUS))
            * (field_pressure - vapour)
            / STANDARD_PRESSURE_MMHG
    }

    /// ν = μ(T)/ρ (m²/s).
    pub fn kinematic_viscosity(&self) -> f64 {
        dynamic_viscosity(self.temperature) / self.air_density()
    }
}

impl Default for Atmosphere {
    fn default() -> Self {
        Atmosphere::STANDARD
    }
}

impl std::fmt::Display for Atmosphere {
    /// "21 °C, 5 m, 1013 hPa, 50 %", each to six significant digits (70 °F
    /// typed is 21.1111 °C, not 21.11111111111111).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} °C, {} m, {} hPa, {} %",
            significant(self.temperature),
            significant(self.elevation),
            significant(self.pressure),
            significant(self.humidity)
        )
    }
}

/// The ρ and ν in force, and where they come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Air {
    /// ρ (kg/m³).
    pub density: f64,
    /// ν (m²/s).
    pub kinematic_viscosity: f64,
    /// The weather they were derived from; `None` when they were given.
    pub atmosphere: Option<Atmosphere>,
}

impl std::fmt::Display for Air {
    /// "1.194 kg/m³ from 21 °C, 5 m, 1013 hPa, 50 %", or "1.23 kg/m³ as given".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.atmosphere {
            Some(atmosphere) => write!(f, "{:.3} kg/m³ from {atmosphere}", self.density),
            None => write!(f, "{} kg/m³ as given", self.density),
        }
    }
}

/// Saturation vapour pressure of water over water (mmHg) at T (°C), the
/// Buck-type fit of Nathan's calculator:
/// SVP = 4.5841·exp((18.687 − T/234.5)·T/(257.14 + T)).
pub fn saturation_vapour_pressure(temperature: f64) -> f64 {
    4.5841 * ((18.687 - temperature / 234.5) * temperature / (257.14 + temperature)).exp()
}

/// μ (Pa·s) at T (°C), Sutherland's law:
/// μ = μ₀·(T/T₀)^(3/2)·(T₀ + S)/(T + S), T in K, with μ₀ = 1.716·10⁻⁵ Pa·s
/// at T₀ = 273.15 K and S = 110.4 K for air (W. Sutherland, Phil. Mag. 36,
/// 507 (1893); the constants are those of F. M. White, Viscous Fluid Flow,
/// and equal the U.S. Standard Atmosphere 1976's β = 1.458·10⁻⁶
/// kg/(m·s·K^½)). Good to ~2 % from −50 °C to 60 °C.
pub fn dynamic_viscosity(temperature: f64) -> f64 {
    let kelvin = temperature + ZERO_CELSIUS;
    SUTHERLAND_VISCOSITY
        * (kelvin / ZERO_CELSIUS).powf(1.5)
        * ((ZERO_CELSIUS + SUTHERLAND_CONSTANT) / (kelvin + SUTHERLAND_CONSTANT))
}

/// 0 °C in kelvin.
const ZERO_CELSIUS: f64 = 273.15;
/// Dry air at 0 °C and 760 mmHg (kg/m³).
const DRY_AIR_DENSITY_AT_0C: f64 = 1.2929;
/// One standard atmosphere: 760 mmHg = 1013.25 hPa.
const STANDARD_PRESSURE_MMHG: f64 = 760.0;
const STANDARD_PRESSURE_HPA: f64 = 1013.25;
const MMHG_PER_HPA: f64 = STANDARD_PRESSURE_MMHG / STANDARD_PRESSURE_HPA;
/// β: the pressure falls as e^(−βh) with elevation h (1/m), an isothermal
/// scale height of 8.2 km.
const ELEVATION_DECAY: f64 = 1.217e-4;
/// Sutherland's μ₀ (Pa·s) at T₀ = 0 °C, and his constant S (K), for air.
const SUTHERLAND_VISCOSITY: f64 = 1.716e-5;
const SUTHERLAND_CONSTANT: f64 = 110.4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dry_air_at_15_c_and_sea_level_is_the_standard_atmosphere() {
        // ISA: 1.2250 kg/m³ at 15 °C, 1013.25 hPa, dry. The formula's 1.2929
        // kg/m³ at 0 °C gives 1.2256: 0.05 % above.
        let dry = Atmosphere {
            humidity: 0.0,
            ..Atmosphere::STANDARD
        };
        let rho = dry.air_density();
        assert!((rho - 1.2929 * 273.15 / 288.15).abs() < 1e-15, "{rho}");
        assert!((rho / 1.2250 - 1.0).abs() < 6e-4, "{rho}");
        // ISA: μ = 1.7894e-5 Pa·s, ν = 1.4607e-5 m²/s at 15 °C.
        assert!((dynamic_viscosity(15.0) / 1.7894e-5 - 1.0).abs() < 1e-4);
        assert!((dry.kinematic_viscosity() / 1.4607e-5 - 1.0).abs() < 1e-3);
    }

    #[test]
    fn vapour_pressure_matches_steam_tables() {
        // 4.58 mmHg at 0 °C, 17.54 at 20 °C, 55.3 at 40 °C, 149.4 at 60 °C.
        for (t, svp) in [(0.0, 4.5841), (20.0, 17.54), (40.0, 55.32), (60.0, 149.4)] {
            let got = saturation_vapour_pressure(t);
            assert!((got / svp - 1.0).abs() < 3e-3, "{t} °C: {got}");
        }
    }

    #[test]
    fn density_falls_with_heat_height_and_humidity() {
        let base = Atmosphere::STANDARD;
        let mut last = f64::INFINITY;
        for t in (-50..=60).map(f64::from) {
            let rho = Atmosphere {
                temperature: t,
                ..base
            }
            .air_density();
            assert!(rho < last, "{t}");
            last = rho;
        }
        last = f64::INFINITY;
        for h in (-500..=5000).step_by(100).map(f64::from) {
            let rho = Atmosphere {
                elevation: h,
                ..base
            }
            .air_density();
            assert!(rho < last, "{h}");
            last = rho;
        }
        last = f64::INFINITY;
        for rh in (0..=100).map(f64::from) {
            let rho = Atmosphere {
                humidity: rh,
                ..base
            }
            .air_density();
            assert!(rho < last, "{rh}");
            last = rho;
        }
    }

    #[test]
    fn air_says_where_it_comes_from() {
        let atmosphere = Atmosphere {
            temperature: 21.0,
            elevation: 5.0,
            pressure: 1013.0,
            humidity: 50.0,
        };
        let air = Air {
            density: atmosphere.air_density(),
            kinematic_viscosity: atmosphere.kinematic_viscosity(),
            atmosphere: Some(atmosphere),
        };
        assert_eq!(
            air.to_string(),
            "1.194 kg/m³ from 21 °C, 5 m, 1013 hPa, 50 %"
        );
    }
}
