//! Each park in its own air, settled from the row's own flight
//! ([`crate::park_air`]), against every park flown.

use super::*;

/// Each park judges a row on a flight in its own air: the parks a row
/// clears, settled from the row's own flight where the air cannot move
/// the verdict, are those it clears flown in every park's air
/// (`--all-parks` flies them all), and not those of its one flight.
#[test]
fn each_park_counts_a_row_in_its_own_air_as_a_flight_there_would() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let codes = ["BOS", "COL", "NYY", "AZ", "HOU", "SEA"];
    let mut next = uniform(11);
    let mut input = String::from(
        "launch.speed,launch.angle,launch.spin,launch.direction,launch.sidespin,home_team\n",
    );
    // Fly balls near the walls: 95-115 mph, 20-40°, pulled, hooked and
    // sliced to the foul poles.
    for i in 0..900 {
        let launch = [
            42.5 + 9.0 * next(),
            0.35 + 0.35 * next(),
            150.0 + 250.0 * next(),
            1.6 * next() - 0.8,
            400.0 * next() - 200.0,
        ];
        let cells: Vec<String> = launch.iter().map(f64::to_string).collect();
        input += &format!("{},{}\n", cells.join(","), codes[i % codes.len()]);
    }
    let counts = |set: &dyn Fn(&mut Setup)| -> Vec<usize> {
        let mut setup = Setup::new(&preset, &parks);
        set(&mut setup);
        let (out, _, _) = run(&setup, &input, false, Shown::default());
        let mut lines = out.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let at = header.iter().position(|h| *h == "parks_cleared").unwrap();
        lines
            .map(|line| line.split(',').nth(at).unwrap().parse().unwrap())
            .collect()
    };
    let settled = counts(&|_| {});
    let flown = counts(&|setup| setup.all_parks = true);
    let one_flight = counts(&|setup| setup.one_flight = true);
    assert_eq!(settled.len(), 900);
    assert_eq!(settled, flown);
    // The rows reach the walls, some parks but not all, and the air moves
    // the count of many.
    let between = settled.iter().filter(|&&n| n > 0 && n < 30).count();
    assert!(between > 200, "{between} rows clear some parks but not all");
    let moved = settled
        .iter()
        .zip(&one_flight)
        .filter(|(a, b)| a != b)
        .count();
    assert!(moved > 50, "the air moved {moved} counts");
    // And a row alone, each park flown in its air, counts the same.
    let setup = Setup::new(&preset, &parks);
    for (line, want) in input.lines().skip(1).zip(&settled).step_by(37) {
        let cells: Vec<f64> = line
            .split(',')
            .take(5)
            .map(|c| c.parse().unwrap())
            .collect();
        let code = line.rsplit(',').next().unwrap();
        let park = parks.parks.iter().find(|p| p.code == code).unwrap();
        let mut scene = launched(&preset.scene, &cells.try_into().unwrap());
        model::park::GivenWeather::default().park_air(&mut scene.environment, park.elevation);
        assert_eq!(
            alone(&scene, &park.fence, &setup.parks.parks).parks_cleared,
            *want
        );
    }
}

/// A ball that clears a park's wall by a micrometre in that park's air, or
/// misses it by one, gets the verdict `fly` gives it there: the flights
/// that settle parks fly at the solve's precision (some 1e-5 m off the
/// readout's), and a verdict nearer than [`park_air::VERDICT_SLACK`] is
/// flown again at the readout's.
#[test]
fn a_ball_on_the_top_of_a_wall_is_judged_as_it_is_alone() {
    let preset = preset::load("fly-ball", None).unwrap();
    let parks = preset::parks::all(None).unwrap();
    let options = Purpose::Readout.flight_options();
    let given = model::park::GivenWeather::default();
    let home = parks.parks.iter().find(|p| p.code == "BOS").unwrap();
    let mut input = String::from(
        "launch.speed,launch.angle,launch.spin,launch.direction,launch.sidespin,home_team\n",
    );
    let mut wanted = Vec::new();
    for (k, code) in ["COL", "NYY", "SEA", "HOU"].iter().enumerate() {
        let k = k as f64;
        let index = parks.parks.iter().position(|p| p.code == *code).unwrap();
        let launch = |speed: f64| [speed, 0.5 + 0.03 * k, 200.0, 0.3 * k - 0.45, 0.0];
        // The ball's height over the wall there, in that park's air.
        let margin = |speed: f64| {
            let mut scene = launched(&preset.scene, &launch(speed));
            given.park_air(&mut scene.environment, home.elevation);
            model::many::judged_in_own_air(&scene, &parks.parks, given, &options)[index]
                .margin
                .unwrap_or(f64::NAN)
        };
        // Bisection on the launch speed onto the wall's top.
        let (mut low, mut high) = (30.0, 60.0);
        assert!(margin(low) < 0.0 && margin(high) > 0.0, "{code}");
        while high - low > 1e-13 * high {
            let middle = 0.5 * (low + high);
            if margin(middle) > 0.0 {
                high = middle;
            } else {
                low = middle;
            }
        }
        for speed in [low, high] {
            let over = margin(speed);
            assert!(over.abs() < 1e-6, "{code}: {over}");
            let cells: Vec<String> = launch(speed).iter().map(f64::to_string).collect();
            input += &format!("{},BOS\n", cells.join(","));
            let mut scene = launched(&preset.scene, &launch(speed));
            given.park_air(&mut scene.environment, home.elevation);
            wanted.push(alone(&scene, &home.fence, &parks.parks).parks_cleared);
        }
    }
    let setup = Setup::new(&preset, &parks);
    let (out, _, _) = run(&setup, &input, false, Shown::default());
    let mut lines = out.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let at = header.iter().position(|h| *h == "parks_cleared").unwrap();
    let counted: Vec<usize> = lines
        .map(|line| line.split(',').nth(at).unwrap().parse().unwrap())
        .collect();
    assert_eq!(counted, wanted);
}

/// The bounds that settle parks were measured in still air: a row in a
/// wind (which changes how much the density moves a flight: a 27 mph wind
/// moved 23 verdicts of 40,000 fly balls past them) is flown in every
/// park's air.
#[test]
fn a_row_in_a_wind_is_flown_in_every_parks_air() {
    let preset = preset::load("fly-ball", None).unwrap();
    let mut scene = preset.scene;
    for (key, value) in [("launch.direction", "0.2"), ("launch.sidespin", "-50")] {
        scene.set_text(key, value).unwrap();
    }
    assert!(park_air::settles(&scene));
    scene.environment.wind = -12.0;
    assert!(!park_air::settles(&scene));
}
