#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks libcmfilter's includes against the module rule of docs/architecture.md.

The rule is the fenced block tagged `modules` in docs/architecture.md: one line
per module, `module: the modules it may include`. This script reads every
`#include "cmfilter/<module>/<file>.h"` under lib/cmfilter/ and fails on
  - a file outside any module folder, or a module the rule does not name;
  - an include of a module the rule does not allow (an edge the wrong way);
  - a cycle in the rule itself;
  - a cycle between files: a file (its .h and .cpp together) that reaches
    itself through includes.
Usage: check_module_deps.py SOURCE_DIR
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"cmfilter/([^"]+)"', re.M)


def read_rule(doc):
    text = doc.read_text()
    block = re.search(r"```modules\n(.*?)```", text, re.S)
    if not block:
        sys.exit(f"{doc}: no ```modules block (the module rule)")
    rule = {}
    for number, line in enumerate(block.group(1).splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        name, _, deps = line.partition(":")
        rule[name.strip()] = set(deps.split())
    for name, deps in rule.items():
        for dep in deps:
            if dep not in rule:
                sys.exit(f"{doc}: module '{name}' may include '{dep}', which the rule does not define")
    return rule


def find_cycle(graph):
    """A list of nodes forming a cycle in {node: set(nodes)}, or None."""
    state = {}
    stack = []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    rule = read_rule(root / "docs" / "architecture.md")
    problems = []
    cycle = find_cycle(rule)
    if cycle:
        problems.append("the module rule has a cycle: " + " -> ".join(cycle))

    lib = root / "lib" / "cmfilter"
    files = {}  # unit "module/base" -> set of included units
    for path in sorted(lib.rglob("*")):
        if path.suffix not in (".h", ".cpp", ".in") or not path.is_file():
            continue
        rel = path.relative_to(lib)
        if len(rel.parts) != 2:
            problems.append(f"lib/cmfilter/{rel}: not in a module folder (lib/cmfilter/<module>/)")
            continue
        module = rel.parts[0]
        if module not in rule:
            problems.append(f"lib/cmfilter/{rel}: module '{module}' is not in docs/architecture.md's rule")
            continue
        unit = f"{module}/{rel.name.split('.')[0]}"
        deps = files.setdefault(unit, set())
        for target in INCLUDE.findall(path.read_text()):
            parts = target.split("/")
            if len(parts) != 2:
                problems.append(f"lib/cmfilter/{rel}: includes \"cmfilter/{target}\", not cmfilter/<module>/<file>.h")
                continue
            to_module = parts[0]
            to_unit = f"{to_module}/{parts[1].split('.')[0]}"
            if to_unit != unit:
                deps.add(to_unit)
            if to_module != module and to_module not in rule.get(module, ()):
                problems.append(f"lib/cmfilter/{rel}: includes cmfilter/{target}, but {module} may not include "
                                f"{to_module} (docs/architecture.md)")
    cycle = find_cycle(files)
    if cycle:
        problems.append("include cycle between files: " + " -> ".join(cycle))
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    edges = sum(len(d) for d in files.values())
    print(f"{len(files)} files in {len({u.split('/')[0] for u in files})} modules, {edges} include edges: "
          "every edge follows docs/architecture.md, no cycles")


if __name__ == "__main__":
    main()
