"""Deformer.analyze, the facade's "deform to quantities" (core/engine/engine.h: analyzePose): the numbers of
`somicage analyze --json` (the same keys, the same values to 1e-12 relative), and checked independently: the volume
change is the signed volume of Deformer.deform's output (NumPy) over the rest volume, and a similarity s R x + t has
det J = s^3, no distortion and area ratios s^2 for every method."""
import json

import numpy as np
import pytest

import somicage
from conftest import FIREHYDRANT, cli_executable, random_rotation, require_firehydrant, unit_cube
from test_front_ends import run_cli

SWEEP = (-0.5, 0.45, 3)


def sphere_mesh(center=0.5, radius=0.3, levels=2):
    """A closed, outward triangle mesh: an octahedron subdivided `levels` times, projected on a sphere."""
    vertices = [np.array(v, dtype=float) for v in
                ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1))]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(levels):
        middle, refined = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                vertices.append((vertices[a] + vertices[b]) / 2)
                middle[key] = len(vertices) - 1
            return middle[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            refined += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = refined
    v = np.array([p / np.linalg.norm(p) for p in vertices]) * radius + center
    return v, [list(f) for f in faces]


def signed_volume(vertices, faces):
    """Sum of the tetrahedra (origin, a, b, c) over the faces, fan-triangulated from their first corner."""
    total = 0.0
    for face in faces:
        for k in range(1, len(face) - 1):
            total += np.linalg.det(vertices[[face[0], face[k], face[k + 1]]]) / 6
    return total


def bent_cube_pose(cage):
    """A pose that is not a similarity (nor affine): a shear-stretch and one corner pulled out."""
    pose = cage.vertices @ np.array([[1.2, 0.3, 0.0], [0.0, 0.9, 0.2], [0.1, 0.0, 1.1]]).T
    pose[7] += [0.2, 0.1, -0.15]
    return pose


def assert_same_numbers(python, cli, where="analyze"):
    """Python's dict against the CLI's JSON: the same keys in the same order; numbers to 1e-12 relative; JSON's
    null where Python has None or a number that is not finite (the CLI writes those as null)."""
    if isinstance(cli, dict):
        assert list(python) == list(cli), f"{where}: keys {list(python)} != {list(cli)}"
        for key in cli:
            assert_same_numbers(python[key], cli[key], f"{where}.{key}")
    elif isinstance(cli, list):
        assert len(python) == len(cli), where
        for k, (p, c) in enumerate(zip(python, cli)):
            assert_same_numbers(p, c, f"{where}[{k}]")
    elif cli is None:
        assert python is None or not np.isfinite(python), f"{where}: {python} where the CLI has null"
    elif isinstance(cli, (bool, str)):
        assert python == cli, f"{where}: {python!r} != {cli!r}"
    else:
        assert python == pytest.approx(cli, rel=1e-12, abs=1e-300), f"{where}: {python!r} != {cli!r}"


def cli_analyze(rest, posed, mesh, *flags):
    result = run_cli("analyze", "--cage", rest, "--posed", posed, "--mesh", mesh, "--json", *flags)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


@pytest.fixture
def cube_files(tmp_path):
    """The unit cube cage, its bent pose and a closed sphere mesh inside, as OBJ files and arrays."""
    cage_vertices, cage_faces = unit_cube()
    cage = somicage.Cage(cage_vertices, cage_faces)
    mesh_vertices, mesh_faces = sphere_mesh()
    paths = {name: str(tmp_path / f"{name}.obj") for name in ("rest", "posed", "mesh")}
    somicage.save_obj(paths["rest"], cage_vertices, cage_faces.tolist())
    somicage.save_obj(paths["posed"], bent_cube_pose(cage), cage_faces.tolist())
    somicage.save_obj(paths["mesh"], mesh_vertices, mesh_faces)
    return dict(paths, cage=cage, points=mesh_vertices, faces=mesh_faces)


@pytest.mark.parametrize("method", somicage.methods())
def test_analyze_matches_cli_on_a_small_shape(cube_files, method):
    cli_executable()
    flags = ["--method", method, "--nu", "0.3", "--gamma", "1", "--variant", "local",
             "--nu-sweep", ":".join(map(str, SWEEP))]
    expected = cli_analyze(cube_files["rest"], cube_files["posed"], cube_files["mesh"], *flags)
    deformer = somicage.Deformer(cube_files["cage"], cube_files["points"], method=method)
    analysis = deformer.analyze(bent_cube_pose(cube_files["cage"]), cube_files["faces"], nu=0.3, gamma=1.0,
                                variant="local", nu_sweep=SWEEP)
    assert analysis["closed"] and len(analysis["nu_sweep"]) == SWEEP[2]
    assert_same_numbers(analysis, expected)


@pytest.mark.parametrize("method", ["somigliana", "phong"])  # every method's 0 or not: tests/core/seam_jumps_test.cpp
def test_seam_jump_matches_analyze_seams(cube_files, method):
    """seams=True is analyze --seams: the same seam_jump over the cube's star; 0 for a smooth method (one J), more for
    Phong (C0 across the tetrahedra); seams=False leaves the key out, as analyze does for a smooth method."""
    cli_executable()
    expected = cli_analyze(cube_files["rest"], cube_files["posed"], cube_files["mesh"], "--method", method,
                           "--nu", "0.3", "--seams")
    deformer = somicage.Deformer(cube_files["cage"], cube_files["points"], method=method)
    pose = bent_cube_pose(cube_files["cage"])
    analysis = deformer.analyze(pose, cube_files["faces"], nu=0.3, seams=True)
    assert_same_numbers(analysis, expected)
    if method == "phong":
        assert analysis["seam_jump"]["max"] > 1e-2
    else:
        assert analysis["seam_jump"]["max"] <= 1e-12
    assert "seam_jump" not in deformer.analyze(pose, cube_files["faces"], nu=0.3, seams=False)


def test_analyze_matches_cli_on_firehydrant():
    require_firehydrant()
    cli_executable()
    rest, posed = (str(FIREHYDRANT / name) for name in ("fireHydrant_cages_triangulated.obj",
                                                        "fireHydrant_cages_triangulated_deformed.obj"))
    mesh = str(FIREHYDRANT / "fireHydrant.obj")
    expected = cli_analyze(rest, posed, mesh, "--nu", "0.3", "--gamma", "1", "--variant", "local",
                           "--nu-sweep", "0:0.45:2")
    cage = somicage.Cage.from_obj(rest)
    points, faces = somicage.load_mesh(mesh)
    analysis = somicage.Deformer(cage, points).analyze(somicage.load_posed(posed, cage), faces, nu=0.3, gamma=1.0,
                                                       variant="local", nu_sweep=(0.0, 0.45, 2))
    assert_same_numbers(analysis, expected)


def test_volume_change_is_the_signed_volume_of_the_deformed_mesh(cube_files):
    deformer = somicage.Deformer(cube_files["cage"], cube_files["points"])
    pose, faces = bent_cube_pose(cube_files["cage"]), cube_files["faces"]
    analysis = deformer.analyze(pose, faces, nu=0.3, gamma=1.0, variant="local", nu_sweep=SWEEP)
    rest = signed_volume(cube_files["points"], faces)
    deformed = signed_volume(deformer.deform(pose, nu=0.3, gamma=1.0, variant="local"), faces)
    assert analysis["volume_rest"] == pytest.approx(rest, rel=1e-12)
    assert analysis["volume_deformed"] == pytest.approx(deformed, rel=1e-12)
    assert analysis["volume_change"] == pytest.approx(deformed / rest - 1, abs=1e-12)
    assert abs(analysis["volume_change"]) > 1e-2  # the pose changes the volume: the check is not 0 == 0
    for entry in analysis["nu_sweep"]:
        swept = signed_volume(deformer.deform(pose, nu=entry["nu"], gamma=1.0, variant="local"), faces)
        assert entry["volume_change"] == pytest.approx(swept / rest - 1, abs=1e-12), entry


@pytest.mark.parametrize("method", somicage.methods())
def test_similarity_has_closed_form_quantities(cube_files, method):
    scale = 1.7
    pose = scale * cube_files["cage"].vertices @ random_rotation(3, 4).T + [0.3, -2.0, 1.0]
    analysis = somicage.Deformer(cube_files["cage"], cube_files["points"], method=method).analyze(
        pose, cube_files["faces"])
    for value in analysis["jacobian_det"].values():
        assert value == pytest.approx(scale ** 3, rel=1e-9)
    for value in analysis["conformal_distortion"].values():
        assert value == pytest.approx(1.0, abs=1e-9)
    for value in analysis["area_ratio"].values():
        assert value == pytest.approx(scale ** 2, rel=1e-9)
    assert analysis["volume_change"] == pytest.approx(scale ** 3 - 1, rel=1e-9)
    assert analysis["foldover_vertices"] == 0 and analysis["outside_points"] == 0


def test_analyze_errors_name_the_keyword(cube_files):
    deformer = somicage.Deformer(cube_files["cage"], cube_files["points"])
    with pytest.raises(somicage.InputError, match=r"^faces: face 0 refers to vertex 999 of 66"):
        deformer.analyze(cube_files["cage"].vertices, [[0, 1, 999]])
    with pytest.raises(somicage.InputError, match=r"^nu_sweep: the sweep"):
        deformer.analyze(cube_files["cage"].vertices, nu_sweep=(0.0, 0.7, 3))
    with pytest.raises(somicage.InputError, match=r"^posed: the posed cage has 7 vertices"):
        deformer.analyze(cube_files["cage"].vertices[:7])


def test_analyze_integrates_the_gradients_once_per_deformer(cube_files):
    """Issue 27: the exact J's gradients are kept with the coordinates (CageDeformer::gradients): analyze at other
    poses and parameters reuses them (what it returns is still that pose's: the volume change of the deformed mesh),
    and a Deformer of other points integrates its own."""
    deformer = somicage.Deformer(cube_files["cage"], cube_files["points"])
    faces = cube_files["faces"]
    assert deformer.gradient_integrations == 0, "lazy: nothing before analyze"
    rest = signed_volume(cube_files["points"], faces)
    for pose, settings in ((bent_cube_pose(cube_files["cage"]), {"nu": 0.3}),
                           (1.1 * cube_files["cage"].vertices, {"nu": 0.45, "gamma": 1.0, "variant": "local"}),
                           (bent_cube_pose(cube_files["cage"]) + 0.05, {"nu": 0.0, "variant": "affine"})):
        analysis = deformer.analyze(pose, faces, **settings)
        deformed = signed_volume(deformer.deform(pose, **settings), faces)
        assert analysis["volume_change"] == pytest.approx(deformed / rest - 1, abs=1e-12), settings
        if settings.get("variant") == "local":  # the uniform scale by 1.1: det J = 1.1^3 from the kept gradients
            assert all(v == pytest.approx(1.1 ** 3, rel=1e-9) for v in analysis["jacobian_det"].values())
    assert deformer.gradient_integrations == 1, "three poses and parameter sets, one integration"
    other = somicage.Deformer(cube_files["cage"], 0.9 * cube_files["points"] + 0.05)
    other.analyze(bent_cube_pose(cube_files["cage"]), faces)
    assert other.gradient_integrations == 1 and deformer.gradient_integrations == 1
