#!/usr/bin/env python3
"""The sidespin table of docs/swing-3d.md ("Sidespin against direction"):
the bat's direction scanned from -29 deg to +20 deg (1-deg steps) at Table
II's fastball swing, for the fastball and the knuckleball presets, the swing
plane tilted 15 and 30 deg, a right-handed batter; a least-squares line of
the model's sidespin (rpm) against its own launch direction (deg), and the
launch direction where the sidespin vanishes. A convenience for developers
(never run by the tests).

    cargo build --release
    python3 scripts/sidespin_by_direction.py
"""
import json
import math
import subprocess

BINARY = "target/release/homerun"


def launch(pitch, tilt, direction):
    out = subprocess.run(
        [BINARY, "hit", "--preset", pitch, "--json", "--set", f"bat.tilt={math.radians(tilt):.6f}",
         "--set", f"bat.direction={math.radians(direction):.6f}"],
        capture_output=True, text=True, check=True).stdout
    impact = json.loads(out)["impact"]
    return (math.degrees(impact["launch_direction"]),
            impact["launch_sidespin"] * 60 / (2 * math.pi))


def line(points):
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    slope = sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)
    return my - slope * mx, slope


print("| pitch | tilt | model's sidespin (rpm, right-handed) | straight (no sidespin) at | Nathan's relation |")
print("|---|---|---|---|---|")
for pitch in ("knuckleball", "fastball"):
    for tilt in (15, 30):
        points = [launch(pitch, tilt, d) for d in range(-29, 21)]
        intercept, slope = line(points)
        print(f"| {pitch} | {tilt}° | {intercept:+.0f} + {slope:.1f}·φ | {-intercept / slope:+.1f}° "
              f"| +849 + 94·φ |")
