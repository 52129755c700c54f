"""somicage.load_session reads a session with the reader the editor and `somicage animate` use (core/engine/session.h):
its inline cage, every parameter, the poses and the timeline; its frames deform to what `animate` writes. And the
module reads every mesh format `deform` reads (one loader)."""
import json
import subprocess

import numpy as np
import pytest

import somicage
from conftest import cli_executable, unit_cube

PYRAMID = "v 0.25 0.25 0.25\nv 0.75 0.25 0.25\nv 0.75 0.75 0.25\nv 0.25 0.75 0.25\nv 0.5 0.5 0.875\n" \
          "f 1 3 2\nf 1 4 3\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n"


def twist(vertices):
    """The top of the unit cube turned about its vertical axis, and the cube stretched upwards."""
    angle = 0.5 * vertices[:, 2]
    x, y = vertices[:, 0] - 0.5, vertices[:, 1] - 0.5
    return np.column_stack([0.5 + np.cos(angle) * x - np.sin(angle) * y, 0.5 + np.sin(angle) * x + np.cos(angle) * y,
                            1.25 * vertices[:, 2]])


@pytest.fixture
def session(tmp_path):
    vertices, faces = unit_cube()
    (tmp_path / "pyramid.obj").write_text(PYRAMID)
    text = {"format": "somicage-session", "version": 3, "mesh": "pyramid.obj", "cage": "",
            "restCage": {"vertices": vertices.tolist(), "faces": faces.tolist()}, "method": "bem",
            "params": {"blend": 0, "nu": 0.3, "gamma": 0, "tractionCorrection": True, "corotational": True},
            "poses": [{"name": "rest", "vertices": vertices.tolist()},
                      {"name": "twist", "vertices": twist(vertices).tolist()}],
            "timeline": {"fps": 24, "first": 0, "last": 4, "loop": False, "interpolation": "linear",
                         "keys": [{"frame": 0, "pose": "rest", "nu": 0.2}, {"frame": 4, "pose": "twist", "nu": 0.4}]}}
    path = tmp_path / "s.json"
    path.write_text(json.dumps(text))
    return path


def test_load_session_reads_every_part(session):
    s = somicage.load_session(str(session))
    vertices, faces = unit_cube()
    assert s["mesh"] == str(session.parent / "pyramid.obj"), "resolved next to the session"
    assert s["method"] == "bem" and s["cage_path"] == "" and s["tets"] == ""
    np.testing.assert_array_equal(s["cage"].vertices, vertices)
    # Every keyword of Deformer.deform (the parameter table's rows): variant, bulging and normals were missing, so a
    # session of the affine variant or another bulging deformed as the default one.
    assert s["params"] == dict(variant="global", blend=0.0, nu=0.3, gamma=0.0, traction_fix=True, corotational=True,
                               bulging="solid-angle", normals="area")
    assert s["pose"] is None and sorted(s["poses"]) == ["rest", "twist"]
    assert s["timeline"]["keys"][1] == dict(frame=4.0, pose="twist", nu=0.4, gamma=None)
    # Linear keys: frame 2 is the mean pose and the mean nu, computed here independently of the engine.
    assert len(s["frames"]) == 5
    pose, params = s["frames"][2]
    np.testing.assert_allclose(pose, 0.5 * vertices + 0.5 * twist(vertices), rtol=0, atol=1e-15)
    assert params["nu"] == pytest.approx(0.3, abs=1e-15) and params["corotational"]


def test_session_frames_deform_to_what_animate_writes(session, tmp_path):
    out = tmp_path / "seq"
    result = subprocess.run([cli_executable(), "animate", "--session", str(session), "--out", f"{out}/"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    s = somicage.load_session(str(session))
    points, _ = somicage.load_mesh(s["mesh"])
    deformer = somicage.Deformer(s["cage"], points, method=s["method"])
    for frame, (pose, params) in enumerate(s["frames"]):
        written, _ = somicage.load_mesh(str(out / f"pyramid_{frame:04d}.obj"))
        assert np.abs(deformer.deform(pose, **params) - written).max() <= 1e-9 * np.sqrt(3), frame


def test_a_phong_sessions_tetrahedra_are_found_next_to_it(session):
    """"methodOptions" {"tets": NAME}: load_session gives the file as animate finds it (next to the session), for
    Deformer(tets=); a Deformer on it differs from one on the cube's default star, so the file is the one read."""
    text = json.loads(session.read_text())
    text.update(method="phong", methodOptions={"tets": "cube.mesh"})
    vertices, faces = unit_cube()
    lines = ["MeshVersionFormatted 2", "Dimension 3", "Vertices", "9"]
    lines += [" ".join(map(str, v)) + " 0" for v in vertices] + ["0.6 0.45 0.55 0", "Tetrahedra", str(len(faces))]
    lines += [f"{a + 1} {c + 1} {b + 1} 9 0" for a, b, c in faces] + ["End"]  # outward faces, apex inside: positive
    (session.parent / "cube.mesh").write_text("\n".join(lines) + "\n")
    session.write_text(json.dumps(text))
    s = somicage.load_session(str(session))
    assert s["method"] == "phong" and s["tets"] == str(session.parent / "cube.mesh")
    points, _ = somicage.load_mesh(s["mesh"])
    pose, params = s["frames"][4]
    given = somicage.Deformer(s["cage"], points, method="phong", tets=s["tets"]).deform(pose, **params)
    star = somicage.Deformer(s["cage"], points, method="phong").deform(pose, **params)
    assert np.abs(given - star).max() > 1e-3


def test_a_file_that_is_not_a_session_is_refused(tmp_path):
    path = tmp_path / "x.json"
    path.write_text('{"format": "something-else", "version": 3}')
    with pytest.raises(somicage.InputError, match="not a SomiCage session"):
        somicage.load_session(str(path))


def test_every_format_reads_as_obj(tmp_path):
    """PLY and OFF (shared vertices) as they are, STL (a vertex per corner) with weld, give the OBJ's numbers."""
    (tmp_path / "m.obj").write_text(PYRAMID)
    points, faces = somicage.load_mesh(str(tmp_path / "m.obj"))
    rows = "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in points)
    (tmp_path / "m.off").write_text(f"OFF\n5 {len(faces)} 0\n{rows}" + "".join(f"3 {a} {b} {c}\n" for a, b, c in faces))
    (tmp_path / "m.ply").write_text(
        f"ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
        f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n{rows}"
        + "".join(f"3 {a} {b} {c}\n" for a, b, c in faces))
    for ext in ("off", "ply"):
        read, read_faces = somicage.load_mesh(str(tmp_path / f"m.{ext}"))
        np.testing.assert_array_equal(read, points, err_msg=ext)
        assert read_faces == faces, ext
    vertices, cube_faces = unit_cube()
    stl = "solid c\n" + "".join("facet normal 0 0 0\nouter loop\n" + "".join(
        f"vertex {x!r} {y!r} {z!r}\n" for x, y, z in vertices[list(f)]) + "endloop\nendfacet\n" for f in cube_faces)
    (tmp_path / "c.stl").write_text(stl + "endsolid c\n")
    cage = somicage.Cage.from_obj(str(tmp_path / "c.stl"), weld=True)
    assert cage.num_vertices == 8 and cage.num_faces == 12
    assert somicage.check(str(tmp_path / "c.stl"))["cage_vertices"] == 36, "without weld: one vertex per corner"
