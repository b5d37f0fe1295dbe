#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Progress on a terminal: `alembert run` on a pseudo-terminal shows a step's line
# ("roadmap E: planning, forming and printing ... 0 s") and erases it before the results are
# printed, so no progress text is left in what the user reads; on a pipe it shows nothing.
# ALEMBERT_PROGRESS_DELAY_MS=0 shows the line at once instead of after 2 s.
# Usage: progress_pty_test.py ALEMBERT SOURCE_DIR
import os
import pty
import re
import select
import subprocess
import sys
import tempfile
import time

alembert, source = sys.argv[1:3]
script = os.path.join(source, "examples", "sit_to_stand", "model.alb")
out = tempfile.mkdtemp()
env = dict(os.environ, ALEMBERT_PROGRESS_DELAY_MS="0", TERM="xterm")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


pid, fd = pty.fork()
if pid == 0:
    os.execve(alembert, [alembert, "run", "--out", out, script], env)
seen = b""
end = time.monotonic() + 300
while time.monotonic() < end:
    ready, _, _ = select.select([fd], [], [], end - time.monotonic())
    if not ready:
        break
    try:
        chunk = os.read(fd, 65536)
    except OSError:
        chunk = b""
    if not chunk:
        break
    seen += chunk
_, status = os.waitpid(pid, 0)
text = seen.decode(errors="replace")
check(os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0, "the script runs on a terminal and exits 0")

erase = "\r\x1b[K"
line = re.compile(r"roadmap E: planning, forming and printing \.\.\. \d+ s")
check(line.search(text) is not None, "the road-map's step shows its progress line on a terminal")
# every progress line is erased before anything else is printed: after each, the next
# output starts with the erase sequence (the line is redrawn or cleared, never left)
for m in line.finditer(text):
    check(text.startswith(erase, m.end()), "a progress line is erased before what follows it (%r)"
          % text[m.end():m.end() + 40])
    break
visible = text.replace(erase, "\n")
check("E_T_A: 0 = " in visible and "T_A = 57.2015 N*m" in visible,
      "the results are printed whole after the line is erased")
results = [l for l in visible.splitlines() if l.startswith("E_T_A:") or l.startswith("T_A = ")]
check(all(" ... " not in l or not l.endswith(" s") for l in results), "no progress text inside a result line")

# on a pipe: nothing of it
r = subprocess.run([alembert, "run", "--out", out, script], capture_output=True, text=True, env=env, timeout=300)
check(r.returncode == 0 and " ... 0 s" not in r.stdout + r.stderr and "\x1b[K" not in r.stdout + r.stderr,
      "on a pipe no progress is shown")
sys.exit(1 if failures else 0)
