#!/usr/bin/env python3
"""What 2025's measured swings change (issue 37, item 3; the table of
docs/bat-tracking.md, "What the measured swing changes"): a Savant export
with 2025's bat tracking put through `homerun hit --batch` twice, once as it
comes (`attack_angle`, `attack_direction` and `swing_path_tilt` measured) and
once with those three columns dropped (the swing angle at the prior, the
direction solved onto the spray, the league's tilt), as a 2024 row is solved.
By launch-angle band: the solved share, and over the rows solved both ways
the median swing angle, undercut, spin (total, backspin, sidespin), the
bat's lead and the carry (model − Statcast's distance, the impact's spin
flown). A research script (pandas, numpy; never run by the tests).

    cargo build --release
    /tmp/venv/bin/python scripts/attack_angles.py [FILE] > table.md

FILE defaults to ../shared/data/statcast-2025-bat-tracking-three-hitters.csv;
a second file (default ../shared/data/statcast-2024-04-balls-in-play.csv, a
season without measured swings) is solved the 2024 way beside it, at the
prior's ψ and at the measured swings' steeper ψ given to every row.
"""
import io
import subprocess
import sys

import numpy as np
import pandas as pd

BINARY = "target/release/homerun"
MEASURED = ["attack_angle", "attack_direction", "swing_path_tilt"]
EDGES = [-91, 10, 20, 25, 30, 35, 50, 91]
LABELS = ["< 10°", "10–20°", "20–25°", "25–30°", "30–35°", "35–50°", "50°+"]
FT = 0.3048
RPM = 60.0 / (2.0 * np.pi)
INCH = 0.0254


def solve(frame, extra=()):
    """`hit --batch` on `frame`; its rows, one per input row, in order."""
    out = subprocess.run([BINARY, "hit", "--batch", "-", "--keep", "bat_speed"] + list(extra),
                         input=frame.to_csv(index=False), capture_output=True, text=True,
                         check=True)
    rows = pd.read_csv(io.StringIO(out.stdout), low_memory=False)
    assert len(rows) == len(frame), "every row answered, in order"
    rows["solved"] = rows.solved.astype(str).str.lower() == "true"
    return rows


def main(path):
    data = pd.read_csv(path, low_memory=False)
    data = data[data.launch_speed.notna()].reset_index(drop=True)
    measured = solve(data)
    prior = solve(data.drop(columns=[c for c in MEASURED if c in data]))
    tracked = measured.bat_speed.notna()
    band = pd.cut(data.launch_angle, EDGES, labels=LABELS, right=False)
    both = tracked & measured.solved & prior.solved

    def spin(rows):
        return np.sqrt(rows["launch.spin"]**2 + rows["launch.sidespin"]**2
                       + rows["launch.gyrospin"]**2) * RPM

    print(f"`{path}`: {tracked.sum()} tracked rows; solved with the measured swing "
          f"{(tracked & measured.solved).sum()}, with the prior {(tracked & prior.solved).sum()}, "
          f"both {both.sum()}\n")
    print("| launch angle | " + " | ".join(LABELS) + " |\n|---|" + "---|" * len(LABELS))
    rows = [
        ("tracked rows", lambda b: f"{(tracked & (band == b)).sum()}"),
        ("solved, measured swing", lambda b: share(measured, tracked & (band == b))),
        ("solved, the prior", lambda b: share(prior, tracked & (band == b))),
    ]
    for name, cell in rows:
        print(f"| {name} | " + " | ".join(cell(b) for b in LABELS) + " |")
    quantities = [
        ("swing angle ψ (°)", lambda r: np.degrees(r["swing.angle"]), "{:+.1f}"),
        ("undercut (in)", lambda r: r["impact.undercut"] / INCH, "{:+.2f}"),
        ("total spin (rpm)", spin, "{:,.0f}"),
        ("backspin (rpm)", lambda r: r["launch.spin"] * RPM, "{:,.0f}"),
        ("sidespin, its size (rpm)", lambda r: r["launch.sidespin"].abs() * RPM, "{:,.0f}"),
        ("the bat's lead (°)", lambda r: np.degrees(r["swing.lead"]), "{:+.1f}"),
        ("carry, model − Statcast (ft)", lambda r: r["difference"] / FT, "{:+.1f}"),
    ]
    for name, of, fmt in quantities:
        for label, r in [("measured", measured), ("prior", prior)]:
            values = of(r)
            cells = []
            for b in LABELS:
                sel = both & (band == b) & values.notna()
                cells.append(fmt.format(values[sel].median()) if sel.sum() else "")
            print(f"| {name}, {label} | " + " | ".join(cells) + " |")
    print(f"\n(rows solved both ways by band: "
          + ", ".join(f"{b} {(both & (band == b)).sum()}" for b in LABELS) + ")")
    air = both & (data.launch_angle >= 10)
    for label, r in [("measured", measured), ("prior", prior)]:
        e = (r["difference"] / FT)[air].dropna()
        print(f"\ncarry at 10° and up, {label}: median {e.median():+.1f} ft, "
              f"median |error| {e.abs().median():.1f} ft ({len(e)} balls)")
    # A contact that grips (`bat.tangential_restitution`): the carry by band
    # over each run's own solved rows, and its median |error| at 10° and up.
    print("\nWith a contact that grips (each run over its own solved rows; carry, ft):\n")
    print("| e_T, swing | solved | " + " | ".join(LABELS[1:]) + " | median \\|e\\| |\n|---|---|"
          + "---|" * (len(LABELS) - 1) + "---|")
    for grip in ("0", "0.1", "0.2"):
        for label, frame in [("measured", data), ("prior", data.drop(columns=MEASURED))]:
            r = solve(frame, ["--set", f"bat.tangential_restitution={grip}"])
            ok = tracked & r.solved
            carry = r["difference"] / FT
            cells = [f"{carry[ok & (band == b)].median():+.1f}" for b in LABELS[1:]]
            e = carry[ok & (data.launch_angle >= 10)].abs().median()
            print(f"| {grip}, {label} | {100.0 * ok.sum() / tracked.sum():.1f} % | "
                  + " | ".join(cells) + f" | {e:.1f} |")


def one_at_a_time(path):
    """Which measurement moves the line drives: one column dropped at a
    time (the rest measured), and the prior with ψ = 14° given."""
    data = pd.read_csv(path, low_memory=False)
    data = data[data.launch_speed.notna()].reset_index(drop=True)
    line_drive = (data.launch_angle >= 10) & (data.launch_angle < 20)
    print("\n10–20°, one measurement dropped at a time (medians of each run's solved rows):\n")
    print("| swing | backspin (rpm) | carry (ft) |\n|---|---|---|")
    for label, drop, extra in [("all measured", [], []),
                               ("without attack_direction", ["attack_direction"], []),
                               ("without attack_angle", ["attack_angle"], []),
                               ("without swing_path_tilt", ["swing_path_tilt"], []),
                               ("none measured (the prior)", MEASURED, []),
                               ("none measured, ψ = 14° given", MEASURED,
                                ["--set", "bat.swing_angle=14deg"])]:
        r = solve(data.drop(columns=drop), extra)
        ok = r.bat_speed.notna() & r.solved & line_drive
        print(f"| {label} | {(r['launch.spin'] * RPM)[ok].median():,.0f} | "
              f"{(r['difference'] / FT)[ok].median():+.1f} |")


def beside(path, psi):
    """The same solve on a season without measured swings: the carry by band
    at the prior's ψ and at `psi` (°) given to every row."""
    data = pd.read_csv(path, low_memory=False)
    data = data[data.launch_speed.notna()].reset_index(drop=True)
    band = pd.cut(data.launch_angle, EDGES, labels=LABELS, right=False)
    print(f"\n`{path}`, solved the 2024 way (carry, ft; each run over its own solved rows):\n")
    print("| ψ | solved | " + " | ".join(LABELS[1:]) + " | median \\|e\\| |\n|---|---|"
          + "---|" * (len(LABELS) - 1) + "---|")
    for label, extra in [("the prior, 9.13°", []),
                         (f"{psi}° for every row", ["--set", f"bat.swing_angle={psi}deg"])]:
        r = solve(data, extra)
        tracked = r.bat_speed.notna()
        ok = tracked & r.solved
        carry = r["difference"] / FT
        cells = [f"{carry[ok & (band == b)].median():+.1f}" for b in LABELS[1:]]
        e = carry[ok & (data.launch_angle >= 10)].abs().median()
        print(f"| {label} | {100.0 * ok.sum() / tracked.sum():.1f} % | " + " | ".join(cells)
              + f" | {e:.1f} |")


def share(rows, sel):
    n = sel.sum()
    return f"{100.0 * rows.solved[sel].mean():.1f} %" if n else ""


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1
         else "../shared/data/statcast-2025-bat-tracking-three-hitters.csv")
    one_at_a_time(sys.argv[1] if len(sys.argv) > 1
                  else "../shared/data/statcast-2025-bat-tracking-three-hitters.csv")
    beside(sys.argv[2] if len(sys.argv) > 2
           else "../shared/data/statcast-2024-04-balls-in-play.csv", 14)
