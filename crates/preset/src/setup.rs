//! A preset's `[explorer]` table: the explorer's set-up around the scene
//! (the park chosen, whether the scene flies in that park's air, the units
//! shown), so that a preset saved from the explorer opens as it was left.
//! The physics does not read it: the air the scene flies in is written in
//! `[environment]` as any preset's is, so `fly --preset` flies the same
//! ball the explorer showed, and a file without the table loads as before.

use super::{PresetError, escape_cut, escape_for_terminal};
use units::UnitSystem;

/// The TOML table the set-up is written in.
pub const EXPLORER_SECTION: &str = "explorer";

/// The longest park code kept (a code is a few letters; a longer text is
/// a mistake, refused rather than carried around).
const MAX_PARK_CODE: usize = 40;

/// What the explorer showed around a preset's scene when it was saved.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ExplorerSetup {
    /// The park chosen (`m`/`M`), by its code; `None`: the preset's fence.
    pub park: Option<String>,
    /// Whether the scene flew in the park's own air (key `a`). The air
    /// itself is the preset's `[environment]`.
    pub park_air: bool,
    /// The units every quantity was shown in (key `u`).
    pub units: UnitSystem,
}

impl ExplorerSetup {
    /// Reads the `[explorer]` table; `origin` names the file in errors.
    pub fn parse(value: &toml::Value, origin: &str) -> Result<ExplorerSetup, PresetError> {
        let wrong = |key: &str, value: &toml::Value, expected| PresetError::WrongType {
            path: origin.to_owned(),
            key: format!("{EXPLORER_SECTION}.{}", escape_for_terminal(key)),
            value: escape_cut(&value.to_string(), 80),
            expected,
        };
        let table = value.as_table().ok_or_else(|| {
            wrong(
                "",
                value,
                "a section: its keys (park, park_air, units) under an [explorer] line",
            )
        })?;
        let mut setup = ExplorerSetup::default();
        for (key, value) in table {
            match key.as_str() {
                "park" => {
                    let code = value
                        .as_str()
                        .filter(|c| !c.is_empty() && c.len() <= MAX_PARK_CODE)
                        .ok_or_else(|| wrong(key, value, "expected a park's code in quotes"))?;
                    setup.park = Some(code.to_owned());
                }
                "park_air" => {
                    setup.park_air = value
                        .as_bool()
                        .ok_or_else(|| wrong(key, value, "expected true or false"))?;
                }
                "units" => {
                    setup.units = value
                        .as_str()
                        .and_then(|u| u.parse().ok())
                        .ok_or_else(|| wrong(key, value, "expected \"si\" or \"imperial\""))?;
                }
                _ => {
                    return Err(wrong(
                        key,
                        value,
                        "not a key of [explorer]: its keys are park, park_air and units",
                    ));
                }
            }
        }
        // The park's air without a park says nothing: a park is needed.
        if setup.park_air && setup.park.is_none() {
            return Err(wrong(
                "park_air",
                &toml::Value::Boolean(true),
                "the park's air needs a park: give explorer.park too",
            ));
        }
        Ok(setup)
    }

    /// The table's text, each key with what it is for.
    pub fn to_toml(&self) -> String {
        let mut out = format!(
            "\n[{EXPLORER_SECTION}]  # the explorer's set-up, restored when it loads this preset; the physics ignores it\n"
        );
        if let Some(park) = &self.park {
            out += &format!(
                "park = {}  # the park chosen (m/M); its fence is drawn\n",
                toml::Value::from(park.as_str())
            );
            out += &format!(
                "park_air = {}  # whether [environment] above is the park's own air (a)\n",
                self.park_air
            );
        }
        out += &format!(
            "units = \"{}\"  # the units shown and typed (u): si, imperial\n",
            self.units
        );
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parsed(text: &str) -> Result<ExplorerSetup, PresetError> {
        let table: toml::Table = text.parse().unwrap();
        ExplorerSetup::parse(&table[EXPLORER_SECTION], "x.toml")
    }

    #[test]
    fn a_setup_reads_back_as_written() {
        let setup = ExplorerSetup {
            park: Some("COL".into()),
            park_air: true,
            units: UnitSystem::Imperial,
        };
        assert_eq!(parsed(&setup.to_toml()).unwrap(), setup);
        let plain = ExplorerSetup::default();
        assert_eq!(parsed(&plain.to_toml()).unwrap(), plain);
    }

    #[test]
    fn a_wrong_key_or_value_is_named() {
        let e = parsed("[explorer]\nunits = \"furlongs\"").unwrap_err();
        assert!(e.to_string().contains("explorer.units"), "{e}");
        assert!(e.to_string().contains("\"si\" or \"imperial\""), "{e}");
        let e = parsed("[explorer]\npark = 3").unwrap_err();
        assert!(e.to_string().contains("explorer.park = 3"), "{e}");
        let e = parsed("[explorer]\npark_air = true").unwrap_err();
        assert!(e.to_string().contains("needs a park"), "{e}");
        let e = parsed("[explorer]\nzoom = 2").unwrap_err();
        assert!(e.to_string().contains("explorer.zoom"), "{e}");
    }
}
