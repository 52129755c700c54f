"""Properties every cage coordinate must have, checked through the Python module (2D and 3D, every method):
identity at rest, partition of unity (a translated cage translates the points), similarity invariance."""
import numpy as np
import pytest

import somicage
from conftest import random_rotation

DEFORM_SETTINGS = [dict(), dict(variant="local"), dict(nu=0.3, gamma=1.0, variant="local"), dict(nu=-0.5, blend=0.4),
                   dict(nu=float("inf"), traction_fix=False)]
# The options beyond the paper (issue 26), for the methods that read them: each variant, bulging convention and
# normal weighting at least once, at a high nu where the stable variant acts.
CHOICE_SETTINGS = [dict(variant="affine", nu=0.3, gamma=1.0, bulging="reference"),
                   dict(variant="stable", nu=0.45, gamma=1.0, normals="angle", bulging="swept-volume"),
                   dict(variant="local", gamma=1.0, bulging="polygon", normals="angle")]


def settings_for(method):
    """The settings a method accepts: Phong refuses nu = +-inf (its Steiner vertices' elastic energy is indefinite
    there; tests/core/phong_method_test.cpp checks the refusal). CHOICE_SETTINGS go to the methods that read them."""
    reads = next(m["parameters"] for m in somicage.method_info() if m["name"] == method)
    return ([s for s in DEFORM_SETTINGS if method != "phong" or abs(s.get("nu", 0.0)) != float("inf")] +
            [s for s in CHOICE_SETTINGS if all(keyword in reads for keyword in s)])


def diameter(vertices):
    return np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))


@pytest.mark.parametrize("method", somicage.methods())
@pytest.mark.parametrize("shape", ["cube", "star"])
def test_identity_at_rest(method, shape, request):
    cage = request.getfixturevalue(f"{shape}_cage")
    points = request.getfixturevalue(f"{shape}_points")
    deformer = somicage.Deformer(cage, points, method=method)
    for settings in settings_for(method):
        moved = deformer.deform(cage.vertices, **settings)
        assert moved.shape == points.shape and moved.dtype == np.float64
        error = np.abs(moved - points).max() / diameter(cage.vertices)
        assert error <= 1e-12, f"{method} {settings}: identity at rest off by {error:.2e} diameters"


@pytest.mark.parametrize("method", somicage.methods())
@pytest.mark.parametrize("shape", ["cube", "star"])
def test_translated_cage_translates_points(method, shape, request):
    cage = request.getfixturevalue(f"{shape}_cage")
    points = request.getfixturevalue(f"{shape}_points")
    shift = np.array([0.7, -1.3, 2.1][: cage.dim])
    moved = somicage.Deformer(cage, points, method=method).deform(cage.vertices + shift)
    error = np.abs(moved - (points + shift)).max() / diameter(cage.vertices)
    assert error <= 1e-12, f"{method}: translation reproduced to {error:.2e} diameters"


def test_somigliana_partition_of_unity_residual(cube_cage, cube_points):
    deformer = somicage.Deformer(cube_cage, cube_points)
    assert deformer.unity_residual.shape == (len(cube_points),)
    assert deformer.unity_residual.max() <= 1e-12  # Eq. 9, exact integrals
    np.testing.assert_allclose(deformer.winding, 1.0, atol=1e-12)  # every point is inside


@pytest.mark.parametrize("method", somicage.methods())
@pytest.mark.parametrize("shape", ["cube", "star"])
def test_similarity_invariance(method, shape, request):
    """x~ = s R x + t when the cage moves by the similarity x -> s R x + t, for every variant and parameter."""
    cage = request.getfixturevalue(f"{shape}_cage")
    points = request.getfixturevalue(f"{shape}_points")
    rotation, scale, shift = random_rotation(cage.dim, 5), 2.5, np.array([3.0, -1.0, 0.5][: cage.dim])
    posed = scale * cage.vertices @ rotation.T + shift
    expected = scale * points @ rotation.T + shift
    deformer = somicage.Deformer(cage, points, method=method)
    for settings in settings_for(method):
        error = np.abs(deformer.deform(posed, **settings) - expected).max() / diameter(posed)
        assert error <= 1e-11, f"{method} {settings}: similarity reproduced to {error:.2e} diameters"


def test_two_dimensional_cage_takes_xy_of_3d_points(star_cage, star_points):
    """Like `somicage deform`, a 2D cage deforms the x, y of (n, 3) points."""
    flat = somicage.Deformer(star_cage, star_points).deform(star_cage.vertices * 2)
    lifted = somicage.Deformer(star_cage, np.column_stack([star_points, np.ones(len(star_points))]))
    np.testing.assert_array_equal(lifted.deform(star_cage.vertices * 2), flat)
    np.testing.assert_allclose(flat, 2 * star_points, atol=1e-12)


@pytest.mark.parametrize("shape", ["cube", "star"])
@pytest.mark.parametrize("corotational", [False, True])
def test_bem_reproduces_affine_cage_motions(shape, corotational, request):
    """Linear elasticity with affine boundary displacement has the affine map as its exact interior solution (constant
    stress, constant traction per face), so the boundary element reference must reproduce any affine map."""
    cage = request.getfixturevalue(f"{shape}_cage")
    points = request.getfixturevalue(f"{shape}_points")
    d = cage.dim
    linear = np.eye(d) + np.random.RandomState(3).uniform(-0.3, 0.3, (d, d))
    shift = np.array([0.2, -0.4, 0.1][:d])
    deformer = somicage.Deformer(cage, points, method="bem")
    for nu in [-0.5, 0.0, 0.3, 0.45]:
        moved = deformer.deform(cage.vertices @ linear.T + shift, nu=nu, corotational=corotational)
        error = np.abs(moved - (points @ linear.T + shift)).max() / diameter(cage.vertices)
        assert error <= 1e-9, f"nu {nu}: affine map reproduced to {error:.2e} diameters"


@pytest.mark.parametrize("shape", ["cube", "star"])
def test_affine_variant_reproduces_affine_poses(shape, request):
    """variant="affine" (issue 26): the tractions of the best-fit affine map make the Somigliana identity reproduce
    any affine pose x -> A x + b, for every nu (the global variant, fitting a similarity, does not)."""
    cage = request.getfixturevalue(f"{shape}_cage")
    points = request.getfixturevalue(f"{shape}_points")
    d = cage.dim
    linear = np.eye(d) + np.random.RandomState(4).uniform(-0.3, 0.3, (d, d))
    shift = np.array([0.2, -0.4, 0.1][:d])
    posed, expected = cage.vertices @ linear.T + shift, points @ linear.T + shift
    deformer = somicage.Deformer(cage, points)
    for nu in [-0.5, 0.0, 0.3, 0.49, float("inf")]:
        error = np.abs(deformer.deform(posed, nu=nu, variant="affine") - expected).max() / diameter(posed)
        assert error <= 1e-9, f"nu {nu}: affine pose reproduced to {error:.2e} diameters"
    error = np.abs(deformer.deform(posed, nu=0.3) - expected).max() / diameter(posed)
    assert error > 1e-4, f"the global variant reproduces the pose too ({error:.2e}): the case tests nothing"
