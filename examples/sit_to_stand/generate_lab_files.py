#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes a synthetic lab trial of the sit-to-stand: lab/rise.trc (markers) and lab/rise.mot
(chair and floor force plates), from model.alb's minimum-jerk motion and the model's own
dynamics, computed here independently of Alembert.

The trial runs from t = -0.5 s, seated still in the seat-off posture while the chair's load on
the thighs fades out, through the rise (t = 0 to 1.5 s, model.alb's motion) to standing still
until 2 s. Coordinates are the lab's: the floor at Y = 0, the ankle at (0.25, 0.08) m, X
forward, Y up, Z to the subject's right (out of the sagittal plane, at the viewer).

    python3 examples/sit_to_stand/generate_lab_files.py [DIR]   # writes DIR (default lab/)
"""
import math
import os
import sys

# ---- model.alb's values (Winter 2009, Table 4.1, 70 kg, 1.70 m) ---------------------------
g = 9.81
L_A, L_B = 0.4182, 0.4165
d_A, d_B, d_C = 0.2371, 0.2362, 0.3065
m_A, m_B, m_C = 6.51, 14.00, 47.46
I_A, I_B, I_C = 0.1038, 0.2534, 2.799
L_ACR, F_ACR = 0.50, 0.05  # the shoulder marker: 50 cm up the trunk, 5 cm forward of its axis

# ---- the lab ------------------------------------------------------------------------------
ANKLE_LAB = (0.25, 0.08)  # the model's origin N_o (the ankle) in the lab, m
RATE = 100.0              # Hz
T0, T1 = -0.5, 2.0        # s
CHAIR_FORCE = 300.0       # N, the chair's vertical load on the thighs while seated
CHAIR_FADE = (-0.3, 0.0)  # s: the load fades (half cosine) to zero at seat-off, t = 0


def minimum_jerk(t, t0, t1):
    """s(u) = 10u^3 - 15u^4 + 6u^5 of u = (t - t0)/(t1 - t0), held at 0 before and 1 after;
    returns s, s', s'' (Flash and Hogan 1985)."""
    T = t1 - t0
    u = (t - t0) / T
    if u <= 0:
        return 0.0, 0.0, 0.0
    if u >= 1:
        return 1.0, 0.0, 0.0
    return (10 * u**3 - 15 * u**4 + 6 * u**5,
            (30 * u**2 - 60 * u**3 + 30 * u**4) / T,
            (60 * u - 180 * u**2 + 120 * u**3) / T**2)


def coordinates(t):
    """model.alb's motion: (q, q', q'') of qA, qB, qC in rad."""
    rad = math.pi / 180
    out = []
    for start, span, t0 in ((-25, 20, 0.15), (105, -95, 0.0), (-130, 120, 0.0)):
        s, sd, sdd = minimum_jerk(t, t0, 1.5)
        out.append(((start + span * s) * rad, span * sd * rad, span * sdd * rad))
    return out


def chair_force(t):
    """The chair's vertical force on the thighs, N."""
    a, b = CHAIR_FADE
    if t <= a:
        return CHAIR_FORCE
    if t >= b:
        return 0.0
    return CHAIR_FORCE * 0.5 * (1 + math.cos(math.pi * (t - a) / (b - a)))


def along(theta, d):
    """d Ay> of a segment at angle theta from Ny> (Ay> = -sin theta Nx> + cos theta Ny>)."""
    return (-d * math.sin(theta), d * math.cos(theta))


def across(theta, d):
    """d Ax> (Ax> = cos theta Nx> + sin theta Ny>)."""
    return (d * math.cos(theta), d * math.sin(theta))


def add(*vs):
    return (sum(v[0] for v in vs), sum(v[1] for v in vs))


def state(t):
    """Joint and centre-of-mass positions (from the ankle, m), the segments' angles, angular
    velocities and accelerations, and the centres of mass's accelerations at t."""
    (qA, wA, aA), (qB, wB, aB), (qC, wC, aC) = coordinates(t)
    th = (qA, qA + qB, qA + qB + qC)
    w = (wA, wA + wB, wA + wB + wC)
    al = (aA, aA + aB, aA + aB + aC)

    def acc(i, d):  # acceleration of the point d along segment i's axis, from its proximal joint
        # d/dt^2 of d (-sin th, cos th) = d [al (-cos th, -sin th) + w^2 (sin th, -cos th)]
        return (d * (-al[i] * math.cos(th[i]) + w[i] ** 2 * math.sin(th[i])),
                d * (-al[i] * math.sin(th[i]) - w[i] ** 2 * math.cos(th[i])))

    knee = along(th[0], L_A)
    hip = add(knee, along(th[1], L_B))
    shoulder = add(hip, along(th[2], L_ACR), across(th[2], F_ACR))
    cms = (along(th[0], d_A), add(knee, along(th[1], d_B)), add(hip, along(th[2], d_C)))
    a_knee = acc(0, L_A)
    a_hip = add(a_knee, acc(1, L_B))
    a_cm = (acc(0, d_A), add(a_knee, acc(1, d_B)), add(a_hip, acc(2, d_C)))
    return dict(ankle=(0.0, 0.0), knee=knee, hip=hip, shoulder=shoulder, cm=cms, alpha=al, a_cm=a_cm)


def cross(r, f):
    return r[0] * f[1] - r[1] * f[0]


def loads(t):
    """The chair's load on the thighs (force, centre of pressure, from the ankle) and the
    floor's on the feet, from the model's dynamics: the feet are still and massless, so the
    floor's force is the ankle's force on the shank, F = sum m_i (a_i - g) - F_chair, and its
    centre of pressure on the floor (y = -0.08 m) carries the ankle moment,
    p x F = T_A = sum [r_i x m_i (a_i - g) + I_i alpha_i] - p_chair x F_chair."""
    s = state(t)
    masses, inertias = (m_A, m_B, m_C), (I_A, I_B, I_C)
    Fc = (0.0, chair_force(t))
    p_chair = (0.5 * (s['knee'][0] + s['hip'][0]), s['hip'][1] - 0.08)  # under the thigh, on the seat
    F = [0.0, 0.0]
    T_A = 0.0
    for m, I, r, a, al in zip(masses, inertias, s['cm'], s['a_cm'], s['alpha']):
        f = (m * a[0], m * (a[1] + g))
        F[0] += f[0]
        F[1] += f[1]
        T_A += cross(r, f) + I * al
    F = (F[0] - Fc[0], F[1] - Fc[1])
    T_A -= cross(p_chair, Fc)
    floor_y = -ANKLE_LAB[1]
    # p x F = px Fy - py Fx = T_A at py = floor_y
    p_floor = ((T_A + floor_y * F[0]) / F[1], floor_y)
    return Fc, p_chair, F, p_floor, T_A


def lab(p):
    return (p[0] + ANKLE_LAB[0], p[1] + ANKLE_LAB[1])


def write(path, text):
    tmp = path + '.tmp'
    with open(tmp, 'w', newline='\n') as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lab')
    os.makedirs(out, exist_ok=True)
    n = int(round((T1 - T0) * RATE)) + 1
    times = [T0 + k / RATE for k in range(n)]
    names = ('LMAL', 'LFE', 'GTR', 'ACR')

    # markers, mm with three decimals (0.5 micrometre rounding), Z the same plane
    rows = []
    for k, t in enumerate(times):
        s = state(t)
        cells = [str(k + 1), '%.3f' % t]
        for p in (s['ankle'], s['knee'], s['hip'], s['shoulder']):
            x, y = lab(p)
            cells += ['%.3f' % (1000 * x), '%.3f' % (1000 * y), '%.3f' % 0.0]
        rows.append('\t'.join(cells))
    header = ['PathFileType\t4\t(X/Y/Z)\trise.trc',
              'DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames',
              '%.2f\t%.2f\t%d\t%d\tmm\t%.2f\t1\t%d' % (RATE, RATE, n, len(names), RATE, n),
              'Frame#\tTime\t' + '\t\t\t'.join(names) + '\t\t',
              '\t\t' + '\t'.join('X%d\tY%d\tZ%d' % (i + 1, i + 1, i + 1) for i in range(len(names))),
              '']
    write(os.path.join(out, 'rise.trc'), '\n'.join(header + rows) + '\n')

    # force plates: floor (ground_force) and chair (1_ground_force), N and m, 4 decimals
    labels = ['time']
    for plate in ('ground', '1_ground'):
        labels += ['%s_force_v%s' % (plate, a) for a in 'xyz'] + ['%s_force_p%s' % (plate, a) for a in 'xyz']
    for plate in ('ground', '1_ground'):
        labels += ['%s_torque_%s' % (plate, a) for a in 'xyz']
    rows = []
    for t in times:
        Fc, pc, F, pf, _ = loads(t)
        pf, pc = lab(pf), lab(pc)
        if Fc[1] == 0:
            pc = (0.0, 0.0)  # out of contact the centre of pressure is not defined
        cells = [t, F[0], F[1], 0.0, pf[0], pf[1], 0.0, Fc[0], Fc[1], 0.0, pc[0], pc[1], 0.0] + [0.0] * 6
        rows.append('\t'.join('%.4f' % c if i else '%.3f' % c for i, c in enumerate(cells)))
    header = ['rise_grf', 'version=1', 'nRows=%d' % n, 'nColumns=%d' % len(labels), 'inDegrees=no', 'endheader',
              '\t'.join(labels)]
    write(os.path.join(out, 'rise.mot'), '\n'.join(header + rows) + '\n')


if __name__ == '__main__':
    main()
