#!/usr/bin/env python3
"""The documented results format is the written one: results files made by the urdfsnap binary
(an unsharded check, two shards, their merge) validate against docs/snapshot-results.schema.json,
and the schema is not vacuous (a damaged file fails it).

usage: check_results_schema.py URDFSNAP SCHEMA MODEL
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from json_schema import load_validator, refuse_damages  # noqa: E402


def run(*args, expect):
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode not in expect:
        sys.exit(f"{' '.join(args)} exited {result.returncode}:\n{result.stdout}{result.stderr}")


def main():
    urdfsnap, schema_path, model = (os.path.abspath(p) for p in sys.argv[1:4])
    validator = load_validator(schema_path)
    work = tempfile.mkdtemp(prefix="urdfsnap_results_schema.")
    try:
        suite = os.path.join(work, "suite.yaml")
        with open(suite, "w") as f:
            f.write(f"defaults:\n  model: {model}\n  size: 160x120\ncases:\n"
                    "  - name: home\n    depth: true\n    labels: true\n"
                    "  - name: drifted\n    joints: {link_01__link_02: 0.8}\n    depth: true\n    labels: true\n"
                    "  - name: new_view\n    yaw: 1.0\n    labels: true\n"
                    "  - name: broken\n    joints: {nope: 1}\n")
        run(urdfsnap, "snapshot", "update", suite, expect={2})
        for kind in (".png", ".labels.png"):
            os.remove(os.path.join(work, "new_view" + kind))
        for kind in (".png", ".depth.png", ".labels.png"):
            shutil.copy(os.path.join(work, "home" + kind), os.path.join(work, "drifted" + kind))
        files = []
        for name, shard in (("whole", []), ("one", ["--shard", "1/2"]), ("two", ["--shard", "2/2"])):
            files.append(os.path.join(work, name, "results.json"))
            run(urdfsnap, "snapshot", "check", suite, *shard, "--results", files[-1],
                "--report", os.path.join(work, name, "report"), expect={0, 1, 2})
        files.append(os.path.join(work, "merged.json"))
        run(urdfsnap, "snapshot", "merge", files[1], files[2], "--results", files[-1],
            "--report", os.path.join(work, "merged_report"), expect={2})
        statuses, part_statuses = set(), set()
        for path in files:
            with open(path) as f:
                results = json.load(f)
            validator.validate(results)
            statuses |= {c["status"] for c in results["cases"]}
            part_statuses |= {c[part]["status"] for c in results["cases"] for part in ("depth", "labels") if part in c}
        if statuses != {"passed", "failed", "missing", "error"}:
            sys.exit(f"expected every status in the files, got {statuses}")
        if part_statuses != {"passed", "failed", "missing"}:
            sys.exit(f"expected every depth/labels status in the files, got {part_statuses}")
        drifted = next(c for c in results["cases"] if c["name"] == "drifted")
        if drifted["depth"]["figures"]["max_delta"] <= 0 or "diff" not in drifted["labels"]["images"]:
            sys.exit(f"expected depth figures and a labels diff image for 'drifted', got {drifted}")
        case_of = lambda r, name: next(c for c in r["cases"] if c["name"] == name)  # noqa: E731
        refuse_damages(validator, results, [
            lambda r: case_of(r, "drifted")["depth"]["figures"].update(pixels_coverage=-1),
            lambda r: r["cases"][0].update(status="ok")], "a results file")
        print(f"{len(files)} results files valid against {schema_path}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
