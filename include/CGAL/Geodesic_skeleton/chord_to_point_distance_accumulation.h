// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CHORD_TO_POINT_DISTANCE_ACCUMULATION_H
#define CGAL_GEODESIC_SKELETON_CHORD_TO_POINT_DISTANCE_ACCUMULATION_H

/// \file chord_to_point_distance_accumulation.h
/// Han and Poston's chord-to-point distance accumulation (paper, equation 4), carried to
/// 3D polylines with chords of a fixed arc length.

#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Distance from p to the line through a and b (to a when a and b coincide).
inline double distance_to_line(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = sub(b, a), ap = sub(p, a);
  const double length = norm3(ab);
  if(!(length > 0))
    return norm3(ap);
  // Unit direction first: |ab x ap| squared is a 4th power of lengths, which overflows for
  // a skeleton about 1e77 across.
  return norm3(cross3(Vec3{ab[0] / length, ab[1] / length, ab[2] / length}, ap));
}

// A polyline parameterised by arc length, read at increasing arc lengths (each reader
// moves forward only, so a sweep over all points costs O(N) per reader). A closed
// polyline is unrolled over three laps so that arc lengths in [-S, 2S) can be read.
class Arc_length_polyline
{
public:
  Arc_length_polyline(const std::vector<Vec3>& points, bool closed)
  {
    const std::size_t n = points.size();
    if(!closed)
    {
      m_points = points;
      m_offset = 0;
    }
    else
    {
      for(int lap = 0; lap < 3; ++lap)
        for(std::size_t i = 0; i < n; ++i)
          m_points.push_back(points[i]);
      m_points.push_back(points[0]);
    }
    m_s.assign(m_points.size(), 0.0);
    for(std::size_t i = 1; i < m_points.size(); ++i)
      m_s[i] = m_s[i - 1] + norm3(sub(m_points[i], m_points[i - 1]));
    m_length = closed ? m_s[n] : m_s.back();
    if(closed)
      m_offset = m_length; // arc length 0 is the start of the middle lap
  }

  double length() const { return m_length; }

  struct Reader
  {
    const Arc_length_polyline* line;
    std::size_t segment = 0;
    // The point at arc length s (s never smaller than at the previous call).
    Vec3 at(double s)
    {
      const std::vector<double>& arc = line->m_s;
      const double u = s + line->m_offset;
      while(segment + 2 < arc.size() && arc[segment + 1] < u)
        ++segment;
      const double span = arc[segment + 1] - arc[segment];
      const double t = span > 0 ? std::clamp((u - arc[segment]) / span, 0.0, 1.0) : 0.0;
      const Vec3& a = line->m_points[segment];
      const Vec3& b = line->m_points[segment + 1];
      return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    }
  };
  Reader reader() const { return Reader{this, 0}; }

private:
  std::vector<Vec3> m_points;
  std::vector<double> m_s; // cumulative arc length of m_points
  double m_length = 0, m_offset = 0;
};

// The accumulation h(k) of every point of `p` (finite coordinates), `chords` + 1 chords of
// arc length L > 0 per point; a `closed` polyline links its last point back to its first.
template <typename OutputIterator>
OutputIterator chord_to_point_accumulation(const std::vector<Vec3>& p, double L, bool closed, int chords,
                                           OutputIterator out)
{
  if(p.empty())
    return out;
  const Arc_length_polyline line(p, closed);
  const double total = line.length();
  std::vector<Arc_length_polyline::Reader> chord_start(chords + 1, line.reader());
  std::vector<Arc_length_polyline::Reader> chord_end(chords + 1, line.reader());
  double s_k = 0;
  for(std::size_t k = 0; k < p.size(); ++k)
  {
    if(k > 0)
      s_k += norm3(sub(p[k], p[k - 1]));
    double sum = 0;
    int count = 0;
    for(int t = 0; t <= chords; ++t)
    {
      const double a = s_k - L + L * t / chords;
      const bool fits = closed ? (L < total) : (a >= -1e-12 * L && a + L <= total + 1e-12 * L);
      if(!fits)
        continue;
      sum += distance_to_line(p[k], chord_start[t].at(a), chord_end[t].at(a + L));
      ++count;
    }
    *out++ = count > 0 ? sum / (L * count) : 0.0;
  }
  return out;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Computes the chord-to-point distance accumulation of Han and Poston (paper, equation 4)
/// at every point of a 3D polyline, with chords of a fixed *arc length* instead of a fixed
/// number of points (the paper's "geodesic instead of Euclidean"), so that the result does
/// not depend on how densely the polyline is sampled, nor on rotation, translation or
/// scale.
///
/// For the point p_k at arc length s_k, the chords are the segments from P(a) to P(a + L)
/// for `number_of_chords` + 1 starting arc lengths a evenly spread over [s_k - L, s_k]
/// (P(s) is the point of the polyline at arc length s): the chords that span p_k, as i runs
/// from k-L to k in equation 4. D is the unsigned distance from p_k to the line of a chord
/// (in 3D there is no signed "left side"). The value written for p_k is
///
///     h(k) = (1 / (L * c)) * sum of D over the c chords that lie on the polyline,
///
/// the mean distance in units of the chord length: 0 where the polyline is straight over
/// a length L around p_k; at a corner whose arms are longer than L, the mean of
/// x (1 - x) sin(t) / |chord| over the c + 1 values x = 0, 1/c, ..., 1 for a turn by the
/// angle t: with the default 16 + 1 chords, 0.054 for 20 degrees, 0.080 for 30, 0.118 for
/// 45, 0.204 for a right angle (about 16/17 of the mean over all x in [0, 1], 0.058,
/// 0.080 at 28 degrees, 0.126 and 0.217, which it tends to as c grows); and 0 when no
/// chord fits (an open polyline shorter than L). On an open polyline chords that would run
/// past an end are left out; a closed polyline (whose last point repeats its first, as
/// CGAL's polylines do) wraps around.
///
/// \tparam PointRange a range of CGAL 3D points (with `x()`, `y()`, `z()`).
/// \tparam OutputIterator an output iterator accepting `double`.
/// \param points the polyline, in order; when it has at least 3 points and the last equals
///        the first, it is closed, and the last point's value is the first's.
/// \param chord_length L, in the polyline's units; finite and positive.
/// \param out receives one value per point, in order.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_chords}
///     \cgalParamDescription{c + 1 chords are sampled per point, c in [1, 1000] (package
///                           parameter)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{16}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the output iterator after the last value.
/// \throws std::invalid_argument when L is not finite and positive, c is out of range, or
///         a coordinate is not finite.
///
/// \b Complexity: O(N c) for N points (each chord position is read by a reader that only
/// moves forward), O(N) memory; O(N) for a fixed c.
template <typename PointRange, typename OutputIterator,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator chord_to_point_distance_accumulation(const PointRange& points, double chord_length,
                                                    OutputIterator out,
                                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int chords = internal::checked_parameter(
      parameter_ranges::number_of_chords,
      choose_parameter(get_parameter(np, internal_np::number_of_chords_tag),
                       static_cast<int>(parameter_ranges::number_of_chords.default_value)),
      "chord_to_point_distance_accumulation");
  if(!(chord_length > 0) || !std::isfinite(chord_length))
    throw std::invalid_argument("chord_to_point_distance_accumulation: the chord length must be "
                                "finite and positive");

  std::vector<internal::Vec3> p;
  for(const auto& q : points)
  {
    p.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
    for(double c : p.back())
      if(!std::isfinite(c))
        throw std::invalid_argument("chord_to_point_distance_accumulation: a point has a "
                                    "non-finite coordinate");
  }
  // A closed polyline repeats its first point last: the accumulation wraps around, and the
  // repeated point gets the first point's value.
  const bool closed = p.size() >= 3 && p.front() == p.back();
  if(closed)
    p.pop_back();
  std::vector<double> h;
  internal::chord_to_point_accumulation(p, chord_length, closed, chords, std::back_inserter(h));
  if(closed)
    h.push_back(h.front());
  return std::copy(h.begin(), h.end(), out);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CHORD_TO_POINT_DISTANCE_ACCUMULATION_H
