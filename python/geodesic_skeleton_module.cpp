// The Python module geodesic_skeleton: the package's functions with numpy arrays in and
// out (python/README.md). Meshes come in as V (n x 3 numbers) and F (m x 3 vertex indices)
// and are built into a CGAL::Surface_mesh; the settings are the named parameters' names,
// read from skeletonize's table (examples/skeletonize_settings.h) with the library's
// ranges. The GIL is released while the C++ runs, so threads rig meshes in parallel.

#include "skeletonize_settings.h"

#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/IO/gltf.h>
#include <CGAL/Geodesic_skeleton/IO/internal/indexed_soup.h>
#include <CGAL/Geodesic_skeleton/IO/json.h>
#include <CGAL/Geodesic_skeleton/IO/read_control_skeleton_json.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh_with_assimp.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/geodesic_distances.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <nlohmann/json.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace gs = CGAL::Geodesic_skeleton;
namespace settings = skeletonize_settings;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Curve = gs::Curve_skeleton<Point, vertex_descriptor>;
using Control = gs::Control_skeleton<Point>;
using Index = std::int64_t;

// ---- Arrays in and out ------------------------------------------------------------------

template <typename T>
py::array_t<T> new_array(std::vector<py::ssize_t> shape)
{
  return py::array_t<T>(shape);
}

// An n x 3 array of doubles from any array-like of numbers (any dtype, order, or a list).
std::vector<std::array<double, 3>> points_of(const py::handle& object, const char* name)
{
  py::array array;
  try
  {
    array = py::array::ensure(object);
  }
  catch(const py::error_already_set&)
  {
  }
  if(!array || !(array.dtype().kind() == 'f' || array.dtype().kind() == 'i' || array.dtype().kind() == 'u'))
    throw py::value_error(std::string(name) + " must be an array of numbers (n x 3)");
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if(values.ndim() != 2 || values.shape(1) != 3)
    throw py::value_error(std::string(name) + " must have shape (n, 3), got " +
                          std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                              array.shape(), array.shape() + array.ndim()))))));
  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(values.shape(0)));
  const double* data = values.data();
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int c = 0; c < 3; ++c)
    {
      points[i][c] = data[3 * i + c];
      if(!std::isfinite(points[i][c]))
        throw py::value_error(std::string(name) + "[" + std::to_string(i) +
                              "] has a non-finite coordinate (NaN or infinite)");
    }
  return points;
}

// A one- or two-dimensional array of integers (any integer dtype, order, or a list).
py::array_t<Index, py::array::c_style | py::array::forcecast> integers_of(const py::handle& object, const char* name)
{
  py::array array;
  try
  {
    array = py::array::ensure(object);
  }
  catch(const py::error_already_set&)
  {
  }
  if(!array || !(array.dtype().kind() == 'i' || array.dtype().kind() == 'u'))
    throw py::value_error(std::string(name) + " must be an array of integers");
  return py::array_t<Index, py::array::c_style | py::array::forcecast>::ensure(array);
}

std::vector<std::array<Index, 3>> faces_of(const py::handle& object, std::size_t vertices)
{
  const auto values = integers_of(object, "F");
  if(values.ndim() != 2 || values.shape(1) != 3)
    throw py::value_error("F must have shape (m, 3): triangles as three vertex indices");
  if(values.shape(0) == 0)
    throw py::value_error("F has no faces");
  std::vector<std::array<Index, 3>> faces(static_cast<std::size_t>(values.shape(0)));
  const Index* data = values.data();
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      faces[f][c] = data[3 * f + c];
      if(faces[f][c] < 0 || faces[f][c] >= Index(vertices))
        throw py::value_error("F[" + std::to_string(f) + "] refers to vertex " + std::to_string(faces[f][c]) +
                              ", but V has only " + std::to_string(vertices) + " vertices");
    }
  return faces;
}

// ---- The mesh ---------------------------------------------------------------------------

// A mesh built from V and F, and the mesh vertex of each row of V. As IO::read_mesh()
// builds the mesh of a file: when the triangles are an oriented manifold, directly from
// them (the same mesh as read_mesh()'s, so the same rig as skeletonize's), row i being
// vertex i; otherwise repaired (merged duplicates, split non-manifold vertices, faces
// oriented), each row then taking the vertex at its position, or the nearest one for a
// point the repair dropped.
//
// This uses read_mesh()'s own fast builder, from IO/internal/indexed_soup.h (an internal
// header): CGAL's polygon_soup_to_polygon_mesh() gives the same mesh, but its search of the
// mesh for every edge costs about as much as the whole chain on the demo cow.
struct Input_mesh
{
  Mesh mesh;
  std::vector<vertex_descriptor> vertex_of_row;
  double milliseconds = 0; // building the mesh, as input_mesh() times it

  // Must be built without the GIL: it copies nothing from Python.
  Input_mesh(std::vector<std::array<double, 3>> V, const std::vector<std::array<Index, 3>>& F)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    namespace soup_io = CGAL::Geodesic_skeleton::IO::internal;
    soup_io::Indexed_soup soup;
    soup.points = std::move(V);
    soup.corners.reserve(3 * F.size());
    soup.offsets.reserve(F.size() + 1);
    for(const auto& f : F)
    {
      for(const Index i : f)
        soup.corners.push_back(static_cast<std::uint32_t>(i));
      soup.close_polygon();
    }
    const std::size_t rows = soup.points.size();
    {
      const soup_io::Directed_edge_table edges(soup);
      if(soup_io::is_oriented_manifold(soup, edges))
      {
        soup_io::build_mesh_from_manifold_soup(soup, edges, mesh, get(CGAL::vertex_point, mesh));
        vertex_of_row.reserve(rows);
        for(std::size_t i = 0; i < rows; ++i)
          vertex_of_row.push_back(vertex_descriptor(static_cast<Mesh::size_type>(i)));
        return;
      }
    }
    std::vector<Point> points;
    points.reserve(rows);
    for(const auto& p : soup.points)
      points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::vector<std::size_t>> polygons(F.size());
    for(std::size_t f = 0; f < F.size(); ++f)
      polygons[f] = {std::size_t(F[f][0]), std::size_t(F[f][1]), std::size_t(F[f][2])};
    const std::vector<Point> row_points = points;
    if(PMP::is_polygon_soup_a_polygon_mesh(polygons))
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    else
    {
      PMP::repair_polygon_soup(points, polygons);
      PMP::orient_polygon_soup(points, polygons);
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      if(num_faces(mesh) == 0)
        throw std::invalid_argument("the mesh has no faces (every face is degenerate)");
    }
    std::map<Point, vertex_descriptor> vertex_at;
    for(vertex_descriptor v : vertices(mesh))
      vertex_at.emplace(mesh.point(v), v);
    vertex_of_row.resize(rows);
    for(std::size_t i = 0; i < rows; ++i)
    {
      if(const auto found = vertex_at.find(row_points[i]); found != vertex_at.end())
      {
        vertex_of_row[i] = found->second;
        continue;
      }
      double best = HUGE_VAL;
      for(vertex_descriptor v : vertices(mesh))
        if(const double d = CGAL::squared_distance(row_points[i], mesh.point(v)); d < best)
        {
          best = d;
          vertex_of_row[i] = v;
        }
    }
  }
};

// Runs `work` without the GIL; the package's exceptions become ValueError with their message.
template <typename Work>
auto without_gil(Work&& work)
{
  try
  {
    py::gil_scoped_release release;
    return work();
  }
  catch(const std::bad_alloc&)
  {
    throw;
  }
  catch(const py::error_already_set&)
  {
    throw;
  }
  catch(const py::builtin_exception&)
  {
    throw;
  }
  catch(const std::exception& e)
  {
    throw py::value_error(e.what());
  }
}

// V and F checked and copied (with the GIL), then the mesh built (without it).
Input_mesh input_mesh(const py::handle& V, const py::handle& F)
{
  auto points = points_of(V, "V");
  auto faces = faces_of(F, points.size());
  return without_gil([&] {
    const auto start = std::chrono::steady_clock::now();
    Input_mesh input(std::move(points), faces);
    input.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return input;
  });
}

// ---- Settings ---------------------------------------------------------------------------

std::string number_text(double value)
{
  std::ostringstream text;
  text.precision(12);
  text << value;
  return text.str();
}

// The keyword settings of `caller`, those of skeletonize's table that `takes` accepts
// (plus fill_holes and keep_surface_voxels when `voxel_flags`), checked against the
// library's ranges: "caller: name must be <valid values>, got <value>", as the C++ says.
template <typename Takes>
settings::Settings settings_of(const py::kwargs& kwargs, const char* caller, Takes takes, bool voxel_flags)
{
  settings::Settings s;
  for(const auto& [key, value] : kwargs)
  {
    const std::string name = py::str(key);
    if(voxel_flags && (name == "fill_holes" || name == "keep_surface_voxels"))
    {
      if(!py::isinstance<py::bool_>(value))
        throw py::type_error(std::string(caller) + ": " + name + " must be True or False");
      (name == "fill_holes" ? s.fill_holes : s.keep_surface_voxels) = value.template cast<bool>();
      continue;
    }
    const settings::Numeric_setting* setting = settings::setting_of_parameter(name);
    if(setting == nullptr || !takes(*setting))
    {
      std::string names;
      for(const settings::Numeric_setting& t : settings::numeric_settings)
        if(takes(t))
          names += std::string(names.empty() ? "" : ", ") + t.range.name;
      if(voxel_flags)
        names += ", fill_holes, keep_surface_voxels";
      throw py::type_error(std::string(caller) + "() got an unexpected setting '" + name + "' (its settings: " +
                           names + ")");
    }
    if(py::isinstance<py::bool_>(value) || !(py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
                                             py::hasattr(value, "__float__")))
      throw py::type_error(std::string(caller) + ": " + name + " must be a number, got " +
                           std::string(py::repr(value)));
    const double v = py::float_(py::reinterpret_borrow<py::object>(value)).template cast<double>();
    if(!setting->range.contains(v))
      throw py::value_error(std::string(caller) + ": " + name + " must be " + setting->range.valid_values() +
                            ", got " + number_text(v));
    setting->set(s, v);
  }
  return s;
}

bool chain_setting(const settings::Numeric_setting& s) { return (s.use & settings::chain) != 0; }
bool weights_setting(const settings::Numeric_setting& s) { return (s.use & settings::weights) != 0; }

// ---- The rig ----------------------------------------------------------------------------

// A control skeleton, the curve skeleton it was split from (when extracted or read with
// one) and the chain's timings.
struct Rig
{
  Control control;
  Curve curve;
  std::vector<std::pair<std::string, double>> timings_ms;
  double chain_ms = 0;
  double mesh_ms = 0; // building the Surface_mesh from V and F

  std::size_t joints() const { return num_vertices(control); }
  std::size_t bones() const { return num_edges(control); }

  nlohmann::json json() const
  {
    const nlohmann::json c = gs::IO::control_skeleton_to_json(control);
    return {{"skeleton", gs::IO::curve_skeleton_to_json(curve)},
            {"control", {{"joints", c["joints"]}, {"bones", c["bones"]}, {"cut_bones", c["cut_bones"]},
                         {"roots", c["roots"]}}}};
  }
};

// The "skeleton" object of the contract: points, radii, edges.
Curve curve_of_json(const nlohmann::json& skeleton)
{
  Curve curve;
  if(!skeleton.is_object() || !skeleton.contains("points") || !skeleton["points"].is_array())
    throw std::invalid_argument("\"skeleton\" must be an object with \"points\", \"radii\" and \"edges\"");
  const nlohmann::json& points = skeleton["points"];
  const nlohmann::json radii = skeleton.value("radii", nlohmann::json::array());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const nlohmann::json& p = points[i];
    if(!p.is_array() || p.size() != 3 || !std::all_of(p.begin(), p.end(), [](const auto& c) { return c.is_number(); }))
      throw std::invalid_argument("skeleton.points[" + std::to_string(i) + "] must be an array of three numbers");
    gs::Curve_skeleton_vertex<Point, vertex_descriptor> vertex;
    vertex.point = Point(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    if(i < radii.size() && radii[i].is_number())
      vertex.radius = radii[i].get<double>();
    add_vertex(vertex, curve);
  }
  for(const nlohmann::json& e : skeleton.value("edges", nlohmann::json::array()))
  {
    if(!e.is_array() || e.size() != 2 || !e[0].is_number_unsigned() || !e[1].is_number_unsigned() ||
       e[0].get<std::size_t>() >= points.size() || e[1].get<std::size_t>() >= points.size())
      throw std::invalid_argument("skeleton.edges: each edge must be two indices of \"points\"");
    add_edge(e[0].get<std::size_t>(), e[1].get<std::size_t>(), curve);
  }
  return curve;
}

Rig rig_of_json(const std::string& text)
{
  nlohmann::json json;
  try
  {
    json = nlohmann::json::parse(text);
  }
  catch(const nlohmann::json::exception& e)
  {
    throw py::value_error(std::string("Rig.from_json: not JSON: ") + e.what());
  }
  return without_gil([&] {
    Rig rig;
    try
    {
      gs::IO::read_control_skeleton_json(json, rig.control);
      if(json.is_object() && json.contains("skeleton"))
        rig.curve = curve_of_json(json["skeleton"]);
    }
    catch(const std::exception& e)
    {
      throw std::invalid_argument(std::string("Rig.from_json: ") + e.what());
    }
    return rig;
  });
}

py::array_t<double> points_array(const std::vector<Point>& points)
{
  auto out = new_array<double>({py::ssize_t(points.size()), 3});
  auto a = out.mutable_unchecked<2>();
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    a(i, 0) = points[i].x();
    a(i, 1) = points[i].y();
    a(i, 2) = points[i].z();
  }
  return out;
}

py::array_t<Index> pairs_array(const std::vector<std::pair<std::size_t, std::size_t>>& pairs)
{
  auto out = new_array<Index>({py::ssize_t(pairs.size()), 2});
  auto a = out.mutable_unchecked<2>();
  for(std::size_t i = 0; i < pairs.size(); ++i)
  {
    a(i, 0) = Index(pairs[i].first);
    a(i, 1) = Index(pairs[i].second);
  }
  return out;
}

template <typename Graph>
py::array_t<Index> edges_array(const Graph& graph)
{
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(const auto e : boost::make_iterator_range(edges(graph)))
    pairs.emplace_back(std::size_t(source(e, graph)), std::size_t(target(e, graph)));
  return pairs_array(pairs);
}

py::array_t<double> doubles_array(const std::vector<double>& values)
{
  auto out = new_array<double>({py::ssize_t(values.size())});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// ---- Weights ----------------------------------------------------------------------------

// The weights of the mesh's vertices from an n x B array (dense or a SciPy sparse matrix)
// by rows of V: each vertex's non-zero weights by decreasing weight, at most 8.
std::vector<gs::Bone_weights> bone_weights_of(const py::handle& W, const Input_mesh& input, std::size_t bones)
{
  const std::size_t rows = input.vertex_of_row.size();
  std::vector<std::vector<std::pair<double, std::size_t>>> entries(rows);
  auto check = [&](double w, std::size_t row) {
    if(!(w >= 0) || !std::isfinite(w))
      throw py::value_error("W[" + std::to_string(row) + "] has a weight that is negative or not finite");
  };
  if(py::hasattr(W, "tocsr"))
  {
    const py::object csr = W.attr("tocsr")();
    const auto shape = csr.attr("shape").cast<std::pair<std::size_t, std::size_t>>();
    if(shape.first != rows || shape.second != bones)
      throw py::value_error("W must have shape (" + std::to_string(rows) + ", " + std::to_string(bones) +
                            "): one row per vertex, one column per bone");
    const auto indptr = integers_of(csr.attr("indptr"), "W.indptr");
    const auto indices = integers_of(csr.attr("indices"), "W.indices");
    const auto data = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(csr.attr("data"));
    for(std::size_t r = 0; r < rows; ++r)
      for(Index k = indptr.data()[r]; k < indptr.data()[r + 1]; ++k)
      {
        check(data.data()[k], r);
        if(data.data()[k] > 0)
          entries[r].emplace_back(data.data()[k], std::size_t(indices.data()[k]));
      }
  }
  else
  {
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(W);
    if(!values || values.ndim() != 2 || std::size_t(values.shape(0)) != rows || std::size_t(values.shape(1)) != bones)
      throw py::value_error("W must be an array of shape (" + std::to_string(rows) + ", " + std::to_string(bones) +
                            "): one row per vertex, one column per bone");
    for(std::size_t r = 0; r < rows; ++r)
      for(std::size_t b = 0; b < bones; ++b)
      {
        const double w = values.data()[r * bones + b];
        check(w, r);
        if(w > 0)
          entries[r].emplace_back(w, b);
      }
  }
  std::vector<gs::Bone_weights> weights(num_vertices(input.mesh));
  for(std::size_t r = 0; r < rows; ++r)
  {
    auto& e = entries[r];
    if(e.size() > gs::Bone_weights::capacity)
      throw py::value_error("W[" + std::to_string(r) + "] has " + std::to_string(e.size()) +
                            " non-zero weights; a vertex holds at most 8");
    std::stable_sort(e.begin(), e.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    gs::Bone_weights& out = weights[std::size_t(input.vertex_of_row[r])];
    out.clear();
    for(const auto& [w, b] : e)
      out.push_back(std::uint32_t(b), float(w));
  }
  return weights;
}

// ---- The voxel stages -------------------------------------------------------------------

struct Voxels
{
  gs::Dense_voxel_grid grid;
  int resolution = gs::default_voxel_resolution; // voxelize()'s

  std::vector<gs::Voxel_key> keys() const
  {
    std::vector<gs::Voxel_key> out;
    out.reserve(grid.size());
    grid.for_each([&](const gs::Voxel_key& k) { out.push_back(k); });
    return out;
  }
};

struct Distance_field
{
  gs::Voxel_distance_field field;
  std::vector<gs::Voxel_key> keys; // the solid's voxels, in the order of Voxels.coordinates
};

py::array_t<std::int32_t> keys_array(const std::vector<gs::Voxel_key>& keys)
{
  auto out = new_array<std::int32_t>({py::ssize_t(keys.size()), 3});
  auto a = out.mutable_unchecked<2>();
  for(std::size_t i = 0; i < keys.size(); ++i)
  {
    a(i, 0) = keys[i].x;
    a(i, 1) = keys[i].y;
    a(i, 2) = keys[i].z;
  }
  return out;
}

// The functions on a built mesh: those of the module build it from V and F, Mesh's use its own.
Rig rig_of_mesh(const Input_mesh& input, const settings::Settings& s)
{
  return without_gil([&] {
    Rig rig;
    settings::Chain_outputs<Mesh, Point> outputs;
    outputs.curve = &rig.curve;
    const gs::Control_skeleton_report report = settings::extract_control_skeleton(input.mesh, rig.control, s, outputs);
    rig.timings_ms = report.timings_ms;
    rig.chain_ms = report.total_ms;
    rig.mesh_ms = input.milliseconds;
    return rig;
  });
}

py::object weights_of_mesh(const Input_mesh& input, const Rig& rig, bool sparse, const settings::Settings& s)
{
  const std::vector<gs::Bone_weights> weights = without_gil([&] {
    std::vector<gs::Bone_weights> w(num_vertices(input.mesh));
    std::vector<int> segment(num_vertices(input.mesh), -1);
    settings::compute_skinning_weights(input.mesh, rig.control, s, nullptr,
                                       boost::make_iterator_property_map(w.begin(), get(CGAL::vertex_index, input.mesh)),
                                       boost::make_iterator_property_map(segment.begin(), get(CGAL::vertex_index, input.mesh)),
                                       true);
    return w;
  });
  const std::size_t rows = input.vertex_of_row.size(), bones = rig.bones();
  if(!sparse)
  {
    auto out = new_array<double>({py::ssize_t(rows), py::ssize_t(bones)});
    std::fill(out.mutable_data(), out.mutable_data() + rows * bones, 0.);
    for(std::size_t r = 0; r < rows; ++r)
    {
      const gs::Bone_weights& w = weights[std::size_t(input.vertex_of_row[r])];
      for(std::size_t i = 0; i < w.size(); ++i)
        out.mutable_data()[r * bones + w.bone[i]] = w.weight[i];
    }
    return std::move(out);
  }
  std::vector<Index> row_of, column;
  std::vector<double> value;
  for(std::size_t r = 0; r < rows; ++r)
  {
    const gs::Bone_weights& w = weights[std::size_t(input.vertex_of_row[r])];
    for(std::size_t i = 0; i < w.size(); ++i)
    {
      row_of.push_back(Index(r));
      column.push_back(Index(w.bone[i]));
      value.push_back(w.weight[i]);
    }
  }
  const py::module_ scipy_sparse = py::module_::import("scipy.sparse");
  return scipy_sparse.attr("csr_matrix")(
      py::make_tuple(py::array(py::cast(value)), py::make_tuple(py::array(py::cast(row_of)), py::array(py::cast(column)))),
      py::arg("shape") = py::make_tuple(rows, bones));
}

void write_gltf_of_mesh(const std::string& path, const Input_mesh& input, const Rig& rig, const py::object& W)
{
  const std::vector<gs::Bone_weights> weights = bone_weights_of(W, input, rig.bones());
  without_gil([&] {
    gs::IO::write_glTF(path, input.mesh, rig.control,
                       boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, input.mesh)));
    return 0;
  });
}

const char* const rig_doc = R"(A control skeleton: joints, parents and bones, with the curve skeleton it was split from.

Arrays are copies (numpy): ``joints`` (J x 3), ``parents`` (J, -1 for a root), ``radii`` (J, the
MAT radius at each joint, world units), ``kinds`` (J strings: root, junction, bend, end), ``bones``
(B x 2, parent and child joint, in the order of the skinning weights' columns), ``cut_bones``
(C x 2), ``roots``, and the curve skeleton's ``curve_points`` (P x 3), ``curve_radii`` (P) and
``curve_edges`` (E x 2). ``to_json()`` and ``Rig.from_json()`` use skeletonize's JSON contract.)";

} // namespace

PYBIND11_MODULE(geodesic_skeleton, m)
{
  // numpy's C API, loaded now: pybind11 loads it on the first array made, in a static whose
  // initialisation imports numpy and so may give the GIL to a thread that then waits on that
  // static (a deadlock when the first calls come from two threads at once).
  py::module_::import("numpy");
  new_array<double>({0});

  m.doc() = "Animation control skeletons and skinning weights of triangle meshes (CGAL Geodesic_skeleton), "
            "with numpy arrays in and out. Meshes are V (n x 3 numbers) and F (m x 3 vertex indices).";

  // The settings, from the table that skeletonize reads.
  py::dict table;
  for(const settings::Numeric_setting& s : settings::numeric_settings)
  {
    py::dict entry;
    entry["low"] = s.range.low;
    entry["high"] = s.range.high;
    entry["default"] = s.default_text ? py::object(py::str(s.default_text)) : py::object(py::float_(s.range.default_value));
    entry["integer"] = s.range.integer;
    entry["odd"] = s.range.odd;
    entry["valid_values"] = s.range.valid_values();
    entry["option"] = s.option;
    entry["help"] = s.help;
    py::list functions;
    if(s.use & settings::chain)
      functions.append("extract_control_skeleton");
    if(s.use & settings::weights)
      functions.append("skinning_weights");
    entry["functions"] = functions;
    table[s.range.name] = entry;
  }
  m.attr("SETTINGS") = table;

  py::class_<Rig>(m, "Rig", rig_doc)
      .def_property_readonly("joints", [](const Rig& r) {
        std::vector<Point> points;
        for(std::size_t j = 0; j < r.joints(); ++j)
          points.push_back(r.control[j].point);
        return points_array(points);
      }, "joint positions (J x 3)")
      .def_property_readonly("parents", [](const Rig& r) {
        auto out = new_array<Index>({py::ssize_t(r.joints())});
        for(std::size_t j = 0; j < r.joints(); ++j)
        {
          const auto p = gs::parent_joint(j, r.control);
          out.mutable_data()[j] = p == boost::graph_traits<Control>::null_vertex() ? Index(-1) : Index(p);
        }
        return out;
      }, "the parent joint of each joint, -1 for a root (J)")
      .def_property_readonly("radii", [](const Rig& r) {
        std::vector<double> radii;
        for(std::size_t j = 0; j < r.joints(); ++j)
          radii.push_back(r.control[j].radius);
        return doubles_array(radii);
      }, "the MAT radius at each joint, world units (J)")
      .def_property_readonly("kinds", [](const Rig& r) {
        std::vector<std::string> kinds;
        for(std::size_t j = 0; j < r.joints(); ++j)
          kinds.push_back(gs::to_string(r.control[j].kind));
        return kinds;
      }, "root, junction, bend or end, for each joint")
      .def_property_readonly("bones", [](const Rig& r) { return edges_array(r.control); },
                             "bones as (parent, child) joints (B x 2), in the order of the weights' columns")
      .def_property_readonly("cut_bones", [](const Rig& r) {
        std::vector<std::pair<std::size_t, std::size_t>> pairs;
        for(const auto& b : r.control[boost::graph_bundle].cut_bones)
          pairs.emplace_back(b.source, b.target);
        return pairs_array(pairs);
      }, "the bones cut to make a tree of a cycle (C x 2)")
      .def_property_readonly("roots", [](const Rig& r) {
        const auto& roots = r.control[boost::graph_bundle].roots;
        auto out = new_array<Index>({py::ssize_t(roots.size())});
        std::copy(roots.begin(), roots.end(), out.mutable_data());
        return out;
      }, "the root joint of each tree")
      .def_property_readonly("curve_points", [](const Rig& r) {
        std::vector<Point> points;
        for(std::size_t v = 0; v < num_vertices(r.curve); ++v)
          points.push_back(r.curve[v].point);
        return points_array(points);
      }, "the curve skeleton's points (P x 3)")
      .def_property_readonly("curve_radii", [](const Rig& r) {
        std::vector<double> radii;
        for(std::size_t v = 0; v < num_vertices(r.curve); ++v)
          radii.push_back(r.curve[v].radius);
        return doubles_array(radii);
      }, "the MAT radius at the curve skeleton's points (P)")
      .def_property_readonly("curve_edges", [](const Rig& r) { return edges_array(r.curve); },
                             "the curve skeleton's edges (E x 2)")
      .def_property_readonly("timings_ms", [](const Rig& r) {
        py::dict out;
        for(const auto& [stage, ms] : r.timings_ms)
          out[py::str(stage)] = ms;
        return out;
      }, "the chain's stages and their milliseconds (empty for a rig read from JSON)")
      .def_property_readonly("chain_ms", [](const Rig& r) { return r.chain_ms; },
                             "milliseconds of the C++ extract_control_skeleton() call (0 for a rig read from JSON)")
      .def_property_readonly("mesh_ms", [](const Rig& r) { return r.mesh_ms; },
                             "milliseconds of building the C++ mesh from V and F (0 for a rig read from JSON)")
      .def("to_json", [](const Rig& r) { return r.json().dump(1); },
           "The rig in skeletonize's JSON contract: {\"skeleton\": {points, radii, edges}, \"control\": {joints, "
           "bones, cut_bones, roots}}.")
      .def_static("from_json", [](const py::object& json) {
        const std::string text = py::isinstance<py::str>(json) ? json.cast<std::string>()
                                 : py::isinstance<py::bytes>(json)
                                     ? json.cast<std::string>()
                                     : py::module_::import("json").attr("dumps")(json).cast<std::string>();
        return rig_of_json(text);
      }, py::arg("json"),
           "A rig from skeletonize's JSON (a str, or the parsed dict): its report, or a bare \"control\" object.")
      .def("__repr__", [](const Rig& r) {
        return "<geodesic_skeleton.Rig: " + std::to_string(r.joints()) + " joints, " + std::to_string(r.bones()) +
               " bones>";
      });

  m.def("read_mesh", [](const std::string& path) {
    Mesh mesh = without_gil([&] {
      Mesh mesh;
      const std::string extension = gs::IO::internal::file_extension(path);
      if(extension == "fbx" || extension == "gltf" || extension == "glb" || extension == "dae")
        gs::IO::read_mesh_with_assimp(path, mesh);
      else
        gs::IO::read_mesh(path, mesh);
      mesh.collect_garbage();
      return mesh;
    });
    auto V = new_array<double>({py::ssize_t(num_vertices(mesh)), 3});
    auto F = new_array<Index>({py::ssize_t(num_faces(mesh)), 3});
    auto v = V.mutable_unchecked<2>();
    auto f = F.mutable_unchecked<2>();
    for(vertex_descriptor u : vertices(mesh))
      for(int c = 0; c < 3; ++c)
        v(std::size_t(u), c) = mesh.point(u)[c];
    for(auto face : faces(mesh))
    {
      int c = 0;
      for(vertex_descriptor u : vertices_around_face(halfedge(face, mesh), mesh))
        if(c < 3)
          f(std::size_t(face), c++) = Index(std::size_t(u));
      if(c != 3)
        throw py::value_error(path + ": face " + std::to_string(std::size_t(face)) + " is not a triangle");
    }
    return py::make_tuple(V, F);
  }, py::arg("path"),
        "Reads a triangle mesh as skeletonize does (OFF, OBJ, PLY, STL and the other formats CGAL reads; FBX, "
        "glTF/GLB and DAE through Assimp), repaired when it is not a clean manifold. Returns (V, F): float64 "
        "(n x 3) and int64 (m x 3).");

  m.def("extract_control_skeleton", [](const py::object& V, const py::object& F, const py::kwargs& kwargs) {
    const settings::Settings s = settings_of(kwargs, "extract_control_skeleton", chain_setting, true);
    return rig_of_mesh(input_mesh(V, F), s);
  }, py::arg("V"), py::arg("F"),
        "Extracts the animation control skeleton of the mesh (V, F): the package's whole chain. Settings: the "
        "named parameters of extract_control_skeleton() (see SETTINGS: resolution, spur_length_factor, ...; "
        "fill_holes and keep_surface_voxels), checked against the library's ranges (ValueError otherwise). "
        "Returns a Rig.");

  m.def("skinning_weights", [](const py::object& V, const py::object& F, const Rig& rig, bool sparse,
                               const py::kwargs& kwargs) {
    const settings::Settings s = settings_of(kwargs, "skinning_weights", weights_setting, true);
    return weights_of_mesh(input_mesh(V, F), rig, sparse, s);
  }, py::arg("V"), py::arg("F"), py::arg("rig"), py::kw_only(), py::arg("sparse") = false,
        "Skinning weights of the mesh (V, F) for the rig's bones (bone heat through the solid): an (n x B) "
        "float64 array, or a scipy.sparse.csr_matrix with sparse=True; each row sums to 1 (the weights are "
        "float32 in the C++). Settings: resolution, max_bones_per_vertex, sharpness, minimum_weight, "
        "influence_ratio, fill_holes, keep_surface_voxels.");

  m.def("write_gltf", [](const std::string& path, const py::object& V, const py::object& F, const Rig& rig,
                         const py::object& W) {
    write_gltf_of_mesh(path, input_mesh(V, F), rig, W);
  }, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("rig"), py::arg("W"),
        "Writes the mesh skinned to the rig as glTF 2.0 (.glb binary or .gltf), as skeletonize -o does; W: the "
        "(n x B) weights, dense or SciPy sparse, at most 8 non-zero per row.");

  py::class_<Input_mesh, std::shared_ptr<Input_mesh>>(
      m, "Mesh",
      "The C++ mesh of (V, F), built once (checked, repaired if need be, as the functions build it) for "
      "several calls: rigging, skinning and writing a mesh build it once instead of three times.")
      .def(py::init([](const py::object& V, const py::object& F) { return std::make_shared<Input_mesh>(input_mesh(V, F)); }),
           py::arg("V"), py::arg("F"))
      .def_property_readonly("num_vertices", [](const Input_mesh& i) { return num_vertices(i.mesh); },
                             "vertices of the C++ mesh (the rows of V, unless the repair merged or split some)")
      .def_property_readonly("num_faces", [](const Input_mesh& i) { return num_faces(i.mesh); })
      .def("extract_control_skeleton", [](const Input_mesh& input, const py::kwargs& kwargs) {
        Rig rig = rig_of_mesh(input, settings_of(kwargs, "extract_control_skeleton", chain_setting, true));
        rig.mesh_ms = 0; // built before
        return rig;
      }, "extract_control_skeleton(V, F, **settings) on this mesh.")
      .def("skinning_weights", [](const Input_mesh& input, const Rig& rig, bool sparse, const py::kwargs& kwargs) {
        return weights_of_mesh(input, rig, sparse, settings_of(kwargs, "skinning_weights", weights_setting, true));
      }, py::arg("rig"), py::kw_only(), py::arg("sparse") = false, "skinning_weights(V, F, rig, ...) on this mesh.")
      .def("write_gltf", [](const Input_mesh& input, const std::string& path, const Rig& rig, const py::object& W) {
        write_gltf_of_mesh(path, input, rig, W);
      }, py::arg("path"), py::arg("rig"), py::arg("W"), "write_gltf(path, V, F, rig, W) of this mesh.")
      .def("__repr__", [](const Input_mesh& i) {
        return "<geodesic_skeleton.Mesh: " + std::to_string(num_vertices(i.mesh)) + " vertices, " +
               std::to_string(num_faces(i.mesh)) + " faces>";
      });

  m.def("geodesic_distances", [](const py::object& V, const py::object& F, const py::object& sources) {
    Input_mesh input = input_mesh(V, F);
    const auto s = integers_of(sources, "sources");
    if(s.ndim() > 1 || s.size() == 0)
      throw py::value_error("sources must be a vertex index or a non-empty list of them");
    std::vector<vertex_descriptor> source_vertices;
    for(py::ssize_t i = 0; i < s.size(); ++i)
    {
      const Index v = s.data()[i];
      if(v < 0 || v >= Index(input.vertex_of_row.size()))
        throw py::value_error("source " + std::to_string(v) + " is not a vertex (V has " +
                              std::to_string(input.vertex_of_row.size()) + ")");
      source_vertices.push_back(input.vertex_of_row[std::size_t(v)]);
    }
    const std::vector<double> distance = without_gil([&] {
      std::vector<double> d(num_vertices(input.mesh));
      gs::geodesic_distances(input.mesh, source_vertices,
                             boost::make_iterator_property_map(d.begin(), get(CGAL::vertex_index, input.mesh)));
      return d;
    });
    std::vector<double> by_row(input.vertex_of_row.size());
    for(std::size_t r = 0; r < by_row.size(); ++r)
      by_row[r] = distance[std::size_t(input.vertex_of_row[r])];
    return doubles_array(by_row);
  }, py::arg("V"), py::arg("F"), py::arg("sources"),
        "Geodesic distances (shortest paths along the edges) from a vertex or a list of vertices to every vertex "
        "(n,); infinity where no path reaches.");

  m.def("reeb_graph", [](const py::object& V, const py::object& F, const py::object& values, const py::kwargs& kwargs) {
    const settings::Settings s = settings_of(
        kwargs, "reeb_graph", [](const settings::Numeric_setting& t) { return &t.range == &gs::parameter_ranges::number_of_reeb_intervals; },
        false);
    Input_mesh input = input_mesh(V, F);
    const auto field_rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
    if(!field_rows || field_rows.ndim() != 1 || std::size_t(field_rows.size()) != input.vertex_of_row.size())
      throw py::value_error("values must hold one number per vertex (" + std::to_string(input.vertex_of_row.size()) + ")");
    std::vector<double> field(num_vertices(input.mesh), 0.);
    for(std::size_t r = 0; r < input.vertex_of_row.size(); ++r)
    {
      if(!std::isfinite(field_rows.data()[r]))
        throw py::value_error("values[" + std::to_string(r) + "] is not finite");
      field[std::size_t(input.vertex_of_row[r])] = field_rows.data()[r];
    }
    gs::Reeb_graph<Mesh> reeb = without_gil([&] {
      gs::Reeb_graph<Mesh> graph;
      gs::reeb_graph(input.mesh, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, input.mesh)),
                     s.reeb_intervals, graph);
      return graph;
    });
    std::vector<Point> points;
    auto intervals = new_array<Index>({py::ssize_t(num_vertices(reeb))});
    for(std::size_t v = 0; v < num_vertices(reeb); ++v)
    {
      points.push_back(reeb[v].point);
      intervals.mutable_data()[v] = Index(reeb[v].interval);
    }
    return py::make_tuple(points_array(points), edges_array(reeb), intervals);
  }, py::arg("V"), py::arg("F"), py::arg("values"),
        "The Reeb graph of a function on the vertices (n values), its range cut into number_of_reeb_intervals "
        "intervals (default 30). Returns (points (K x 3): the nodes' centroids, edges (E x 2), intervals (K)).");

  py::class_<Voxels>(m, "Voxels",
                     "A set of voxels on a grid aligned with the mesh's principal axes: coordinates (N x 3 int32 "
                     "keys), centres (N x 3, world), voxel_size, origin and axes (rows) of the grid.")
      .def_property_readonly("coordinates", [](const Voxels& v) { return keys_array(v.keys()); })
      .def_property_readonly("centres", [](const Voxels& v) {
        std::vector<Point> points;
        for(const gs::Voxel_key& k : v.keys())
          points.push_back(v.grid.frame().centre_point<Point>(k));
        return points_array(points);
      })
      .def_property_readonly("voxel_size", [](const Voxels& v) { return v.grid.frame().voxel_size(); })
      .def_property_readonly("origin", [](const Voxels& v) { return v.grid.frame().origin(); })
      .def_property_readonly("axes", [](const Voxels& v) {
        auto out = new_array<double>({3, 3});
        for(int i = 0; i < 3; ++i)
          for(int c = 0; c < 3; ++c)
            out.mutable_data()[3 * i + c] = v.grid.frame().axis(i)[c];
        return out;
      })
      .def("__len__", [](const Voxels& v) { return v.grid.size(); });

  py::class_<Distance_field>(m, "DistanceField",
                             "The squared distance of every solid voxel to the outside, in voxels (the MAT radius "
                             "function): coordinates, squared_distances and radii (world units) in the order of "
                             "the voxels' coordinates.")
      .def_property_readonly("coordinates", [](const Distance_field& d) { return keys_array(d.keys); })
      .def_property_readonly("squared_distances", [](const Distance_field& d) {
        auto out = new_array<std::uint32_t>({py::ssize_t(d.keys.size())});
        for(std::size_t i = 0; i < d.keys.size(); ++i)
          out.mutable_data()[i] = d.field.squared_distance(d.keys[i]);
        return out;
      })
      .def_property_readonly("radii", [](const Distance_field& d) {
        std::vector<double> radii;
        for(const gs::Voxel_key& k : d.keys)
          radii.push_back(d.field.radius(k));
        return doubles_array(radii);
      });

  m.def("voxelize", [](const py::object& V, const py::object& F, const py::kwargs& kwargs) {
    const settings::Settings s = settings_of(
        kwargs, "voxelize", [](const settings::Numeric_setting& t) { return &t.range == &gs::parameter_ranges::resolution; },
        true);
    Input_mesh input = input_mesh(V, F);
    return without_gil([&] {
      Voxels voxels;
      voxels.resolution = s.resolution;
      namespace params = CGAL::Geodesic_skeleton::parameters;
      gs::voxelize(input.mesh, voxels.grid,
                   params::combine(params::resolution(s.resolution), params::fill_holes(s.fill_holes),
                                   params::keep_surface_voxels(s.keep_surface_voxels)));
      return voxels;
    });
  }, py::arg("V"), py::arg("F"),
        "The solid interior of the mesh as voxels (resolution: the longest principal extent in voxels; "
        "fill_holes, keep_surface_voxels).");

  m.def("distance_transform", [](const Voxels& voxels) {
    return without_gil([&] { return Distance_field{gs::distance_transform(voxels.grid), voxels.keys()}; });
  }, py::arg("voxels"), "The exact Euclidean distance transform of the voxels (a DistanceField).");

  m.def("thin", [](const Voxels& voxels, const Distance_field& distances, const py::kwargs& kwargs) {
    const settings::Settings s = settings_of(
        kwargs, "thin", [](const settings::Numeric_setting& t) { return &t.range == &gs::parameter_ranges::thin_part_radius; },
        false);
    return without_gil([&] {
      Voxels thinned = voxels;
      namespace params = CGAL::Geodesic_skeleton::parameters;
      gs::thin(thinned.grid, distances.field,
               params::thin_part_radius(s.thin_part_radius.value_or(gs::default_thin_part_radius(voxels.resolution))));
      return thinned;
    });
  }, py::arg("voxels"), py::arg("distances"),
        "The grassfire thinning of the voxels (not modified): a one-voxel-thick curve skeleton with their "
        "topology, as new Voxels. thin_part_radius: in voxels (default: sqrt(2) at resolution 64 and below, scaled with the resolution of the voxels).");
}
