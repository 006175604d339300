// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The triangles of one polygonal face (a quad, an n-gon as modelling tools leave them),
// convex or not, for the rasterisation and the inside tests of the voxel stages.

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_VOXELIZE_POLYGON_TRIANGLES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_VOXELIZE_POLYGON_TRIANGLES_H

#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A triangle of a polygon: the indices of its corners in the polygon.
using Corner_triple = std::array<std::size_t, 3>;

// Twice the signed area of the triangle (a, b, c) of the plane.
inline double signed_area_2(const std::array<double, 2>& a, const std::array<double, 2>& b,
                            const std::array<double, 2>& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Appends the n - 2 triangles of the polygon `corners` (n >= 3, in order around the face)
// to `out`, as triples of indices into `corners`, in the polygon's orientation. A convex polygon is split into a fan from its
// first corner; a non-convex one by ear clipping in the plane across the largest
// component of its Newell normal, since a fan would cover the outside of the polygon
// where it bends inwards (an L-shaped or letter-shaped face) and leave part of its inside
// uncovered. A polygon with no ear left (it crosses itself, or is degenerate) gets a fan
// for the rest. O(n) for a convex polygon, O(n^3) at worst for a non-convex one (O(n^2)
// in practice).
inline void append_polygon_triangles(const std::vector<Vec3>& corners, std::vector<Corner_triple>& out)
{
  const std::size_t n = corners.size();
  if(n < 3)
    return;
  Vec3 normal{0, 0, 0}; // Newell's normal: twice the vector area
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vec3& p = corners[i];
    const Vec3& q = corners[(i + 1) % n];
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  int dropped = 0;
  for(int a = 1; a < 3; ++a)
    if(std::abs(normal[a]) > std::abs(normal[dropped]))
      dropped = a;
  const int u = (dropped + 1) % 3, v = (dropped + 2) % 3;
  // In the (u, v) plane the polygon turns counter-clockwise when the normal's dropped
  // component is positive: orient so that its area is positive.
  const double orientation = normal[dropped] >= 0 ? 1.0 : -1.0;
  std::vector<std::array<double, 2>> plane(n);
  for(std::size_t i = 0; i < n; ++i)
    plane[i] = {corners[i][u], orientation * corners[i][v]};

  auto fan = [&](const std::vector<std::size_t>& ring) {
    for(std::size_t i = 1; i + 1 < ring.size(); ++i)
      out.push_back(Corner_triple{ring[0], ring[i], ring[i + 1]});
  };
  std::vector<std::size_t> ring(n);
  for(std::size_t i = 0; i < n; ++i)
    ring[i] = i;
  bool convex = true;
  for(std::size_t i = 0; i < n && convex; ++i)
    convex = signed_area_2(plane[i], plane[(i + 1) % n], plane[(i + 2) % n]) >= 0;
  if(convex || !(normal[dropped] != 0))
  {
    fan(ring);
    return;
  }

  // Ear clipping: a corner whose triangle with its two neighbours turns the polygon's way
  // and contains no other corner left is cut off.
  auto is_ear = [&](std::size_t k) {
    const std::size_t m = ring.size();
    const auto& a = plane[ring[(k + m - 1) % m]];
    const auto& b = plane[ring[k]];
    const auto& c = plane[ring[(k + 1) % m]];
    if(!(signed_area_2(a, b, c) > 0))
      return false;
    for(std::size_t j = 0; j < m; ++j)
    {
      if(j == k || j == (k + m - 1) % m || j == (k + 1) % m)
        continue;
      const auto& p = plane[ring[j]];
      if(signed_area_2(a, b, p) >= 0 && signed_area_2(b, c, p) >= 0 && signed_area_2(c, a, p) >= 0)
        return false;
    }
    return true;
  };
  std::size_t k = 0, tried = 0;
  while(ring.size() > 3 && tried < ring.size())
  {
    if(is_ear(k))
    {
      const std::size_t m = ring.size();
      out.push_back(Corner_triple{ring[(k + m - 1) % m], ring[k], ring[(k + 1) % m]});
      ring.erase(ring.begin() + std::ptrdiff_t(k));
      if(k == ring.size())
        k = 0;
      tried = 0;
    }
    else
    {
      k = (k + 1) % ring.size();
      ++tried;
    }
  }
  fan(ring);
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_VOXELIZE_POLYGON_TRIANGLES_H
