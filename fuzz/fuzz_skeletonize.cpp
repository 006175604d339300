// fuzz_skeletonize: a libFuzzer harness over what skeletonize does with a file: read it
// (CGAL::Geodesic_skeleton::IO::read_mesh(): mesh, or polygon soup repaired and oriented) and, when it reads,
// run the whole chain (extract_control_skeleton, with the Reeb graph) at a low resolution
// under a small memory limit, then write the results (JSON, BVH, OBJ).
//
// The bytes are a mesh file; its format is guessed from its first bytes, as a person would
// name the file: "ply" -> .ply, "solid" -> .stl (ASCII), an "OFF" header -> .off, a line
// starting with an OBJ keyword or a comment -> .obj, anything else -> .stl (binary).
//
// The outcomes that are fine: the file does not read (std::runtime_error from read_mesh()),
// or the chain refuses it with the exceptions it documents (std::invalid_argument for bad
// input, std::length_error over the memory limit). Anything else is a finding: another
// exception (std::bad_alloc included), a crash, a sanitizer report, a hang (libFuzzer's
// -timeout) or a non-finite coordinate in the control skeleton.
//
// Built with GEODESIC_SKELETON_FUZZ_REPLAY, the same code is a plain program whose main()
// runs each file (or each file of each folder) given on its command line: CTest replays
// the seed corpus and the regressions with it in the normal build.

#include <CGAL/Geodesic_skeleton.h>

#include <CGAL/Geodesic_skeleton/IO/json.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh.h>

#include "../examples/skeletonize/svg_preview.h" // the picture skeletonize --svg draws

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace {

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

constexpr int fuzz_resolution = 16;
constexpr double fuzz_memory_limit = 64. * 1024 * 1024; // bytes

bool starts_with(const std::uint8_t* data, std::size_t size, const char* prefix)
{
  std::size_t n = std::char_traits<char>::length(prefix);
  return size >= n && std::char_traits<char>::compare(reinterpret_cast<const char*>(data), prefix, n) == 0;
}

const char* guess_extension(const std::uint8_t* data, std::size_t size)
{
  if(starts_with(data, size, "ply"))
    return ".ply";
  if(starts_with(data, size, "solid"))
    return ".stl";
  // OFF, COFF, NOFF, STOFF, 4OFF, nOFF, ...: "OFF" within the first word.
  const std::string head(reinterpret_cast<const char*>(data), size < 6 ? size : 6);
  if(head.find("OFF") != std::string::npos)
    return ".off";
  if(size > 0 && std::string("vfo#gslmu").find(char(data[0])) != std::string::npos)
    return ".obj";
  return ".stl";
}

[[noreturn]] void finding(const std::string& what)
{
  std::cerr << "fuzz_skeletonize: finding: " << what << std::endl;
  std::abort();
}

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// A file of its own in the temporary folder per process (CGAL's readers pick the format
// by the extension of a path), removed at exit.
struct Scratch_file
{
  std::string path;
  explicit Scratch_file(const char* extension)
  {
    const char* dir = std::getenv("TMPDIR");
    path = std::string(dir && *dir ? dir : "/tmp") + "/fuzz_skeletonize_" + std::to_string(getpid()) + extension;
  }
  ~Scratch_file() { std::remove(path.c_str()); }
};

void run_one(const std::uint8_t* data, std::size_t size)
{
  const Scratch_file file(guess_extension(data, size));
  {
    std::ofstream out(file.path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if(!out.flush())
      finding("cannot write " + file.path);
  }

  Mesh mesh;
  try
  {
    gs::IO::read_mesh(file.path, mesh);
  }
  catch(const std::runtime_error&)
  {
    return; // the file does not read: a clear error, as skeletonize prints it
  }

  gs::Control_skeleton<Point> control;
  gs::Curve_skeleton<Point, vertex_descriptor> curve;
  gs::Reeb_graph<Mesh> reeb;
  try
  {
    gs::extract_control_skeleton(
        mesh, control,
        params::combine(params::resolution(fuzz_resolution), params::memory_limit(fuzz_memory_limit),
                        params::number_of_reeb_intervals(std::size_t(8)),
                        params::curve_skeleton_output(&curve), params::reeb_graph_output(&reeb)));
  }
  catch(const std::invalid_argument&)
  {
    return; // documented: bad input (no volume at the resolution, ...)
  }
  catch(const std::length_error&)
  {
    return; // documented: more than memory_limit
  }

  for(const auto joint : CGAL::make_range(vertices(control)))
    if(!finite(control[joint].point))
      finding("a joint of the control skeleton has a non-finite coordinate");
  for(const auto bone : CGAL::make_range(edges(control)))
    for(const Point& p : control[bone].points)
      if(!finite(p))
        finding("a bone of the control skeleton has a non-finite point");
  for(auto v : CGAL::make_range(vertices(curve)))
    if(!finite(curve[v].point))
      finding("a point of the curve skeleton is not finite");

  std::ostringstream sink;
  sink << gs::IO::control_skeleton_to_json(control) << gs::IO::curve_skeleton_to_json(curve);
  gs::IO::write_BVH(sink, control);
  gs::IO::write_OBJ(sink, control);
  gs::IO::write_polylines(sink, control);
  gs::IO::write_svg_preview(sink, mesh, control, 120, "fuzz");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try
  {
    run_one(data, size);
  }
  catch(const std::exception& e)
  {
    finding(std::string("undocumented exception: ") + e.what());
  }
  return 0;
}

#ifdef GEODESIC_SKELETON_FUZZ_REPLAY
#include <filesystem>
#include <iterator>
#include <vector>

// Replays files: fuzz_skeletonize_replay FILE_OR_FOLDER... Any finding aborts.
int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for(int i = 1; i < argc; ++i)
  {
    if(fs::is_directory(argv[i]))
    {
      for(const auto& entry : fs::directory_iterator(argv[i]))
        if(entry.is_regular_file() && entry.path().filename().string()[0] != '.')
          files.push_back(entry.path());
    }
    else if(fs::is_regular_file(argv[i]))
      files.push_back(argv[i]);
    else
    {
      std::cerr << "fuzz_skeletonize_replay: no such file or folder: " << argv[i] << '\n';
      return 1;
    }
  }
  std::sort(files.begin(), files.end());
  if(files.empty())
  {
    std::cerr << "fuzz_skeletonize_replay: no input file\n";
    return 1;
  }
  for(const fs::path& path : files)
  {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << "replaying " << path.string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << files.size() << " passed, 0 failed" << std::endl;
  return 0;
}
#endif
