"""Independent reference for the batted ball's flight in three dimensions:
spray direction, sidespin, a wind from any direction blowing above a height,
under Nathan's and the paper's drag and lift, with spin decay and the air
from the weather.

Written from the physics and the conventions of shared/DESIGN.md ("Three
dimensions"), apart from the Rust core: plain formulas, scipy's solve_ivp
with DOP853 (an 8th-order pair; the Rust flight uses the 5th-order DOPRI5)
at rtol = atol = 1e-12. Every place where the right-hand side is not smooth
is an event at which the integration stops and starts again, so that no
step ever straddles one:
  - the wind's layer (y = wind_height), where the wind starts or stops;
  - the paper's drag curve's three kinks in Re;
  - the paper's lift's kink at S = 0.1.
Each piece's formula is used, continued analytically, for the whole of the
steps between two such events. The landing (y = 0) and the apex (v_y = 0)
are located by events too. It prints the fixture the Rust tests read, so
that CI needs no Python:

    python3 reference/flight3d.py > tests/data/aero3d_reference.csv

Frame: x toward centre field, y up, z toward right field. A launch at speed
V, angle theta above the horizontal, direction phi (positive toward right
field) leaves with V (cos theta cos phi, sin theta, cos theta sin phi) from
(0, 1 m, 0). Its spin vector, fixed in direction during the flight,
    omega = backspin (-sin phi, 0, cos phi)
          + sidespin (sin theta cos phi, -cos theta, sin theta sin phi),
has a size that decays as exp(-t/tau) when tau > 0. The wind
w (cos phi_w, 0, sin phi_w) blows where y >= wind_height. With
V_r = V_wind - V_ball, k = rho pi r^2 / (2 m):
    drag = k C_D |V_r| V_r,  C_D(Re = 2 r |V_r| / nu, |omega| in rpm)
    lift = k C_L(S) |V_r| (omega_hat x (V_ball - V_wind)),  S = r |omega| / |V_r|
    a = drag + lift - g y_hat.
"""
import math
import sys

from scipy.integrate import solve_ivp

from aero import G, HEIGHT, MASS, PAPER_AIR, RADIUS, air_from_weather

RTOL = ATOL = 1e-12
T_MAX = 600.0


# --- Aerodynamic coefficients, each smooth piece on its own ----------------
# The paper's C_D(Re) (Fig. 3, as reference/model.py writes it) is
# min(0.5, rising exponential) below 160 000, flat at 0.15 to 175 000, then a
# recovering exponential. Its pieces, each continued past its ends:
def _cd_rising(re):
    return 0.15 + 0.0416812 * (math.exp((160000.0 - re) / 8784.46) - 1.0)


def _cd_recovering(re):
    return 0.15 + 0.309620 * (1.0 - math.exp(-(re - 175000.0) / 49808.6))


SAWICKI_DRAG_PIECES = [lambda re: 0.5, _cd_rising, lambda re: 0.15, _cd_recovering]
# Where the rising exponential meets 0.5, then the two ends of the floor.
SAWICKI_DRAG_KINKS = [160000.0 - 8784.46 * math.log(1.0 + 0.35 / 0.0416812), 160000.0, 175000.0]


def _cd_nathan(re, rpm):
    return 0.3008 + 0.0292 * rpm / 1000.0


# name -> (kinks in Re, pieces(re, rpm))
DRAG = {
    "nathan": ([], [_cd_nathan]),
    "constant": ([], [lambda re, rpm: 0.5]),
    "sawicki2003": (SAWICKI_DRAG_KINKS, [lambda re, rpm, f=f: f(re) for f in SAWICKI_DRAG_PIECES]),
}
# name -> (kinks in S, pieces(S)); the paper's Eq. 29 turns at S = 0.1.
LIFT = {
    "nathan": ([], [lambda s: 1.120 * s / (0.583 + 2.333 * s)]),
    "sawicki2003": ([0.1], [lambda s: 1.5 * s, lambda s: 0.09 + 0.6 * s]),
    "none": ([], [lambda s: 0.0]),
}


def piece_of(kinks, value, rising):
    """The piece a value lies on; exactly at a kink, the one it moves into."""
    return sum(1 for k in kinks if value > k or (value == k and rising))


# --- Vectors ---------------------------------------------------------------
def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


def spin_vector(backspin, sidespin, angle, direction):
    st, ct = math.sin(angle), math.cos(angle)
    sp, cp = math.sin(direction), math.cos(direction)
    return (-sp * backspin + st * cp * sidespin,
            -ct * sidespin,
            cp * backspin + st * sp * sidespin)


# --- The flight --------------------------------------------------------------
class Flight:
    def __init__(self, row, rho, nu):
        self.row = row
        self.k = rho * math.pi * RADIUS ** 2 / (2.0 * MASS)
        self.nu = nu
        self.drag_kinks, self.drag_pieces = DRAG[row["drag"]]
        self.lift_kinks, self.lift_pieces = LIFT[row["lift"]]
        omega = spin_vector(row["spin"], row["sidespin"], row["angle"], row["direction"])
        self.spin = norm(omega)
        self.axis = tuple(c / self.spin for c in omega) if self.spin > 0 else (0.0, 0.0, 0.0)
        self.tau = row["spin_decay"]
        w, pw = row["wind"], row["wind_direction"]
        self.wind = (w * math.cos(pw), 0.0, w * math.sin(pw))
        self.wind_height = row["wind_height"]

    def spin_at(self, t):
        return self.spin * math.exp(-t / self.tau) if self.tau > 0 else self.spin

    def air(self, t, u, in_wind):
        """V_r, |V_r|, Re, |omega| and S at (t, u)."""
        wind = self.wind if in_wind else (0.0, 0.0, 0.0)
        rel = (wind[0] - u[3], wind[1] - u[4], wind[2] - u[5])
        q = norm(rel)
        w = self.spin_at(t)
        s = RADIUS * w / q if q > 0 else math.inf
        return rel, q, 2.0 * RADIUS * q / self.nu, w, s

    def rhs(self, regime):
        drag_piece, lift_piece, in_wind = regime
        cd = self.drag_pieces[drag_piece]
        cl = self.lift_pieces[lift_piece]

        def f(t, u):
            rel, q, re, w, s = self.air(t, u, in_wind)
            c_d = cd(re, w * 60.0 / (2.0 * math.pi))
            c_l = cl(s) if w > 0 and q > 0 else 0.0
            # omega_hat x (V_b - V_w) = omega_hat x (-V_r)
            lift_dir = cross(self.axis, (-rel[0], -rel[1], -rel[2]))
            a = [self.k * q * (c_d * rel[i] + c_l * lift_dir[i]) for i in range(3)]
            return [u[3], u[4], u[5], a[0], a[1] - G, a[2]]

        return f

    def regime_at(self, t, u, in_wind):
        """The drag and lift pieces at (t, u), or the ones being entered."""
        f = self.rhs((0, 0, in_wind))
        a = f(t, u)[3:]
        rel, q, re, w, s = self.air(t, u, in_wind)
        # d|V_r|/dt has the sign of -V_r . a; S = r|omega|/|V_r| moves the
        # other way (and falls with the spin's decay).
        q_rising = -(rel[0] * a[0] + rel[1] * a[1] + rel[2] * a[2]) >= 0.0
        return (piece_of(self.drag_kinks, re, q_rising),
                piece_of(self.lift_kinks, s, not q_rising),
                in_wind)

    def events(self, regime):
        drag_piece, lift_piece, in_wind = regime
        found = []

        def landing(t, u):
            return u[1]
        landing.terminal, landing.direction = True, -1
        found.append(("landing", landing))

        def apex(t, u):
            return u[4]
        apex.terminal, apex.direction = False, -1
        found.append(("apex", apex))

        if self.wind_height > 0 and self.wind != (0.0, 0.0, 0.0):
            def layer(t, u):
                return u[1] - self.wind_height
            layer.terminal, layer.direction = True, (-1 if in_wind else 1)
            found.append(("layer", layer))

        for i, kink in enumerate(self.drag_kinks):
            def drag_kink(t, u, kink=kink):
                return self.air(t, u, in_wind)[2] - kink
            drag_kink.terminal, drag_kink.direction = True, (-1 if drag_piece > i else 1)
            found.append((("drag", i), drag_kink))

        for i, kink in enumerate(self.lift_kinks):
            def lift_kink(t, u, kink=kink):
                _, q, _, w, _ = self.air(t, u, in_wind)
                return RADIUS * w - kink * q  # S - kink, times |V_r|
            lift_kink.terminal, lift_kink.direction = True, (-1 if lift_piece > i else 1)
            found.append((("lift", i), lift_kink))
        return found

    def fly(self, method="DOP853"):
        row = self.row
        speed, angle, direction = row["speed"], row["angle"], row["direction"]
        u = [0.0, HEIGHT, 0.0,
             speed * math.cos(angle) * math.cos(direction),
             speed * math.sin(angle),
             speed * math.cos(angle) * math.sin(direction)]
        in_wind = HEIGHT >= self.wind_height
        regime = self.regime_at(0.0, u, in_wind)
        t = 0.0
        apex = (HEIGHT, 0.0)
        crossings = {"layer": 0, "drag": 0, "lift": 0}
        while True:
            events = self.events(regime)
            sol = solve_ivp(self.rhs(regime), (t, T_MAX), u, method=method, rtol=RTOL, atol=ATOL,
                            events=[e for _, e in events])
            for (name, _), ys in zip(events, sol.y_events):
                if name == "apex":
                    for y in ys:
                        if y[1] > apex[0]:
                            apex = (float(y[1]), math.hypot(y[0], y[2]))
            # The terminal event that stopped this leg, if any.
            stop = [(float(ts[0]), name, ys[0]) for (name, _), ts, ys
                    in zip(events, sol.t_events, sol.y_events)
                    if len(ts) and name != "apex"]
            if not stop:
                raise RuntimeError(f"no landing before {T_MAX} s: {row}")
            t, name, y = min(stop, key=lambda s: s[0])
            u = list(y)
            if name == "landing":
                break
            drag_piece, lift_piece, in_wind = regime
            if name == "layer":
                crossings["layer"] += 1
                # Into or out of the wind: Re and S jump with V_r.
                regime = self.regime_at(t, u, not in_wind)
            elif name[0] == "drag":
                crossings["drag"] += 1
                i = name[1]
                regime = (i if drag_piece > i else i + 1, lift_piece, in_wind)
            else:
                crossings["lift"] += 1
                i = name[1]
                regime = (drag_piece, i if lift_piece > i else i + 1, in_wind)
        x, _, z, vx, vy, vz = u
        horizontal = math.hypot(vx, vz)
        return {
            "range": math.hypot(x, z),
            "landing_direction": math.atan2(z, x),
            "flight_time": t,
            "apex": apex[0],
            "apex_distance": apex[1],
            "landing_speed": math.sqrt(horizontal * horizontal + vy * vy),
            "landing_angle": math.atan2(-vy, horizontal),
            "layer_crossings": crossings["layer"],
            "drag_kink_crossings": crossings["drag"],
            "lift_kink_crossings": crossings["lift"],
        }


# --- The launches --------------------------------------------------------------
RPM = 2.0 * math.pi / 60.0
DENVER = (30.0, 1580.0, 1013.25, 50.0)
COLD = (-5.0, 300.0, 990.0, 90.0)
HOT = (38.0, 20.0, 1030.0, 10.0)


def launches():
    """Each a dict of the inputs; angles in degrees, spins in rpm here."""
    base = dict(drag="nathan", lift="nathan", spin_decay=0.0, weather=None, wind=0.0,
                wind_direction=0.0, wind_height=0.0, speed=46.04, angle=28.0, direction=0.0,
                spin=2500.0, sidespin=0.0)
    rows = []

    def add(**changes):
        row = dict(base)
        row.update(changes)
        rows.append(row)

    for models in [("nathan", "nathan"), ("sawicki2003", "sawicki2003")]:
        m = dict(drag=models[0], lift=models[1])
        # Spray direction and sidespin, calm.
        add(**m, sidespin=500.0)
        add(**m, sidespin=-500.0)
        add(**m, direction=30.0)  # planar, in a turned plane
        add(**m, direction=-35.0, sidespin=800.0)
        add(**m, direction=40.0, sidespin=-1200.0)
        add(**m, spin=0.0, sidespin=1500.0)  # pure sidespin
        # Crosswinds, tail- and headwinds from several directions.
        add(**m, wind=5.0, wind_direction=math.pi / 2)
        add(**m, wind=6.0, wind_direction=-math.pi / 2, direction=10.0, sidespin=300.0)
        add(**m, wind=4.0, wind_direction=math.pi / 4, direction=-17.0, sidespin=300.0)
        add(**m, wind=-5.0, wind_direction=2.5, direction=20.0)
        add(**m, wind=8.0, wind_direction=math.pi, direction=12.0, sidespin=-700.0)
        # A wind that blows only above a height: crossed going up and coming
        # down, crossed only coming down, never reached.
        add(**m, wind=7.0, wind_direction=0.6, wind_height=10.0, direction=-5.0, sidespin=400.0)
        add(**m, wind=10.0, wind_direction=-1.2, wind_height=20.0, sidespin=-600.0)
        add(**m, wind=9.0, wind_direction=0.0, wind_height=15.0)  # tailwind aloft: no sidespin
        add(**m, wind=6.0, wind_direction=1.0, wind_height=0.5, direction=25.0)
        add(**m, wind=12.0, wind_direction=-2.0, wind_height=80.0, sidespin=200.0)
        # Spin decay.
        add(**m, spin_decay=5.0, direction=15.0, sidespin=900.0)
        add(**m, spin_decay=25.0, wind=5.0, wind_direction=-0.8, wind_height=8.0,
            sidespin=-400.0)
    # Nathan's models, more launches: a line drive, a pop-up, topspin.
    add(speed=38.0, angle=12.0, spin=1500.0, sidespin=-900.0, direction=-30.0)
    add(speed=35.0, angle=55.0, spin=3000.0, sidespin=1000.0, direction=5.0,
        wind=6.0, wind_direction=2.0)
    add(speed=42.0, angle=10.0, spin=-1200.0, sidespin=600.0, direction=-10.0)
    add(speed=52.0, angle=32.0, spin=2800.0, sidespin=-300.0, direction=44.0,
        wind=3.0, wind_direction=-math.pi / 4)
    add(speed=48.0, angle=25.0, spin=2200.0, sidespin=2500.0, direction=-44.0)
    add(speed=40.0, angle=-3.0, spin=800.0, sidespin=-500.0, direction=20.0)
    # The paper's drag at lower spin: its lift crosses its kink at S = 0.1.
    add(drag="sawicki2003", lift="sawicki2003", speed=44.0, angle=30.0, spin=700.0,
        sidespin=400.0, direction=-12.0, wind=4.0, wind_direction=0.3)
    add(drag="sawicki2003", lift="sawicki2003", speed=30.0, angle=35.0, spin=600.0,
        sidespin=-300.0, direction=8.0)
    # Other pairs.
    add(drag="nathan", lift="sawicki2003", sidespin=600.0, direction=-20.0, wind=4.0,
        wind_direction=1.3)
    add(drag="constant", lift="nathan", sidespin=-800.0, direction=15.0, wind=5.0,
        wind_direction=-0.4, wind_height=12.0)
    add(drag="nathan", lift="none", sidespin=1000.0, direction=18.0, wind=7.0,
        wind_direction=math.pi / 2)
    add(drag="sawicki2003", lift="nathan", sidespin=500.0, direction=-8.0, spin_decay=15.0)
    # Weather-derived air.
    add(weather=DENVER, sidespin=700.0, direction=-25.0, wind=4.0, wind_direction=0.9)
    add(weather=COLD, spin_decay=40.0, sidespin=-500.0, direction=10.0, wind=8.0,
        wind_direction=-math.pi / 2, wind_height=6.0)
    add(weather=HOT, drag="sawicki2003", lift="sawicki2003", sidespin=400.0, direction=30.0,
        wind=-6.0, wind_direction=0.2)
    add(weather=DENVER, drag="sawicki2003", lift="sawicki2003", sidespin=-600.0,
        direction=-15.0, wind=9.0, wind_direction=1.7, wind_height=18.0)
    return rows


COLUMNS = ["drag", "lift", "spin_decay", "temperature", "elevation", "pressure", "humidity",
           "wind", "wind_direction", "wind_height", "speed", "angle", "direction", "spin",
           "sidespin", "air_density", "kinematic_viscosity", "range", "landing_direction",
           "flight_time", "apex", "apex_distance", "landing_speed", "landing_angle",
           "layer_crossings", "drag_kink_crossings", "lift_kink_crossings"]
OUTPUTS = ["range", "landing_direction", "flight_time", "apex", "apex_distance",
           "landing_speed", "landing_angle"]


def reference_row(launch, method="DOP853"):
    """The inputs in SI units (angles in rad, spins in rad/s) and the flight."""
    row = dict(launch)
    for key in ["angle", "direction"]:
        row[key] = math.radians(row[key])
    for key in ["spin", "sidespin"]:
        row[key] = row[key] * RPM
    weather = row.pop("weather")
    rho, nu = air_from_weather(*weather) if weather else PAPER_AIR
    row.update(zip(["temperature", "elevation", "pressure", "humidity"],
                   weather if weather else [None] * 4))
    row["air_density"], row["kinematic_viscosity"] = rho, nu
    row.update(Flight(row, rho, nu).fly(method))
    return row


def text(value):
    if value is None:
        return ""
    return value if isinstance(value, str) else repr(value)


def main(out=sys.stdout):
    out.write("# generated by: python3 reference/flight3d.py > tests/data/aero3d_reference.csv\n")
    out.write("# angles and directions in rad (0 centre field, positive toward right field),\n")
    out.write("# spins in rad/s, spin_decay in s (0 = none), wind in m/s toward wind_direction\n")
    out.write("# above wind_height (0 = everywhere); weather blank = the paper's air\n")
    out.write(",".join(COLUMNS) + "\n")
    for launch in launches():
        row = reference_row(launch)
        out.write(",".join(text(row[c]) for c in COLUMNS) + "\n")


def self_check():
    """The reference against itself with another integrator (Radau, implicit,
    5th order): the worst relative difference in each output."""
    worst = {k: 0.0 for k in OUTPUTS}
    for launch in launches():
        a, b = reference_row(launch), reference_row(launch, "Radau")
        for k in OUTPUTS:
            d = abs(a[k] - b[k]) / max(abs(b[k]), 1e-300)
            worst[k] = max(worst[k], d)
    for k, v in worst.items():
        print(f"{k}: {v:.1e}")


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-check"]:
        self_check()
    else:
        main()
