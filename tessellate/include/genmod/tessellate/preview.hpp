// preview: a picture of any triangle mesh, by a small software rasterizer.
//
// The view is orthographic, looking at the mesh from the direction `view` (from the centre of
// the bounding box toward the eye; default (1, -1.5, 1.2): from the front right, above), with
// +z up in the picture (+y when looking along z). The picture is framed on the projected
// bounding rectangle of the vertices, centred, `margin` of the size left free on each side, with
// equal scale on both axes.
//
// Shading: Lambert by the face normal, with a light a little above and to the left of the eye,
// plus ambient. Each pixel shows the nearest triangle (z-buffer; pixel centres sampled, ties
// on shared edges given to exactly one triangle). A triangle seen from its back (the normal
// pointing away from the eye) is drawn in a much darker range, so an inside-out mesh, a hole
// looking into the inside, or a misoriented patch stands out:
//   background 255, front faces 60..230, back faces 20..80.
//
// Example:
//   Mesh mesh = mesh_implicit(implicit_sphere(1.0), {Interval(-2, 2), Interval(-2, 2), Interval(-2, 2)},
//                             {.min_feature = 0.25}).mesh;
//   Image img = preview(mesh);           // write_png("mesh.png", img) saves it
#pragma once

#include "genmod/tessellate/image.hpp"
#include "genmod/tessellate/triangle_mesh.hpp"

#include <array>

namespace genmod {

struct PreviewOptions {
  int width = 512;   // pixels, 1..8192
  int height = 512;  // pixels, 1..8192
  std::array<double, 3> view{1.0, -1.5, 1.2};  // toward the eye; any non-zero finite vector
  double margin = 0.05;                         // fraction of the size on each side, [0, 0.45]
};

// The picture of the mesh. Throws std::invalid_argument for a mesh without triangles (there
// is nothing to frame), an index out of range, a coordinate that is not finite, or options
// out of their ranges.
Image preview(const Mesh& mesh, const PreviewOptions& options = {});

}  // namespace genmod
