// What cage generation's CGAL files share (Epick kernel: exact predicates on double coordinates): a mesh as a
// triangle soup with its AABB tree type, and exact triangle tests. Include only from the files of the
// somicage_cage_generation library (core/CMakeLists.txt).
#pragma once

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Core>
#include <array>
#include <vector>

namespace somicage::cage_geometry {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangles = std::vector<Kernel::Triangle_3>;
using SoupTree =
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>>>;

// Triangle j is (vertices(triangles(j, 0)), ...). A SoupTree over it must not outlive it.
Triangles triangleSoup(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles);

// Whether two triangles meet other than at the corners they share: triangles that share corners cross only when an
// edge of one pierces the other away from them, or (sharing an edge) when they are folded flat onto each other.
bool trianglesCross(const Kernel::Triangle_3& t, const std::array<Point, 3>& q);

// The smallest angle of triangle (a, b, c), in radians.
double minAngle(const Point& a, const Point& b, const Point& c);

}  // namespace somicage::cage_geometry
