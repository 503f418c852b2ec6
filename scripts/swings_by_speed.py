#!/usr/bin/env python3
"""The solved-share table of docs/bat-tracking.md ("What to trust", "The
season's bat"): a Savant export with bat tracking put through `homerun hit
--batch` at each bat given, its tracked rows' solved share by Statcast's exit
speed, and Savant's squared-up beside the model's. A convenience for
developers (never run by the tests; tests/commands/swing_found.rs checks the
columns on the committed sample).

    cargo build --release
    python3 scripts/swings_by_speed.py FILE [--dates FIRST LAST] [LABEL=--set,bat.effective_mass=0.8 ...]

--dates keeps the rows whose game_date lies in FIRST..LAST (ISO dates): the
held-out tables of docs/bat-tracking.md ("The swing plane") are the bat
fitted on one half of April 2024 (`homerun calibrate --impact` on that half,
0.8819 kg on April 1-15, 0.8857 kg on April 16-30) measured on the other,
e.g. `--dates 2024-04-16 2024-04-30 held-out=--set,bat.effective_mass=0.8819`.

Without LABEL=ARGS, three bats: the paper's (0.8 kg), the default (the row's
season's where known), and 0.8819 kg (fitted on April 1-15, 2024 alone).
"""
import csv
import io
import statistics
import subprocess
import sys

BINARY = "target/release/homerun"
BANDS = [(0, 90, "< 90"), (90, 100, "90–100"), (100, 105, "100–105"), (105, 110, "105–110"),
         (110, 999, "110+")]
DEFAULT = [
    ("the paper's bat (0.8 kg)", ["--set", "bat.effective_mass=0.8"]),
    ("the default (the row's season's bat)", []),
    ("fitted on April 1–15, 2024 (0.8819 kg)", ["--set", "bat.effective_mass=0.8819"]),
]


DATES = None


def run(path, extra):
    args = [BINARY, "hit", "--batch", path, "--keep", "launch_speed,game_date"] + extra
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode not in (0, 1):
        sys.exit(done.stderr)
    rows = [r for r in csv.DictReader(io.StringIO(done.stdout)) if r["solved"] in ("true", "false")]
    # Tracked rows only: a reason of no bat_speed or no pitch is untracked.
    rows = [r for r in rows if r["pitch.speed"] != "" and r["swing.bat_speed"] != ""]
    if DATES:
        rows = [r for r in rows if DATES[0] <= r["game_date"] <= DATES[1]]
    return rows


def table(path, variants):
    print(f"`{path}`, tracked rows by Statcast's exit speed (mph): solved share\n")
    print("| bat | " + " | ".join(b[2] for b in BANDS) + " | all |")
    print("|---" * (len(BANDS) + 2) + "|")
    for label, extra in variants:
        rows = run(path, extra)
        cells = []
        for low, high, _ in BANDS:
            band = [r for r in rows if low <= float(r["launch_speed"]) < high]
            solved = sum(r["solved"] == "true" for r in band)
            cells.append(f"{100 * solved / max(len(band), 1):.1f} % ({len(band)})")
        solved = sum(r["solved"] == "true" for r in rows)
        cells.append(f"{100 * solved / max(len(rows), 1):.1f} % ({len(rows)})")
        print(f"| {label} | " + " | ".join(cells) + " |")
    rows = run(path, [])
    both = [(float(r["impact.squared_up"]), float(r["impact.squared_up_savant"]))
            for r in rows if r["impact.squared_up"] and r["impact.squared_up_savant"]]
    savant = [float(r["impact.squared_up_savant"]) for r in rows if r["impact.squared_up_savant"]]
    if both:
        print(f"\nsquared-up (default bat): Savant's on {len(savant)} tracked rows, median "
              f"{statistics.median(savant):.3f}, {100 * sum(s >= 0.8 for s in savant) / len(savant):.1f} % "
              f"at 0.8 or more, {sum(s > 1 for s in savant)} above 1; the model's on "
              f"{len(both)} solved rows, median {statistics.median(b[0] for b in both):.3f}, "
              f"{100 * sum(b[0] >= 0.8 for b in both) / len(both):.1f} % at 0.8 or more, "
              f"{sum(b[0] > 1 for b in both)} above 1")
    found = {}
    for r in rows:
        if r["solved"] == "true":
            key = tuple(r[f"swing.from.{q}"] for q in ("angle", "contact_speed", "direction", "tilt"))
            found[key] = found.get(key, 0) + 1
    print("\nsolved rows by how (angle, contact speed, direction, tilt) were found:")
    for key, n in sorted(found.items(), key=lambda kv: -kv[1]):
        print(f"  {n:6d}  {', '.join(key)}")


if __name__ == "__main__":
    args = sys.argv[1:]
    if "--dates" in args:
        at = args.index("--dates")
        DATES = (args[at + 1], args[at + 2])
        del args[at:at + 3]
    path = args[0]
    variants = [(a.split("=", 1)[0], [x for x in a.split("=", 1)[1].split(",") if x])
                for a in args[1:]]
    table(path, variants or DEFAULT)
