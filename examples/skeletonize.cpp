// skeletonize: the package's main program. Mesh in, animation control skeleton out, with
// every stage's counts and timings, and a picture on request.
//
//   skeletonize INPUT_MESH [-o OUT] [--resolution N] [--svg PREVIEW.svg] [stage options]
//   skeletonize --batch DIR_OR_LIST -o OUT_DIR [--threads N] [stage options]
//
// The format of OUT follows its extension: .json (the documented contract, also written to
// standard output when there is no -o), .obj, .bvh, .polylines.txt, and .glb or .gltf (the
// mesh skinned to its skeleton). See --help.

#include "skeletonize/svg_preview.h"
#include "skeletonize_formats.h"
#include "skeletonize_settings.h"

#include <CGAL/Geodesic_skeleton.h>
#include <CGAL/Geodesic_skeleton/IO/json.h>
#include <CGAL/Geodesic_skeleton/IO/read_control_skeleton_json.h>
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/internal/parallel_parts.h> // start_beside()

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <dlfcn.h>  // dlopen: the formats' plug-in
#include <unistd.h> // isatty
#if defined(__GLIBC__)
#include <malloc.h> // mallopt
#endif
#if defined(_OPENMP)
#include <omp.h>
#endif

namespace gs = CGAL::Geodesic_skeleton;

using skeletonize_formats::Kernel;
using skeletonize_formats::Mesh;
using skeletonize_formats::Point;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

namespace {

// An error the user can fix: printed as "skeletonize: error: <message>", exit code 1.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The chain's and the weights' settings are skeletonize_settings.h's (the library's
// defaults and ranges); the rest says what to read and write.
struct Options : skeletonize_settings::Settings
{
  std::string input, output, svg, svg_stage = "control";
  std::string batch;       // a folder of meshes or a file listing them, one per line
  int threads = 0;         // batch mode's threads; 0: one per core
  bool reeb_graph = false; // compute the Reeb graph (a comparison baseline) and report it
  // Skinning: a given skeleton instead of the extracted one, the weights in the report.
  std::string skeleton;
  bool weights = false;
};

// The numeric options: skeletonize_settings.h's table.
using skeletonize_settings::Numeric_setting;

const Numeric_setting& numeric_option(const std::string& option)
{
  if(const Numeric_setting* o = skeletonize_settings::setting_of_option(option))
    return *o;
  throw std::logic_error("no numeric option " + option);
}

const char* const usage_head = R"(usage: skeletonize INPUT_MESH [-o OUT] [--resolution N] [--svg PREVIEW.svg] [options]
       skeletonize --batch DIR_OR_LIST -o OUT_DIR [--threads N] [options]

Extracts the animation control skeleton of a triangle mesh (any format that CGAL reads:
OFF, OBJ, PLY, STL, ...; FBX, glTF/GLB and DAE through Assimp). Without -o, writes the JSON
report to standard output.

  -o, --output OUT           write the result to OUT; its extension picks the format:
                             .json (report and skeletons), .obj (joints and bone lines),
                             .bvh (hierarchy with a rest pose), .polylines.txt (bone polylines),
                             .glb or .gltf (the mesh skinned to the skeleton, glTF 2.0)
  --skeleton RIG.json        skin the mesh to this control skeleton (skeletonize's JSON
                             report or its "control" object) instead of extracting one
  --weights                  add the skinning weights to the JSON report
  --svg PREVIEW.svg          also draw the mesh and its control skeleton in three views
  --svg-stage STAGE          what the picture shows: control (default), pruned (the smoothed
                             curve skeleton), thinned (the curve skeleton after thinning), reeb,
                             weights (the mesh coloured by the bone of largest weight)
  --reeb                     also compute the Reeb graph of the geodesic distance (the
                             paper's baseline) and report it in the JSON (stages.reeb)
  --batch DIR_OR_LIST        skeletonize every mesh of a folder (.off, .obj, .ply, .stl, .fbx,
                             .gltf, .glb, .dae), or every path listed in a text file (one
                             per line), writing OUT_DIR/NAME.json for each, on all cores; one
                             JSON summary line per mesh on standard output, a progress bar
                             on a terminal
  --threads N                batch mode: meshes skeletonized at once (default: the cores)
  --no-fill-holes            do not close the mesh's holes before voxelizing
  --peel-surface-voxels      drop the surface voxels whose centre is outside the mesh (opens
                             false loops between parts that nearly touch; default: kept)
)";

std::string usage_text()
{
  std::ostringstream text;
  text << usage_head;
  for(const Numeric_setting& o : skeletonize_settings::numeric_settings)
  {
    // An option too long for its column gets its words on the next line.
    const std::string name = std::string(o.option) + " " + o.metavar;
    text << "  " << std::left << std::setw(27) << name;
    if(name.size() >= 27)
      text << "\n" << std::setw(29) << "";
    text << o.help << ",\n" << std::setw(29) << "" << o.range.valid_values() << " (default ";
    if(o.default_text)
      text << o.default_text;
    else
      text << o.range.default_value;
    text << ")\n";
  }
  text << "  -h, --help                 show this help\n";
  return text.str();
}

// The value of a numeric option, checked against the library's range of its parameter, so
// that a bad value fails before the mesh is read, naming the option and its range.
double parse_number(const std::string& option, const std::string& text)
{
  const Numeric_setting& o = numeric_option(option);
  std::istringstream in(text);
  double value;
  if(!(in >> value) || !in.eof())
  {
    // istream cannot read "nan" or "inf": name them as out of range, not as unreadable.
    if(text == "nan" || text == "NaN" || text == "inf" || text == "-inf")
      value = text == "-inf" ? -HUGE_VAL : text == "inf" ? HUGE_VAL : std::nan("");
    else
      throw Usage_error("option " + option + " needs a number, got '" + text + "'");
  }
  if(!o.range.contains(value))
    throw Usage_error("option " + option + " (" + o.range.name + ") must be " + o.range.valid_values() +
                      ", got " + text);
  return value;
}

int parse_thread_count(const std::string& text)
{
  int threads = 0;
  std::istringstream in(text);
  if(!(in >> threads) || !in.eof() || threads < 1 || threads > 1024)
    throw Usage_error("option --threads needs an integer in [1, 1024], got '" + text + "'");
  return threads;
}

Options parse_options(int argc, char** argv)
{
  Options o;
  std::vector<std::string> args(argv + 1, argv + argc);
  for(std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if(i + 1 >= args.size())
        throw Usage_error("option " + a + " needs a value");
      return args[++i];
    };
    if(a == "-h" || a == "--help")
    {
      std::cout << usage_text();
      std::exit(0);
    }
    else if(a == "-o" || a == "--output") o.output = value();
    else if(a == "--svg") o.svg = value();
    else if(a == "--svg-stage") o.svg_stage = value();
    else if(a == "--reeb") o.reeb_graph = true;
    else if(a == "--batch") o.batch = value();
    else if(a == "--threads") o.threads = parse_thread_count(value());
    else if(a == "--no-fill-holes") o.fill_holes = false;
    else if(a == "--peel-surface-voxels") o.keep_surface_voxels = false;
    else if(a == "--skeleton") o.skeleton = value();
    else if(a == "--weights") o.weights = true;
    else if(const Numeric_setting* setting = skeletonize_settings::setting_of_option(a))
      setting->set(o, parse_number(a, value()));
    else if(!a.empty() && a[0] == '-')
      throw Usage_error("unknown option " + a + " (see --help)");
    else if(o.input.empty()) o.input = a;
    else
      throw Usage_error("more than one input mesh: '" + o.input + "' and '" + a + "'");
  }
  if(!o.batch.empty())
  {
    if(!o.input.empty())
      throw Usage_error("--batch takes its meshes from " + o.batch + ", not '" + o.input + "'");
    if(o.output.empty())
      throw Usage_error("--batch needs an output folder: -o OUT_DIR");
    if(!o.svg.empty())
      throw Usage_error("--svg draws one mesh; it cannot be used with --batch");
    if(!o.skeleton.empty())
      throw Usage_error("--skeleton is the rig of one mesh; it cannot be used with --batch");
  }
  else if(o.input.empty())
    throw Usage_error("no input mesh (see --help)");
  if(o.svg_stage == "reeb")
    o.reeb_graph = true;
  return o;
}

bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The formats read through Assimp rather than CGAL.
bool is_scene_file(const std::string& path)
{
  const std::string extension = gs::IO::internal::file_extension(path);
  return extension == "fbx" || extension == "gltf" || extension == "glb" || extension == "dae";
}

bool is_gltf_output(const std::string& path) { return ends_with(path, ".glb") || ends_with(path, ".gltf"); }

// The plug-in of the scene formats (skeletonize_formats.h), loaded once, on first use, from
// the folder of this program.
const skeletonize_formats::Functions& scene_formats()
{
  static const skeletonize_formats::Functions* functions = nullptr;
  static std::string problem;
  static std::once_flag loaded;
  std::call_once(loaded, [] {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::string path =
        error ? std::string(skeletonize_formats::file_name) : (program.parent_path() / skeletonize_formats::file_name).string();
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if(library == nullptr)
    {
      problem = std::string("reading FBX, glTF and DAE files and writing glTF files need the plug-in ") +
                skeletonize_formats::file_name + " beside skeletonize: " + dlerror();
      return;
    }
    using Entry_point = const skeletonize_formats::Functions* (*)();
    if(auto entry = reinterpret_cast<Entry_point>(dlsym(library, skeletonize_formats::entry_point)))
      functions = entry();
    else
      problem = path + " is not skeletonize's formats plug-in";
  });
  if(functions == nullptr)
    throw Usage_error(problem);
  return *functions;
}

// The skinning weights of the mesh for the control skeleton, and what they cost.
struct Skinning
{
  std::vector<gs::Bone_weights> weights;
  std::vector<int> segment; // the bone of largest weight of each vertex
  gs::Skinning_report report;
  const Mesh& mesh;
  std::string input;            // the mesh file
  bool file_numbering = false;  // the mesh's vertex i is the file's point i
};

// `solid`: the chain's voxelization of the mesh at `o.resolution`, if it ran (none with a
// given skeleton): the weights do not voxelize the mesh again.
void compute_skinning(const Options& o, const std::string& input, const gs::Control_skeleton<Point>& control,
                      const gs::Dense_voxel_grid* solid, Skinning& skinning)
{
  const Mesh& mesh = skinning.mesh;
  skinning.weights.assign(num_vertices(mesh), gs::Bone_weights());
  skinning.segment.assign(num_vertices(mesh), -1);
  try
  {
    skinning.report = skeletonize_settings::compute_skinning_weights(
        mesh, control, o, solid,
        boost::make_iterator_property_map(skinning.weights.begin(), get(CGAL::vertex_index, mesh)),
        boost::make_iterator_property_map(skinning.segment.begin(), get(CGAL::vertex_index, mesh)),
        o.batch.empty()); // a batch keeps every core busy with meshes already
  }
  catch(const std::exception& e)
  {
    throw Usage_error(input + ": " + e.what());
  }
}

// For each point of the mesh file `path` (a format CGAL reads), the mesh vertex at the same
// position; a point the repair dropped (isolated, or only in degenerate faces) takes the
// nearest vertex. The repair of a file that is not a clean manifold merges, splits and drops
// points, so the mesh's vertex numbers are not the file's: weights are written by the file's.
std::vector<std::size_t> mesh_vertex_of_file_points(const std::string& path, const Mesh& mesh)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    throw Usage_error(path + ": cannot be read again to number the weights by its vertices");
  std::map<Point, std::size_t> vertex_at;
  for(vertex_descriptor v : vertices(mesh))
    vertex_at.emplace(mesh.point(v), std::size_t(v));
  std::vector<std::size_t> vertex_of(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(const auto found = vertex_at.find(points[i]); found != vertex_at.end())
    {
      vertex_of[i] = found->second;
      continue;
    }
    double best = HUGE_VAL; // rare (dropped points): a linear scan
    for(vertex_descriptor v : vertices(mesh))
      if(const double d = CGAL::squared_distance(points[i], mesh.point(v)); d < best)
      {
        best = d;
        vertex_of[i] = std::size_t(v);
      }
  }
  return vertex_of;
}

// The report's "skinning": the settings and costs.
void add_skinning_json(const Options& o, const Skinning& skinning, nlohmann::json& json)
{
  const gs::Skinning_report& r = skinning.report;
  json["skinning"] = {{"max_bones_per_vertex", o.max_bones_per_vertex}, {"sharpness", o.sharpness},
                      {"minimum_weight", o.minimum_weight},
                      {"influence_ratio", o.influence_ratio}, {"resolution", o.resolution},
                      {"voxel_size", r.voxel_size}, {"solid_voxels", r.solid_voxels},
                      {"voxel_visits", r.voxel_visits},
                      {"vertices_bound_in_straight_line", r.vertices_bound_in_straight_line},
                      {"milliseconds", r.milliseconds}};
}

// Writes the report's "weights" to `out`: the non-zero weights as three parallel arrays
// (vertex, bone, weight), vertex by vertex, largest weight first. Vertices are numbered as
// in the input file when CGAL reads its format (the mesh's own numbering for the scene
// formats read through Assimp). The numbers are written by std::to_chars, each in its
// shortest form that reads back to the same value, in pieces of a few thousand vertices,
// two at a time, one on each core, then handed to the file: formatting, not the disk, is
// what takes the time (3.3 million faces: 78 MB at about 40 ns per weight), and the text of
// all the weights is never held at once.
void write_weights_json(std::ostream& out, const Skinning& skinning)
{
  std::vector<std::size_t> mesh_vertex(skinning.weights.size());
  for(std::size_t v = 0; v < mesh_vertex.size(); ++v)
    mesh_vertex[v] = v;
  if(!is_scene_file(skinning.input) && !skinning.file_numbering)
    mesh_vertex = mesh_vertex_of_file_points(skinning.input, skinning.mesh);
  // Piece p of an array is its numbers for the vertices [p * piece, (p + 1) * piece), each
  // after a comma; the array's first comma is not written.
  constexpr std::size_t piece = 1 << 15;
  const std::size_t pieces = (mesh_vertex.size() + piece - 1) / piece;
  auto piece_end = [&](std::size_t p) { return std::min(mesh_vertex.size(), (p + 1) * piece); };
  std::size_t most_pairs = 0; // in a piece
  for(std::size_t p = 0; p < pieces; ++p)
  {
    std::size_t pairs = 0;
    for(std::size_t v = p * piece; v < piece_end(p); ++v)
      pairs += skinning.weights[mesh_vertex[v]].size();
    most_pairs = std::max(most_pairs, pairs);
  }
  struct Text
  {
    std::unique_ptr<char[]> bytes; // not initialised: only what is written is touched
    std::size_t size = 0;
  };
  auto write_piece = [&](int array, std::size_t p, Text& text) {
    char* c = text.bytes.get();
    for(std::size_t v = p * piece; v < piece_end(p); ++v)
    {
      const gs::Bone_weights& w = skinning.weights[mesh_vertex[v]];
      for(std::size_t i = 0; i < w.size(); ++i)
      {
        *c++ = ',';
        c = array == 0   ? std::to_chars(c, c + 32, std::uint32_t(v)).ptr
            : array == 1 ? std::to_chars(c, c + 32, w.bone[i]).ptr
                         : std::to_chars(c, c + 32, w.weight[i]).ptr;
      }
    }
    text.size = std::size_t(c - text.bytes.get());
  };
  Text text[2] = {{std::unique_ptr<char[]>(new char[33 * most_pairs + 1])},
                  {std::unique_ptr<char[]>(new char[33 * most_pairs + 1])}};
  out << "{\"vertices\": " << mesh_vertex.size();
  for(int array = 0; array < 3; ++array)
  {
    out << (array == 0 ? ", \"vertex\": [" : array == 1 ? "], \"bone\": [" : "], \"weight\": [");
    bool empty = true; // nothing written yet: the next text's comma is left off
    for(std::size_t p = 0; p < pieces; p += 2)
    {
      std::future<void> second;
      if(p + 1 < pieces)
        second = gs::internal::start_beside(2, [&, p] { write_piece(array, p + 1, text[1]); });
      write_piece(array, p, text[0]);
      if(p + 1 < pieces)
        second.get();
      for(int t = 0; t < (p + 1 < pieces ? 2 : 1); ++t)
        if(text[t].size > 0)
        {
          out.write(text[t].bytes.get() + empty, std::streamsize(text[t].size - empty));
          empty = false;
        }
    }
  }
  out << "]}";
}

// Writes the report: `json`, and then, when `skinning` is not null, the weights as its last
// member "weights" (after every other key: the tree's keys are in alphabetical order).
void write_report(std::ostream& out, const nlohmann::json& json, const Skinning* skinning)
{
  std::string text = json.dump(1);
  if(skinning != nullptr)
  {
    text.pop_back(); // the closing brace
    out << text << ",\n \"weights\": ";
    write_weights_json(out, *skinning);
    out << "\n}\n";
  }
  else
    out << text << '\n';
}

// Reads any mesh CGAL reads, and FBX, glTF/GLB and DAE files through Assimp (a file that is
// not a clean manifold is repaired); the library's readers name the file and the problem.
// `file_numbering` is set when the mesh's vertex i is the file's point i.
Mesh read_mesh(const std::string& path, bool& file_numbering)
{
  Mesh mesh;
  file_numbering = false;
  try
  {
    if(is_scene_file(path))
    {
      if(const std::string problem = scene_formats().read_scene(path, mesh); !problem.empty())
        throw Usage_error(problem);
    }
    else
      file_numbering = gs::IO::read_mesh(path, mesh);
  }
  catch(const std::runtime_error& e)
  {
    throw Usage_error(e.what());
  }
  return mesh;
}

nlohmann::json stage_json(const gs::Skeleton_statistics& s)
{
  return {{"points", s.points}, {"end_points", s.end_points}, {"junctions", s.junctions}, {"cycles", s.cycles}};
}

// Calls write(stream) on a temporary file and renames it `path`, so that a failure (of the
// stream, or an exception of `write`) leaves no half file.
template <typename Write>
void write_file(const std::string& path, const Write& write)
{
  const std::string temporary = path + ".partial";
  try
  {
    std::ofstream out(temporary, std::ios::binary);
    if(out)
      write(out);
    if(!out || !out.flush())
      throw Usage_error(path + ": cannot write the file");
  }
  catch(...)
  {
    std::remove(temporary.c_str());
    throw;
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw Usage_error(path + ": cannot write the file");
  }
}

// The mesh's counts for the JSON, in one pass over the edges: whether it is closed, and its
// connected parts, its vertices joined along edges, isolated vertices left out (a
// union-find: PMP::connected_components() walks the faces through property maps, and on a
// mesh of a million faces costs as much as the whole chain).
nlohmann::json mesh_json(const Mesh& mesh)
{
  boost::disjoint_sets_with_storage<> parts(mesh.num_vertices()); // by vertex index, removed ones too
  bool closed = true;
  for(auto e : edges(mesh))
  {
    closed = closed && !is_border(e, mesh);
    parts.union_set(std::size_t(source(e, mesh)), std::size_t(target(e, mesh)));
  }
  std::size_t components = 0;
  for(vertex_descriptor v : vertices(mesh))
    components += !mesh.is_isolated(v) && parts.find_set(std::size_t(v)) == std::size_t(v);
  return {{"vertices", num_vertices(mesh)}, {"faces", num_faces(mesh)}, {"closed", closed}, {"components", components}};
}

// The largest resident memory of this process so far, in MiB (Linux: VmHWM of
// /proc/self/status), or a negative number where the system does not say.
double peak_resident_mib()
{
  std::ifstream status("/proc/self/status");
  for(std::string line; std::getline(status, line);)
    if(line.compare(0, 6, "VmHWM:") == 0)
      return std::stod(line.substr(6)) / 1024; // kB
  return -1;
}

// What one mesh gave, for the summary line and the batch's report.
struct Mesh_summary
{
  std::size_t vertices = 0, faces = 0, joints = 0, bones = 0;
  double read_ms = 0, chain_ms = 0;
};

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void check_output_format(const std::string& output)
{
  if(!output.empty() && !ends_with(output, ".json") && !ends_with(output, ".obj") && !ends_with(output, ".bvh") &&
     !ends_with(output, ".polylines.txt") && !is_gltf_output(output))
    throw Usage_error(output + ": unknown output format (use .json, .obj, .bvh, .polylines.txt, .glb or .gltf)");
}

// Skeletonizes `input` and writes `output` (standard output when empty) as `o` says.
Mesh_summary skeletonize(const Options& o, const std::string& input, const std::string& output)
{
  const auto start = std::chrono::steady_clock::now();
  const bool to_json = output.empty() || ends_with(output, ".json");
  const bool to_gltf = is_gltf_output(output);
  const bool given_skeleton = !o.skeleton.empty();
  bool file_numbering = false;
  const Mesh mesh = read_mesh(input, file_numbering);
  Mesh_summary summary;
  summary.read_ms = milliseconds_since(start);
  // The JSON's "mesh" entry (its parts and border edges: a union-find over every edge, long
  // on a large mesh) is counted on the second core while the chain runs on the first (a
  // batch already keeps every core busy with meshes).
  std::future<nlohmann::json> mesh_entry =
      gs::internal::start_beside(o.batch.empty() && to_json ? 2 : 1, [&mesh] { return mesh_json(mesh); });
  gs::Curve_skeleton<Point, vertex_descriptor> curve, thinned;
  gs::Reeb_graph<Mesh> reeb;
  gs::Control_skeleton<Point> control;
  gs::Control_skeleton_report report;
  // The thinned graph and the Reeb graph cost as much as the chain on large meshes: each is
  // computed only when asked for (the picture of the thinned skeleton, --reeb).
  const bool thinned_graph = o.svg_stage == "thinned" && !o.svg.empty();
  // A given skeleton is there to be skinned: its report always has the weights' summary.
  const bool skin = given_skeleton || o.weights || to_gltf || o.svg_stage == "weights";
  gs::Dense_voxel_grid solid; // the chain's, for the weights
  if(given_skeleton)
  {
    try
    {
      gs::IO::read_control_skeleton_json(o.skeleton, control);
    }
    catch(const std::runtime_error& e) // "RIG.json: problem"
    {
      throw Usage_error(e.what());
    }
  }
  else try
  {
    report = skeletonize_settings::extract_control_skeleton(
        mesh, control, o,
        skeletonize_settings::Chain_outputs<Mesh, Point>{&curve, thinned_graph ? &thinned : nullptr,
                                                         o.reeb_graph ? &reeb : nullptr, skin ? &solid : nullptr});
  }
  catch(const std::exception& e) // the stages' messages name the stage and the problem
  {
    throw Usage_error(input + ": " + e.what());
  }
  Skinning skinning{{}, {}, {}, mesh, input, file_numbering};
  if(skin)
    compute_skinning(o, input, control, given_skeleton ? nullptr : &solid, skinning);

  // What goes to the output, written straight into the file (or standard output) at the end.
  std::function<void(std::ostream&)> write_output;
  if(to_json && given_skeleton)
  {
    nlohmann::json json = {{"input", input},
                           {"skeleton_input", o.skeleton},
                           {"mesh", mesh_entry.get()},
                           {"timings_ms", {{"skinning_weights", skinning.report.milliseconds}}},
                           {"control", gs::IO::control_skeleton_to_json(control)}};
    add_skinning_json(o, skinning, json); // a given skeleton is always skinned
    write_output = [&, json = std::move(json)](std::ostream& out) {
      write_report(out, json, o.weights ? &skinning : nullptr);
    };
  }
  else if(to_json)
  {
    nlohmann::json timings{{"total", report.total_ms}, {"read", summary.read_ms}};
    for(const auto& [stage, ms] : report.timings_ms)
      timings[stage] = ms;
    if(skin)
      timings["skinning_weights"] = skinning.report.milliseconds;
    nlohmann::json stages = {
        {"solid", {{"voxels", report.solid_voxels}, {"pieces", report.small_pieces.pieces},
                   {"voxels_joining_pieces", report.voxels_joining_pieces},
                   {"small_pieces_removed", report.small_pieces.removed_pieces}}},
        {"thinned", stage_json(report.thinned)},
        {"sheet_lobes", {{"sheet_voxels", report.sheet_lobes.sheet_voxels},
                         {"lobes_reached", report.sheet_lobes.lobes_reached},
                         {"voxels_added", report.sheet_lobes.voxels_added}}},
        {"spurious_cycles", {{"cut", report.spurious_cycles_cut}}},
        {"pruned", stage_json(report.pruned)},
        {"routed", {{"branches_along_level_of_detail", report.branches_along_level_of_detail}}},
        {"inside", {{"curve_points_moved", report.curve_points_moved_inside},
                    {"joints_moved", report.joints_moved_inside}}}};
    nlohmann::json computed = {"curve_skeleton", "control_skeleton"};
    if(o.reeb_graph)
    {
      stages["reeb"] = {{"nodes", report.reeb_nodes}, {"edges", report.reeb_edges}};
      computed.push_back("reeb_graph");
    }
    if(thinned_graph)
      computed.push_back("thinned_graph");
    if(skin)
      computed.push_back("skinning_weights");
    const nlohmann::json control_json = gs::IO::control_skeleton_to_json(control);
    // Batch mode's meshes share the process: its peak is no one mesh's.
    const double peak_mib = o.batch.empty() ? peak_resident_mib() : -1;
    nlohmann::json json = {
        {"input", input},
        {"mesh", mesh_entry.get()},
        {"parameters", {{"resolution", o.resolution}, {"fill_holes", o.fill_holes},
                        {"keep_surface_voxels", o.keep_surface_voxels},
                        {"small_piece_fraction", o.small_piece_fraction},
                        {"thin_part_radius", report.thin_part_radius},
                        {"spur_length_factor", o.spur_length_factor},
                        {"limb_protrusion_factor", o.limb_protrusion_factor},
                        {"sheet_lobe_reach_factor", o.sheet_lobe_reach_factor},
                        {"level_of_detail_resolution", o.level_of_detail_resolution},
                        {"smoothing_window", report.smoothing_window},
                        {"bend_threshold", o.bend_threshold},
                        {"straightness_tolerance", o.straightness_tolerance},
                        {"minimum_bone_length_factor", o.minimum_bone_length_factor},
                        {"maximum_bone_length_factor", o.maximum_bone_length_factor},
                        {"minimum_bone_length_of_piece_factor", o.minimum_bone_length_of_piece_factor},
                        {"tip_joint_setback", report.tip_joint_setback},
                        {"joint_spacing", report.joint_spacing},
                        {"smallest_radius", report.smallest_radius},
                        {"reeb_intervals", o.reeb_intervals}, {"voxel_size", report.voxel_size}}},
        {"computed", computed},
        {"timings_ms", timings},
        {"peak_memory_mib", peak_mib >= 0 ? nlohmann::json(peak_mib) : nlohmann::json(nullptr)},
        {"stages", stages},
        {"skeleton", gs::IO::curve_skeleton_to_json(curve)},
        {"control", {{"joints", control_json["joints"]}, {"bones", control_json["bones"]},
                     {"cut_bones", control_json["cut_bones"]}, {"roots", control_json["roots"]}}}};
    if(skin)
      add_skinning_json(o, skinning, json);
    write_output = [&, json = std::move(json)](std::ostream& out) {
      write_report(out, json, skin && o.weights ? &skinning : nullptr);
    };
  }
  else if(to_gltf)
  {
    write_output = [&](std::ostream& out) {
      if(const std::string problem =
             scene_formats().write_glTF(out, mesh, control, skinning.weights, ends_with(output, ".glb"));
         !problem.empty())
        throw Usage_error(output + ": " + problem);
    };
  }
  else
  {
    std::ostringstream out;
    if(ends_with(output, ".obj"))
      gs::IO::write_OBJ(out, control);
    else if(ends_with(output, ".bvh"))
      gs::IO::write_BVH(out, control);
    else
      gs::IO::write_polylines(out, control);
    write_output = [text = out.str()](std::ostream& out) { out << text; };
  }
  if(output.empty())
    write_output(std::cout);
  else
    write_file(output, write_output);

  if(!o.svg.empty())
  {
    std::ostringstream picture;
    const std::string name = input.substr(input.find_last_of('/') + 1);
    if(o.svg_stage == "weights")
      gs::IO::write_svg_preview_of_labels(picture, mesh, skinning.segment, control, 360,
                                          name + ": skinning, the bone of largest weight, " +
                                              std::to_string(num_edges(control)) + " bones");
    else if(o.svg_stage == "control")
      gs::IO::write_svg_preview(picture, mesh, control, 360,
                                name + ": control skeleton, " + std::to_string(num_edges(control)) + " bones");
    else if(o.svg_stage == "pruned")
      gs::IO::write_svg_preview_of_graph(picture, mesh, curve, 360,
                                         name + ": pruned, smoothed curve skeleton, " +
                                             std::to_string(num_vertices(curve)) + " points");
    else if(o.svg_stage == "thinned")
      gs::IO::write_svg_preview_of_graph(picture, mesh, thinned, 360,
                                         name + ": curve skeleton after thinning, " +
                                             std::to_string(num_vertices(thinned)) + " points");
    else
      gs::IO::write_svg_preview_of_graph(picture, mesh, reeb, 360,
                                         name + ": Reeb graph of the geodesic distance, " +
                                             std::to_string(num_vertices(reeb)) + " nodes");
    write_file(o.svg, [&picture](std::ostream& out) { out << picture.str(); });
  }

  summary.vertices = num_vertices(mesh);
  summary.faces = num_faces(mesh);
  summary.joints = num_vertices(control);
  summary.bones = num_edges(control);
  summary.chain_ms = report.total_ms;
  if(!o.batch.empty())
    return summary;
  if(given_skeleton)
    std::cerr << "skeletonize: " << input << ": " << num_vertices(mesh) << " vertices, skinned to "
              << o.skeleton << " (" << num_vertices(control) << " joints, " << num_edges(control) << " bones) in "
              << skinning.report.milliseconds << " ms\n";
  else
    std::cerr << "skeletonize: " << input << ": " << num_vertices(mesh) << " vertices, " << report.solid_voxels
              << " solid voxels, " << report.thinned.points << " thinned points, " << report.pruned.points
              << " pruned points, " << num_vertices(control) << " joints, " << num_edges(control) << " bones, "
              << summary.read_ms << " ms reading, " << report.total_ms << " ms skeletonizing\n";
  return summary;
}

int run(const Options& o)
{
  // Check the output's format and the picture's options before the work.
  check_output_format(o.output);
  if(!o.svg.empty() && !ends_with(o.svg, ".svg"))
    throw Usage_error(o.svg + ": the preview must be an .svg file");
  if(o.svg_stage != "control" && o.svg_stage != "pruned" && o.svg_stage != "thinned" && o.svg_stage != "reeb" &&
     o.svg_stage != "weights")
    throw Usage_error("--svg-stage must be control, pruned, thinned, reeb or weights, got '" + o.svg_stage + "'");
  if(!o.skeleton.empty() && o.svg_stage != "control" && o.svg_stage != "weights")
    throw Usage_error("--svg-stage " + o.svg_stage + " shows a stage of the extraction, which --skeleton skips");
  if(is_scene_file(o.input) || is_gltf_output(o.output))
    scene_formats(); // fails now, before the work, when the plug-in is missing
  skeletonize(o, o.input, o.output);
  return 0;
}

// ---- Batch mode ------------------------------------------------------------------------

// The files a batch takes from a folder: CGAL's common mesh formats and the scene formats.
bool is_mesh_file(const std::string& path)
{
  const std::string extension = gs::IO::internal::file_extension(path);
  return extension == "off" || extension == "obj" || extension == "ply" || extension == "stl" || is_scene_file(path);
}

// The meshes of a batch: the mesh files of a folder, by name, or the lines of a list file
// (blank lines and lines starting with '#' skipped; relative paths are relative to the
// list's folder).
std::vector<std::string> batch_inputs(const std::string& batch)
{
  namespace fs = std::filesystem;
  std::error_code error;
  std::vector<std::string> inputs;
  if(fs::is_directory(batch, error))
  {
    for(const fs::directory_entry& entry : fs::directory_iterator(batch, error))
      if(entry.is_regular_file(error) && is_mesh_file(entry.path().string()))
        inputs.push_back(entry.path().string());
    if(error)
      throw Usage_error(batch + ": cannot list the folder: " + error.message());
    std::sort(inputs.begin(), inputs.end());
  }
  else
  {
    std::ifstream list(batch);
    if(!list)
      throw Usage_error(batch + ": no such folder or list file");
    const fs::path folder = fs::path(batch).parent_path();
    for(std::string line; std::getline(list, line);)
    {
      line.erase(0, line.find_first_not_of(" \t\r"));
      line.erase(line.find_last_not_of(" \t\r") + 1);
      if(line.empty() || line[0] == '#')
        continue;
      const fs::path path(line);
      inputs.push_back(path.is_absolute() || folder.empty() ? line : (folder / path).string());
    }
  }
  if(inputs.empty())
    throw Usage_error(batch + ": no meshes to skeletonize (.off, .obj, .ply, .stl, .fbx, .gltf, .glb, .dae)");
  return inputs;
}

// OUT_DIR/NAME.json for each input; a second mesh of the same name gets NAME-2.json, etc.
std::vector<std::string> batch_outputs(const std::vector<std::string>& inputs, const std::string& folder)
{
  namespace fs = std::filesystem;
  std::map<std::string, int> uses;
  std::vector<std::string> outputs;
  for(const std::string& input : inputs)
  {
    const std::string stem = fs::path(input).stem().string();
    const int n = ++uses[stem];
    outputs.push_back((fs::path(folder) / (stem + (n > 1 ? "-" + std::to_string(n) : "") + ".json")).string());
  }
  return outputs;
}

// Prints the summary lines in the order of the inputs, whatever order the meshes finish
// in, and a progress bar on standard error when it is a terminal.
class Batch_report
{
public:
  explicit Batch_report(std::size_t meshes)
    : m_lines(meshes), m_ready(meshes, false), m_progress_bar(isatty(fileno(stderr)) != 0)
  {}

  void finished(std::size_t i, std::string line, bool failed)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_lines[i] = std::move(line);
    m_ready[i] = true;
    ++m_done;
    m_failed += failed;
    if(m_progress_bar)
      std::cerr << "\r\033[K";
    for(; m_printed < m_lines.size() && m_ready[m_printed]; ++m_printed)
      std::cout << m_lines[m_printed] << std::endl;
    if(m_progress_bar)
      draw_bar();
  }
  std::size_t failed() const { return m_failed; }
  void close()
  {
    if(m_progress_bar)
      std::cerr << "\r\033[K";
  }

private:
  void draw_bar()
  {
    const std::size_t width = 30, filled = width * m_done / m_lines.size();
    std::cerr << "[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << m_done << "/"
              << m_lines.size() << " meshes" << (m_failed ? ", " + std::to_string(m_failed) + " failed" : "")
              << std::flush;
  }

  std::mutex m_mutex;
  std::vector<std::string> m_lines;
  std::vector<bool> m_ready;
  std::size_t m_printed = 0, m_done = 0, m_failed = 0;
  bool m_progress_bar;
};

// Skeletonizes every mesh of the batch, several at once; a mesh that fails is reported
// and the batch goes on. Exit code 1 when any mesh failed.
int run_batch(const Options& o)
{
  const std::vector<std::string> inputs = batch_inputs(o.batch);
  std::error_code error;
  std::filesystem::create_directories(o.output, error);
  if(!std::filesystem::is_directory(o.output))
    throw Usage_error(o.output + ": cannot create the output folder");
  const std::vector<std::string> outputs = batch_outputs(inputs, o.output);

  const auto start = std::chrono::steady_clock::now();
  Batch_report report(inputs.size());
  const long count = static_cast<long>(inputs.size());
#if defined(_OPENMP)
  const int threads = o.threads > 0 ? o.threads : omp_get_num_procs();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
#endif
  for(long i = 0; i < count; ++i)
  {
    const auto mesh_start = std::chrono::steady_clock::now();
    nlohmann::json line = {{"input", inputs[i]}};
    bool failed = false;
    try
    {
      const Mesh_summary s = skeletonize(o, inputs[i], outputs[i]);
      line.update({{"ok", true}, {"output", outputs[i]}, {"vertices", s.vertices}, {"faces", s.faces},
                   {"joints", s.joints}, {"bones", s.bones}, {"read_ms", s.read_ms}, {"chain_ms", s.chain_ms}});
    }
    catch(const std::exception& e)
    {
      failed = true;
      line.update({{"ok", false}, {"error", e.what()}});
    }
    line["wall_ms"] = milliseconds_since(mesh_start);
    report.finished(std::size_t(i), line.dump(), failed);
  }
  report.close();
  const double seconds = milliseconds_since(start) / 1000;
  std::cerr << "skeletonize: " << inputs.size() - report.failed() << " of " << inputs.size()
            << " meshes skeletonized in " << seconds << " s (" << double(inputs.size()) / seconds
            << " meshes/s)" << (report.failed() ? ", " + std::to_string(report.failed()) + " failed" : "") << "\n";
  return report.failed() == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
#if defined(__GLIBC__)
  // Keep freed memory in the heap for the next stage instead of handing it back to the
  // system: the reader's arrays are freed before the chain allocates its own, and on a
  // virtual machine a fresh page can cost more than the work done in it (measured in
  // benchmark/README.md).
  mallopt(M_MMAP_MAX, 0); // big arrays come from the heap too, and go back to it
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  try
  {
    const Options options = parse_options(argc, argv);
    return options.batch.empty() ? run(options) : run_batch(options);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "skeletonize: error: " << e.what() << '\n';
  }
  catch(const std::exception& e)
  {
    std::cerr << "skeletonize: error: " << e.what() << '\n';
  }
  return 1;
}
