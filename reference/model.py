"""Independent reference implementation of Sawicki, Hubbard & Stronge (2003).

Written separately from the Rust core (plain formulas + scipy's solve_ivp at
very tight tolerance) so the Rust numbers can be checked against it. Run
`python3 reference/model.py` to print the fixture values used in tests/.
"""
import math
from scipy.integrate import solve_ivp

G = 9.81
RHO = 1.23
NU = 1.5e-5
MB_BALL = 0.145
R_BALL = 0.0366
R_BAT = 0.035
K_BALL = 0.0231   # Table I swaps k_b and k_B2; corrected here
K_BAT = 0.0247
M_BAT = 0.8


def pitch(speed, g=G):
    # Eq. (3), unrounded form with g
    vy = (-speed**2 + 36 * 0.95 * speed - 3.42 * 0.95**2 * g * 18.52) / (3.42 * 0.95 * speed)
    gamma = -math.asin(vy / speed)
    return vy, gamma


def impact(pitch_speed, pitch_spin, bat_speed, undercut, swing_angle, mu=0.5, bat_roll=0.0, g=G):
    _, gamma = pitch(pitch_speed, g)
    theta = math.asin(undercut / (R_BALL + R_BAT))
    n3 = (math.cos(theta), math.sin(theta))
    n1 = (-math.sin(theta), math.cos(theta))
    vb = (-pitch_speed * math.cos(gamma), -pitch_speed * math.sin(gamma))
    vB = (bat_speed * math.cos(swing_angle), bat_speed * math.sin(swing_angle))
    wb = pitch_spin
    wB = -bat_roll  # Fig. 9 sense is -z
    dot = lambda a, b: a[0] * b[0] + a[1] * b[1]
    v1 = dot(vb, n1) - R_BALL * wb - dot(vB, n1) - R_BAT * wB
    v3 = dot(vb, n3) - dot(vB, n3)
    m = MB_BALL * M_BAT / (MB_BALL + M_BAT)
    beta1 = 1 + m * R_BALL**2 / (MB_BALL * K_BALL**2) + m * R_BAT**2 / (M_BAT * K_BAT**2)
    e = 0.540 - (abs(v3) - 26.8) / 400
    pc = -m * v3
    pf = pc * (1 + e)
    s = (v1 > 0) - (v1 < 0)
    ps = m * v1 / (mu * s * beta1) if s != 0 else 0.0
    p1 = -mu * s * min(ps, pf)
    vbf = (vb[0] + (p1 * n1[0] + pf * n3[0]) / MB_BALL, vb[1] + (p1 * n1[1] + pf * n3[1]) / MB_BALL)
    wbf = wb - R_BALL * p1 / (MB_BALL * K_BALL**2)
    speed = math.hypot(*vbf)
    zeta = math.atan2(vbf[1], vbf[0])
    return dict(speed=speed, spin=wbf, angle=zeta, vx=vbf[0], vy=vbf[1], e=e, pc=pc, pf=pf, ps=ps, v1=v1, v3=v3)


def cd_sawicki(re):
    if re < 160000:
        return min(0.5, 0.15 + 0.0416812 * (math.exp((160000 - re) / 8784.46) - 1))
    if re <= 175000:
        return 0.15
    return 0.15 + 0.309620 * (1 - math.exp(-(re - 175000) / 49808.6))


def cl(s):
    return 1.5 * s if s <= 0.1 else 0.09 + 0.6 * s


def rhs(t, u, spin, wind, cd=cd_sawicki):
    x, y, vx, vy = u
    rx, ry = wind - vx, -vy
    q = math.hypot(rx, ry)
    area = math.pi * R_BALL**2
    k = 0.5 * RHO * area / MB_BALL
    ax = ay = 0.0
    if q > 0:
        c = cd(2 * q * R_BALL / NU)
        ax += k * c * q * rx
        ay += k * c * q * ry
        if spin != 0:
            clv = cl(R_BALL * abs(spin) / q)
            sg = 1 if spin > 0 else -1
            ax += k * clv * q * sg * ry
            ay += k * clv * q * sg * (-rx)
    return [vx, vy, ax, ay - G]


def fly(vx, vy, spin, wind=0.0, cd=cd_sawicki, rtol=1e-12, atol=1e-12):
    land = lambda t, u, *a: u[1]
    land.terminal = True
    land.direction = -1
    sol = solve_ivp(rhs, (0, 60), [0, 1.0, vx, vy], args=(spin, wind, cd), method="DOP853",
                    rtol=rtol, atol=atol, events=land, dense_output=True)
    t = sol.t_events[0][0]
    u = sol.y_events[0][0]
    return dict(range=u[0], time=t)


def swing_range(pitch_speed, pitch_spin, undercut, swing_angle, bat_speed=30.0, **kw):
    imp = impact(pitch_speed, pitch_spin, bat_speed, undercut, swing_angle)
    return fly(imp["vx"], imp["vy"], imp["spin"], **kw), imp


if __name__ == "__main__":
    print("V_by0(38) =", pitch(38)[0])
    for name, vb, wb, E, psi in [("fast", 42, -200, 0.0265, 0.1594), ("knuckle", 36, 0, 0.0250, 0.1549),
                                 ("curve", 35, 200, 0.0223, 0.1152)]:
        f, imp = swing_range(vb, wb, E, psi)
        print(name, "speed %.4f spin %.3f angle %.5f range %.6f time %.6f" % (imp["speed"], imp["spin"], imp["angle"], f["range"], f["time"]))
