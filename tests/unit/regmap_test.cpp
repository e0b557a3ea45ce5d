// The register-map generator accepts the project's map and rejects malformed descriptions with a
// message that names the file and the register.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "regmap.hpp"

namespace fs = std::filesystem;
using htx::regmap::Error;

namespace {

class RegmapTest : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("htx_regmap_test_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }

  fs::path write(const std::string& name, const std::string& text) {
    fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
  }
  // A one-register peripheral with the given fields array and register offset.
  fs::path periph(const std::string& fields, const std::string& extra_reg = "") {
    return write("demo.json", R"({"name":"DEMO","base":"0x20009000","description":"d","registers":[
      {"name":"CTRL","offset":"0x4","access":"rw","fields":)" + fields + "}" + extra_reg + "]}");
  }
  std::string error_of(const fs::path& p) {
    try {
      htx::regmap::load_peripheral(p);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(RegmapTest, ProjectMapLoadsAndEmits) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(HTX_REGS_DIR))
    if (e.path().extension() == ".json") files.push_back(e.path());
  ASSERT_FALSE(files.empty());
  const auto map = htx::regmap::load_map(files);
  ASSERT_EQ(map.size(), files.size());
  for (size_t i = 1; i < map.size(); ++i) EXPECT_LT(map[i - 1].base, map[i].base);
  std::ostringstream c, sv, md;
  htx::regmap::emit_c_header(c, map);
  htx::regmap::emit_sv_package(sv, map.front());
  htx::regmap::emit_markdown(md, map);
  EXPECT_NE(c.str().find("HTX_" + map.front().name + "_Type"), std::string::npos);
  EXPECT_NE(sv.str().find("package htx_"), std::string::npos);
  EXPECT_NE(md.str().find("## " + map.front().name), std::string::npos);
}

TEST_F(RegmapTest, ResetIsOrOfFieldResets) {
  auto p = htx::regmap::load_peripheral(periph(R"([{"name":"A","lsb":0,"width":4,"access":"rw","reset":5},
      {"name":"B","lsb":8,"width":8,"access":"ro","reset":"0x12"}])"));
  ASSERT_EQ(p.registers.size(), 1u);
  EXPECT_EQ(p.registers[0].reset(), 0x1205u);
  EXPECT_EQ(p.registers[0].fields[1].mask(), 0xFF00u);
}

TEST_F(RegmapTest, RejectsOverlappingFields) {
  auto msg = error_of(periph(R"([{"name":"A","lsb":0,"width":4,"access":"rw"},{"name":"B","lsb":3,"width":2,"access":"rw"}])"));
  EXPECT_NE(msg.find("CTRL.B"), std::string::npos) << msg;
  EXPECT_NE(msg.find("overlaps"), std::string::npos) << msg;
}

TEST_F(RegmapTest, RejectsFieldPastBit31) {
  EXPECT_NE(error_of(periph(R"([{"name":"A","lsb":30,"width":4,"access":"rw"}])")).find("fit"), std::string::npos);
}

TEST_F(RegmapTest, RejectsSignedOrWrappingPositions) {
  // "-1" must not parse as 2^64 - 1, and lsb + width must not wrap around.
  EXPECT_NE(error_of(periph(R"([{"name":"A","lsb":"-1","width":1,"access":"rw"}])")).find("non-negative"), std::string::npos);
  EXPECT_NE(error_of(periph(R"([{"name":"A","lsb":18446744073709551615,"width":1,"access":"rw"}])")).find("fit"), std::string::npos);
  EXPECT_NE(error_of(periph(R"([{"name":"A","lsb":0,"width":" 4","access":"rw"}])")).find("non-negative"), std::string::npos);
}

TEST_F(RegmapTest, RejectsResetWiderThanField) {
  EXPECT_NE(error_of(periph(R"([{"name":"A","lsb":0,"width":2,"access":"rw","reset":4}])")).find("reset"), std::string::npos);
}

TEST_F(RegmapTest, RejectsDuplicateOffset) {
  auto msg = error_of(periph(R"([{"name":"A","lsb":0,"width":1,"access":"rw"}])",
                             R"(,{"name":"OTHER","offset":"0x4","access":"rw","fields":[{"name":"A","lsb":0,"width":1,"access":"rw"}]})"));
  EXPECT_NE(msg.find("already used by CTRL"), std::string::npos) << msg;
}

TEST_F(RegmapTest, RejectsMisalignedOffset) {
  auto msg = error_of(write("demo.json", R"({"name":"DEMO","base":"0x20009000","registers":[
      {"name":"CTRL","offset":"0x6","access":"rw","fields":[{"name":"A","lsb":0,"width":1,"access":"rw"}]}]})"));
  EXPECT_NE(msg.find("4-aligned"), std::string::npos) << msg;
}

TEST_F(RegmapTest, RejectsUnknownAccess) {
  EXPECT_NE(error_of(periph(R"([{"name":"A","lsb":0,"width":1,"access":"rwx"}])")).find("unknown access"), std::string::npos);
}

TEST_F(RegmapTest, RejectsMalformedJsonAndWrongFileName) {
  EXPECT_NE(error_of(write("demo.json", "{ not json")).find("not valid JSON"), std::string::npos);
  auto msg = error_of(write("other.json", R"({"name":"DEMO","base":"0x20009000","registers":[
      {"name":"CTRL","offset":"0x0","access":"rw","fields":[{"name":"A","lsb":0,"width":1,"access":"rw"}]}]})"));
  EXPECT_NE(msg.find("demo.json"), std::string::npos) << msg;
}

TEST_F(RegmapTest, RejectsDuplicateBaseAcrossFiles) {
  auto a = periph(R"([{"name":"A","lsb":0,"width":1,"access":"rw"}])");
  auto b = write("twin.json", R"({"name":"TWIN","base":"0x20009000","registers":[
      {"name":"CTRL","offset":"0x0","access":"rw","fields":[{"name":"A","lsb":0,"width":1,"access":"rw"}]}]})");
  EXPECT_THROW(htx::regmap::load_map({a, b}), Error);
}

}  // namespace
