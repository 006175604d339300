// Archetypes of the package's voxel concepts (doc/Concepts/VoxelSet.h,
// doc/Concepts/VoxelDistanceField.h): minimal models with exactly the members that the
// concepts require and nothing more, so that a stage instantiated with them fails to compile
// when it uses more than its concept.

#ifndef GEODESIC_SKELETON_TEST_VOXEL_ARCHETYPES_H
#define GEODESIC_SKELETON_TEST_VOXEL_ARCHETYPES_H

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace Geodesic_skeleton_test {

namespace gs = CGAL::Geodesic_skeleton;

// A model of `VoxelSet`: an ordered set of keys, iterated in decreasing key order (an order
// that neither model of the package has, so a stage that depends on the order shows it).
class Voxel_set_archetype
{
public:
  Voxel_set_archetype() = default;

  void reset(const gs::Voxel_frame& frame, const gs::Voxel_box&)
  {
    m_frame = frame;
    m_voxels.clear();
  }
  void clear() { m_voxels.clear(); }
  const gs::Voxel_frame& frame() const { return m_frame; }
  gs::Voxel_box bounding_box() const
  {
    gs::Voxel_box box;
    for(const gs::Voxel_key& k : m_voxels)
      box.extend(k);
    return box;
  }

  std::size_t size() const { return m_voxels.size(); }
  bool contains(const gs::Voxel_key& k) const { return m_voxels.count(k) != 0; }
  bool insert(const gs::Voxel_key& k) { return m_voxels.insert(k).second; }
  bool erase(const gs::Voxel_key& k) { return m_voxels.erase(k) != 0; }

  template <typename Function>
  void for_each(Function f) const
  {
    for(auto k = m_voxels.rbegin(); k != m_voxels.rend(); ++k)
      f(*k);
  }

private:
  gs::Voxel_frame m_frame;
  std::set<gs::Voxel_key> m_voxels;
};

// A model of `VoxelDistanceField` that answers from a `Voxel_distance_field` it owns.
class Voxel_distance_field_archetype
{
public:
  explicit Voxel_distance_field_archetype(gs::Voxel_distance_field field) : m_field(std::move(field)) {}

  const gs::Voxel_frame& frame() const { return m_field.frame(); }
  const gs::Voxel_box& box() const { return m_field.box(); }
  std::uint32_t squared_distance(const gs::Voxel_key& k) const { return m_field.squared_distance(k); }
  bool inside(const gs::Voxel_key& k) const { return m_field.inside(k); }
  double radius(const gs::Voxel_key& k) const { return m_field.radius(k); }
  const std::vector<std::uint32_t>& values() const { return m_field.values(); }

private:
  gs::Voxel_distance_field m_field;
};

} // namespace Geodesic_skeleton_test

#endif // GEODESIC_SKELETON_TEST_VOXEL_ARCHETYPES_H
