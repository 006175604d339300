// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_INTERNAL_MESH_FILE_CHECKS_H
#define CGAL_GEODESIC_SKELETON_IO_INTERNAL_MESH_FILE_CHECKS_H

// Checks that IO::read_mesh() runs on a file before CGAL 5.5's readers see it: those readers
// trust their input, and the fuzzer (fuzz/) found files that crash them, hang them or make
// them read out of bounds (fuzz/regressions/). Each check returns what is wrong with the
// file, or an empty string.

#include <CGAL/IO/OFF/File_scanner_OFF.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
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

// The size in bytes of the file that `in` reads, `in` left at its start.
inline double file_size_of(std::ifstream& in)
{
  in.seekg(0, std::ios::end);
  const double size = double(in.tellg());
  in.seekg(0);
  return size;
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
  const double file_size = file_size_of(in);
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

// The most items (vertices and faces together) a header may announce: a few bytes must
// not ask for gigabytes of storage. Every item also takes two bytes of the file at least
// ("0\n" is the shortest face), checked where the file's size is known.
constexpr double largest_header_count = double(1 << 28);

// CGAL 5.5's OFF header reader (File_header_OFF_impl.h) reads the three counts as int and
// derives a halfedge count from them in int arithmetic: twice the edge count, or 2.1 times
// (vertices + faces + 10), which overflow past about 10^9 (undefined behaviour), before any
// check of the file's lines could run; found by fuzzing (fuzz/regressions/off_huge_*.off).
// This reads the header's keyword and counts as text first and bounds each count and the
// sum of the vertex and face counts by 2^28 (a binary OFF file's counts, which follow the
// keyword in binary, are left to CGAL). Returns what is wrong, or an empty string.
inline std::string off_header_counts_problem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> tokens;
  std::string line;
  while(tokens.size() < 6 && std::getline(in, line))
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string word;
    while(tokens.size() < 6 && words >> word)
      tokens.push_back(word);
  }
  if(tokens.empty() || tokens[0].find("OFF") == std::string::npos)
    return std::string(); // not an OFF header: CGAL refuses the file itself
  // CGAL ends the keyword at its first character that is not a letter or a digit, and drops
  // that character: "OFF\x18" "1040010041" is the keyword OFF and a count (found by fuzzing).
  const std::string& first = tokens[0];
  const std::size_t keyword_end = std::size_t(
      std::find_if(first.begin(), first.end(), [](unsigned char c) { return !std::isalnum(c); }) - first.begin());
  if(keyword_end + 1 < first.size())
    tokens.insert(tokens.begin() + 1, first.substr(keyword_end + 1));
  tokens[0].resize(keyword_end);
  std::size_t first_count = 1;
  if(tokens.size() > 1 && tokens[1] == "BINARY")
    return std::string();
  if(tokens[0].find("nOFF") != std::string::npos)
    ++first_count; // the dimension comes first
  double vertices_and_faces = 0;
  for(std::size_t i = first_count; i < first_count + 3 && i < tokens.size(); ++i)
  {
    std::istringstream number(tokens[i]);
    double value = 0;
    if(!(number >> value))
      return std::string(); // not a number: CGAL refuses it
    if(!(value >= 0 && value <= largest_header_count))
      return "the OFF header's counts must be in [0, 2^28], got " + tokens[i];
    if(i < first_count + 2)
      vertices_and_faces += value;
  }
  if(vertices_and_faces > largest_header_count)
    return "the OFF header announces more than 2^28 vertices and faces";
  return std::string();
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
  if(const std::string problem = off_header_counts_problem(path); !problem.empty())
    return problem;
  std::ifstream in(path, std::ios::binary);
  const double file_size = file_size_of(in);
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
      return "vertex " + std::to_string(v) + " does not start with " + std::to_string(3 + H) + " numbers";
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
} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_INTERNAL_MESH_FILE_CHECKS_H
