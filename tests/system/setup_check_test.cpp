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

// The checksum of one configuration, computed with the model.
uint32_t model_checksum(const setupcheck::Config& c) {
  const htx::model::RecipParams rp{c.recip_k, c.recip_g, c.recip_width, c.setup_steps};
  setupcheck::Lcg gen{2026};
  uint32_t crc = 0;
  for (uint32_t i = 0; i < setupcheck::kTriangles; ++i) {
    const htx::fw::TriangleRecord rec = setupcheck::make_record(c, gen);
    const htx::model::TriSetup s = htx::model::setup_coverage(rec, c.width, c.height);
    crc = setupcheck::fold(crc, static_cast<uint64_t>(s.det));
    if (s.det == 0) continue;
    crc = setupcheck::fold(crc, s.empty ? 1 : 0);
    crc = setupcheck::fold(crc, static_cast<uint64_t>(static_cast<int64_t>(s.x_lo)) ^ (static_cast<uint64_t>(s.x_hi) << 32));
    crc = setupcheck::fold(crc, static_cast<uint64_t>(static_cast<int64_t>(s.y_lo)) ^ (static_cast<uint64_t>(s.y_hi) << 32));
    for (const htx::model::Edge& e : s.edges) {
      crc = setupcheck::fold(crc, static_cast<uint64_t>(e.a));
      crc = setupcheck::fold(crc, static_cast<uint64_t>(e.b));
      crc = setupcheck::fold(crc, static_cast<uint64_t>(e.threshold));
    }
    if (s.empty) continue;
    const htx::model::Reciprocal inv = htx::model::reciprocal(rp, static_cast<u128>(s.det));
    crc = setupcheck::fold(crc, inv.value);
    crc = setupcheck::fold(crc, static_cast<uint64_t>(static_cast<int64_t>(inv.shift)));
    for (int a = 0; a < 8; ++a) {
      std::array<i128, 3> v{};
      for (int k = 0; k < 3; ++k) v[k] = setupcheck::attribute(s.rec.v[k], a);
      const htx::model::Plane p = htx::model::make_plane(s, v, {inv.value, inv.shift}, c.grad_frac_bits);
      for (const i128 w : {p.base, p.gx, p.gy}) {
        crc = setupcheck::fold(crc, static_cast<uint64_t>(static_cast<u128>(w)));
        crc = setupcheck::fold(crc, static_cast<uint64_t>(static_cast<u128>(w) >> 64));
      }
    }
    for (const htx::fw::VertexRecord& v : s.rec.v) {
      for (const int64_t n : {v.uq, v.vq}) {
        crc = setupcheck::fold(crc, static_cast<uint64_t>(htx::model::divide_fixed(rp, n, v.q, c.texcoord_frac_bits)));
      }
    }
  }
  return crc;
}

TEST(SystemSetupCheck, FirmwareSetupOnTheCpuMatchesTheModel) {
  // The shared configurations are the model's.
  for (const setupcheck::Config& c : setupcheck::kConfigs) {
    const htx::ModelConfig& m = htx::model_config(c.name);
    EXPECT_EQ(c.format.xy_int_bits, m.xy_int_bits) << c.name;
    EXPECT_EQ(c.format.z_bits, m.z_bits) << c.name;
    EXPECT_EQ(c.format.q_bits, m.q_bits) << c.name;
    EXPECT_EQ(c.format.uv_int_bits, m.uv_int_bits) << c.name;
    EXPECT_EQ(c.recip_k, m.recip_table_bits) << c.name;
    EXPECT_EQ(c.recip_g, m.recip_guard_bits) << c.name;
    EXPECT_EQ(c.recip_width, m.recip_width) << c.name;
    EXPECT_EQ(c.setup_steps, m.setup_nr_steps) << c.name;
    EXPECT_EQ(c.grad_frac_bits, m.grad_frac_bits) << c.name;
    EXPECT_EQ(c.texcoord_frac_bits, m.texcoord_frac_bits) << c.name;
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
