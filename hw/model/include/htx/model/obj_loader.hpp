// Scenes from Wavefront OBJ/MTL files with PNG textures (tinyobjloader, stb_image).
//
// - One mesh per (shape, material); faces are triangulated; front faces counter-clockwise.
// - A UTF-8 byte-order mark before the OBJ or an MTL is stripped. Only the materials faces use
//   have their map_Kd image read.
// - A material's map_Kd image becomes a texture (RGB565) with sides that are powers of two in
//   8..256: other sides are shrunk to the largest powers of two within them (area averaging), a
//   side above 256 halved as the mip levels are made, each with a line in Scene::notes.
//   OBJ's vt has v = 0 at the image bottom, so image rows are stored bottom-up (texel row 0 = v 0).
// - Colour: the material's Kd times the vertex colour (white when absent), modulating the texture.
// - The camera frames the bounding sphere from +z, slightly above, 60 degree vertical field of view.
#pragma once

#include <cstdint>
#include <string>

#include "htx/model/image_io.hpp"
#include "htx/model/scene.hpp"

namespace htx {

// The largest OBJ or MTL file read (a 64 MiB OBJ holds some 1.5 million vertices; reading it takes
// seconds and some hundreds of MiB): a larger one is refused before it is read.
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{64} << 20;

// Throws std::runtime_error naming the file on any load or validation failure, including what
// tinyobjloader passes silently or with a warning (docs/scenes.md): a v, vt or Kd number that is not
// a decimal finite as a float or a count the format does not allow, a missing material library, a
// usemtl naming no material of a library before it, a face of fewer than 3 corners, a v, vt or vn
// index out of range (relative ones too), texture coordinates at some corners of a face only, and
// any warning of tinyobjloader's that drops a face or a material; a file larger than
// kMaxSceneFileBytes, not a regular file, or holding a NUL byte (not text).
Scene load_obj_scene(const std::string& path);

// An image as a texture the way an OBJ's map_Kd is read (sides powers of two in 8..256, texel
// row 0 = the image's bottom row), encoded in `format` with its whole mip chain. Throws
// std::runtime_error naming `name` when its sides do not fit.
Texture texture_from_image(const Image& image, const std::string& name, TexFormat format = TexFormat::RGB565);

}  // namespace htx
