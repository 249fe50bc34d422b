#include "furniture_tools.hpp"

#include "genmod/procedural/affine.hpp"
#include "genmod/procedural/stitching.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace genmod::models::detail {

void refuse_parameter(std::string_view procedure, std::string_view parameter, const std::string& problem) {
  std::string message = "call '";
  message.append(procedure);
  message.append("': parameter '");
  message.append(parameter);
  message.append("' ");
  message.append(problem);
  throw std::invalid_argument(message);
}

namespace {
std::string shown(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}
}  // namespace

double positive_real(const Arguments& a, std::string_view procedure, std::string_view name) {
  const double v = a.real(name);
  if (!(std::isfinite(v) && v > 0)) refuse_parameter(procedure, name, "must be a finite number > 0, got " + shown(v));
  return v;
}

double real_in(const Arguments& a, std::string_view procedure, std::string_view name, double lo, double hi) {
  const double v = a.real(name);
  if (!(std::isfinite(v) && v >= lo && v <= hi))
    refuse_parameter(procedure, name, "must be in [" + shown(lo) + ", " + shown(hi) + "], got " + shown(v));
  return v;
}

int integer_in(const Arguments& a, std::string_view procedure, std::string_view name, int lo, int hi) {
  const std::int64_t v = a.integer(name);
  if (v < lo || v > hi)
    refuse_parameter(procedure, name,
                     "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                         std::to_string(v));
  return static_cast<int>(v);
}

std::pair<double, double> cell_range(int first, int last, int cells) {
  return {(first - 0.25) / cells, (last + 1.25) / cells};
}

std::array<Vec3, 2> padded_box(const Vec3& lo, const Vec3& hi, double fraction) {
  const double pad = fraction * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  return {lo - Vec3(pad, pad, pad), hi + Vec3(pad, pad, pad)};
}

int lod_levels(int levels, int lod, int max_levels) {
  // In 64 bits: any int lod (a caller's, a camera's) without overflow.
  return static_cast<int>(std::clamp<std::int64_t>(std::int64_t{levels} + lod, 0, max_levels));
}

int lod_steps(int steps, int lod) {
  for (int i = 0; i > lod && steps > 1; --i) steps = (steps + 1) / 2;
  return steps;
}

RatioBox ratio_box(std::pair<double, double> x, std::pair<double, double> y, std::pair<double, double> z) {
  return RatioBox{x.first, x.second, y.first, y.second, z.first, z.second};
}

FaceList Workpiece::select(const std::string& parent, const RatioBox& box) const {
  return sets.select(mesh, parent, box, "").faces;
}

FaceList Workpiece::name(const std::string& id, const FaceList& faces) {
  sets.add(mesh, FaceSet{id, "", faces});
  return sets.get(id).faces;
}

FaceList Workpiece::extrude_chain(FaceList faces, const Vec3& by, int times) {
  for (int i = 0; i < times; ++i) faces = extrude(mesh, faces, by);
  sets.update(mesh);
  return faces;
}

void attach_leg(Workpiece& w, const PolyMesh& leg, const FaceList& cell, double gap) { attach_leg(w.mesh, leg, cell, gap); }

void attach_leg(PolyMesh& mesh, const PolyMesh& leg, const FaceList& cell, double gap) {
  const auto [lo, hi] = bounds(mesh, cell);
  // append_mesh adds the leg's faces in order after the mesh's, so its top keeps its index
  // offset by the faces already there (no search of the whole mesh per leg).
  const int first_face = static_cast<int>(mesh.n_faces());
  FaceList top;
  for (PolyMesh::FaceHandle f : faces_labelled(leg, "legtop")) top.emplace_back(first_face + f.idx());
  append_mesh(mesh, leg, Affine::translation(Vec3(0.5 * (lo[0] + hi[0]), lo[1] - gap, 0.5 * (lo[2] + hi[2]))));
  bridge(mesh, top, cell, "ankle");
}

FaceList merged(std::initializer_list<FaceList> lists) {
  FaceList all;
  for (const FaceList& l : lists) all.insert(all.end(), l.begin(), l.end());
  std::sort(all.begin(), all.end(), [](auto a, auto b) { return a.idx() < b.idx(); });
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace genmod::models::detail
