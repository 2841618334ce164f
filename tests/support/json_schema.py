"""The JSON-Schema tests' shared steps (check_info_schema.py, check_results_schema.py): a schema
file checked as JSON Schema draft 7 and made into a validator, and damaged copies of a valid
document that the schema must refuse, so that it is not vacuous."""
import copy
import json
import sys

import jsonschema


def load_validator(schema_path):
    with open(schema_path) as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    return jsonschema.Draft7Validator(schema)


def refuse_damages(validator, document, damages, what):
    """Exits naming `what` unless `validator` refuses each copy of `document` that a function of
    `damages` (each changing the copy in place) damaged."""
    for number, damage in enumerate(damages, 1):
        broken = copy.deepcopy(document)
        damage(broken)
        if validator.is_valid(broken):
            sys.exit(f"the schema accepts {what} with damage {number} of {len(damages)}")
