// Which of the compiled-in scenes an image of the render firmware draws: `render` draws all of them,
// `render_cube` only the cube (the system test's scene: a shorter simulation). One definition per
// image, linked in from select_all.cpp or select_cube.cpp.
#pragma once

namespace render_app {

bool draw_scene_named(const char* name);

}  // namespace render_app
