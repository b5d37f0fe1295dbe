#!/usr/bin/env bash
# A batch of gait trials, each with its own force record ("{trial}_grf.mot"): five good trials
# of a swinging leg with amplitudes 0.20 ... 0.28 rad and one whose record is missing. The good
# ones finish, each writing its cycle normalised to 0-100 %; the batch pools them into the mean
# and SD, checked against the closed form, with a summary table and a plot.
# Usage: gait_batch_cli_test.sh ALEMBERT
set -euo pipefail
alembert=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "gait_batch_cli_test: $*" >&2; exit 1; }
mkdir trials
cat > leg.alb <<'ALB'
newtonian N
body A
constant g = 9.81 m/s^2, m_A = 2 kg, d_A = 0.5 m, I_A = 0.1 kg*m^2
variable qA''
unknown T_A N*m
rotate A from N about z by qA
translate A_o from N_o by 0>
translate Acm from A_o by d_A*Ay>
mass A = m_A
inertia A = 0, 0, I_A
gravity -g*Ny>
torque T_A on A from N = T_A*Nz>
plate floor on A from "{trial}_grf.mot"
inverse for T_A per kg mass 70 kg cycles floor
ALB
# the motion qA = a sin(2 pi t / 0.6), 100 Hz, 0 to 1.4 s; the plate loaded from 0.1 s and from
# 0.7 s (400 N, ramps of 40 N per 10 ms): strikes at 0.105 and 0.705 s
for a in 0.20 0.22 0.24 0.26 0.28; do
  awk -v a="$a" 'BEGIN { print "t [s],qA [rad]"; for (k = 0; k <= 140; ++k) printf "%.2f,%.17g\n", k / 100, a * sin(2 * 3.141592653589793 * k / 100 / 0.6) }' > "trials/leg$a.csv"
  awk 'BEGIN {
    print "grf\nversion=1\nnRows=141\nnColumns=10\ninDegrees=no\nendheader"
    print "time\tground_force_vx\tground_force_vy\tground_force_vz\tground_force_px\tground_force_py\tground_force_pz\tground_torque_x\tground_torque_y\tground_torque_z"
    for (k = 0; k <= 140; ++k) {
      ms = 10 * k; F = 0
      for (i = 0; i < 2; ++i) {
        on = i ? 700 : 100; off = on + 350
        if (ms > on && ms < on + 100) F = 4 * (ms - on)
        else if (ms >= on + 100 && ms <= off) F = 400
        else if (ms > off && ms < off + 100) F = 400 - 4 * (ms - off)
      }
      printf "%.2f\t0\t%d\t0\t0\t0\t0\t0\t0\t0\n", k / 100, F
    }
  }' > "trials/leg${a}_grf.mot"
done
cp trials/leg0.20.csv trials/nogrf.csv  # its force record is missing

status=0
"$alembert" inverse leg.alb --motion 'trials/*.csv' --jobs 2 --cutoff 0 --out out > out.txt || status=$?
[[ $status == 1 ]] || fail "exit status $status, expected 1 (one trial failed): $(cat out.txt)"
grep -q "^6 trials: 5 ok, 1 failed" out.txt || fail "counts: $(cat out.txt)"
grep -q "^failed: trials/nogrf.csv: .*nogrf_grf.mot" out.txt || fail "the failure does not name the missing record: $(cat out.txt)"
grep -q "^cycles: 5 from 5 trials; mean and SD in out/cycles.csv out/cycles_summary.csv out/cycles_band.csv" out.txt ||
  fail "no pooled cycles: $(cat out.txt)"
for a in 0.20 0.22 0.24 0.26 0.28; do
  for f in cycle_1.csv gait_events.csv kinematics.csv kinematics.sto powers.csv powers.sto torques.sto; do
    [[ -s "out/leg$a/$f" ]] || fail "trial leg$a wrote no $f"
  done
done
[[ $(wc -l < out/cycles.csv) == 102 ]] || fail "cycles.csv: 101 rows expected"

# at 25 % of the cycle, t = 0.105 + 0.15 s: qA = a sin(2 pi 0.255 / 0.6), so the mean is
# 0.24 s25 and the sample SD sd(a) s25 = 0.0316228 s25; linear interpolation at 10 ms moves a
# trial's value by at most h^2/8 max|qA''| = 3.8e-4 a/0.28
awk -F, 'NR == 1 { for (c = 1; c <= NF; ++c) { if ($c == "qA_mean [rad]") m = c; if ($c == "qA_sd [rad]") s = c } }
  $1 == 25 {
    s25 = sin(2 * 3.141592653589793 * 0.255 / 0.6)
    dm = $m - 0.24 * s25; ds = $s - 0.0316227766016838 * s25
    if (dm < 0) dm = -dm; if (ds < 0) ds = -ds
    if (dm > 4e-4 || ds > 1e-4) { print "mean " $m " sd " $s " at 25 %" > "/dev/stderr"; exit 1 }
    found = 1 }
  END { exit found ? 0 : 1 }' out/cycles.csv || fail "qA's mean or SD at 25 % differ from the closed form"
grep -q '^qA,rad,' out/cycles_summary.csv || fail "no summary row for qA: $(cat out/cycles_summary.csv)"
grep -q '^T_A,N m/kg,' out/cycles_summary.csv || fail "no summary row for T_A per kg: $(cat out/cycles_summary.csv)"
if command -v "${ALEMBERT_GNUPLOT:-gnuplot}" > /dev/null; then
  [[ -s out/cycles.png && -s out/cycles.svg ]] || fail "gnuplot is installed but the bands were not plotted: $(cat out.txt)"
else
  grep -q "(no plot: " out.txt || fail "no gnuplot and no word of the missing plot: $(cat out.txt)"
fi
# the same batch again writes the same bytes
"$alembert" inverse leg.alb --motion 'trials/*.csv' --jobs 2 --cutoff 0 --out again > /dev/null || true
cmp out/cycles.csv again/cycles.csv || fail "a second run wrote other numbers"
echo "gait_batch_cli_test: ok"
