"""The module against the command line (an independent front end over the same engine): the same deformation of
FIREHYDRANT as `somicage deform`, and the same error messages for the same bad input."""
import subprocess

import numpy as np
import pytest

import somicage
from conftest import FIREHYDRANT, cli_executable, require_firehydrant, unit_cube


def run_cli(*args):
    return subprocess.run([cli_executable(), *args], capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def firehydrant():
    """FIREHYDRANT's cage, mesh points, pose and one Somigliana deformer (one precompute for the module)."""
    require_firehydrant()
    rest, posed = FIREHYDRANT / "fireHydrant_cages_triangulated.obj", FIREHYDRANT / "fireHydrant_cages_triangulated_deformed.obj"
    cage = somicage.Cage.from_obj(str(rest))
    points, _ = somicage.load_mesh(str(FIREHYDRANT / "fireHydrant.obj"))
    return dict(rest=str(rest), posed=str(posed), cage=cage, deformer=somicage.Deformer(cage, points),
                pose=somicage.load_posed(str(posed), cage))


@pytest.mark.parametrize("settings,flags", [(dict(), []),
                                            (dict(nu=0.3, gamma=1.0, variant="local"),
                                             ["--nu", "0.3", "--gamma", "1", "--variant", "local"])])
def test_firehydrant_matches_cli(tmp_path, firehydrant, settings, flags):
    out = tmp_path / "out.obj"
    result = run_cli("deform", "--cage", firehydrant["rest"], "--posed", firehydrant["posed"], "--mesh",
                     str(FIREHYDRANT / "fireHydrant.obj"), "--out", str(out), *flags)
    assert result.returncode == 0, result.stderr
    expected, _ = somicage.load_mesh(str(out))  # %.17g: the CLI's doubles exactly
    moved = firehydrant["deformer"].deform(firehydrant["pose"], **settings)
    vertices = firehydrant["cage"].vertices
    error = np.abs(moved - expected).max() / np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))
    assert error <= 1e-12, f"module and CLI differ by {error:.2e} cage diameters"
    # Both front ends drive one engine, so agreeing proves the binding, not the numbers. Independent of the engine:
    # Somigliana coordinates are similarity-invariant (any variant, nu, gamma), so the pose moved by a similarity S
    # (scale 1.5, a rotation, a translation) gives S of the CLI's output.
    angle = 0.7
    rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
    similarity = lambda x: 1.5 * x @ rotation.T + np.array([0.3, -2.0, 5.0])  # noqa: E731
    turned = firehydrant["deformer"].deform(similarity(firehydrant["pose"]), **settings)
    error = np.abs(turned - similarity(expected)).max() / np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))
    assert error <= 1e-8, f"a similarity of the pose moves the mesh {error:.2e} cage diameters off S(deformed)"


def test_points_outside_warn(cube_cage, cube_points):
    outside = np.vstack([cube_points, [[2.0, 0.5, 0.5]]])
    with pytest.warns(somicage.SomiCageWarning, match="1 of 201 points lie outside the cage"):
        deformer = somicage.Deformer(cube_cage, outside)
    assert deformer.exterior_count == 1 and deformer.winding[-1] == pytest.approx(0, abs=1e-12)


def cli_error(*args):
    """The CLI's message without its 'somicage COMMAND: ' prefix."""
    result = run_cli(*args)
    assert result.returncode == 2, result.stderr
    line = result.stderr.strip().splitlines()[-1]
    return line.split(": ", 1)[1]


def write(path, text):
    path.write_text(text)
    return str(path)


def test_missing_file_message_matches_cli(tmp_path):
    missing = str(tmp_path / "nope.obj")
    with pytest.raises(somicage.InputError) as error:
        somicage.Cage.from_obj(missing)
    assert str(error.value) == cli_error("check", "--cage", missing)
    assert error.value.source == missing and isinstance(error.value, ValueError)


def test_bad_face_message_matches_cli(tmp_path):
    cage = write(tmp_path / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 9\n")
    with pytest.raises(somicage.InputError) as error:
        somicage.Cage.from_obj(cage)
    assert str(error.value) == cli_error("check", "--cage", cage)
    assert error.value.line == 6


def test_open_cage_message_matches_cli(tmp_path):
    vertices, faces = unit_cube()
    text = "".join(f"v {x} {y} {z}\n" for x, y, z in vertices) + "".join(
        f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces[:-1])  # one triangle missing: a hole
    cage = write(tmp_path / "open.obj", text)
    mesh = write(tmp_path / "points.obj", "v 0.5 0.5 0.5\n")
    expected = cli_error("deform", "--cage", cage, "--posed", cage, "--mesh", mesh, "--out", str(tmp_path / "o.obj"))
    with pytest.raises(somicage.InputError, match="hole") as error:
        somicage.Cage.from_obj(cage)
    assert str(error.value) == expected
    with pytest.raises(somicage.InputError) as from_arrays:
        somicage.Cage(vertices, faces[:-1])
    assert from_arrays.value.problem == error.value.problem


def test_parameter_messages_match_cli(tmp_path, cube_cage, cube_points):
    cage = write(tmp_path / "cube.obj", "".join(f"v {x} {y} {z}\n" for x, y, z in cube_cage.vertices) +
                 "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in cube_cage.faces))
    mesh = write(tmp_path / "points.obj", "v 0.5 0.5 0.5\n")
    common = ["deform", "--cage", cage, "--posed", cage, "--mesh", mesh, "--out", str(tmp_path / "o.obj")]
    deformer = somicage.Deformer(cube_cage, cube_points)
    for keyword, value, flag in [("nu", 0.7, "0.7"), ("gamma", -1.0, "-1"), ("blend", 2.0, "2")]:
        with pytest.raises(somicage.InputError) as error:
            deformer.deform(cube_cage.vertices, **{keyword: value})
        # The CLI names the option (--nu), the module the keyword (nu); the rest is the same.
        assert "--" + str(error.value) == cli_error(*common, "--" + keyword, flag)
    with pytest.raises(somicage.InputError) as error:
        somicage.Deformer(cube_cage, cube_points, method="harmonic")
    assert "--" + str(error.value) == cli_error(*common, "--method", "harmonic")


def test_array_input_errors_name_the_argument(cube_cage, cube_points):
    with pytest.raises(somicage.InputError, match=r"^points: has shape \(200,\)"):
        somicage.Deformer(cube_cage, cube_points[:, 0])
    with pytest.raises(somicage.InputError, match=r"^points: row 3 is not finite"):
        somicage.Deformer(cube_cage, np.where(np.arange(200)[:, None] == 3, np.nan, cube_points))
    with pytest.raises(somicage.InputError, match=r"^posed: the posed cage has 7 vertices, the rest cage has 8"):
        somicage.Deformer(cube_cage, cube_points).deform(cube_cage.vertices[:7])
    with pytest.raises(somicage.InputError, match=r"^faces: is not an array of integers"):
        somicage.Cage(cube_cage.vertices, cube_cage.faces.astype(float))
    with pytest.raises(somicage.InputError, match=r"^variant: 'wide' is not a choice \(use global, local, affine or stable\)"):
        somicage.Deformer(cube_cage, cube_points).deform(cube_cage.vertices, variant="wide")


def test_repair_and_check(cube_cage):
    inside_out = cube_cage.faces[:, ::-1].copy()
    report = somicage.check(np.array(cube_cage.vertices), inside_out)
    assert not report["valid"] and not report["outward"] and report["usable"]
    assert report["repairs"] and report["signed_volume"] == pytest.approx(-1.0, abs=1e-12)
    with pytest.warns(somicage.SomiCageWarning, match="note: Cage"):
        repaired = somicage.Cage(cube_cage.vertices, inside_out)
    assert repaired.repairs == report["repairs"]
    np.testing.assert_array_equal(np.sort(repaired.faces, axis=1), np.sort(cube_cage.faces, axis=1))
    assert somicage.check(np.array(cube_cage.vertices), cube_cage.faces)["valid"]


def test_save_obj_round_trip_and_errors(tmp_path, cube_cage):
    path = str(tmp_path / "cube.obj")
    vertices = cube_cage.vertices * np.pi  # digits that only %.17g keeps
    somicage.save_obj(path, vertices, cube_cage.faces.tolist())
    read, faces = somicage.load_mesh(path)
    np.testing.assert_array_equal(read, vertices)
    assert faces == cube_cage.faces.tolist()
    with pytest.raises(somicage.InputError, match="face 0 refers to vertex 99 of 8"):
        somicage.save_obj(str(tmp_path / "bad.obj"), vertices, [[0, 1, 99]])
    assert not (tmp_path / "bad.obj").exists()  # nothing written on failure


def test_points_outside_warn_in_the_cli_words(tmp_path, cube_cage, cube_points):
    """Both front ends show the engine's one notice (engine.h: exteriorPointsNotice), each naming its own source."""
    outside = np.vstack([cube_points, [[2.0, 0.5, 0.5]]])
    cage_path, mesh_path = str(tmp_path / "cage.obj"), str(tmp_path / "points.obj")
    somicage.save_obj(cage_path, *unit_cube())
    somicage.save_obj(mesh_path, outside)
    result = run_cli("deform", "--cage", cage_path, "--posed", cage_path, "--mesh", mesh_path,
                     "--out", str(tmp_path / "out.obj"))
    assert result.returncode == 0, result.stderr
    cli = [line for line in result.stderr.splitlines() if "lie outside" in line]
    prefix = f"somicage: warning: {mesh_path}: "
    assert len(cli) == 1 and cli[0].startswith(prefix + "1 of 201 points lie outside the cage"), result.stderr
    with pytest.warns(somicage.SomiCageWarning) as caught:
        somicage.Deformer(cube_cage, outside)
    python = [str(w.message) for w in caught if "lie outside" in str(w.message)]
    assert python == ["warning: points: " + cli[0][len(prefix):]]


# The CLI's options that set a method's parameters, and the Deformer.deform keywords that set the same ones.
CLI_PARAMETER_OPTIONS = {"--variant": ["variant", "blend"], "--nu": ["nu"], "--gamma": ["gamma"],
                         "--no-traction-fix": ["traction_fix"], "--corotational": ["corotational"],
                         "--bulging": ["bulging"], "--normals": ["normals"]}


def methods_reading(help_line):
    """The methods an option's help line says read it: '...; somigliana only', '...; somigliana and bem'."""
    readers = help_line.rsplit("; ", 1)[1].strip()
    if readers == "no method":
        return set()
    return set(readers.removesuffix(" only").replace(" and ", ", ").split(", "))


def test_method_info_matches_cli_help():
    """method_info() is the registry as `somicage deform --help` shows it: the --method list in order, each method's
    display name and description, and which options (here: keywords) it reads."""
    result = run_cli("deform", "--help")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    option = {line.split()[0]: line for line in lines if line.startswith("  --")}
    names = option["--method"].split("NAME", 1)[1].split("(default")[0].strip().replace(" or ", ", ").split(", ")
    described = {}
    for line in lines[lines.index("methods (--method):") + 1:]:
        name, text = line.strip().split("  ", 1)
        display_name, description = text.strip().split(": ", 1)
        described[name] = dict(display_name=display_name, description=description)
    info = somicage.method_info()
    assert [m["name"] for m in info] == names == somicage.methods() and len(names) >= 4
    for m in info:
        assert {k: m[k] for k in ("display_name", "description")} == described[m["name"]], m["name"]
        read = [keyword for flag, keywords in CLI_PARAMETER_OPTIONS.items() if m["name"] in methods_reading(option[flag])
                for keyword in keywords]
        assert sorted(m["parameters"]) == sorted(read), m["name"]


def test_choice_info_matches_cli_help():
    """choice_info() is the table `somicage deform --help` lists as --bulging and --normals: values, default first."""
    result = run_cli("deform", "--help")
    assert result.returncode == 0, result.stderr
    option = {line.split()[0]: line for line in result.stdout.splitlines() if line.startswith("  --")}
    for choice in somicage.choice_info():
        line = option["--" + choice["name"]]
        listed = line.split(": ", 1)[1].split(" (default")[0].replace(" or ", ", ").split(", ")
        assert listed == [value[0] for value in choice["values"]], line
        assert f"(default {choice['values'][0][0]})" in line


def test_methods_ignore_the_keywords_method_info_leaves_out(cube_cage, cube_points):
    """A keyword a method does not list in method_info() leaves its deformation bit for bit as it was."""
    pose = cube_cage.vertices @ np.array([[1.2, 0.3, 0.0], [0.0, 0.9, 0.2], [0.1, 0.0, 1.1]]).T
    pose[7] += [0.2, 0.1, -0.15]  # not affine either
    changed = dict(nu=0.3, gamma=1.0, variant="local", blend=0.5, traction_fix=False, corotational=True,
                   bulging="reference", normals="angle")
    for m in somicage.method_info():
        deformer = somicage.Deformer(cube_cage, cube_points, method=m["name"])
        base = deformer.deform(pose)
        for keyword, value in changed.items():
            if keyword not in m["parameters"]:
                np.testing.assert_array_equal(deformer.deform(pose, **{keyword: value}), base,
                                              err_msg=f"{m['name']} reads {keyword}")
        if "nu" in m["parameters"]:
            assert np.abs(deformer.deform(pose, nu=0.3) - base).max() > 1e-6, f"{m['name']} ignores nu"
