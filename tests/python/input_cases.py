"""Runs input cases of test_hypothesis_inputs.py in this process (a child of the test, so that a crash fails the
test instead of ending it): python3 input_cases.py CASES.pickle RESULTS.pickle PROGRESS.txt

Each case describes arrays (values, dtype, memory layout) and one call; it is run twice: as described, and as the
float64 / int64 C-order reference of the same values. The results (a NumPy result, or the exception's type and
message) go to RESULTS; PROGRESS names the case being run, so the parent can say which one crashed.
"""
import pickle
import sys
import warnings

import numpy as np

import somicage

# The cube's 12 outward triangles: the one rest cage of every case.
CUBE_QUADS = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
CUBE_FACES = np.array([t for a, b, c, d in CUBE_QUADS for t in ((a, b, c), (a, c, d))], dtype=np.int64)
CUBE_VERTICES = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=np.float64)


def build(spec):
    """The array a spec describes: its values (flat, then reshaped) in its dtype, laid out in memory as it says."""
    values, dtype, layout = spec["values"], np.dtype(spec["dtype"]), spec["layout"]
    with np.errstate(all="ignore"):  # float16 of 1e300 is inf: a value like any other here
        flat = np.array(values, dtype=object if dtype.kind in "iu" else np.float64).astype(dtype)
    array = flat.reshape(spec["shape"])
    if layout == "F":
        return np.asfortranarray(array)
    if layout == "strided":  # every other element of a bigger array
        big = np.zeros(tuple(2 * n for n in array.shape), dtype=dtype)
        view = big[tuple(slice(None, None, 2) for _ in array.shape)]
        view[...] = array
        return view
    if layout == "reversed":  # negative strides in every dimension
        every = tuple(slice(None, None, -1) for _ in array.shape)
        return np.ascontiguousarray(array[every])[every]
    return np.ascontiguousarray(array)


def reference(spec):
    """The same values as a C-order float64 (coordinates) or int64 (indices) array: the call every case must match."""
    with np.errstate(all="ignore"):
        return build(dict(spec, layout="C")).astype(np.float64 if spec["role"] == "coordinates" else np.int64)


def call(case, make):
    kind = case["kind"]
    if kind == "cage":
        cage = somicage.Cage(make(case["vertices"]), make(case["faces"]) if case["faces"] else None)
        return np.array(cage.vertices), np.array(cage.faces)
    if kind == "check":
        report = somicage.check(make(case["vertices"]), make(case["faces"]) if case["faces"] else None)
        return sorted((k, repr(v)) for k, v in report.items())
    if kind == "deform":
        deformer = somicage.Deformer(somicage.Cage(CUBE_VERTICES, CUBE_FACES), make(case["points"]), case["method"],
                                     threads=1)  # a dozen points: threads would cost more than they save
        return deformer.deform(make(case["posed"]), **case["parameters"])
    raise ValueError(kind)


def outcome(case, make):
    try:
        return ("result", call(case, make))
    except (somicage.InputError, TypeError) as error:
        return ("refused", type(error).__name__, str(error))
    except Exception as error:  # anything else is a finding: recorded, compared, reported by the parent
        return ("unexpected", type(error).__name__, str(error))


def main(cases_path, results_path, progress_path):
    warnings.simplefilter("ignore")  # repairs and self-intersection warnings are not what is tested here
    with open(cases_path, "rb") as f:
        cases = pickle.load(f)
    results = []
    with open(progress_path, "w") as progress:
        for index, case in enumerate(cases):
            progress.write(f"{index}\n")
            progress.flush()
            results.append((outcome(case, build), outcome(case, reference)))
    with open(results_path, "wb") as f:
        pickle.dump(results, f)


if __name__ == "__main__":
    main(*sys.argv[1:])
