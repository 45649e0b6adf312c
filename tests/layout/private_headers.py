#!/usr/bin/env python3
"""The machine stage's private headers stay inside it: a file outside src/machine/ and
tests/machine/ may include only the headers at the top of src/machine/ that make its API
(interpreter.hpp, profile.hpp, library.hpp, move.hpp, observer.hpp, trace.hpp, macro_output.hpp,
rapid_path.hpp, arc_points.hpp),
never executor.hpp, the G-code table or a header of a sub-folder (frame/, cycles/, path/, profile/).

usage: private_headers.py SOURCE_ROOT
"""
import os
import re
import sys

root = os.path.abspath(sys.argv[1])
public = {"interpreter.hpp", "profile.hpp", "library.hpp", "move.hpp", "observer.hpp", "trace.hpp",
          "macro_output.hpp", "rapid_path.hpp", "arc_points.hpp"}
inside = (os.path.join("src", "machine"), os.path.join("tests", "machine"))
include = re.compile(r'^\s*#\s*include\s*"machine/([^"]+)"')
found = []
for top in ("src", "tests", "bench", "fuzz"):
    for folder, _, files in os.walk(os.path.join(root, top)):
        rel_folder = os.path.relpath(folder, root)
        if rel_folder.startswith(inside):
            continue
        for name in files:
            if not name.endswith((".cpp", ".hpp", ".h", ".cc")):
                continue
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                for number, line in enumerate(f, 1):
                    m = include.match(line)
                    if m and m.group(1) not in public:
                        found.append(f"{os.path.relpath(path, root)}:{number}: includes machine/{m.group(1)}, "
                                     "a header private to src/machine/")
for line in found:
    print(line)
if found:
    sys.exit(1)
print("no file outside src/machine/ and tests/machine/ includes a private header of machine/")
