// Mesh files: OBJ, PLY, STL and OFF, written and read by genmod itself.
//
// Exact: every coordinate is written so that reading it back gives bitwise the same double
// (the shortest decimal that round-trips, std::to_chars; PLY stores the doubles themselves),
// so a mesh that is intersection-free in doubles stays so in the file. Checked: every write,
// the flush and the close are checked, so a full disk or /dev/full is an error, never a
// silently truncated file reported as success.
//
//   format  written as                                       read
//   .obj    `v x y z` and `f a b c` (1-based)                v and f (i, i/t, i/t/n, i//n,
//                                                            negative = relative); polygons are
//                                                            fanned; vt, vn, g, o, s, usemtl, ...
//                                                            are ignored
//   .ply    binary_little_endian 1.0, vertex x y z as        ascii, binary_little_endian and
//           double, face list uchar uint vertex_indices      binary_big_endian; any scalar types;
//                                                            other properties and elements skipped
//   .stl    ASCII STL with round-trip doubles (binary STL    ASCII and binary STL; vertices at
//           is float32 by the format, which would move       bitwise-equal positions are merged,
//           vertices and can create self-intersections)     numbered by first appearance
//   .off    `OFF`, counts, vertices, `3 a b c` faces         OFF; polygons are fanned
//
// The format follows the extension (case-insensitive). Vertices are never duplicated per face:
// a closed mesh reads back closed. STL keeps no vertex list, so reading an STL gives the
// vertices used by the triangles in the order they first appear (a mesh whose vertices are
// already in that order and all used reads back identical).
//
// Errors: std::invalid_argument for an unknown extension and for a mesh that cannot be written
// (an index out of range, a coordinate that is not finite); MeshFileError, naming the path,
// for a file that cannot be created, written or read, and for malformed contents (naming the
// line, or the element for binary files, and the problem).
#pragma once

#include "genmod/tessellate/triangle_mesh.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>

namespace genmod {

// A mesh file could not be written or read, or its contents are malformed.
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class MeshFormat { Obj, Ply, Stl, Off };

// The format of a path's extension, or nothing for an extension that is not a mesh format.
std::optional<MeshFormat> mesh_format(const std::filesystem::path& path);

// Writes the mesh in the format of the extension. On a write error the partial file is removed
// (when it is a regular file).
void write_mesh(const Mesh& mesh, const std::filesystem::path& path);

// Reads a mesh in the format of the extension (exact doubles back; polygons fanned into
// triangles from their first corner).
Mesh read_mesh(const std::filesystem::path& path);

}  // namespace genmod
