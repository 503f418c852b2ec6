//! A row at its home_team's park is judged at the park's walls only on the
//! days they stood ([`model::park::Park::walls_on`]): a 2019 or a 2025 row
//! at Camden Yards met another left-field wall than the 2022–2024 one
//! bundled, and is at no park, flown in Camden Yards' air, and named. A
//! park that bundles its earlier walls too (Toronto's before 2023) judges
//! a row of their days at them.

use model::park::HomeSpan;

use super::*;

/// The summary's lines and the rows' `park`, `outcome` and `range`.
struct Judged {
    parks: Vec<String>,
    outcomes: Vec<String>,
    ranges: Vec<f64>,
    err: String,
    json: serde_json::Value,
}

fn judge(setup: &Setup, rows: &[(&str, &str, &str)]) -> Judged {
    let mut input = String::from("launch_speed,launch_angle,home_team,game_date,game_year\n");
    for (code, date, year) in rows {
        input += &format!("104,28,{code},{date},{year}\n");
    }
    let shown = Shown::default();
    let (out, err, outcome, tally) = run_tallied(setup, &input, false, shown);
    assert_eq!(outcome.failed, 0, "{err}");
    let mut lines = out.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (park, verdict, range) = (column("park"), column("outcome"), column("range"));
    let cells: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    Judged {
        parks: cells.iter().map(|c| c[park].to_owned()).collect(),
        outcomes: cells.iter().map(|c| c[verdict].to_owned()).collect(),
        ranges: cells.iter().map(|c| c[range].parse().unwrap()).collect(),
        err,
        json: tally.json(setup, shown),
    }
}

#[test]
fn a_row_played_before_or_after_its_parks_walls_is_at_no_park_in_its_air() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let rows = [
        // Camden Yards: the bundled left field stood 2022–2024, its
        // earlier walls (bundled too) 2015–2021; before, not known.
        ("BAL", "2014-06-01", "", "none"),
        ("BAL", "2021-09-30", "", "BAL"),
        ("BAL", "2022-04-11", "", "BAL"),
        ("BAL", "2024-09-29", "", "BAL"),
        ("BAL", "2025-03-31", "", "none"),
        // The season alone: inside the span, outside it.
        ("BAL", "", "2023", "BAL"),
        ("BAL", "", "2014", "none"),
        // No date: judged as bundled, and counted.
        ("BAL", "", "", "BAL"),
        // Houston's centre field from 2017.
        ("HOU", "2016-09-28", "", "none"),
        ("HOU", "2017-04-03", "", "HOU"),
        // A park whose walls never changed.
        ("BOS", "2016-06-01", "", "BOS"),
    ];
    let judged = judge(&setup, &rows.map(|(c, d, y, _)| (c, d, y)));
    let wanted: Vec<&str> = rows.iter().map(|r| r.3).collect();
    assert_eq!(judged.parks, wanted, "{}", judged.err);
    for (park, outcome) in judged.parks.iter().zip(&judged.outcomes) {
        assert_eq!(park == "none", outcome == "no_park", "{park} {outcome}");
    }
    // Flown in the park's own air, not the preset's: the same ball at
    // Camden Yards in 2014 and in 2022 carries alike.
    let (before, during) = (judged.ranges[0], judged.ranges[2]);
    assert_eq!(before, during);
    let in_houston = judged.ranges[8];
    assert_eq!(in_houston, judged.ranges[9]);
    let err = &judged.err;
    assert!(
        err.contains(
            "4 rows played at home_team's park when its walls were not those given, at no \
             park, in its air: BAL 2014 (2 rows), BAL 2025 (1 row), HOU 2016 (1 row) (BAL's \
             Oriole Park at Camden Yards was home 1992 on, its walls as given 2022–2024, \
             earlier walls 2015–2021; HOU's Daikin Park was home 2000 on, its walls as given \
             2017 on"
        ),
        "{err}"
    );
    assert!(
        err.contains(
            "1 row without a date (game_date, game_year) judged at a park that was not always \
             home, or not always so walled: BAL (1 row) (BAL's Oriole Park at Camden Yards was \
             home 1992 on, its walls as given 2022–2024, earlier walls 2015–2021)"
        ),
        "{err}"
    );
    let entries = judged.json["away_from_home_park"].as_array().unwrap();
    let bal_2014 = (entries.iter())
        .find(|e| e["home_team"] == "BAL" && e["season"] == 2014)
        .unwrap();
    assert_eq!(bal_2014["rows"], 2);
    assert_eq!(bal_2014["judged"], "no_park: other walls then");
    assert_eq!(bal_2014["walls"], "2022–2024");
    assert_eq!(bal_2014["earlier_walls"], serde_json::json!(["2015–2021"]));

    // `--park` asks "would it be out there today": every date at the park
    // as bundled.
    let mut at_camden = Setup::new(&preset, &parks);
    at_camden.park = parks.parks.iter().position(|p| p.code == "BAL");
    let judged = judge(
        &at_camden,
        &[("BAL", "2019-06-01", ""), ("BAL", "2025-04-01", "")],
    );
    assert_eq!(judged.parks, ["BAL", "BAL"]);
}

#[test]
fn a_season_the_walls_stood_for_part_of_is_at_no_park_without_a_date() {
    let preset = preset::load("fly-ball", None).unwrap();
    let mut parks = preset::parks::all(None).unwrap();
    // Walls put up at the All-Star break, in a park file of one's own.
    let camden = parks.parks.iter_mut().find(|p| p.code == "BAL").unwrap();
    camden.walls = vec![HomeSpan::parse("2022-07-20..2024").unwrap()];
    let setup = Setup::new(&preset, &parks);
    let judged = judge(
        &setup,
        &[
            ("BAL", "", "2022"),
            ("BAL", "2022-07-19", ""),
            ("BAL", "2022-07-20", ""),
            ("BAL", "", "2023"),
        ],
    );
    assert_eq!(judged.parks, ["none", "none", "BAL", "BAL"]);
    assert!(
        judged.err.contains(
            "2 rows played at home_team's park when its walls were not those given, at no \
             park, in its air: BAL 2022 (1 row), BAL 2022, its date not given (1 row)"
        ),
        "{}",
        judged.err
    );
}

#[test]
fn a_row_of_a_parks_earlier_walls_is_judged_at_them() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    // Toronto's walls: rebuilt for 2023, the outline's before. The same
    // ball to the right-centre power alley, where the wall came in 11 ft
    // (383 to 372) and went up 9 in.
    let rows = [
        ("2019-06-01", ""),
        ("", "2022"),
        ("2023-04-11", ""),
        ("", "2024"),
        ("2020-08-11", ""),
    ];
    let mut input = String::from(
        "launch_speed,launch_angle,launch.direction,launch.sidespin,home_team,game_date,game_year\n",
    );
    for (date, year) in rows {
        input += &format!("96,27,0.35,0,TOR,{date},{year}\n");
    }
    let shown = Shown::default();
    let (out, err, outcome, tally) = run_tallied(&setup, &input, false, shown);
    assert_eq!(outcome.failed, 0, "{err}");
    // Said, for a park's own column is at the walls as given.
    assert!(
        err.contains(
            "2 rows judged at their park's walls of the day, not those given (--park, \
             --all-parks and parks_cleared judge those): TOR 1989–2022 (2 rows)"
        ),
        "{err}"
    );
    let json = tally.json(&setup, shown);
    assert_eq!(json["at_earlier_walls"][0]["rows"], 2);
    assert_eq!(json["at_earlier_walls"][0]["walls"], "1989–2022");
    let judged = |out: &str| -> Vec<(String, String, String)> {
        let mut lines = out.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
        let (park, verdict, margin) = (column("park"), column("outcome"), column("margin"));
        (lines.map(|l| l.split(',').collect::<Vec<_>>()))
            .map(|c| {
                (
                    c[park].to_owned(),
                    c[verdict].to_owned(),
                    c[margin].to_owned(),
                )
            })
            .collect()
    };
    let rows = judged(&out);
    let parks: Vec<&str> = rows.iter().map(|r| r.0.as_str()).collect();
    // 2020: the Blue Jays played in Buffalo.
    assert_eq!(parks, ["TOR", "TOR", "TOR", "TOR", "none"], "{err}");
    assert_eq!(rows[0], rows[1]);
    assert_eq!(rows[2], rows[3]);
    // Off the old wall, over the new one.
    let verdicts = (rows[0].1.as_str(), rows[2].1.as_str());
    assert_eq!(verdicts, ("off the wall", "clears"));
    // Each as a park of those walls alone, always standing, judges it.
    let mut old_walls = preset::parks::all(None).unwrap();
    let toronto = old_walls
        .parks
        .iter_mut()
        .find(|p| p.code == "TOR")
        .unwrap();
    toronto.fence = toronto.earlier.remove(0).fence;
    toronto.walls = Vec::new();
    let setup = Setup::new(&preset, &old_walls);
    let (out, err, _, _) = run_tallied(&setup, &input, false, shown);
    assert_eq!(judged(&out)[3], rows[0], "{err}");
}
