// Cages for Python: the engine's Cage exactly as `somicage deform` uses it (repaired, validated, warned about), with
// where it came from and what was said about it; and `somicage.check`, the cage part of `somicage check --json`.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "geometry/cage.h"
#include "numpy_arrays.h"

namespace somicage {

struct PythonCage {
  Cage cage;
  std::string source;                 // the file, or "Cage(vertices, faces)": the name in error messages
  std::vector<std::string> repairs;   // the faces repairCage flipped (cage_repair.h), one sentence each
  std::vector<std::string> warnings;  // describeCageWarnings (3D self-intersections)
};

// The cage as written in the arrays: vertices (V, 3) with triangles (F, 3), or (V, 2) with edges (F, 2) or, when
// faces is None, the vertices as a counter-clockwise loop. Dtypes, shapes, finiteness and index ranges are checked
// (numpy_arrays.h); the rest is the cage validation's.
Cage cageFromArrays(const ArrayArgument& vertices, const std::optional<ArrayArgument>& faces);

// The engine's prepareCage (engine.h: repair, validate, notices, refusal naming source), with each notice emitted
// as a somicage.SomiCageWarning in the command line's words.
PythonCage makeUsableCage(Cage cage, std::string source);

// The cage keys and values of `somicage check --json` (core/cage/cage_check.h, the one place both are made) as a dict.
pybind11::dict checkReport(const Cage& cage, const std::string& source);

}  // namespace somicage
