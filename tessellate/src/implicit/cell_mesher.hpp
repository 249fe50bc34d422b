// Meshing one surface cell of the octree (the algorithm is described in tessellate/README.md).
//
// Each face of the cell is cut into the pieces of its smaller neighbours. A piece's boundary
// points are its corners and the corners of smaller cells on its sides. The surface's trace
// on a piece:
//  * "direct" when the boundary has exactly two sign changes: one segment between the two
//    roots, bent at a feature point where the tangent lines there meet inside the piece;
//  * "fan" otherwise (four or more sign changes, or an island only the piece's center sees,
//    or forced, see below): the piece is triangulated from its center and marching triangles
//    gives one segment per triangle with a sign change (bent at a feature point inside it).
// The trace of a piece depends only on the piece, so the two cells on it agree bit for bit.
// The traces on the cell's faces form closed loops.
//
// A cell with one loop gets the cone from one interior vertex (the quadric point, moved onto
// the surface): any point strictly inside a convex cell sees a loop on the cell's boundary
// without overlap, so the cone is an embedded disk, and cones of different cells meet only in
// the traces they share. A cell with several loops asks to be split; where it cannot be, it is
// cut into tetrahedra (cell center x the fan triangles of its pieces) and meshed by marching
// tetrahedra, whose pieces also meet the cell's boundary exactly in the trace. That needs every
// piece of the cell in fan mode: the cell reports its direct pieces, the mesher forces them to
// fan mode and meshes the cell and its neighbours again.
#pragma once

#include "genmod/kernel/batch_evaluator.hpp"
#include "implicit/octree.hpp"

#include <compare>
#include <cstdint>
#include <span>
#include <vector>

namespace genmod::implicit {

enum class VertexKind : std::uint8_t { EdgePoint, FacePoint, Apex, TetApex };

// Identifies an output vertex across cells: equal keys are the same vertex.
//   EdgePoint: root on the segment from lattice point a (inside) to b (outside).
//   FacePoint: feature point of the fan triangle (a = piece center, b < c its other corners),
//              or of the direct piece with center a (b = kNoKey, c = its axis).
//   Apex: vertex of the cell with low corner a.
//   TetApex: interior vertex of the tetrahedron on fan triangle (a, b, c) of its cell.
struct VertexKey {
  VertexKind kind;
  Key a, b, c;
  auto operator<=>(const VertexKey&) const = default;
};
inline constexpr Key kNoKey = ~Key{0};

// A face piece, by its center, the axis its plane is perpendicular to, and its half side.
struct PieceId {
  Key center;
  std::uint8_t axis;
  std::uint32_t half;
  auto operator<=>(const PieceId&) const = default;
};

struct OutVertex {
  VertexKey key;
  Vec3 position;
  double error;  // certified distance bound to the surface, or < 0 when not certified
};

struct CellOutput {
  std::vector<OutVertex> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // local vertex indices, outward
  bool wants_split = false;  // several loops, or faces / vertex beyond the tolerance
  bool multi_loop = false;   // several loops (meshed by the tetrahedral fallback when all fan)
  bool inaccurate = false;   // face estimate or vertex beyond the tolerance
  bool folded = false;       // a triangle faces against the surface's normal
  std::vector<PieceId> direct_pieces;  // multi_loop: pieces to force to fan mode
};

struct MeshContext {
  const Octree* octree;
  const Frame* frame;
  double tolerance;       // vertex and face distance target
  double root_tolerance;  // bracket width of roots on edges
  bool sharp_features;
  double feature_cos;     // cos(feature_angle)
  const std::vector<PieceId>* fan_pieces;  // sorted: pieces forced to fan mode
};

// One per thread: scratch memory and evaluators.
class CellMesher {
 public:
  explicit CellMesher(const MeshContext& context) : ctx_(context) {}
  void mesh(const Cell& cell, CellOutput& out);

 private:
  // A box in space for finite differences and feature points (flat along the plane axis).
  struct Region {
    Vec3 lo, hi;
  };
  struct Piece {
    int axis;
    Key center;
    double center_g;
    std::uint32_t half;  // half its side in lattice units
    Region region;
    std::uint32_t first, count;  // boundary points in boundary_, counter-clockwise from outside
    bool fan;
  };
  // A convex polygon on which the trace is one segment (or none): a fan triangle, a direct
  // piece, or an inner face of a fallback tetrahedron.
  struct Polygon {
    std::uint32_t first, count;  // vertex keys in polygon_keys_, counter-clockwise from outside
    int axis;                    // plane axis (outer polygons)
    bool outer;                  // on the cell boundary: may get a feature point
    VertexKey feature_key;       // the key of its feature point
    Region region;               // where finite differences and feature probes may go
  };
  struct Segment {
    std::uint32_t from, to;  // local vertex indices
    std::uint32_t polygon;
  };
  struct Root {
    Key in, out;
    double g_in, g_out;  // the samples at its ends
    bool operator<(const Root& o) const { return in != o.in ? in < o.in : out < o.out; }
    bool operator==(const Root& o) const { return in == o.in && out == o.out; }
  };

  void gather_pieces(const Cell& cell);
  // Octree::points_on_segment into line_points_, once per side of the cell's pieces.
  void side_points(const Cell& cell, const Octree::Neighborhood& nb, int axis, const std::array<std::uint32_t, 3>& on,
                   std::uint32_t t0, std::uint32_t t1);
  struct Side {
    int axis;
    std::uint32_t a, b, t0, t1;  // the line's two fixed coordinates and the segment
    std::uint32_t first, count;  // its points in side_store_
  };
  std::vector<Side> sides_;
  std::vector<std::uint32_t> side_store_;
  void choose_modes(CellOutput& out);
  void add_fan_triangles(const Piece& p, std::vector<Polygon>& polygons, std::vector<Key>& keys,
                         std::vector<double>& values) const;
  double sample(Key k) const;
  // g = max(f, clip) and f at points, with the cell's tape.
  void evaluate(std::span<const Vec3> points, std::vector<double>& g, std::vector<double>* f = nullptr);
  // Unit normals of g at points (whose f values are given) and |grad g|: the symbolic
  // gradient where it is finite and nonzero, else central differences of g with the steps
  // kept inside regions[i] (or regions[0] for all). `symbolic` tells which were symbolic.
  void normals(std::span<const Vec3> points, std::span<const double> f, std::span<const Region> regions,
               std::vector<Vec3>& normals, std::vector<double>* lengths = nullptr,
               std::vector<char>* symbolic = nullptr);
  // Roots on segments a (g < 0) -> b (g >= 0 or error): parameters in (0, 1) and bracket
  // half-widths in space.
  void find_roots(std::span<const Vec3> a, std::span<const Vec3> b, std::span<const double> ga,
                  std::span<const double> gb, std::vector<double>& t, std::vector<double>& error);
  // Marching polygons: roots, feature points and segments of `polygons` (corner keys in
  // `keys`, their samples in `values`).
  void trace(const std::vector<Polygon>& polygons, const std::vector<Key>& keys, const std::vector<double>& values,
             CellOutput& out, std::vector<Segment>& segments);
  std::uint32_t vertex(CellOutput& out, const VertexKey& key, const Vec3& p, double error);
  // The cell less a small margin: where moved vertices may go.
  struct ShrunkCell {
    double lo[3], hi[3];
    Vec3 clamp(const Vec3& p) const;
    // How far from x (inside) along d the boundary is (infinity for d = 0).
    double reach(const Vec3& x, const Vec3& d) const;
  };
  ShrunkCell shrunk_cell() const;
  // Moves `start` onto the surface along the gradient; false when no root is within reach.
  bool snap(const Vec3& start, Vec3& apex, double& error);
  // The same inside the tetrahedron t (start strictly inside, the result too).
  bool snap_in_tetrahedron(const Vec3& start, const Vec3 (&t)[4], Vec3& apex, double& error);
  // The root nearest to `start` on the line through it along `direction` within the cell.
  bool line_root(const Vec3& start, const Vec3& direction, Vec3& apex, double& error);
  // Keeps `start` (clamped into the cell) when g changes sign within the tolerance along the
  // mean of `normals`; false otherwise.
  bool certify(const Vec3& start, std::span<const Vec3> normals, Vec3& apex, double& error);
  // The root nearest to `start` (clamped into the cell) on rays along the normals, their mean
  // and the 26 lattice directions, bracketed; false when no ray in the cell changes sign.
  bool nearest_root(const Vec3& start, std::span<const Vec3> normals, Vec3& apex, double& error);
  // The root nearest to `start` (strictly inside t) on the segments to t's corners; the
  // result stays strictly inside.
  bool root_in_tetrahedron(const Vec3& start, const Vec3 (&t)[4], Vec3& apex, double& error);
  // samples[0] is the rays' common start and samples[1 + r * per_ray + i] sample i + 1 on
  // ray r: of the first sign change on each ray, the bracketed root nearest to the start;
  // false when no ray changes sign (or g fails at the start).
  bool root_on_rays(std::span<const Vec3> samples, std::size_t rays, int per_ray, Vec3& apex, double& error);
  void cone(const Cell& cell, const std::vector<std::uint32_t>& loop, CellOutput& out);
  void tetrahedra(const Cell& cell, CellOutput& out);
  struct Accuracy {
    bool inaccurate = false, folded = false;
  };
  Accuracy accuracy(const CellOutput& out, std::span<const std::array<std::uint32_t, 3>> triangles);
  // Triangles of the loop without an interior vertex; false when that is not provably valid.
  bool triangulate_loop(const CellOutput& out, const std::vector<std::uint32_t>& loop,
                        std::vector<std::array<std::uint32_t, 3>>& triangles);
  Region cell_region() const;

  const MeshContext& ctx_;
  BatchEvaluator batch_;
  const CellTapes* tapes_ = nullptr;
  double cell_lo_[3] = {0, 0, 0}, cell_hi_[3] = {0, 0, 0}, cell_size_ = 0;

  std::vector<std::array<std::uint32_t, 4>> rects_;
  std::vector<std::uint32_t> line_points_;
  std::vector<Piece> pieces_;
  std::vector<Key> boundary_;
  std::vector<double> boundary_g_;  // samples at boundary_
  std::vector<Polygon> polygons_;
  std::vector<Key> polygon_keys_;
  std::vector<double> polygon_g_;  // samples at polygon_keys_
  std::vector<Key> sample_keys_;
  std::vector<double> sample_g_;
  std::vector<std::array<std::uint32_t, 3>> loop_triangles_;
  std::vector<Vec3> normal_;  // unit normal at each output vertex of the cell (0 if none)
  std::vector<double> grad_length_;  // |grad g| there (0 if unknown)
  std::vector<Vec3> probe_points_;
  // Evaluation scratch.
  std::vector<double> xs_, ys_, zs_, fs_, gx_, gy_, gz_;
  struct RootScratch {
    std::vector<double> lo, hi, flo, fhi, length, last_width, trial_t, trial_g;
    std::vector<int> side;
    std::vector<std::uint32_t> active, still;
    std::vector<Vec3> trial_points;
  } roots_;
  std::vector<Vec3> fd_points_;
  std::vector<double> fd_g_;
};

}  // namespace genmod::implicit
