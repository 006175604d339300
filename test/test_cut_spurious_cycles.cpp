// Specification of CGAL/Geodesic_skeleton/cut_spurious_cycles.h.
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/internal/move_skeleton_inside/closed_mesh_interior.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>

#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(cut_spurious_cycles)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

// The thinned skeleton of a mesh before and after cut_spurious_cycles().
struct Cut_result
{
  long cycles_before = 0, cycles_after = 0;
  int components_before = 0, components_after = 0;
  std::size_t reported = 0;
  std::size_t removed = 0;            // skeleton voxels removed
  double farthest_removed_voxel = 0;  // from the mesh's surface, in voxels (centre to surface)
};

// The largest distance, in voxels, from the centres of the voxels of `before` missing from
// `after` to the surface of `mesh` (grid coordinates of the voxels' frame).
template <typename VoxelSet>
double farthest_removed_voxel(const Mesh& mesh, const VoxelSet& before, const VoxelSet& after, std::size_t& removed)
{
  const gs::Voxel_frame& frame = before.frame();
  const auto lines = gs::internal::mesh_grid_lines(mesh, get(CGAL::vertex_point, mesh), frame, true, "test");
  double farthest = 0;
  removed = 0;
  before.for_each([&](const gs::Voxel_key& k) {
    if(after.contains(k))
      return;
    ++removed;
    const gs::internal::Vec3 centre = frame.to_grid(frame.centre(k));
    const gs::internal::Vec3 nearest = gs::internal::nearest_point_on_soup(lines, centre);
    farthest = std::max(farthest, gs::internal::norm3(gs::internal::sub(nearest, centre)));
  });
  return farthest;
}

Cut_result cut(const Mesh& mesh, int resolution)
{
  test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(mesh, resolution);
  Cut_result r;
  r.cycles_before = test::graph_cycles(p.graph);
  r.components_before = test::graph_components(p.graph);
  const auto thinned = p.voxels;
  r.reported = gs::cut_spurious_cycles(p.voxels, mesh);
  r.farthest_removed_voxel = farthest_removed_voxel(mesh, thinned, p.voxels, r.removed);
  decltype(p.graph) after;
  gs::to_graph(p.voxels, p.distances, mesh, after);
  r.cycles_after = test::graph_cycles(after);
  r.components_after = test::graph_components(after);
  return r;
}

// The number of handles of the mesh's surface, over its own vertex components.
std::size_t capped_genus_sum(const Mesh& mesh)
{
  return gs::internal::capped_genus_sum(
      mesh, gs::internal::vertex_components(mesh, CGAL::get_initialized_vertex_index_map(mesh)));
}

// The curve ends of a voxel skeleton: its voxels with one 26-neighbour.
template <typename VoxelSet>
std::size_t curve_ends(const VoxelSet& skeleton)
{
  return gs::classify_skeleton_points(skeleton, boost::dummy_property_map()).end;
}

// A horseshoe of five overlapping boxes (two pillars, a bar on top, a foot under each
// pillar) whose feet end `gap` apart, in the plane y = [0, 1]; the shape spans 6 units.
Mesh horseshoe(double gap)
{
  test::Soup s = test::box(0, 0, 0, 1, 1, 6);
  test::append(s, test::box(5, 0, 0, 6, 1, 6));
  test::append(s, test::box(0, 0, 5, 6, 1, 6));
  test::append(s, test::box(0.5, 0, 0, 3 - gap / 2, 1, 1));
  test::append(s, test::box(3 + gap / 2, 0, 0, 5.5, 1, 1));
  return test::mesh_of<Mesh>(s);
}

// The four corners of a square section of a tube, turning the same way in every section.
using Tube_section = std::array<std::array<double, 3>, 4>;

// Appends to `s` a tube through `sections` (two or more), capped at both ends: one closed
// surface.
void add_capped_tube(test::Soup& s, const std::vector<Tube_section>& sections)
{
  const std::size_t base = s.points.size();
  for(const Tube_section& section : sections)
    for(const auto& p : section)
      s.add_point(p[0], p[1], p[2]);
  const auto at = [&](std::size_t section, int corner) { return base + 4 * section + std::size_t(corner % 4); };
  for(std::size_t i = 0; i + 1 < sections.size(); ++i)
    for(int k = 0; k < 4; ++k)
      s.add_quad(at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1));
  const std::size_t last = sections.size() - 1;
  s.add_quad(at(0, 0), at(0, 1), at(0, 2), at(0, 3));
  s.add_quad(at(last, 3), at(last, 2), at(last, 1), at(last, 0));
}

// A tube of square section (1 unit wide) coiled a little more than once around the z axis
// (from angle 0 to 2 pi + 1, its radius growing from 3 to 3.3 units so that its ends
// overlap without coinciding), capped, in `pieces` parts: one connected surface whose two
// ends overlap, or two tubes (the turn's two halves, each a little longer) that overlap at
// both ends.
Mesh coiled_tube(int pieces)
{
  const double turn = 2 * test::pi + 1.0;
  const int sections = 80;
  test::Soup s;
  const auto add_tube = [&](int first, int last) {
    std::vector<Tube_section> tube;
    for(int i = first; i <= last; ++i)
    {
      const double angle = turn * i / sections, radius = 3 + 0.3 * angle / (2 * test::pi);
      Tube_section& section = tube.emplace_back();
      int corner = 0;
      for(const auto& [dr, dz] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}})
        section[std::size_t(corner++)] = {(radius + dr) * std::cos(angle), (radius + dr) * std::sin(angle), dz};
    }
    add_capped_tube(s, tube);
  };
  if(pieces == 1)
    add_tube(0, sections);
  else
  {
    add_tube(0, sections / 2 + 4);
    add_tube(sections / 2 - 4, sections);
  }
  const Mesh mesh = test::mesh_of<Mesh>(s);
  BOOST_TEST_REQUIRE(CGAL::is_closed(mesh)); // each tube a closed surface
  return mesh;
}

// A body (a box 4 x 1 x 1) on two legs, with a thin tail of square section (0.06 wide,
// under a voxel at resolution 64) that leaves the rump, turns down around a half circle of
// radius 0.6 and comes back forward under the body, its tip 0.03 short of the back of the
// hind leg: within a voxel, so that the solid joins them and the skeleton has a cycle
// through the tail, the leg and the body. The tail is a piece of its own, as artists
// model one. Every coordinate is multiplied by `scale`.
const std::array<double, 3> tail_root{0.0, 0.5, 1.5}, tail_tip{0.17, 0.5, 0.3};

Mesh body_with_a_tail_resting_on_a_leg(double scale = 1)
{
  test::Soup s = test::box(0, 0, 1, 4, 1, 2);
  test::append(s, test::box(0.2, 0.2, -1, 0.8, 0.8, 1.05));
  test::append(s, test::box(3.2, 0.2, -1, 3.8, 0.8, 1.05));
  std::vector<std::array<double, 3>> path; // from inside the rump to the tip
  for(int i = 0; i <= 4; ++i)
    path.push_back({0.3 - 0.3 * i / 4, 0.5, 1.5});
  for(int i = 1; i <= 24; ++i)
  {
    const double angle = test::pi / 2 + test::pi * i / 24;
    path.push_back({0.6 * std::cos(angle), 0.5, 0.9 + 0.6 * std::sin(angle)});
  }
  for(int i = 1; i <= 4; ++i)
    path.push_back({tail_tip[0] * i / 4, 0.5, 0.3});
  const double half_width = 0.03;
  std::vector<Tube_section> tail;
  for(std::size_t i = 0; i < path.size(); ++i)
  {
    const auto& before = path[i == 0 ? 0 : i - 1];
    const auto& after = path[std::min(i + 1, path.size() - 1)];
    const double tx = after[0] - before[0], tz = after[2] - before[2], length = std::hypot(tx, tz);
    const double nx = -tz / length, nz = tx / length; // normal to the path in its plane
    Tube_section& section = tail.emplace_back();
    int corner = 0;
    for(const auto& [dn, dy] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
      section[std::size_t(corner++)] = {path[i][0] + half_width * dn * nx, path[i][1] + half_width * dy,
                                        path[i][2] + half_width * dn * nz};
  }
  add_capped_tube(s, tail);
  for(auto& p : s.points)
    for(double& c : p)
      c *= scale;
  const Mesh mesh = test::mesh_of<Mesh>(s);
  BOOST_TEST_REQUIRE(CGAL::is_closed(mesh));
  return mesh;
}

// The skeleton had one cycle, and the cut opened it without splitting the skeleton.
void expect_the_one_cycle_opened(const Cut_result& r)
{
  BOOST_TEST(r.cycles_before == 1);
  BOOST_TEST(r.reported == 1u);
  BOOST_TEST(r.cycles_after == 0);
  BOOST_TEST(r.components_after == 1);
}

} // namespace

BOOST_AUTO_TEST_CASE(a_surface_that_overlaps_itself_is_cut_where_it_does)
{
  // The coil's solid is a ring and its skeleton a cycle, but its surface has genus 0: the
  // cycle closes where the tube's ends overlap (winding number 2, as where the camel's
  // front legs interpenetrate), and no step of it leaves the solid. The steps through
  // the overlap are the evidence of a gap between two pieces of the one surface.
  const Cut_result r = cut(coiled_tube(1), 32);
  expect_the_one_cycle_opened(r);
}

BOOST_AUTO_TEST_CASE(separate_parts_that_overlap_are_one_solid)
{
  // The same coil in two parts that overlap at both ends: a real ring (each part winds
  // once around the overlaps), as the horseshoe of overlapping boxes.
  const Cut_result r = cut(coiled_tube(2), 32);
  BOOST_TEST(r.cycles_before == 1);
  BOOST_TEST(r.reported == 0u);
  BOOST_TEST(r.cycles_after == 1);
}

BOOST_AUTO_TEST_CASE(a_gap_narrower_than_a_voxel_makes_a_cycle_that_is_cut)
{
  // At resolution 32 a voxel is 6/32 = 0.19 units: a gap of 0.05 is bridged by the solid.
  const Cut_result r = cut(horseshoe(0.05), 32);
  expect_the_one_cycle_opened(r);
  // Cut at the gap: each voxel removed has a step out of the mesh to a neighbour, so its
  // centre is within a diagonal step (sqrt(3) voxels) of the surface.
  BOOST_TEST(r.removed > 0u);
  BOOST_TEST(r.farthest_removed_voxel <= std::sqrt(3.0));
}

BOOST_AUTO_TEST_CASE(a_ring_of_overlapping_parts_keeps_its_cycle)
{
  // The same parts with overlapping feet: a real ring, although every part has genus 0.
  const Cut_result r = cut(horseshoe(-0.5), 32);
  BOOST_TEST(r.cycles_before == 1);
  BOOST_TEST(r.reported == 0u);
  BOOST_TEST(r.cycles_after == 1);
}

BOOST_AUTO_TEST_CASE(a_gap_wider_than_a_voxel_makes_no_cycle)
{
  const Cut_result r = cut(horseshoe(1.0), 32);
  BOOST_TEST(r.cycles_before == 0);
  BOOST_TEST(r.reported == 0u);
  BOOST_TEST(r.cycles_after == 0);
}

BOOST_AUTO_TEST_CASE(real_handles_are_kept)
{
  // eight.off and the double torus have genus 2, elephant.off genus 3. The elephant's
  // handles (the tail against the body among them) have holes about a voxel wide at
  // resolution 64, which the conservative solid closes or not as the grid falls: 2 to 5
  // cycles at 48 to 96; from 128 on the solid has exactly its three.
  for(const auto& [name, genus, resolution] : {std::tuple<std::string, long, int>{"eight.off", 2, 64},
                                               {"double-torus-example.off", 2, 64}, {"elephant.off", 3, 128}})
  {
    const Cut_result r = cut(test::demo_mesh<Mesh>(name), resolution);
    BOOST_TEST(r.cycles_before == genus, name);
    BOOST_TEST(r.reported == 0u, name);
    BOOST_TEST(r.removed == 0u, name);
    BOOST_TEST(r.cycles_after == genus, name);
  }
  BOOST_TEST(capped_genus_sum(test::mesh_of<Mesh>(test::torus(2, 0.5, 24, 12))) == 1u);
}

BOOST_AUTO_TEST_CASE(near_contacts_of_demo_characters_are_opened)
{
  // At resolution 64 these genus-0 characters have parts within a voxel of each other
  // (hand on thigh, legs, fingers), which the conservative solid joins. (bear.off's near
  // contact is joined or not as the grid falls: not at 64.)
  for(const char* name : {"man.off", "homer.off", "hand.off"})
  {
    const Mesh mesh = test::demo_mesh<Mesh>(name);
    BOOST_TEST(capped_genus_sum(mesh) == 0u, name);
    const Cut_result r = cut(mesh, 64);
    BOOST_TEST_MESSAGE(name << ": " << r.cycles_before << " cycles after thinning, " << r.reported << " cut");
    BOOST_TEST(r.cycles_before > 0, name);
    BOOST_TEST(r.cycles_after == 0, name);
    // The cuts are at the contacts, not inside a part: every voxel removed is within a
    // diagonal step of the surface (see above).
    BOOST_TEST(r.farthest_removed_voxel <= std::sqrt(3.0), name);
  }
}

BOOST_AUTO_TEST_CASE(touching_curves_are_pulled_apart_not_cut)
{
  // At resolution 64 the skeletons of the camel's two front legs touch at one voxel (the
  // legs cross: they come within a voxel of each other there, and interpenetrate in the mesh
  // a little lower), and those of its hind legs touch a one-voxel bridge between them: each
  // contact closes a cycle through the body. Removing the voxel of a contact
  // would split the skeleton, and the cut used to remove a voxel of a leg above it: that
  // leg's upper part ended in a stub and its lower part hung from the other leg. Moving the
  // voxel of the contact to a free neighbour that still links its own leg opens each cycle
  // and cuts no leg: the skeleton has no curve end that it did not have.
  const Mesh camel = test::demo_mesh<Mesh>("camel.off");
  test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(camel, 64);
  BOOST_TEST(test::graph_cycles(p.graph) == 2);
  const std::size_t ends_before = curve_ends(p.voxels);
  const std::size_t voxels_before = p.voxels.size();
  BOOST_TEST(gs::cut_spurious_cycles(p.voxels, camel) == 2u);
  decltype(p.graph) after;
  gs::to_graph(p.voxels, p.distances, camel, after);
  BOOST_TEST(test::graph_cycles(after) == 0);
  BOOST_TEST(test::graph_components(after) == 1);
  BOOST_TEST(curve_ends(p.voxels) == ends_before);
  BOOST_TEST(p.voxels.size() == voxels_before); // moved, none removed
  // Every voxel is still inside the solid: a moved voxel stays in its leg.
  p.voxels.for_each([&](const gs::Voxel_key& k) { BOOST_TEST(p.distances.inside(k)); });
}

BOOST_AUTO_TEST_CASE(a_thin_tail_resting_on_a_leg_stays_hung_from_its_root)
{
  // The tail is thinner than a voxel, so its curve pokes out of its surface all along, at
  // its root as much as at its tip: the test of steps alone cannot tell where the contact
  // is, and the cut removed a voxel at the root, leaving the tail hung from the leg by its
  // tip. The voxels are now tried farthest along the surface from the middle of the model
  // first, and the tip is the farthest.
  const Mesh mesh = body_with_a_tail_resting_on_a_leg();
  for(int resolution : {64, 96})
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(mesh, resolution);
      BOOST_TEST_REQUIRE(test::graph_cycles(p.graph) == 1);
      const auto thinned = p.voxels;
      BOOST_TEST(gs::cut_spurious_cycles(p.voxels, mesh) == 1u);
      decltype(p.graph) after;
      gs::to_graph(p.voxels, p.distances, mesh, after);
      BOOST_TEST(test::graph_cycles(after) == 0);
      BOOST_TEST(test::graph_components(after) == 1);
      std::size_t removed = 0;
      thinned.for_each([&](const gs::Voxel_key& k) {
        if(p.voxels.contains(k))
          return;
        ++removed;
        const auto c = thinned.frame().centre(k);
        BOOST_TEST(gs::internal::squared_distance3(c, tail_tip) < gs::internal::squared_distance3(c, tail_root),
                   "removed voxel at " << c[0] << " " << c[1] << " " << c[2] << " is nearer the tail's root");
      });
      BOOST_TEST(removed > 0u);
    }
}

BOOST_AUTO_TEST_CASE(where_the_tail_is_cut_does_not_depend_on_the_model_s_scale)
{
  // The distances along the surface are measured in voxels, so that their sums neither
  // overflow nor vanish: at the ends of the range of scales the package takes, the cut
  // removes the same voxels (in world units, single-precision lengths would be infinite at
  // 1e120 and zero at 1e-120, and every voxel would tie).
  const auto removed_voxels = [](double scale) {
    const Mesh mesh = body_with_a_tail_resting_on_a_leg(scale);
    test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(mesh, 64);
    const auto thinned = p.voxels;
    gs::cut_spurious_cycles(p.voxels, mesh);
    std::vector<gs::Voxel_key> removed;
    thinned.for_each([&](const gs::Voxel_key& k) {
      if(!p.voxels.contains(k))
        removed.push_back(k);
    });
    std::sort(removed.begin(), removed.end());
    return removed;
  };
  const std::vector<gs::Voxel_key> at_unit_scale = removed_voxels(1);
  BOOST_TEST_REQUIRE(!at_unit_scale.empty());
  for(double scale : {1e120, 1e-120})
    BOOST_TEST_CONTEXT("scale " << scale)
    {
      BOOST_TEST((removed_voxels(scale) == at_unit_scale));
    }
}

BOOST_AUTO_TEST_CASE(the_cycles_are_counted_on_the_graph_that_is_left)
{
  // Removing a voxel can free an edge that a junction triangle through it hid, and that
  // edge can close again the cycle the removal opened. The cut counted its cycles on the
  // graph it started from: on the camel at 128 it reported 6 cycles opened of 7, and 3 were
  // left; at 96, 3 of its cycles were left. It now counts them on the graph of the voxels
  // left, and tries again on it while it opens cycles. (At 128 one cycle was still left,
  // through the front legs, which interpenetrate: see
  // a_surface_that_overlaps_itself_is_cut_where_it_does.)
  const Mesh camel = test::demo_mesh<Mesh>("camel.off");
  for(int resolution : {96, 128})
  {
    const Cut_result r = cut(camel, resolution);
    BOOST_TEST_CONTEXT("resolution " << resolution)
    {
      BOOST_TEST(r.cycles_before > 0);
      BOOST_TEST(long(r.reported) == r.cycles_before - r.cycles_after);
      BOOST_TEST(r.components_after == r.components_before);
      BOOST_TEST(r.farthest_removed_voxel <= std::sqrt(3.0));
      BOOST_TEST(r.cycles_after == 0);
    }
  }
}

BOOST_AUTO_TEST_CASE(an_empty_skeleton_or_mesh_cuts_nothing)
{
  gs::Sparse_voxel_set empty;
  BOOST_TEST(gs::cut_spurious_cycles(empty, test::mesh_of<Mesh>(test::box(0, 0, 0, 1, 1, 1))) == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
