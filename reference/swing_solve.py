"""Independent reference for the swing behind a tracked ball (issue 27,
docs/bat-tracking.md): each Statcast row of tests/data/savant_swings.csv
solved for the undercut E, the swing angle psi and the bat's direction phi
so that the 3-D impact of reference/impact3d.py (integrated over the
impulse with scipy, not the Rust core's closed forms) gives the measured
launch speed and launch angle, and the launch direction it is given: the
spray, or with --aimed FILE (line,direction) the direction whose flight
lands on the spray, as homerun finds it (tests/data/*_aimed.csv: `homerun
hit --batch FILE --json`, each solved row's launch.direction). The aiming
is homerun's, checked by its own test that the flight lands on the spray;
the impact solved toward it is checked here.

Written apart from the Rust solve:
  - the pitch at the front of the plate from its nine-parameter fit by
    numpy's polynomial roots (the smallest positive time at which
    y(t) = 50 + vy0 t + ay t^2 / 2 reaches 17/12 ft), then v0 + a t,
    Statcast's (x, y, z) made the flight frame's (z, x, y);
  - the pitch's spin rate * cos(spin_axis) (topspin positive), else the
    preset's -200 rad/s; the bat speed bat_speed in mph, unscaled;
  - the bat's tilt swing_path_tilt where the row has it, else MLB's league
    average swing path tilt, 32 degrees (MLB glossary, Swing Path (Tilt));
  - the three equations solved by scipy.optimize.root (Powell's hybrid)
    from a fan of starts, in the Rust solve's order: first off the sweet
    spot (solve_off: psi held at the preset's 0.1594, the prior, and the
    bat's speed at the contact, 0.02 to 1 times bat_speed, solved with E and
    phi); where no root is found there, psi solved at the sweet spot's
    speed (solve_sweet_spot: of the roots with |E| < r_b + r_B and psi in
    [-0.6, 1.0] rad, the one whose psi is nearest the prior).
A 2025 row that measures the sweet spot's path (attack_angle and
attack_direction, + toward the batter's opposite field) holds psi and phi
at the measured ones and solves E, the bat's speed at the contact (0.3 to
2 times bat_speed) and the bat's lead over its path (reference/impact3d.py's
bat turned in its swing plane; session 20) toward the aimed direction
(solve_measured).
A row with no root is "unsolved" here; the Rust test checks that the two
agree on which rows are solved, and on E, psi, the contact speed, phi, the
lead and the launch spin of those that are.

    python3 reference/swing_solve.py --aimed tests/data/savant_swings_aimed.csv \
        > tests/data/swing_solve_reference.csv
    python3 reference/swing_solve.py --aimed tests/data/savant_swings_off_sweet_spot_aimed.csv \
        tests/data/savant_swings_off_sweet_spot.csv > tests/data/swing_off_sweet_spot_reference.csv
    python3 reference/swing_solve.py --aimed tests/data/savant_2025_every_20th_aimed.csv \
        tests/data/savant_2025_every_20th.csv > tests/data/swing_lead_reference.csv
"""
import csv
import math
import sys

import numpy as np
from scipy.optimize import root

from impact3d import impact
from model import R_BALL, R_BAT

FT = 0.3048
MPH = 0.44704
PRIOR = 0.1594
LEAGUE_TILT = math.radians(32.0)
PRESET_SPIN = -200.0
SWING_ANGLES = (-0.6, 1.0)


def at_plate(row):
    v0 = np.array([float(row[k]) for k in ("vx0", "vy0", "vz0")])
    a = np.array([float(row[k]) for k in ("ax", "ay", "az")])
    times = np.roots([0.5 * a[1], v0[1], 50.0 - 17.0 / 12.0])
    t = min(r.real for r in times if abs(r.imag) < 1e-12 and r.real > 0)
    v = (v0 + a * t) * FT
    return np.array([v[1], v[2], v[0]])


def case_of(row, x, lead=0.0):
    undercut, swing_angle, direction = x
    rate, axis = row["release_spin_rate"], row["spin_axis"]
    spin = PRESET_SPIN
    if rate not in ("NA", "") and axis not in ("NA", ""):
        spin = float(rate) * 2 * math.pi / 60 * math.cos(math.radians(float(axis)))
    velocity = at_plate(row)
    tilt = row.get("swing_path_tilt", "NA")
    tilt = LEAGUE_TILT if tilt in ("NA", "") else math.radians(float(tilt))
    return dict(
        hand="left" if row["stand"] == "L" else "right",
        tilt=tilt, direction=direction, undercut=undercut, swing_angle=swing_angle,
        friction=0.5, pitch_speed=float(np.linalg.norm(velocity)), pitch_spin=spin,
        pitch_velocity=velocity, bat_speed=float(row["bat_speed"]) * MPH, bat_spin=0.0,
        lead=lead,
    )


# The launch direction each row is solved toward, by line: the spray, or
# where --aimed gives one.
AIMED = {}


def spray(row):
    return math.atan((float(row["hc_x"]) - 125.42) / (198.27 - float(row["hc_y"])))


def solve_sweet_spot(row):
    target = np.array([
        float(row["launch_speed"]) * MPH, math.radians(float(row["launch_angle"])),
        AIMED.get(row["_line"], spray(row))
    ])
    reach = R_BALL + R_BAT

    def residual(x):
        if abs(x[0]) >= reach * 0.999:
            return np.array([1e3, 1e3, 1e3])
        out = impact(case_of(row, x))
        return np.array([out["launch_speed"], out["launch_angle"], out["launch_direction"]]) - target

    roots = []
    attempts = 0
    for psi in (PRIOR, -0.3, 0.5, 0.8, -0.5):
        if attempts >= 6:
            break  # no root from six starts: unsolved (a row too fast or too slow)
        for undercut in (0.02, -0.02, 0.045):
            attempts += 1
            sol = root(residual, [undercut, psi, target[2]], method="hybr",
                       options={"xtol": 1e-12, "maxfev": 120})
            r = residual(sol.x)
            if (abs(r[0]) < 1e-7 and abs(r[1]) < 1e-9 and abs(r[2]) < 1e-9
                    and abs(sol.x[0]) < reach
                    and SWING_ANGLES[0] <= sol.x[1] <= SWING_ANGLES[1]):
                roots.append(sol.x)
        if roots:
            break
    if not roots:
        return None
    best = min(roots, key=lambda x: abs(x[1] - PRIOR))
    return best, impact(case_of(row, best))


def solve_off(row):
    """Off the sweet spot: psi held at the prior, the bat's speed at the
    contact (0.02 to 1 times bat_speed) the second unknown with E and phi;
    (E, psi, contact speed, phi) and the impact, or None."""
    target = np.array([
        float(row["launch_speed"]) * MPH, math.radians(float(row["launch_angle"])),
        AIMED.get(row["_line"], spray(row))
    ])
    reach = R_BALL + R_BAT
    bat = float(row["bat_speed"]) * MPH

    def case(x):
        c = case_of(row, [x[0], PRIOR, x[2]])
        c["bat_speed"] = x[1]
        return c

    def residual(x):
        if abs(x[0]) >= reach * 0.999 or not 0.02 * bat <= x[1] <= bat:
            return np.array([1e3, 1e3, 1e3])
        out = impact(case(x))
        return np.array([out["launch_speed"], out["launch_angle"], out["launch_direction"]]) - target

    for speed in (0.9 * bat, 0.5 * bat, 0.2 * bat):
        for undercut in (0.02, -0.02, 0.045):
            sol = root(residual, [undercut, speed, target[2]], method="hybr",
                       options={"xtol": 1e-12, "maxfev": 120})
            r = residual(sol.x)
            if abs(r[0]) < 1e-7 and abs(r[1]) < 1e-9 and abs(r[2]) < 1e-9:
                e, v, phi = sol.x
                return (e, PRIOR, v, phi), impact(case(sol.x))
    return None


def measured(row, column):
    cell = row.get(column, "NA")
    return None if cell in ("NA", "") else math.radians(float(cell))


def solve_measured(row):
    """A measured path (attack_angle, attack_direction): psi and phi held
    there, E, the contact speed (0.3 to 2 times bat_speed) and the bat's
    lead over its path solved; (E, psi, contact speed, phi, lead) and the
    impact, or None."""
    target = np.array([
        float(row["launch_speed"]) * MPH, math.radians(float(row["launch_angle"])),
        AIMED.get(row["_line"], spray(row))
    ])
    reach = R_BALL + R_BAT
    bat = float(row["bat_speed"]) * MPH
    psi = measured(row, "attack_angle")
    phi = measured(row, "attack_direction") * (1.0 if row["stand"] == "R" else -1.0)

    def case(x):
        c = case_of(row, [x[0], psi, phi], lead=x[2])
        c["bat_speed"] = x[1]
        return c

    def residual(x):
        if abs(x[0]) >= reach * 0.999 or not 0.3 * bat <= x[1] <= 2.0 * bat or abs(x[2]) > 1.2:
            return np.array([1e3, 1e3, 1e3])
        out = impact(case(x))
        return np.array([out["launch_speed"], out["launch_angle"], out["launch_direction"]]) - target

    for speed in (0.9 * bat, 0.5 * bat, 1.3 * bat):
        for undercut in (0.02, -0.02, 0.045):
            for lead in (0.0, 0.3):
                sol = root(residual, [undercut, speed, lead], method="hybr",
                           options={"xtol": 1e-12, "maxfev": 120})
                r = residual(sol.x)
                if abs(r[0]) < 1e-7 and abs(r[1]) < 1e-9 and abs(r[2]) < 1e-9:
                    e, v, lead = sol.x
                    return (e, psi, v, phi, lead), impact(case(sol.x))
    return None


def solve(row):
    """(E, psi, contact speed, phi, lead) and the impact, or None: a
    measured path's lead solved where the row has one; else off the sweet
    spot where a root is found there, else psi solved at the sweet spot."""
    if measured(row, "attack_angle") is not None and measured(row, "attack_direction") is not None:
        return solve_measured(row)
    found = solve_off(row)
    if found is not None:
        (e, psi, v, phi), out = found
        return (e, psi, v, phi, 0.0), out
    found = solve_sweet_spot(row)
    if found is None:
        return None
    (e, psi, phi), out = found
    return (e, psi, float(row["bat_speed"]) * MPH, phi, 0.0), out


def main():
    args = sys.argv[1:]
    aimed_from = ""
    if "--aimed" in args:
        at = args.index("--aimed")
        aimed_from = f"--aimed {args[at + 1]} "
        with open(args[at + 1], newline="") as f:
            aimed = csv.DictReader(line for line in f if not line.startswith("#"))
            AIMED.update({int(r["line"]): float(r["direction"]) for r in aimed})
        del args[at:at + 2]
    path = args.pop(0) if args and not args[0].isdigit() else "tests/data/savant_swings.csv"
    # Optionally only lines FIRST..LAST (to run in pieces): no header then.
    if len(args) == 2:
        return rows(path, int(args[0]), int(args[1]))
    print(f"# generated by: python3 reference/swing_solve.py {aimed_from}{path}")
    print(f"# line of {path}; undercut m, swing_angle, direction and lead rad, "
          "contact_speed and max_exit_speed m/s, spin rad/s")
    print("line,solved,target_direction,undercut,swing_angle,contact_speed,direction,lead,spin,"
          "sidespin,max_exit_speed")
    rows(path, 2, None)


def rows(path, first, last):
    with open(path, newline="") as f:
        for index, row in enumerate(csv.DictReader(f)):
            line = index + 2
            if line < first or (last is not None and line > last):
                continue
            row["_line"] = line
            target = AIMED.get(line, spray(row))
            found = solve(row)
            if found is None:
                print(f"{line},false,{target!r},,,,,,,,")
                continue
            x, out = found
            # The most this swing gives: centred, at the sweet spot.
            centred = impact(case_of(row, [0.0, x[1], x[3]], lead=x[4]))
            print(",".join([str(line), "true", repr(target)] + [repr(float(v)) for v in (
                *x, out["backspin"], out["sidespin"], centred["launch_speed"])]))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
