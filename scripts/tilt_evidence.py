#!/usr/bin/env python3
"""The launch-angle tilt, session 20 (issue 37, item 4): the tables of
docs/accuracy.md, "The tilt, checked again". Each table tests one more
assumption against measurements, with no constant fitted to distances.
A research script (pandas, numpy; never run by the tests); it reuses
scripts/tilt.py's readers and tables.

    cargo build --release
    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install pandas numpy
    /tmp/venv/bin/python scripts/tilt_evidence.py [DATA_DIR] > tables.md

About two minutes on 2 cores. DATA_DIR (default ../shared/data) holds the
files of its README (provenance there and in scripts/tilt.py).

The tables:
  1. Nathan's sidespin relation against Trackman's measured sidespin and
     launch direction (summer league 2024-25), and the hook it makes;
  2. the backspin a line drive gets: the model's against both trackers;
  3. a spin that decays in flight (the paper's Sec. II.D: 30-50 s);
  4. a caught ball measured at the glove (MLB's Statcast glossary: hang
     time and hit distance end at "contact by a fielder");
  5. 2018's drag / lift by band, by the play's outcome;
  6. 2024's error by exit speed and band, at the defaults and at the
     season's level (`calibrate --drag-only`);
  7. held out within 2024: calibrated on March 28 - April 14, measured on
     April 15 - 30;
  8. what half a degree of launch angle does to the bands;
  9. lift and drag measured on Trackman's own fitted trajectories (summer
     league), against Nathan's, by band and by S;
 10. that measured C_L(S) given, in flight, to 2018, 2019 and 2024.
"""
import os
import re
import subprocess
import sys

import numpy as np
import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tilt as T  # noqa: E402  (the readers, bands and table of scripts/tilt.py)

BINARY = T.BINARY
SPEEDS = [0, 85, 95, 105, 130]
SPEED_LABELS = ["< 85 mph", "85–95", "95–105", "105+"]


def band_row(name, values, fmt="{:+.1f}"):
    return f"| {name} | " + " | ".join(
        fmt.format(values[b]) if b in values and pd.notna(values[b]) else "" for b in T.LABELS) + " |"


BAND_HEADER = "| | " + " | ".join(T.LABELS) + " |\n|---|" + "---|" * len(T.LABELS)


def summer_league(data):
    t = pd.read_csv(os.path.join(data, "trackman-2024-25-potters-batted-balls.csv"),
                    low_memory=False)
    t = t.dropna(subset=["ExitSpeed", "Angle", "Direction", "Bearing", "Distance"])
    keep = (t.Angle >= 10) & (t.Direction.abs() < 45) & t.BatterSide.isin(["Right", "Left"])
    return t[keep].reset_index(drop=True)


def sidespin_relation(data, out):
    """Table 1: sidespin against the launch direction, measured (Trackman's
    HitSpinRate and HitSpinAxis, its Direction) and Nathan's."""
    t = summer_league(data)
    side = np.where(t.BatterSide == "Right", 1.0, -1.0)
    f = pd.DataFrame({"launch_speed": t.ExitSpeed, "launch_angle": t.Angle,
                      "exit_direction": t.Direction,
                      "stand": t.BatterSide.map({"Right": "R", "Left": "L"})})
    rows = T.fly(f)
    b = T.band(t.Angle)
    # Trackman's axis: 180° is pure backspin. homerun's sidespin is + when the
    # ball curves toward right field: the sign that makes the measured
    # sidespin curve the ball the way the measured curve (Bearing −
    # Direction) goes (their correlation is −0.81 with the sine as it is).
    raw = t.HitSpinRate * np.sin(np.radians(t.HitSpinAxis))
    curve = t.Bearing - t.Direction
    ok = raw.notna()
    sign = np.sign(np.corrcoef(raw[ok], curve[ok])[0, 1])
    measured = sign * raw * side  # homerun's sidespin times the batter's side
    phi = t.Direction * side      # the launch direction, + toward the batter's opposite field
    out.append("**1. Nathan's sidespin relation against Trackman's measurements** (summer league "
               "2024–25: each ball's measured launch direction `Direction`, sidespin from "
               "`HitSpinRate`·sin `HitSpinAxis`; a least-squares line by band, "
               "sidespin·s = a + b·φ·s, rpm and degrees, s = +1 right-handed, −1 left):\n")
    out.append("| | " + " | ".join(T.LABELS) + " |\n|---|" + "---|" * len(T.LABELS))
    cells, counts = {}, {}
    for x in T.LABELS:
        sel = (b == x) & ok
        counts[x] = int(sel.sum())
        if sel.sum() >= 10:
            a_b = np.linalg.lstsq(np.vstack([np.ones(sel.sum()), phi[sel]]).T, measured[sel],
                                  rcond=None)[0]
            cells[x] = f"{a_b[0]:+.0f} {a_b[1]:+.1f}·φ ({counts[x]})"
    out.append(band_row("measured: a + b·φ (balls)", cells, "{}"))
    out.append(band_row("Nathan's relation", {x: "+849 +94.0·φ" for x in T.LABELS}, "{}"))
    model_curve = (np.degrees(rows.direction) - t.Direction) * side
    g = pd.DataFrame({"b": b, "m": curve * side, "model": model_curve})
    out.append(band_row("the curve, Bearing − Direction, + toward the opposite field, measured (°)",
                        g.groupby("b", observed=False).m.median()))
    out.append(band_row("the same, the model at the measured direction and Nathan's spin (°)",
                        g.groupby("b", observed=False).model.median()))
    out.append("")


def backspin_table(data, out):
    """Table 2: the backspin (rpm) a ball gets, by band: the model's (the
    defaults) against the trackers' (each ball's spin times its backspin
    share, then the median)."""
    y = T.yakkertech_axes(data)
    t = T.trackman_axes(data)
    out.append("**2. Backspin by band, median rpm** (the trackers: each ball's spin × its "
               "backspin share; the share of balls with topspin in brackets):\n")
    out.append(BAND_HEADER)
    for name, fr in [("Yakkertech 2025", y), ("Trackman 2024–25", t)]:
        bs = fr.HitSpinRate * fr.back
        g = pd.DataFrame({"b": fr.band, "bs": bs}).groupby("b", observed=False).bs
        med, top = g.median(), g.apply(lambda s: (s < 0).mean())
        out.append(band_row(name, {x: f"{med[x]:,.0f} ({top[x]:.2f})" for x in T.LABELS}, "{}"))
    for name, frame in [("the model, 2018 (at `EXIT_DIRECTION`)", T.season_2018(data)),
                        ("the model, 2024 (direction solved)", season_2024(data))]:
        r = T.fly(frame)
        g = pd.DataFrame({"b": T.band(np.degrees(r["launch.angle"])),
                          "bs": r["launch.spin"] * T.RPM,
                          "share": r["launch.spin"] / np.hypot(r["launch.spin"],
                                                               r["launch.sidespin"])})
        med = g.groupby("b", observed=False).median()
        out.append(band_row(name + ", backspin (share)",
                            {x: f"{med.bs[x]:,.0f} ({med.share[x]:.2f})" for x in T.LABELS},
                            "{}"))
    out.append("")


def season_2024(data):
    cols = ["launch_speed", "launch_angle", "hit_distance_sc", "hc_x", "hc_y", "stand",
            "home_team", "plate_z", "events", "bb_type", "game_date"]
    f = pd.read_csv(os.path.join(data, "statcast-2024-04-balls-in-play.csv"), usecols=cols,
                    low_memory=False)
    return f.dropna(subset=["launch_speed"]).reset_index(drop=True)


def tilt_row(name, rows, error, out):
    return T.table(name, rows, error, out)


def hang_row(name, rows, out):
    dt = (rows.flight_time - rows.HANG_TIME).groupby(
        T.band(np.degrees(rows["launch.angle"])), observed=False).median()
    out.append(f"| {name}: hang time, model − measured (s) | | "
               + " | ".join(f"{dt[x]:+.2f}" for x in T.LABELS) + " | | |")


def drag_level(frame, args=()):
    fit = subprocess.run([BINARY, "calibrate", "-", "--drag-only"] + list(args),
                         input=frame.to_csv(index=False), capture_output=True, text=True,
                         check=True)
    return float(re.search(r"model.drag_scale = ([\d.]+)", fit.stdout + fit.stderr).group(1))


def spin_decay(data, out):
    """Table 3: the spin decays as ω₀·e^(−t/τ) (`model.spin_decay`)."""
    out.append("**3. A spin that decays in flight** (`--set model.spin_decay=τ`; the paper's "
               "§II.D puts τ at 30–50 s for a baseball; model − measured, ft):\n")
    out.append(T.HEADER)
    seasons = [("2018", T.season_2018(data), ["HANG_TIME"]),
               ("2019 HR", T.season_2019(), []),
               ("2024", season_2024(data), [])]
    for name, frame, keep in seasons:
        for tau in (0, 50, 30):
            rows = T.fly(frame, ["--set", f"model.spin_decay={tau}"], keep=keep)
            label = f"{name}, τ = {tau} s" if tau else f"{name}, no decay (the default)"
            tilt_row(label, rows, T.error_ft(rows), out)
            if keep:
                hang_row(label, rows, out)
    out.append("")


def glove(data, out):
    """Table 4: a caught ball's flight ended at the glove. 2018: each caught
    row's flight started h lower (contact 1 m − h), which ends it h above the
    ground, in distance and hang time alike (the model's air does not change
    over a few metres). 2024: the distance h/tan(landing angle) shorter."""
    f = T.season_2018(data).reset_index(drop=True)
    caught = f.PLAY_OUTCOME.isin(T.CAUGHT_2018)
    cols = ["LAUNCH_ANGLE", "EXIT_SPEED", "EXIT_DIRECTION", "HIT_DISTANCE", "HANG_TIME", "stand",
            "environment.contact_height"]
    out.append("**4. A caught ball measured at the glove** (hang time and hit distance end at "
               "\"contact by a fielder\"; model − measured, ft; the glove h above the ground):\n")
    out.append(T.HEADER)
    lifts = []
    for h in (0.0, 0.5, 1.0):
        g = f.copy()
        g["environment.contact_height"] = np.where(caught, 1.0 - h, 1.0)
        rows = T.fly(g, keep=["HANG_TIME"])
        tilt_row(f"2018, caught balls ended {h} m up", rows, T.error_ft(rows), out)
        hang_row(f"2018, caught balls ended {h} m up", rows, out)
        k = T.calibrate_by_band(g, cols)
        lifts.append((h, k))
    frame = season_2024(data)
    level = drag_level(frame)
    for args, name in [([], "defaults"), (["--set", f"model.drag_scale={level}"],
                                          f"the season's level, drag {level}")]:
        rows = T.fly(frame, args, keep=["events"])
        caught24 = rows.events.isin(T.CAUGHT_2024)
        for h in (0.0, 1.0, 1.5):
            short = np.where(caught24, h / np.tan(rows.landing_angle.abs()) / T.FT, 0.0)
            tilt_row(f"2024, {name}, caught balls ended {h} m up", rows,
                     T.error_ft(rows) - short, out)
    out.append("\n2018's drag / lift factors by band (`calibrate --by band`, distances and hang "
               "times), the caught balls ended at the glove:\n")
    out.append(BAND_HEADER)
    for h, k in lifts:
        out.append(band_row(f"glove {h} m up", {x: f"{k[x][0]} / {k[x][2]} ± {k[x][3]}"
                                                for x in k}, "{}"))
    out.append("")


def by_outcome(data, out):
    """Table 5: 2018's drag / lift by band, the balls split by the play."""
    f = T.season_2018(data).reset_index(drop=True)
    cols = ["LAUNCH_ANGLE", "EXIT_SPEED", "EXIT_DIRECTION", "HIT_DISTANCE", "HANG_TIME", "stand"]
    out.append("**5. 2018's drag / lift by band and by the play** (`calibrate --by band`; "
               "3.0000 is the fit's bound):\n")
    out.append(BAND_HEADER)
    rows = T.fly(f, keep=["HANG_TIME", "PLAY_OUTCOME"])
    b = T.band(np.degrees(rows["launch.angle"]))
    for name, sel in [("all", f.index >= 0),
                      ("caught (out, sacrifice)", f.PLAY_OUTCOME.isin(T.CAUGHT_2018)),
                      ("singles", f.PLAY_OUTCOME == "Single"),
                      ("doubles and triples", f.PLAY_OUTCOME.isin(["Double", "Triple"]))]:
        k = T.calibrate_by_band(f[sel], cols)
        out.append(band_row(name, {x: f"{k[x][0]} / {k[x][2]}" for x in k}, "{}"))
        err = pd.DataFrame({"b": b, "e": T.error_ft(rows), "dt": rows.flight_time - rows.HANG_TIME})
        m = err[sel].groupby("b", observed=False).median()
        n = err[sel].groupby("b", observed=False).size()
        out.append(band_row(f"{name}: distance (ft), hang time (s), balls",
                            {x: f"{m.e[x]:+.1f}, {m.dt[x]:+.2f}, {n[x]}" for x in T.LABELS
                             if n[x]}, "{}"))
    out.append("")


def by_speed(data, out):
    """Table 6: 2024's error by exit speed within each band."""
    frame = season_2024(data)
    level = drag_level(frame)
    out.append("**6. 2024 by exit speed** (model − measured, median ft; rows: exit speed):\n")
    for args, name in [([], "the defaults"),
                       (["--set", f"model.drag_scale={level}"],
                        f"the season's level (drag {level})")]:
        rows = T.fly(frame, args)
        d = pd.DataFrame({"b": T.band(np.degrees(rows["launch.angle"])),
                          "v": pd.cut(rows["launch.speed"] / 0.44704, SPEEDS,
                                      labels=SPEED_LABELS),
                          "e": T.error_ft(rows)})
        p = d.pivot_table(index="v", columns="b", values="e", aggfunc="median", observed=False)
        out.append(f"{name}:\n\n" + BAND_HEADER.replace("| |", "| exit speed |", 1))
        for v in SPEED_LABELS:
            out.append(band_row(v, p.loc[v]))
        out.append("")


def held_out(data, out):
    """Table 7: calibrated on the first half of April 2024, measured on the
    second (the months the issue's table uses are kept apart)."""
    frame = season_2024(data)
    first = frame[frame.game_date < "2024-04-15"].reset_index(drop=True)
    second = frame[frame.game_date >= "2024-04-15"].reset_index(drop=True)
    out.append("**7. Held out within 2024** (calibrated on March 28 – April 14, "
               f"{len(first):,} rows; measured on April 15–30, {len(second):,} rows):\n")
    out.append(T.HEADER)
    rows = T.fly(second)
    tilt_row("the defaults", rows, T.error_ft(rows), out)
    fit = subprocess.run([BINARY, "calibrate", "-"], input=first.to_csv(index=False),
                         capture_output=True, text=True, check=True)
    text = fit.stdout + fit.stderr
    drag = re.search(r"model.drag_scale = ([\d.]+)", text).group(1)
    lift = re.search(r"model.lift_scale = ([\d.]+)", text).group(1)
    for name, args in [(f"calibrated (drag {drag}, lift {lift})",
                        ["--set", f"model.drag_scale={drag}", "--set", f"model.lift_scale={lift}"]),
                       (f"calibrated, τ = 30 s (the same factors)",
                        ["--set", f"model.drag_scale={drag}", "--set", f"model.lift_scale={lift}",
                         "--set", "model.spin_decay=30"])]:
        rows = T.fly(second, args, keep=["events"])
        tilt_row(name, rows, T.error_ft(rows), out)
        caught = rows.events.isin(T.CAUGHT_2024)
        short = np.where(caught, 1.0 / np.tan(rows.landing_angle.abs()) / T.FT, 0.0)
        tilt_row(name + ", caught balls ended 1.0 m up", rows, T.error_ft(rows) - short, out)
    out.append("")


def angle_sensitivity(data, out):
    """Table 8: what half a degree of launch angle does. Every ball flown
    at its measured angle + δ and binned by its measured angle: not a
    correction (no offset of any tracker is known here), the size of the
    lever."""
    out.append("**8. Half a degree of launch angle** (each ball flown at its measured angle + δ, "
               "binned by the measured angle; model − measured, ft):\n")
    out.append(T.HEADER)
    for name, frame, column, deltas in [
            ("2018", T.season_2018(data), "LAUNCH_ANGLE", (0.0, -0.5, -1.0)),
            ("2024", season_2024(data), "launch_angle", (0.0, -0.5, -1.0)),
            ("2025 (three hitters)", T.season_2025(data).dropna(subset=["launch_speed"])
             .reset_index(drop=True), "launch_angle", (0.0, -0.5, -1.0, -1.5))]:
        for delta in deltas:
            g = frame.copy()
            g[column] = g[column] + delta
            rows = T.fly(g, keep=["HANG_TIME"] if "HANG_TIME" in g else [])
            rows["launch.angle"] = np.radians(frame[column].to_numpy())
            label = f"{name}, δ = {delta:+.1f}°"
            tilt_row(label, rows, T.error_ft(rows), out)
            if "HANG_TIME" in rows:
                hang_row(label, rows, out)
    out.append("")


# Trackman's hit trajectory: x(t), y(t), z(t) as polynomials of degree 8
# (ft, s; x toward centre field, y up, z toward the side). Their first
# derivative at 0 is the reported exit speed, angle and direction (checked:
# within 0.07° and 0.01 mph on every ball).
TRAJECTORY = [[f"HitTrajectory{axis}c{i}" for i in range(9)] for axis in "XYZ"]
GRAVITY_FT = 32.174
# The summer league's air: 1.18 kg/m³ (about 25 °C near sea level; the files
# carry no weather). It sets the level of C_D and C_L measured below, not
# their shape: the ratio to Nathan's by band or by S moves by the same factor.
AIR_DENSITY = 1.18
BALL_RADIUS_M = 0.0366
BALL_MASS = 0.145


def nathan_lift(s):
    """Nathan's C_L = 1.120·S/(0.583 + 2.333·S), as the model has it."""
    return 1.120 * s / (0.583 + 2.333 * s)


def trackman_aero(data, window=(0.15, 0.85)):
    """C_D and C_L measured on each summer-league ball from Trackman's own
    fitted trajectory: the acceleration less gravity, along −v̂ (drag) and
    across v̂ (lift), at 15 instants over `window` of the tracked flight
    (15 % to 85 %), the medians; S from the measured spin and the speed
    there."""
    t = pd.read_csv(os.path.join(data, "trackman-2024-25-potters-batted-balls.csv"),
                    low_memory=False)
    flat = [c for axis in TRAJECTORY for c in axis]
    t = t.dropna(subset=flat + ["Angle", "ExitSpeed", "HangTime", "HitSpinRate"])
    t = t[t.Angle >= 10].reset_index(drop=True)
    c = np.stack([t[axis].to_numpy(float) for axis in TRAJECTORY], 1)  # ball, axis, power
    powers = np.arange(9)
    velocity_c = c[..., 1:] * powers[1:]
    accel_c = velocity_c[..., 1:] * powers[1:-1]
    k = AIR_DENSITY * np.pi * BALL_RADIUS_M**2 / (2 * BALL_MASS) * 0.3048  # 1/ft
    tracked = (t.LastTrackedDistance / t.Distance).clip(0, 1).fillna(1.0)
    end = (t.HangTime * tracked).to_numpy()
    cd, cl, speed = [], [], []
    for share in np.linspace(window[0], window[1], 15):
        at = share * end
        v = sum(velocity_c[..., i] * at[:, None] ** i for i in range(8))
        a = sum(accel_c[..., i] * at[:, None] ** i for i in range(7))
        a[:, 1] += GRAVITY_FT
        sp = np.linalg.norm(v, axis=1)
        along = -(a * v).sum(1) / sp
        across = np.linalg.norm(a + along[:, None] * v / sp[:, None], axis=1)
        cd.append(along / (k * sp**2))
        cl.append(across / (k * sp**2))
        speed.append(sp)
    t = t.copy()  # one block, not the file's hundreds of columns appended to
    t = t.assign(cd=np.median(cd, 0), cl=np.median(cl, 0), speed=np.median(speed, 0))
    t = t.assign(S=(BALL_RADIUS_M / 0.3048) * t.HitSpinRate * np.pi / 30 / t.speed)
    return t.assign(lift_ratio=t.cl / nathan_lift(t.S),
                    drag_ratio=t.cd / (0.3008 + 0.0292 * t.HitSpinRate / 1000),
                    band=T.band(t.Angle))


def fit_lift(t):
    """C_L = a·S/(b + S), Nathan's form, least squares on the measured
    balls (b on a grid, a linear)."""
    s, y = t.S.to_numpy(), t.cl.to_numpy()
    best = None
    for b in np.linspace(0.05, 2.0, 391):
        x = s / (b + s)
        a = (x * y).sum() / (x * x).sum()
        r = ((y - a * x) ** 2).sum()
        if best is None or r < best[0]:
            best = (r, a, b)
    return best[1], best[2]


def measured_lift(data, out):
    """Table 9: the lift and drag Trackman's trajectories measure, by band
    and by S; and table 10: that C_L(S) given to the MLB seasons."""
    t = trackman_aero(data)
    out.append("**9. Lift and drag measured on Trackman's trajectories** (summer league 2024–25, "
               f"{len(t)} balls at 10° and up with a trajectory and a measured spin; C_L and C_D "
               f"at air {AIR_DENSITY} kg/m³; Nathan's at the measured spin and the speed "
               "mid-flight):\n")
    out.append(BAND_HEADER)
    g = t.groupby("band", observed=False)
    out.append(band_row("balls", g.size(), "{:d}"))
    out.append(band_row("S mid-flight", g.S.median(), "{:.2f}"))
    out.append(band_row("C_L measured / Nathan's C_L(S)", g.lift_ratio.median(), "{:.2f}"))
    out.append(band_row("C_D measured / Nathan's C_D(ω)", g.drag_ratio.median(), "{:.2f}"))
    low = t[t.band == T.LABELS[0]]
    by_speed = low.groupby(pd.cut(low.ExitSpeed, [0, 80, 90, 100, 130],
                                  labels=["< 80 mph", "80–90", "90–100", "100+"]), observed=False)
    out.append("\nAt 10–20°, C_L measured / Nathan's by exit speed: " + ", ".join(
        f"{k} {v:.2f} ({n})" for (k, v), n in zip(by_speed.lift_ratio.median().items(),
                                                   by_speed.size())) + ".")
    edges = [0, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.7, 1.0, 3.0]
    labels = [f"{lo}–{hi}" for lo, hi in zip(edges[:-1], edges[1:])]
    g = t.groupby(pd.cut(t.S, edges, labels=labels), observed=False)
    out.append("\nBy S:\n\n| S | " + " | ".join(labels) + " |\n|---|" + "---|" * len(labels))
    for name, col, fmt in [("balls", None, "{:d}"), ("C_L measured", "cl", "{:.3f}"),
                           ("Nathan's C_L(S)", None, "{:.3f}"),
                           ("measured / Nathan's", "lift_ratio", "{:.2f}"),
                           ("launch angle (median °)", "Angle", "{:.0f}")]:
        if name == "balls":
            vals = g.size()
        elif col is None:
            vals = nathan_lift(g.S.median())
        else:
            vals = g[col].median()
        out.append(f"| {name} | " + " | ".join(fmt.format(vals[x]) for x in labels) + " |")
    robust = [("instants at 25–75 % of the flight", trackman_aero(data, (0.25, 0.75))),
              ("instants at 5–50 % (its first half)", trackman_aero(data, (0.05, 0.5))),
              ("balls tracked to 95 % of their distance or more",
               t[t.LastTrackedDistance >= 0.95 * t.Distance])]
    coarse = [0, 0.2, 0.3, 0.5, 0.7, 3.0]
    names = [f"{lo}–{hi}" for lo, hi in zip(coarse[:-1], coarse[1:])]
    out.append("\nThe same ratio, measured / Nathan's, other ways (balls in brackets):\n\n| S | "
               + " | ".join(names) + " |\n|---|" + "---|" * len(names))
    for name, frame in [("15–85 % (as above)", t)] + robust:
        g = frame.groupby(pd.cut(frame.S, coarse, labels=names), observed=False)
        m, n = g.lift_ratio.median(), g.size()
        out.append(f"| {name} | " + " | ".join(f"{m[x]:.2f} ({n[x]})" for x in names) + " |")
    a, b = fit_lift(t)
    out.append(f"\nNathan's form fitted to these balls: C_L = {a:.3f}·S/({b:.3f} + S) (Nathan's: "
               "0.480·S/(0.250 + S)): a slope at small S of "
               f"{a / b:.2f} against Nathan's 1.92.\n")
    # Table 10: the fitted C_L(S) on the MLB seasons, in flight. Each row's
    # launch (speed, angle, direction, backspin, sidespin, as the defaults
    # give them) flown twice by `lockstep_flights` below, with Nathan's C_L(S)
    # and with the fitted one; the difference in range and in flight time is
    # added to the binary's own flight. (The difference is taken in sea-level
    # air from 1 m; the binary's flights are in each park's air from the
    # pitch's height.)
    out.append("**10. That C_L(S) given to the MLB seasons** (in flight: the change it makes to "
               "each row's range and flight time, added to the defaults'; model − measured, "
               "ft):\n")
    out.append(T.HEADER)
    for name, frame, keep in [("2018", T.season_2018(data), ["HANG_TIME"]),
                              ("2019 HR", T.season_2019(), []),
                              ("2024", season_2024(data), [])]:
        base = T.fly(frame, keep=keep)
        tilt_row(f"{name}, Nathan's C_L(S) (the default)", base, T.error_ft(base), out)
        if keep:
            hang_row(f"{name}, Nathan's C_L(S)", base, out)
        launch = [base[c].to_numpy(float) for c in ("launch.speed", "launch.angle",
                                                      "launch.direction", "launch.spin",
                                                      "launch.sidespin")]
        nathan = lockstep_flights(*launch, nathan_lift)
        fitted = lockstep_flights(*launch, lambda s: a * s / (b + s))
        if name == "2018":
            off = np.nanmedian(np.abs(nathan[0] - base.range.to_numpy())) / T.FT
            out.append(f"| (the lock-step flights against the binary's, 2018: median "
                       f"\\|Δrange\\| {off:.2f} ft) | | | | | | | | | |")
        rows = base.assign(range=base.range + (fitted[0] - nathan[0]),
                           flight_time=base.flight_time + (fitted[1] - nathan[1]))
        tilt_row(f"{name}, the summer league's C_L(S)", rows, T.error_ft(rows), out)
        if keep:
            hang_row(f"{name}, the summer league's C_L(S)", rows, out)
    out.append("")


def lockstep_flights(speed, angle, direction, backspin, sidespin, lift, dt=0.004):
    """Range (m) and flight time (s) of many flights at once: Nathan's drag,
    C_L = lift(S), the spin vector fixed in space (DESIGN.md's "Three
    dimensions"), the paper's ball, 15 °C, 1013.25 hPa, 50 % at sea level,
    from 1 m up; classical RK4 in steps of `dt`, the landing interpolated."""
    t_c, humidity = 15.0, 50.0
    svp = 4.5841 * np.exp((18.687 - t_c / 234.5) * t_c / (257.14 + t_c))
    rho = 1.2929 * (273.15 / (t_c + 273.15)) * (760.0 - 0.3783 * humidity / 100 * svp) / 760.0
    k = rho * np.pi * BALL_RADIUS_M**2 / (2 * BALL_MASS)
    ct, st, cp, sp_ = np.cos(angle), np.sin(angle), np.cos(direction), np.sin(direction)
    v = np.stack([speed * ct * cp, speed * st, speed * ct * sp_], 1)
    x = np.zeros_like(v)
    x[:, 1] = 1.0
    w = (backspin[:, None] * np.stack([-sp_, 0 * sp_, cp], 1)
         + sidespin[:, None] * np.stack([st * cp, -ct, st * sp_], 1))
    size = np.linalg.norm(w, axis=1)
    axis = w / np.where(size > 0, size, 1.0)[:, None]
    cd = 0.3008 + 0.0292 * size * 30 / np.pi / 1000

    def accel(v):
        air = np.linalg.norm(v, axis=1)
        cl = lift(BALL_RADIUS_M * size / air)
        a = (-k * (cd * air)[:, None] * v
             + k * (cl * air)[:, None] * np.cross(axis, v))
        a[:, 1] -= 9.81
        return a

    n = len(speed)
    landed = np.zeros(n, bool)
    reach, when = np.full(n, np.nan), np.full(n, np.nan)
    t = 0.0
    while not landed.all() and t < 15.0:
        k1 = accel(v)
        k2 = accel(v + 0.5 * dt * k1)
        k3 = accel(v + 0.5 * dt * k2)
        k4 = accel(v + dt * k3)
        x_next = x + dt / 6 * (v + 2 * (v + 0.5 * dt * k1) + 2 * (v + 0.5 * dt * k2)
                               + (v + dt * k3))
        v_next = v + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        now = ~landed & (x_next[:, 1] <= 0) & (v_next[:, 1] < 0)
        if now.any():
            f = x[now, 1] / (x[now, 1] - x_next[now, 1])
            p = x[now] + f[:, None] * (x_next[now] - x[now])
            reach[now], when[now] = np.hypot(p[:, 0], p[:, 2]), t + f * dt
            landed |= now
        x, v, t = x_next, v_next, t + dt
    return reach, when


def main(data):
    out = []
    sidespin_relation(data, out)
    backspin_table(data, out)
    spin_decay(data, out)
    glove(data, out)
    by_outcome(data, out)
    by_speed(data, out)
    held_out(data, out)
    angle_sensitivity(data, out)
    measured_lift(data, out)
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "../shared/data")
