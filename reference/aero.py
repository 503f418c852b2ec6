"""Independent reference for the aerodynamic models beyond the paper: Alan
Nathan's drag and lift, spin decay, and the air from the weather (his
trajectory calculator), with the paper's lift and constant drag beside them.

Written apart from the Rust core: plain formulas, scipy's solve_ivp (DOP853)
at rtol = atol = 1e-12. It prints the fixture the Rust tests read, so that CI
needs no Python:

    python3 reference/aero.py > tests/data/aero_reference.csv

Each row is one launch from 1 m (speed, angle, spin) under one drag x lift
pair, spin decay time and air; its carry, flight time and apex follow.
"""
import math
import sys

from scipy.integrate import solve_ivp

G = 9.81
MASS = 0.145
RADIUS = 0.0366
HEIGHT = 1.0
PAPER_AIR = (1.23, 1.5e-5)  # rho (kg/m^3), nu (m^2/s): the paper's presets


def air_from_weather(t_c, elevation_m, pressure_hpa, humidity_pct):
    """Nathan's calculator: rho from T, h, sea-level pressure and RH; nu from
    Sutherland's law (mu0 = 1.716e-5 Pa s at 273.15 K, S = 110.4 K)."""
    p_mmhg = pressure_hpa * 760.0 / 1013.25
    svp = 4.5841 * math.exp((18.687 - t_c / 234.5) * t_c / (257.14 + t_c))
    rho = 1.2929 * (273.15 / (t_c + 273.15)) * (
        p_mmhg * math.exp(-1.217e-4 * elevation_m) - 0.3783 * humidity_pct / 100.0 * svp) / 760.0
    t_k = t_c + 273.15
    mu = 1.716e-5 * (t_k / 273.15) ** 1.5 * (273.15 + 110.4) / (t_k + 110.4)
    return rho, mu / rho


def cd_nathan(re, rpm):
    return 0.3008 + 0.0292 * rpm / 1000.0


def cd_constant(re, rpm):
    return 0.5


def cd_sawicki(re, rpm):
    # The paper's drag crisis, as reference/model.py writes it.
    if re < 160000:
        return min(0.5, 0.15 + 0.0416812 * (math.exp((160000 - re) / 8784.46) - 1))
    if re <= 175000:
        return 0.15
    return 0.15 + 0.309620 * (1 - math.exp(-(re - 175000) / 49808.6))


def cl_nathan(s):
    return 1.120 * s / (0.583 + 2.333 * s)


def cl_sawicki(s):
    return 1.5 * s if s <= 0.1 else 0.09 + 0.6 * s


def cl_none(s):
    return 0.0


DRAG = {"nathan": cd_nathan, "constant": cd_constant, "sawicki2003": cd_sawicki}
LIFT = {"nathan": cl_nathan, "sawicki2003": cl_sawicki, "none": cl_none}


def fly(drag, lift, speed, angle, spin, tau, rho, nu, wind):
    """Carry (m), flight time (s) and apex (m) of one launch."""
    cd, cl = DRAG[drag], LIFT[lift]
    k = rho * math.pi * RADIUS ** 2 / (2.0 * MASS)

    def omega(t):
        return spin * math.exp(-t / tau) if tau > 0 else spin

    def rhs(t, u):
        _, _, vx, vy = u
        rx, ry = wind - vx, -vy  # relative wind V_w - V_b
        q = math.hypot(rx, ry)
        w = omega(t)
        rpm = abs(w) * 60.0 / (2.0 * math.pi)
        c_d = cd(2.0 * q * RADIUS / nu, rpm)
        c_l = cl(RADIUS * abs(w) / q) if q > 0 else 0.0
        sign = math.copysign(1.0, w) if w != 0 else 0.0
        # Drag along V_r; lift along omega z x V_b, i.e. sign * (ry, -rx).
        ax = k * q * (c_d * rx + sign * c_l * ry)
        ay = k * q * (c_d * ry - sign * c_l * rx) - G
        return [vx, vy, ax, ay]

    def landing(t, u):
        return u[1]

    landing.terminal = True
    landing.direction = -1

    def top(t, u):
        return u[3]

    top.direction = -1
    start = [0.0, HEIGHT, speed * math.cos(angle), speed * math.sin(angle)]
    sol = solve_ivp(rhs, (0.0, 60.0), start, method="DOP853", rtol=1e-12, atol=1e-12,
                    events=[landing, top])
    t_land = float(sol.t_events[0][0])
    carry = float(sol.y_events[0][0][0])
    apex = max([HEIGHT] + [float(u[1]) for u in sol.y_events[1]])
    return carry, t_land, apex


def launches():
    """(drag, lift, tau, weather or None, wind, speed, angle deg, spin rpm)."""
    rows = []
    # Nathan x Nathan in the paper's air: speeds, angles and spins of batted
    # balls, backspin and topspin, none.
    for speed, angle, rpm in [
        (46.04, 28.0, 2500.0), (46.04, 28.0, 0.0), (30.0, 12.0, 1200.0),
        (38.0, 20.0, 1800.0), (44.0, 35.0, 3000.0), (50.0, 25.0, 2200.0),
        (52.0, 30.0, 4000.0), (35.0, 45.0, 2500.0), (42.0, 10.0, -1500.0),
        (40.0, 18.0, -800.0), (48.0, 40.0, 1000.0), (33.0, 55.0, 3500.0),
    ]:
        rows.append(("nathan", "nathan", 0.0, None, 0.0, speed, angle, rpm))
    # With spin decay, wind and weather.
    rows += [
        ("nathan", "nathan", 25.0, None, 0.0, 46.04, 28.0, 2500.0),
        ("nathan", "nathan", 5.0, None, 0.0, 44.0, 32.0, 3000.0),
        ("nathan", "nathan", 0.0, None, 5.0, 46.04, 28.0, 2500.0),
        ("nathan", "nathan", 0.0, None, -8.0, 40.0, 25.0, 2000.0),
        ("nathan", "nathan", 0.0, (30.0, 1580.0, 1013.25, 50.0), 0.0, 46.04, 28.0, 2500.0),
        ("nathan", "nathan", 0.0, (15.0, 0.0, 1013.25, 50.0), 0.0, 46.04, 28.0, 2500.0),
        ("nathan", "nathan", 40.0, (-5.0, 300.0, 990.0, 90.0), 3.0, 41.0, 22.0, 1800.0),
        ("nathan", "nathan", 0.0, (38.0, 20.0, 1030.0, 10.0), 0.0, 47.0, 26.0, 2600.0),
    ]
    # Every other smooth pair at the 103 mph, 28 deg, 2500 rpm fly ball.
    for drag, lift in [("nathan", "sawicki2003"), ("nathan", "none"), ("constant", "nathan"),
                       ("constant", "sawicki2003"), ("constant", "none")]:
        rows.append((drag, lift, 0.0, None, 0.0, 46.04, 28.0, 2500.0))
    rows.append(("constant", "sawicki2003", 30.0, (25.0, 500.0, 1005.0, 60.0), 0.0, 40.0, 30.0, 2000.0))
    return rows


def main(out=sys.stdout):
    out.write("# generated by: python3 reference/aero.py > tests/data/aero_reference.csv\n")
    out.write("# angle in rad, spin in rad/s (backspin positive), spin_decay in s (0 = none);\n")
    out.write("# weather blank = the paper's air (rho 1.23 kg/m^3, nu 1.5e-5 m^2/s)\n")
    out.write("drag,lift,spin_decay,temperature,elevation,pressure,humidity,wind,speed,angle,spin,"
              "air_density,kinematic_viscosity,range,flight_time,apex\n")
    for drag, lift, tau, weather, wind, speed, angle_deg, rpm in launches():
        angle = math.radians(angle_deg)
        spin = rpm * 2.0 * math.pi / 60.0
        rho, nu = air_from_weather(*weather) if weather else PAPER_AIR
        carry, time, apex = fly(drag, lift, speed, angle, spin, tau, rho, nu, wind)
        weather_text = ",".join(repr(x) for x in weather) if weather else ",,,"
        fields = [drag, lift, repr(tau), weather_text, repr(wind), repr(speed), repr(angle),
                  repr(spin), repr(rho), repr(nu), repr(carry), repr(time), repr(apex)]
        out.write(",".join(fields) + "\n")


if __name__ == "__main__":
    main()
