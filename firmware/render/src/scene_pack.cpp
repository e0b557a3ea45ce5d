#include "htx/render/scene_pack.h"

#include "htx/fw/console_packet.h"

namespace htx::render {

namespace {

constexpr uint8_t kMagic[4] = {'H', 'T', 'X', 'S'};
constexpr size_t kMatBytes = 68;
constexpr size_t kVertexBytes = 24;
constexpr int32_t kPositionLimit = 1 << 30;  // 2^14 in Q16.16

size_t indices_bytes(uint32_t triangles) { return (6u * triangles + 3u) & ~size_t{3}; }

void put_mat(uint8_t* p, const Mat4& m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) fw::put_le32(p + 4 * (4 * i + j), static_cast<uint32_t>(m.m[i][j]));
  fw::put_le32(p + 64, static_cast<uint32_t>(m.frac));
}

bool get_mat(const uint8_t* p, Mat4* m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m->m[i][j] = static_cast<int32_t>(fw::get_le32(p + 4 * (4 * i + j)));
  m->frac = static_cast<int32_t>(fw::get_le32(p + 64));
  return m->frac >= kMatMinFrac && m->frac <= kMatMaxFrac;
}

bool state_ok(const TriState& s) {
  const bool method = s.method <= kMethodDivFree || s.method == kMethodAuto;
  return method && s.subdiv_n >= 2 && s.subdiv_n <= 64 && s.filter <= 2 && s.wrap_u <= 2 && s.wrap_v <= 2 &&
         s.depth_func <= 5 && s.combine <= 1;
}

}  // namespace

size_t packed_scene_size(const Mesh* meshes, uint32_t mesh_count) {
  size_t n = kScenePackHeader;
  for (uint32_t m = 0; m < mesh_count; ++m)
    n += kScenePackMeshHeader + kVertexBytes * meshes[m].vertex_count + indices_bytes(meshes[m].triangle_count);
  return n;
}

size_t pack_scene(const Mat4& view_proj, bool cull_backfaces, const Mesh* meshes, uint32_t mesh_count, uint8_t* out,
                  size_t capacity) {
  const size_t size = packed_scene_size(meshes, mesh_count);
  if (size > capacity || mesh_count > 0xFFFF) return 0;
  for (size_t i = 0; i < size; ++i) out[i] = 0;
  for (int i = 0; i < 4; ++i) out[i] = kMagic[i];
  fw::put_le16(out + 4, kScenePackVersion);
  fw::put_le16(out + 6, mesh_count);
  out[8] = cull_backfaces ? 1 : 0;
  put_mat(out + 12, view_proj);
  uint8_t* p = out + kScenePackHeader;
  for (uint32_t m = 0; m < mesh_count; ++m) {
    const Mesh& mesh = meshes[m];
    if (mesh.vertex_count > 0xFFFF || mesh.triangle_count > 0xFFFF) return 0;
    fw::put_le16(p, mesh.vertex_count);
    fw::put_le16(p + 2, mesh.triangle_count);
    put_mat(p + 4, mesh.model);
    const TriState& s = mesh.state;
    const uint8_t state[13] = {s.method,   s.subdiv_n,     s.filter,          s.wrap_u,          s.wrap_v,
                               s.depth_func, s.depth_write, s.textured,       s.gouraud,         s.combine,
                               s.texture,  mesh.tex.log2_width, mesh.tex.log2_height};
    for (int i = 0; i < 13; ++i) p[72 + i] = state[i];
    p += kScenePackMeshHeader;
    for (uint32_t v = 0; v < mesh.vertex_count; ++v, p += kVertexBytes) {
      const MeshVertex& mv = mesh.vertices[v];
      const uint32_t f[6] = {static_cast<uint32_t>(mv.x), static_cast<uint32_t>(mv.y), static_cast<uint32_t>(mv.z),
                             static_cast<uint32_t>(mv.s), static_cast<uint32_t>(mv.t), mv.rgba};
      for (int i = 0; i < 6; ++i) fw::put_le32(p + 4 * i, f[i]);
    }
    for (uint32_t i = 0; i < 3 * mesh.triangle_count; ++i) fw::put_le16(p + 2 * i, mesh.indices[i]);
    p += indices_bytes(mesh.triangle_count);
  }
  return size;
}

const char* unpack_scene(const uint8_t* bytes, size_t size, Mesh* meshes, uint32_t max_meshes, uint32_t max_vertices,
                         UnpackedScene* out) {
  if (size < kScenePackHeader) return "shorter than its header";
  for (int i = 0; i < 4; ++i)
    if (bytes[i] != kMagic[i]) return "not a packed scene (no HTXS)";
  if (fw::get_le16(bytes + 4) != kScenePackVersion) return "unknown version";
  const uint32_t mesh_count = fw::get_le16(bytes + 6);
  if (mesh_count == 0) return "no meshes";
  if (mesh_count > max_meshes) return "more meshes than the console holds";
  if (bytes[8] > 1) return "bad cull flag";
  UnpackedScene scene;
  if (!get_mat(bytes + 12, &scene.view_proj)) return "camera matrix fraction out of range";
  scene.cull_backfaces = bytes[8] != 0;
  size_t at = kScenePackHeader;
  for (uint32_t m = 0; m < mesh_count; ++m) {
    if (size - at < kScenePackMeshHeader) return "truncated mesh header";
    const uint8_t* h = bytes + at;
    Mesh mesh{};
    mesh.vertex_count = fw::get_le16(h);
    mesh.triangle_count = fw::get_le16(h + 2);
    if (mesh.vertex_count == 0 || mesh.triangle_count == 0) return "empty mesh";
    if (mesh.vertex_count > max_vertices) return "a mesh has more vertices than the console's vertex cache";
    if (!get_mat(h + 4, &mesh.model)) return "model matrix fraction out of range";
    const uint8_t* s = h + 72;
    mesh.state.method = s[0];
    mesh.state.subdiv_n = s[1];
    mesh.state.filter = s[2];
    mesh.state.wrap_u = s[3];
    mesh.state.wrap_v = s[4];
    mesh.state.depth_func = s[5];
    if (s[6] > 1 || s[7] > 1 || s[8] > 1) return "bad state flag";
    mesh.state.depth_write = s[6] != 0;
    mesh.state.textured = s[7] != 0;
    mesh.state.gouraud = s[8] != 0;
    mesh.state.combine = s[9];
    mesh.state.texture = s[10];
    mesh.tex = {s[11], s[12]};
    if (!state_ok(mesh.state)) return "state field out of range";
    if (mesh.tex.log2_width > 8 || mesh.tex.log2_height > 8) return "texture size out of range";
    at += kScenePackMeshHeader;
    const size_t vbytes = kVertexBytes * mesh.vertex_count, ibytes = indices_bytes(mesh.triangle_count);
    if (size - at < vbytes + ibytes) return "truncated vertices or indices";
    // In place: the MeshVertex layout is the packed one on a little-endian CPU.
    mesh.vertices = reinterpret_cast<const MeshVertex*>(bytes + at);
    for (uint32_t v = 0; v < mesh.vertex_count; ++v)
      for (int c = 0; c < 3; ++c) {
        const int32_t q = static_cast<int32_t>(fw::get_le32(bytes + at + kVertexBytes * v + 4 * c));
        if (q >= kPositionLimit || q <= -kPositionLimit) return "a position is 2^14 or more";
      }
    at += vbytes;
    mesh.indices = reinterpret_cast<const uint16_t*>(bytes + at);
    for (uint32_t i = 0; i < 3 * mesh.triangle_count; ++i)
      if (fw::get_le16(bytes + at + 2 * i) >= mesh.vertex_count) return "an index is past its mesh's vertices";
    at += ibytes;
    mesh.position_bits = static_cast<int8_t>(mesh_position_bits(mesh.vertices, mesh.vertex_count));
    meshes[m] = mesh;
    scene.triangle_count += mesh.triangle_count;
  }
  if (at != size) return "bytes left over after the last mesh";
  scene.mesh_count = mesh_count;
  *out = scene;
  return nullptr;
}

}  // namespace htx::render
