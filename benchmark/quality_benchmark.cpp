// quality_benchmark: what the control skeletons look like, in numbers, on the closed demo
// meshes that are characters or animals and on five synthetic shapes (a thin plate, a
// winged body, a T-pose figure, the same wearing an open cape, a six-armed star with nearly
// equal principal axes:
// test/include/Geodesic_skeleton_test/characters.h), at
// several resolutions. Per mesh and resolution, one run of extract_control_skeleton():
//   - end points and junctions: joints of degree 1 and of degree >= 3 (the degree counts
//     the bones and the cut bones at a joint); joints; bones (cut bones included);
//   - joints per chain: the joints of degree 2 over the chains (maximal paths of bones
//     between joints of degree != 2; a cycle of degree-2 joints is one chain);
//   - curve points: the vertices of the curve skeleton (pruned, smoothed); points outside:
//     those outside the mesh by the non-zero winding rule, as the package counts inside
//     (outside every connected component by CGAL::Side_of_triangle_mesh, and a generalized
//     winding number below 1/2: where a mesh overlaps itself, the parity of the crossings
//     calls outside what is inside two shells; both on the mesh with its faces
//     triangulated; "-" for an open mesh); max
//     outside: the largest distance from one of them to the surface (AABB tree), in % of
//     the diagonal of the mesh's bounding box;
//   - trees: the trees of the control skeleton (its root joints): one per body that the
//     solid has, more when pruning leaves a piece of the skeleton on its own.
// Then the resolution stability: joints at each resolution, and joints at the last
// resolution over joints at 64 (or at the first, without 64), flagged "*" outside
// [0.75, 1.25].
//
// With --rigid-motions N, then the invariance under rigid motion: per mesh and resolution,
// the mesh moved by N random rigid motions (seeds 1 to N), the end points of each moved
// copy's control skeleton (fewest and most), and the farthest joint of a moved copy's
// skeleton, moved back, from the original's nearest joint or the reverse (the symmetric
// Hausdorff distance, worst over the N copies), in % of the diagonal.
//
// With --radii-on-mesh (not with --rigid-motions), each curve skeleton is split again with the radii of its points
// measured on the mesh (the distance to the surface) instead of the voxels' MAT radii, with
// the same smallest radius and without the sheet widths, and the rows and the stability
// table count those joints; each row ends with the median, over the curve points, of the
// voxel radius over the radius measured on the mesh. The synthetic shape thin_capsule (a
// capsule of radius 0.02, 1 long, tilted to the axes; not in the default list) shows how a
// thin part's radius is measured at each resolution.
//
//   quality_benchmark [DATA_DIR] [--meshes a,b,c] [--resolutions 48,64,96,128]
//                     [--rigid-motions N] [--radii-on-mesh] [--write-shapes DIR]
//
// --write-shapes DIR writes the synthetic shapes to DIR/plate.off, DIR/winged_body.off,
// DIR/t_pose_figure.off, DIR/caped_figure.off, DIR/six_armed_star.off and
// DIR/thin_capsule.off (to look at them with skeletonize) and stops.

#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <Geodesic_skeleton_test/characters.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>
#include <Geodesic_skeleton_test/winding_number.h>

#include "benchmark_common.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
namespace shapes = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Control = gs::Control_skeleton<Point>;
using Curve = gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor>;

using benchmark_common::median;
using benchmark_common::split_commas;

namespace {

struct Options
{
  std::string data_dir = GEODESIC_SKELETON_DATA_DIR;
  std::vector<std::string> names = {"cow", "elephant", "dino",  "camel",   "horse",       "armadillo",    "man",
                                    "bunny", "hand",   "octopus", "plate", "winged_body", "t_pose_figure",
                                    "caped_figure", "six_armed_star"};
  std::vector<int> resolutions = {48, 64, 96, 128};
  int rigid_motions = 0;
  bool radii_on_mesh = false;
  std::string shapes_dir; // --write-shapes
};

// Reads [DATA_DIR] [--meshes a,b] [--resolutions 48,64] [--rigid-motions N]
// [--radii-on-mesh] [--write-shapes DIR]; prints the usage and returns false on anything
// else.
bool parse_options(int argc, char* argv[], Options& o)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg == "--meshes" && i + 1 < argc)
      o.names = split_commas(argv[++i]);
    else if(arg == "--resolutions" && i + 1 < argc)
    {
      o.resolutions.clear();
      for(const std::string& r : split_commas(argv[++i]))
        o.resolutions.push_back(std::atoi(r.c_str()));
    }
    else if(arg == "--rigid-motions" && i + 1 < argc)
    {
      o.rigid_motions = std::atoi(argv[++i]);
      if(o.rigid_motions < 0)
        return false;
    }
    else if(arg == "--radii-on-mesh")
      o.radii_on_mesh = true;
    else if(arg == "--write-shapes" && i + 1 < argc)
      o.shapes_dir = argv[++i];
    else if(!arg.empty() && arg[0] != '-')
      o.data_dir = arg;
    else
    {
      std::cout << "usage: " << argv[0]
                << " [DATA_DIR] [--meshes a,b,c] [--resolutions 48,64,96,128] [--rigid-motions N]"
                   " [--radii-on-mesh] [--write-shapes DIR]\n";
      return false;
    }
  }
  // The rigid motions compare extract_control_skeleton()'s joints, not those split again.
  if(o.radii_on_mesh && o.rigid_motions > 0)
  {
    std::cout << "--radii-on-mesh and --rigid-motions do not go together\n";
    return false;
  }
  return !o.resolutions.empty();
}

// The synthetic shapes of characters.h, by name.
// A thin limb alone: radius 0.02, 1.3 and 1.7 voxels at resolutions 64 and 128.
shapes::Soup thin_capsule() { return shapes::capsule({0, 0, 0}, {1, 0.37, 0.11}, 0.02); }

const std::map<std::string, shapes::Soup (*)()> synthetic_shapes = {
    {"thin_capsule", thin_capsule},
    {"plate", shapes::plate},
    {"winged_body", shapes::winged_body},
    {"t_pose_figure", shapes::t_pose_figure},
    {"caped_figure", shapes::caped_figure},
    {"six_armed_star", shapes::six_armed_star}};

// A synthetic shape, or DATA_DIR/NAME.off; nothing when neither exists.
std::optional<Mesh> load_mesh(const std::string& name, const std::string& data_dir)
{
  if(auto shape = synthetic_shapes.find(name); shape != synthetic_shapes.end())
    return shapes::mesh_of<Mesh>(shape->second());
  // The package's reader, as skeletonize reads: it also takes the polygon soups among the
  // demo meshes (the *-shuffled ones), which CGAL's read_polygon_mesh() refuses.
  Mesh mesh;
  try
  {
    CGAL::Geodesic_skeleton::IO::read_mesh(data_dir + "/" + name + ".off", mesh);
  }
  catch(const std::runtime_error&)
  {
    return std::nullopt;
  }
  return mesh;
}

struct Joint_counts
{
  std::size_t end_points = 0, junctions = 0, joints = 0, bones = 0;
  double joints_per_chain = 0;
};

// The joints by degree, and the chains: each walk from a joint of degree != 2 along an
// unwalked bone, through joints of degree 2, is one chain; the bones left unwalked after
// that form cycles of degree-2 joints, one chain each.
Joint_counts count_joints(const Control& control)
{
  std::vector<std::pair<std::size_t, std::size_t>> bones; // the two joints of each bone, cut ones too
  for(const auto e : CGAL::make_range(edges(control)))
    bones.emplace_back(source(e, control), target(e, control));
  for(const auto& cut : control[boost::graph_bundle].cut_bones)
    bones.emplace_back(cut.source, cut.target);
  std::vector<std::vector<std::size_t>> bones_at(num_vertices(control));
  for(std::size_t b = 0; b < bones.size(); ++b)
  {
    bones_at[bones[b].first].push_back(b);
    bones_at[bones[b].second].push_back(b);
  }
  Joint_counts c;
  c.joints = num_vertices(control);
  c.bones = bones.size();
  std::size_t middle_joints = 0;
  for(const auto& at : bones_at)
  {
    c.end_points += at.size() == 1;
    c.junctions += at.size() >= 3;
    middle_joints += at.size() == 2;
  }
  std::vector<bool> walked(bones.size(), false);
  auto walk = [&](std::size_t joint, std::size_t bone) {
    while(!walked[bone])
    {
      walked[bone] = true;
      joint = bones[bone].first == joint ? bones[bone].second : bones[bone].first;
      if(bones_at[joint].size() != 2)
        break;
      bone = bones_at[joint][0] == bone ? bones_at[joint][1] : bones_at[joint][0];
    }
  };
  std::size_t chains = 0;
  for(std::size_t j = 0; j < bones_at.size(); ++j)
    if(bones_at[j].size() != 2)
      for(std::size_t b : bones_at[j])
        if(!walked[b])
        {
          walk(j, b);
          ++chains;
        }
  for(std::size_t b = 0; b < bones.size(); ++b)
    if(!walked[b])
    {
      walk(bones[b].first, b);
      ++chains;
    }
  c.joints_per_chain = chains > 0 ? double(middle_joints) / double(chains) : 0.0;
  return c;
}

double bounding_box_diagonal(const Mesh& mesh)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

// The surface of a mesh, its faces triangulated as the voxelizer does (the tests below need
// triangles), and the distance of a point to it. Not copyable: the tree points into the mesh.
class Mesh_surface
{
public:
  explicit Mesh_surface(const Mesh& mesh)
    : mesh_(triangulated(mesh)), tree_(faces(mesh_).first, faces(mesh_).second, mesh_)
  {}
  Mesh_surface(const Mesh_surface&) = delete;
  Mesh_surface& operator=(const Mesh_surface&) = delete;
  const Mesh& triangles() const { return mesh_; }
  double distance(const Point& p) const { return std::sqrt(tree_.squared_distance(p)); }

private:
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  static Mesh triangulated(Mesh mesh)
  {
    if(!CGAL::is_triangle_mesh(mesh))
      CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    return mesh;
  }

  Mesh mesh_;
  Tree tree_;
};

// The inside of a closed mesh as the voxelizer sees it (the non-zero winding rule): inside
// any of its connected components (overlapping pieces of a character are each filled) or
// where its winding number is 1/2 or more (a piece that overlaps itself), and the distance
// to its surface.
class Mesh_inside
{
public:
  explicit Mesh_inside(const Mesh_surface& surface) : surface_(surface)
  {
    CGAL::Polygon_mesh_processing::split_connected_components(surface.triangles(), pieces_);
    for(const Mesh& piece : pieces_)
      sides_.push_back(std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(piece));
  }
  bool outside(const Point& p) const
  {
    // Parity first: the winding number sums over every face, and few points need it.
    return std::all_of(sides_.begin(), sides_.end(),
                       [&](const auto& side) { return (*side)(p) == CGAL::ON_UNBOUNDED_SIDE; }) &&
           !Geodesic_skeleton_test::is_inside_by_winding(surface_.triangles(), p);
  }
  double distance_to_surface(const Point& p) const { return surface_.distance(p); }

private:
  const Mesh_surface& surface_;
  std::vector<Mesh> pieces_;
  std::vector<std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>> sides_;
};

// Splits `curve` into `control` again with the radius of each curve point measured on the
// mesh (`--radii-on-mesh`), with the same smallest radius, without the sheet widths and with
// the joints at the tips; returns the median over the curve points of the voxel radius over
// the radius measured on the mesh.
double split_with_radii_on_mesh(Curve curve, const Mesh_surface& surface, double smallest_radius, Control& control)
{
  std::vector<double> ratios;
  for(auto v : CGAL::make_range(vertices(curve)))
  {
    const double on_mesh = surface.distance(curve[v].point);
    if(on_mesh > 0)
      ratios.push_back(curve[v].radius / on_mesh);
    curve[v].radius = on_mesh;
    curve[v].sheet_half_width = curve[v].piece_radius = 0; // the radii alone
  }
  gs::split_into_bones(curve, control,
                       params::combine(params::smallest_radius(smallest_radius), params::tip_joint_setback(0.0)));
  return ratios.empty() ? 0.0 : median(ratios);
}

struct Points_outside
{
  std::size_t count = 0;
  double max_distance = 0; // world units
};

// The curve-skeleton points outside the mesh, and the farthest one's distance to it.
Points_outside curve_points_outside(const Mesh_inside& inside, const Curve& curve)
{
  Points_outside out;
  for(auto v : CGAL::make_range(vertices(curve)))
    if(inside.outside(curve[v].point))
    {
      ++out.count;
      out.max_distance = std::max(out.max_distance, inside.distance_to_surface(curve[v].point));
    }
  return out;
}

// What one run leaves for the later tables: its joints (none when the chain failed) and
// its end points.
struct Quality_run
{
  std::vector<Point> joints;
  std::size_t end_points = 0;
};

std::vector<Point> joint_points(const Control& control)
{
  std::vector<Point> points;
  for(auto j : CGAL::make_range(vertices(control)))
    points.push_back(control[j].point);
  return points;
}

// One row of the quality table for `mesh` at `resolution`; with `radii_on_mesh`, of the
// control skeleton split with the radii measured on the mesh (split_with_radii_on_mesh()).
Quality_run print_quality_row(const std::string& name, const Mesh& mesh, const Mesh_inside* inside, int resolution,
                              const Mesh_surface* radii_on_mesh)
{
  std::cout << "| " << name << " | " << resolution << " | ";
  Control control;
  Curve curve;
  double radius_ratio = 0;
  try
  {
    const gs::Control_skeleton_report report = gs::extract_control_skeleton(
        mesh, control, params::combine(params::resolution(resolution), params::curve_skeleton_output(&curve)));
    if(radii_on_mesh != nullptr)
      radius_ratio = split_with_radii_on_mesh(curve, *radii_on_mesh, report.smallest_radius, control);
  }
  catch(const std::exception& e)
  {
    std::cout << "failed: " << e.what() << " | | | | | | | | |\n";
    return {};
  }
  const Joint_counts c = count_joints(control);
  std::cout << c.end_points << " | " << c.junctions << " | " << c.joints << " | " << c.bones << " | "
            << c.joints_per_chain << " | " << num_vertices(curve) << " | ";
  if(inside == nullptr)
    std::cout << "- | - | ";
  else
  {
    const Points_outside out = curve_points_outside(*inside, curve);
    std::cout << out.count << " | " << 100 * out.max_distance / bounding_box_diagonal(mesh) << " | ";
  }
  std::cout << control[boost::graph_bundle].roots.size() << " |";
  if(radii_on_mesh != nullptr)
    std::cout << " " << radius_ratio << " |";
  std::cout << "\n";
  return {joint_points(control), c.end_points};
}

// The resolution-stability table: joints per resolution, and joints at the last resolution
// over joints at 64 (or at the first), flagged outside [0.75, 1.25]; then their median.
void print_stability_table(const std::vector<std::pair<std::string, std::vector<std::size_t>>>& joints,
                           const std::vector<int>& resolutions)
{
  const auto at_64 = std::find(resolutions.begin(), resolutions.end(), 64);
  const std::size_t reference = at_64 == resolutions.end() ? 0 : std::size_t(at_64 - resolutions.begin());
  std::cout << "\nresolution stability\n\n| mesh |";
  for(int r : resolutions)
    std::cout << " joints at " << r << " |";
  std::cout << " " << resolutions.back() << "/" << resolutions[reference] << " |\n|---|";
  for(std::size_t k = 0; k <= resolutions.size(); ++k)
    std::cout << "---:|";
  std::cout << "\n";
  std::vector<double> ratios;
  std::size_t flagged = 0;
  for(const auto& [name, counts] : joints)
  {
    std::cout << "| " << name << " |";
    for(std::size_t n : counts)
      std::cout << " " << n << " |";
    if(counts[reference] == 0 || counts.back() == 0)
    {
      std::cout << " - |\n";
      continue;
    }
    const double ratio = double(counts.back()) / double(counts[reference]);
    const bool flag = ratio < 0.75 || ratio > 1.25;
    ratios.push_back(ratio);
    flagged += flag;
    std::cout << " " << ratio << (flag ? " *" : "") << " |\n";
  }
  if(!ratios.empty())
    std::cout << "\nmedian ratio " << median(ratios) << ", flagged " << flagged << " of " << ratios.size()
              << " meshes\n";
}

// One row of the rigid-motion table for `mesh` at `resolution`, whose own run is
// `original`, over `motions` random rigid motions (a rotation, and a translation of about
// two diagonals), to `out`.
void print_rigid_motion_row(std::ostream& out, const std::string& name, const Mesh& mesh, int resolution,
                            const Quality_run& original, int motions)
{
  out << "| " << name << " | " << resolution << " | ";
  if(original.joints.empty())
  {
    out << "failed | | | |\n";
    return;
  }
  try
  {
    const double diagonal = bounding_box_diagonal(mesh);
    std::size_t fewest = std::size_t(-1), most = 0;
    double worst = 0;
    for(int seed = 1; seed <= motions; ++seed)
    {
      const auto motion = shapes::random_rigid_motion<Kernel>(unsigned(seed), 0.3 * diagonal, -1.2 * diagonal,
                                                              2.0 * diagonal);
      Mesh moved = mesh;
      for(auto v : vertices(moved))
        moved.point(v) = motion.transform(moved.point(v));
      Control control;
      gs::extract_control_skeleton(moved, control, params::resolution(resolution));
      std::vector<Point> back = joint_points(control);
      const auto inverse = motion.inverse();
      for(Point& p : back)
        p = inverse.transform(p);
      const std::size_t moved_ends = count_joints(control).end_points;
      fewest = (std::min)(fewest, moved_ends);
      most = (std::max)(most, moved_ends);
      worst = (std::max)(worst, shapes::hausdorff(original.joints, back));
    }
    out << original.end_points << " | " << fewest << " | " << most << " | " << 100 * worst / diagonal << " |\n";
  }
  catch(const std::exception& e)
  {
    out << "failed: " << e.what() << " | | | |\n";
  }
}

// Writes the synthetic shapes to DIR/NAME.off.
bool write_shapes(const std::string& dir)
{
  for(const auto& [name, build] : synthetic_shapes)
  {
    const std::string path = dir + "/" + name + ".off";
    Mesh mesh = shapes::mesh_of<Mesh>(build());
    if(!CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(10)))
    {
      std::cerr << "cannot write " << path << "\n";
      return false;
    }
    std::cout << "wrote " << path << "\n";
  }
  return true;
}

} // namespace

int main(int argc, char* argv[])
{
  Options options;
  if(!parse_options(argc, argv, options))
    return 2;
  if(!options.shapes_dir.empty())
    return write_shapes(options.shapes_dir) ? 0 : 1;

  std::cout << std::fixed << std::setprecision(2);
  std::cout << "| mesh | resolution | end points | junctions | joints | bones | joints per chain | curve points"
               " | points outside | max outside (% of diagonal) | trees |"
            << (options.radii_on_mesh ? " voxel radius / radius on the mesh |" : "")
            << "\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" << (options.radii_on_mesh ? "---:|" : "")
            << "\n";
  std::vector<std::pair<std::string, std::vector<std::size_t>>> joints;
  std::ostringstream rigid_motion_rows; // printed after the stability table
  rigid_motion_rows << std::fixed << std::setprecision(2);
  for(const std::string& name : options.names)
  {
    const std::optional<Mesh> mesh = load_mesh(name, options.data_dir);
    if(!mesh)
    {
      std::cerr << "note: no mesh " << options.data_dir << "/" << name << ".off, skipped\n";
      continue;
    }
    std::optional<Mesh_surface> surface;
    if(CGAL::is_closed(*mesh) || options.radii_on_mesh)
      surface.emplace(*mesh);
    std::optional<Mesh_inside> inside;
    if(CGAL::is_closed(*mesh))
      inside.emplace(*surface);
    joints.emplace_back(name, std::vector<std::size_t>());
    for(int resolution : options.resolutions)
    {
      const Quality_run run = print_quality_row(name, *mesh, inside ? &*inside : nullptr, resolution,
                                                options.radii_on_mesh ? &*surface : nullptr);
      joints.back().second.push_back(run.joints.size());
      if(options.rigid_motions > 0)
        print_rigid_motion_row(rigid_motion_rows, name, *mesh, resolution, run, options.rigid_motions);
    }
  }
  print_stability_table(joints, options.resolutions);
  if(options.rigid_motions > 0)
  {
    std::cout << "\ninvariance under " << options.rigid_motions
              << " random rigid motions\n\n| mesh | resolution | end points | end points moved, fewest | most"
                 " | farthest joint (% of diagonal) |\n|---|---:|---:|---:|---:|---:|\n"
              << rigid_motion_rows.str();
  }
  return 0;
}
