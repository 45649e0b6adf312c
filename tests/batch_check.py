#!/usr/bin/env python3
"""ncurve run with several programs or a folder: the table's rows match running each file alone
(result, blocks, motions, time, warnings, the alarm), in the programs' order, whatever core ran
them; the exit status is the worst row's; options for one program are refused.
    batch_check.py NCURVE SOURCE_DIR OUT_DIR"""
import json
import os
import subprocess
import sys

ncurve, src, out = sys.argv[1:4]
failed = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failed.append(what)


def run(args):
    p = subprocess.run([ncurve, "run", *args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


os.makedirs(out, exist_ok=True)
examples = os.path.join(src, "examples")
rc, table, _ = run([examples, "--json"])
rows = json.loads(table)["programs"]
names = sorted(f for f in os.listdir(examples) if f.endswith(".nc"))
check([os.path.basename(r["program"]) for r in rows] == names, "the folder's programs in name order")
check(rc == 1, f"exit 1: some stop on an alarm ({rc})")
for r in rows:
    code, text, _ = run([r["program"], "--json"])
    alone = json.loads(text)
    same = (r["ok"] == alone["ok"] and r["blocks_executed"] == alone["blocks_executed"]
            and r["motions"] == alone["motions"]
            and r["time_at_programmed_feed_s"] == alone["time_at_programmed_feed_s"]
            and r["warning_count"] == len(alone["warnings"]) + len(alone["text_problems"]) + alone["text_problems_left_out"]
            and r["alarm"] == alone["alarm"])
    check(same, f"{os.path.basename(r['program'])}: the row is the run alone's")

# the same with a profile and a library: the lathe programs complete
lathe = [os.path.join(examples, f) for f in ("lathe-mrc.nc", "lathe-thread.nc", "lathe-hyperbola.nc")]
rc, text, _ = run([*lathe, "--machine", "fanuc-lathe"])
check(rc == 0 and "3 programs: 3 completed, 0 stopped on an alarm, 0 not run" in text, f"three lathe programs: {text}")
# a file that cannot be read is a row of its own, exit 2
bad = os.path.join(out, "batch-not-a-program.nc")
with open(bad, "wb") as f:
    f.write(b"G01 X1 F100\n" + b"\x00" * 10)
rc, text, _ = run([lathe[0], bad, "--machine", "fanuc-lathe", "--json"])
both = json.loads(text)["programs"]
check(both[0]["ok"] and not both[1]["ok"] and both[1]["alarm"] is not None and rc == 1,
      f"a bad program is a row of its own, the good one runs: {text}")
missing = os.path.join(out, "batch-missing.nc")
rc, text, err = run([lathe[0], missing, "--machine", "fanuc-lathe"])
check(rc == 2 and f"no file '{missing}'" in err, f"a program that is not there: exit 2 ({rc}: {err.strip()})")
# options that name one program's output are refused
for opt in (["--plot", os.path.join(out, "b.svg")], ["--format", "csv"], ["--verify"], ["-o", os.path.join(out, "b.txt")]):
    rc, _, err = run([lathe[0], lathe[1], *opt])
    check(rc == 2 and "is for one program" in err, f"{opt[0]} with two programs refused: {err.strip()}")
# an empty folder
empty = os.path.join(out, "batch-empty")
os.makedirs(empty, exist_ok=True)
rc, _, err = run([empty])
check(rc == 2 and "no program files in" in err, f"an empty folder: {err.strip()}")
print(f"{len(failed)} failed")
sys.exit(1 if failed else 0)
