// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_BONE_SPLITTING_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_BONE_SPLITTING_H

// The recursive split of one branch of a curve skeleton into bones (paper, III.B.ii).

#include <CGAL/Geodesic_skeleton/chord_to_point_distance_accumulation.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The longest chord of the accumulation in a part of a branch, in lengths of the part: a
// chord of `chord_length_factors` radii is shortened to half the part, so that a part
// shorter than the chords still gets an accumulation around its middle (a chord longer
// than the part fits nowhere in it and gives none).
constexpr double longest_chord_in_part_lengths = 0.5;

// The most bones the cut of its long straight parts gives a branch: a limb has three or
// four, and a shape whose thickest part is thin (a plate, a strip, a cape alone) would
// otherwise get a bone every few thicknesses. A straight part gets its share, in
// proportion to its length: a cut at a bend or a stray near the tip of a strip would
// otherwise give the short part as many bones again.
constexpr std::size_t most_bones_per_branch = 4;

struct Bone_splitting_settings
{
  double bend_threshold;           // CPDA value (in chord lengths) that makes a bend a joint
  double straightness_tolerance;   // allowed deviation from the chord, in MAT radii (at least the level of detail's)
  double minimum_bone_length_factor; // shortest bone, in MAT radii
  double maximum_bone_length_factor; // longest straight bone, in largest MAT radii of the piece (0: no limit)
  std::vector<double> chord_length_factors; // CPDA chord lengths, in MAT radii
  double smallest_radius = 0;               // radii below it count as it in every length (world units)
  double minimum_bone_length_of_piece_factor = 0; // shortest bone, in largest MAT radii of the piece
  double tip_joint_setback = 0; // a tip's joint sits this share of its bone's length back from the tip
  double joint_spacing = 0;     // bones are cut into lengths of about this (world units; 0: not cut)
};

class Branch_splitter
{
public:
  // `largest_radius`: the largest MAT radius of the skeleton's piece that the branch is in.
  Branch_splitter(const std::vector<Vec3>& points, const std::vector<double>& radii,
                  const Bone_splitting_settings& settings, double largest_radius)
    : m_p(points), m_r(radii), m_settings(settings), m_s(points.size(), 0.0),
      m_longest_bone(settings.maximum_bone_length_factor * largest_radius),
      m_shortest_of_piece(settings.minimum_bone_length_of_piece_factor * largest_radius)
  {
    for(std::size_t i = 1; i < m_p.size(); ++i)
      m_s[i] = m_s[i - 1] + norm3(sub(m_p[i], m_p[i - 1]));
  }

  // The arc length from the branch's first point to each of its points.
  const std::vector<double>& arc_lengths() const { return m_s; }

  // The indices where the branch is cut into bones, from 0 to N-1 included, increasing.
  std::vector<std::size_t> joints()
  {
    std::vector<std::size_t> cuts{0};
    if(m_p.size() >= 2)
    {
      split(0, m_p.size() - 1, cuts);
      cuts.push_back(m_p.size() - 1);
    }
    return cuts;
  }

private:
  // The branch's points come from the curve skeleton in world coordinates, so a
  // mirror-symmetric branch has pairs of points whose bends or deviations are equal up to
  // the rounding of the mesh's placement: the first of such a pair (in the branch's order,
  // which the voxels fix) wins, by clearly_greater(), whatever the rigid motion.

  double mean_radius(std::size_t i, std::size_t j) const
  {
    double sum = 0;
    for(std::size_t k = i; k <= j; ++k)
      sum += m_r[k];
    const double r = sum / static_cast<double>(j - i + 1);
    // A skeleton without radii still splits, at a scale tied to its length.
    return std::max(r, 1e-6 * std::max(m_s.back(), 1e-300));
  }

  // The shortest bone of a part of mean radius `radius`: `minimum_bone_length_factor` radii,
  // and no shorter than the level of detail of the piece. A thin part near a tip (a hoof, a
  // finger tip, a tail) is measured in its own small radius, and a finer grid resolves
  // bends there that a coarser one smooths away: bones shorter than a fraction of the
  // piece's thickness would come and go with the resolution.
  double shortest_bone(double radius) const
  {
    return (std::max)(m_settings.minimum_bone_length_factor * radius, m_shortest_of_piece);
  }

  // How far a part of mean radius `radius` may stray from its chord and stay one bone:
  // `straightness_tolerance` radii, the radius taken as at least that of the piece's level
  // of detail (the radius whose shortest bone is the piece's, a quarter of its largest MAT
  // radius by default). Like the shortest bone: in its own small radius, a thin part (a
  // leg, a wall, a lens) strays by more than the tolerance wherever a finer grid resolves
  // a wave that a coarser one smooths away.
  double straightness_tolerance(double radius) const
  {
    const double level_of_detail_radius = m_settings.minimum_bone_length_factor > 0
                                              ? m_shortest_of_piece / m_settings.minimum_bone_length_factor
                                              : 0.0;
    return m_settings.straightness_tolerance * (std::max)(radius, level_of_detail_radius);
  }

  // Whether a bone `length` long is longer than the shortest bone: clearly, so that a part
  // exactly twice the shortest bone long, which a shape aligned with the grid gives (an
  // arm of a cross 26 voxels long with a radius of 6.5), stays whole whatever the rounding,
  // as it does at any other placement of the shape.
  static bool longer_than_shortest(double length, double shortest) { return clearly_greater(length, shortest); }

  // Appends the inner cut points of [i, j] to `cuts`, in increasing order.
  void split(std::size_t i, std::size_t j, std::vector<std::size_t>& cuts)
  {
    if(j <= i + 1)
      return;
    const double radius = mean_radius(i, j);
    const double shortest = shortest_bone(radius);
    // Candidates: the inner points that leave both parts longer than `shortest`.
    std::vector<std::size_t> candidates;
    for(std::size_t k = i + 1; k < j; ++k)
      if(longer_than_shortest(m_s[k] - m_s[i], shortest) && longer_than_shortest(m_s[j] - m_s[k], shortest))
        candidates.push_back(k);
    if(candidates.empty())
      return;

    // The accumulation at each point of the part, averaged over the chord lengths.
    const std::vector<Vec3> part(m_p.begin() + i, m_p.begin() + j + 1);
    const double part_length = m_s[j] - m_s[i];
    std::vector<double> bend(part.size(), 0.0);
    for(double factor : m_settings.chord_length_factors)
    {
      const double L = std::min(factor * radius, longest_chord_in_part_lengths * part_length);
      if(!(L > 0))
        continue;
      std::vector<double> h;
      chord_to_point_accumulation(part, L, false, static_cast<int>(parameter_ranges::number_of_chords.default_value),
                                  std::back_inserter(h));
      for(std::size_t k = 0; k < h.size(); ++k)
        bend[k] += h[k] / static_cast<double>(m_settings.chord_length_factors.size());
    }

    std::size_t best = candidates.front();
    for(std::size_t k : candidates)
      if(clearly_greater(bend[k - i], bend[best - i]))
        best = k;
    if(bend[best - i] < m_settings.bend_threshold)
    {
      // No marked bend: keep the part as one bone if it is straight enough, else cut it
      // where it strays farthest from its chord.
      double deviation = -1;
      for(std::size_t k : candidates)
      {
        const double d = distance_to_segment(m_p[k], m_p[i], m_p[j]);
        if(deviation < 0 || clearly_greater(d, deviation))
        {
          deviation = d;
          best = k;
        }
      }
      if(deviation <= straightness_tolerance(radius))
      {
        subdivide(i, j, shortest, cuts);
        return;
      }
    }
    split(i, best, cuts);
    cuts.push_back(best);
    split(best, j, cuts);
  }

  // The bones that a straight part `length` long may be cut into: its share of
  // `most_bones_per_branch`, in proportion to its length, rounded up (a share that is a
  // whole number to rounding stays that number).
  double share_of_most_bones(double length) const
  {
    const double share = double(most_bones_per_branch) * length / m_s.back();
    return std::ceil(share - 1e-9 * share);
  }

  // A straight part longer than the longest bone (`maximum_bone_length_factor` times the
  // largest MAT radius of the piece: the body's thickness, so that a thin limb gets as
  // many bones as a thick one of the same length): cut it into n bones of about equal
  // length, n the fewest that are short enough (at most the part's share of
  // `most_bones_per_branch`, rounded up, and few enough that each is longer than
  // `shortest`, the part's shortest_bone()), each cut at
  // the narrowest point (the smallest MAT radius, where an elbow, a knee or a wrist is)
  // within a quarter of a bone's length of its equal-length position, ties to the nearest
  // that position.
  void subdivide(std::size_t i, std::size_t j, double shortest, std::vector<std::size_t>& cuts) const
  {
    const double longest = m_longest_bone;
    const double length = m_s[j] - m_s[i];
    if(!(longest > 0) || length <= longest)
      return;
    double bones = std::min(std::ceil(length / longest), share_of_most_bones(length));
    while(bones > 1 && !longer_than_shortest(length / bones, shortest))
      --bones;
    const std::size_t n = bones >= 2 ? std::size_t(bones) : 1;
    const double bone = length / double(n);
    std::size_t previous = i;
    for(std::size_t c = 1; c < n; ++c)
    {
      const double target = m_s[i] + bone * double(c);
      std::size_t best = j;
      for(std::size_t k = previous + 1; k < j; ++k)
      {
        if(std::abs(m_s[k] - target) > bone / 4 || !longer_than_shortest(m_s[k] - m_s[previous], shortest) ||
           !longer_than_shortest(m_s[j] - m_s[k], shortest))
          continue;
        if(best == j || narrower(k, best, target, bone))
          best = k;
      }
      if(best == j)
        continue;
      cuts.push_back(best);
      previous = best;
    }
  }

  // Whether point k is a better cut than point `best` for a cut at arc length `target`:
  // narrower, or as narrow and nearer. Values equal up to rounding (relative, 1e-9) are
  // equal: the smoothed radii of a straight bar of constant thickness differ only in their
  // last bits, which a scaling of the mesh would change, and with them the cut.
  bool narrower(std::size_t k, std::size_t best, double target, double bone) const
  {
    const double radius_rounding = 1e-9 * std::max(m_r[k], m_r[best]);
    if(m_r[k] < m_r[best] - radius_rounding)
      return true;
    return m_r[k] <= m_r[best] + radius_rounding &&
           std::abs(m_s[k] - target) < std::abs(m_s[best] - target) - 1e-9 * bone;
  }

  const std::vector<Vec3>& m_p;
  const std::vector<double>& m_r;
  const Bone_splitting_settings& m_settings;
  std::vector<double> m_s;
  double m_longest_bone;
  double m_shortest_of_piece; // no bone shorter, whatever its radius: the rig's level of detail
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_BONE_SPLITTING_H
