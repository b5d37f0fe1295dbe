#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes winter_table_a1.trc from WinterTableA1.txt (Winter 2009, Table A.1, as published in the
# BMClab/BMC repository): the same coordinates (cm) in OpenSim's marker format, with Z = 0, and
# times (frame - 1) * 0.0143 s (69.93 Hz), which round to the table's millisecond times.
import pathlib

here = pathlib.Path(__file__).parent
rows = [line.split() for line in (here / "WinterTableA1.txt").read_text().splitlines()[2:] if line.strip()]
markers = ["RIB_CAGE", "HIP", "KNEE", "FIBULA", "ANKLE", "HEEL", "MT5", "TOE"]
step = 0.0143
rate = 1 / step
for r in rows:
    t = (int(r[0]) - 1) * step
    assert abs(t - float(r[1])) <= 0.0005 + 1e-9, (r[0], t, r[1])

out = ["PathFileType\t4\t(X/Y/Z)\twinter_table_a1.trc",
       "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames",
       f"{rate:.2f}\t{rate:.2f}\t{len(rows)}\t{len(markers)}\tcm\t{rate:.2f}\t1\t{len(rows)}",
       "Frame#\tTime\t" + "\t\t\t".join(markers) + "\t\t",
       "\t\t" + "\t".join(f"X{i}\tY{i}\tZ{i}" for i in range(1, len(markers) + 1)),
       ""]
for r in rows:
    t = (int(r[0]) - 1) * step
    cells = [r[0], f"{t:.6f}"]
    for m in range(len(markers)):
        cells += [r[2 + 2 * m], r[3 + 2 * m], "0"]
    out.append("\t".join(cells))
(here / "winter_table_a1.trc").write_text("\n".join(out) + "\n")
