// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_PEEL_SURFACE_VOXELS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_PEEL_SURFACE_VOXELS_H

// The second half of voxelize(): which of the voxels that the outside flood did not reach
// have their centre inside the mesh (winding numbers counted along grid lines), and which
// of the others can leave the solid without losing a thin part (see voxelize()'s doc).

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/principal_frame.h>
#include <CGAL/Geodesic_skeleton/internal/thin/simple_point.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Labels of the voxelization grid. EMPTY, SURFACE and OUTSIDE come from the rasterisation
// and the flood; FAN marks the voxels met only by hole-filling triangles. The peeling then
// uses CORE (kept for sure), CANDIDATE (centre outside the mesh, may leave), REMOVED,
// NEAR_1 / NEAR_2 (candidates one or two 26-steps from the core), FAR (candidates kept as
// thin parts) and, from VISITED on, near candidates reached by the linking search (the
// value minus VISITED is the search depth).
enum Voxel_label : std::uint8_t {
  EMPTY = 0, SURFACE = 1, OUTSIDE = 2, FAN = 3, CORE = 4, CANDIDATE = 5, REMOVED = 6,
  NEAR_1 = 7, NEAR_2 = 8, FAR = 9, KEEP = 10, CORE_SURFACE = 11, VISITED = 16
};

// One signed crossing of a grid line by a triangle: the line's number, the coordinate of
// the crossing along the line (in voxels) and +1 or -1 by the side the triangle faces.
struct Line_crossing
{
  std::uint32_t line;
  float at;
  std::int8_t sign;
};

// Adds to `votes` one vote per voxel that is neither OUTSIDE nor FAN and lies on a grid
// line parallel to `axis` whose crossings sum to zero (a line that only meets closed,
// consistently oriented surfaces): "inside" (bits 0-1) when the winding number of the
// surface around the voxel's centre is not zero, "outside" (bits 2-3) otherwise. The
// winding number is the signed count of the crossings before the centre along the line;
// `g` holds the triangles in grid coordinates. A line through a shared edge counts it once
// (edge functions computed the same way for both triangles, ties broken by the edge's
// direction); a line with a non-zero sum (an open border, a flipped face) votes nothing.
inline bool vote_along_lines(const std::vector<std::array<Vec3, 3>>& g, int axis,
                             const Grid_layout& layout, const std::vector<std::uint8_t>& labels,
                             std::vector<std::uint8_t>& votes)
{
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  const std::size_t n[3] = {layout.nx, layout.ny, layout.nz};
  const std::size_t stride[3] = {1, layout.nx, layout.nx * layout.ny};
  const std::size_t nb = n[b], nc = n[c], na = n[axis];
  std::vector<Line_crossing> crossings;
  crossings.reserve(g.size() * 2);
  for(const auto& t : g)
  {
    const Projected_triangle pt(t, axis);
    if(!pt.crossable())
      continue;
    const double* u = pt.u;
    const double* v = pt.v;
    const int from_u = (std::max)(0, int(std::ceil((std::min)({u[0], u[1], u[2]}) - 0.5)));
    const int to_u = (std::min)(int(nb) - 1, int(std::floor((std::max)({u[0], u[1], u[2]}) - 0.5)));
    const int from_v = (std::max)(0, int(std::ceil((std::min)({v[0], v[1], v[2]}) - 0.5)));
    const int to_v = (std::min)(int(nc) - 1, int(std::floor((std::max)({v[0], v[1], v[2]}) - 0.5)));
    for(int jv = from_v; jv <= to_v; ++jv)
      for(int ju = from_u; ju <= to_u; ++ju)
      {
        double at;
        if(pt.crossing(ju + 0.5, jv + 0.5, at))
          crossings.push_back(Line_crossing{std::uint32_t(std::size_t(jv) * nb + std::size_t(ju)),
                                            float(at), std::int8_t(pt.sign())});
      }
  }
  // Bucket the crossings by line (counting sort), then order each line's crossings.
  std::vector<std::uint32_t> start(nb * nc + 1, 0);
  for(const Line_crossing& x : crossings)
    ++start[x.line + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Line_crossing> sorted(crossings.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for(const Line_crossing& x : crossings)
      sorted[fill[x.line]++] = x;
  }
  const std::uint8_t inside_vote = 1, outside_vote = 4;
  bool all_trusted = true;
  for(std::size_t line = 0; line < nb * nc; ++line)
  {
    const std::uint32_t first = start[line], last = start[line + 1];
    int total = 0;
    for(std::uint32_t k = first; k < last; ++k)
      total += sorted[k].sign;
    const std::size_t ju = line % nb, jv = line / nb;
    const std::size_t base = ju * stride[b] + jv * stride[c];
    if(total != 0)
    {
      all_trusted = false;
      continue;
    }
    std::sort(sorted.begin() + first, sorted.begin() + last,
              [](const Line_crossing& x, const Line_crossing& y) { return x.at < y.at; });
    std::uint32_t k = first;
    int winding = 0;
    for(std::size_t ja = 0; ja < na; ++ja)
    {
      const std::size_t i = base + ja * stride[axis];
      if(labels[i] != EMPTY && labels[i] != SURFACE)
        continue;
      const float centre = float(ja) + 0.5f;
      while(k < last && sorted[k].at < centre)
        winding += sorted[k++].sign;
      votes[i] += winding != 0 ? inside_vote : outside_vote;
    }
  }
  return all_trusted;
}

// The votes of every voxel neither OUTSIDE nor FAN on whether its centre is inside the
// mesh (vote_along_lines(): "inside" in bits 0-1, "outside" in bits 2-3), along x, and
// along y and z when an x line abstains.
inline std::vector<std::uint8_t> centre_votes(const std::vector<std::array<Vec3, 3>>& g, const Grid_layout& layout,
                                              const std::vector<std::uint8_t>& labels)
{
  std::vector<std::uint8_t> votes(layout.volume(), 0);
  if(!vote_along_lines(g, 0, layout, labels, votes))
    for(int axis = 1; axis < 3; ++axis)
      vote_along_lines(g, axis, layout, labels, votes);
  return votes;
}

// Whether the surface encloses the centre of some voxel it touches (more "inside" than
// "outside" votes) while the flood found no centre inside it: a closed mesh thinner than
// about two voxels (a plate, a wing), all of whose voxels its surface touches, does; an open
// sheet does not, nor an open tube, whose hollow the flood filled through its openings
// although the lines across it count it inside.
inline bool thin_closed_surface_encloses_centres(const std::vector<std::array<Vec3, 3>>& g,
                                                 const Grid_layout& layout, const std::vector<std::uint8_t>& labels)
{
  std::vector<std::uint8_t> voting = labels; // the flooded voxels voted on too
  std::replace(voting.begin(), voting.end(), std::uint8_t(OUTSIDE), std::uint8_t(EMPTY));
  // Lines along all three axes: a leak may show across a hollow only (an open tube's
  // lines along its axis cross nothing).
  std::vector<std::uint8_t> votes(layout.volume(), 0);
  for(int axis = 0; axis < 3; ++axis)
    vote_along_lines(g, axis, layout, voting, votes);
  bool surface_centre_inside = false;
  for(std::size_t i = 0; i < votes.size(); ++i)
    if((votes[i] & 3) > (votes[i] >> 2))
    {
      if(labels[i] == OUTSIDE)
        return false; // the flood reached a centre that the surface encloses: it leaks
      surface_centre_inside = surface_centre_inside || labels[i] == SURFACE;
    }
  return surface_centre_inside;
}

// The local tests of the peeling are those of the simple-point test
// (internal/thin/simple_point.h): Simple_point_test::background_is_one_piece() (T6 = 1: no
// cavity or tunnel opened) and Simple_point_test::object_is_split() (T26 >= 2). Removals
// that pass the first may still disconnect the object or cut a handle: those are the
// removals peel_surface_voxels wants, and it restores the connections it must keep.

// Turns the labels left by the flood (EMPTY, SURFACE, FAN, OUTSIDE) into the solid: on
// return, a voxel is in the solid iff its label is neither OUTSIDE nor REMOVED. `g` holds
// the mesh's triangles, hole-filling fans included, in grid coordinates. The rule is the
// one of voxelize()'s documentation:
//   1. each EMPTY or SURFACE voxel gets votes (vote_along_lines: lines along x, and along
//      y and z when an x line abstains): CANDIDATE when the "outside" votes win, CORE or
//      CORE_SURFACE otherwise (ties and voxels without any vote stay); FAN voxels are CORE;
//   2. candidates not 26-connected to OUTSIDE through candidates are CORE (cavities);
//   3. candidates 26-adjacent to the core are NEAR_1, their candidate neighbours NEAR_2,
//      the others FAR (thin parts: kept);
//   4. near candidates leave while the background around them stays one piece; then the
//      CORE_SURFACE cut points (T26 >= 2, T6 = 1) leave;
//   5. the removed voxels that link components of the rest which the solid linked come
//      back (shortest links first, Kruskal over the meeting points of a breadth-first
//      search from all those components at once);
//   6. removed candidates with three face neighbours or more in the solid come back (two
//      passes: dents).
inline void peel_surface_voxels(const std::vector<std::array<Vec3, 3>>& g, const Grid_layout& layout,
                                std::vector<std::uint8_t>& labels)
{
  const std::size_t volume = layout.volume();
  const std::array<std::ptrdiff_t, 26> offsets = layout.neighbour_offsets();
  // The margin of the grid is OUTSIDE, so neighbours of non-OUTSIDE voxels are in the box.

  // 1. Votes.
  std::vector<std::uint8_t> votes = centre_votes(g, layout, labels);
  std::vector<std::uint32_t> candidates;
  for(std::size_t i = 0; i < volume; ++i)
  {
    std::uint8_t& l = labels[i];
    if(l == OUTSIDE)
      continue;
    if(l == FAN)
    {
      l = CORE;
      continue;
    }
    const int in = votes[i] & 3, out = votes[i] >> 2;
    if(out > in)
    {
      l = CANDIDATE;
      candidates.push_back(std::uint32_t(i));
    }
    else
      l = l == SURFACE ? CORE_SURFACE : CORE;
  }
  votes.clear();
  votes.shrink_to_fit();
  if(candidates.empty())
    return;

  // 2. Candidates reached from OUTSIDE through candidates become REMOVED for now.
  std::vector<std::uint32_t> stack;
  for(std::uint32_t i : candidates)
    for(std::ptrdiff_t o : offsets)
      if(labels[std::size_t(std::ptrdiff_t(i) + o)] == OUTSIDE)
      {
        labels[i] = REMOVED;
        stack.push_back(i);
        break;
      }
  while(!stack.empty())
  {
    const std::size_t i = stack.back();
    stack.pop_back();
    for(std::ptrdiff_t o : offsets)
    {
      const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
      if(labels[j] == CANDIDATE)
      {
        labels[j] = REMOVED;
        stack.push_back(std::uint32_t(j));
      }
    }
  }
  std::size_t kept = 0;
  for(std::uint32_t i : candidates)
    if(labels[i] == CANDIDATE)
      labels[i] = CORE;
    else
      candidates[kept++] = i;
  candidates.resize(kept);
  if(candidates.empty())
    return;

  // 3. Distance to the core, capped: NEAR_1, NEAR_2, FAR.
  std::vector<std::uint32_t> near;
  for(std::uint32_t i : candidates)
    for(std::ptrdiff_t o : offsets)
      if(labels[std::size_t(std::ptrdiff_t(i) + o)] == CORE ||
         labels[std::size_t(std::ptrdiff_t(i) + o)] == CORE_SURFACE)
      {
        labels[i] = NEAR_1;
        near.push_back(i);
        break;
      }
  const std::size_t first_ring = near.size();
  for(std::size_t n = 0; n < first_ring; ++n)
    for(std::ptrdiff_t o : offsets)
    {
      const std::size_t j = std::size_t(std::ptrdiff_t(near[n]) + o);
      if(labels[j] == REMOVED)
      {
        labels[j] = NEAR_2;
        near.push_back(std::uint32_t(j));
      }
    }
  for(std::uint32_t i : candidates)
    if(labels[i] == REMOVED)
      labels[i] = FAR;
  std::size_t first_cut = 0;
  // Erosion: near candidates leave one at a time, outer ring first, while the background
  // around them stays one piece (no new tunnel, no cavity); a removal re-examines the near
  // neighbours still there. The near candidates that stay are kept.
  {
    const Simple_point_test& test = Simple_point_test::instance();
    auto object_mask = [&](std::size_t i) {
      std::uint32_t mask = 0;
      for(std::size_t n = 0; n < 26; ++n)
      {
        const std::uint8_t l = labels[std::size_t(std::ptrdiff_t(i) + offsets[n])];
        if(l != OUTSIDE && l != REMOVED)
          mask |= 1u << n;
      }
      return mask;
    };
    std::vector<std::uint32_t> queue(near); // taken from the back: NEAR_2 first
    while(!queue.empty())
    {
      const std::size_t i = queue.back();
      queue.pop_back();
      if((labels[i] != NEAR_1 && labels[i] != NEAR_2) || !test.background_is_one_piece(object_mask(i)))
        continue;
      labels[i] = REMOVED;
      for(std::ptrdiff_t o : offsets)
      {
        const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
        if(labels[j] == NEAR_1 || labels[j] == NEAR_2)
          queue.push_back(std::uint32_t(j));
      }
    }
    std::size_t still = 0;
    for(std::uint32_t i : near)
      if(labels[i] == REMOVED)
        near[still++] = i;
    near.resize(still);
    first_cut = near.size();
    // Cut points of the core next to the surface: the voxels whose removal splits the
    // object locally without joining two pieces of background (two parts touching
    // diagonally). They leave; the linking below puts back those a component needs.
    for(std::size_t i = 0; i < volume; ++i)
      if(labels[i] == CORE_SURFACE)
        queue.push_back(std::uint32_t(i));
    while(!queue.empty())
    {
      const std::size_t i = queue.back();
      queue.pop_back();
      if(labels[i] != CORE_SURFACE)
        continue;
      const std::uint32_t mask = object_mask(i);
      if(!test.object_is_split(mask) || !test.background_is_one_piece(mask))
        continue;
      labels[i] = REMOVED;
      near.push_back(std::uint32_t(i));
      for(std::ptrdiff_t o : offsets)
      {
        const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
        if(labels[j] == CORE_SURFACE)
          queue.push_back(std::uint32_t(j));
      }
    }
  }

  // 4. Components of CORE + FAR (26-connected): `owner` holds a component for them and,
  //    for the near candidates reached by the linking search, the voxel they came from.
  const std::uint32_t none = std::uint32_t(-1);
  std::vector<std::uint32_t> owner(volume, none);
  std::uint32_t component_count = 0;
  auto kept_label = [](std::uint8_t l) { return l == CORE || l == FAR || l == NEAR_1 || l == NEAR_2 || l == CORE_SURFACE; };
  // Only components that touch a near candidate matter; grow those from the near ones.
  for(std::uint32_t i : near)
    for(std::ptrdiff_t o : offsets)
    {
      const std::size_t start_voxel = std::size_t(std::ptrdiff_t(i) + o);
      if(!kept_label(labels[start_voxel]) || owner[start_voxel] != none)
        continue;
      const std::uint32_t id = component_count++;
      owner[start_voxel] = id;
      stack.push_back(std::uint32_t(start_voxel));
      while(!stack.empty())
      {
        const std::size_t k = stack.back();
        stack.pop_back();
        for(std::ptrdiff_t p : offsets)
        {
          const std::size_t j = std::size_t(std::ptrdiff_t(k) + p);
          if(kept_label(labels[j]) && owner[j] == none)
          {
            owner[j] = id;
            stack.push_back(std::uint32_t(j));
          }
        }
      }
    }

  // Breadth-first search from all components through the near candidates; each meeting of
  // two searches is a possible link, of the length of the two paths.
  struct Link
  {
    std::uint32_t length, a, b; // a, b: the two meeting voxels (a == b for one voxel)
  };
  std::vector<Link> links;
  boost::disjoint_sets_with_storage<> components(component_count);
  // Joins two components; false when they were one already.
  auto unite = [&](std::uint32_t a, std::uint32_t b) {
    const std::size_t root_a = components.find_set(a), root_b = components.find_set(b);
    if(root_a != root_b)
      components.link(root_a, root_b);
    return root_a != root_b;
  };
  auto origin = [&](std::uint32_t v) { // the component a visited near voxel came from
    while(labels[v] >= VISITED || labels[v] == KEEP)
      v = owner[v];
    return owner[v];
  };
  std::vector<std::uint32_t> layer, next_layer;
  for(std::uint32_t i : near)
  {
    std::uint32_t from = none;
    for(std::ptrdiff_t o : offsets)
    {
      const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
      if(!kept_label(labels[j]))
        continue;
      if(from == none)
      {
        from = std::uint32_t(j);
        owner[i] = from;
        labels[i] = VISITED;
        layer.push_back(i);
      }
      else if(owner[j] != owner[from])
        links.push_back(Link{1, i, i});
    }
  }
  for(int depth = 1; !layer.empty(); ++depth)
  {
    next_layer.clear();
    for(std::uint32_t i : layer)
      for(std::ptrdiff_t o : offsets)
      {
        const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
        if(labels[j] == REMOVED)
        {
          owner[j] = i;
          labels[j] = std::uint8_t(VISITED + (std::min)(depth, 200));
          next_layer.push_back(std::uint32_t(j));
        }
        else if(labels[j] >= VISITED)
        {
          if(j > i) // each pair once
            links.push_back(Link{std::uint32_t(labels[i] - VISITED + labels[j] - VISITED + 2),
                                 i, std::uint32_t(j)});
        }
      }
    layer.swap(next_layer);
  }
  std::stable_sort(links.begin(), links.end(),
                   [](const Link& x, const Link& y) { return x.length < y.length; });
  auto keep_path = [&](std::uint32_t v) {
    while(labels[v] >= VISITED || labels[v] == KEEP)
    {
      if(labels[v] == KEEP)
        return;
      labels[v] = KEEP;
      v = owner[v];
    }
  };
  for(const Link& link : links)
  {
    if(link.a == link.b)
    {
      // One near voxel touching two components: link it to each one it touches.
      const std::size_t i = link.a;
      std::uint32_t root = none;
      for(std::ptrdiff_t o : offsets)
      {
        const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
        if(!kept_label(labels[j]))
          continue;
        if(root == none)
          root = std::uint32_t(components.find_set(owner[j]));
        else if(unite(root, owner[j]))
        {
          root = std::uint32_t(components.find_set(root));
          keep_path(link.a);
        }
      }
      continue;
    }
    const std::uint32_t ca = origin(link.a), cb = origin(link.b);
    if(unite(ca, cb))
    {
      keep_path(link.a);
      keep_path(link.b);
    }
  }
  for(std::uint32_t i : near)
    labels[i] = labels[i] == KEEP ? KEEP : REMOVED;
  // Dents: a removed candidate with three face neighbours or more in the solid fills a
  // notch of the digital surface (which thinning would turn into a spur); two passes.
  {
    const auto& faces = face_neighbour_positions();
    std::vector<std::uint32_t> add;
    for(int pass = 0; pass < 2; ++pass)
    {
      add.clear();
      for(std::size_t n = 0; n < first_cut; ++n)
      {
        const std::size_t i = near[n];
        if(labels[i] != REMOVED)
          continue;
        int in = 0;
        for(int q : faces)
        {
          const std::uint8_t l = labels[std::size_t(std::ptrdiff_t(i) + offsets[std::size_t(q)])];
          in += l != OUTSIDE && l != REMOVED;
        }
        if(in >= 3)
          add.push_back(std::uint32_t(i));
      }
      for(std::uint32_t i : add)
        labels[i] = KEEP;
    }
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_PEEL_SURFACE_VOXELS_H
