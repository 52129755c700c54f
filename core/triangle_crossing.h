// Exact triangle tests that cage generation's CGAL files share (Epick kernel: exact predicates on double
// coordinates). Include only from the files of the somicage_cage_generation library (core/CMakeLists.txt).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>

namespace somicage::cage_geometry {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// Whether two triangles meet other than at the corners they share: triangles that share corners cross only when an
// edge of one pierces the other away from them, or (sharing an edge) when they are folded flat onto each other.
bool trianglesCross(const Kernel::Triangle_3& t, const std::array<Point, 3>& q);

// The smallest angle of triangle (a, b, c), in radians.
double minAngle(const Point& a, const Point& b, const Point& c);

}  // namespace somicage::cage_geometry
