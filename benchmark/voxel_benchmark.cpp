// Benchmark of the voxel medial axis stages: voxelize, distance_transform, thin, to_graph.
//
// Usage: voxel_benchmark [DATA_DIR] [--repeats N] [--meshes a,b,c] [--resolutions r1,r2,...]
//   DATA_DIR  folder of the demo meshes (default: the build tree's data/meshes)
//   N         repetitions of every timed step; the median is reported (default 5)
//
// Prints, per mesh and resolution: the time of each stage (median, milliseconds), the peak
// heap memory of each stage (bytes allocated on top of what existed before it, measured by
// counting operator new/delete), the voxel counts, the throughput of the distance
// transform (voxels of its box per second) and of the thinning (solid voxels per second),
// and the nanoseconds per voxel, whose constancy across resolutions shows linear cost.
// Then the cost of the simple-point test alone, and the table behind the default
// resolution. See benchmark/README.md for the figures.

#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/internal/thin/simple_point.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <random>
#include <sstream>
#include <string>
#include <vector>

// --- Heap accounting: every allocation carries its size in a 16-byte header. ------------
namespace heap {
std::atomic<long long> current{0}, peak{0};
inline void add(long long n)
{
  const long long now = current += n;
  long long p = peak.load();
  while(now > p && !peak.compare_exchange_weak(p, now))
  {
  }
}
// Starts a measurement: the peak restarts from the current use.
inline long long start()
{
  peak = current.load();
  return current.load();
}
} // namespace heap

void* operator new(std::size_t n)
{
  void* p = std::malloc(n + 16);
  if(!p)
    throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  heap::add((long long)n);
  return static_cast<char*>(p) + 16;
}
void operator delete(void* p) noexcept
{
  if(!p)
    return;
  char* base = static_cast<char*>(p) - 16;
  heap::add(-(long long)*reinterpret_cast<std::size_t*>(base));
  std::free(base);
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

namespace gs = CGAL::Geodesic_skeleton;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeleton = gs::Curve_skeleton<Kernel::Point_3, Mesh::Vertex_index>;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ','))
    out.push_back(item);
  return out;
}

struct Stage
{
  std::vector<double> ms;
  long long peak_bytes = 0;
};

struct Run
{
  Stage voxelize, distance, thin, graph;
  std::size_t solid = 0, box = 0, skeleton = 0, skeleton_vertices = 0, end_points = 0;
  long cycles = 0;
  int components = 0;
};

template <typename F>
double timed(Stage& stage, F f)
{
  const long long before = heap::start();
  const auto t = Clock::now();
  f();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t).count();
  stage.ms.push_back(ms);
  stage.peak_bytes = std::max(stage.peak_bytes, heap::peak.load() - before);
  return ms;
}

Run run(const Mesh& mesh, int resolution, int repeats)
{
  Run r;
  for(int i = 0; i < repeats; ++i)
  {
    gs::Dense_voxel_grid voxels;
    gs::Voxel_distance_field field;
    Skeleton skeleton;
    timed(r.voxelize, [&] { r.solid = gs::voxelize(mesh, voxels, gs::parameters::resolution(resolution)); });
    timed(r.distance, [&] { field = gs::distance_transform(voxels); });
    r.box = field.box().volume();
    timed(r.thin, [&] { gs::thin(voxels, field); });
    timed(r.graph, [&] { gs::to_graph(voxels, field, mesh, skeleton); });
    r.skeleton = voxels.size();
    r.skeleton_vertices = num_vertices(skeleton);
    std::vector<int> component(num_vertices(skeleton));
    r.components = int(boost::connected_components(skeleton, component.data()));
    r.cycles = long(num_edges(skeleton)) - long(num_vertices(skeleton)) + r.components;
    r.end_points = 0;
    for(auto v : boost::make_iterator_range(vertices(skeleton)))
      r.end_points += degree(v, skeleton) == 1;
  }
  return r;
}

std::string mib(long long bytes)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", double(bytes) / (1024. * 1024.));
  return buf;
}

// The simple-point test alone, on the configurations met while thinning a real solid.
void simple_point_benchmark()
{
  const auto& test = gs::internal::Simple_point_test::instance();
  std::mt19937 random(1);
  std::vector<std::uint32_t> configs(1 << 20);
  for(auto& c : configs)
  {
    // Mixtures: interior-like (dense), surface-like (half), curve-like (sparse).
    const unsigned density = 1 + random() % 7;
    c = 0;
    for(int b = 0; b < 26; ++b)
      if(random() % 8 < density)
        c |= 1u << b;
  }
  std::size_t simple = 0;
  const auto t = Clock::now();
  for(int rep = 0; rep < 10; ++rep)
    for(std::uint32_t c : configs)
      simple += test.is_simple(c);
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t).count() / (10. * configs.size());
  std::printf("\nSimple-point test: %.1f ns per test (%zu random configurations of mixed density, %.0f%% simple)\n",
              ns, configs.size(), 100. * double(simple) / (10. * configs.size()));
}

} // namespace

int main(int argc, char** argv)
{
  std::string data_dir = GEODESIC_SKELETON_DATA_DIR;
  int repeats = 5;
  std::vector<std::string> meshes = {"cow.off", "camel.off", "elephant.off", "dino.off"};
  std::vector<int> resolutions = {64, 128, 256, 512};
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--repeats" && i + 1 < argc)
      repeats = std::max(1, std::atoi(argv[++i]));
    else if(a == "--meshes" && i + 1 < argc)
      meshes = split(argv[++i]);
    else if(a == "--resolutions" && i + 1 < argc)
    {
      resolutions.clear();
      for(const auto& r : split(argv[++i]))
        resolutions.push_back(std::atoi(r.c_str()));
    }
    else
      data_dir = a;
  }

  std::printf("Voxel medial axis, median of %d runs, Dense_voxel_grid. ms = milliseconds, MiB = peak heap of the stage.\n\n", repeats);
  std::printf("| mesh | res | solid voxels | DT box voxels | skeleton voxels | voxelize ms (MiB) | distance ms (MiB) | thin ms (MiB) | to_graph ms (MiB) | total ms | DT Mvoxels/s | thin Mvoxels/s | ns per box voxel (total) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& name : meshes)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(data_dir + "/" + name, mesh) || num_vertices(mesh) == 0)
    {
      std::cerr << "cannot read " << data_dir + "/" + name << "\n";
      return 1;
    }
    for(int resolution : resolutions)
    {
      Run r;
      try
      {
        r = run(mesh, resolution, resolution >= 512 ? 1 : repeats);
      }
      catch(const std::exception& e)
      {
        std::printf("| %s | %d | %s |\n", name.c_str(), resolution, e.what());
        continue;
      }
      const double v = median(r.voxelize.ms), d = median(r.distance.ms), t = median(r.thin.ms), g = median(r.graph.ms);
      const double total = v + d + t + g;
      std::printf("| %s | %d | %zu | %zu | %zu | %.2f (%s) | %.2f (%s) | %.2f (%s) | %.2f (%s) | %.2f | %.0f | %.1f | %.1f |\n",
                  name.c_str(), resolution, r.solid, r.box, r.skeleton, v, mib(r.voxelize.peak_bytes).c_str(), d,
                  mib(r.distance.peak_bytes).c_str(), t, mib(r.thin.peak_bytes).c_str(), g,
                  mib(r.graph.peak_bytes).c_str(), total, double(r.box) / d / 1e3, double(r.solid) / t / 1e3,
                  total * 1e6 / double(r.box));
      std::fflush(stdout);
    }
  }

  simple_point_benchmark();

  // The default resolution: cost against what the skeleton resolves.
  std::printf("\nDefault resolution: total ms and skeleton (graph vertices / end points / cycles) per mesh\n\n");
  std::printf("| res |");
  for(const auto& name : meshes)
    std::printf(" %s |", name.c_str());
  std::printf("\n|---|");
  for(std::size_t i = 0; i < meshes.size(); ++i)
    std::printf("---|");
  std::printf("\n");
  std::vector<Mesh> loaded(meshes.size());
  for(std::size_t i = 0; i < meshes.size(); ++i)
    CGAL::IO::read_polygon_mesh(data_dir + "/" + meshes[i], loaded[i]);
  for(int resolution : {32, 48, 64, 96, 128})
  {
    std::printf("| %d |", resolution);
    for(const Mesh& mesh : loaded)
    {
      const Run r = run(mesh, resolution, repeats);
      const double total = median(r.voxelize.ms) + median(r.distance.ms) + median(r.thin.ms) + median(r.graph.ms);
      std::printf(" %.1f ms: %zu / %zu / %ld |", total, r.skeleton_vertices, r.end_points, r.cycles);
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}
