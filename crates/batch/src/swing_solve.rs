//! A row's tracked swing solved ([`solve_row`]): the paper's impact found
//! that gives the row's measured launch, and the row's flight given the
//! impact's launch. The rows' swing cells are read in [`crate::swing`].

use crate::row::Job;
use crate::setup::Priors;
use crate::swing::{REFUSED_CELL, RowSwing};
use analysis::bat_tracking::{self, TrackedSwing, savant_squared_up};
use analysis::precision::Purpose;
use analysis::savant::{DirectionFrom, RowLaunch, Spray};
use units::{Quantity, UnitSystem};

impl Job {
    /// Where the row's launch direction came from: a solved swing's, its
    /// impact's ([`bat_tracking::solve_landing`]); else `launched`, how the
    /// row's launch was completed.
    pub(crate) fn direction_from(&self, launched: DirectionFrom) -> DirectionFrom {
        (self.swing.as_ref())
            .and_then(|s| s.direction_from)
            .unwrap_or(launched)
    }

    /// The row's tracked swing, with its measured launch, spray and side;
    /// or why it has none.
    pub(crate) fn tracked_swing(&self) -> Result<TrackedSwing, &'static str> {
        // A tracking cell outside its range (named as read): no swing.
        if self.swing_note.is_some() {
            return Err(REFUSED_CELL);
        }
        let launch = self.scene.launch;
        let measured = (
            launch.speed.unwrap_or(f64::NAN),
            launch.angle.unwrap_or(f64::NAN),
        );
        (self.tracked).swing(measured, self.launch.spray, self.launch.side)
    }

    /// Whether the row flies its solved swing's launch.
    pub(crate) fn swing_solved(&self) -> bool {
        (self.swing.as_ref()).is_some_and(|s| s.solved().is_some())
    }
}

/// Solves the row's swing (when it has a tracked one) and, solved, gives
/// its flight the impact's launch: the measured speed and angle, the
/// impact's direction, backspin and sidespin (nothing estimated). With
/// `spray` the landing (the default), the impact is solved toward the
/// direction whose flight lands on the spray
/// ([`bat_tracking::solve_landing`]); taken as the launch direction, toward
/// the spray itself. A row not solved keeps what `fly --batch` makes of it.
/// `priors` ([`Setup::priors`]): the bat's tilt where a tracked row
/// measured none, and whether the row's season picks its bat.
pub(crate) fn solve_row(job: &mut Job, spray: Spray, priors: Priors) {
    let tracked = job.tracked_swing();
    if let (Ok(swing), Some(prior)) = (&tracked, priors.tilt)
        && swing.tilt.is_none()
    {
        job.scene.bat.tilt = prior;
    }
    let season = job.season;
    let bat = (priors.season_bats && tracked.is_ok())
        .then(|| bat_tracking::season_bat(season))
        .flatten();
    if bat.is_some() {
        job.scene = bat_tracking::season_scene(&job.scene, season);
    }
    let effective_mass = job.scene.bat.effective_mass;
    let savant_squared_up = tracked.ok().and_then(|swing| {
        let mph = Quantity::Speed.unit(UnitSystem::Imperial, "");
        let release = mph.read(job.tracked.release_speed?);
        Some(savant_squared_up(
            swing.launch_speed,
            swing.bat_speed,
            release,
        ))
    });
    let options = Purpose::Solve.flight_options();
    let solved = tracked.ok().map(|swing| match spray {
        Spray::Landing => bat_tracking::solve_landing(&job.scene, &swing, &options),
        Spray::Launch => {
            let given = match swing.spray_to_solve() {
                Some(_) => DirectionFrom::Spray,
                None => DirectionFrom::Scene,
            };
            (bat_tracking::solve(&job.scene, &swing), given)
        }
    });
    let (answer, direction_from) = (solved.map(|s| s.0), solved.map(|s| s.1));
    if let Some(solved) = answer.as_ref().and_then(|a| a.solved.as_ref().ok()) {
        job.scene.launch = solved.launch.given();
        job.launch = RowLaunch {
            spray: None,
            side: job.launch.side,
            estimate_backspin: false,
            estimate_sidespin: false,
            measured_spin: None,
        };
    }
    let solved = answer.is_some_and(|a| a.solved.is_ok());
    job.swing = Some(RowSwing {
        tracked,
        answer,
        direction_from: direction_from.filter(|_| solved),
        bat,
        effective_mass,
        savant_squared_up,
        tilt_given: priors.tilt.is_none(),
    });
}
