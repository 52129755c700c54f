"""Property-based tests of the module's input boundary (Debian's python3-hypothesis): arrays of every real dtype
(float16 ... float64 and longdouble, int8 ... uint64), in C or Fortran order, strided or with negative strides, of
good and bad shapes (empty, one row, wrong width, 1-D), with NaN, infinities and the dtype's extreme values. Every
call either raises somicage.InputError or TypeError, or returns exactly what the float64 / int64 C-order call with
the same values returns (and then only finite numbers).

The calls run in a child process (input_cases.py), a batch of cases per child: a crash (segfault, abort) is a failed
test naming the case, not the end of the test run. Bounded and derandomised: the same examples on every run.
"""
import os
import pickle
import subprocess
import sys

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")  # Debian: python3-hypothesis (third_party/install-deps.sh)
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import input_cases  # noqa: E402

REAL_DTYPES = ["float16", "float32", "float64", "longdouble", "int8", "int16", "int32", "int64", "uint8", "uint16",
               "uint32", "uint64"]
INTEGER_DTYPES = [d for d in REAL_DTYPES if np.dtype(d).kind in "iu"]
LAYOUTS = ["C", "F", "strided", "reversed"]
BATCH = dict(min_size=16, max_size=32)
SETTINGS = settings(derandomize=True, max_examples=8, deadline=None, suppress_health_check=list(HealthCheck))


def extremes(dtype):
    dtype = np.dtype(dtype)
    if dtype.kind == "f":
        largest = float(min(np.finfo(dtype).max, np.finfo(np.float64).max))  # the cases hold float64 values
        return [np.nan, np.inf, -np.inf, 1e300, -1e300, largest, -largest, 1e-300]
    info = np.iinfo(dtype)
    return [int(info.min), int(info.max), -1, 2**31, 2**31 - 1]


@st.composite
def array_spec(draw, values, role, dtypes):
    """An array of the given values (rows of equal length) as hypothesis varies it: dtype, layout, shape, values."""
    dtype = draw(st.sampled_from(dtypes))
    rows = np.array(values, dtype=object)
    change = draw(st.sampled_from(["none"] * 6 + ["empty", "one row", "narrow", "wide", "flat", "extreme"]))
    if change == "empty":
        rows = rows[:0]
    elif change == "one row":
        rows = rows[:1]
    elif change == "narrow":
        rows = rows[:, :-1]
    elif change == "wide":
        rows = np.column_stack([rows, rows[:, :1]])
    elif change == "flat":
        rows = rows.reshape(-1)
    elif change == "extreme":
        rows = rows.copy()
        value = draw(st.sampled_from(extremes(dtype)))
        rows.flat[draw(st.integers(0, rows.size - 1))] = value
    flat = [v if np.dtype(dtype).kind in "iu" else float(v) for v in rows.reshape(-1)]
    if np.dtype(dtype).kind in "iu":  # values the dtype cannot hold are another case: the extremes cover its range
        info = np.iinfo(dtype)
        flat = [min(max(int(v), int(info.min)), int(info.max)) for v in flat]
    return dict(values=flat, shape=rows.shape, dtype=dtype, layout=draw(st.sampled_from(LAYOUTS)), role=role)


# The cube's corners or a square's, scaled and moved: exact in every dtype (float16 holds integers up to 2048).
SQUARE = [[0, 0], [1, 0], [1, 1], [0, 1]]


@st.composite
def cage_case(draw, kind):
    scale, shift = draw(st.sampled_from([1, 2, 40])), draw(st.integers(0, 100))
    if draw(st.booleans()):
        corners, faces = input_cases.CUBE_VERTICES.tolist(), input_cases.CUBE_FACES.tolist()
    else:  # a 2D polygon: edges, or faces=None for the vertex loop
        corners, faces = SQUARE, [[k, (k + 1) % 4] for k in range(4)]
    vertices = draw(array_spec((np.array(corners) * scale + shift).tolist(), "coordinates", REAL_DTYPES))
    no_faces = draw(st.integers(0, 5)) == 0
    return dict(kind=kind, vertices=vertices,
                faces=None if no_faces else draw(array_spec(faces, "indices", INTEGER_DTYPES)))


@st.composite
def deform_case(draw):
    # Points on a grid of eighths inside the cube, a pose moved by eighths: exact in float16, truncated for integer
    # dtypes (the reference sees the same truncated values).
    grid = draw(st.lists(st.tuples(*[st.integers(1, 7)] * 3), min_size=1, max_size=12))
    points = (np.array(grid) / 8.0).tolist()
    posed = (input_cases.CUBE_VERTICES + np.array(draw(st.lists(st.tuples(*[st.integers(-2, 2)] * 3), min_size=8,
                                                                  max_size=8))) / 8.0).tolist()
    parameters = draw(st.fixed_dictionaries({}, optional=dict(
        nu=st.sampled_from([0.0, 0.3, 0.49, -0.99, np.inf, -np.inf, np.nan, 0.5, 1e300]),
        gamma=st.sampled_from([0.0, 1.0, 10.0, 10.5, 1e4, 1e6, np.inf, np.nan, -1.0]),
        variant=st.sampled_from(["global", "local"]))))
    return dict(kind="deform", method=draw(st.sampled_from(["somigliana", "green", "mvc"])),
                points=draw(array_spec(points, "coordinates", REAL_DTYPES)),
                posed=draw(array_spec(posed, "coordinates", REAL_DTYPES)), parameters=parameters)


def run_batch(tmp_path, cases):
    cases_path, results_path, progress_path = tmp_path / "cases.pickle", tmp_path / "results.pickle", tmp_path / "at"
    cases_path.write_bytes(pickle.dumps(cases))
    child = subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "input_cases.py"),
                            str(cases_path), str(results_path), str(progress_path)],
                           capture_output=True, text=True, timeout=120)
    if child.returncode != 0:
        at = progress_path.read_text().split()[-1] if progress_path.exists() else "?"
        case = cases[int(at)] if at.isdigit() else None
        pytest.fail(f"the child exited with {child.returncode} in case {at}: {case}\n{child.stderr[-2000:]}")
    return pickle.loads(results_path.read_bytes())


def same(a, b):
    if isinstance(a, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, np.ndarray):
        return a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b)
    return a == b


def check_outcomes(cases, results):
    for case, (got, expected) in zip(cases, results):
        assert got[0] != "unexpected", f"{got[1]}: {got[2]} for {case}"
        assert expected[0] != "unexpected", f"reference: {expected[1]}: {expected[2]} for {case}"
        if got[0] == "refused":
            continue
        assert expected[0] == "result", f"accepted what the reference refuses ({expected[2]}): {case}"
        assert same(got[1], expected[1]), f"not the reference's result: {case}"
        arrays = got[1] if isinstance(got[1], tuple) else (got[1],)
        assert all(np.isfinite(a).all() for a in arrays if isinstance(a, np.ndarray) and a.dtype.kind == "f"), case


@SETTINGS
@given(st.lists(cage_case("cage"), **BATCH))
def test_cage_any_dtype_layout_shape(tmp_path_factory, cases):
    check_outcomes(cases, run_batch(tmp_path_factory.mktemp("cage"), cases))


@SETTINGS
@given(st.lists(cage_case("check"), **BATCH))
def test_check_any_dtype_layout_shape(tmp_path_factory, cases):
    check_outcomes(cases, run_batch(tmp_path_factory.mktemp("check"), cases))


@SETTINGS
@given(st.lists(deform_case(), **BATCH))
def test_deform_any_dtype_layout_shape_and_parameter(tmp_path_factory, cases):
    check_outcomes(cases, run_batch(tmp_path_factory.mktemp("deform"), cases))


def test_the_good_layouts_are_accepted(tmp_path):
    """The property above must not pass by refusing everything: every dtype and layout of a good cage is accepted
    and gives the float64 call's cage exactly."""
    cases = []
    for dtype in REAL_DTYPES:
        for layout in LAYOUTS:
            vertices = dict(values=input_cases.CUBE_VERTICES.reshape(-1).tolist(), shape=(8, 3), dtype=dtype,
                            layout=layout, role="coordinates")
            index_dtype = dtype if np.dtype(dtype).kind in "iu" else "int16"
            faces = dict(values=input_cases.CUBE_FACES.reshape(-1).tolist(), shape=(12, 3), dtype=index_dtype,
                         layout=layout, role="indices")
            cases.append(dict(kind="cage", vertices=vertices, faces=faces))
    results = run_batch(tmp_path, cases)
    check_outcomes(cases, results)
    refused = [(c["vertices"]["dtype"], c["vertices"]["layout"], got[2]) for c, (got, _) in zip(cases, results)
               if got[0] != "result"]
    assert not refused
