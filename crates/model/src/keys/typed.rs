//! Text typed for a key: a number with or without a unit (`103mph`), read
//! by [`units::read_typed`], checked against the key's bounds, with
//! a suggestion when a bare number was likely meant in another unit; and
//! bounds printed in another unit so that each end is accepted typed back.

use super::{Bounds, InputError, Key};
use units::{self, Quantity, TypedError, Unit, UnitSystem};

impl Key {
    /// A value of this key typed as text, in SI: a bare number (SI) or one
    /// with a unit of the key's quantity (`103mph`, `28°`), checked against
    /// the bounds. The one reading of `--set`, preset strings and batch cells.
    pub fn read(&self, text: &str) -> Result<f64, InputError> {
        read_typed((self.name, self.quantity(), self.unit, self.bounds), text)
    }

    /// A value of this key typed under `system`, in SI: what you see is
    /// what you type. A bare number is in the unit the key is shown in
    /// there (`100` is 100 mph for `launch.speed` under imperial), a
    /// number with a unit is read in that unit; either is checked against
    /// the bounds, a refusal giving the range in the unit shown too. Under
    /// SI this is [`Key::read`]. The one rule of `--set` under `--units`
    /// (and of the explorer's inputs, which show the same units).
    pub fn read_in(&self, text: &str, system: UnitSystem) -> Result<f64, InputError> {
        read_in_system(
            (self.name, self.quantity(), self.unit, self.bounds),
            text,
            system,
        )
    }

    /// [`Key::read`] where a bare number means the unit `shown` (the
    /// explorer's inputs, a sweep's ends), for text that is not a bare
    /// number: a value with a unit (`103mph`), read and bounded as `--set`
    /// reads it, its refusal saying what a bare number is here.
    pub fn read_with_unit(&self, text: &str, shown: Unit) -> Result<f64, InputError> {
        let spec = (self.name, self.quantity(), self.unit, self.bounds);
        if shown.is_identity() {
            return read_typed(spec, text);
        }
        read_typed_where(spec, text, &format!("{}, as shown", shown.symbol))
    }
}

/// [`Key::read`] for any input named `name`, of `quantity` (its SI unit
/// `unit`), accepted in `bounds` (the fence's keys too).
pub fn read_typed(
    spec: (&'static str, Quantity, &'static str, Bounds),
    text: &str,
) -> Result<f64, InputError> {
    read_typed_where(spec, text, spec.2)
}

/// [`Key::read_in`] for any input named `name`, of `quantity` (its SI unit
/// `unit`), accepted in `bounds` (the fence's keys too): a bare number is
/// in `quantity`'s unit under `system`.
pub fn read_in_system(
    spec: (&'static str, Quantity, &'static str, Bounds),
    text: &str,
    system: UnitSystem,
) -> Result<f64, InputError> {
    let (_, quantity, unit, bounds) = spec;
    let shown = quantity.unit(system, unit);
    if shown.is_identity() {
        return read_typed(spec, text);
    }
    let bare = format!("{}, as shown with --units {}", shown.symbol, system.name());
    let Some(number) = bare_number(text) else {
        return read_typed_where(spec, text, &bare);
    };
    let si = shown.read(number);
    if bounds.contains(si) {
        return Ok(si);
    }
    Err(out_of_range_shown(spec, si, &typed_text(text), shown))
}

/// The refusal of `si`, given as `typed` in `shown` (the unit a bare
/// number is in): the value in both units, and the range in `shown`'s
/// too ("95 ° (1.65806 rad): … [-π/2, π/2] rad, that is [-90, 90] °").
pub fn out_of_range_shown(
    (name, _, unit, bounds): (&'static str, Quantity, &'static str, Bounds),
    si: f64,
    typed: &str,
    shown: Unit,
) -> InputError {
    InputError::OutOfRange {
        key: name,
        value: si,
        bounds,
        unit,
        typed: Some(Box::new(Typed {
            text: format!(
                "{typed} {} ({} {unit})",
                shown.symbol,
                units::significant(si)
            ),
            suggestion: format!(", that is {} {}", bounds.shown_in(shown), shown.symbol),
        })),
    }
}

/// The number `text` is, if it is a bare number (no unit after it).
fn bare_number(text: &str) -> Option<f64> {
    text.trim().parse().ok()
}

/// [`read_typed`] where a bare number is in `bare` (its refusals say so).
fn read_typed_where(
    (name, quantity, unit, bounds): (&'static str, Quantity, &'static str, Bounds),
    text: &str,
    bare: &str,
) -> Result<f64, InputError> {
    // Made only for an error: an input read well costs no allocation.
    let shown = || typed_text(text);
    let reading = units::read_typed(text, quantity, unit).map_err(|error| match error {
        // Quoted by the error itself, which escapes what must be.
        TypedError::NotANumber => InputError::NotANumber {
            key: name.to_owned(),
            text: cut(text.trim()),
        },
        TypedError::OtherQuantity {
            unit: typed,
            quantity: other,
        } => InputError::WrongUnit {
            key: name,
            text: shown(),
            why: match quantity {
                Quantity::Unchanged => format!("{} measures {}", typed_text(&typed), other.noun()),
                _ => format!(
                    "{} measures {}, not {}",
                    typed_text(&typed),
                    other.noun(),
                    quantity.noun()
                ),
            },
            accepted: accepted_units(quantity, unit, bare),
        },
        TypedError::UnknownUnit { unit: typed } => InputError::WrongUnit {
            key: name,
            text: shown(),
            why: format!("unknown unit `{}`", typed_text(&typed)),
            accepted: accepted_units(quantity, unit, bare),
        },
    })?;
    if bounds.contains(reading.si) {
        return Ok(reading.si);
    }
    let (typed, suggestion) = match reading.unit {
        // The SI value the unit gave, to six significant digits.
        Some(given) if !given.is_identity() => (
            format!("{} ({} {unit})", shown(), units::significant(reading.si)),
            String::new(),
        ),
        Some(_) => (shown(), String::new()),
        None => {
            let likely = units::suggested_units(quantity, reading.number, |si| bounds.contains(si));
            let number = text.trim();
            let guesses: Vec<String> = likely.iter().map(|u| format!("{number}{u}")).collect();
            let suggestion = if guesses.is_empty() {
                String::new()
            } else {
                format!(" (did you mean {}?)", guesses.join(" or "))
            };
            (shown(), suggestion)
        }
    };
    Err(InputError::OutOfRange {
        key: name,
        value: reading.si,
        bounds,
        unit,
        typed: Some(Box::new(Typed {
            text: typed,
            suggestion,
        })),
    })
}

/// The units an input is typed in, for an error: "m/s, km/h, mph, ft/s
/// (a bare number is m/s)" (`bare`, the unit a bare number is in there),
/// or that it takes a plain number.
fn accepted_units(quantity: Quantity, unit: &str, bare: &str) -> String {
    match units::accepted(quantity, unit).as_str() {
        "" => "a plain number".to_owned(),
        listed => format!("{listed} (a bare number is {bare})"),
    }
}

/// Text as typed, for an error: control characters escaped, cut to 80
/// characters.
fn typed_text(text: &str) -> String {
    let escaped: String = text
        .trim()
        .chars()
        .map(|c| {
            if c.is_control() {
                c.escape_debug().to_string()
            } else {
                c.to_string()
            }
        })
        .collect();
    cut(&escaped)
}

/// `text` cut to 80 characters, the last an "…" if it was longer.
fn cut(text: &str) -> String {
    if text.chars().count() <= 80 {
        text.to_owned()
    } else {
        text.chars().take(79).chain(['…']).collect()
    }
}

/// A value typed as text, as an error about it shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct Typed {
    /// As typed, with its SI value if a unit came with it ("300mph
    /// (134.112 m/s)").
    pub text: String,
    /// " (did you mean 103mph?)" for a bare number that a likely unit
    /// brings in range, else empty.
    pub suggestion: String,
}

impl Bounds {
    /// This interval in `unit` (the unit's symbol not written), each end to
    /// at most three decimals and rounded so that the number printed, typed
    /// back in `unit`, is what the bracket says: accepted at a closed end,
    /// refused at an open one. An end that is not a round number in `unit`
    /// is rounded inward, and shown closed: pitch.speed's (0, 100] m/s is
    /// "(0, 223.693]" mph, since 223.694 mph is 100.0003 m/s. In SI (an
    /// identity unit), the table's own text, with its π/2.
    pub fn shown_in(&self, unit: Unit) -> String {
        if unit.is_identity() {
            return self.to_string();
        }
        let (min, min_open) = self.shown_end(unit, self.min, self.min_exclusive, 1.0);
        let (max, max_open) = self.shown_end(unit, self.max, self.max_exclusive, -1.0);
        let open = if min_open { '(' } else { '[' };
        let close = if max_open { ')' } else { ']' };
        format!("{open}{min}, {max}{close}")
    }

    /// One end, `bound` in SI, as [`Bounds::shown_in`] writes it, and
    /// whether it is shown open; `inward` is +1 at the minimum, −1 at the
    /// maximum.
    fn shown_end(&self, unit: Unit, bound: f64, exclusive: bool, inward: f64) -> (String, bool) {
        const PER_UNIT: f64 = 1000.0;
        let shown = unit.show(bound);
        let nearest = (shown * PER_UNIT).round() / PER_UNIT;
        let round = (nearest - shown).abs() <= 1e-9 * shown.abs().max(1.0);
        if exclusive && round {
            return (decimals_text(nearest), true);
        }
        if !exclusive && self.contains(unit.read(nearest)) {
            return (decimals_text(nearest), false);
        }
        // Inward: up at the minimum, down at the maximum, a last digit more
        // if the conversion back lands just outside.
        let scaled = shown * PER_UNIT;
        let mut end = if inward > 0.0 {
            scaled.ceil()
        } else {
            scaled.floor()
        } / PER_UNIT;
        for _ in 0..3 {
            if self.contains(unit.read(end)) {
                break;
            }
            end += inward / PER_UNIT;
        }
        (decimals_text(end), false)
    }
}

/// At most three decimals, trailing zeros trimmed, never "-0".
fn decimals_text(value: f64) -> String {
    let text = format!("{value:.3}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" { "0" } else { text }.to_owned()
}
