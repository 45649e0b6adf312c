#!/usr/bin/env python3
"""ncurve stopped by SIGINT, SIGTERM or SIGHUP while writing -o leaves no temporary file behind and
the earlier file of that name as it was; run standard input of a program larger than memory allows
is refused, never cut and run.
usage: stop_signals.py NCURVE WORKDIR [--no-memory-limit]   (a sanitizer build cannot run under one)"""
import glob
import os
import resource
import signal
import subprocess
import sys
import time

ncurve, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
failures = []

# an endless loop writing a row a block: still running when the signal comes
loop = os.path.join(work, "endless.nc")
with open(loop, "w") as f:
    f.write("WHILE [1 EQ 1] DO1\nG01 X1. Y0 F1000\nG01 X0\nEND1\nM30\n")
out = os.path.join(work, "out.csv")
for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
    with open(out, "w") as f:
        f.write("the earlier file\n")
    p = subprocess.Popen([ncurve, "run", loop, "--format", "csv", "-o", out, "--max-seconds", "60"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 20
    while not glob.glob(os.path.join(work, ".out.csv.*.tmp")) and time.monotonic() < deadline:
        time.sleep(0.02)
    time.sleep(0.2)
    p.send_signal(sig)
    try:
        rc = p.wait(timeout=20)
    except subprocess.TimeoutExpired:
        p.kill()
        failures.append(f"{sig.name}: ncurve run went on")
        continue
    if rc != -sig:
        failures.append(f"{sig.name}: exit {rc}, not ended by the signal")
    left = glob.glob(os.path.join(work, ".out.csv.*.tmp"))
    if left:
        failures.append(f"{sig.name}: temporaries left behind: {left}")
        for t in left:
            os.remove(t)
    with open(out) as f:
        if f.read() != "the earlier file\n":
            failures.append(f"{sig.name}: the earlier {out} was changed")

# standard input of 600 MiB under a 1 GiB address-space limit: the whole program, or exit 2 saying
# memory ran out; never a cut program run to "completed"
def limit():
    resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))

block = b"G01 X1. Y2. F100\n"
big = os.path.join(work, "big.nc")
cases = 3
if "--no-memory-limit" not in sys.argv:
    cases += 1
    with open(big, "wb") as f:
        chunk = block * (1 << 16)
        for _ in range((600 << 20) // len(chunk)):
            f.write(chunk)
    with open(big, "rb") as f:  # through a pipe: its size not known in advance
        cat = subprocess.Popen(["cat"], stdin=f, stdout=subprocess.PIPE)
        r = subprocess.run([ncurve, "run", "-"], stdin=cat.stdout, capture_output=True, preexec_fn=limit,
                           timeout=300)
        cat.stdout.close()
        cat.wait()
    os.remove(big)
    err = r.stderr.decode(errors="replace")
    if r.returncode == 0:
        failures.append("600 MiB on standard input under a 1 GiB limit: exit 0 (the whole program cannot have been run)")
    elif r.returncode != 2 or "out of memory" not in err:
        failures.append(f"600 MiB on standard input under a 1 GiB limit: exit {r.returncode}, {err[:300]!r}")

for f in failures:
    print("FAIL:", f)
failed = len({f.split(":")[0] for f in failures})
print(f"{cases - failed} passed, {failed} failed")
sys.exit(1 if failures else 0)
