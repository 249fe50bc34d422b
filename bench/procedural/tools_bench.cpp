// Throughput of the mesh tools on a closed box of about one million quads (a 408 x 408 grid per
// side: 998,784 quads, 2.0 M triangles). Counter "s_per_Mface" = seconds per million input
// faces of the mesh: extrusion and sqrt(2) subdivision rebuild the whole mesh (its canonical
// element order is what keeps every model's bytes), so the mesh size is their cost driver.
// The *Small* cases edit a 4 x 4 patch (16 faces) of the same mesh: selection, curve shaping
// and bridging work in place and cost what the patch costs (bridge: the mesh already has
// OpenMesh's status flags, as after a first bridge; requesting them is one pass over the mesh).
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/extrusion.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "genmod/procedural/selection.hpp"
#include "genmod/procedural/sqrt2_subdivision.hpp"
#include "genmod/procedural/stitching.hpp"

#include <benchmark/benchmark.h>

namespace genmod {
namespace {

const PolyMesh& big_box() {
  static const PolyMesh mesh = make_grid_box(Vec3(-1, -1, -1), Vec3(1, 1, 1), 408);
  return mesh;
}

void per_million_faces(benchmark::State& state, std::size_t faces) {
  state.counters["Mfaces"] = static_cast<double>(faces) / 1e6;
  state.counters["s_per_Mface"] = benchmark::Counter(static_cast<double>(faces) / 1e6,
                                                     benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

// Extrudes the upper half of the box (the +z side and the upper halves of four sides).
void BM_ExtrudeUpperHalf(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList half = select_faces(source, all_faces(source), RatioBox{0, 1, 0, 1, 0.5, 1});
  PolyMesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = source;  // the previous result is freed here, outside the timing
    state.ResumeTiming();
    FaceList caps = extrude(mesh, half, Vec3(0, 0, 0.25));
    benchmark::DoNotOptimize(caps.data());
  }
  state.counters["selected"] = static_cast<double>(half.size());
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_ExtrudeUpperHalf)->Unit(benchmark::kMillisecond);

void BM_Sqrt2Global(benchmark::State& state) {
  const PolyMesh& source = big_box();
  PolyMesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = source;  // the previous result is freed here, outside the timing
    state.ResumeTiming();
    sqrt2_subdivide_all(mesh, 1, 1.0);
    benchmark::DoNotOptimize(mesh.n_faces());
  }
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_Sqrt2Global)->Unit(benchmark::kMillisecond);

void BM_Sqrt2AdaptiveUpperHalf(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList half = select_faces(source, all_faces(source), RatioBox{0, 1, 0, 1, 0.5, 1});
  PolyMesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = source;  // the previous result is freed here, outside the timing
    state.ResumeTiming();
    FaceList created = sqrt2_subdivide(mesh, half, 1, 1.0);
    benchmark::DoNotOptimize(created.data());
  }
  state.counters["selected"] = static_cast<double>(half.size());
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_Sqrt2AdaptiveUpperHalf)->Unit(benchmark::kMillisecond);

void BM_SelectUpperHalf(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList all = all_faces(source);
  for (auto _ : state) {
    FaceList half = select_faces(source, all, RatioBox{0, 1, 0, 1, 0.5, 1});
    benchmark::DoNotOptimize(half.data());
  }
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_SelectUpperHalf)->Unit(benchmark::kMillisecond);

// A 4 x 4 patch of the centre of the -x side (x near 0.05 from the -x end: ratios) or of the +x side.
FaceList small_patch(const PolyMesh& mesh, bool plus_x) {
  const double c = 0.5, h = 2.0 / 408;  // 2 cells each side of the centre (box side 2, 408 cells)
  const double x0 = plus_x ? 0.99 : -0.01, x1 = plus_x ? 1.01 : 0.01;
  return select_faces(mesh, all_faces(mesh), RatioBox{x0, x1, c - h - 1e-9, c + h + 1e-9, c - h - 1e-9, c + h + 1e-9});
}

const PolyMesh& big_box_with_status() {
  static const PolyMesh mesh = [] {
    PolyMesh m = big_box();
    m.request_face_status();
    m.request_edge_status();
    m.request_halfedge_status();
    m.request_vertex_status();
    return m;
  }();
  return mesh;
}

void BM_SelectSmallParent(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList patch = small_patch(source, false);
  for (auto _ : state) {
    FaceList half = select_faces(source, patch, RatioBox{0, 1, 0, 0.5, 0, 1});
    benchmark::DoNotOptimize(half.data());
  }
  state.counters["selected"] = static_cast<double>(patch.size());
}
BENCHMARK(BM_SelectSmallParent)->Unit(benchmark::kMicrosecond);

void BM_ShapeToCurveSmallPatch(benchmark::State& state) {
  PolyMesh mesh = big_box();
  const FaceList patch = small_patch(mesh, false);
  const BezierCurve bow({Vec3(-1.0, -1, 0), Vec3(-1.05, 0, 0), Vec3(-1.0, 1, 0)});
  for (auto _ : state) benchmark::DoNotOptimize(shape_to_curve(mesh, patch, bow, Vec3(-1, 0, 0), Vec3(0, 0, 1)));
  state.counters["selected"] = static_cast<double>(patch.size());
}
BENCHMARK(BM_ShapeToCurveSmallPatch)->Unit(benchmark::kMicrosecond);

void BM_BridgeSmallPatches(benchmark::State& state) {
  const PolyMesh& source = big_box_with_status();
  const FaceList a = small_patch(source, false), b = small_patch(source, true);
  PolyMesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = source;  // the previous copy is freed here, outside the timing
    // Room for the new elements, as a mesh that has been edited before has: the first element
    // added to a fresh copy makes std::vector reallocate every array (amortised O(1) per element,
    // but one whole-mesh copy in a one-call benchmark).
    mesh.reserve(mesh.n_vertices() + 64, mesh.n_edges() + 256, mesh.n_faces() + 128);
    state.ResumeTiming();
    FaceList joined = bridge(mesh, a, b, "bridge");
    benchmark::DoNotOptimize(joined.data());
  }
  state.counters["selected"] = static_cast<double>(a.size() + b.size());
}
// A fixed count: each iteration copies the million-face mesh outside the timing.
BENCHMARK(BM_BridgeSmallPatches)->Iterations(20)->Unit(benchmark::kMicrosecond);

void BM_ExtrudeSmallPatch(benchmark::State& state) {
  const PolyMesh& source = big_box();
  const FaceList patch = small_patch(source, false);
  PolyMesh mesh;
  for (auto _ : state) {
    state.PauseTiming();
    mesh = source;
    state.ResumeTiming();
    FaceList caps = extrude(mesh, patch, Vec3(-0.1, 0, 0));
    benchmark::DoNotOptimize(caps.data());
  }
  state.counters["selected"] = static_cast<double>(patch.size());
  per_million_faces(state, source.n_faces());
}
BENCHMARK(BM_ExtrudeSmallPatch)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace genmod
