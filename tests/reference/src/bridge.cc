// OpenSubdiv 3.5 (Far) and OpenMesh 9 behind the calls declared in
// include/bridge.h. The Rust side has already checked every index and length;
// what can still fail here (OpenSubdiv rejecting a topology, OpenMesh refusing
// a face) is thrown as std::runtime_error and reaches Rust as an Err.
#include "weft-reference/include/bridge.h"
#include "weft-reference/src/bridge.rs.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/ompEvaluator.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace weft_reference {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

namespace {

// OpenSubdiv reports through global callbacks (by default it prints, and exits
// on fatal errors); collect the messages of the calling thread instead.
thread_local std::string far_errors;

void collect_error(Far::ErrorType, const char *message) {
  if (!far_errors.empty()) far_errors += "; ";
  far_errors += message;
}

void ignore_warning(const char *) {}

void install_callbacks() {
  static std::once_flag once;
  std::call_once(once, [] {
    Far::SetErrorCallback(collect_error);
    Far::SetWarningCallback(ignore_warning);
  });
  far_errors.clear();
}

void throw_if_failed(const char *what) {
  if (!far_errors.empty()) {
    std::string message = std::string(what) + ": " + far_errors;
    far_errors.clear();
    throw std::runtime_error(message);
  }
}

// One row of `W` doubles (W == 0: the width is known only at run time), the
// value type PrimvarRefiner and StencilTable accumulate with.
template <std::size_t W> struct Row {
  double *p;
  std::size_t w;
  std::size_t width() const { return W ? W : w; }
  void Clear() { std::fill(p, p + width(), 0.0); }
  void AddWithWeight(const Row &src, double weight) {
    for (std::size_t i = 0; i < width(); ++i) p[i] += weight * src.p[i];
  }
};

template <std::size_t W> struct Rows {
  double *base;
  std::size_t w;
  Row<W> operator[](int i) const { return Row<W>{base + std::size_t(i) * w, w}; }
};

template <std::size_t W> Rows<W> rows(const double *data, std::size_t width) {
  return Rows<W>{const_cast<double *>(data), width};
}

// Applies `step(level, src, dst)` for levels 1..max, reading the cage from
// `cage` and writing the last level to `out`; `count(level)` is the number of
// rows at a level.
template <std::size_t W, class Count, class Step>
void refine_levels(const Far::TopologyRefiner &refiner, const double *cage, std::size_t width,
                   double *out, Count count, Step step) {
  const int max = refiner.GetMaxLevel();
  if (max == 0) {
    std::copy(cage, cage + count(0) * width, out);
    return;
  }
  std::vector<double> previous, next;
  const double *src = cage;
  for (int level = 1; level <= max; ++level) {
    double *dst = out;
    if (level < max) {
      next.assign(count(level) * width, 0.0);
      dst = next.data();
    }
    auto src_rows = rows<W>(src, width);
    auto dst_rows = rows<W>(dst, width);
    step(level, src_rows, dst_rows);
    std::swap(previous, next);
    src = previous.data();
  }
}

template <std::size_t W>
void interpolate_vertices(const Far::TopologyRefiner &refiner, const double *cage,
                          std::size_t width, bool varying, double *out) {
  Far::PrimvarRefinerReal<double> primvar(refiner);
  refine_levels<W>(
      refiner, cage, width, out,
      [&](int level) { return std::size_t(refiner.GetLevel(level).GetNumVertices()); },
      [&](int level, const Rows<W> &src, Rows<W> &dst) {
        if (varying)
          primvar.InterpolateVarying(level, src, dst);
        else
          primvar.Interpolate(level, src, dst);
      });
}

} // namespace

OsdRefiner::OsdRefiner(std::unique_ptr<Far::TopologyRefiner> refiner)
    : refiner_(std::move(refiner)) {}

std::unique_ptr<OsdRefiner> osd_refiner_new(
    uint32_t vertex_count, rust::Slice<const uint32_t> face_sizes,
    rust::Slice<const uint32_t> face_indices, rust::Slice<const uint32_t> crease_pairs,
    rust::Slice<const float> crease_sharpness, rust::Slice<const uint32_t> corners,
    rust::Slice<const float> corner_sharpness, uint32_t fvar_value_count,
    rust::Slice<const uint32_t> fvar_indices, rust::Slice<const uint32_t> holes,
    const OsdSettings &settings, uint32_t levels) {
  install_callbacks();

  // Index is int; the Rust side keeps every value below 2^31, and signed and
  // unsigned variants of a type may alias.
  auto as_index = [](rust::Slice<const uint32_t> s) {
    return reinterpret_cast<const Far::Index *>(s.data());
  };
  Far::TopologyDescriptor desc;
  desc.numVertices = int(vertex_count);
  desc.numFaces = int(face_sizes.size());
  desc.numVertsPerFace = reinterpret_cast<const int *>(face_sizes.data());
  desc.vertIndicesPerFace = as_index(face_indices);
  desc.numCreases = int(crease_sharpness.size());
  desc.creaseVertexIndexPairs = as_index(crease_pairs);
  desc.creaseWeights = crease_sharpness.data();
  desc.numCorners = int(corner_sharpness.size());
  desc.cornerVertexIndices = as_index(corners);
  desc.cornerWeights = corner_sharpness.data();
  desc.numHoles = int(holes.size());
  desc.holeIndices = as_index(holes);
  Far::TopologyDescriptor::FVarChannel channel;
  if (!fvar_indices.empty()) {
    channel.numValues = int(fvar_value_count);
    channel.valueIndices = as_index(fvar_indices);
    desc.numFVarChannels = 1;
    desc.fvarChannels = &channel;
  }

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(
      Sdc::Options::VtxBoundaryInterpolation(settings.boundary));
  options.SetCreasingMethod(Sdc::Options::CreasingMethod(settings.creasing));
  options.SetFVarLinearInterpolation(
      Sdc::Options::FVarLinearInterpolation(settings.fvar_linear));
  options.SetTriangleSubdivision(Sdc::Options::TriangleSubdivision(settings.triangles));
  const Sdc::SchemeType scheme = settings.scheme == 2   ? Sdc::SCHEME_BILINEAR
                                 : settings.scheme == 1 ? Sdc::SCHEME_LOOP
                                                        : Sdc::SCHEME_CATMARK;

  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(scheme, options)));
  if (!refiner) {
    if (far_errors.empty()) far_errors = "no message";
    throw_if_failed("OpenSubdiv rejected the cage");
  }
  throw_if_failed("OpenSubdiv reported an error building the cage");
  if (levels > 0) {
    Far::TopologyRefiner::UniformOptions uniform{static_cast<int>(levels)};
    uniform.fullTopologyInLastLevel = settings.full_topology;
    refiner->RefineUniform(uniform);
    throw_if_failed("OpenSubdiv reported an error refining");
  }
  return std::make_unique<OsdRefiner>(std::move(refiner));
}

std::size_t OsdRefiner::vertex_count() const {
  return std::size_t(refiner_->GetLevel(refiner_->GetMaxLevel()).GetNumVertices());
}

// Faces tagged as holes (given, or made by VTX_BOUNDARY_NONE) are skipped,
// as OpenSubdiv's users draw and export a refined level.
std::size_t OsdRefiner::face_count() const {
  const auto &last = refiner_->GetLevel(refiner_->GetMaxLevel());
  std::size_t count = 0;
  for (int f = 0; f < last.GetNumFaces(); ++f) count += !last.IsFaceHole(f);
  return count;
}

std::size_t OsdRefiner::corner_count() const {
  const auto &last = refiner_->GetLevel(refiner_->GetMaxLevel());
  std::size_t count = 0;
  for (int f = 0; f < last.GetNumFaces(); ++f)
    if (!last.IsFaceHole(f)) count += std::size_t(last.GetFaceVertices(f).size());
  return count;
}

std::size_t OsdRefiner::fvar_value_count() const {
  const auto &last = refiner_->GetLevel(refiner_->GetMaxLevel());
  return refiner_->GetNumFVarChannels() > 0 ? std::size_t(last.GetNumFVarValues(0)) : 0;
}

void OsdRefiner::faces(rust::Slice<uint32_t> sizes, rust::Slice<uint32_t> indices) const {
  const auto &last = refiner_->GetLevel(refiner_->GetMaxLevel());
  std::size_t corner = 0, face = 0;
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    if (last.IsFaceHole(f)) continue;
    auto verts = last.GetFaceVertices(f);
    sizes[face++] = uint32_t(verts.size());
    for (int i = 0; i < verts.size(); ++i) indices[corner++] = uint32_t(verts[i]);
  }
}

void OsdRefiner::interpolate(rust::Slice<const double> cage, std::size_t width, bool varying,
                             rust::Slice<double> out) const {
  switch (width) {
  case 1: interpolate_vertices<1>(*refiner_, cage.data(), width, varying, out.data()); break;
  case 2: interpolate_vertices<2>(*refiner_, cage.data(), width, varying, out.data()); break;
  case 3: interpolate_vertices<3>(*refiner_, cage.data(), width, varying, out.data()); break;
  case 4: interpolate_vertices<4>(*refiner_, cage.data(), width, varying, out.data()); break;
  default: interpolate_vertices<0>(*refiner_, cage.data(), width, varying, out.data()); break;
  }
}

void OsdRefiner::interpolate_face_varying(rust::Slice<const double> cage, std::size_t width,
                                          rust::Slice<double> out_values,
                                          rust::Slice<uint32_t> out_indices) const {
  const Far::TopologyRefiner &refiner = *refiner_;
  Far::PrimvarRefinerReal<double> primvar(refiner);
  refine_levels<0>(
      refiner, cage.data(), width, out_values.data(),
      [&](int level) { return std::size_t(refiner.GetLevel(level).GetNumFVarValues(0)); },
      [&](int level, const Rows<0> &src, Rows<0> &dst) {
        primvar.InterpolateFaceVarying(level, src, dst, 0);
      });
  const auto &last = refiner.GetLevel(refiner.GetMaxLevel());
  std::size_t corner = 0;
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    if (last.IsFaceHole(f)) continue;
    auto values = last.GetFaceFVarValues(f, 0);
    for (int i = 0; i < values.size(); ++i) out_indices[corner++] = uint32_t(values[i]);
  }
}

void OsdRefiner::limit(rust::Slice<const double> cage_positions, rust::Slice<double> positions,
                       rust::Slice<double> du, rust::Slice<double> dv) const {
  install_callbacks();
  std::vector<double> last(vertex_count() * 3);
  interpolate_vertices<3>(*refiner_, cage_positions.data(), 3, false, last.data());
  Far::PrimvarRefinerReal<double> primvar(*refiner_);
  auto src = rows<3>(last.data(), 3);
  auto pos = rows<3>(positions.data(), 3);
  auto tan1 = rows<3>(du.data(), 3);
  auto tan2 = rows<3>(dv.data(), 3);
  primvar.Limit(src, pos, tan1, tan2);
  throw_if_failed("OpenSubdiv could not evaluate the limit");
}

void OsdRefiner::bfr_evaluate(rust::Slice<const double> cage_positions, int32_t approx_smooth,
                              int32_t approx_sharp, rust::Slice<const uint32_t> faces,
                              rust::Slice<const double> uvs, rust::Slice<double> positions,
                              rust::Slice<double> du, rust::Slice<double> dv) const {
  namespace Bfr = OpenSubdiv::Bfr;
  install_callbacks();
  Bfr::SurfaceFactory::Options options;
  options.SetApproxLevelSmooth(approx_smooth);
  options.SetApproxLevelSharp(approx_sharp);
  Bfr::RefinerSurfaceFactory<> factory(*refiner_, options);
  Bfr::Surface<double> surface;
  std::vector<double> patch_points;
  // Samples of the same face in a row share its surface, as Bfr's users
  // evaluate a face's samples together.
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (i == 0 || faces[i] != faces[i - 1]) {
      if (!factory.InitVertexSurface<double>(int(faces[i]), &surface) || !surface.IsValid()) {
        throw std::runtime_error("Bfr has no limit surface for face " + std::to_string(faces[i]));
      }
      patch_points.resize(std::size_t(surface.GetNumPatchPoints()) * 3);
      surface.PreparePatchPoints(cage_positions.data(), 3, patch_points.data(), 3);
    }
    const double uv[2] = {uvs[2 * i], uvs[2 * i + 1]};
    surface.Evaluate(uv, patch_points.data(), 3, &positions[3 * i], &du[3 * i], &dv[3 * i]);
  }
  throw_if_failed("OpenSubdiv reported an error evaluating the limit surface");
}

OsdStencils::OsdStencils(std::unique_ptr<const Far::StencilTableReal<double>> table)
    : table_(std::move(table)) {}

namespace {

// The stencils of the last level's vertices from the cage, intermediate
// levels factorized, as `Factory` makes them; throws OpenSubdiv's message.
template <class Factory, class Table>
std::unique_ptr<const Table> last_level_stencils(const OsdRefiner &refiner) {
  install_callbacks();
  typename Factory::Options options;
  options.interpolationMode = Factory::INTERPOLATE_VERTEX;
  options.generateOffsets = true;
  options.generateControlVerts = false;
  options.generateIntermediateLevels = false;
  options.factorizeIntermediateLevels = true;
  options.maxLevel = unsigned(refiner.refiner().GetMaxLevel());
  std::unique_ptr<const Table> table(Factory::Create(refiner.refiner(), options));
  if (!table) far_errors += far_errors.empty() ? "no message" : "";
  throw_if_failed("OpenSubdiv could not build the stencil table");
  return table;
}

} // namespace

std::unique_ptr<OsdStencils> osd_stencils_new(const OsdRefiner &refiner) {
  using Factory = Far::StencilTableFactoryReal<double>;
  return std::make_unique<OsdStencils>(
      last_level_stencils<Factory, Far::StencilTableReal<double>>(refiner));
}

std::size_t OsdStencils::stencil_count() const { return std::size_t(table_->GetNumStencils()); }

void OsdStencils::update(rust::Slice<const double> cage_positions, rust::Slice<double> out) const {
  auto src = rows<3>(cage_positions.data(), 3);
  auto dst = rows<3>(out.data(), 3);
  table_->UpdateValues(src, dst);
}

void OsdStencils::update_on_threads(rust::Slice<const double> cage_positions,
                                    rust::Slice<double> out, uint32_t threads) const {
  const int count = table_->GetNumStencils();
  const int parts = int(std::max<uint32_t>(threads, 1));
  std::vector<std::thread> workers;
  workers.reserve(std::size_t(parts - 1));
  auto run = [&](int part) {
    auto src = rows<3>(cage_positions.data(), 3);
    auto dst = rows<3>(out.data(), 3);
    const int start = int(std::int64_t(count) * part / parts);
    const int end = int(std::int64_t(count) * (part + 1) / parts);
    if (start < end) table_->UpdateValues(src, dst, start, end);
  };
  try {
    for (int part = 1; part < parts; ++part) workers.emplace_back(run, part);
  } catch (...) {
    // No thread left running on `out` when the error reaches the caller.
    for (auto &worker : workers) worker.join();
    throw;
  }
  run(0);
  for (auto &worker : workers) worker.join();
}

OsdParallelStencils::OsdParallelStencils(std::unique_ptr<const Far::StencilTable> table)
    : table_(std::move(table)) {}

std::unique_ptr<OsdParallelStencils> osd_parallel_stencils_new(const OsdRefiner &refiner) {
  return std::make_unique<OsdParallelStencils>(
      last_level_stencils<Far::StencilTableFactory, Far::StencilTable>(refiner));
}

std::size_t OsdParallelStencils::stencil_count() const {
  return std::size_t(table_->GetNumStencils());
}

void OsdParallelStencils::update(rust::Slice<const float> cage_positions,
                                 rust::Slice<float> out, uint32_t threads) const {
  namespace Osd = OpenSubdiv::Osd;
  Osd::OmpEvaluator::SetNumThreads(int(std::max<uint32_t>(threads, 1)));
  const Osd::BufferDescriptor desc(0, 3, 3);
  const bool ok = Osd::OmpEvaluator::EvalStencils(
      cage_positions.data(), desc, out.data(), desc, table_->GetSizes().data(),
      table_->GetOffsets().data(), table_->GetControlIndices().data(),
      table_->GetWeights().data(), 0, table_->GetNumStencils());
  if (!ok) throw std::runtime_error("Osd::OmpEvaluator::EvalStencils failed");
}

// ---- OpenMesh ---------------------------------------------------------------

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

template <class Mesh>
void build(Mesh &mesh, rust::Slice<const double> positions, rust::Slice<const uint32_t> face_sizes,
           rust::Slice<const uint32_t> face_indices) {
  std::vector<typename Mesh::VertexHandle> handles;
  handles.reserve(positions.size() / 3);
  for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
    handles.push_back(
        mesh.add_vertex(OpenMesh::Vec3d(positions[i], positions[i + 1], positions[i + 2])));
  std::vector<typename Mesh::VertexHandle> face;
  std::size_t corner = 0;
  for (std::size_t f = 0; f < face_sizes.size(); ++f) {
    face.clear();
    for (uint32_t i = 0; i < face_sizes[f]; ++i) face.push_back(handles[face_indices[corner++]]);
    if (!mesh.add_face(face).is_valid())
      throw std::runtime_error("OpenMesh refused face " + std::to_string(f) +
                               " (a non-manifold edge or vertex, or a flipped face)");
  }
}

template <class Mesh> OmMesh extract(const Mesh &mesh) {
  OmMesh out;
  out.positions.reserve(mesh.n_vertices() * 3);
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
    const auto &p = mesh.point(typename Mesh::VertexHandle(int(v)));
    out.positions.push_back(p[0]);
    out.positions.push_back(p[1]);
    out.positions.push_back(p[2]);
  }
  out.face_sizes.reserve(mesh.n_faces());
  // Every corner is a halfedge: room for all without regrowing.
  out.face_indices.reserve(mesh.n_halfedges());
  for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
    uint32_t size = 0;
    for (auto v : mesh.fv_range(typename Mesh::FaceHandle(int(f)))) {
      out.face_indices.push_back(uint32_t(v.idx()));
      ++size;
    }
    out.face_sizes.push_back(size);
  }
  return out;
}

template <class Mesh, class Subdivider>
OmMesh om_subdivide(rust::Slice<const double> positions, rust::Slice<const uint32_t> face_sizes,
                    rust::Slice<const uint32_t> face_indices, uint32_t levels) {
  Mesh mesh;
  build(mesh, positions, face_sizes, face_indices);
  if (levels > 0) {
    Subdivider subdivider;
    if (!subdivider.attach(mesh) || !subdivider(std::size_t(levels)))
      throw std::runtime_error(std::string("OpenMesh ") + subdivider.name() + " failed");
    subdivider.detach();
  }
  return extract(mesh);
}

} // namespace

OmMesh om_catmull_clark(rust::Slice<const double> positions, rust::Slice<const uint32_t> face_sizes,
                        rust::Slice<const uint32_t> face_indices, uint32_t levels) {
  return om_subdivide<PolyMesh, OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh, double>>(
      positions, face_sizes, face_indices, levels);
}

OmMesh om_loop(rust::Slice<const double> positions, rust::Slice<const uint32_t> face_sizes,
               rust::Slice<const uint32_t> face_indices, uint32_t levels) {
  return om_subdivide<TriMesh, OpenMesh::Subdivider::Uniform::LoopT<TriMesh, double>>(
      positions, face_sizes, face_indices, levels);
}

} // namespace weft_reference
