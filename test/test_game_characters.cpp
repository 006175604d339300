// Characters as artists make them: many overlapping pieces (self-intersecting), holes, eyes
// half sunk in the head, teeth inside it, a loose piece floating free of the body.
// Specification of CGAL/Geodesic_skeleton/remove_small_pieces.h and of the pipeline on
// such meshes.
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <Geodesic_skeleton_test/characters.h>
#include <Geodesic_skeleton_test/joints.h>
#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

BOOST_AUTO_TEST_SUITE(game_characters)

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
namespace test = Geodesic_skeleton_test;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Control = gs::Control_skeleton<Point>;
using Curve = gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor>;
using Vec = std::array<double, 3>;

// The solid pieces a character is made of, as segments with a radius (a sphere is a
// segment of length zero): inside the character means within the radius of one of them.
struct Piece
{
  Vec from, to;
  double radius;
};

double distance_to_segment(const Vec& p, const Piece& s)
{
  Vec d{s.to[0] - s.from[0], s.to[1] - s.from[1], s.to[2] - s.from[2]};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  double t = 0;
  if(dd > 0)
    t = std::clamp(((p[0] - s.from[0]) * d[0] + (p[1] - s.from[1]) * d[1] + (p[2] - s.from[2]) * d[2]) / dd, 0., 1.);
  const Vec q{s.from[0] + t * d[0] - p[0], s.from[1] + t * d[1] - p[1], s.from[2] + t * d[2] - p[2]};
  return std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
}

// Appends a capped cylinder from `a` to `b` and a sphere at `b`, both of radius `r`, as two
// separate closed surfaces that overlap (an artist's limb with a rounded end). Faces whose
// index is in `missing` are left out (holes).
void add_limb(test::Soup& soup, const Vec& a, const Vec& b, double r, const std::vector<std::size_t>& missing = {})
{
  const Vec w0{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double length = std::sqrt(w0[0] * w0[0] + w0[1] * w0[1] + w0[2] * w0[2]);
  const Vec w{w0[0] / length, w0[1] / length, w0[2] / length};
  const Vec helper = std::abs(w[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
  Vec u{helper[1] * w[2] - helper[2] * w[1], helper[2] * w[0] - helper[0] * w[2], helper[0] * w[1] - helper[1] * w[0]};
  const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  u = {u[0] / nu, u[1] / nu, u[2] / nu};
  const Vec v{w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
  test::Soup tube = test::cylinder(r, length, 16, std::max(2, int(length / r)), true);
  for(auto& p : tube.points)
    p = {a[0] + p[0] * u[0] + p[1] * v[0] + p[2] * w[0], a[1] + p[0] * u[1] + p[1] * v[1] + p[2] * w[1],
         a[2] + p[0] * u[2] + p[1] * v[2] + p[2] * w[2]};
  test::Soup kept;
  kept.points = tube.points;
  for(std::size_t f = 0; f < tube.faces.size(); ++f)
    if(std::find(missing.begin(), missing.end(), f) == missing.end())
      kept.faces.push_back(tube.faces[f]);
  test::append(soup, kept);
  test::append(soup, test::icosphere(r, 2), b[0], b[1], b[2]);
}

void add_ball(test::Soup& soup, const Vec& c, double r) { test::append(soup, test::icosphere(r, 2), c[0], c[1], c[2]); }

// A biped about 2.5 units tall: torso (with holes), head, two eyes half sunk in the head,
// teeth inside it, two arms, two legs, and a bobble floating above the head, two voxels
// (at resolution 64) away from it. `pieces` receives the solid parts.
Mesh biped(std::vector<Piece>& pieces, bool with_bobble = true)
{
  test::Soup s;
  pieces.clear();
  auto limb = [&](const Vec& a, const Vec& b, double r, const std::vector<std::size_t>& missing = {}) {
    add_limb(s, a, b, r, missing);
    pieces.push_back({a, b, r});
  };
  auto ball = [&](const Vec& c, double r) {
    add_ball(s, c, r);
    pieces.push_back({c, c, r});
  };
  limb({0, 0, 1.0}, {0, 0, 1.75}, 0.25, {3, 4, 40, 41}); // torso, with two holes
  ball({0, 0, 2.08}, 0.22);                               // head, overlapping the torso's end
  ball({0.08, 0.19, 2.14}, 0.045);                        // eyes, half sunk in the head
  ball({-0.08, 0.19, 2.14}, 0.045);
  test::append(s, test::box(-0.05, 0.08, 1.97, 0.05, 0.14, 2.0)); // teeth, inside the head
  limb({0.22, 0, 1.68}, {0.9, 0, 1.25}, 0.08);            // arms
  limb({-0.22, 0, 1.68}, {-0.9, 0, 1.25}, 0.08);
  limb({0.12, 0, 1.0}, {0.22, 0, 0.08}, 0.1);             // legs
  limb({-0.12, 0, 1.0}, {-0.22, 0, 0.08}, 0.1);
  if(with_bobble)
    ball({0, 0, 2.42}, 0.04); // 0.08 above the head: detached
  return test::mesh_of<Mesh>(s);
}

Vec vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

double distance_to_character(const Point& p, const std::vector<Piece>& pieces)
{
  double best = std::numeric_limits<double>::infinity();
  for(const Piece& piece : pieces)
    best = std::min(best, distance_to_segment(vec(p), piece) - piece.radius);
  return best; // negative inside
}

// Whether some end joint lies within `tolerance` of `tip`.
// Whether an end point of the curve skeleton lies within `tolerance` of `tip`: the limb has
// a chain (the rig's end joint sits back from the tip, where artists end a chain).
bool an_end_reaches(const Curve& c, const Vec& tip, double tolerance)
{
  for(std::size_t v = 0; v < num_vertices(c); ++v)
    if(degree(v, c) == 1 && distance_to_segment(vec(c[v].point), Piece{tip, tip, 0}) <= tolerance)
      return true;
  return false;
}

} // namespace

BOOST_AUTO_TEST_CASE(the_mesh_is_as_artists_make_it)
{
  std::vector<Piece> pieces;
  const Mesh mesh = biped(pieces);
  BOOST_TEST(!CGAL::is_closed(mesh)); // the torso's holes
  std::vector<std::size_t> component(num_faces(mesh));
  BOOST_TEST(CGAL::Polygon_mesh_processing::connected_components(
                 mesh, boost::make_iterator_property_map(component.begin(), get(CGAL::face_index, mesh))) >= 15u);
}

BOOST_AUTO_TEST_CASE(a_character_gets_one_connected_skeleton)
{
  std::vector<Piece> pieces;
  const Mesh mesh = biped(pieces);
  Control control;
  Curve curve;
  const gs::Control_skeleton_report report =
      gs::extract_control_skeleton(mesh, control, params::curve_skeleton_output(&curve));
  BOOST_TEST_MESSAGE("biped: " << report.small_pieces.pieces << " pieces, " << report.small_pieces.removed_pieces
                               << " removed, " << num_vertices(control) << " joints, " << num_edges(control)
                               << " bones");
  BOOST_TEST(report.small_pieces.pieces == 2u); // the body and the bobble
  BOOST_TEST(report.small_pieces.removed_pieces == 1u);
  BOOST_TEST(control[boost::graph_bundle].roots.size() == 1u);
  BOOST_TEST(control[boost::graph_bundle].cut_bones.empty());
  BOOST_TEST(num_edges(control) >= 6u);
  BOOST_TEST(num_edges(control) <= 35u);

  // Every joint inside the body (within a voxel: the solid holds the surface voxels).
  for(const auto& j : test::joints(control))
  {
    BOOST_TEST(std::isfinite(j.point.x() + j.point.y() + j.point.z()));
    BOOST_TEST(distance_to_character(j.point, pieces) <= report.voxel_size);
  }
  // Every limb reached to its tip (hands and feet), within its radius and two voxels.
  for(const Vec& tip : {Vec{0.9, 0, 1.25}, Vec{-0.9, 0, 1.25}, Vec{0.22, 0, 0.08}, Vec{-0.22, 0, 0.08}})
    BOOST_TEST(an_end_reaches(curve, tip, 0.1 + 2 * report.voxel_size));

  // Every mesh vertex, the bobble's too, maps to exactly one curve-skeleton vertex.
  std::size_t mapped = 0;
  for(std::size_t v = 0; v < num_vertices(curve); ++v)
    mapped += curve[v].vertices.size();
  BOOST_TEST(mapped == std::size_t(num_vertices(mesh)));
}

// The resolution is a sampling choice, not a modelling one: from 48 to 128, the character
// has a chain to each hand and foot, the same end points, and about as many joints as at
// the default resolution (within a quarter).
BOOST_AUTO_TEST_CASE(a_character_keeps_its_limbs_and_joints_from_resolution_48_to_128)
{
  std::vector<Piece> pieces;
  const Mesh mesh = biped(pieces);
  Control at_64;
  const gs::Control_skeleton_report r_64 = gs::extract_control_skeleton(mesh, at_64);
  for(int resolution : {48, 80, 96, 128})
  {
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      Control control;
      Curve curve;
      const gs::Control_skeleton_report r = gs::extract_control_skeleton(
          mesh, control, params::combine(params::resolution(resolution), params::curve_skeleton_output(&curve)));
      BOOST_TEST(r.pruned.end_points == r_64.pruned.end_points);
      BOOST_TEST(r.pruned.components == 1u);
      for(const Vec& tip : {Vec{0.9, 0, 1.25}, Vec{-0.9, 0, 1.25}, Vec{0.22, 0, 0.08}, Vec{-0.22, 0, 0.08}})
        BOOST_TEST(an_end_reaches(curve, tip, 0.1 + 2 * r_64.voxel_size));
      const double joints = double(num_vertices(control)), joints_at_64 = double(num_vertices(at_64));
      BOOST_TEST(std::abs(joints - joints_at_64) <= 0.25 * joints_at_64);
    }
  }
}

BOOST_AUTO_TEST_CASE(small_pieces_can_be_kept_as_their_own_trees)
{
  std::vector<Piece> pieces;
  const Mesh mesh = biped(pieces);
  Control control;
  const gs::Control_skeleton_report report =
      gs::extract_control_skeleton(mesh, control, params::small_piece_fraction(0.));
  BOOST_TEST(report.small_pieces.removed_pieces == 0u);
  BOOST_TEST(control[boost::graph_bundle].roots.size() == 2u);
}

BOOST_AUTO_TEST_CASE(two_characters_keep_two_skeletons)
{
  std::vector<Piece> pieces;
  const Mesh one = biped(pieces, false);
  Mesh two = one;
  for(auto v : vertices(two))
    two.point(v) = Point(two.point(v).x() + 3, two.point(v).y(), two.point(v).z());
  Mesh both = one;
  CGAL::copy_face_graph(two, both);
  Control control;
  const gs::Control_skeleton_report report = gs::extract_control_skeleton(both, control);
  BOOST_TEST(report.small_pieces.pieces == 2u);
  BOOST_TEST(report.small_pieces.removed_pieces == 0u);
  BOOST_TEST(control[boost::graph_bundle].roots.size() == 2u);
}

// A cape, a fin or a wing: a thin plate (about a voxel thick at the default resolution)
// with a ragged rim, made as an artist would, of overlapping boxes (the plate and a tab every
// sixth of its length along each edge). Every tab grows a twig to the plate's middle line
// in the thinning; judged by the plate's half thickness they are tens of radii long, by its
// half width (the sheet radius that thin() measures) they are spurs. The rig is one chain
// along the middle of the plate.
BOOST_AUTO_TEST_CASE(a_thin_plate_with_a_ragged_rim_gets_one_chain)
{
  const double length = 60, width = 30, thickness = 1.2;
  test::Soup s = test::box(0, 0, 0, length, width, thickness);
  for(double x = 1; x + 2 < length; x += 6)
  {
    test::append(s, test::box(x, -2, 0, x + 2, 0.5, thickness));
    test::append(s, test::box(x, width - 0.5, 0, x + 2, width + 2, thickness));
  }
  for(double y = 1; y + 2 < width; y += 6)
  {
    test::append(s, test::box(-2, y, 0, 0.5, y + 2, thickness));
    test::append(s, test::box(length - 0.5, y, 0, length + 2, y + 2, thickness));
  }
  const Mesh mesh = test::mesh_of<Mesh>(s);
  Control control;
  // The chain to its tips: a plate's chain, set back, would span less of it.
  const gs::Control_skeleton_report report =
      gs::extract_control_skeleton(mesh, control, params::tip_joint_setback(0.0));
  BOOST_TEST_MESSAGE("ragged plate: " << report.thinned.end_points << " ends after thinning, "
                                      << report.pruned.end_points << " after pruning");
  BOOST_TEST(report.thinned.end_points > 10u); // the tabs' twigs
  BOOST_TEST(report.pruned.end_points == 2u);
  BOOST_TEST(report.pruned.junctions == 0u);
  BOOST_TEST(control[boost::graph_bundle].roots.size() == 1u);
  // The chain runs along the middle of the plate, over half its length or more.
  double min_x = length, max_x = 0;
  for(const auto& j : test::joints(control))
  {
    BOOST_TEST(std::abs(j.point.y() - width / 2) <= 0.1 * width);
    min_x = std::min(min_x, j.point.x());
    max_x = std::max(max_x, j.point.x());
  }
  BOOST_TEST(max_x - min_x >= 0.5 * length);
}

// The winged body's wings (characters.h) are sheets about one voxel of the default grid
// thick, slightly tilted to the grid (the head is off the wings' plane), so their voxels
// shift by one layer along lines across the wing. Thinning by distance alone kept such a
// line as a chain at 64, along the leading edge of one wing, beside a branch on its rim.
// Each wing's skeleton is one chain through the middle of its chord, at every resolution:
// the curve points over the wing (a fifth to seven tenths of the span out, short of the
// rounded tip) are within a quarter chord of its middle, and the skeleton has four end
// points (head, tail, two wing tips).
BOOST_AUTO_TEST_CASE(each_wing_of_a_winged_body_gets_one_chain_through_its_middle)
{
  const Mesh mesh = test::mesh_of<Mesh>(test::winged_body());
  for(int resolution : {48, 64, 96, 128})
  {
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      Control control;
      Curve curve;
      const gs::Control_skeleton_report report = gs::extract_control_skeleton(
          mesh, control, params::combine(params::resolution(resolution), params::curve_skeleton_output(&curve)));
      BOOST_TEST(report.pruned.end_points == 4u);
      std::size_t over_the_wings = 0;
      for(auto v : CGAL::make_range(vertices(curve)))
      {
        const Point& p = curve[v].point;
        const double span = std::abs(p.y());
        if(span < 0.2 || span > 0.7)
          continue;
        ++over_the_wings;
        // wing(): leading edge from x = 0.2 at the root to -0.05 at |y| = 0.92, trailing
        // edge from -0.2 to -0.15.
        const double leading = 0.2 - 0.25 * span / 0.92, trailing = -0.2 + 0.05 * span / 0.92;
        BOOST_TEST(std::abs(p.x() - (leading + trailing) / 2) < 0.25 * (leading - trailing),
                   "curve point (" << p.x() << ", " << p.y() << ")");
      }
      BOOST_TEST(over_the_wings >= 8u);
    }
  }
}

// A wing's chain is split in lengths of the wing's width (its sheet radius), not of its
// thickness, which is about a voxel and shrinks with it: split in its thickness, each wing
// got 6 or 7 joints, more on a finer grid. Each wing gets 2 to 4 joints (its tip included:
// the joints more than 0.2 out, past the body's radius of 0.12), and as many at every
// resolution.
BOOST_AUTO_TEST_CASE(a_wing_gets_a_few_joints_whatever_the_resolution)
{
  const Mesh mesh = test::mesh_of<Mesh>(test::winged_body());
  std::vector<std::size_t> joints_per_wing;
  for(int resolution : {48, 64, 96, 128})
  {
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      Control control;
      // The split's own joints along a sheet, measured in its width (the joint spacing would
      // add joints near the wing's root, on either side of the |y| = 0.2 that counts them).
      gs::extract_control_skeleton(mesh, control,
                                   params::combine(params::resolution(resolution), params::joint_spacing_factor(0.0)));
      std::size_t left = 0, right = 0;
      for(const auto& j : test::joints(control))
      {
        left += j.point.y() < -0.2 ? 1 : 0;
        right += j.point.y() > 0.2 ? 1 : 0;
      }
      BOOST_TEST(left >= 2u);
      BOOST_TEST(left <= 4u);
      BOOST_TEST(right == left);
      joints_per_wing.push_back(left);
    }
  }
  BOOST_TEST(*std::min_element(joints_per_wing.begin(), joints_per_wing.end()) ==
             *std::max_element(joints_per_wing.begin(), joints_per_wing.end()));
}

// A mirror-symmetric character, moved by random rigid motions, is rigged mirror-symmetrically:
// each arm and leg of the T-pose figure has as many joints as its mirror image, and each
// joint has a mirror joint within 1 % of the diagonal (the figure is symmetric across x = 0).
// The chains end short of the hands and feet and the limbs get joints along them (the
// defaults of tip_joint_setback and joint_spacing_factor), on both sides alike.
BOOST_AUTO_TEST_CASE(a_mirror_symmetric_figure_gets_mirror_symmetric_limbs_under_rigid_motions)
{
  const Mesh figure = test::mesh_of<Mesh>(test::t_pose_figure());
  const double diagonal = std::sqrt(1.77 * 1.77 + 1.79 * 1.79 + 0.32 * 0.32);
  for(unsigned seed = 0; seed <= 3; ++seed)
  {
    BOOST_TEST_CONTEXT("motion " << seed)
    {
      const auto motion = seed == 0 ? CGAL::Aff_transformation_3<Kernel>(CGAL::IDENTITY)
                                    : test::random_rigid_motion<Kernel>(seed, 0.3, -1.2, 2.);
      Mesh moved = figure;
      for(const auto v : vertices(moved))
        moved.point(v) = motion.transform(moved.point(v));
      Control control;
      gs::extract_control_skeleton(moved, control);
      std::vector<Point> joints;
      for(const auto& j : test::joints(control))
        joints.push_back(motion.inverse().transform(j.point));
      // Left and right: the arms beyond the shoulders, the legs below the hips.
      std::size_t left_arm = 0, right_arm = 0, left_leg = 0, right_leg = 0;
      for(const Point& p : joints)
      {
        left_arm += p.x() < -0.2 && p.z() > 1.2;
        right_arm += p.x() > 0.2 && p.z() > 1.2;
        left_leg += p.x() < -0.05 && p.z() < 0.8;
        right_leg += p.x() > 0.05 && p.z() < 0.8;
      }
      BOOST_TEST(left_arm >= 2u);
      BOOST_TEST(left_leg >= 2u);
      BOOST_TEST(right_arm == left_arm);
      BOOST_TEST(right_leg == left_leg);
      double worst = 0;
      for(const Point& p : joints)
      {
        double nearest = std::numeric_limits<double>::infinity();
        for(const Point& q : joints)
          nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(Point(-p.x(), p.y(), p.z()), q)));
        worst = (std::max)(worst, nearest);
      }
      BOOST_TEST(worst <= 0.01 * diagonal);
      // No chain ends at a fingertip: the hands end at most 0.75 from the middle (the hand
      // spheres reach 0.885).
      for(const Point& p : joints)
        BOOST_TEST(std::abs(p.x()) <= 0.8);
    }
  }
}

// A cape made as game artists make it: one open sheet of quads whose top edge runs into the
// torso of the T-pose figure (characters.h). Its rim is not a hole: closed by a fan, it made
// a second layer beside the cape and a lens of volume between them, whose skeleton forked
// at the hem (14 end points at 64, 9 more than the figure alone). The cape is a sheet of
// surface voxels; the rig is the figure's five end points and one chain down the middle of
// the cape into its lowest third, at every resolution. Like the end of a strip, whose medial
// axis forks to the two corners half its width from the edge, the chain may end towards a
// corner of the hem.
BOOST_AUTO_TEST_CASE(a_cape_made_of_one_sheet_gets_one_chain_down_its_middle)
{
  const Mesh mesh = test::mesh_of<Mesh>(test::caped_figure());
  for(int resolution : {64, 96, 128})
  {
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      Control control;
      gs::extract_control_skeleton(mesh, control, params::resolution(resolution));
      std::size_t ends = 0, ends_on_the_cape = 0, joints_on_the_cape = 0;
      for(const auto& j : test::joints(control))
      {
        const bool end = j.kind == gs::Joint_kind::end;
        ends += end ? 1 : 0;
        if(j.point.y() >= -0.2) // the torso's radius is 0.16: behind it is the cape
          continue;
        ++joints_on_the_cape;
        if(end)
        {
          ++ends_on_the_cape;
          BOOST_TEST(j.point.z() < 0.72, "the cape's end at z = " << j.point.z()); // hem at 0.35, top at 1.45
        }
        else // half width 0.25
          BOOST_TEST(std::abs(j.point.x()) < 0.1, "a joint on the cape at x = " << j.point.x());
      }
      BOOST_TEST(ends == 6u);
      BOOST_TEST(ends_on_the_cape == 1u);
      BOOST_TEST(joints_on_the_cape >= 2u);
    }
  }
}

// A thick plate tapering to its rim (a plush starfish, a cushion, a flat body with stubby
// limbs; 4286 and 10467 of the artists' val split) thins from its rim inwards to a point or
// to stubs: reach_sheet_lobes() gives each arm a chain to near its tip (the val split had
// two characters with fewer than 4 joints; none since).
BOOST_AUTO_TEST_CASE(each_arm_of_a_thick_starfish_gets_a_chain)
{
  const int arms = 5;
  const double turn = 0.3;
  const Mesh mesh = test::mesh_of<Mesh>(test::thick_starfish(arms, turn));
  Control without;
  const gs::Control_skeleton_report before =
      gs::extract_control_skeleton(mesh, without, params::sheet_lobe_reach_factor(0));
  BOOST_TEST(before.sheet_lobes.lobes_reached == 0u);
  for(const auto& j : test::joints(without)) // the premise: thinning alone burns the arms to stubs
    BOOST_TEST(std::hypot(j.point.x(), j.point.y()) < 0.2);
  for(int resolution : {64, 96, 128}) // above 64, the grid of the level of detail decides
  {
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      Control control;
      const gs::Control_skeleton_report r = gs::extract_control_skeleton(mesh, control, params::resolution(resolution));
      BOOST_TEST(r.sheet_lobes.lobes_reached == std::size_t(arms));
      std::vector<int> ends_per_arm(arms, 0);
      for(const auto& j : test::joints(control))
        if(j.kind == gs::Joint_kind::end)
        {
          const test::Starfish_arm a = test::starfish_arm(arms, turn, j.point.x(), j.point.y());
          BOOST_TEST(std::abs(a.off_axis) < test::pi / arms / 2);
          BOOST_TEST(std::hypot(j.point.x(), j.point.y()) > 0.3); // the arms reach 0.5 out, the notches 0.1
          ++ends_per_arm[std::size_t(a.arm)];
        }
      for(int arm = 0; arm < arms; ++arm)
        BOOST_TEST(ends_per_arm[std::size_t(arm)] == 1, "arm " << arm);
    }
  }
}

BOOST_AUTO_TEST_CASE(remove_small_pieces_removes_exactly_the_small_ones)
{
  // Three balls of radius 1, 0.5 and 0.2: at fraction 0.05 only the smallest (0.8 % of the
  // largest's volume) goes; at 0.2 the middle one (12.5 %) too; at 0 none.
  test::Soup s = test::icosphere(1, 3);
  test::append(s, test::icosphere(0.5, 3), 3, 0, 0);
  test::append(s, test::icosphere(0.2, 3), 0, 3, 0);
  const Mesh mesh = test::mesh_of<Mesh>(s);
  gs::Dense_voxel_grid solid;
  gs::voxelize(mesh, solid);
  const gs::Voxel_distance_field distances = gs::distance_transform(solid);
  gs::thin(solid, distances);
  for(const auto& [fraction, removed] : {std::pair<double, std::size_t>{0.05, 1}, {0.2, 2}, {0., 0}})
  {
    gs::Dense_voxel_grid skeleton = solid;
    const gs::Small_pieces_report r = gs::remove_small_pieces(skeleton, distances, params::small_piece_fraction(fraction));
    BOOST_TEST(r.pieces == 3u);
    BOOST_TEST(r.removed_pieces == removed);
    BOOST_TEST(skeleton.size() + r.removed_voxels == solid.size());
    BOOST_TEST(gs::internal::skeleton_statistics_of_voxels(skeleton).components == 3 - removed);
  }
  BOOST_CHECK_THROW(gs::remove_small_pieces(solid, distances, params::small_piece_fraction(1.5)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::remove_small_pieces(solid, distances, params::small_piece_fraction(-0.1)), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
