#!/usr/bin/env python3
"""The bat's lead tables of docs/swing-3d.md and docs/bat-tracking.md (issue
37, item 3; session 20): a 2025 Savant export with `attack_direction` put
through `homerun hit --batch`, where each row's lead over its measured path
(`swing.lead`, `swing.from.lead = solved`) is the unknown that turns the
launch toward the spray. Prints, in markdown:
  - the solved share of tracked rows by Statcast's exit speed, for this
    build and (with --before BINARY, a build from before the lead: the bat
    square to its path) for the square bat;
  - the solved lead's median and quartiles, by launch angle and by where the
    ball was met (`intercept_ball_minus_batter_pos_x_inches`), with the
    least-squares line against that intercept and the correlation;
  - the rows not solved, by reason, and each with its launch, attack angle
    and tilt.
A convenience for developers (never run by the tests).

    cargo build --release
    python3 scripts/bat_lead.py ../shared/data/statcast-2025-bat-tracking-three-hitters.csv \
        [--before /path/to/homerun-before]
"""
import csv
import io
import math
import statistics
import subprocess
import sys

BINARY = "target/release/homerun"
KEEP = ("launch_speed,launch_angle,attack_angle,attack_direction,swing_path_tilt,stand,"
        "intercept_ball_minus_batter_pos_x_inches,intercept_ball_minus_batter_pos_y_inches,"
        "bat_speed")
SPEEDS = [(0, 90, "< 90"), (90, 100, "90–100"), (100, 105, "100–105"), (105, 110, "105–110"),
          (110, 999, "110+")]
ANGLES = [(-90, -10), (-10, 10), (10, 25), (25, 50), (50, 91)]
INTERCEPT = [(-99, 32), (32, 38), (38, 44), (44, 99)]


def run(binary, path):
    done = subprocess.run([binary, "hit", "--batch", path, "--keep", KEEP],
                          capture_output=True, text=True)
    if done.returncode not in (0, 1):
        sys.exit(done.stderr)
    return list(csv.DictReader(io.StringIO(done.stdout)))


def number(cell):
    return float(cell) if cell not in ("", "NA") else None


def tracked(rows):
    return [r for r in rows if r["solved"] in ("true", "false")
            and r["reason"] != "no bat_speed (the swing was not tracked)"]


def shares(rows):
    out = []
    for low, high, _ in SPEEDS + [(0, 999, "all")]:
        band = [r for r in tracked(rows) if low <= float(r["launch_speed"]) < high]
        solved = sum(r["solved"] == "true" for r in band)
        out.append(f"{100 * solved / len(band):.1f} % ({len(band)})" if band else "–")
    return out


def quartiles(values):
    q = statistics.quantiles(values, n=4)
    return f"{q[1]:+.1f}° ({q[0]:+.1f}, {q[2]:+.1f})"


def line(xs, ys):
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    sxx = sum((x - mx) ** 2 for x in xs)
    syy = sum((y - my) ** 2 for y in ys)
    return my - sxy / sxx * mx, sxy / sxx, sxy / math.sqrt(sxx * syy)


def banded(title, labels, bands, leads, column):
    """A table of the lead's median and quartiles by bands of `column`."""
    print(f"\n| {title} | " + " | ".join(labels) + " |")
    print("|---" * (len(bands) + 1) + "|")
    cells = []
    for low, high in bands:
        band = [l[0] for l in leads if low <= l[column] < high]
        cells.append(f"{quartiles(band)}, {len(band)}" if len(band) > 3 else "–")
    print("| λ, median (quartiles), rows | " + " | ".join(cells) + " |")


def main(path, before):
    rows = run(BINARY, path)
    print("Solved share of tracked rows, by Statcast's exit speed (mph):\n")
    print("| | " + " | ".join(label for *_, label in SPEEDS) + " | all |")
    print("|---" * (len(SPEEDS) + 2) + "|")
    if before:
        print("| the square bat (λ = 0; before) | " + " | ".join(shares(run(before, path))) + " |")
    print("| the lead solved (now) | " + " | ".join(shares(rows)) + " |")

    leads = []
    for r in rows:
        if r["solved"] != "true" or r["swing.from.lead"] != "solved":
            continue
        leads.append((math.degrees(float(r["swing.lead"])), float(r["launch_angle"]),
                      number(r["intercept_ball_minus_batter_pos_x_inches"]),
                      number(r["intercept_ball_minus_batter_pos_y_inches"]),
                      float(r["launch_speed"]), r["direction_from"]))
    from_counts = {}
    for r in rows:
        if r["solved"] == "true":
            from_counts[r["swing.from.lead"]] = from_counts.get(r["swing.from.lead"], 0) + 1
    print(f"\nSolved rows by how the lead was found: {from_counts}; of the solved leads, "
          f"{sum(l[5] == 'landing' for l in leads)} land on their spray "
          f"(direction_from = landing), {sum(l[5] == 'spray_unsolved' for l in leads)} "
          "spray_unsolved (the last solve kept)")
    print(f"\nThe solved lead λ (deg, + the barrel ahead of square), {len(leads)} rows: "
          f"median and quartiles {quartiles([l[0] for l in leads])}; "
          f"5th–95th percentile {statistics.quantiles([l[0] for l in leads], n=20)[0]:+.1f}° to "
          f"{statistics.quantiles([l[0] for l in leads], n=20)[-1]:+.1f}°; "
          f"beyond ±30°: {sum(abs(l[0]) > 30 for l in leads)}")
    banded("launch angle", [f"{a}° to {b}°" for a, b in ANGLES], ANGLES, leads, 1)
    met = [l for l in leads if l[2] is not None]
    banded("where the ball was met (intercept x, in)",
           [f"{a}–{b}" if a > 0 and b < 99 else (f"< {b}" if a < 0 else f"{a}+")
            for a, b in INTERCEPT], INTERCEPT, met, 2)
    for label, chosen in (("all launch angles", met),
                          ("launch angles −10° to 50°", [l for l in met if -10 <= l[1] < 50])):
        a, b, r = line([l[2] for l in chosen], [l[0] for l in chosen])
        ay, by, ry = line([l[3] for l in chosen if l[3] is not None],
                          [l[0] for l in chosen if l[3] is not None])
        print(f"\n{label} ({len(chosen)} rows): λ = {a:+.1f}° {b:+.3f}°/in · intercept x, "
              f"correlation {r:+.2f}; against intercept y {by:+.3f}°/in, correlation {ry:+.2f}")

    print("\nNot solved (tracked rows):\n")
    reasons = {}
    for r in tracked(rows):
        if r["solved"] == "false":
            reasons.setdefault(r["reason"], []).append(r)
    for reason, band in sorted(reasons.items(), key=lambda kv: -len(kv[1])):
        print(f"- {len(band)} {reason}:")
        for r in band:
            shortfall = f", shortfall {float(r['shortfall']):+.2f} m/s" if r["shortfall"] else ""
            print(f"  - line {r['line']}: {float(r['launch_speed']):.1f} mph at "
                  f"{float(r['launch_angle']):.0f}°, bat {float(r['bat_speed']):.1f} mph, "
                  f"attack angle {float(r['attack_angle']):.1f}°, tilt "
                  f"{float(r['swing_path_tilt']):.1f}°, intercept x "
                  f"{r['intercept_ball_minus_batter_pos_x_inches'][:5]} in{shortfall}")


if __name__ == "__main__":
    args = sys.argv[1:]
    before = None
    if "--before" in args:
        i = args.index("--before")
        before = args[i + 1]
        del args[i:i + 2]
    main(args[0], before)
