// The firmware's triangle setup on the simulated SoC's rv32im CPU (firmware/app/setupcheck) against
// the host model's setup (htx/model/raster_setup.hpp, recip.hpp) on the same triangles
// (setup_cases.hpp): one checksum per configuration over every coverage, reciprocal, plane and
// division result.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>

#include "htx/model/config.hpp"
#include "htx/model/raster_setup.hpp"
#include "htx/model/recip.hpp"
#include "setup_cases.hpp"
#include "subprocess.hpp"

namespace {

using namespace std::chrono_literals;
using htx::model::i128;
using htx::model::u128;

htx::fw::Int128 to_fw(i128 v) {
  const auto u = static_cast<u128>(v);
  return htx::fw::Int128{static_cast<uint64_t>(u), static_cast<uint64_t>(u >> 64)};
}

// setup_cases.hpp's checksum interface on the model's setup (coverage is the firmware's code in
// both; the reciprocal, the planes and the divisions are the model's own).
struct ModelSetup {
  const setupcheck::Config& c;
  htx::model::RecipParams recip;
  htx::fw::CoverageSetup coverage(const htx::fw::TriangleRecord& rec, int32_t width, int32_t height) const {
    return htx::model::setup_coverage(rec, width, height);
  }
  htx::fw::RecipResult reciprocal(int64_t det) const {
    const htx::model::Reciprocal r = htx::model::reciprocal(recip, static_cast<u128>(det));
    return {r.value, r.shift};
  }
  htx::fw::PlaneSetup plane(const htx::fw::CoverageSetup& s, int plane, htx::fw::RecipResult inv) const {
    std::array<i128, 3> v{};
    for (int k = 0; k < 3; ++k) v[k] = htx::fw::plane_value(s.rec.v[k], plane);
    const htx::model::Plane p = htx::model::make_plane(s, v, {inv.value, inv.shift}, c.params.grad_frac_bits);
    htx::fw::PlaneSetup f;
    f.base = to_fw(p.base);
    f.gx = to_fw(p.gx);
    f.gy = to_fw(p.gy);
    f.x0 = p.x0;
    f.y0 = p.y0;
    return f;
  }
  int64_t divide(int64_t num, uint32_t q) const {
    return htx::model::divide_fixed(recip, num, q, c.params.texcoord_frac_bits);
  }
};

// The checksum of one configuration, computed with the model.
uint32_t model_checksum(const setupcheck::Config& c) {
  ModelSetup setup{c, {c.params.recip.k, c.params.recip.g, c.params.recip.width, c.params.recip.steps}};
  uint32_t drawn = 0;
  return setupcheck::checksum(c, setup, &drawn);
}

TEST(SystemSetupCheck, FirmwareSetupOnTheCpuMatchesTheModel) {
  // The shared configurations are the model's.
  for (const setupcheck::Config& c : setupcheck::kConfigs) {
    const htx::ModelConfig& m = htx::model_config(c.name);
    const htx::fw::SetupParams& p = c.params;
    EXPECT_EQ(p.format.xy_int_bits, m.xy_int_bits) << c.name;
    EXPECT_EQ(p.format.z_bits, m.z_bits) << c.name;
    EXPECT_EQ(p.format.q_bits, m.q_bits) << c.name;
    EXPECT_EQ(p.format.uv_int_bits, m.uv_int_bits) << c.name;
    EXPECT_EQ(p.recip.k, m.recip_table_bits) << c.name;
    EXPECT_EQ(p.recip.g, m.recip_guard_bits) << c.name;
    EXPECT_EQ(p.recip.width, m.recip_width) << c.name;
    EXPECT_EQ(p.recip.steps, m.setup_nr_steps) << c.name;
    EXPECT_EQ(p.grad_frac_bits, m.grad_frac_bits) << c.name;
    EXPECT_EQ(p.texcoord_frac_bits, m.texcoord_frac_bits) << c.name;
    EXPECT_EQ(p.lod_grad_bits, m.lod_grad_bits) << c.name;
  }

  const auto r = htx::test::run_program(
      {HTX_BIN, "sim", "--elf", HTX_FIRMWARE_DIR "/setupcheck.elf", "--max-cycles", "200000000"}, 120s);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  std::map<std::string, unsigned> sums;
  std::istringstream in(r.out);
  std::string line;
  while (std::getline(in, line)) {
    char name[32];
    unsigned drawn = 0, sum = 0;
    if (std::sscanf(line.c_str(), "setupcheck %31s triangles %*u drawn %u checksum %x", name, &drawn,
                    &sum) == 3) {
      sums[name] = sum;
      EXPECT_GT(drawn, setupcheck::kTriangles / 4) << line;  // the set exercises drawn triangles
      std::printf("%s\n", line.c_str());
    }
  }
  for (const setupcheck::Config& c : setupcheck::kConfigs) {
    ASSERT_TRUE(sums.count(c.name)) << c.name << " missing in\n" << r.out;
    char want[16], got[16];
    std::snprintf(want, sizeof want, "%08x", model_checksum(c));
    std::snprintf(got, sizeof got, "%08x", sums.at(c.name));
    EXPECT_STREQ(got, want) << c.name;
  }
}

}  // namespace
