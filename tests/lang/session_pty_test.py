#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The interactive session on a real terminal (a pseudo-terminal): Ctrl-C drops the line being
# typed, or an unfinished bracketed statement, and the session goes on; quit ends it with 0.
# Usage: session_pty_test.py ALEMBERT
import os
import pty
import select
import sys
import tempfile
import time

alembert = sys.argv[1]
home = tempfile.mkdtemp()  # the session's history goes here, not to the user's home
pid, fd = pty.fork()
if pid == 0:
    os.environ.update({"HOME": home, "TERM": "xterm"})
    os.execv(alembert, [alembert])

seen = b""  # the session's output so far
pos = 0  # how much of it the checks have passed


def read_until(text, timeout=20.0):
    """Reads the session's output until `text` appears after the last text found."""
    global seen, pos
    end = time.monotonic() + timeout
    while seen.find(text.encode(), pos) < 0:
        left = end - time.monotonic()
        if left <= 0:
            sys.exit(f"FAIL: no {text!r} within {timeout} s; the session printed:\n"
                     + seen.decode(errors="replace"))
        ready, _, _ = select.select([fd], [], [], left)
        if ready:
            try:
                chunk = os.read(fd, 4096)
            except OSError:
                chunk = b""
            if not chunk:
                sys.exit(f"FAIL: the session ended before {text!r}; it printed:\n"
                         + seen.decode(errors="replace"))
            seen += chunk
    pos = seen.find(text.encode(), pos) + len(text.encode())


def send(keys):
    os.write(fd, keys.encode())


read_until("alembert> ")
send("newtonian N\r")
read_until("alembert> ")
# Ctrl-C in the middle of a line: the line is dropped, a new prompt comes
send("z = 1 + nope")
read_until("nope")
send("\x03")
read_until("alembert> ")
send("w = 5\r")
read_until("w = 5\r\n")
read_until("alembert> ")
# Ctrl-C in the continuation of an open bracket drops the whole statement
send("Z = [1,\r")
read_until("... ")
send("\x03")
read_until("alembert> ")
send("v = 7\r")
read_until("v = 7\r\n")
read_until("alembert> ")
send("quit\r")
_, status = os.waitpid(pid, 0)
text = seen.decode(errors="replace")
if "error" in text:
    sys.exit("FAIL: a dropped line was run:\n" + text)
if not os.WIFEXITED(status) or os.WEXITSTATUS(status) != 0:
    sys.exit(f"FAIL: the session ended with status {status}:\n" + text)
print("session_pty_test: OK")
