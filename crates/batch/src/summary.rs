//! A batch's tally said: its lines (for stderr), its tables by launch angle,
//! by kind and of the swings (with `--summary`), and all of it as JSON
//! (`--summary-file`), every number in the units shown, keys named with
//! their unit outside SI.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use analysis::bat_tracking::season_bat;

use analysis::savant::Spray;
use model::park::spans_text;
use serde_json::{Value, json};
use units::Quantity;

use crate::kinds::KIND_NAMES;
use crate::tally::{BANDS, Tally, band_bounds};
use crate::words::plural;
use crate::{Setup, Shown};

/// A band's name in a table: "< 10°", "10–20°", "50°+".
pub fn band_name((from, to): (Option<f64>, Option<f64>)) -> String {
    match (from, to) {
        (None, Some(to)) => format!("< {to}°"),
        (Some(from), None) => format!("{from}°+"),
        (Some(from), Some(to)) => format!("{from}–{to}°"),
        (None, None) => String::from("all"),
    }
}

impl Tally {
    /// The summary's lines: what the rows used, their swings, and how they
    /// came out ("summary: flown 248 rows, skipped 0; at their parks …").
    pub fn lines(&self, setup: &Setup, shown: Shown) -> Vec<String> {
        let mut lines = Vec::new();
        let used = self.used_line(setup, shown);
        lines.extend(used);
        if self.empty > 0 {
            let n = self.empty;
            lines.push(format!("{n} empty line{} skipped", plural(n)));
        }
        lines.push(self.outcome_line(setup, shown));
        lines.extend(self.metres_line());
        lines.extend(self.radians_line());
        lines.extend(self.home_runs_line());
        if self.failed > 0 {
            let rows = self.failed + self.answered;
            lines.push(crate::pieces::rows_failed(self.failed, rows));
        }
        lines
    }

    fn used_line(&self, setup: &Setup, shown: Shown) -> Option<String> {
        let mut parts = Vec::new();
        parts.extend(self.swings_line(shown));
        if !self.used.is_empty() {
            parts.push(format!("read {}", self.used.join(", ")));
        }
        let flown = self.answered;
        let [whole, size, zero] = self.spin_measured;
        if whole + size > 0 {
            let alone = match size {
                0 => String::new(),
                _ => format!(" ({size} of them its size alone, about the estimate's axis)"),
            };
            parts.push(format!(
                "spin measured (hit_spin_rate) on {} of {flown} row{}{alone}",
                whole + size,
                plural(flown)
            ));
        }
        if self.estimated > 0 {
            let none = match zero {
                0 => String::new(),
                _ => format!(" ({zero} whose hit_spin_rate of 0 is none measured)"),
            };
            parts.push(format!(
                "spin estimated (Nathan's relation) on {} of {flown} row{}{none}",
                self.estimated,
                plural(flown)
            ));
        }
        if self.sprayed > 0 {
            parts.push(match setup.spray {
                Spray::Landing => format!(
                    "spray taken as the landing bearing on {} row{} (launch direction solved, \
                     {:.1} flights a row)",
                    self.sprayed,
                    plural(self.sprayed),
                    self.solve_flights as f64 / self.sprayed as f64
                ),
                Spray::Launch => {
                    format!(
                        "spray taken as the launch direction on {} row{}",
                        self.sprayed,
                        plural(self.sprayed)
                    )
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
                "{} row{} without hit coordinates flown toward the preset's direction",
                self.without_spray,
                plural(self.without_spray)
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
                "flown from the pitch's height at the plate (plate_z) on {} row{}",
                self.from_plate,
                plural(self.from_plate)
            ));
        }
        if self.plate_unusable > 0 {
            parts.push(format!(
                "{} row{} whose plate_z is no contact height (below the ground, past 10 m, or \
                 not a number) flown from the preset's",
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
            let air = match setup.given.any() {
                true => "the air given",
                false => "each in the standard air at its elevation",
            };
            parts.push(format!("{parks} park{} from {how}, {air}", plural(parks)));
        }
        if self.at_no_park > 0 && parks > 0 {
            let n = self.at_no_park;
            parts.push(format!("{n} row{} at no park", plural(n)));
        }
        parts.extend(self.away.parts(setup));
        if let Some(part) = self.earlier_walls_part(setup) {
            parts.push(part);
        }
        if self.side_unknown > 0 {
            parts.push(format!(
                "{} row{} whose batter's side is not known (no stand, or Undefined or Switch) \
                 spin-estimated as either side's average",
                self.side_unknown,
                plural(self.side_unknown)
            ));
        }
        if self.at_unknown_park > 0 {
            parts.push(format!(
                "{} row{} whose home_team no park answers to ({}) at no park (`homerun parks` \
                 lists the codes; --park judges every row at one)",
                self.at_unknown_park,
                plural(self.at_unknown_park),
                self.unknown_codes()
            ));
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

    /// "51 rows judged at their park's walls of the day, not those given (…): BAL
    /// 2015–2021 (15 rows), …": where a park's earlier walls stood, so that
    /// its `<CODE>_outcome` (the walls as given) may differ from `outcome`.
    fn earlier_walls_part(&self, setup: &Setup) -> Option<String> {
        let rows: usize = self.at_earlier_walls.values().sum();
        let named: Vec<String> = (self.at_earlier_walls.iter())
            .map(|(&(park, walls), &n)| {
                let park = &setup.parks.parks[park];
                let walls = spans_text(&park.earlier[walls].walls);
                format!("{} {walls} ({n} row{})", park.code, plural(n))
            })
            .collect();
        (rows > 0).then(|| {
            let (s, their) = match rows {
                1 => ("", "its"),
                _ => ("s", "their"),
            };
            format!(
                "{rows} row{s} judged at {their} park's walls of the day, not those given \
                 (--park, --all-parks and parks_cleared judge those): {}",
                named.join(", ")
            )
        })
    }

    /// "LIN_POT, Normal Cornbelters, …": the codes no park answers to.
    fn unknown_codes(&self) -> String {
        let named: Vec<String> = (self.unknown_parks.iter())
            .map(|(code, _)| preset::escape_cut(code, 20))
            .collect();
        let shown: usize = self.unknown_parks.iter().map(|(_, n)| n).sum();
        let more = shown < self.at_unknown_park;
        format!("{}{}", named.join(", "), if more { ", …" } else { "" })
    }

    /// Where the rows were judged, for the outcome line.
    fn judged_at(&self, setup: &Setup) -> String {
        let air = match setup.one_flight {
            false => "in its air; parks_cleared: each park in its own air",
            true => "in its air; parks_cleared: on that one flight (--one-flight)",
        };
        // No row had a fence to be judged at.
        let no_fence = self.outcomes[..3].iter().sum::<usize>() == 0 && self.at_no_park > 0;
        match setup.park {
            Some(i) => format!(
                "at {} ({air})",
                preset::escape_cut(&setup.parks.parks[i].code, 20)
            ),
            None if no_fence && self.at_unknown_park > 0 => format!(
                "at no park (home_team {}: no park answers to {}, no --park: no fence to judge; \
                 foul balls still called)",
                self.unknown_codes(),
                if self.unknown_parks.len() > 1 {
                    "them"
                } else {
                    "it"
                }
            ),
            None if no_fence && self.away.at_no_park() > 0 => String::from(
                "at no park (home_team's park was not home, or not so walled, when they were \
                 played: no fence to judge; foul balls still called)",
            ),
            None if no_fence => String::from(
                "at no park (no home_team, no --park: no fence to judge; foul balls still called)",
            ),
            None => format!("at each row's park ({air})"),
        }
    }

    /// "summary: flown 248 rows, skipped 0; at their parks 169 clear, 39
    /// off the wall, 37 short, 3 foul; against hit_distance_sc (248 rows):
    /// median difference +1.3 ft, median |difference| 9.8 ft".
    fn outcome_line(&self, setup: &Setup, shown: Shown) -> String {
        let [clear, wall, short, foul] = self.outcomes;
        let skipped = self.failed + self.without_speed;
        if self.answered == 0 {
            // Nothing was judged anywhere: no park to name.
            return format!("summary: flown 0 rows, skipped {skipped}");
        }
        let mut line = format!(
            "summary: flown {} row{}, skipped {skipped}; {}: {clear} clear, {wall} off the wall, \
             {short} short, {foul} foul",
            self.answered,
            plural(self.answered),
            self.judged_at(setup)
        );
        let judged: usize = self.outcomes.iter().sum();
        if judged < self.answered {
            let _ = write!(line, ", {} at no park", self.answered - judged);
        }
        if !self.differences.is_empty() {
            let unit = shown.unit(Quantity::Distance);
            let distance = self.distance_shown();
            let _ = write!(
                line,
                "; against {distance} ({} row{}): median difference {:+.1} {}, median \
                 |difference| {:.1} {}",
                self.differences.len(),
                plural(self.differences.len()),
                unit.show(self.differences.median()),
                unit.symbol,
                unit.show(self.differences.median_abs()),
                unit.symbol
            );
            if let Some(i) = setup.park {
                // Not the model's error: another park's air against the
                // distance each ball went where it was hit.
                let code = preset::escape_cut(&setup.parks.parks[i].code, 20);
                let _ = write!(
                    line,
                    " (flown in {code}'s air, {distance} where each ball was hit)"
                );
            }
        }
        line
    }

    /// The file's name for the distance compared against, as the text
    /// shows it.
    fn distance_shown(&self) -> String {
        preset::escape_cut(&self.distance_column, 40)
    }

    /// Where most balls in the air measured under half their flight: a
    /// distance column in metres read as feet (a metric Trackman export's
    /// `Distance`), which makes every difference wrong.
    fn metres_line(&self) -> Option<String> {
        let (n, short) = (self.compared_in_air, self.under_half);
        (n >= 10 && 2 * short > n).then(|| {
            let column = self.distance_shown();
            format!(
                "{column} is under half the flight's distance on {short} of {n} balls launched at \
                 20° and up: a column in metres? map it, --column hit_distance_sc={column}:m \
                 (exit status 1)"
            )
        })
    }

    /// Where every launch of a file of batted balls lies within ±1.6°
    /// (none steeper than a radian's π/2 read as degrees), though line
    /// drives alone rise 10–25°: a column in radians read as degrees.
    fn radians_line(&self) -> Option<String> {
        let rows = self.answered;
        (rows >= 50 && self.steepest < 1.6f64.to_radians()).then(|| {
            format!(
                "every launch angle of the {rows} rows lies within ±1.6°: a column in radians \
                 read as degrees? map it, --column launch_angle=COLUMN:rad (exit status 1)"
            )
        })
    }

    /// Whether a column looks read in the wrong unit ([`Tally::radians_line`],
    /// [`Tally::metres_line`]): the rows are written, and the exit status
    /// says they are suspect.
    pub fn suspect(&self) -> bool {
        self.radians_line().is_some() || self.metres_line().is_some()
    }

    /// "40 home runs (events) the model calls short or foul at their park:
    /// lines 10, 14, …", so that an analyst can find them.
    fn home_runs_line(&self) -> Option<String> {
        let n = self.home_runs_not_count;
        let lines: Vec<String> = self.home_runs_not.iter().map(|l| l.to_string()).collect();
        let more = if n > lines.len() { ", …" } else { "" };
        (n > 0).then(|| {
            format!(
                "{n} home run{} (events) the model calls short or foul where judged: line{} {}{more}",
                plural(n),
                plural(n),
                lines.join(", ")
            )
        })
    }

    /// "swings: solved 16627 of 17436 tracked (95.4 %, …); q median …".
    fn swings_line(&self, shown: Shown) -> Option<String> {
        let swings = &self.swings;
        let tracked = swings.data_efficiency.len();
        let untracked: usize = swings.untracked.values().sum();
        if tracked + untracked == 0 {
            return None;
        }
        let solved = swings.model_efficiency.len();
        let mut line = match tracked {
            0 => "swings: none tracked".to_owned(),
            _ => format!(
                "swings: solved {solved} of {tracked} tracked ({:.1} %, {} of them off the sweet \
                 spot)",
                100.0 * solved as f64 / tracked as f64,
                swings.off_sweet_spot
            ),
        };
        if tracked > 0 {
            let data = &swings.data_efficiency;
            let _ = write!(
                line,
                "; q median {:.3}, 99th percentile {:.3} (data)",
                data.quantile(0.5),
                data.quantile(0.99)
            );
        }
        if solved > 0 {
            let model = &swings.model_efficiency;
            let _ = write!(
                line,
                ", median {:.3}, 99th {:.3} (model: each solved swing at E = 0, at the sweet spot)",
                model.quantile(0.5),
                model.quantile(0.99),
            );
            let mut undercuts = numerics::quantile::Quantiles::default();
            swings
                .bands
                .iter()
                .for_each(|b| undercuts.merge(&b.undercut));
            // In mm, or under --units imperial in inches.
            let (scale, unit, decimals) = match shown.is_si() {
                true => (1e3, "mm", 1),
                false => (1.0 / 0.0254, "in", 2),
            };
            let e = [0.25, 0.5, 0.75].map(|q| undercuts.quantile(q) * scale);
            let _ = write!(
                line,
                "; undercut median {:.decimals$} {unit} (quartiles {:.decimals$}, {:.decimals$})",
                e[1], e[0], e[2]
            );
        }
        let bats = bats_named(&swings.bats);
        if !bats.is_empty() {
            let _ = write!(line, "; bat: {}", bats.join(", "));
        }
        let reasons: Vec<String> = (swings.unsolved.iter().map(|(why, n)| format!("{n} {why}")))
            .chain(swings.untracked.iter().map(|(why, n)| format!("{n} {why}")))
            .collect();
        if !reasons.is_empty() {
            let _ = write!(line, "; not solved: {}", reasons.join(", "));
        }
        Some(line)
    }

    /// `--summary`'s tables, in the units shown (none without their data).
    pub fn tables(&self, setup: &Setup, shown: Shown) -> Vec<String> {
        let json = self.json(setup, shown);
        let (d, unit) = (
            shown.unit(Quantity::Distance),
            shown.csv_key("", Quantity::Distance),
        );
        let key = |name: &str| format!("{name}{unit}");
        let distance = self.distance_shown();
        let cell = |v: &Value, sign: bool| match v.as_f64() {
            Some(m) if sign => format!("{m:+.1}"),
            Some(m) => format!("{m:.1}"),
            None => String::from("-"),
        };
        let mut tables = Vec::new();
        if let Some(bands) = json["bands"].as_array() {
            let mut table = format!(
                "by launch angle, model − {} ({}):\n{:<8} {:>7} {:>8} {:>10}",
                distance, d.symbol, "angle", "rows", "median", "median |d|"
            );
            for band in bands {
                let name = band_name((band["from"].as_f64(), band["to"].as_f64()));
                let _ = write!(
                    table,
                    "\n{name:<8} {:>7} {:>8} {:>10}",
                    // serde_json's Display pads nothing: the text pads.
                    band["rows"].to_string(),
                    cell(&band[key("median")], true),
                    cell(&band[key("median_abs")], false)
                );
            }
            tables.push(table);
        }
        let mut kinds = Vec::new();
        if let Some(rows) = json["kinds"].as_array().filter(|r| !r.is_empty()) {
            kinds.push(format!(
                "by kind of ball (bb_type; home runs by events), launched at 10° or more, model − \
                 {distance} ({}):\n{:<13} {:>7} {:>8} {:>10}",
                d.symbol, "kind", "rows", "median", "median |d|"
            ));
            for row in rows {
                kinds.push(format!(
                    "{:<13} {:>7} {:>8} {:>10}",
                    row["kind"].as_str().unwrap_or(""),
                    row["rows"].to_string(),
                    cell(&row[key("median")], true),
                    cell(&row[key("median_abs")], false)
                ));
            }
        }
        if self.home_runs_judged > 0 {
            let at_no_park = self.home_runs - self.home_runs_judged;
            kinds.push(format!(
                "home runs that clear the fence they are judged at: {} of {} ({:.1} %){}",
                self.home_runs_clear,
                self.home_runs_judged,
                100.0 * self.home_runs_clear as f64 / self.home_runs_judged as f64,
                match at_no_park {
                    0 => String::new(),
                    n => format!("; {n} more at no park"),
                }
            ));
        }
        if !kinds.is_empty() {
            tables.push(kinds.join("\n"));
        }
        if let Some(bands) = json["swings"].as_array() {
            tables.push(self.swings_table(bands, shown));
        }
        tables
    }

    fn swings_table(&self, bands: &[Value], shown: Shown) -> String {
        let (size, spin) = (shown.unit(Quantity::Size), shown.unit(Quantity::Spin));
        let (size_scale, size_symbol, size_decimals) = match shown.is_si() {
            true => (1e3, "mm", 1),
            false => (1.0, size.symbol, 2),
        };
        let mut table = format!(
            "swings by launch angle, medians of the solved (contact: its speed / bat_speed):\n\
             {:<8} {:>7} {:>7} {:>13} {:>10} {:>8} {:>12}",
            "angle",
            "tracked",
            "solved",
            format!("undercut ({size_symbol})"),
            "squared up",
            "contact",
            format!("spin ({})", spin.symbol),
        );
        for (k, band) in self.swings.bands.iter().enumerate() {
            if band.tracked == 0 {
                continue;
            }
            let solved = band.undercut.len();
            let show = |q: &numerics::quantile::Quantiles, text: &dyn Fn(f64) -> String| match q
                .is_empty()
            {
                true => String::from("-"),
                false => text(q.median()),
            };
            let name = band_name((bands[k]["from"].as_f64(), bands[k]["to"].as_f64()));
            let _ = write!(
                table,
                "\n{name:<8} {:>7} {:>6.1}% {:>13} {:>10} {:>8} {:>12}",
                band.tracked,
                100.0 * solved as f64 / band.tracked as f64,
                show(&band.undercut, &|e| format!(
                    "{:+.size_decimals$}",
                    size.show(e) * size_scale
                )),
                show(&band.squared_up, &|q| format!("{q:.3}")),
                show(&band.contact_speed, &|c| format!("{c:.3}")),
                show(&band.spin, &|w| format!("{:.0}", spin.show(w))),
            );
        }
        table
    }

    /// The whole summary as JSON, in the units shown (keys named with their
    /// unit outside SI, as the CSV's columns are).
    pub fn json(&self, setup: &Setup, shown: Shown) -> Value {
        let d = |q: &numerics::quantile::Quantiles| {
            let value = |v: f64| json!(shown.convert(Quantity::Distance, v));
            match q.is_empty() {
                true => (Value::Null, Value::Null),
                false => (value(q.median()), value(q.median_abs())),
            }
        };
        let key = |name: &str| shown.csv_key(name, Quantity::Distance);
        let mut value = json!({
            "rows": self.answered,
            "failed": self.failed,
            "without_launch_speed": self.without_speed,
            "outcomes": {
                "clears": self.outcomes[0], "off_the_wall": self.outcomes[1],
                "short": self.outcomes[2], "foul": self.outcomes[3],
                "no_park": self.answered - self.outcomes.iter().sum::<usize>().min(self.answered),
            },
            "spin_estimated": self.estimated,
        });
        let [whole, size, zero] = self.spin_measured;
        if whole + size + zero > 0 {
            value["spin_measured"] =
                json!({ "whole": whole, "size_alone": size, "rate_zero": zero });
        }
        if self.radians_line().is_some() {
            value["launch_angles_within_1_6_deg"] = true.into();
        }
        if self.metres_line().is_some() {
            value["distance_under_half"] =
                json!({ "rows": self.under_half, "of": self.compared_in_air });
        }
        // The rows answered on an assumption, as the text names them.
        for (name, rows) in [
            ("side_unknown", self.side_unknown),
            ("spray_unsolved", self.unsolved),
            ("without_spray", self.without_spray),
            ("at_unknown_park", self.at_unknown_park),
        ] {
            if rows > 0 {
                value[name] = rows.into();
            }
        }
        if !self.differences.is_empty() {
            let (median, median_abs) = d(&self.differences);
            value["difference"] = json!({ "rows": self.differences.len(),
                key("median"): median, key("median_abs"): median_abs });
            // As the outcome line says: --park's air against where each
            // ball was hit.
            if let Some(i) = setup.park {
                value["difference"]["flown_in_air_of"] = json!(setup.parks.parks[i].code);
            }
            let bands: Vec<Value> = (0..BANDS)
                .map(|band| {
                    let (from, to) = band_bounds(band);
                    let (median, median_abs) = d(&self.by_band[band]);
                    json!({ "from": from, "to": to, "rows": self.by_band[band].len(),
                        key("median"): median, key("median_abs"): median_abs })
                })
                .collect();
            value["bands"] = json!(bands);
        }
        let kinds: Vec<Value> = (KIND_NAMES.iter().zip(&self.by_kind))
            .filter(|(_, q)| !q.is_empty())
            .map(|(kind, q)| {
                let (median, median_abs) = d(q);
                json!({ "kind": kind, "rows": q.len(), key("median"): median,
                    key("median_abs"): median_abs })
            })
            .collect();
        if !kinds.is_empty() {
            value["kinds"] = json!(kinds);
        }
        if !self.away.is_empty() {
            value["away_from_home_park"] = self.away.json(setup);
        }
        if !self.at_earlier_walls.is_empty() {
            let entries = (self.at_earlier_walls.iter()).map(|(&(park, walls), rows)| {
                let park = &setup.parks.parks[park];
                json!({ "home_team": park.code, "park": park.name, "rows": rows,
                    "walls": spans_text(&park.earlier[walls].walls) })
            });
            value["at_earlier_walls"] = json!(entries.collect::<Vec<_>>());
        }
        if self.home_runs > 0 {
            value["home_runs"] = json!({ "clear": self.home_runs_clear, "of": self.home_runs,
                "judged_at_a_park": self.home_runs_judged,
                "short_or_foul": self.home_runs_not_count,
                "short_or_foul_lines": self.home_runs_not });
        }
        if self.swings.bands.iter().any(|b| b.tracked > 0) {
            let size = |v: f64| shown.convert(Quantity::Size, v);
            let spin = |v: f64| shown.convert(Quantity::Spin, v);
            let median = |q: &numerics::quantile::Quantiles, convert: &dyn Fn(f64) -> f64| {
                (!q.is_empty()).then(|| convert(q.median()))
            };
            let bands: Vec<Value> = (self.swings.bands.iter().enumerate())
                .map(|(k, band)| {
                    let (from, to) = band_bounds(k);
                    json!({ "from": from, "to": to, "tracked": band.tracked,
                        "solved": band.undercut.len(),
                        shown.csv_key("undercut", Quantity::Size): median(&band.undercut, &size),
                        "squared_up": median(&band.squared_up, &|v| v),
                        "contact_speed": median(&band.contact_speed, &|v| v),
                        shown.csv_key("spin", Quantity::Spin): median(&band.spin, &spin) })
                })
                .collect();
            value["swings"] = json!(bands);
        }
        if !self.swings.bats.is_empty() {
            value["bats"] = bats_json(&self.swings.bats);
        }
        value
    }
}

/// The bats a batch's tracked rows were solved with
/// ([`Swings::bats`](crate::tally::Swings)), for the summary line: "17436 with the
/// 2024 bat: M_B 0.884 kg, …".
pub(crate) fn bats_named(bats: &BTreeMap<(Option<i32>, u64), usize>) -> Vec<String> {
    (bats.iter())
        .map(
            |(&(season, mass), n)| match season.and_then(|s| season_bat(Some(s))) {
                Some(bat) => format!("{n} with the {}", bat.source),
                None => format!("{n} with the preset's (M_B {:.3} kg)", f64::from_bits(mass)),
            },
        )
        .collect()
}

/// The same as the summary's JSON: `[{"bat", "effective_mass", "source",
/// "tracked"}]`, masses in kg.
pub(crate) fn bats_json(bats: &BTreeMap<(Option<i32>, u64), usize>) -> serde_json::Value {
    (bats.iter())
        .map(|(&(season, mass), n)| {
            let bat = season.and_then(|s| season_bat(Some(s)));
            serde_json::json!({
                "bat": season.map_or("preset".to_owned(), |s| s.to_string()),
                "effective_mass": f64::from_bits(mass),
                "source": bat.map_or("the preset's bat", |b| b.source),
                "tracked": n,
            })
        })
        .collect()
}
