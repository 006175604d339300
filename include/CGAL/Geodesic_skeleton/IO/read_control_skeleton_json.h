// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_READ_CONTROL_SKELETON_JSON_H
#define CGAL_GEODESIC_SKELETON_IO_READ_CONTROL_SKELETON_JSON_H

/// \file IO/read_control_skeleton_json.h
/// Reads a control skeleton from the JSON that `control_skeleton_to_json()` and
/// `skeletonize` write, or that a person writes by hand.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/joint_tree.h>

#include <CGAL/number_utils.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

inline Joint_kind joint_kind_of(const std::string& name, const std::string& where)
{
  for(Joint_kind kind : {Joint_kind::root, Joint_kind::junction, Joint_kind::bend, Joint_kind::end})
    if(to_string(kind) == name)
      return kind;
  throw std::invalid_argument(where + ": unknown kind '" + name + "' (root, junction, bend or end)");
}

// The joint pairs of "bones" or "cut_bones": arrays [parent, child] of joint indices.
inline std::vector<std::pair<std::size_t, std::size_t>> joint_pairs(const nlohmann::json& list, const std::string& key,
                                                                    std::size_t joints)
{
  if(!list.is_array())
    throw std::invalid_argument("\"" + key + "\" must be an array of [parent, child] pairs");
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(std::size_t i = 0; i < list.size(); ++i)
  {
    const nlohmann::json& pair = list[i];
    const std::string where = key + "[" + std::to_string(i) + "]";
    if(!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer() || !pair[1].is_number_integer())
      throw std::invalid_argument(where + " must be a pair [parent, child] of joint indices");
    const long a = pair[0].get<long>(), b = pair[1].get<long>();
    if(a < 0 || b < 0 || std::size_t(a) >= joints || std::size_t(b) >= joints)
      throw std::invalid_argument(where + " refers to a joint that does not exist (there are " +
                                  std::to_string(joints) + ")");
    pairs.emplace_back(std::size_t(a), std::size_t(b));
  }
  return pairs;
}

template <typename Point>
double segment_length(const Point& p, const Point& q)
{
  const double d[3] = {CGAL::to_double(q.x()) - CGAL::to_double(p.x()), CGAL::to_double(q.y()) - CGAL::to_double(p.y()),
                       CGAL::to_double(q.z()) - CGAL::to_double(p.z())};
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Reads a control skeleton from `json` (cleared first): the `"control"` object of a
/// `skeletonize` report, or a bare control object; a whole report is recognised by its
/// `"control"` key. The object:
/// `{"joints": [{"position": [x, y, z], "radius": r, "parent": p, "kind": "end"}, ...],
///   "bones": [[parent, child], ...], "cut_bones": [[a, b], ...], "roots": [i, ...]}`.
/// Required: `joints`, each with `position` (three finite numbers) and `parent` (a joint
/// index, or -1 for a root). Optional: `radius` (default 0), `kind` (default: `root` for a
/// joint without parent, `end` for a joint without children, else `bend`), `bones` (default:
/// one bone from each joint's parent to it; given, there must be exactly that: one bone
/// `[joints[c].parent, c]` per joint `c` that has a parent, in any order, which is kept),
/// `cut_bones` (default none), `roots` (default: the joints without parent; given, it must
/// list exactly those). Joint indices are positions in `joints`, which may come in any order
/// (it is kept: a parent may come after its child). Bones get no `points` (their segment)
/// and their straight length.
///
/// \throws std::invalid_argument naming what is wrong: a missing key, a value of the wrong
///         type, a non-finite coordinate, a parent or bone that refers to a joint that does
///         not exist, parents that make a cycle, bones or roots that do not match the
///         parents.
/// \b Complexity: O(J log J) for J joints.
template <typename Point>
void read_control_skeleton_json(const nlohmann::json& json, Control_skeleton<Point>& skeleton)
{
  skeleton = Control_skeleton<Point>();
  if(!json.is_object())
    throw std::invalid_argument("a control skeleton must be a JSON object");
  const nlohmann::json& control = json.contains("control") ? json["control"] : json;
  if(!control.is_object() || !control.contains("joints"))
    throw std::invalid_argument("missing key \"joints\" (a control skeleton, or a skeletonize report with "
                                "a \"control\" object)");
  const nlohmann::json& joints = control["joints"];
  if(!joints.is_array() || joints.empty())
    throw std::invalid_argument("\"joints\" must be a non-empty array");
  std::vector<long> parents; // per joint, -1 for a root
  for(std::size_t j = 0; j < joints.size(); ++j)
  {
    const nlohmann::json& joint = joints[j];
    const std::string where = "joints[" + std::to_string(j) + "]";
    if(!joint.is_object())
      throw std::invalid_argument(where + " must be an object");
    for(const char* key : {"position", "parent"})
      if(!joint.contains(key))
        throw std::invalid_argument(where + ": missing key \"" + key + "\"");
    const nlohmann::json& position = joint["position"];
    if(!position.is_array() || position.size() != 3 ||
       !std::all_of(position.begin(), position.end(), [](const nlohmann::json& c) { return c.is_number(); }))
      throw std::invalid_argument(where + ": \"position\" must be an array of three numbers");
    Control_joint<Point> out;
    const double x = position[0].get<double>(), y = position[1].get<double>(), z = position[2].get<double>();
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw std::invalid_argument(where + ": \"position\" must be finite");
    out.point = Point(x, y, z);
    if(!joint["parent"].is_number_integer())
      throw std::invalid_argument(where + ": \"parent\" must be a joint index or -1");
    const long parent = joint["parent"].get<long>();
    if(parent < -1 || parent >= long(joints.size()))
      throw std::invalid_argument(where + ": parent " + std::to_string(parent) + " does not exist (there are " +
                                  std::to_string(joints.size()) + " joints; -1 for a root)");
    if(parent == long(j))
      throw std::invalid_argument("the control skeleton: joint " + std::to_string(j) + " has parent " +
                                  std::to_string(j) + ", itself (a root has parent -1)");
    parents.push_back(parent);
    if(joint.contains("radius"))
    {
      if(!joint["radius"].is_number() || !(joint["radius"].get<double>() >= 0))
        throw std::invalid_argument(where + ": \"radius\" must be a non-negative number");
      out.radius = joint["radius"].get<double>();
    }
    out.skeleton_vertex = j;
    add_vertex(out, skeleton);
  }

  auto add_bone = [&](std::size_t parent, std::size_t child) {
    Control_bone<Point> b;
    b.length = internal::segment_length(skeleton[parent].point, skeleton[child].point);
    add_edge(parent, child, b, skeleton);
  };
  if(control.contains("bones"))
  {
    // Exactly one bone [parents[c], c] per joint c that has a parent, in the file's order.
    const auto pairs = internal::joint_pairs(control["bones"], "bones", joints.size());
    std::vector<bool> led_to(joints.size(), false);
    for(std::size_t b = 0; b < pairs.size(); ++b)
    {
      const auto [parent, child] = pairs[b];
      if(parents[child] != long(parent))
        throw std::invalid_argument("the control skeleton: bone " + std::to_string(b) + " (" + std::to_string(parent) +
                                    " -> " + std::to_string(child) + ") does not match the parent of joint " +
                                    std::to_string(child) + " (" + std::to_string(parents[child]) + ")");
      if(led_to[child])
        throw std::invalid_argument("the control skeleton: two bones lead to joint " + std::to_string(child));
      led_to[child] = true;
    }
    for(std::size_t j = 0; j < joints.size(); ++j)
      if(parents[j] >= 0 && !led_to[j])
        throw std::invalid_argument("the control skeleton: no bone leads to joint " + std::to_string(j) +
                                    " from its parent " + std::to_string(parents[j]));
    for(const auto& [parent, child] : pairs)
      add_bone(parent, child);
  }
  else
    for(std::size_t j = 0; j < joints.size(); ++j)
      if(parents[j] >= 0)
        add_bone(std::size_t(parents[j]), j);
  const Geodesic_skeleton::internal::Joint_tree tree =
      Geodesic_skeleton::internal::joint_tree(skeleton, "the control skeleton");
  for(std::size_t j = 0; j < joints.size(); ++j)
  {
    Control_joint<Point>& joint = skeleton[j];
    if(joints[j].contains("kind"))
    {
      if(!joints[j]["kind"].is_string())
        throw std::invalid_argument("joints[" + std::to_string(j) + "]: \"kind\" must be a string");
      joint.kind = internal::joint_kind_of(joints[j]["kind"].get<std::string>(), "joints[" + std::to_string(j) + "]");
    }
    else
      joint.kind = parents[j] < 0 ? Joint_kind::root : tree.children[j].empty() ? Joint_kind::end : Joint_kind::bend;
  }

  Control_skeleton_property<Point>& forest = skeleton[boost::graph_bundle];
  if(control.contains("cut_bones"))
    for(const auto& [a, b] : internal::joint_pairs(control["cut_bones"], "cut_bones", joints.size()))
    {
      Control_cut_bone<Point> cut;
      cut.source = a;
      cut.target = b;
      cut.length = internal::segment_length(skeleton[a].point, skeleton[b].point);
      forest.cut_bones.push_back(cut);
    }

  forest.roots = tree.roots;
  if(control.contains("roots"))
  {
    const nlohmann::json& roots = control["roots"];
    std::vector<std::size_t> given;
    if(!roots.is_array() ||
       !std::all_of(roots.begin(), roots.end(), [](const nlohmann::json& r) { return r.is_number_integer() && r.get<long>() >= 0; }))
      throw std::invalid_argument("\"roots\" must be an array of joint indices");
    for(const nlohmann::json& r : roots)
      given.push_back(r.get<std::size_t>());
    std::vector<std::size_t> sorted = given;
    std::sort(sorted.begin(), sorted.end());
    if(sorted != tree.roots)
      throw std::invalid_argument("\"roots\" must list exactly the joints whose parent is -1");
    forest.roots = given; // the file's order
  }
}

/// \ingroup PkgGeodesicSkeletonRef
/// Reads a control skeleton from the JSON file `path`, as
/// `read_control_skeleton_json(const nlohmann::json&, Control_skeleton<Point>&)` does.
/// \throws std::runtime_error "PATH: problem" when the file cannot be opened or parsed as
///         JSON, or holds no valid control skeleton (the problem as above).
template <typename Point>
void read_control_skeleton_json(const std::string& path, Control_skeleton<Point>& skeleton)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error(path + ": cannot open the file");
  nlohmann::json json;
  try
  {
    in >> json;
    read_control_skeleton_json(json, skeleton);
  }
  catch(const nlohmann::json::exception& e)
  {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
  catch(const std::invalid_argument& e)
  {
    throw std::runtime_error(path + ": " + e.what());
  }
}

/// \ingroup PkgGeodesicSkeletonRef
/// The same, for a path given as a C string.
template <typename Point>
void read_control_skeleton_json(const char* path, Control_skeleton<Point>& skeleton)
{
  read_control_skeleton_json(std::string(path), skeleton);
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_READ_CONTROL_SKELETON_JSON_H
