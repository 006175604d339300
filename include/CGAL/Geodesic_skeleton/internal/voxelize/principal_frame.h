// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_PRINCIPAL_FRAME_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_PRINCIPAL_FRAME_H

#include <CGAL/Geodesic_skeleton/internal/nearest_integer.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/triangle_box_overlap.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

using Triangle3 = std::array<Vec3, 3>;

// The principal axes of a triangle soup seen as a uniform surface (every point of every
// triangle weighs the same), so they do not depend on the tessellation, nor on a rigid
// motion of the soup: the centroid, then the eigenvectors of the covariance by decreasing
// eigenvalue. Each of the first two axes points to the side where the third moment of the
// surface is positive (the "heavier tail"); the third is their cross product, so the frame
// is right-handed and moves with the mesh.
struct Principal_frame
{
  Vec3 centroid;
  std::array<Vec3, 3> axes;
};

// The largest coordinate and the smallest extent of a mesh that the package handles.
constexpr double max_coordinate_magnitude = 1e150;
constexpr double min_mesh_size = 1e-150;

inline Principal_frame principal_frame(const std::vector<Triangle3>& world_triangles, const char* caller)
{
  // The moments below are powers 4 and 5 of the coordinates (squared areas, third moments
  // times areas): in world units they overflow for a mesh about 1e60 across and underflow
  // for one about 1e-60 across (a "zero area" error, a NaN frame). So they are computed on
  // the mesh moved to its box's centre and scaled to unit size, which changes nothing else:
  // the axes are the same, and the centroid is scaled back.
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(const Triangle3& t : world_triangles)
    for(const Vec3& p : t)
      for(int c = 0; c < 3; ++c)
      {
        lo[c] = (std::min)(lo[c], p[c]);
        hi[c] = (std::max)(hi[c], p[c]);
      }
  const Vec3 centre{0.5 * lo[0] + 0.5 * hi[0], 0.5 * lo[1] + 0.5 * hi[1], 0.5 * lo[2] + 0.5 * hi[2]};
  const double size = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double magnitude = (std::max)({-lo[0], -lo[1], -lo[2], hi[0], hi[1], hi[2]});
  if(!(size > 0))
    throw std::invalid_argument(std::string(caller) + ": the mesh has zero area (all its points are equal)");
  // The later stages square world lengths (distances, radii), which overflows past 1e154
  // and loses every digit under 1e-154: outside these bounds, an error rather than a
  // NaN or silently wrong skeleton.
  if(!(magnitude <= max_coordinate_magnitude) || size < min_mesh_size)
  {
    std::ostringstream msg;
    msg << caller << ": the mesh is " << size << " across with coordinates up to " << magnitude
        << "; the package needs coordinates up to " << max_coordinate_magnitude << " and a mesh at least "
        << min_mesh_size << " across: scale the mesh";
    throw std::invalid_argument(msg.str());
  }
  // The triangles are centred and scaled to unit size on the fly (a copy of them would be
  // as large as the mesh), each value by the same expression at each use.
  // Each pass scales a triangle once and reads its area from the scaled corners.
  // The scaled coordinates are rounded to 2^-30, far above the rounding errors of a scaling
  // or a translation of the mesh: the moments of a moved or scaled copy are then the same
  // bit for bit, rounding noise included. A mirror-symmetric mesh has no third moment
  // across its mirror plane but that noise, whose sign orients the axis.
  const double to_steps = 0x1p30 / size; // a product, not a division, per coordinate
  auto scaled = [&](const Triangle3& w) {
    Triangle3 t;
    for(int j = 0; j < 3; ++j)
      for(int c = 0; c < 3; ++c)
        t[j][c] = nearest_integer((w[j][c] - centre[c]) * to_steps) * 0x1p-30;
    return t;
  };
  auto area_of = [](const Triangle3& t) {
    return 0.5 * std::sqrt(dot3(cross3(sub(t[1], t[0]), sub(t[2], t[0])), cross3(sub(t[1], t[0]), sub(t[2], t[0]))));
  };

  double area_sum = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for(const Triangle3& w : world_triangles)
  {
    const Triangle3 t = scaled(w);
    const double area = area_of(t);
    area_sum += area;
    for(int c = 0; c < 3; ++c)
      centroid[c] += area * (t[0][c] + t[1][c] + t[2][c]) / 3.;
  }
  if(!(area_sum > 0) || !std::isfinite(area_sum))
    throw std::invalid_argument(std::string(caller) +
                                ": the mesh has zero area (every face is degenerate)");
  centroid /= area_sum;

  // Second moments about the centroid: E[x x^T] over a triangle is (sum_i v_i v_i^T + s s^T)/12
  // with s the sum of its vertices.
  // (Six sums: the matrix is symmetric.)
  double moment[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for(const Triangle3& w : world_triangles)
  {
    const Triangle3 t = scaled(w);
    double v[3][3], s[3];
    for(int c = 0; c < 3; ++c)
    {
      for(int j = 0; j < 3; ++j)
        v[j][c] = t[j][c] - centroid[c];
      s[c] = (v[0][c] + v[1][c]) + v[2][c];
    }
    const double weight = area_of(t) / 12.;
    for(int r = 0; r < 3; ++r)
      for(int c = r; c < 3; ++c)
        moment[r][c] += weight * (((v[0][r] * v[0][c] + v[1][r] * v[1][c]) + v[2][r] * v[2][c]) + s[r] * s[c]);
  }
  Eigen::Matrix3d covariance;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c)
      covariance(r, c) = r <= c ? moment[r][c] : moment[c][r];
  covariance /= area_sum;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if(solver.info() != Eigen::Success)
    throw std::runtime_error(std::string(caller) + ": the principal axes could not be computed");

  Principal_frame frame;
  for(int c = 0; c < 3; ++c)
    frame.centroid[c] = centre[c] + size * centroid[c];
  // Third moment along each of the first two axes (one pass for both): E[t^3] over a
  // triangle is h3(t0, t1, t2) / 10, the complete homogeneous symmetric polynomial of
  // degree 3 of its vertex values.
  const Eigen::Vector3d axis[2] = {solver.eigenvectors().col(2).normalized(),
                                   solver.eigenvectors().col(1).normalized()};
  double third_moment[2] = {0, 0};
  for(const Triangle3& w : world_triangles)
  {
    const Triangle3 scaled_triangle = scaled(w);
    Eigen::Vector3d v[3];
    for(int j = 0; j < 3; ++j)
      v[j] = Eigen::Vector3d(scaled_triangle[j][0], scaled_triangle[j][1], scaled_triangle[j][2]) - centroid;
    const double area = area_of(scaled_triangle);
    for(int a = 0; a < 2; ++a)
    {
      double t[3];
      for(int j = 0; j < 3; ++j)
        t[j] = v[j].dot(axis[a]);
      const double h3 = t[0] * t[0] * t[0] + t[1] * t[1] * t[1] + t[2] * t[2] * t[2] +
                        t[0] * t[0] * (t[1] + t[2]) + t[1] * t[1] * (t[0] + t[2]) +
                        t[2] * t[2] * (t[0] + t[1]) + t[0] * t[1] * t[2];
      third_moment[a] += area * h3 / 10.;
    }
  }
  for(int a = 0; a < 2; ++a)
  {
    const Eigen::Vector3d oriented = third_moment[a] < 0 ? Eigen::Vector3d(-axis[a]) : axis[a];
    frame.axes[a] = Vec3{oriented[0], oriented[1], oriented[2]};
  }
  frame.axes[2] = cross3(frame.axes[0], frame.axes[1]);
  const double norm = std::sqrt(dot3(frame.axes[2], frame.axes[2]));
  for(double& c : frame.axes[2])
    c /= norm;
  return frame;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_PRINCIPAL_FRAME_H
