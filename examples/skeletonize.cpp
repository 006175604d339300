// skeletonize: the package's main program. Mesh in, animation control skeleton out, with
// every stage's counts and timings, and a picture on request.
//
//   skeletonize INPUT_MESH [-o OUT] [--resolution N] [--svg PREVIEW.svg] [stage options]
//
// The format of OUT follows its extension: .json (the documented contract, also written to
// standard output when there is no -o), .obj, .bvh, .polylines.txt. See --help.

#include <CGAL/Geodesic_skeleton.h>

#include "read_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
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

struct Options
{
  std::string input, output, svg, svg_stage = "control";
  int resolution = gs::default_voxel_resolution;
  double spur_length_factor = 1.2;
  int smoothing_window = 5;
  double bend_threshold = 0.08;
  double straightness_tolerance = 0.5;
  double minimum_bone_length_factor = 2.0;
  std::size_t reeb_intervals = 30;
  bool fill_holes = true;
  bool keep_surface_voxels = true;
};

const char* const usage_text = R"(usage: skeletonize INPUT_MESH [-o OUT] [--resolution N] [--svg PREVIEW.svg] [options]

Extracts the animation control skeleton of a triangle mesh (any format that CGAL reads:
OFF, OBJ, PLY, STL, ...). Without -o, writes the JSON report to standard output.

  -o, --output OUT           write the result to OUT; its extension picks the format:
                             .json (report and skeletons), .obj (joints and bone lines),
                             .bvh (hierarchy with a rest pose), .polylines.txt (bone polylines)
  --svg PREVIEW.svg          also draw the mesh and its control skeleton in three views
  --svg-stage STAGE          what the picture shows: control (default), pruned (the smoothed
                             curve skeleton), thinned (the curve skeleton after thinning), reeb
  --resolution N             voxels along the longest principal axis, 4..8192 (default 64)
  --no-fill-holes            do not close the mesh's holes before voxelizing
  --peel-surface-voxels      drop the surface voxels whose centre is outside the mesh (opens
                             false loops between parts that nearly touch; default: kept)
  --spur-length F            snip end branches shorter than F MAT radii, 0..100 (default 1.2)
  --smoothing-window W       points averaged along branches, odd, 1..1001 (default 5)
  --bend-threshold T         chord-to-point accumulation that makes a joint, 0..1 (default 0.08)
  --straightness S           allowed bone deviation in MAT radii, 0..100 (default 0.5)
  --min-bone-length F        shortest bone in MAT radii, 0..1000 (default 2)
  --reeb-intervals N         intervals of the Reeb graph reported for comparison, 1..1000000 (default 30)
  -h, --help                 show this help
)";

template <typename T>
T parse_number(const std::string& option, const std::string& text)
{
  std::istringstream in(text);
  T value;
  if(!(in >> value) || !in.eof())
    throw Usage_error("option " + option + " needs a number, got '" + text + "'");
  return value;
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
      std::cout << usage_text;
      std::exit(0);
    }
    else if(a == "-o" || a == "--output") o.output = value();
    else if(a == "--svg") o.svg = value();
    else if(a == "--svg-stage") o.svg_stage = value();
    else if(a == "--resolution") o.resolution = parse_number<int>(a, value());
    else if(a == "--no-fill-holes") o.fill_holes = false;
    else if(a == "--peel-surface-voxels") o.keep_surface_voxels = false;
    else if(a == "--spur-length") o.spur_length_factor = parse_number<double>(a, value());
    else if(a == "--smoothing-window") o.smoothing_window = parse_number<int>(a, value());
    else if(a == "--bend-threshold") o.bend_threshold = parse_number<double>(a, value());
    else if(a == "--straightness") o.straightness_tolerance = parse_number<double>(a, value());
    else if(a == "--min-bone-length") o.minimum_bone_length_factor = parse_number<double>(a, value());
    else if(a == "--reeb-intervals") o.reeb_intervals = parse_number<std::size_t>(a, value());
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
  if(!to_json && !ends_with(o.output, ".obj") && !ends_with(o.output, ".bvh") &&
     !ends_with(o.output, ".polylines.txt"))
    throw Usage_error(o.output + ": unknown output format (use .json, .obj, .bvh or .polylines.txt)");
  if(!o.svg.empty() && !ends_with(o.svg, ".svg"))
    throw Usage_error(o.svg + ": the preview must be an .svg file");
  if(o.svg_stage != "control" && o.svg_stage != "pruned" && o.svg_stage != "thinned" && o.svg_stage != "reeb")
    throw Usage_error("--svg-stage must be control, pruned, thinned or reeb, got '" + o.svg_stage + "'");

  const Mesh mesh = skeletonize::read_mesh<Mesh>(o.input);
  gs::Curve_skeleton<Point, vertex_descriptor> curve, thinned;
  gs::Reeb_graph<Mesh> reeb;
  gs::Control_skeleton<Point> control;
  gs::Control_skeleton_report report;
  try
  {
    report = gs::extract_control_skeleton(
        mesh, control,
        params::combine(params::resolution(o.resolution), params::fill_holes(o.fill_holes),
                        params::keep_surface_voxels(o.keep_surface_voxels),
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

  std::string text;
  if(to_json)
  {
    std::vector<std::size_t> face_component(num_faces(mesh));
    const std::size_t components = PMP::connected_components(
        mesh, boost::make_iterator_property_map(face_component.begin(), get(CGAL::face_index, mesh)));
    nlohmann::json timings{{"total", report.total_ms}};
    for(const auto& [stage, ms] : report.timings_ms)
      timings[stage] = ms;
    const nlohmann::json control_json = gs::IO::control_skeleton_to_json(control);
    const nlohmann::json json = {
        {"input", o.input},
        {"mesh", {{"vertices", num_vertices(mesh)}, {"faces", num_faces(mesh)},
                  {"closed", CGAL::is_closed(mesh)}, {"components", components}}},
        {"parameters", {{"resolution", o.resolution}, {"fill_holes", o.fill_holes},
                        {"keep_surface_voxels", o.keep_surface_voxels},
                        {"spur_length_factor", o.spur_length_factor},
                        {"smoothing_window", o.smoothing_window},
                        {"bend_threshold", o.bend_threshold},
                        {"straightness_tolerance", o.straightness_tolerance},
                        {"minimum_bone_length_factor", o.minimum_bone_length_factor},
                        {"reeb_intervals", o.reeb_intervals}, {"voxel_size", report.voxel_size}}},
        {"timings_ms", timings},
        {"stages", {{"solid", {{"voxels", report.solid_voxels}}},
                    {"thinned", stage_json(report.thinned)},
                    {"pruned", stage_json(report.pruned)},
                    {"reeb", {{"nodes", report.reeb_nodes}, {"edges", report.reeb_edges}}}}},
        {"skeleton", gs::IO::curve_skeleton_to_json(curve)},
        {"control", {{"joints", control_json["joints"]}, {"bones", control_json["bones"]},
                     {"cut_bones", control_json["cut_bones"]}, {"roots", control_json["roots"]}}}};
    text = json.dump(1) + "\n";
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
    if(o.svg_stage == "control")
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
