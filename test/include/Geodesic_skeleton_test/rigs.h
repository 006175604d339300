// Skinning rigs that the tests build themselves: a skeleton given by hand, a bar and its
// two-bone skeleton, and the weights of a mesh in a vector.

#ifndef GEODESIC_SKELETON_TEST_RIGS_H
#define GEODESIC_SKELETON_TEST_RIGS_H

#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Geodesic_skeleton_test/shapes.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace Geodesic_skeleton_test {

namespace gs = CGAL::Geodesic_skeleton;
using Rig_point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Rig_mesh = CGAL::Surface_mesh<Rig_point>;
using Rig_skeleton = gs::Control_skeleton<Rig_point>;
// A skeleton given by hand: a chain of joints along `points`, one bone between each two,
// bones without points (the segment from parent to child is used), added to `skeleton`.
inline Rig_skeleton chain_skeleton(const std::vector<Rig_point>& points, Rig_skeleton skeleton = Rig_skeleton())
{
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    gs::Control_joint<Rig_point> joint;
    joint.point = points[i];
    joint.kind = i == 0 ? gs::Joint_kind::root : i + 1 == points.size() ? gs::Joint_kind::end : gs::Joint_kind::bend;
    const std::size_t j = add_vertex(joint, skeleton);
    if(i == 0)
      skeleton[boost::graph_bundle].roots.push_back(j);
    else
      add_edge(j - 1, j, skeleton);
  }
  return skeleton;
}

// A capped bar of radius 1 along z from 0 to 20, and two bones: 0 from z=0 to z=10, 1 from
// z=10 to z=20.
inline Rig_mesh bar() { return mesh_of<Rig_mesh>(cylinder(1, 20, 24, 46, true)); }
inline Rig_skeleton bar_skeleton()
{
  return chain_skeleton({Rig_point(0, 0, 0), Rig_point(0, 0, 10), Rig_point(0, 0, 20)});
}

// A demo mesh (e.g. "cow.off") and the control skeleton extract_control_skeleton() gives it.
struct Rigged_mesh
{
  Rig_mesh mesh;
  Rig_skeleton skeleton;
};
inline Rigged_mesh demo_mesh_with_skeleton(const std::string& name)
{
  Rigged_mesh r{demo_mesh<Rig_mesh>(name), Rig_skeleton()};
  gs::extract_control_skeleton(r.mesh, r.skeleton);
  return r;
}

template <typename NamedParameters>
std::vector<gs::Bone_weights> weights_of(const Rig_mesh& mesh, const Rig_skeleton& skeleton, const NamedParameters& np,
                                         gs::Skinning_report* report = nullptr)
{
  std::vector<gs::Bone_weights> weights(num_vertices(mesh));
  const gs::Skinning_report r = gs::compute_skinning_weights(
      mesh, skeleton, boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, mesh)), np);
  if(report)
    *report = r;
  return weights;
}

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_RIGS_H
