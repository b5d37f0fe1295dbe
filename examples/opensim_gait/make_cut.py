#!/usr/bin/env python3
"""Cut OpenSim's Gait10dof18musc example trial to the right leg, and work out the planar
model's constants from the scaled model subject01.osim.

Usage: make_cut.py OPENSIM_MODELS_DIR [OUT_DIR]

OPENSIM_MODELS_DIR is a checkout of github.com/opensim-org/opensim-models; the files are read
from Pipelines/Gait10dof18musc/. The cut keeps every frame (the filter then sees the whole
trial, as OpenSim's did) but only the columns the right leg needs; each cell is copied as
published, never recomputed. Printed: the foot's composite mass, centre of mass and moment of
inertia (talus, calcaneus and toes are welded in the model), and the knee's tibia translation
as polynomials in the knee angle (the model's SimmSplines, evaluated as OpenSim evaluates them,
fitted over the angles of both knees in the trial)."""
import math
import os
import sys
import xml.etree.ElementTree as ET

SRC = "Pipelines/Gait10dof18musc"
TORSO = ["Sternum", "R.Acromium", "L.Acromium", "Top.Head"]
PELVIS = ["R.ASIS", "L.ASIS", "V.Sacral"]
RIGHT = ["R.Thigh.Upper", "R.Thigh.Front", "R.Thigh.Rear", "R.Shank.Upper", "R.Shank.Front", "R.Shank.Rear",
         "R.Heel", "R.Midfoot.Sup", "R.Midfoot.Lat", "R.Toe.Lat", "R.Toe.Med", "R.Toe.Tip"]
LEFT = ["L" + m[1:] for m in RIGHT]


def cut_trc(src, dst, keep):
    lines = open(src).read().split("\n")
    names = lines[3].split("\t")
    # the marker names sit every third column from column 2
    markers = [names[2 + 3 * i] for i in range((len(names) - 2 + 2) // 3) if 2 + 3 * i < len(names)]
    markers = [m.strip() for m in markers]
    idx = [markers.index(m) for m in keep]
    out = [lines[0]]
    rate = lines[2].split("\t")
    rate[3] = str(len(keep))  # NumMarkers
    out += [lines[1], "\t".join(rate)]
    out.append("\t".join(["Frame#", "Time"] + sum([[m, "", ""] for m in keep], [])))
    out.append("\t".join(["", ""] + sum([["X%d" % (k + 1), "Y%d" % (k + 1), "Z%d" % (k + 1)]
                                        for k in range(len(keep))], [])))
    out.append("")
    for line in lines[6:]:
        if not line.strip():
            continue
        cells = line.split("\t")
        row = cells[:2]
        for i in idx:
            row += cells[2 + 3 * i: 5 + 3 * i]
        out.append("\t".join(row))
    open(dst, "w").write("\n".join(out) + "\n")


def cut_storage(src, dst, keep):
    text = open(src).read().split("\n")
    end = next(i for i, l in enumerate(text) if l.strip() == "endheader")
    labels = text[end + 1].split()
    idx = [labels.index(k) for k in keep]
    rows = [l.split() for l in text[end + 2:] if l.strip()]
    header = []
    for l in text[:end + 1]:
        l = l.rstrip("\t ")
        if l.startswith("nColumns="):
            l = "nColumns=%d" % len(keep)
        header.append(l)
    out = header + ["\t".join(keep)] + ["\t".join(r[i] for i in idx) for r in rows]
    open(dst, "w").write("\n".join(out) + "\n")


def model_constants(osim, ik):
    m = ET.parse(osim).getroot().find("Model")
    body = {b.get("name"): b for b in m.iter("Body")}

    def vec(e, tag):
        return [float(v) for v in e.findtext(tag).split()]

    for name in ["pelvis", "femur_r", "tibia_r", "torso"]:
        b = body[name]
        print("%-8s mass %.10g kg, centre of mass %s m, Izz %.10g kg m^2" % (
            name, float(b.findtext("mass")), vec(b, "mass_center")[:2], vec(b, "inertia")[2]))
    # the foot: talus, calcaneus and toes welded; positions in the talus frame
    offsets = {}
    for j in m.find("JointSet").iter():
        if j.get("name") in ("subtalar_r", "mtp_r", "hip_r", "ankle_r", "subtalar_l", "back"):
            frames = {f.get("name"): vec(f, "translation") for f in j.iter("PhysicalOffsetFrame")}
            offsets[j.get("name")] = frames
    print("hip centre in the pelvis frame", offsets["hip_r"]["pelvis_offset"])
    print("lumbar joint in the pelvis frame", offsets["back"]["pelvis_offset"])
    print("ankle in the tibia frame", offsets["ankle_r"]["tibia_r_offset"][:2])
    calcn_o = offsets["subtalar_r"]["talus_r_offset"]
    toes_o = [calcn_o[k] + offsets["mtp_r"]["calcn_r_offset"][k] for k in range(3)]
    parts = [("talus_r", [0, 0, 0]), ("calcn_r", calcn_o), ("toes_r", toes_o)]
    M = sum(float(body[n].findtext("mass")) for n, _ in parts)
    c = [sum(float(body[n].findtext("mass")) * (o[k] + vec(body[n], "mass_center")[k]) for n, o in parts) / M
         for k in range(2)]
    Izz = 0.0
    for n, o in parts:
        mk = float(body[n].findtext("mass"))
        p = [o[k] + vec(body[n], "mass_center")[k] - c[k] for k in range(2)]
        Izz += vec(body[n], "inertia")[2] + mk * (p[0] ** 2 + p[1] ** 2)
    print("foot     mass %.10g kg, centre of mass [%.10g, %.10g] m (talus frame), Izz %.10g kg m^2" % (M, c[0], c[1], Izz))
    print("calcaneus origin in the talus frame [%.10g, %.10g] m" % (calcn_o[0], calcn_o[1]))
    for mk in m.iter("Marker"):
        frame = mk.findtext("socket_parent_frame").split("/")[-1]
        if mk.get("name") in TORSO + PELVIS + RIGHT + LEFT:
            loc = vec(mk, "location")
            if frame.startswith("calcn_"):
                side = offsets["subtalar_" + frame[-1]]["talus_" + frame[-1] + "_offset"]
                loc = [loc[k] + side[k] for k in range(3)]
                frame = "talus_%s (from %s)" % (frame[-1], frame)
            print("marker %-14s on %-22s %.6f %.6f %.6f" % (mk.get("name"), frame, loc[0], loc[1], loc[2]))
    # the knee: the tibia's origin from the femur's, in the femur frame, SimmSpline(knee) * scale
    knee = next(j for j in m.find("JointSet").iter("CustomJoint") if j.get("name") == "knee_r")
    lo, hi = knee_range(ik)
    for axis in ("translation1", "translation2"):
        ta = next(t for t in knee.find("SpatialTransform") if t.get("name") == axis)
        sp = next(ta.iter("SimmSpline"))
        xs = [float(v) for v in sp.findtext("x").split()]
        ys = [float(v) for v in sp.findtext("y").split()]
        scale = float(next(ta.iter("MultiplierFunction")).findtext("scale"))
        coef = fmm_spline(xs, ys)
        f = lambda q: scale * fmm_eval(xs, ys, coef, q)
        poly, err = fit_poly(f, lo, hi, 6)
        print("knee %s: %s  (knee angle %.4f to %.4f rad; largest difference from the spline %.3g m)" % (
            axis, " + ".join("%.8g*qK^%d" % (a, k) for k, a in enumerate(poly)), lo, hi, err))


def knee_range(ik):
    text = open(ik).read().split("\n")
    end = next(i for i, l in enumerate(text) if l.strip() == "endheader")
    labels = text[end + 1].split()
    q = [math.radians(float(l.split()[labels.index(c)])) for l in text[end + 2:] if l.strip()
         for c in ("knee_angle_r", "knee_angle_l")]
    margin = 0.1
    return min(q) - margin, max(q) + margin


def fmm_spline(x, y):
    """Forsythe, Malcolm and Moler's cubic spline (as SimmSpline computes it): third
    derivatives at the ends matched to cubics through the first and last four points."""
    n = len(x)
    b, c, d = [0.0] * n, [0.0] * n, [0.0] * n
    nm1 = n - 1
    d[0] = x[1] - x[0]
    c[1] = (y[1] - y[0]) / d[0]
    for i in range(1, nm1):
        d[i] = x[i + 1] - x[i]
        b[i] = 2.0 * (d[i - 1] + d[i])
        c[i + 1] = (y[i + 1] - y[i]) / d[i]
        c[i] = c[i + 1] - c[i]
    b[0] = -d[0]
    b[nm1] = -d[n - 2]
    c[0] = c[nm1] = 0.0
    if n > 3:
        d1 = x[3] - x[0]
        d2 = x[nm1] - x[n - 4]
        c[0] = c[2] / (x[3] - x[1]) - c[1] / (x[2] - x[0])
        c[nm1] = c[n - 2] / (x[nm1] - x[n - 3]) - c[n - 3] / (x[n - 2] - x[n - 4])
        c[0] = c[0] * d[0] * d[0] / d1
        c[nm1] = -c[nm1] * d[n - 2] * d[n - 2] / d2
    for i in range(1, n):
        t = d[i - 1] / b[i - 1]
        b[i] -= t * d[i - 1]
        c[i] -= t * c[i - 1]
    c[nm1] /= b[nm1]
    for j in range(nm1):
        i = nm1 - 1 - j
        c[i] = (c[i] - d[i] * c[i + 1]) / b[i]
    b[nm1] = (y[nm1] - y[n - 2]) / d[n - 2] + d[n - 2] * (c[n - 2] + 2.0 * c[nm1])
    for i in range(nm1):
        b[i] = (y[i + 1] - y[i]) / d[i] - d[i] * (c[i + 1] + 2.0 * c[i])
        d[i] = (c[i + 1] - c[i]) / d[i]
        c[i] *= 3.0
    c[nm1] *= 3.0
    d[nm1] = d[n - 2]
    return b, c, d


def fmm_eval(x, y, coef, q):
    b, c, d = coef
    i = 0
    while i < len(x) - 2 and q > x[i + 1]:
        i += 1
    dx = q - x[i]
    return y[i] + dx * (b[i] + dx * (c[i] + dx * d[i]))


def fit_poly(f, lo, hi, degree):
    # least squares on 401 points by the normal equations in a scaled variable, then back
    n = 401
    qs = [lo + (hi - lo) * k / (n - 1) for k in range(n)]
    mid, half = (lo + hi) / 2, (hi - lo) / 2
    A = [[((q - mid) / half) ** p for p in range(degree + 1)] for q in qs]
    ys = [f(q) for q in qs]
    m = degree + 1
    N = [[sum(A[k][i] * A[k][j] for k in range(n)) for j in range(m)] for i in range(m)]
    r = [sum(A[k][i] * ys[k] for k in range(n)) for i in range(m)]
    for i in range(m):  # Gaussian elimination
        for j in range(i + 1, m):
            t = N[j][i] / N[i][i]
            for k in range(i, m):
                N[j][k] -= t * N[i][k]
            r[j] -= t * r[i]
    s = [0.0] * m
    for i in reversed(range(m)):
        s[i] = (r[i] - sum(N[i][k] * s[k] for k in range(i + 1, m))) / N[i][i]
    # expand sum s_p ((q - mid)/half)^p into powers of q
    poly = [0.0] * m
    for p in range(m):
        for k in range(p + 1):
            poly[k] += s[p] * math.comb(p, k) * (-mid) ** (p - k) / half ** p
    err = max(abs(sum(a * q ** k for k, a in enumerate(poly)) - f(q)) for q in qs)
    return poly, err


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    src = os.path.join(sys.argv[1], SRC)
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.dirname(os.path.abspath(__file__))
    cut_trc(os.path.join(src, "ExperimentalData/subject01_walk.trc"), os.path.join(out, "subject01_walk.trc"),
            TORSO + PELVIS + RIGHT + LEFT)
    plates = ["time"]
    for prefix in ("", "1_"):
        plates += [prefix + "ground_force_v" + a for a in "xyz"] + [prefix + "ground_force_p" + a for a in "xyz"] + \
                  [prefix + "ground_torque_" + a for a in "xyz"]
    cut_storage(os.path.join(src, "ExperimentalData/subject01_walk_grf.mot"),
                os.path.join(out, "subject01_walk_grf.mot"), plates)
    ik = os.path.join(src, "OutputReference/IK/subject01_walk_IK.mot")
    coordinates = ["pelvis_tilt", "pelvis_tx", "pelvis_ty", "hip_flexion_r", "knee_angle_r", "ankle_angle_r",
                   "hip_flexion_l", "knee_angle_l", "ankle_angle_l", "lumbar_extension"]
    cut_storage(ik, os.path.join(out, "subject01_walk_IK.mot"), ["time"] + coordinates)
    cut_storage(os.path.join(src, "OutputReference/ID/Results/subject01_walk_ID.sto"),
                os.path.join(out, "subject01_walk_ID.sto"),
                ["time"] + [c + ("_force" if c[-3:] in ("_tx", "_ty") else "_moment") for c in coordinates])
    model_constants(os.path.join(src, "OutputReference/subject01.osim"), ik)


if __name__ == "__main__":
    main()
