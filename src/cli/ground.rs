//! Where `fly` judges a flight: a park (`--park CODE`: its fence and, unless
//! the user gave the air, the standard air at its elevation) or the
//! preset's generic fence; the outcome there, in words and in JSON; how
//! many of the parks the same flight clears; and `--all-parks`' table.

use serde_json::{Value, json};

use super::shown::Shown;
use super::table::{Align, Cell, Column, Digits, Table, Width};
use crate::Scene;
use crate::analysis::landing;
use crate::analysis::precision::Purpose;
use crate::model::clearing::{Clearing, Outcome};
use crate::model::flight::FlightSummary;
use crate::model::launch::{self, BattedBall};
use crate::model::many::judged_in_own_air;
use crate::model::park::{self, GivenWeather, Park};
use crate::preset::parks::Parks;
use crate::preset::{FIELD_KEYS, Preset, escape_cut, escape_for_terminal};
use crate::units::Quantity;

/// The fence a flight is judged at.
#[derive(Clone, Copy, Debug)]
pub(super) enum Ground<'a> {
    /// The preset's `[field]` fence, the same in every direction (121.9 m
    /// and 3.0 m unless the preset or a `--set` says otherwise).
    Generic(&'a park::Fence),
    Park(&'a Park),
}

impl<'a> Ground<'a> {
    pub fn fence(&self) -> &'a park::Fence {
        match self {
            Ground::Generic(fence) => fence,
            Ground::Park(park) => &park.fence,
        }
    }

    /// The park's code, or "generic".
    pub fn code(&self) -> &'a str {
        match self {
            Ground::Generic(_) => "generic",
            Ground::Park(park) => &park.code,
        }
    }

    /// "at BOS (Fenway Park)" or "at the generic fence".
    fn at(&self) -> String {
        match self {
            Ground::Generic(_) => "at the generic fence".to_owned(),
            Ground::Park(park) => format!(
                "at {} ({})",
                escape_for_terminal(&park.code),
                escape_cut(&park.name, 40)
            ),
        }
    }
}

/// The preset's fence as a park's: `[field]`'s, or the default one.
pub(super) fn generic_fence(preset: &Preset) -> park::Fence {
    preset
        .fence
        .unwrap_or(crate::preset::Fence {
            distance: FIELD_KEYS[0].default,
            height: FIELD_KEYS[1].default,
        })
        .uniform()
}

/// Takes `scene` to `park`: the standard air at its elevation, the weather
/// `given` kept.
pub(super) fn to_park(scene: &mut Scene, park: &Park, given: GivenWeather) {
    given.park_air(&mut scene.environment, park.elevation);
}

/// One scene's flight, at readout precision, judged at its own fence and at
/// every park's.
pub(super) struct FlownToFence {
    pub launch: BattedBall,
    pub flight: FlightSummary,
    /// At the fence the flight was taken to.
    pub clearing: Clearing,
    /// At each park of the list, in its order (the same flight).
    pub parks: Vec<Clearing>,
}

impl FlownToFence {
    /// Flies `scene` once and judges it at `fence` and at each of `parks`;
    /// with `own_air`, each park instead gets a flight of its own in its
    /// own air (the standard air at its elevation, the weather given kept).
    pub fn new(
        scene: &Scene,
        fence: &park::Fence,
        parks: &[&park::Fence],
        own_air: Option<(&Parks, GivenWeather)>,
    ) -> FlownToFence {
        let options = Purpose::Readout.flight_options();
        let (flight, launch, _) = launch::scene_start(scene);
        let mut fences = Vec::with_capacity(parks.len() + 1);
        fences.push(fence);
        if own_air.is_none() {
            fences.extend_from_slice(parks);
        }
        let (summary, mut clearings) = flight.judge(&options, &fences);
        let clearing = clearings.remove(0);
        if let Some((list, given)) = own_air {
            clearings = judged_in_own_air(scene, &list.parks, given, &options);
        }
        FlownToFence {
            launch,
            flight: summary,
            clearing,
            parks: clearings,
        }
    }

    pub fn clears_fence(&self) -> bool {
        self.clearing.clears()
    }

    pub fn parks_cleared(&self) -> usize {
        self.parks.iter().filter(|c| c.clears()).count()
    }

    /// The codes of the parks it clears, in the list's order.
    pub fn codes_cleared<'p>(&self, parks: &'p Parks) -> Vec<&'p str> {
        parks
            .parks
            .iter()
            .zip(&self.parks)
            .filter(|(_, c)| c.clears())
            .map(|(p, _)| p.code.as_str())
            .collect()
    }
}

/// A clearing as JSON: `{park, outcome, margin, direction, distance,
/// height, height_at_fence}` (SI; `distance` and `height` are the wall's
/// where it was judged).
pub(super) fn clearing_json(code: &str, c: &Clearing) -> Value {
    json!({
        "park": code,
        "outcome": c.outcome.name(),
        "margin": c.margin,
        "direction": c.direction,
        "distance": c.wall.map(|w| w.distance),
        "height": c.wall.map(|w| w.height),
        "height_at_fence": c.height_at_fence,
    })
}

/// `{cleared, of, codes}`: how many parks the flight clears, and which.
pub(super) fn parks_json(flown: &FlownToFence, parks: &Parks) -> Value {
    json!({
        "cleared": flown.parks_cleared(),
        "of": parks.parks.len(),
        "codes": flown.codes_cleared(parks),
    })
}

/// "clears at BOS (Fenway Park) by 2.78 m: 14.08 m up at 94.5 m, over 11.3 m",
/// "off the wall at …, 1.20 m under its top: …", "short at … by 12.30 m: …",
/// "foul at …: lands 0.8500 rad (48.7° toward right field) from centre".
pub(super) fn clearing_text(ground: &Ground, c: &Clearing, shown: Shown) -> String {
    let unit = shown.unit(Quantity::Distance);
    // The generic fence in the explorer's words, "121.9 m, 3.0 m high: over
    // by 9.2 m" (400 ft, not 399.9 ft), so that both read the same.
    if let (Ground::Generic(_), Some(wall)) = (ground, c.wall)
        && c.outcome != Outcome::Foul
    {
        return landing::fence_text(wall.distance, wall.height, c.height_at_fence, unit);
    }
    let d = |m: f64, decimals| shown.value(Quantity::Distance, m, decimals);
    // A wall's distance and height as published (400 ft, not 399.9 ft).
    let given = |m: f64| format!("{} {}", landing::as_given(m, 1, unit), unit.symbol);
    let at = ground.at();
    let crossing = |height: f64, word: &str| {
        let wall = c.wall.expect("judged in fair territory");
        format!(
            "{} up at {}, {word} {}",
            d(height, 2),
            given(wall.distance),
            given(wall.height)
        )
    };
    match (c.outcome, c.margin, c.height_at_fence) {
        (Outcome::Clears, Some(m), Some(h)) => {
            format!("clears {at} by {}: {}", d(m, 2), crossing(h, "over"))
        }
        (Outcome::OffTheWall, Some(m), Some(h)) => format!(
            "off the wall {at}, {} under its top: {}",
            d(-m, 2),
            crossing(h, "under")
        ),
        (Outcome::Short, Some(m), _) => {
            let wall = c.wall.expect("short is fair");
            format!(
                "short {at} by {}: lands {} from the plate, the wall {} away there",
                d(-m, 2),
                d(wall.distance + m, 1),
                given(wall.distance)
            )
        }
        (Outcome::Short, None, _) => format!("short {at}: it does not land"),
        (Outcome::Foul, ..) => format!(
            "foul {at}: {} from centre field, outside the foul lines",
            shown.direction(c.direction)
        ),
        (outcome, ..) => format!("{outcome} {at}"),
    }
}

/// "clears 22 of 30 parks (each in its own air)", "… (on this one flight,
/// in its air)": every count says whose air it is in.
pub(super) fn parks_text(flown: &FlownToFence, parks: &Parks, own_air: bool) -> String {
    format!(
        "clears {} of {} parks{}",
        flown.parks_cleared(),
        parks.parks.len(),
        if own_air {
            " (each in its own air)"
        } else {
            " (on this one flight, in its air)"
        }
    )
}

/// `--all-parks`: one line per park, the outcome and margin there.
pub(super) fn all_parks_table(flown: &FlownToFence, parks: &Parks, shown: Shown) -> String {
    let distance = |key: &str, head: &str| {
        Column::right(
            key,
            &shown.head(head, Quantity::Distance, "m"),
            9,
            Digits::Fixed(2),
        )
    };
    let columns = vec![
        Column::text("code", Width::Fit, Align::Left, ""),
        Column::text("name", Width::Fit, Align::Left, "  "),
        Column::text("outcome", Width::Fit, Align::Left, "  "),
        distance("margin", "margin").after("  "),
        distance("distance", "wall at"),
        distance("height", "wall"),
        distance("height_at_fence", "ball"),
    ];
    let number = |m: Option<f64>| {
        m.map_or(Cell::Blank, |m| {
            Cell::Num(shown.convert(Quantity::Distance, m))
        })
    };
    let rows = parks
        .parks
        .iter()
        .zip(&flown.parks)
        .map(|(p, c)| {
            vec![
                Cell::Text(escape_for_terminal(&p.code)),
                Cell::Text(escape_cut(&p.name, 30)),
                Cell::Text(c.outcome.name().to_owned()),
                number(c.margin),
                number(c.wall.map(|w| w.distance)),
                number(c.wall.map(|w| w.height)),
                number(c.height_at_fence),
            ]
        })
        .collect();
    Table { columns, rows }.text()
}

/// `--all-parks` in JSON: one [`clearing_json`] per park.
pub(super) fn all_parks_json(flown: &FlownToFence, parks: &Parks) -> Value {
    Value::Array(
        parks
            .parks
            .iter()
            .zip(&flown.parks)
            .map(|(p, c)| clearing_json(&p.code, c))
            .collect(),
    )
}
