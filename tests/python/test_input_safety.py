"""The module's input boundary, case by case (test_hypothesis_inputs.py varies the same inputs at random): indices of
every integer dtype kept alive while read, empty and out-of-range arrays refused naming the argument, the parameter
ranges of the engine's one list, check() against `somicage check --json`, analyze()'s progress and Ctrl-C, paths,
and signatures with real types."""
import json
import os
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import somicage
from conftest import FIREHYDRANT, cli_executable, require_firehydrant, star_polygon, unit_cube
from test_front_ends import cli_error, run_cli

INTEGER_DTYPES = [np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint32, np.uint64]


def run_isolated(code, silent=False):
    """Runs code in a fresh interpreter: a crash there is a failed assertion here, not the end of the test run.
    silent: it must write nothing to stderr either."""
    child = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True, timeout=120,
                           cwd=os.path.dirname(__file__))
    assert child.returncode == 0, f"exit {child.returncode}\n{child.stdout}\n{child.stderr}"
    assert not (silent and child.stderr), child.stderr
    return child.stdout


def test_firehydrant_faces_of_every_integer_dtype_round_trip():
    """Cage.faces is int32: handing it back used to read a converted copy after it was freed (garbage indices from
    the 94th face on; the 12 faces of a cube happened to survive)."""
    require_firehydrant()
    cage = somicage.Cage.from_obj(FIREHYDRANT / "fireHydrant_cages_triangulated.obj")
    assert cage.num_faces == 94 and cage.faces.dtype == np.int32
    for _ in range(20):
        np.testing.assert_array_equal(somicage.Cage(cage.vertices, cage.faces).faces, cage.faces)
    for dtype in INTEGER_DTYPES:
        faces = cage.faces.astype(dtype)
        for layout in (faces, np.asfortranarray(faces), np.repeat(faces, 2, axis=1)[:, ::2], faces[::-1][::-1]):
            np.testing.assert_array_equal(somicage.Cage(cage.vertices, layout).faces, cage.faces, err_msg=str(dtype))
    for dtype in (np.float32, np.longdouble):  # (float16 or integers would round the cage into another one)
        vertices = cage.vertices.astype(dtype)
        expected = vertices.astype(np.float64)
        np.testing.assert_array_equal(somicage.Cage(vertices, cage.faces).vertices, expected, err_msg=str(dtype))


def test_empty_arrays_are_refused_not_crashes():
    out = run_isolated("""
        import numpy as np, somicage
        calls = [lambda: somicage.Cage(np.zeros((0, 3)), np.zeros((0, 3), np.int64)),
                 lambda: somicage.Cage(np.zeros((0, 2))),
                 lambda: somicage.check(np.zeros((0, 3)), np.zeros((0, 3), np.int64)),
                 lambda: somicage.check(np.zeros((0, 2)))]
        for call in calls:
            try:
                call()
            except somicage.InputError as error:
                print(error.source, "|", error.problem)
        """)
    assert out.splitlines() == ["vertices | has shape (0, 3): no rows", "vertices | has shape (0, 2): no rows"] * 2


def test_empty_faces_points_and_poses_are_refused(cube_cage, cube_points):
    with pytest.raises(somicage.InputError, match=r"^faces: has shape \(0, 3\): no rows"):
        somicage.Cage(cube_cage.vertices, np.zeros((0, 3), np.int32))
    with pytest.raises(somicage.InputError, match=r"^points: has shape \(0, 3\): no rows"):
        somicage.Deformer(cube_cage, np.zeros((0, 3)))
    with pytest.raises(somicage.InputError, match=r"^posed: has shape \(0, 3\): no rows"):
        somicage.Deformer(cube_cage, cube_points).deform(np.zeros((0, 3)))


@pytest.mark.parametrize("index,dtype", [(-1, np.int8), (8, np.int32), (2**40, np.int64), (2**63 + 5, np.uint64),
                                         (-2**63, np.int64), (255, np.uint8)])
def test_out_of_range_indices_name_faces(index, dtype):
    vertices, faces = unit_cube()
    faces = faces.astype(dtype)
    faces[4, 1] = index
    with pytest.raises(somicage.InputError) as error:
        somicage.Cage(vertices, faces)
    assert error.value.source == "faces"
    assert error.value.problem == f"face 4 has index {index}" and "[0, 8)" in error.value.hint
    with pytest.raises(somicage.InputError, match=f"^faces: face 4 has index {index}"):
        somicage.check(vertices, faces)


@pytest.mark.parametrize("name,vertices,faces", [
    ("vertices", unit_cube()[0].astype(complex), unit_cube()[1]),
    ("vertices", np.array([["a", "b", "c"]] * 8), unit_cube()[1]),
    ("vertices", unit_cube()[0] > 0, unit_cube()[1]),
    ("faces", unit_cube()[0], unit_cube()[1] > 2),
    ("faces", unit_cube()[0], unit_cube()[1].astype(object)),
    ("vertices", [[0, 0, 0], [1, 0]], unit_cube()[1]),
])
def test_arrays_that_hold_no_real_numbers_are_refused(name, vertices, faces):
    with pytest.raises(somicage.InputError) as error:
        somicage.Cage(vertices, faces)
    assert error.value.source == name and error.value.problem.startswith("is not an array of")


def cli_range(option):
    """The range `somicage deform --help` gives for an option: 'in [0, 10]' -> (0.0, 10.0)."""
    result = run_cli("deform", "--help")
    line = next(line for line in result.stdout.splitlines() if line.strip().startswith(option + " "))
    low, high = re.search(r" in [\[(]([^,]+), ([^\])]+)[\])]", line).groups()
    return float(low), float(high)


def test_parameter_ranges_are_the_clis(cube_cage, cube_points):
    ranges = somicage.parameter_ranges()
    assert ranges["gamma"] == cli_range("--gamma") and ranges["nu"] == cli_range("--nu")
    assert ranges["gamma"][1] >= 5  # the editor's slider and the paper's values (up to 2) lie inside
    deformer = somicage.Deformer(cube_cage, cube_points)
    for gamma in (1e4, 1e6, np.nextafter(ranges["gamma"][1], np.inf)):
        with pytest.raises(somicage.InputError) as error:
            deformer.deform(cube_cage.vertices, gamma=gamma)
        assert error.value.source == "gamma" and "bug" not in str(error.value)


def test_gamma_beyond_the_range_has_the_clis_message(tmp_path, cube_cage, cube_points):
    cage, mesh = str(tmp_path / "cube.obj"), str(tmp_path / "points.obj")
    somicage.save_obj(cage, *unit_cube())
    somicage.save_obj(mesh, cube_points)
    deformer = somicage.Deformer(cube_cage, cube_points)
    for value in ("1e4", "1e6"):
        with pytest.raises(somicage.InputError) as error:
            deformer.deform(cube_cage.vertices, gamma=float(value))
        expected = cli_error("deform", "--cage", cage, "--posed", cage, "--mesh", mesh, "--out",
                             str(tmp_path / "o.obj"), "--gamma", value)
        assert "--" + str(error.value) == expected


def test_largest_gamma_stays_finite_under_a_face_turned_inside_out(cube_cage, cube_points):
    """At the largest gamma the normal stretch is at most exp(gamma) (core/deform/deformer.h): even a pose that pushes a
    corner through the cube (solid angles change by up to 4 pi) gives finite points, within exp(gamma) cage
    diameters of the cage."""
    gamma = somicage.parameter_ranges()["gamma"][1]
    posed = np.array(cube_cage.vertices)
    posed[7] = [0.2, 0.2, 0.2]  # the corner (1, 1, 1) pushed inside: its three faces fold inward
    moved = somicage.Deformer(cube_cage, cube_points).deform(posed, gamma=gamma, variant="local")
    assert np.isfinite(moved).all()
    assert np.abs(moved).max() <= np.exp(gamma) * np.sqrt(3) * 10


def cli_check(path):
    result = run_cli("check", "--cage", str(path), "--json")
    assert result.returncode in (0, 1), result.stderr
    return json.loads(result.stdout)


def cage_keys(report):
    """The keys of `check --json` about the cage: those before the mesh's (mesh_vertices ...), without "mesh"."""
    keys = list(report)
    return [k for k in keys[:keys.index("mesh_vertices")] if k != "mesh"]


def write_obj(path, vertices, faces):
    lines = [f"v {' '.join(repr(float(x)) for x in v)}" + (" 0.0" if len(v) == 2 else "") for v in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def cube_cages():
    vertices, faces = unit_cube()
    spike = np.vstack([vertices, [[0.5, 0.5, 1.6]]])
    spiked = np.vstack([faces, [[4, 5, 8], [5, 7, 8], [7, 6, 8], [6, 4, 8]]])  # a pyramid sharing cube corners
    fin = np.vstack([vertices, [[0.5, -0.5, 0.0]]])
    extra = np.vstack([vertices, vertices[3:4], [[0.5, 0.5, 0.5]]])  # a duplicate of vertex 3, an unused vertex
    return {
        "cube": (vertices, faces),
        "inside_out": (vertices, faces[:, ::-1]),
        "one_face_flipped": (vertices, np.vstack([faces[:5], faces[5:6, ::-1], faces[6:]])),
        "open": (vertices, faces[:-1]),
        "fin": (fin, np.vstack([faces, [[0, 1, 8]]])),
        "degenerate_duplicate_unused": (extra, np.vstack([faces, [[0, 1, 1]]])),
        "self_intersecting": (spike, spiked),
    }


def polygon_cages():
    star = star_polygon()
    n = len(star)
    loop = [[k, (k + 1) % n] for k in range(n)]
    bowtie = np.array([[0, 0], [1, 1], [1, 0], [0, 1]], dtype=float)
    return {"star": (star, loop), "clockwise_star": (star[::-1].copy(), loop),
            "bowtie": (bowtie, [[k, (k + 1) % 4] for k in range(4)])}


@pytest.mark.parametrize("name", list(cube_cages()) + list(polygon_cages()))
def test_check_is_the_clis_check_json(tmp_path, name):
    """Every cage key of `somicage check --json`, no other, with the same values: from the file and from arrays."""
    cli_executable()
    vertices, faces = {**cube_cages(), **polygon_cages()}[name]
    faces = np.asarray(faces, dtype=np.int64)
    path = write_obj(tmp_path / f"{name}.obj", vertices, [faces[:, 0]] if vertices.shape[1] == 2 else faces)
    expected = cli_check(path)
    keys = cage_keys(expected)
    assert {"boundary_edges", "non_manifold_edges", "misoriented_edges", "degenerate_faces", "duplicate_vertices",
            "unreferenced_vertices", "intersecting_face_pairs"} <= set(keys)
    from_file = somicage.check(path)
    assert list(from_file) == keys
    assert from_file == {k: expected[k] for k in keys}
    from_arrays = somicage.check(vertices, None if vertices.shape[1] == 2 else faces)
    assert from_arrays == {**from_file, "cage": "Cage(vertices, faces)"}


def test_check_reports_what_makes_each_cage_bad():
    """The counts themselves, from the constructions above (not from the code under test)."""
    reports = {name: somicage.check(v, f) for name, (v, f) in cube_cages().items()}
    assert reports["cube"]["valid"] and reports["cube"]["intersecting_face_pairs"] == 0
    assert reports["open"]["boundary_edges"] == 3 and not reports["open"]["usable"]
    assert reports["fin"]["non_manifold_edges"] == 1
    assert reports["one_face_flipped"]["misoriented_edges"] == 3 and reports["one_face_flipped"]["usable"]
    bad = reports["degenerate_duplicate_unused"]
    assert (bad["degenerate_faces"], bad["duplicate_vertices"], bad["unreferenced_vertices"]) == (1, 1, 2)
    assert reports["self_intersecting"]["intersecting_face_pairs"] > 0
    assert somicage.check(*polygon_cages()["bowtie"])["simple"] is False


def test_analyze_progress_reaches_one_and_false_cancels(cube_cage):
    points = np.random.default_rng(5).uniform(0.05, 0.95, size=(6000, 3))
    pose = cube_cage.vertices * 1.1
    fractions = []
    somicage.Deformer(cube_cage, points).analyze(pose, progress=fractions.append)
    assert fractions and fractions[-1] == 1.0 and all(0 <= f <= 1 for f in fractions)
    calls = []
    deformer = somicage.Deformer(cube_cage, points)
    with pytest.raises(somicage.Cancelled):
        deformer.analyze(pose, progress=lambda f: calls.append(f) or False)
    assert len(calls) == 1
    assert deformer.analyze(pose)["vertices"] == 6000  # a cancelled integration leaves nothing half-made


def test_analyze_honours_ctrl_c():
    """SIGINT 0.3 s into analyze's integration of J (about 1 s for 400,000 points on 2 cores) raises KeyboardInterrupt
    within 0.5 s of it."""
    out = run_isolated("""
        import os, signal, threading, time
        import numpy as np, somicage
        from conftest import unit_cube
        cage = somicage.Cage(*unit_cube())
        points = np.random.default_rng(6).uniform(0.05, 0.95, size=(400000, 3))
        deformer = somicage.Deformer(cage, points, float_storage=True)
        sent = []
        def interrupt():
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)
        threading.Timer(0.3, interrupt).start()
        start = time.monotonic()
        try:
            deformer.analyze(cage.vertices * 1.1)
            print("finished", time.monotonic() - start)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic() - sent[0])
        """)
    what, seconds = out.split()
    assert what == "interrupted" and float(seconds) < 0.5, out


def test_paths_may_be_pathlike(tmp_path, cube_cage):
    path = tmp_path / "cube.obj"
    somicage.save_obj(path, *unit_cube())
    assert somicage.Cage.from_obj(path).num_faces == 12
    vertices, faces = somicage.load_mesh(path)
    np.testing.assert_array_equal(somicage.load_posed(path, cube_cage), vertices)
    assert somicage.check(path)["cage"] == str(path) and somicage.check(path)["valid"]
    with pytest.raises(TypeError):
        somicage.load_mesh(12)


@pytest.mark.parametrize("name", ["x.ply", "x.glb", "x", "x.obj.tmp"])
def test_save_obj_refuses_another_format_name(tmp_path, name):
    with pytest.raises(somicage.InputError, match="save_obj writes OBJ text") as error:
        somicage.save_obj(tmp_path / name, *unit_cube())
    assert error.value.source == str(tmp_path / name) and not (tmp_path / name).exists()
    somicage.save_obj(tmp_path / "UPPER.OBJ", *unit_cube())  # the extension's case does not matter


def test_signatures_show_real_types():
    """help() shows what to pass, not pybind11's 'handle' or 'object'."""
    documented = [somicage.Cage.__init__, somicage.Cage.from_obj, somicage.Deformer.__init__, somicage.Deformer.deform,
                  somicage.Deformer.analyze, somicage.load_mesh, somicage.save_obj, somicage.load_posed,
                  somicage.check]
    for function in documented:
        signature = function.__doc__.splitlines()[0]
        assert "handle" not in signature and ": object" not in signature, signature
    assert "posed: numpy.typing.ArrayLike" in somicage.Deformer.deform.__doc__
    assert "progress: Optional[Callable[[float], Optional[bool]]]" in somicage.Deformer.analyze.__doc__
    assert "path: os.PathLike" in somicage.load_mesh.__doc__


def test_the_module_prints_nothing_and_its_warnings_can_go_to_logging():
    """Progress goes to progress= only; notices are SomiCageWarnings, which the standard filters silence and
    logging.captureWarnings routes (a pipeline's log, not the terminal)."""
    out = run_isolated("""
        import logging, sys, warnings
        import numpy as np, somicage
        from conftest import unit_cube
        vertices, faces = unit_cube()
        points = np.vstack([np.full((50, 3), 0.5), [[3.0, 0.5, 0.5]]])  # one point outside: a warning
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", somicage.SomiCageWarning)
            deformer = somicage.Deformer(somicage.Cage(vertices, faces[:, ::-1]), points)  # a repair: a warning
            deformer.analyze(vertices * 1.1)
        records = []
        handler = logging.Handler()
        handler.emit = records.append
        logging.getLogger("py.warnings").addHandler(handler)
        logging.captureWarnings(True)
        somicage.Deformer(somicage.Cage(vertices, faces), points)
        sys.stdout.write(str(len(records)) + " " + ("outside the cage" in records[0].getMessage()) * "outside")
        """, silent=True)
    assert out == "1 outside"
