// Small synthetic shapes that the tests build themselves (no third-party meshes), and the
// loader of Debian's demo meshes. Every builder fills any FaceGraph through a polygon soup.

#ifndef GEODESIC_SKELETON_TEST_SHAPES_H
#define GEODESIC_SKELETON_TEST_SHAPES_H

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_skeleton_test {

constexpr double pi = 3.14159265358979323846;

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;

  std::size_t add_point(double x, double y, double z)
  {
    points.push_back({x, y, z});
    return points.size() - 1;
  }
  void add_triangle(std::size_t a, std::size_t b, std::size_t c) { faces.push_back({a, b, c}); }
  // Two triangles of the quad a-b-c-d (counter-clockwise seen from outside).
  void add_quad(std::size_t a, std::size_t b, std::size_t c, std::size_t d)
  {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }
};

// Converts a soup into `mesh` (cleared first), for any FaceGraph.
template <typename Mesh>
void soup_to_mesh(const Soup& soup, Mesh& mesh)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.faces, mesh);
}

// Splits every triangle of `s` into four at its edges: `edge_point(p, q)` adds the point
// that splits the edge p-q to `s` and returns its index (once per edge).
template <typename EdgePoint>
void split_in_four(Soup& s, EdgePoint edge_point)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> point_of_edge;
  auto split_point = [&](std::size_t a, std::size_t b) {
    const std::pair<std::size_t, std::size_t> edge((std::min)(a, b), (std::max)(a, b));
    if(const auto known = point_of_edge.find(edge); known != point_of_edge.end())
      return known->second;
    const std::array<double, 3> p = s.points[a], q = s.points[b]; // copies: adding a point may move them
    return point_of_edge[edge] = edge_point(p, q);
  };
  std::vector<std::vector<std::size_t>> finer;
  for(const auto& f : s.faces)
  {
    const std::size_t ab = split_point(f[0], f[1]), bc = split_point(f[1], f[2]), ca = split_point(f[2], f[0]);
    finer.push_back({f[0], ab, ca});
    finer.push_back({f[1], bc, ab});
    finer.push_back({f[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  s.faces.swap(finer);
}

// An icosahedron whose faces are split `subdivisions` times into 4, projected on the sphere.
inline Soup icosphere(double radius, int subdivisions)
{
  Soup s;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double base[12][3] = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t},  {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  auto add_on_sphere = [&](double x, double y, double z) {
    const double n = std::sqrt(x * x + y * y + z * z);
    return s.add_point(radius * x / n, radius * y / n, radius * z / n);
  };
  for(const auto& p : base)
    add_on_sphere(p[0], p[1], p[2]);
  s.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9},  {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6},  {3, 6, 8},
             {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for(int level = 0; level < subdivisions; ++level)
    split_in_four(s, [&](const std::array<double, 3>& p, const std::array<double, 3>& q) {
      return add_on_sphere(p[0] + q[0], p[1] + q[1], p[2] + q[2]);
    });
  return s;
}

// A cylinder of axis z from z=0 to z=height: `along`+1 rings of `around` vertices, every
// other ring turned by half a step, so that rings spaced by sqrt(3)/2 of the vertex spacing
// give equilateral triangles. Closed by two fans when `capped`.
inline Soup cylinder(double radius, double height, int around, int along, bool capped)
{
  Soup s;
  for(int j = 0; j <= along; ++j)
    for(int i = 0; i < around; ++i)
    {
      const double a = 2 * pi * (i + 0.5 * (j % 2)) / around;
      s.add_point(radius * std::cos(a), radius * std::sin(a), height * j / along);
    }
  auto at = [&](int i, int j) { return static_cast<std::size_t>(j * around + (i % around)); };
  for(int j = 0; j < along; ++j)
    for(int i = 0; i < around; ++i)
    {
      if(j % 2 == 0) // the upper ring is shifted forward by half a step
      {
        s.add_triangle(at(i, j), at(i + 1, j), at(i, j + 1));
        s.add_triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
      else // the lower ring is shifted forward
      {
        s.add_triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        s.add_triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      }
    }
  if(capped)
  {
    const std::size_t bottom = s.add_point(0, 0, 0), top = s.add_point(0, 0, height);
    for(int i = 0; i < around; ++i)
    {
      s.add_triangle(bottom, at(i + 1, 0), at(i, 0));
      s.add_triangle(top, at(i, along), at(i + 1, along));
    }
  }
  return s;
}

// A torus around the z axis: `major` radius of the centre circle, `minor` of the tube.
inline Soup torus(double major, double minor, int around_major, int around_minor)
{
  Soup s;
  for(int i = 0; i < around_major; ++i)
    for(int j = 0; j < around_minor; ++j)
    {
      const double u = 2 * pi * i / around_major, v = 2 * pi * j / around_minor;
      const double r = major + minor * std::cos(v);
      s.add_point(r * std::cos(u), r * std::sin(u), minor * std::sin(v));
    }
  auto at = [&](int i, int j) {
    return static_cast<std::size_t>((i % around_major) * around_minor + (j % around_minor));
  };
  for(int i = 0; i < around_major; ++i)
    for(int j = 0; j < around_minor; ++j)
      s.add_quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return s;
}

// An axis-aligned box, 12 triangles.
inline Soup box(double x0, double y0, double z0, double x1, double y1, double z1)
{
  Soup s;
  for(int k = 0; k < 8; ++k)
    s.add_point(k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? z1 : z0);
  s.add_quad(0, 2, 3, 1); // z0
  s.add_quad(4, 5, 7, 6); // z1
  s.add_quad(0, 1, 5, 4); // y0
  s.add_quad(2, 6, 7, 3); // y1
  s.add_quad(0, 4, 6, 2); // x0
  s.add_quad(1, 3, 7, 5); // x1
  return s;
}

// Appends `other` to `s` (disjoint union), e.g. two spheres side by side.
inline void append(Soup& s, const Soup& other, double dx = 0, double dy = 0, double dz = 0)
{
  const std::size_t offset = s.points.size();
  for(const auto& p : other.points)
    s.add_point(p[0] + dx, p[1] + dy, p[2] + dz);
  for(auto f : other.faces)
  {
    for(auto& i : f)
      i += offset;
    s.faces.push_back(f);
  }
}

// Path of a demo mesh of Debian's libcgal-demo, unpacked into the build tree by CMake.
inline std::string demo_mesh_path(const std::string& name)
{
  return std::string(GEODESIC_SKELETON_DATA_DIR) + "/" + name;
}

// Reads a demo mesh (e.g. "cow.off") into any FaceGraph; throws when it cannot.
template <typename Mesh>
void read_demo_mesh(const std::string& name, Mesh& mesh)
{
  const std::string path = demo_mesh_path(name);
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_vertices(mesh) == 0)
    throw std::runtime_error("cannot read the demo mesh " + path +
                             " (run scripts/unpack_demo_meshes.sh)");
}

// The mesh of a soup, by value.
template <typename Mesh>
Mesh mesh_of(const Soup& soup)
{
  Mesh mesh;
  soup_to_mesh(soup, mesh);
  return mesh;
}

// A demo mesh, by value.
template <typename Mesh>
Mesh demo_mesh(const std::string& name)
{
  Mesh mesh;
  read_demo_mesh(name, mesh);
  return mesh;
}

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_SHAPES_H
