#!/usr/bin/python3
"""A second generator of whole-machine recordings, written apart from planter-sim: the same
columns, but its own structure and integrator. There is no firmware and no bus: an operator's
speed profile drives the machine open loop, the clamp cycles between positions, the states are
integrated with classical fourth-order Runge-Kutta at 1 ms, and the rows are sampled at about
100 Hz with +-1 ms jitter. The forms are the nominal structures of PRODUCT.md (what planter-fit
assumes): the soil wheel's speed estimate lags the ground, the disc drive is a first-order lag
with a torque of J dw/dt + b w, the clamp law is k (x - x0)^n, the depth actuator a rate-limited
first-order lag, the draft F (A + B S + C S^2) T_ref (d/T_ref)^m in ASABE D497's form, built up
over travel and relaxing at rest (a share s: ds/dt = v (1 - s) / K - s / tau). Effects are hidden
with options.

Usage: outside_machine.py OUT.csv [--noise K] [--seed N] [--relaxation FRAC TAU_S]
       [--command-delay S] [--coulomb NM] [--force-offset N] [--vibration HZ AMP_N]
       [--hysteresis H_N DELTA_MM] [--draw-nominal SEED] [--instant-draft]
       [--depth-play GAP_MM low|high] [--clamp-scale S] [--ground-noise MPS]
       [--force-limit N] [--omega-step RADPS] [--stiffer-at T_S RATIO] [--disc-only]
--noise scales every channel's measurement noise (1: the reference levels).
--draw-nominal draws every nominal value uniformly across a range around this file's own (the
  ranges are in DRAWN below; the depth exponent across the 1-2 a soil's D497 exponent spans).
--instant-draft: the draft is there in full while the ground moves and gone at rest (no
  build-up over travel, no relaxation): the limit the nominal draft structure must reach.
--depth-play: a play of GAP_MM between the depth actuator and the opener (the recorded depth is
  the opener's), powered up against one end of the gap, as a gear train is.
--clamp-scale multiplies the clamp's stiffness and its load cell's noise (a larger press), so a
  hysteresis of kilonewtons keeps its share of the channel's range.
--ground-noise: the ground speed sensor's (v_ground's) noise, m/s (an input the ground channel
  reads; the reference is NOISE["v"]).
--force-limit: the load cell reads no more than N (a hard limit on an output).
--omega-step: the disc speed is logged in steps of RADPS (a coarse speed log).
--stiffer-at: the clamp is RATIO times as stiff from T_S on (a new seedling batch).
--disc-only: only t, omega_cmd and omega are written (a clean first-order system, as a log of
  another machine's speed loop would be).
"""
import argparse
import math
import random

p = argparse.ArgumentParser()
p.add_argument("out")
p.add_argument("--noise", type=float, default=1.0)
p.add_argument("--seed", type=int, default=1)
p.add_argument("--relaxation", type=float, nargs=2, default=[0.0, 1.0])
p.add_argument("--command-delay", type=float, default=0.0)
p.add_argument("--coulomb", type=float, default=0.0)
p.add_argument("--force-offset", type=float, default=0.0)
p.add_argument("--vibration", type=float, nargs=2, default=[0.0, 0.0])
p.add_argument("--hysteresis", type=float, nargs=2, default=[0.0, 1.0])
p.add_argument("--draw-nominal", type=int, default=None)
p.add_argument("--instant-draft", action="store_true")
p.add_argument("--depth-play", nargs=2, default=None)
p.add_argument("--clamp-scale", type=float, default=1.0)
p.add_argument("--ground-noise", type=float, default=None)
p.add_argument("--force-limit", type=float, default=None)
p.add_argument("--omega-step", type=float, default=None)
p.add_argument("--stiffer-at", type=float, nargs=2, default=None)
p.add_argument("--disc-only", action="store_true")
a = p.parse_args()
rng = random.Random(a.seed)

# The machine (values of its own, not planter-sim's).
SIGMA, DISC_R = 1.5, 0.19          # m
T_D, OMEGA_MAX = 0.08, 1.2         # s, rad/s
J, B = 0.35, 1.8                   # kg m^2, N m s/rad
K_C, X0, N_EXP = 16.0, 1.2, 1.25   # N/mm^n, mm, 1
T_A, R_MAX = 0.4, 30.0             # s, mm/s
# Draft (D497 form): coarse soil, a lighter tine than planter-sim's default, depth exponent 1.3.
F_TEX, A_D, B_D, M_D = 0.65, 60.0, 4.0, 1.3   # 1, N/cm, N/(cm km/h), 1
K_MOB, TAU_REST = 0.015, 20.0      # m, s: a longer build-up and a quicker relaxation than planter-sim
LAG = 0.06                         # s, the wheel's speed estimate
DURATION, DT = 300.0, 0.001
NOISE = {"v": 2e-4, "w": 1e-3, "q": 5e-3, "f": 0.5, "d": 0.05, "df": 0.3}

# --draw-nominal: each value drawn uniformly from (low, high). The ranges are this generator's
# own guesses at what machines of this kind span ("assumed"), not fitted to anything.
DRAWN = {"T_D": (0.04, 0.16), "J": (0.2, 0.6), "B": (1.0, 3.0), "K_C": (8.0, 30.0),
         "X0": (0.6, 1.8), "N_EXP": (1.0, 1.6), "T_A": (0.2, 0.8), "R_MAX": (15.0, 45.0),
         "F_TEX": (0.45, 1.0), "A_D": (40.0, 90.0), "B_D": (2.0, 6.0), "M_D": (1.0, 2.0),
         "K_MOB": (0.005, 0.04), "TAU_REST": (5.0, 60.0), "LAG": (0.03, 0.12)}
if a.draw_nominal is not None:
    drawn_rng = random.Random(a.draw_nominal)
    for name, (low, high) in DRAWN.items():
        globals()[name] = drawn_rng.uniform(low, high)
K_C *= a.clamp_scale
NOISE["f"] *= a.clamp_scale
PLAY = float(a.depth_play[0]) if a.depth_play else 0.0
if a.depth_play and a.depth_play[1] not in ("low", "high"):
    p.error("--depth-play END must be low or high")


def wheel_speed(t):
    """The soil wheel's speed estimate: it lags the ground, and its noise comes from counting
    encoder edges, so a wheel that stands reads exactly zero."""
    w = ground_speed(t - LAG)
    return w + rng.gauss(0, noise["v"]) if w > 0.0 else 0.0


def ground_speed(t):
    """The operator: starts, two stops, a slower stretch (m/s)."""
    def ramp(t0, t1, v0, v1, x):
        return v0 + (v1 - v0) * min(1.0, max(0.0, (x - t0) / (t1 - t0)))
    if t < 3:
        return ramp(1, 3, 0, 0.06, t)
    if t < 90:
        return 0.06
    if t < 105:
        return ramp(90, 92, 0.06, 0.0, t)
    if t < 200:
        return ramp(105, 107, 0.0, 0.045, t)
    if t < 215:
        return ramp(200, 202, 0.045, 0.0, t)
    return ramp(215, 217, 0.0, 0.06, t)


def clamp_target(t):
    """The roller cycles: closed at a level that changes every 7 s, open for 1 s (mm); it
    travels there at up to 40 mm/s."""
    k = int(t // 7.0)
    if t - 7.0 * k > 6.0:
        return 0.0
    return 3.0 + 5.0 * ((k * 7919) % 100) / 100.0


def depth_command(t):
    return 60.0 if t < 120 else (45.0 if t < 180 else 75.0)


def rk4(f, y, t, h):
    k1 = f(t, y)
    k2 = f(t + h / 2, [yi + h / 2 * ki for yi, ki in zip(y, k1)])
    k3 = f(t + h / 2, [yi + h / 2 * ki for yi, ki in zip(y, k2)])
    k4 = f(t + h, [yi + h * ki for yi, ki in zip(y, k3)])
    return [yi + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4) for yi, a1, a2, a3, a4 in zip(y, k1, k2, k3, k4)]


def omega_command(t):
    return SIGMA * ground_speed(t) / DISC_R


def derivatives(t, y):
    """States: disc speed, depth, the relaxed share of the clamp force, the roller, and the
    clamp's hysteresis (Bouc-Wen with n = 1, beta = gamma), and the mobilised share of the draft."""
    w, d, relaxed, x, z, share = y
    target = min(omega_command(t - a.command_delay), OMEGA_MAX)
    dw = (target - w) / T_D
    dd = max(-R_MAX, min(R_MAX, (depth_command(t) - d) / T_A))
    dx = max(-40.0, min(40.0, (clamp_target(t) - x) / 0.01))
    elastic = clamp_k(t) * max(0.0, x - X0) ** N_EXP
    frac, tau = a.relaxation
    dr = (frac * elastic - relaxed) / tau if frac > 0 else 0.0
    delta = a.hysteresis[1]
    dz = (dx - 0.5 * abs(dx) * z - 0.5 * dx * abs(z)) / delta
    dshare = 0.0 if a.instant_draft else ground_speed(t) * (1.0 - share) / K_MOB - share / TAU_REST
    return [dw, dd, dr, dx, dz, dshare]


def clamp_k(t):
    return K_C * (a.stiffer_at[1] if a.stiffer_at and t >= a.stiffer_at[0] else 1.0)


def logged_omega(w):
    return round(w / a.omega_step) * a.omega_step if a.omega_step else w


def opener(d):
    """The opener behind a play of PLAY (mm): the play operator, its state kept between rows.
    It starts against one end: 'low' leaves the opener half the gap below the actuator."""
    global opener_at
    half = 0.5 * PLAY
    opener_at = min(max(opener_at, d - half), d + half)
    return opener_at


columns = ["t", "v_ground", "v_wheel", "omega_cmd", "omega", "disc_torque", "clamp_pos_mm",
           "clamp_force", "depth_cmd_mm", "depth_mm", "depth_force"]
written = [columns.index(c) for c in (["t", "omega_cmd", "omega"] if a.disc_only else columns)]
t, y = 0.0, [0.0, 60.0, 0.0, 0.0, 0.0, 0.0]
opener_at = 60.0 + (0.5 * PLAY if a.depth_play and a.depth_play[1] == "high" else -0.5 * PLAY)
next_sample = 0.0
noise = {k: v * a.noise for k, v in NOISE.items()}
ground_noise = noise["v"] if a.ground_noise is None else a.ground_noise
with open(a.out, "w") as out:
    out.write("# source: outside_machine.py (a second generator, not planter-sim)\n")
    out.write(",".join(columns[i] for i in written) + "\n")
    while t < DURATION:
        if t >= next_sample:
            w, d, relaxed, x, z, share = y
            dw = derivatives(t, y)[0]
            v = ground_speed(t)
            dry = a.coulomb * math.tanh(w / 1e-3)
            elastic = clamp_k(t) * max(0.0, x - X0) ** N_EXP
            force = max(0.0, elastic - relaxed) + a.hysteresis[0] * z + a.force_offset + \
                a.vibration[1] * math.sin(2 * math.pi * a.vibration[0] * t)
            read = force + rng.gauss(0, noise["f"])
            if a.force_limit is not None:
                read = min(read, a.force_limit)
            s_kmh = 3.6 * max(0.0, v)
            if a.instant_draft:
                share = 1.0 if v > 0.0 else 0.0
            d = opener(d)
            draft = F_TEX * (A_D + B_D * s_kmh) * 10.0 * (max(0.0, d) / 100.0) ** M_D * share
            row = [t, v + rng.gauss(0, ground_noise), wheel_speed(t),
                   omega_command(t), logged_omega(w + rng.gauss(0, noise["w"])),
                   J * dw + B * w + dry + rng.gauss(0, noise["q"]), x,
                   read, depth_command(t), d + rng.gauss(0, noise["d"]),
                   draft + rng.gauss(0, noise["df"])]
            out.write(",".join("%.6g" % row[i] if i else "%.4f" % row[i] for i in written) + "\n")
            next_sample += 0.01 + rng.uniform(-0.001, 0.001)
        y = rk4(derivatives, y, t, DT)
        t += DT
