#!/usr/bin/env python3
"""The launch-angle tilt (issue 37, item 4): the tables of docs/accuracy.md,
"The launch-angle tilt: what causes it". Each season's balls flown by
`homerun fly --batch` with one assumption changed at a time, model −
Statcast's distance by launch-angle band. A research script (pandas, numpy;
never run by the tests).

    cargo build --release
    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install pandas numpy
    /tmp/venv/bin/python scripts/tilt.py [DATA_DIR] > tables.md

About a minute on 2 cores (some thirty runs of `fly --batch` and `calibrate`).

DATA_DIR (default ../shared/data) holds the files of its README:
  - braves-2018-04-batted-balls-hang-time.csv (danhogan/batted-ball @ e5ffdc8):
    2018, Trackman's measured launch direction, hang time and spin rate;
  - statcast-2024-04-balls-in-play.csv (teajay/baseball @ 8ddb6bc): April 2024;
  - statcast-2025-bat-tracking-three-hitters.csv (Matart930/Rolling-xwOBA-Dashboard
    @ f055c23): 2025, the balls in play of three hitters over a whole season;
  - trackman-2024-25-potters-batted-balls.csv (carson3m/TrackmanAnalyticsProgram
    @ cd0579a) and yakkertech-2025-kcl-batted-balls.csv
    (NoahLippman/Kernelytics-Projects @ 65df256): measured spin axes.
2019 is the committed sample of home runs (tests/data/savant_home_runs.csv).
"""
import io
import os
import re
import subprocess
import sys

import numpy as np
import pandas as pd

BINARY = "target/release/homerun"
FT = 0.3048
RPM = 60.0 / (2.0 * np.pi)
EDGES = [10, 20, 25, 30, 35, 50, 91]
LABELS = ["10–20°", "20–25°", "25–30°", "30–35°", "35–50°", "50°+"]
# Catch height of a ball caught in the air (m): a fielder's glove at the
# chest on a line drive, overhead on a fly ball. Not fitted; see the docs.
CATCH_HEIGHT = 1.5
# Nathan's C_D = 0.3008 + 0.0292·(ω/1000 rpm) at 3,000 rpm, about the median
# measured spin of balls launched at 10° and up (2018): the spin-free drag
# with Nathan's level, from his relation, not fitted.
NATHAN_3000 = 0.3008 + 0.0292 * 3.0


def band(angle_deg):
    return pd.cut(angle_deg, EDGES, labels=LABELS, right=False)


def fly(frame, args=(), keep=()):
    """Flies `frame` (a DataFrame written as CSV) through `fly --batch`;
    returns the output rows (SI) with `keep` copied."""
    text = frame.to_csv(index=False)
    cmd = [BINARY, "fly", "--batch", "-"] + list(args)
    if keep:
        cmd += ["--keep", ",".join(keep)]
    out = subprocess.run(cmd, input=text, capture_output=True, text=True, check=True)
    rows = pd.read_csv(io.StringIO(out.stdout), low_memory=False)
    assert len(rows) == len(frame), "every row flown, in order"
    return rows


def calibrate_by_band(frame, keep_cols):
    """`homerun calibrate --by band` on `frame` (with its hang times): the
    drag and lift factors each band's distances and hang times ask for. A
    diagnostic of where the model is wrong, never a model change."""
    f = frame[keep_cols].copy()
    angle = f["LAUNCH_ANGLE" if "LAUNCH_ANGLE" in f else "launch_angle"]
    f["band"] = band(angle).astype(str)
    f = f[angle >= 10]
    out = subprocess.run([BINARY, "calibrate", "-", "--by", "band"], input=f.to_csv(index=False),
                         capture_output=True, text=True, check=True)
    factors = {}
    for line in out.stdout.splitlines() + out.stderr.splitlines():
        m = re.match(r"(\S+)\s+\d+ rows\s+model.drag_scale = ([\d.]+) ± ([\d.]+)\s+"
                     r"model.lift_scale = ([\d.]+) ± ([\d.]+)", line)
        if m:
            factors[m.group(1)] = m.groups()[1:]
    return factors


def error_ft(rows):
    return (rows["range"] - rows["statcast_distance"]) / FT


def table(name, rows, error, out):
    """One line of a table: median error (ft) by band, rows, median |e|."""
    frame = pd.DataFrame({"band": band(np.degrees(rows["launch.angle"])), "e": error})
    frame = frame.dropna()
    medians = frame.groupby("band", observed=False)["e"].median()
    cells = " | ".join(f"{medians[b]:+.1f}" for b in LABELS)
    low = frame[frame.band.isin(LABELS[:2])].e.median()
    high = frame[frame.band.isin(LABELS[4:])].e.median()
    out.append(f"| {name} | {len(frame):,} | {cells} | {low - high:+.1f} | "
               f"{frame.e.abs().median():.1f} |")
    return medians


HEADER = ("| | rows | " + " | ".join(LABELS) + " | tilt (10–25° − 35°+) | median \\|e\\| |\n"
          "|---|---|" + "---|" * len(LABELS) + "---|---|")


# --- the measured spin axes -------------------------------------------------
def yakkertech_axes(data):
    y = pd.read_csv(os.path.join(data, "yakkertech-2025-kcl-batted-balls.csv"), low_memory=False)
    y = y.dropna(subset=["yt_HitSpinComponentX", "yt_HitVelocityX", "HitSpinRate"])
    y = y[y.yt_HitSpinConfidence > 0.9].copy()
    v = y[["yt_HitVelocityX", "yt_HitVelocityY", "yt_HitVelocityZ"]].to_numpy(float, copy=True)
    v /= np.linalg.norm(v, axis=1)[:, None]
    spin_cols = ["yt_HitSpinComponentX", "yt_HitSpinComponentY", "yt_HitSpinComponentZ"]
    w = y[spin_cols].to_numpy(float, copy=True)
    w /= np.linalg.norm(w, axis=1)[:, None]
    # Yakkertech's frame: X toward right field, Y toward centre field, Z up;
    # backspin is along v × z (x̂ for a ball to centre), gyrospin along v.
    back_axis = np.cross(v, [0.0, 0.0, 1.0])
    back_axis /= np.linalg.norm(back_axis, axis=1)[:, None]
    y["back"] = (w * back_axis).sum(1)
    y["gyro"] = (w * v).sum(1)
    y["band"] = band(np.degrees(np.arcsin(v[:, 2])))
    return y


def trackman_axes(data):
    t = pd.read_csv(os.path.join(data, "trackman-2024-25-potters-batted-balls.csv"),
                    low_memory=False)
    t = t.dropna(subset=["HitSpinRate", "HitSpinAxis"]).copy()
    # Trackman's HitSpinAxis: 180° is pure backspin (the clock face of a
    # pitch's axis); its cosine's opposite is the backspin's share.
    t["back"] = -np.cos(np.radians(t.HitSpinAxis))
    t["band"] = band(t.Angle)
    return t


def axes_table(data, out):
    y = yakkertech_axes(data)
    t = trackman_axes(data)
    out.append("| measured | " + " | ".join(LABELS) + " |\n|---|" + "---|" * len(LABELS))
    for name, frame, col, fmt in [
        ("Yakkertech 2025, total spin (rpm)", y, "HitSpinRate", "{:,.0f}"),
        ("Yakkertech 2025, backspin share ω_b/ω", y, "back", "{:.2f}"),
        ("Yakkertech 2025, gyrospin share \\|ω·v̂\\|/ω", y.assign(gyro=y.gyro.abs()), "gyro",
         "{:.2f}"),
        ("Trackman 2024–25, total spin (rpm)", t, "HitSpinRate", "{:,.0f}"),
        ("Trackman 2024–25, backspin share", t, "back", "{:.2f}"),
    ]:
        m = frame.groupby("band", observed=False)[col].median()
        n = frame.groupby("band", observed=False)[col].size()
        out.append(f"| {name} | " + " | ".join(fmt.format(m[b]) + f" ({n[b]})" for b in LABELS)
                   + " |")
    cells = []
    for name, frame in [("Yakkertech", y), ("Trackman", t)]:
        low = frame[frame.band == LABELS[0]]
        speeds = pd.cut(low.ExitSpeed, [0, 85, 95, 130], labels=["< 85", "85–95", "95+"])
        m = low.groupby(speeds, observed=False).back.median()
        cells.append(f"{name} " + ", ".join(f"{k} mph {v:.2f}" for k, v in m.items()))
    out.append("\nBackspin share at 10–20° by exit speed: " + "; ".join(cells) + "\n")
    return (y.groupby("band", observed=False)["back"].median(),
            t.groupby("band", observed=False)["back"].median())


# --- the seasons ------------------------------------------------------------
def season_2018(data):
    b = pd.read_csv(os.path.join(data, "braves-2018-04-batted-balls-hang-time.csv"))
    # The batter's side from where his ground balls went (the pull side);
    # the set has no `stand`.
    ground = b[b.LAUNCH_ANGLE < 10].groupby("BATTER_ID").EXIT_DIRECTION.median()
    b["stand"] = b.BATTER_ID.map(lambda i: "" if i not in ground else
                                 ("R" if ground[i] < 0 else "L"))
    keep = ["LAUNCH_ANGLE", "EXIT_SPEED", "EXIT_DIRECTION", "HIT_DISTANCE", "HANG_TIME",
            "HIT_SPIN_RATE", "PLAY_OUTCOME", "stand"]
    return b[keep].rename(columns={"HIT_SPIN_RATE": "measured_spin"})


def season_2024(data):
    cols = ["launch_speed", "launch_angle", "hit_distance_sc", "hc_x", "hc_y", "stand",
            "home_team", "plate_z", "events", "bb_type"]
    return pd.read_csv(os.path.join(data, "statcast-2024-04-balls-in-play.csv"),
                       usecols=cols, low_memory=False)


def season_2025(data):
    """Three hitters' 2025 (Altuve, Springer, Schwarber; March to November):
    a second Hawk-Eye season, read as 2024's."""
    cols = ["launch_speed", "launch_angle", "hit_distance_sc", "hc_x", "hc_y", "stand",
            "home_team", "plate_z", "events", "bb_type"]
    return pd.read_csv(os.path.join(data, "statcast-2025-bat-tracking-three-hitters.csv"),
                       usecols=cols, low_memory=False)


def season_2019():
    return pd.read_csv("tests/data/savant_home_runs.csv")


def summer_league(data):
    """The same diagnostic on Trackman's summer-league balls (2024–25, wood
    bats): each ball's measured spin and spin axis, its measured launch
    direction, distance and hang time (the tracker's)."""
    t = pd.read_csv(os.path.join(data, "trackman-2024-25-potters-batted-balls.csv"),
                    low_memory=False)
    t = t.dropna(subset=["ExitSpeed", "Angle", "Direction", "Distance", "HangTime"])
    t = t[(t.Angle >= 10) & (t.Direction.abs() < 50)].reset_index(drop=True)
    f = pd.DataFrame({"launch_speed": t.ExitSpeed, "launch_angle": t.Angle,
                      "exit_direction": t.Direction, "hit_distance": t.Distance,
                      "hang_time": t.HangTime,
                      "stand": t.BatterSide.map({"Right": "R", "Left": "L"}).fillna("")})
    base = fly(f)
    sign = np.where(base["launch.sidespin"] < 0, -1.0, 1.0)
    ok = (t.HitSpinRate.notna() & t.HitSpinAxis.notna()).to_numpy()
    w = t.HitSpinRate / RPM
    axis = np.radians(t.HitSpinAxis)
    measured = f.assign(**{"launch.spin": w * -np.cos(axis),
                           "launch.sidespin": sign * np.abs(w * np.sin(axis))})
    cols = list(f.columns)
    lines = ["Trackman's summer league (2024–25), drag / lift factors by band "
             "(`calibrate --by band`, distances and hang times):\n",
             "| spin | " + " | ".join(LABELS) + " |\n|---|" + "---|" * len(LABELS)]
    for name, frame, extra in [("Nathan's estimate", f[ok], []),
                               ("each ball's measured spin and axis", measured[ok],
                                ["launch.spin", "launch.sidespin"])]:
        k = calibrate_by_band(frame, cols + extra)
        lines.append(f"| {name} ({ok.sum()} balls) | " + " | ".join(
            f"{k[x][0]} / {k[x][2]}" if x in k else "" for x in LABELS) + " |")
    return "\n".join(lines) + "\n"


CAUGHT_2018 = ("Out", "Sacrifice")
CAUGHT_2024 = ("field_out", "sac_fly", "double_play", "sac_fly_double_play", "force_out")


def main(data):
    out = []
    ax_yak, ax_tm = axes_table(data, out)

    seasons = {
        "2018 (April 1–14, Trackman's launch direction, sea level)":
            (season_2018(data), ["measured_spin", "PLAY_OUTCOME", "HANG_TIME"]),
        "2019 (home runs, the committed sample)": (season_2019(), ["events"]),
        "2024 (March 28 – April 30)": (season_2024(data), ["events", "bb_type"]),
        "2025 (three hitters, March 27 – November 1)": (season_2025(data), ["events", "bb_type"]),
    }
    # The 2018 set's measured spin against the estimate, by band: the
    # factor that scales an estimate to the measured size (an independent
    # measurement, used on the other seasons).
    b18, _ = seasons["2018 (April 1–14, Trackman's launch direction, sea level)"]
    base18 = fly(b18, keep=["measured_spin"])
    est = np.hypot(base18["launch.spin"], base18["launch.sidespin"]) * RPM
    sized = pd.DataFrame({"band": band(np.degrees(base18["launch.angle"])),
                          "m": base18.measured_spin, "e": est})
    sized = sized[sized.m > 0]
    measured_median = sized.groupby("band", observed=False).m.median()
    out.append("| 2018, total spin (rpm), median | " + " | ".join(
        f"{sized[sized.band == b].m.median():,.0f} measured, "
        f"{sized[sized.band == b].e.median():,.0f} Nathan's" for b in LABELS) + " |\n")

    lift_2018 = {}  # the lift factor by band that 2018's hang times ask for
    for title, (frame, keep) in seasons.items():
        frame = frame.dropna(subset=[c for c in ("launch_speed", "EXIT_SPEED") if c in frame])
        frame = frame.reset_index(drop=True)
        out.append(f"**{title}**\n")
        out.append(HEADER)
        base = fly(frame, keep=keep)
        table("the default", base, error_ft(base), out)
        angle = np.degrees(base["launch.angle"])
        b = band(angle)
        spin = np.hypot(base["launch.spin"], base["launch.sidespin"])
        sign = np.where(base["launch.sidespin"] < 0, -1.0, 1.0)

        def with_side(total):
            """Nathan's backspin kept; the sidespin made up to `total` (rad/s)."""
            f = frame.copy()
            # A row without a total keeps the estimate (both cells empty).
            back = base["launch.spin"].where(pd.notna(total))
            f["launch.spin"] = back.to_numpy()
            side = np.sqrt(np.maximum(total**2 - back**2, 0.0))
            f["launch.sidespin"] = (sign * side).to_numpy()
            if "hc_x" in f:
                f["launch.direction"] = base["launch.direction"].to_numpy()
                f = f.drop(columns=["hc_x", "hc_y"])
            return fly(f, keep=keep)

        def spun(total, share):
            """The rows with their launch direction fixed at the default's
            and the spin given: total (rad/s), backspin share."""
            f = frame.copy()
            f["launch.spin"] = (total * share).to_numpy()
            f["launch.sidespin"] = (total * sign * np.sqrt(1 - share**2)).to_numpy()
            if "hc_x" in f:
                f["launch.direction"] = base["launch.direction"].to_numpy()
                f = f.drop(columns=["hc_x", "hc_y"])
            return f

        def with_spin(total, share):
            return fly(spun(total, share), keep=keep)

        if "measured_spin" in base:
            # Each ball's own measured spin; rows without one keep the estimate.
            total = base.measured_spin.where(base.measured_spin > 0) / RPM
            which = "each ball's measured spin"
        else:
            # 2018's measured median by band, against this season's estimate.
            est_median = (spin * RPM).groupby(b, observed=False).median()
            total = spin * b.map(measured_median / est_median).astype(float)
            which = "2018's measured spin by band"
        rows = with_spin(total, base["launch.spin"] / spin)
        table(f"{which}, Nathan's axis", rows, error_ft(rows), out)
        rows = with_side(total)
        table(f"{which}, Nathan's backspin, the rest sidespin", rows, error_ft(rows), out)
        for name, shares in [("Trackman's", ax_tm), ("Yakkertech's", ax_yak)]:
            share = b.map(shares).astype(float).clip(0, 1)
            rows = with_spin(total, share)
            table(f"{which}, {name} measured backspin share by band", rows, error_ft(rows), out)
            if name == "Trackman's":
                measured_axis = rows
        for name, args in [
            ("C_D without spin: Nathan's C_D at 3,000 rpm (0.3884) for every ball",
             ["--set", "model.drag=constant", "--set", f"model.drag_scale={NATHAN_3000 / 0.5}"]),
            ("Nathan's drag, the paper's lift C_L(S) (Eq. 29)",
             ["--set", "model.lift=sawicki2003"]),
        ] + ([("the spray taken as the launch direction (`--spray launch`)",
                ["--spray", "launch"]),
               ("every park's air at sea level", ["--set", "environment.elevation=0"]),
               ("every contact 1 m up", ["--set", "environment.contact_height=1"])]
              if "hc_x" in frame else []):
            rows = fly(frame, args, keep=keep)
            table(name, rows, error_ft(rows), out)
        if lift_2018 and "hc_x" in frame:
            # A held-out check: 2018's hang-time lift by band, on this season.
            f = frame.copy()
            f["model.lift_scale"] = band(f.launch_angle).map(lift_2018).astype(float).fillna(1.0)
            rows = fly(f, keep=keep)
            table("the lift by band that 2018's hang times ask for (Nathan's estimate)", rows,
                  error_ft(rows), out)
            # The same at the season's own level: the drag alone fitted by
            # `calibrate --drag-only` (one factor on every band: a level, not a shape).
            fit = subprocess.run([BINARY, "calibrate", "-", "--drag-only"],
                                 input=frame.to_csv(index=False), capture_output=True, text=True,
                                 check=True)
            level = re.search(r"model.drag_scale = ([\d.]+)", fit.stdout + fit.stderr).group(1)
            for name, g in [(f"the season's level (drag {level}, `calibrate --drag-only`)", frame),
                            ("the season's level and 2018's lift by band", f)]:
                rows = fly(g, ["--set", f"model.drag_scale={level}"], keep=keep)
                table(name, rows, error_ft(rows), out)
        # The catch: a ball caught in the air is caught above the ground;
        # its distance, were Statcast's measured at the glove, would be
        # short of the model's landing by h / tan(landing angle).
        outcome = base.get("PLAY_OUTCOME", base.get("events"))
        caught = outcome.isin(CAUGHT_2018 + CAUGHT_2024)
        if caught.any():
            short = CATCH_HEIGHT / np.tan(base["landing_angle"].abs())
            table("caught balls only (default)", base[caught], error_ft(base)[caught], out)
            table("balls not caught only (default)", base[~caught], error_ft(base)[~caught], out)
            table(f"caught balls ended {CATCH_HEIGHT} m up", base[caught],
                  error_ft(base)[caught] - short[caught] / FT, out)
        out.append("")
        if "HANG_TIME" in base:
            out.append("Drag and lift factors each band's distances and hang times ask for "
                       "(`calibrate --by band`; a diagnostic):\n")
            out.append("| spin | " + " | ".join(LABELS) + " |\n|---|" + "---|" * len(LABELS))
            cols = ["LAUNCH_ANGLE", "EXIT_SPEED", "EXIT_DIRECTION", "HIT_DISTANCE", "HANG_TIME",
                    "stand"]
            measured = frame.measured_spin.where(frame.measured_spin > 0) / RPM
            for name, f in [
                ("Nathan's estimate (the default)", frame),
                ("each ball's measured spin, Nathan's axis",
                 spun(measured, base["launch.spin"] / spin)),
                ("each ball's measured spin, Trackman's backspin share",
                 spun(measured, b.map(ax_tm).astype(float).clip(0, 1))),
                ("each ball's measured spin, Yakkertech's backspin share",
                 spun(measured, b.map(ax_yak).astype(float).clip(0, 1))),
            ]:
                f = f[f.measured_spin > 0] if name != "Nathan's estimate (the default)" else f
                extra = [c for c in ("launch.spin", "launch.sidespin") if c in f]
                k = calibrate_by_band(f, cols + extra)
                if name == "Nathan's estimate (the default)":
                    lift_2018.update({x: float(k[x][2]) for x in k})
                out.append(f"| {name} | " + " | ".join(
                    f"{k[x][0]} / {k[x][2]}" if x in k else "" for x in LABELS) + " |")
            out.append("")
            # Within 10–20°, by exit speed: is the lift's excess a speed's?
            out.append("10–20°, Nathan's estimate, by exit speed (drag / lift):\n")
            low = frame[(frame.LAUNCH_ANGLE >= 10) & (frame.LAUNCH_ANGLE < 20)].copy()
            speeds = pd.cut(low.EXIT_SPEED, [0, 85, 95, 102, 130],
                            labels=["< 85 mph", "85–95", "95–102", "102+"])
            cells = []
            for s in speeds.cat.categories:
                k = calibrate_by_band(low[speeds == s], cols)
                drag, _, lift, lift_sd = k["10–20°"]
                cells.append(f"{s}: {drag} / {lift} ± {lift_sd}")
            out.append("; ".join(cells) + "\n")
            out.append("Hang time, model − measured (s), by band:\n")
            out.append("| | " + " | ".join(LABELS) + " |\n|---|" + "---|" * len(LABELS))
            dt = pd.DataFrame({"band": b, "dt": base.flight_time - base.HANG_TIME,
                               "caught": caught})
            dt["measured_axis"] = measured_axis.flight_time - base.HANG_TIME
            for name, sel, col in [("the default, all", dt, "dt"),
                                   ("the default, caught", dt[dt.caught], "dt"),
                                   ("the default, not caught", dt[~dt.caught], "dt"),
                                   ("measured spin, Trackman's backspin share", dt,
                                    "measured_axis")]:
                m = sel.groupby("band", observed=False)[col].median()
                out.append(f"| {name} | " + " | ".join(f"{m[x]:+.2f}" for x in LABELS) + " |")
            out.append("")
    out.append(summer_league(data))
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "../shared/data")
