// The C example's cube through weft.hpp: subdivide, re-evaluate with a
// refiner as a slider would, join and weld two boxes, and catch an error.
// Build: c++ -std=c++17 subdivide_cube.cpp $(pkg-config --cflags --libs weft)
#include <cstdio>
#include <vector>

#include "weft.hpp"

int main() {
  // A unit cube: 8 vertices, 6 quads, counter-clockwise seen from outside.
  const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
  const std::vector<uint32_t> sizes = {4, 4, 4, 4, 4, 4};
  const std::vector<uint32_t> indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  int failures = 0;
  auto expect = [&failures](bool ok, const char* what) {
    if (!ok) {
      std::fprintf(stderr, "unexpected: %s\n", what);
      ++failures;
    }
  };

  try {
    std::printf("Weft %s\n", weft::version());
    weft::Mesh cage(positions, sizes, indices);
    weft::Mesh smooth = weft::catmull_clark(cage, 2, WEFT_NAKED_EDGES_FIXED);
    WeftMeshInfo info = smooth.info();
    std::printf("%zu vertices, %zu faces, closed: %d\n", smooth.vertex_count(), smooth.face_count(),
                info.is_closed);
    expect(smooth.vertex_count() == 98 && smooth.face_count() == 96 && info.is_closed,
           "level 2 of a cube is 98 vertices, 96 closed quads");
    std::size_t quads = 0;
    for (uint32_t size : smooth.face_sizes()) quads += size == 4;
    expect(quads == smooth.face_count(), "every face of Catmull-Clark is a quad");
    expect(smooth.positions().size() == 3 * smooth.vertex_count(), "3 doubles per vertex");
    std::printf("vertex 0 moved to (%.4f, %.4f, %.4f)\n", smooth.positions()[0], smooth.positions()[1],
                smooth.positions()[2]);

    // Loop needs triangles: 12 triangles, 4 each after one step.
    weft::Mesh triangles = weft::triangulate(cage);
    weft::Mesh looped = weft::loop(triangles, 1, WEFT_NAKED_EDGES_SMOOTH);
    expect(looped.face_count() == 48, "one Loop step of 12 triangles makes 48");

    // A refiner plans the topology once; moving the cage costs only arithmetic.
    weft::Refiner refiner(cage, WEFT_SCHEME_CATMULL_CLARK, 2);
    std::vector<double> moved = positions;
    for (double& coordinate : moved) coordinate *= 2.0;
    std::vector<double> refined = refiner.evaluate(moved);
    expect(refined.size() == 3 * refiner.vertex_count(), "the refiner fills 3 doubles per refined vertex");
    bool doubled = true;
    for (std::size_t i = 0; i < refined.size(); ++i) {
      double expected = 2.0 * smooth.positions()[i];
      doubled = doubled && refined[i] > expected - 1e-12 && refined[i] < expected + 1e-12;
    }
    expect(doubled, "a cage scaled by 2 refines to the refined cage scaled by 2");

    // Two touching boxes, joined then welded: the shared corners merge.
    weft::Mesh left = weft::box(1, 1, 1);
    std::vector<double> shifted = left.positions().to_vector();
    for (std::size_t i = 0; i < shifted.size(); i += 3) shifted[i] += 1.0;
    weft::Mesh right(shifted, left.face_sizes().to_vector(), left.face_indices().to_vector());
    WeftWeldReport report{};
    std::size_t culled = 0;
    weft::Mesh welded = weft::weld(weft::join(left, right), WEFT_DEFAULT_WELD_TOLERANCE, &report);
    weft::Mesh aggregate = weft::cull_adjacent(welded, &culled);
    std::printf("joined boxes: %zu vertices merged, %zu inner faces culled\n", report.merged_vertex_count,
                culled);
    expect(report.merged_vertex_count == 4 && culled == 2 && aggregate.face_count() == 10,
           "two boxes sharing a side weld 4 vertices and lose their 2 inner faces");

    // Handles move, never copy; a moved-from mesh is empty.
    weft::Mesh taken = std::move(aggregate);
    expect(!aggregate && aggregate.vertex_count() == 0 && taken.vertex_count() == 12, "moving a mesh");
  } catch (const weft::Error& error) {
    std::fprintf(stderr, "weft: %s (status %u)\n", error.what(), static_cast<unsigned>(error.status()));
    return 1;
  }

  // Bad input is an exception naming what and where.
  try {
    const std::vector<uint32_t> bad = {0, 1, 9};
    weft::Mesh broken(std::vector<double>(9, 0.0), {3}, bad);
    expect(false, "a face naming vertex 9 of 3 is rejected");
  } catch (const weft::Error& error) {
    std::printf("rejected as expected: %s\n", error.what());
    expect(error.status() == WEFT_STATUS_INDEX_OUT_OF_RANGE, "the status is WEFT_STATUS_INDEX_OUT_OF_RANGE");
  }
  return failures == 0 ? 0 : 1;
}
