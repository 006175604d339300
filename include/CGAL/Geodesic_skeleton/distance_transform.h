// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_DISTANCE_TRANSFORM_H
#define CGAL_GEODESIC_SKELETON_DISTANCE_TRANSFORM_H

/// \file distance_transform.h
/// The exact Euclidean distance transform of a voxel set: the radius function of its
/// medial axis transform.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// One line of the separable transform (Felzenszwalb and Huttenlocher 2012, "Distance
// transforms of sampled functions"): out[q] = min_p (q - p)^2 + f[p], by the lower envelope
// of the parabolas rooted at the finite samples. `f` and `out` are read and written with a
// stride; `v`, `z_num` and `z_den` are scratch of at least n + 1 entries. The envelope's
// breakpoints are kept as fractions z_num / z_den (z_den > 0) and compared by cross
// multiplication: exact, and without a division per sample.
inline void lower_envelope_pass(std::uint32_t* data, std::size_t n, std::ptrdiff_t stride,
                                std::vector<std::int64_t>& f, std::vector<std::int64_t>& v,
                                std::vector<std::int64_t>& z_num, std::vector<std::int64_t>& z_den)
{
  constexpr std::uint32_t infinity = 0xFFFFFFFFu;
  std::int64_t first = -1, last = -1; // the first and last samples that are not 0
  for(std::size_t q = 0; q < n; ++q)
  {
    const std::uint32_t value = data[std::ptrdiff_t(q) * stride];
    f[q] = value == infinity ? -1 : std::int64_t(value);
    if(value != 0)
    {
      last = std::int64_t(q);
      if(first < 0)
        first = last;
    }
  }
  if(first < 0)
    return; // a line outside the solid stays at 0
  // A 0 sample is its own nearest, and hides the samples beyond it from the others: only
  // [first - 1, last + 1] needs the envelope, the 0s around it stay.
  const std::int64_t from = (std::max)(first - 1, std::int64_t(0));
  const std::int64_t to = (std::min)(last + 2, std::int64_t(n));
  // v[0..k]: the samples whose parabolas make the envelope; the parabola of v[i] is lowest
  // from z[i] = z_num[i] / z_den[i] on (z[0] is minus infinity).
  std::ptrdiff_t k = -1;
  for(std::int64_t q = from; q < to; ++q)
  {
    if(f[q] < 0)
      continue;
    std::int64_t num = 0, den = 1; // where the parabola of q overtakes that of v[k]
    while(k >= 0)
    {
      const std::int64_t p = v[k];
      num = (f[q] + q * q) - (f[p] + p * p);
      den = 2 * (q - p);
      if(k > 0 && num * z_den[k] <= z_num[k] * den)
        --k; // v[k]'s parabola is nowhere lowest any more
      else
        break;
    }
    ++k;
    v[k] = q;
    z_num[k] = num;
    z_den[k] = den;
  }
  if(k < 0)
    return; // no finite sample: the line stays infinite
  std::ptrdiff_t j = 0;
  for(std::int64_t q = from; q < to; ++q)
  {
    while(j < k && z_num[j + 1] < q * z_den[j + 1])
      ++j;
    const std::int64_t p = v[j];
    data[std::ptrdiff_t(q) * stride] = std::uint32_t((q - p) * (q - p) + f[p]);
  }
}

} // namespace internal

namespace internal {

// distance_transform() once its memory limit is read: compiled once per voxel set type.
template <typename VoxelSet>
Voxel_distance_field distance_transform_with(const VoxelSet& voxels, double memory_limit)
{
  const char* caller = "distance_transform";
  const Voxel_box box = internal::require_nonempty_box(voxels, 1, caller);
  const internal::Grid_layout layout(box);
  internal::require_memory(4. * double(layout.volume()), memory_limit, layout, caller, "a distance field");

  constexpr std::uint32_t infinity = 0xFFFFFFFFu;
  std::vector<std::uint32_t> d(layout.volume(), 0u);
  voxels.for_each([&](const Voxel_key& k) { d[layout.index(k)] = infinity; });

  // Along x: the distance to the nearest outside voxel of the row, squared. Every row has
  // outside voxels at both ends (the box has a margin of one voxel).
  const std::size_t nx = layout.nx;
  for(std::size_t row = 0; row < layout.ny * layout.nz; ++row)
  {
    std::uint32_t* line = d.data() + row * nx;
    std::uint32_t run = infinity;
    for(std::size_t x = 0; x < nx; ++x)
    {
      run = line[x] == 0 ? 0 : (run == infinity ? infinity : run + 1);
      line[x] = run;
    }
    run = infinity;
    for(std::size_t x = nx; x-- > 0;)
    {
      run = line[x] == 0 ? 0 : (run == infinity ? infinity : run + 1);
      if(run < line[x])
        line[x] = run;
    }
    for(std::size_t x = 0; x < nx; ++x)
      line[x] = line[x] * line[x];
  }

  const std::size_t longest = (std::max)({layout.nx, layout.ny, layout.nz}) + 1;
  std::vector<std::int64_t> f(longest), v(longest), z_num(longest), z_den(longest);
  for(std::size_t zz = 0; zz < layout.nz; ++zz) // along y
    for(std::size_t x = 0; x < nx; ++x)
      internal::lower_envelope_pass(d.data() + zz * layout.stride_z + x, layout.ny,
                                    layout.stride_y, f, v, z_num, z_den);
  for(std::size_t y = 0; y < layout.ny; ++y) // along z
    for(std::size_t x = 0; x < nx; ++x)
      internal::lower_envelope_pass(d.data() + y * layout.stride_y + x, layout.nz,
                                    layout.stride_z, f, v, z_num, z_den);

  return Voxel_distance_field(voxels.frame(), box, std::move(d));
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Computes the exact squared Euclidean distance transform of `voxels`: for every voxel
/// of the set, the squared distance (unit: squared voxels) from its centre to the centre of
/// the nearest voxel not in the set. Its square root minus half a voxel, times the voxel
/// size, is the radius function of the medial axis transform (`Voxel_distance_field::radius()`).
///
/// <b>Method.</b> Separable: along x, the distance to the nearest outside voxel of the row
/// (two scans); then along y and along z, the lower envelope of parabolas of Felzenszwalb
/// and Huttenlocher, which is exact for the Euclidean metric. Integer arithmetic.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, the set is copied into a
///         dense array over its bounding box (the field's own array).
/// \param voxels the solid (e.g. `voxelize()`'s output); it is not modified.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{memory_limit}
///     \cgalParamDescription{the most memory the function may allocate, in bytes (package
///                           parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_voxel_memory_limit`, 2 GiB}
///     \cgalParamExtra{The need, 4 bytes per voxel of the set's bounding box grown by one
///                     voxel, is checked before allocating.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the distance field, over the tight bounding box of the set grown by one voxel.
/// \pre `voxels` is not empty.
/// \throws std::invalid_argument when `voxels` is empty.
/// \throws std::length_error when the field would need more than `memory_limit` bytes.
///
/// \b Complexity: O(B) time and memory, for B voxels in the set's bounding box: linear.
template <typename VoxelSet, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Voxel_distance_field distance_transform(const VoxelSet& voxels,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::distance_transform_with(voxels, internal::memory_limit(np, "distance_transform"));
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_DISTANCE_TRANSFORM_H
