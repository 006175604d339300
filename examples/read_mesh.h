// read_mesh.h: how skeletonize reads a mesh file, shared with the fuzzer
// (fuzz/fuzz_skeletonize.cpp), so that the fuzzer reads exactly what the program reads.
// Not part of the package's API.

#ifndef GEODESIC_SKELETON_EXAMPLES_READ_MESH_H
#define GEODESIC_SKELETON_EXAMPLES_READ_MESH_H

#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace skeletonize {

/// A mesh file that cannot be read; the message names the file and the problem.
struct Mesh_reading_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

namespace internal {

// The extension of `path`, in lower case, as CGAL's readers pick the format.
inline std::string file_extension(const std::string& path)
{
  const std::string::size_type dot = path.rfind('.');
  std::string extension = dot == std::string::npos ? std::string() : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

// CGAL 5.5's PLY reader (CGAL/IO/PLY/PLY_reader.h) trusts the header. It adds each
// "property" line to the last "element" without checking that there is one: a property
// before any element calls back() on an empty vector, undefined behaviour that crashes.
// And it reads as many items as an element announces, even when the file has ended:
// "element face -1" (read as 2^64 - 1) is a loop without end. And it reads the x, y, z of
// a vertex as float or double without checking their declared type: an integer or list x
// fails an assertion, or with NDEBUG dereferences a null pointer. And it resizes a list to
// the size the file gives: a size of -1 in a list of signed sizes ("property list char
// int vertex_indices") is 2^64 - 1 (std::length_error), and 2^31 in a list of int sizes
// is gigabytes that the file never fills; so only lists with unsigned 8- or 16-bit sizes
// are read ("list uchar int" is what exporters write). All found by fuzzing
// (fuzz/regressions/ply_*). This reads the header as CGAL does, line by line, and returns
// what is wrong, or an empty string.
inline std::string ply_header_problem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const double file_size = double(in.tellg());
  in.seekg(0);
  std::string line;
  bool element_seen = false;
  std::string element;
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    std::string keyword;
    if(!(words >> keyword))
      continue;
    if(keyword == "element")
    {
      element_seen = true;
      std::string& type = element;
      type.clear();
      std::size_t number = 0;
      // An item takes a byte at least, in binary as in ASCII.
      if(words >> type >> number && double(number) > file_size)
        return "the PLY header announces " + std::to_string(number) + " items of '" + type +
               "', more than the file holds";
    }
    else if(keyword == "property" && !element_seen)
      return "the PLY header has a property before any element";
    else if(keyword == "property")
    {
      std::string type, name;
      words >> type >> name;
      if(type == "list")
      {
        const std::string size_type = name;
        words >> name >> name;
        if(size_type != "uchar" && size_type != "uint8" && size_type != "ushort" && size_type != "uint16")
          return "the PLY list property '" + name + "' has sizes of type " + size_type +
                 " (only uchar, uint8, ushort and uint16 are read)";
      }
      if(element != "vertex" && element != "vertices")
        continue;
      const bool coordinate = name == "x" || name == "y" || name == "z";
      const bool floating = type == "float" || type == "float32" || type == "double" || type == "float64";
      if(coordinate && !floating)
        return "the PLY vertex property '" + name + "' is a " + type + ", not a float or a double";
    }
    else if(keyword == "end_header")
      break;
  }
  return std::string();
}

// The colour entries e[first, first + n) of an OFF line as CGAL 5.5's File_scanner_OFF
// reads them (scan_color): one index into its map of 149 colours, or 3 (or 4, the last
// ignored) values that it casts to unsigned char, as they are when all three are integers,
// times 255 when not. Any other count, index or value reads past the line's entries or the
// colour map, or converts out of range: undefined behaviour.
inline bool off_colour_is_readable(const std::vector<double>& e, std::size_t first, long n)
{
  if(n != 1 && n != 3 && n != 4)
    return false;
  if(first + std::size_t(n) > e.size())
    return false;
  if(n == 1)
    return e[first] >= 0 && e[first] < 149;
  const bool integers = std::floor(e[first]) == e[first] && std::floor(e[first + 1]) == e[first + 1] &&
                        std::floor(e[first + 2]) == e[first + 2];
  for(std::size_t i = first; i < first + 3; ++i)
    if(!(e[i] >= 0 && e[i] <= (integers ? 255 : 1)))
      return false;
  return true;
}

// CGAL 5.5's OFF reader (CGAL/IO/OFF.h, File_scanner_OFF.h) trusts the file: it resizes
// its arrays to the counts of the header (a few bytes can ask for terabytes: bad_alloc),
// casts face sizes and indices read as doubles to std::size_t (-2 or 1e30: undefined
// behaviour), and reads colours and texture coordinates at positions it computes from the
// entry counts of each line, past the line's entries when they do not add up (a heap
// overflow), or from members it never set (STOFF without colours). All found by fuzzing
// (fuzz/regressions/off_*). This walks an ASCII OFF file line by line as CGAL does and
// returns what is wrong, or an empty string when CGAL can read it safely (the counts alone
// for a binary OFF file).
inline std::string off_file_problem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const double file_size = double(in.tellg());
  in.seekg(0);
  CGAL::File_scanner_OFF scanner(in);
  if(in.fail())
    return std::string(); // no OFF header: CGAL refuses the file itself
  const std::size_t vertices = scanner.size_of_vertices(), faces = scanner.size_of_facets();
  // Every vertex and face takes 2 bytes at least ("0\n" is the shortest face).
  if(2. * (double(vertices) + double(faces)) > file_size)
    return "the OFF header announces " + std::to_string(vertices) + " vertices and " +
           std::to_string(faces) + " faces, more than the file holds";
  if(scanner.binary())
    return std::string();
  if(scanner.has_textures() && !scanner.has_colors())
    return "texture coordinates (STOFF) without colours cannot be read (CGAL 5.5)";

  std::vector<double> e;
  auto next_line = [&]() {
    in >> CGAL::skip_comment_OFF;
    std::string line;
    std::getline(in, line);
    line = line.substr(0, line.find('#'));
    std::istringstream numbers(line);
    e.clear();
    double d;
    while(numbers >> CGAL::IO::iformat(d))
      e.push_back(d);
  };
  const long H = scanner.is_homogeneous() ? 1 : 0;
  bool vertex_colours = false;
  for(std::size_t v = 0; v < vertices && in; ++v)
  {
    next_line();
    if(e.size() < std::size_t(3 + H)) // with colours, CGAL reads them even so
      return "vertex " + std::to_string(v) + " has fewer than " + std::to_string(3 + H) + " coordinates";
    if(!scanner.has_colors())
      continue;
    // As File_scanner_OFF::scan_vertex counts them.
    long first = 3 + H, n = long(e.size()) - 3 - H;
    if(scanner.has_normals())
    {
      first += 3 + H;
      n -= 3 + H;
    }
    if(scanner.has_textures())
      n -= 2 + H;
    vertex_colours = vertex_colours || n != 0; // CGAL's flag stays set
    if(vertex_colours && (n < 0 || !off_colour_is_readable(e, std::size_t(first), n)))
      return "vertex " + std::to_string(v) + " has a colour that cannot be read";
    if(scanner.has_textures() && std::size_t(first + n + 2 + H) > e.size())
      return "vertex " + std::to_string(v) + " has no texture coordinates";
  }
  bool face_colours = false;
  for(std::size_t f = 0; f < faces && in; ++f)
  {
    next_line();
    if(e.empty())
      return std::string(); // CGAL stops there, cleanly
    if(!(e[0] >= 0 && e[0] <= double(e.size() - 1)))
      return "face " + std::to_string(f) + " does not have the number of vertices it announces";
    const std::size_t size = std::size_t(e[0]);
    for(std::size_t i = 1; i <= size; ++i)
      if(!(e[i] >= 0 && e[i] < double(vertices)))
        return "face " + std::to_string(f) + " refers to a vertex that does not exist";
    if(!scanner.has_colors())
      continue;
    const long n = long(e.size() - size - 1);
    face_colours = face_colours || n != 0;
    if(face_colours && !off_colour_is_readable(e, size + 1, n))
      return "face " + std::to_string(f) + " has a colour that cannot be read";
  }
  return std::string();
}

} // namespace internal

/// Reads any mesh CGAL reads (the format follows the extension of `path`). A file that is
/// not a clean manifold (as artists' meshes often are) is read as a polygon soup,
/// repaired, oriented and turned into a mesh.
/// \throws Mesh_reading_error when the file cannot be opened or read as a mesh.
template <typename Mesh>
Mesh read_mesh(const std::string& path)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;

  std::ifstream probe(path);
  if(!probe)
    throw Mesh_reading_error(path + ": cannot open the file");
  if(internal::file_extension(path) == "ply")
    if(const std::string problem = internal::ply_header_problem(path); !problem.empty())
      throw Mesh_reading_error(path + ": " + problem);
  if(internal::file_extension(path) == "off")
    if(const std::string problem = internal::off_file_problem(path); !problem.empty())
      throw Mesh_reading_error(path + ": " + problem);
  // Read as a polygon soup and checked before any mesh is built: CGAL 5.5's
  // read_polygon_mesh() builds the mesh from the soup without checking the face indices of
  // an OBJ file, and an index past the last vertex reads past its array (a heap overflow,
  // found by fuzzing: fuzz/regressions/obj_face_index_out_of_range.obj).
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    throw Mesh_reading_error(path + ": the file cannot be parsed as a mesh (OFF, OBJ, PLY, STL, ...)");
  for(const Point& p : points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Mesh_reading_error(path + ": a vertex has a non-finite coordinate (NaN or infinite)");
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i >= points.size())
        throw Mesh_reading_error(path + ": a face refers to a vertex that does not exist");
  Mesh mesh;
  // A clean manifold soup is taken as it is, as read_polygon_mesh() would take it.
  if(!polygons.empty() && PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    if(CGAL::is_valid_polygon_mesh(mesh) && !is_empty(mesh))
      return mesh;
    mesh.clear();
  }
  PMP::repair_polygon_soup(points, polygons);
  PMP::orient_polygon_soup(points, polygons);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(num_faces(mesh) == 0)
    throw Mesh_reading_error(path + ": the mesh has no faces");
  return mesh;
}

} // namespace skeletonize

#endif // GEODESIC_SKELETON_EXAMPLES_READ_MESH_H
