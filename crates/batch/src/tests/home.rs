//! A row is judged at its home_team's park only when the park was home
//! ([`model::park::Park::home_on`]): the Athletics' 2025 in Sacramento and
//! the Blue Jays' 2020–21 in Buffalo and Dunedin are no verdict at the
//! Oakland Coliseum or the Rogers Centre; nor are spring training and the
//! games at neutral sites ([`model::park::neutral_site`]).

use super::*;

#[test]
fn a_row_played_where_its_home_team_was_not_at_home_is_at_no_park() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let setup = Setup::new(&preset, &parks);
    let rows = [
        ("ATH", "2025-05-01", "", "none"),
        ("ATH", "2024-09-26", "", "ATH"),
        ("ATH", "", "2025", "none"),
        ("TB", "4/2/2025", "", "none"),
        ("TB", "2026-04-02", "", "TB"),
        ("TOR", "2021-07-29", "", "none"),
        ("TOR", "2021-07-30", "", "TOR"),
        // The season alone, Toronto home for part of it.
        ("TOR", "", "2021", "none"),
        ("TOR", "", "2019", "TOR"),
        ("TEX", "2019-06-01", "", "none"),
        ("ATL", "2016-06-01", "", "none"),
        ("BOS", "2016-06-01", "", "BOS"),
        // No date: judged at the park as bundled, and counted.
        ("TB", "", "", "TB"),
        ("BOS", "", "", "BOS"),
        // Spring training: at the team's spring park, whatever the date.
        ("BOS", "2024-03-01", "S", "none"),
        ("BOS", "2024-10-05", "D", "BOS"),
        // Mexico City, a neutral site: the Rockies' home games, and the
        // Astros' there.
        ("COL", "2024-04-27", "", "none"),
        ("HOU", "2024-04-28", "", "none"),
        ("COL", "2024-04-29", "", "COL"),
    ];
    let mut input =
        String::from("launch_speed,launch_angle,home_team,game_date,game_year,game_type\n");
    for (code, date, year, _) in rows {
        // A game_year cell of S or D is the row's game_type.
        let (year, game_type) = match year {
            "S" | "D" => ("", year),
            _ => (year, "R"),
        };
        input += &format!("104,28,{code},{date},{year},{game_type}\n");
    }
    let (out, err, outcome) = run(&setup, &input, false, Shown::default());
    assert_eq!(outcome.failed, 0, "{err}");
    let mut lines = out.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = header.iter().position(|h| *h == "park").unwrap();
    let cells: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let judged: Vec<&str> = cells.iter().map(|c| c[at]).collect();
    // Mexico City's air (2,240 m up) carries a ball farther than Coors
    // Field's (1,580 m), and Coors' farther than Fenway's.
    let range = |code: &str, date: &str| -> f64 {
        let k = rows
            .iter()
            .position(|r| (r.0, r.1) == (code, date))
            .unwrap();
        cells[k][header.iter().position(|h| *h == "range").unwrap()]
            .parse()
            .unwrap()
    };
    let (mexico, coors, fenway) = (
        range("COL", "2024-04-27"),
        range("COL", "2024-04-29"),
        range("BOS", "2016-06-01"),
    );
    assert!(
        mexico > coors + 2.0 && coors > fenway + 5.0,
        "{mexico} {coors} {fenway}"
    );
    let wanted: Vec<&str> = rows.iter().map(|r| r.3).collect();
    assert_eq!(judged, wanted);
    assert!(
        err.contains(
            "10 rows played where home_team's park was not home, at no park: ATL 2016 (1 row), \
             BOS 2024, spring training (1 row), \
             COL 2024, at Estadio Alfredo Harp Helú, Mexico City, in its air (1 row), \
             HOU 2024, at Estadio Alfredo Harp Helú, Mexico City, in its air (1 row), \
             ATH 2025 (2 rows), TB 2025 (1 row), \
             TEX 2019 (1 row), TOR 2021 (1 row), TOR 2021, its date not given (1 row)"
        ),
        "{err}"
    );
    assert!(
        err.contains("ATH's Oakland Coliseum was home 1968–2024"),
        "{err}"
    );
    assert!(
        err.contains("1 row without a date (game_date, game_year) judged at a park that was not always home, or not always so walled: TB (1 row)"),
        "{err}"
    );
    // `--park` judges every row at the park asked for, whatever its date.
    let mut at_oakland = Setup::new(&preset, &parks);
    at_oakland.park = parks.parks.iter().position(|p| p.code == "ATH");
    let (out, _, _) = run(&at_oakland, &input, false, Shown::default());
    assert!(
        out.lines()
            .skip(1)
            .all(|l| l.split(',').nth(at) == Some("ATH"))
    );
    // A game_type Savant does not write is named.
    let (_, err, outcome) = run(
        &setup,
        "launch_speed,launch_angle,home_team,game_type\n104,28,BOS,Q\n",
        false,
        Shown::default(),
    );
    assert_eq!(outcome.failed, 1);
    assert!(
        err.contains("game_type = \"Q\": expected Savant's R, F, D, L, W"),
        "{err}"
    );
    // A date that is no date is named.
    let (_, err, outcome) = run(
        &setup,
        "launch_speed,launch_angle,home_team,game_date\n104,28,ATH,2025-02-30\n",
        false,
        Shown::default(),
    );
    assert_eq!(outcome.failed, 1);
    assert!(
        err.contains("game_date = \"2025-02-30\": expected a date, YYYY-MM-DD or M/D/YYYY"),
        "{err}"
    );
}
