// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_INTERNAL_SOUP_TO_MESH_H
#define CGAL_GEODESIC_SKELETON_IO_INTERNAL_SOUP_TO_MESH_H

// The last step of the package's mesh readers (IO::read_mesh(), IO::read_mesh_with_assimp()):
// a polygon soup, read from a file by any means, checked and turned into a mesh, repaired
// when it is not a clean manifold.

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

// Fills `mesh` (cleared first) with the soup `points` and `polygons` read from `path`:
// checks that every coordinate is finite, every index names a point and there is a face
// (std::runtime_error "PATH: problem" otherwise), then builds the mesh directly when the
// soup is a polygon mesh, else after repair_polygon_soup() and orient_polygon_soup().
template <typename Point, typename PolygonMesh>
void polygon_soup_to_checked_mesh(const std::string& path, std::vector<Point>& points,
                                  std::vector<std::vector<std::size_t>>& polygons, PolygonMesh& mesh)
{
  auto fail = [&](const std::string& problem) { throw std::runtime_error(path + ": " + problem); };
  auto finite = [](const Point& p) {
    return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
           std::isfinite(CGAL::to_double(p.z()));
  };
  for(const Point& p : points)
    if(!finite(p))
      fail("a vertex has a non-finite coordinate (NaN or infinite)");
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i >= points.size())
        fail("a face refers to vertex " + std::to_string(i) + ", but the file has only " +
             std::to_string(points.size()) + " vertices");
  if(polygons.empty())
    fail("the mesh has no faces");
  clear(mesh);
  if(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    return;
  }
  CGAL::Polygon_mesh_processing::repair_polygon_soup(points, polygons);
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(num_faces(mesh) == 0)
    fail("the mesh has no faces (every face is degenerate)");
}

} // namespace internal
} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_INTERNAL_SOUP_TO_MESH_H
