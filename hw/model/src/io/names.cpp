#include "htx/model/names.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <utility>

namespace htx {

namespace {

template <typename E, size_t N>
E parse_enum(std::string_view name, const std::array<std::pair<std::string_view, E>, N>& table,
             std::string_view what) {
  for (const auto& [text, value] : table)
    if (text == name) return value;
  std::string accepted;
  for (const auto& [text, value] : table) accepted += (accepted.empty() ? "" : ", ") + std::string(text);
  throw std::invalid_argument("unknown " + std::string(what) + " '" + std::string(name) +
                              "' (accepted: " + accepted + ")");
}

template <typename E, size_t N>
std::string_view enum_name(E value, const std::array<std::pair<std::string_view, E>, N>& table) {
  for (const auto& [text, v] : table)
    if (v == value) return text;
  return "?";
}

constexpr std::array<std::pair<std::string_view, Filter>, 3> kFilters{
    {{"nearest", Filter::Nearest}, {"bilinear", Filter::Bilinear}, {"trilinear", Filter::Trilinear}}};
constexpr std::array<std::pair<std::string_view, Wrap>, 3> kWraps{
    {{"repeat", Wrap::Repeat}, {"clamp", Wrap::Clamp}, {"mirror", Wrap::Mirror}}};
constexpr std::array<std::pair<std::string_view, TexFormat>, 3> kFormats{
    {{"rgb565", TexFormat::RGB565}, {"rgba4444", TexFormat::RGBA4444}, {"rgba8888", TexFormat::RGBA8888}}};
constexpr std::array<std::pair<std::string_view, DepthFunc>, 6> kDepthFuncs{
    {{"never", DepthFunc::Never},
     {"less", DepthFunc::Less},
     {"lequal", DepthFunc::LEqual},
     {"equal", DepthFunc::Equal},
     {"greater", DepthFunc::Greater},
     {"always", DepthFunc::Always}}};
constexpr std::array<std::pair<std::string_view, Method>, 6> kMethods{
    {{"affine", Method::Affine},
     {"recip_lut", Method::RecipLut},
     {"recip_nr", Method::RecipNr},
     {"divfree", Method::DivFree},
     {"quadratic", Method::Quadratic},
     {"auto", Method::Auto}}};

}  // namespace

MethodChoice parse_method(std::string_view name) {
  constexpr std::string_view kSubdiv = "subdiv";
  if (name.substr(0, kSubdiv.size()) == kSubdiv) {
    const std::string_view digits = name.substr(kSubdiv.size());
    unsigned n = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (digits.empty() || ec != std::errc() || ptr != digits.data() + digits.size() || n < 2 || n > 64)
      throw std::invalid_argument("method '" + std::string(name) + "': subdivN needs N in 2..64");
    return {Method::Subdiv, n};
  }
  try {
    return {parse_enum(name, kMethods, "method"), 16};
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("unknown method '" + std::string(name) +
                                "' (accepted: affine, subdivN with N in 2..64, recip_lut, recip_nr, "
                                "divfree, quadratic, auto)");
  }
}

std::string method_name(Method method, unsigned subdiv_n) {
  if (method == Method::Subdiv) return "subdiv" + std::to_string(subdiv_n);
  return std::string(enum_name(method, kMethods));
}

Filter parse_filter(std::string_view name) { return parse_enum(name, kFilters, "filter"); }
std::string_view filter_name(Filter filter) { return enum_name(filter, kFilters); }
Wrap parse_wrap(std::string_view name) { return parse_enum(name, kWraps, "wrap mode"); }
std::string_view wrap_name(Wrap wrap) { return enum_name(wrap, kWraps); }
TexFormat parse_tex_format(std::string_view name) { return parse_enum(name, kFormats, "texture format"); }
std::string_view tex_format_name(TexFormat format) { return enum_name(format, kFormats); }
DepthFunc parse_depth_func(std::string_view name) { return parse_enum(name, kDepthFuncs, "depth function"); }
std::string_view depth_func_name(DepthFunc func) { return enum_name(func, kDepthFuncs); }

}  // namespace htx
