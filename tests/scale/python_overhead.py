"""Python's overhead over the engine's own time on a model: `somicage bench` (medians of the precompute and of the
frames, float storage) against the same calls through the somicage module, in alternating rounds so that both see
the same machine load. Usage (from the repository root):

    PYTHONPATH=build/python /usr/bin/python3 tests/scale/python_overhead.py build/app/somicage ../shared/models/firehydrant [ROUNDS]
"""
import json
import pathlib
import statistics
import subprocess
import sys
import time

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
    for k, name in enumerate(("precompute", "frame global", "frame local")):
        c = statistics.median(t[k] for t in cli_times)
        p = statistics.median(t[k] for t in python_times)
        print(f"{name:14s} CLI {c * 1e3:9.2f} ms   Python {p * 1e3:9.2f} ms   overhead {100 * (p - c) / c:+6.1f} %")


if __name__ == "__main__":
    main()
