// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_VOXELIZE_SOLID_VOXELS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_VOXELIZE_SOLID_VOXELS_H

// The machinery of voxelize() (include/CGAL/Geodesic_skeleton/voxelize.h): not part of the API.

#include <CGAL/Geodesic_skeleton/No_enclosed_volume.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/byte_runs.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/peel_surface_voxels.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/principal_frame.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/triangle_box_overlap.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The voxels of the grid along an axis across which the mesh extends `extent` voxels: the
// odd number that covers the extent (see grid_frame()).
inline int odd_voxel_count(double extent)
{
  const int n = (std::max)(1, int(std::ceil(extent - 1e-9)));
  return n + 1 - n % 2;
}

// The frame and box of the grid: voxels of 1 / `resolution` of the longest principal extent
// of the mesh, an odd number of them along each axis (the extent's, or one more), the mesh
// centred in the box, and `margin` empty voxels all around. With an odd count the centre of
// the mesh's box is a voxel's centre, so a plane of mirror symmetry of the shape through it
// runs through a layer of voxel centres, not between two layers: a part crossing it is
// rasterised an odd number of voxels across, and its ridge is one voxel thick there, which
// thinning keeps whatever its order of deletion (between two layers the ridge is two voxels
// thick, and which of the two stays depends on that order).
inline Voxel_frame grid_frame(const std::vector<Triangle3>& triangles, int resolution, int margin,
                              Voxel_box& box, const char* caller)
{
  const Principal_frame pf = principal_frame(triangles, caller);
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(const Triangle3& t : triangles)
    for(const Vec3& p : t)
    {
      const Vec3 d = sub(p, pf.centroid);
      for(int a = 0; a < 3; ++a)
      {
        const double c = dot3(d, pf.axes[a]);
        lo[a] = (std::min)(lo[a], c);
        hi[a] = (std::max)(hi[a], c);
      }
    }
  const double longest = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double h = longest / resolution;
  Vec3 origin = pf.centroid;
  for(int a = 0; a < 3; ++a)
  {
    const double extent = hi[a] - lo[a];
    const int n = odd_voxel_count(extent / h);
    const double local_origin = lo[a] - 0.5 * (n * h - extent) - margin * h;
    for(int c = 0; c < 3; ++c)
      origin[c] += local_origin * pf.axes[a][c];
    (a == 0 ? box.max.x : a == 1 ? box.max.y : box.max.z) = n + 2 * margin;
  }
  box.min = Voxel_key{0, 0, 0};
  return Voxel_frame(origin, pf.axes, h);
}

// Labels `label` every EMPTY voxel that one of the triangles [first, last) of `g` (in grid
// coordinates) meets (conservative rasterisation).
inline void rasterize(const std::vector<Triangle3>& g, std::size_t first, std::size_t last,
                      const Grid_layout& layout, std::uint8_t label, std::vector<std::uint8_t>& labels)
{
  // Half a voxel, slightly enlarged so that rounding never opens a gap between triangles.
  const double half = 0.5 + 1e-6;
  const int hi[3] = {layout.box.max.x - 1, layout.box.max.y - 1, layout.box.max.z - 1};
  Triangle_cube_test test;
  for(std::size_t t = first; t < last; ++t)
  {
    const Vec3* c = g[t].data();
    const Triangle_box box(g[t]);
    int from[3], to[3];
    for(int a = 0; a < 3; ++a)
    {
      from[a] = int((std::max)(0L, floor_to_long(box.lo[a] - 1e-6)));
      to[a] = int((std::min)(long(hi[a]), floor_to_long(box.hi[a] + 1e-6)));
    }
    // A triangle whose box is one voxel wide along two axes meets every voxel of its box
    // (it is connected, and it runs through that row of voxels from end to end): no test.
    const bool meets_whole_box = (from[0] != to[0]) + (from[1] != to[1]) + (from[2] != to[2]) <= 1;
    bool test_set = false; // `test` is set up at the first voxel that needs it
    for(int z = from[2]; z <= to[2]; ++z)
      for(int y = from[1]; y <= to[1]; ++y)
        for(int x = from[0]; x <= to[0]; ++x)
        {
          const std::size_t i = layout.index(Voxel_key{x, y, z});
          if(labels[i] != EMPTY)
            continue;
          if(!meets_whole_box && !test_set)
          {
            test.set(c[0], c[1], c[2], half);
            test_set = true;
          }
          if(meets_whole_box || test.meets(Vec3{x + 0.5, y + 0.5, z + 0.5}))
            labels[i] = label;
        }
  }
}

// Labels OUTSIDE every EMPTY voxel 6-connected to the border of the box through EMPTY
// voxels (a 6-path cannot cross a conservatively rasterised surface). A scanline fill: a
// seed grows into the whole run of EMPTY voxels along x that holds it, and the runs of the
// four neighbouring rows (y +- 1, z +- 1) that touch it are seeded in turn. Seeds: every
// EMPTY run of the rows on the box's faces, and the two end voxels of the other rows.
inline void flood_outside(const Grid_layout& layout, std::vector<std::uint8_t>& labels)
{
  const std::size_t nx = layout.nx, ny = layout.ny, nz = layout.nz;
  static_assert(EMPTY == 0, "the run scans below look for zero bytes");
  std::vector<std::uint32_t> seeds; // indices of EMPTY voxels, each the start of a run to fill
  auto seed_runs = [&](std::size_t row_start, std::size_t from, std::size_t to) {
    // Seeds the EMPTY runs of the row that meet [from, to].
    const std::uint8_t* row = labels.data() + row_start;
    for(std::size_t x = first_zero(row, from, to + 1); x <= to; x = first_zero(row, x, to + 1))
    {
      seeds.push_back(std::uint32_t(row_start + x));
      x = first_nonzero(row, x, to + 1);
    }
  };
  for(std::size_t z = 0; z < nz; ++z)
    for(std::size_t y = 0; y < ny; ++y)
    {
      const std::size_t row_start = (z * ny + y) * nx;
      if(z == 0 || y == 0 || z + 1 == nz || y + 1 == ny)
        seed_runs(row_start, 0, nx - 1);
      else
      {
        seed_runs(row_start, 0, 0);
        seed_runs(row_start, nx - 1, nx - 1);
      }
    }
  while(!seeds.empty())
  {
    const std::size_t i = seeds.back();
    seeds.pop_back();
    if(labels[i] != EMPTY)
      continue; // filled since it was seeded
    const std::size_t row_start = i - i % nx, yz = i / nx, y = yz % ny, z = yz / ny;
    std::uint8_t* row = labels.data() + row_start;
    std::size_t from = i - row_start;
    const std::size_t to = first_nonzero(row, from, nx) - 1;
    while(from > 0 && row[from - 1] == EMPTY)
      --from;
    std::fill(row + from, row + to + 1, std::uint8_t(OUTSIDE));
    if(y > 0)
      seed_runs(row_start - nx, from, to);
    if(y + 1 < ny)
      seed_runs(row_start + nx, from, to);
    if(z > 0)
      seed_runs(row_start - nx * ny, from, to);
    if(z + 1 < nz)
      seed_runs(row_start + nx * ny, from, to);
  }
}

// voxelize(), which also hands over, when `rasterised` is not null, the triangles it
// rasterised, for the later inside tests of the pipeline.
// The settings of voxelize(), read from its named parameters.
struct Voxelize_settings
{
  int resolution;
  bool fill_holes;
  bool keep_surface_voxels;
  double memory_limit;
  Voxelized_surface* rasterised; // receives the triangles rasterised, when not null
};

// The frame and box of voxelize()'s grid for the mesh's triangles: one empty voxel all
// around the mesh.
inline Voxel_frame voxelize_frame(const std::vector<Triangle3>& triangles, int resolution, Voxel_box& box,
                                  const char* caller)
{
  return grid_frame(triangles, resolution, 1, box, caller);
}

// voxelize()'s parameters, read (and checked) from `np`.
template <typename NamedParameters>
Voxelize_settings voxelize_settings(const NamedParameters& np, const char* caller)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Voxelize_settings settings;
  settings.resolution = internal::checked_parameter(
      parameter_ranges::resolution,
      choose_parameter(get_parameter(np, internal_np::resolution_tag), default_voxel_resolution), caller);
  settings.fill_holes = choose_parameter(get_parameter(np, internal_np::fill_holes_tag), true);
  settings.keep_surface_voxels = choose_parameter(get_parameter(np, internal_np::keep_surface_voxels_tag), true);
  settings.memory_limit = internal::memory_limit(np, caller); // checked before any work
  settings.rasterised = written_output<Voxelized_surface>(np, internal_np::voxelized_surface_tag);
  return settings;
}

// voxelize() once its parameters are read: compiled once per mesh, point map and voxel set
// type, whatever the parameter pack.
template <typename FaceGraph, typename VertexPointMap, typename VoxelSet>
std::size_t voxelize_with(const FaceGraph& mesh, const VertexPointMap& vpm, VoxelSet& voxels,
                          const Voxelize_settings& settings)
{
  const char* caller = "voxelize";
  const int resolution = settings.resolution;
  const bool fill_holes = settings.fill_holes;
  const bool keep_surface_voxels = settings.keep_surface_voxels;
  std::vector<internal::Triangle3> triangles = internal::mesh_triangles(mesh, vpm, caller);

  Voxel_box box;
  const Voxel_frame frame = voxelize_frame(triangles, resolution, box, caller);
  const std::size_t mesh_triangle_count = triangles.size();
  internal::close_holes(mesh, vpm, triangles, fill_holes);
  const internal::Grid_layout layout(box);
  internal::require_memory((keep_surface_voxels ? 6. : 11.) * double(layout.volume()),
                           settings.memory_limit, layout, caller,
                           "a grid (resolution " + std::to_string(resolution) + ")");

  std::vector<std::uint8_t> labels(layout.volume(), internal::EMPTY);
  std::vector<internal::Triangle3>& grid_triangles = triangles;
  internal::to_grid(grid_triangles, frame);
  internal::rasterize(grid_triangles, 0, mesh_triangle_count, layout, internal::SURFACE, labels);
  internal::rasterize(grid_triangles, mesh_triangle_count, grid_triangles.size(), layout,
                      internal::FAN, labels);
  internal::flood_outside(layout, labels);

  Voxel_box solid_box;
  std::size_t enclosed = 0;
  internal::for_each_cell(layout, [&](std::size_t i, const Voxel_key& k) {
    if(labels[i] != internal::OUTSIDE)
    {
      solid_box.extend(k);
      enclosed += labels[i] == internal::EMPTY;
    }
  });
  // A closed shape under about two voxels thick (a plate, a wing) leaves no voxel
  // untouched by its surface: it still encloses volume when the centres of touched voxels
  // are inside it.
  if(enclosed == 0 && !internal::thin_closed_surface_encloses_centres(grid_triangles, layout, labels))
  {
    std::ostringstream msg;
    msg << caller << ": the mesh encloses no volume at resolution " << resolution
        << " (an open sheet, a surface with holes wider than a voxel, or a shape thinner "
           "than a voxel); close the mesh or raise the resolution";
    throw No_enclosed_volume(msg.str());
  }

  if(!keep_surface_voxels)
  {
    internal::peel_surface_voxels(grid_triangles, layout, labels);
    solid_box = Voxel_box();
    internal::for_each_cell(layout, [&](std::size_t i, const Voxel_key& k) {
      if(labels[i] != internal::OUTSIDE && labels[i] != internal::REMOVED)
        solid_box.extend(k);
    });
  }

  voxels.reset(frame, solid_box);
  std::size_t count = 0;
  internal::for_each_cell(layout, [&](std::size_t i, const Voxel_key& k) {
    if(labels[i] != internal::OUTSIDE && labels[i] != internal::REMOVED)
    {
      voxels.insert(k);
      ++count;
    }
  });
  if(settings.rasterised != nullptr)
    *settings.rasterised = Voxelized_surface(frame, std::move(grid_triangles), internal::Triangles_of_a_mesh{});
  return count;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_VOXELIZE_SOLID_VOXELS_H
