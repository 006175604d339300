// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_READ_MESH_H
#define CGAL_GEODESIC_SKELETON_IO_READ_MESH_H

/// \file IO/read_mesh.h
/// Reads a mesh file as `skeletonize` does: any format CGAL reads, repaired when it is not
/// a clean manifold, with a clear error for a file that holds no usable mesh.

#include <CGAL/Geodesic_skeleton/IO/internal/fast_soup_readers.h>
#include <CGAL/Geodesic_skeleton/IO/internal/indexed_soup.h>
#include <CGAL/Geodesic_skeleton/IO/internal/mesh_file_checks.h>
#include <CGAL/Geodesic_skeleton/IO/internal/soup_to_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

// Whether `path` is a binary STL file with a non-finite vertex coordinate. CGAL's STL
// reader merges the corners of the triangles by comparing points, and a NaN compares equal
// to any point there: a NaN corner would silently become another vertex. So binary STL
// files (an 80-byte header, a 32-bit count, 50 bytes per triangle) are scanned first.
inline bool binary_STL_has_non_finite_coordinate(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char header[80];
  unsigned char count_bytes[4];
  if(file_extension(path) != "stl" || !in.read(header, 80) || !in.read(reinterpret_cast<char*>(count_bytes), 4))
    return false;
  const std::uint64_t count = count_bytes[0] | (count_bytes[1] << 8) | (count_bytes[2] << 16) |
                              (std::uint64_t(count_bytes[3]) << 24);
  in.seekg(0, std::ios::end);
  if(std::uint64_t(in.tellg()) != 84 + 50 * count) // not binary STL: the text reader parses it
    return false;
  in.seekg(84);
  static_assert(sizeof(float) == 4, "STL stores 32-bit floats");
  char record[50];
  for(std::uint64_t t = 0; t < count && in.read(record, 50); ++t)
    for(int c = 3; c < 12; ++c) // the normal (floats 0-2) is not read
    {
      float value; // little-endian, as on every platform CGAL's binary STL reader supports
      std::memcpy(&value, record + 4 * c, 4);
      if(!std::isfinite(value))
        return true;
    }
  return false;
}

// Reads `path` with CGAL's readers, after the checks of mesh_file_checks.h that keep CGAL's
// readers from files they mishandle; throws "PATH: problem" when the file does not parse.
// The soup's coordinates and indices are checked after, by polygon_soup_to_checked_mesh().
template <typename Point>
void read_soup_with_CGAL(const std::string& path, std::vector<Point>& points,
                         std::vector<std::vector<std::size_t>>& polygons)
{
  auto fail = [&](const std::string& problem) { throw std::runtime_error(path + ": " + problem); };
  if(binary_STL_has_non_finite_coordinate(path))
    fail("a vertex has a non-finite coordinate (NaN or infinite)");
  if(file_extension(path) == "ply")
    if(const std::string problem = ply_header_problem(path); !problem.empty())
      fail("the file cannot be parsed as a mesh: " + problem);
  if(file_extension(path) == "off")
    if(const std::string problem = off_file_problem(path); !problem.empty())
      fail("the file cannot be parsed as a mesh: " + problem);
  // Read the soup first, so that its indices and coordinates are checked before CGAL builds
  // anything from them (a face index past the vertices would be read out of bounds).
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    fail("the file cannot be parsed as a mesh (OFF, OBJ, PLY, STL, ...)");
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Reads the mesh file `path` (OFF, OBJ, PLY, STL, ...: any format CGAL reads, by its
/// extension) into `mesh` (cleared first). A file that is not a clean manifold (as artists'
/// meshes often are: non-manifold edges or vertices, duplicated faces, inconsistent
/// orientation) is read as a polygon soup, repaired (`repair_polygon_soup()`: duplicated
/// and degenerate polygons go), oriented (`orient_polygon_soup()`: non-manifold vertices and
/// edges are split) and turned into a mesh. Before CGAL's readers see it, a PLY header and
/// an ASCII OFF file are checked for what those readers trust (element and face counts,
/// face sizes and indices, property types, colours): files the package's fuzzer found to
/// crash, hang or overrun them are refused with the reason (see `fuzz/README.md`).
///
/// The common forms are read by the package's own fast readers (plain ASCII OFF, OBJ,
/// little-endian binary STL): the file in one read, numbers parsed without streams, and,
/// when the faces already form an oriented manifold mesh (checked in linear time), the
/// mesh built directly from them. Any other form, and any file they find a problem in,
/// goes through CGAL's readers and the checks above; both paths give the same mesh, with
/// point i of the file as vertex i and face j as face j.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with a vertex point map
///         (`Surface_mesh`, `Polyhedron_3`, ...).
/// \returns true when the mesh's vertex i is the file's point i for every point (the fast
///          readers' direct path); false when the repair may have merged, split or dropped
///          points, so that a vertex is found by its position.
/// \throws std::runtime_error with a message "PATH: problem" when the file cannot be
///         opened, cannot be parsed (empty, garbage, wrong counts), has a non-finite
///         coordinate or a face that refers to a vertex that does not exist, or holds no
///         face.
///
/// \b Complexity: linear in the size of the file for a manifold mesh in a common form;
/// O(n log n) otherwise (CGAL's readers and repair).
template <typename PolygonMesh>
bool read_mesh(const std::string& path, PolygonMesh& mesh)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  if(!std::ifstream(path))
    throw std::runtime_error(path + ": cannot open the file");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  internal::Indexed_soup soup;
  if(internal::read_soup_fast(path, internal::file_extension(path), soup))
  {
    const internal::Directed_edge_table edges(soup);
    if(internal::is_oriented_manifold(soup, edges))
    {
      internal::build_mesh_from_manifold_soup(soup, edges, mesh, get(CGAL::vertex_point, mesh));
      return true;
    }
    points.reserve(soup.points.size());
    for(const auto& p : soup.points)
      points.emplace_back(p[0], p[1], p[2]);
    polygons.resize(soup.number_of_polygons());
    for(std::size_t f = 0; f < polygons.size(); ++f)
      polygons[f].assign(soup.corners.begin() + soup.offsets[f], soup.corners.begin() + soup.offsets[f + 1]);
  }
  else
    internal::read_soup_with_CGAL(path, points, polygons);
  internal::polygon_soup_to_checked_mesh(path, points, polygons, mesh);
  return false;
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_READ_MESH_H
