// skinning_benchmark: the cost of compute_skinning_weights() against extract_control_skeleton()
// on the closed demo meshes, at the same resolution, in the same run; and on a mesh of about
// a million faces (armadillo.off, Loop-subdivided twice here). Per mesh: vertices, faces,
// bones, the median times (ms) of the skeleton and of the weights and their ratio, the same
// with the skeleton's solid handed to the weights (as skeletonize does), the solid's voxels,
// the voxels the bones' bounded searches visit per solid voxel (the bones that reach a voxel,
// on average), and the bones per vertex.
//
//   skinning_benchmark [DATA_DIR] [--repeats N] [--meshes a,b] [--resolution R] [--no-large]

#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <boost/property_map/property_map.hpp>

#include "benchmark_common.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

using benchmark_common::median;

namespace {

template <typename Function>
double median_ms(int repeats, Function f)
{
  std::vector<double> ms;
  for(int r = 0; r < repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    f();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return median(ms);
}

void run(const std::string& name, const Mesh& mesh, int repeats, int resolution)
{
  gs::Control_skeleton<Point> control;
  const double skeleton_ms =
      median_ms(repeats, [&] { gs::extract_control_skeleton(mesh, control, params::resolution(resolution)); });
  std::vector<gs::Bone_weights> weights(num_vertices(mesh));
  const auto weight_map = boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, mesh));
  gs::Skinning_report report;
  const double weights_ms = median_ms(repeats, [&] {
    report = gs::compute_skinning_weights(mesh, control, weight_map, params::resolution(resolution));
  });
  // As skeletonize skins its own skeleton: the chain hands its solid to the weights (the
  // chain's time with the copy of its grid).
  gs::Dense_voxel_grid solid;
  const double skeleton_with_solid_ms = median_ms(repeats, [&] {
    gs::extract_control_skeleton(mesh, control,
                                 params::combine(params::resolution(resolution), params::voxelized_solid(&solid)));
  });
  const double weights_given_solid_ms = median_ms(repeats, [&] {
    gs::compute_skinning_weights(mesh, control, weight_map,
                                 params::combine(params::resolution(resolution), params::voxelized_solid(&std::as_const(solid))));
  });
  double influences = 0;
  for(const gs::Bone_weights& w : weights)
    influences += double(w.size());
  std::cout << "| " << name << " | " << num_vertices(mesh) << " | " << num_faces(mesh) << " | "
            << num_edges(control) << " | " << skeleton_ms << " | " << weights_ms << " | "
            << weights_ms / skeleton_ms << " | " << weights_given_solid_ms << " | "
            << weights_given_solid_ms / skeleton_with_solid_ms << " | " << report.solid_voxels << " | "
            << double(report.voxel_visits) / double(report.solid_voxels) << " | "
            << influences / double(num_vertices(mesh)) << " |" << std::endl;
}

} // namespace

int main(int argc, char* argv[])
{
  benchmark_common::Options options =
      benchmark_common::default_options(GEODESIC_SKELETON_DATA_DIR, gs::default_voxel_resolution);
  if(!benchmark_common::parse_options(argc, argv, "--no-large", options))
    return 2;
  const std::string& data_dir = options.data_dir;
  const int repeats = options.repeats, resolution = options.resolution;
  const bool large = !options.flag;

  std::cout << std::fixed << std::setprecision(2);
  std::cout << "resolution " << resolution << ", median of " << repeats << " runs\n\n"
            << "| mesh | vertices | faces | bones | skeleton ms | weights ms | weights/skeleton"
               " | weights given the chain's solid ms | that/skeleton | solid voxels"
               " | visits per voxel | bones per vertex |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& name : options.names)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(data_dir + "/" + name + ".off", mesh) || num_vertices(mesh) == 0)
    {
      std::cerr << "skinning_benchmark: cannot read " << data_dir << "/" << name << ".off\n";
      return 1;
    }
    run(name, mesh, repeats, resolution);
  }
  if(large)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(data_dir + "/armadillo.off", mesh))
    {
      std::cerr << "skinning_benchmark: cannot read armadillo.off\n";
      return 1;
    }
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
    run("armadillo, Loop x2", mesh, std::min(repeats, 3), resolution);
  }
  return 0;
}
