//! Key `x`: the chart in view written as SVG to a fresh file in the current
//! folder (`homerun-trajectory-1.svg`, `-2`, …; never over an existing
//! file), with where it went, or why not, in the status line (the screen's
//! full width, where a path fits best; until the next key). The trajectory
//! (from the side and from above) for tabs 1 and 5, the impact chart (the
//! paper's Fig. 2) for tab 3, the range surface for tab 2, the figure for
//! tab 4, each in the units shown (as the command
//! line's `--units` draws them). A write of ~50 KB is done at once, on the
//! UI thread.

use std::path::{Path, PathBuf};

use super::App;
use crate::layout::Tab;
use analysis::figures::{FigureData, shown};
use picture::{self, FlightPath, ImpactPicture, PictureError, SurfacePicture, TrajectoryPicture};

/// The most files of one kind `x` numbers before it gives up.
const MAX_NUMBER: u32 = 10_000;

/// `homerun-{kind}-{n}.svg` in `dir`, for the smallest n ≥ 1 not taken.
pub fn fresh_path(dir: &Path, kind: &str) -> Option<PathBuf> {
    (1..=MAX_NUMBER)
        .map(|n| dir.join(format!("homerun-{kind}-{n}.svg")))
        .find(|path| !path.exists() && path.symlink_metadata().is_err())
}

impl App {
    /// Writes the chart in view to a fresh file in the current folder.
    pub(super) fn export(&mut self) {
        // The folder in full, so that the message says where to look.
        let here = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
        self.export_in(&here);
    }

    /// Writes the chart in view to a fresh file in `dir`, and says in the
    /// status line where it went, or why nothing was written.
    pub fn export_in(&mut self, dir: &Path) {
        self.export_message = Some(match self.export_to(dir) {
            Ok(path) => (format!("x: wrote {}", path.display()), false),
            Err(why) => (format!("x: no SVG written: {why}"), true),
        });
    }

    /// Writes the chart in view to a fresh file in `dir`: its path, or why not.
    pub fn export_to(&self, dir: &Path) -> Result<PathBuf, String> {
        // A folder that is not there is named as such, not as a file.
        if !dir.is_dir() {
            return Err(format!("no such folder: {}", dir.display()));
        }
        let (kind, svg) = self.chart_svg()?;
        let svg = svg.map_err(|e: PictureError| e.to_string())?;
        let fresh = || {
            fresh_path(dir, &kind).ok_or_else(|| {
                format!("{MAX_NUMBER} homerun-{kind}-N.svg files already in the folder")
            })
        };
        let mut path = fresh()?;
        // A name taken meanwhile (another explorer's `x`): the next one.
        let mut written = preset::atomic_file::write_new(&path, svg.as_bytes());
        for _ in 0..8 {
            if !matches!(&written, Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists) {
                break;
            }
            path = fresh()?;
            written = preset::atomic_file::write_new(&path, svg.as_bytes());
        }
        written
            // The reason first and the path last, so that a narrow status line
            // cuts the path's start, not the reason or the file's name.
            .map_err(|e| {
                let reason = e.to_string();
                // "(os error 2)" tells a user nothing the words do not.
                let reason = reason.split(" (os error").next().unwrap_or_default();
                format!("{reason}, writing {}", path.display())
            })?;
        Ok(path)
    }

    /// The impact as the tab draws it: v1 (and a 3-D swing's v2) and v3
    /// against p, with p_s, p_c, p_f and the step-through's cursor.
    fn impact_picture(&self) -> ImpactPicture {
        let mut picture = ImpactPicture {
            preset: self.preset_name.clone(),
            curves: Vec::new(),
            marks: Vec::new(),
            cursor: None,
        };
        let Some(impact) = &self.flown.impact else {
            return picture;
        };
        let pf = impact.separation_impulse();
        let states: Vec<_> = (0..=400)
            .map(|k| impact.at(pf * f64::from(k) / 400.0))
            .collect();
        let curve = |name: &str, value: fn(&model::impact::Moment) -> f64| {
            let points = states.iter().map(|s| (s.impulse, value(s))).collect();
            (name.to_owned(), points)
        };
        picture.curves.push(curve("v1", |s| s.slip.x));
        if impact.spatial().is_some() {
            picture.curves.push(curve("v2", |s| s.slip.y));
        }
        picture.curves.push(curve("v3", |s| s.normal_velocity));
        picture
            .marks
            .extend(impact.stick_impulse().map(|p| ("p_s".to_owned(), p)));
        picture
            .marks
            .push(("p_c".to_owned(), impact.compression_impulse()));
        picture.marks.push(("p_f".to_owned(), pf));
        let stops = super::impact_stops(impact);
        picture.cursor = stops.get(self.impact_stop).map(|s| s.impulse);
        picture
    }

    /// The chart in view as SVG, with its kind for the file's name.
    fn chart_svg(&self) -> Result<(String, Result<String, PictureError>), String> {
        match self.tab {
            // Short enough that the status line at 80 columns keeps the key.
            Tab::Surface if !self.is_swing() => {
                Err("the range surface needs a swing (b switches scenes)".into())
            }
            Tab::Figures if !self.figure_applies() => Err(format!(
                "Fig. {} needs a swing: b switches to the swing scene",
                self.figure_number
            )),
            Tab::Surface if self.shows_margin() => {
                Err("the margin map has no SVG; c shows the range surface, which has".into())
            }
            Tab::Surface => {
                let state = self
                    .surface
                    .as_ref()
                    .ok_or("the range surface is still being computed")?;
                let optimum = self
                    .optimum
                    .filter(|o| o.done && o.best.range.is_finite())
                    .map(|o| (o.best.undercut, o.best.swing_angle, o.best.range));
                let picture = SurfacePicture {
                    surface: &state.surface,
                    title: format!("Range over (E, ψ) — preset {}", self.preset_name),
                    conditions: shown::conditions(&self.preset_name, &self.scene, self.units)
                        .split_once(": ")
                        .map_or(String::new(), |(_, rest)| rest.to_owned()),
                    now: Some((self.scene.bat.undercut, self.scene.bat.swing_angle)),
                    optimum,
                    paper: None,
                    level: self.fence.map(|f| f.distance),
                };
                Ok((
                    "surface".into(),
                    picture::surface_svg_in(&picture, self.units),
                ))
            }
            Tab::Figures => {
                let state = self
                    .figure
                    .as_ref()
                    .ok_or("the figure is still being computed")?;
                let data = state.data.as_ref().map_err(Clone::clone)?;
                // In the units shown, as `figure N --svg --units` draws it.
                let now = shown::now(data, &self.scene, self.units);
                let data = FigureData {
                    conditions: shown::conditions(&self.preset_name, &self.scene, self.units),
                    ..shown::converted(data.clone(), self.units)
                };
                Ok((
                    format!("figure{}", data.number),
                    picture::table_figure_svg_now(&data, now, &self.preset_name),
                ))
            }
            // The impact chart on screen (the paper's Fig. 2), a swing's.
            Tab::Impact if self.flown.impact.is_some() => Ok((
                "impact".into(),
                picture::impact_svg_in(&self.impact_picture(), self.units),
            )),
            Tab::Flight | Tab::Impact | Tab::Field => {
                let flight = &self.flown.flight;
                let mut paths = vec![FlightPath {
                    name: "now".into(),
                    points: self.path.clone(),
                    ground: self.ground.clone(),
                }];
                if !self.optimal_path.is_empty() {
                    paths.push(FlightPath {
                        name: "best".into(),
                        points: self.optimal_path.clone(),
                        ground: self.optimal_ground.clone(),
                    });
                }
                if let Some(pin) = &self.pin {
                    paths.push(FlightPath {
                        name: "pin".into(),
                        points: pin.path.clone(),
                        ground: pin.ground.clone(),
                    });
                }
                let picture = TrajectoryPicture {
                    preset: self.preset_name.clone(),
                    paths,
                    range: flight.landed.then_some(flight.range),
                    apex: flight.apex,
                    not_landed: (!flight.landed).then(|| "did not land".to_owned()),
                    // With a park chosen, its wall, as the panes draw it.
                    fence: self
                        .side_fence()
                        .map(|(distance, height)| preset::Fence { distance, height }),
                    park: self.chosen_park().map(|park| {
                        let wall = park
                            .fence
                            .points()
                            .iter()
                            .map(|p| (p.direction, p.distance));
                        (park.code.clone(), wall.collect())
                    }),
                };
                Ok((
                    "trajectory".into(),
                    picture::trajectory_svg_in(&picture, self.units),
                ))
            }
        }
    }
}
