//! What a batch's rows came to, in one tally: what each row used (its
//! spin, spray, park, contact height), its outcome at its park, the
//! model's range less Statcast's distance (in all, by launch-angle band,
//! by kind of ball), and its swing. Each piece keeps one; the batch adds
//! them in order. Medians in bounded memory ([`Quantiles`]), so a stream of
//! any length holds a tally of fixed size (docs/batch.md).

use std::collections::BTreeMap;

use analysis::calibrate::{BAND_EDGES, band_of};
use analysis::savant::DirectionFrom;
use model::clearing::Outcome as Verdict;
use numerics::quantile::Quantiles;

use crate::away::AwayRows;
use crate::cells::ContactFrom;
use crate::columns::{Column, SavantColumn};
use crate::flights::RowFlight;
use crate::header::Header;
use crate::kinds::KINDS;
use crate::pieces::Outcome;
use crate::row::{Job, SpinMeasured};
use crate::setup::Setup;

/// The summary's bands of launch angle: below 10°, then `calibrate`'s
/// bands of balls in the air (a tilt by launch angle shows there, not in
/// one median).
pub(crate) const BANDS: usize = BAND_EDGES.len() + 1;

/// The band of a launch angle (rad): 0 below the first edge.
pub(crate) fn band_index(angle: f64) -> usize {
    band_of(angle).map_or(0, |b| b + 1)
}

/// Band `band`'s launch angles (°): from (none for the lowest) up to.
pub(crate) fn band_bounds(band: usize) -> (Option<f64>, Option<f64>) {
    (
        band.checked_sub(1).map(|k| BAND_EDGES[k]),
        BAND_EDGES.get(band).copied(),
    )
}

/// The launch angle (rad) from which a ball's distance is a flight's, as
/// `calibrate` takes it: below, a grounder's distance is where it was
/// fielded (10°, where Statcast's own bands put the line drive).
pub const LOWEST_FLIGHT: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// One band's solved swings.
#[derive(Clone, Debug, Default)]
pub(crate) struct SwingBand {
    pub tracked: usize,
    /// Undercut (m), squared-up, contact speed / bat_speed, whole spin.
    pub undercut: Quantiles,
    pub squared_up: Quantiles,
    pub contact_speed: Quantiles,
    pub spin: Quantiles,
}

/// The rows' swings, when they are solved.
#[derive(Clone, Debug, Default)]
pub(crate) struct Swings {
    /// Rows without a tracked swing, by reason; tracked ones not solved.
    pub untracked: BTreeMap<&'static str, usize>,
    pub unsolved: BTreeMap<String, usize>,
    /// q from the data on every tracked row; the model's at E = 0 on each
    /// solved one.
    pub data_efficiency: Quantiles,
    pub model_efficiency: Quantiles,
    pub off_sweet_spot: usize,
    pub bands: [SwingBand; BANDS],
    /// Tracked rows by the bat they were solved with: its season, or
    /// `None` for the preset's (with its M_B, kg, as bits).
    pub bats: BTreeMap<(Option<i32>, u64), usize>,
}

/// The batch's one tally.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// Rows flown with an estimated spin ([`Job::spin_estimated`]).
    pub(crate) estimated: usize,
    /// Rows flown with a tracker's measured spin: whole, its size alone
    /// (about the estimate's axis); and rows whose rate was 0 (none
    /// measured), estimated.
    pub(crate) spin_measured: [usize; 3],
    /// Rows whose direction came from a spray angle; the flights spent
    /// solving them; those whose spray no flight lands on.
    pub(crate) sprayed: usize,
    pub(crate) solve_flights: usize,
    pub(crate) unsolved: usize,
    /// Rows without hit coordinates (though the header has them), and
    /// with the plate's own.
    pub(crate) without_spray: usize,
    pub(crate) at_plate: usize,
    /// Rows at each park (by index), and at no park.
    pub(crate) at_park: Vec<usize>,
    pub(crate) at_no_park: usize,
    /// Of those, the rows whose home_team no park answers to, and the
    /// first few such codes with their rows.
    pub(crate) at_unknown_park: usize,
    pub(crate) unknown_parks: Vec<(String, usize)>,
    /// Rows whose spin was estimated without the batter's side (no
    /// `stand`, or a side not recorded).
    pub(crate) side_unknown: usize,
    /// Balls in the air (20° and up, flown past 60 m) with a measured
    /// distance, and those whose measured distance is under half the
    /// flight's: most of them so is a column in metres read as feet.
    pub(crate) compared_in_air: usize,
    pub(crate) under_half: usize,
    /// The steepest launch flown (rad, either way): under 1.6° on a whole
    /// file is a column in radians read as degrees.
    pub(crate) steepest: f64,
    /// Rows judged at a park's earlier walls: by park and walls (index).
    pub(crate) at_earlier_walls: BTreeMap<(usize, usize), usize>,
    /// Rows played where their home_team's park was not home.
    pub(crate) away: AwayRows,
    /// Rows flown from the pitch's height, and those whose `plate_z` was
    /// no height.
    pub(crate) from_plate: usize,
    pub(crate) plate_unusable: usize,
    /// Clears, off the wall, short, foul: at the rows' parks.
    pub(crate) outcomes: [usize; 4],
    /// Model − Statcast (m): every row with both, by band, by kind
    /// (launched at 10° or more; the four kinds, then the home runs).
    pub(crate) differences: Quantiles,
    pub(crate) by_band: [Quantiles; BANDS],
    pub(crate) by_kind: [Quantiles; KINDS + 1],
    /// Home runs (by `events`), those that clear where they are judged,
    /// and the lines of the first that the model calls short or foul.
    pub(crate) home_runs: usize,
    /// Of those, the home runs with a fence to be judged at.
    pub(crate) home_runs_judged: usize,
    pub(crate) home_runs_clear: usize,
    pub(crate) home_runs_not: Vec<usize>,
    pub(crate) home_runs_not_count: usize,
    pub(crate) swings: Swings,
    /// Closing counts, and the header's Savant columns.
    pub(crate) answered: usize,
    pub(crate) failed: usize,
    pub(crate) without_speed: usize,
    pub(crate) empty: usize,
    pub(crate) used: Vec<String>,
    /// The file's name for Statcast's distance (`hit_distance_sc`,
    /// Trackman's `Distance`, …), which the summary compares against.
    pub(crate) distance_column: String,
    pub(crate) hit_coordinates: bool,
}

/// The home runs short or foul named by line, at most.
const NAMED_HOME_RUNS: usize = 20;

/// The home_team codes no park answers to, named in the summary at most.
const NAMED_UNKNOWN_PARKS: usize = 6;

impl Tally {
    pub(crate) fn new(setup: &Setup, header: Option<&Header>) -> Tally {
        // Each piece keeps one: the header's names wait for the close.
        Tally {
            at_park: vec![0; setup.parks.parks.len()],
            hit_coordinates: header.is_some_and(|h| h.hit_coordinates),
            ..Tally::default()
        }
    }

    /// Counts a row flown.
    pub(crate) fn count(&mut self, job: &Job, flown: &RowFlight) {
        self.estimated += usize::from(job.spin_estimated());
        match job.spin_measured {
            SpinMeasured::No => {}
            SpinMeasured::Whole => self.spin_measured[0] += 1,
            SpinMeasured::Size => self.spin_measured[1] += 1,
            SpinMeasured::Zero => self.spin_measured[2] += 1,
        }
        // A solved swing's direction is the impact's (aimed at the spray).
        if job.swing_solved() {
        } else if job.launch.spray.is_some() {
            self.sprayed += 1;
            self.solve_flights += flown.flights;
            self.unsolved += usize::from(flown.direction_from == DirectionFrom::SprayUnsolved);
        } else if job.spray_at_plate {
            self.at_plate += 1;
        } else if self.hit_coordinates {
            self.without_spray += 1;
        }
        self.from_plate += usize::from(job.contact == ContactFrom::Pitch);
        self.plate_unusable += usize::from(job.contact == ContactFrom::PitchUnusable);
        match job.park {
            Some(index) => self.at_park[index] += 1,
            None => self.at_no_park += 1,
        }
        if let Some(walls) = job.park.zip(job.earlier) {
            *self.at_earlier_walls.entry(walls).or_default() += 1;
        }
        self.side_unknown += usize::from(job.side_unknown);
        if let Some(away) = &job.away {
            self.away.count(away);
        }
        if let Some(code) = &job.unknown_park {
            self.at_unknown_park += 1;
            self.name_unknown_park(code, 1);
        }
        let at = match flown.clearing.outcome {
            Verdict::Clears => 0,
            Verdict::OffTheWall => 1,
            Verdict::Short => 2,
            Verdict::Foul => 3,
        };
        // A foul ball is called with no fence to judge at.
        if job.fence_known() || at == 3 {
            self.outcomes[at] += 1;
        }
        let angle = flown.launch.angle;
        self.steepest = self.steepest.max(angle.abs());
        let difference = flown.difference(job);
        let called = job.called;
        if called.home_run {
            self.home_runs += 1;
            self.home_runs_judged += usize::from(job.fence_known());
            self.home_runs_clear += usize::from(at == 0);
            if at >= 2 && job.fence_known() {
                self.home_runs_not_count += 1;
                if self.home_runs_not.len() < NAMED_HOME_RUNS {
                    self.home_runs_not.push(job.line);
                }
            }
        }
        if let Some(d) = difference {
            let range = flown.flight.range;
            if angle >= 20f64.to_radians() && range > 60.0 {
                self.compared_in_air += 1;
                self.under_half += usize::from(range - d < 0.5 * range);
            }
            self.differences.push(d);
            self.by_band[band_index(angle)].push(d);
            if angle >= LOWEST_FLIGHT {
                if let Some(kind) = called.kind {
                    self.by_kind[kind.index()].push(d);
                }
                if called.home_run {
                    self.by_kind[KINDS].push(d);
                }
            }
        }
        self.count_swing(job);
    }

    fn count_swing(&mut self, job: &Job) {
        let Some(swing) = &job.swing else { return };
        let swings = &mut self.swings;
        let tracked = match &swing.tracked {
            Err(why) => {
                *swings.untracked.entry(why).or_default() += 1;
                return;
            }
            Ok(tracked) => tracked,
        };
        let bat = (swing.bat.map(|b| b.season), swing.effective_mass.to_bits());
        *swings.bats.entry(bat).or_default() += 1;
        let answer = swing.answer.expect("a tracked swing is answered");
        swings.data_efficiency.push(answer.collision_efficiency);
        let band = &mut swings.bands[band_index(tracked.launch_angle)];
        band.tracked += 1;
        let Some(solved) = swing.solved() else {
            let reason = swing.reason().unwrap_or_default();
            *swings.unsolved.entry(reason).or_default() += 1;
            return;
        };
        if let Some(q) = swing.model_efficiency() {
            swings.model_efficiency.push(q);
        }
        swings.off_sweet_spot += usize::from(solved.off_sweet_spot);
        let launch = solved.launch;
        band.undercut.push(solved.scene.bat.undercut);
        band.squared_up.push(solved.squared_up());
        band.contact_speed
            .push(solved.scene.bat.speed / tracked.bat_speed);
        // The whole spin, back, side and gyro, as a tracker measures it.
        let spin = launch.spin.powi(2) + launch.sidespin.powi(2) + launch.gyrospin.powi(2);
        band.spin.push(spin.sqrt());
    }

    /// Names `rows` at `code`, a home_team no park answers to, among the
    /// first few such codes.
    fn name_unknown_park(&mut self, code: &str, rows: usize) {
        let known = self.unknown_parks.iter().position(|(c, _)| c == code);
        match known {
            Some(k) => self.unknown_parks[k].1 += rows,
            None if self.unknown_parks.len() < NAMED_UNKNOWN_PARKS => {
                self.unknown_parks.push((code.to_owned(), rows));
            }
            None => {}
        }
    }

    /// Adds another piece's tally.
    pub(crate) fn add(&mut self, other: &Tally) {
        self.steepest = self.steepest.max(other.steepest);
        self.at_unknown_park += other.at_unknown_park;
        self.away.add(&other.away);
        for (code, rows) in &other.unknown_parks {
            self.name_unknown_park(code, *rows);
        }
        let sums = [
            (&mut self.estimated, other.estimated),
            (&mut self.sprayed, other.sprayed),
            (&mut self.solve_flights, other.solve_flights),
            (&mut self.unsolved, other.unsolved),
            (&mut self.without_spray, other.without_spray),
            (&mut self.at_plate, other.at_plate),
            (&mut self.at_no_park, other.at_no_park),
            (&mut self.side_unknown, other.side_unknown),
            (&mut self.compared_in_air, other.compared_in_air),
            (&mut self.under_half, other.under_half),
            (&mut self.from_plate, other.from_plate),
            (&mut self.plate_unusable, other.plate_unusable),
            (&mut self.home_runs, other.home_runs),
            (&mut self.home_runs_judged, other.home_runs_judged),
            (&mut self.home_runs_clear, other.home_runs_clear),
            (&mut self.home_runs_not_count, other.home_runs_not_count),
            (&mut self.swings.off_sweet_spot, other.swings.off_sweet_spot),
        ];
        for (mine, theirs) in sums {
            *mine += theirs;
        }
        for (mine, theirs) in self.spin_measured.iter_mut().zip(other.spin_measured) {
            *mine += theirs;
        }
        for (mine, theirs) in self.at_park.iter_mut().zip(&other.at_park) {
            *mine += theirs;
        }
        for (&walls, rows) in &other.at_earlier_walls {
            *self.at_earlier_walls.entry(walls).or_default() += rows;
        }
        for (mine, theirs) in self.outcomes.iter_mut().zip(other.outcomes) {
            *mine += theirs;
        }
        let room = NAMED_HOME_RUNS.saturating_sub(self.home_runs_not.len());
        (self.home_runs_not).extend(other.home_runs_not.iter().take(room));
        self.differences.merge(&other.differences);
        for (mine, theirs) in (self.by_band.iter_mut().chain(&mut self.by_kind))
            .zip(other.by_band.iter().chain(&other.by_kind))
        {
            mine.merge(theirs);
        }
        let (mine, theirs) = (&mut self.swings, &other.swings);
        for (why, n) in &theirs.untracked {
            *mine.untracked.entry(why).or_default() += n;
        }
        for (bat, n) in &theirs.bats {
            *mine.bats.entry(*bat).or_default() += n;
        }
        for (why, n) in &theirs.unsolved {
            *mine.unsolved.entry(why.clone()).or_default() += n;
        }
        mine.data_efficiency.merge(&theirs.data_efficiency);
        mine.model_efficiency.merge(&theirs.model_efficiency);
        for (band, other) in mine.bands.iter_mut().zip(&theirs.bands) {
            band.tracked += other.tracked;
            band.undercut.merge(&other.undercut);
            band.squared_up.merge(&other.squared_up);
            band.contact_speed.merge(&other.contact_speed);
            band.spin.merge(&other.spin);
        }
    }

    /// Takes the batch's closing counts, and the Savant columns it read.
    pub(crate) fn close(&mut self, outcome: &Outcome, header: &Header) {
        self.answered = outcome.answered;
        self.failed = outcome.failed;
        self.without_speed = outcome.without_launch;
        self.empty = outcome.empty;
        self.used = header
            .savant_used()
            .into_iter()
            .map(str::to_owned)
            .collect();
        self.distance_column = header
            .name_of(&Column::Savant(SavantColumn::Distance))
            .unwrap_or("hit_distance_sc")
            .to_owned();
    }
}
