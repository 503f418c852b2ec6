//! A figure's table, conditions and title in the units shown (the command
//! line's `--units`, the explorer's `u`). The figures are computed in SI
//! ([`super`]); this only rewrites what text, CSV and SVG show: the
//! paper's stated numbers and the notes too ([`super::stated`]), but for
//! the paper's words in quotes.

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
    // The marks' labels ("A (182.4 rad/s)") beside the converted axes.
    for cell in data.rows.iter_mut().flatten() {
        if let Cell::Text(text) = cell {
            *text = quoted(text, shown);
        }
    }
    data.title = title(&data.title, shown);
    // The paper's numbers beside ours, and the notes, in the same units.
    for c in &mut data.comparisons {
        *c = super::stated::comparison(c, shown);
    }
    for note in &mut data.notes {
        *note = super::stated::words(note, shown);
    }
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

/// The units a title names for its axes, in the units shown, and the
/// numbers it quotes too ("ψ = 9.13°", "ω_bf = 1742 rpm"), so that no
/// title has rad/s beside rpm.
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
    // (rad/s, topspin positive)".
    let out = out.replace("(m/s", "(mph").replace("(rad/s", "(rpm");
    quoted(&out, shown)
}

/// `text` with each number quoted with an angle's or a spin's SI unit
/// ("0.1594 rad", "182.4 rad/s") in the units shown, to about its digits
/// ("9.13°", "1742 rpm"): a mark's label, a title.
pub fn quoted(text: &str, shown: UnitSystem) -> String {
    if shown == UnitSystem::Si {
        return text.to_owned();
    }
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(" rad") {
        let (before, after) = rest.split_at(at);
        let spin = after.starts_with(" rad/s");
        let unit_len = if spin { " rad/s".len() } else { " rad".len() };
        // A unit ends there: "rad" is not the start of "radius".
        let ends = after[unit_len..]
            .chars()
            .next()
            .is_none_or(|c| !c.is_alphanumeric());
        let start = before
            .rfind(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
            .map_or(0, |k| {
                k + before[k..].chars().next().map_or(1, char::len_utf8)
            });
        let number = &before[start..];
        match number.parse::<f64>() {
            Ok(si) if ends && !number.is_empty() => {
                let quantity = if spin {
                    Quantity::Spin
                } else {
                    Quantity::Angle
                };
                let unit = quantity.in_system(shown);
                let decimals = number.split_once('.').map_or(0, |(_, d)| d.len());
                let value = unit.show(si);
                let decimals = unit.decimals(decimals);
                let gap = if unit.symbol == "°" { "" } else { " " };
                out.push_str(&before[..start]);
                out.push_str(&format!("{value:.decimals$}{gap}{}", unit.symbol));
            }
            _ => {
                out.push_str(before);
                out.push_str(&after[..unit_len]);
            }
        }
        rest = &after[unit_len..];
    }
    out.push_str(rest);
    out
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
        if unit.is_identity() {
            return format!("{}{gap}{}", figures::short(si), unit.symbol);
        }
        // Four significant digits: more (-1909.859 rpm for -200 rad/s)
        // show only the conversion.
        let value = unit.show(si);
        let decimals = (3 - value.abs().max(1e-9).log10().floor() as i32).clamp(0, 6) as usize;
        let text = format!("{value:.decimals$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.')
        } else {
            &text
        };
        format!("{text}{gap}{}", unit.symbol)
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
        // The numbers it quotes too: no rad/s beside rpm (issue 36).
        assert_eq!(
            title(
                "range (m) against undercut E (m) at ψ = 0.1594 rad, with launch; A and B are the E giving ω_bf = 182.4 rad/s and 240.1 rad/s",
                imperial
            ),
            "range (ft) against undercut E (in) at ψ = 9.13°, with launch; A and B are the E giving ω_bf = 1742 rpm and 2293 rpm"
        );
        assert_eq!(quoted("A (182.4 rad/s)", imperial), "A (1742 rpm)");
        // The conditions to four significant digits, not the conversion's.
        let fastball = Scene::default();
        let line = conditions("fastball", &fastball, imperial);
        assert!(
            line.contains("pitch 93.95 mph, spin -1910 rpm; bat 67.11 mph"),
            "{line}"
        );
        assert_eq!(
            quoted("the bat's radius 0.035 m", imperial),
            "the bat's radius 0.035 m"
        );
        assert_eq!(quoted("A (182.4 rad/s)", UnitSystem::Si), "A (182.4 rad/s)");
    }
}
