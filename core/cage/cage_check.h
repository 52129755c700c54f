// The cage part of `somicage check` (app/cli/command_check.cpp) and of Python's somicage.check(): the cage validated
// as given (cage_validation.h), the repairs deform would apply (cage_repair.h), whether it is usable then and its
// warnings; and the fields `check --json` prints for it, made here once so both front ends give the same keys and
// values.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "cage/cage_repair.h"
#include "cage/cage_validation.h"
#include "geometry/cage.h"

namespace somicage {

struct CageCheck {
  CageReport report;                  // the cage as given
  std::vector<std::string> problems;  // describeCageProblems(report): empty exactly when report.valid()
  CageRepair repair;                  // what deform, bench and the editor apply; repair.cage is the cage they use
  CageReport repairedReport;          // repair.cage's (report itself when nothing was repaired)
  std::vector<std::string> warnings;  // describeCageWarnings(repairedReport)

  bool usable() const { return repairedReport.valid(); }
};

CageCheck checkCage(const Cage& cage);

// One field of a JSON report: null, a boolean, an integer, a number, a string or a list of strings.
using ReportValue = std::variant<std::nullptr_t, bool, int, double, std::string, std::vector<std::string>>;
using ReportFields = std::vector<std::pair<std::string, ReportValue>>;

// The cage's keys of `somicage check --json` that follow "cage" (its source, which each front end names itself),
// in order: dim, cage_vertices, cage_faces, valid, closed, ..., the defect counts, problems, repairs, usable,
// warnings, intersecting_face_pairs.
ReportFields cageCheckFields(const CageCheck& check);

}  // namespace somicage
