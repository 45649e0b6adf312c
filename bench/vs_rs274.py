#!/usr/bin/env python3
"""ncurve against LinuxCNC's standalone interpreter, rs274 (Debian's linuxcnc-uspace), workload by workload.

What it measures: the wall time and the peak resident memory of one process reading a generated
program and writing its path, for each workload below, `ncurve run` against `rs274 -g prog.ngc
out.txt` (canonical calls to a file):

  expanded  1,000,000 blocks `G01 X.. Y.. Z.. F1000`, varied 3-decimal coordinates (seeded random);
            ncurve twice: summary only (`ncurve run P`) and CSV (`--format csv -o FILE`)
  spiral    a 100,000-point Archimedean spiral made by a WHILE loop (LinuxCNC: o100 while)
  calls     100,000 calls of a subprogram in the same file making one move each
            (FANUC G65 P9100 with arguments, LinuxCNC o9100 call with parameters)
  holes     100,000 holes of G81 under G99 on a 1 mm grid, one `X_ Y_` block a hole
  contour   1,000,000 blocks of a circle of R100 in 10,000 pieces a turn, G01 and G03 R100
            alternating, under cutter compensation G41 (tool inside: every corner an inner one,
            where both interpreters take the offset paths' intersection) with a 5 mm tool radius
            (FANUC: G10 L11 P1 R5. and D1; LinuxCNC: a tool table, in inches as rs274 without an
            INI file reads it, T1 M6 and G41 D1)
  --big     a ~1 GB expanded program (about 28 M blocks), ncurve summary and CSV; rs274 too,
            stopped after --big-timeout seconds

All but `expanded` write CSV. The sizes are multiplied by --scale. The two programs of a workload
make the same motion; each is generated into a temporary folder, never into the repository.

How: --rounds rounds (default 3); in each, every workload's ncurve runs and its rs274 run follow
each other (interleaved, rs274 first in every second round), one process at a time. Each runs under GNU
time (/usr/bin/time -f "%e %M"): the peak RSS is its %M, in MB of 2^20 bytes; the wall time is
time.perf_counter from spawn to exit around it (GNU time adds about 1 ms). The table gives the
range over the rounds (min-max); the ratio is rs274's wall over ncurve's in the same round. The
load average is printed before and after.

The check, after the runs (on the last round's outputs): ncurve's CSV rows of motions (rapid, line,
arc: every row after the first, which is the path's start point) must equal rs274's
STRAIGHT_TRAVERSE + STRAIGHT_FEED + ARC_FEED calls, both counted without the moves to where the
tool already is (the same X Y Z as the move before, as each writes it). That drops the one
documented difference: at the first hole the tool is already over it (the G00 before went there),
and rs274 still writes the cycle's rapid to the hole's X Y, a zero-length STRAIGHT_TRAVERSE, where
ncurve makes no move. The raw counts are printed as well. An arc is one CSV row where it is within
--arc-tol of its chord: the contour's arcs are 0.06 mm chords on R95, sagitta 5e-6 mm, under the
default 0.001 mm. The expanded summary run must count as many motions as the CSV has rows.
Either interpreter's exit status other than 0, an alarm row in the CSV, a result other than
`completed` in ncurve's summary or anything rs274 writes to stderr but "executing" is an error.
The exit status is 1 if a check fails or an interpreter reports an error.

usage: vs_rs274.py [--rounds N] [--scale F] [--only NAME[,NAME]] [--ncurve PATH] [--big]
"""
import argparse
import math
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GNU_TIME = "/usr/bin/time"
MOTION_CALLS = ("STRAIGHT_TRAVERSE(", "STRAIGHT_FEED(", "ARC_FEED(")


def write_lines(path, head, body, tail):
    """Writes head, the lines body yields (in chunks) and tail."""
    with open(path, "w") as f:
        f.write(head)
        chunk = []
        for line in body:
            chunk.append(line)
            if len(chunk) >= 65536:
                f.write("".join(chunk))
                chunk.clear()
        f.write("".join(chunk))
        f.write(tail)


# ---- the workloads' programs: (FANUC text for ncurve, LinuxCNC text for rs274) ----

def expanded(n, nc, ngc, seed=1):
    # as docs/performance.md's "Writing a CAM-size program's path"; rs274 reads the same text
    rng = random.Random(seed)
    u = rng.uniform
    write_lines(nc, "%\nO1000\nG21 G90 G17 G54\n",
                ("G01 X%.3f Y%.3f Z%.3f F1000\n" % (u(-100, 100), u(-100, 100), u(-20, 0)) for _ in range(n)),
                "M30\n%\n")
    os.link(nc, ngc)


def expanded_bytes(size, nc, ngc):
    """An expanded program of about `size` bytes (--big): its blocks average 35.3 bytes."""
    expanded(max(1, round(size / 35.3)), nc, ngc, seed=2)


def spiral(n, nc, ngc):
    # r = 1 + 0.0005 mm a point, 0.36 degrees a point: 100 turns for 100,000 points. F alone: rs274
    # writes a block `G01 F1000` without axis words as a STRAIGHT_FEED to where the tool is
    with open(nc, "w") as f:
        f.write(f"%\nO1001\nG21 G90 G17 G54\nG00 X0. Y0. Z5.\nF1000.\n#1=0\nWHILE [#1 LT {n}] DO1\n"
                "#2=#1*0.36\n#3=1.+#1*0.0005\nG01 X[#3*COS[#2]] Y[#3*SIN[#2]]\n#1=#1+1\nEND1\nM30\n%\n")
    with open(ngc, "w") as f:
        f.write(f"%\nG21 G90 G17 G54\nG00 X0 Y0 Z5\nF1000\n#1=0\no100 while [#1 LT {n}]\n"
                "#2=[#1*0.36]\n#3=[1+#1*0.0005]\nG01 X[#3*COS[#2]] Y[#3*SIN[#2]]\n#1=[#1+1]\n"
                "o100 endwhile\nM2\n%\n")


def calls(n, nc, ngc):
    # bench_run.cpp's G65-heavy loop: O9100 moves to (#1*0.001, #1*0.002) with A#1 B0.002 X[#1*0.001]
    with open(nc, "w") as f:
        f.write(f"%\nO1002\nG21 G90 G17 G54\nG00 X-1. Y-1. Z5.\n#1=0\nWHILE [#1 LT {n}] DO1\n"
                "G65 P9100 A#1 B0.002 X[#1*0.001]\n#1=#1+1\nEND1\nM30\n"
                "O9100\n#3=#1*#2\nG01 X#24 Y#3 F500.\nM99\n%\n")
    # LinuxCNC: the sub before its first call; #1..#3 are the call's parameters (saved across it)
    with open(ngc, "w") as f:
        f.write("%\no9100 sub\n#4=[#1*#2]\nG01 X#3 Y#4 F500\no9100 endsub\n"
                f"G21 G90 G17 G54\nG00 X-1 Y-1 Z5\n#1=0\no101 while [#1 LT {n}]\n"
                "o9100 call [#1] [0.002] [#1*0.001]\n#1=[#1+1]\no101 endwhile\nM2\n%\n")


def holes(n, nc, ngc):
    # bench_run.cpp's drilling(), on a 1 mm grid (decimal points: FANUC reads X5 as 5 increments)
    body = [f"X{i % 1000}. Y{i // 1000}.\n" for i in range(1, n)]
    write_lines(nc, "%\nO1003\nG21 G90 G17 G54\nG00 X0. Y0. Z10.\nG99 G81 X0. Y0. Z-5. R2. F300.\n", body,
                "G80\nM30\n%\n")
    write_lines(ngc, "%\nG21 G90 G17 G54\nG00 X0 Y0 Z10\nG99 G81 X0 Y0 Z-5 R2 F300\n", body, "G80\nM2\n%\n")


CONTOUR_TOOL_RADIUS = 5.0


def contour_body(n):
    # bench_run.cpp's contour(): 100 mm circle, 10,000 pieces a turn, G01 and G03 R100 alternating
    per_turn = 10_000
    for i in range(1, n + 1):
        a = 2 * math.pi * (i % per_turn) / per_turn
        x, y = 100 * math.cos(a), 100 * math.sin(a)
        yield f"G01 X{x:.4f} Y{y:.4f}\n" if i % 2 else f"G03 X{x:.4f} Y{y:.4f} R100.\n"


def contour(n, nc, ngc):
    r = CONTOUR_TOOL_RADIUS
    # entry from the centre to (100, 0), CCW with the tool on the left (inside), exit to the centre
    write_lines(nc, f"%\nO1004\nG21 G90 G17 G54 G40\nG10 L11 P1 R{r:.3f}\nG00 X0. Y0. Z5.\n"
                "G41 G01 X100. Y0. D1 F2000.\n", contour_body(n), "G40 G01 X0. Y0.\nM30\n%\n")
    write_lines(ngc, "%\nG21 G90 G17 G54 G40\nT1 M6\nG00 X0 Y0 Z5\nG41 D1 G01 X100 Y0 F2000\n",
                contour_body(n), "G40 G01 X0 Y0\nM2\n%\n")
    with open(os.path.join(os.path.dirname(ngc), "tool.tbl"), "w") as f:
        f.write(f"T1 P1 D{2 * r / 25.4:.9f} ;bench\n")  # rs274 without an INI reads the table in inches


class Workload:
    def __init__(self, name, size, make, modes, what, rs274_timeout=None, ncurve_extra=()):
        self.name, self.size, self.make, self.modes, self.what = name, size, make, modes, what
        self.rs274_timeout = rs274_timeout
        self.ncurve_extra = list(ncurve_extra)


def workloads(scale, big, big_timeout):
    n = lambda base: max(1, round(base * scale))
    w = [
        Workload("expanded", n(1_000_000), expanded, ("summary", "csv"), "{n:,} G01 blocks"),
        Workload("spiral", n(100_000), spiral, ("csv",), "WHILE loop, {n:,} points"),
        Workload("calls", n(100_000), calls, ("csv",), "{n:,} G65 / o-call calls, one move each"),
        Workload("holes", n(100_000), holes, ("csv",), "{n:,} G81 holes"),
        Workload("contour", n(1_000_000), contour, ("csv",), "{n:,} G01/G03 blocks under G41"),
    ]
    if big:
        # the run's time bound is off: 29 M blocks take longer than the default 60 s on a slow machine
        w.append(Workload("big", n(1_000_000_000), expanded_bytes, ("summary", "csv"), "expanded, {mb:,.0f} MB",
                          rs274_timeout=big_timeout, ncurve_extra=("--max-seconds", "0")))
    return w


# ---- running ----

def run_timed(cmd, cwd, out_prefix, env=None, timeout=None):
    """(wall s, peak RSS MB, exit status, stdout, stderr, timed out) of one child process."""
    # GNU time for the peak RSS: a child Python spawns reports Python's own RSS as its ru_maxrss
    # (the address space it leaves at exec counts), one that time forks does not
    tfile = out_prefix + ".time"
    with open(out_prefix + ".stdout", "wb") as o, open(out_prefix + ".stderr", "wb") as e:
        t0 = time.perf_counter()
        p = subprocess.Popen([GNU_TIME, "-f", "%e %M", "-o", tfile] + cmd, cwd=cwd, env=env,
                             stdin=subprocess.DEVNULL, stdout=o, stderr=e, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout)
            killed = False
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)  # its own session: time and the interpreter
            rc = p.wait()
            killed = True
        wall = time.perf_counter() - t0
    rss = float("nan")
    if os.path.exists(tfile):
        with open(tfile) as f:
            last = f.read().strip().splitlines()[-1:]  # after "Command exited with non-zero status N"
        if last and len(last[0].split()) == 2:
            rss = int(last[0].split()[1]) / 1024
    with open(out_prefix + ".stdout", errors="replace") as f:
        stdout = f.read(200_000)
    with open(out_prefix + ".stderr", errors="replace") as f:
        stderr = f.read(200_000)
    return wall, rss, rc, stdout, stderr, killed


def csv_motions(path):
    """(rows after the start point, of them the moves to a new point, alarm rows' text)."""
    raw = moved = 0
    alarms = []
    with open(path) as f:
        next(f)  # header
        first = next(f, None)
        if first is None:
            return 0, 0, alarms
        last = first.split(",")[2:5]
        for line in f:
            c = line.split(",")
            if c[1].startswith("alarm"):
                alarms.append(line.strip())
                continue
            if c[1] not in ("rapid", "line", "arc"):
                continue
            raw += 1
            p = c[2:5]
            if p != last:
                moved += 1
            last = p
    return raw, moved, alarms


def canon_motions(path):
    """(rs274's motion calls, of them the moves to a new point): the end point is X Y Z of a
    STRAIGHT_* call and, in the XY plane, first_end, second_end and axis_end of an ARC_FEED."""
    raw = moved = 0
    last = ("0.0000", "0.0000", "0.0000")  # where rs274 starts
    with open(path, errors="replace") as f:
        for line in f:
            k = line.find("(")
            if k < 0:
                continue
            head = line[:k + 1]
            if not head.endswith(MOTION_CALLS):
                continue
            raw += 1
            v = line[k + 1:line.rindex(")")].split(",")
            p = (v[0].strip(), v[1].strip(), v[5 if head.endswith("ARC_FEED(") else 2].strip())
            if p != last:
                moved += 1
            last = p
    return raw, moved


def summary_motions(text):
    """The motions (rapid, line, arc) that ncurve's summary counts, and its result."""
    count, result = None, None
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("moves "):
            count = 0
            for part in s[len("moves"):].split(","):
                num, _, kind = part.strip().partition(" ")
                if kind in ("rapid", "line", "arc"):
                    count += int(num)
        elif s.startswith("result "):
            result = s[len("result"):].strip()
    return count, result


def span(values, fmt, unit=""):
    """The range of the rounds, "lo–hi" (one figure when they agree)."""
    a, b = fmt.format(min(values)), fmt.format(max(values))
    return (a if a == b else f"{a}–{b}") + unit


def seconds(values):
    return span(values, "{:.2f}" if min(values) >= 1 else "{:.3f}")


def commit():
    try:
        h = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                           check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return h + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def load():
    return "{:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--scale", type=float, default=1.0, help="multiply every workload's size (0.01: a smoke run)")
    ap.add_argument("--only", help="these workloads only, comma-separated")
    ap.add_argument("--ncurve", default=os.path.join(REPO, "build", "ncurve"))
    ap.add_argument("--big", action="store_true", help="also a ~1 GB expanded program")
    ap.add_argument("--big-timeout", type=float, default=900, help="--big: stop rs274 after this many seconds")
    ap.add_argument("--keep", action="store_true", help="keep the temporary folder (its path is printed)")
    a = ap.parse_args()

    ncurve = os.path.abspath(a.ncurve)
    rs274 = shutil.which("rs274")
    if not os.access(ncurve, os.X_OK):
        print(f"ncurve not found at {ncurve}: build it, or give --ncurve")
        return 1
    if not rs274:
        print("rs274 not found: install linuxcnc-uspace (scripts/test.sh does)")
        return 1
    if not os.access(GNU_TIME, os.X_OK):
        print(f"GNU time not found at {GNU_TIME}: install the package time")
        return 1
    todo = workloads(a.scale, a.big, a.big_timeout)
    if a.only:
        names = a.only.split(",")
        unknown = [x for x in names if x not in {w.name for w in todo}]
        if unknown:
            print(f"unknown workload(s): {', '.join(unknown)}; there are {', '.join(w.name for w in todo)}")
            return 1
        todo = [w for w in todo if w.name in names]

    tmp = tempfile.mkdtemp(prefix="ncurve-vs-rs274-")
    errors = []
    try:
        print(f"# ncurve against rs274\n\n```text\n{' '.join([os.path.relpath(sys.argv[0], os.getcwd())] + sys.argv[1:])}")
        print(f"commit {commit()}, ncurve {ncurve}, rs274 {rs274}, {os.cpu_count()} cores, folder {tmp}")
        print(f"load average before: {load()}")

        # generate every program first (not timed)
        for w in todo:
            d = os.path.join(tmp, w.name)
            os.makedirs(d)
            w.dir, w.nc, w.ngc = d, os.path.join(d, "prog.nc"), os.path.join(d, "prog.ngc")
            t0 = time.perf_counter()
            w.make(w.size, w.nc, w.ngc)
            mb = os.path.getsize(w.nc) / 1e6
            w.label = w.what.format(n=w.size, mb=mb)
            print(f"{w.name}: {w.label}; programs of {os.path.getsize(w.nc):,} bytes (FANUC) and "
                  f"{os.path.getsize(w.ngc):,} (LinuxCNC), generated in {time.perf_counter() - t0:.1f} s")

        # timed[(workload, mode)] = list of (wall, rss) a round; mode "rs274" for LinuxCNC
        timed = {}
        for r in range(a.rounds):
            for w in todo:
                steps = [("ncurve", m) for m in w.modes] + [("rs274", None)]
                if r % 2:
                    steps = steps[-1:] + steps[:-1]  # interleaved: rs274 first in every second round
                for who, mode in steps:
                    if who == "ncurve":
                        cmd = [ncurve, "run", w.nc] + w.ncurve_extra
                        if mode == "csv":
                            cmd += ["--format", "csv", "-o", os.path.join(w.dir, "out.csv")]
                        res = run_timed(cmd, w.dir, os.path.join(w.dir, f"ncurve-{mode}"))
                        wall, rss, rc, out, err, _ = res
                        bad = rc != 0
                        if mode == "summary":
                            w.summary_count, result = summary_motions(out)
                            bad |= result != "completed"
                        if bad:
                            errors.append(f"{w.name}: ncurve {mode} exited {rc}: {(out + err)[-2000:]}")
                        timed.setdefault((w.name, mode), []).append((wall, rss))
                    else:
                        # a private HOME: rs274 maps its tool table to $HOME/.tool.mmap
                        cmd = [rs274, "-g"]
                        if os.path.exists(os.path.join(w.dir, "tool.tbl")):
                            cmd += ["-t", "tool.tbl"]
                        cmd += ["prog.ngc", "out.txt"]
                        wall, rss, rc, out, err, killed = run_timed(
                            cmd, w.dir, os.path.join(w.dir, "rs274"), env=dict(os.environ, HOME=w.dir),
                            timeout=w.rs274_timeout)
                        said = [x for x in (out + err).splitlines() if x.strip() not in ("", "executing")]
                        if killed:
                            w.rs274_killed = True
                        elif rc != 0 or said:
                            errors.append(f"{w.name}: rs274 exited {rc}: " + "\n".join(said)[-2000:])
                        timed.setdefault((w.name, "rs274"), []).append((None if killed else wall, rss))
            print(f"round {r + 1} of {a.rounds} done, load average {load()}", flush=True)

        # the motion check, on the last round's outputs
        print()
        checks = []
        for w in todo:
            csv, canon = os.path.join(w.dir, "out.csv"), os.path.join(w.dir, "out.txt")
            missing = [f for f in (csv, canon) if not os.path.exists(f)]
            if missing:
                checks.append(f"{w.name}: FAILED: no output {', '.join(missing)}")
                errors.append(checks[-1])
                continue
            ours_raw, ours, alarms = csv_motions(csv)
            for x in alarms[:3]:
                errors.append(f"{w.name}: ncurve's CSV ends in an alarm: {x}")
            if getattr(w, "rs274_killed", False):
                checks.append(f"{w.name}: ncurve {ours:,} moves (CSV); rs274 stopped after {w.rs274_timeout:.0f} s, "
                              "not compared")
                continue
            theirs_raw, theirs = canon_motions(canon)
            ok = ours == theirs and ours > 0
            summary = getattr(w, "summary_count", None)
            if summary is not None and summary != ours_raw:
                ok = False
            checks.append(f"{w.name}: {'ok' if ok else 'FAILED'}: ncurve {ours:,} moves to a new point "
                          f"({ours_raw:,} CSV rows{'' if summary is None else f', summary {summary:,}'}), "
                          f"rs274 {theirs:,} ({theirs_raw:,} motion calls)")
            if not ok:
                errors.append(checks[-1])
        print("load average after: " + load())
        print("\n".join(checks))
        print("```\n")

        # the table
        print("| workload | ncurve wall s | rs274 wall s | rs274 ÷ ncurve | ncurve peak RSS MB | rs274 peak RSS MB |")
        print("|---|---|---|---|---|---|")
        for w in todo:
            theirs = timed[(w.name, "rs274")]
            t_walls = [t for t, _ in theirs if t is not None]
            for mode in w.modes:
                ours = timed[(w.name, mode)]
                walls = [t for t, _ in ours]
                ratios = [t2 / t1 for (t1, _), (t2, _) in zip(ours, theirs) if t2 is not None]
                t_wall = seconds(t_walls) if t_walls else f"> {w.rs274_timeout:.0f} (stopped)"
                print(f"| {w.name} ({w.label}), {'summary' if mode == 'summary' else 'CSV'} | "
                      f"{seconds(walls)} | {t_wall} | "
                      f"{span(ratios, '{:.1f}', '×') if ratios else ''} | {span([m for _, m in ours], '{:.0f}')} | "
                      f"{span([m for _, m in theirs], '{:.0f}')} |")
        if errors:
            print("\nerrors:\n" + "\n".join(errors))
        return 1 if errors else 0
    finally:
        if a.keep:
            print(f"kept {tmp}")
        else:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
