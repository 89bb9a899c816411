#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The module check fails where it must: builds small trees in a temporary
folder (a rule and a few headers) and runs check_module_deps.py on each,
expecting success on a tree that follows its rule and failure, naming the
problem, on a wrong-way edge, a cycle between files, a cycle in the rule, a
file outside a module and an unknown module."""
import pathlib
import subprocess
import sys
import tempfile

CHECK = pathlib.Path(__file__).with_name("check_module_deps.py")
RULE = "```modules\nutil:\nmath: util\nrender: util math\n```\n"


def run(files, rule=RULE):
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "docs").mkdir()
        (root / "docs" / "architecture.md").write_text("# rule\n" + rule)
        for name, text in files.items():
            path = root / "lib" / "cmfilter" / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        done = subprocess.run([sys.executable, str(CHECK), str(root)], capture_output=True, text=True)
        return done.returncode, done.stdout + done.stderr


def inc(target):
    return f'#include "cmfilter/{target}"\n'


failures = []


def expect(name, files, ok, says=None, rule=RULE):
    code, out = run(files, rule)
    if (code == 0) != ok or (says and says not in out):
        failures.append(f"{name}: exit {code}, expected {'0' if ok else 'non-zero'}"
                        f"{' naming ' + repr(says) if says else ''}; output:\n{out}")


good = {"util/error.h": "", "math/fft.h": inc("util/error.h"), "math/fft.cpp": inc("math/fft.h"),
        "render/render.h": inc("math/fft.h") + inc("util/error.h")}
expect("a tree that follows its rule", good, True)
expect("an edge the wrong way", {**good, "util/error.cpp": inc("render/render.h")}, False,
       "util may not include render")
expect("a cycle between files", {**good, "math/a.h": inc("math/b.h"), "math/b.cpp": inc("math/a.h")}, False,
       "include cycle between files")
expect("a cycle in the rule", good, False, "the module rule has a cycle",
       rule="```modules\nutil: render\nmath: util\nrender: util math\n```\n")
expect("a file outside a module folder", {**good, "loose.h": ""}, False, "not in a module folder")
expect("a module the rule does not name", {**good, "extra/x.h": ""}, False, "is not in docs/architecture.md's rule")
expect("an include without its module", {**good, "math/c.h": inc("fft.h")}, False, "not cmfilter/<module>/<file>.h")

for f in failures:
    print(f)
if failures:
    sys.exit(1)
print("check_module_deps.py: 7 of 7 cases as expected")
