#!/usr/bin/env python3
"""Cutter compensation against LinuxCNC's interpreter (rs274, Debian's linuxcnc-uspace) where the
two follow the same rules: random convex pockets of lines and arcs cut with G41 from inside, so
every corner is an inner one (both take the offset paths' intersection) and every arc keeps its
centre. Arcs are never next to each other: at an arc-to-arc corner LinuxCNC's end point differs
from the circles' intersection by up to 0.06 mm, where ncurve's is the intersection to 1e-12
(worked by hand). The entry and exit moves differ by design (LinuxCNC enters along a tangent, FANUC type A
perpendicular to the next block) and are not compared; every move between them must agree.

usage: linuxcnc_compensation.py NCURVE [WORKDIR]"""
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys

from rs274 import canon as rs274_canon


def pocket(rng):
    n = rng.randint(4, 9)
    angles = [2 * math.pi * (i + rng.uniform(0.2, 0.8)) / n for i in range(n)]  # no slivers
    # a convex polygon: vertices on an ellipse, counter-clockwise
    a, b = rng.uniform(30, 60), rng.uniform(30, 60)
    pts = [(round(a * math.cos(t), 3), round(b * math.sin(t), 3)) for t in angles]
    pts = [p for i, p in enumerate(pts) if math.dist(p, pts[i - 1]) > 8]
    if len(pts) < 3:
        return None
    tool = round(rng.uniform(1, 4), 3)
    blocks = []
    for i in range(len(pts)):
        p, q = pts[i], pts[(i + 1) % len(pts)]
        # an arc bulging outwards keeps the pocket convex; never two arcs in a row (below)
        after_arc = blocks and blocks[-1][2] is not None
        closing_before_arc = i == len(pts) - 1 and blocks and blocks[0][2] is not None
        if rng.random() < 0.4 and not after_arc and not closing_before_arc:
            chord = math.dist(p, q)
            blocks.append(("G3", q, round(chord * rng.uniform(1.2, 4), 3)))
        else:
            blocks.append(("G1", q, None))
    # start at the centre, enter to the first vertex, go round once and then to the second vertex
    start = pts[0]
    moves = blocks + [blocks[0]]
    return tool, start, moves


def program(tool, start, moves, fanuc):
    def num(v):
        return f"{v:.3f}"

    lines = ["G21 G17 G90 G40"]
    lines.append(f"G10 L11 P1 R{num(tool)}" if fanuc else "T1 M6")
    lines.append("G0 X0. Y0." if fanuc else "G0 X0 Y0")
    lines.append(f"G41 D1 G1 X{num(start[0])} Y{num(start[1])} F100.")
    for kind, q, r in moves:
        w = f"{kind} X{num(q[0])} Y{num(q[1])}"
        if r is not None:
            w += f" R{num(r)}"
        lines.append(w)
    lines.append("G40 G1 X0. Y0." if fanuc else "G40 G1 X0 Y0")
    lines.append("M30" if fanuc else "M2")
    return "\n".join(lines) + "\n"


def ncurve_moves(ncurve, path):
    out = subprocess.run([ncurve, "run", path, "--format", "jsonl"], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(out.stdout + out.stderr)
    moves = []
    for line in out.stdout.splitlines():
        j = json.loads(line)
        if j["kind"] in ("line", "arc"):
            moves.append((j["kind"], j["end"][0], j["end"][1], j.get("center")))
    return moves


def linuxcnc_moves(rs274, path, work):
    text, printed = rs274_canon(rs274, path, work, ("-t", os.path.join(work, "tool.tbl")))
    moves = []
    for m in re.finditer(r"(STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)", text):
        v = [float(x) for x in m.group(2).split(",")]
        if m.group(1) == "STRAIGHT_FEED":
            moves.append(("line", v[0], v[1], None))
        else:  # ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, ...)
            moves.append(("arc", v[0], v[1], [v[2], v[3]]))
    if "error" in printed.lower() and not moves:
        raise RuntimeError(printed)
    return moves


def main():
    ncurve = sys.argv[1]
    work = sys.argv[2] if len(sys.argv) > 2 else "linuxcnc-work"
    rs274 = shutil.which("rs274")
    if not rs274:
        print("rs274 not found: install linuxcnc-uspace (scripts/test.sh does)")
        return 1
    os.makedirs(work, exist_ok=True)
    rng = random.Random(20261124)
    compared = failures = 0
    for case in range(120):
        p = pocket(rng)
        if p is None:
            continue
        tool, start, moves = p
        with open(os.path.join(work, "tool.tbl"), "w") as f:
            f.write(f"T1 P1 D{2 * tool / 25.4:.9f} ;tool\n")  # rs274 without an INI reads the table in inches
        nc = os.path.join(work, f"case{case}.nc")
        ngc = os.path.join(work, f"case{case}.ngc")
        open(nc, "w").write(program(tool, start, moves, True))
        open(ngc, "w").write(program(tool, start, moves, False))
        ours = ncurve_moves(ncurve, nc)
        theirs = linuxcnc_moves(rs274, ngc, work)
        # drop the entry move and the exit move of each
        ours, theirs = ours[1:-1], theirs[1:-1]
        if len(ours) != len(theirs):
            print(f"case {case}: {len(ours)} moves against LinuxCNC's {len(theirs)}\n{open(nc).read()}")
            failures += 1
            continue
        for i, (a, b) in enumerate(zip(ours, theirs)):
            bad = a[0] != b[0] or abs(a[1] - b[1]) > 2e-4 or abs(a[2] - b[2]) > 2e-4
            if a[3] is not None and b[3] is not None:
                bad |= abs(a[3][0] - b[3][0]) > 2e-4 or abs(a[3][1] - b[3][1]) > 2e-4
            if bad:
                print(f"case {case} move {i}: ncurve {a} LinuxCNC {b}\n{open(nc).read()}")
                failures += 1
                break
        compared += 1
    print(f"{compared - failures} passed, {failures} failed")
    return 1 if failures or compared < 100 else 0


if __name__ == "__main__":
    sys.exit(main())
