// Specification of CGAL/Geodesic_skeleton/voxelize.h.
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/route_skeleton_on_finer_grid.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/polygon_triangles.h>

#include <Geodesic_skeleton_test/characters.h>
#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(voxelize)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

Mesh mesh_of(const test::Soup& soup) { return test::mesh_of<Mesh>(soup); }


// Whether `what()` of the exception thrown by f contains `text`.
template <typename Exception, typename F>
bool throws_with(F f, const std::string& text)
{
  try
  {
    f();
  }
  catch(const Exception& e)
  {
    return std::string(e.what()).find(text) != std::string::npos;
  }
  return false;
}


} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(a_box_fills_its_voxels, VoxelSet, Voxel_set_models)
{
  // A 4 x 2 x 1 box at resolution 32: voxels of 1/8, 32 x 16 x 8 voxels inside, plus at
  // most one layer of surface voxels around.
  VoxelSet s;
  const std::size_t n = gs::voxelize(mesh_of(test::box(0, 0, 0, 4, 2, 1)), s, gs::parameters::resolution(32));
  BOOST_TEST(n == s.size());
  BOOST_TEST(s.frame().voxel_size() == 0.125, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(n >= 32u * 16u * 8u);
  BOOST_TEST(n <= 34u * 18u * 10u);
  BOOST_TEST(test::components_26(s) == 1);
  BOOST_TEST(1 - test::euler_characteristic(s) == 0); // no tunnel
}

BOOST_AUTO_TEST_CASE(both_models_and_both_mesh_types_give_the_same_voxels)
{
  Mesh mesh;
  test::read_demo_mesh("cow.off", mesh);
  Polyhedron polyhedron;
  test::read_demo_mesh("cow.off", polyhedron);
  gs::Dense_voxel_grid dense;
  gs::Sparse_voxel_set sparse, from_polyhedron;
  gs::voxelize(mesh, dense);
  gs::voxelize(mesh, sparse);
  gs::voxelize(polyhedron, from_polyhedron);
  BOOST_TEST((test::keys_of(dense) == test::keys_of(sparse)));
  BOOST_TEST((test::keys_of(sparse) == test::keys_of(from_polyhedron)));
}

BOOST_AUTO_TEST_CASE(the_volume_of_a_sphere_is_close_to_the_exact_one)
{
  // The solid includes the surface voxels: between the ball and the ball grown by one voxel.
  gs::Sparse_voxel_set s;
  gs::voxelize(mesh_of(test::icosphere(1., 4)), s, gs::parameters::resolution(40));
  const double h = s.frame().voxel_size();
  const double volume = double(s.size()) * h * h * h;
  BOOST_TEST(volume > 4. / 3. * test::pi * 0.97);
  BOOST_TEST(volume < 4. / 3. * test::pi * std::pow(1. + 1.8 * h, 3));
}

BOOST_AUTO_TEST_CASE(a_rigid_motion_gives_the_same_voxels_moved_with_the_mesh)
{
  Mesh cow;
  test::read_demo_mesh("cow.off", cow);
  gs::Dense_voxel_grid original;
  gs::voxelize(cow, original);
  for(unsigned seed : {1u, 2u, 3u})
  {
    const auto motion = test::random_rigid_motion<Kernel>(seed, 3.7, -1.2, 0.4);
    Mesh moved = cow;
    for(auto v : vertices(moved))
      moved.point(v) = motion.transform(moved.point(v));
    gs::Dense_voxel_grid s;
    gs::voxelize(moved, s);
    const auto a = test::keys_of(original), b = test::keys_of(s);
    std::size_t differences = 0;
    for(const auto& k : a)
      differences += b.count(k) == 0;
    for(const auto& k : b)
      differences += a.count(k) == 0;
    BOOST_TEST_MESSAGE("seed " << seed << ": " << differences << " voxels differ of " << a.size());
    BOOST_TEST(differences <= a.size() / 1000); // rounding at exact voxel boundaries only
    // The frame moves with the mesh: a voxel centre maps to the moved point.
    const gs::Voxel_key k = *a.begin();
    const auto p = original.frame().centre(k), q = s.frame().centre(k);
    const Point moved_p = motion.transform(Point(p[0], p[1], p[2]));
    BOOST_TEST(std::sqrt(test::squared_distance_3(moved_p, Point(q[0], q[1], q[2]))) < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(overlapping_and_self_intersecting_parts_make_one_solid)
{
  test::Soup soup = test::box(0, 0, 0, 4, 1, 1);
  test::append(soup, test::box(1, -1, -1, 2, 2, 2)); // crossing the first box
  test::append(soup, test::box(1.5, 0.25, 0.25, 1.6, 0.75, 0.75)); // inside both
  gs::Sparse_voxel_set s;
  gs::voxelize(mesh_of(soup), s, gs::parameters::resolution(32));
  BOOST_TEST(test::components_26(s) == 1);
  BOOST_TEST(1 - test::euler_characteristic(s) == 0);
  const double h = s.frame().voxel_size();
  const double union_volume = 4. + 9. - 1.;
  BOOST_TEST(double(s.size()) * h * h * h > union_volume);
}

BOOST_AUTO_TEST_CASE(holes_are_closed)
{
  // An open tube (no caps): its two border cycles are closed by fans.
  gs::Sparse_voxel_set tube;
  gs::voxelize(mesh_of(test::cylinder(1., 6., 32, 40, false)), tube, gs::parameters::resolution(48));
  const double h = tube.frame().voxel_size();
  BOOST_TEST(double(tube.size()) * h * h * h > test::pi * 6. * 0.95);

  // The demo elephant with 106 holes is nearly the closed elephant.
  Mesh elephant, holed;
  test::read_demo_mesh("elephant.off", elephant);
  test::read_demo_mesh("elephant-with-holes.off", holed);
  gs::Sparse_voxel_set a, b;
  gs::voxelize(elephant, a);
  gs::voxelize(holed, b);
  BOOST_TEST(double(b.size()) > 0.9 * double(a.size()));
  BOOST_TEST(double(b.size()) < 1.1 * double(a.size()));

  // Without hole filling, the flood enters the tube: nothing is enclosed.
  gs::Sparse_voxel_set open;
  BOOST_CHECK_THROW(gs::voxelize(mesh_of(test::cylinder(1., 6., 32, 40, false)), open,
                                 gs::parameters::fill_holes(false)),
                    std::invalid_argument);
}

// The rim of a sheet is not a hole. A cape made as one layer of faces (characters.h) has
// one border cycle, whose fan is about as large as the cape: closed, it made a second layer
// a few voxels off the cape and a lens of volume between them, which thinned to a fork at
// the hem. A hole is small beside the component it opens (the tube's ends, a few faces of
// the torso missing): it is closed. When every component is a sheet (the cape alone), every
// rim is closed, as before: the only way such a mesh encloses some volume.
BOOST_AUTO_TEST_CASE(the_rim_of_a_sheet_is_not_closed_unless_every_component_is_a_sheet)
{
  // The fan triangles voxelize() rasterised: the triangles beyond the faces' own.
  const auto fan_triangles = [](const Mesh& mesh) {
    gs::Sparse_voxel_set voxels;
    gs::Voxelized_surface surface;
    gs::voxelize(mesh, voxels, gs::parameters::voxelized_surface(&surface));
    std::size_t face_triangles = 0;
    for(auto f : faces(mesh))
      face_triangles += degree(f, mesh) - 2;
    return surface.number_of_triangles() - face_triangles;
  };
  BOOST_TEST(fan_triangles(mesh_of(test::caped_figure())) == 0u);
  BOOST_TEST(fan_triangles(mesh_of(test::cape())) == 2u * (20u + 44u)); // its rim, closed
  BOOST_TEST(fan_triangles(mesh_of(test::cylinder(1., 6., 32, 40, false))) == 2u * 32u);

  // Two faces of the torso missing: their hole is closed, the cape's rim is not.
  test::Soup holed = test::caped_figure();
  holed.faces.erase(holed.faces.begin() + 40, holed.faces.begin() + 42);
  const std::size_t fans = fan_triangles(mesh_of(holed));
  BOOST_TEST(fans >= 3u);
  BOOST_TEST(fans <= 6u);
}

BOOST_AUTO_TEST_CASE(a_closed_plate_under_two_voxels_thick_is_solid)
{
  // The plate (1.0 x 0.6, 0.03 thick) is 1.4 to 1.9 voxels thick at these resolutions: its
  // surface touches every voxel it covers, so no voxel is left untouched inside, yet the
  // centres of those voxels are inside it: a solid over the plate's whole outline (about
  // 0.53 of the bounding rectangle, at least 0.4 of it per layer), not the error of an open
  // sheet. It is three layers thick: the plate's mid-plane is the grid's centre plane,
  // which runs through voxel centres (an odd number of voxels per axis), and each face,
  // 0.7 to 0.95 voxels from it, crosses the layer beside the middle one.
  const Mesh plate = mesh_of(test::plate());
  for(int resolution : {48, 64})
  {
    gs::Dense_voxel_grid s;
    const std::size_t n = gs::voxelize(plate, s, gs::parameters::resolution(resolution));
    const double cells_of_outline = 0.94 * resolution * 0.6 * resolution; // rounded rectangle
    BOOST_TEST(double(n) >= 0.8 * cells_of_outline, "resolution " << resolution << ": " << n << " voxels");
    BOOST_TEST(double(n) <= 3.5 * cells_of_outline, "resolution " << resolution << ": " << n << " voxels");
    std::set<int> layers; // along the third principal axis, the plate's normal
    s.for_each([&](const gs::Voxel_key& k) { layers.insert(k.z); });
    BOOST_TEST(layers.size() == 3u, "resolution " << resolution);
  }
  // An open tube whose holes stay open still encloses nothing: the flood fills its hollow,
  // which the lines across it count inside.
  gs::Dense_voxel_grid open;
  BOOST_CHECK_THROW(gs::voxelize(mesh_of(test::cylinder(0.05, 1., 32, 40, false)), open,
                                 gs::parameters::combine(gs::parameters::resolution(48), gs::parameters::fill_holes(false))),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(a_non_convex_face_is_split_inside_its_outline)
{
  // An L and a U, listed from a corner that does not see the whole polygon (a fan from it
  // would cover the notch), in a tilted plane, both ways round: n - 2 triangles that turn
  // the polygon's way, lie inside it, and add up to its area.
  using Vec3 = gs::internal::Vec3;
  struct Polygon { std::vector<std::array<double, 2>> corners; double area; };
  const Polygon shapes[] = {{{{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}}, 3.0},
                            {{{2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {3, 0}, {3, 2}}, 5.0}};
  const Vec3 e1{0.6, 0.8, 0}, e2{-0.48, 0.36, 0.8}, offset{5, -2, 1};
  for(const Polygon& shape : shapes)
    for(const bool reversed : {false, true})
    {
      std::vector<std::array<double, 2>> plane = shape.corners;
      if(reversed)
        std::reverse(plane.begin(), plane.end());
      std::vector<Vec3> corners;
      for(const auto& c : plane)
        corners.push_back({offset[0] + c[0] * e1[0] + c[1] * e2[0], offset[1] + c[0] * e1[1] + c[1] * e2[1],
                           offset[2] + c[0] * e1[2] + c[1] * e2[2]});
      double twice_area = 0; // of the polygon, signed, in the (e1, e2) plane
      for(std::size_t i = 0; i < plane.size(); ++i)
        twice_area += gs::internal::signed_area_2({0, 0}, plane[i], plane[(i + 1) % plane.size()]);
      std::vector<gs::internal::Corner_triple> triangles;
      gs::internal::append_polygon_triangles(corners, triangles);
      BOOST_TEST_CONTEXT(plane.size() << " corners" << (reversed ? ", reversed" : ""))
      {
        BOOST_TEST(triangles.size() == plane.size() - 2);
        double sum = 0;
        for(const auto& t : triangles)
        {
          const double a = gs::internal::signed_area_2(plane[t[0]], plane[t[1]], plane[t[2]]);
          BOOST_TEST(a * twice_area > 0); // the polygon's way round
          sum += std::abs(a) / 2;
          // The centroid is inside the polygon (crossings of a ray along +x, odd).
          const double x = (plane[t[0]][0] + plane[t[1]][0] + plane[t[2]][0]) / 3;
          const double y = (plane[t[0]][1] + plane[t[1]][1] + plane[t[2]][1]) / 3;
          int crossings = 0;
          for(std::size_t i = 0; i < plane.size(); ++i)
          {
            const auto& p = plane[i];
            const auto& q = plane[(i + 1) % plane.size()];
            if((p[1] > y) != (q[1] > y) && x < p[0] + (y - p[1]) / (q[1] - p[1]) * (q[0] - p[0]))
              ++crossings;
          }
          BOOST_TEST(crossings % 2 == 1);
        }
        BOOST_TEST(sum == shape.area, boost::test_tools::tolerance(1e-9));
      }
    }
}

BOOST_AUTO_TEST_CASE(a_mesh_of_non_convex_polygons_gives_the_solid_of_its_triangulation)
{
  // mpi.off spells MPI with letter-shaped faces of up to ten corners; split into fans, its
  // front and back faces covered the notches of the letters, and about 30 % of the solid
  // lay outside them.
  const Mesh letters = test::demo_mesh<Mesh>("mpi.off");
  Mesh triangulated = letters;
  CGAL::Polygon_mesh_processing::triangulate_faces(triangulated);
  for(const int resolution : {32, 64})
  {
    gs::Sparse_voxel_set a, b;
    gs::voxelize(letters, a, gs::parameters::resolution(resolution));
    gs::voxelize(triangulated, b, gs::parameters::resolution(resolution));
    BOOST_TEST(test::keys_of(a) == test::keys_of(b), "resolution " << resolution);
  }
}

BOOST_AUTO_TEST_CASE(a_gap_of_a_fraction_of_a_voxel_between_components_is_closed)
{
  // Two half-boxes 0.3 voxel apart, with no border cycle to fill: a polygon soup of two
  // open boxes (each missing the face towards the other).
  test::Soup soup = test::box(0, 0, 0, 2, 1, 1);
  soup.faces.erase(soup.faces.begin() + 10, soup.faces.begin() + 12); // drop the x1 face
  test::Soup right = test::box(2, 0, 0, 4, 1, 1);
  right.faces.erase(right.faces.begin() + 8, right.faces.begin() + 10); // drop the x0 face
  test::append(soup, right, 0.3 * 4. / 32., 0, 0);
  gs::Sparse_voxel_set s;
  gs::voxelize(mesh_of(soup), s, gs::parameters::combine(gs::parameters::resolution(32),
                                                        gs::parameters::fill_holes(false)));
  const double h = s.frame().voxel_size();
  BOOST_TEST(double(s.size()) * h * h * h > 4. * 0.95);
}

// The straight voxel path between the voxels of a grid that hold two points: a skeleton
// by hand, on that grid.
gs::Sparse_voxel_set skeleton_between(const gs::Dense_voxel_grid& solid, const gs::Voxel_frame::Vector& a,
                                      const gs::Voxel_frame::Vector& b)
{
  gs::Sparse_voxel_set skeleton;
  skeleton.reset(solid.frame(), solid.bounding_box());
  for(const gs::Voxel_key& k :
      gs::internal::straight_voxel_path(solid.frame().voxel_of(a), solid.frame().voxel_of(b)))
    skeleton.insert(k);
  return skeleton;
}

BOOST_AUTO_TEST_CASE(two_boxes_a_coarser_skeleton_links_are_linked_on_a_finer_grid)
{
  // Two unit cubes side by side along x, 0.6 voxel apart at resolution 32: their surfaces
  // touch neighbouring voxels there, and the solid is one piece. At 128 the gap is 2.4
  // voxels, and the solid two pieces, until the coarser skeleton's link is added.
  const double gap = 0.6 * 2. / (32. - 0.6);
  test::Soup soup = test::box(0, 0, 0, 1, 1, 1);
  test::append(soup, test::box(0, 0, 0, 1, 1, 1), 1 + gap, 0, 0);
  const Mesh boxes = mesh_of(soup);
  gs::Dense_voxel_grid coarse, fine;
  gs::voxelize(boxes, coarse, gs::parameters::resolution(32));
  gs::voxelize(boxes, fine, gs::parameters::resolution(128));
  BOOST_REQUIRE(test::components_26(coarse) == 1);
  BOOST_REQUIRE(test::components_26(fine) == 2);
  const gs::Sparse_voxel_set link = skeleton_between(coarse, {0.5, 0.5, 0.5}, {1.5 + gap, 0.5, 0.5});
  BOOST_REQUIRE(test::components_26(link) == 1);
  const std::size_t before = fine.size();
  const std::size_t added = gs::add_skeleton_to_solid(link, fine);
  BOOST_TEST(added == fine.size() - before);
  BOOST_TEST(test::components_26(fine) == 1);
  BOOST_TEST(added <= 8u); // a link across the gap, a few voxels
  BOOST_TEST(gs::add_skeleton_to_solid(link, fine) == 0u); // nothing left to add

  // A skeleton of two pieces, one in each cube: the finer solid stays two pieces.
  gs::voxelize(boxes, fine, gs::parameters::resolution(128));
  gs::Sparse_voxel_set apart = skeleton_between(coarse, {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5});
  apart.insert(coarse.frame().voxel_of({1.5 + gap, 0.5, 0.5}));
  gs::add_skeleton_to_solid(apart, fine);
  BOOST_TEST(test::components_26(fine) == 2);
}

// A T of two bars, its skeleton pruned at 32 and routed at 96: the same three ends and one
// junction, one piece, every voxel inside the finer solid and standing for a voxel of the
// coarser skeleton; a branch across a gap that the finer solid has follows the coarser
// skeleton's voxels.
BOOST_AUTO_TEST_CASE(a_skeleton_routed_on_a_finer_grid_keeps_its_branches)
{
  test::Soup soup = test::box(0, 0, 0, 4, 0.6, 0.6);          // the bar of the T
  test::append(soup, test::box(1.7, -3, 0, 2.3, 0.3, 0.6));  // its stem
  const Mesh t = mesh_of(soup);
  gs::Dense_voxel_grid coarse;
  gs::voxelize(t, coarse, gs::parameters::resolution(32));
  const gs::Voxel_distance_field coarse_distances = gs::distance_transform(coarse);
  gs::thin(coarse, coarse_distances);
  gs::Sparse_voxel_set skeleton;
  skeleton.reset(coarse.frame(), coarse.bounding_box());
  coarse.for_each([&](const gs::Voxel_key& k) { skeleton.insert(k); });
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(gs::mat_radius_in_voxels_map(coarse_distances)));
  const gs::Skeleton_statistics before = gs::internal::skeleton_statistics_of_voxels(skeleton);
  BOOST_REQUIRE(before.end_points == 3u);

  gs::Dense_voxel_grid fine;
  gs::voxelize(t, fine, gs::parameters::resolution(96));
  gs::add_skeleton_to_solid(skeleton, fine);
  const gs::Voxel_distance_field fine_distances = gs::distance_transform(fine);
  gs::Sparse_voxel_set routed;
  routed.reset(fine.frame(), fine.bounding_box());
  gs::Coarser_voxel_map coarser_voxel;
  BOOST_TEST(gs::route_skeleton_on_finer_grid(skeleton, coarse_distances, fine_distances, routed, coarser_voxel) == 0u);
  const gs::Skeleton_statistics after = gs::internal::skeleton_statistics_of_voxels(routed);
  BOOST_TEST(after.end_points == before.end_points);
  BOOST_TEST(after.cycles == 0u);
  BOOST_TEST(after.components == 1u);
  BOOST_TEST(routed.size() > 2 * skeleton.size()); // three times as many voxels along each bar
  routed.for_each([&](const gs::Voxel_key& k) {
    BOOST_TEST(fine_distances.inside(k));
    BOOST_TEST((coarser_voxel.count(k) == 1 && skeleton.contains(coarser_voxel.at(k))));
  });

  // Two cubes that the grid of 32 joins and the grid of 128 separates, and a skeleton
  // across the gap: without its link in the finer solid, the branch follows the coarser
  // voxels, and the routed skeleton is one piece still.
  const double gap = 0.6 * 2. / (32. - 0.6);
  test::Soup cubes = test::box(0, 0, 0, 1, 1, 1);
  test::append(cubes, test::box(0, 0, 0, 1, 1, 1), 1 + gap, 0, 0);
  gs::Dense_voxel_grid joined, apart;
  gs::voxelize(mesh_of(cubes), joined, gs::parameters::resolution(32));
  gs::voxelize(mesh_of(cubes), apart, gs::parameters::resolution(128));
  const gs::Sparse_voxel_set link = skeleton_between(joined, {0.5, 0.5, 0.5}, {1.5 + gap, 0.5, 0.5});
  gs::Sparse_voxel_set across;
  across.reset(apart.frame(), apart.bounding_box());
  gs::Coarser_voxel_map across_coarser;
  BOOST_TEST(gs::route_skeleton_on_finer_grid(link, gs::distance_transform(joined), gs::distance_transform(apart),
                                              across, across_coarser) == 1u);
  BOOST_TEST(gs::internal::skeleton_statistics_of_voxels(across).components == 1u);
}

BOOST_AUTO_TEST_CASE(bad_input_is_a_clear_error)
{
  gs::Sparse_voxel_set s;
  Mesh empty;
  BOOST_TEST(throws_with<std::invalid_argument>([&] { gs::voxelize(empty, s); }, "no faces"));

  Mesh nan_mesh = mesh_of(test::box(0, 0, 0, 1, 1, 1));
  nan_mesh.point(*vertices(nan_mesh).begin()) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  BOOST_TEST(throws_with<std::invalid_argument>([&] { gs::voxelize(nan_mesh, s); }, "non-finite"));
  Mesh inf_mesh = mesh_of(test::box(0, 0, 0, 1, 1, 1));
  inf_mesh.point(*vertices(inf_mesh).begin()) = Point(0, std::numeric_limits<double>::infinity(), 0);
  BOOST_TEST(throws_with<std::invalid_argument>([&] { gs::voxelize(inf_mesh, s); }, "non-finite"));

  test::Soup sheet; // a flat open square
  sheet.add_point(0, 0, 0);
  sheet.add_point(1, 0, 0);
  sheet.add_point(1, 1, 0);
  sheet.add_point(0, 1, 0);
  sheet.add_quad(0, 1, 2, 3);
  BOOST_TEST(throws_with<std::invalid_argument>([&] { gs::voxelize(mesh_of(sheet), s); }, "encloses no volume"));
  // That one, and only that one, is a No_enclosed_volume: a finer grid or a closed mesh may
  // have volume where this one has none, bad input has none at any resolution.
  BOOST_TEST(throws_with<gs::No_enclosed_volume>([&] { gs::voxelize(mesh_of(sheet), s); }, "encloses no volume"));
  BOOST_CHECK_THROW(gs::voxelize(nan_mesh, s), std::invalid_argument);
  try
  {
    gs::voxelize(nan_mesh, s);
  }
  catch(const gs::No_enclosed_volume&)
  {
    BOOST_ERROR("a non-finite coordinate is bad input, not a mesh without volume");
  }
  catch(const std::invalid_argument&)
  {
  }

  const Mesh cube = mesh_of(test::box(0, 0, 0, 1, 1, 1));
  BOOST_TEST(throws_with<std::invalid_argument>([&] { gs::voxelize(cube, s, gs::parameters::resolution(3)); }, "resolution must be an integer in [4, 8192], got 3"));
  BOOST_TEST(throws_with<std::invalid_argument>([&] { gs::voxelize(cube, s, gs::parameters::resolution(100000)); }, "resolution must be an integer in [4, 8192], got 100000"));
  BOOST_TEST(throws_with<std::length_error>(
      [&] { gs::voxelize(cube, s, gs::parameters::combine(gs::parameters::resolution(1000), gs::parameters::memory_limit(1e9))); },
      "needs about"));
  BOOST_TEST(s.size() == 0u); // nothing was filled by the failed calls
}

BOOST_AUTO_TEST_SUITE_END()
