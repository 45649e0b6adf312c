#!/usr/bin/env python3
"""The Python module's memory for a long run: the peak resident memory of a python process that
runs a program of N moves through ncurve.run() and keeps its moves array (issue 39: 10,000,000
moves under 1.5 GB).

How: a child /usr/bin/python3 imports numpy and ncurve, notes its resident memory (VmRSS), runs a
WHILE loop making N G01 moves (two a turn, X0 to X10 and back), touches the array's last record,
and reports its peak (VmHWM) and the wall time of the run. The moves array is N records of
moves.dtype.itemsize bytes; what the peak holds beyond the baseline and the array is the
interpreter's. The default limit fails (exit 1) a peak above 1.5 GB (10^9 bytes) for 10,000,000
moves; for other N, what it allows beyond the baseline scales with N.

usage: PYTHONPATH=build/python bench/python_memory.py [--moves N] [--python /usr/bin/python3]
"""
import argparse
import json
import subprocess
import sys

CHILD = r"""
import json, sys, time
import numpy, ncurve

def status(key):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024

turns = int(sys.argv[1]) // 2
program = f"#1=0\nG90 G01 X0. Y0. Z0. F1000.\nWHILE [#1 LT {turns}] DO1\n#1=#1+1\nG01 X10.\nG01 X0.\nEND1\nM30\n"
base = status("VmRSS")
start = time.perf_counter()
r = ncurve.run(program, max_steps=30 * turns + 100, max_seconds=0)
seconds = time.perf_counter() - start
assert r.ok, r.alarm
last = float(r.moves["x"][-2])
print(json.dumps({"moves": len(r.moves), "itemsize": r.moves.dtype.itemsize, "array": r.moves.nbytes,
                  "base": base, "peak": status("VmHWM"), "seconds": seconds}))
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--moves", type=int, default=10_000_000)
    ap.add_argument("--python", default="/usr/bin/python3")
    ap.add_argument("--limit-gb", type=float, default=1.5, help="at 10,000,000 moves (see above)")
    a = ap.parse_args()
    done = subprocess.run([a.python, "-c", CHILD, str(a.moves)], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"the run failed:\n{done.stderr}")
    m = json.loads(done.stdout)
    mb = 2 ** 20
    limit = m["base"] + (a.limit_gb * 1e9 - m["base"]) * a.moves / 10_000_000
    print(f"{m['moves']:,} moves in {m['seconds']:.1f} s; record {m['itemsize']} bytes, array {m['array'] / mb:.0f} MB")
    print(f"resident before the run {m['base'] / mb:.0f} MB, peak {m['peak'] / mb:.0f} MB "
          f"({(m['peak'] - m['base'] - m['array']) / mb:.0f} MB beyond the array); limit {limit / mb:.0f} MB")
    sys.exit(0 if m["peak"] <= limit else 1)


if __name__ == "__main__":
    main()
