#!/usr/bin/env python3
"""Writes an n-link spatial chain as an Alembert script, for the scaling study of the script
path (bench/pipeline/time_chain.sh, bench/README.md "Printing and planning at scale").

Usage: chain.py N STEP OUT.alb
  STEP: kane | roadmap | simulate | model   (the statement the script ends with)

Link i turns about z (odd i) or x (even i) of the link before it, hangs L below it, and is
driven by the torque Ti; gravity pulls along -Ny.
"""
import sys

n, step, out = int(sys.argv[1]), sys.argv[2], sys.argv[3]
qs = [f"q{i}" for i in range(1, n + 1)]
L = ["newtonian N", "body " + ", ".join(f"B{i}" for i in range(1, n + 1)),
     "constant g = 9.81 m/s^2, L = 0.1 m, mL = 0.2 kg, IL = 0.0002 kg*m^2",
     "variable " + ", ".join(f"{q}'' rad" for q in qs)]
if step == "roadmap":
    L.append("unknown " + ", ".join(f"T{i} N*m" for i in range(1, n + 1)))
for i in range(1, n + 1):
    p = "N" if i == 1 else f"B{i-1}"
    axis = "z" if i % 2 else "x"
    L += [f"rotate B{i} from {p} about {axis} by q{i}",
          f"translate B{i}_o from " + ("N_o by 0>" if i == 1 else f"B{i-1}_o by -L*B{i-1}y>"),
          f"translate B{i}cm from B{i}_o by -L/2*B{i}y>",
          f"mass B{i} = mL; inertia B{i} = IL, IL/10, IL"]
    if step == "roadmap":
        L.append(f"torque T{i} on B{i} from {p} = T{i}*B{i}{axis}>")
L.append("gravity -g*Ny>")
if step == "kane":
    L.append("kane K for " + ", ".join(qs))
elif step == "roadmap":
    L.append("roadmap E for " + ", ".join(f"T{i}" for i in range(1, n + 1)))
elif step == "simulate":
    L += ["initial " + ", ".join(f"{q} = {0.1 * (1 + i % 3):.1f}" for i, q in enumerate(qs)),
          "final time 1 s", "output step 0.01 s", "output " + ", ".join(qs),
          "simulate plot none"]
open(out, "w").write("\n".join(L) + "\n")
