// Helpers of the voxel-stage tests: the voxel pipeline in one call, and independent
// measures of a voxel set's topology and of a skeleton graph's shape.

#ifndef GEODESIC_SKELETON_TEST_VOXEL_SKELETON_H
#define GEODESIC_SKELETON_TEST_VOXEL_SKELETON_H

#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <Geodesic_skeleton_test/shapes.h>

#include <CGAL/Aff_transformation_3.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <unordered_set>
#include <vector>

namespace Geodesic_skeleton_test {

namespace gs = CGAL::Geodesic_skeleton;

// The voxels of `box` (identity frame) whose keys satisfy `inside`, in a set of type VoxelSet.
template <typename VoxelSet>
VoxelSet voxels_where(const gs::Voxel_box& box, const std::function<bool(int, int, int)>& inside)
{
  VoxelSet s;
  s.reset(gs::Voxel_frame(), box);
  for(int z = box.min.z; z < box.max.z; ++z)
    for(int y = box.min.y; y < box.max.y; ++y)
      for(int x = box.min.x; x < box.max.x; ++x)
        if(inside(x, y, z))
          s.insert(gs::Voxel_key{x, y, z});
  return s;
}

// The largest of the sheet radii that thin() recorded, 0 when there are none.
inline double largest_sheet_radius(const gs::Sheet_radii& radii)
{
  double largest = 0;
  for(const auto& [k, radius] : radii)
    largest = (std::max)(largest, radius);
  return largest;
}

// The keys of a voxel set, ordered.
template <typename VoxelSet>
std::set<gs::Voxel_key> keys_of(const VoxelSet& s)
{
  std::set<gs::Voxel_key> keys;
  s.for_each([&](const gs::Voxel_key& k) { keys.insert(k); });
  return keys;
}

// A random rotation (a uniform random unit quaternion) followed by the translation (tx, ty, tz).
template <typename Kernel>
CGAL::Aff_transformation_3<Kernel> random_rigid_motion(unsigned seed, double tx, double ty, double tz)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  double q[4], n = 0;
  for(double& c : q)
  {
    c = normal(random);
    n += c * c;
  }
  for(double& c : q)
    c /= std::sqrt(n);
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return CGAL::Aff_transformation_3<Kernel>(
      1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), tx,
      2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), ty,
      2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), tz);
}

// Euler characteristic of the union of the closed unit cubes of the voxels (the topology
// of a 26-connected set): vertices - edges + faces - cubes, counted on the doubled grid.
template <typename VoxelSet>
long euler_characteristic(const VoxelSet& voxels)
{
  auto pack = [](long x, long y, long z) {
    return std::uint64_t((x + (1 << 20)) & 0x1FFFFF) << 42 | std::uint64_t((y + (1 << 20)) & 0x1FFFFF) << 21 |
           std::uint64_t((z + (1 << 20)) & 0x1FFFFF);
  };
  std::unordered_set<std::uint64_t> cells[3]; // vertices, edges, faces (by dimension)
  long cubes = 0;
  voxels.for_each([&](const gs::Voxel_key& k) {
    ++cubes;
    for(int dx = 0; dx <= 2; ++dx)
      for(int dy = 0; dy <= 2; ++dy)
        for(int dz = 0; dz <= 2; ++dz)
        {
          const int dim = (dx == 1) + (dy == 1) + (dz == 1);
          if(dim < 3)
            cells[dim].insert(pack(2 * k.x + dx, 2 * k.y + dy, 2 * k.z + dz));
        }
  });
  return long(cells[0].size()) - long(cells[1].size()) + long(cells[2].size()) - cubes;
}

// The number of 26-components of a voxel set.
template <typename VoxelSet>
int components_26(const VoxelSet& voxels)
{
  std::unordered_set<gs::Voxel_key, gs::Voxel_key_hash> left;
  voxels.for_each([&](const gs::Voxel_key& k) { left.insert(k); });
  int count = 0;
  std::vector<gs::Voxel_key> stack;
  while(!left.empty())
  {
    ++count;
    stack.push_back(*left.begin());
    left.erase(left.begin());
    while(!stack.empty())
    {
      const gs::Voxel_key k = stack.back();
      stack.pop_back();
      for(const gs::Voxel_key& o : gs::neighbourhood_26())
      {
        auto it = left.find(k + o);
        if(it != left.end())
        {
          stack.push_back(*it);
          left.erase(it);
        }
      }
    }
  }
  return count;
}

template <typename Graph>
int graph_components(const Graph& g)
{
  std::vector<int> component(num_vertices(g));
  return num_vertices(g) == 0 ? 0 : int(boost::connected_components(g, component.data()));
}

// Independent cycles of a graph: E - V + C.
template <typename Graph>
long graph_cycles(const Graph& g)
{
  return long(num_edges(g)) - long(num_vertices(g)) + graph_components(g);
}

// The voxel stages in a row, on any voxel set model.
template <typename Mesh, typename VoxelSet>
struct Voxel_pipeline
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Skeleton = gs::Curve_skeleton<Point, vertex_descriptor>;

  VoxelSet voxels;
  std::size_t solid_size = 0;
  long solid_euler = 0;
  gs::Voxel_distance_field distances;
  Skeleton graph;

  Voxel_pipeline(const Mesh& mesh, int resolution)
  {
    solid_size = gs::voxelize(mesh, voxels, gs::parameters::resolution(resolution));
    solid_euler = euler_characteristic(voxels);
    distances = gs::distance_transform(voxels);
    gs::thin(voxels, distances);
    gs::to_graph(voxels, distances, mesh, graph);
  }

  double voxel_size() const { return voxels.frame().voxel_size(); }
};

template <typename Point>
double squared_distance_3(const Point& a, const Point& b)
{
  const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
  return dx * dx + dy * dy + dz * dz;
}

// Hausdorff distance between two point sets (brute force; skeletons are small).
template <typename Points>
double hausdorff(const Points& a, const Points& b)
{
  auto one_sided = [](const Points& p, const Points& q) {
    double worst = 0;
    for(const auto& x : p)
    {
      double best = std::numeric_limits<double>::infinity();
      for(const auto& y : q)
        best = (std::min)(best, squared_distance_3(x, y));
      worst = (std::max)(worst, best);
    }
    return std::sqrt(worst);
  };
  return (std::max)(one_sided(a, b), one_sided(b, a));
}

template <typename Graph>
auto skeleton_points(const Graph& g)
{
  std::vector<decltype(g[0].point)> points;
  for(auto v : boost::make_iterator_range(vertices(g)))
    points.push_back(g[v].point);
  return points;
}

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_VOXEL_SKELETON_H
