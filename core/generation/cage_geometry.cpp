#include "generation/cage_geometry.h"

#include <algorithm>
#include <cmath>

namespace somicage::cage_geometry {

Triangles triangleSoup(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles) {
  const auto corner = [&](int j, int k) {
    const int i = triangles(j, k);
    return Point(vertices(i, 0), vertices(i, 1), vertices(i, 2));
  };
  Triangles soup;
  soup.reserve(triangles.rows());
  for (int j = 0; j < triangles.rows(); ++j) soup.emplace_back(corner(j, 0), corner(j, 1), corner(j, 2));
  return soup;
}

double minAngle(const Point& a, const Point& b, const Point& c) {
  const auto angle = [](const Point& o, const Point& p, const Point& q) {
    const Kernel::Vector_3 u = p - o, v = q - o;
    return std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v);
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

bool trianglesCross(const Kernel::Triangle_3& t, const std::array<Point, 3>& q) {
  int shared = 0, sharedAt[3] = {-1, -1, -1};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t[i] == q[j]) sharedAt[i] = j, ++shared;
  const Kernel::Triangle_3 u(q[0], q[1], q[2]);
  if (shared == 0) return CGAL::do_intersect(t, u);
  if (shared == 3) return true;  // the same triangle twice
  if (shared == 2) {             // edge neighbours overlap only when folded flat onto each other
    int o = 0, r = 0;
    while (sharedAt[r] >= 0) ++r;                                          // t's corner off the shared edge
    while (o == sharedAt[0] || o == sharedAt[1] || o == sharedAt[2]) ++o;  // u's
    const int s0 = (r + 1) % 3, s1 = (r + 2) % 3;
    return CGAL::orientation(t[0], t[1], t[2], q[o]) == CGAL::COPLANAR &&
           CGAL::coplanar_orientation(t[s0], t[s1], t[r], q[o]) == CGAL::POSITIVE;
  }
  int i = 0;
  while (sharedAt[i] < 0) ++i;
  const int j = sharedAt[i];
  return CGAL::do_intersect(Kernel::Segment_3(t[(i + 1) % 3], t[(i + 2) % 3]), u) ||
         CGAL::do_intersect(Kernel::Segment_3(q[(j + 1) % 3], q[(j + 2) % 3]), t);
}

}  // namespace somicage::cage_geometry
