// Constructors of the built-in scenes, one per file; scene_registry.cpp lists and dispatches them.
#pragma once

#include "../mesh_builder.hpp"
#include "../scene_params.hpp"
#include "htx/model/proc_textures.hpp"
#include "htx/model/scene.hpp"

namespace htx::scenes {

Scene make_floor(SceneParams& p);
Scene make_cube(SceneParams& p);
Scene make_tunnel(SceneParams& p);
Scene make_wsweep(SceneParams& p);
Scene make_nearclip(SceneParams& p);
Scene make_slivers(SceneParams& p);
Scene make_bigtri(SceneParams& p);
Scene make_wrap(SceneParams& p);
Scene make_pan(SceneParams& p);
Scene make_randmesh(SceneParams& p);

inline constexpr double kPi = 3.14159265358979323846;
inline double radians(double degrees) { return degrees * kPi / 180.0; }

inline constexpr Rgba8 kWhite{255, 255, 255, 255};
inline constexpr Rgba8 kInk{40, 60, 140, 255};
inline constexpr Rgba8 kRed{220, 40, 30, 255};
inline constexpr Rgba8 kYellow{250, 210, 60, 255};

// The default texture: 64x64 RGB565 checkerboard of 8x8-texel cells.
inline Texture default_checker() { return checkerboard_texture(TexFormat::RGB565, 6, 3, kWhite, kInk); }

}  // namespace htx::scenes
