// Specification of compute_skinning_weights(): weights that skin a mesh to a control
// skeleton (non-negative, summing to 1, at most K per vertex, local, through the solid).
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <Geodesic_skeleton_test/characters.h>
#include <Geodesic_skeleton_test/rigs.h>
#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(skinning_weights)

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
namespace shapes = Geodesic_skeleton_test;

using Point = Geodesic_skeleton_test::Rig_point;
using Mesh = Geodesic_skeleton_test::Rig_mesh;
using Control = Geodesic_skeleton_test::Rig_skeleton;
using vertex_descriptor = Mesh::Vertex_index;
using Geodesic_skeleton_test::bar;
using Geodesic_skeleton_test::bar_skeleton;
using Geodesic_skeleton_test::chain_skeleton;
using Geodesic_skeleton_test::weights_of;

namespace {

double weight_of(const gs::Bone_weights& w, std::size_t bone)
{
  for(std::size_t i = 0; i < w.size(); ++i)
    if(w.bone[i] == bone)
      return w.weight[i];
  return 0;
}

// A bar of radius 1 and length 20 along z (`segments` segments long), with two bones, each
// a segment, skinned at resolution 96.
struct Two_bones_on_a_bar
{
  Mesh mesh;
  std::vector<gs::Bone_weights> weights;

  Two_bones_on_a_bar(const std::vector<Point>& first, const std::vector<Point>& second, int segments)
      : mesh(shapes::mesh_of<Mesh>(shapes::cylinder(1, 20, 24, segments, true)))
  {
    weights = weights_of(mesh, chain_skeleton(second, chain_skeleton(first)), params::resolution(96));
  }

  template <typename Predicate>
  std::vector<vertex_descriptor> vertices_where(Predicate keep) const
  {
    std::vector<vertex_descriptor> kept;
    for(vertex_descriptor v : vertices(mesh))
      if(keep(mesh.point(v)))
        kept.push_back(v);
    return kept;
  }
};

} // namespace

BOOST_AUTO_TEST_CASE(weights_are_non_negative_sorted_and_sum_to_one)
{
  const auto [cow, control] = shapes::demo_mesh_with_skeleton("cow.off");
  BOOST_REQUIRE_GT(num_edges(control), 5u);
  gs::Skinning_report report;
  const auto weights = weights_of(cow, control, CGAL::parameters::default_values(), &report);
  BOOST_CHECK_GT(report.solid_voxels, 1000u);
  // The bounded searches visit far fewer voxels than one full search per bone.
  BOOST_CHECK_LT(report.voxel_visits, report.solid_voxels * num_edges(control) / 2);
  for(const gs::Bone_weights& w : weights)
  {
    BOOST_REQUIRE_GE(w.size(), 1u);
    BOOST_REQUIRE_LE(w.size(), 4u);
    double sum = 0;
    for(std::size_t i = 0; i < w.size(); ++i)
    {
      BOOST_REQUIRE_LT(w.bone[i], num_edges(control));
      BOOST_REQUIRE_GE(w.weight[i], 0.f);
      if(i > 0)
        BOOST_REQUIRE_GE(w.weight[i - 1], w.weight[i]);
      sum += w.weight[i];
    }
    BOOST_REQUIRE_SMALL(sum - 1, 1e-5);
  }
}

BOOST_AUTO_TEST_CASE(at_most_max_bones_per_vertex_influence_a_vertex)
{
  const auto [cow, control] = shapes::demo_mesh_with_skeleton("cow.off");
  std::size_t most[3] = {0, 0, 0};
  for(int k : {1, 2, 8})
  {
    const auto weights = weights_of(cow, control, params::max_bones_per_vertex(k));
    for(const gs::Bone_weights& w : weights)
    {
      BOOST_REQUIRE_LE(w.size(), std::size_t(k));
      BOOST_REQUIRE_SMALL(w.total() - 1, 1e-5);
      most[k == 1 ? 0 : k == 2 ? 1 : 2] = std::max(most[k == 1 ? 0 : k == 2 ? 1 : 2], w.size());
    }
  }
  BOOST_CHECK_EQUAL(most[0], 1u);
  BOOST_CHECK_EQUAL(most[1], 2u);
  BOOST_CHECK_GT(most[2], 2u); // somewhere (a junction) more than two bones meet
}

BOOST_AUTO_TEST_CASE(a_bone_has_no_weight_at_the_far_end_of_a_long_bar)
{
  const Mesh mesh = bar();
  const auto weights = weights_of(mesh, bar_skeleton(), params::resolution(96));
  std::size_t blended = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    const gs::Bone_weights& w = weights[v];
    if(z > 15)
      BOOST_CHECK_EQUAL(weight_of(w, 0), 0.);
    if(z < 5)
      BOOST_CHECK_EQUAL(weight_of(w, 1), 0.);
    if(std::abs(z - 10) < 0.25)
    {
      // On the two rings next to the joint, both bones pull (the blend is as narrow as
      // artists paint it: a fifth of the bar's radius from the joint, the far bone has 15 %).
      BOOST_CHECK_GT(weight_of(w, 0), 0.1);
      BOOST_CHECK_GT(weight_of(w, 1), 0.1);
      ++blended;
    }
  }
  BOOST_CHECK_GT(blended, 20u);
}

BOOST_AUTO_TEST_CASE(a_joint_s_weight_reaches_past_its_child_joint)
{
  // Artists paint a bone's weight a little past its child joint: on a bar rigged with two
  // bones meeting at its middle, the ring of vertices at the joint (z = 10), where the heat
  // of both bones is the same by symmetry, leans to the lower bone by about the parent
  // joint's preference sharpened (1.1^2.5 = 1.27); and no vertex below the joint leads with
  // the upper bone.
  const Mesh mesh = bar();
  const auto weights = weights_of(mesh, bar_skeleton(), CGAL::parameters::default_values());
  std::size_t on_the_joint = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    const gs::Bone_weights& w = weights[v];
    if(std::abs(z - 10) < 1e-6)
    {
      ++on_the_joint;
      BOOST_TEST(weight_of(w, 0) > 1.2 * weight_of(w, 1), "at (" << mesh.point(v) << ")");
      BOOST_TEST(weight_of(w, 0) < 1.4 * weight_of(w, 1), "at (" << mesh.point(v) << ")");
    }
    if(z < 10 - 1e-6)
      BOOST_TEST(w.bone[0] == 0u);
  }
  BOOST_TEST(on_the_joint >= 24u);
}

BOOST_AUTO_TEST_CASE(the_segmentation_is_the_bone_of_largest_weight)
{
  const Mesh mesh = bar();
  std::vector<int> segment(num_vertices(mesh), -1);
  const auto weights = weights_of(
      mesh, bar_skeleton(),
      params::bone_segmentation_map(boost::make_iterator_property_map(segment.begin(), get(CGAL::vertex_index, mesh))));
  for(vertex_descriptor v : vertices(mesh))
  {
    BOOST_CHECK_EQUAL(segment[v], int(weights[v].bone[0]));
    const double z = mesh.point(v).z();
    if(z < 9)
      BOOST_CHECK_EQUAL(segment[v], 0);
    if(z > 11)
      BOOST_CHECK_EQUAL(segment[v], 1);
  }
}

BOOST_AUTO_TEST_CASE(distances_run_through_the_solid_not_through_the_air)
{
  // Two parallel bars 0.6 apart (their axes 2.6 apart), each with its own bone: straight-line
  // distances would give each bar some weight of the other's bone (where a vertex is 1 from
  // its own bone, it is 1.6 from the other, less than twice as far).
  shapes::Soup soup = shapes::cylinder(1, 20, 24, 46, true);
  shapes::append(soup, shapes::cylinder(1, 20, 24, 46, true), 2.6, 0, 0);
  const Mesh mesh = shapes::mesh_of<Mesh>(soup);
  Control skeleton = chain_skeleton({Point(0, 0, 2), Point(0, 0, 18)});
  skeleton = chain_skeleton({Point(2.6, 0, 2), Point(2.6, 0, 18)}, skeleton);
  gs::Skinning_report report;
  const auto weights = weights_of(mesh, skeleton, params::resolution(96), &report);
  BOOST_CHECK_EQUAL(report.vertices_bound_in_straight_line, 0u);
  for(vertex_descriptor v : vertices(mesh))
  {
    BOOST_REQUIRE_EQUAL(weights[v].size(), 1u);
    BOOST_CHECK_EQUAL(weights[v].bone[0], mesh.point(v).x() < 1.3 ? 0u : 1u);
  }
}

BOOST_AUTO_TEST_CASE(a_bone_the_surface_turns_its_back_on_does_not_take_it)
{
  // A bar with its bone along the axis, and a prop's bone outside it, 0.3 from its +x side
  // (a sword held along a thigh). The +x side is 0.3 from the prop's bone in straight line
  // and 1 from its own, but it faces away from the prop's bone: it stays with the bar's.
  const Two_bones_on_a_bar bar({Point(0, 0, 2), Point(0, 0, 18)}, {Point(1.3, 0, 5), Point(1.3, 0, 15)}, 46);
  std::size_t facing_the_prop = 0;
  for(vertex_descriptor v : bar.vertices_where([](const Point& p) { return p.x() > 0.9 && p.z() > 7 && p.z() < 13; }))
  {
    BOOST_CHECK_EQUAL(bar.weights[v].bone[0], 0u);
    BOOST_CHECK_LT(weight_of(bar.weights[v], 1), 0.1);
    ++facing_the_prop;
  }
  BOOST_CHECK_GT(facing_the_prop, 20u);
}

BOOST_AUTO_TEST_CASE(a_big_head_follows_its_own_bone_not_the_arms_through_it)
{
  // A torso, a big round head (radius 3, centre at z 13) and arms along x whose bones leave
  // the neck at z 11 and run through the lower part of the head, as on a cartoon character.
  // On the head's side an arm's bone is straight below the surface and nearer than the head's
  // short bone (bone heat's choice), but the vertex's inscribed ball is centred in the head.
  shapes::Soup soup = shapes::cylinder(1.5, 10, 24, 20, true);
  shapes::append(soup, shapes::icosphere(3, 3), 0, 0, 13);
  shapes::append(soup, shapes::box(-8, -0.6, 10.4, 8, 0.6, 11.6));
  const Mesh mesh = shapes::mesh_of<Mesh>(soup);
  Control skeleton;
  for(const Point& p : {Point(0, 0, 1), Point(0, 0, 11), Point(0, 0, 11.5), Point(3.5, 0, 11), Point(7.5, 0, 11),
                        Point(-3.5, 0, 11), Point(-7.5, 0, 11)})
  {
    gs::Control_joint<Point> joint;
    joint.point = p;
    add_vertex(joint, skeleton);
  }
  skeleton[boost::graph_bundle].roots.push_back(0);
  for(const auto& [parent, child] : {std::pair{0, 1}, {1, 2}, {1, 3}, {3, 4}, {1, 5}, {5, 6}})
    add_edge(std::size_t(parent), std::size_t(child), skeleton);
  const std::size_t head_bone = 1; // the bone from the neck to the head joint
  BOOST_REQUIRE_EQUAL(source(gs::numbered_bones(skeleton)[head_bone], skeleton), 1u);
  BOOST_REQUIRE_EQUAL(target(gs::numbered_bones(skeleton)[head_bone], skeleton), 2u);

  const auto weights = weights_of(mesh, skeleton, CGAL::parameters::default_values());
  std::size_t head_vertices = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    if(std::abs(std::sqrt(p.x() * p.x() + p.y() * p.y() + (p.z() - 13) * (p.z() - 13)) - 3) > 1e-6 || p.z() < 12.2)
      continue; // not on the head, or within 0.6 of the arms
    BOOST_CHECK_EQUAL(weights[v].bone[0], head_bone);
    ++head_vertices;
  }
  BOOST_CHECK_GT(head_vertices, 400u);
}

namespace {

// The voxels of a 44^3 box whose centres satisfy `inside` (grid coordinates).
gs::Dense_voxel_grid voxels_whose_centres(const std::function<bool(double, double, double)>& inside)
{
  return Geodesic_skeleton_test::voxels_where<gs::Dense_voxel_grid>(
      gs::Voxel_box{gs::Voxel_key{0, 0, 0}, gs::Voxel_key{44, 44, 44}},
      [&](int x, int y, int z) { return inside(x + 0.5, y + 0.5, z + 0.5); });
}

} // namespace

BOOST_AUTO_TEST_CASE(an_inscribed_balls_centre_is_the_middle_of_a_ball_or_the_axis_of_a_bar)
{
  const gs::Dense_voxel_grid ball = voxels_whose_centres([](double x, double y, double z) {
    return std::hypot(x - 22, y - 22, z - 22) < 15;
  });
  const gs::Dense_voxel_grid bar = voxels_whose_centres([](double, double y, double z) {
    return std::hypot(y - 22, z - 22) < 6;
  });
  for(const gs::Dense_voxel_grid* grid : {&ball, &bar})
  {
    const gs::Voxel_distance_field depth = gs::distance_transform(*grid);
    const double radius = grid == &ball ? 15 : 6;
    for(int i = 0; i < 40; ++i)
    {
      // Points spread over the surface, each with its outward normal.
      const double polar = std::acos(1 - 2 * (i + 0.5) / 40), around = 2.39996 * i;
      const gs::internal::Vec3 normal = grid == &ball
                                            ? gs::internal::Vec3{std::sin(polar) * std::cos(around),
                                                                 std::sin(polar) * std::sin(around), std::cos(polar)}
                                            : gs::internal::Vec3{0, std::cos(around), std::sin(around)};
      const double x = grid == &ball ? 22 : 12 + 0.5 * i; // along the bar, away from its ends
      const gs::internal::Vec3 point{x + radius * normal[0], 22 + radius * normal[1], 22 + radius * normal[2]};
      const gs::internal::Vec3 centre = gs::internal::inscribed_ball_centre(point, normal, depth);
      const gs::internal::Vec3 expected{x, 22, 22};
      BOOST_TEST(gs::internal::norm3(gs::internal::sub(centre, expected)) < 1.5,
                 "point " << i << ": centre " << centre[0] << " " << centre[1] << " " << centre[2]);
    }
    const gs::internal::Vec3 on_surface{22, 22 + radius, 22};
    const gs::internal::Vec3 no_normal = gs::internal::inscribed_ball_centre(on_surface, {0, 0, 0}, depth);
    BOOST_TEST(gs::internal::norm3(gs::internal::sub(no_normal, on_surface)) == 0);
  }
}

BOOST_AUTO_TEST_CASE(bones_at_the_same_distance_share_the_heat)
{
  // Two bones leave the middle of a bar in opposite directions: on the ring through their
  // common end, both are at the same distance, and neither takes the ring because the
  // searches happened to reach it first.
  const Two_bones_on_a_bar bar({Point(0, 0, 10), Point(0, 0, 1)}, {Point(0, 0, 10), Point(0, 0, 19)}, 40);
  const auto ring = bar.vertices_where([](const Point& p) { return std::abs(p.z() - 10) < 1e-9 && std::abs(p.x()) < 2; });
  BOOST_CHECK_EQUAL(ring.size(), 24u);
  for(vertex_descriptor v : ring)
    BOOST_CHECK_SMALL(weight_of(bar.weights[v], 0) - weight_of(bar.weights[v], 1), 0.02);
}

BOOST_AUTO_TEST_CASE(the_weights_do_not_depend_on_the_winding)
{
  // Outward normals come from each piece's signed volume, not from the modeller's winding.
  const auto [cow, control] = shapes::demo_mesh_with_skeleton("cow.off");
  const auto outward = weights_of(cow, control, CGAL::parameters::default_values());
  Mesh inward = cow;
  CGAL::Polygon_mesh_processing::reverse_face_orientations(inward);
  const auto weights = weights_of(inward, control, CGAL::parameters::default_values());
  double largest_change = 0;
  for(vertex_descriptor v : vertices(cow))
  {
    BOOST_REQUIRE_EQUAL(weights[v].bone[0], outward[v].bone[0]);
    for(std::size_t b = 0; b < num_edges(control); ++b)
      largest_change = std::max(largest_change, std::abs(weight_of(weights[v], b) - weight_of(outward[v], b)));
  }
  BOOST_CHECK_LT(largest_change, 1e-4);
}

BOOST_AUTO_TEST_CASE(a_piece_without_bone_follows_the_nearest_bone)
{
  shapes::Soup soup = shapes::cylinder(1, 20, 24, 46, true);
  shapes::append(soup, shapes::icosphere(1, 2), 5, 0, 18); // a loose "eye" near the top
  const Mesh mesh = shapes::mesh_of<Mesh>(soup);
  gs::Skinning_report report;
  const auto weights = weights_of(mesh, bar_skeleton(), CGAL::parameters::default_values(), &report);
  BOOST_CHECK_EQUAL(report.vertices_bound_in_straight_line, 162u); // the icosphere's vertices
  for(vertex_descriptor v : vertices(mesh))
    if(mesh.point(v).x() > 3)
    {
      BOOST_REQUIRE_EQUAL(weights[v].size(), 1u);
      BOOST_CHECK_EQUAL(weights[v].bone[0], 1u);
    }
}

BOOST_AUTO_TEST_CASE(the_chains_solid_gives_the_same_weights)
{
  // skeletonize hands the skeleton's solid to the weights instead of voxelizing twice: the
  // weights are the same, and a solid of another resolution or mesh is refused.
  const Mesh mesh = shapes::mesh_of<Mesh>(shapes::cylinder(1, 20, 24, 46, true));
  Control skeleton;
  gs::Dense_voxel_grid solid;
  gs::extract_control_skeleton(mesh, skeleton, params::combine(params::resolution(48), params::voxelized_solid(&solid)));
  BOOST_TEST_REQUIRE(num_edges(skeleton) > 0u);
  BOOST_TEST_REQUIRE(!solid.empty());
  const auto expected = weights_of(mesh, skeleton, params::resolution(48));
  const auto given = weights_of(mesh, skeleton, params::combine(params::resolution(48), params::voxelized_solid(&std::as_const(solid))));
  std::size_t differing = 0;
  for(vertex_descriptor v : vertices(mesh))
    differing += !(given[v].size() == expected[v].size() &&
                   std::equal(given[v].bone.begin(), given[v].bone.begin() + given[v].size(), expected[v].bone.begin()) &&
                   std::equal(given[v].weight.begin(), given[v].weight.begin() + given[v].size(), expected[v].weight.begin()));
  BOOST_TEST(differing == 0u);
  // The stages' pack may hold the voxelized surface, for reading or writing: the weights
  // neither read nor write it.
  gs::Voxelized_surface surface;
  const auto with_writable_surface =
      weights_of(mesh, skeleton, params::combine(params::resolution(48), params::voxelized_surface(&surface)));
  const auto with_read_only_surface =
      weights_of(mesh, skeleton, params::combine(params::resolution(48), params::voxelized_surface(&std::as_const(surface))));
  BOOST_TEST(surface.empty());
  auto same = [](const gs::Bone_weights& a, const gs::Bone_weights& b) { return a.bone == b.bone && a.weight == b.weight; };
  for(vertex_descriptor v : vertices(mesh))
  {
    BOOST_TEST(same(with_writable_surface[v], expected[v]));
    BOOST_TEST(same(with_read_only_surface[v], expected[v]));
  }
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::combine(params::resolution(64), params::voxelized_solid(&std::as_const(solid)))),
                    std::invalid_argument);
  const Mesh other = shapes::mesh_of<Mesh>(shapes::cylinder(1, 21, 24, 46, true));
  BOOST_CHECK_THROW(weights_of(other, skeleton, params::combine(params::resolution(48), params::voxelized_solid(&std::as_const(solid)))),
                    std::invalid_argument);
  const gs::Dense_voxel_grid empty;
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::voxelized_solid(&empty)), std::invalid_argument);
}

namespace {

template <typename P>
P scaled_point(const P& p, double scale)
{
  return P(scale * p.x(), scale * p.y(), scale * p.z());
}

// `weights_of(mesh, control)` and the same with both scaled by `scale`, vertex by vertex.
void check_the_same_weights_at_scale(const Mesh& mesh, const Control& control, double scale)
{
  const auto at_one = weights_of(mesh, control, CGAL::parameters::default_values());
  Mesh scaled = mesh;
  for(vertex_descriptor v : vertices(scaled))
    scaled.point(v) = scaled_point(mesh.point(v), scale);
  Control scaled_control = control;
  for(auto j : CGAL::make_range(vertices(scaled_control)))
    scaled_control[j].point = scaled_point(control[j].point, scale);
  for(auto e : CGAL::make_range(edges(scaled_control)))
    for(Point& p : scaled_control[e].points)
      p = scaled_point(p, scale);
  const auto weights = weights_of(scaled, scaled_control, CGAL::parameters::default_values());
  std::size_t different = 0;
  for(vertex_descriptor v : vertices(mesh))
    different += !(weights[v].bone == at_one[v].bone && weights[v].weight == at_one[v].weight);
  BOOST_TEST_CONTEXT("scale " << scale) { BOOST_CHECK_EQUAL(different, 0u); }
}

} // namespace

BOOST_AUTO_TEST_CASE(the_weights_do_not_depend_on_the_scale)
{
  // All lengths are in voxels, the grid follows the mesh, and the grid coordinates are
  // rounded far above the rounding errors of a scaling (Voxel_frame::to_grid()): a character
  // scaled by 0.01, 0.3, 7 or 1000, none a power of two, gets the very weights it gets at 1.
  // Without the rounding, 370 to 709 of the T-pose figure's 8,730 vertices changed at every
  // one of these scales (a corner moved across a voxel's face), and at 0.01 the mirror-
  // symmetric starfish's frame turned over (its third moment across the mirror plane is only
  // rounding noise, the same at every scale only when computed from rounded coordinates).
  const Mesh figure = shapes::mesh_of<Mesh>(shapes::t_pose_figure());
  const Mesh starfish = shapes::mesh_of<Mesh>(shapes::thick_starfish(5, 0.3));
  for(const Mesh* mesh : {&figure, &starfish})
  {
    Control control;
    gs::extract_control_skeleton(*mesh, control);
    for(double scale : {0.01, 0.3, 7., 1000.})
      check_the_same_weights_at_scale(*mesh, control, scale);
  }
}

BOOST_AUTO_TEST_CASE(every_vertex_is_weighted_on_a_mesh_as_artists_make_them)
{
  // Bone heat fails when a piece of the mesh cannot see a bone or a triangle has no area;
  // here a bar with a second bar through it (self-intersecting), a zero-area triangle and a
  // detached piece without bone all get weights.
  shapes::Soup soup = shapes::cylinder(1, 20, 24, 46, true);
  shapes::append(soup, shapes::cylinder(0.5, 6, 12, 10, true), 0.7, 0, 7);
  const std::size_t a = soup.add_point(0.5, 0, 5), b = soup.add_point(0.6, 0, 5), c = soup.add_point(0.7, 0, 5);
  soup.add_triangle(a, b, c);
  shapes::append(soup, shapes::icosphere(1, 2), 5, 0, 18);
  const Mesh mesh = shapes::mesh_of<Mesh>(soup);
  gs::Skinning_report report;
  const auto weights = weights_of(mesh, bar_skeleton(), CGAL::parameters::default_values(), &report);
  BOOST_CHECK(report.heat_diffused);
  BOOST_CHECK_EQUAL(report.vertices_bound_in_straight_line, 162u); // the detached sphere
  for(vertex_descriptor v : vertices(mesh))
  {
    BOOST_REQUIRE_GE(weights[v].size(), 1u);
    BOOST_REQUIRE(std::isfinite(weights[v].total()));
    BOOST_REQUIRE_SMALL(weights[v].total() - 1, 1e-5);
  }
}

BOOST_AUTO_TEST_CASE(weights_are_sharp_away_from_the_joints)
{
  // Artists give most vertices one bone: half way along a bone, a vertex follows it alone.
  const Mesh mesh = bar();
  const auto weights = weights_of(mesh, bar_skeleton(), params::resolution(96));
  for(vertex_descriptor v : vertices(mesh))
  {
    const double z = mesh.point(v).z();
    if(std::abs(z - 5) < 2)
      BOOST_CHECK_EQUAL(weights[v].size(), 1u);
  }
}

BOOST_AUTO_TEST_CASE(the_solve_in_rows_is_the_solvers_solve)
{
  // The diffusion's solve of several bones in one pass over the factor gives, to the last
  // bit, what Eigen's solve gives one column at a time.
  const Mesh mesh = bar();
  std::vector<gs::internal::Vec3> points;
  for(vertex_descriptor v : vertices(mesh))
    points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  const auto triangles = gs::internal::triangles_of(mesh, get(CGAL::vertex_index, mesh));
  std::vector<double> heat(points.size());
  for(std::size_t v = 0; v < heat.size(); ++v)
    heat[v] = 0.1 / double(1 + v % 7);
  const auto system = gs::internal::screened_cotangent_laplacian(points, triangles, heat);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  BOOST_TEST_REQUIRE(solver.info() == Eigen::Success);
  const std::size_t n = points.size(), width = 3;
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(width));
  std::vector<double> rows(n * width, 0.);
  for(std::size_t v = 0; v < n; ++v)
    for(std::size_t c = 0; c < width; ++c)
      if((v + c) % 5 == 0) // sparse, as a bone's heat is
        columns(Eigen::Index(v), Eigen::Index(c)) = rows[v * width + c] = heat[v] * double(c + 1);
  const Eigen::MatrixXd expected = solver.solve(columns);
  gs::internal::solve_in_rows(solver, rows, width);
  std::size_t differing = 0;
  for(std::size_t v = 0; v < n; ++v)
    for(std::size_t c = 0; c < width; ++c)
      differing += rows[v * width + c] != expected(Eigen::Index(v), Eigen::Index(c));
  BOOST_TEST(differing == 0u);
  BOOST_TEST(expected.norm() > 0);
}

BOOST_AUTO_TEST_CASE(bad_parameters_and_skeletons_are_refused)
{
  const Mesh mesh = bar();
  const Control skeleton = bar_skeleton();
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::max_bones_per_vertex(0)), std::invalid_argument);
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::max_bones_per_vertex(9)), std::invalid_argument);
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::sharpness(0.5)), std::invalid_argument);
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::minimum_weight(0.6)), std::invalid_argument);
  BOOST_CHECK_THROW(weights_of(mesh, skeleton, params::influence_ratio(1.)), std::invalid_argument);
  Control no_bones = skeleton;
  while(num_edges(no_bones) > 0)
    remove_edge(*edges(no_bones).first, no_bones);
  BOOST_CHECK_THROW(weights_of(mesh, no_bones, CGAL::parameters::default_values()), std::invalid_argument);
  Control bad_point = skeleton;
  bad_point[gs::numbered_bones(bad_point)[1]].points = {Point(0, 0, 10), Point(0, 0, std::nan(""))};
  BOOST_CHECK_THROW(weights_of(mesh, bad_point, CGAL::parameters::default_values()), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_concurrent_forest_gives_the_sets_of_one_thread)
{
  // Random joins over 200,000 elements, by two threads at once (the skinning's clusters
  // are joined so); the sets must be those one thread gives, each rooted at its smallest.
  const std::uint32_t n = 200000;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> joins;
  std::uint64_t state = 12345;
  auto next = [&] { return std::uint32_t((state = state * 6364136223846793005ull + 1442695040888963407ull) >> 33) % n; };
  for(std::uint32_t i = 0; i < 150000; ++i)
  {
    const std::uint32_t a = next();
    joins.emplace_back(a, std::min(n - 1, a + next() % 64)); // mostly near: the threads meet
  }
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for(const auto& [a, b] : joins)
    if(const std::uint32_t ra = gs::internal::find_root(parent, a), rb = gs::internal::find_root(parent, b); ra != rb)
      parent[std::max(ra, rb)] = std::min(ra, rb);
  gs::internal::Concurrent_forest forest(n);
  gs::internal::for_each_part(joins.size(), 2, 2, [&](std::size_t, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
      forest.join(joins[i].first, joins[i].second);
  });
  std::size_t sets = 0;
  for(std::uint32_t x = 0; x < n; ++x)
  {
    const std::uint32_t root = gs::internal::find_root(parent, x);
    BOOST_REQUIRE_EQUAL(forest.root(x), root);
    BOOST_REQUIRE_LE(root, x);
    sets += root == x;
  }
  BOOST_CHECK_LT(sets, std::size_t(n) / 2); // the joins made large sets
  BOOST_CHECK_GT(sets, 1u);
}

BOOST_AUTO_TEST_CASE(the_weights_are_the_same_on_one_thread_and_on_all)
{
  // 24 x 401 vertices and 3 bones: past the size at which the passes over the vertices and
  // the clusters are split between threads.
  const Mesh mesh = shapes::mesh_of<Mesh>(shapes::cylinder(1, 20, 24, 400, true));
  const Control control = chain_skeleton({Point(0, 0, 1), Point(0, 0, 7), Point(0, 0, 14), Point(0, 0, 19)});
  BOOST_REQUIRE_GT(num_vertices(mesh), 8192u);
  std::vector<gs::Bone_weights> sequential(num_vertices(mesh)), parallel(num_vertices(mesh));
  const auto index = get(CGAL::vertex_index, mesh);
  gs::compute_skinning_weights<CGAL::Sequential_tag>(
      mesh, control, boost::make_iterator_property_map(sequential.begin(), index), params::resolution(96));
  gs::compute_skinning_weights<CGAL::Parallel_tag>(mesh, control,
                                                   boost::make_iterator_property_map(parallel.begin(), index),
                                                   params::resolution(96));
  std::size_t blended = 0;
  for(std::size_t v = 0; v < sequential.size(); ++v)
  {
    BOOST_REQUIRE_EQUAL(sequential[v].size(), parallel[v].size());
    blended += sequential[v].size() > 1;
    for(std::size_t i = 0; i < sequential[v].size(); ++i)
    {
      BOOST_REQUIRE_EQUAL(sequential[v].bone[i], parallel[v].bone[i]);
      BOOST_REQUIRE_EQUAL(sequential[v].weight[i], parallel[v].weight[i]);
    }
  }
  BOOST_CHECK_GT(blended, 0u); // the bones share vertices around the joints
}

BOOST_AUTO_TEST_SUITE_END()
