//! A row's Savant cells (and Trackman's), read: the hit coordinates, the
//! batter's side, the park and the day it was played, the measurements
//! compared, the pitch's height, a tracker's measured spin; and where the
//! row is judged.

use analysis::savant::spray_angle;
use model::frame;
use model::keys::Key;
use model::park::{AtHome, Day, Played, neutral_site};
use model::scene::Scene;
use model::spin_estimate::Side;
use nalgebra::Vector3;
use preset::{cut, escape_cut};
use units::Quantity;

use crate::Setup;
use crate::away::{Away, AwayWhy, GameType};
use crate::columns::{SavantColumn, Unit};
use crate::kinds::{Called, Kind};

/// Exactly 0.3048 m to the foot (Statcast's distances are in feet).
const METRES_PER_FOOT: f64 = 0.3048;

/// A measured spin's largest rate (rpm): its backspin and sidespin stay
/// inside `launch.spin`'s and `launch.sidespin`'s ±1,000 rad/s.
const MAX_SPIN_RPM: f64 = 9000.0;

/// A measured cell of `quantity`: a bare number in the column's own unit
/// (`bare` makes it SI), or a number with a unit as `--set` takes it
/// (`103mph`, `460ft`, `140m`); `None` if it is neither, or not finite.
pub(crate) fn measure(text: &str, quantity: Quantity, bare: impl Fn(f64) -> f64) -> Option<f64> {
    let reading = units::read_typed(text, quantity, quantity.si_symbol()).ok()?;
    let si = match reading.unit {
        Some(_) => reading.si,
        None => bare(reading.number),
    };
    si.is_finite().then_some(si)
}

/// Where a row is judged: its park's index and the park's earlier walls it
/// met (none: the fence as given), and why it is at no park or counted.
type Judged = ((Option<usize>, Option<usize>), Option<Away>);

/// Statcast's first season: a row without a date at a park that was home,
/// with its walls as given, from then on is surely judged where and as it
/// was played.
const STATCAST: i32 = 2015;

/// The key `plate_z` gives.
pub(crate) const CONTACT_HEIGHT: &str = "environment.contact_height";

/// `environment.contact_height`, looked up once.
fn contact_height_key() -> &'static Key {
    static KEY: std::sync::OnceLock<&'static Key> = std::sync::OnceLock::new();
    KEY.get_or_init(|| Scene::key(CONTACT_HEIGHT).expect("the contact height's key"))
}

/// Where a row's flight starts from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) enum ContactFrom {
    /// The preset's (or `--set`'s, or a column's) contact height.
    #[default]
    Given,
    /// The pitch's height at the plate, `plate_z`.
    Pitch,
    /// A `plate_z` that is no height (below the ground, or not a number):
    /// the given contact height instead.
    PitchUnusable,
}

/// What a row's Savant cells say.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct SavantCells {
    pub hc_x: Option<f64>,
    pub hc_y: Option<f64>,
    /// The landing bearing (rad), where a column gives it.
    pub bearing: Option<f64>,
    pub side: Option<Side>,
    /// The index of the row's park in the list.
    pub park: Option<usize>,
    /// Statcast's distance (m).
    pub distance: Option<f64>,
    /// Hang time (s) and apex (m).
    pub hang_time: Option<f64>,
    pub apex: Option<f64>,
    /// The launch direction (rad).
    pub direction: Option<f64>,
    /// The pitch's height at the plate (m), as read; `None` where the
    /// cell cannot be read (an empty cell is never read).
    pub plate_height: Option<Option<f64>>,
    /// What Savant called the ball.
    pub called: Called,
    /// `game_year` (or `season`), and `game_date`.
    pub season: Option<i32>,
    pub day: Option<Day>,
    /// A `game_type` not played at the home team's park.
    pub game_type: Option<GameType>,
    /// A tracker's measured spin (rad/s; 0 where it measured none) and its
    /// axis's turn (rad) from pure backspin (180° on Trackman's clock face):
    /// + curves the ball toward right field.
    pub spin_rate: Option<f64>,
    pub spin_axis: Option<f64>,
    /// Or its direction as a vector (Yakkertech's frame).
    pub spin_vector: [Option<f64>; 3],
}

impl SavantCells {
    /// Reads one (trimmed, non-empty, not "null") cell.
    pub(crate) fn read(
        &mut self,
        column: SavantColumn,
        value: &str,
        setup: &Setup,
    ) -> Result<(), String> {
        let number = || {
            (value.parse::<f64>().ok())
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "{} = {:?}: not a number",
                        crate::columns::name_of(crate::columns::Becomes::Savant(column)),
                        cut(value, 80)
                    )
                })
        };
        // A measurement inside (low, high), said as `expected`.
        let within = |read: f64, (low, high, expected): (f64, f64, &str)| match (low..=high)
            .contains(&read)
        {
            true => Ok(read),
            false => Err(format!(
                "{} = {:?}: expected {expected}",
                crate::columns::name_of(crate::columns::Becomes::Savant(column)),
                cut(value, 80)
            )),
        };
        // Measurements, only compared: one that cannot be read is missing.
        let feet = || measure(value, Quantity::Distance, |ft| ft * METRES_PER_FOOT);
        match column {
            SavantColumn::HcX => self.hc_x = Some(number()?),
            SavantColumn::HcY => self.hc_y = Some(number()?),
            SavantColumn::LandingBearing => {
                let range = (-180.0, 180.0, "-180 to 180° (+ toward right field)");
                self.bearing = Some(within(number()?, range)?.to_radians());
            }
            // A distance past 10 km is no batted ball's (1e308 would print
            // 309 digits): missing, as one that cannot be read.
            SavantColumn::Distance => self.distance = feet().filter(|m| m.abs() <= 1e4),
            SavantColumn::HangTime => self.hang_time = measure(value, Quantity::Unchanged, |s| s),
            SavantColumn::Apex => self.apex = feet(),
            SavantColumn::ExitDirection => self.direction = Some(number()?.to_radians()),
            // The contact's height, only where it can be one (read_cells);
            // one that cannot be read leaves the preset's, as a missing one.
            SavantColumn::PlateZ => self.plate_height = Some(feet()),
            SavantColumn::BbType => self.called.kind = Kind::of(value),
            SavantColumn::Events => self.called.home_run = value.eq_ignore_ascii_case("home_run"),
            SavantColumn::Stand => {
                // Savant's R and L, Trackman's Right and Left.
                self.side = Some(match value.to_ascii_lowercase().as_str() {
                    "r" | "right" => Side::Right,
                    "l" | "left" => Side::Left,
                    // Trackman's and Yakkertech's words for a side not
                    // recorded: the estimate averages the two sides
                    // (`Side::sign`), and the summary counts the rows.
                    "undefined" | "unknown" | "switch" | "s" | "b" | "both" => return Ok(()),
                    _ => {
                        return Err(format!(
                            "stand = {:?}: expected R or L (the batter's side)",
                            cut(value, 80)
                        ));
                    }
                });
            }
            // A code no park answers to leaves the row at no park, named in
            // the summary ([`Job::unknown_park`]).
            SavantColumn::HomeTeam => self.park = setup.park_of(value),
            SavantColumn::GameType => self.game_type = GameType::of(value)?,
            SavantColumn::HitSpinRate => {
                // rpm, or with its unit as `--set` takes one (`262rad/s`).
                let rate = match measure(value, Quantity::Spin, |rpm| Unit::Rpm.to_si(rpm)) {
                    Some(rate) => rate,
                    None => Unit::Rpm.to_si(number().map_err(|e| {
                        let name = "hit_spin_rate";
                        unit_unknown(name, value, (Quantity::Spin, Unit::Rpm)).unwrap_or(e)
                    })?),
                };
                let most = Unit::Rpm.to_si(MAX_SPIN_RPM);
                let expected = format!("0 (none measured) to {MAX_SPIN_RPM} rpm");
                self.spin_rate = Some(within(rate, (0.0, most, &expected))?);
            }
            SavantColumn::HitSpinVector(index) => self.spin_vector[index] = Some(number()?),
            SavantColumn::HitSpinAxis => {
                let degrees = within(number()?, (0.0, 360.0, "0 to 360°"))?;
                // As its turn from pure backspin, so that 180° is exactly
                // backspin alone.
                self.spin_axis = Some((degrees - 180.0).to_radians());
            }
            SavantColumn::Season => {
                let year = crate::dates::season(number()?).ok_or_else(|| {
                    format!(
                        "game_year = {:?}: expected a whole year from 1800 to 2200",
                        cut(value, 80)
                    )
                })?;
                self.season = Some(year);
            }
            SavantColumn::Date => {
                self.day = Some(crate::dates::day(value).ok_or_else(|| {
                    format!(
                        "game_date = {:?}: expected a date, YYYY-MM-DD or M/D/YYYY",
                        cut(value, 80)
                    )
                })?);
            }
        }
        Ok(())
    }

    /// The row's season: `game_year` (or `season`), else its date's year.
    pub(crate) fn season(&self) -> Option<i32> {
        self.season.or(self.day.map(Day::year))
    }

    /// Where a row at `park` (its `home_team`'s) is judged: there (at the
    /// earlier walls it met, where they were not the fence as given),
    /// unless the park was not its team's home when the row was played,
    /// or its walls then are not known (then at no park, and why); a row
    /// without a date at a park that was not always home, or not always so
    /// walled, is judged there, and counted.
    pub(crate) fn at_home(&self, park: usize, setup: &Setup) -> Judged {
        let played = match (self.day, self.season) {
            (Some(day), _) => Played::On(day),
            (None, Some(year)) => Played::In(year),
            (None, None) => Played::Unknown,
        };
        let away = |why| Away {
            park,
            season: self.season(),
            why,
            air_elevation: None,
        };
        if let Some(game_type) = self.game_type {
            return ((None, None), Some(away(AwayWhy::NotAtHome(game_type))));
        }
        let at = &setup.parks.parks[park];
        let neutral = self.day.and_then(|day| neutral_site(day, at));
        if let Some(site) = neutral {
            let at_site = Away {
                air_elevation: Some(site.elevation),
                ..away(AwayWhy::Neutral(&site.venue))
            };
            return ((None, None), Some(at_site));
        }
        // Played there, but at other walls: in the park's air, no fence.
        let walled = |why| Away {
            air_elevation: Some(at.elevation),
            ..away(why)
        };
        let none = (None, None);
        match (at.home_on(played), at.walls_on(played)) {
            (AtHome::No, _) => (none, Some(away(AwayWhy::NotHome))),
            (AtHome::Unsure, _) => (none, Some(away(AwayWhy::Unsure))),
            (AtHome::Undated, _) | (_, AtHome::Undated) if at.as_given_since(STATCAST) => {
                ((Some(park), None), None)
            }
            (AtHome::Undated, _) | (_, AtHome::Undated) => {
                ((Some(park), None), Some(away(AwayWhy::Undated)))
            }
            (AtHome::Yes, AtHome::Yes) => ((Some(park), None), None),
            (AtHome::Yes, _) if let Some(earlier) = at.earlier_on(played) => {
                ((Some(park), Some(earlier)), None)
            }
            (AtHome::Yes, AtHome::No) => (none, Some(walled(AwayWhy::WallsNotThen))),
            (AtHome::Yes, AtHome::Unsure) => (none, Some(walled(AwayWhy::WallsUnsure))),
        }
    }

    /// Starts the row's flight where the bat met the pitch: at the pitch's
    /// height over the plate (`plate_z`), unless the contact height is
    /// `given` (by `--set` or a column) for every row.
    pub(crate) fn start_at_pitch(&self, scene: &mut Scene, given: bool) -> ContactFrom {
        let Some(read) = self.plate_height.filter(|_| !given) else {
            return ContactFrom::Given;
        };
        let key = contact_height_key();
        match read.filter(|&height| key.bounds.contains(height)) {
            Some(height) => {
                (key.set)(scene, height);
                ContactFrom::Pitch
            }
            None => ContactFrom::PitchUnusable,
        }
    }

    /// The spray angle (rad): the landing bearing given, or the hit
    /// coordinates' where the row has both and they are not the plate's
    /// own (which gives no direction).
    pub(crate) fn spray(&self) -> Option<f64> {
        self.bearing
            .or_else(|| Some(spray_angle(self.hc_x?, self.hc_y?)).filter(|angle| !angle.is_nan()))
    }

    /// A measured spin of `rate` (rad/s) as backspin and sidespin, where
    /// its axis is measured: on Trackman's clock face (180° pure backspin,
    /// past 180° curving toward right field: −cos and −sin of the axis), or
    /// as Yakkertech's vector, split about the launch (`angle`, and the
    /// row's own `direction`: without one, the vector cannot be split); its
    /// gyrospin, which the flight does not take (`model::frame::spin_parts`),
    /// is dropped. `None` where no axis is measured.
    pub(crate) fn measured_spin(
        &self,
        rate: f64,
        (angle, direction): (Option<f64>, Option<f64>),
    ) -> Option<(f64, f64)> {
        if let Some(turn) = self.spin_axis {
            let (sin, cos) = turn.sin_cos();
            return Some((cos * rate, sin * rate));
        }
        let spin = self.spin_direction()? * rate;
        let (backspin, sidespin, _gyrospin) = frame::spin_parts(spin, angle?, direction?);
        Some((backspin, sidespin))
    }

    /// The measured spin's direction as a unit vector in the flight's frame
    /// (x toward centre field, y up, z toward right field), from
    /// Yakkertech's (x toward right field, y toward centre field, z up: the
    /// same turn of hand), if all three parts are given and not all 0.
    pub(crate) fn spin_direction(&self) -> Option<Vector3<f64>> {
        let [Some(x), Some(y), Some(z)] = self.spin_vector else {
            return None;
        };
        Vector3::new(y, z, x).try_normalize(0.0)
    }

    /// Whether the hit coordinates are exactly the plate's.
    pub(crate) fn at_plate(&self) -> bool {
        self.hc_x
            .zip(self.hc_y)
            .is_some_and(|(x, y)| spray_angle(x, y).is_nan())
    }
}

/// Why a Statcast cell with a unit after its number (`45kph`, `28deg` in
/// `launch_speed`) cannot be read: the unit named, and those accepted.
pub(crate) fn unit_unknown(
    name: &str,
    value: &str,
    (quantity, unit): (Quantity, Unit),
) -> Option<String> {
    let why = match units::read_typed(value, quantity, quantity.si_symbol()) {
        Err(units::TypedError::UnknownUnit { unit }) => {
            format!("unknown unit `{}`", cut(&unit, 20))
        }
        Err(units::TypedError::OtherQuantity {
            unit,
            quantity: other,
        }) => {
            format!(
                "`{}` measures {}, not {}",
                cut(&unit, 20),
                other.noun(),
                quantity.noun()
            )
        }
        _ => return None,
    };
    Some(format!(
        "{} = {:?}: {why}; it takes {} (a bare number is {})",
        escape_cut(name, 80),
        cut(value, 80),
        units::accepted(quantity, quantity.si_symbol()),
        unit.name()
    ))
}
