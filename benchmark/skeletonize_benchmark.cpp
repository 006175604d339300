// skeletonize_benchmark: the user's whole run, timed as a user waits for it. Runs the real
// `skeletonize` program (a child process: reading the mesh, the chain, writing the JSON,
// exiting) and compares its wall time with CGAL's mean curvature flow skeletonization
// (CGAL::extract_mean_curvature_flow_skeleton) run in this process on the same mesh, on the
// closed demo meshes. Then a large mesh (armadillo, Loop-subdivided twice: 832,000 faces),
// written here as OFF, OBJ and binary STL: the time to read the file's bytes once (the
// floor for any reader), skeletonize's wall time and peak memory against the mesh's own
// size in memory. Last, batch mode over the demo folder, with one thread and with all.
//
//   skeletonize_benchmark [DATA_DIR] [--skeletonize PATH] [--repeats N] [--meshes a,b]
//                         [--work-dir DIR] [--no-mcf] [--no-large] [--no-batch]

#include "benchmark_common.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <malloc.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using benchmark_common::median;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Process_run
{
  int exit_code = -1;
  double wall_ms = 0;
  double peak_mib = 0; // the child's largest resident set, as it reports it in its JSON
};

// skeletonize's own report of its peak memory (`peak_memory_mib` of its JSON). The rusage
// of a child is no measure here: Linux counts in it the memory of the parent it was
// spawned from, and this parent has just run MCF.
double reported_peak_mib(const std::string& json_path)
{
  std::ifstream in(json_path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = "\"peak_memory_mib\":";
  const std::size_t at = text.find(key);
  return at == std::string::npos ? -1 : std::atof(text.c_str() + at + key.size());
}

// Runs `arguments` as a child process, standard output and error to /dev/null.
Process_run run_process(const std::vector<std::string>& arguments)
{
  std::vector<char*> argv;
  for(const std::string& a : arguments)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  Process_run run;
  const auto start = Clock::now();
  pid_t pid;
  if(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0)
  {
    int status = 0;
    if(waitpid(pid, &status, 0) == pid)
    {
      run.wall_ms = ms_since(start);
      run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
  }
  posix_spawn_file_actions_destroy(&actions);
  return run;
}

// The median of `repeats` runs of skeletonize writing `json_path` (and the largest peak
// memory); a failed run ends the benchmark.
Process_run time_skeletonize(const std::vector<std::string>& arguments, const std::string& json_path, int repeats)
{
  std::vector<double> times;
  Process_run result;
  for(int r = 0; r < repeats; ++r)
  {
    const Process_run run = run_process(arguments);
    if(run.exit_code != 0)
    {
      std::cerr << "failed (" << run.exit_code << "): " << arguments[0] << " " << arguments[1] << "\n";
      std::exit(1);
    }
    times.push_back(run.wall_ms);
    result.peak_mib = std::max(result.peak_mib, reported_peak_mib(json_path));
  }
  result.exit_code = 0;
  result.wall_ms = median(times);
  return result;
}

// Reading the file's bytes once, into one reused buffer: no reader can take less.
double read_bytes_ms(const std::string& path)
{
  std::vector<char> buffer(1 << 20);
  const auto start = Clock::now();
  std::FILE* file = std::fopen(path.c_str(), "rb");
  while(file != nullptr && std::fread(buffer.data(), 1, buffer.size(), file) == buffer.size())
  {
  }
  if(file != nullptr)
    std::fclose(file);
  return ms_since(start);
}

// The heap in use: small blocks and blocks of their own mapping (large arrays) alike.
std::size_t heap_in_use()
{
  const struct mallinfo2 heap = mallinfo2();
  return heap.uordblks + heap.hblkhd;
}

// The heap that a Surface_mesh of the file takes once read (its own size in memory).
double mesh_size_mib(const std::string& path)
{
  const std::size_t before = heap_in_use();
  auto* mesh = new Mesh;
  CGAL::IO::read_polygon_mesh(path, *mesh);
  const std::size_t after = heap_in_use();
  delete mesh;
  return double(after - before) / (1024 * 1024);
}

} // namespace

int main(int argc, char* argv[])
{
  std::string data_dir = GEODESIC_SKELETON_DATA_DIR, skeletonize = GEODESIC_SKELETON_SKELETONIZE;
  std::string work_dir = (fs::temp_directory_path() / "skeletonize_benchmark").string();
  int repeats = 5;
  bool run_mcf = true, run_large = true, run_batch = true;
  std::vector<std::string> names = {"elephant", "cow", "triceratops", "dino", "homer", "bull", "camel",
                                    "bear", "man", "armadillo", "hand"};
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--skeletonize" && i + 1 < argc)
      skeletonize = argv[++i];
    else if(arg == "--repeats" && i + 1 < argc)
      repeats = std::max(1, std::atoi(argv[++i]));
    else if(arg == "--meshes" && i + 1 < argc)
      names = benchmark_common::split_commas(argv[++i]);
    else if(arg == "--work-dir" && i + 1 < argc)
      work_dir = argv[++i];
    else if(arg == "--no-mcf")
      run_mcf = false;
    else if(arg == "--no-large")
      run_large = false;
    else if(arg == "--no-batch")
      run_batch = false;
    else if(!arg.empty() && arg[0] != '-')
      data_dir = arg;
    else
    {
      std::cout << "usage: " << argv[0]
                << " [DATA_DIR] [--skeletonize PATH] [--repeats N] [--meshes a,b] [--work-dir DIR]"
                   " [--no-mcf] [--no-large] [--no-batch]\n";
      return 2;
    }
  }
  fs::create_directories(work_dir);
  const std::string out_json = (fs::path(work_dir) / "out.json").string();
  std::cout << std::fixed << std::setprecision(1);

  // 1. The demo meshes: skeletonize's whole process against MCF in this process.
  std::cout << "## skeletonize (whole process) vs MCF, median of " << repeats << " runs\n\n"
            << "| mesh | faces | file KiB | skeletonize wall ms | peak MiB | MCF ms | MCF / skeletonize |\n"
            << "|---|---:|---:|---:|---:|---:|---:|\n";
  std::vector<double> ratios;
  for(const std::string& name : names)
  {
    const std::string path = data_dir + "/" + name + ".off";
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "skipping " << path << " (unreadable, open or not triangulated)\n";
      continue;
    }
    const Process_run ours = time_skeletonize({skeletonize, path, "-o", out_json}, out_json, repeats);
    double mcf_ms = 0;
    if(run_mcf)
    {
      CGAL::Mean_curvature_flow_skeletonization<Mesh>::Skeleton skeleton;
      const auto start = Clock::now();
      CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton);
      mcf_ms = ms_since(start);
      ratios.push_back(mcf_ms / ours.wall_ms);
    }
    std::cout << "| " << name << " | " << num_faces(mesh) << " | " << double(fs::file_size(path)) / 1024 << " | "
              << ours.wall_ms << " | " << ours.peak_mib << " | " << mcf_ms << " | "
              << (run_mcf ? mcf_ms / ours.wall_ms : 0.0) << " |" << std::endl;
  }
  if(!ratios.empty())
    std::cout << "\nmedian MCF / skeletonize (whole process): " << median(ratios) << " over " << ratios.size()
              << " meshes\n";

  // 2. A large mesh in three formats.
  if(run_large)
  {
    Mesh large;
    CGAL::IO::read_polygon_mesh(data_dir + "/armadillo.off", large);
    CGAL::Subdivision_method_3::Loop_subdivision(large, CGAL::parameters::number_of_iterations(2));
    std::cout << "\n## A large mesh: armadillo.off Loop-subdivided twice, " << num_vertices(large) << " vertices, "
              << num_faces(large) << " faces\n\n"
              << "| file | MiB | read the bytes once ms | skeletonize wall ms | wall / read once"
                 " | peak MiB | mesh in memory MiB | peak / mesh |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for(const std::string extension : {"off", "obj", "stl"})
    {
      const std::string path = (fs::path(work_dir) / ("armadillo_x2." + extension)).string();
      if(!fs::exists(path))
        CGAL::IO::write_polygon_mesh(path, large, CGAL::parameters::stream_precision(9));
      const double mesh_mib = mesh_size_mib(path);
      std::vector<double> reads;
      for(int r = 0; r < repeats; ++r)
        reads.push_back(read_bytes_ms(path));
      const Process_run ours = time_skeletonize({skeletonize, path, "-o", out_json}, out_json, repeats);
      const double read_ms = median(reads);
      std::cout << "| armadillo_x2." << extension << " | " << double(fs::file_size(path)) / (1024 * 1024) << " | "
                << read_ms << " | " << ours.wall_ms << " | " << ours.wall_ms / read_ms << " | " << ours.peak_mib
                << " | " << mesh_mib << " | " << ours.peak_mib / mesh_mib << " |" << std::endl;
    }
  }

  // 3. Batch mode over the whole demo folder.
  if(run_batch)
  {
    std::size_t meshes = 0;
    for(const auto& entry : fs::directory_iterator(data_dir))
      meshes += entry.path().extension() == ".off";
    std::cout << "\n## Batch mode over " << data_dir << " (" << meshes << " meshes; those that fail count)\n\n"
              << "| threads | wall s | meshes / s |\n|---|---:|---:|\n";
    for(const std::string threads : {"1", "2"})
    {
      const std::string out_dir = (fs::path(work_dir) / ("batch_" + threads)).string();
      const Process_run run = run_process({skeletonize, "--batch", data_dir, "-o", out_dir, "--threads", threads});
      std::cout << "| " << threads << " | " << run.wall_ms / 1000 << " | " << double(meshes) / (run.wall_ms / 1000)
                << " |" << std::endl;
    }
  }
  return 0;
}
