/* Weft for C++17: a header-only wrapper over the C ABI of weft.h.
 *
 *   weft::Mesh cage(positions, 8, sizes, 6, indices, 24);
 *   weft::Mesh smooth = weft::catmull_clark(cage, 2, WEFT_NAKED_EDGES_SMOOTH);
 *   for (double x : smooth.positions()) ...
 *
 * Every function here calls the weft_* function of the same name (the
 * comment says which); weft.h documents its parameters, rules and errors.
 * A failing call throws weft::Error with the status and the library's
 * message. Handles (Mesh, Refiner, Cells) are move-only and free themselves.
 * Modes are uint32_t taking the header's WEFT_* constants.
 */
#ifndef WEFT_HPP
#define WEFT_HPP

#include "weft.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace weft {

/** A failed Weft call: the WeftStatus and the library's sentence saying what and where. */
class Error : public std::runtime_error {
 public:
  Error(WeftStatus status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  /** The WEFT_STATUS_* value the call returned. */
  WeftStatus status() const noexcept { return status_; }

 private:
  WeftStatus status_;
};

namespace detail {
/* Throws the status with the calling thread's last error message, which
   the next failing call would overwrite, so it is copied at once. */
inline void check(WeftStatus status) {
  if (status == WEFT_STATUS_OK) return;
  const char* message = weft_last_error_message();
  throw Error(status, message != nullptr && *message != '\0'
                          ? std::string(message)
                          : "weft: call failed with status " + std::to_string(static_cast<unsigned>(status)));
}

/* Buffers of x, y, z triples: the length must be a multiple of 3. */
inline std::size_t triples(const std::vector<double>& values, const char* what) {
  if (values.size() % 3 != 0) {
    throw Error(WEFT_STATUS_COUNT_MISMATCH, std::string("weft: ") + what + " holds " +
                                                std::to_string(values.size()) +
                                                " doubles, not a multiple of 3 (x, y, z per point)");
  }
  return values.size() / 3;
}
}  // namespace detail

/** A read-only view of a buffer owned by a Weft handle: valid while the handle lives. */
template <class T>
class View {
 public:
  View() noexcept = default;
  View(const T* data, std::size_t size) noexcept : data_(size == 0 ? nullptr : data), size_(data_ ? size : 0) {}
  const T* data() const noexcept { return data_; }
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  const T* begin() const noexcept { return data_; }
  const T* end() const noexcept { return data_ + size_; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }
  std::vector<T> to_vector() const { return std::vector<T>(begin(), end()); }

 private:
  const T* data_ = nullptr;
  std::size_t size_ = 0;
};

/** An immutable polygon mesh owning a WeftMesh handle (freed with weft_mesh_free). */
class Mesh {
 public:
  /** weft_mesh_new_ex: copies the buffers (3 × vertex_count doubles, face_count sizes, index_count
   *  indices); flags 0 or WEFT_MESH_ALLOW_REPEATED_VERTICES. */
  Mesh(const double* positions, std::size_t vertex_count, const uint32_t* face_sizes, std::size_t face_count,
       const uint32_t* face_indices, std::size_t index_count, uint32_t flags = 0) {
    detail::check(weft_mesh_new_ex(positions, vertex_count, face_sizes, face_count, face_indices, index_count, flags,
                                   &handle_));
  }
  /** The same from vectors: positions holds x, y, z per vertex. */
  Mesh(const std::vector<double>& positions, const std::vector<uint32_t>& face_sizes,
       const std::vector<uint32_t>& face_indices, uint32_t flags = 0)
      : Mesh(positions.data(), detail::triples(positions, "positions"), face_sizes.data(), face_sizes.size(),
             face_indices.data(), face_indices.size(), flags) {}

  /** weft_mesh_new_borrowed: a mesh that reads `positions` and `face_indices` where they are, checked
   *  but not copied. They must stay valid and unchanged until this Mesh (or the one it moves to) is
   *  destroyed; face_sizes is read during the call only. */
  static Mesh borrow(const double* positions, std::size_t vertex_count, const uint32_t* face_sizes,
                     std::size_t face_count, const uint32_t* face_indices, std::size_t index_count,
                     uint32_t flags = 0) {
    WeftMesh* handle = nullptr;
    detail::check(weft_mesh_new_borrowed(positions, vertex_count, face_sizes, face_count, face_indices, index_count,
                                         flags, &handle));
    return Mesh(handle);
  }
  /** The same from vectors, which must outlive the Mesh unchanged. */
  static Mesh borrow(const std::vector<double>& positions, const std::vector<uint32_t>& face_sizes,
                     const std::vector<uint32_t>& face_indices, uint32_t flags = 0) {
    return borrow(positions.data(), detail::triples(positions, "positions"), face_sizes.data(), face_sizes.size(),
                  face_indices.data(), face_indices.size(), flags);
  }

  /** Takes ownership of a handle from the C API (NULL makes an empty, moved-from-like Mesh). */
  static Mesh adopt(WeftMesh* handle) noexcept { return Mesh(handle); }

  Mesh(Mesh&& other) noexcept : handle_(std::exchange(other.handle_, nullptr)) {}
  Mesh& operator=(Mesh&& other) noexcept {
    if (this != &other) {
      weft_mesh_free(handle_);
      handle_ = std::exchange(other.handle_, nullptr);
    }
    return *this;
  }
  Mesh(const Mesh&) = delete;
  Mesh& operator=(const Mesh&) = delete;
  ~Mesh() { weft_mesh_free(handle_); }

  /** The handle, for calling weft.h directly; NULL after a move. */
  const WeftMesh* get() const noexcept { return handle_; }
  /** Gives the handle up: the caller frees it with weft_mesh_free. */
  WeftMesh* release() noexcept { return std::exchange(handle_, nullptr); }
  explicit operator bool() const noexcept { return handle_ != nullptr; }

  /** Whether the mesh reads arrays it was lent (Mesh::borrow). */
  bool is_borrowed() const noexcept { return weft_mesh_is_borrowed(handle_); }
  std::size_t vertex_count() const noexcept { return weft_mesh_vertex_count(handle_); }
  std::size_t face_count() const noexcept { return weft_mesh_face_count(handle_); }
  std::size_t index_count() const noexcept { return weft_mesh_index_count(handle_); }
  /** 3 × vertex_count() doubles: x, y, z per vertex. */
  View<double> positions() const noexcept { return {weft_mesh_positions(handle_), 3 * vertex_count()}; }
  /** face_count() corner counts. */
  View<uint32_t> face_sizes() const noexcept { return {weft_mesh_face_sizes(handle_), face_count()}; }
  /** index_count() vertex indices, the faces one after another. */
  View<uint32_t> face_indices() const noexcept { return {weft_mesh_face_indices(handle_), index_count()}; }

  /** weft_mesh_info: counts and flags of the topology. */
  WeftMeshInfo info() const {
    WeftMeshInfo result{};
    detail::check(weft_mesh_info(handle_, &result));
    return result;
  }

 private:
  explicit Mesh(WeftMesh* handle) noexcept : handle_(handle) {}
  WeftMesh* handle_ = nullptr;
};

namespace detail {
/* Calls a weft_* function whose last parameter receives a new mesh. */
template <class Function, class... Args>
Mesh make_mesh(Function function, Args... args) {
  WeftMesh* out = nullptr;
  check(function(args..., &out));
  return Mesh::adopt(out);
}
}  // namespace detail

/** The library's version, such as "0.1.0" (weft_version). */
inline const char* version() noexcept { return weft_version(); }

/* ---- Subdivision ---- */

/** weft_catmull_clark: `levels` steps; naked_edges is a WEFT_NAKED_EDGES_* value. */
inline Mesh catmull_clark(const Mesh& mesh, uint32_t levels, uint32_t naked_edges = WEFT_NAKED_EDGES_FIXED) {
  return detail::make_mesh(weft_catmull_clark, mesh.get(), levels, naked_edges);
}

/** weft_loop: `levels` steps on a triangle mesh. */
inline Mesh loop(const Mesh& mesh, uint32_t levels, uint32_t naked_edges = WEFT_NAKED_EDGES_FIXED) {
  return detail::make_mesh(weft_loop, mesh.get(), levels, naked_edges);
}

/** What shapes a subdivision besides the mesh (WeftSubdivisionOptions with owned arrays). */
struct SubdivisionOptions {
  uint32_t scheme = WEFT_SCHEME_CATMULL_CLARK;     /**< a WEFT_SCHEME_* value */
  uint32_t naked_edges = WEFT_NAKED_EDGES_FIXED;   /**< a WEFT_NAKED_EDGES_* value */
  uint32_t creasing = WEFT_CREASING_UNIFORM;       /**< a WEFT_CREASING_* value */
  std::vector<uint32_t> crease_vertex_pairs;       /**< two vertex indices per creased edge */
  std::vector<double> crease_sharpness;            /**< one per creased edge */
  std::vector<uint32_t> corner_vertices;           /**< sharp vertices */
  std::vector<double> corner_sharpness;            /**< one per sharp vertex */
  std::vector<uint32_t> hole_faces;                /**< faces left out of the result */
  uint32_t triangles = WEFT_TRIANGLES_CATMARK;     /**< a WEFT_TRIANGLES_* value */

  /** Adds a creased edge (sharpness WEFT_SHARPNESS_INFINITE for a hard one). */
  SubdivisionOptions& crease(uint32_t from, uint32_t to, double sharpness = WEFT_SHARPNESS_INFINITE) {
    crease_vertex_pairs.push_back(from);
    crease_vertex_pairs.push_back(to);
    crease_sharpness.push_back(sharpness);
    return *this;
  }
  /** Adds a sharp vertex. */
  SubdivisionOptions& corner(uint32_t vertex, double sharpness = WEFT_SHARPNESS_INFINITE) {
    corner_vertices.push_back(vertex);
    corner_sharpness.push_back(sharpness);
    return *this;
  }
  /** Leaves a face out of the result; its vertices and edges still shape its neighbours. */
  SubdivisionOptions& hole(uint32_t face) {
    hole_faces.push_back(face);
    return *this;
  }

  /** The C struct viewing these arrays; valid while this object is unchanged. */
  WeftSubdivisionOptions c_options() const {
    if (crease_vertex_pairs.size() != 2 * crease_sharpness.size()) {
      throw Error(WEFT_STATUS_COUNT_MISMATCH,
                  "weft: crease_vertex_pairs holds " + std::to_string(crease_vertex_pairs.size()) +
                      " indices for " + std::to_string(crease_sharpness.size()) +
                      " crease sharpness values (two per crease)");
    }
    if (corner_vertices.size() != corner_sharpness.size()) {
      throw Error(WEFT_STATUS_COUNT_MISMATCH,
                  "weft: corner_vertices holds " + std::to_string(corner_vertices.size()) + " vertices for " +
                      std::to_string(corner_sharpness.size()) + " corner sharpness values (one per corner)");
    }
    WeftSubdivisionOptions options{};
    options.scheme = scheme;
    options.naked_edges = naked_edges;
    options.creasing = creasing;
    options.crease_count = crease_sharpness.size();
    options.crease_vertex_pairs = crease_vertex_pairs.empty() ? nullptr : crease_vertex_pairs.data();
    options.crease_sharpness = crease_sharpness.empty() ? nullptr : crease_sharpness.data();
    options.corner_count = corner_sharpness.size();
    options.corner_vertices = corner_vertices.empty() ? nullptr : corner_vertices.data();
    options.corner_sharpness = corner_sharpness.empty() ? nullptr : corner_sharpness.data();
    options.hole_count = hole_faces.size();
    options.hole_faces = hole_faces.empty() ? nullptr : hole_faces.data();
    options.triangles = triangles;
    return options;
  }
};

/** weft_subdivide_ex: `levels` steps with the scheme, naked edges, creases and corners of `options`. */
inline Mesh subdivide(const Mesh& mesh, const SubdivisionOptions& options, uint32_t levels) {
  const WeftSubdivisionOptions c = options.c_options();
  return detail::make_mesh(weft_subdivide_ex, mesh.get(), &c, levels);
}

/** The sizes of a subdivision's result (weft_subdivision_counts). */
struct SubdivisionCounts {
  std::size_t vertex_count = 0;
  std::size_t face_count = 0;
  std::size_t index_count = 0;
};

/** weft_subdivision_counts: what `levels` steps of `scheme` make, without subdividing. */
inline SubdivisionCounts subdivision_counts(const Mesh& mesh, uint32_t scheme, uint32_t levels) {
  SubdivisionCounts counts;
  detail::check(weft_subdivision_counts(mesh.get(), scheme, levels, &counts.vertex_count, &counts.face_count,
                                        &counts.index_count));
  return counts;
}

/** weft_subdivide_into: `levels` steps of `scheme` written into the host's own buffers, kept from call to call.
 * Size them once from subdivision_counts (3 doubles per vertex, index_count indices); a buffer too small throws
 * WEFT_STATUS_BUFFER_TOO_SMALL and is left as it was. Faces are quads (Catmull-Clark) or triangles (Loop) from
 * level 1 on. */
inline void subdivide_into(const Mesh& mesh, uint32_t scheme, uint32_t levels, uint32_t naked_edges,
                           std::vector<double>& positions, std::vector<uint32_t>& face_indices) {
  detail::check(weft_subdivide_into(mesh.get(), scheme, levels, naked_edges, positions.data(), positions.size(),
                                    face_indices.data(), face_indices.size()));
}

/** weft_subdivision_counts_ex: what `levels` steps with `options` make (holes leave no faces). */
inline SubdivisionCounts subdivision_counts(const Mesh& mesh, const SubdivisionOptions& options, uint32_t levels) {
  const WeftSubdivisionOptions c = options.c_options();
  SubdivisionCounts counts;
  detail::check(weft_subdivision_counts_ex(mesh.get(), &c, levels, &counts.vertex_count, &counts.face_count,
                                           &counts.index_count));
  return counts;
}

/** weft_subdivision_parent_faces_ex: the cage face each face of `subdivide(cage, options, levels)` comes from. */
inline std::vector<uint32_t> parent_faces(const Mesh& cage, const SubdivisionOptions& options, uint32_t levels) {
  const WeftSubdivisionOptions c = options.c_options();
  std::vector<uint32_t> parents(subdivision_counts(cage, options, levels).face_count);
  detail::check(weft_subdivision_parent_faces_ex(cage.get(), &c, levels, parents.data(), parents.size()));
  return parents;
}

/** weft_subdivision_parent_faces: the cage face each refined face comes from. */
inline std::vector<uint32_t> parent_faces(const Mesh& cage, uint32_t scheme, uint32_t levels) {
  std::size_t count = 0;
  detail::check(weft_subdivision_face_count(cage.get(), scheme, levels, &count));
  std::vector<uint32_t> parents(count);
  detail::check(weft_subdivision_parent_faces(cage.get(), scheme, levels, parents.data(), parents.size()));
  return parents;
}

/** weft_subdivide_vertex_data: `width` doubles per cage vertex carried to every refined vertex. */
inline std::vector<double> subdivide_vertex_data(const Mesh& mesh, const SubdivisionOptions& options,
                                                 uint32_t levels, const std::vector<double>& data,
                                                 std::size_t width) {
  const WeftSubdivisionOptions c = options.c_options();
  std::size_t out_len = width * subdivision_counts(mesh, options.scheme, levels).vertex_count;
  std::vector<double> out(out_len);
  detail::check(weft_subdivide_vertex_data(mesh.get(), &c, levels, data.data(), data.size(), width, out.data(),
                                           out.size()));
  return out;
}

/** Points on the limit surface and its unit normals there, x, y, z per refined vertex. */
struct LimitSurface {
  std::vector<double> positions;
  std::vector<double> normals;
};

/** weft_subdivide_limit: the refined vertices projected onto the limit surface. */
inline LimitSurface subdivide_limit(const Mesh& mesh, const SubdivisionOptions& options, uint32_t levels) {
  const WeftSubdivisionOptions c = options.c_options();
  LimitSurface limit;
  std::size_t capacity = 3 * subdivision_counts(mesh, options.scheme, levels).vertex_count;
  limit.positions.resize(capacity);
  limit.normals.resize(capacity);
  detail::check(
      weft_subdivide_limit(mesh.get(), &c, levels, limit.positions.data(), limit.normals.data(), capacity));
  return limit;
}

/** weft_limit_patches: the Catmull-Clark limit surface as bicubic Bézier patches. */
struct LimitPatches {
  /** 48 doubles per patch: control point i along u and j along v of patch p at 48 p + 12 i + 3 j. */
  std::vector<double> control_points;
  /** The cage face each patch lies on. */
  std::vector<uint32_t> cage_faces;
  /** Each patch's largest distance from the limit surface. */
  std::vector<double> errors;
  double max_error = 0;
  /** How many patches are exact (the limit surface to rounding). */
  std::size_t exact_count = 0;
  std::size_t size() const noexcept { return cage_faces.size(); }
};

/** weft_limit_patches: one patch per face of `cage` refined `isolation` levels (1 to 8), Catmull-Clark. */
inline LimitPatches limit_patches(const Mesh& cage, const SubdivisionOptions& options, uint32_t isolation) {
  const WeftSubdivisionOptions c = options.c_options();
  LimitPatches patches;
  const std::size_t count = subdivision_counts(cage, options, isolation).face_count;
  patches.control_points.resize(WEFT_PATCH_DOUBLES * count);
  patches.cage_faces.resize(count);
  patches.errors.resize(count);
  std::size_t written = 0;
  detail::check(weft_limit_patches(cage.get(), &c, isolation, patches.control_points.data(), patches.cage_faces.data(),
                                   patches.errors.data(), count, &written, &patches.max_error, &patches.exact_count));
  return patches;
}

/** A subdivision planned once for one cage topology, re-evaluated for new positions (owns a WeftRefiner). */
class Refiner {
 public:
  /** weft_refiner_new: scheme is a WEFT_SCHEME_* value, naked_edges a WEFT_NAKED_EDGES_* value. */
  Refiner(const Mesh& cage, uint32_t scheme, uint32_t levels, uint32_t naked_edges = WEFT_NAKED_EDGES_FIXED) {
    detail::check(weft_refiner_new(cage.get(), scheme, levels, naked_edges, &handle_));
  }
  /** weft_refiner_new_ex: with the creases and corners of `options`. */
  Refiner(const Mesh& cage, const SubdivisionOptions& options, uint32_t levels) {
    const WeftSubdivisionOptions c = options.c_options();
    detail::check(weft_refiner_new_ex(cage.get(), &c, levels, &handle_));
  }
  Refiner(Refiner&& other) noexcept : handle_(std::exchange(other.handle_, nullptr)) {}
  Refiner& operator=(Refiner&& other) noexcept {
    if (this != &other) {
      weft_refiner_free(handle_);
      handle_ = std::exchange(other.handle_, nullptr);
    }
    return *this;
  }
  Refiner(const Refiner&) = delete;
  Refiner& operator=(const Refiner&) = delete;
  ~Refiner() { weft_refiner_free(handle_); }

  const WeftRefiner* get() const noexcept { return handle_; }
  /** Refined vertices: evaluate() writes 3 doubles for each. */
  std::size_t vertex_count() const noexcept { return weft_refiner_vertex_count(handle_); }
  std::size_t face_count() const noexcept { return weft_refiner_face_count(handle_); }

  /** weft_refiner_evaluate into a caller buffer of out_len doubles (3 × vertex_count() needed). */
  void evaluate(const double* cage_positions, std::size_t cage_vertex_count, double* out_positions,
                std::size_t out_len) const {
    detail::check(weft_refiner_evaluate(handle_, cage_positions, cage_vertex_count, out_positions, out_len));
  }
  /** weft_refiner_evaluate into `out`, resized to 3 × vertex_count() (reuse it to avoid allocating). */
  void evaluate(const std::vector<double>& cage_positions, std::vector<double>& out) const {
    std::size_t cage_vertex_count = detail::triples(cage_positions, "cage_positions");
    out.resize(3 * vertex_count());
    evaluate(cage_positions.data(), cage_vertex_count, out.data(), out.size());
  }
  std::vector<double> evaluate(const std::vector<double>& cage_positions) const {
    std::vector<double> out;
    evaluate(cage_positions, out);
    return out;
  }
  /** weft_refiner_mesh: the refined mesh at the cage's own positions. */
  Mesh mesh() const { return detail::make_mesh(weft_refiner_mesh, handle_); }

 private:
  WeftRefiner* handle_ = nullptr;
};

/* ---- Mending ---- */

/** weft_join of any number of meshes, in order. */
inline Mesh join(const std::vector<std::reference_wrapper<const Mesh>>& meshes) {
  std::vector<const WeftMesh*> handles;
  handles.reserve(meshes.size());
  for (const Mesh& mesh : meshes) handles.push_back(mesh.get());
  return detail::make_mesh(weft_join, handles.empty() ? nullptr : handles.data(), handles.size());
}
inline Mesh join(const std::vector<Mesh>& meshes) {
  return join(std::vector<std::reference_wrapper<const Mesh>>(meshes.begin(), meshes.end()));
}
/** weft_join: join(a, b, c). */
template <class... More>
Mesh join(const Mesh& first, const More&... more) {
  return join(std::vector<std::reference_wrapper<const Mesh>>{std::cref(first), std::cref(more)...});
}

/** weft_weld: merges vertices at most `tolerance` apart; `report`, when given, receives what changed. */
inline Mesh weld(const Mesh& mesh, double tolerance = WEFT_DEFAULT_WELD_TOLERANCE,
                 WeftWeldReport* report = nullptr) {
  WeftMesh* out = nullptr;
  detail::check(weft_weld(mesh.get(), tolerance, &out, report));
  return Mesh::adopt(out);
}

/** weft_find_t_nodes: every vertex lying inside another face's naked edge. */
inline std::vector<WeftTNode> find_t_nodes(const Mesh& mesh, double tolerance = WEFT_DEFAULT_WELD_TOLERANCE) {
  std::size_t count = 0;
  detail::check(weft_find_t_nodes(mesh.get(), tolerance, nullptr, 0, &count));
  std::vector<WeftTNode> nodes(count);
  if (count > 0) detail::check(weft_find_t_nodes(mesh.get(), tolerance, nodes.data(), nodes.size(), &count));
  return nodes;
}

/** weft_repair_t_nodes: inserts each T-node into its edge; `inserted` receives how many. */
inline Mesh repair_t_nodes(const Mesh& mesh, double tolerance = WEFT_DEFAULT_WELD_TOLERANCE,
                           std::size_t* inserted = nullptr) {
  WeftMesh* out = nullptr;
  detail::check(weft_repair_t_nodes(mesh.get(), tolerance, &out, inserted));
  return Mesh::adopt(out);
}

/** weft_cull_adjacent: removes every face that has a twin; `removed` receives how many. */
inline Mesh cull_adjacent(const Mesh& mesh, std::size_t* removed = nullptr) {
  WeftMesh* out = nullptr;
  detail::check(weft_cull_adjacent(mesh.get(), &out, removed));
  return Mesh::adopt(out);
}

/** weft_unify_orientation: one winding per piece; `flipped` receives how many faces turned. */
inline Mesh unify_orientation(const Mesh& mesh, std::size_t* flipped = nullptr) {
  WeftMesh* out = nullptr;
  detail::check(weft_unify_orientation(mesh.get(), &out, flipped));
  return Mesh::adopt(out);
}

/** weft_flip: reverses every face. */
inline Mesh flip(const Mesh& mesh) { return detail::make_mesh(weft_flip, mesh.get()); }

/** weft_triangulate: triangles stay, quads split on the shorter diagonal, n-gons ear-clipped. */
inline Mesh triangulate(const Mesh& mesh) { return detail::make_mesh(weft_triangulate, mesh.get()); }

/* ---- Analysis ---- */

/** weft_face_normals: x, y, z per face. */
inline std::vector<double> face_normals(const Mesh& mesh) {
  std::vector<double> normals(3 * mesh.face_count());
  detail::check(weft_face_normals(mesh.get(), normals.data(), normals.size()));
  return normals;
}

/** weft_vertex_normals: x, y, z per vertex. */
inline std::vector<double> vertex_normals(const Mesh& mesh) {
  std::vector<double> normals(3 * mesh.vertex_count());
  detail::check(weft_vertex_normals(mesh.get(), normals.data(), normals.size()));
  return normals;
}

/** weft_planarity: per face, the largest distance of a corner from its best-fit plane. */
inline std::vector<double> planarity(const Mesh& mesh) {
  std::vector<double> deviations(mesh.face_count());
  detail::check(weft_planarity(mesh.get(), deviations.data(), deviations.size()));
  return deviations;
}

/* ---- Making ---- */

/** The world XY plane, for delaunay and voronoi. */
inline WeftPlane world_xy() noexcept { return WeftPlane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}; }

/** weft_delaunay of x, y, z points projected onto `plane`; `merged` receives how many coincided. */
inline Mesh delaunay(const std::vector<double>& points, const WeftPlane& plane = world_xy(),
                     std::size_t* merged = nullptr) {
  std::size_t count = detail::triples(points, "points");
  WeftMesh* out = nullptr;
  detail::check(weft_delaunay(points.data(), count, &plane, &out, merged));
  return Mesh::adopt(out);
}

/** Voronoi cells, one polygon per input point (owns a WeftCells, freed with weft_cells_free). */
class Cells {
 public:
  static Cells adopt(WeftCells* handle) noexcept { return Cells(handle); }
  Cells(Cells&& other) noexcept : handle_(std::exchange(other.handle_, nullptr)) {}
  Cells& operator=(Cells&& other) noexcept {
    if (this != &other) {
      weft_cells_free(handle_);
      handle_ = std::exchange(other.handle_, nullptr);
    }
    return *this;
  }
  Cells(const Cells&) = delete;
  Cells& operator=(const Cells&) = delete;
  ~Cells() { weft_cells_free(handle_); }

  const WeftCells* get() const noexcept { return handle_; }
  /** One cell per input point. */
  std::size_t count() const noexcept { return weft_cells_count(handle_); }
  std::size_t corner_count() const noexcept { return weft_cells_corner_count(handle_); }
  /** The corner count of each cell, 0 for an empty one. */
  View<uint32_t> sizes() const noexcept { return {weft_cells_sizes(handle_), count()}; }
  /** x, y, z of every corner, cell after cell. */
  View<double> corners() const noexcept { return {weft_cells_corners(handle_), 3 * corner_count()}; }
  /** weft_cells_to_mesh: one n-gon per non-empty cell, unwelded. */
  Mesh to_mesh() const { return detail::make_mesh(weft_cells_to_mesh, handle_); }

 private:
  explicit Cells(WeftCells* handle) noexcept : handle_(handle) {}
  WeftCells* handle_ = nullptr;
};

/** weft_voronoi: an empty `boundary` is the points' bounding rectangle grown by 10 %; radius 0 is no circle. */
inline Cells voronoi(const std::vector<double>& points, const WeftPlane& plane = world_xy(),
                     const std::vector<double>& boundary = {}, double radius = 0.0) {
  std::size_t count = detail::triples(points, "points");
  std::size_t boundary_count = detail::triples(boundary, "boundary");
  WeftCells* out = nullptr;
  detail::check(weft_voronoi(points.data(), count, &plane, boundary_count ? boundary.data() : nullptr,
                             boundary_count, radius, &out));
  return Cells::adopt(out);
}

/** weft_mesh_from_grid: u_count × v_count points, u running fastest. */
inline Mesh mesh_from_grid(const std::vector<double>& points, std::size_t u_count, std::size_t v_count,
                           bool closed_u = false, bool closed_v = false, bool triangulate = false) {
  std::size_t count = detail::triples(points, "points");
  return detail::make_mesh(weft_mesh_from_grid, points.data(), count, u_count, v_count, closed_u, closed_v,
                           triangulate);
}

/** weft_stellate: a pyramid on every face; one height for all faces or one per face. */
inline Mesh stellate(const Mesh& mesh, const std::vector<double>& heights) {
  return detail::make_mesh(weft_stellate, mesh.get(), heights.data(), heights.size());
}

/** weft_plane_grid. */
inline Mesh plane_grid(double size_x, double size_y, std::size_t u_count, std::size_t v_count) {
  return detail::make_mesh(weft_plane_grid, size_x, size_y, u_count, v_count);
}
/** weft_box. */
inline Mesh box(double size_x, double size_y, double size_z, std::size_t u_count = 1, std::size_t v_count = 1,
                std::size_t w_count = 1) {
  return detail::make_mesh(weft_box, size_x, size_y, size_z, u_count, v_count, w_count);
}
/** weft_uv_sphere. */
inline Mesh uv_sphere(double radius, std::size_t u_count, std::size_t v_count) {
  return detail::make_mesh(weft_uv_sphere, radius, u_count, v_count);
}
/** weft_platonic: kind is a WEFT_PLATONIC_* value. */
inline Mesh platonic(uint32_t kind, double radius = 1.0) { return detail::make_mesh(weft_platonic, kind, radius); }
/** weft_sided_solid: kind is a WEFT_SIDED_* value. */
inline Mesh sided_solid(uint32_t kind, std::size_t sides, double radius, double height) {
  return detail::make_mesh(weft_sided_solid, kind, sides, radius, height);
}
/** weft_mesh_from_lines: 6 doubles per segment. */
inline Mesh mesh_from_lines(const std::vector<double>& segments, double tolerance, uint32_t max_valence) {
  if (segments.size() % 6 != 0) {
    throw Error(WEFT_STATUS_COUNT_MISMATCH, "weft: segments holds " + std::to_string(segments.size()) +
                                                " doubles, not a multiple of 6 (two points per segment)");
  }
  return detail::make_mesh(weft_mesh_from_lines, segments.empty() ? nullptr : segments.data(),
                           segments.size() / 6, tolerance, max_valence);
}

/* ---- Weaverbird's toolbar ---- */

inline Mesh split_polygons(const Mesh& mesh, uint32_t levels) {
  return detail::make_mesh(weft_split_polygons, mesh.get(), levels);
}
inline Mesh split_triangles(const Mesh& mesh, uint32_t levels) {
  return detail::make_mesh(weft_split_triangles, mesh.get(), levels);
}
inline Mesh constant_quads_split(const Mesh& mesh, uint32_t levels) {
  return detail::make_mesh(weft_constant_quads_split, mesh.get(), levels);
}
inline Mesh midedge(const Mesh& mesh, uint32_t levels) { return detail::make_mesh(weft_midedge, mesh.get(), levels); }
inline Mesh inner_polygons(const Mesh& mesh, uint32_t levels, double pull) {
  return detail::make_mesh(weft_inner_polygons, mesh.get(), levels, pull);
}
inline Mesh sierpinski_triangles(const Mesh& mesh, uint32_t levels) {
  return detail::make_mesh(weft_sierpinski_triangles, mesh.get(), levels);
}
inline Mesh sierpinski_carpet(const Mesh& mesh, uint32_t levels) {
  return detail::make_mesh(weft_sierpinski_carpet, mesh.get(), levels);
}
inline Mesh laplacian_smooth(const Mesh& mesh, uint32_t iterations, double blend,
                             uint32_t naked_edges = WEFT_NAKED_EDGES_FIXED) {
  return detail::make_mesh(weft_laplacian_smooth, mesh.get(), iterations, blend, naked_edges);
}
inline Mesh laplacian_hc_smooth(const Mesh& mesh, uint32_t iterations, double alpha, double beta,
                                uint32_t naked_edges = WEFT_NAKED_EDGES_FIXED) {
  return detail::make_mesh(weft_laplacian_hc_smooth, mesh.get(), iterations, alpha, beta, naked_edges);
}
/** weft_offset_mesh: offset_type is a WEFT_OFFSET_* value. */
inline Mesh offset_mesh(const Mesh& mesh, double distance, uint32_t offset_type = WEFT_OFFSET_DIAGONAL) {
  return detail::make_mesh(weft_offset_mesh, mesh.get(), distance, offset_type);
}
inline Mesh thicken_mesh(const Mesh& mesh, double distance, uint32_t offset_type = WEFT_OFFSET_DIAGONAL) {
  return detail::make_mesh(weft_thicken_mesh, mesh.get(), distance, offset_type);
}
/** weft_mesh_window: one distance for every face or one per face; inset_mode a WEFT_INSET_* value. */
inline Mesh mesh_window(const Mesh& mesh, const std::vector<double>& distances,
                        uint32_t inset_mode = WEFT_INSET_EDGE_FRACTION) {
  return detail::make_mesh(weft_mesh_window, mesh.get(), distances.data(), distances.size(), inset_mode);
}
inline Mesh picture_frame(const Mesh& mesh, const std::vector<double>& distances,
                          uint32_t inset_mode = WEFT_INSET_EDGE_FRACTION) {
  return detail::make_mesh(weft_picture_frame, mesh.get(), distances.data(), distances.size(), inset_mode);
}
inline Mesh bevel_edges(const Mesh& mesh, double fraction) {
  return detail::make_mesh(weft_bevel_edges, mesh.get(), fraction);
}
inline Mesh bevel_vertices(const Mesh& mesh, double fraction) {
  return detail::make_mesh(weft_bevel_vertices, mesh.get(), fraction);
}
/** weft_dual: dual_mode is a WEFT_DUAL_* value. */
inline Mesh dual(const Mesh& mesh, uint32_t dual_mode = WEFT_DUAL_VERTEX_AVERAGE) {
  return detail::make_mesh(weft_dual, mesh.get(), dual_mode);
}
inline Mesh reroute_faces(const Mesh& mesh, int64_t shift) {
  return detail::make_mesh(weft_reroute_faces, mesh.get(), shift);
}
/** weft_tile: fill a WEFT_TILE_FILL_* value, faces a WEFT_TILE_FACES_* value. */
inline Mesh tile(const Mesh& mesh, uint32_t fill, uint32_t faces = WEFT_TILE_FACES_ALL) {
  return detail::make_mesh(weft_tile, mesh.get(), fill, faces);
}

/** weft_mesh_copy_edges: two vertex indices per unique edge. */
inline std::vector<uint32_t> edges(const Mesh& mesh) {
  std::size_t count = 0;
  detail::check(weft_mesh_edge_count(mesh.get(), &count));
  std::vector<uint32_t> pairs(2 * count);
  detail::check(weft_mesh_copy_edges(mesh.get(), pairs.data(), pairs.size()));
  return pairs;
}

}  // namespace weft

#endif  // WEFT_HPP
