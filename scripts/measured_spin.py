#!/usr/bin/env python3
"""A tracker's measured spin against Nathan's estimate, on the trackers' own balls.

Prints the table in docs/accuracy.md, "A tracker's measured spin". Each data set
in ../shared/data is flown twice by the release binary: as it comes (its
`HitSpinRate` / `HIT_SPIN_RATE`, and Trackman's `HitSpinAxis`, read), and with
those columns renamed so that the spin is Nathan's estimate. On the rows with a
measured spin, in the air (10° and up, landing past 40 m), the medians of
|model - tracker| for the landing bearing, the distance and the hang time.

    python3 scripts/measured_spin.py ../shared/data    (numpy, pandas; ~20 s)
"""

import io
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd

BINARY = Path(__file__).resolve().parent.parent / "target" / "release" / "homerun"

SETS = [
    # file, its spin columns, its bearing column (None: not measured)
    ("trackman-2024-25-potters-batted-balls.csv", ["HitSpinRate", "HitSpinAxis"], "Bearing"),
    ("yakkertech-2025-kcl-batted-balls.csv", ["HitSpinRate"], "Bearing"),
    ("braves-2018-04-batted-balls-hang-time.csv", ["HIT_SPIN_RATE"], None),
]


def fly(text, keep):
    """The batch's JSON rows for `text`, with the `keep` columns kept."""
    args = [str(BINARY), "fly", "--batch", "-", "--json", "--keep", ",".join(keep)]
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True).stdout
    return [pd.json_normalize(pd.read_json(io.StringIO(out), lines=True).to_dict("records"))][0]


def main(data):
    print("| data set, rows | spin | landing bearing (°) | distance (m) | hang time (s) |")
    print("|---|---|---|---|---|")
    for name, spin_columns, bearing in SETS:
        text = (Path(data) / name).read_text()
        hang = "HangTime" if "HangTime" in text.splitlines()[0] else "HANG_TIME"
        keep = [hang] + ([bearing] if bearing else [])
        measured = fly(text, keep)
        header, rest = text.split("\n", 1)
        for column in spin_columns:
            header = header.replace(column, column + "Unread")
        estimated = fly(header + "\n" + rest, keep)
        angle = np.degrees(measured["launch.angle"])
        rows = (
            measured["spin_measured"].astype(bool)
            & (angle >= 10)
            & (measured["flight.range"] > 40)
        ).to_numpy()
        for label, flown in [("Nathan's estimate", estimated), ("measured", measured)]:
            f = flown[rows]
            cells = []
            if bearing:
                kept = pd.to_numeric(f[f"kept.{bearing}"], errors="coerce")
                cells.append(np.nanmedian(np.abs(np.degrees(f["flight.direction"]) - kept)))
            else:
                cells.append(np.nan)
            cells.append(np.nanmedian(np.abs(f["statcast.difference"])))
            time = pd.to_numeric(f[f"kept.{hang}"], errors="coerce")
            cells.append(np.nanmedian(np.abs(f["flight.flight_time"] - time)))
            shown = ["" if np.isnan(c) else f"{c:.2f}" for c in cells]
            print(f"| {name.split('-batted')[0]}, {rows.sum()} | {label} | " + " | ".join(shown) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "../shared/data")
