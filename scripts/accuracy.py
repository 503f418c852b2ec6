#!/usr/bin/env python3
"""The tables of docs/accuracy.md: a Savant export of home runs flown by
`homerun fly --batch` under several models, each row's model distance
against Statcast's hit_distance_sc, by launch-angle band; and the share of
home runs that clear their own park's fence. A convenience for developers
(never run by the tests; tests/accuracy.rs checks the default pipeline on
the committed sample without Python).

    cargo build --release
    python3 scripts/accuracy.py tests/data/savant_home_runs.csv
    python3 scripts/accuracy.py /work/wt/data/savant_hr_2019_benhg.csv
"""
import json
import statistics
import subprocess
import sys

# The release binary (`cargo build --release`).
BINARY = "target/release/homerun"
FT = 0.3048
BANDS = [(-90, 20, "< 20°"), (20, 25, "20–25°"), (25, 30, "25–30°"), (30, 35, "30–35°"),
         (35, 90, "≥ 35°")]
PAPER = ["--set", "model.drag=sawicki2003", "--set", "model.lift=sawicki2003"]
VARIANTS = [
    ("the paper's model, 2-D (Nathan's backspin, no sidespin)",
     PAPER + ["--set", "launch.sidespin=0"]),
    ("Nathan's, 2-D (his backspin, no sidespin)", ["--set", "launch.sidespin=0"]),
    ("Nathan's, 3-D, spray taken as the launch direction", ["--spray", "launch"]),
    ("**Nathan's, 3-D, launch direction solved (the default)**", []),
    ("the default at 70 °F (the anchor's temperature)",
     ["--set", "environment.temperature=21.1111"]),
    ("the default with Nathan's ball (5.125 oz, 9.125 in)",
     ["--set", "ball.mass=0.145295", "--set", "ball.radius=0.036890"]),
]


def fly(path, args):
    out = subprocess.run([BINARY, "fly", "--batch", path, "--json", "--keep", "hc_x,hc_y"] + args,
                         capture_output=True, text=True, check=False)
    rows = [json.loads(line) for line in out.stdout.splitlines()]
    return rows, out.stderr.strip().splitlines()[-1]


def comparable(row):
    kept = row.get("kept", {})
    spray = all(kept.get(c, "null") not in ("null", "") for c in ("hc_x", "hc_y"))
    statcast = row.get("statcast") or {}
    return spray and statcast.get("difference") is not None


def stats(errors):
    if not errors:
        return "0", "", "", ""
    m = statistics.median(errors)
    return (str(len(errors)), f"{m:+.1f}", f"{statistics.median(abs(e) for e in errors):.1f}",
            f"{statistics.median(abs(e - m) for e in errors):.1f}")


def main(path):
    print(f"`{path}`\n")
    print("| model | n | median | median \\|e\\| | spread | " +
          " | ".join(name for _, _, name in BANDS) + " |")
    print("|---|---|---|---|---|" + "---|" * len(BANDS))
    default = None
    for label, args in VARIANTS:
        rows, summary = fly(path, args)
        if not args:
            default = (rows, summary)
        used = [r for r in rows if comparable(r)]
        errors = [(r["launch"]["angle"] * 57.29577951308232, r["statcast"]["difference"] / FT)
                  for r in used]
        n, med, mad, spread = stats([e for _, e in errors])
        bands = []
        for lo, hi, _ in BANDS:
            n_b, med_b, mad_b, _ = stats([e for a, e in errors if lo <= a < hi])
            bands.append(f"{med_b} / {mad_b}")
        print(f"| {label} | {n} | {med} | {mad} | {spread} | " + " | ".join(bands) + " |")
    rows, summary = default
    used = [r for r in rows if comparable(r)]
    clears = sum(r["fence"]["outcome"] == "clears" for r in used)
    allc = sum(r["fence"]["outcome"] == "clears" for r in rows)
    print(f"\nband cells: median / median |e| (ft)\n")
    print(f"own park (default): {clears} of {len(used)} comparable rows clear "
          f"({100 * clears / len(used):.1f} %); all rows: {allc} of {len(rows)} "
          f"({100 * allc / len(rows):.1f} %)")
    outcomes = {}
    for r in used:
        outcomes[r["fence"]["outcome"]] = outcomes.get(r["fence"]["outcome"], 0) + 1
    print("outcomes (comparable rows):", outcomes)
    counts = [r["parks"]["cleared"] for r in used]
    print(f"parks cleared: median {statistics.median(counts)}, mean {statistics.fmean(counts):.1f}")
    print(summary)


if __name__ == "__main__":
    for p in sys.argv[1:]:
        main(p)
