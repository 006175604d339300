// Synthetic characters for the skeleton-quality benchmark: a thin plate, a winged body, a
// humanoid in T-pose (also wearing an open cape) and a six-armed star. Each is a union of overlapping closed, outward-oriented pieces
// (the union self-intersects; the package's voxelizer fills each closed piece), built from
// shapes.h's soups. Units are arbitrary (about a metre for the figure).

#ifndef GEODESIC_SKELETON_TEST_CHARACTERS_H
#define GEODESIC_SKELETON_TEST_CHARACTERS_H

#include <Geodesic_skeleton_test/shapes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace Geodesic_skeleton_test {

using Point_2d = std::array<double, 2>;
using Point_3d = std::array<double, 3>;

// A closed slab: the convex polygon `outline` (in the xy plane, either orientation)
// extruded from z = z0 to z = z1 (z0 < z1). Caps are fans from the first point.
inline Soup convex_slab(std::vector<Point_2d> outline, double z0, double z1)
{
  double twice_area = 0;
  for(std::size_t i = 0; i < outline.size(); ++i)
  {
    const Point_2d& p = outline[i];
    const Point_2d& q = outline[(i + 1) % outline.size()];
    twice_area += p[0] * q[1] - q[0] * p[1];
  }
  if(twice_area < 0) // counter-clockwise seen from +z
    std::reverse(outline.begin(), outline.end());
  Soup s;
  const std::size_t n = outline.size();
  for(const Point_2d& p : outline)
    s.add_point(p[0], p[1], z0);
  for(const Point_2d& p : outline)
    s.add_point(p[0], p[1], z1);
  for(std::size_t i = 1; i + 1 < n; ++i)
  {
    s.add_triangle(0, i + 1, i);             // bottom, facing -z
    s.add_triangle(n, n + i, n + i + 1);     // top, facing +z
  }
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    s.add_quad(i, j, n + j, n + i); // side, facing out of the counter-clockwise outline
  }
  return s;
}

// `count` points of the ellipse of centre `c`, semi-axis `a` along the unit vector `u` and
// semi-axis `b` across it.
inline std::vector<Point_2d> ellipse_outline(const Point_2d& c, const Point_2d& u, double a, double b, int count)
{
  std::vector<Point_2d> out;
  for(int i = 0; i < count; ++i)
  {
    const double t = 2 * pi * i / count;
    const double along = a * std::cos(t), across = b * std::sin(t);
    out.push_back({c[0] + along * u[0] - across * u[1], c[1] + along * u[1] + across * u[0]});
  }
  return out;
}

// An ellipsoid of semi-axes (a, b, c) along x, y, z centred at `centre`: a scaled icosphere.
inline Soup ellipsoid(const Point_3d& centre, double a, double b, double c, int subdivisions = 3)
{
  Soup s = icosphere(1, subdivisions);
  for(auto& p : s.points)
    p = {centre[0] + a * p[0], centre[1] + b * p[1], centre[2] + c * p[2]};
  return s;
}

// A capsule of radius `r` from `a` to `b`: a capped cylinder between them and a sphere at
// each end, three overlapping closed pieces.
inline Soup capsule(const Point_3d& a, const Point_3d& b, double r)
{
  const Point_3d d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const Point_3d w{d[0] / length, d[1] / length, d[2] / length};
  const Point_3d helper = std::abs(w[0]) < 0.9 ? Point_3d{1, 0, 0} : Point_3d{0, 1, 0};
  Point_3d u{helper[1] * w[2] - helper[2] * w[1], helper[2] * w[0] - helper[0] * w[2],
             helper[0] * w[1] - helper[1] * w[0]};
  const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  u = {u[0] / nu, u[1] / nu, u[2] / nu};
  const Point_3d v{w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
  const int around = 24; // (u, v, w) is right-handed: the rotation keeps the normals outward
  const int along = std::max(2, int(std::ceil(length / (2 * pi * r / around) / 0.866)));
  Soup s = cylinder(r, length, around, along, true);
  for(auto& p : s.points)
    p = {a[0] + p[0] * u[0] + p[1] * v[0] + p[2] * w[0], a[1] + p[0] * u[1] + p[1] * v[1] + p[2] * w[1],
         a[2] + p[0] * u[2] + p[1] * v[2] + p[2] * w[2]};
  append(s, icosphere(r, 2), a[0], a[1], a[2]);
  append(s, icosphere(r, 2), b[0], b[1], b[2]);
  return s;
}

// A thin sheet alone: a rounded rectangle 1.0 (x) by 0.6 (y), corners of radius 0.1,
// 0.03 thick (z), centred at the origin. One closed piece.
inline Soup plate()
{
  const double half_x = 0.5, half_y = 0.3, r = 0.1, half_thickness = 0.015;
  std::vector<Point_2d> outline;
  const double corner[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for(int c = 0; c < 4; ++c) // counter-clockwise, 8 segments per quarter circle
    for(int i = 0; i <= 8; ++i)
    {
      const double t = pi / 2 * (c + i / 8.0);
      outline.push_back({corner[c][0] * (half_x - r) + r * std::cos(t), corner[c][1] * (half_y - r) + r * std::sin(t)});
    }
  return convex_slab(outline, -half_thickness, half_thickness);
}

// One wing, for y >= 0 (`side` = 1) or its mirror image (`side` = -1), 0.03 thick (z from
// -0.015 to 0.015), from the body's axis (y = 0) to its tip at |y| = 0.97, 0.85 out from
// the body's surface: a swept-back trapezoid to |y| = 0.92 (chord 0.4 at the root, 0.1 at
// the tip, leading edge from x = 0.2 to x = -0.05), a rounded tip (disc of radius 0.05),
// and three elliptic lobes on the trailing edge (0.2 long, reaching 0.06 behind it) that
// make its scallops. Five overlapping convex slabs.
inline Soup wing(int side)
{
  const double z0 = -0.015, z1 = 0.015;
  auto mirrored = [side](std::vector<Point_2d> outline) {
    for(Point_2d& p : outline)
      p[1] *= side;
    return outline; // convex_slab() restores the orientation
  };
  const Point_2d root_trailing{-0.2, 0.0}, tip_trailing{-0.15, 0.92};
  Soup s = convex_slab(mirrored({root_trailing, {0.2, 0.0}, {-0.05, 0.92}, tip_trailing}), z0, z1);
  append(s, convex_slab(mirrored(ellipse_outline({-0.1, 0.92}, {1, 0}, 0.05, 0.05, 16)), z0, z1)); // tip
  const double dx = tip_trailing[0] - root_trailing[0], dy = tip_trailing[1] - root_trailing[1];
  const double length = std::sqrt(dx * dx + dy * dy);
  const Point_2d along{dx / length, dy / length};
  for(double t : {0.3, 0.55, 0.8}) // the lobes, centred on the trailing edge
  {
    const Point_2d centre{root_trailing[0] + t * dx, root_trailing[1] + t * dy};
    append(s, convex_slab(mirrored(ellipse_outline(centre, along, 0.1, 0.06, 20)), z0, z1));
  }
  return s;
}

// A winged body, 1.46 long (x from -0.815 to 0.64, head forward at +x), 1.94 across the
// wings (y) and 0.24 high (z): an ellipsoidal body 1.0 long of radius 0.12 at the origin, a
// head (sphere of radius 0.09 at x = 0.55), a tail (capsule of radius 0.035 from x = -0.45
// to x = -0.78) and two thin flat wings (wing(): 0.03 thick, tips at y = +-0.97). The
// wings are thin sheets whose skeleton should be one chain through the middle of each wing.
inline Soup winged_body()
{
  Soup s = ellipsoid({0, 0, 0}, 0.5, 0.12, 0.12);
  append(s, icosphere(0.09, 3), 0.55, 0, 0.03);
  append(s, capsule({-0.45, 0, 0}, {-0.78, 0, 0}, 0.035));
  append(s, wing(1));
  append(s, wing(-1));
  return s;
}

// A humanoid in T-pose, 1.79 tall (z from 0.01 to 1.80), 1.77 across the hands (x), 0.32
// deep (y), from overlapping capsules and spheres: two straight legs (radius 0.07, x = +-0.12,
// z 0.08 to 0.85), a torso (radius 0.16, z 0.9 to 1.4), a neck (radius 0.05) and a head
// (sphere of radius 0.11 at z = 1.69), two straight horizontal arms (radius 0.05, from the
// shoulders at x = +-0.12 to x = +-0.75, z = 1.42) with hands (spheres of radius 0.065 at
// x = +-0.82). Straight limbs, no bends, on purpose.
inline Soup t_pose_figure()
{
  Soup s = capsule({0, 0, 0.9}, {0, 0, 1.4}, 0.16); // torso
  append(s, capsule({0, 0, 1.45}, {0, 0, 1.58}, 0.05)); // neck
  append(s, icosphere(0.11, 3), 0, 0, 1.69);           // head
  for(int side : {-1, 1})
  {
    append(s, capsule({side * 0.12, 0, 0.08}, {side * 0.12, 0, 0.85}, 0.07)); // leg
    append(s, capsule({side * 0.12, 0, 1.42}, {side * 0.75, 0, 1.42}, 0.05)); // arm
    append(s, icosphere(0.065, 2), side * 0.82, 0, 1.42);                      // hand
  }
  return s;
}

// A cape as game artists model it: one open sheet of quads, no thickness, 0.5 wide (x from
// -0.25 to 0.25) and 1.1 long, from the shoulders (z = 1.45, where its top edge runs into
// the torso, y = -0.12 at its middle) down to the knees (z = 0.35), hanging back from the
// body by up to 0.25 at the hem and curved across, its side edges 0.08 nearer the body than
// its middle line. An animator wants one chain down its middle.
inline Soup cape()
{
  const int across = 20, down = 44;
  Soup s;
  for(int i = 0; i <= down; ++i)
  {
    const double t = double(i) / down;
    for(int j = 0; j <= across; ++j)
    {
      const double x = -0.25 + 0.5 * j / across;
      s.add_point(x, -0.12 - 0.25 * std::pow(t, 0.6) + 0.04 * (1 - std::cos(pi * x / 0.25)), 1.45 - 1.1 * t);
    }
  }
  for(int i = 0; i < down; ++i)
    for(int j = 0; j < across; ++j)
    {
      const std::size_t a = std::size_t(i * (across + 1) + j);
      s.add_quad(a, a + 1, a + across + 2, a + across + 1);
    }
  return s;
}

// The T-pose figure wearing the cape: a closed body and an open sheet that runs into it.
inline Soup caped_figure()
{
  Soup s = t_pose_figure();
  append(s, cape());
  return s;
}

// A six-armed star, 1.24 across: three capsules of radius 0.1 crossed at the origin, along
// x, y and z, from -0.5 to 0.5, -0.51 to 0.51 and -0.52 to 0.52. Its principal axes are
// nearly equal, so its voxel frame turns a long way under a small change of the shape;
// each of the six arms should end in an end point whatever the frame.
inline Soup six_armed_star()
{
  Soup s = capsule({-0.5, 0, 0}, {0.5, 0, 0}, 0.1);
  append(s, capsule({0, -0.51, 0}, {0, 0.51, 0}, 0.1));
  append(s, capsule({0, 0, -0.52}, {0, 0, 0.52}, 0.1));
  return s;
}

// The outline of a starfish of `arms` arms turned by `turn`: its distance from the centre in
// the direction `angle`, in lengths of its arms (0.2 in the notches, 1 at the arms' ends).
inline double starfish_rim(int arms, double turn, double angle)
{
  return 0.6 + 0.4 * std::cos(arms * (angle - turn));
}

// The arm of that starfish nearest to the direction of (x, y) from its centre, and the angle
// from the arm's axis to that direction.
struct Starfish_arm
{
  int arm;
  double off_axis;
};
inline Starfish_arm starfish_arm(int arms, double turn, double x, double y)
{
  const double angle = std::atan2(y, x) - turn;
  const int arm = int(std::lround(angle * arms / (2 * pi) + arms)) % arms;
  return {arm, std::remainder(angle - arm * 2 * pi / arms, 2 * pi)};
}

// A thick starfish of `arms` arms, lens-shaped (a plush toy, a cushion with corners): in the
// plane z = 0 its outline is at 0.5 (0.6 + 0.4 cos(arms (angle - turn))) from the centre, and
// its half thickness falls linearly from 0.14 at the centre to 0 at the rim. One closed piece:
// a top and a bottom polar grid sharing the rim.
inline Soup thick_starfish(int arms, double turn)
{
  const int around = 24 * arms, rings = 16;
  const double half_thickness = 0.14;
  Soup s;
  auto point = [&](int ring, int k, int side) {
    const double angle = 2 * pi * k / around;
    const double t = double(ring) / rings, rim = 0.5 * starfish_rim(arms, turn, angle);
    return s.add_point(t * rim * std::cos(angle), t * rim * std::sin(angle), side * half_thickness * (1 - t));
  };
  const std::size_t top = point(0, 0, 1), bottom = point(0, 0, -1);
  std::vector<std::vector<std::size_t>> upper(rings + 1), lower(rings + 1);
  for(int ring = 1; ring <= rings; ++ring)
    for(int k = 0; k < around; ++k)
    {
      upper[std::size_t(ring)].push_back(point(ring, k, 1));
      lower[std::size_t(ring)].push_back(ring == rings ? upper[std::size_t(ring)].back() : point(ring, k, -1));
    }
  for(int k = 0; k < around; ++k)
  {
    const std::size_t a = std::size_t(k), b = std::size_t((k + 1) % around);
    s.add_triangle(top, upper[1][a], upper[1][b]);
    s.add_triangle(bottom, lower[1][b], lower[1][a]);
    for(std::size_t ring = 1; ring < std::size_t(rings); ++ring)
    {
      s.add_quad(upper[ring][a], upper[ring + 1][a], upper[ring + 1][b], upper[ring][b]);
      s.add_quad(lower[ring][b], lower[ring + 1][b], lower[ring + 1][a], lower[ring][a]);
    }
  }
  return s;
}

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_CHARACTERS_H
