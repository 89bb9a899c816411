#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""One command's --json summary against docs/cmfilter.schema.json:
    check_json_schema.py SCHEMA -- COMMAND SUBCOMMAND ARGS... --json
Runs the command, parses its stdout as JSON (nothing else may be printed
there), checks "command" is SUBCOMMAND and validates the summary against the
schema (JSON Schema 2020-12, python3-jsonschema). Then checks the schema can
fail on this summary: with an undocumented field added, and with a number of
it turned into text, validation must fail."""
import json
import subprocess
import sys

import jsonschema


def main():
    schema_path = sys.argv[1]
    argv = sys.argv[sys.argv.index("--") + 1:]
    with open(schema_path) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    run = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if run.returncode not in (0, 5, 6):  # compare's gates exit 5 or 6 after printing
        print(f"FAIL: {' '.join(argv)} exited {run.returncode}:\n{run.stderr}")
        return 1
    try:
        summary = json.loads(run.stdout)
    except json.JSONDecodeError as e:
        print(f"FAIL: stdout is not one JSON document ({e}):\n{run.stdout[:2000]}")
        return 1
    if summary.get("command") != argv[1]:
        print(f"FAIL: \"command\" is {summary.get('command')!r}, expected {argv[1]!r}")
        return 1
    errors = sorted(validator.iter_errors(summary), key=lambda e: list(e.path))
    if errors:
        best = jsonschema.exceptions.best_match(errors)
        print(f"FAIL: {argv[1]}'s summary does not match the schema at /{'/'.join(map(str, best.path))}: {best.message}")
        return 1
    # The schema must be able to fail.
    extra = dict(summary, undocumented_field=1)
    if validator.is_valid(extra):
        print("FAIL: the schema accepts an undocumented field")
        return 1
    numbers = [k for k, v in summary.items() if isinstance(v, (int, float)) and not isinstance(v, bool)
               and k != "schema_version"]
    if numbers:
        as_text = dict(summary, **{numbers[0]: str(summary[numbers[0]])})
        if validator.is_valid(as_text):
            print(f"FAIL: the schema accepts \"{numbers[0]}\" as text")
            return 1
    print(f"{argv[1]}: the summary matches schema version {summary['schema_version']}"
          f" ({len(summary)} fields); an undocumented field and a number as text are refused")
    return 0


if __name__ == "__main__":
    sys.exit(main())
