#!/usr/bin/env python3
"""A Statcast-like batch for timing `homerun fly --batch` (issue 18): batted
balls with Statcast's spread of launches, written with homerun's own column
names in SI. A convenience for developers, never run by the tests; the rows
are seeded, so that before/after timings fly the same balls.

    python3 scripts/batch_rows.py planar 200000 > /tmp/planar.csv
    python3 scripts/batch_rows.py spray 200000 > /tmp/spray.csv
    python3 scripts/batch_rows.py savant 200000 > /tmp/savant.csv
    time RAYON_NUM_THREADS=2 target/release/homerun fly --preset fly-ball \
        --batch /tmp/planar.csv > /dev/null

planar: launch.speed, launch.angle, launch.spin (m/s, rad, rad/s), in the
        plane (the fly-ball preset's Nathan drag and lift).
spray:  the same with launch.direction and launch.sidespin: 3-D flights.
savant: a Savant export's own columns (launch_speed in mph, launch_angle in
        degrees, hc_x, hc_y, stand, home_team) with quoted text columns
        holding commas ("Last, First", `des`), as Savant writes them: each
        row's spin estimated, its launch direction solved and its park's air.
"""
import math
import random
import sys

TEAMS = ["BOS", "NYY", "COL", "SF", "LAD", "CHC", "HOU", "MIN", "SEA", "TEX",
         "ATL", "MIA", "AZ", "ATH", "TB", "TOR"]
NAMES = ["Judge, Aaron", "Ohtani, Shohei", "Alonso, Pete", "Betts, Mookie",
         "Soto, Juan", "Trout, Mike"]


def launch(rng):
    """Speed (mph), angle (degrees) and backspin (rpm), spread as Statcast's
    balls in play are: ~88 ± 14 mph, ~12 ± 25 degrees; backspin rising with
    the angle (Nathan's relation) with scatter."""
    speed = min(max(rng.gauss(88.0, 14.0), 30.0), 120.0)
    angle = min(max(rng.gauss(12.0, 25.0), -60.0), 75.0)
    spin = min(max(-763.0 + 120.0 * max(angle, 5.0) + rng.gauss(0.0, 400.0), 200.0), 4500.0)
    return speed, angle, spin


def main():
    kind = sys.argv[1] if len(sys.argv) > 1 else "planar"
    rows = int(sys.argv[2]) if len(sys.argv) > 2 else 200_000
    rng = random.Random(18)
    out = sys.stdout
    if kind == "planar":
        out.write("launch.speed,launch.angle,launch.spin\n")
    elif kind == "spray":
        out.write("launch.speed,launch.angle,launch.spin,launch.direction,launch.sidespin\n")
    elif kind == "savant":
        out.write("game_date,player_name,launch_speed,launch_angle,hc_x,hc_y,stand,"
                  "home_team,des\n")
    else:
        sys.exit(f"batch_rows.py: kind {kind!r}: expected planar, spray or savant")
    lines = []
    for i in range(rows):
        speed, angle, spin = launch(rng)
        si = (speed * 0.44704, math.radians(angle), spin * math.tau / 60.0)
        if kind == "planar":
            lines.append("%.4f,%.6f,%.3f\n" % si)
        elif kind == "spray":
            direction = math.radians(rng.uniform(-44.0, 44.0))
            sidespin = rng.gauss(0.0, 100.0)
            lines.append("%.4f,%.6f,%.3f,%.6f,%.3f\n" % (si + (direction, sidespin)))
        else:
            spray = math.radians(rng.uniform(-44.0, 44.0))
            reach = rng.uniform(60.0, 160.0)
            hc_x = 125.42 + reach * math.sin(spray)
            hc_y = 198.27 - reach * math.cos(spray)
            name = rng.choice(NAMES)
            lines.append('"2024-%02d-%02d","%s","%.1f","%d","%.2f","%.2f","%s","%s",'
                         '"%s homers (%d) on a fly ball, to %s field.  "\n'
                         % (4 + i % 6, 1 + i % 28, name, speed, round(angle), hc_x, hc_y,
                            rng.choice("RL"), rng.choice(TEAMS), name.split(", ")[1],
                            1 + i % 40, "left" if spray < 0 else "right"))
        if len(lines) >= 10_000:
            out.write("".join(lines))
            lines = []
    out.write("".join(lines))


if __name__ == "__main__":
    main()
