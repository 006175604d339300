// Specification of CGAL/Geodesic_skeleton/IO/read_mesh.h's fast path: the package's own
// readers (plain OFF, OBJ, binary STL) and its direct mesh construction give the very mesh
// that CGAL's readers and polygon_soup_to_polygon_mesh() give, and its manifold test agrees
// with CGAL's is_polygon_soup_a_polygon_mesh(). (Bad files: the robustness suite.)
#include <CGAL/Geodesic_skeleton/IO/read_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(read_mesh)

namespace gs = CGAL::Geodesic_skeleton;
namespace gio = CGAL::Geodesic_skeleton::IO;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;

namespace {

const std::string data_dir = GEODESIC_SKELETON_DATA_DIR;

// The mesh that CGAL's readers give for `path`, as read_mesh() gave it before its fast path.
Mesh read_with_CGAL(const std::string& path)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  gio::internal::read_soup_with_CGAL(path, points, polygons);
  Mesh mesh;
  gio::internal::polygon_soup_to_checked_mesh(path, points, polygons, mesh);
  return mesh;
}

// Same points, same faces, and the same halfedge structure, index for index.
void check_identical(const Mesh& a, const Mesh& b, const std::string& what)
{
  BOOST_TEST_CONTEXT(what)
  {
    BOOST_REQUIRE_EQUAL(a.number_of_vertices(), b.number_of_vertices());
    BOOST_REQUIRE_EQUAL(a.number_of_faces(), b.number_of_faces());
    BOOST_REQUIRE_EQUAL(a.number_of_edges(), b.number_of_edges());
    BOOST_TEST(a.is_valid(false));
    std::size_t different = 0;
    for(auto v : vertices(a))
      different += a.point(v) != b.point(v) || a.halfedge(v) != b.halfedge(v);
    for(auto f : faces(a))
      different += a.halfedge(f) != b.halfedge(f);
    for(auto h : halfedges(a))
      different += a.target(h) != b.target(h) || a.next(h) != b.next(h) || a.face(h) != b.face(h);
    BOOST_TEST(different == 0u);
  }
}

std::string temporary_path(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("gs_test_read_mesh_" + name)).string();
}

// A random soup of triangles over a few points: often non-manifold, sometimes not.
gio::internal::Indexed_soup random_soup(std::mt19937& random)
{
  gio::internal::Indexed_soup soup;
  const int points = std::uniform_int_distribution<int>(3, 7)(random);
  const int triangles = std::uniform_int_distribution<int>(1, 8)(random);
  soup.points.assign(std::size_t(points), {0, 0, 0});
  std::uniform_int_distribution<std::uint32_t> index(0, std::uint32_t(points - 1));
  for(int t = 0; t < triangles; ++t)
  {
    std::uint32_t a = index(random), b = index(random), c = index(random);
    while(b == a)
      b = index(random);
    while(c == a || c == b)
      c = index(random);
    soup.corners.insert(soup.corners.end(), {a, b, c});
    soup.close_polygon();
  }
  return soup;
}

// A fan of 17 to 40 triangles around point 0 (more than the table scans unsorted), closed
// or not, with a few triangles dropped, flipped or repeated at random.
gio::internal::Indexed_soup random_large_fan(std::mt19937& random)
{
  gio::internal::Indexed_soup soup;
  const std::uint32_t ring = std::uniform_int_distribution<std::uint32_t>(17, 40)(random);
  soup.points.assign(ring + 1, {0, 0, 0});
  const bool closed = random() % 2 == 0;
  for(std::uint32_t i = 0; i + (closed ? 0 : 1) < ring; ++i)
  {
    const std::uint32_t a = 1 + i, b = 1 + (i + 1) % ring;
    const unsigned change = random() % 80;
    if(change == 0) // dropped
      continue;
    soup.corners.insert(soup.corners.end(), {0u, change == 1 ? b : a, change == 1 ? a : b});
    soup.close_polygon();
    if(change == 2) // repeated
    {
      soup.corners.insert(soup.corners.end(), {0u, a, b});
      soup.close_polygon();
    }
  }
  return soup;
}

// Requires the fast manifold test to answer as CGAL's does on `trials` soups made by
// `make_soup`; returns how many of them were manifold.
template <typename MakeSoup>
std::size_t count_manifold_soups_as_CGAL_does(MakeSoup make_soup, int trials)
{
  std::size_t manifold = 0;
  for(int trial = 0; trial < trials; ++trial)
  {
    const gio::internal::Indexed_soup soup = make_soup();
    std::vector<std::vector<std::size_t>> polygons;
    for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
      polygons.emplace_back(soup.corners.begin() + soup.offsets[f], soup.corners.begin() + soup.offsets[f + 1]);
    const gio::internal::Directed_edge_table edges(soup);
    const bool ours = gio::internal::is_oriented_manifold(soup, edges);
    BOOST_TEST_REQUIRE(ours == CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons),
                       "trial " << trial);
    manifold += ours;
  }
  return manifold;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_cone_of_many_triangles_is_read_fast_into_the_mesh_of_CGALs_reader)
{
  // Apex and bottom centre each in 48 triangles; an open cone keeps its border too.
  for(const bool closed : {true, false})
  {
    const std::string path = temporary_path(closed ? "cone.off" : "open_cone.off");
    const int ring = 48;
    std::ofstream out(path);
    out << "OFF\n" << ring + 2 << " " << (closed ? 2 * ring : ring) << " 0\n0 0 1\n0 0 0\n";
    for(int i = 0; i < ring; ++i)
      out << std::cos(2 * CGAL_PI * i / ring) << " " << std::sin(2 * CGAL_PI * i / ring) << " 0\n";
    for(int i = 0; i < ring; ++i)
    {
      out << "3 0 " << 2 + i << " " << 2 + (i + 1) % ring << "\n";
      if(closed)
        out << "3 1 " << 2 + (i + 1) % ring << " " << 2 + i << "\n";
    }
    out.close();
    gio::internal::Indexed_soup soup;
    BOOST_TEST_REQUIRE(gio::internal::read_soup_fast(path, "off", soup));
    const gio::internal::Directed_edge_table edges(soup);
    BOOST_TEST(gio::internal::is_oriented_manifold(soup, edges));
    Mesh mesh;
    BOOST_TEST(gio::read_mesh(path, mesh));
    BOOST_TEST(CGAL::is_closed(mesh) == closed);
    check_identical(mesh, read_with_CGAL(path), path);
    std::filesystem::remove(path);
  }
}

BOOST_AUTO_TEST_CASE(the_fast_path_gives_the_mesh_of_CGALs_readers_on_every_demo_mesh)
{
  std::size_t fast = 0, meshes = 0;
  for(const auto& entry : std::filesystem::directory_iterator(data_dir))
  {
    const std::string path = entry.path().string();
    if(entry.path().extension() != ".off")
      continue;
    ++meshes;
    gio::internal::Indexed_soup soup;
    fast += gio::internal::read_soup_fast(path, "off", soup);
    Mesh mesh;
    gio::read_mesh(path, mesh);
    check_identical(mesh, read_with_CGAL(path), path);
  }
  BOOST_TEST_MESSAGE(fast << " of " << meshes << " demo meshes read by the fast path");
  BOOST_TEST(meshes > 50u);
  BOOST_TEST(fast > meshes / 2); // the demo files are plain OFF, most of them
}

BOOST_AUTO_TEST_CASE(obj_and_binary_stl_are_read_fast_into_the_same_mesh)
{
  Mesh cow;
  gio::read_mesh(data_dir + "/cow.off", cow);
  for(const std::string extension : {"obj", "stl"})
  {
    const std::string path = temporary_path("cow." + extension);
    BOOST_REQUIRE(CGAL::IO::write_polygon_mesh(path, cow, CGAL::parameters::stream_precision(17)));
    gio::internal::Indexed_soup soup;
    BOOST_TEST(gio::internal::read_soup_fast(path, extension, soup), extension);
    Mesh mesh;
    gio::read_mesh(path, mesh);
    check_identical(mesh, read_with_CGAL(path), path);
    BOOST_TEST(mesh.number_of_faces() == cow.number_of_faces());
    std::filesystem::remove(path);
  }
}

BOOST_AUTO_TEST_CASE(obj_corners_with_texture_and_normal_indices_and_comments)
{
  const std::string path = temporary_path("quad.obj");
  std::ofstream(path) << "# a tetrahedron with the extras exporters write\nmtllib a.mtl\no tet\n"
                         "v 0 0 0\nv 1 0 0 # a comment\nv 0 1 0\nv 0 0 1 1 0 0\nvt 0 0\nvn 0 0 1\n"
                         "usemtl skin\ns off\nf 1/1/1 3/1/1 2/1/1\nf 1//1 2//1 4//1\nf 2/1 3/1 4/1\nf 1 4 3\n";
  gio::internal::Indexed_soup soup;
  BOOST_TEST(gio::internal::read_soup_fast(path, "obj", soup));
  BOOST_TEST(soup.points.size() == 4u);
  BOOST_TEST(soup.number_of_polygons() == 4u);
  Mesh mesh;
  gio::read_mesh(path, mesh);
  BOOST_TEST(CGAL::is_closed(mesh));
  check_identical(mesh, read_with_CGAL(path), path);
  std::filesystem::remove(path);
}

BOOST_AUTO_TEST_CASE(unusual_forms_are_left_to_CGALs_readers)
{
  const std::string path = temporary_path("homogeneous.off");
  // Homogeneous coordinates, and a negative OBJ index: both for CGAL's readers.
  std::ofstream(path) << "4OFF\n4 4 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  gio::internal::Indexed_soup soup;
  BOOST_TEST(!gio::internal::read_soup_fast(path, "off", soup));
  Mesh mesh;
  gio::read_mesh(path, mesh);
  BOOST_TEST(mesh.number_of_faces() == 4u);
  const std::string obj = temporary_path("relative.obj");
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n";
  BOOST_TEST(!gio::internal::read_soup_fast(obj, "obj", soup));
  std::filesystem::remove(path);
  std::filesystem::remove(obj);
}

BOOST_AUTO_TEST_CASE(colours_are_skipped_as_CGAL_skips_them)
{
  const std::string path = temporary_path("coloured.off");
  std::ofstream(path) << "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
                         "0 0 1 9 9 9 255\n3 0 2 1 255 0 0\n3 0 1 3 0 255 0\n3 1 2 3 0 0 255\n3 0 3 2 7 7 7\n";
  gio::internal::Indexed_soup soup;
  BOOST_TEST(gio::internal::read_soup_fast(path, "off", soup));
  Mesh mesh;
  gio::read_mesh(path, mesh);
  BOOST_TEST(CGAL::is_closed(mesh));
  check_identical(mesh, read_with_CGAL(path), path);
  std::filesystem::remove(path);
}

BOOST_AUTO_TEST_CASE(a_keyword_glued_to_a_huge_count_is_refused_before_CGAL_reads_it)
{
  // CGAL's header reader ends the keyword at any character that is not alphanumeric, so
  // this header announces 1040010041 vertices, whose halfedge estimate overflows an int in
  // CGAL (undefined behaviour, found by fuzzing). The count must be refused first.
  const std::string path = temporary_path("glued.off");
  std::ofstream(path, std::ios::binary) << "OFF\x18" "1040010041 0\n\n0 0 0\n";
  Mesh mesh;
  BOOST_CHECK_EXCEPTION(gio::read_mesh(path, mesh), std::runtime_error, [](const std::runtime_error& e) {
    return std::string(e.what()).find("counts must be in [0, 2^28], got 1040010041") != std::string::npos;
  });
  std::filesystem::remove(path);
}

BOOST_AUTO_TEST_CASE(the_manifold_test_agrees_with_CGALs_on_random_soups_and_large_fans)
{
  std::mt19937 random(7);
  const std::size_t manifold = count_manifold_soups_as_CGAL_does([&] { return random_soup(random); }, 20000);
  // Both answers occur often enough for the agreement to mean something.
  BOOST_TEST(manifold > 1000u);
  BOOST_TEST(manifold < 19000u);
  // Stars larger than the table scans unsorted.
  const std::size_t manifold_fans =
      count_manifold_soups_as_CGAL_does([&] { return random_large_fan(random); }, 2000);
  BOOST_TEST(manifold_fans > 100u);
  BOOST_TEST(manifold_fans < 1900u);
}

BOOST_AUTO_TEST_CASE(a_manifold_soup_builds_a_valid_polyhedron_too)
{
  Polyhedron polyhedron;
  gio::read_mesh(data_dir + "/elephant.off", polyhedron);
  BOOST_TEST(polyhedron.is_valid());
  BOOST_TEST(polyhedron.size_of_facets() == 5558u);
  Mesh mesh;
  gio::read_mesh(data_dir + "/elephant.off", mesh);
  BOOST_TEST(polyhedron.size_of_vertices() == mesh.number_of_vertices());
}

BOOST_AUTO_TEST_CASE(an_open_mesh_keeps_its_border)
{
  // A square of two triangles and a fan with a hole: border halfedges linked in cycles.
  const std::string path = temporary_path("open.off");
  std::ofstream(path) << "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 2\n3 0 1 2\n3 0 2 3\n3 1 4 2\n";
  Mesh mesh;
  gio::read_mesh(path, mesh);
  check_identical(mesh, read_with_CGAL(path), path);
  BOOST_TEST(!CGAL::is_closed(mesh));
  std::filesystem::remove(path);
}

BOOST_AUTO_TEST_SUITE_END()
