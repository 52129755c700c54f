"""Deformer(method="phong", tet_level=N): the module tetrahedralizes the cage as the CLI's --tet-level does (it links
the tetrahedralization), so a cage that is not star-shaped needs no tets= file."""
import numpy as np
import pytest

import somicage

# A U extruded along z (arms up): not star-shaped from its centroid, which lies in the gap between the arms.
OUTLINE = [(0, 0), (3, 0), (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]
CAP = [(0, 1, 4), (1, 2, 4), (2, 3, 4), (0, 4, 5), (0, 5, 7), (5, 6, 7)]  # the U's 7 units of area, counter-clockwise


def u_cage():
    n = len(OUTLINE)
    vertices = np.array([(x, y, z) for z in (0.0, 1.0) for x, y in OUTLINE], dtype=float)
    faces = [(a, c, b) for a, b, c in CAP] + [(a + n, b + n, c + n) for a, b, c in CAP]
    for k in range(n):
        j = (k + 1) % n
        faces += [(k, j, j + n), (k, j + n, k + n)]
    return somicage.Cage(vertices, np.array(faces))


def arm_points(count=60, seed=3):
    """Points inside the U's two arms."""
    rng = np.random.default_rng(seed)
    points = rng.uniform([0.1, 0.1, 0.1], [0.9, 2.9, 0.9], size=(count, 3))
    points[count // 2:, 0] += 2.0
    return points


def test_method_info_lists_the_deformer_keywords_each_method_reads():
    options = {m["name"]: m["options"] for m in somicage.method_info()}
    assert options.pop("phong") == ["tets", "tet_level"]
    assert all(keywords == [] for keywords in options.values()), options


@pytest.mark.parametrize("level", [0, 1])
def test_tet_level_meshes_a_cage_that_is_not_star_shaped(level):
    # Phong reproduces every affine map (each F_t is the map's matrix): a closed form for any tetrahedral mesh.
    cage, points = u_cage(), arm_points()
    if level == 0:
        deformer = somicage.Deformer(cage, points, method="phong", tet_level=level)
    else:  # Mesh_3 (CGAL 5.5) leaves a hole in the U's boundary: TetGen's mesh is used, and the user is told
        with pytest.warns(somicage.SomiCageWarning, match="Mesh_3 made a mesh of the cage that does not keep"):
            deformer = somicage.Deformer(cage, points, method="phong", tet_level=level)
    A = np.array([[1.2, 0.3, 0.0], [-0.1, 0.8, 0.2], [0.1, 0.0, 1.1]])
    t = np.array([0.5, -1.0, 2.0])
    moved = deformer.deform(cage.vertices @ A.T + t, nu=0.3)
    diameter = np.linalg.norm(cage.vertices.max(axis=0) - cage.vertices.min(axis=0))
    assert np.abs(moved - (points @ A.T + t)).max() / diameter <= 1e-9


def test_each_level_is_its_own_mesh_and_a_bad_level_names_the_keyword():
    cage, points = u_cage(), arm_points()
    bent = cage.vertices.copy()
    bent[:, 2] += 0.3 * bent[:, 0] ** 2  # not affine: the Steiner vertices, so the points, depend on the mesh
    coarse = somicage.Deformer(cage, points, method="phong", tet_level=0).deform(bent, nu=0.3)
    with pytest.warns(somicage.SomiCageWarning, match="TetGen"):  # as at level 1 above
        fine = somicage.Deformer(cage, points, method="phong", tet_level=2).deform(bent, nu=0.3)
    assert np.abs(coarse - fine).max() > 1e-4
    with pytest.raises(somicage.InputError, match="tet_level"):
        somicage.Deformer(cage, points, method="phong", tet_level=9)
