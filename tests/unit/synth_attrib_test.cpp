// htx-synth-attrib's attribution on a hand-made flattened netlist: flip-flops count where their
// register is, LUTs and carries where the first named signal after them is made, an input port's
// alias and a pass-through output never take a signal from its source, and a mapped name that
// steps forward through a cell names nothing.
#include <gtest/gtest.h>

#include <string>

#include "attrib.hpp"

namespace htx::synth {
namespace {

Json cell(const std::string& type, const Json& connections) {
  Json dirs = Json::object();
  for (const auto& [port, bits] : connections.items()) {
    dirs[port] = (port == "O" || port == "Q" || port == "CO") ? "output" : "input";
  }
  return Json{{"type", type}, {"port_directions", dirs}, {"connections", connections}};
}

Json net(const Json& bits, bool hidden = false) { return Json{{"bits", bits}, {"hide_name", hidden ? 1 : 0}}; }

Json netlist() {
  Json m;
  // u_a.x_q (bit 2) is a register; u_b.y (bit 4) is made by two LUTs, the first of which drives
  // an unnamed net (3); u_c.in_i aliases bit 4 in a deeper scope; u_d passes bit 4 through as
  // out_o at u_b's depth; a carry computes u_a's next value (bit 5); the top's own signal z (6)
  // named by the mapping after the LUT input it feeds; lut5's output (8) named by a path forward
  // from u_b.y, which does not make it u_b's.
  m["netnames"] = {{"u_a.x_q", net({2})},         {"$abc$3", net({3}, true)}, {"u_b.y", net({4})},
                   {"u_top_c.u_c.in_i", net({4})}, {"u_d.out_o", net({4})},  {"u_a.x_d", net({5})},
                   {"z_SB_LUT4_O_I0", net({6})}, {"u_b.y_SB_LUT4_I0_O", net({8})}};
  m["cells"] = {
      {"u_a.x_q_SB_DFF_Q", cell("SB_DFF", {{"C", {1}}, {"D", {5}}, {"Q", {2}}})},
      {"$abc$lut1", cell("SB_LUT4", {{"I0", {2}}, {"I1", {2}}, {"I2", {2}}, {"I3", {2}}, {"O", {3}}})},
      {"$abc$lut2", cell("SB_LUT4", {{"I0", {3}}, {"I1", {2}}, {"I2", {2}}, {"I3", {2}}, {"O", {4}}})},
      {"$abc$carry", cell("SB_CARRY", {{"I0", {4}}, {"I1", {2}}, {"CI", {2}}, {"CO", {7}}})},
      {"$abc$lut3", cell("SB_LUT4", {{"I0", {7}}, {"I1", {2}}, {"I2", {2}}, {"I3", {2}}, {"O", {5}}})},
      {"$abc$lut4", cell("SB_LUT4", {{"I0", {4}}, {"I1", {2}}, {"I2", {2}}, {"I3", {2}}, {"O", {6}}})},
      {"$abc$lut5", cell("SB_LUT4", {{"I0", {4}}, {"I1", {2}}, {"I2", {2}}, {"I3", {2}}, {"O", {8}}})},
  };
  return m;
}

TEST(SynthAttrib, CountsEachCellWhereItsSignalIsMade) {
  const std::string table = attribute(netlist(), "t", 4);
  // The carry's CO (7) is unnamed: it counts with the LUT after it, which makes u_a.x_d.
  EXPECT_NE(table.find("u_a | 1 | 1 | 1\n"), std::string::npos) << table;
  EXPECT_NE(table.find("u_b | 2 | 0 | 0\n"), std::string::npos) << table;
  EXPECT_NE(table.find("(top) | 1 | 0 | 0\n"), std::string::npos) << table;
  EXPECT_NE(table.find("(unnamed) | 1 | 0 | 0\n"), std::string::npos) << table;  // lut5 drives nothing named
  EXPECT_EQ(table.find("u_c"), std::string::npos) << table;
  EXPECT_EQ(table.find("u_d"), std::string::npos) << table;
  EXPECT_NE(table.find("total | 5 | 1 | 1\n"), std::string::npos) << table;
}

TEST(SynthAttrib, DepthCutsScopesBelowTheirCommonPrefix) {
  Json m;
  m["netnames"] = {{"top.u_x.u_y.a", net({2})}, {"top.u_x.u_z.b", net({3})}, {"top.u_w.c", net({4})}};
  m["cells"] = {
      {"$l1", cell("SB_LUT4", {{"I0", {9}}, {"I1", {9}}, {"I2", {9}}, {"I3", {9}}, {"O", {2}}})},
      {"$l2", cell("SB_LUT4", {{"I0", {9}}, {"I1", {9}}, {"I2", {9}}, {"I3", {9}}, {"O", {3}}})},
      {"$l3", cell("SB_LUT4", {{"I0", {9}}, {"I1", {9}}, {"I2", {9}}, {"I3", {9}}, {"O", {4}}})},
  };
  const std::string deep = attribute(m, "t", 2);
  EXPECT_NE(deep.find("scope (below top) |"), std::string::npos) << deep;
  EXPECT_NE(deep.find("u_x.u_y | 1 | 0 | 0\n"), std::string::npos) << deep;
  EXPECT_NE(deep.find("u_x.u_z | 1 | 0 | 0\n"), std::string::npos) << deep;
  const std::string shallow = attribute(m, "t", 1);
  EXPECT_NE(shallow.find("u_x | 2 | 0 | 0\n"), std::string::npos) << shallow;
  EXPECT_NE(shallow.find("u_w | 1 | 0 | 0\n"), std::string::npos) << shallow;
  // A signal of the common prefix's own scope (a harness's register around its design).
  m["netnames"]["top.d"] = net({5});
  m["cells"]["$l4"] = cell("SB_LUT4", {{"I0", {9}}, {"I1", {9}}, {"I2", {9}}, {"I3", {9}}, {"O", {5}}});
  const std::string own = attribute(m, "t", 1);
  EXPECT_NE(own.find("scope (below top) |"), std::string::npos) << own;
  EXPECT_NE(own.find("(own) | 1 | 0 | 0\n"), std::string::npos) << own;
}

TEST(SynthAttrib, BySignalGivesEachSignalItsOwnRow) {
  const std::string table = attribute(netlist(), "t", 1, true);
  EXPECT_NE(table.find("signal (below t) |"), std::string::npos) << table;
  EXPECT_NE(table.find("u_a.x_d | 1 | 1 | 0\n"), std::string::npos) << table;
  EXPECT_NE(table.find("u_a.x_q | 0 | 0 | 1\n"), std::string::npos) << table;
  EXPECT_NE(table.find("u_b.y | 2 | 0 | 0\n"), std::string::npos) << table;
  EXPECT_NE(table.find("z | 1 | 0 | 0\n"), std::string::npos) << table;
  EXPECT_NE(table.find("total | 5 | 1 | 1\n"), std::string::npos) << table;
}

}  // namespace
}  // namespace htx::synth
