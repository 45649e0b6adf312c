#!/usr/bin/env python3
"""Programs of any size read as a stream (`ncurve run --stream`, and any file of 8 MB or more).

1. Through a pipe (no seeking): a program whose GOTO, WHILE and M99 P jump back across many pieces,
   with a subprogram after M30 and a program after the closing '%', read in 4 KB pieces, gives the
   moves (CSV) and summary that the same text gives read whole.
2. The outputs besides the moves (the HTML page with its source, the SVG plot, the verification's
   summary, the G code) of shipped examples, streamed in 64-byte pieces, are those of the whole reading.
3. A generated program of about 72 MB whose GOTO jumps back over all of it runs, streamed because of
   its size, under an address-space cap of 96 MB (setrlimit) that its compiled form (several bytes for
   each byte of text) would exceed; its moves and blocks are counted by hand.

usage: stream_check.py NCURVE [--no-cap]   (--no-cap under a sanitizer, which reserves terabytes)
"""
import json
import os
import resource
import subprocess
import sys
import tempfile

ncurve = os.path.abspath(sys.argv[1])
cap = "--no-cap" not in sys.argv
failures = []


def check(what, ok):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def looping_program(body_lines):
    body = "".join(f"G01 X{i % 97}.{i % 10} Y{-(i % 89)}.5 F800\n" for i in range(body_lines))
    return (
        "%\nO1000 (LOOPS ACROSS PIECES)\nG21 G90 G17 G54\n#1=0\n"
        "N10 #1=#1+1\n" + body + "IF [#1 LT 2] GOTO 10\n"       # GOTO back over the body
        "#2=0\nWHILE [#2 LT 2] DO1\n" + body + "#2=#2+1\nEND1\n"  # a WHILE around it
        "#3=0\nN20 #3=#3+1\nIF [#3 GT 2] GOTO 30\nM98 P2000\n"     # M99 P20 returns to an earlier block
        "N30 G00 Z50.\nM30\n"
        "O2000 (AFTER M30)\n" + body + "M99 P20\n"
        "%\nO3000 (AFTER THE END)\nG00 X1.\nM99\n"
    )


with tempfile.TemporaryDirectory() as tmp:
    text = looping_program(3000).encode()
    runs = {}
    for name, extra in (("whole", []), ("stream", ["--stream"])):
        out = os.path.join(tmp, name + ".csv")
        r = subprocess.run([ncurve, "run", "-", "--json", "--format", "csv", "-o", out] + extra, input=text,
                           capture_output=True, env=dict(os.environ, NCURVE_STREAM_CHUNK="4096"), timeout=120)
        with open(out, "rb") as f:
            runs[name] = (r.returncode, r.stdout, r.stderr, f.read())
    check(f"a pipe read in 4 KB pieces ({len(text)} bytes): exit, summary, messages and moves as read whole",
          runs["whole"] == runs["stream"] and runs["whole"][0] == 0)
    summary = json.loads(runs["stream"][2] or runs["stream"][1])
    # by hand: the body twice by GOTO, twice by WHILE, twice by the subprogram; the last G00 Z50.
    check("its moves as counted by hand (6 bodies of 3000 feed moves, 1 rapid)",
          summary["moves"]["line"] == 6 * 3000 and summary["moves"]["rapid"] == 1)

    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for example, extra in (("spiral.nc", []), ("lathe-mrc.nc", ["--machine", "fanuc-lathe"])):
        outs = []
        for stream_args in ([], ["--stream"]):
            page, plot = os.path.join(tmp, "p.html"), os.path.join(tmp, "p.svg")
            r = subprocess.run([ncurve, "run", os.path.join(root, "examples", example), "--html", page, "--plot", plot,
                                "--verify", "--json", "--format", "gcode", "-o", "-"] + extra + stream_args,
                               capture_output=True, env=dict(os.environ, NCURVE_STREAM_CHUNK="64"), timeout=120)
            with open(page, "rb") as f1, open(plot, "rb") as f2:
                outs.append((r.returncode, r.stdout, r.stderr, f1.read(), f2.read()))
        check(f"examples/{example} streamed: HTML page, plot, verification and G code as read whole",
              outs[0] == outs[1])

    big = os.path.join(tmp, "big.nc")
    lines = 2_800_000
    block = "".join(f"G01 X{i % 1000}.5 Y-{i % 977}.25 F1000\n" for i in range(1000))
    with open(big, "w") as f:
        f.write("%\nO1000\n#1=0\nN10 #1=#1+1\n")
        for _ in range(lines // 1000):
            f.write(block)
        f.write("IF [#1 LT 2] GOTO 10\nM30\n%\n")
    size = os.path.getsize(big)

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (96 << 20, 96 << 20))

    r = subprocess.run([ncurve, "run", big, "--json"], capture_output=True, timeout=600,
                       preexec_fn=limit if cap else None)
    ok = r.returncode == 0
    summary = json.loads(r.stdout) if ok else {}
    check(f"{size / 1e6:.0f} MB under a 96 MB address-space cap{'' if cap else ' (not set)'}: completes"
          + ("" if ok else f" (exit {r.returncode}: {r.stderr.decode()[-300:]})"), ok)
    if ok:
        # #1=0, twice N10 + the body + IF, then M30
        check("its blocks and moves as counted by hand",
              summary["blocks_executed"] == 1 + 2 * (lines + 2) + 1 and summary["moves"]["line"] == 2 * lines)

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
