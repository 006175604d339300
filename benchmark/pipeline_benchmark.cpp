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
// Also prints the paper's Table 1 and Table 2 on our meshes. Table 1: the mesh's vertices
// (the paper's "Reeb graph" column: its cow row, 2,904, is the vertex count of the same
// cow.off), the points of our thinned skeleton and of the skeleton just before pruning,
// its branched connection points (Definition 7) before Algorithm 1, after Algorithm 1
// alone and after the whole pruning, the points that Algorithm 1 removed and those that the
// package's snipping of end branches (not in the paper) removed, and the pruned points;
// the skeleton before pruning comes from the public stages composed as
// extract_control_skeleton() does, checked against its report. Then our Reeb graph and the
// times of the Reeb graph and pruning. Table 2: control segments of the pruned skeleton
// (its branches) against bend joints and bones of the smoothed, split skeleton.

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
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
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

// The paper's Table 1 on one mesh: the public stages composed as extract_control_skeleton()
// composes them up to pruning, with the branched connection points (Definition 7) counted
// before Algorithm 1, after Algorithm 1 alone (snipping off) and after the whole pruning.
struct Pruning_counts
{
  std::size_t thinned = 0;           // points after thin()
  std::size_t before = 0;            // after remove_small_pieces() and cut_spurious_cycles()
  std::size_t branched_before = 0;   // branched connection points there
  std::size_t regions = 0;           // branched regions there (their 26-connected components)
  std::size_t algorithm_1_removed = 0;  // Algorithm 1 alone: points removed
  std::size_t algorithm_1_branched = 0; // Algorithm 1 alone: branched connection points left
  gs::Pruning_report pruning;        // the whole pruning (Algorithm 1 and snipping)
  std::size_t branched_after = 0;    // branched connection points after it
  std::size_t pruned = 0;            // points after it
};

Pruning_counts pruning_counts(const Mesh& mesh, int resolution)
{
  Pruning_counts c;
  gs::Dense_voxel_grid solid;
  // The stages up to pruning run on the grid of the level of detail (at most the default
  // resolution); a finer grid routes the pruned skeleton's branches.
  gs::voxelize(mesh, solid, gs::parameters::resolution((std::min)(resolution, gs::default_voxel_resolution)));
  const gs::Voxel_distance_field distances = gs::distance_transform(solid);
  gs::Voxel_skeleton skeleton;
  gs::thin(solid, distances, skeleton);
  c.thinned = skeleton.voxels.size();
  gs::remove_small_pieces(skeleton.voxels, distances);
  gs::cut_spurious_cycles(skeleton.voxels, mesh);
  c.before = skeleton.voxels.size();
  c.branched_before = gs::count_skeleton_points(skeleton.voxels).branched_connection;

  // Algorithm 1 alone: the radii that extract_control_skeleton() prunes by, no snipping.
  gs::Voxel_skeleton algorithm_1 = skeleton;
  const gs::Pruning_report report_1 = gs::prune_skeleton(
      algorithm_1, distances,
      gs::parameters::combine(gs::parameters::spur_length_factor(0.0), gs::parameters::limb_protrusion_factor(0.0)));
  c.algorithm_1_removed = c.before - algorithm_1.voxels.size();
  c.regions = report_1.branched_regions;
  c.algorithm_1_branched = gs::count_skeleton_points(algorithm_1.voxels).branched_connection;

  c.pruning = gs::prune_skeleton(skeleton, distances);
  c.branched_after = gs::count_skeleton_points(skeleton.voxels).branched_connection;
  c.pruned = skeleton.voxels.size();
  return c;
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
  // The paper's Table 1 (table_1), our Reeb graph and the times (reeb_table), Table 2 (table_2).
  std::ostringstream table_1, reeb_table, table_2;
  table_1 << "\n| mesh | mesh vertices | thinned points | points before pruning"
             " | branched connection points before | branched regions | Algorithm 1 alone: points removed"
             " | Algorithm 1 alone: branched connection points left | pruning: points removed by Algorithm 1"
             " | pruning: points snipped (package's addition) | pruning: branched connection points left"
             " | pruned points | same as extract_control_skeleton |\n"
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  reeb_table << "\n| mesh | our Reeb graph nodes (30 intervals) | pruned junctions | Reeb ms | pruning ms |\n"
                "|---|---:|---:|---:|---:|\n";
  table_2 << "\n| mesh | pruned segments | bend joints | bones (smoothed, split) |\n|---|---:|---:|---:|\n";
  reeb_table << std::fixed << std::setprecision(2);
  bool all_agree = true;
  // Where our time goes: the median over the timed runs of each stage's time.
  const std::vector<std::string> stages = {"voxelize", "distance_transform", "thin", "thinned_graph", "remove_small_pieces",
                                           "cut_spurious_cycles", "prune", "voxelize_finer", "distance_transform_finer",
                                           "route_on_finer_grid", "to_graph", "smooth", "curve_points_inside", "split_into_bones"};
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
    for(const auto bone : CGAL::make_range(edges(ours.control)))
    {
      const std::vector<Point>& points = ours.control[bone].points;
      for(std::size_t k = 1; k < points.size(); ++k)
        our_segments.emplace_back(points[k - 1], points[k]);
    }
    CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(mesh);
    std::size_t inside = 0;
    for(const auto j : CGAL::make_range(vertices(ours.control)))
      inside += side(ours.control[j].point) != CGAL::ON_UNBOUNDED_SIDE;

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
              << (run_mcf ? mcf_ms / ours.ms : 0.0) << " | " << num_edges(ours.control) << " | " << mcf_vertices
              << " | " << mcf_ends << " | " << mcf_junctions << " | "
              << double(inside) / double(std::max<std::size_t>(1, num_vertices(ours.control))) << " | "
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
    const Pruning_counts counts = pruning_counts(mesh, resolution);
    // Above the default resolution the pruned skeleton is routed on the finer grid, and its
    // points are counted there.
    const bool agree = (resolution > gs::default_voxel_resolution || counts.pruned == ours.report.pruned.points) &&
                       counts.thinned == ours.report.thinned.points;
    if(!agree)
    {
      all_agree = false;
      std::cerr << "warning: " << name << ": the composed stages give " << counts.thinned << " thinned and "
                << counts.pruned << " pruned points, extract_control_skeleton " << ours.report.thinned.points
                << " and " << ours.report.pruned.points << "\n";
    }
    table_1 << "| " << name << " | " << num_vertices(mesh) << " | " << counts.thinned << " | " << counts.before << " | "
            << counts.branched_before << " | " << counts.regions << " | " << counts.algorithm_1_removed << " | "
            << counts.algorithm_1_branched << " | " << counts.pruning.removed_branched_points << " | "
            << counts.pruning.snipped_points << " | " << counts.branched_after << " | " << counts.pruned << " | "
            << (agree ? "yes" : "NO (" + std::to_string(ours.report.pruned.points) + ")") << " |\n";
    reeb_table << "| " << name << " | " << num_vertices(ours.reeb) << " | " << ours.report.pruned.junctions << " | "
               << reeb_ms << " | " << prune_ms << " |\n";

    const std::size_t segments = gs::internal::skeleton_branches(ours.curve).size();
    std::size_t bends = 0;
    for(const auto j : CGAL::make_range(vertices(ours.control)))
      bends += ours.control[j].kind == gs::Joint_kind::bend;
    table_2 << "| " << name << " | " << segments << " | " << bends << " | " << num_edges(ours.control) << " |\n";
  }
  if(!ratios.empty())
    std::cout << "\nmedian MCF/ours: " << median(ratios) << " over " << ratios.size() << " meshes\n";
  std::cout << "\nThe paper's Table 1 (mesh vertices: its \"Reeb graph\" column, e.g. 2,904 for cow.off):"
            << table_1.str()
            << "(paper, cow.off: 2,904 -> 2,655 points; its other meshes are not among ours)\n"
            << reeb_table.str()
            << "\nThe paper's Table 2 (control segments):" << table_2.str()
            << "(paper, none of these meshes: boy 860 -> 19, alien 40 -> 30, femme 50 -> 26, horse 56 -> 27,"
               " dinopet 120 -> 31)\n";
  std::cout << stage_table.str();
  if(!all_agree)
  {
    std::cerr << "error: the composed stages and extract_control_skeleton() disagree (see the warnings)\n";
    return 1;
  }
  return 0;
}
