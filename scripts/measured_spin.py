#!/usr/bin/env python3
"""A tracker's measured spin against Nathan's estimate, on the trackers' own balls.

Prints the table in docs/accuracy.md, "A tracker's measured spin". Each data set
in ../shared/data is flown twice by the release binary: as it comes (its
`HitSpinRate` / `HIT_SPIN_RATE`, with Trackman's `HitSpinAxis` or Yakkertech's
`yt_HitSpinComponentX/Y/Z`, read), and with the rate's column renamed so that
the spin is Nathan's estimate. On the rows with a
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
    # file, its bearing column (None: not measured), and each way of flying
    # it: its label and the columns left unread
    ("trackman-2024-25-potters-batted-balls.csv", "Bearing",
     [("Nathan's estimate", ["HitSpinRate"]), ("measured, rate and axis", [])]),
    ("yakkertech-2025-kcl-batted-balls.csv", "Bearing",
     [("Nathan's estimate", ["HitSpinRate"]), ("measured rate and axis vector", []),
      ("the rate alone, Nathan's axis",
       ["yt_HitSpinComponentX", "yt_HitSpinComponentY", "yt_HitSpinComponentZ"])]),
    ("braves-2018-04-batted-balls-hang-time.csv", None,
     [("Nathan's estimate", ["HIT_SPIN_RATE"]), ("measured rate, Nathan's axis", [])]),
]


def fly(text, keep):
    """The batch's JSON rows for `text`, with the `keep` columns kept."""
    args = [str(BINARY), "fly", "--batch", "-", "--json", "--keep", ",".join(keep)]
    out = subprocess.run(args, input=text, capture_output=True, text=True, check=True).stdout
    return [pd.json_normalize(pd.read_json(io.StringIO(out), lines=True).to_dict("records"))][0]


def main(data):
    print("| data set, rows | spin | landing bearing (°) | distance (m) | hang time (s) |")
    print("|---|---|---|---|---|")
    for name, bearing, ways in SETS:
        text = (Path(data) / name).read_text()
        hang = "HangTime" if "HangTime" in text.splitlines()[0] else "HANG_TIME"
        keep = [hang] + ([bearing] if bearing else [])
        header, rest = text.split("\n", 1)
        flown = []
        for label, unread in ways:
            renamed = header
            for column in unread:
                renamed = renamed.replace(column, column + "Unread")
            flown.append((label, fly(renamed + "\n" + rest, keep)))
        # The rows the whole measured spin flies, in the air.
        measured = flown[1][1]
        angle = np.degrees(measured["launch.angle"])
        rows = (
            measured["spin_measured"].astype(bool)
            & (angle >= 10)
            & (measured["flight.range"] > 40)
        ).to_numpy()
        for label, f in flown:
            f = f[rows]
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
