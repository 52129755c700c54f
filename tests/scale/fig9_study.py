#!/usr/bin/env python3
"""The paper's Fig. 9 study (issue 26): scale a pose's displacement by a = 1 ... 0.01 and measure each method's
distance to the boundary element reference (`--method bem`), relative to the reference's displacement:
rms |x_method - x_bem| / rms |x_bem - x_rest| over the mesh's vertices (all inside the cage for these three), nu = 0, gamma = 0.

    /usr/bin/python3 tests/scale/fig9_study.py build/app/somicage ../shared/models [botijo cactus firehydrant]

Prints one table row per model, method and a. Writes its files under a temporary folder."""
import pathlib
import subprocess
import sys
import tempfile

import numpy as np

MODELS = {"botijo": ("botijo.obj", "botijo_cages_triangulated.obj", "botijo_cages_triangulated_deformed.obj"),
          "cactus": ("cactus.obj", "cactus_cages_triangulated.obj", "cactus_cages_triangulated_deformed.obj"),
          "firehydrant": ("fireHydrant.obj", "fireHydrant_cages_triangulated.obj",
                          "fireHydrant_cages_triangulated_deformed.obj")}
METHODS = [("global", ["--method", "somigliana", "--variant", "global"]),
           ("affine", ["--method", "somigliana", "--variant", "affine"]),
           ("local", ["--method", "somigliana", "--variant", "local"]),
           ("stable", ["--method", "somigliana", "--variant", "stable"]),
           ("mvc", ["--method", "mvc"]), ("green", ["--method", "green"])]
SCALES = [1, 0.3, 0.1, 0.03, 0.01]


def read_vertices(path):
    return np.array([[float(t) for t in line.split()[1:4]] for line in open(path) if line.startswith("v ")])


def write_points(path, points):
    with open(path, "w") as f:
        for p in points:
            f.write("v %.17g %.17g %.17g\n" % tuple(p))


def main():
    exe, models = sys.argv[1], pathlib.Path(sys.argv[2])
    names = sys.argv[3:] or list(MODELS)
    work = pathlib.Path(tempfile.mkdtemp())
    print("| model | method | " + " | ".join(f"a = {a}" for a in SCALES) + " |")
    print("|---|---|" + "---|" * len(SCALES))
    for name in names:
        mesh, cage, pose = (models / name / f for f in MODELS[name])
        rest = read_vertices(cage)
        posed = read_vertices(pose)
        points = read_vertices(mesh)
        results = {}
        for a in SCALES:
            scaled = work / f"{name}_{a}.obj"
            # The cage file with its vertices moved: keep its faces (the l/f lines) as they are.
            lines = open(cage).read().splitlines()
            k = 0
            with open(scaled, "w") as f:
                for line in lines:
                    if line.startswith("v "):
                        f.write("v %.17g %.17g %.17g\n" % tuple(rest[k] + a * (posed[k] - rest[k])))
                        k += 1
                    else:
                        f.write(line + "\n")
            for label, options in [("bem", ["--method", "bem"])] + METHODS:
                out = work / f"{name}_{a}_{label}.obj"
                run = subprocess.run([exe, "deform", "--cage", str(cage), "--posed", str(scaled), "--mesh", str(mesh),
                                      "--out", str(out)] + options, capture_output=True, text=True)
                if run.returncode != 0:
                    sys.exit(run.stderr)
                results[(label, a)] = read_vertices(out)
        for label, _ in METHODS:
            row = []
            for a in SCALES:
                bem = results[("bem", a)]
                moved = np.sqrt(np.mean(np.sum((bem - points) ** 2, axis=1)))
                miss = np.sqrt(np.mean(np.sum((results[(label, a)] - bem) ** 2, axis=1)))
                row.append(f"{miss / moved:.3f}")
            print(f"| {name} | {label} | " + " | ".join(row) + " |", flush=True)


if __name__ == "__main__":
    main()
