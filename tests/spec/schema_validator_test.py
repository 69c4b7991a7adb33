#!/usr/bin/env python3
"""`canopy schema` under a standard JSON Schema validator (Draft 2020-12, python3-jsonschema).

Every scenario canopy accepts must pass: the built-in library and its layouts, the schema probes,
the fuzz corpus's scenarios and tests/data/schema/valid/. Every file of tests/data/schema/invalid/
(one per class of error a schema can express: wrong type, out of range, unknown key, missing
required field, two exclusive variants at once, ...) must be refused by the validator and, so
that the set stays honest, by `canopy validate` too.

usage: schema_validator_test.py CANOPY_BINARY SOURCE_DIR. Exits 77 (ctest's skip) when
jsonschema is not installed.
"""
import glob
import json
import os
import subprocess
import sys

try:
    import jsonschema
except ImportError:
    print("skipped: python3-jsonschema is not installed")
    sys.exit(77)


def strip_comments(text):
    """The scenario format allows // and /* */ comments (spec/json_text.h); JSON does not."""
    out, i, in_string = [], 0, False
    while i < len(text):
        c = text[i]
        if in_string:
            out.append(c)
            if c == "\\":
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
            out.append(c)
        elif text.startswith("//", i):
            while i < len(text) and text[i] != "\n":
                i += 1
            continue
        elif text.startswith("/*", i):
            i = text.index("*/", i) + 2
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.loads(strip_comments(f.read()))


def main():
    canopy, source = sys.argv[1], sys.argv[2]
    schema = json.loads(subprocess.run([canopy, "schema"], check=True, capture_output=True,
                                       text=True).stdout)
    jsonschema.Draft202012Validator.check_schema(schema)
    scenario = jsonschema.Draft202012Validator(schema)
    layout = jsonschema.Draft202012Validator(
        {"$schema": schema["$schema"], "$defs": schema["$defs"], "$ref": "#/$defs/layout"})

    def files(*patterns):
        found = sorted(p for pattern in patterns for p in glob.glob(os.path.join(source, pattern)))
        assert found, patterns
        return found

    failures = []
    valid = files("scenarios/library/*.json", "scenarios/schema_probe*.json",
                  "fuzz/corpus/scenario_loader/*.json", "tests/data/schema/valid/*.json")
    layouts = files("scenarios/library/layouts/*.json")
    invalid = files("tests/data/schema/invalid/*.json")
    for validator, paths in ((scenario, valid), (layout, layouts)):
        for path in paths:
            errors = list(validator.iter_errors(load(path)))
            if errors:
                failures.append(f"{path}: refused, {len(errors)} errors, first: "
                                f"{'/'.join(map(str, errors[0].absolute_path))}: "
                                f"{errors[0].message[:300]}")
    for path in invalid:
        if scenario.is_valid(load(path)):
            failures.append(f"{path}: accepted by the schema")
        loader = subprocess.run([canopy, "validate", path], capture_output=True, text=True)
        if loader.returncode == 0:
            failures.append(f"{path}: accepted by canopy validate (not an error the loader "
                            f"rejects)")
    print(f"{len(valid)} scenarios and {len(layouts)} layouts checked valid, "
          f"{len(invalid)} invalid files checked refused")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
