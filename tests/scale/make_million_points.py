#!/usr/bin/env python3
"""Writes a point set of N vertices (default 1,000,000) made from a mesh's vertices, each copied and jittered by
up to 0.2% of the mesh's bounding-box diagonal, for scale tests of somicage deform / bench (issue 6):

    python3 tests/scale/make_million_points.py ../shared/models/firehydrant/fireHydrant.obj /tmp/hydrant_1m.obj
    somicage bench --mesh /tmp/hydrant_1m.obj \
        --cage ../shared/models/firehydrant/fireHydrant_cages_triangulated.obj --frames 3 --repeat 1

Write the output outside the repository: it is about 40 MB. Deterministic (fixed seed)."""
import random
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: make_million_points.py IN.obj OUT.obj [N]")
    source, target = sys.argv[1], sys.argv[2]
    count = int(sys.argv[3]) if len(sys.argv) == 4 else 1000000
    vertices = []
    with open(source) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(tuple(float(x) for x in line.split()[1:4]))
    if not vertices:
        sys.exit(f"{source}: no vertices ('v x y z' lines)")
    low = [min(v[a] for v in vertices) for a in range(3)]
    high = [max(v[a] for v in vertices) for a in range(3)]
    jitter = 0.002 * sum((h - l) ** 2 for l, h in zip(low, high)) ** 0.5
    rng = random.Random(12345)
    with open(target, "w") as out:
        out.write(f"# {count} points: the vertices of {source}, jittered by up to {jitter:.3g}\n")
        for k in range(count):
            x, y, z = vertices[k % len(vertices)]
            if k >= len(vertices):  # the first copy is the mesh itself
                x, y, z = (c + rng.uniform(-jitter, jitter) for c in (x, y, z))
            out.write(f"v {x:.7g} {y:.7g} {z:.7g}\n")


if __name__ == "__main__":
    main()
