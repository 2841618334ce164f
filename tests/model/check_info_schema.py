#!/usr/bin/env python3
"""`urdfsnap info --json` is the documented format: its output for the sample robots validates
against docs/info.schema.json, agrees with the URDF it describes (every <limit> and <mass> value,
parents and children), and the schema is not vacuous (a damaged description fails it).

usage: check_info_schema.py URDFSNAP SCHEMA MODELS_DIR
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from json_schema import load_validator, refuse_damages  # noqa: E402


def info(urdfsnap, model):
    result = subprocess.run([urdfsnap, "info", "--json", model], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"info --json {model} exited {result.returncode}: {result.stderr}")
    return json.loads(result.stdout)


def expanded(urdfsnap, model):
    result = subprocess.run([urdfsnap, "xacro", model], capture_output=True, text=True, check=True)
    return ElementTree.fromstring(result.stdout)


def check_against_urdf(description, urdf, model):
    joints = {j["name"]: j for j in description["joints"]}
    links = {l["name"]: l for l in description["links"]}
    assert len(joints) == len(urdf.findall("joint")), model
    assert len(links) == len(urdf.findall("link")), model
    for element in urdf.findall("joint"):
        joint = joints[element.get("name")]
        assert joint["type"] == element.get("type"), (model, joint)
        assert joint["parent"] == element.find("parent").get("link"), (model, joint)
        assert joint["child"] == element.find("child").get("link"), (model, joint)
        limit = element.find("limit")
        if limit is None:
            assert joint["limits"] is None or joint["type"] not in ("continuous", "fixed"), (model, joint)
            continue
        for key in ("velocity", "effort"):
            assert joint["limits"][key] == float(limit.get(key, 0)), (model, joint, key)
        if joint["type"] in ("revolute", "prismatic"):
            for key in ("lower", "upper"):
                assert joint["limits"][key] == float(limit.get(key, 0)), (model, joint, key)
    for element in urdf.findall("link"):
        mass = element.find("inertial/mass")
        expected = float(mass.get("value")) if mass is not None else None
        assert links[element.get("name")]["mass"] == expected, (model, element.get("name"))


def main():
    urdfsnap, schema_path, models = (os.path.abspath(p) for p in sys.argv[1:4])
    validator = load_validator(schema_path)
    cases = [os.path.join(models, p) for p in ("mrm_description/urdf/mrm.urdf",
                                               "mrm_description/urdf/mrm.xacro",
                                               "meshbot_description/urdf/meshbot.urdf")]
    for model in cases:
        description = info(urdfsnap, model)
        validator.validate(description)
        check_against_urdf(description, expanded(urdfsnap, model), model)
    # not vacuous: each damage is caught
    description = info(urdfsnap, cases[0])
    damages = [lambda d: d.pop("joints"),
               lambda d: d["joints"][0].update(type="hinge"),
               lambda d: d["joints"][0]["origin"].update(xyz=[1, 2]),
               lambda d: d["links"][0].update(mass="heavy"),
               lambda d: d["tree"][0].update(depth=-1)]
    refuse_damages(validator, description, damages, "a robot description")
    print(f"info_schema: {len(cases)} robots valid, {len(damages)} damaged descriptions refused")


if __name__ == "__main__":
    main()
