#include "scene_upload.hpp"

#include <stdio.h>

#include "packet_receive.hpp"
#include "scene_store.hpp"

namespace console_app {

void receive_scene(uint32_t size, uint32_t crc32) {
  if (!receive_packets(size, crc32, kStoreBytes, "scene")) return;
  const char* why = commit_staged(size);
  if (why) {
    printf("error: not a valid scene (%s); the scene is unchanged\r\n", why);
    return;
  }
  const render_app::SceneData* s = uploaded_scene();
  uint32_t triangles = 0;
  for (uint32_t m = 0; m < s->mesh_count; ++m) triangles += s->meshes[m].triangle_count;
  printf("upload ok: %lu bytes, %lu meshes, %lu triangles; `render upload` draws it\r\n",
         static_cast<unsigned long>(size), static_cast<unsigned long>(s->mesh_count),
         static_cast<unsigned long>(triangles));
}

}  // namespace console_app
