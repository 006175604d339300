// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_INTERNAL_FAST_SOUP_READERS_H
#define CGAL_GEODESIC_SKELETON_IO_INTERNAL_FAST_SOUP_READERS_H

// Fast readers of the common forms of OFF, OBJ and binary STL into an Indexed_soup: the
// whole file mapped or read at once, numbers parsed with std::from_chars (no stream, no
// locale), storage reserved from the counts. They parse what exporters write and nothing
// more: each returns false (and leaves the soup unspecified) at the first thing it does not
// know (homogeneous or n-dimensional OFF, a binary STL that starts with "solid", negative
// OBJ indices, ...) or that is wrong (a bad count, a number that
// does not parse, an index out of range, a non-finite coordinate), and IO::read_mesh()
// then reads the file with CGAL's readers and their checks, which name the problem.

#include <CGAL/Geodesic_skeleton/IO/internal/indexed_soup.h>
#include <CGAL/Geodesic_skeleton/IO/internal/mesh_file_checks.h>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define GEODESIC_SKELETON_HAS_MMAP 1
#endif
#ifndef MAP_POPULATE
#define MAP_POPULATE 0
#endif

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

// The bytes of a file, mapped into memory where the system can (POSIX), read otherwise:
// a mapping costs no copy, and no fresh memory (which on a virtual machine can cost more
// than parsing the bytes).
class File_bytes
{
public:
  explicit File_bytes(const std::string& path)
  {
#if defined(GEODESIC_SKELETON_HAS_MMAP)
    const int fd = ::open(path.c_str(), O_RDONLY);
    struct stat status;
    if(fd >= 0 && ::fstat(fd, &status) == 0 && S_ISREG(status.st_mode))
    {
      m_size = static_cast<std::size_t>(status.st_size);
      if(m_size == 0)
        m_ok = true;
      else
      {
        void* map = ::mmap(nullptr, m_size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if(map != MAP_FAILED)
        {
          m_mapped = static_cast<const char*>(map);
          m_ok = true;
        }
      }
    }
    if(fd >= 0)
      ::close(fd);
    if(m_ok)
      return;
#endif
    m_ok = read_all(path);
  }
  File_bytes(const File_bytes&) = delete;
  File_bytes& operator=(const File_bytes&) = delete;
  ~File_bytes()
  {
#if defined(GEODESIC_SKELETON_HAS_MMAP)
    if(m_mapped != nullptr)
      ::munmap(const_cast<char*>(m_mapped), m_size);
#endif
  }

  bool ok() const { return m_ok; }
  const char* data() const { return m_mapped != nullptr ? m_mapped : m_read.data(); }
  std::size_t size() const { return m_mapped != nullptr ? m_size : m_read.size(); }

private:
  bool read_all(const std::string& path)
  {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if(file == nullptr)
      return false;
    bool ok = std::fseek(file, 0, SEEK_END) == 0;
    const long size = ok ? std::ftell(file) : -1;
    ok = ok && size >= 0 && std::fseek(file, 0, SEEK_SET) == 0;
    if(ok)
    {
      m_read.resize(static_cast<std::size_t>(size));
      ok = size == 0 || std::fread(&m_read[0], 1, m_read.size(), file) == m_read.size();
    }
    std::fclose(file);
    return ok;
  }

  bool m_ok = false;
  const char* m_mapped = nullptr;
  std::size_t m_size = 0;
  std::string m_read;
};

// A cursor over the text of an ASCII mesh file that knows lines: numbers are read within
// the current line, comments ('#' to the end of the line) are blanks.
class Text_cursor
{
public:
  Text_cursor(const char* begin, const char* end) : m_p(begin), m_end(end) {}

  bool at_end() const { return m_p == m_end; }
  // Skips blanks and comments, not line ends.
  void skip_blanks()
  {
    while(m_p != m_end)
    {
      if(*m_p == ' ' || *m_p == '\t' || *m_p == '\r')
        ++m_p;
      else if(*m_p == '#')
        while(m_p != m_end && *m_p != '\n')
          ++m_p;
      else
        break;
    }
  }
  // Skips blanks, comments and line ends.
  void skip_space()
  {
    for(skip_blanks(); m_p != m_end && *m_p == '\n'; skip_blanks())
      ++m_p;
  }
  // Whether the current line has no more entries (and goes to the next line if so).
  bool end_of_line()
  {
    skip_blanks();
    if(m_p == m_end)
      return true;
    if(*m_p != '\n')
      return false;
    ++m_p;
    return true;
  }
  void skip_line()
  {
    while(m_p != m_end && *m_p != '\n')
      ++m_p;
    if(m_p != m_end)
      ++m_p;
  }
  // The next word of the line (letters, digits, punctuation up to a blank).
  std::string word()
  {
    skip_blanks();
    const char* start = m_p;
    while(m_p != m_end && !is_blank(*m_p))
      ++m_p;
    return std::string(start, m_p);
  }
  bool number(double& value)
  {
    skip_blanks();
    if(m_p != m_end && *m_p == '+')
      ++m_p;
    return parse(value);
  }
  template <typename Integer>
  bool integer(Integer& value)
  {
    skip_blanks();
    return parse(value);
  }
  bool point(std::array<double, 3>& p) { return number(p[0]) && number(p[1]) && number(p[2]); }
  // Consumes `c` if it is the next character.
  bool accept(char c)
  {
    if(m_p == m_end || *m_p != c)
      return false;
    ++m_p;
    return true;
  }
  const char* position() const { return m_p; }

private:
  // A number at the cursor that ends at a blank, a '/' (OBJ corners) or the end.
  template <typename T>
  bool parse(T& value)
  {
    const auto result = std::from_chars(m_p, m_end, value);
    if(result.ec != std::errc() || (result.ptr != m_end && !is_blank(*result.ptr) && *result.ptr != '/'))
      return false;
    m_p = result.ptr;
    return true;
  }
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '#'; }

  const char* m_p;
  const char* m_end;
};

// Counts of a header bounded as IO::read_mesh()'s checks bound them (mesh_file_checks.h).
inline bool counts_fit(double items, std::size_t file_size)
{
  return items >= 0 && items <= largest_header_count && 2 * items <= double(file_size);
}

// "OFF", three counts, "x y z" lines, "n i_1 ... i_n" lines (a face colour after the
// indices is skipped); comments anywhere. "COFF", "NOFF" and "CNOFF" too: their vertex
// lines start with x y z, and their colours and normals are skipped.
inline bool read_plain_OFF(const char* text, std::size_t size, Indexed_soup& soup)
{
  Text_cursor in(text, text + size);
  in.skip_space();
  const std::string keyword = in.word();
  const bool vertex_extras = keyword == "COFF" || keyword == "NOFF" || keyword == "CNOFF";
  if(keyword != "OFF" && !vertex_extras)
    return false;
  in.skip_space();
  std::size_t vertices = 0, faces = 0, edges = 0;
  if(!in.integer(vertices) || !in.integer(faces) || !(in.end_of_line() || (in.integer(edges) && in.end_of_line())))
    return false;
  if(!counts_fit(double(vertices) + double(faces), size) || vertices >= std::uint32_t(-1))
    return false;
  soup.points.resize(vertices);
  for(auto& p : soup.points)
  {
    in.skip_space();
    if(!in.point(p))
      return false;
    if(vertex_extras)
      in.skip_line();
    else if(!in.end_of_line())
      return false;
  }
  soup.offsets.reserve(faces + 1);
  soup.corners.reserve(3 * faces);
  for(std::size_t f = 0; f < faces; ++f)
  {
    in.skip_space();
    std::size_t corners = 0;
    if(!in.integer(corners) || corners < 3 || corners > vertices) // degenerate faces: CGAL's reader
      return false;
    for(std::size_t k = 0; k < corners; ++k)
    {
      std::uint32_t i = 0;
      if(!in.integer(i) || i >= vertices)
        return false;
      soup.corners.push_back(i);
    }
    in.skip_line(); // a colour, if any
    soup.close_polygon();
  }
  return faces > 0 && soup.has_only_finite_points();
}

// "v x y z" (a fourth value or a colour after it is ignored, as CGAL does) and
// "f a b c ..." lines with positive indices, each "i", "i/t", "i//n" or "i/t/n"; every
// other line (normals, texture coordinates, groups, materials, lines) is skipped.
inline bool read_plain_OBJ(const char* text, std::size_t size, Indexed_soup& soup)
{
  Text_cursor in(text, text + size);
  const char* end = text + size;
  while(true)
  {
    in.skip_space();
    if(in.at_end())
      break;
    const char* line = in.position();
    if(line[0] == 'v' && (line + 1 == end || line[1] == ' ' || line[1] == '\t'))
    {
      in.accept('v');
      std::array<double, 3> p;
      if(!in.point(p))
        return false;
      soup.points.push_back(p);
      in.skip_line();
    }
    else if(line[0] == 'f' && (line + 1 == end || line[1] == ' ' || line[1] == '\t'))
    {
      in.accept('f');
      std::size_t corners = 0;
      while(!in.end_of_line())
      {
        std::uint32_t i = 0;
        if(!in.integer(i) || i == 0)
          return false; // negative (relative) indices are left to CGAL
        soup.corners.push_back(i - 1);
        ++corners;
        // Skip the texture and normal indices of the corner.
        while(in.accept('/'))
        {
          std::uint32_t ignored;
          in.integer(ignored);
        }
      }
      if(corners < 3) // degenerate faces: CGAL's reader
        return false;
      soup.close_polygon();
    }
    else
      in.skip_line();
  }
  return soup.has_only_finite_points() && soup.has_only_valid_indices() && soup.number_of_polygons() > 0;
}

// Little-endian binary STL (an 80-byte header, a 32-bit triangle count, 50 bytes per
// triangle) that does not start with "solid" (CGAL reads such files as ASCII first). The
// corners are merged into points by their exact coordinates, in the order they come, as
// CGAL's reader merges them.
inline bool read_binary_STL(const char* data, std::size_t size, Indexed_soup& soup)
{
  if(size < 84 || std::memcmp(data, "solid", 5) == 0)
    return false;
  std::uint32_t count = 0;
  for(int b = 3; b >= 0; --b)
    count = (count << 8) | static_cast<unsigned char>(data[80 + b]);
  if(size != 84 + 50 * std::uint64_t(count) || count == 0)
    return false;
  struct Key_hash
  {
    std::size_t operator()(const std::array<double, 3>& p) const
    {
      std::size_t h = 0;
      for(double c : p)
      {
        const double zero_is_zero = c == 0 ? 0.0 : c; // -0 and 0 are one point, as in CGAL's map
        std::uint64_t bits;
        std::memcpy(&bits, &zero_is_zero, 8);
        h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
      }
      return h ^ (h >> 29);
    }
  };
  std::unordered_map<std::array<double, 3>, std::uint32_t, Key_hash> index_of;
  index_of.reserve(count);
  soup.corners.reserve(3 * std::size_t(count));
  soup.offsets.reserve(count + 1);
  for(std::uint32_t t = 0; t < count; ++t)
  {
    const char* record = data + 84 + 50 * std::size_t(t);
    for(int corner = 0; corner < 3; ++corner)
    {
      std::array<double, 3> p;
      for(int c = 0; c < 3; ++c)
      {
        float value;
        std::memcpy(&value, record + 12 + 12 * corner + 4 * c, 4);
        if(!std::isfinite(value))
          return false;
        p[c] = double(value);
      }
      const auto inserted = index_of.emplace(p, std::uint32_t(soup.points.size()));
      if(inserted.second)
        soup.points.push_back(p);
      soup.corners.push_back(inserted.first->second);
    }
    soup.close_polygon();
  }
  return true;
}

// Reads `path` into `soup` when the file has one of the forms above (by its extension);
// false otherwise, or when the file is not as its form says.
inline bool read_soup_fast(const std::string& path, const std::string& extension, Indexed_soup& soup)
{
  if(extension != "off" && extension != "obj" && extension != "stl")
    return false;
  const File_bytes file(path);
  if(!file.ok())
    return false;
  soup = Indexed_soup();
  const bool read = extension == "off"   ? read_plain_OFF(file.data(), file.size(), soup)
                    : extension == "obj" ? read_plain_OBJ(file.data(), file.size(), soup)
                                         : read_binary_STL(file.data(), file.size(), soup);
  // Corners are numbered with 32 bits (Directed_edge_table).
  return read && soup.corners.size() < std::size_t(std::uint32_t(-1));
}

} // namespace internal
} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_INTERNAL_FAST_SOUP_READERS_H
