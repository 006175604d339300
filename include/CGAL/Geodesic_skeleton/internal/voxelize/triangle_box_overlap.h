// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_TRIANGLE_BOX_OVERLAP_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_TRIANGLE_BOX_OVERLAP_H

#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The axis-aligned bounding box of a triangle.
struct Triangle_box
{
  Vec3 lo, hi;
  Triangle_box() = default;
  Triangle_box(const Vec3& a, const Vec3& b, const Vec3& c)
  {
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = (std::min)({a[i], b[i], c[i]});
      hi[i] = (std::max)({a[i], b[i], c[i]});
    }
  }
  explicit Triangle_box(const std::array<Vec3, 3>& t) : Triangle_box(t[0], t[1], t[2]) {}
};

// Whether a triangle meets axis-aligned cubes of half edge `half`, each given by its
// centre: the separating axis theorem with the 13 candidate axes (3 cube normals, the
// triangle normal, 9 cross products of cube and triangle edges), as in Akenine-Moller's
// "Fast 3D triangle-box overlap testing" (2001). Touching counts as overlapping. What
// depends only on the triangle (its box, normal, and its extent along each axis) is
// computed once, so that testing a cube costs a few products per axis.
class Triangle_cube_test
{
public:
  Triangle_cube_test() = default;
  Triangle_cube_test(const Vec3& a, const Vec3& b, const Vec3& c, double half) { set(a, b, c, half); }

  // Tests this triangle from now on.
  void set(const Vec3& a, const Vec3& b, const Vec3& c, double half)
  {
    m_half = half;
    const Vec3 v[3] = {a, b, c};
    m_box = Triangle_box(a, b, c);
    const Vec3 e[3] = {sub(b, a), sub(c, b), sub(a, c)};
    m_normal = cross3(e[0], e[1]);
    m_plane = dot3(m_normal, a);
    m_normal_radius = half * (std::abs(m_normal[0]) + std::abs(m_normal[1]) + std::abs(m_normal[2]));
    for(int i = 0; i < 3; ++i)
      for(int axis = 0; axis < 3; ++axis)
      {
        Vec3 u{0., 0., 0.};
        u[axis] = 1.;
        Edge_axis& l = m_edge_axes[3 * i + axis];
        l.direction = cross3(u, e[i]);
        const double p0 = dot3(l.direction, v[0]), p1 = dot3(l.direction, v[1]), p2 = dot3(l.direction, v[2]);
        l.lo = (std::min)({p0, p1, p2});
        l.hi = (std::max)({p0, p1, p2});
        l.radius = half * (std::abs(l.direction[0]) + std::abs(l.direction[1]) + std::abs(l.direction[2]));
      }
  }

  bool meets(const Vec3& centre) const
  {
    // The cube's face normals: the triangle's bounding box against the cube.
    for(int i = 0; i < 3; ++i)
      if(m_box.lo[i] - centre[i] > m_half || m_box.hi[i] - centre[i] < -m_half)
        return false;
    // The triangle's plane against the cube.
    if(std::abs(m_plane - dot3(m_normal, centre)) > m_normal_radius)
      return false;
    // The nine cross products of a cube axis with a triangle edge.
    for(const Edge_axis& l : m_edge_axes)
    {
      const double at = dot3(l.direction, centre);
      if(l.lo - at > l.radius || l.hi - at < -l.radius)
        return false;
    }
    return true;
  }

private:
  struct Edge_axis
  {
    Vec3 direction;
    double lo, hi, radius; // the triangle's extent along the direction, the cube's half
  };
  double m_half = 0;
  Triangle_box m_box{};
  Vec3 m_normal{};
  double m_plane = 0, m_normal_radius = 0;
  std::array<Edge_axis, 9> m_edge_axes{};
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_TRIANGLE_BOX_OVERLAP_H
