// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Named parameters of the package.
//
// The package reuses CGAL's named-parameter machinery (CGAL::Named_function_parameters,
// CGAL::parameters::get_parameter, CGAL::parameters::choose_parameter) and CGAL's own
// names for CGAL's ideas (vertex_point_map, vertex_index_map, edge_weight_map,
// geom_traits, ...). CGAL keeps its names in one central list that an out-of-tree package
// cannot extend, so the names that are new here are defined in this header, in the
// namespace CGAL::Geodesic_skeleton::parameters, and any two packs (ours or CGAL's) are
// joined with `combine()`.

#ifndef CGAL_GEODESIC_SKELETON_PARAMETERS_H
#define CGAL_GEODESIC_SKELETON_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Geodesic_skeleton {

/// Tag types of the package's own named parameters (one enum per name, as in CGAL).
namespace internal_np {
#define CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(NAME) enum NAME##_t { NAME##_tag };
#include <CGAL/Geodesic_skeleton/internal/parameter_names.h>
#undef CGAL_GEODESIC_SKELETON_NAMED_PARAMETER
} // namespace internal_np

namespace internal {

// What an output named parameter (`curve_skeleton_output`, `voxelized_surface` given to
// voxelize(), ...) points to, or null when it is not given or is a null pointer: that output
// is then not made. A name that one stage writes and the next reads must reach the writer as
// a pointer to a writable object.
template <typename Output, typename NamedParameters, typename Tag>
Output* written_output(const NamedParameters& np, Tag)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
    return nullptr;
  else
  {
    using Given = std::decay_t<decltype(CGAL::parameters::get_parameter(np, Tag{}))>;
    static_assert(std::is_convertible_v<Given, Output*>,
                  "this output named parameter must be a pointer to a writable (non-const) object");
    return CGAL::parameters::get_parameter(np, Tag{});
  }
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Named parameters: CGAL's own (re-exported) and the package's new names.
///
/// CGAL's names (`vertex_point_map`, `vertex_index_map`, `geom_traits`, ...) are usable from
/// this namespace. The package's own names are functions of this namespace that take the
/// value and return a one-element pack, `CGAL::Named_function_parameters<T, Tag>`; among
/// them:
/// - `edge_weight_map(map)`: a readable edge property map of finite, non-negative lengths
///   (read by `geodesic_distances()`, `shortest_path()` and `farthest_vertex()`).
/// - `vertex_predecessor_map(map)`: a writable vertex property map that receives the
///   predecessor of every vertex on a shortest path (read by `geodesic_distances()`).
///
/// Each function documents the names it reads, with their types and defaults. A pack of the
/// package's names and a pack of CGAL's names are joined with `combine()`.
namespace parameters {

using namespace CGAL::parameters; // vertex_point_map, vertex_index_map, geom_traits, ...

#define CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(NAME)                                  \
  template <typename T>                                                               \
  CGAL::Named_function_parameters<T, CGAL::Geodesic_skeleton::internal_np::NAME##_t>  \
  NAME(const T& value)                                                                \
  {                                                                                   \
    return CGAL::Named_function_parameters<                                           \
        T, CGAL::Geodesic_skeleton::internal_np::NAME##_t>(value);                    \
  }
#include <CGAL/Geodesic_skeleton/internal/parameter_names.h>
#undef CGAL_GEODESIC_SKELETON_NAMED_PARAMETER

namespace internal {

// The last link of a pack: it takes the whole second pack as its base.
template <typename T, typename Tag, typename Pack>
CGAL::Named_function_parameters<T, Tag, Pack>
append_pack(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& first,
            const Pack& second)
{
  return CGAL::Named_function_parameters<T, Tag, Pack>(first.v, second);
}

// An inner link: rebuild it on top of the first pack's base joined with the second pack.
template <typename T, typename Tag, typename Base, typename Pack>
auto append_pack(const CGAL::Named_function_parameters<T, Tag, Base>& first, const Pack& second)
{
  auto joined_base = append_pack(static_cast<const Base&>(first), second);
  return CGAL::Named_function_parameters<T, Tag, decltype(joined_base)>(first.v, joined_base);
}

} // namespace internal

/// Joins two named-parameter packs into one. When a name appears in both, the value in
/// `first` wins (lookups stop at the first match).
///
/// Example: `combine(parameters::edge_weight_map(lengths), parameters::vertex_point_map(vpm))`.
///
/// \param first a pack: the package's names or CGAL's.
/// \param second another pack, of either kind.
/// \returns one pack that holds the settings of `first`, then those of `second`.
template <typename T1, typename Tag1, typename Base1, typename T2, typename Tag2, typename Base2>
auto combine(const CGAL::Named_function_parameters<T1, Tag1, Base1>& first,
             const CGAL::Named_function_parameters<T2, Tag2, Base2>& second)
{
  return internal::append_pack(first, second);
}

/// Joins more than two packs, left to right: `combine(combine(first, second), rest...)`.
///
/// \param first the first pack (its settings win over the later ones).
/// \param second the second pack.
/// \param rest the other packs.
/// \returns one pack that holds the settings of every pack, in order.
template <typename Pack1, typename Pack2, typename... Packs>
auto combine(const Pack1& first, const Pack2& second, const Packs&... rest)
{
  return combine(combine(first, second), rest...);
}

} // namespace parameters

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_PARAMETERS_H
