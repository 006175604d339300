// The joints of a control skeleton as a vector of their bundles, in vertex order (what the
// tests' range-for loops over joints read), and a joint's parent as the file formats write it.

#ifndef GEODESIC_SKELETON_TEST_JOINTS_H
#define GEODESIC_SKELETON_TEST_JOINTS_H

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <cstddef>
#include <vector>

namespace Geodesic_skeleton_test {

template <typename Point>
std::vector<CGAL::Geodesic_skeleton::Control_joint<Point>>
joints(const CGAL::Geodesic_skeleton::Control_skeleton<Point>& skeleton)
{
  std::vector<CGAL::Geodesic_skeleton::Control_joint<Point>> out;
  for(const auto v : boost::make_iterator_range(vertices(skeleton)))
    out.push_back(skeleton[v]);
  return out;
}

// The parent of joint `j` as the file formats write it: its index, or -1 for a root.
template <typename Point>
long parent_index(const CGAL::Geodesic_skeleton::Control_skeleton<Point>& skeleton, std::size_t j)
{
  const auto parent = CGAL::Geodesic_skeleton::parent_joint(j, skeleton);
  return parent == boost::graph_traits<CGAL::Geodesic_skeleton::Control_skeleton<Point>>::null_vertex() ? -1L
                                                                                                      : long(parent);
}

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_JOINTS_H
