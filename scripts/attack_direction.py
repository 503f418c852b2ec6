#!/usr/bin/env python3
"""The bat's heading table of docs/bat-tracking.md ("The bat's heading"): a
2025 Savant export with `attack_direction` put through `homerun hit --batch`,
and for each solved row with hit coordinates the model's launch direction
against the spray (Statcast's hc_x/hc_y), signed toward each batter's
opposite field (+); by launch angle, by batter and pitcher hand, and the
least-squares line of each against the measured attack direction. The launch
direction is no target where `attack_direction` is measured (the bat's
direction is the measured one), so it is the model's prediction. A
convenience for developers (never run by the tests).

    cargo build --release
    python3 scripts/attack_direction.py ../shared/data/statcast-2025-bat-tracking-three-hitters.csv
"""
import csv
import io
import math
import statistics
import subprocess
import sys

BINARY = "target/release/homerun"
KEEP = ("launch_angle,attack_direction,stand,p_throws,player_name,hc_x,hc_y,"
        "intercept_ball_minus_batter_pos_x_inches")
INTERCEPT = [(0, 32), (32, 38), (38, 44), (44, 99)]
BANDS = [(-90, -10), (-10, 10), (10, 25), (25, 50), (50, 91)]


def spray(row):
    """Statcast's spray angle (deg, + toward right field)."""
    return math.degrees(math.atan((float(row["hc_x"]) - 125.42) / (198.27 - float(row["hc_y"]))))


def line(xs, ys):
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return my - slope * mx, slope


def main(path):
    done = subprocess.run([BINARY, "hit", "--batch", path, "--keep", KEEP],
                          capture_output=True, text=True)
    if done.returncode not in (0, 1):
        sys.exit(done.stderr)
    summary = next(l for l in done.stderr.splitlines() if "swings: solved" in l)
    print(summary.split(";")[0].replace("homerun: ", ""))
    rows = []
    for r in csv.DictReader(io.StringIO(done.stdout)):
        if r["solved"] != "true" or r["hc_x"] in ("", "NA") or r["attack_direction"] in ("", "NA"):
            continue
        hand = 1 if r["stand"] == "R" else -1
        model = math.degrees(float(r["launch.direction"])) * hand
        real = spray(r) * hand
        intercept = r["intercept_ball_minus_batter_pos_x_inches"]
        intercept = float(intercept) if intercept not in ("", "NA") else None
        rows.append((float(r["launch_angle"]), model, real, float(r["attack_direction"]),
                     r["player_name"], r["stand"], r["p_throws"], intercept))
    print(f"\n{len(rows)} solved rows with hit coordinates; degrees, + toward the batter's opposite field\n")
    print("| launch angle | rows | model's launch − spray, median | median \\|…\\| |")
    print("|---|---|---|---|")
    for low, high in BANDS:
        band = [m - s for a, m, s, *_ in rows if low <= a < high]
        if band:
            print(f"| {low}° to {high}° | {len(band)} | {statistics.median(band):+.1f}° "
                  f"| {statistics.median(abs(x) for x in band):.1f}° |")
    every = [m - s for _, m, s, *_ in rows]
    print(f"| all | {len(every)} | {statistics.median(every):+.1f}° "
          f"| {statistics.median(abs(x) for x in every):.1f}° |")
    print("\n| batter | pitcher throws | rows | model − spray, median |")
    print("|---|---|---|---|")
    groups = {}
    for _, m, s, _, name, stand, throws, _ in rows:
        groups.setdefault((name, stand, throws), []).append(m - s)
    for (name, stand, throws), values in sorted(groups.items()):
        print(f"| {name} ({stand}) | {throws} | {len(values)} | {statistics.median(values):+.1f}° |")
    ground_to_fly = [(d, m, s) for a, m, s, d, *_ in rows if -10 <= a < 50]
    d = [x[0] for x in ground_to_fly]
    print("\nLaunch angles −10° to 50°, against the attack direction D (deg, + opposite field):")
    for label, values in (("spray", [x[2] for x in ground_to_fly]),
                          ("model's launch direction", [x[1] for x in ground_to_fly])):
        intercept, slope = line(d, values)
        print(f"- {label}: {intercept:+.1f}° + {slope:.2f}·D")
    print("\nLaunch angles −10° to 50°, by Statcast's intercept_ball_minus_batter_pos_x_inches:\n")
    print("| intercept x (in) | rows | model − spray, median |")
    print("|---|---|---|")
    for low, high in INTERCEPT:
        band = [m - s for a, m, s, *_, x in rows if -10 <= a < 50 and x is not None and low <= x < high]
        if band:
            print(f"| {low} to {high} | {len(band)} | {statistics.median(band):+.1f}° |")


if __name__ == "__main__":
    main(sys.argv[1])
