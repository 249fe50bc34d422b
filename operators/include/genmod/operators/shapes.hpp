// Standard shapes, as plain kernel Fns (scalarized compositions: the kernel supplies point,
// inclusion and derivative methods).
//
// Parametric surfaces are functions of (u, v) = (x(0), x(1)) over [0, 1]^2 with values in R^3.
// Their normal S_u x S_v points OUTWARD (away from the solid) wherever it is nonzero; the
// poles / apex / center where it vanishes are noted per shape. The size arguments may be
// functions (a radius that varies with a third coordinate, say).
//
// Implicit shapes are scalar functions of the point p = (x(0), x(1), x(2)), negative inside,
// positive outside, zero on the surface. Sphere, box, capped cylinder and torus are exact
// signed distances. CSG uses min / max (union = min, intersection = max, difference =
// max(a, -b)); smooth_union is the polynomial smooth minimum. Transforms of an implicit shape
// compose it with the inverse transform: translate_implicit(f, t)(p) = f(p - t). Only rigid
// transforms keep the value a distance.
//
// Example:
//   Fn ball = implicit_sphere(1.0);
//   Fn part = csg_difference(implicit_box(cat({1.0, 1.0, 1.0})), translate_implicit(ball, cat({1.0, 1.0, 1.0})));
#pragma once

#include "genmod/kernel/fn.hpp"
#include "genmod/operators/matrix.hpp"

namespace genmod {

// ---- parametric surfaces over [0,1]^2 --------------------------------------------------

// theta = 2 pi u, phi = pi (v - 1/2):
// S = r (cos theta cos phi, sin theta cos phi, sin phi). Normal = 2 pi^2 r cos phi * S,
// zero at the poles v = 0, 1.
Fn sphere_surface(const Fn& radius = 1.0);
// theta = 2 pi u around z, phi = 2 pi v around the tube:
// S = ((R + r cos phi) cos theta, (R + r cos phi) sin theta, r sin phi); the normal points
// away from the tube's center circle.
Fn torus_surface(const Fn& major_radius, const Fn& minor_radius);
// Open cylinder about the z axis: S = (r cos 2 pi u, r sin 2 pi u, h v), z in [0, h].
Fn cylinder_surface(const Fn& radius, const Fn& height);
// Open cone, base circle of radius r at z = 0, apex (0, 0, h) at v = 1:
// S = (r (1 - v) cos 2 pi u, r (1 - v) sin 2 pi u, h v). Normal zero at the apex.
Fn cone_surface(const Fn& radius, const Fn& height);
// Disk in the plane z = 0: S = (r u cos 2 pi v, r u sin 2 pi v, 0); normal +z (zero at u = 0).
Fn disk_surface(const Fn& radius);
// Barr's superquadric (superellipsoid) with the sphere's parameterization and signed powers
// spow(c, e) = sign(c) |c|^e: S = (a1 spow(cos phi, e1) spow(cos theta, e2),
// a2 spow(cos phi, e1) spow(sin theta, e2), a3 spow(sin phi, e1)). It satisfies
// (|x/a1|^(2/e2) + |y/a2|^(2/e2))^(e2/e1) + |z/a3|^(2/e1) = 1; e1 = e2 = 1 is the ellipsoid.
// For exponents < 1 the derivative is infinite where a cosine or sine vanishes.
// `radii` has dimension 3 (or 1: the same for all axes).
Fn superquadric_surface(const Fn& e1, const Fn& e2, const Fn& radii = 1.0);

// ---- implicit shapes of p = (x(0), x(1), x(2)), f < 0 inside ---------------------------

// p = (x(0), x(1), x(2)).
Fn point3();
// |p - center| - r; center of dimension 3 (or the scalar 0: the origin).
Fn implicit_sphere(const Fn& radius, const Fn& center = 0.0);
// Axis-aligned box centered at the origin with half extents b (dimension 3): the exact
// distance |max(q, 0)| + min(max(q1, q2, q3), 0), q = |p| - b.
Fn implicit_box(const Fn& half_extents);
// Cylinder about the z axis with |z| <= half_height (exact distance, capped).
Fn implicit_cylinder(const Fn& radius, const Fn& half_height);
// Torus about the z axis: |(|p_xy| - R, z)| - r.
Fn implicit_torus(const Fn& major_radius, const Fn& minor_radius);
// Gyroid g = sin(kx) cos(ky) + sin(ky) cos(kz) + sin(kz) cos(kx) with k = frequency. With
// thickness 0 the solid is g < 0; with thickness > 0 it is the sheet |g| - thickness < 0.
Fn implicit_gyroid(const Fn& frequency = 1.0, const Fn& thickness = 0.0);

// CSG on scalar implicit functions.
Fn csg_union(const Fn& a, const Fn& b);         // min(a, b)
Fn csg_intersection(const Fn& a, const Fn& b);  // max(a, b)
Fn csg_difference(const Fn& a, const Fn& b);    // max(a, -b): a minus b
// Polynomial smooth minimum with blend radius k > 0:
// h = clamp(1/2 + (b - a) / (2k), 0, 1), result = b + (a - b) h - k h (1 - h).
// Equals min(a, b) where |a - b| >= k, and is at most min(a, b) everywhere (by k/4 at most).
Fn smooth_union(const Fn& a, const Fn& b, const Fn& k);

// Transforms of a scalar implicit shape f(x(0), x(1), x(2)) by composition with the inverse.
// The affine 4x4 matrices of transform.hpp apply: transform_implicit(f, rotate_z(a)) rotates
// the shape by a about z.
Fn transform_implicit(const Fn& f, const Matrix& m);
Fn translate_implicit(const Fn& f, const Fn& offset);  // offset of dimension 3
// Scales by s (scalar: uniform, or dimension 3): f(p / s). Not a distance unless |s| = 1.
Fn scale_implicit(const Fn& f, const Fn& s);

}  // namespace genmod
