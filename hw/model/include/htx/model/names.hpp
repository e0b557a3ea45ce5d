// Text names of the engine enums, as used on the command line, in JSON and in docs.
// Parsers throw std::invalid_argument naming the accepted values.
#pragma once

#include <string>
#include <string_view>

#include "htx/model/types.hpp"

namespace htx {

// A perspective method with its parameter: "subdiv16" is {Method::Subdiv, 16}.
struct MethodChoice {
  Method method = Method::RecipNr;
  unsigned subdiv_n = 16;
};

// affine, subdivN (N = 2..64), recip_lut, recip_nr, divfree, quadratic, auto
MethodChoice parse_method(std::string_view name);
std::string method_name(Method method, unsigned subdiv_n = 16);

Filter parse_filter(std::string_view name);  // nearest, bilinear, trilinear
std::string_view filter_name(Filter filter);

Wrap parse_wrap(std::string_view name);  // repeat, clamp, mirror
std::string_view wrap_name(Wrap wrap);

TexFormat parse_tex_format(std::string_view name);  // rgb565, rgba4444, rgba8888
std::string_view tex_format_name(TexFormat format);

DepthFunc parse_depth_func(std::string_view name);  // never, less, lequal, equal, greater, always
std::string_view depth_func_name(DepthFunc func);

}  // namespace htx
