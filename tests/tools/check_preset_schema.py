#!/usr/bin/env python3
"""Checks presets against presets/aerial-preset.schema.json (JSON Schema
draft 2020-12) with python3-jsonschema.

usage: check_preset_schema.py SCHEMA PRESET_DIR [--must-fail FIXTURE ...]

Every *.json in PRESET_DIR except the schema must validate; every
--must-fail fixture must be rejected (so the check cannot pass vacuously).
Exit status 0 when all hold, 1 otherwise (reasons on stderr).
"""
import json
import pathlib
import sys

import jsonschema


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    schema_path = pathlib.Path(argv[1])
    preset_dir = pathlib.Path(argv[2])
    must_fail = []
    if len(argv) > 3:
        if argv[3] != "--must-fail":
            print(__doc__, file=sys.stderr)
            return 2
        must_fail = [pathlib.Path(p) for p in argv[4:]]

    schema = json.loads(schema_path.read_text())
    validator_class = jsonschema.validators.validator_for(schema)
    validator_class.check_schema(schema)
    validator = validator_class(schema)

    failures = 0
    presets = sorted(p for p in preset_dir.glob("*.json") if p.resolve() != schema_path.resolve())
    if len(presets) < 5:
        print(f"expected at least 5 presets in {preset_dir}, found {len(presets)}", file=sys.stderr)
        failures += 1
    for path in presets:
        errors = sorted(validator.iter_errors(json.loads(path.read_text())), key=lambda e: list(e.path))
        for error in errors:
            pointer = "/" + "/".join(str(p) for p in error.path)
            print(f"{path}: {pointer}: {error.message}", file=sys.stderr)
        failures += bool(errors)
        if not errors:
            print(f"ok   {path.name}")
    for path in must_fail:
        if validator.is_valid(json.loads(path.read_text())):
            print(f"{path}: expected the schema to reject this fixture", file=sys.stderr)
            failures += 1
        else:
            print(f"ok   {path.name} rejected")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
