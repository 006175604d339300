// skeletonize: the package's main program. Mesh in, animation control skeleton out, with
// every stage's counts and timings, and a picture on request.
//
//   skeletonize INPUT_MESH [-o OUT] [--resolution N] [--svg PREVIEW.svg] [stage options]
//
// The format of OUT follows its extension: .json (the documented contract, also written to
// standard output when there is no -o), .obj, .bvh, .polylines.txt, and .glb or .gltf (the
// mesh skinned to its skeleton). See --help.

#include <CGAL/Geodesic_skeleton.h>
#include <CGAL/Geodesic_skeleton/IO/gltf.h>
#include <CGAL/Geodesic_skeleton/IO/read_control_skeleton_json.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh_with_assimp.h>
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
namespace ranges = CGAL::Geodesic_skeleton::parameter_ranges;
namespace PMP = CGAL::Polygon_mesh_processing;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

namespace {

// An error the user can fix: printed as "skeletonize: error: <message>", exit code 1.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The defaults and valid ranges are the library's (CGAL/Geodesic_skeleton/parameter_ranges.h).
struct Options
{
  std::string input, output, svg, svg_stage = "control";
  int resolution = gs::default_voxel_resolution;
  double small_piece_fraction = ranges::small_piece_fraction.default_value;
  double spur_length_factor = ranges::spur_length_factor.default_value;
  int smoothing_window = static_cast<int>(ranges::smoothing_window.default_value);
  double bend_threshold = ranges::bend_threshold.default_value;
  double straightness_tolerance = ranges::straightness_tolerance.default_value;
  double minimum_bone_length_factor = ranges::minimum_bone_length_factor.default_value;
  std::size_t reeb_intervals = static_cast<std::size_t>(ranges::number_of_reeb_intervals.default_value);
  bool fill_holes = true;
  bool keep_surface_voxels = true;
  // Skinning: a given skeleton instead of the extracted one, the weights in the report.
  std::string skeleton;
  bool weights = false;
  int max_bones_per_vertex = static_cast<int>(ranges::max_bones_per_vertex.default_value);
  double falloff = ranges::falloff.default_value;
  double influence_ratio = ranges::influence_ratio.default_value;
};

// The numeric options: option, library range, the words of --help.
struct Numeric_option
{
  const char* option;
  const char* metavar;
  const gs::Parameter_range& range;
  const char* help;
};
const Numeric_option numeric_options[] = {
    {"--resolution", "N", ranges::resolution, "voxels along the longest principal axis"},
    {"--small-pieces", "F", ranges::small_piece_fraction,
     "drop detached pieces smaller than F times the largest (0 keeps all)"},
    {"--spur-length", "F", ranges::spur_length_factor, "snip end branches shorter than F MAT radii"},
    {"--smoothing-window", "W", ranges::smoothing_window, "points averaged along branches"},
    {"--bend-threshold", "T", ranges::bend_threshold, "chord-to-point accumulation that makes a joint"},
    {"--straightness", "S", ranges::straightness_tolerance, "allowed bone deviation in MAT radii"},
    {"--min-bone-length", "F", ranges::minimum_bone_length_factor, "shortest bone in MAT radii"},
    {"--reeb-intervals", "N", ranges::number_of_reeb_intervals, "intervals of the Reeb graph reported for comparison"},
    {"--max-bones", "K", ranges::max_bones_per_vertex, "skinning: bones that may influence one vertex"},
    {"--falloff", "P", ranges::falloff, "skinning: exponent of the inverse-distance weights"},
    {"--influence-ratio", "S", ranges::influence_ratio,
     "skinning: a bone pulls a vertex up to S times the nearest bone's distance"},
};

const Numeric_option& numeric_option(const std::string& option)
{
  for(const Numeric_option& o : numeric_options)
    if(option == o.option)
      return o;
  throw std::logic_error("no numeric option " + option);
}

const char* const usage_head = R"(usage: skeletonize INPUT_MESH [-o OUT] [--resolution N] [--svg PREVIEW.svg] [options]

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
  --no-fill-holes            do not close the mesh's holes before voxelizing
  --peel-surface-voxels      drop the surface voxels whose centre is outside the mesh (opens
                             false loops between parts that nearly touch; default: kept)
)";

std::string usage_text()
{
  std::ostringstream text;
  text << usage_head;
  for(const Numeric_option& o : numeric_options)
    text << "  " << std::left << std::setw(27) << (std::string(o.option) + " " + o.metavar) << o.help << ",\n"
         << std::setw(29) << "" << o.range.valid_values() << " (default " << o.range.default_value << ")\n";
  text << "  -h, --help                 show this help\n";
  return text.str();
}

// The value of a numeric option, checked against the library's range of its parameter, so
// that a bad value fails before the mesh is read, naming the option and its range.
template <typename T>
T parse_number(const std::string& option, const std::string& text)
{
  const Numeric_option& o = numeric_option(option);
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
  return static_cast<T>(value);
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
    else if(a == "--resolution") o.resolution = parse_number<int>(a, value());
    else if(a == "--no-fill-holes") o.fill_holes = false;
    else if(a == "--peel-surface-voxels") o.keep_surface_voxels = false;
    else if(a == "--small-pieces") o.small_piece_fraction = parse_number<double>(a, value());
    else if(a == "--spur-length") o.spur_length_factor = parse_number<double>(a, value());
    else if(a == "--smoothing-window") o.smoothing_window = parse_number<int>(a, value());
    else if(a == "--bend-threshold") o.bend_threshold = parse_number<double>(a, value());
    else if(a == "--straightness") o.straightness_tolerance = parse_number<double>(a, value());
    else if(a == "--min-bone-length") o.minimum_bone_length_factor = parse_number<double>(a, value());
    else if(a == "--reeb-intervals") o.reeb_intervals = parse_number<std::size_t>(a, value());
    else if(a == "--skeleton") o.skeleton = value();
    else if(a == "--weights") o.weights = true;
    else if(a == "--max-bones") o.max_bones_per_vertex = parse_number<int>(a, value());
    else if(a == "--falloff") o.falloff = parse_number<double>(a, value());
    else if(a == "--influence-ratio") o.influence_ratio = parse_number<double>(a, value());
    else if(!a.empty() && a[0] == '-')
      throw Usage_error("unknown option " + a + " (see --help)");
    else if(o.input.empty()) o.input = a;
    else
      throw Usage_error("more than one input mesh: '" + o.input + "' and '" + a + "'");
  }
  if(o.input.empty())
    throw Usage_error("no input mesh (see --help)");
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

// The skinning weights of the mesh for the control skeleton, and what they cost.
struct Skinning
{
  std::vector<gs::Bone_weights> weights;
  std::vector<int> segment; // the bone of largest weight of each vertex
  gs::Skinning_report report;
  auto weight_map() const { return boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, mesh)); }
  const Mesh& mesh;
};

void compute_skinning(const Options& o, const gs::Control_skeleton<Point>& control, Skinning& skinning)
{
  const Mesh& mesh = skinning.mesh;
  skinning.weights.assign(num_vertices(mesh), gs::Bone_weights());
  skinning.segment.assign(num_vertices(mesh), -1);
  try
  {
    skinning.report = gs::compute_skinning_weights(
        mesh, control,
        boost::make_iterator_property_map(skinning.weights.begin(), get(CGAL::vertex_index, mesh)),
        params::combine(params::resolution(o.resolution), params::fill_holes(o.fill_holes),
                        params::max_bones_per_vertex(o.max_bones_per_vertex), params::falloff(o.falloff),
                        params::influence_ratio(o.influence_ratio),
                        params::bone_segmentation_map(
                            boost::make_iterator_property_map(skinning.segment.begin(), get(CGAL::vertex_index, mesh)))));
  }
  catch(const std::exception& e)
  {
    throw Usage_error(o.input + ": " + e.what());
  }
}

// The report's "skinning" and "weights": the settings and costs, and the non-zero weights
// as three parallel arrays (vertex, bone, weight), vertex by vertex, largest weight first.
void add_skinning_json(const Options& o, const Skinning& skinning, nlohmann::json& json)
{
  const gs::Skinning_report& r = skinning.report;
  json["skinning"] = {{"max_bones_per_vertex", o.max_bones_per_vertex}, {"falloff", o.falloff},
                      {"influence_ratio", o.influence_ratio}, {"resolution", o.resolution},
                      {"voxel_size", r.voxel_size}, {"solid_voxels", r.solid_voxels},
                      {"voxel_visits", r.voxel_visits},
                      {"vertices_bound_in_straight_line", r.vertices_bound_in_straight_line},
                      {"milliseconds", r.milliseconds}};
  if(!o.weights)
    return;
  std::vector<std::size_t> vertex, bone;
  std::vector<float> weight;
  for(std::size_t v = 0; v < skinning.weights.size(); ++v)
    for(std::size_t i = 0; i < skinning.weights[v].size(); ++i)
    {
      vertex.push_back(v);
      bone.push_back(skinning.weights[v].bone[i]);
      weight.push_back(skinning.weights[v].weight[i]);
    }
  json["weights"] = {{"vertex", vertex}, {"bone", bone}, {"weight", weight}};
}

// Reads any mesh CGAL reads, and FBX, glTF/GLB and DAE files through Assimp (a file that is
// not a clean manifold is repaired); the library's readers name the file and the problem.
Mesh read_mesh(const std::string& path)
{
  Mesh mesh;
  try
  {
    if(is_scene_file(path))
      gs::IO::read_mesh_with_assimp(path, mesh);
    else
      gs::IO::read_mesh(path, mesh);
  }
  catch(const std::runtime_error& e)
  {
    throw Usage_error(e.what());
  }
  return mesh;
}

nlohmann::json mesh_json(const Mesh& mesh)
{
  std::vector<std::size_t> face_component(num_faces(mesh));
  const std::size_t components = PMP::connected_components(
      mesh, boost::make_iterator_property_map(face_component.begin(), get(CGAL::face_index, mesh)));
  return {{"vertices", num_vertices(mesh)}, {"faces", num_faces(mesh)}, {"closed", CGAL::is_closed(mesh)},
          {"components", components}};
}

nlohmann::json stage_json(const gs::Skeleton_statistics& s)
{
  return {{"points", s.points}, {"end_points", s.end_points}, {"junctions", s.junctions}, {"cycles", s.cycles}};
}

// Writes `text` to `path` through a temporary file, so that a failure leaves no half file.
void write_file(const std::string& path, const std::string& text)
{
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    if(!out || !(out << text) || !out.flush())
    {
      std::remove(temporary.c_str());
      throw Usage_error(path + ": cannot write the file");
    }
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw Usage_error(path + ": cannot write the file");
  }
}

int run(const Options& o)
{
  // Check the output's format before the work.
  const bool to_json = o.output.empty() || ends_with(o.output, ".json");
  const bool to_gltf = is_gltf_output(o.output);
  if(!to_json && !to_gltf && !ends_with(o.output, ".obj") && !ends_with(o.output, ".bvh") &&
     !ends_with(o.output, ".polylines.txt"))
    throw Usage_error(o.output + ": unknown output format (use .json, .obj, .bvh, .polylines.txt, .glb or .gltf)");
  if(!o.svg.empty() && !ends_with(o.svg, ".svg"))
    throw Usage_error(o.svg + ": the preview must be an .svg file");
  if(o.svg_stage != "control" && o.svg_stage != "pruned" && o.svg_stage != "thinned" && o.svg_stage != "reeb" &&
     o.svg_stage != "weights")
    throw Usage_error("--svg-stage must be control, pruned, thinned, reeb or weights, got '" + o.svg_stage + "'");
  const bool given_skeleton = !o.skeleton.empty();
  if(given_skeleton && o.svg_stage != "control" && o.svg_stage != "weights")
    throw Usage_error("--svg-stage " + o.svg_stage + " shows a stage of the extraction, which --skeleton skips");

  const Mesh mesh = read_mesh(o.input);
  gs::Curve_skeleton<Point, vertex_descriptor> curve, thinned;
  gs::Reeb_graph<Mesh> reeb;
  gs::Control_skeleton<Point> control;
  gs::Control_skeleton_report report;
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
    report = gs::extract_control_skeleton(
        mesh, control,
        params::combine(params::resolution(o.resolution), params::fill_holes(o.fill_holes),
                        params::keep_surface_voxels(o.keep_surface_voxels),
                        params::small_piece_fraction(o.small_piece_fraction),
                        params::spur_length_factor(o.spur_length_factor),
                        params::smoothing_window(o.smoothing_window),
                        params::bend_threshold(o.bend_threshold),
                        params::straightness_tolerance(o.straightness_tolerance),
                        params::minimum_bone_length_factor(o.minimum_bone_length_factor),
                        params::number_of_reeb_intervals(o.reeb_intervals),
                        params::curve_skeleton_output(&curve), params::thinned_skeleton_output(&thinned),
                        params::reeb_graph_output(&reeb)));
  }
  catch(const std::exception& e) // the stages' messages name the stage and the problem
  {
    throw Usage_error(o.input + ": " + e.what());
  }
  Skinning skinning{{}, {}, {}, mesh};
  // A given skeleton is there to be skinned: its report always has the weights' summary.
  const bool skin = given_skeleton || o.weights || to_gltf || o.svg_stage == "weights";
  if(skin)
    compute_skinning(o, control, skinning);

  std::string text;
  if(to_json && given_skeleton)
  {
    nlohmann::json json = {{"input", o.input},
                           {"skeleton_input", o.skeleton},
                           {"mesh", mesh_json(mesh)},
                           {"timings_ms", {{"skinning_weights", skinning.report.milliseconds}}},
                           {"control", gs::IO::control_skeleton_to_json(control)}};
    if(skin)
      add_skinning_json(o, skinning, json);
    text = json.dump(1) + "\n";
  }
  else if(to_json)
  {
    nlohmann::json timings{{"total", report.total_ms}};
    for(const auto& [stage, ms] : report.timings_ms)
      timings[stage] = ms;
    if(skin)
      timings["skinning_weights"] = skinning.report.milliseconds;
    const nlohmann::json control_json = gs::IO::control_skeleton_to_json(control);
    nlohmann::json json = {
        {"input", o.input},
        {"mesh", mesh_json(mesh)},
        {"parameters", {{"resolution", o.resolution}, {"fill_holes", o.fill_holes},
                        {"keep_surface_voxels", o.keep_surface_voxels},
                        {"small_piece_fraction", o.small_piece_fraction},
                        {"spur_length_factor", o.spur_length_factor},
                        {"smoothing_window", o.smoothing_window},
                        {"bend_threshold", o.bend_threshold},
                        {"straightness_tolerance", o.straightness_tolerance},
                        {"minimum_bone_length_factor", o.minimum_bone_length_factor},
                        {"reeb_intervals", o.reeb_intervals}, {"voxel_size", report.voxel_size}}},
        {"timings_ms", timings},
        {"stages", {{"solid", {{"voxels", report.solid_voxels}, {"pieces", report.small_pieces.pieces},
                               {"small_pieces_removed", report.small_pieces.removed_pieces}}},
                    {"thinned", stage_json(report.thinned)},
                    {"spurious_cycles", {{"cut", report.spurious_cycles_cut}}},
                    {"pruned", stage_json(report.pruned)},
                    {"reeb", {{"nodes", report.reeb_nodes}, {"edges", report.reeb_edges}}}}},
        {"skeleton", gs::IO::curve_skeleton_to_json(curve)},
        {"control", {{"joints", control_json["joints"]}, {"bones", control_json["bones"]},
                     {"cut_bones", control_json["cut_bones"]}, {"roots", control_json["roots"]}}}};
    if(skin)
      add_skinning_json(o, skinning, json);
    text = json.dump(1) + "\n";
  }
  else if(to_gltf)
  {
    std::ostringstream out(std::ios::binary);
    try
    {
      gs::IO::write_glTF(out, mesh, control, skinning.weight_map(), ends_with(o.output, ".glb"));
    }
    catch(const std::exception& e)
    {
      throw Usage_error(o.output + ": " + e.what());
    }
    text = out.str();
  }
  else
  {
    std::ostringstream out;
    if(ends_with(o.output, ".obj"))
      gs::IO::write_OBJ(out, control);
    else if(ends_with(o.output, ".bvh"))
      gs::IO::write_BVH(out, control);
    else
      gs::IO::write_polylines(out, control);
    text = out.str();
  }

  if(!o.svg.empty())
  {
    std::ostringstream picture;
    const std::string name = o.input.substr(o.input.find_last_of('/') + 1);
    if(o.svg_stage == "weights")
      gs::IO::write_svg_preview_of_labels(picture, mesh, skinning.segment, control, 360,
                                          name + ": skinning, the bone of largest weight, " +
                                              std::to_string(control.bones.size()) + " bones");
    else if(o.svg_stage == "control")
      gs::IO::write_svg_preview(picture, mesh, control, 360,
                                name + ": control skeleton, " + std::to_string(control.bones.size()) + " bones");
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
    write_file(o.svg, picture.str());
  }
  if(o.output.empty())
    std::cout << text;
  else
    write_file(o.output, text);

  if(given_skeleton)
  {
    std::cerr << "skeletonize: " << o.input << ": " << num_vertices(mesh) << " vertices, skinned to "
              << o.skeleton << " (" << control.joints.size() << " joints, " << control.bones.size() << " bones) in "
              << skinning.report.milliseconds << " ms\n";
    return 0;
  }
  std::cerr << "skeletonize: " << o.input << ": " << num_vertices(mesh) << " vertices, "
            << report.solid_voxels << " solid voxels, " << report.thinned.points << " thinned points, "
            << report.pruned.points << " pruned points, " << control.joints.size() << " joints, "
            << control.bones.size() << " bones, " << report.total_ms << " ms\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(parse_options(argc, argv));
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
