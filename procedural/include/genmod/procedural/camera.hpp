// The camera of Morkel's level of detail and lazy evaluation (research/morkel.md section 1.8):
// a procedure that declares a bounding box is not evaluated when its box, placed by the call's
// transform, misses the view frustum, and otherwise gets a level of detail from the number of
// pixels the box covers ("The further away the object, the fewer the number of refinement
// steps are required").
//
// The level of detail is a refinement offset relative to the procedure's own parameters:
// lod 0 builds the model as its parameters say (the default, and what every call without a
// camera gets), each step below 0 drops one refinement step (a tree level, a subdivision
// level), each step above adds one. That keeps every existing call's mesh unchanged, and a
// camera can only make distant objects coarser unless max_lod is raised.
//
// The formula (view_of_box):
//   pixels = the area, in pixels, of the screen rectangle bounding the projected box corners,
//            clipped to the image (the whole image when the box reaches behind the near plane)
//   lod    = clamp(floor(log2(max(pixels, 1)) / 2) + lod_bias, min_lod, max_lod)
// log2(pixels) / 2 is log2 of the box's side on screen, so one level per doubling of its size.
// With the defaults (bias -8, range [-8, 0]) a box of 256 x 256 pixels or more gets lod 0, one
// of 128 x 128 gets -1, one of 16 x 16 gets -4, and a box of a pixel or less gets -8.
//
// The frustum test is conservative: a box is culled when all eight of its transformed corners
// are outside one of the five planes (near, left, right, bottom, top; there is no far plane),
// so a box is never culled while part of it is in view, but a box just beyond a frustum edge
// may be kept.
//
// Example:
//   using namespace genmod;
//   Camera camera;
//   camera.position = Vec3(0, 0, 10);  // looking down -z at the origin, 640 x 480 pixels
//   const std::array<Vec3, 2> box{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
//   const BoxView near = view_of_box(camera, box);                                        // lod -2
//   const BoxView far = view_of_box(camera, box, Affine::translation(Vec3(0, 0, -90)));   // lod -5
//   const BoxView behind = view_of_box(camera, box, Affine::translation(Vec3(0, 0, 20)));
//   if (!near.visible || !far.visible || behind.visible || !(far.lod < near.lod)) throw std::runtime_error("lod");
#pragma once

#include "genmod/procedural/affine.hpp"
#include "genmod/procedural/poly_mesh.hpp"

#include <array>

namespace genmod {

struct Camera {
  Vec3 position{0, 0, 0};
  Vec3 direction{0, 0, -1};  // the view direction (need not be unit)
  Vec3 up{0, 1, 0};          // any vector not parallel to direction
  double fov_y = 0.8;        // the vertical field of view in radians, in (0, pi)
  int image_width = 640, image_height = 480;  // pixels, both > 0
  double near = 1e-3;        // the near plane's distance along direction, > 0
  int lod_bias = -8, min_lod = -8, max_lod = 0;  // the formula above; min_lod <= max_lod
};

// Throws std::invalid_argument naming the first bad field ("camera field 'fov_y' ..."): a
// non-finite position, direction, up, fov_y or near; a zero direction; an up parallel to the
// direction; fov_y outside (0, pi); an image width or height <= 0; near <= 0; min_lod > max_lod.
void check_camera(const Camera& camera);

struct BoxView {
  bool visible = false;  // false: the box misses the frustum (lazy evaluation skips the call)
  double pixels = 0;     // the covered area (0 when not visible)
  int lod = 0;           // the formula's level (meaningless when not visible)
};

// How `camera` sees the box [box[0], box[1]] (a procedure's local frame) mapped by `xf`. The
// camera must be valid (check_camera).
BoxView view_of_box(const Camera& camera, const std::array<Vec3, 2>& box, const Affine& xf = {});

}  // namespace genmod
