// Robustness of the register-map generator (host_tools/regmap): the real hw/regs files with random
// byte flips, insertions and deletions, and with numbers replaced by extreme values. Each mutated
// file either loads (and then every field fits bits 31..0, and the emitters run) or is refused with
// htx::regmap::Error naming the file. Nothing else may happen. The library's sources are compiled
// into this test with the undefined-behaviour sanitizer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "regmap.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> real_files() {
  std::vector<fs::path> v;
  for (const auto& e : fs::directory_iterator(HTX_REGS_DIR))
    if (e.path().extension() == ".json") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Loads `text` as a file named like the original (the generator checks the name); true if loaded.
bool try_load(const std::string& text, const fs::path& original, const fs::path& dir, const std::string& what) {
  const fs::path p = dir / original.filename();
  std::ofstream(p, std::ios::binary) << text;
  try {
    const htx::regmap::Peripheral per = htx::regmap::load_peripheral(p);
    for (const auto& r : per.registers) {
      EXPECT_LT(r.offset, 0x1000u) << what;
      for (const auto& f : r.fields) {
        EXPECT_GE(f.width, 1u) << what;
        // (lsb and width each checked: their sum can wrap)
        EXPECT_LT(f.lsb, 32u) << what << ": field " << r.name << "." << f.name << " lsb " << f.lsb;
        EXPECT_LE(f.width, 32u - std::min(f.lsb, 32u)) << what << ": field " << r.name << "." << f.name << " lsb "
                                                        << f.lsb << " width " << f.width;
      }
    }
    std::ostringstream os;
    htx::regmap::emit_c_header(os, {per});
    htx::regmap::emit_sv_package(os, per);
    htx::regmap::emit_markdown(os, {per});
    return true;
  } catch (const htx::regmap::Error& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << what << ": " << e.what();
    return false;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": exception other than htx::regmap::Error: " << e.what();
    return false;
  }
}

class RegmapFuzz : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("htx_regmap_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(RegmapFuzz, RealFilesLoad) {
  const auto files = real_files();
  ASSERT_GE(files.size(), 4u);
  for (const auto& f : files) EXPECT_TRUE(try_load(slurp(f), f, dir_, f.string()));
}

TEST_F(RegmapFuzz, ByteMutations) {
  std::mt19937 rng(21);
  const auto files = real_files();
  int loaded = 0;
  for (int iter = 0; iter < 600; ++iter) {
    const fs::path& src = files[iter % files.size()];
    std::string t = slurp(src);
    for (unsigned k = 1 + rng() % 4; k > 0; --k) {
      const size_t at = rng() % t.size();
      switch (rng() % 4) {
        case 0: t[at] = static_cast<char>(t[at] ^ (1 << (rng() % 8))); break;
        case 1: t[at] = "{}[]\",:0123456789-x \\"[rng() % 20]; break;
        case 2: t.erase(at, 1 + rng() % 8); break;
        default: t.insert(at, 1, static_cast<char>(rng())); break;
      }
      if (t.empty()) t = "{";
    }
    loaded += try_load(t, src, dir_, "mutation " + std::to_string(iter) + " of " + src.filename().string());
    if (HasFailure()) FAIL() << "iteration " << iter;
  }
  EXPECT_GT(loaded, 10);  // flips inside descriptions keep the file loadable
}

// Every number in a file (hex strings and plain integers) replaced by an extreme: 2^32, zero,
// just past a limit, negative JSON numbers, floats, empty and non-numeric strings, null, arrays.
TEST_F(RegmapFuzz, ExtremeNumbers) {
  std::mt19937 rng(22);
  const auto files = real_files();
  // Signed strings and 2^64 - 1 once wrapped lsb + width (docs/robustness.md, "Defects these tests
  // found", 2).
  const char* extremes[] = {"\"0\"", "\"0x100000000\"", "4294967296", "33", "\"32\"", "\"31\"", "-1",
                            "1e3", "\"0x\"", "\"\"", "\" 4\"", "null", "[]", "\"0xFFFFFFFF\"", "\"4096\"",
                            "\"-1\"", "\"-0x1\"", "\"18446744073709551615\"", "\"0xFFFFFFFFFFFFFFFF\"",
                            "18446744073709551615"};
  for (int iter = 0; iter < 500; ++iter) {
    const fs::path& src = files[iter % files.size()];
    std::string t = slurp(src);
    // Candidate positions: the value after every ':' that starts a number or a "0x..." string.
    std::vector<std::pair<size_t, size_t>> spans;
    for (size_t i = 0; i + 1 < t.size(); ++i) {
      if (t[i] != ':') continue;
      size_t b = i + 1;
      while (b < t.size() && t[b] == ' ') ++b;
      size_t e = b;
      if (b < t.size() && std::isdigit(static_cast<unsigned char>(t[b]))) {
        while (e < t.size() && std::isalnum(static_cast<unsigned char>(t[e]))) ++e;
      } else if (b + 1 < t.size() && t[b] == '"' && std::isdigit(static_cast<unsigned char>(t[b + 1]))) {
        e = t.find('"', b + 1);
        if (e == std::string::npos) continue;
        ++e;
      } else {
        continue;
      }
      spans.emplace_back(b, e);
    }
    ASSERT_FALSE(spans.empty());
    for (unsigned k = 1 + rng() % 2; k > 0; --k) {
      const auto [b, e] = spans[rng() % spans.size()];
      if (e > t.size()) continue;
      t.replace(b, e - b, extremes[rng() % (sizeof extremes / sizeof extremes[0])]);
      break;  // positions after the first replacement have moved
    }
    try_load(t, src, dir_, "extreme number " + std::to_string(iter) + " in " + src.filename().string());
    if (HasFailure()) FAIL() << "iteration " << iter;
  }
}

}  // namespace
