"""Python's and Blender's parameters against the engine's one table (core/deform/parameter_schema.h, issue 23): the
keywords of Deformer.deform and analyze (as built and in the stub), load_session's keywords and the Blender panel's
properties are the table's rows with its defaults and ranges, so a row added to the table fails here until every
front end has it."""
import ast
import math
import pathlib
import re

import somicage
from somicage import _somicage

STUB = pathlib.Path(_somicage.__file__).with_name("_somicage.pyi")
BINDING = pathlib.Path(__file__).resolve().parents[2] / "blender" / "somicage_cage_deform" / "binding.py"
SCHEMA = somicage.parameter_schema()
# The keywords whose Python default differs from the table's on purpose: blend is None (the variant's blend).
PYTHON_DEFAULTS = {"blend": None}
# Blender shows the variants by name and no blend slider; nu's infinity is a checkbox of its own (nu_infinite).
BLENDER_OMITS = {"blend"}


def keyword_defaults(signature):
    """{keyword: default text} of a pybind11 signature line 'deform(self, posed, *, nu: float = 0.0, ...)'."""
    return dict(re.findall(r"(\w+): [^=,]+ = ([^,)]+)", signature))


def literal(text):
    return ast.literal_eval(text) if text != "None" else None


def expected_default(row):
    if row["key"] in PYTHON_DEFAULTS:
        return PYTHON_DEFAULTS[row["key"]]
    return row["default"]


def test_the_table_is_the_engines():
    keys = [row["key"] for row in SCHEMA]
    assert len(set(keys)) == len(keys)
    for field in ("keyword", "session_key", "view_key", "cli_flag"):
        values = [row[field] for row in SCHEMA]
        assert len(set(values)) == len(values), field
    ranges = somicage.parameter_ranges()
    for row in SCHEMA:
        if row["type"] == "number":
            assert ranges[row["keyword"]] == row["range"], row["key"]
        assert set(row["methods"]) <= set(somicage.methods())
    for info in somicage.method_info():
        assert set(info["parameters"]) == {row["keyword"] for row in SCHEMA if info["name"] in row["methods"]}


def test_deform_and_analyze_take_every_row_with_its_default():
    for function in (somicage.Deformer.deform, somicage.Deformer.analyze):
        defaults = keyword_defaults(function.__doc__.splitlines()[0])
        for row in SCHEMA:
            assert row["keyword"] in defaults, f"{function.__name__} lacks {row['keyword']}"
            assert literal(defaults[row["keyword"]]) == expected_default(row), row["keyword"]


def test_the_stub_has_every_row_with_its_default():
    tree = ast.parse(STUB.read_text())
    deformer = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Deformer")
    for function in (n for n in deformer.body if isinstance(n, ast.FunctionDef) and n.name in ("deform", "analyze")):
        defaults = {a.arg: ast.literal_eval(d) for a, d in zip(function.args.kwonlyargs, function.args.kw_defaults)}
        for row in SCHEMA:
            assert row["keyword"] in defaults, f"the stub's {function.name} lacks {row['keyword']}"
            assert defaults[row["keyword"]] == expected_default(row), row["keyword"]


def test_load_session_gives_every_row(tmp_path):
    session = tmp_path / "s.json"
    session.write_text('{"format": "somicage-session", "version": 3, "mesh": "", "cage": "", "demoDim": 2, '
                       '"method": "somigliana", "params": {"variant": "affine", "nu": "inf", "bulging": "reference", '
                       '"tractionCorrection": false}}')
    params = somicage.load_session(str(session))["params"]
    assert set(params) == {row["keyword"] for row in SCHEMA}
    assert params["variant"] == "affine" and params["bulging"] == "reference"
    assert math.isinf(params["nu"]) and params["traction_fix"] is False  # the session's old key, read


def blender_properties():
    tree = ast.parse(BINDING.read_text())
    binding = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "SomicageBinding")
    properties = {}
    for node in binding.body:
        if isinstance(node, ast.AnnAssign) and isinstance(node.annotation, ast.Call):
            keywords = {k.arg: k.value for k in node.annotation.keywords}
            properties[node.target.id] = {k: ast.literal_eval(v) for k, v in keywords.items()
                                          if k in ("default", "min", "max")}
    return properties


def test_the_blender_panel_has_every_row_with_the_tables_default_and_range():
    properties = blender_properties()
    for row in SCHEMA:
        if row["key"] in BLENDER_OMITS:
            continue
        assert row["keyword"] in properties, f"the Blender binding lacks {row['keyword']}"
        prop = properties[row["keyword"]]
        assert prop.get("default") == row["default"], row["keyword"]
        if row["type"] == "number":
            low, high = row["range"]
            # An open range's ends are not values: the slider stops short of them.
            assert (low < prop["min"] if row["open_range"] else low == prop["min"]), row["keyword"]
            assert (prop["max"] < high if row["open_range"] else prop["max"] == high), row["keyword"]
