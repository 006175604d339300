// Bad and awkward input: every mesh of the corpus (built here, or the tiny files of
// test/data/bad_meshes/ read as skeletonize reads them) gives either a valid skeleton
// (finite, every joint inside the solid) or a clear exception that names the problem, and
// every out-of-range parameter is refused before any voxel work, naming itself and its
// range. doc/manual.md ("Input the package accepts and rejects") lists what each case gives.
#include <CGAL/Geodesic_skeleton/IO/read_mesh.h>
#include <CGAL/Geodesic_skeleton/chord_to_point_distance_accumulation.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
#include <CGAL/Geodesic_skeleton/integral_geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>

#include <Geodesic_skeleton_test/joints.h>
#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(robustness)

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
namespace test = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Control = gs::Control_skeleton<Point>;
using Curve = gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor>;

namespace {

using Box = std::array<double, 6>; // x0, y0, z0, x1, y1, z1

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// Inside one of the boxes, or within `tolerance` of it.
std::function<bool(const Point&)> inside_boxes(std::vector<Box> boxes, double tolerance)
{
  return [boxes, tolerance](const Point& p) {
    for(const Box& b : boxes)
      if(p.x() >= b[0] - tolerance && p.x() <= b[3] + tolerance && p.y() >= b[1] - tolerance &&
         p.y() <= b[4] + tolerance && p.z() >= b[2] - tolerance && p.z() <= b[5] + tolerance)
        return true;
    return false;
  };
}

test::Soup box_soup(const Box& b) { return test::box(b[0], b[1], b[2], b[3], b[4], b[5]); }

// The mesh of a soup that may be non-manifold or badly oriented, made as skeletonize makes
// it (orient_polygon_soup splits non-manifold edges and vertices).
Mesh repaired_mesh_of(const test::Soup& soup)
{
  std::vector<Point> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> faces = soup.faces;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, faces);
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return mesh;
}

struct Result
{
  Control control;
  Curve curve;
  gs::Control_skeleton_report report;
};

Result skeleton_of(const Mesh& mesh, int resolution = 32)
{
  Result r;
  r.report = gs::extract_control_skeleton(
      mesh, r.control, params::combine(params::resolution(resolution), params::curve_skeleton_output(&r.curve)));
  return r;
}

// A valid skeleton: at least one joint, a tree per component, every coordinate and radius
// finite, and every joint (and every point of every bone) inside the solid.
void check_valid(const Result& r, const std::function<bool(const Point&)>& inside)
{
  BOOST_TEST_REQUIRE(num_vertices(r.control) > 0u);
  BOOST_TEST(num_edges(r.control) + r.control[boost::graph_bundle].roots.size() == num_vertices(r.control));
  for(const auto& j : test::joints(r.control))
  {
    BOOST_TEST(finite(j.point));
    BOOST_TEST(std::isfinite(j.radius));
    BOOST_TEST(inside(j.point), "joint (" << j.point << ") is outside the solid");
  }
  for(const auto b : boost::make_iterator_range(edges(r.control)))
    for(const Point& p : r.control[b].points)
      BOOST_TEST(finite(p));
  BOOST_TEST(num_vertices(r.curve) > 0u);
  for(std::size_t v = 0; v < num_vertices(r.curve); ++v)
  {
    BOOST_TEST(finite(r.curve[v].point));
    BOOST_TEST((std::isfinite(r.curve[v].radius) && r.curve[v].radius >= 0));
  }
}

// Inside a closed triangle mesh (CGAL's test), or within `tolerance` of its surface.
std::function<bool(const Point&)> inside_closed_mesh(const Mesh& mesh)
{
  auto side = std::make_shared<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(mesh);
  return [side](const Point& p) { return (*side)(p) != CGAL::ON_UNBOUNDED_SIDE; };
}

// Whether f() throws E whose message contains every one of `words`.
template <typename E, typename F>
bool throws_naming(F f, std::vector<std::string> words)
{
  try
  {
    f();
  }
  catch(const E& e)
  {
    const std::string what = e.what();
    for(const std::string& w : words)
      if(what.find(w) == std::string::npos)
      {
        BOOST_TEST_MESSAGE("message '" << what << "' lacks '" << w << "'");
        return false;
      }
    BOOST_TEST_MESSAGE("clear error: " << what);
    return true;
  }
  return false;
}

std::string bad_mesh(const std::string& name) { return std::string(GEODESIC_SKELETON_BAD_MESH_DIR) + "/" + name; }

const Box bar{0, 0, 0, 1, 1, 4};

} // namespace

// ---- Section 1: bad meshes give clear errors ------------------------------------------

BOOST_AUTO_TEST_CASE(an_empty_mesh_or_one_without_faces_is_refused)
{
  Control c;
  BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::extract_control_skeleton(Mesh(), c); },
                                                  {"voxelize", "no faces"}));
  Mesh points_only;
  points_only.add_vertex(Point(0, 0, 0));
  points_only.add_vertex(Point(1, 0, 0));
  BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::extract_control_skeleton(points_only, c); },
                                                  {"no faces"}));
}

BOOST_AUTO_TEST_CASE(nan_and_infinite_coordinates_are_refused)
{
  for(double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL})
  {
    Mesh mesh = test::mesh_of<Mesh>(box_soup(bar));
    mesh.point(*std::next(mesh.vertices().begin(), 3)) = Point(0.5, bad, 1);
    Control c;
    BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::extract_control_skeleton(mesh, c); },
                                                    {"non-finite coordinate"}));
  }
}

BOOST_AUTO_TEST_CASE(a_mesh_of_equal_points_has_zero_area)
{
  test::Soup s = box_soup(bar);
  for(auto& p : s.points)
    p = {2, 2, 2};
  Control c;
  BOOST_TEST(throws_naming<std::invalid_argument>(
      [&] { gs::extract_control_skeleton(test::mesh_of<Mesh>(s), c); }, {"zero area"}));
}

BOOST_AUTO_TEST_CASE(a_single_triangle_and_a_flat_sheet_enclose_no_volume)
{
  test::Soup triangle;
  triangle.add_triangle(triangle.add_point(0, 0, 0), triangle.add_point(1, 0, 0), triangle.add_point(0, 1, 0));
  test::Soup sheet;
  const int n = 8;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      sheet.add_point(i, j, 0);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      sheet.add_quad(j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i);
  for(const test::Soup* s : {&triangle, &sheet})
  {
    Control c;
    BOOST_TEST(throws_naming<std::invalid_argument>(
        [&] { gs::extract_control_skeleton(test::mesh_of<Mesh>(*s), c, params::resolution(32)); },
        {"encloses no volume", "resolution 32"}));
  }
}

BOOST_AUTO_TEST_CASE(an_open_tube_without_filling_its_holes_encloses_no_volume)
{
  const Mesh tube = test::mesh_of<Mesh>(test::cylinder(1, 4, 16, 8, false));
  Control c;
  BOOST_TEST(throws_naming<std::invalid_argument>(
      [&] { gs::extract_control_skeleton(tube, c, params::combine(params::resolution(32), params::fill_holes(false))); },
      {"encloses no volume"}));
}

// ---- Section 1: awkward meshes as artists make them give valid skeletons --------------

BOOST_AUTO_TEST_CASE(a_mesh_with_holes_is_closed_and_skeletonized)
{
  const Mesh tube = test::mesh_of<Mesh>(test::cylinder(1, 4, 16, 8, false));
  const Result r = skeleton_of(tube);
  // The solid is the tube closed by its fans: the cylinder of radius 1, z in [0, 4].
  check_valid(r, [](const Point& p) { return std::hypot(p.x(), p.y()) <= 1 && p.z() >= 0 && p.z() <= 4; });
}

BOOST_AUTO_TEST_CASE(polygons_of_five_and_more_sides_are_split_into_fans)
{
  // Prisms of 5, 6 and 9 sides: two n-gon caps and n quads, radius 1, height 4.
  for(int n : {5, 6, 9})
  {
    test::Soup s;
    for(int k = 0; k < 2; ++k)
      for(int i = 0; i < n; ++i)
        s.add_point(std::cos(2 * test::pi * i / n), std::sin(2 * test::pi * i / n), 4. * k);
    std::vector<std::size_t> bottom, top;
    for(int i = 0; i < n; ++i)
    {
      bottom.push_back(std::size_t(n - 1 - i));
      top.push_back(std::size_t(n + i));
      s.faces.push_back({std::size_t(i), std::size_t((i + 1) % n), std::size_t(n + (i + 1) % n), std::size_t(n + i)});
    }
    s.faces.push_back(bottom);
    s.faces.push_back(top);
    const Mesh prism = test::mesh_of<Mesh>(s);
    BOOST_TEST_REQUIRE(CGAL::is_closed(prism));
    const Result r = skeleton_of(prism);
    const double apothem = std::cos(test::pi / n);
    check_valid(r, [&](const Point& p) { return std::hypot(p.x(), p.y()) <= apothem && p.z() >= 0 && p.z() <= 4; });
  }
}

BOOST_AUTO_TEST_CASE(non_manifold_edges_and_vertices_are_split_and_skeletonized)
{
  // Two bars sharing an edge, and two bars sharing a corner (one vertex list, so the edge
  // and the vertex are really shared).
  for(const Box& second : {Box{1, 1, 0, 2, 2, 4}, Box{1, 1, 4, 2, 2, 8}})
  {
    test::Soup s = box_soup(bar);
    test::append(s, box_soup(second));
    // Merge equal points into one vertex.
    std::vector<std::size_t> index(s.points.size());
    test::Soup merged;
    for(std::size_t i = 0; i < s.points.size(); ++i)
    {
      index[i] = merged.points.size();
      for(std::size_t j = 0; j < merged.points.size(); ++j)
        if(merged.points[j] == s.points[i])
          index[i] = j;
      if(index[i] == merged.points.size())
        merged.points.push_back(s.points[i]);
    }
    for(auto f : s.faces)
    {
      for(auto& i : f)
        i = index[i];
      merged.faces.push_back(f);
    }
    BOOST_TEST_REQUIRE(merged.points.size() < s.points.size()); // something is shared
    const Mesh mesh = repaired_mesh_of(merged);
    const Result r = skeleton_of(mesh);
    check_valid(r, inside_boxes({bar, second}, 0));
    check_valid(r, inside_closed_mesh(mesh));
  }
}

BOOST_AUTO_TEST_CASE(zero_area_faces_are_harmless)
{
  // A closed bar whose bottom edge (0, 2) is split at m by a zero-area triangle (2, m, 0).
  test::Soup s = box_soup(bar);
  const std::size_t m = s.add_point(0, 0.5, 0);
  s.faces[0] = {0, m, 3};
  s.faces.push_back({m, 2, 3});
  s.faces.push_back({2, m, 0});
  const Mesh mesh = test::mesh_of<Mesh>(s);
  BOOST_TEST_REQUIRE(CGAL::is_closed(mesh));
  const Result r = skeleton_of(mesh);
  check_valid(r, inside_boxes({bar}, 0));
  // The same rig as the bar without the zero-area face: a straight bar is one bone in the
  // paper's split, cut into bones of about equal length when it is long: about a tenth of
  // the mesh's extent each (the default joint spacing), and its chain is shorter than that.
  const Result plain = skeleton_of(test::mesh_of<Mesh>(box_soup(bar)));
  BOOST_TEST(num_edges(r.control) == num_edges(plain.control));
  BOOST_TEST(num_edges(r.control) >= 2u);
  BOOST_TEST(num_edges(r.control) <= 10u);
}

BOOST_AUTO_TEST_CASE(overlapping_boxes_give_the_skeleton_of_their_union)
{
  // A self-intersecting union: a cross bar passes through the bar. A ray parity test sees
  // their common part as outside; the joints must still be inside the union.
  const Box cross{-1, 0.25, 1.5, 2, 0.75, 2.5};
  test::Soup s = box_soup(bar);
  test::append(s, box_soup(cross));
  const Result r = skeleton_of(test::mesh_of<Mesh>(s), 48);
  check_valid(r, inside_boxes({bar, cross}, 0));
  // A cross: a junction joint, and the four arms reached.
  BOOST_TEST(num_vertices(r.control) >= 5u);
}

BOOST_AUTO_TEST_CASE(hundreds_of_small_parts_each_get_a_skeleton)
{
  std::vector<Box> boxes;
  test::Soup s;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j)
      for(int k = 0; k < 6; ++k)
      {
        boxes.push_back(Box{2. * i, 2. * j, 3. * k, 2. * i + 0.6, 2. * j + 0.6, 3. * k + 1.8});
        test::append(s, box_soup(boxes.back()));
      }
  const Mesh mesh = test::mesh_of<Mesh>(s);
  const Result r = skeleton_of(mesh, 64);
  check_valid(r, inside_closed_mesh(mesh));
  BOOST_TEST(r.control[boost::graph_bundle].roots.size() == boxes.size()); // one tree per part, none lost
}

BOOST_AUTO_TEST_CASE(huge_and_tiny_coordinates_scale_the_skeleton)
{
  // An L of two overlapping bars (distinct principal axes, non-zero third moments, so the
  // grid's orientation is fixed) at scale 1, 1e30, 1e-30, 1e100 and 1e-100: the same
  // joints in the same order, scaled, to rounding. The scaled coordinates round
  // differently, but the grid coordinates are rounded far above that (Voxel_frame::to_grid())
  // and the split treats radii equal to rounding as equal: without the latter, the cuts of
  // the long bar, whose smoothed radii differ only in their last bits, moved by a voxel at
  // 1e30.
  const std::vector<Box> l_shape{Box{0.013, 0.021, 0.007, 1.029, 1.517, 4.053},
                                 Box{0.51, 0.021, 0.007, 2.531, 1.517, 1.019}};
  auto mesh_at = [&](double scale) {
    test::Soup s;
    for(const Box& b : l_shape)
      test::append(s, box_soup(Box{b[0] * scale, b[1] * scale, b[2] * scale, b[3] * scale, b[4] * scale, b[5] * scale}));
    return test::mesh_of<Mesh>(s);
  };
  const Result unit = skeleton_of(mesh_at(1));
  check_valid(unit, inside_boxes(l_shape, 0));
  BOOST_TEST(num_vertices(unit.control) >= 3u);
  for(double scale : {1e30, 1e-30, 1e100, 1e-100})
  {
    BOOST_TEST_MESSAGE("scale " << scale);
    const Result r = skeleton_of(mesh_at(scale));
    std::vector<Box> scaled;
    for(const Box& b : l_shape)
      scaled.push_back(Box{b[0] * scale, b[1] * scale, b[2] * scale, b[3] * scale, b[4] * scale, b[5] * scale});
    check_valid(r, inside_boxes(scaled, 0));
    BOOST_TEST(r.report.voxel_size / scale == unit.report.voxel_size, boost::test_tools::tolerance(1e-9));
    BOOST_TEST_REQUIRE(num_vertices(r.control) == num_vertices(unit.control));
    for(std::size_t i = 0; i < num_vertices(r.control); ++i)
    {
      const Point& p = r.control[i].point;
      const Point scaled_back(p.x() / scale, p.y() / scale, p.z() / scale);
      BOOST_TEST(std::sqrt(CGAL::squared_distance(scaled_back, unit.control[i].point)) <= 1e-9 * unit.report.voxel_size,
                 "joint " << i << " at (" << scaled_back << "), at scale 1 (" << unit.control[i].point << ")");
    }
  }
}

BOOST_AUTO_TEST_CASE(coordinates_beyond_the_arithmetic_are_refused)
{
  // Past 1e150 the squares of lengths overflow a double, under 1e-150 they vanish: a clear
  // error, not a NaN skeleton (a mesh 1e308 across even overflows its own extent).
  for(const Box& b : {Box{0, 0, 0, 1e200, 1e200, 4e200}, Box{-1e308, 0, 0, 1e308, 1, 1},
                      Box{0, 0, 0, 1e-200, 1e-200, 4e-200}, Box{1e151, 0, 0, 1e151 + 1e136, 1e136, 1e136}})
  {
    Control c;
    BOOST_TEST(throws_naming<std::invalid_argument>(
        [&] { gs::extract_control_skeleton(test::mesh_of<Mesh>(box_soup(b)), c); },
        {"voxelize", "the package needs coordinates up to 1e+150 and a mesh at least 1e-150 across"}));
  }
}

// ---- Section 1: files, read as skeletonize reads them ----------------------------------

BOOST_AUTO_TEST_CASE(unusable_files_are_refused_by_the_reader)
{
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"no_such_file.off", "cannot open"},
      {"empty.off", "cannot be parsed"},
      {"garbage.off", "cannot be parsed"},
      {"wrong_counts.off", "cannot be parsed"},
      {"missing_vertex.off", "cannot be parsed"},
      {"missing_vertex.obj", "cannot be parsed"},
      {"missing_vertex_binary.ply", "refers to vertex 9, but the file has only 4 vertices"},
      {"nan.off", "cannot be parsed"},
      {"nan.obj", "cannot be parsed"},
      {"infinite.off", "cannot be parsed"},
      {"nan_binary.stl", "non-finite coordinate"},
      {"no_faces.off", "no faces"}};
  for(const auto& [file, problem] : cases)
  {
    Mesh mesh;
    BOOST_TEST(throws_naming<std::runtime_error>([&] { gs::IO::read_mesh(bad_mesh(file), mesh); }, {file, problem}),
               file);
  }
}

BOOST_AUTO_TEST_CASE(readable_bad_files_give_a_skeleton_or_a_clear_error)
{
  const std::vector<std::pair<std::string, std::string>> errors = {
      {"all_points_equal.off", "zero area"},
      {"single_triangle.off", "encloses no volume"},
      {"flat_sheet.off", "encloses no volume"}};
  for(const auto& [file, problem] : errors)
  {
    Mesh mesh;
    gs::IO::read_mesh(bad_mesh(file), mesh);
    Control c;
    BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::extract_control_skeleton(mesh, c); }, {problem}), file);
  }
  const std::vector<std::pair<std::string, std::vector<Box>>> skeletons = {
      {"duplicated_faces.off", {bar}},
      {"zero_area_face.off", {bar}},
      {"nonmanifold_edge.off", {bar, Box{1, 1, 0, 2, 2, 4}}},
      {"nonmanifold_vertex.off", {bar, Box{1, 1, 4, 2, 2, 8}}},
      {"overlapping_boxes.off", {bar, Box{0.5, 0.5, 2, 3.5, 1.5, 3}}},
      {"polygons.off", {Box{-1, -1, 0, 1, 1, 4}, Box{-1, -1, 6, 1, 1, 10}}},
      {"open_tube.off", {Box{-1, -1, 0, 1, 1, 4}}}};
  for(const auto& [file, boxes] : skeletons)
  {
    BOOST_TEST_MESSAGE(file);
    Mesh mesh;
    gs::IO::read_mesh(bad_mesh(file), mesh);
    check_valid(skeleton_of(mesh), inside_boxes(boxes, 0));
  }
  for(const auto& [file, scale] : {std::pair<std::string, double>{"huge_coordinates.off", 1e30},
                                   std::pair<std::string, double>{"tiny_coordinates.off", 1e-30}})
  {
    Mesh mesh;
    gs::IO::read_mesh(bad_mesh(file), mesh);
    check_valid(skeleton_of(mesh), inside_boxes({Box{0, 0, 0, scale, scale, 4 * scale}}, 0));
  }
}

// ---- Section 2: parameters -------------------------------------------------------------

namespace {

struct Stage_counter
{
  int* stages;
  void stage_finished(const std::string&, double) { ++*stages; }
};

// extract_control_skeleton(np) on a bar throws std::invalid_argument naming `name` and
// `range`, before any stage ran.
template <typename NamedParameters>
bool refused_up_front(const NamedParameters& np, const std::string& name, const std::string& range)
{
  const Mesh mesh = test::mesh_of<Mesh>(box_soup(bar));
  int stages = 0;
  Control c;
  const bool refused = throws_naming<std::invalid_argument>(
      [&] { gs::extract_control_skeleton(mesh, c, params::combine(params::visitor(Stage_counter{&stages}), np)); },
      {"extract_control_skeleton", name + " must be", range});
  BOOST_TEST(stages == 0);
  return refused;
}

} // namespace

BOOST_AUTO_TEST_CASE(out_of_range_parameters_are_refused_before_any_work)
{
  const double nan = std::nan("");
  BOOST_TEST(refused_up_front(params::resolution(0), "resolution", "[4, 8192], got 0"));
  BOOST_TEST(refused_up_front(params::resolution(1), "resolution", "[4, 8192], got 1"));
  BOOST_TEST(refused_up_front(params::resolution(1000000), "resolution", "[4, 8192], got 1000000"));
  BOOST_TEST(refused_up_front(params::resolution(-64), "resolution", "[4, 8192], got -64"));
  BOOST_TEST(refused_up_front(params::smoothing_window(0), "smoothing_window", "odd number in [1, 1001], got 0"));
  BOOST_TEST(refused_up_front(params::smoothing_window(4), "smoothing_window", "odd number in [1, 1001], got 4"));
  BOOST_TEST(refused_up_front(params::smoothing_window(-3), "smoothing_window", "odd number in [1, 1001]"));
  BOOST_TEST(refused_up_front(params::spur_length_factor(-1.), "spur_length_factor", "[0, 100], got -1"));
  BOOST_TEST(refused_up_front(params::bend_threshold(-0.1), "bend_threshold", "[0, 1], got -0.1"));
  BOOST_TEST(refused_up_front(params::bend_threshold(nan), "bend_threshold", "[0, 1], got nan"));
  BOOST_TEST(refused_up_front(params::straightness_tolerance(-1.), "straightness_tolerance", "[0, 100]"));
  BOOST_TEST(refused_up_front(params::minimum_bone_length_factor(-1.), "minimum_bone_length_factor", "[0, 1000]"));
  BOOST_TEST(refused_up_front(params::smallest_radius(-1.), "smallest_radius", "[0, inf], got -1"));
  BOOST_TEST(refused_up_front(params::smallest_radius(nan), "smallest_radius", "[0, inf], got nan"));
  BOOST_TEST(refused_up_front(params::sheet_lobe_reach_factor(-1.), "sheet_lobe_reach_factor", "[0, 100], got -1"));
  BOOST_TEST(refused_up_front(params::sheet_lobe_reach_factor(nan), "sheet_lobe_reach_factor", "[0, 100], got nan"));
  BOOST_TEST(refused_up_front(params::thin_part_radius(-1.), "thin_part_radius", "[0, 1000], got -1"));
  BOOST_TEST(refused_up_front(params::thin_part_radius(nan), "thin_part_radius", "[0, 1000], got nan"));
  BOOST_TEST(refused_up_front(params::minimum_bone_length_of_piece_factor(-1.), "minimum_bone_length_of_piece_factor",
                              "[0, 1000], got -1"));
  BOOST_TEST(refused_up_front(params::minimum_bone_length_of_piece_factor(nan), "minimum_bone_length_of_piece_factor",
                              "[0, 1000], got nan"));
  BOOST_TEST(refused_up_front(params::chord_length_factors(std::vector<double>{3., 0.}), "chord_length_factors",
                              "[0.001, 1000], got 0"));
  BOOST_TEST(refused_up_front(params::number_of_reeb_intervals(std::size_t(0)), "number_of_reeb_intervals",
                              "[1, 1000000], got 0"));
  BOOST_TEST(refused_up_front(params::memory_limit(nan), "memory_limit", "[1, inf], got nan"));
  BOOST_TEST(refused_up_front(params::memory_limit(-5.), "memory_limit", "[1, inf], got -5"));
}

BOOST_AUTO_TEST_CASE(the_stages_check_their_own_parameters)
{
  const Mesh mesh = test::mesh_of<Mesh>(box_soup(bar));
  gs::Dense_voxel_grid grid;
  BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::voxelize(mesh, grid, params::resolution(2)); },
                                                  {"voxelize: resolution must be an integer in [4, 8192], got 2"}));
  BOOST_TEST(throws_naming<std::invalid_argument>(
      [&] { gs::voxelize(mesh, grid, params::memory_limit(std::nan(""))); }, {"voxelize: memory_limit must be"}));
  gs::Sparse_voxel_set skeleton;
  BOOST_TEST(throws_naming<std::invalid_argument>(
      [&] { gs::prune_skeleton(skeleton, params::spur_length_factor(101.)); },
      {"prune_skeleton: spur_length_factor must be in [0, 100], got 101"}));
  Curve curve;
  BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::smooth_skeleton(curve, params::smoothing_window(0)); },
                                                  {"smooth_skeleton: smoothing_window must be an odd number"}));
  Control c;
  BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::split_into_bones(curve, c, params::bend_threshold(2.)); },
                                                  {"split_into_bones: bend_threshold must be in [0, 1], got 2"}));
  std::vector<double> field(num_vertices(mesh), 0.);
  auto field_map = boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, mesh));
  gs::Reeb_graph<Mesh> reeb;
  BOOST_TEST(throws_naming<std::invalid_argument>([&] { gs::reeb_graph(mesh, field_map, 0, reeb); },
                                                  {"reeb_graph: number_of_intervals must be an integer in [1, 1000000]"}));
  BOOST_TEST(throws_naming<std::invalid_argument>(
      [&] { gs::integral_geodesic_mapping_function(mesh, field_map, params::number_of_base_vertices(std::size_t(0))); },
      {"number_of_base_vertices must be an integer in [1, 100000], got 0"}));
  std::vector<Point> line{Point(0, 0, 0), Point(1, 0, 0)};
  std::vector<double> out;
  BOOST_TEST(throws_naming<std::invalid_argument>(
      [&] { gs::chord_to_point_distance_accumulation(line, 1., std::back_inserter(out), params::number_of_chords(0)); },
      {"number_of_chords must be an integer in [1, 1000], got 0"}));
}

BOOST_AUTO_TEST_CASE(the_ends_of_the_ranges)
{
  const Mesh mesh = test::mesh_of<Mesh>(box_soup(bar));
  // The lowest resolution: a bar one voxel thick, whose surface touches all its voxels but
  // encloses their centres, gives a skeleton inside it (a line of up to four points); a
  // ball four voxels across gives one inside it too.
  Control c;
  gs::extract_control_skeleton(mesh, c, params::resolution(4));
  BOOST_TEST(!(num_vertices(c) == 0));
  BOOST_TEST(num_vertices(c) <= 4u);
  for(const auto& j : test::joints(c))
    BOOST_TEST(inside_boxes({bar}, 1e-9)(j.point));
  const Mesh ball = test::mesh_of<Mesh>(test::icosphere(1, 2));
  gs::extract_control_skeleton(ball, c, params::resolution(4));
  BOOST_TEST(!(num_vertices(c) == 0));
  for(const auto& j : test::joints(c))
    BOOST_TEST(inside_closed_mesh(ball)(j.point));
  // The highest needs a grid far beyond the default memory limit: a clear length_error
  // naming the need, before allocating.
  BOOST_TEST(throws_naming<std::length_error>([&] { gs::extract_control_skeleton(mesh, c, params::resolution(8192)); },
                                              {"voxelize", "lower the resolution"}));
}

BOOST_AUTO_TEST_SUITE_END()
