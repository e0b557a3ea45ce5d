#include "regmap.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

namespace htx::regmap {
namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw Error(where + ": " + what);
}

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isupper(static_cast<unsigned char>(s[0])))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
  });
}

uint64_t parse_number(const json& j, const std::string& where, const char* key) {
  if (!j.contains(key)) fail(where, std::string("missing \"") + key + "\"");
  const json& v = j.at(key);
  if (v.is_number_unsigned()) return v.get<uint64_t>();
  if (v.is_string()) {
    const auto s = v.get<std::string>();
    // stoull would accept a sign or leading blanks ("-1" becomes 2^64 - 1): digits only.
    if (s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])))
      fail(where, std::string("\"") + key + "\" must be a non-negative number or a numeric string");
    size_t used = 0;
    uint64_t n = 0;
    try {
      n = std::stoull(s, &used, 0);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == s.size() && used > 0) return n;
  }
  fail(where, std::string("\"") + key + "\" must be a non-negative number or a numeric string");
}

std::string get_string(const json& j, const std::string& where, const char* key, bool required) {
  if (!j.contains(key)) {
    if (required) fail(where, std::string("missing \"") + key + "\"");
    return {};
  }
  if (!j.at(key).is_string()) fail(where, std::string("\"") + key + "\" must be a string");
  return j.at(key).get<std::string>();
}

Access parse_access(const std::string& s, const std::string& where) {
  static const std::map<std::string, Access> names = {
      {"ro", Access::RO}, {"wo", Access::WO}, {"rw", Access::RW}, {"rw1c", Access::RW1C}, {"rc", Access::RC}};
  auto it = names.find(s);
  if (it == names.end()) fail(where, "unknown access \"" + s + "\" (ro, wo, rw, rw1c, rc)");
  return it->second;
}

}  // namespace

const char* access_name(Access a) {
  switch (a) {
    case Access::RO: return "ro";
    case Access::WO: return "wo";
    case Access::RW: return "rw";
    case Access::RW1C: return "rw1c";
    case Access::RC: return "rc";
  }
  return "?";
}

std::string lower_name(std::string name) {
  for (auto& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

std::string sv_package_name(const Peripheral& p) { return "htx_" + lower_name(p.name) + "_reg_pkg"; }

uint32_t Register::reset() const {
  uint32_t r = 0;
  for (const auto& f : fields) r |= (f.reset << f.lsb) & f.mask();
  return r;
}

Peripheral load_peripheral(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail(file.string(), "cannot open");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    fail(file.string(), std::string("not valid JSON: ") + e.what());
  }
  Peripheral p;
  p.source = file.string();
  const std::string top = file.string();
  if (!j.is_object()) fail(top, "top level must be an object");
  p.name = get_string(j, top, "name", true);
  if (!is_identifier(p.name)) fail(top, "peripheral name \"" + p.name + "\" must be an upper-case identifier");
  if (p.name.find('_') != std::string::npos) fail(top, "peripheral name \"" + p.name + "\" may not contain '_'");
  const std::string stem = lower_name(p.name);
  if (file.stem().string() != stem) fail(top, "file must be named " + stem + ".json after its peripheral");
  const uint64_t base = parse_number(j, top, "base");
  if (base > 0xFFFFFFFFu || (base & 0xFFFu) != 0) fail(top, "base must be a 4 KiB-aligned 32-bit address");
  p.base = static_cast<uint32_t>(base);
  p.description = get_string(j, top, "description", false);
  if (!j.contains("registers") || !j.at("registers").is_array() || j.at("registers").empty())
    fail(top, "\"registers\" must be a non-empty array");

  for (const json& jr : j.at("registers")) {
    Register r;
    r.name = get_string(jr, top, "name", true);
    const std::string where = top + ": register " + r.name;
    if (!is_identifier(r.name)) fail(where, "name must be an upper-case identifier");
    const uint64_t off = parse_number(jr, where, "offset");
    if (off >= 0x1000 || (off & 3u) != 0) fail(where, "offset must be 4-aligned and below 0x1000");
    r.offset = static_cast<uint32_t>(off);
    r.access = parse_access(get_string(jr, where, "access", true), where);
    if (r.access == Access::RW1C || r.access == Access::RC) fail(where, "register access is ro, wo or rw");
    r.description = get_string(jr, where, "description", false);
    if (!jr.contains("fields") || !jr.at("fields").is_array() || jr.at("fields").empty())
      fail(where, "\"fields\" must be a non-empty array");
    uint64_t used = 0;
    for (const json& jf : jr.at("fields")) {
      Field f;
      f.name = get_string(jf, where, "name", true);
      const std::string fwhere = where + "." + f.name;
      if (!is_identifier(f.name)) fail(fwhere, "name must be an upper-case identifier");
      const uint64_t lsb = parse_number(jf, fwhere, "lsb");
      const uint64_t width = parse_number(jf, fwhere, "width");
      if (width < 1 || lsb >= 32 || width > 32 - lsb) fail(fwhere, "field must have width >= 1 and fit in bits 31..0");
      f.lsb = static_cast<unsigned>(lsb);
      f.width = static_cast<unsigned>(width);
      f.access = parse_access(get_string(jf, fwhere, "access", true), fwhere);
      const uint64_t reset = jf.contains("reset") ? parse_number(jf, fwhere, "reset") : 0;
      if (width < 64 && (reset >> width) != 0) fail(fwhere, "reset value does not fit the field");
      f.reset = static_cast<uint32_t>(reset);
      f.description = get_string(jf, fwhere, "description", false);
      if (used & f.mask()) fail(fwhere, "overlaps another field");
      used |= f.mask();
      for (const auto& other : r.fields)
        if (other.name == f.name) fail(fwhere, "duplicate field name");
      r.fields.push_back(std::move(f));
    }
    std::sort(r.fields.begin(), r.fields.end(), [](const Field& a, const Field& b) { return a.lsb < b.lsb; });
    for (const auto& other : p.registers) {
      if (other.name == r.name) fail(where, "duplicate register name");
      if (other.offset == r.offset) fail(where, "offset already used by " + other.name);
    }
    p.registers.push_back(std::move(r));
  }
  std::sort(p.registers.begin(), p.registers.end(),
            [](const Register& a, const Register& b) { return a.offset < b.offset; });
  return p;
}

std::vector<Peripheral> load_map(const std::vector<std::filesystem::path>& files) {
  std::vector<Peripheral> map;
  for (const auto& f : files) {
    Peripheral p = load_peripheral(f);
    for (const auto& other : map) {
      if (other.name == p.name) fail(p.source, "peripheral " + p.name + " also defined in " + other.source);
      if (other.base == p.base) fail(p.source, "base address already used by " + other.name);
    }
    map.push_back(std::move(p));
  }
  std::sort(map.begin(), map.end(), [](const Peripheral& a, const Peripheral& b) { return a.base < b.base; });
  return map;
}

}  // namespace htx::regmap
