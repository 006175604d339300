// Specification of smooth_skeleton.h, chord_to_point_distance_accumulation.h and
// split_into_bones.h, on hand-made curve skeletons (polylines with a MAT radius), and of
// their point and radius maps on CGAL's mean curvature flow skeleton and on the package's
// curve skeleton of a demo mesh.
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/chord_to_point_distance_accumulation.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/smooth_skeleton.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>

#include <Geodesic_skeleton_test/joints.h>
#include <Geodesic_skeleton_test/shapes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>
#include <CGAL/property_map.h>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(control_skeleton)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Skeleton = gs::Curve_skeleton<Point, int>;
using Control = gs::Control_skeleton<Point>;
using Mesh = CGAL::Surface_mesh<Point>;
using Mcf_skeleton = CGAL::Mean_curvature_flow_skeletonization<Mesh>::Skeleton;
using Mesh_skeleton = gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor>;

namespace {

constexpr double pi = 3.14159265358979323846;

// Points from `from` to `to` spaced by about `step`, `from` included, `to` excluded.
void add_segment(std::vector<Point>& points, const Point& from, const Point& to, double step)
{
  const int count = std::max(1, static_cast<int>(std::round(std::sqrt(CGAL::squared_distance(from, to)) / step)));
  for(int i = 0; i < count; ++i)
    points.push_back(from + (to - from) * (double(i) / count));
}

std::vector<Point> polyline(const std::vector<Point>& corners, double step)
{
  std::vector<Point> points;
  for(std::size_t i = 0; i + 1 < corners.size(); ++i)
    add_segment(points, corners[i], corners[i + 1], step);
  points.push_back(corners.back());
  return points;
}

// Appends a chain of skeleton vertices along `points`; returns their indices.
std::vector<std::size_t> add_chain(Skeleton& s, const std::vector<Point>& points, double radius,
                                   long attach_to = -1)
{
  std::vector<std::size_t> ids;
  for(const Point& p : points)
  {
    const std::size_t v = add_vertex(s);
    s[v].point = p;
    s[v].radius = radius;
    if(!ids.empty())
      add_edge(ids.back(), v, s);
    else if(attach_to >= 0)
      add_edge(static_cast<std::size_t>(attach_to), v, s);
    ids.push_back(v);
  }
  return ids;
}

Skeleton chain_skeleton(const std::vector<Point>& points, double radius)
{
  Skeleton s;
  add_chain(s, points, radius);
  return s;
}

template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
Control bones_of(const Skeleton& s, const NamedParameters& np = CGAL::parameters::default_values())
{
  Control control;
  gs::split_into_bones(s, control, np);
  return control;
}

// The length of the shortest bone of `c`, along the skeleton (infinite without bones).
double shortest_bone(const Control& c)
{
  double shortest = HUGE_VAL;
  for(const auto bone : boost::make_iterator_range(edges(c)))
    shortest = (std::min)(shortest, c[bone].length);
  return shortest;
}

// The paper's split alone, without the package's cut of long straight bones and without
// its floor on bone lengths in the piece's largest radius.
const auto paper_split = gs::parameters::combine(gs::parameters::maximum_bone_length_factor(0.0),
                                                 gs::parameters::minimum_bone_length_of_piece_factor(0.0));

std::vector<double> accumulation(const std::vector<Point>& points, double L)
{
  std::vector<double> h;
  gs::chord_to_point_distance_accumulation(points, L, std::back_inserter(h));
  return h;
}

double distance(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

// Every joint but the roots has a parent listed before it, and bones link parent to child.
void check_tree(const Control& c)
{
  std::size_t roots = 0;
  for(std::size_t j = 0; j < num_vertices(c); ++j)
  {
    const std::size_t parent = gs::parent_joint(j, c);
    if(parent == boost::graph_traits<Control>::null_vertex())
    {
      ++roots;
      BOOST_TEST((c[j].kind == gs::Joint_kind::root));
    }
    else
      BOOST_TEST(parent < j);
  }
  BOOST_TEST(roots == c[boost::graph_bundle].roots.size());
  BOOST_TEST(num_edges(c) + roots == num_vertices(c));
  for(const auto bone : boost::make_iterator_range(edges(c)))
  {
    BOOST_TEST(in_degree(target(bone, c), c) == 1u);
    BOOST_TEST(distance(c[bone].points.front(), c[source(bone, c)].point) < 1e-9);
    BOOST_TEST(distance(c[bone].points.back(), c[target(bone, c)].point) < 1e-9);
  }
}

// Whether two control skeletons are the same, to the last bit.
bool identical(const Control& a, const Control& b)
{
  auto same_bone = [](const gs::Control_bone<Point>& p, const gs::Control_bone<Point>& q) {
    return p.points == q.points && p.length == q.length;
  };
  const auto a_joints = vertices(a), b_joints = vertices(b);
  const auto a_bones = edges(a), b_bones = edges(b);
  const auto& a_forest = a[boost::graph_bundle];
  const auto& b_forest = b[boost::graph_bundle];
  return std::equal(a_joints.first, a_joints.second, b_joints.first, b_joints.second,
                    [&](std::size_t p, std::size_t q) {
                      return p == q && a[p].point == b[q].point && a[p].radius == b[q].radius &&
                             a[p].kind == b[q].kind && a[p].skeleton_vertex == b[q].skeleton_vertex;
                    }) &&
         std::equal(a_bones.first, a_bones.second, b_bones.first, b_bones.second,
                    [&](const auto& p, const auto& q) {
                      return source(p, a) == source(q, b) && target(p, a) == target(q, b) && same_bone(a[p], b[q]);
                    }) &&
         std::equal(a_forest.cut_bones.begin(), a_forest.cut_bones.end(), b_forest.cut_bones.begin(),
                    b_forest.cut_bones.end(),
                    [&](const auto& p, const auto& q) {
                      return p.source == q.source && p.target == q.target && same_bone(p, q);
                    }) &&
         a_forest.roots == b_forest.roots;
}

// CGAL's mean curvature flow skeleton of cow.off, computed once (1-3 s).
struct Mcf_of_cow
{
  Mesh mesh = test::demo_mesh<Mesh>("cow.off");
  Mcf_skeleton skeleton;
  Mcf_of_cow() { CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton); }
};

const Mcf_of_cow& mcf_of_cow()
{
  static const Mcf_of_cow mcf;
  return mcf;
}

// A MAT radius for an MCF skeleton, which has none: the mean distance from each skeleton
// point to the mesh points collapsed into it; a skeleton vertex without mesh vertices (a
// few on the cow) takes the mean radius of its neighbours that have one.
std::vector<double> mean_distance_to_collapsed_vertices(const Mcf_of_cow& mcf)
{
  const Mcf_skeleton& s = mcf.skeleton;
  std::vector<double> radii(num_vertices(s), 0.0);
  std::vector<bool> known(radii.size(), false);
  for(std::size_t v = 0; v < radii.size(); ++v)
  {
    for(const auto& w : s[v].vertices)
      radii[v] += distance(s[v].point, mcf.mesh.point(w)) / double(s[v].vertices.size());
    known[v] = !s[v].vertices.empty();
  }
  for(bool changed = true; changed;)
  {
    changed = false;
    for(std::size_t v = 0; v < radii.size(); ++v)
    {
      if(known[v])
        continue;
      double sum = 0;
      int count = 0;
      for(auto w : boost::make_iterator_range(boost::adjacent_vertices(v, s)))
        if(known[w])
        {
          sum += radii[w];
          ++count;
        }
      if(count > 0)
      {
        radii[v] = sum / count;
        known[v] = changed = true;
      }
    }
  }
  return radii;
}

} // namespace

// --- smooth_skeleton -------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(smoothing_averages_five_points_and_keeps_ends_fixed)
{
  std::vector<Point> zigzag;
  for(int i = 0; i < 12; ++i)
    zigzag.emplace_back(i, (i % 2) ? 1.0 : 0.0, 0);
  Skeleton s = chain_skeleton(zigzag, 1.0);
  s[5].radius = 6.0;
  gs::smooth_skeleton(s);
  BOOST_TEST(distance(s[0].point, zigzag[0]) == 0.0);
  BOOST_TEST(distance(s[11].point, zigzag[11]) == 0.0);
  // Equation 3 at i = 5: the mean of points 3..7.
  BOOST_TEST(s[5].point.x() == 5.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s[5].point.y() == 0.6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s[5].radius == 2.0, boost::test_tools::tolerance(1e-12));
  // Near an end the window shrinks symmetrically: point 1 averages points 0..2.
  BOOST_TEST(s[1].point.y() == 1.0 / 3.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(smoothing_keeps_junctions_fixed_and_handles_short_branches)
{
  Skeleton s;
  const auto trunk = add_chain(s, {Point(0, 0, 0), Point(1, 0.5, 0), Point(2, 0, 0), Point(3, 0.5, 0), Point(4, 0, 0)}, 1.0);
  add_chain(s, {Point(2, 1, 0), Point(2.5, 2, 0)}, 1.0, long(trunk[2])); // a branch of 2 points
  const Point junction = s[trunk[2]].point;
  gs::smooth_skeleton(s);
  BOOST_TEST(distance(s[trunk[2]].point, junction) == 0.0);
  BOOST_TEST(s[trunk[1]].point.y() == (0.0 + 0.5 + 0.0) / 3.0, boost::test_tools::tolerance(1e-12));
  // The short branch (junction, middle, end): its middle averages the three.
  BOOST_TEST(s[5].point.x() == (2.0 + 2.0 + 2.5) / 3.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(smoothing_a_closed_loop_wraps_around)
{
  std::vector<Point> square;
  for(const Point& p : polyline({Point(0, 0, 0), Point(4, 0, 0), Point(4, 4, 0), Point(0, 4, 0), Point(0, 0, 0)}, 1))
    square.push_back(p);
  square.pop_back(); // closed: the first point is not repeated
  Skeleton s = chain_skeleton(square, 1.0);
  add_edge(square.size() - 1, 0, s);
  gs::smooth_skeleton(s);
  // The corner (0,0,0) moves inwards to the mean of (0,2),(0,1),(0,0),(1,0),(2,0).
  BOOST_TEST(s[0].point.x() == 0.6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s[0].point.y() == 0.6, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_window_of_one_changes_nothing_and_bad_windows_throw)
{
  Skeleton s = chain_skeleton(polyline({Point(0, 0, 0), Point(5, 3, 0)}, 0.5), 1.0);
  const Point before = s[4].point;
  gs::smooth_skeleton(s, gs::parameters::smoothing_window(1));
  BOOST_TEST(distance(s[4].point, before) == 0.0);
  BOOST_CHECK_THROW(gs::smooth_skeleton(s, gs::parameters::smoothing_window(4)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::smooth_skeleton(s, gs::parameters::smoothing_window(0)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::smooth_skeleton(s, gs::parameters::smoothing_window(-3)), std::invalid_argument);
}

// --- chord_to_point_distance_accumulation ----------------------------------------------

BOOST_AUTO_TEST_CASE(accumulation_is_zero_on_a_straight_line)
{
  for(double h : accumulation(polyline({Point(0, 0, 0), Point(10, 5, -2)}, 0.3), 2.0))
    BOOST_TEST(h == 0.0, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(accumulation_peaks_at_a_right_angle)
{
  const std::vector<Point> l_shape = polyline({Point(0, 0, 0), Point(10, 0, 0), Point(10, 10, 0)}, 0.25);
  const std::vector<double> h = accumulation(l_shape, 4.0);
  const std::size_t peak = std::max_element(h.begin(), h.end()) - h.begin();
  BOOST_TEST(distance(l_shape[peak], Point(10, 0, 0)) < 0.3);
  // The corner's distance to the chord that starts x L before it on the first arm is
  // L x (1 - x) / sqrt(x^2 + (1 - x)^2); the value is the mean over the 17 chords.
  double expected = 0;
  for(int t = 0; t <= 16; ++t)
  {
    const double x = t / 16.0;
    expected += (x == 0 || x == 1) ? 0.0 : x * (1 - x) / std::sqrt(x * x + (1 - x) * (1 - x));
  }
  expected /= 17;
  BOOST_TEST(h[peak] == expected, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(h[peak] > 0.2);
}

BOOST_AUTO_TEST_CASE(accumulation_does_not_depend_on_sampling_rotation_or_scale)
{
  const std::vector<Point> coarse = polyline({Point(0, 0, 0), Point(8, 0, 0), Point(12, 5, 3)}, 0.5);
  const std::vector<Point> fine = polyline({Point(0, 0, 0), Point(8, 0, 0), Point(12, 5, 3)}, 0.1);
  const std::vector<double> hc = accumulation(coarse, 3.0), hf = accumulation(fine, 3.0);
  BOOST_TEST(*std::max_element(hc.begin(), hc.end()) ==
                 *std::max_element(hf.begin(), hf.end()), boost::test_tools::tolerance(0.02));

  // Rotated about z by 1 radian, scaled by 7 and moved: the same values.
  std::vector<Point> moved;
  for(const Point& p : coarse)
    moved.emplace_back(7 * (std::cos(1.0) * p.x() - std::sin(1.0) * p.y()) + 3,
                       7 * (std::sin(1.0) * p.x() + std::cos(1.0) * p.y()) - 2, 7 * p.z() + 1);
  const std::vector<double> hm = accumulation(moved, 21.0);
  for(std::size_t i = 0; i < hc.size(); ++i)
    BOOST_TEST(std::abs(hm[i] - hc[i]) < 1e-9);
}

BOOST_AUTO_TEST_CASE(accumulation_on_a_closed_square_peaks_at_its_four_corners)
{
  // Its last point repeats its first: the polyline is closed, and wraps around its first
  // corner, which an open polyline (the same points but the last) leaves flat.
  const std::vector<Point> square =
      polyline({Point(0, 0, 0), Point(8, 0, 0), Point(8, 8, 0), Point(0, 8, 0), Point(0, 0, 0)}, 0.5);
  const std::vector<double> h = accumulation(square, 3.0);
  BOOST_REQUIRE(h.size() == square.size());
  BOOST_TEST(h.back() == h.front());
  const std::size_t n = h.size() - 1; // the distinct points
  std::vector<std::size_t> local_maxima;
  for(std::size_t i = 0; i < n; ++i)
    if(h[i] > h[(i + n - 1) % n] && h[i] >= h[(i + 1) % n] && h[i] > 0.1)
      local_maxima.push_back(i);
  BOOST_TEST(local_maxima.size() == 4u);
  for(std::size_t i : local_maxima)
    BOOST_TEST(std::fmod(square[i].x(), 8.0) + std::fmod(square[i].y(), 8.0) == 0.0);
  const std::vector<double> open = accumulation(std::vector<Point>(square.begin(), square.end() - 1), 3.0);
  BOOST_TEST(open.front() == 0.0);
  BOOST_TEST(h.front() > 0.1);
}

BOOST_AUTO_TEST_CASE(accumulation_rejects_bad_chords)
{
  const std::vector<Point> p = polyline({Point(0, 0, 0), Point(1, 0, 0)}, 0.5);
  std::vector<double> h;
  BOOST_CHECK_THROW(gs::chord_to_point_distance_accumulation(p, 0.0, std::back_inserter(h)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::chord_to_point_distance_accumulation(p, std::nan(""), std::back_inserter(h)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::chord_to_point_distance_accumulation(p, 1.0, std::back_inserter(h), gs::parameters::number_of_chords(0)),
                    std::invalid_argument);
  // A polyline shorter than the chord: no chord fits, all zero.
  h.clear();
  gs::chord_to_point_distance_accumulation(p, 5.0, std::back_inserter(h));
  BOOST_TEST(h.size() == p.size());
  BOOST_TEST(*std::max_element(h.begin(), h.end()) == 0.0);
}

// --- split_into_bones ------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(a_straight_tube_gives_one_bone)
{
  const Control c = bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 30)}, 0.5), 2.0), paper_split);
  BOOST_TEST(num_edges(c) == 1u);
  BOOST_TEST(num_vertices(c) == 2u);
  check_tree(c);
  // Up to the longest bone (3 largest radii by default), a straight tube stays one bone.
  BOOST_TEST(num_edges(bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 30)}, 0.5), 12.0))) == 1u);
}

// A straight limb has no bend for the accumulation, yet an animator wants an elbow and a
// wrist: a straight part longer than maximum_bone_length_factor times the largest radius is
// cut into bones of about equal length, at the narrowings near the equal-length positions.
BOOST_AUTO_TEST_CASE(a_long_straight_limb_is_cut_at_its_narrowings)
{
  // 45 long, radius 5: 45 / (3 x 5) gives 3 bones, cut near z = 15 and z = 30.
  const std::vector<Point> limb = polyline({Point(0, 0, 0), Point(0, 0, 45)}, 0.5);
  const Control even = bones_of(chain_skeleton(limb, 5.0), gs::parameters::tip_joint_setback(0.0)); // joints at the tips
  BOOST_TEST(num_edges(even) == 3u);
  check_tree(even);
  for(const auto bone : boost::make_iterator_range(edges(even)))
  {
    BOOST_TEST(even[bone].length >= 15.0 * 0.75);
    BOOST_TEST(even[bone].length <= 15.0 * 1.25);
  }

  // Narrowings at z = 17.5 (an elbow) and z = 27.5 (a wrist): the cuts go there.
  Skeleton narrowed;
  const std::vector<std::size_t> ids = add_chain(narrowed, limb, 5.0);
  for(std::size_t id : ids)
  {
    const double z = narrowed[id].point.z();
    if(std::abs(z - 17.5) < 0.01 || std::abs(z - 27.5) < 0.01)
      narrowed[id].radius = 4.0;
  }
  const Control cut = bones_of(narrowed);
  BOOST_TEST(num_edges(cut) == 3u);
  std::vector<double> bend_heights;
  for(const auto& j : test::joints(cut))
    if(j.kind == gs::Joint_kind::bend || j.kind == gs::Joint_kind::root)
      if(j.point.z() > 1 && j.point.z() < 44)
        bend_heights.push_back(j.point.z());
  std::sort(bend_heights.begin(), bend_heights.end());
  BOOST_REQUIRE(bend_heights.size() == 2u);
  BOOST_TEST(bend_heights[0] == 17.5, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(bend_heights[1] == 27.5, boost::test_tools::tolerance(1e-9));

  // The paper's split alone keeps it whole, and the longest bone follows the factor.
  BOOST_TEST(num_edges(bones_of(chain_skeleton(limb, 5.0), paper_split)) == 1u);
  BOOST_TEST(num_edges(bones_of(chain_skeleton(limb, 5.0), gs::parameters::maximum_bone_length_factor(4.5))) == 2u);

  // A thin limb on a thick body is measured in the body's radius: a limb of radius 1 and 44
  // long, hanging from a trunk of radius 5, gets 3 bones, not 44 / 3 = 15 (capped to 4).
  Skeleton body;
  const auto trunk = add_chain(body, polyline({Point(-20, 0, -0.5), Point(20, 0, -0.5)}, 0.5), 5.0);
  add_chain(body, polyline({Point(0, 0, 0), Point(0, 0, 44)}, 0.5), 1.0, long(trunk[40]));
  const Control thin_limb = bones_of(body);
  std::size_t limb_bones = 0;
  for(const auto bone : boost::make_iterator_range(edges(thin_limb)))
    limb_bones +=
        thin_limb[target(bone, thin_limb)].point.z() > 0.25 || thin_limb[source(bone, thin_limb)].point.z() > 0.25;
  BOOST_TEST(limb_bones == 3u);
}

// A strip alone (radius 0.1, 12 long: the longest bone is 0.3) steps aside by 0.2 at 10.5,
// 1.5 from its tip, as the skeleton of a thin blade steps by a voxel: each corner of the
// step is a joint. Both straight parts are far longer than the longest bone; they share
// the branch's 4 bones in proportion to their lengths (4 and 1), not 4 each.
BOOST_AUTO_TEST_CASE(the_straight_parts_of_a_branch_share_its_bones)
{
  std::vector<Point> strip = polyline({Point(0, 0, 0), Point(10.5, 0, 0)}, 0.05);
  for(const Point& p : polyline({Point(10.5, 0.2, 0), Point(12, 0.2, 0)}, 0.05))
    strip.push_back(p);
  const Control c = bones_of(chain_skeleton(strip, 0.1));
  check_tree(c);
  std::size_t bones_before_the_step = 0, bones_past_the_step = 0;
  for(const auto bone : boost::make_iterator_range(edges(c)))
  {
    const double x0 = c[source(bone, c)].point.x(), x1 = c[target(bone, c)].point.x();
    bones_before_the_step += x0 < 10.51 && x1 < 10.51;
    bones_past_the_step += x0 > 10.52 && x1 > 10.52;
  }
  BOOST_TEST(bones_before_the_step == 4u);
  BOOST_TEST(bones_past_the_step == 1u);
  BOOST_TEST(num_edges(c) == 6u); // and the short bone of the step, between its corners
  // Without the step, the strip is one straight part: 4 bones.
  BOOST_TEST(num_edges(bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(12, 0, 0)}, 0.05), 0.1))) == 4u);
}

// A straight part exactly twice the shortest bone long stays one bone, wherever it lies: an
// arm of the demo cross aligned with the grid is 26 voxels long with a radius of 6.5, and it
// used to be cut in two there by an exact tie, and kept whole at any other placement or at a
// finer grid. A little longer, the part is cut in two.
BOOST_AUTO_TEST_CASE(a_part_twice_the_shortest_bone_long_stays_whole)
{
  // Radius 1: the shortest bone is 2 radii (the default factor), the longest 3.
  const Control aligned = bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 4)}, 0.25), 1.0));
  BOOST_TEST(num_edges(aligned) == 1u);
  check_tree(aligned);
  // The same part along (1, 2, 2) / 3 from an arbitrary origin: its lengths are 4 up to rounding.
  const Point origin(0.1, 0.7, -0.3);
  const Kernel::Vector_3 along(4.0 / 3, 8.0 / 3, 8.0 / 3);
  BOOST_TEST(num_edges(bones_of(chain_skeleton(polyline({origin, origin + along}, 0.25), 1.0))) == 1u);
  BOOST_TEST(num_edges(bones_of(chain_skeleton(polyline({origin, origin + along * 1.125}, 0.25), 1.0))) == 2u);

  const Control longer =
      bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 4.5)}, 0.25), 1.0), gs::parameters::tip_joint_setback(0.0)); // joints at the tips
  BOOST_REQUIRE(num_edges(longer) == 2u);
  for(const auto bone : boost::make_iterator_range(edges(longer)))
    BOOST_TEST(longer[bone].length == 2.25, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(an_l_shaped_tube_gives_two_bones_with_the_joint_at_the_corner)
{
  const double radius = 1.5;
  const Control c =
      bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(20, 0, 0), Point(20, 20, 0)}, 0.5), radius), paper_split);
  BOOST_REQUIRE(num_edges(c) == 2u);
  check_tree(c);
  bool corner_found = false;
  for(const auto& j : test::joints(c))
    if(distance(j.point, Point(20, 0, 0)) < radius)
      corner_found = true;
  BOOST_TEST(corner_found);
}

BOOST_AUTO_TEST_CASE(a_zigzag_of_k_straight_parts_gives_k_bones)
{
  for(int k = 2; k <= 6; ++k)
  {
    std::vector<Point> corners;
    for(int i = 0; i <= k; ++i)
      corners.emplace_back(12.0 * i, (i % 2) ? 9.0 : 0.0, 0);
    const Control c = bones_of(chain_skeleton(polyline(corners, 0.4), 1.0), paper_split);
    BOOST_TEST(num_edges(c) == std::size_t(k), "zigzag of " << k << " parts");
    check_tree(c);
  }
}

BOOST_AUTO_TEST_CASE(noise_on_a_straight_tube_adds_no_joint)
{
  CGAL::Random rng(5);
  std::vector<Point> noisy;
  for(const Point& p : polyline({Point(0, 0, 0), Point(40, 0, 0)}, 0.5))
    noisy.emplace_back(p.x(), p.y() + rng.get_double(-0.3, 0.3), p.z() + rng.get_double(-0.3, 0.3));
  Skeleton s = chain_skeleton(noisy, 2.0);
  gs::smooth_skeleton(s);
  const Control c = bones_of(s, paper_split);
  BOOST_TEST(num_edges(c) == 1u);
}

BOOST_AUTO_TEST_CASE(a_star_is_rooted_at_its_junction)
{
  Skeleton s;
  const auto arm = add_chain(s, polyline({Point(0, 0, 0), Point(15, 0, 0)}, 0.5), 1.0);
  add_chain(s, polyline({Point(-0.5, 0, 0), Point(-15, 0, 0)}, 0.5), 1.0, long(arm[0]));
  add_chain(s, polyline({Point(0, 0.5, 0), Point(0, 15, 0)}, 0.5), 1.0, long(arm[0]));
  s[arm[0]].radius = 3.0;
  const Control c = bones_of(s, paper_split);
  check_tree(c);
  BOOST_REQUIRE(c[boost::graph_bundle].roots.size() == 1u);
  const auto& root = c[c[boost::graph_bundle].roots[0]];
  BOOST_TEST(distance(root.point, Point(0, 0, 0)) < 1e-9);
  BOOST_TEST(num_edges(c) == 3u);
  std::size_t ends = 0;
  for(const auto& j : test::joints(c))
    ends += j.kind == gs::Joint_kind::end;
  BOOST_TEST(ends == 3u);
}

BOOST_AUTO_TEST_CASE(the_root_is_the_most_central_junction)
{
  // A long chain with two forks: the fork nearer the middle is the root.
  Skeleton s;
  const auto spine = add_chain(s, polyline({Point(0, 0, 0), Point(60, 0, 0)}, 1.0), 1.0);
  add_chain(s, polyline({Point(20, 1, 0), Point(20, 10, 0)}, 1.0), 1.0, long(spine[20]));
  add_chain(s, polyline({Point(50, 1, 0), Point(50, 10, 0)}, 1.0), 1.0, long(spine[50]));
  const Control c = bones_of(s);
  check_tree(c);
  BOOST_TEST(distance(c[c[boost::graph_bundle].roots[0]].point, Point(20, 0, 0)) < 1e-9);
}

BOOST_AUTO_TEST_CASE(a_loop_is_cut_once_into_a_tree)
{
  std::vector<Point> ring;
  for(int i = 0; i < 120; ++i)
    ring.emplace_back(10 * std::cos(2 * pi * i / 120), 10 * std::sin(2 * pi * i / 120), 0);
  Skeleton s = chain_skeleton(ring, 1.0);
  add_edge(ring.size() - 1, 0, s);
  const Control c = bones_of(s);
  check_tree(c);
  BOOST_TEST(c[boost::graph_bundle].cut_bones.size() == 1u);
  BOOST_TEST(num_edges(c) >= 3u); // a circle is not straight anywhere
}

// A wavy chain of MAT radius 0.1 (a thin tail, as a fine grid measures it) bends every 2
// units: its lengths in radii of 0.1 give it a joint at every bend; measured in radii of at
// least 1 (smallest_radius), its waves are under the straightness tolerance.
BOOST_AUTO_TEST_CASE(the_smallest_radius_is_the_unit_of_thin_parts)
{
  std::vector<Point> wave;
  for(int i = 0; i <= 200; ++i)
    wave.emplace_back(0.1 * i, 0.3 * std::sin(0.1 * i * 3.14159265358979 / 2.), 0);
  const Skeleton s = chain_skeleton(wave, 0.1);
  const Control fine = bones_of(s, paper_split);
  const Control floored = bones_of(s, gs::parameters::combine(paper_split, gs::parameters::smallest_radius(1.0)));
  BOOST_TEST(num_edges(fine) >= 8u);
  BOOST_TEST(num_edges(floored) <= 2u);
  for(std::size_t j = 0; j < num_vertices(floored); ++j)
    BOOST_TEST(floored[j].radius == 0.1); // the joints keep their own radius
  // A floor under every radius changes nothing.
  BOOST_TEST(num_edges(bones_of(s, gs::parameters::combine(paper_split, gs::parameters::smallest_radius(0.05)))) ==
             num_edges(fine));
}

// A limb of radius 1, 10 long and straight, turns at a right angle into a wavy tip of
// radius 0.1, 4 long (a hoof or a finger as a fine grid resolves it). Measured in its own
// radius the tip gets a joint at every wave; with the floor of half the piece's largest
// radius, no bone is shorter than 0.5, and the tip gets fewer joints.
BOOST_AUTO_TEST_CASE(no_bone_is_shorter_than_the_level_of_detail_of_its_piece)
{
  std::vector<Point> limb = polyline({Point(0, 0, 0), Point(10, 0, 0)}, 0.05);
  limb.pop_back();
  const std::size_t thick = limb.size();
  for(int i = 0; i <= 80; ++i)
    limb.emplace_back(10 + 0.15 * std::sin(0.05 * i * pi / 0.4), 0.05 * i, 0);
  Skeleton s = chain_skeleton(limb, 1.0);
  for(std::size_t v = thick; v < num_vertices(s); ++v)
    s[v].radius = 0.1;
  const Control paper = bones_of(s, paper_split);
  const Control floored =
      bones_of(s, gs::parameters::combine(gs::parameters::maximum_bone_length_factor(0.0),
                                          gs::parameters::minimum_bone_length_of_piece_factor(0.5)));
  check_tree(floored);
  BOOST_TEST(num_edges(paper) >= 6u);
  BOOST_TEST(shortest_bone(paper) < 0.5);
  BOOST_TEST(num_edges(floored) >= 2u); // the tip still bends away from the limb
  BOOST_TEST(num_edges(floored) < num_edges(paper));
  BOOST_TEST(shortest_bone(floored) >= 0.5 * (1 - 1e-12));
  // The default of split_into_bones() is this floor.
  BOOST_TEST(num_edges(bones_of(s, gs::parameters::maximum_bone_length_factor(0.0))) == num_edges(floored));
}

// A limb of radius 1, 2 long, turns at a right angle into a thin part of radius 0.05, 2 long,
// that bows out by 0.06 (a leg, or a wall, as a fine grid resolves it): more than half its
// own radius, less than half the radius of the rig's level of detail (a quarter of 1).
// Measured in its own radius it is cut where it strays most; at the level of detail it is
// one bone.
BOOST_AUTO_TEST_CASE(a_thin_part_strays_from_its_chord_in_radii_of_the_level_of_detail)
{
  std::vector<Point> limb = polyline({Point(0, 0, 0), Point(2, 0, 0)}, 0.05);
  limb.pop_back();
  const std::size_t thick = limb.size();
  for(int i = 0; i <= 40; ++i)
    limb.emplace_back(2 + 0.06 * std::sin(pi * i / 40.), 0.05 * i, 0);
  Skeleton s = chain_skeleton(limb, 1.0);
  for(std::size_t v = thick; v < num_vertices(s); ++v)
    s[v].radius = 0.05;
  auto bends_in_thin_part = [](const Control& c) {
    std::size_t bends = 0;
    for(std::size_t j = 0; j < num_vertices(c); ++j)
      if(c[j].kind == gs::Joint_kind::bend && c[j].point.y() > 0.1)
        ++bends;
    return bends;
  };
  const Control at_level_of_detail = bones_of(s);
  const Control in_own_radius = bones_of(s, gs::parameters::minimum_bone_length_of_piece_factor(0.0));
  check_tree(at_level_of_detail);
  BOOST_TEST(bends_in_thin_part(at_level_of_detail) == 0u);
  BOOST_TEST(bends_in_thin_part(in_own_radius) >= 1u);
  // A tolerance of 0.2 radii (0.05 at the level of detail) cuts it again.
  BOOST_TEST(bends_in_thin_part(bones_of(s, gs::parameters::straightness_tolerance(0.2))) >= 1u);
}

// The same wavy chain as a wing's chain: its MAT radius is the wing's half thickness, 0.1,
// and its sheet half width is 1. Measured in the width, its waves are under the
// straightness tolerance; the joints keep their MAT radius; a width under the radius
// changes nothing.
BOOST_AUTO_TEST_CASE(a_sheet_is_split_in_lengths_of_its_half_width)
{
  std::vector<Point> wave;
  for(int i = 0; i <= 200; ++i)
    wave.emplace_back(0.1 * i, 0.3 * std::sin(0.1 * i * pi / 2.), 0);
  const Skeleton s = chain_skeleton(wave, 0.1);
  const Control fine = bones_of(s, paper_split);
  auto with_sheet_half_width = [&](double width) {
    Skeleton sheet = s;
    for(std::size_t v = 0; v < num_vertices(sheet); ++v)
      sheet[v].sheet_half_width = width;
    return sheet;
  };
  const Control in_width = bones_of(with_sheet_half_width(1.0), paper_split);
  BOOST_TEST(num_edges(fine) >= 8u);
  BOOST_TEST(num_edges(in_width) <= 2u);
  for(std::size_t j = 0; j < num_vertices(in_width); ++j)
    BOOST_TEST(in_width[j].radius == 0.1);
  BOOST_TEST(num_edges(bones_of(with_sheet_half_width(0.05), paper_split)) == num_edges(fine));
}

// A sheet radius of r rounds is a half width of r - 2 voxels (the two rounds that any level
// may burn in say nothing of a sheet), never less than 0; a voxel without one is 0.
BOOST_AUTO_TEST_CASE(sheet_half_widths_discount_the_rounds_of_any_level)
{
  const gs::Sheet_radii radii{{gs::Voxel_key{0, 0, 0}, 12.0}, {gs::Voxel_key{0, 0, 1}, 2.0}, {gs::Voxel_key{0, 0, 2}, 1.0}};
  std::vector<double> widths;
  for(int z = 0; z < 4; ++z)
    widths.push_back(gs::internal::sheet_half_width(radii, gs::Voxel_key{0, 0, z}, 0.5));
  BOOST_TEST(widths == (std::vector<double>{5.0, 0.0, 0.0, 0.0}), boost::test_tools::per_element());
}

// A wavy chain of radius 0.1, as a bar that pruning kept beside a plate of half width 1:
// with the piece's radius from the plate (the vertices' piece_radius, given at one vertex or
// at all), its bones are as long as the plate's level of detail (half of 1) asks; the joints
// keep their MAT radius; a piece radius under the radii changes nothing.
BOOST_AUTO_TEST_CASE(a_piece_radius_sets_the_level_of_detail_of_its_piece)
{
  std::vector<Point> wave;
  for(int i = 0; i <= 200; ++i)
    wave.emplace_back(0.1 * i, 0.3 * std::sin(0.1 * i * pi / 2.), 0);
  const Skeleton s = chain_skeleton(wave, 0.1);
  auto with_piece_radius = [&](double radius, bool at_one_vertex) {
    Skeleton piece = s;
    for(std::size_t v = 0; v < num_vertices(piece); ++v)
      piece[v].piece_radius = at_one_vertex && v != 7 ? 0.0 : radius;
    return piece;
  };
  const Control own = bones_of(s);
  const Control in_piece = bones_of(with_piece_radius(1.0, true));
  check_tree(in_piece);
  BOOST_TEST(num_edges(own) >= 8u);
  BOOST_TEST(num_edges(in_piece) < num_edges(own));
  BOOST_TEST(shortest_bone(own) < 0.5);
  BOOST_TEST(shortest_bone(in_piece) > 0.5);
  for(std::size_t j = 0; j < num_vertices(in_piece); ++j)
    BOOST_TEST(in_piece[j].radius == 0.1);
  const Control given_everywhere = bones_of(with_piece_radius(1.0, false));
  BOOST_TEST(num_edges(given_everywhere) == num_edges(in_piece));
  BOOST_TEST(num_edges(bones_of(with_piece_radius(0.05, false))) == num_edges(own));
}

// prune_skeleton() of a Voxel_skeleton takes the widest sheet of each piece first: every
// voxel of a 26-connected piece gets the largest sheet radius of the piece read across close
// levels, a piece without one 0; radii of voxels outside the set count for nothing.
BOOST_AUTO_TEST_CASE(every_voxel_of_a_piece_gets_its_widest_sheet)
{
  using gs::Voxel_key;
  const gs::Voxel_box box{Voxel_key{-20, -20, -20}, Voxel_key{20, 20, 20}};
  gs::Voxel_skeleton skeleton;
  skeleton.voxels.reset(gs::Voxel_frame(), box);
  const std::vector<Voxel_key> plate{{0, 0, 0}, {1, 0, 0}, {2, 1, 1}, {3, 2, 1}}, bar{{10, 0, 0}, {11, 0, 0}};
  for(const Voxel_key& k : plate)
    skeleton.voxels.insert(k);
  for(const Voxel_key& k : bar)
    skeleton.voxels.insert(k);
  skeleton.slanted_sheet_radii = {{Voxel_key{1, 0, 0}, 9.0}, {Voxel_key{3, 2, 1}, 4.0}, {Voxel_key{12, 0, 0}, 30.0}};
  const gs::Voxel_distance_field distances(gs::Voxel_frame(), box, std::vector<std::uint32_t>(box.volume(), 1));
  gs::prune_skeleton(skeleton, distances);
  const gs::Sheet_radii& widest = skeleton.piece_sheet_radii;
  BOOST_TEST(widest.size() == plate.size() + bar.size());
  for(const Voxel_key& k : plate)
    BOOST_TEST(widest.at(k) == 9.0);
  for(const Voxel_key& k : bar)
    BOOST_TEST(widest.at(k) == 0.0);
  BOOST_TEST(skeleton.voxels.size() == plate.size() + bar.size()); // two paths: nothing pruned
}

// Artists end a chain short of the tip (the wrist, the head joint, the last tail joint): a
// tip's joint is set back along its bone by tip_joint_setback of the bone's length, onto a
// point of the skeleton, and the bone ends there.
BOOST_AUTO_TEST_CASE(a_tip_joint_is_set_back_along_its_bone)
{
  // A T: a trunk along x with a limb 20 long up from its middle, radius 1, points 0.5 apart.
  Skeleton t;
  const auto trunk = add_chain(t, polyline({Point(-20, 0, 0), Point(20, 0, 0)}, 0.5), 1.0);
  add_chain(t, polyline({Point(0, 0, 0.5), Point(0, 0, 20)}, 0.5), 1.0, long(trunk[40]));
  const auto options = gs::parameters::combine(paper_split, gs::parameters::minimum_bone_length_factor(0.0));
  const Control at_tips = bones_of(t, gs::parameters::combine(gs::parameters::tip_joint_setback(0.0), options));
  const Control set_back = bones_of(t, gs::parameters::combine(gs::parameters::tip_joint_setback(0.25), options));
  // By default a tip's joint is set back as extract_control_skeleton() sets it back.
  const Control by_default = bones_of(t, options);
  BOOST_TEST(identical(by_default, bones_of(t, gs::parameters::combine(gs::parameters::tip_joint_setback(
                                                                           gs::parameter_ranges::tip_joint_setback.default_value),
                                                                       options))));
  BOOST_TEST(!identical(by_default, at_tips));
  check_tree(set_back);
  BOOST_TEST(num_vertices(set_back) == num_vertices(at_tips));
  BOOST_TEST(num_edges(set_back) == num_edges(at_tips));
  std::vector<Point> tips;
  for(const auto j : boost::make_iterator_range(vertices(set_back)))
  {
    if(set_back[j].kind != gs::Joint_kind::end)
      continue;
    tips.push_back(set_back[j].point);
    // The joint sits on a skeleton vertex, with its radius, and its bone ends there.
    BOOST_TEST(set_back[j].point == t[set_back[j].skeleton_vertex].point);
    BOOST_TEST(set_back[gs::bone_to(j, set_back)].points.back() == set_back[j].point);
  }
  // Each bone of the trunk is 20 long and the limb 20: each tip moves 5 back.
  std::sort(tips.begin(), tips.end());
  BOOST_REQUIRE(tips.size() == 3u);
  BOOST_TEST(tips[0].x() == -15.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(tips[1].z() == 15.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(tips[2].x() == 15.0, boost::test_tools::tolerance(1e-9));

  // A lone bone with two tips is set back from both ends alike.
  const Control lone =
      bones_of(chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 30)}, 0.5), 1.0),
               gs::parameters::combine(gs::parameters::tip_joint_setback(0.2), options));
  BOOST_REQUIRE(num_edges(lone) == 1u);
  std::vector<double> heights;
  for(const auto& j : test::joints(lone))
    heights.push_back(j.point.z());
  std::sort(heights.begin(), heights.end());
  BOOST_TEST(heights[0] == 6.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(heights[1] == 24.0, boost::test_tools::tolerance(1e-9));

  // A loop has no tip: nothing moves.
  Skeleton loop;
  std::vector<Point> ring;
  for(int k = 0; k < 60; ++k)
    ring.emplace_back(10 * std::cos(2 * pi * k / 60), 10 * std::sin(2 * pi * k / 60), 0);
  const auto ids = add_chain(loop, ring, 1.0);
  add_edge(ids.back(), ids.front(), loop);
  const Control closed = bones_of(loop, gs::parameters::tip_joint_setback(0.4));
  BOOST_TEST(num_vertices(closed) == num_vertices(bones_of(loop)));
}

// Artists space joints along a spine or a straight limb: with a joint_spacing, each bone is
// cut into the whole number of bones nearest its length over the spacing, of equal length.
BOOST_AUTO_TEST_CASE(bones_are_cut_at_the_joint_spacing)
{
  const Skeleton s = chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 30)}, 0.5), 1.0);
  const auto options = gs::parameters::combine(paper_split, gs::parameters::minimum_bone_length_factor(0.0));
  const auto at_tips = gs::parameters::combine(gs::parameters::tip_joint_setback(0.0), options);
  BOOST_TEST(num_edges(bones_of(s, at_tips)) == 1u);
  for(const auto& [spacing, bones] : std::vector<std::pair<double, std::size_t>>{{10, 3}, {7, 4}, {8.4, 4}, {40, 1}, {0, 1}})
  {
    const Control c = bones_of(s, gs::parameters::combine(gs::parameters::joint_spacing(spacing), at_tips));
    check_tree(c);
    BOOST_TEST(num_edges(c) == bones);
    for(const auto bone : boost::make_iterator_range(edges(c)))
      BOOST_TEST(c[bone].length == 30.0 / double(bones), boost::test_tools::tolerance(0.5 / 30.0));
  }
  // With a set-back tip, the spacing cuts the bones as they are after the set-back.
  const Control both = bones_of(s, gs::parameters::combine(gs::parameters::joint_spacing(9.0),
                                                           gs::parameters::tip_joint_setback(0.2), options));
  BOOST_TEST(num_edges(both) == 2u); // 18 long: 2 bones of 9
}

BOOST_AUTO_TEST_CASE(bad_parameters_throw)
{
  const Skeleton s = chain_skeleton(polyline({Point(0, 0, 0), Point(0, 0, 30)}, 0.5), 2.0);
  Control c;
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::bend_threshold(-0.1)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::straightness_tolerance(std::nan(""))), std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::maximum_bone_length_factor(-1.0)), std::invalid_argument);
  for(double bad : {-0.1, 0.5, std::nan("")})
    BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::tip_joint_setback(bad)), std::invalid_argument);
  for(double bad : {-1.0, std::nan("")})
    BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::joint_spacing(bad)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::smallest_radius(-1.0)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::smallest_radius(std::nan(""))), std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::minimum_bone_length_of_piece_factor(-1.0)),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::minimum_bone_length_of_piece_factor(std::nan(""))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::chord_length_factors(std::vector<double>{})),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::minimum_bone_length_factor(-1.0)), std::invalid_argument);
  for(double bad : {-1.0, std::nan(""), HUGE_VAL})
  {
    std::vector<double> radii(num_vertices(s), 2.0);
    radii[3] = bad;
    BOOST_CHECK_THROW(gs::split_into_bones(s, c, gs::parameters::mat_radius_map(CGAL::make_property_map(radii))),
                      std::invalid_argument);
    Skeleton bad_sheet = s, bad_piece = s;
    bad_sheet[3].sheet_half_width = bad;
    bad_piece[3].piece_radius = bad;
    BOOST_CHECK_THROW(gs::split_into_bones(bad_sheet, c), std::invalid_argument);
    BOOST_CHECK_THROW(gs::split_into_bones(bad_piece, c), std::invalid_argument);
  }
  for(double bad : {std::nan(""), HUGE_VAL})
  {
    Skeleton bad_point = s;
    bad_point[3].point = Point(0, bad, 0);
    BOOST_CHECK_THROW(gs::split_into_bones(bad_point, c), std::invalid_argument);
  }
  Skeleton empty;
  gs::split_into_bones(empty, c);
  BOOST_TEST((num_vertices(c) == 0));
}

// --- the control skeleton as a Boost.Graph forest ----------------------------------------

namespace {

// A demo mesh's control skeleton and curve skeleton, from extract_control_skeleton().
struct Demo_rig
{
  Control control;
  Mesh_skeleton curve;
};

Demo_rig demo_rig(const std::string& name)
{
  const Mesh mesh = test::demo_mesh<Mesh>(name);
  Demo_rig rig;
  gs::extract_control_skeleton(mesh, rig.control, gs::parameters::curve_skeleton_output(&rig.curve));
  return rig;
}

// The independent cycles of a graph seen as undirected: edges - vertices + components.
template <typename Graph>
std::size_t independent_cycles(const Graph& g)
{
  std::vector<std::size_t> component(num_vertices(g));
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> undirected(num_vertices(g));
  for(const auto e : boost::make_iterator_range(edges(g)))
    add_edge(source(e, g), target(e, g), undirected);
  const std::size_t components = boost::connected_components(undirected, component.data());
  return num_edges(g) + components - num_vertices(g);
}

// Records, in a breadth-first search, the order in which joints are reached and the edges
// the search meets that lead to a joint already reached (none in a forest).
struct Forest_recorder : boost::default_bfs_visitor
{
  std::vector<std::size_t>* reached;
  std::size_t* edges_to_reached;
  template <typename Vertex, typename Graph>
  void discover_vertex(Vertex v, const Graph&) { reached->push_back(v); }
  template <typename Edge, typename Graph>
  void non_tree_edge(Edge, const Graph&) { ++*edges_to_reached; }
};

} // namespace

BOOST_AUTO_TEST_CASE(every_joint_but_a_root_has_exactly_one_bone_in_and_roots_have_none)
{
  for(const char* name : {"cow.off", "eight.off"})
  {
    const Control c = demo_rig(name).control;
    const std::vector<std::size_t>& roots = c[boost::graph_bundle].roots;
    BOOST_REQUIRE(num_vertices(c) > 5u);
    for(const auto j : boost::make_iterator_range(vertices(c)))
    {
      const bool is_root = std::find(roots.begin(), roots.end(), j) != roots.end();
      BOOST_TEST(in_degree(j, c) == (is_root ? 0u : 1u), name << " joint " << j);
      BOOST_TEST((c[j].kind == gs::Joint_kind::root) == is_root, name << " joint " << j);
      if(is_root)
        BOOST_TEST(gs::parent_joint(j, c) == boost::graph_traits<Control>::null_vertex());
      else
      {
        BOOST_TEST(target(gs::bone_to(j, c), c) == j);
        BOOST_TEST(source(gs::bone_to(j, c), c) == gs::parent_joint(j, c));
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(a_breadth_first_search_from_the_roots_reaches_every_joint_once_parents_first)
{
  for(const char* name : {"cow.off", "eight.off"})
  {
    const Control c = demo_rig(name).control;
    std::vector<std::size_t> reached;
    std::size_t edges_to_reached = 0;
    std::vector<boost::default_color_type> colour(num_vertices(c), boost::white_color);
    Forest_recorder recorder;
    recorder.reached = &reached;
    recorder.edges_to_reached = &edges_to_reached;
    for(std::size_t root : c[boost::graph_bundle].roots)
    {
      BOOST_TEST(colour[root] == boost::white_color, name << ": root " << root << " is in another tree");
      boost::breadth_first_search(c, root, boost::visitor(recorder).color_map(colour.data()));
    }
    BOOST_TEST(edges_to_reached == 0u, name);
    std::vector<std::size_t> sorted = reached;
    std::sort(sorted.begin(), sorted.end());
    BOOST_TEST((std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()), name << ": a joint reached twice");
    BOOST_TEST(reached.size() == num_vertices(c), name << ": every joint in a tree");
    // Vertex order is an order animation formats may write: each parent before its children.
    for(const auto bone : boost::make_iterator_range(edges(c)))
      BOOST_TEST(source(bone, c) < target(bone, c), name);
  }
}

BOOST_AUTO_TEST_CASE(bones_and_cut_bones_are_the_joints_minus_the_trees_plus_the_cycles)
{
  // eight.off has two handles, double-torus-example.off two, cow.off none.
  for(const char* name : {"cow.off", "eight.off", "double-torus-example.off"})
  {
    const Demo_rig rig = demo_rig(name);
    const Control& c = rig.control;
    const std::size_t trees = c[boost::graph_bundle].roots.size();
    const std::size_t cut = c[boost::graph_bundle].cut_bones.size();
    const std::size_t cycles = independent_cycles(rig.curve);
    BOOST_TEST(num_edges(c) == num_vertices(c) - trees, name);
    BOOST_TEST(num_edges(c) + cut == num_vertices(c) - trees + cycles, name);
    BOOST_TEST(independent_cycles(c) == 0u, name << ": the bones alone make a forest");
    // With the cut bones put back, the joints make as many cycles as the curve skeleton.
    Control closed = c;
    for(const auto& bone : c[boost::graph_bundle].cut_bones)
    {
      BOOST_TEST(bone.source < num_vertices(c));
      BOOST_TEST(bone.target < num_vertices(c));
      add_edge(bone.source, bone.target, closed);
    }
    BOOST_TEST(independent_cycles(closed) == cycles, name);
  }
}

// --- point and radius maps ------------------------------------------------------------

// The call that must not compile, a split without radius, is refused by this condition.
static_assert(!gs::internal::has_radius_map<Mcf_skeleton, CGAL::parameters::Default_named_parameters>(),
              "an MCF skeleton has no radius of its own");
static_assert(gs::internal::has_radius_map<
                  Mcf_skeleton, decltype(gs::parameters::mat_radius_map(CGAL::make_property_map(std::vector<double>())))>(),
              "a mat_radius_map gives an MCF skeleton its radius");
static_assert(gs::internal::has_radius_map<Mesh_skeleton, CGAL::parameters::Default_named_parameters>(),
              "the package's curve skeleton has a radius member");

BOOST_AUTO_TEST_CASE(an_mcf_skeleton_smooths_and_splits_with_a_user_radius_map)
{
  const Mcf_of_cow& mcf = mcf_of_cow();
  const Mcf_skeleton& original = mcf.skeleton;
  Mcf_skeleton s = original;
  const std::size_t n = num_vertices(s);
  BOOST_REQUIRE(n > 50u);
  const std::vector<double> radii_before = mean_distance_to_collapsed_vertices(mcf);
  std::vector<double> radii = radii_before;
  BOOST_REQUIRE(*std::min_element(radii.begin(), radii.end()) > 0.0);
  const auto radius_map = CGAL::make_property_map(radii);

  gs::smooth_skeleton(s, gs::parameters::mat_radius_map(radius_map));
  Control c;
  gs::split_into_bones(s, c, gs::parameters::combine(gs::parameters::mat_radius_map(radius_map), gs::parameters::tip_joint_setback(0.0)));
  check_tree(c);
  BOOST_TEST(c[boost::graph_bundle].roots.size() == 1u); // the cow is one piece
  BOOST_TEST((radii != radii_before)); // smoothing wrote the interior radii through the map

  // The end points and junctions of the MCF skeleton are joints, where the MCF put them,
  // with the radius of the map; the other joints are bends.
  std::size_t ends = 0, junctions = 0;
  std::map<std::size_t, const gs::Control_joint<Point>*> joint_at;
  for(const auto v : boost::make_iterator_range(vertices(c)))
  {
    const gs::Control_joint<Point>& j = c[v];
    BOOST_TEST(joint_at.emplace(j.skeleton_vertex, &j).second, "one joint per skeleton vertex");
    BOOST_TEST(j.radius == radii[j.skeleton_vertex]);
  }
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::size_t d = boost::degree(v, original);
    BOOST_TEST(d > 0u);
    if(d == 2)
      continue;
    ++(d == 1 ? ends : junctions);
    BOOST_TEST_CONTEXT("skeleton vertex " << v << " of degree " << d)
    {
      BOOST_REQUIRE(joint_at.count(v) == 1u);
      const auto& j = *joint_at[v];
      BOOST_TEST(j.point == original[v].point);
      BOOST_TEST(j.radius == radii_before[v]);
      if(d == 1)
        BOOST_TEST((j.kind == gs::Joint_kind::end));
      else
        BOOST_TEST((j.kind == gs::Joint_kind::junction || j.kind == gs::Joint_kind::root));
    }
  }
  BOOST_TEST(ends >= 5u); // four legs and the head, at least
  BOOST_TEST(junctions >= 2u);
  std::size_t bends = 0;
  for(const auto& j : test::joints(c))
    bends += j.kind == gs::Joint_kind::bend;
  BOOST_TEST(num_vertices(c) == ends + junctions + bends);
  BOOST_TEST((c[c[boost::graph_bundle].roots[0]].kind == gs::Joint_kind::root && boost::degree(c[c[boost::graph_bundle].roots[0]].skeleton_vertex, s) >= 3u));

  // Every bone runs along skeleton points, and the bones cover each skeleton edge once.
  std::set<Point> skeleton_points;
  for(std::size_t v = 0; v < n; ++v)
    skeleton_points.insert(s[v].point);
  std::size_t bone_edges = 0;
  auto check_bone = [&](const gs::Control_bone<Point>& bone, std::size_t from, std::size_t to) {
    BOOST_TEST(bone.points.size() >= 2u);
    bone_edges += bone.points.size() - 1;
    for(const Point& p : bone.points)
      BOOST_TEST(skeleton_points.count(p) == 1u, "bone point " << p << " is a skeleton point");
    BOOST_TEST(bone.points.front() == s[c[from].skeleton_vertex].point);
    BOOST_TEST(bone.points.back() == s[c[to].skeleton_vertex].point);
  };
  for(const auto bone : boost::make_iterator_range(edges(c)))
    check_bone(c[bone], source(bone, c), target(bone, c));
  for(const auto& cut : c[boost::graph_bundle].cut_bones)
    check_bone(cut, cut.source, cut.target);
  BOOST_TEST(bone_edges == num_edges(s));
}

BOOST_AUTO_TEST_CASE(smoothing_an_mcf_skeleton_without_radius_moves_its_interior_points_only)
{
  const Mcf_skeleton& original = mcf_of_cow().skeleton;
  Mcf_skeleton s = original;
  gs::smooth_skeleton(s); // the points only: the MCF skeleton has no radius
  const std::size_t n = num_vertices(s);
  std::size_t moved = 0;
  long checked = -1;
  for(std::size_t v = 0; v < n; ++v)
  {
    BOOST_TEST((s[v].vertices == original[v].vertices));
    if(boost::degree(v, s) != 2)
    {
      BOOST_TEST(s[v].point == original[v].point, "end or junction " << v << " stays");
      continue;
    }
    moved += s[v].point != original[v].point;
    // A point two steps or more from both ends of its branch averages the 5 around it.
    std::vector<std::size_t> window{v};
    bool inner = true;
    for(auto w : boost::make_iterator_range(boost::adjacent_vertices(v, s)))
    {
      std::size_t previous = v, current = std::size_t(w);
      window.push_back(current);
      inner = inner && boost::degree(current, s) == 2;
      if(!inner)
        break;
      for(auto x : boost::make_iterator_range(boost::adjacent_vertices(current, s)))
        if(std::size_t(x) != previous)
          window.push_back(std::size_t(x));
    }
    if(checked >= 0 || !inner || window.size() != 5 || std::set<std::size_t>(window.begin(), window.end()).size() != 5)
      continue;
    checked = long(v);
    double x = 0, y = 0, z = 0;
    for(std::size_t w : window)
    {
      x += original[w].point.x() / 5;
      y += original[w].point.y() / 5;
      z += original[w].point.z() / 5;
    }
    BOOST_TEST(distance(s[v].point, Point(x, y, z)) < 1e-12 * (1 + distance(Point(0, 0, 0), Point(x, y, z))));
  }
  BOOST_TEST(moved > 0u);
  BOOST_TEST(checked >= 0);
}

BOOST_AUTO_TEST_CASE(default_maps_given_explicitly_change_nothing_and_doubled_radii_double_the_joints_radii)
{
  using Vertex = gs::Curve_skeleton_vertex<Point, boost::graph_traits<Mesh>::vertex_descriptor>;
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  Control extracted;
  Mesh_skeleton curve;
  const gs::Control_skeleton_report report =
      gs::extract_control_skeleton(cow, extracted, gs::parameters::curve_skeleton_output(&curve));
  const std::size_t n = num_vertices(curve);
  BOOST_REQUIRE(n > 50u);

  // split_into_bones: the chain's own call, the call without maps and with the default
  // maps named give the same control skeleton.
  // The chain's settings of where joints go (not maps): its set-back and spacing.
  const auto placement = gs::parameters::combine(gs::parameters::tip_joint_setback(report.tip_joint_setback),
                                                 gs::parameters::joint_spacing(report.joint_spacing));
  Control by_default, with_maps;
  gs::split_into_bones(curve, by_default, placement);
  gs::split_into_bones(curve, with_maps,
                       gs::parameters::combine(gs::parameters::vertex_point_map(get(&Vertex::point, std::as_const(curve))),
                                               gs::parameters::mat_radius_map(get(&Vertex::radius, std::as_const(curve))),
                                               placement));
  BOOST_TEST(num_vertices(by_default) > 10u);
  BOOST_TEST(identical(by_default, extracted));
  BOOST_TEST(identical(by_default, with_maps));

  // smooth_skeleton: the same.
  Mesh_skeleton smoothed = curve, smoothed_with_maps = curve;
  gs::smooth_skeleton(smoothed);
  gs::smooth_skeleton(smoothed_with_maps,
                      gs::parameters::combine(gs::parameters::vertex_point_map(get(&Vertex::point, smoothed_with_maps)),
                                              gs::parameters::mat_radius_map(get(&Vertex::radius, smoothed_with_maps))));
  std::size_t changed = 0;
  for(std::size_t v = 0; v < n; ++v)
  {
    BOOST_TEST(smoothed[v].point == smoothed_with_maps[v].point);
    BOOST_TEST(smoothed[v].radius == smoothed_with_maps[v].radius);
    changed += smoothed[v].point != curve[v].point || smoothed[v].radius != curve[v].radius;
  }
  BOOST_TEST(changed > 0u); // a second smoothing still moves points: the comparison is not empty

  // Radii doubled: the same ends and junctions, each with twice the radius; the bends
  // (their lengths are in radii) move or go.
  std::vector<double> doubled(n);
  for(std::size_t v = 0; v < n; ++v)
    doubled[v] = 2 * curve[v].radius;
  // (Joints at the tips: a set-back tip moves with its bone, whose length the radii change.)
  Control twice, at_tips;
  gs::split_into_bones(curve, twice, gs::parameters::combine(gs::parameters::mat_radius_map(CGAL::make_property_map(doubled)), gs::parameters::tip_joint_setback(0.0)));
  gs::split_into_bones(curve, at_tips, gs::parameters::tip_joint_setback(0.0));
  check_tree(twice);
  BOOST_TEST(!identical(twice, at_tips));
  std::map<std::size_t, double> node_radius;
  for(const auto& j : test::joints(at_tips))
    if(j.kind != gs::Joint_kind::bend)
      node_radius[j.skeleton_vertex] = j.radius;
  std::size_t nodes = 0;
  for(const auto& j : test::joints(twice))
  {
    BOOST_TEST(j.radius == 2 * curve[j.skeleton_vertex].radius);
    if(j.kind == gs::Joint_kind::bend)
      continue;
    ++nodes;
    BOOST_REQUIRE(node_radius.count(j.skeleton_vertex) == 1u);
    BOOST_TEST(j.radius == 2 * node_radius[j.skeleton_vertex]);
    BOOST_TEST(j.radius > 0.0);
  }
  BOOST_TEST(nodes == node_radius.size());
  BOOST_TEST_MESSAGE("cow: " << num_vertices(at_tips) << " joints, " << num_vertices(twice)
                             << " with the radii doubled");
}

BOOST_AUTO_TEST_CASE(the_chain_reads_the_mesh_vertex_point_map_and_the_skeleton_maps_apart)
{
  // extract_control_skeleton() passes its named parameters on; the mesh's
  // vertex_point_map must not reach the curve-skeleton stages, whose keys are skeleton
  // vertices.
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  Control plain, with_mesh_map;
  gs::extract_control_skeleton(cow, plain);
  gs::extract_control_skeleton(cow, with_mesh_map, gs::parameters::vertex_point_map(get(CGAL::vertex_point, cow)));
  BOOST_TEST(!(num_vertices(plain) == 0));
  BOOST_TEST(identical(plain, with_mesh_map));
}

BOOST_AUTO_TEST_SUITE_END()
