"""Python's overhead over the engine's own time on a model: `somicage bench` (medians of the precompute and of the
frames, float storage) against the same calls through the somicage module, in alternating rounds so that both see
the same machine load. On a busy machine that difference drowns in noise, so the script also bounds the overhead
from above: the median cost of a call on one point, one thread (the binding's fixed work plus the core's per-frame
weights), and the
cost of the input copy (a NumPy copy of the points into Fortran order, which is what the binding does).
Usage (from the repository root):

    PYTHONPATH=build/python /usr/bin/python3 tests/scale/python_overhead.py build/app/somicage ../shared/models/firehydrant [ROUNDS]
"""
import json
import pathlib
import statistics
import subprocess
import sys
import time

import numpy as np

import somicage

FRAMES, REPEAT = 30, 3


def cli_round(cli, mesh, rest, posed):
    result = subprocess.run([cli, "bench", "--mesh", mesh, "--cage", rest, "--posed", posed, "--frames", str(FRAMES),
                             "--repeat", str(REPEAT), "--baseline-points", "100", "--baseline-quadrature", "5",
                             "--json"], capture_output=True, text=True, check=True)
    report = json.loads(result.stdout)
    return report["precompute_s"], report["deform_ms"]["cpu_global"] / 1e3, report["deform_ms"]["cpu_local"] / 1e3


def timed(call):
    start = time.perf_counter()
    value = call()
    return time.perf_counter() - start, value


def python_round(mesh, rest, posed):
    cage = somicage.Cage.from_obj(rest)
    points, _ = somicage.load_mesh(mesh)
    pose = somicage.load_posed(posed, cage)
    precomputes = [timed(lambda: somicage.Deformer(cage, points, float_storage=True)) for _ in range(REPEAT)]
    deformer = precomputes[-1][1]
    frames = {variant: statistics.median(timed(lambda: deformer.deform(pose, variant=variant))[0]
                                         for _ in range(FRAMES)) for variant in ("global", "local")}
    return statistics.median(t for t, _ in precomputes), frames["global"], frames["local"]


def main():
    cli, models = sys.argv[1], pathlib.Path(sys.argv[2])
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    files = [str(models / name) for name in ("fireHydrant.obj", "fireHydrant_cages_triangulated.obj",
                                             "fireHydrant_cages_triangulated_deformed.obj")]
    cli_times, python_times = [], []
    for _ in range(rounds):
        cli_times.append(cli_round(cli, *files))
        python_times.append(python_round(*files))
    medians = []
    for k, name in enumerate(("precompute", "frame global", "frame local")):
        c = statistics.median(t[k] for t in cli_times)
        p = statistics.median(t[k] for t in python_times)
        medians.append(c)
        print(f"{name:14s} CLI {c * 1e3:9.2f} ms   Python {p * 1e3:9.2f} ms   difference {100 * (p - c) / c:+6.1f} %")

    cage = somicage.Cage.from_obj(files[1])
    points, _ = somicage.load_mesh(files[0])
    pose = somicage.load_posed(files[2], cage)
    # One thread: on a loaded machine an OpenMP fork/join alone can take milliseconds, which is no binding cost.
    one = somicage.Deformer(cage, points[:1], threads=1)
    calls = 2000
    per_call = {v: statistics.median(timed(lambda: one.deform(pose, variant=v))[0] for _ in range(calls))
                for v in ("global", "local")}
    c_order = np.ascontiguousarray(points)  # load_mesh gives Fortran order, which asfortranarray would not copy
    copy = statistics.median(timed(lambda: np.asfortranarray(c_order))[0] for _ in range(50))
    precompute_one = statistics.median(timed(lambda: somicage.Deformer(cage, points[:1]))[0] for _ in range(20))
    print(f"bound: one-point deform {per_call['global'] * 1e6:.0f} us global, {per_call['local'] * 1e6:.0f} us local "
          f"({100 * per_call['global'] / medians[1]:.2f} %, {100 * per_call['local'] / medians[2]:.2f} % of a frame); "
          f"one-point precompute {precompute_one * 1e3:.2f} ms + input copy {copy * 1e3:.2f} ms "
          f"({100 * (precompute_one + copy) / medians[0]:.2f} % of the precompute)")


if __name__ == "__main__":
    main()
