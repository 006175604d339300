// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// geodesic_benchmark: times CGAL::Geodesic_skeleton::geodesic_distances (Dijkstra over the
// mesh edges, Boost.Graph) against CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3
// (Direct mode) on demo meshes of growing size, in the same run, and compares the fields.
//
// A second table answers a design question of issue 2: would a hand-written Dijkstra
// (binary heap with lazy deletion over a flat CSR adjacency built once) be faster than the
// Boost.Graph dijkstra that geodesic_distances uses? The hand-written variant lives here,
// in the benchmark only (namespace `hand_written`), and is checked against the library.
//
// Usage: geodesic_benchmark [DATA_DIR] [--repeats N] [--meshes a,b,c]
//   DATA_DIR  folder of the demo meshes (*.off); default: the build tree's data folder.
//   N         repetitions of every timed step; the median is reported (default 9).
// All times are wall-clock milliseconds (std::chrono::steady_clock).

#include <CGAL/Geodesic_skeleton/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <queue>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#ifndef GEODESIC_SKELETON_DATA_DIR
#define GEODESIC_SKELETON_DATA_DIR "data/meshes"
#endif

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Heat_method =
    CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh, CGAL::Heat_method_3::Direct>;

// ---------------------------------------------------------------------------------------
// HAND-WRITTEN DIJKSTRA (benchmark only, not part of the package): the adjacency of the
// mesh as a flat CSR array (offsets + neighbour index + edge length), built once, and a
// std::priority_queue binary heap with lazy deletion (a vertex can be pushed several
// times; stale entries are skipped when popped).
// ---------------------------------------------------------------------------------------
namespace hand_written {

struct Csr_graph
{
  std::vector<std::size_t> offsets;  // neighbours of v are [offsets[v], offsets[v + 1])
  std::vector<std::size_t> neighbor; // vertex index
  std::vector<double> length;        // edge length, world units
};

Csr_graph build_csr(const Mesh& mesh)
{
  const std::size_t n = num_vertices(mesh);
  Csr_graph csr;
  csr.offsets.assign(n + 1, 0);
  for(auto e : edges(mesh))
  {
    ++csr.offsets[std::size_t(source(e, mesh)) + 1];
    ++csr.offsets[std::size_t(target(e, mesh)) + 1];
  }
  for(std::size_t i = 0; i < n; ++i)
    csr.offsets[i + 1] += csr.offsets[i];
  csr.neighbor.resize(csr.offsets[n]);
  csr.length.resize(csr.offsets[n]);
  std::vector<std::size_t> fill(csr.offsets.begin(), csr.offsets.end() - 1);
  for(auto e : edges(mesh))
  {
    const std::size_t a = std::size_t(source(e, mesh));
    const std::size_t b = std::size_t(target(e, mesh));
    const double l = std::sqrt(CGAL::squared_distance(mesh.point(vertex_descriptor(a)),
                                                      mesh.point(vertex_descriptor(b))));
    csr.neighbor[fill[a]] = b;
    csr.length[fill[a]++] = l;
    csr.neighbor[fill[b]] = a;
    csr.length[fill[b]++] = l;
  }
  return csr;
}

void dijkstra(const Csr_graph& csr, std::size_t source, std::vector<double>& distance)
{
  using Entry = std::pair<double, std::size_t>; // (tentative distance, vertex)
  const std::size_t n = csr.offsets.size() - 1;
  distance.assign(n, std::numeric_limits<double>::infinity());
  std::vector<Entry> storage;
  storage.reserve(n);
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap(
      std::greater<Entry>(), std::move(storage));
  distance[source] = 0.;
  heap.emplace(0., source);
  while(!heap.empty())
  {
    const auto [d, v] = heap.top();
    heap.pop();
    if(d > distance[v]) // stale entry: v was settled with a smaller distance already
      continue;
    for(std::size_t k = csr.offsets[v]; k < csr.offsets[v + 1]; ++k)
    {
      const std::size_t w = csr.neighbor[k];
      const double dw = d + csr.length[k];
      if(dw < distance[w])
      {
        distance[w] = dw;
        heap.emplace(dw, w);
      }
    }
  }
}

} // namespace hand_written

// ---------------------------------------------------------------------------------------

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Runs `f` once and returns its wall time, in milliseconds.
template <typename F>
double time_ms(F&& f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return milliseconds_since(start);
}

struct Row
{
  std::string mesh;
  std::size_t vertices = 0;
  double ours_ms = 0, heat_pre_ms = 0, heat_solve_ms = 0;
  double mean_rel_diff = 0, mean_signed_rel_diff = 0;
  std::size_t compared = 0;
  double ours_stored_ms = 0, csr_build_ms = 0, hand_ms = 0, hand_max_abs_diff = 0;
};

std::string format(const char* fmt, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, x);
  return buffer;
}

std::vector<std::string> split_commas(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ','))
    if(!item.empty())
      out.push_back(item);
  return out;
}

} // namespace

int main(int argc, char* argv[])
{
  std::string data_dir = GEODESIC_SKELETON_DATA_DIR;
  int repeats = 9;
  // Demo meshes of Debian's libcgal-demo, by growing vertex count.
  std::vector<std::string> names = {"elephant", "cow",  "dino",  "bull",     "camel",
                                    "ChineseDragon-10kv", "man", "diplodocus", "armadillo", "bunny00",
                                    "refined_elephant"};
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--repeats" && i + 1 < argc)
      repeats = std::max(1, std::atoi(argv[++i]));
    else if(arg == "--meshes" && i + 1 < argc)
      names = split_commas(argv[++i]);
    else if(arg == "-h" || arg == "--help")
    {
      std::cout << "usage: " << argv[0] << " [DATA_DIR] [--repeats N] [--meshes a,b,c]\n";
      return EXIT_SUCCESS;
    }
    else
      data_dir = arg;
  }

  std::cout << "geodesic_benchmark: one source (vertex 0), median of " << repeats
            << " interleaved rounds, wall times in ms, data: " << data_dir << "\n\n";

  std::vector<Row> rows;
  for(const std::string& name : names)
  {
    const std::string file = data_dir + "/" + name + ".off";
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh) || num_vertices(mesh) == 0)
    {
      std::cerr << "skipping " << name << ": cannot read a mesh from " << file << "\n";
      continue;
    }
    if(!CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "skipping " << name << ": not a triangle mesh (the heat method needs one)\n";
      continue;
    }
    std::size_t degenerate = 0;
    for(auto f : faces(mesh))
      if(CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, mesh))
        ++degenerate;
    if(degenerate > 0)
    {
      std::cerr << "skipping " << name << ": " << degenerate
                << " degenerate faces (Heat_method_3 Direct needs none)\n";
      continue;
    }

    Row row;
    row.mesh = name;
    row.vertices = num_vertices(mesh);
    const vertex_descriptor source_vertex = *vertices(mesh).begin();

    auto ours = mesh.add_property_map<vertex_descriptor, double>("v:ours", 0.).first;
    auto ours_stored = mesh.add_property_map<vertex_descriptor, double>("v:stored", 0.).first;
    auto heat = mesh.add_property_map<vertex_descriptor, double>("v:heat", 0.).first;
    auto lengths = mesh.add_property_map<Mesh::Edge_index, double>("e:length", 0.).first;
    for(auto e : edges(mesh))
      lengths[e] = std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)),
                                                    mesh.point(target(e, mesh))));
    hand_written::Csr_graph csr;
    std::vector<double> hand;

    // The variants run in interleaved rounds, so that load from other processes on the
    // machine hits all of them alike; each reports the median of its rounds.
    std::vector<double> ours_t, stored_t, heat_pre_t, heat_solve_t, csr_t, hand_t;
    for(int r = 0; r < repeats; ++r)
    {
      // Ours: the whole geodesic_distances call (checks, then Boost.Graph's dijkstra with
      // edge lengths computed from the points on the fly).
      ours_t.push_back(time_ms([&] {
        CGAL::Geodesic_skeleton::geodesic_distances(mesh, source_vertex, ours);
      }));
      // Ours with the edge lengths computed once and passed as `edge_weight_map`: isolates
      // Boost.Graph's dijkstra from the square roots of the default weight map.
      stored_t.push_back(time_ms([&] {
        CGAL::Geodesic_skeleton::geodesic_distances(
            mesh, source_vertex, ours_stored,
            CGAL::Geodesic_skeleton::parameters::edge_weight_map(lengths));
      }));
      // Heat method, Direct: the constructor is the precomputation (it builds and factors
      // the matrices); estimate_geodesic_distances is the solve for the source set.
      std::unique_ptr<Heat_method> hm;
      heat_pre_t.push_back(time_ms([&] { hm = std::make_unique<Heat_method>(mesh); }));
      hm->add_source(source_vertex);
      heat_solve_t.push_back(time_ms([&] { hm->estimate_geodesic_distances(heat); }));
      // HAND-WRITTEN Dijkstra (benchmark only): CSR build, then the solve.
      csr_t.push_back(time_ms([&] { csr = hand_written::build_csr(mesh); }));
      hand_t.push_back(time_ms([&] {
        hand_written::dijkstra(csr, std::size_t(source_vertex), hand);
      }));
    }
    row.ours_ms = median(ours_t);
    row.ours_stored_ms = median(stored_t);
    row.heat_pre_ms = median(heat_pre_t);
    row.heat_solve_ms = median(heat_solve_t);
    row.csr_build_ms = median(csr_t);
    row.hand_ms = median(hand_t);

    // Mean relative difference over the vertices that are not (almost) at the source.
    double max_heat = 0.;
    for(auto v : vertices(mesh))
      if(std::isfinite(heat[v]))
        max_heat = std::max(max_heat, heat[v]);
    double sum = 0., signed_sum = 0.;
    for(auto v : vertices(mesh))
    {
      const double h = heat[v];
      if(!std::isfinite(h) || !std::isfinite(ours[v]) || h <= 1e-3 * max_heat)
        continue;
      sum += std::abs(ours[v] - h) / h;
      signed_sum += (ours[v] - h) / h;
      ++row.compared;
    }
    row.mean_rel_diff = row.compared > 0 ? sum / double(row.compared) : 0.;
    row.mean_signed_rel_diff = row.compared > 0 ? signed_sum / double(row.compared) : 0.;

    // The three Dijkstra variants must agree exactly (same edge lengths, same sums).
    for(auto v : vertices(mesh))
    {
      const double a = ours[v], b = hand[std::size_t(v)], c = ours_stored[v];
      if(std::isinf(a) && std::isinf(b) && std::isinf(c))
        continue;
      row.hand_max_abs_diff =
          std::max({row.hand_max_abs_diff, std::abs(a - b), std::abs(a - c)});
    }

    rows.push_back(row);
    std::cerr << "done " << name << " (" << row.vertices << " vertices)\n";
  }

  std::cout << "Dijkstra (ours) vs Heat_method_3 (Direct)\n\n"
            << "| mesh | vertices | ours ms | heat precompute ms | heat solve ms | heat total ms "
               "| heat total / ours | heat solve / ours | mean rel. diff | mean signed rel. diff |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const Row& r : rows)
  {
    const double heat_total = r.heat_pre_ms + r.heat_solve_ms;
    std::cout << "| " << r.mesh << " | " << r.vertices << " | " << format("%.2f", r.ours_ms)
              << " | " << format("%.2f", r.heat_pre_ms) << " | " << format("%.2f", r.heat_solve_ms)
              << " | " << format("%.2f", heat_total) << " | "
              << format("%.1f", heat_total / r.ours_ms) << " | "
              << format("%.2f", r.heat_solve_ms / r.ours_ms) << " | "
              << format("%.1f%%", 100. * r.mean_rel_diff) << " | "
              << format("%+.1f%%", 100. * r.mean_signed_rel_diff) << " |\n";
  }

  std::cout << "\nBoost.Graph dijkstra (ours, whole geodesic_distances call) vs HAND-WRITTEN "
               "Dijkstra (binary heap, lazy deletion, CSR adjacency)\n\n"
            << "| mesh | vertices | ours ms | ours, stored weights ms | CSR build ms "
               "| hand-written solve ms | ours / hand solve | ours / (build + solve) "
               "| max abs diff (3 variants) |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const Row& r : rows)
  {
    std::cout << "| " << r.mesh << " | " << r.vertices << " | " << format("%.2f", r.ours_ms)
              << " | " << format("%.2f", r.ours_stored_ms) << " | "
              << format("%.2f", r.csr_build_ms) << " | " << format("%.2f", r.hand_ms)
              << " | " << format("%.2f", r.ours_ms / r.hand_ms) << " | "
              << format("%.2f", r.ours_ms / (r.csr_build_ms + r.hand_ms)) << " | "
              << format("%.1e", r.hand_max_abs_diff) << " |\n";
  }
  return rows.empty() ? EXIT_FAILURE : EXIT_SUCCESS;
}
