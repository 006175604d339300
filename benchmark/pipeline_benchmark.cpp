// pipeline_benchmark: extract_control_skeleton against CGAL's mean curvature flow
// skeletonization (CGAL::extract_mean_curvature_flow_skeleton), in the same run, on the
// closed demo meshes. Per mesh: vertices, our time and MCF's (ms) and their ratio; our
// bones and MCF's skeleton vertices, ends and junctions; the fraction of our joints inside
// the mesh; and for both the coverage: the 95th percentile, over the mesh vertices, of the
// distance to the nearest bone (ours: the polylines of the bones) or skeleton edge (MCF),
// divided by the diagonal of the mesh's bounding box (lower is better).
//
//   pipeline_benchmark [DATA_DIR] [--repeats N] [--meshes a,b] [--resolution R] [--no-mcf]
//
// Also prints the paper's Table 1 and Table 2 on our meshes: points of the Reeb-graph
// skeleton against points of the pruned skeleton, and control segments of the pruned
// skeleton (its branches) against bones of the smoothed, split skeleton.

#include <CGAL/Geodesic_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_branches.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>

#include "benchmark_common.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Mcf = CGAL::Mean_curvature_flow_skeletonization<Mesh>;
using Segment = std::pair<Point, Point>;

using benchmark_common::median;

namespace {

double now_ms()
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double segment_distance(const Point& p, const Segment& s)
{
  const Kernel::Vector_3 d = s.second - s.first;
  const double l2 = d.squared_length();
  double t = l2 > 0 ? ((p - s.first) * d) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::sqrt(CGAL::squared_distance(p, s.first + t * d));
}

// 95th percentile over the mesh vertices of the distance to the nearest segment, over the
// bounding-box diagonal.
double coverage(const Mesh& mesh, const std::vector<Segment>& segments)
{
  if(segments.empty())
    return 1.0;
  std::vector<double> d;
  d.reserve(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    double best = 1e300;
    for(const Segment& s : segments)
      best = std::min(best, segment_distance(mesh.point(v), s));
    d.push_back(best);
  }
  std::sort(d.begin(), d.end());
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                                    std::pow(box.zmax() - box.zmin(), 2));
  return d[std::min(d.size() - 1, std::size_t(0.95 * double(d.size())))] / diagonal;
}

struct Our_run
{
  double ms = 0;
  gs::Control_skeleton<Point> control;
  gs::Control_skeleton_report report;
  gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor> curve;
  gs::Reeb_graph<Mesh> reeb;
};

} // namespace

int main(int argc, char* argv[])
{
  benchmark_common::Options options =
      benchmark_common::default_options(GEODESIC_SKELETON_DATA_DIR, gs::default_voxel_resolution);
  if(!benchmark_common::parse_options(argc, argv, "--no-mcf", options))
    return 2;
  const std::string& data_dir = options.data_dir;
  const int repeats = options.repeats, resolution = options.resolution;
  const bool run_mcf = !options.flag;
  const std::vector<std::string>& names = options.names;

  std::cout << std::fixed << std::setprecision(2);
  std::cout << "| mesh | vertices | ours ms | MCF ms | MCF/ours | our bones | MCF vertices | MCF ends | MCF junctions"
               " | our joints inside | our coverage | MCF coverage |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::ostringstream tables;
  tables << "\n| mesh | Reeb graph points | pruned skeleton points | thinned points | pruned junctions"
            " | Reeb ms | pruning ms | pruned segments | bones (smoothed, split) |\n"
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  // Where our time goes: the median over the timed runs of each stage's time.
  const std::vector<std::string> stages = {"voxelize", "distance_transform", "thin", "thinned_graph",
                                           "remove_small_pieces", "cut_spurious_cycles", "prune", "to_graph",
                                           "smooth", "curve_points_inside", "split_into_bones"};
  std::ostringstream stage_table;
  stage_table << "\n| mesh |";
  for(const std::string& stage : stages)
    stage_table << " " << stage << " ms |";
  stage_table << "\n|---|";
  for(std::size_t k = 0; k < stages.size(); ++k)
    stage_table << "---:|";
  stage_table << "\n" << std::fixed << std::setprecision(2);
  std::vector<double> ratios;
  for(const std::string& name : names)
  {
    Mesh mesh;
    const std::string path = data_dir + "/" + name + ".off";
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "skipping " << path << " (unreadable, open or not triangulated)\n";
      continue;
    }

    // Ours: the median of `repeats` runs of the default pipeline.
    Our_run ours;
    std::vector<double> times;
    std::vector<std::vector<double>> stage_times(stages.size());
    for(int r = 0; r < repeats; ++r)
    {
      const double t0 = now_ms();
      ours.report = gs::extract_control_skeleton(mesh, ours.control, gs::parameters::resolution(resolution));
      times.push_back(now_ms() - t0);
      for(const auto& [stage, ms] : ours.report.timings_ms)
        for(std::size_t k = 0; k < stages.size(); ++k)
          if(stage == stages[k])
            stage_times[k].push_back(ms);
    }
    ours.ms = median(times);
    stage_table << "| " << name << " |";
    for(auto& t : stage_times)
      stage_table << " " << (t.empty() ? 0.0 : median(t)) << " |";
    stage_table << "\n";
    // Once more for the intermediate outputs and the Reeb graph's time (not timed).
    const gs::Control_skeleton_report with_reeb = gs::extract_control_skeleton(
        mesh, ours.control,
        gs::parameters::combine(gs::parameters::resolution(resolution), gs::parameters::curve_skeleton_output(&ours.curve),
                                gs::parameters::reeb_graph_output(&ours.reeb)));

    std::vector<Segment> our_segments;
    for(const auto& bone : ours.control.bones)
      for(std::size_t k = 1; k < bone.points.size(); ++k)
        our_segments.emplace_back(bone.points[k - 1], bone.points[k]);
    CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(mesh);
    std::size_t inside = 0;
    for(const auto& j : ours.control.joints)
      inside += side(j.point) != CGAL::ON_UNBOUNDED_SIDE;

    // MCF, once (it is slow).
    double mcf_ms = 0;
    std::size_t mcf_vertices = 0, mcf_ends = 0, mcf_junctions = 0;
    double mcf_coverage = 0;
    if(run_mcf)
    {
      Mcf::Skeleton skeleton;
      const double t0 = now_ms();
      CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton);
      mcf_ms = now_ms() - t0;
      mcf_vertices = num_vertices(skeleton);
      std::vector<Segment> segments;
      for(auto v : CGAL::make_range(vertices(skeleton)))
      {
        mcf_ends += degree(v, skeleton) == 1;
        mcf_junctions += degree(v, skeleton) >= 3;
      }
      for(auto e : CGAL::make_range(edges(skeleton)))
        segments.emplace_back(skeleton[source(e, skeleton)].point, skeleton[target(e, skeleton)].point);
      mcf_coverage = coverage(mesh, segments);
      ratios.push_back(mcf_ms / ours.ms);
    }

    std::cout << "| " << name << " | " << num_vertices(mesh) << " | " << ours.ms << " | " << mcf_ms << " | "
              << (run_mcf ? mcf_ms / ours.ms : 0.0) << " | " << ours.control.bones.size() << " | " << mcf_vertices
              << " | " << mcf_ends << " | " << mcf_junctions << " | "
              << double(inside) / double(std::max<std::size_t>(1, ours.control.joints.size())) << " | "
              << std::setprecision(4) << coverage(mesh, our_segments) << " | " << mcf_coverage
              << std::setprecision(2) << " |" << std::endl;

    double reeb_ms = 0, prune_ms = 0;
    for(const auto& [stage, ms] : with_reeb.timings_ms)
    {
      if(stage == "reeb_graph")
        reeb_ms = ms;
      if(stage == "prune")
        prune_ms = ms;
    }
    const std::size_t segments = gs::internal::skeleton_branches(ours.curve).size();
    tables << "| " << name << " | " << num_vertices(ours.reeb) << " | " << ours.report.pruned.points << " | "
           << ours.report.thinned.points << " | " << ours.report.pruned.junctions << " | " << reeb_ms << " | "
           << prune_ms << " | " << segments << " | " << ours.control.bones.size() << " |\n";
  }
  if(!ratios.empty())
    std::cout << "\nmedian MCF/ours: " << median(ratios) << " over " << ratios.size() << " meshes\n";
  std::cout << tables.str();
  std::cout << stage_table.str();
  return 0;
}
