// Tests of weft.hpp against the installed library: each wrapper hands the
// C function's result back (counts, values, ownership) and turns a failing
// status into weft::Error with the library's message. Built by run.sh with
// -std=c++17 -Wall -Wextra -Werror -pedantic under AddressSanitizer.
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "weft.hpp"

static int failures = 0;
static int checks = 0;
#define CHECK(condition)                                                     \
  do {                                                                       \
    ++checks;                                                                \
    if (!(condition)) {                                                      \
      std::fprintf(stderr, "%s:%d: failed: %s\n", __FILE__, __LINE__, #condition); \
      ++failures;                                                            \
    }                                                                        \
  } while (0)

// Runs `action`, which must throw weft::Error with `status` and a message.
template <class Action>
static void expect_error(WeftStatus status, Action action, const char* what) {
  ++checks;
  try {
    action();
    std::fprintf(stderr, "failed: %s did not throw\n", what);
    ++failures;
  } catch (const weft::Error& error) {
    if (error.status() != status || std::string(error.what()).empty()) {
      std::fprintf(stderr, "failed: %s threw status %u (%s)\n", what, static_cast<unsigned>(error.status()),
                   error.what());
      ++failures;
    }
  }
}

static double max_difference(weft::View<double> a, weft::View<double> b) {
  if (a.size() != b.size()) return INFINITY;
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::fmax(worst, std::fabs(a[i] - b[i]));
  return worst;
}

static weft::Mesh cube() {
  return weft::Mesh({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1}, {4, 4, 4, 4, 4, 4},
                    {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5});
}

static void test_mesh_and_views() {
  weft::Mesh m = cube();
  CHECK(m.vertex_count() == 8 && m.face_count() == 6 && m.index_count() == 24);
  CHECK(m.positions().size() == 24 && m.positions()[21] == 1.0);
  CHECK(m.face_indices().size() == 24 && m.face_indices()[3] == 1);
  double sum = 0;
  for (double x : m.positions()) sum += x;
  CHECK(sum == 12.0);
  CHECK(m.info().is_closed && m.info().edge_count == 12);
  CHECK(weft::edges(m).size() == 24);

  weft::Mesh moved = std::move(m);
  CHECK(!m && m.vertex_count() == 0 && m.positions().empty() && moved.vertex_count() == 8);
  expect_error(WEFT_STATUS_NULL_POINTER, [&] { weft::catmull_clark(m, 1); }, "subdividing a moved-from mesh");
  WeftMesh* raw = moved.release();
  CHECK(raw != nullptr && !moved);
  weft::Mesh adopted = weft::Mesh::adopt(raw);
  CHECK(adopted.face_count() == 6);

  expect_error(WEFT_STATUS_INDEX_OUT_OF_RANGE, [] { weft::Mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {3}, {0, 1, 3}); },
               "a face naming vertex 3 of 3");
  expect_error(WEFT_STATUS_COUNT_MISMATCH, [] { weft::Mesh({0, 0, 0, 1}, {}, {}); },
               "positions not a multiple of 3");

  // A face naming a vertex twice: refused unless the flag allows it.
  const std::vector<double> grid = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
  expect_error(WEFT_STATUS_REPEATED_INDEX, [&] { weft::Mesh(grid, {5, 4}, {0, 1, 1, 4, 3, 1, 2, 5, 4}); },
               "a face naming vertex 1 twice");
  weft::Mesh repeating(grid, {5, 4}, {0, 1, 1, 4, 3, 1, 2, 5, 4}, WEFT_MESH_ALLOW_REPEATED_VERTICES);
  CHECK(repeating.face_count() == 2 && weft::catmull_clark(repeating, 1).vertex_count() == 16);
}

// A borrowed mesh reads the caller's vectors in place and subdivides as a copied one.
static void test_borrowed_mesh() {
  const weft::Mesh copied = cube();
  const std::vector<double> positions = copied.positions().to_vector();
  const std::vector<uint32_t> sizes = copied.face_sizes().to_vector(), indices = copied.face_indices().to_vector();
  weft::Mesh borrowed = weft::Mesh::borrow(positions, sizes, indices);
  CHECK(borrowed.is_borrowed() && !copied.is_borrowed());
  CHECK(borrowed.positions().data() == positions.data() && borrowed.face_indices().data() == indices.data());
  const weft::Mesh smooth = weft::catmull_clark(borrowed, 2), expected = weft::catmull_clark(copied, 2);
  CHECK(!smooth.is_borrowed() && max_difference(smooth.positions(), expected.positions()) == 0.0);
  weft::Mesh moved = std::move(borrowed);
  CHECK(moved.is_borrowed() && !borrowed.is_borrowed());
  const std::vector<uint32_t> out_of_range = {0, 1, 8};
  expect_error(WEFT_STATUS_INDEX_OUT_OF_RANGE, [&] { weft::Mesh::borrow(positions, {3}, out_of_range); },
               "a borrowed face naming vertex 8 of 8");
}

static void test_subdivision() {
  weft::Mesh cage = cube();
  weft::Mesh smooth = weft::catmull_clark(cage, 2);
  weft::SubdivisionCounts counts = weft::subdivision_counts(cage, WEFT_SCHEME_CATMULL_CLARK, 2);
  CHECK(counts.vertex_count == 98 && counts.face_count == 96 && counts.index_count == 384);
  CHECK(smooth.vertex_count() == counts.vertex_count && smooth.face_count() == counts.face_count);
  // Into the host's own buffers, twice into the same ones: the same values.
  std::vector<double> positions(3 * counts.vertex_count);
  std::vector<uint32_t> quads(counts.index_count);
  for (int round = 0; round < 2; ++round) {
    weft::subdivide_into(cage, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_FIXED, positions, quads);
    CHECK(positions == smooth.positions().to_vector() && quads == smooth.face_indices().to_vector());
  }
  std::vector<uint32_t> short_quads(counts.index_count - 1, 7u);
  expect_error(WEFT_STATUS_BUFFER_TOO_SMALL,
               [&] { weft::subdivide_into(cage, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_FIXED, positions,
                                          short_quads); },
               "subdividing into a buffer one index short");
  CHECK(short_quads == std::vector<uint32_t>(counts.index_count - 1, 7u));

  // The options struct at its defaults is plain Catmull-Clark (to round-off).
  weft::Mesh same = weft::subdivide(cage, weft::SubdivisionOptions{}, 2);
  CHECK(same.face_indices().to_vector() == smooth.face_indices().to_vector());
  CHECK(max_difference(same.positions(), smooth.positions()) < 1e-12);
  // A sharp corner stays where it is; without it the vertex moves inward.
  weft::SubdivisionOptions cornered;
  cornered.corner(0);
  weft::Mesh sharp = weft::subdivide(cage, cornered, 2);
  CHECK(sharp.positions()[0] == 0.0 && sharp.positions()[1] == 0.0 && sharp.positions()[2] == 0.0);
  CHECK(smooth.positions()[0] > 0.1);
  weft::SubdivisionOptions lopsided;
  lopsided.crease_vertex_pairs = {0, 1, 2};
  lopsided.crease_sharpness = {1.0};
  expect_error(WEFT_STATUS_COUNT_MISMATCH, [&] { weft::subdivide(cage, lopsided, 1); },
               "three crease indices for one crease");
  weft::SubdivisionOptions not_an_edge;
  not_an_edge.crease(0, 7);
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [&] { weft::subdivide(cage, not_an_edge, 1); },
               "a crease on the cube's diagonal");

  // The limit surface as patches: 96 at isolation 2, all exact but the 3 at each corner.
  weft::SubdivisionOptions smooth_cc;
  smooth_cc.naked_edges = WEFT_NAKED_EDGES_SMOOTH;
  weft::LimitPatches patches = weft::limit_patches(cage, smooth_cc, 2);
  CHECK(patches.size() == 96 && patches.exact_count == 72 && patches.max_error > 1e-4);
  CHECK(patches.control_points.size() == 48 * 96 && patches.cage_faces[95] == 5);
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [&] { weft::limit_patches(cage, smooth_cc, 9); }, "isolation 9");

  std::vector<uint32_t> parents = weft::parent_faces(cage, WEFT_SCHEME_CATMULL_CLARK, 1);
  CHECK(parents.size() == 24 && parents[0] == 0 && parents[3] == 0 && parents[4] == 1 && parents[23] == 5);

  // Holes leave their children out and keep every vertex; the counts and
  // parents with the same options agree; smooth triangles change nothing
  // on a cube of quads.
  weft::SubdivisionOptions holed;
  holed.hole(1).hole(4);
  weft::Mesh open_box = weft::subdivide(cage, holed, 2);
  CHECK(open_box.vertex_count() == 98 && open_box.face_count() == 96 - 32);
  weft::SubdivisionCounts holed_counts = weft::subdivision_counts(cage, holed, 2);
  CHECK(holed_counts.face_count == open_box.face_count() && holed_counts.index_count == 4 * open_box.face_count());
  std::vector<uint32_t> holed_parents = weft::parent_faces(cage, holed, 2);
  CHECK(holed_parents.size() == 64 && holed_parents[0] == 0 && holed_parents[16] == 2 && holed_parents[63] == 5);
  weft::SubdivisionOptions far_hole;
  far_hole.hole(6);
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [&] { weft::subdivide(cage, far_hole, 1); }, "a hole past the faces");
  weft::SubdivisionOptions smooth_triangles;
  smooth_triangles.triangles = WEFT_TRIANGLES_SMOOTH;
  CHECK(max_difference(weft::subdivide(cage, smooth_triangles, 2).positions(), smooth.positions()) < 1e-12);

  // Loop: an icosahedron has 80 faces after one step (pmp's golden); not on quads.
  weft::Mesh ico = weft::platonic(WEFT_PLATONIC_ICOSAHEDRON);
  CHECK(weft::loop(ico, 1, WEFT_NAKED_EDGES_SMOOTH).face_count() == 80);
  expect_error(WEFT_STATUS_NOT_TRIANGLES, [&] { weft::loop(cage, 1); }, "Loop on quads");
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [&] { weft::catmull_clark(cage, 1, 7); }, "naked-edge mode 7");

  // Data carried with the weights of the positions: the x coordinates come out as the refined x.
  std::vector<double> xs;
  for (std::size_t v = 0; v < 8; ++v) xs.push_back(cage.positions()[3 * v]);
  std::vector<double> carried = weft::subdivide_vertex_data(cage, weft::SubdivisionOptions{}, 1, xs, 1);
  weft::Mesh once = weft::subdivide(cage, weft::SubdivisionOptions{}, 1);
  CHECK(carried.size() == 26);
  double worst = 0;
  for (std::size_t v = 0; v < carried.size() && 3 * v < once.positions().size(); ++v) {
    worst = std::fmax(worst, std::fabs(carried[v] - once.positions()[3 * v]));
  }
  CHECK(worst < 1e-12);
  weft::LimitSurface limit = weft::subdivide_limit(cage, weft::SubdivisionOptions{}, 2);
  CHECK(limit.positions.size() == 3 * 98 && limit.normals.size() == 3 * 98);
  double length = std::sqrt(limit.normals[0] * limit.normals[0] + limit.normals[1] * limit.normals[1] +
                            limit.normals[2] * limit.normals[2]);
  CHECK(std::fabs(length - 1.0) < 1e-12);
}

static void test_refiner() {
  weft::Mesh cage = cube();
  weft::Refiner refiner(cage, WEFT_SCHEME_CATMULL_CLARK, 2, WEFT_NAKED_EDGES_SMOOTH);
  CHECK(refiner.vertex_count() == 98 && refiner.face_count() == 96);
  weft::Mesh direct = weft::catmull_clark(cage, 2, WEFT_NAKED_EDGES_SMOOTH);
  CHECK(refiner.mesh().positions().to_vector() == direct.positions().to_vector());
  std::vector<double> out;
  refiner.evaluate(cage.positions().to_vector(), out);
  CHECK(out == direct.positions().to_vector());
  expect_error(WEFT_STATUS_COUNT_MISMATCH, [&] { refiner.evaluate(std::vector<double>(9, 0.0)); },
               "three cage vertices for a cage of eight");
  weft::Refiner moved = std::move(refiner);
  CHECK(moved.vertex_count() == 98 && refiner.get() == nullptr);
  weft::SubdivisionOptions loop;
  loop.scheme = WEFT_SCHEME_LOOP;
  weft::Refiner triangles(weft::platonic(WEFT_PLATONIC_OCTAHEDRON), loop, 2);
  CHECK(triangles.face_count() == 8 * 16);
}

static void test_mending() {
  // Quad A below two quads B and C; their shared vertex 4 lies on A's top edge.
  weft::Mesh t({0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0, 2, 2, 0}, {4, 4, 4},
               {0, 1, 2, 3, 3, 4, 5, 6, 4, 2, 7, 5});
  std::vector<WeftTNode> nodes = weft::find_t_nodes(t);
  CHECK(nodes.size() == 1);
  if (nodes.size() == 1) {
    CHECK(nodes[0].vertex == 4 && nodes[0].face == 0 && nodes[0].edge_start == 2 && nodes[0].edge_end == 3);
    CHECK(std::fabs(nodes[0].parameter - 0.5) < 1e-12);
  }
  std::size_t inserted = 0;
  weft::Mesh repaired = weft::repair_t_nodes(t, WEFT_DEFAULT_WELD_TOLERANCE, &inserted);
  CHECK(inserted == 1 && repaired.face_sizes()[0] == 5 && weft::find_t_nodes(repaired).empty());
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [&] { weft::find_t_nodes(t, -1.0); }, "a negative tolerance");

  weft::Mesh a = weft::box(1, 1, 1);
  weft::Mesh joined = weft::join(a, a, a);
  CHECK(joined.vertex_count() == 24 && joined.face_count() == 18);
  std::vector<weft::Mesh> boxes;
  boxes.push_back(weft::box(1, 1, 1));
  boxes.push_back(weft::box(2, 2, 2));
  CHECK(weft::join(boxes).face_count() == 12);
  CHECK(weft::join(std::vector<weft::Mesh>{}).vertex_count() == 0);
  WeftWeldReport report{};
  weft::Mesh welded = weft::weld(joined, 0.0, &report);
  CHECK(report.merged_vertex_count == 16 && welded.vertex_count() == 8);
  std::size_t removed = 0;
  CHECK(weft::cull_adjacent(welded, &removed).face_count() == 0 && removed == 18);

  weft::Mesh flipped = weft::flip(cube());
  CHECK(weft::flip(flipped).face_indices().to_vector() == cube().face_indices().to_vector());
  std::size_t turned = 0;
  weft::Mesh outward = weft::unify_orientation(flipped, &turned);
  CHECK(turned == 6 && outward.face_indices().to_vector() == cube().face_indices().to_vector());
  CHECK(weft::triangulate(cube()).face_count() == 12);
}

static void test_analysis_and_making() {
  weft::Mesh c = cube();
  std::vector<double> normals = weft::face_normals(c);
  CHECK(normals.size() == 18 && normals[0] == 0.0 && normals[1] == 0.0 && normals[2] == -1.0);
  CHECK(weft::vertex_normals(c).size() == 24);
  std::vector<double> deviations = weft::planarity(c);
  CHECK(deviations.size() == 6 && deviations[0] == 0.0);
  weft::Mesh pyramids = weft::stellate(c, {0.5});
  CHECK(pyramids.vertex_count() == 14 && pyramids.face_count() == 24);
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [&] { weft::stellate(c, {1, 2}); }, "two heights for six faces");

  // A square and its centre, once more: four triangles, one point merged.
  std::size_t merged = 0;
  weft::Mesh tin = weft::delaunay({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0, 0.5, 0.5, 0}, weft::world_xy(),
                                  &merged);
  CHECK(tin.vertex_count() == 5 && tin.face_count() == 4 && merged == 1);
  expect_error(WEFT_STATUS_DEGENERATE_INPUT, [] { weft::delaunay({0, 0, 0, 1, 0, 0, 2, 0, 0}); },
               "collinear points");
  weft::Cells cells = weft::voronoi({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  CHECK(cells.count() == 4 && cells.sizes().size() == 4 && cells.corners().size() == 3 * cells.corner_count());
  bool all_polygons = true;
  for (uint32_t size : cells.sizes()) all_polygons = all_polygons && size >= 3;
  CHECK(all_polygons && cells.to_mesh().face_count() == 4);
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [] { weft::voronoi({0, 0, 0, 1, 0, 0, 1, 1, 0}, weft::world_xy(), {}, -1.0); },
               "a negative radius");

  CHECK(weft::mesh_from_grid({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, 2, 2).face_count() == 1);
  CHECK(weft::plane_grid(2, 1, 4, 2).face_count() == 8);
  CHECK(weft::uv_sphere(1, 8, 4).vertex_count() == 8 * 3 + 2);
  CHECK(weft::sided_solid(WEFT_SIDED_PRISM, 5, 1, 1).face_count() == 7);
  CHECK(weft::split_polygons(c, 1).face_count() == 24);
  CHECK(weft::tile(c, WEFT_TILE_FILL_TRIANGLE_FAN).face_count() == 24);
  CHECK(weft::dual(weft::platonic(WEFT_PLATONIC_OCTAHEDRON)).face_count() == 6);
  expect_error(WEFT_STATUS_INVALID_ARGUMENT, [] { weft::platonic(99); }, "platonic solid 99");
}

int main() {
  test_mesh_and_views();
  test_borrowed_mesh();
  test_subdivision();
  test_refiner();
  test_mending();
  test_analysis_and_making();
  std::printf("weft.hpp: %d checks, %d failed\n", checks, failures);
  return failures == 0 ? 0 : 1;
}
