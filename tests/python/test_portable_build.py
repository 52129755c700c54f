"""The portable build on an old CPU (core/base/cpu_dispatch.h, docs/performance.md): `somicage deform` and the module's
Deformer run FIREHYDRANT under `qemu-x86_64 -cpu Nehalem` (SSE4.2: no AVX, no FMA; qemu stops at any newer
instruction) and give the same points to 1e-12 as on this machine, where the kernels run their AVX2/FMA (and
AVX-512) copies. Kept short for CI: the mesh's first 400 vertices, one thread (qemu is 10-50x slower than the host)."""
import os
import pathlib
import platform
import shutil
import subprocess
import sys

import numpy as np
import pytest

import somicage
from conftest import FIREHYDRANT, cli_executable, require_firehydrant

POINTS = 400
TOLERANCE = 1e-12  # FIREHYDRANT is about 2 units across: the copies differ by fused vs rounded products only
CAGE = FIREHYDRANT / "fireHydrant_cages_triangulated.obj"
POSED = FIREHYDRANT / "fireHydrant_cages_triangulated_deformed.obj"
NEHALEM = ["qemu-x86_64", "-cpu", "Nehalem"]

# Runs in a fresh interpreter (natively or under qemu): deforms the points with both variants, prints the kernels.
MODULE_RUN = """
import sys
import numpy as np
import somicage
cage = somicage.Cage.from_obj(sys.argv[1])
points = somicage.load_mesh(sys.argv[2])[0]
deformer = somicage.Deformer(cage, points, threads=1)
posed = somicage.load_posed(sys.argv[3], cage)
np.save(sys.argv[4], np.stack([deformer.deform(posed, nu=0.3, variant=v) for v in ("global", "local")]))
print(somicage.cpu_kernels)
"""


@pytest.fixture(scope="module")
def subset(tmp_path_factory):
    if platform.machine() != "x86_64":
        pytest.skip(f"the Nehalem run is for x86-64 builds (this is {platform.machine()})")
    if shutil.which(NEHALEM[0]) is None:
        pytest.skip("qemu-x86_64 is not installed (Debian qemu-user; third_party/install-deps.sh)")
    if somicage.cpu_kernels == "native":
        pytest.skip("a SOMICAGE_NATIVE build runs only on CPUs like the build machine's: nothing portable to test")
    require_firehydrant()
    path = tmp_path_factory.mktemp("nehalem") / "firehydrant_points.obj"
    vertices = somicage.load_mesh(str(FIREHYDRANT / "fireHydrant.obj"))[0][:POINTS]
    somicage.save_obj(str(path), vertices)
    return path


def host_kernels():
    """What the dispatch should pick here, from the CPU's own flags (Linux's /proc/cpuinfo)."""
    flags = set(next(line for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines()
                     if line.startswith("flags")).split())
    if not {"avx2", "fma", "bmi2", "movbe"} <= flags:
        return "baseline"
    return "x86-64-v4" if {"avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"} <= flags else "x86-64-v3"


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, timeout=240, **kwargs)
    assert result.returncode == 0, f"{' '.join(map(str, command))} exited {result.returncode}:\n{result.stderr}"
    return result


def test_cli_deform_under_nehalem_matches_this_cpu(subset, tmp_path):
    cli = cli_executable()
    outputs = {}
    for name, prefix in (("host", []), ("nehalem", NEHALEM)):
        out = tmp_path / f"{name}.obj"
        run(prefix + [cli, "deform", "--cage", str(CAGE), "--posed", str(POSED), "--mesh", str(subset),
                      "--out", str(out), "--nu", "0.3", "--threads", "1"])
        outputs[name] = somicage.load_mesh(str(out))[0]
    assert outputs["host"].shape == (POINTS, 3)
    moved = np.abs(outputs["host"] - somicage.load_mesh(str(subset))[0]).max()
    assert moved > 1e-3, "the pose moves the points (else the comparison below says little)"
    difference = np.abs(outputs["nehalem"] - outputs["host"]).max()
    assert difference <= TOLERANCE, f"CLI: Nehalem and host differ by {difference:.3g}"


def test_module_deform_under_nehalem_matches_this_cpu(subset, tmp_path):
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(somicage.__file__).parents[1]))
    results, kernels = {}, {}
    for name, prefix in (("host", []), ("nehalem", NEHALEM)):
        out = tmp_path / f"{name}.npy"
        printed = run(prefix + [sys.executable, "-c", MODULE_RUN, str(CAGE), str(subset), str(POSED), str(out)],
                      env=env).stdout
        kernels[name] = printed.split()[-1]
        results[name] = np.load(out)
    # The two runs compared the two copies of the kernels, not one copy twice.
    assert kernels == {"host": host_kernels(), "nehalem": "baseline"}
    assert results["host"].shape == (2, POINTS, 3)
    difference = np.abs(results["nehalem"] - results["host"]).max()
    assert difference <= TOLERANCE, f"module: Nehalem and host differ by {difference:.3g}"
