//! A preset's values as its reader takes them ([`PresetValue`]): TOML's,
//! from a file, or the bundled presets' own, compiled in ([`PRESETS`]:
//! build.rs reads `presets/*.toml` with the same TOML crate), so that a run
//! reads no TOML for them. A test holds each compiled-in preset equal to a
//! parse of its file, which stays the one source.

/// A value of a preset's tables.
pub(super) trait PresetValue {
    fn as_str(&self) -> Option<&str>;
    /// A table's entries, in order (`None` for a lone value).
    fn entries(&self) -> Option<impl Iterator<Item = (&str, &Self)>>;
    /// A number (a float, or an integer as a float) or a text; `None` for
    /// anything else (a table, a date, a list, a boolean).
    fn scalar(&self) -> Option<Scalar<'_>>;
    /// As TOML writes it, for a message naming it.
    fn shown(&self) -> String;
}

/// A preset's number or text.
pub(super) enum Scalar<'a> {
    Number(f64),
    Text(&'a str),
}

impl PresetValue for toml::Value {
    fn as_str(&self) -> Option<&str> {
        toml::Value::as_str(self)
    }

    fn entries(&self) -> Option<impl Iterator<Item = (&str, &Self)>> {
        let table = self.as_table()?;
        Some(table.iter().map(|(name, value)| (name.as_str(), value)))
    }

    fn scalar(&self) -> Option<Scalar<'_>> {
        match self {
            toml::Value::Float(f) => Some(Scalar::Number(*f)),
            toml::Value::Integer(i) => Some(Scalar::Number(*i as f64)),
            toml::Value::String(text) => Some(Scalar::Text(text)),
            _ => None,
        }
    }

    fn shown(&self) -> String {
        self.to_string()
    }
}

/// A bundled preset's value, as build.rs compiles it in: what the bundled
/// files hold (numbers, texts, and tables of them).
pub(super) enum Value {
    Number(f64),
    Text(&'static str),
    Table(&'static [(&'static str, Value)]),
}

impl PresetValue for Value {
    fn as_str(&self) -> Option<&str> {
        match self {
            Value::Text(text) => Some(text),
            _ => None,
        }
    }

    fn entries(&self) -> Option<impl Iterator<Item = (&str, &Self)>> {
        match self {
            Value::Table(entries) => Some(entries.iter().map(|(name, value)| (*name, value))),
            _ => None,
        }
    }

    fn scalar(&self) -> Option<Scalar<'_>> {
        match self {
            Value::Number(number) => Some(Scalar::Number(*number)),
            Value::Text(text) => Some(Scalar::Text(text)),
            Value::Table(_) => None,
        }
    }

    fn shown(&self) -> String {
        match self {
            Value::Number(number) => number.to_string(),
            Value::Text(text) => format!("{text:?}"),
            Value::Table(_) => "a table".to_owned(),
        }
    }
}

/// Each bundled preset (name, its top-level entries in the file's order).
pub(super) static PRESETS: &[(&str, &[(&str, Value)])] =
    include!(concat!(env!("OUT_DIR"), "/bundled_presets.rs"));
