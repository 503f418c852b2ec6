#!/usr/bin/env python3
"""homerun side by side with SciPy on this machine, in one run (the goals of issue 25).

The SciPy side is a plain RK45 integration (solve_ivp, rtol 1e-6, its
default atol 1e-6, a terminal landing event) of the same model, with the
right-hand sides of reference/ (model.py: the paper's impact and flight;
aero.py: Nathan's drag and lift; flight3d.py: the 3-D flight). It is timed
per trajectory in this process, on a sample where the workload is large.

homerun's side is the real binary (--homerun PATH):
  - one trajectory: the fastest row of `homerun bench --json` whose range
    error is within 1 mm (in-process, no start-up: the goal's ≤ 2.5 µs),
    and, for scale, the whole `homerun fly` command's wall clock;
  - a 64×64 surface: `homerun surface --grid 64x64 --csv` over Fig. 7's
    window (its default), wall clock with start-up and output, per cell;
  - 200k-row Statcast-like batches: `homerun fly --batch FILE --preset
    fly-ball` (Nathan's aero), planar rows (speed, angle, spin) and 3-D
    rows (with direction and sidespin), generated here with a fixed seed,
    wall clock with start-up, parsing and output, per row.
Every wall clock is the best of --repeats runs (the machine is shared).

A developer's script (never run by the tests; docs/speed.md explains the
columns):

    cargo build --release
    python3 scripts/versus_scipy.py                       # target/release/homerun
    python3 scripts/versus_scipy.py --homerun /work/wt/notes/homerun-before18
"""
import argparse
import json
import math
import os
import random
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "reference"))

import scipy  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

import aero  # noqa: E402
import flight3d  # noqa: E402
import model  # noqa: E402

RTOL = 1e-6  # the SciPy side: plain RK45 at rtol 1e-6
RPM = 2.0 * math.pi / 60.0
MPH = 0.44704
GRID = 64
# Fig. 7's window, `homerun surface`'s default: undercut (m), swing angle (rad).
UNDERCUT = (0.0, 0.05)
SWING_ANGLE = (-0.6, 1.0)
# The Table II fastball (reference/model.py's "fast") and the fly-ball preset.
FASTBALL = dict(pitch_speed=42.0, pitch_spin=-200.0, bat_speed=30.0, undercut=0.0265,
                swing_angle=0.1594)
FLY_BALL = (46.04512, math.radians(28.0), 2500.0 * RPM)


# --- The SciPy side ------------------------------------------------------------
def landing(t, u, *args):
    return u[1]


landing.terminal = True
landing.direction = -1


def rk45(rhs, start, args=()):
    """One flight to the ground: (range, right-hand-side evaluations)."""
    sol = solve_ivp(rhs, (0.0, 60.0), start, method="RK45", rtol=RTOL, events=landing, args=args)
    end = sol.y_events[0][0]
    return (math.hypot(end[0], end[2]) if len(start) == 6 else end[0]), sol.nfev


def paper_flight(vx, vy, spin):
    """reference/model.py's flight (the paper's drag crisis and lift)."""
    return rk45(model.rhs, [0.0, 1.0, vx, vy], (spin, 0.0))


def paper_cell(undercut, swing_angle):
    """One surface cell: the fastball's impact at (E, ψ), then its flight."""
    imp = model.impact(FASTBALL["pitch_speed"], FASTBALL["pitch_spin"], FASTBALL["bat_speed"],
                       undercut, swing_angle)
    return paper_flight(imp["vx"], imp["vy"], imp["spin"])


def nathan_planar_rhs(spin):
    """reference/aero.py's planar right-hand side, Nathan's drag and lift,
    the paper's air, no spin decay or wind."""
    rho, nu = aero.PAPER_AIR
    k = rho * math.pi * aero.RADIUS ** 2 / (2.0 * aero.MASS)
    rpm = abs(spin) / RPM
    sign = math.copysign(1.0, spin) if spin != 0 else 0.0

    def rhs(t, u):
        rx, ry = -u[2], -u[3]
        q = math.hypot(rx, ry)
        c_d = aero.cd_nathan(2.0 * q * aero.RADIUS / nu, rpm)
        c_l = aero.cl_nathan(aero.RADIUS * abs(spin) / q) if q > 0 else 0.0
        return [u[2], u[3], k * q * (c_d * rx + sign * c_l * ry),
                k * q * (c_d * ry - sign * c_l * rx) - aero.G]

    return rhs


def nathan_planar(speed, angle, spin):
    start = [0.0, aero.HEIGHT, speed * math.cos(angle), speed * math.sin(angle)]
    return rk45(nathan_planar_rhs(spin), start)


def nathan_3d(speed, angle, spin, direction, sidespin):
    """reference/flight3d.py's right-hand side (Nathan's models have no
    kinks: one regime), the paper's air, no wind."""
    row = dict(drag="nathan", lift="nathan", spin=spin, sidespin=sidespin, angle=angle,
               direction=direction, spin_decay=0.0, wind=0.0, wind_direction=0.0,
               wind_height=0.0, speed=speed)
    flight = flight3d.Flight(row, *aero.PAPER_AIR)
    start = [0.0, aero.HEIGHT, 0.0, speed * math.cos(angle) * math.cos(direction),
             speed * math.sin(angle), speed * math.cos(angle) * math.sin(direction)]
    return rk45(flight.rhs((0, 0, True)), start)


def scipy_seconds(jobs, repeats):
    """Per job: the best over `repeats` of the mean wall clock; and the
    mean evaluations."""
    best = math.inf
    evaluations = 0
    for _ in range(repeats):
        start = time.perf_counter()
        evaluations = sum(job()[1] for job in jobs)
        best = min(best, time.perf_counter() - start)
    return best / len(jobs), evaluations / len(jobs)


# --- The workloads' inputs -------------------------------------------------------
def statcast_rows(count, spatial, fly_balls=False, seed=18):
    """Batted balls in play, roughly as Statcast sees them: exit speed
    ~ 89 ± 14 mph, launch angle ~ 12 ± 25° (a third of them ground balls),
    backspin ~ 2300 ± 700 rpm; with `spatial`, a spray direction within ±45°
    and ±1500 rpm of sidespin. `fly_balls` keeps to fly balls and line
    drives: ~ 27 ± 9°, within 10–50°. Returns (header, rows of text, rows in
    SI units)."""
    rng = random.Random(seed)
    angle = (27.0, 9.0, 10.0, 50.0) if fly_balls else (12.0, 25.0, -40.0, 70.0)
    header = ["launch_speed", "launch_angle", "spin_rpm"]
    if spatial:
        header += ["launch.direction", "launch.sidespin"]
    text, si = [], []
    for _ in range(count):
        mph = round(min(120.0, max(40.0, rng.gauss(89.0, 14.0))), 1)
        degrees = round(min(angle[3], max(angle[2], rng.gauss(angle[0], angle[1]))), 1)
        rpm = round(min(4500.0, max(200.0, rng.gauss(2300.0, 700.0))))
        cells = [f"{mph:.1f}", f"{degrees:.1f}", f"{rpm:d}"]
        launch = [mph * MPH, math.radians(degrees), rpm * RPM]
        if spatial:
            direction = round(rng.uniform(-0.78, 0.78), 4)
            sidespin = round(rng.uniform(-1500.0, 1500.0) * RPM, 2)
            cells += [f"{direction:.4f}", f"{sidespin:.2f}"]
            launch += [direction, sidespin]
        text.append(",".join(cells))
        si.append(launch)
    return header, text, si


def surface_cells(sample, seed=7):
    """`sample` of the 64×64 cells, drawn without replacement."""
    rng = random.Random(seed)
    cells = rng.sample(range(GRID * GRID), sample)

    def at(window, i):
        return window[0] + (window[1] - window[0]) * i / (GRID - 1)

    return [(at(UNDERCUT, k % GRID), at(SWING_ANGLE, k // GRID)) for k in cells]


# --- homerun's side ----------------------------------------------------------------
def run_homerun(command, repeats, out_path=os.devnull):
    """Best wall clock (s) over `repeats` runs of `command`, stdout to
    `out_path`, and the CPU time (s, user + system, all threads) of that run."""
    best = (math.inf, math.nan)
    for _ in range(repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        with open(out_path, "wb") as out:
            done = subprocess.run(command, stdout=out, stderr=subprocess.PIPE)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if done.returncode != 0:
            sys.exit(f"{' '.join(command)} failed: {done.stderr.decode().strip()}")
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        if wall < best[0]:
            best = (wall, cpu)
    return best


def fastest_within(rows, limit=1e-3):
    """The fastest bench row whose range error is within `limit` (m)."""
    rows = [r for r in rows if abs(r["range_error"]) <= limit]
    return min(rows, key=lambda r: r["time_us"]) if rows else None


def setting(row):
    return f"rtol {row['tolerance']:.0e}, atol {row['absolute']:.0e}"


# --- The table ------------------------------------------------------------------------
def fmt_ratio(ratio):
    return f"{ratio:,.0f}×" if ratio >= 10 else f"{ratio:.2f}×"


def fmt_time(seconds):
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.2f} ms"
    return f"{seconds * 1e6:.2f} µs"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    # The release binary (`cargo build --release`).
    parser.add_argument("--homerun", default=os.path.join(HERE, "..", "target", "release",
                                                          "homerun"))
    parser.add_argument("--rows", type=int, default=200_000, help="rows per batch")
    parser.add_argument("--repeats", type=int, default=3, help="runs of each command (best kept)")
    parser.add_argument("--sample", type=int, default=200,
                        help="SciPy flights timed per surface or batch (scaled)")
    parser.add_argument("--fly-balls", action="store_true",
                        help="batches of fly balls and line drives only (10–50°)")
    parser.add_argument("--quick-bench", action="store_true", help="homerun bench --quick")
    parser.add_argument("--json", metavar="FILE", help="also write the table as JSON")
    args = parser.parse_args()
    homerun = os.path.abspath(args.homerun)
    env = dict(os.environ, RAYON_NUM_THREADS="2")
    version = subprocess.run([homerun, "--version"], capture_output=True, text=True).stdout
    print(f"homerun: {homerun} ({version.strip()}); SciPy {scipy.__version__}, Python "
          f"{sys.version.split()[0]}; {os.cpu_count()} cores, load average "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    rows = []

    def add(workload, scipy_s, homerun_s, goal, note, homerun_cpu=None, scipy_nfev=None):
        ratio = scipy_s / homerun_s
        rows.append(dict(workload=workload, scipy_s=scipy_s, scipy_evaluations=scipy_nfev,
                         homerun_s=homerun_s, homerun_cpu_s=homerun_cpu, ratio=ratio,
                         goal=goal, note=note))
        print(f"  {workload}: SciPy {fmt_time(scipy_s)}, homerun {fmt_time(homerun_s)}, "
              f"{fmt_ratio(ratio)}", flush=True)

    # One trajectory.
    bench_command = [homerun, "bench", "--json"] + (["--quick"] if args.quick_bench else [])
    report = json.loads(subprocess.run(bench_command, capture_output=True, text=True,
                                       env=env, check=True).stdout)
    imp = model.impact(**FASTBALL)
    fastball = (imp["vx"], imp["vy"], imp["spin"])
    singles = [
        ("one trajectory: Table II fastball, paper's aero (bench, in-process)",
         lambda: paper_flight(*fastball), model.fly(*fastball)["range"],
         [r for r in report["trajectory"] if r["method"] == "dopri5"]),
        ("one trajectory: fly ball, Nathan's aero (bench, in-process)",
         lambda: nathan_planar(*FLY_BALL),
         aero.fly("nathan", "nathan", *FLY_BALL, 0.0, *aero.PAPER_AIR, 0.0)[0],
         [r for r in report["spatial"] if r["flight"] == "planar"]),
    ]
    scipy_single = []
    for workload, job, reference, bench_rows in singles:
        scipy_s, nfev = scipy_seconds([job], 20)
        scipy_single.append(scipy_s)
        best = fastest_within(bench_rows)
        add(workload, scipy_s, best["time_us"] * 1e-6, "≤ 2.5 µs",
            f"homerun {setting(best)}, {best['evaluations']} evaluations, error "
            f"{best['range_error']:+.1e} m; SciPy error {job()[0] - reference:+.1e} m",
            scipy_nfev=nfev)
    wall, cpu = run_homerun([homerun, "fly"], 10)
    add("one trajectory: `homerun fly` (fastball swing), whole command", scipy_single[0], wall,
        "-", "start-up and output included: a process, not a flight", cpu, None)

    # The surface.
    cells = surface_cells(min(args.sample, GRID * GRID))
    scipy_cell, nfev = scipy_seconds([lambda c=c: paper_cell(*c) for c in cells], 1)
    wall, cpu = run_homerun([homerun, "surface", "--grid", f"{GRID}x{GRID}", "--csv"],
                            args.repeats)
    add(f"{GRID}×{GRID} surface, Fig. 7's window (`homerun surface --csv`)", scipy_cell,
        wall / GRID ** 2, "≥ 600×",
        f"whole command {fmt_time(wall)} wall, {fmt_time(cpu)} CPU; SciPy: impact + flight on "
        f"{len(cells)} random cells", cpu / GRID ** 2, nfev)

    # The batches.
    with tempfile.TemporaryDirectory(prefix="versus-scipy-") as folder:
        for spatial, goal in [(False, "≥ 250×"), (True, "≥ 200×")]:
            header, text, si = statcast_rows(args.rows, spatial, args.fly_balls)
            path = os.path.join(folder, "batch3d.csv" if spatial else "batch.csv")
            with open(path, "w") as f:
                f.write(",".join(header) + "\n" + "\n".join(text) + "\n")
            sample = random.Random(1).sample(si, min(args.sample, len(si)))
            fly = nathan_3d if spatial else nathan_planar
            scipy_row, nfev = scipy_seconds([lambda r=r: fly(*r) for r in sample], 1)
            wall, cpu = run_homerun(
                [homerun, "fly", "--batch", path, "--preset", "fly-ball"], args.repeats,
                os.path.join(folder, "out.csv"))
            kind = "3-D: + direction, sidespin" if spatial else "planar: speed, angle, spin"
            if args.fly_balls:
                kind += ", fly balls"
            add(f"{args.rows // 1000}k-row batch, Nathan's aero, {kind} (`fly --batch`)",
                scipy_row, wall / args.rows, goal,
                f"whole command {fmt_time(wall)} wall, {fmt_time(cpu)} CPU, "
                f"{args.rows / wall:,.0f} rows/s; SciPy on {len(sample)} random rows",
                cpu / args.rows, nfev)

    print()
    print("| workload | SciPy per trajectory | homerun per trajectory (wall, 2 threads) | "
          "ratio | goal |")
    print("|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['workload']} | {fmt_time(r['scipy_s'])} | {fmt_time(r['homerun_s'])} | "
              f"{fmt_ratio(r['ratio'])} | {r['goal']} |")
    print()
    for r in rows:
        extra = f"; SciPy {r['scipy_evaluations']:.0f} evaluations" \
            if r["scipy_evaluations"] else ""
        cpu = f"; homerun CPU {fmt_time(r['homerun_cpu_s'])}" if r["homerun_cpu_s"] else ""
        print(f"- {r['workload']}: {r['note']}{cpu}{extra}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(dict(homerun=homerun, load=os.getloadavg(), rows=rows), f, indent=1)


if __name__ == "__main__":
    main()
