"""How the module behaves around the computation: progress and cancel, the GIL, thread counts, and which arrays
cross the boundary without a copy."""
import sys
import threading

import numpy as np
import pytest

import somicage


@pytest.fixture(scope="module")
def many_points():
    """Enough points for a precompute of a good fraction of a second."""
    return np.random.default_rng(3).uniform(0.05, 0.95, size=(20000, 3))


def test_progress_is_throttled_and_reaches_one(cube_cage, many_points):
    fractions = []
    somicage.Deformer(cube_cage, many_points, progress=fractions.append)
    assert fractions and fractions[-1] == 1.0
    assert all(0 <= a <= b <= 1 for a, b in zip(fractions, fractions[1:]))
    assert len(fractions) < 1000  # one call per 0.1 s at most, plus the end: never one per point


def test_progress_returning_false_cancels(cube_cage, many_points):
    calls = []
    with pytest.raises(somicage.Cancelled, match="cancelled by the user"):
        somicage.Deformer(cube_cage, many_points, progress=lambda f: calls.append(f) or False)
    assert len(calls) == 1


@pytest.mark.parametrize("raised", [KeyboardInterrupt, ZeroDivisionError])
def test_exception_in_progress_stops_and_propagates(cube_cage, many_points, raised):
    calls = []

    def progress(fraction):
        calls.append(fraction)
        raise raised()

    with pytest.raises(raised):
        somicage.Deformer(cube_cage, many_points, progress=progress)
    assert len(calls) == 1  # the engine stopped at once


class Ticker:
    """A second Python thread that counts while it can get the GIL (it waits 1 ms between counts, GIL released)."""

    def __init__(self):
        self.count, self.stop = 0, threading.Event()
        self.thread = threading.Thread(target=self.run)

    def run(self):
        while not self.stop.wait(0.001):
            self.count += 1

    def __enter__(self):
        self.switch = sys.getswitchinterval()
        sys.setswitchinterval(100.0)  # this thread never hands the GIL over unless C++ releases it
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join()
        sys.setswitchinterval(self.switch)


def test_gil_released_during_precompute_and_deform(cube_cage, many_points):
    """With the GIL held through a call, the ticker could not count during it: before == after exactly."""
    with Ticker() as ticker:
        before = ticker.count
        deformer = somicage.Deformer(cube_cage, many_points, method="somigliana")
        during_precompute = ticker.count - before
        during_deform = 0
        for _ in range(20):
            before = ticker.count
            deformer.deform(cube_cage.vertices * 1.1, variant="local")
            during_deform += ticker.count - before
    assert during_precompute > 0 and during_deform > 0


def test_results_do_not_depend_on_thread_count(cube_cage, many_points):
    posed = cube_cage.vertices + np.random.default_rng(4).normal(scale=0.1, size=cube_cage.vertices.shape)
    one = somicage.Deformer(cube_cage, many_points, threads=1).deform(posed, nu=0.3, variant="local")
    two = somicage.Deformer(cube_cage, many_points, threads=2).deform(posed, nu=0.3, variant="local")
    np.testing.assert_array_equal(one, two)
    with pytest.raises(somicage.InputError, match="^threads: is -1"):
        somicage.Deformer(cube_cage, many_points, threads=-1)


def test_arrays_out_are_the_engines_own(cube_cage, cube_points):
    deformer = somicage.Deformer(cube_cage, cube_points)
    first, second = deformer.deform(cube_cage.vertices), deformer.deform(cube_cage.vertices)
    # The result wraps the engine's result matrix (owned by a capsule), column-major as the engine stores it.
    assert first.base is not None and not first.flags.owndata and first.flags.f_contiguous and first.flags.writeable
    assert not np.shares_memory(first, second)  # every call returns its own buffer
    # Views into the cage and the diagnostics: the same memory on every access, and read-only.
    assert np.shares_memory(cube_cage.vertices, cube_cage.vertices) and not cube_cage.vertices.flags.writeable
    assert np.shares_memory(deformer.winding, deformer.winding) and not deformer.winding.flags.writeable
    with pytest.raises(ValueError):
        cube_cage.vertices[0, 0] = 5.0


def test_any_layout_and_dtype_in(cube_cage, cube_points):
    """Inputs are copied once into the engine's column-major storage from NumPy's buffer with its strides: C order,
    Fortran order, strided views and lists give the same numbers; float32 is converted by NumPy first."""
    reference = somicage.Deformer(cube_cage, cube_points).deform(cube_cage.vertices * 2)
    padded = np.zeros((len(cube_points), 6))
    padded[:, ::2] = cube_points
    for points in [np.asfortranarray(cube_points), padded[:, ::2], cube_points.tolist()]:
        np.testing.assert_array_equal(somicage.Deformer(cube_cage, points).deform(cube_cage.vertices * 2), reference)
    single = somicage.Deformer(cube_cage, cube_points.astype(np.float32)).deform(np.float32(2) * cube_cage.vertices)
    np.testing.assert_allclose(single, reference, atol=1e-6)
