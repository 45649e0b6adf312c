#!/usr/bin/env python3
"""What every program does, as one digest each: the moves (--format jsonl), the summary (--json),
the messages and the exit status of `ncurve run` on every tests/programs/**/*.nc, examples/*.nc and
corpus program, compared with digests.tsv. A restructuring keeps them all; a change of behaviour
(a defect fixed) updates the digests of the programs it changes, in the commit that makes it.
The program's own path and its machine file's (the messages and the moves name them) are hashed as
<program> and <machine>, so a program moved to another folder keeps its digest: only its key changes.

With --stream BYTES every program is read as a stream (`run --stream`) in pieces of about BYTES
bytes (NCURVE_STREAM_CHUNK), so that jumps, loops and calls cross pieces: the digests must not change.

usage: digests.py NCURVE [--update] [--corpus DIR] [--stream BYTES]
"""
import concurrent.futures
import hashlib
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
table = os.path.join(here, "digests.tsv")
ncurve = os.path.abspath(sys.argv[1])
update = "--update" in sys.argv
corpus = os.environ.get("NCURVE_CORPUS", os.path.join(root, "..", "shared", "corpus"))
if "--corpus" in sys.argv:
    corpus = sys.argv[sys.argv.index("--corpus") + 1]
corpus = os.path.abspath(corpus)
stream = sys.argv[sys.argv.index("--stream") + 1] if "--stream" in sys.argv else None
if stream and update:
    sys.exit("--stream checks the digests; it records none")

# the examples' machines and options, as the README runs them
examples = {
    "lathe-hyperbola.nc": ["--machine", "fanuc-lathe"],
    "lathe-mrc.nc": ["--machine", "fanuc-lathe"],
    "lathe-thread.nc": ["--machine", "fanuc-lathe"],
    "4-axis.nc": ["--machine", "fanuc-4axis-helicoid"],
    "custom-cycle.nc": ["--lib", "macros", "--param", "6050=102"],
}


def programs():
    """the path of each tests/programs/**/*.nc under the repository, with '/' between folders, sorted"""
    found = []
    for folder, _, names in os.walk(os.path.join(root, "tests", "programs")):
        rel = os.path.relpath(folder, root).replace(os.sep, "/")
        found += [rel + "/" + name for name in names if name.endswith(".nc")]
    return sorted(found)


def cases():
    """(key, folder to run in, arguments after `run`)"""
    for path in programs():
        stem = path[:-3]
        args = [path, "--lib", "macros"]
        if os.path.exists(os.path.join(root, stem + ".toml")):
            args += ["--machine", stem + ".toml"]
        if os.path.exists(os.path.join(root, stem + ".args")):
            with open(os.path.join(root, stem + ".args")) as f:
                args += [line.rstrip("\n") for line in f if line.strip()]
        yield path, root, args
    for name in sorted(os.listdir(os.path.join(root, "examples"))):
        if name.endswith(".nc"):
            yield "examples/" + name, root, [os.path.join("examples", name)] + examples.get(name, [])
    expected = os.path.join(root, "tests", "corpus", "expected.tsv")
    if not os.path.isdir(corpus):
        return
    with open(expected) as f:
        for row in f:
            cols = row.rstrip("\n").split("\t")
            if cols[0] == "path" or len(cols) < 2:
                continue
            opts = cols[4].split() if len(cols) > 4 else []
            opts = [os.path.join(root, "tests", "corpus", o) if o.startswith("profiles/") else o for o in opts]
            if cols[1] == "lathe" and "--machine" not in opts:
                opts += ["--machine", "fanuc-lathe"]
            yield "corpus/" + cols[0], corpus, [cols[0]] + opts


def own_paths(args):
    """what the run's output names the program and its machine file by, and the placeholder of each"""
    paths = [(args[0], b"<program>")]
    if "--machine" in args:
        machine = args[args.index("--machine") + 1]
        if machine.endswith(".toml"):
            paths.append((machine, b"<machine>"))
    return paths


def hashed(text, args):
    """the text without the folders the run happened in, nor the program's and machine file's paths"""
    text = text.replace(root.encode(), b"<root>").replace(corpus.encode(), b"<corpus>")
    for path, placeholder in own_paths(args):
        text = text.replace(path.encode(), placeholder)
    return text


def digest(case):
    key, cwd, args = case
    with tempfile.TemporaryDirectory() as tmp:
        moves = os.path.join(tmp, "moves.jsonl")
        env = dict(os.environ, NCURVE_STREAM_CHUNK=stream) if stream else None
        r = subprocess.run([ncurve, "run", *args, "--format", "jsonl", "-o", moves, "--json",
                            "--max-steps", "2000000"] + (["--stream"] if stream else []),
                           cwd=cwd, capture_output=True, timeout=120, env=env)
        h = hashlib.sha256()
        h.update(b"exit %d\n" % r.returncode)
        for part in (r.stdout, r.stderr):
            h.update(hashed(part, args))
        if os.path.exists(moves):
            with open(moves, "rb") as f:
                h.update(hashed(f.read(), args))
    return key, " ".join(args), h.hexdigest()[:16]


def main():
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        got = {key: (args, d) for key, args, d in pool.map(digest, cases())}
    recorded = {}
    if os.path.exists(table):
        with open(table) as f:
            for row in f:
                if row.startswith("#") or not row.strip():
                    continue
                key, d = row.rstrip("\n").split("\t")[:2]
                recorded[key] = d
    if update:
        # a corpus absent here keeps its recorded rows
        rows = {k: d for k, d in recorded.items() if k.startswith("corpus/") and not os.path.isdir(corpus)}
        rows.update({k: d for k, (_, d) in got.items()})
        with open(table, "w") as f:
            f.write("# program\tdigest of `ncurve run` (moves, summary, messages, exit): tests/digest/digests.py\n")
            for k in sorted(rows):
                f.write(f"{k}\t{rows[k]}\n")
        changed = sorted(k for k in got if recorded.get(k) != got[k][1])
        print(f"{len(rows)} digests written; changed or new: {len(changed)}")
        for k in changed:
            print("  ", k)
        return 0
    failed = []
    for k, (args, d) in sorted(got.items()):
        if k not in recorded:
            failed.append(f"{k}: no recorded digest (ncurve run {args})")
        elif recorded[k] != d:
            failed.append(f"{k}: what `ncurve run {args}` does has changed")
    for k in sorted(recorded):
        if k not in got and (not k.startswith("corpus/") or os.path.isdir(corpus)):
            failed.append(f"{k}: recorded but not found")
    for line in failed:
        print("FAIL:", line)
    if failed:
        print("A change of behaviour: if it is intended (a defect fixed), record it in the same commit with\n"
              f"  python3 tests/digest/digests.py {sys.argv[1]} --update")
    if not os.path.isdir(corpus):
        print(f"(the corpus is not at {corpus}: its programs were not run)")
    print(f"{len(got) - len(failed)} passed, {len(failed)} failed")
    return 1 if failed else 0


sys.exit(main())
