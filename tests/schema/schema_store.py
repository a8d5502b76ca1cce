"""The schemas of schemas/ as validators (docs/reports.md): a report schema refers to common.schema.json by its
$id, so every schema of the folder goes in the store. Shared by the schema tests."""
import glob
import json
import os
import sys
import warnings

try:
    import jsonschema
except ImportError:
    sys.exit("schema tests: python3-jsonschema is not installed (scripts/install-deps.sh installs it)")


def load(path):
    with open(path) as f:
        return json.load(f)


_stores = {}


def store(schemas_dir):
    """Every schema of the folder, each checked to be a valid schema, loaded once per folder."""
    if schemas_dir not in _stores:
        schemas = []
        for path in glob.glob(os.path.join(schemas_dir, "*.schema.json")):
            s = load(path)
            jsonschema.Draft202012Validator.check_schema(s)
            schemas.append(s)
        _stores[schemas_dir] = schemas
    return _stores[schemas_dir]


def validator(schemas_dir, name):
    """Draft 2020-12 validator for SCHEMAS_DIR/NAME.schema.json, its references (common.schema.json) resolved
    from the folder: through `referencing` where jsonschema has it (4.18 and later), else RefResolver
    (Debian bookworm's 4.10). Every schema of the folder is checked to be a valid schema first."""
    schemas = store(schemas_dir)
    schema = load(os.path.join(schemas_dir, name + ".schema.json"))
    try:
        from referencing import Registry, Resource
        from referencing.jsonschema import DRAFT202012
    except ImportError:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            resolver = jsonschema.RefResolver.from_schema(schema, store={s["$id"]: s for s in schemas})
            return jsonschema.Draft202012Validator(schema, resolver=resolver)
    registry = Registry().with_resources(
        (s["$id"], Resource.from_contents(s, default_specification=DRAFT202012)) for s in schemas)
    return jsonschema.Draft202012Validator(schema, registry=registry)


def errors(v, doc):
    """The validation errors' messages (empty: valid)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return [e.message for e in v.iter_errors(doc)]
