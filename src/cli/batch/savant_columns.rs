//! A Baseball Savant export read as it comes: the columns beyond the launch
//! that `fly --batch` reads (the hit coordinates, the batter's side, the
//! park, Statcast's distance), what every row shares (the parks, the
//! command line's choices), and the one summary line said at the end.

use crate::Scene;
use crate::analysis::bat_tracking;
use crate::analysis::savant::{DirectionFrom, Spray, spray_angle};
use crate::cli::UsageError;
use crate::cli::shown::Shown;
use crate::model::keys::Key;
use crate::model::park::{self, GivenWeather};
use crate::model::spin_estimate::Side;
use crate::preset::parks::Parks;
use crate::preset::{Preset, cut, escape_cut};

use super::kinds::{Called, Kind};
use super::plural;
use super::rows::{Header, Job, measure};
use super::swing_columns::SwingTally;
use crate::units::Quantity;

/// Exactly 0.3048 m to the foot (Statcast's distances are in feet).
const METRES_PER_FOOT: f64 = 0.3048;

/// A Savant column that is no key: read for what it says of the row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SavantColumn {
    /// Hit coordinates: with `hc_y`, the spray angle.
    HcX,
    HcY,
    /// The batter's side, R or L.
    Stand,
    /// The home team's code: the park.
    HomeTeam,
    /// Statcast's projected distance (ft).
    Distance,
    /// Measured hang time (s) and apex (ft), for `calibrate`'s lift.
    HangTime,
    Apex,
    /// The launch direction measured at the bat (°, positive toward right
    /// field, as Trackman's "Direction"): Statcast's older and Trackman's
    /// files have it where Savant's exports have the hit coordinates.
    ExitDirection,
    /// The pitch's height as it crosses the front of the plate (ft): where
    /// the bat met it, so the height the flight starts from.
    PlateZ,
    /// Savant's kind of ball and the play's result: only counted, for the
    /// summary's table by kind.
    BbType,
    Events,
}

impl SavantColumn {
    /// Each column's names, lower case (a header's are matched in either
    /// case); the first is the one named in messages.
    pub(super) const ALL: [(&'static str, SavantColumn); 12] = [
        ("hc_x", SavantColumn::HcX),
        ("hc_y", SavantColumn::HcY),
        ("stand", SavantColumn::Stand),
        ("home_team", SavantColumn::HomeTeam),
        ("hit_distance_sc", SavantColumn::Distance),
        // Statcast's older and Trackman's files (the 2018 set).
        ("hit_distance", SavantColumn::Distance),
        ("hang_time", SavantColumn::HangTime),
        ("apex", SavantColumn::Apex),
        ("exit_direction", SavantColumn::ExitDirection),
        ("plate_z", SavantColumn::PlateZ),
        ("bb_type", SavantColumn::BbType),
        ("events", SavantColumn::Events),
    ];

    pub(super) fn of(name: &str) -> Option<SavantColumn> {
        Self::ALL.iter().find(|(n, _)| *n == name).map(|(_, c)| *c)
    }

    pub(super) fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(_, c)| *c == self)
            .map_or("", |(n, _)| n)
    }
}

/// What every row of a batch shares.
pub(in crate::cli) struct Setup<'a> {
    pub base: &'a Preset,
    /// Every park: a row's `home_team` is looked up here, and every flight
    /// is judged at each of their fences.
    pub parks: &'a Parks,
    /// The parks' fences, in `parks`' order.
    pub fences: Vec<&'a park::Fence>,
    /// `--park`: the index of the park every row is taken to, whatever its
    /// `home_team`.
    pub park: Option<usize>,
    /// The air keys `--set` gave: a park does not replace them.
    pub given: GivenWeather,
    /// Whether `--set` gave `launch.spin`, `launch.sidespin`: then no row's
    /// is estimated.
    pub spin_given: bool,
    pub sidespin_given: bool,
    /// Whether `--set` gave `environment.contact_height`: then no row's
    /// `plate_z` replaces it.
    pub contact_height_given: bool,
    /// Whether `--set` gave `bat.tilt`: then a tracked row without
    /// `swing_path_tilt` is solved at it, not at the league's.
    pub tilt_given: bool,
    pub spray: Spray,
    /// `--own-air`: each park counted in its own air (a flight per park).
    pub own_air: bool,
    /// `--all-parks`: each park's outcome and margin on every row.
    pub all_parks: bool,
    /// `--summary`: the closing summary on stdout, after the rows (else stderr).
    pub summary_to_stdout: bool,
    /// `--keep`'s column names.
    pub keep: Vec<String>,
    /// Solve each row's swing from bat tracking and fly the impact's
    /// launch where it is solved (`hit --batch`, `fly --batch --spin swing`).
    pub solve_swings: bool,
    /// Print the swing's columns (`hit --batch`).
    pub swing_columns: bool,
    /// Whether the kept cells go to a terminal: their control characters
    /// are then escaped (a file or pipe gets them as read).
    pub escape_kept: bool,
    /// Each park's code as a CSV field (quoted if it must be), for every
    /// row's `park` column.
    pub(super) code_fields: Vec<String>,
}

impl<'a> Setup<'a> {
    /// The setup a command line gives: its `--set` list's air and spin keys,
    /// and `--park`'s park.
    pub fn for_command(
        base: &'a Preset,
        parks: &'a Parks,
        set: &[String],
        park: Option<&str>,
    ) -> Result<Setup<'a>, UsageError> {
        let mut setup = Setup::new(base, parks);
        setup.given = super::super::ground::given_weather(set);
        let keys: Vec<&str> = set
            .iter()
            .filter_map(|a| a.split_once('=').map(|(k, _)| k.trim()))
            .collect();
        setup.spin_given = keys.contains(&"launch.spin");
        setup.sidespin_given = keys.contains(&"launch.sidespin");
        setup.contact_height_given = keys.contains(&CONTACT_HEIGHT);
        setup.tilt_given = keys.contains(&"bat.tilt");
        if let Some(code) = park {
            let named = super::super::parks::lookup(code, parks)?;
            let found = parks
                .parks
                .iter()
                .position(|p| std::ptr::eq(p, named))
                .expect("a park of the list");
            setup.park = Some(found);
        }
        Ok(setup)
    }

    /// The bat's tilt a tracked row without `swing_path_tilt` is solved
    /// at: MLB's league average ([`bat_tracking::LEAGUE_SWING_PATH_TILT`]),
    /// unless `--set bat.tilt` or a `bat.tilt` column gives one (`None`:
    /// the row's scene's).
    pub(super) fn tilt_prior(&self, header: &Header) -> Option<f64> {
        (!self.tilt_given && !header.tilt_given).then_some(bat_tracking::LEAGUE_SWING_PATH_TILT)
    }

    pub fn new(base: &'a Preset, parks: &'a Parks) -> Setup<'a> {
        Setup {
            base,
            parks,
            fences: parks.parks.iter().map(|p| &p.fence).collect(),
            park: None,
            given: GivenWeather::default(),
            spin_given: false,
            sidespin_given: false,
            contact_height_given: false,
            tilt_given: false,
            spray: Spray::Landing,
            own_air: false,
            all_parks: false,
            summary_to_stdout: false,
            keep: Vec::new(),
            solve_swings: false,
            swing_columns: false,
            escape_kept: false,
            code_fields: parks.parks.iter().map(|p| quoted(&p.code)).collect(),
        }
    }

    /// The index of the first park that answers to `code` (any case), as
    /// [`park::Park::answers_to`] says.
    pub(super) fn park_of(&self, code: &str) -> Option<usize> {
        self.parks.parks.iter().position(|p| p.answers_to(code))
    }
}

/// The key `plate_z` gives.
pub(super) const CONTACT_HEIGHT: &str = "environment.contact_height";

/// `environment.contact_height`, looked up once.
fn contact_height_key() -> &'static Key {
    static KEY: std::sync::OnceLock<&'static Key> = std::sync::OnceLock::new();
    KEY.get_or_init(|| Scene::key(CONTACT_HEIGHT).expect("the contact height's key"))
}

/// Where a row's flight starts from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) enum ContactFrom {
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
pub(super) struct SavantCells {
    pub hc_x: Option<f64>,
    pub hc_y: Option<f64>,
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
}

impl SavantCells {
    /// Reads one (trimmed, non-empty, not "null") cell.
    pub(super) fn read(
        &mut self,
        column: SavantColumn,
        value: &str,
        setup: &Setup,
    ) -> Result<(), String> {
        let number = || {
            (value.parse::<f64>().ok())
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("{} = {:?}: not a number", column.name(), cut(value, 80)))
        };
        // Measurements, only compared: one that cannot be read is missing.
        let feet = || measure(value, Quantity::Distance, |ft| ft * METRES_PER_FOOT);
        match column {
            SavantColumn::HcX => self.hc_x = Some(number()?),
            SavantColumn::HcY => self.hc_y = Some(number()?),
            SavantColumn::Distance => self.distance = feet(),
            SavantColumn::HangTime => self.hang_time = measure(value, Quantity::Unchanged, |s| s),
            SavantColumn::Apex => self.apex = feet(),
            SavantColumn::ExitDirection => self.direction = Some(number()?.to_radians()),
            // The contact's height, only where it can be one (read_cells);
            // one that cannot be read leaves the preset's, as a missing one.
            SavantColumn::PlateZ => self.plate_height = Some(feet()),
            SavantColumn::BbType => self.called.kind = Kind::of(value),
            SavantColumn::Events => self.called.home_run = value.eq_ignore_ascii_case("home_run"),
            SavantColumn::Stand => {
                self.side = Some(match value {
                    "R" | "r" => Side::Right,
                    "L" | "l" => Side::Left,
                    _ => {
                        return Err(format!(
                            "stand = {:?}: expected R or L (the batter's side)",
                            cut(value, 80)
                        ));
                    }
                });
            }
            SavantColumn::HomeTeam => {
                let park = setup.park_of(value);
                self.park = Some(park.ok_or_else(|| {
                    format!(
                        "home_team = {:?}: no park has that code (`homerun parks` lists them)",
                        escape_cut(value, 20)
                    )
                })?);
            }
        }
        Ok(())
    }

    /// Starts the row's flight where the bat met the pitch: at the pitch's
    /// height over the plate (`plate_z`), unless the contact height is
    /// `given` (by `--set` or a column) for every row.
    pub(super) fn start_at_pitch(&self, scene: &mut Scene, given: bool) -> ContactFrom {
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

    /// The spray angle (rad), if the row has both hit coordinates and they
    /// are not the plate's own (which gives no direction).
    pub(super) fn spray(&self) -> Option<f64> {
        Some(spray_angle(self.hc_x?, self.hc_y?)).filter(|angle| !angle.is_nan())
    }

    /// Whether the hit coordinates are exactly the plate's.
    pub(super) fn at_plate(&self) -> bool {
        self.hc_x
            .zip(self.hc_y)
            .is_some_and(|(x, y)| spray_angle(x, y).is_nan())
    }
}

/// A field for CSV output, quoted as RFC 4180 asks when it holds a comma, a
/// quote or a line break (and when it starts or ends with a space, which
/// some readers would trim).
pub(super) fn quoted(field: &str) -> String {
    let special = field.contains([',', '"', '\n', '\r']);
    if special || field.starts_with(' ') || field.ends_with(' ') {
        format!("\"{}\"", field.replace('"', "\"\""))
    } else {
        field.to_owned()
    }
}

/// What the batch used and skipped, said in one line at the end.
#[derive(Clone, Debug, Default)]
pub(super) struct Summary {
    /// Rows flown with an estimated spin.
    pub estimated: usize,
    /// Rows flown whose direction came from a spray angle.
    pub sprayed: usize,
    /// Rows flown without hit coordinates (though the header has them).
    pub without_spray: usize,
    /// Rows whose hit coordinates are the plate's: no spray.
    pub at_plate: usize,
    /// Flights spent solving launch directions.
    pub solve_flights: usize,
    /// Rows whose spray no launch direction lands on, flown toward it.
    pub unsolved: usize,
    /// Rows flown at each park (by index), and at the generic fence.
    pub at_park: Vec<usize>,
    pub at_generic: usize,
    /// Rows skipped for having no launch speed.
    pub without_speed: usize,
    /// Rows flown from the pitch's height, and those whose `plate_z` was
    /// no height (flown from the preset's).
    pub from_plate: usize,
    pub plate_unusable: usize,
    /// The rows' swings, when they are solved.
    pub swings: SwingTally,
}

impl Summary {
    pub(super) fn new(parks: usize) -> Summary {
        Summary {
            at_park: vec![0; parks],
            ..Summary::default()
        }
    }

    /// Adds another piece's counts.
    pub(super) fn add(&mut self, other: &Summary) {
        self.estimated += other.estimated;
        self.sprayed += other.sprayed;
        self.without_spray += other.without_spray;
        self.at_plate += other.at_plate;
        self.solve_flights += other.solve_flights;
        self.unsolved += other.unsolved;
        for (mine, theirs) in self.at_park.iter_mut().zip(&other.at_park) {
            *mine += theirs;
        }
        self.at_generic += other.at_generic;
        self.without_speed += other.without_speed;
        self.from_plate += other.from_plate;
        self.plate_unusable += other.plate_unusable;
        self.swings.add(&other.swings);
    }

    /// Counts a row flown, whose direction took `flights` to solve and
    /// came `from` there.
    pub(super) fn count(
        &mut self,
        job: &Job,
        header: &Header,
        (flights, from): (usize, DirectionFrom),
    ) {
        self.estimated += usize::from(job.launch.estimates_spin());
        // A solved swing's direction is the impact's (aimed at the spray).
        if job.swing_solved() {
        } else if job.launch.spray.is_some() {
            self.sprayed += 1;
            self.solve_flights += flights;
            self.unsolved += usize::from(from == DirectionFrom::SprayUnsolved);
        } else if job.spray_at_plate {
            self.at_plate += 1;
        } else if header.hit_coordinates {
            self.without_spray += 1;
        }
        self.from_plate += usize::from(job.contact == ContactFrom::Pitch);
        self.plate_unusable += usize::from(job.contact == ContactFrom::PitchUnusable);
        match job.park {
            Some(index) => self.at_park[index] += 1,
            None => self.at_generic += 1,
        }
        self.swings.count(job);
    }

    /// "read launch_speed, …; spin estimated (Nathan's relation) on 239 of
    /// 239 rows; …": the line's text, if there is anything to say.
    pub(super) fn line(
        &self,
        used: &[&str],
        flown: usize,
        setup: &Setup,
        shown: Shown,
    ) -> Option<String> {
        let mut parts = Vec::new();
        parts.extend(self.swings.line(shown));
        if !used.is_empty() {
            parts.push(format!("read {}", used.join(", ")));
        }
        if self.estimated > 0 {
            parts.push(format!(
                "spin estimated (Nathan's relation) on {} of {flown} rows",
                self.estimated
            ));
        }
        if self.sprayed > 0 {
            parts.push(match setup.spray {
                Spray::Landing => format!(
                    "spray taken as the landing bearing on {} rows (launch direction solved, {:.1} flights a row)",
                    self.sprayed,
                    self.solve_flights as f64 / self.sprayed as f64
                ),
                Spray::Launch => {
                    format!("spray taken as the launch direction on {} rows", self.sprayed)
                }
            });
        }
        if self.unsolved > 0 {
            parts.push(format!(
                "{} row{} whose spray no flight lands on (a grounder or popup fielded where it \
                 never came down) flown toward the spray (direction_from = spray_unsolved)",
                self.unsolved,
                plural(self.unsolved)
            ));
        }
        if self.without_spray > 0 {
            parts.push(format!(
                "{} rows without hit coordinates flown toward the preset's direction",
                self.without_spray
            ));
        }
        if self.at_plate > 0 {
            parts.push(format!(
                "{} row{} with a spray at the plate (hit coordinates 125.42, 198.27: no \
                 direction) flown toward the preset's direction",
                self.at_plate,
                plural(self.at_plate)
            ));
        }
        if self.from_plate > 0 {
            parts.push(format!(
                "flown from the pitch's height at the plate (plate_z) on {} rows",
                self.from_plate
            ));
        }
        if self.plate_unusable > 0 {
            parts.push(format!(
                "{} row{} whose plate_z is no contact height (below the ground, past 10 m, \
                 or not a number) flown from the preset's",
                self.plate_unusable,
                plural(self.plate_unusable)
            ));
        }
        let parks = self.at_park.iter().filter(|&&n| n > 0).count();
        if parks > 0 {
            let how = if setup.park.is_some() {
                "--park"
            } else {
                "home_team"
            };
            let air = if setup.given.any() {
                "the air given"
            } else {
                "each in the standard air at its elevation"
            };
            parts.push(format!("{parks} park{} from {how}, {air}", plural(parks)));
        }
        if self.at_generic > 0 && parks > 0 {
            parts.push(format!("{} rows at the generic fence", self.at_generic));
        }
        if self.without_speed > 0 {
            parts.push(format!(
                "skipped {} row{} without a launch speed (not batted balls)",
                self.without_speed,
                plural(self.without_speed)
            ));
        }
        (!parts.is_empty()).then(|| parts.join("; "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kept_fields_are_quoted_as_rfc_4180_asks() {
        assert_eq!(quoted("Target Field"), "Target Field");
        assert_eq!(quoted("homers, to left"), "\"homers, to left\"");
        assert_eq!(quoted("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(quoted("two\nlines"), "\"two\nlines\"");
        assert_eq!(quoted("trailing "), "\"trailing \"");
        assert_eq!(quoted(""), "");
    }
}
