//! Every column the pipeline reads, in one table: its names (Savant's,
//! Statcast's older and Trackman's, common aliases), the unit its cells
//! come in, and what it becomes (a launch value, a measurement, tracking, a
//! label). The program's own keys (`launch.speed`, `bat.mass`, …) are
//! columns too, in SI, as `--set` takes them. A new Savant column is one
//! entry here plus what it does where it is read.

use model::keys::TEXT_KEYS;
use model::scene::Scene;
use preset::FIELD_KEYS;
use units::{Quantity, UnitSystem};

/// How a launch column's values become SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Unit {
    Si,
    /// Statcast's `launch_speed`: mph, exactly 0.44704 m/s.
    Mph,
    Degrees,
    /// Revolutions per minute, 2π/60 rad/s.
    Rpm,
}

impl Unit {
    /// The explorer's and `--units`' conversion, so that 103 mph is the
    /// same launch to the last bit wherever it is typed.
    pub fn to_si(self, value: f64) -> f64 {
        match self.quantity() {
            None => value,
            Some(quantity) => quantity.unit(UnitSystem::Imperial, "").read(value),
        }
    }

    /// `si` in this unit: [`Unit::to_si`]'s inverse.
    pub fn from_si(self, si: f64) -> f64 {
        match self.quantity() {
            None => si,
            Some(quantity) => quantity.unit(UnitSystem::Imperial, "").show(si),
        }
    }

    pub fn quantity(self) -> Option<Quantity> {
        match self {
            Unit::Si => None,
            Unit::Mph => Some(Quantity::Speed),
            Unit::Degrees => Some(Quantity::Angle),
            Unit::Rpm => Some(Quantity::Spin),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Unit::Si => "",
            Unit::Mph => "mph",
            Unit::Degrees => "°",
            Unit::Rpm => "rpm",
        }
    }
}

/// The launch keys, in the order a [`Column::Launch`] indexes them.
pub const LAUNCH_KEYS: [&str; 3] = ["launch.speed", "launch.angle", "launch.spin"];

/// A measured or descriptive column that is no key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SavantColumn {
    /// Hit coordinates: with `hc_y`, the spray angle.
    HcX,
    HcY,
    /// Or the spray itself: where the ball came down, as a bearing (°, +
    /// toward right field).
    LandingBearing,
    /// The batter's side, R or L.
    Stand,
    /// The home team's code: the park.
    HomeTeam,
    /// Statcast's projected distance (ft).
    Distance,
    /// Measured hang time (s) and apex (ft), for `calibrate`'s lift.
    HangTime,
    Apex,
    /// The launch direction measured at the bat (°, + toward right field).
    ExitDirection,
    /// The pitch's height over the plate (ft): the contact's height.
    PlateZ,
    /// Savant's kind of ball and the play's result: counted only.
    BbType,
    Events,
    /// The season (a year), and the date: the row's park is its team's
    /// home on some days only ([`model::park::Park::home_on`]); a tracked
    /// swing's season picks its bat ([`analysis::bat_tracking::season_bat`]).
    Season,
    Date,
    /// Savant's kind of game: spring training, exhibitions and the
    /// All-Star Game are not at the home team's park.
    GameType,
    /// A tracker's measured spin of the batted ball (rpm, Trackman's
    /// `HitSpinRate`; 0 where it measured none), and its axis (°, Trackman's
    /// clock face: 180 is pure backspin, past 180 the ball curves toward
    /// right field).
    HitSpinRate,
    HitSpinAxis,
    /// The measured spin's direction as a vector, Yakkertech's
    /// `yt_HitSpinComponentX/Y/Z` by index: x toward right field, y toward
    /// centre field, z up.
    HitSpinVector(usize),
}

/// A bat-tracking or pitch-tracking column (read when swings are solved).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SwingColumn {
    BatSpeed,
    AttackAngle,
    AttackDirection,
    SwingPathTilt,
    /// vx0, vy0, vz0 (ft/s) by index.
    Velocity(usize),
    /// ax, ay, az (ft/s²) by index.
    Acceleration(usize),
    SpinRate,
    SpinAxis,
    /// The pitch's speed at release (mph): Savant's squared-up.
    ReleaseSpeed,
}

/// What a column of the table becomes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Becomes {
    Launch(usize, Unit),
    Savant(SavantColumn),
    /// With the values it accepts, in its own unit: the angles those of the
    /// keys they become (`bat.swing_angle` ±90°, `bat.direction` and
    /// `bat.tilt` ±60°), so that a row past them is named, not solved
    /// outside what the model takes.
    Swing(SwingColumn, (f64, f64)),
}

/// One entry: the names (the first is the one messages use), what it
/// becomes, and what it means (`fly --batch --help`).
pub struct Entry {
    pub names: &'static [&'static str],
    pub becomes: Becomes,
    pub meaning: &'static str,
}

const fn entry(names: &'static [&'static str], becomes: Becomes, meaning: &'static str) -> Entry {
    Entry {
        names,
        becomes,
        meaning,
    }
}

use Becomes::{Launch, Savant, Swing};
use SavantColumn as S;
use SwingColumn as W;

/// The table. Names are matched ignoring case, spaces and underscores
/// (`Launch Speed`, `LaunchSpeed`, `LAUNCH_SPEED`), never dots: a key
/// (`launch.speed`, SI) is matched exactly.
pub const TABLE: &[Entry] = &[
    entry(
        &["launch_speed", "exit_speed", "exit_velocity", "ExitSpeed"],
        Launch(0, Unit::Mph),
        "launch.speed in mph (Statcast's, Trackman's ExitSpeed)",
    ),
    entry(
        &["launch_angle", "Angle"],
        Launch(1, Unit::Degrees),
        "launch.angle in ° (Trackman's Angle)",
    ),
    entry(
        &["spin_rpm"],
        Launch(2, Unit::Rpm),
        "launch.spin (backspin) in rpm",
    ),
    entry(
        &["hc_x"],
        Savant(S::HcX),
        "Savant's hit coordinates, with hc_y: the spray angle (see --spray)",
    ),
    entry(&["hc_y"], Savant(S::HcY), "the other hit coordinate"),
    entry(
        &["landing_bearing"],
        Savant(S::LandingBearing),
        "where the ball came down, as a bearing in ° (+ toward right field, as the spray from \
         hc_x/hc_y gives it): the launch direction is solved to land there. A spray angle or \
         Trackman's Bearing is read as one only when mapped (--column landing_bearing=COLUMN): \
         their signs follow no one convention",
    ),
    entry(
        &["stand", "BatterSide"],
        Savant(S::Stand),
        "the batter's side, R or L (for the spin estimate)",
    ),
    entry(
        &["home_team"],
        Savant(S::HomeTeam),
        "the park: its fence, and the standard air at its elevation",
    ),
    entry(
        &["hit_distance_sc", "hit_distance", "Distance"],
        Savant(S::Distance),
        "Statcast's distance (ft): the output adds it and the difference",
    ),
    entry(
        &["hang_time", "HangTime"],
        Savant(S::HangTime),
        "measured hang time (s): calibrate fits the lift on it",
    ),
    entry(
        &["apex"],
        Savant(S::Apex),
        "measured apex (ft): calibrate fits the lift on it",
    ),
    entry(
        &["exit_direction", "Direction"],
        Savant(S::ExitDirection),
        "the launch direction measured at the bat (°, + toward right field)",
    ),
    entry(
        &["plate_z", "PlateLocHeight"],
        Savant(S::PlateZ),
        "the pitch's height over the plate (ft): the contact height, unless \
         environment.contact_height is given",
    ),
    entry(
        &["bb_type"],
        Savant(S::BbType),
        "Savant's kind of ball: --summary's table by kind",
    ),
    entry(
        &["events"],
        Savant(S::Events),
        "the play: --summary counts home runs by it",
    ),
    entry(
        &["bat_speed"],
        Swing(W::BatSpeed, (0.0, 150.0)),
        "bat tracking: the sweet spot's speed (mph)",
    ),
    entry(
        &["attack_angle"],
        Swing(W::AttackAngle, (-90.0, 90.0)),
        "bat tracking (2025): the swing's angle (°)",
    ),
    entry(
        &["attack_direction"],
        Swing(W::AttackDirection, (-60.0, 60.0)),
        "bat tracking (2025): the swing's direction (°, + toward the opposite field)",
    ),
    entry(
        &["swing_path_tilt"],
        Swing(W::SwingPathTilt, (-60.0, 60.0)),
        "bat tracking (2025): the swing plane's tilt (°; without it the league's 32°)",
    ),
    entry(
        &["vx0"],
        Swing(W::Velocity(0), (-100.0, 100.0)),
        "the pitch's velocity at y = 50 ft (ft/s), with vy0, vz0",
    ),
    entry(&["vy0"], Swing(W::Velocity(1), (-250.0, -20.0)), ""),
    entry(&["vz0"], Swing(W::Velocity(2), (-100.0, 100.0)), ""),
    entry(
        &["ax"],
        Swing(W::Acceleration(0), (-100.0, 100.0)),
        "the pitch's acceleration (ft/s²), with ay, az",
    ),
    entry(&["ay"], Swing(W::Acceleration(1), (-100.0, 100.0)), ""),
    entry(&["az"], Swing(W::Acceleration(2), (-100.0, 100.0)), ""),
    entry(
        &["release_spin_rate"],
        Swing(W::SpinRate, (0.0, 5000.0)),
        "the pitch's spin (rpm), with spin_axis (°): the pitch's backspin at the bat",
    ),
    entry(&["spin_axis"], Swing(W::SpinAxis, (0.0, 360.0)), ""),
    entry(
        &["release_speed"],
        Swing(W::ReleaseSpeed, (0.0, 150.0)),
        "the pitch's speed at release (mph): Savant's squared-up, beside the model's",
    ),
    entry(
        &["game_year", "season"],
        Savant(S::Season),
        "the season: whether home_team's park was home then, and a tracked swing's bat",
    ),
    entry(
        &["hit_spin_rate"],
        Savant(S::HitSpinRate),
        "the ball's measured spin in rpm (Trackman's HitSpinRate; 0 is none measured): with \
         hit_spin_axis, its backspin and sidespin; alone, the estimate's axis at this size",
    ),
    entry(
        &["hit_spin_axis"],
        Savant(S::HitSpinAxis),
        "the measured spin's axis in ° (Trackman's HitSpinAxis: 180 pure backspin, over 180 \
         curving toward right field)",
    ),
    entry(
        &["yt_HitSpinComponentX"],
        Savant(S::HitSpinVector(0)),
        "the measured spin's direction (Yakkertech's, with yt_HitSpinComponentY and Z: x toward \
         right field, y toward centre field, z up): with hit_spin_rate and the launch's \
         direction, its backspin and sidespin",
    ),
    entry(&["yt_HitSpinComponentY"], Savant(S::HitSpinVector(1)), ""),
    entry(&["yt_HitSpinComponentZ"], Savant(S::HitSpinVector(2)), ""),
    entry(
        &["game_type"],
        Savant(S::GameType),
        "Savant's kind of game: S (spring training), E (exhibition) and A (All-Star Game) \
         rows are at no park, not at home_team's",
    ),
    entry(
        &["game_date", "Date"],
        Savant(S::Date),
        "the date (YYYY-MM-DD or M/D/YYYY): whether home_team's park was home that day; \
         its year the season, without game_year",
    ),
];

/// Savant's columns whose names look like a launch value's and that are
/// something else, with what they are: never suggested for one, and
/// refused as one (`--column launch_angle=launch_speed_angle` would fly
/// every ball at 1–6°).
pub const LOOKALIKES: [(&str, &str); 9] = [
    (
        "launch_speed_angle",
        "Savant's contact class (1 weak to 6 barrel)",
    ),
    ("bat_speed", "the bat's speed (bat tracking)"),
    ("attack_angle", "the bat's path at contact (bat tracking)"),
    ("swing_length", "the bat's path length (bat tracking)"),
    ("release_speed", "the pitch's speed at release"),
    ("effective_speed", "the pitch's speed as the batter sees it"),
    ("release_spin_rate", "the pitch's spin"),
    ("spin_axis", "the pitch's spin axis"),
    ("release_extension", "the pitcher's release extension"),
];

/// What a lookalike column ([`LOOKALIKES`]) is, if `name` is one.
pub fn lookalike(name: &str) -> Option<&'static str> {
    let name = folded(name);
    (LOOKALIKES.iter())
        .find(|(n, _)| folded(n) == name)
        .map(|(_, what)| *what)
}

/// The columns a row needs for its swing to be solved.
pub const NEEDED_FOR_SWINGS: [&str; 7] = ["bat_speed", "vx0", "vy0", "vz0", "ax", "ay", "az"];

/// A name as the table matches it: lower case, no spaces or underscores.
pub fn folded(name: &str) -> String {
    name.chars()
        .filter(|c| !matches!(c, ' ' | '_' | '-'))
        .flat_map(char::to_lowercase)
        .collect()
}

/// The entry a header name is, if any (dotted names are keys, never
/// matched here).
pub fn entry_of(name: &str) -> Option<&'static Entry> {
    if name.contains('.') {
        return None;
    }
    let name = folded(name);
    TABLE
        .iter()
        .find(|e| e.names.iter().any(|n| folded(n) == name))
}

/// The table's entry for launch value `index` (its names and unit).
pub fn launch_entry(index: usize) -> Option<(&'static Entry, Unit)> {
    TABLE.iter().find_map(|e| match e.becomes {
        Becomes::Launch(i, unit) if i == index => Some((e, unit)),
        _ => None,
    })
}

/// The first name of the entry that becomes `becomes`.
pub fn name_of(becomes: Becomes) -> &'static str {
    TABLE
        .iter()
        .find(|e| e.becomes == becomes)
        .map_or("", |e| e.names[0])
}

/// What one input column is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Column {
    /// A launch value (index into [`LAUNCH_KEYS`]), in `Unit`.
    Launch(usize, Unit),
    /// Any other input key, as `--set` takes it.
    Input(&'static str),
    /// A `[field]` key (index into [`FIELD_KEYS`]).
    Field(usize),
    Savant(SavantColumn),
    /// Bat or pitch tracking, read when swings are solved.
    Swing(SwingColumn, (f64, f64)),
    /// Not an input: ignored (Statcast's other 80-odd columns).
    Ignored,
}

/// What the column `name` is: a key as written, else an entry of the table.
pub fn column_of(name: &str) -> Column {
    if let Some(index) = LAUNCH_KEYS.iter().position(|k| *k == name) {
        return Column::Launch(index, Unit::Si);
    }
    if let Some(index) = FIELD_KEYS.iter().position(|f| f.name == name) {
        return Column::Field(index);
    }
    if let Some(key) = TEXT_KEYS.iter().find(|k| **k == name) {
        return Column::Input(key);
    }
    if let Ok(key) = Scene::key(name) {
        return Column::Input(key.name);
    }
    match entry_of(name).map(|e| e.becomes) {
        Some(Launch(index, unit)) => Column::Launch(index, unit),
        Some(Savant(column)) => Column::Savant(column),
        Some(Swing(column, range)) => Column::Swing(column, range),
        None => Column::Ignored,
    }
}

/// How alike two folded names are, 0 to 1: Jaro–Winkler's, or where one
/// holds the other (`exitangle` and `angle`, which Jaro's window misses)
/// 0.7 and more as it holds more of it.
fn similarity(a: &str, b: &str) -> f64 {
    let (short, long) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    let held = match short.len() >= 4 && long.contains(short) {
        true => 0.7 + 0.3 * short.len() as f64 / long.len() as f64,
        false => 0.0,
    };
    strsim::jaro_winkler(a, b).max(held)
}

/// The header's names nearest `wanted` (any of an entry's names), best
/// first: for "did you mean".
pub fn nearest<'a>(wanted: &[&str], names: &'a [String]) -> Vec<&'a str> {
    let mut scored: Vec<(f64, &str)> = names
        .iter()
        .map(|name| {
            let score = wanted
                .iter()
                .map(|w| similarity(&folded(w), &folded(name)))
                .fold(0.0, f64::max);
            (score, name.as_str())
        })
        .filter(|(score, _)| *score >= 0.7)
        .collect();
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    scored.into_iter().take(3).map(|(_, n)| n).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_match_in_any_case_without_spaces_or_underscores_but_keys_only_as_written() {
        for name in [
            "launch_speed",
            "Launch Speed",
            "LaunchSpeed",
            "EXIT_SPEED",
            "ExitSpeed",
        ] {
            assert_eq!(column_of(name), Column::Launch(0, Unit::Mph), "{name}");
        }
        assert_eq!(column_of("launch.speed"), Column::Launch(0, Unit::Si));
        assert_eq!(column_of("Launch.Speed"), Column::Ignored);
        assert_eq!(column_of("hit_distance"), Column::Savant(S::Distance));
        assert!(matches!(
            column_of("bat_speed"),
            Column::Swing(W::BatSpeed, _)
        ));
        assert_eq!(column_of("player_name"), Column::Ignored);
    }

    #[test]
    fn the_nearest_names_are_offered() {
        let names = [
            "EV".to_owned(),
            "exit_velo".to_owned(),
            "pitcher".to_owned(),
        ];
        let near = nearest(&["launch_speed", "exit_velocity"], &names);
        assert_eq!(near[0], "exit_velo");
        assert!(!near.contains(&"pitcher"), "{near:?}");
    }
}
