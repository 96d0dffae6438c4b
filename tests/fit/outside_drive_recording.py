#!/usr/bin/python3
"""Writes a recording planter-fit has never seen the like of: a belt-driven disc whose speed
loop is second order (natural frequency 12 rad/s, damping 0.7), with Coulomb friction of
1.5 N m, a 0.12 s command delay and measurement noise, sampled at about 50 Hz with jitter.
Only t, omega_cmd, omega and disc_torque are present. Usage: outside_drive_recording.py OUT.csv"""
import math
import random
import sys

random.seed(3)
J, b, coulomb, delay = 0.4, 2.0, 1.5, 0.12
wn, zeta, dt = 12.0, 0.7, 0.001


def command(t):
    if t < 2:
        return 0.0
    if t < 40:
        return 0.4
    if t < 70:
        return 0.2
    if t < 80:
        return 0.0
    return 0.35 * (1 + 0.2 * math.sin(t / 5))


t = w = dw = 0.0
next_sample = 0.0
with open(sys.argv[1], "w") as f:
    f.write("# source: an outside drive model (second-order loop)\n")
    f.write("t,omega_cmd,omega,disc_torque\n")
    while t < 150.0:
        acc = wn * wn * (command(t - delay) - w) - 2 * zeta * wn * dw
        dw += acc * dt
        w += dw * dt
        torque = J * dw + b * w + coulomb * math.tanh(w / 0.01)
        if t >= next_sample:
            f.write("%.4f,%.5f,%.5f,%.4f\n" % (t, command(t), w + random.gauss(0, 0.002),
                                              torque + random.gauss(0, 0.05)))
            next_sample = t + 0.02 + random.uniform(-0.003, 0.003)
        t += dt
