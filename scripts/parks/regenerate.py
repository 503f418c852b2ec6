#!/usr/bin/env python3
"""Builds data/parks.toml, the bundled parks, from the sources in
scripts/parks/sources/ (provenance in docs/parks.md).

    python3 scripts/parks/regenerate.py            # writes data/parks.toml
    python3 scripts/parks/regenerate.py --check    # fails if it would change

Needs only the Python standard library. Nothing here runs at build or test
time: the Rust crate embeds the generated file.

The steps, each checked as it goes:
1. Home plate of the outlines: the vertex where the two foul lines meet,
   fitted to the outlines' own foul lines (they must be square, at +-45°).
2. Scale: one factor (feet per outline unit) for all parks, the median of
   published / outline distance over every park's foul lines and centre.
3. The fence: the outline's wall from foul pole to foul pole, in polar form
   about home plate (direction from the centre-field line, + toward right
   field).
4. Anchoring: each park's outline is stretched so that its left-field line,
   straightaway centre and right-field line match the published distances
   exactly; the factor varies linearly with direction between those three.
5. Wall heights: from the transcribed stretches of fence_heights.csv; a
   change of height is a step, two points at the same direction.
6. Points: every 5°, every outline vertex, and both sides of every step.
"""

import csv
import math
import statistics
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCES = HERE / "sources"
OUTPUT = HERE.parent.parent / "data" / "parks.toml"

FOOT = 0.3048  # m
# GeomMLBStadiums' nominal scale (feet per unit, mlb_xy_transformation).
NOMINAL_SCALE = 2.495671
# The Dinger Machine's transform of the same outlines (its angles' origin).
DINGER_ORIGIN = (125.0, 199.0)
DINGER_ANGLE_FACTOR = 0.75
POLE = 45.0  # degrees
GRID = 5.0  # degrees between regular points
MERGE = 0.3  # degrees: an outline vertex this close to a grid point is dropped


def rows(name):
    with open(SOURCES / name, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def outlines():
    """{team: {segment: [(x, y), ...]}} in outline units, in file order: the
    outlines of today, and those of walls since rebuilt (their teams named
    apart, `orioles_2018`)."""
    out = {}
    for row in rows("mlb_stadia_paths.csv") + rows("mlb_stadia_paths_2018.csv"):
        seg = out.setdefault(row["team"], {}).setdefault(row["segment"], [])
        seg.append((float(row["x"]), float(row["y"])))
    return out


def fit_line(points):
    """Centre and unit direction of the least-squares line through points."""
    n = len(points)
    cx = sum(p[0] for p in points) / n
    cy = sum(p[1] for p in points) / n
    sxx = sum((p[0] - cx) ** 2 for p in points)
    syy = sum((p[1] - cy) ** 2 for p in points)
    sxy = sum((p[0] - cx) * (p[1] - cy) for p in points)
    angle = 0.5 * math.atan2(2 * sxy, sxx - syy)
    return (cx, cy), (math.cos(angle), math.sin(angle))


def intersect(c1, v1, c2, v2):
    det = v1[0] * (-v2[1]) - v1[1] * (-v2[0])
    dx, dy = c2[0] - c1[0], c2[1] - c1[1]
    t = (dx * (-v2[1]) - dy * (-v2[0])) / det
    return (c1[0] + t * v1[0], c1[1] + t * v1[1])


def home_plate(team, foul):
    """The foul lines' vertex, checked square and at +-45°."""
    far = [p for p in foul if math.hypot(p[0] - 125, p[1] - 200) > 30]
    left = fit_line([p for p in far if p[0] < 125])
    right = fit_line([p for p in far if p[0] > 125])
    home = intersect(*left, *right)
    for (_, v), sign in ((left, -1), (right, 1)):
        # Outline y grows toward home plate; direction from the CF line.
        direction = math.degrees(math.atan2(abs(v[0]) * sign, abs(v[1])))
        assert abs(abs(direction) - POLE) < 0.3, (team, direction)
    return home


def polar(point, home, scale):
    """(direction °, distance ft) of an outline point about home plate."""
    x = (point[0] - home[0]) * scale
    y = (home[1] - point[1]) * scale
    return math.degrees(math.atan2(x, y)), math.hypot(x, y)


def ray_hit(outline, origin, direction):
    """Where a ray from origin (outline units) at direction (°, from the CF
    line, + toward right field) last crosses the closed outline."""
    ux, uy = math.sin(math.radians(direction)), -math.cos(math.radians(direction))
    best = None
    for i, a in enumerate(outline):
        b = outline[(i + 1) % len(outline)]
        ex, ey = b[0] - a[0], b[1] - a[1]
        det = ux * (-ey) - uy * (-ex)
        if abs(det) < 1e-12:
            continue
        dx, dy = a[0] - origin[0], a[1] - origin[1]
        t = (dx * (-ey) - dy * (-ex)) / det
        s = (ux * dy - uy * dx) / det
        if t > 0 and 0 <= s <= 1 and (best is None or t > best[0]):
            best = (t, (a[0] + s * ex, a[1] + s * ey))
    assert best is not None, direction
    return best[1]


def wall(outline, home, scale):
    """The fence from pole to pole: [(direction °, distance ft)] ascending,
    the poles moved onto +-45° exactly. Walks the outline from straightaway
    centre field toward each foul line while the direction keeps moving that
    way, and stops at the first vertex within half a degree of the line (the
    foul pole: past it the outline runs along the line, beside the stands)."""
    pts = [polar(p, home, scale) for p in outline]
    n = len(pts)
    fair = [i for i in range(n) if abs(pts[i][0]) < 30 and pts[i][1] > 250]
    start = min(fair, key=lambda i: abs(pts[i][0]))
    forward = pts[(start + 1) % n][0] > pts[start][0]

    def walk(step, sign):
        chain, i = [], start
        while True:
            i = (i + step) % n
            d, r = pts[i]
            prev = chain[-1][0] if chain else pts[start][0]
            assert (d - prev) * sign > 0, ("direction turned back", d, prev)
            if abs(d) >= POLE - 0.5:
                chain.append((sign * POLE, r))
                return chain
            chain.append((d, r))

    to_right = walk(1 if forward else -1, 1)
    to_left = walk(-1 if forward else 1, -1)
    return list(reversed(to_left)) + [pts[start]] + to_right


def at(profile, direction):
    """Linear interpolation in a [(direction, value)] ascending profile."""
    for (d0, v0), (d1, v1) in zip(profile, profile[1:]):
        if d0 <= direction <= d1:
            return v0 if d1 == d0 else v0 + (v1 - v0) * (direction - d0) / (d1 - d0)
    raise ValueError(direction)


def pchip(xs, ys):
    """Monotone cubic (Fritsch-Carlson) through the points, as a function."""
    h = [x1 - x0 for x0, x1 in zip(xs, xs[1:])]
    delta = [(y1 - y0) / hk for y0, y1, hk in zip(ys, ys[1:], h)]
    m = [delta[0]] + [
        0.0 if d0 * d1 <= 0 else 3 * (h0 + h1) / ((2 * h1 + h0) / d0 + (h1 + 2 * h0) / d1)
        for d0, d1, h0, h1 in zip(delta, delta[1:], h, h[1:])
    ] + [delta[-1]]

    def f(x):
        k = max(i for i in range(len(h)) if xs[i] <= x) if x < xs[-1] else len(h) - 1
        t = (x - xs[k]) / h[k]
        return (
            (2 * t**3 - 3 * t**2 + 1) * ys[k]
            + (t**3 - 2 * t**2 + t) * h[k] * m[k]
            + (-2 * t**3 + 3 * t**2) * ys[k + 1]
            + (t**3 - t**2) * h[k] * m[k + 1]
        )

    return f


def merged_directions(vertices, steps):
    grid = [-POLE + GRID * k for k in range(int(2 * POLE / GRID) + 1)]
    extra = [d for d in vertices if all(abs(d - g) > MERGE for g in grid + steps)]
    return sorted(set(grid + extra))


def park_points(profile, stretches):
    """[(direction °, distance ft, height ft)]: every grid direction, every
    profile vertex and both sides of each change of height."""
    steps = [b for (_, b, _) in stretches[:-1]]
    points = []
    for d in merged_directions([d for d, _ in profile], steps):
        height = next(h for (a, b, h) in stretches if a <= d <= b)
        points.append((d, at(profile, d), height))
    for (_, b, h_left), (_, _, h_right) in zip(stretches, stretches[1:]):
        r = at(profile, b)
        points += [(b, r, h_left), (b, r, h_right)]
    points.sort(key=lambda p: p[0])  # stable: the step's left height first
    return points


def walls_line(walls):
    return "walls = [" + ", ".join(f'"{w}"' for w in walls.split("|")) + "]"


def fence_lines(points):
    out = ["fence = ["]
    for d, r, h in points:
        out.append(
            f"  {{ direction = {math.radians(d):.5f}, distance = {r * FOOT:.3f}, "
            f"height = {h * FOOT:.3f} }},  # {d:6.1f}°  {r:5.1f} ft  {h:4.1f} ft"
        )
    return out + ["]", ""]


def reaches(profile, side, distance):
    """The direction (°) where the outline's fence first reaches `distance`
    walking from the `side`'s foul pole toward centre (C: centre itself)."""
    if side == "C":
        return 0.0
    walk = [(d, r) for d, r in profile if d <= 0] if side == "L" else \
        [(d, r) for d, r in reversed(profile) if d >= 0]
    for (d0, r0), (d1, r1) in zip(walk, walk[1:]):
        if (r0 - distance) * (r1 - distance) <= 0:
            return d0 if r1 == r0 else d0 + (d1 - d0) * (distance - r0) / (r1 - r0)
    raise ValueError((side, distance))


def rebuild(profile, rebuilt):
    """The outline's fence scaled to a rebuilt wall's published distances
    (rebuilt.csv), and its heights: (profile, stretches)."""
    marks = sorted((reaches(profile, r["side"], float(r["old_ft"])),
                    float(r["new_ft"]), float(r["height_ft"])) for r in rebuilt)
    assert marks[0][0] == -POLE and marks[-1][0] == POLE, marks
    factor = [(d, new / at(profile, d)) for d, new, _ in marks]
    scaled = [(d, r * at(factor, d)) for d, r in profile]
    # Each published point a vertex, so that it is met exactly.
    scaled = sorted({d: r for d, r in scaled + [(d, new) for d, new, _ in marks]}.items())
    cuts = [-POLE] + [(a[0] + b[0]) / 2 for a, b in zip(marks, marks[1:])] + [POLE]
    stretches = []
    for a, b, (_, _, h) in zip(cuts, cuts[1:], marks):
        if stretches and stretches[-1][2] == h:  # no step where the height holds
            stretches[-1] = (stretches[-1][0], b, h)
        else:
            stretches.append((a, b, h))
    return scaled, stretches


def outlined(paths, home, scale, pub, heights):
    """An outlined park's fence anchored to its published distances `pub`
    (ft), with `heights` [(from, to, ft)] in the Dinger Machine's angles:
    (profile, stretches, raw), raw the outline's own LF, CF and RF."""
    outline = paths["outfield_outer"]
    profile = wall(outline, home, scale)
    raw = tuple(at(profile, d) for d in (-POLE, 0.0, POLE))
    # Straightaway centre as a vertex, so that it is met exactly.
    profile = sorted(set(profile) | {(0.0, raw[1])})
    # 4. Anchor: a factor per side, linear in direction.
    fl, fc, fr = pub["lf"] / raw[0], pub["cf"] / raw[1], pub["rf"] / raw[2]
    profile = [
        (d, r * (fc + (fl - fc) * (-d / POLE) if d < 0 else fc + (fr - fc) * (d / POLE)))
        for d, r in profile
    ]
    # 5. Heights: the Dinger Machine's angles back onto the outline.
    stretches = []
    for a, b, h in heights:
        ends = []
        for e in (a, b):
            if abs(e) >= 90:
                ends.append(math.copysign(POLE, e))
                continue
            hit = ray_hit(outline, DINGER_ORIGIN, e / DINGER_ANGLE_FACTOR)
            ends.append(max(-POLE, min(POLE, polar(hit, home, scale)[0])))
        stretches.append((ends[0], ends[1], h))
    for (_, b, _), (a, _, _) in zip(stretches, stretches[1:]):
        assert abs(a - b) < 1e-9, (a, b)
    return profile, stretches, raw


def main():
    check = "--check" in sys.argv
    paths = outlines()
    parks = rows("parks.csv")
    heights = {}
    for row in rows("fence_heights.csv"):
        heights.setdefault(row["team"], []).append(
            (float(row["from"]), float(row["to"]), float(row["height_ft"]))
        )

    rebuilts = rows("rebuilt.csv")
    earliers = rows("earlier.csv")
    # Home plate of every outline used: the parks' and their earlier walls'.
    teams = {p["team"] for p in parks if p["team"] != "constructed"}
    homes = {team: home_plate(team, paths[team]["foul_lines"])
             for team in sorted(teams | {e["outline"] for e in earliers})}

    # 2. One scale for all parks.
    ratios = []
    for p in parks:
        if p["team"] == "constructed":
            continue
        outline = paths[p["team"]]["outfield_outer"]
        prof = wall(outline, homes[p["team"]], NOMINAL_SCALE)
        for d, key in ((-POLE, "lf"), (0.0, "cf"), (POLE, "rf")):
            ratios.append(at(prof, d) / float(p[key]))
    scale = NOMINAL_SCALE / statistics.median(ratios)

    report = []
    out = [
        "# The bundled parks. Generated by scripts/parks/regenerate.py from",
        "# scripts/parks/sources/: do not edit by hand (docs/parks.md tells the",
        "# sources, the vintage and how to add a park of your own).",
        "#",
        "# Units: elevation, distances and heights in metres; directions in",
        "# radians from the centre-field line, positive toward right field;",
        "# center_field_bearing in degrees clockwise from true north.",
        f"# Outline scale: {scale:.4f} ft per GeomMLBStadiums unit (nominal {NOMINAL_SCALE}).",
        "",
    ]
    for p in parks:
        pub = {k: float(p[k]) for k in ("lf", "cf", "rf")}
        if p["team"] == "constructed":
            pts = [r for r in rows("constructed.csv") if r["code"] == p["code"]]
            f = pchip([float(r["direction_deg"]) for r in pts],
                      [float(r["distance_ft"]) for r in pts])
            profile = [(d / 2, f(d / 2)) for d in range(-90, 91)]
            stretches = [(-POLE, POLE, float(pts[0]["height_ft"]))]
            raw = (f(-POLE), f(0.0), f(POLE))
        else:
            profile, stretches, raw = outlined(
                paths[p["team"]], homes[p["team"]], scale, pub, heights[p["team"]])
        points = park_points(profile, stretches)
        # 7. Walls rebuilt since the outline: those are the park's fence,
        # the outline's its earlier walls.
        earlier = []
        rebuilt = [r for r in rebuilts if r["code"] == p["code"]]
        if rebuilt:
            earlier = [(p["walls"], points)]
            profile, stretches = rebuild(profile, rebuilt)
            points = park_points(profile, stretches)
        # 8. Earlier walls drawn in an outline of their own, or in the
        # park's, anchored to their own published distances.
        for e in (r for r in earliers if r["code"] == p["code"]):
            team = e["outline"]
            then = {k: float(e[k]) for k in ("lf", "cf", "rf")}
            profile_then, stretches_then, _ = outlined(
                paths[team], homes[team], scale, then, heights[e["heights"]])
            earlier.append((e["walls"], park_points(profile_then, stretches_then)))
        errors = [got - want for got, want in zip(raw, (pub["lf"], pub["cf"], pub["rf"]))]
        report.append((p["code"], errors, max(h for *_, h in points)))

        aliases = [a for a in p["aliases"].split("|") if a]
        out += [
            "[[park]]",
            f'code = "{p["code"]}"',
            "aliases = [" + ", ".join(f'"{a}"' for a in aliases) + "]",
            f'name = "{p["name"]}"',
            f'city = "{p["city"]}"',
            f"elevation = {float(p['elevation_ft']) * FOOT:.1f}  # {p['elevation_ft']} ft",
            f"center_field_bearing = {float(p['bearing']):.1f}  # from {p['bearing_source']}",
            "published = { "
            + ", ".join(f"{k} = {pub[s] * FOOT:.3f}" for k, s in
                        (("left_line", "lf"), ("center", "cf"), ("right_line", "rf")))
            + f" }}  # {p['lf']}, {p['cf']}, {p['rf']} ft",
            "home = [" + ", ".join(f'"{h}"' for h in p["home"].split("|") if h) + "]",
        ]
        walls = rebuilt[0]["walls"] if rebuilt else p["walls"]
        if walls:  # else the home spans (docs/parks.md, When the walls stood)
            out.append(walls_line(walls))
        out += fence_lines(points)
        for walls, points in earlier:
            out += ["[[park.earlier]]", walls_line(walls)] + fence_lines(points)

    text = "\n".join(out)
    print(f"scale {scale:.4f} ft/unit (nominal {NOMINAL_SCALE}, ratio "
          f"{NOMINAL_SCALE / scale:.4f}); outline minus published (ft), before anchoring:")
    for code, (el, ec, er), top in report:
        print(f"  {code:4s} LF {el:+6.1f}  CF {ec:+6.1f}  RF {er:+6.1f}   tallest wall {top:4.1f} ft")
    worst = max(abs(e) for _, errs, _ in report for e in errs)
    print(f"worst before anchoring: {worst:.1f} ft")
    if check:
        if OUTPUT.read_text() != text:
            sys.exit(f"{OUTPUT} is not what the sources give: run {Path(__file__).name}")
        print(f"{OUTPUT} is up to date")
    else:
        OUTPUT.write_text(text)
        print(f"wrote {OUTPUT}")


if __name__ == "__main__":
    main()
