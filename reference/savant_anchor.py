"""The anchor for issue 16: real home runs from a Baseball Savant export, flown
with Alan Nathan's batted-ball calculator as pybaseball implements it
(pybaseball.analysis.trajectories.BattedBallTrajectory), his spin estimate
from launch angle, direction and batter side, and each park's elevation.
Standard air otherwise (pybaseball's defaults: 70 F, 29.92 inHg, 50 % RH, no
wind). Research only: it needs pybaseball (pip), never runs in CI, and prints
fixtures the Rust tests read. docs/savant-sample.md and docs/spin-estimate.md
say where the data and the relation come from.

    python3 reference/savant_anchor.py sample BIG.csv > tests/data/savant_home_runs.csv
    python3 reference/savant_anchor.py rows tests/data/savant_home_runs.csv \
        > tests/data/savant_home_runs_pybaseball.csv
    python3 reference/savant_anchor.py anchor BIG.csv [more.csv ...]
"""
import csv
import math
import statistics
import sys
from functools import partial

from pybaseball.analysis.trajectories import BattedBallTrajectory, EnvironmentalParameters
from scipy.integrate import solve_ivp

FT = 0.3048
MPH = 0.44704

# Savant's hit coordinates of home plate (Jim Albert's and pybaseball's
# add_spray_angle constants); the phi = atan((hc_x - X)/(Y - hc_y)).
PLATE_HC_X, PLATE_HC_Y = 125.42, 198.27

# Park elevations (ft), sheet "Elevations" of Nathan's calculator
# (TrajectoryCalculator-new-3D-May2021.xlsx), keyed by Statcast home_team.
ELEVATION_FT = {
    "LAA": 151, "AZ": 1086, "ARI": 1086, "ATL": 1001, "BAL": 33, "BOS": 21,
    "CWS": 595, "CHC": 595, "CIN": 535, "CLE": 653, "COL": 5190, "DET": 600,
    "MIA": 10, "HOU": 45, "KC": 865, "LAD": 515, "MIL": 597, "MIN": 815,
    "NYY": 55, "NYM": 10, "OAK": 3, "ATH": 3, "PHI": 20, "PIT": 780, "SD": 23,
    "SEA": 10, "SF": 0, "STL": 460, "TB": 15, "TEX": 545, "TOR": 270, "WSH": 35,
}

# Columns the test sample keeps, with Savant's own names, in Savant's order.
SAMPLE_COLUMNS = [
    "game_date", "player_name", "batter", "events", "description", "des", "stand",
    "home_team", "away_team", "bb_type", "game_year", "hc_x", "hc_y",
    "hit_distance_sc", "launch_speed", "launch_angle", "launch_speed_angle",
]
SAMPLE_EVERY = 17  # every 17th row of the export, from its first row


def nathan_spin(launch_angle, direction, stand):
    """Backspin and sidespin (rpm) in Nathan's convention: sheet
    BattedBallTrajectory-1, cells G4 and G5, '=-763+120*theta+21*phi*sign' and
    '=-sign*849-94*phi' with sign = +1 for R, -1 for L. Nathan's sidespin > 0
    swerves toward the left-field line."""
    side = 1.0 if stand == "R" else -1.0
    back = -763.0 + 120.0 * launch_angle + 21.0 * direction * side
    sidespin = -side * 849.0 - 94.0 * direction
    return back, sidespin


def spray(hc_x, hc_y):
    return math.degrees(math.atan((hc_x - PLATE_HC_X) / (PLATE_HC_Y - hc_y)))


def number(text):
    text = text.strip()
    if text in ("", "null", "NA", "NaN"):
        return None
    return float(text)


def read_rows(path):
    with open(path, newline="", encoding="utf-8-sig") as f:
        reader = csv.reader(f)
        header = next(reader)
        index = {}
        for i, name in enumerate(header):
            index.setdefault(name, i)  # Savant repeats pitcher and fielder_2
        for line, fields in enumerate(reader, start=2):
            yield line, {name: fields[i] for name, i in index.items() if i < len(fields)}


_CALCULATORS = {}


def calculator(elevation_ft):
    if elevation_ft not in _CALCULATORS:
        _CALCULATORS[elevation_ft] = BattedBallTrajectory(
            env_parameters=EnvironmentalParameters(elevation_ft=elevation_ft))
    return _CALCULATORS[elevation_ft]


def fly(speed_mph, angle, direction, back, side, elevation_ft, tight=True):
    """Landing (distance ft, bearing deg, time s) of pybaseball's calculator.
    tight: its own equations of motion (trajectory_fun) under DOP853 at
    rtol = atol = 1e-10 with the landing found as the event z = 0; otherwise
    get_trajectory as shipped (RK45, max_step 0.01 s, the first point below
    z = 0 taken as the landing)."""
    calc = calculator(elevation_ft)
    spin = math.hypot(back, side)
    spin_angle = math.degrees(math.atan2(side, back))
    if not tight:
        traj = calc.get_trajectory(speed_mph, angle, direction, spin, spin_angle)
        last = traj.iloc[-1]
        return math.hypot(last.x, last.y), math.degrees(math.atan2(last.x, last.y)), last.t
    rhs = partial(calc.trajectory_fun, spin=spin, spin_angle=spin_angle,
                  launch_angle=angle, launch_direction_angle=direction)
    v0 = speed_mph * calc.env_parameters.unit_conversions.MPH_TO_FTS
    a, d = math.radians(angle), math.radians(direction)
    start = list(calc.initial_position) + [v0 * math.cos(a) * math.sin(d),
                                           v0 * math.cos(a) * math.cos(d), v0 * math.sin(a)]

    def ground(t, u):
        return u[2]

    ground.terminal, ground.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 30.0), start, method="DOP853", rtol=1e-10, atol=1e-10,
                    events=ground)
    x, y = sol.y_events[0][0][0], sol.y_events[0][0][1]
    return math.hypot(x, y), math.degrees(math.atan2(x, y)), float(sol.t_events[0][0])


def inputs(row):
    """The calculator's inputs from one Savant row, or None when a field is
    missing (no launch_speed, no hit coordinates, unknown park)."""
    speed, angle = number(row.get("launch_speed", "")), number(row.get("launch_angle", ""))
    hc_x, hc_y = number(row.get("hc_x", "")), number(row.get("hc_y", ""))
    stand, park = row.get("stand", "").strip(), row.get("home_team", "").strip()
    if None in (speed, angle, hc_x, hc_y) or stand not in ("R", "L") or park not in ELEVATION_FT:
        return None
    direction = spray(hc_x, hc_y)
    back, side = nathan_spin(angle, direction, stand)
    return speed, angle, direction, back, side, ELEVATION_FT[park]


def sample(path):
    """Every SAMPLE_EVERY-th row of the export, its fields kept as they are
    written there (quotes and "null" included), SAMPLE_COLUMNS only."""
    with open(path, newline="", encoding="utf-8-sig") as f:
        lines = f.read().splitlines()
    header = next(csv.reader([lines[0]]))
    keep = [header.index(c) for c in SAMPLE_COLUMNS]
    out = sys.stdout
    for n, line in enumerate(lines):
        if n > 0 and (n - 1) % SAMPLE_EVERY:
            continue
        raw = split_raw(line)
        assert len(raw) == len(header), (n, len(raw))
        out.write(",".join(raw[i] for i in keep) + "\n")


def split_raw(line):
    """Fields of one CSV line with their quotes, as written."""
    fields, field, quoted = [], [], False
    for ch in line:
        if ch == '"':
            quoted = not quoted
        if ch == "," and not quoted:
            fields.append("".join(field))
            field = []
        else:
            field.append(ch)
    fields.append("".join(field))
    return fields


def rows(path):
    """Per-row reference for the committed sample."""
    w = csv.writer(sys.stdout, lineterminator="\n")
    sys.stdout.write("# generated by: python3 reference/savant_anchor.py rows "
                     "tests/data/savant_home_runs.csv (pybaseball's BattedBallTrajectory, "
                     "Nathan's spin estimate, park elevation, 70 F, 29.92 inHg, 50 % RH)\n")
    sys.stdout.write("# row = line in savant_home_runs.csv (header = line 1); directions "
                     "and sidespin + toward right field (homerun's convention); direction = "
                     "the Savant spray taken as the launch direction; launch_* = the launch "
                     "direction whose landing bearing is that spray; distances in ft, blank "
                     "where the row has no input or no measurement\n")
    w.writerow(["row", "speed_mps", "launch_angle_deg", "direction_deg", "backspin_rpm",
                "sidespin_rpm", "elevation_m", "distance_3d_ft", "distance_2d_ft",
                "distance_shipped_ft", "bearing_3d_deg", "hang_time_3d_s", "launch_direction_deg",
                "launch_backspin_rpm", "launch_sidespin_rpm", "distance_launch_ft",
                "hit_distance_sc"])
    for line, row in read_rows(path):
        got = inputs(row)
        measured = number(row.get("hit_distance_sc", ""))
        if got is None:
            w.writerow([line] + [""] * 15 + ["" if measured is None else f"{measured:g}"])
            continue
        speed, angle, direction, back, side, elev = got
        d3, bearing, hang = fly(speed, angle, direction, back, side, elev)
        d2 = fly(speed, angle, direction, back, 0.0, elev)[0]
        shipped = fly(speed, angle, direction, back, side, elev, tight=False)[0]
        launch, lb, ls = launched_toward(speed, angle, direction, row["stand"].strip(), elev)
        dl = fly(speed, angle, launch, lb, ls, elev)[0]
        w.writerow([line, f"{speed * MPH:.4f}", f"{angle:g}", f"{direction:.4f}",
                    f"{back:.1f}", f"{-side:.1f}", f"{elev * FT:.2f}", f"{d3:.2f}",
                    f"{d2:.2f}", f"{shipped:.2f}", f"{bearing:.3f}", f"{hang:.3f}",
                    f"{launch:.4f}", f"{lb:.1f}", f"{-ls:.1f}", f"{dl:.2f}",
                    "" if measured is None else f"{measured:g}"])


BANDS = [(-90, 20, "< 20"), (20, 25, "20-25"), (25, 30, "25-30"), (30, 35, "30-35"),
         (35, 90, ">= 35")]


def summary(label, errors):
    if not errors:
        return f"{label:>8}  n=0"
    med = statistics.median(errors)
    mad = statistics.median(abs(e) for e in errors)
    spread = statistics.median(abs(e - med) for e in errors)
    return (f"{label:>8}  n={len(errors):5d}  median {med:+6.1f}  median|e| {mad:5.1f}"
            f"  spread {spread:5.1f}  mean {statistics.fmean(errors):+6.1f}")


def launched_toward(speed, angle, spray_deg, stand, elev):
    """Launch direction whose landing bearing is the Savant spray (the hit
    coordinates mark where the ball came down, not where it left the bat),
    with Nathan's spin re-estimated from that direction each time."""
    direction = spray_deg
    for _ in range(6):
        back, side = nathan_spin(angle, direction, stand)
        bearing = fly(speed, angle, direction, back, side, elev)[1]
        direction += spray_deg - bearing
        if abs(spray_deg - bearing) < 0.01:
            break
    back, side = nathan_spin(angle, direction, stand)
    return direction, back, side


def suspect(row, pair_counts):
    """Rows a comparison may leave out: Savant's fill-in exit speed and angle
    for untracked balls (the same pair ten times or more in the file),
    inside-the-park home runs, and neutral-site games (this export's
    player_name holds the venue)."""
    pair = (row.get("launch_speed"), row.get("launch_angle"))
    venue = row.get("player_name", "")
    neutral = any(v in venue for v in ("London", "Estadio", "Tokyo", "TD Ameritrade"))
    return pair_counts.get(pair, 0) >= 10 or "inside-the-park" in row.get("des", "") or neutral


def anchor(paths):
    results = []  # (angle, measured, d3, d2, shipped, solved, suspect)
    skipped = 0
    for path in paths:
        all_rows = [row for _, row in read_rows(path)]
        pair_counts = {}
        for row in all_rows:
            pair = (row.get("launch_speed"), row.get("launch_angle"))
            pair_counts[pair] = pair_counts.get(pair, 0) + 1
        for row in all_rows:
            got = inputs(row)
            measured = number(row.get("hit_distance_sc", ""))
            if got is None or measured is None or row.get("events") != "home_run":
                skipped += 1
                continue
            speed, angle, direction, back, side, elev = got
            d3 = fly(speed, angle, direction, back, side, elev)[0]
            d2 = fly(speed, angle, direction, back, 0.0, elev)[0]
            shipped = fly(speed, angle, direction, back, side, elev, tight=False)[0]
            launch, b, s = launched_toward(speed, angle, direction, row["stand"].strip(), elev)
            solved = fly(speed, angle, launch, b, s, elev)[0]
            results.append((angle, measured, d3, d2, shipped, solved, suspect(row, pair_counts)))
    n_suspect = sum(r[6] for r in results)
    print(f"flown {len(results)} ({n_suspect} suspect), skipped {skipped} "
          "(no speed, hit coordinates, distance or park)")
    for k, name in ((2, "3-D, Nathan's spin, tight"), (3, "2-D (no sidespin), tight"),
                    (4, "3-D as shipped (RK45 max_step 0.01, first point below 0)"),
                    (5, "3-D, launch direction solved so the landing bearing is the spray")):
        for subset, keep in (("all rows", lambda r: True), ("without suspect rows", lambda r: not r[6])):
            chosen = [r for r in results if keep(r)]
            print(f"\n{name}, {subset}: model - hit_distance_sc (ft)")
            print(summary("all", [r[k] - r[1] for r in chosen]))
            for lo, hi, label in BANDS:
                print(summary(label, [r[k] - r[1] for r in chosen if lo <= r[0] < hi]))


if __name__ == "__main__":
    command, args = sys.argv[1], sys.argv[2:]
    {"sample": lambda: sample(args[0]), "rows": lambda: rows(args[0]),
     "anchor": lambda: anchor(args)}[command]()
