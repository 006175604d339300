// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_JSON_H
#define CGAL_GEODESIC_SKELETON_IO_JSON_H

/// \file IO/json.h
/// JSON views of skeletons (nlohmann::json), with the keys of the `skeletonize` contract.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <CGAL/number_utils.h>

#include <boost/graph/adjacency_list.hpp>
#include <nlohmann/json.hpp>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {

/// \ingroup PkgGeodesicSkeletonRef
/// The JSON array `[x, y, z]` of a point.
template <typename Point>
nlohmann::json point_to_json(const Point& p)
{
  return nlohmann::json::array({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
}

/// \ingroup PkgGeodesicSkeletonRef
/// A control skeleton as JSON:
/// `{"joints": [{"position": [x, y, z], "radius": r, "parent": p, "kind": "root"}, ...],
///   "bones": [[parent, child], ...], "cut_bones": [[a, b], ...], "roots": [i, ...]}`;
/// joint indices are vertex indices, bones in the order of `edges(skeleton)`, `parent` is -1
/// for a root.
/// \b Complexity: O(J + B) for J joints and B bones.
template <typename Point>
nlohmann::json control_skeleton_to_json(const Control_skeleton<Point>& skeleton)
{
  nlohmann::json joints = nlohmann::json::array(), bones = nlohmann::json::array(),
                 cut = nlohmann::json::array();
  for(const auto v : boost::make_iterator_range(vertices(skeleton)))
  {
    const Control_joint<Point>& j = skeleton[v];
    const auto parent = parent_joint(v, skeleton);
    joints.push_back({{"position", point_to_json(j.point)},
                      {"radius", j.radius},
                      {"parent", parent == boost::graph_traits<Control_skeleton<Point>>::null_vertex() ? -1L : long(parent)},
                      {"kind", to_string(j.kind)}});
  }
  for(const auto e : boost::make_iterator_range(edges(skeleton)))
    bones.push_back({source(e, skeleton), target(e, skeleton)});
  const Control_skeleton_property<Point>& forest = skeleton[boost::graph_bundle];
  for(const Control_cut_bone<Point>& b : forest.cut_bones)
    cut.push_back({b.source, b.target});
  return {{"joints", joints}, {"bones", bones}, {"cut_bones", cut}, {"roots", forest.roots}};
}

/// \ingroup PkgGeodesicSkeletonRef
/// A curve skeleton (a `vecS` adjacency list whose vertex bundle has `point` and `radius`,
/// e.g. `Curve_skeleton`) as JSON: `{"points": [[x, y, z], ...], "radii": [r, ...],
/// "edges": [[a, b], ...]}`. \b Complexity: O(V + E).
template <typename CurveSkeleton>
nlohmann::json curve_skeleton_to_json(const CurveSkeleton& skeleton)
{
  nlohmann::json points = nlohmann::json::array(), radii = nlohmann::json::array(),
                 edges_json = nlohmann::json::array();
  for(std::size_t v = 0; v < num_vertices(skeleton); ++v)
  {
    points.push_back(point_to_json(skeleton[v].point));
    radii.push_back(skeleton[v].radius);
  }
  for(auto e : boost::make_iterator_range(edges(skeleton)))
    edges_json.push_back({static_cast<std::size_t>(source(e, skeleton)), static_cast<std::size_t>(target(e, skeleton))});
  return {{"points", points}, {"radii", radii}, {"edges", edges_json}};
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_JSON_H
