// branch and tree: the L-system trees of Experiments 4 and 6 (research/morkel.md section 3.3;
// the thesis gives neither grammar, angles nor counts, so all of it is documented here).
//
// branch (cacheable Out): a meshed parametric cylinder along +y from y = 0 to y = length, a
// frustum from radius at the bottom to taper * radius at the top: `sides` vertices round,
// `rings` + 1 rings, two convex `sides`-gon caps; closed, outward.
//
// tree (cacheable Out): the string of the bracketed L-system
//     axiom A,   A -> F / [ + A ] [ - A ]
// rewritten `levels` times (A's left over draw nothing) is read by a turtle: F draws a branch
// (a call of `branch`) of the turtle's order d (the number of F's before it on its path) and
// moves to its tip; / rolls the turtle about its heading by 90 degrees; + and - pitch it by
// +angle / -angle; [ and ] push and pop its state. A tree of `levels` levels has 2^levels - 1
// branches; order d has length trunkLength * lengthRatio^d and radius trunkRadius *
// radiusRatio^d, tapering to the next order's radius, so the branch calls have exactly
// `levels` distinct argument tuples: with caching on a tree costs `levels` branch misses and
// 2^levels - 1 - levels hits. The seed (the context's, java.util.Random) jitters every pitch
// and roll by up to `jitter` of itself: the branches' shapes do not depend on it, their
// placement does. The branch calls pass seed 0 (a branch draws no random numbers), so trees of
// every seed share one set of cached branches.
//
// Level of detail (camera.hpp): the tree declares uses_lod and a bounding box, and draws
// the branches of the first clamp(levels + lod, 1, 10) orders, so lod 0 (no camera) is the tree
// its parameters say, each lod below drops the finest order of branches (half of them), and
// lod -4 of the default tree is its trunk alone. A coarser tree is a subset of the finer one:
// the turtle still reads the whole string (and draws the same random numbers), skipping the
// branches beyond the level. Every level is closed, as every tree is. The box is the trunk's plus a cube
// about the trunk's tip reaching as far as branches of 10 levels could (the path's branches and
// gaps end to end, plus the trunk's radius), so it holds the tree at every lod and every seed.
//
// The branches are separate closed components (the mesh as a whole is closed, 2-manifold and
// free of self-intersections): a child starts a gap beyond its parent's tip along its own
// heading, 1.3 child radii / sin(the smallest pitch) long, enough to clear the parent's top
// and the sibling at the opposite pitch (they do not overlap, so none is needed inside another).
#include "body_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/rng.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace genmod::models::detail {
namespace {

PolyMesh build_branch(const Arguments& a, const CallContext&) {
  const char* P = "branch";
  const double length = positive_real(a, P, "length"), radius = positive_real(a, P, "radius");
  const double taper = real_in(a, P, "taper", 0.05, 1.0);
  const int sides = integer_in(a, P, "sides", 3, 256), rings = integer_in(a, P, "rings", 1, 256);
  PolyMesh mesh;
  std::vector<std::vector<PolyMesh::VertexHandle>> ring(rings + 1);
  for (int k = 0; k <= rings; ++k) {
    const double t = static_cast<double>(k) / rings, r = radius * (1.0 + (taper - 1.0) * t), y = length * t;
    for (int i = 0; i < sides; ++i) {
      const double phi = 2.0 * std::numbers::pi * i / sides;
      ring[k].push_back(mesh.add_vertex(Vec3(r * std::cos(phi), y, r * std::sin(phi))));
    }
  }
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const int j = (i + 1) % sides;
      set_face_label(mesh, mesh.add_face(ring[k][i], ring[k + 1][i], ring[k + 1][j], ring[k][j]), "branch");
    }
  std::vector<PolyMesh::VertexHandle> bottom(ring[0].begin(), ring[0].end()), top(ring[rings].rbegin(), ring[rings].rend());
  set_face_label(mesh, mesh.add_face(bottom), "branch");
  set_face_label(mesh, mesh.add_face(top), "branch");
  return mesh;
}

std::string lsystem(int levels) {
  std::string s = "A";
  for (int i = 0; i < levels; ++i) {
    std::string next;
    for (char c : s) next += c == 'A' ? std::string("F/[+A][-A]") : std::string(1, c);
    s = std::move(next);
  }
  return s;
}

// 3 x 3 rotations as Affines without translation: R * rot about the local axis.
Affine about(int axis, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  Affine r;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  r.m[i][i] = c;
  r.m[i][j] = -s;
  r.m[j][i] = s;
  r.m[j][j] = c;
  return r;
}

constexpr int kMaxTreeLevels = 10;

// The tree's parameters, checked (the bounds and the body both read them).
struct TreeShape {
  int levels, sides;
  double angle, length_ratio, radius_ratio, trunk_length, trunk_radius, jitter;
  // The gap before a child, in child radii (see the file comment).
  double clearance() const { return 1.3 / std::sin(angle * (1.0 - jitter)); }
};

TreeShape tree_shape(const Arguments& a) {
  const char* P = "tree";
  TreeShape t;
  t.levels = integer_in(a, P, "levels", 1, kMaxTreeLevels);
  t.angle = real_in(a, P, "angle", 5.0, 80.0) * std::numbers::pi / 180.0;
  t.length_ratio = real_in(a, P, "lengthRatio", 0.1, 0.8);
  t.radius_ratio = real_in(a, P, "radiusRatio", 0.1, 1.0);
  t.trunk_length = positive_real(a, P, "trunkLength");
  t.trunk_radius = positive_real(a, P, "trunkRadius");
  t.sides = integer_in(a, P, "sides", 3, 64);
  t.jitter = real_in(a, P, "jitter", 0.0, 0.5);
  if (!(t.trunk_radius <= 0.2 * t.trunk_length)) refuse_parameter(P, "trunkRadius", "must be at most 0.2 trunkLength");
  return t;
}

std::array<Vec3, 2> tree_bounds(const Arguments& a) {
  const TreeShape t = tree_shape(a);
  // Every point beyond the trunk is within `reach` of the trunk's tip: each later order adds at
  // most its gap and its length along the path, and a branch's surface is within its radius
  // (at most the trunk's: radiusRatio <= 1) of its axis.
  double reach = t.trunk_radius;
  for (int d = 1; d < kMaxTreeLevels; ++d)
    reach += t.clearance() * t.trunk_radius * std::pow(t.radius_ratio, d) + t.trunk_length * std::pow(t.length_ratio, d);
  const double r = std::max(reach, t.trunk_radius), tip = t.trunk_length;
  return {Vec3(-r, std::min(0.0, tip - r), -r), Vec3(r, tip + r, r)};
}

PolyMesh build_tree(const Arguments& a, const CallContext& context) {
  const TreeShape shape = tree_shape(a);
  // The turtle walks the string of at least the parameters' levels and draws the branches of
  // the first `drawn` orders: the random draws are the same as the full tree's, so a coarser
  // tree is the full tree without its finest orders (no branch moves between lods).
  const int drawn = std::clamp(shape.levels + context.lod(), 1, kMaxTreeLevels);
  const int levels = std::max(shape.levels, drawn);
  const double angle = shape.angle, length_ratio = shape.length_ratio, radius_ratio = shape.radius_ratio;
  const double trunk_length = shape.trunk_length, trunk_radius = shape.trunk_radius, jitter = shape.jitter;
  const int sides = shape.sides;

  struct Turtle {
    Affine frame;  // rotation + position: the branch frame (heading = local +y)
    int order = 0;
  };
  Rng rng(context.seed());
  const auto jittered = [&](double v) { return v * (1.0 + jitter * (2.0 * rng.next_double() - 1.0)); };
  const double clearance = shape.clearance();
  PolyMesh tree;
  Turtle t;
  std::vector<Turtle> stack;
  for (char c : lsystem(levels)) {
    switch (c) {
      case 'F': {
        const double len = trunk_length * std::pow(length_ratio, t.order);
        const double r = trunk_radius * std::pow(radius_ratio, t.order);
        if (t.order > 0) t.frame = t.frame * Affine::translation(Vec3(0, clearance * r, 0));
        if (t.order >= drawn) {  // below the level of detail: its children are too
          ++t.order;
          break;
        }
        // Seed 0 for every branch: a branch draws no random numbers, so trees of any seed share
        // the cached branches.
        CallOptions fixed;
        fixed.seed = 0;
        const std::shared_ptr<const PolyMesh> b =
            context.call_shared("branch", {{"length", len}, {"radius", r}, {"taper", radius_ratio}, {"sides", sides}}, fixed);
        append_mesh(tree, *b, t.frame);
        t.frame = t.frame * Affine::translation(Vec3(0, len, 0));
        ++t.order;
        break;
      }
      case '/': t.frame = t.frame * about(1, jittered(0.5 * std::numbers::pi)); break;
      case '+': t.frame = t.frame * about(2, jittered(angle)); break;
      case '-': t.frame = t.frame * about(2, -jittered(angle)); break;
      case '[': stack.push_back(t); break;
      case ']': t = stack.back(); stack.pop_back(); break;
      default: break;
    }
  }
  return tree;
}

}  // namespace

ProceduralModelDef branch_definition() {
  ProcedureSpec spec;
  spec.name = "branch";
  spec.mode = Mode::Out;
  spec.cacheable = true;
  spec.params = {param("length", 1.0), param("radius", 0.06), param("taper", 0.6), param("sides", 8), param("rings", 2)};
  spec.out_body = build_branch;
  ProceduralModel info{"branch",
                       "a tree branch, cacheable: a meshed cylinder (frustum) along +y from y = 0",
                       {{"length", "along +y"},
                        {"radius", "at the bottom"},
                        {"taper", "top radius / bottom radius, 0.05-1"},
                        {"sides", "vertices round, 3-256"},
                        {"rings", "segments along the axis, 1-256"}}};
  return {std::move(spec), std::move(info)};
}

ProceduralModelDef tree_definition() {
  ProcedureSpec spec;
  spec.name = "tree";
  spec.mode = Mode::Out;
  spec.cacheable = true;
  spec.params = {param("levels", 5),         param("angle", 30.0),       param("lengthRatio", 0.7),
                 param("radiusRatio", 0.6),  param("trunkLength", 1.0),  param("trunkRadius", 0.06),
                 param("sides", 8),          param("jitter", 0.15)};
  spec.uses_lod = true;
  spec.bounds = tree_bounds;
  spec.out_body = build_tree;
  ProceduralModel info{
      "tree",
      "an L-system tree (A -> F/[+A][-A]), cacheable, its 2^levels - 1 branches cached `branch` calls; the seed "
      "jitters the angles",
      {{"levels", "rewriting steps, 1-10 (the thesis shows 3-6); the lod adds to it (camera.hpp)"},
       {"angle", "branching (pitch) angle in degrees, 5-80"},
       {"lengthRatio", "a child's length / its parent's, 0.1-0.8"},
       {"radiusRatio", "a child's radius / its parent's (and each branch's taper), 0.1-1"},
       {"trunkLength", "the first branch's length"},
       {"trunkRadius", "the first branch's radius, at most 0.2 trunkLength"},
       {"sides", "vertices round each branch, 3-64"},
       {"jitter", "seeded random variation of every angle, a fraction 0-0.5 of it"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
