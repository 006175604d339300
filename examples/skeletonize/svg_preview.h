// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef GEODESIC_SKELETON_SKELETONIZE_SVG_PREVIEW_H
#define GEODESIC_SKELETON_SKELETONIZE_SVG_PREVIEW_H

// The SVG picture that skeletonize --svg draws (and the fuzzer exercises): the program's,
// not the package's. Dependency-free: a mesh with a skeleton drawn over it in three views.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/principal_frame.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

using Geodesic_skeleton::internal::Vec3;

// One orthographic view: screen x along `right`, screen y along `up`, looking along
// `right x up`.
struct Svg_view
{
  Vec3 right, up;
  std::string name;
};

using Geodesic_skeleton::internal::cross3;
using Geodesic_skeleton::internal::dot3;

inline std::string joint_colour(Joint_kind kind)
{
  switch(kind)
  {
    case Joint_kind::root: return "#d62728";
    case Joint_kind::junction: return "#ff7f0e";
    case Joint_kind::bend: return "#1f77b4";
    case Joint_kind::end: return "#2ca02c";
  }
  return "#000000";
}

// What is drawn over the mesh: polylines (dashed or not) and dots; and, when not empty, a
// label per triangle of mesh_triangles() that colours it (grey when negative).
struct Svg_overlay
{
  struct Line { std::vector<Vec3> points; bool dashed = false; };
  struct Dot { Vec3 point; double radius = 0; std::string colour; };
  std::vector<Line> lines;
  std::vector<Dot> dots;
  std::vector<int> triangle_labels;
};

// The fill of a triangle: grey, or the colour of its label (12 colours in turn), lighter
// the more it faces the viewer (`grey` in 0..15).
inline std::string triangle_fill(int label, int grey)
{
  static const int palette[12][3] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                     {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {188, 189, 34},
                                     {23, 190, 207}, {174, 199, 232}, {255, 187, 120}, {152, 223, 138}};
  std::ostringstream fill;
  if(label < 0)
  {
    const int level = 120 + 8 * grey;
    fill << "rgb(" << level << ',' << level << ',' << level + 6 << ')';
    return fill.str();
  }
  const double shade = 0.5 + 0.5 * grey / 15.0;
  const int* c = palette[label % 12];
  fill << "rgb(" << int(c[0] * shade) << ',' << int(c[1] * shade) << ',' << int(c[2] * shade) << ')';
  return fill.str();
}

template <typename Point>
Vec3 to_vec3(const Point& p)
{
  return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <typename FaceGraph>
std::ostream& write_svg_views(std::ostream& os, const FaceGraph& mesh, const Svg_overlay& overlay,
                              int view_size, const std::string& title);

// The bones (the polylines of their points, or their joints' segment when they have fewer
// than two; cut bones dashed) and the joints (dots coloured by kind) of a control skeleton.
template <typename Point>
Svg_overlay control_skeleton_overlay(const Control_skeleton<Point>& skeleton)
{
  Svg_overlay overlay;
  const std::size_t joints = num_vertices(skeleton);
  auto add_line = [&](const Control_bone<Point>& bone, std::size_t from, std::size_t to, bool dashed) {
    Svg_overlay::Line line;
    line.dashed = dashed;
    for(const Point& p : bone.points)
      line.points.push_back(to_vec3(p));
    if(line.points.size() < 2 && from < joints && to < joints)
      line.points = {to_vec3(skeleton[from].point), to_vec3(skeleton[to].point)};
    overlay.lines.push_back(std::move(line));
  };
  for(const auto e : boost::make_iterator_range(edges(skeleton)))
    add_line(skeleton[e], source(e, skeleton), target(e, skeleton), false);
  for(const Control_cut_bone<Point>& bone : skeleton[boost::graph_bundle].cut_bones)
    add_line(bone, bone.source, bone.target, true);
  for(const auto v : boost::make_iterator_range(vertices(skeleton)))
    overlay.dots.push_back({to_vec3(skeleton[v].point), skeleton[v].radius, joint_colour(skeleton[v].kind)});
  return overlay;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Writes an SVG picture of `mesh` with `skeleton` drawn over it, in three orthographic
/// views along the principal axes of the mesh (side: the two longest axes; top; front).
///
/// The mesh is drawn as its front-facing triangles, shaded by the angle to the viewer
/// (16 grey levels) and painted back to front by slabs of depth; the triangles of one grey
/// in one slab make one path, corners are rounded to whole pixels and triangles smaller than a
/// pixel are left out (a thin stroke of their neighbours covers them), so the file stays
/// small (about 30 bytes per visible triangle and view). Bones are drawn as the
/// polylines of their smoothed points, cut bones dashed; joints as dots whose radius is
/// 0.3 times the joint's MAT radius (at least 2 pixels), coloured by kind: root red,
/// junction orange, bend blue, end green. "Up" on the picture is opposite to the second
/// principal axis, which points to the heavier tail of the shape (the legs of an animal).
///
/// \tparam FaceGraph a model of `FaceListGraph`.
/// \param os the output stream.
/// \param mesh the mesh (any faces; polygons are split into fans).
/// \param skeleton its control skeleton, in the mesh's coordinates.
/// \param view_size the width and height of each view, in pixels, in [32, 4096].
/// \param title a line of text written above the views (escaped), e.g. the file name.
/// \returns `os`.
/// \throws std::invalid_argument for a mesh without faces or with a non-finite
///         coordinate, or a view size out of range.
///
/// \b Complexity: O(F log F) for F faces.
template <typename FaceGraph, typename Point>
std::ostream& write_svg_preview(std::ostream& os, const FaceGraph& mesh,
                                const Control_skeleton<Point>& skeleton, int view_size = 360,
                                const std::string& title = std::string())
{
  return internal::write_svg_views(os, mesh, internal::control_skeleton_overlay(skeleton), view_size, title);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Writes an SVG picture of `mesh` coloured by an integer label per vertex, with `skeleton`
/// drawn over it, in the views of `write_svg_preview()`: for example the hard segmentation
/// of the mesh by bone (`compute_skinning_weights()`'s `bone_segmentation_map`). A face takes
/// the label that most of its corners have (the smallest on a tie), coloured from a cycle of
/// 12 colours (label modulo 12) and shaded by the facing angle; a negative label is grey.
///
/// \param os the stream written to.
/// \param mesh a triangle mesh, a model of `FaceListGraph` with a vertex point map and a
///        vertex index map.
/// \param vertex_labels one label per vertex, indexed by the mesh's vertex index map.
/// \param skeleton the control skeleton drawn over the mesh, in the mesh's coordinates.
/// \param view_size the width and height of each view, in pixels, in [32, 4096].
/// \param title a line of text written above the views (escaped), e.g. the file name.
/// \returns `os`. \throws as `write_svg_preview()`, and std::invalid_argument when
///          `vertex_labels` does not have one label per vertex.
/// \b Complexity: O(F log F) for F faces.
template <typename FaceGraph, typename Point>
std::ostream& write_svg_preview_of_labels(std::ostream& os, const FaceGraph& mesh, const std::vector<int>& vertex_labels,
                                          const Control_skeleton<Point>& skeleton, int view_size = 360,
                                          const std::string& title = std::string())
{
  if(vertex_labels.size() != static_cast<std::size_t>(num_vertices(mesh)))
    throw std::invalid_argument("write_svg_preview_of_labels: one label per vertex is needed");
  internal::Svg_overlay overlay = internal::control_skeleton_overlay(skeleton);
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  std::vector<int> corners;
  for(auto f : faces(mesh)) // the triangles in the order of mesh_triangles(): n - 2 per face
  {
    corners.clear();
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      corners.push_back(vertex_labels[get(vim, v)]);
    std::vector<int> sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    int label = sorted.front(), best = 0;
    for(std::size_t i = 0; i < sorted.size();)
    {
      std::size_t j = i;
      while(j < sorted.size() && sorted[j] == sorted[i])
        ++j;
      if(int(j - i) > best)
      {
        best = int(j - i);
        label = sorted[i];
      }
      i = j;
    }
    for(std::size_t t = 2; t < corners.size(); ++t)
      overlay.triangle_labels.push_back(label);
  }
  return internal::write_svg_views(os, mesh, overlay, view_size, title);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Writes an SVG picture of `mesh` with a skeleton graph drawn over it, in the views of
/// `write_svg_preview()`: every edge as a line, the end points (degree 1) as green dots
/// and the junctions (degree 3 or more) as orange dots, 2.5 pixels wide. For the figures
/// of the intermediate stages: the thinned or pruned curve skeleton (`Curve_skeleton`),
/// the Reeb graph (`Reeb_graph`).
///
/// \tparam Graph an undirected `boost::adjacency_list` with `vecS` vertex storage whose
///         vertex bundle has a `point` in the mesh's coordinates.
/// \returns `os`. \throws as `write_svg_preview()`.
/// \b Complexity: O(F log F + V + E) for F faces, V graph vertices and E edges.
template <typename FaceGraph, typename Graph>
std::ostream& write_svg_preview_of_graph(std::ostream& os, const FaceGraph& mesh, const Graph& graph,
                                         int view_size = 360, const std::string& title = std::string())
{
  internal::Svg_overlay overlay;
  for(auto e : boost::make_iterator_range(edges(graph)))
    overlay.lines.push_back({{internal::to_vec3(graph[source(e, graph)].point),
                              internal::to_vec3(graph[target(e, graph)].point)},
                             false});
  for(std::size_t v = 0; v < num_vertices(graph); ++v)
  {
    const std::size_t d = boost::degree(v, graph);
    if(d != 2)
      overlay.dots.push_back({internal::to_vec3(graph[v].point), -2.5, d >= 3 ? "#ff7f0e" : "#2ca02c"});
  }
  return internal::write_svg_views(os, mesh, overlay, view_size, title);
}

namespace internal {

// Draws the mesh and the overlay in three views. A dot of negative radius has that many
// pixels; a positive radius is in world units (drawn at 0.3 of it, at least 2 pixels).
template <typename FaceGraph>
std::ostream& write_svg_views(std::ostream& os, const FaceGraph& mesh, const Svg_overlay& overlay,
                              int view_size, const std::string& title)
{
  if(view_size < 32 || view_size > 4096)
    throw std::invalid_argument("write_svg_preview: the view size must be in [32, 4096] pixels");
  const auto triangles = Geodesic_skeleton::internal::mesh_triangles(
      mesh, get(CGAL::vertex_point, mesh), "write_svg_preview");
  const auto frame = Geodesic_skeleton::internal::principal_frame(triangles, "write_svg_preview");
  // The second principal axis points to the heavier tail of the shape (the legs of an
  // animal standing on them), so "up" on the picture is its opposite.
  const Vec3 a0 = frame.axes[0], a2 = frame.axes[2];
  const Vec3 up{-frame.axes[1][0], -frame.axes[1][1], -frame.axes[1][2]};
  const std::array<internal::Svg_view, 3> views{{{a0, up, "side"}, {a0, a2, "top"}, {a2, up, "front"}}};

  // One scale for the three views: the largest extent along any principal axis fits.
  double extent = 0;
  Vec3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
  for(const auto& t : triangles)
    for(const Vec3& p : t)
      for(int a = 0; a < 3; ++a)
      {
        const double c = internal::dot3(Geodesic_skeleton::internal::sub(p, frame.centroid), frame.axes[a]);
        low[a] = std::min(low[a], c);
        high[a] = std::max(high[a], c);
      }
  for(int a = 0; a < 3; ++a)
    extent = std::max(extent, high[a] - low[a]);
  const double margin = 0.06 * view_size;
  const double scale = extent > 0 ? (view_size - 2 * margin) / extent : 1.0;
  const int header = title.empty() ? 0 : 24;

  auto round1 = [](double v) {
    std::ostringstream s;
    s.precision(1);
    s << std::fixed << v;
    std::string text = s.str();
    if(text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0)
      text.erase(text.size() - 2);
    return text;
  };
  std::string escaped;
  for(char c : title)
    escaped += c == '<' ? std::string("&lt;") : c == '>' ? std::string("&gt;") : c == '&' ? std::string("&amp;") : std::string(1, c);

  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 3 * view_size << "\" height=\""
     << view_size + header << "\" viewBox=\"0 0 " << 3 * view_size << ' ' << view_size + header << "\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if(header > 0)
    os << "<text x=\"8\" y=\"17\" font-family=\"sans-serif\" font-size=\"14\">" << escaped << "</text>\n";

  for(std::size_t v = 0; v < views.size(); ++v)
  {
    const internal::Svg_view& view = views[v];
    const Vec3 toward_viewer = internal::cross3(view.right, view.up);
    const double x0 = static_cast<double>(v) * view_size + view_size / 2.0;
    const double y0 = header + view_size / 2.0;
    const double cr = internal::dot3(frame.centroid, view.right), cu = internal::dot3(frame.centroid, view.up);
    auto screen = [&](const Vec3& p) {
      return std::array<double, 2>{x0 + scale * (internal::dot3(p, view.right) - cr),
                                   y0 - scale * (internal::dot3(p, view.up) - cu)};
    };

    // Front-facing triangles, back to front, with a grey level from the facing angle.
    struct Drawn { double depth; int grey; std::size_t index; int label; };
    std::vector<Drawn> drawn;
    for(std::size_t i = 0; i < triangles.size(); ++i)
    {
      const auto& t = triangles[i];
      const Vec3 n = internal::cross3(Geodesic_skeleton::internal::sub(t[1], t[0]),
                                     Geodesic_skeleton::internal::sub(t[2], t[0]));
      const double length = std::sqrt(internal::dot3(n, n));
      if(!(length > 0))
        continue;
      const double facing = internal::dot3(n, toward_viewer) / length;
      if(facing <= 0)
        continue;
      const double depth = internal::dot3(t[0], toward_viewer) + internal::dot3(t[1], toward_viewer) +
                           internal::dot3(t[2], toward_viewer);
      drawn.push_back({depth, static_cast<int>(std::min(15.0, facing * 16)), i,
                       overlay.triangle_labels.empty() ? -1 : overlay.triangle_labels.at(i)});
    }
    // Back to front by slabs of depth (a 48th of the depth range each), and by grey within
    // a slab, so that a slab's triangles of one grey make one path: front-facing triangles
    // of one slab seldom overlap.
    double nearest = -1e300, farthest = 1e300;
    for(const Drawn& d : drawn)
    {
      nearest = std::max(nearest, d.depth);
      farthest = std::min(farthest, d.depth);
    }
    const double slab = (nearest - farthest) / 48 + 1e-300;
    auto slab_of = [&](const Drawn& d) { return static_cast<int>((d.depth - farthest) / slab); };
    std::sort(drawn.begin(), drawn.end(), [&](const Drawn& a, const Drawn& b) {
      const int sa = slab_of(a), sb = slab_of(b);
      return sa != sb ? sa < sb : a.label != b.label ? a.label < b.label : a.grey != b.grey ? a.grey < b.grey : a.depth < b.depth;
    });
    os << "<g stroke-linejoin=\"round\" stroke-width=\"0.6\">\n";
    for(std::size_t k = 0; k < drawn.size();)
    {
      const int grey = drawn[k].grey, label = drawn[k].label;
      const std::string fill = triangle_fill(label, grey);
      os << "<path fill=\"" << fill << "\" stroke=\"" << fill << "\" d=\"";
      for(; k < drawn.size() && drawn[k].grey == grey && drawn[k].label == label; ++k)
      {
        // Whole pixels; a triangle that rounds to less than a pixel is left out (its
        // neighbours, drawn with round joins, cover it).
        const auto& t = triangles[drawn[k].index];
        long px[3][2];
        for(int c = 0; c < 3; ++c)
        {
          const auto s = screen(t[c]);
          px[c][0] = std::lround(s[0]);
          px[c][1] = std::lround(s[1]);
        }
        const long twice_area = (px[1][0] - px[0][0]) * (px[2][1] - px[0][1]) -
                                (px[2][0] - px[0][0]) * (px[1][1] - px[0][1]);
        if(twice_area == 0)
          continue;
        os << 'M' << px[0][0] << ' ' << px[0][1] << 'L' << px[1][0] << ' ' << px[1][1] << 'L' << px[2][0]
           << ' ' << px[2][1] << 'Z';
      }
      os << "\"/>\n";
    }
    os << "</g>\n";

    // The skeleton on top.
    for(const Svg_overlay::Line& line : overlay.lines)
    {
      os << "<polyline fill=\"none\" stroke=\"#111\" stroke-width=\"2\""
         << (line.dashed ? " stroke-dasharray=\"4 3\"" : "") << " points=\"";
      for(const Vec3& p : line.points)
      {
        const auto s = screen(p);
        os << round1(s[0]) << ',' << round1(s[1]) << ' ';
      }
      os << "\"/>\n";
    }
    for(const Svg_overlay::Dot& dot : overlay.dots)
    {
      const auto s = screen(dot.point);
      const double r = dot.radius < 0 ? -dot.radius : std::max(2.0, 0.3 * scale * dot.radius);
      os << "<circle cx=\"" << round1(s[0]) << "\" cy=\"" << round1(s[1]) << "\" r=\"" << round1(r)
         << "\" fill=\"" << dot.colour << "\" fill-opacity=\"0.45\" stroke=\"#111\" stroke-width=\"0.5\"/>\n";
    }
    os << "<text x=\"" << static_cast<double>(v) * view_size + 6 << "\" y=\"" << header + view_size - 6
       << "\" font-family=\"sans-serif\" font-size=\"12\" fill=\"#444\">" << view.name << "</text>\n";
  }
  os << "</svg>\n";
  return os;
}

} // namespace internal

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // GEODESIC_SKELETON_SKELETONIZE_SVG_PREVIEW_H
