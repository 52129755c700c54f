#!/usr/bin/env python3
"""The layering rule of core/ (docs/ARCHITECTURE.md): a file includes files of its own folder or of folders below
it, every include names the folder, and no header includes itself through others. Prints each violation with
file:line and exits 1 when there is one.

Usage: check_layers.py [REPOSITORY_ROOT]
"""
import os
import re
import sys

# Layers, lowest first: a folder may include its own files and those of strictly lower layers. Folders of one layer
# know nothing of each other.
LAYERS = [
    ["base"],                                # errors, progress, JSON, files, numbers, SIMD and CPU dispatch
    ["geometry"],                            # cages, volume meshes, closest points, triangle integrals and kernels
    ["cage", "deform"],                      # cage checks and repair; parameters, methods' boundary, frames, J
    ["coordinates"],                         # the coordinate matrices of each method
    ["methods"],                             # one file per method: its descriptor
    ["analysis", "io"],                      # quantities of a deformation; mesh and scene files
    ["animation", "generation", "tetrahedralization"],  # poses over time, their export; cages and tets made
    ["engine"],                              # the facade every front end uses, sessions, views
    ["cuda"],                                # the optional CUDA backend
]
RANK = {folder: rank for rank, folders in enumerate(LAYERS) for folder in folders}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCE = re.compile(r"\.(h|cpp|cu|inc)$")


def core_files(core):
    files = {}
    for folder in sorted(os.listdir(core)):
        path = os.path.join(core, folder)
        if not os.path.isdir(path):
            continue
        for name in sorted(os.listdir(path)):
            if SOURCE.search(name):
                files[f"{folder}/{name}"] = os.path.join(path, name)
    return files


def check(core):
    """The violations in the core folder `core`, as 'file:line: problem' strings."""
    problems = []
    files = core_files(core)
    for loose in sorted(os.listdir(core)):
        if SOURCE.search(loose) and os.path.isfile(os.path.join(core, loose)):
            problems.append(f"core/{loose}: a source file outside every folder (put it in the folder of its layer)")
    graph = {}
    for key, path in files.items():
        folder = key.split("/")[0]
        if folder not in RANK:
            problems.append(f"core/{key}: folder '{folder}' is in no layer of tools/check_layers.py")
            continue
        graph[key] = []
        with open(path, encoding="utf-8") as source:
            for number, line in enumerate(source, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                name = match.group(1)
                where = f"core/{key}:{number}"
                if name in files:
                    target = name.split("/")[0]
                    graph[key].append(name)
                    if target != folder and RANK.get(target, -1) >= RANK[folder]:
                        problems.append(f"{where}: includes {name}, which is not below '{folder}' "
                                        f"(layer {RANK[folder]} includes layer {RANK.get(target)})")
                elif os.path.basename(name) in {k.split("/")[1] for k in files} and "/" not in name:
                    problems.append(f"{where}: includes \"{name}\" without its folder")
    problems += [f"core/{cycle[0]}: include cycle {' -> '.join(cycle)}" for cycle in cycles(graph)]
    return problems


def cycles(graph):
    """One cycle through each strongly connected set of files that includes itself (depth-first search)."""
    found, state, stack = [], {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in graph.get(node, []):
            if state.get(nxt) == "open":
                found.append(stack[stack.index(nxt):] + [nxt])
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = "done"

    for node in sorted(graph):
        if node not in state:
            visit(node)
    return found


if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    found = check(os.path.join(root, "core"))
    for problem in found:
        print(problem)
    print(f"core layering: {len(found)} problem(s)" if found else "core layering: ok")
    sys.exit(1 if found else 0)
