"""Independent reference for the bat-ball impact in three dimensions: a bat
tilted (barrel below the hands), swung toward any direction, by a right- or
left-handed batter (docs/swing-3d.md, shared/DESIGN.md "Three dimensions").

Written from the physics, apart from the Rust core, in the most literal form:
  - the geometry by rotation matrices: a right-handed batter's level, square
    bat lies along +z, moving along +x; tilt it by T (the swing plane's
    tilt) about the direction of its motion: the bottom of a swing arc in a
    plane tilted T; turn bat and velocity together about that plane's normal
    until the velocity rises at the swing angle psi (a rigid bat turning in
    its plane: its velocity stays square to it), or where |sin psi| >=
    |sin T| keep the bat level and tip the velocity up by psi about the bat;
    then turn about the vertical until the velocity's horizontal direction
    is phi; a bat that leads its path by lambda (bat.lead) is then turned
    by lambda about the normal of the plane holding its axis and its
    velocity, the barrel toward the velocity, the velocity kept (Rodrigues'
    rotation); a left-handed batter is that bat, swung toward -phi with the
    same lead, reflected in z;
  - the bodies as full rigid-body vectors in the flight frame (ball velocity
    and spin, bat velocity and spin), with the bat's inverse inertia
    a a^T / (M_B k_B2^2) (it rolls about its own axis only) and its point on
    the axis moving with the effective mass M_B in every direction;
  - the collision integrated over the normal impulse p with scipy's
    solve_ivp (DOP853, rtol = atol = 1e-13), the impulse increment
    dP = (n3 - mu s_hat) dp with s_hat the unit sliding velocity of the
    contact points (V + omega x r, Eq. 9-10) while they slide; when the slip
    falls below 1e-11 of its start (an event), the contact sticks if the
    tangential impulse that keeps it stuck, from the inverse-inertia matrix
    built numerically, is within mu of the normal one, and slides on if not;
  - the end of contact from the energetic definition of e* (Stronge, as the
    paper): compression ends where the normal relative velocity vanishes
    (an event); restitution ends where the normal force has given back
    e*^2 of the work it took in compression, e* from Eq. (19) in the
    approach speed. No closed form for p_c or p_f is used.
The Rust core instead solves the slip in tau = int dp/|s| (closed-form
exponentials) and integrates p(tau) with DOPRI5.

    python3 reference/impact3d.py > tests/data/impact3d_reference.csv
"""
import math
import random
import sys

import numpy as np
from scipy.integrate import solve_ivp

from model import G, K_BALL, K_BAT, M_BAT, MB_BALL, R_BALL, R_BAT, pitch

RTOL = ATOL = 1e-13
STUCK = 1e-11  # the slip, relative to its start, that counts as halted


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def rot_y(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


MIRROR = np.diag([1.0, 1.0, -1.0])


def rot_about(n, a):
    """Rodrigues: the rotation by a about the unit vector n."""
    n = np.asarray(n, dtype=float)
    k = np.array([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return np.eye(3) + math.sin(a) * k + (1 - math.cos(a)) * (k @ k)


def bat_frame(tilt, direction, hand, swing_angle, lead=0.0):
    """(axis hands->barrel, up square to it in its vertical plane, the
    horizontal square to both, the unit velocity) of a bat swung at
    swing_angle within a swing plane tilted `tilt`, leading its path by
    `lead`."""
    if hand == "left":
        axis, up, forward, path = bat_frame(tilt, -direction, "right", swing_angle, lead)
        return MIRROR @ axis, MIRROR @ up, MIRROR @ forward, MIRROR @ path
    x, y, z = np.eye(3)
    if abs(math.sin(swing_angle)) >= abs(math.sin(tilt)):
        # No plane of that tilt holds the velocity: the paper's level bat.
        axis, path = z, rot_z(swing_angle) @ x
    else:
        # The bottom of the arc in the plane tilted about the motion...
        bottom = rot_x(tilt)
        normal = bottom @ y
        # ...then along the arc until the velocity rises at swing_angle:
        # v_y = sin(alpha) sin(tilt).
        alpha = math.asin(math.sin(swing_angle) / math.sin(tilt))
        along = rot_about(normal, alpha)
        axis, path = along @ bottom @ z, along @ x
    # Turn about the vertical until the velocity heads toward `direction`.
    heading = math.atan2(path[2], path[0])
    turn = rot_y(-(direction - heading))
    axis, path = turn @ axis, turn @ path
    if lead != 0.0:
        # The barrel ahead of square by `lead`, within the plane that holds
        # the bat and its velocity: about that plane's normal axis x path.
        normal = np.cross(axis, path)
        axis = rot_about(normal / np.linalg.norm(normal), lead) @ axis
    up = y - (y @ axis) * axis
    up = up / np.linalg.norm(up)
    forward = np.cross(up, axis)
    return axis, up, forward, path


def impact(case):
    hand = case["hand"]
    psi = case["swing_angle"]
    axis, up, forward, path = bat_frame(case["tilt"], case["direction"], hand, psi,
                                        case.get("lead", 0.0))
    theta = math.asin(case["undercut"] / (R_BALL + R_BAT))
    n3 = math.cos(theta) * forward + math.sin(theta) * up
    # The paper's frame: n2 along the bat (+z for either hand at a square,
    # level contact), n1 = n2 x n3.
    n2 = axis if hand == "right" else -axis
    n1 = np.cross(n2, n3)

    speed, spin = case["pitch_speed"], case["pitch_spin"]
    if "pitch_velocity" in case:
        # A tracked pitch (reference/swing_solve.py): its own velocity.
        vb0 = np.array(case["pitch_velocity"], dtype=float)
    else:
        _, gamma = pitch(speed, G)
        vb0 = np.array([-speed * math.cos(gamma), -speed * math.sin(gamma), 0.0])
    wb0 = np.array([0.0, 0.0, spin])
    vB0 = case["bat_speed"] * path
    # Fig. 9's positive roll adds backspin: about -n2.
    wB0 = -case["bat_spin"] * n2

    r_ball = -R_BALL * n3  # centre of the ball -> contact point
    r_bat = R_BAT * n3  # the bat's axis -> contact point
    i_ball = MB_BALL * K_BALL**2
    i_bat = M_BAT * K_BAT**2
    mu = case["friction"]

    def unpack(y):
        return y[0:3], y[3:6], y[6:9], y[9:12]

    def relative(y):
        vb, wb, vB, wB = unpack(y)
        return vb + np.cross(wb, r_ball) - vB - np.cross(wB, r_bat)

    def apply(y, dP):
        """d(state) for an impulse dP on the ball (-dP on the bat)."""
        return np.concatenate(
            [
                dP / MB_BALL,
                np.cross(r_ball, dP) / i_ball,
                -dP / M_BAT,
                axis * np.dot(axis, np.cross(r_bat, -dP)) / i_bat,
            ]
        )

    # The inverse-inertia matrix at the contact, column by column.
    y_any = np.zeros(12)
    K = np.column_stack([relative(apply(y_any, e)) - relative(y_any) for e in np.eye(3)])

    def tangential(v):
        return v - np.dot(v, n3) * n3

    s0 = np.linalg.norm(tangential(relative(np.concatenate([vb0, wb0, vB0, wB0]))))

    def rhs_slip(p, y):
        v = relative(y[:12])
        t = tangential(v)
        dP = n3 - mu * t / np.linalg.norm(t)
        return np.concatenate([apply(y, dP), [np.dot(v, n3)]])

    # Sticking: the tangential impulse rate that keeps dv_t = 0, solved in
    # the tangent plane's basis (n1, n2).
    basis = np.column_stack([n1, n2])
    Ktt = basis.T @ K @ basis
    Ktn = basis.T @ K @ n3
    stick_rate = -np.linalg.solve(Ktt, Ktn)  # d(p1, p2)/dp
    sticks = np.linalg.norm(stick_rate) <= mu

    def rhs_stick(p, y):
        v = relative(y[:12])
        dP = n3 + basis @ stick_rate
        return np.concatenate([apply(y, dP), [np.dot(v, n3)]])

    y = np.concatenate([vb0, wb0, vB0, wB0, [0.0]])
    approach = np.dot(relative(y[:12]), n3)
    restitution = 0.540 - (abs(approach) - 26.8) / 400.0

    # No slip at all: stuck from the start.
    state = {"p": 0.0, "y": y, "stuck": s0 == 0.0, "halt": 0.0 if s0 == 0.0 else None}

    def run(until, event):
        """Integrates from the current state, stopping at `event` (or at the
        halt of slip, which switches to sticking)."""
        while state["p"] < until:
            slipping = not state["stuck"]
            rhs = rhs_slip if slipping else rhs_stick
            events = [event] if event else []
            if slipping and mu > 0:

                def halt(p, y):
                    return np.linalg.norm(tangential(relative(y[:12]))) - STUCK * s0

                halt.terminal, halt.direction = True, -1
                events.append(halt)
            sol = solve_ivp(
                rhs, (state["p"], until), state["y"], method="DOP853",
                rtol=RTOL, atol=ATOL, events=events or None, dense_output=True,
            )
            if sol.status == 1:
                fired = [k for k, t in enumerate(sol.t_events) if len(t)]
                k = min(fired, key=lambda k: sol.t_events[k][0])
                p_event = sol.t_events[k][0]
                state["p"], state["y"] = p_event, sol.y_events[k][0]
                if event and k == 0:
                    return True
                # The slip halted.
                state["halt"] = p_event
                state["stuck"] = sticks
                if not sticks:
                    raise RuntimeError("slip halts but mu is below the stick coefficient")
                continue
            state["p"], state["y"] = until, sol.y[:, -1]
            return False
        return False

    # Compression: to v3 = 0.
    def compressed(p, y):
        return np.dot(relative(y[:12]), n3)

    compressed.terminal, compressed.direction = True, 1
    if approach < 0:
        run(1e3, compressed)
    p_c = state["p"]
    work_in = state["y"][12]  # < 0

    def restored(p, y):
        return (y[12] - work_in) + restitution**2 * work_in

    restored.terminal, restored.direction = True, 1
    if approach < 0:
        run(1e3, restored)
    p_f = state["p"]
    # A contact that grips (tangential restitution e_T, Cross 2002): once
    # the slip has halted it gives back e_T times the tangential impulse
    # that halted it, along it, no more than friction passes over p_s..p_f.
    grip = case.get("tangential_restitution", 0.0)
    halted = state["halt"] is not None and state["halt"] < p_f
    capped = False
    if grip > 0 and halted:
        halting = tangential(MB_BALL * (state["y"][0:3] - vb0))
        size = np.linalg.norm(halting)
        if size > 0:
            given = min(grip * size, mu * (p_f - state["halt"]))
            capped = given < grip * size
            release = halting / size * given
            state["y"] = state["y"] + np.concatenate([apply(state["y"], release), [0.0]])
    vb, wb, _, _ = unpack(state["y"][:12])

    # The slip's direction halfway to where it halts or the ball leaves.
    p_half = 0.5 * min(state["halt"] if state["halt"] is not None else math.inf, p_f)
    half = solve_ivp(
        rhs_slip, (0.0, p_half), np.concatenate([vb0, wb0, vB0, wB0, [0.0]]),
        method="DOP853", rtol=RTOL, atol=ATOL,
    ).y[:, -1] if p_half > 0 and mu > 0 else np.concatenate([vb0, wb0, vB0, wB0, [0.0]])
    v_half = relative(half[:12])
    slip_angle = math.atan2(np.dot(v_half, n2), np.dot(v_half, n1))

    launch_speed = np.linalg.norm(vb)
    angle = math.atan2(vb[1], math.hypot(vb[0], vb[2]))
    direction = math.atan2(vb[2], vb[0])
    back_axis = np.array([-math.sin(direction), 0.0, math.cos(direction)])
    side_axis = np.array(
        [
            math.sin(angle) * math.cos(direction),
            -math.cos(angle),
            math.sin(angle) * math.sin(direction),
        ]
    )
    return {
        "launch_speed": launch_speed,
        "launch_angle": angle,
        "launch_direction": direction,
        "backspin": np.dot(wb, back_axis),
        "sidespin": np.dot(wb, side_axis),
        "gyrospin": np.dot(wb, vb) / launch_speed,
        "regime": "stick" if state["halt"] is not None and state["halt"] < p_f else "slip",
        "stick_impulse": state["halt"] if state["halt"] is not None and state["halt"] < p_f else math.nan,
        "separation_impulse": p_f,
        "compression_impulse": p_c,
        "slip_angle_half": slip_angle,
        "coupling": np.linalg.norm(Ktn),
        "capped": capped,
    }


INPUTS = [
    "hand", "tilt", "direction", "undercut", "swing_angle", "friction",
    "pitch_speed", "pitch_spin", "bat_speed", "bat_spin", "tangential_restitution", "lead",
]
OUTPUTS = [
    "launch_speed", "launch_angle", "launch_direction", "backspin", "sidespin", "gyrospin",
    "regime", "stick_impulse", "compression_impulse", "separation_impulse", "slip_angle_half",
]


def drawn(rng, mu):
    """A swing drawn across the keys' bounds, at friction mu."""
    return dict(
        hand=rng.choice(["right", "left"]),
        tilt=round(rng.uniform(-1.0, 1.0), 4),
        direction=round(rng.uniform(-1.0, 1.0), 4),
        undercut=round(rng.uniform(-0.06, 0.06), 5),
        swing_angle=round(rng.uniform(-0.5, 0.8), 4),
        friction=mu,
        pitch_speed=round(rng.uniform(30.0, 45.0), 2),
        pitch_spin=round(rng.uniform(-300.0, 300.0), 1),
        bat_speed=round(rng.uniform(20.0, 40.0), 2),
        bat_spin=round(rng.choice([0.0, rng.uniform(-60.0, 60.0)]), 1),
    )


def cases():
    # Representative swings first: the fastball at Table II's swing with the
    # barrel 30 degrees down, square, pulled and late, both hands.
    fast = dict(undercut=0.0265, swing_angle=0.1594, friction=0.5,
                pitch_speed=42.0, pitch_spin=-200.0, bat_speed=30.0, bat_spin=0.0)
    out = []
    for direction in (0.0, -0.349, 0.349):
        for hand in ("right", "left"):
            out.append(dict(fast, hand=hand, tilt=0.5236, direction=direction))
    # The rest drawn across the keys' bounds, with low friction often enough
    # to slide through separation, and some topspin and bat roll.
    rng = random.Random(17)
    while len(out) < 32:
        out.append(drawn(rng, rng.choice([0.0, 0.05, 0.1, 0.2, 0.35, 0.5, 0.8])))
    for case in out:
        case["tangential_restitution"] = 0.0
    # Contacts that grip: the fastball's swing tilted, glancing ones whose
    # slip halts late so that friction caps the spring-back, and draws with
    # friction high enough to stick.
    out.append(dict(fast, hand="right", tilt=0.5236, direction=0.2, tangential_restitution=0.4))
    out.append(dict(fast, hand="left", tilt=0.0, direction=0.0, tangential_restitution=0.6))
    for undercut, friction in ((0.055, 0.5), (0.065, 0.5), (-0.06, 0.8)):
        out.append(dict(fast, hand="right", tilt=0.3, direction=-0.2, undercut=undercut,
                        friction=friction, tangential_restitution=1.0))
    grip_rng = random.Random(29)
    while len(out) < 47:
        case = drawn(grip_rng, grip_rng.choice([0.2, 0.35, 0.5, 0.8]))
        case["tangential_restitution"] = grip_rng.choice([0.2, 0.4, 0.7, 1.0])
        out.append(case)
    for case in out:
        case["lead"] = 0.0
    # Bats that lead their path (bat.lead, session 20): the fastball's swing
    # tilted 30 degrees with the barrel 8 and 20 degrees ahead, both hands;
    # then draws across the keys' bounds with leads of up to 45 degrees.
    for lead in (0.14, 0.35, -0.2):
        for hand in ("right", "left"):
            out.append(dict(fast, hand=hand, tilt=0.5236, direction=-0.1, lead=lead,
                            tangential_restitution=0.0))
    lead_rng = random.Random(41)
    while len(out) < 61:
        case = drawn(lead_rng, lead_rng.choice([0.0, 0.1, 0.35, 0.5, 0.8]))
        case["tangential_restitution"] = lead_rng.choice([0.0, 0.0, 0.4])
        case["lead"] = round(lead_rng.uniform(-0.78, 0.78), 4)
        out.append(case)
    return out


def main():
    print("# generated by: python3 reference/impact3d.py > tests/data/impact3d_reference.csv")
    print("# angles and directions in rad (0 centre field, positive toward right field), spins in")
    print("# rad/s, impulses in N*s; stick_impulse is nan where the contact slips to separation;")
    print("# slip_angle_half is atan2(v2, v1) halfway to the halt or the separation; a contact that")
    print("# grips (tangential_restitution > 0) gives back that share of its halting impulse")
    print(",".join(INPUTS + OUTPUTS))
    worst = 0.0
    capped = 0
    for case in cases():
        result = impact(case)
        worst = max(worst, result["coupling"])
        capped += result["capped"]
        row = [str(case[k]) for k in INPUTS] + [
            result[k] if isinstance(result[k], str) else repr(float(result[k])) for k in OUTPUTS
        ]
        print(",".join(row))
    print(f"largest normal-tangential coupling |K_tn| = {worst:.3e} 1/kg", file=sys.stderr)
    print(f"{capped} gripping contacts whose spring-back friction caps", file=sys.stderr)


if __name__ == "__main__":
    main()
