"""Shared set-up for the somicage module tests: small analytic cages and the shared models.

ctest runs these with PYTHONPATH=build/python, SOMICAGE_CLI (the somicage executable) and SOMICAGE_MODELS_DIR.
"""
import os
import pathlib

import numpy as np
import pytest

import somicage

MODELS_DIR = pathlib.Path(os.environ.get("SOMICAGE_MODELS_DIR", pathlib.Path(__file__).parents[3] / "shared/models"))
FIREHYDRANT = MODELS_DIR / "firehydrant"


def unit_cube():
    """The unit cube as 12 outward triangles (counter-clockwise seen from outside)."""
    vertices = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    faces = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))], dtype=np.int64)
    return vertices, faces


def star_polygon(points=7):
    """A counter-clockwise star (a non-convex simple polygon) around the origin."""
    angles = np.arange(2 * points) * np.pi / points
    radii = np.where(np.arange(2 * points) % 2 == 0, 1.0, 0.55)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


@pytest.fixture
def cube_cage():
    return somicage.Cage(*unit_cube())


@pytest.fixture
def cube_points():
    return np.random.default_rng(1).uniform(0.1, 0.9, size=(200, 3))


@pytest.fixture
def star_cage():
    return somicage.Cage(star_polygon())


@pytest.fixture
def star_points():
    """Points well inside the star: within the radius of its inner vertices' incircle."""
    rng = np.random.default_rng(2)
    radius, angle = 0.4 * np.sqrt(rng.uniform(size=150)), rng.uniform(0, 2 * np.pi, size=150)
    return np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])


def random_rotation(dim, seed):
    q, r = np.linalg.qr(np.random.default_rng(seed).normal(size=(dim, dim)))
    q = q @ np.diag(np.sign(np.diag(r)))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return q


def require_firehydrant():
    if not (FIREHYDRANT / "fireHydrant.obj").exists():
        pytest.skip(f"shared model FIREHYDRANT not found in {FIREHYDRANT} (set SOMICAGE_MODELS_DIR)")


def cli_executable():
    path = os.environ.get("SOMICAGE_CLI")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("the somicage executable is not given (SOMICAGE_CLI)")
    return path


def pytest_sessionfinish(session, exitstatus):
    """Under ctest (SOMICAGE_SKIP_RETURN_CODE set), a run whose tests passed but some skipped (models or the CLI
    absent) exits with that code, so that ctest reports the file as skipped instead of passed."""
    skip_code = os.environ.get("SOMICAGE_SKIP_RETURN_CODE")
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    if skip_code and exitstatus == 0 and reporter is not None and reporter.stats.get("skipped"):
        session.exitstatus = int(skip_code)
