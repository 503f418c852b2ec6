//! A figure's table, conditions and title in the units shown (the command
//! line's `--units`, the explorer's `u`). The figures are computed in SI
//! ([`super`]); this only rewrites what text, CSV and SVG show. Marks,
//! notes and the paper's stated numbers keep the paper's SI words, each
//! with its unit.

use super::{self as figures, Cell, FigureData};
use model::keys::all_keys;
use model::launch::SceneKind;
use model::scene::Scene;
use units::{Quantity, UnitSystem};

/// What a figure column measures, from its key: `launch_spin_mu_0.35` is a
/// spin, `bat_speed` (a swept key, dots made underscores) the key's own.
fn quantity(key: &str) -> (Quantity, &'static str) {
    let fixed = match key {
        "undercut" => Some(Quantity::Size),
        "swing_angle" => Some(Quantity::Angle),
        "range" | "x" | "y" => Some(Quantity::Distance),
        "air_speed" | "launch_speed" => Some(Quantity::Speed),
        _ if key.starts_with("launch_spin") => Some(Quantity::Spin),
        _ if key.starts_with("launch_angle") => Some(Quantity::Angle),
        _ => None,
    };
    if let Some(quantity) = fixed {
        return (quantity, quantity.si_symbol());
    }
    all_keys()
        .find(|k| k.name.replace('.', "_") == key)
        .map_or((Quantity::Unchanged, ""), |k| (k.quantity(), k.unit))
}

/// `data` with its numeric columns converted, their headings, CSV names and
/// decimals in the units shown; as it is in SI.
pub fn converted(mut data: FigureData, shown: UnitSystem) -> FigureData {
    if shown == UnitSystem::Si {
        return data;
    }
    for (k, column) in data.columns.iter_mut().enumerate() {
        let (quantity, si_symbol) = quantity(&column.key);
        let unit = quantity.unit(shown, si_symbol);
        if unit.is_identity() {
            continue;
        }
        column.head =
            column
                .head
                .replacen(&format!("({si_symbol})"), &format!("({})", unit.symbol), 1);
        column.key = format!("{}_{}", column.key, unit.ascii_symbol());
        column.decimals = unit.decimals(column.decimals);
        for row in &mut data.rows {
            if let Cell::Num(x) = &mut row[k] {
                *x = unit.show(*x);
            }
        }
    }
    data.title = title(&data.title, shown);
    data
}

/// The current input's value on a figure's x axis, in the units shown
/// (`data` in SI, as computed).
pub fn now(data: &FigureData, scene: &Scene, shown: UnitSystem) -> Option<f64> {
    let value = figures::curves::current_value(data, scene)?;
    let key = &data.columns[figures::curves::x_column(data)].key;
    let (quantity, si_symbol) = quantity(key);
    let unit = quantity.unit(shown, si_symbol);
    Some(if unit.is_identity() {
        value
    } else {
        unit.show(value)
    })
}

/// The units a title names for its axes, in the units shown (the numbers it
/// quotes keep their SI units beside them).
pub fn title(title: &str, shown: UnitSystem) -> String {
    if shown == UnitSystem::Si {
        return title.to_owned();
    }
    let mut out = title.to_owned();
    for (si, imperial) in [
        (
            "(E_opt m, ψ_opt rad, range m)",
            "(E_opt in, ψ_opt °, range ft)",
        ),
        ("range (m)", "range (ft)"),
        ("E (m)", "E (in)"),
        ("ψ (rad)", "ψ (°)"),
        ("ζ (rad)", "ζ (°)"),
        ("x, y (m)", "x, y (ft)"),
    ] {
        out = out.replace(si, imperial);
    }
    // Speeds and spins in parentheses: a sweep's axis, "V_B0 (m/s)", "ω_b0
    // (rad/s, topspin positive)"; numbers quoted in the title keep theirs.
    out.replace("(m/s", "(mph").replace("(rad/s", "(rpm")
}

/// The inputs a figure was computed with, in one line, as
/// [`figures::conditions`] writes them in SI.
pub fn conditions(name: &str, s: &Scene, shown: UnitSystem) -> String {
    if shown == UnitSystem::Si {
        return figures::conditions(name, s);
    }
    let v = |quantity: Quantity, si: f64| {
        let unit = quantity.in_system(shown);
        let gap = if unit.symbol == "°" { "" } else { " " };
        let value = if unit.is_identity() {
            si
        } else {
            unit.show(si)
        };
        format!("{}{gap}{}", figures::short(value), unit.symbol)
    };
    if s.kind == SceneKind::BattedBall {
        let launch = s.batted_ball();
        return format!(
            "preset {name}: launch {}, {}, spin {}; wind {}; ρ {} kg/m³; drag {}, lift {}",
            v(Quantity::Speed, launch.speed),
            v(Quantity::Angle, launch.angle),
            v(Quantity::Spin, launch.spin),
            v(Quantity::Speed, s.environment.wind),
            figures::trimmed(s.environment.air_density),
            s.drag,
            s.lift
        );
    }
    format!(
        "preset {name}: pitch {}, spin {}; bat {}, roll {}, E {}, ψ {}, μ {}; wind {}; ρ {} kg/m³; drag {}, lift {}",
        v(Quantity::Speed, s.pitch.speed),
        v(Quantity::Spin, s.pitch.spin),
        v(Quantity::Speed, s.bat.speed),
        v(Quantity::Spin, s.bat.spin),
        v(Quantity::Size, s.bat.undercut),
        v(Quantity::Angle, s.bat.swing_angle),
        figures::trimmed(s.bat.friction),
        v(Quantity::Speed, s.environment.wind),
        figures::trimmed(s.environment.air_density),
        s.drag,
        s.lift
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_are_known_by_their_keys() {
        assert_eq!(quantity("undercut").0, Quantity::Size);
        assert_eq!(quantity("launch_spin_mu_0.35").0, Quantity::Spin);
        assert_eq!(quantity("bat_speed"), (Quantity::Speed, "m/s"));
        assert_eq!(quantity("reynolds").0, Quantity::Unchanged);
    }

    #[test]
    fn titles_name_the_units_shown() {
        let imperial = UnitSystem::Imperial;
        assert_eq!(
            title(
                "the optimum (E_opt m, ψ_opt rad, range m) and its launch against bat speed V_B0 (m/s)",
                imperial
            ),
            "the optimum (E_opt in, ψ_opt °, range ft) and its launch against bat speed V_B0 (mph)"
        );
    }
}
