// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// An inside test for the tests, independent of the package's grid lines: the generalized
// winding number of a triangle mesh around a point, the sum of the signed solid angles of
// its faces over 4 pi (Van Oosterom and Strackee's formula). Where parts of a mesh overlap
// (a self-intersecting character, an ear through the head), the point is inside both and
// the winding number is 2, which ray parity (CGAL::Side_of_triangle_mesh) calls outside.

#ifndef GEODESIC_SKELETON_TEST_WINDING_NUMBER_H
#define GEODESIC_SKELETON_TEST_WINDING_NUMBER_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace Geodesic_skeleton_test {

// The winding number of the (triangle) mesh around p: about +-1 inside a closed,
// consistently oriented part, 0 outside, +-2 where two parts overlap.
template <typename Mesh, typename Point>
double winding_number(const Mesh& mesh, const Point& p)
{
  const double pi = 3.14159265358979323846;
  double solid_angles = 0;
  for(auto f : faces(mesh))
  {
    std::array<std::array<double, 3>, 3> r;
    double length[3];
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
    {
      if(k == 3)
        break;
      const auto& q = mesh.point(v);
      r[k] = {CGAL::to_double(q.x() - p.x()), CGAL::to_double(q.y() - p.y()), CGAL::to_double(q.z() - p.z())};
      length[k] = std::sqrt(r[k][0] * r[k][0] + r[k][1] * r[k][1] + r[k][2] * r[k][2]);
      ++k;
    }
    auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const std::array<double, 3> bc{r[1][1] * r[2][2] - r[1][2] * r[2][1], r[1][2] * r[2][0] - r[1][0] * r[2][2],
                                   r[1][0] * r[2][1] - r[1][1] * r[2][0]};
    const double numerator = dot(r[0], bc);
    const double denominator = length[0] * length[1] * length[2] + dot(r[0], r[1]) * length[2] +
                               dot(r[1], r[2]) * length[0] + dot(r[2], r[0]) * length[1];
    solid_angles += 2 * std::atan2(numerator, denominator);
  }
  return solid_angles / (4 * pi);
}

// Whether p is inside the mesh by the non-zero rule: a winding number of magnitude 1/2 or more.
template <typename Mesh, typename Point>
bool is_inside_by_winding(const Mesh& mesh, const Point& p)
{
  return std::abs(winding_number(mesh, p)) >= 0.5;
}

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_WINDING_NUMBER_H
