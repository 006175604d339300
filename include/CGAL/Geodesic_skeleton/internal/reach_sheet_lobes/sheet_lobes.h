// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_REACH_SHEET_LOBES_SHEET_LOBES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_REACH_SHEET_LOBES_SHEET_LOBES_H

// The search of reach_sheet_lobes(): the thick medial sheet joined to the skeleton, the
// sheet voxels out of reach of the skeleton's balls, and the medial paths from the lobes'
// tips to the skeleton.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/medial_path_search.h>
#include <CGAL/Geodesic_skeleton/internal/thin/grassfire.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// One search of reach_sheet_lobes() over the box of the distance field: labels per box voxel
// (skeleton, sheet, not sheet), the sheet grown from the skeleton, and a path search whose
// arrays are allocated once, when some lobe is out of reach.
template <typename VoxelDistanceField>
class Sheet_lobe_search
{
public:
  // `layout` is that of the field's box, `padded` the same box grown by ridge_reach_in_steps.
  Sheet_lobe_search(const VoxelDistanceField& distances, const Grid_layout& layout, const Grid_layout& padded,
                    std::uint32_t largest_thin_d2)
      : m_distances(distances), m_layout(layout), m_padded(padded), m_largest_thin_d2(largest_thin_d2),
        m_label(layout.volume(), unvisited), m_padded_d2(distances_over(distances, padded)),
        m_padded_offsets(padded.neighbour_offsets()), m_step_lengths(neighbour_step_lengths())
  {
  }

  template <typename VoxelSet>
  void run(VoxelSet& skeleton, double reach_factor, std::size_t& sheet_voxels, std::size_t& lobes,
           std::size_t& voxels_added)
  {
    label_skeleton_pieces(skeleton);
    const std::vector<std::uint32_t> sheet = grow_sheet_from_skeleton();
    sheet_voxels = sheet.size();
    std::vector<Out_of_reach> out = out_of_reach(sheet, reach_factor);
    while(!out.empty())
    {
      // The farthest in units of its piece's radius; ties to the smallest key.
      const auto tip = std::max_element(out.begin(), out.end(), [&](const Out_of_reach& a, const Out_of_reach& b) {
        const double ra = a.reach / m_largest_radius[piece_of(a.voxel)];
        const double rb = b.reach / m_largest_radius[piece_of(b.voxel)];
        return ra < rb || (ra == rb && m_layout.key(b.voxel) < m_layout.key(a.voxel));
      });
      const std::vector<std::uint32_t> path = medial_path_to_skeleton(tip->voxel);
      if(path.empty()) // cannot happen: the sheet voxel is joined to the skeleton through the solid
      {
        out.erase(tip);
        continue;
      }
      ++lobes;
      for(std::uint32_t v : path)
      {
        skeleton.insert(m_layout.key(v));
        m_label[v] = skeleton_label;
        ++voxels_added;
      }
      still_out_of_reach(out, path, reach_factor);
    }
  }

private:
  static constexpr std::int32_t unvisited = -1, not_sheet = -2, skeleton_label = -3;

  struct Out_of_reach
  {
    std::uint32_t voxel;
    double reach; // min over skeleton voxels t of |s - t| - r(t), in voxels
  };

  // The skeleton piece that sheet voxel v grew from.
  std::int32_t piece_of(std::uint32_t v) const { return m_sheet_piece[v]; }

  double radius(const Voxel_key& k) const { return std::sqrt(double(m_distances.squared_distance(k))); }

  static double reach_from(const Voxel_key& s, const Voxel_key& t, double radius_t)
  {
    const double dx = s.x - t.x, dy = s.y - t.y, dz = s.z - t.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz) - radius_t;
  }

  // The skeleton's voxels, its 26-connected pieces and their largest MAT radii.
  template <typename VoxelSet>
  void label_skeleton_pieces(const VoxelSet& skeleton)
  {
    skeleton.for_each([&](const Voxel_key& k) {
      if(m_layout.box.contains(k))
        m_skeleton.push_back(k);
    });
    // In key order, so that the sheet grows, and its voxels take their pieces, whatever the
    // set's iteration order.
    std::sort(m_skeleton.begin(), m_skeleton.end());
    std::vector<std::size_t> piece;
    const std::size_t pieces =
        voxel_components(m_skeleton, [&](const Voxel_key& k) { return skeleton.contains(k); }, piece);
    m_largest_radius.assign(pieces, 0.);
    m_skeleton_radius.resize(m_skeleton.size());
    for(std::size_t i = 0; i < m_skeleton.size(); ++i)
    {
      m_skeleton_radius[i] = radius(m_skeleton[i]);
      m_largest_radius[piece[i]] = (std::max)(m_largest_radius[piece[i]], m_skeleton_radius[i]);
      const std::uint32_t v = std::uint32_t(m_layout.index(m_skeleton[i]));
      m_label[v] = skeleton_label;
      m_piece_of_skeleton_voxel.emplace_back(v, std::int32_t(piece[i]));
    }
    for(double& r : m_largest_radius)
      r = (std::max)(r, 1.);
  }

  // Whether voxel k of the field's box is a centre of maximal ball as thinning judges a
  // curve's end (the thinning's own test, at tip_growth_when_choosing).
  bool on_medial_sheet(const Voxel_key& k) const
  {
    return centre_of_maximal_ball(m_padded_d2.data(), m_padded.index(k), m_padded_offsets, m_step_lengths,
                                  tip_growth_when_choosing);
  }

  // The thick medial sheet joined to the skeleton (26-adjacency, breadth first from the
  // skeleton's voxels), each voxel labelled with the skeleton piece it grew from.
  std::vector<std::uint32_t> grow_sheet_from_skeleton()
  {
    m_sheet_piece.assign(m_layout.volume(), -1);
    std::vector<std::uint32_t> queue, sheet;
    for(const auto& [v, piece] : m_piece_of_skeleton_voxel)
    {
      m_sheet_piece[v] = piece;
      queue.push_back(v);
    }
    for(std::size_t head = 0; head < queue.size(); ++head)
    {
      const Voxel_key k = m_layout.key(queue[head]);
      for(const Voxel_key& o : neighbourhood_26())
      {
        const Voxel_key n = k + o;
        if(!m_layout.box.contains(n))
          continue;
        const std::uint32_t j = std::uint32_t(m_layout.index(n));
        if(m_label[j] != unvisited)
          continue;
        const std::uint32_t d2 = m_distances.squared_distance(n);
        if(d2 <= m_largest_thin_d2 || !on_medial_sheet(n))
        {
          m_label[j] = not_sheet;
          continue;
        }
        m_label[j] = 0;
        m_sheet_piece[j] = m_sheet_piece[queue[head]];
        queue.push_back(j);
        sheet.push_back(j);
      }
    }
    return sheet;
  }

  double threshold(std::uint32_t v, double reach_factor) const { return reach_factor * m_largest_radius[piece_of(v)]; }

  // The sheet voxels out of the skeleton's balls by at least their threshold.
  std::vector<Out_of_reach> out_of_reach(const std::vector<std::uint32_t>& sheet, double reach_factor) const
  {
    std::vector<Out_of_reach> out;
    // The sheet comes breadth first, so the ball that brought a voxel within reach most
    // often does so for the next one too: it is tried first.
    std::size_t last_cover = 0;
    for(std::uint32_t v : sheet)
    {
      const Voxel_key s = m_layout.key(v);
      const double least = threshold(v, reach_factor);
      double reach = reach_from(s, m_skeleton[last_cover], m_skeleton_radius[last_cover]);
      for(std::size_t i = 0; i < m_skeleton.size() && reach >= least; ++i)
      {
        reach = (std::min)(reach, reach_from(s, m_skeleton[i], m_skeleton_radius[i]));
        if(reach < least)
          last_cover = i;
      }
      if(reach >= least)
        out.push_back({v, reach});
    }
    return out;
  }

  // Drops the voxels that the balls of the path's voxels bring within reach.
  void still_out_of_reach(std::vector<Out_of_reach>& out, const std::vector<std::uint32_t>& path,
                          double reach_factor) const
  {
    std::vector<Voxel_key> keys;
    std::vector<double> radii;
    for(std::uint32_t v : path)
    {
      keys.push_back(m_layout.key(v));
      radii.push_back(radius(keys.back()));
    }
    for(Out_of_reach& o : out)
    {
      const Voxel_key s = m_layout.key(o.voxel);
      for(std::size_t i = 0; i < keys.size(); ++i)
        o.reach = (std::min)(o.reach, reach_from(s, keys[i], radii[i]));
    }
    out.erase(std::remove_if(out.begin(), out.end(),
                             [&](const Out_of_reach& o) { return o.reach < threshold(o.voxel, reach_factor); }),
              out.end());
  }

  // The path of least sum of step length / r^2 through the solid from `tip` to the first
  // skeleton voxel (excluded), from that voxel's neighbour back to `tip`: along the middle of
  // the plate, where the balls are largest.
  std::vector<std::uint32_t> medial_path_to_skeleton(std::uint32_t tip)
  {
    auto on_skeleton = [&](const Voxel_key& k) { return m_label[m_layout.index(k)] == skeleton_label; };
    auto step_cost = [&](const Voxel_key&, std::uint8_t o, const Voxel_key& next, std::size_t) {
      const std::uint32_t d2 = m_distances.squared_distance(next); // 0 outside the solid
      return d2 == 0 ? std::nullopt : std::optional<double>(m_step_lengths[o] / double(d2));
    };
    const std::vector<Voxel_key> keys =
        m_search.cheapest_path(m_layout, m_layout.key(tip), on_skeleton, step_cost, [](const Voxel_key&) { return 0.; });
    std::vector<std::uint32_t> path;
    for(std::size_t i = keys.size(); i-- > 1;)
      path.push_back(std::uint32_t(m_layout.index(keys[i - 1])));
    return path;
  }

  const VoxelDistanceField& m_distances;
  const Grid_layout& m_layout;
  const Grid_layout& m_padded;
  std::uint32_t m_largest_thin_d2;
  std::vector<std::int32_t> m_label;       // by box voxel: unvisited, not_sheet, skeleton_label, or 0 (sheet)
  std::vector<std::int32_t> m_sheet_piece; // by box voxel: the skeleton piece a sheet voxel grew from
  std::vector<std::pair<std::uint32_t, std::int32_t>> m_piece_of_skeleton_voxel; // (box index, piece)
  std::vector<Voxel_key> m_skeleton;
  std::vector<double> m_skeleton_radius;
  std::vector<double> m_largest_radius; // by skeleton piece, at least 1
  std::vector<std::uint32_t> m_padded_d2; // the squared distances over the padded box
  std::array<std::ptrdiff_t, 26> m_padded_offsets;
  std::array<double, 26> m_step_lengths;
  Medial_path_search<double> m_search;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_REACH_SHEET_LOBES_SHEET_LOBES_H
