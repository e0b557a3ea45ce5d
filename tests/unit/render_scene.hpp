// Test support: the triangles the firmware render pipeline streams for a host Scene converted by
// host_tools/scene_convert, captured and decoded. Shared by the unit tests
// of firmware/render and the cosim tests.
#pragma once

#include <cstdint>
#include <vector>

#include "htx/fw/vertex_record.h"
#include "htx/host/captured_triangles.hpp"
#include "htx/host/render_scene.hpp"
#include "htx/model/scene.hpp"
#include "htx/render/pipeline.h"

namespace htx::test {

// The conversion and the capture live in host_tools/scene_convert; the tests keep their names for them.
using host::capture_sink;
using host::CapturedTriangle;
using host::from_state_word;
using host::RenderScene;
using host::to_mat4_fx;
using host::to_q16;
using host::to_render_scene;
using host::to_render_state;

// Runs the firmware pipeline over every mesh into a capturing sink.
std::vector<CapturedTriangle> draw_scene(const RenderScene& scene, const fw::RecordFormat& format,
                                         uint32_t methods_built, render::DrawStats* stats = nullptr);

// Splits a FIFO word stream (state word + kTriangleWords per triangle) into triangles; throws on a
// stream whose length is not a whole number of triangles.
std::vector<CapturedTriangle> split_fifo_stream(const std::vector<uint32_t>& words);

}  // namespace htx::test
