#include "htx/model/config.hpp"

#include <stdexcept>

namespace htx {

namespace {

ModelConfig make_full() {
  ModelConfig c;  // the defaults are the full configuration
  c.name = "full";
  // Perspective-correct Gouraud: the model then differs from `ref` only by its texel and RGB565
  // rounding (max channel difference 9 instead of 66 on nearclip), so image metrics measure the
  // texture method alone. A pipelined reciprocal unit makes the per-pixel division cheap.
  c.perspective_color = true;
  return c;
}

ModelConfig make_icebreaker() {
  ModelConfig c;
  c.name = "icebreaker";
  c.xy_int_bits = 12;  // +-2048 pixels: screens up to 1024 wide (docs/model.md)
  c.z_bits = 16;
  c.q_bits = 24;  // 20 bits leave 0.017 texel on wsweep:r=1000; 24 keep every scene within 1/256
  c.uv_int_bits = 13;  // a triangle may span up to 4096 texels
  c.grad_frac_bits = 16;
  c.recip_table_bits = 8;
  c.recip_guard_bits = 2;
  c.recip_width = 24;
  c.setup_nr_steps = 2;
  c.pixel_nr_steps = 1;
  c.recip_issue_interval = 3;  // one shared unit: table, then one multiply pair per Newton step
  // Measured on the Verilated icebreaker GPU, wsweep:r=10 at 320x240 (31,104 pixels): 12.08
  // clocks a pixel for AFFINE, SUBDIV (n >= 4) and DIVFREE, 15.30 for RECIP_LUT, 23.30 for
  // RECIP_NR; AFFINE's vertex divisions about 160 clocks a triangle on floor (docs/auto.md).
  c.auto_pixel_cost16 = 193;
  c.auto_lut_divide_cost16 = 245;
  c.auto_nr_divide_cost16 = 373;
  c.auto_affine_setup_cost16 = 2560;
  // The render firmware's chooser on the SoC's rv32im CPU: about 4,500 clocks a floor triangle
  // (geombench; docs/auto.md, "When choosing does not pay").
  c.auto_choice_cycles = 4500;
  c.texcoord_frac_bits = 10;
  c.divfree_frac_bits = 2;
  c.divfree_cap = 64;
  c.lod_frac_bits = 6;
  c.lod_log_index_bits = 6;
  c.lod_grad_bits = 16;
  c.methods = 0x3F;
  c.filters = (1u << static_cast<unsigned>(Filter::Nearest)) | (1u << static_cast<unsigned>(Filter::Bilinear));
  c.formats = (1u << static_cast<unsigned>(TexFormat::RGB565)) | (1u << static_cast<unsigned>(TexFormat::RGBA4444));
  return c;
}

void check(bool ok, const char* field, const char* range) {
  if (!ok) throw std::invalid_argument(std::string("ModelConfig.") + field + " outside " + range);
}

}  // namespace

fw::SetupParams ModelConfig::setup_params() const {
  fw::SetupParams p{};
  p.format = record_format();
  p.recip = {recip_table_bits, recip_guard_bits, recip_width, setup_nr_steps, nullptr};
  p.grad_frac_bits = grad_frac_bits;
  p.texcoord_frac_bits = texcoord_frac_bits;
  p.lod_grad_bits = lod_grad_bits;
  return p;
}

fw::RecordFormat ModelConfig::record_format() const {
  fw::RecordFormat f;
  f.xy_int_bits = static_cast<uint8_t>(xy_int_bits);
  f.z_bits = static_cast<uint8_t>(z_bits);
  f.q_bits = static_cast<uint8_t>(q_bits);
  f.uv_int_bits = static_cast<uint8_t>(uv_int_bits);
  return f;
}

void ModelConfig::validate() const {
  check(xy_int_bits >= 12 && xy_int_bits <= 16, "xy_int_bits", "12..16");
  check(z_bits >= 16 && z_bits <= 24, "z_bits", "16..24");
  check(q_bits >= 12 && q_bits <= 32, "q_bits", "12..32");
  check(uv_int_bits >= 4 && uv_int_bits <= 16, "uv_int_bits", "4..16");
  check(grad_frac_bits >= 8 && grad_frac_bits <= 24, "grad_frac_bits", "8..24");
  check(recip_table_bits >= 4 && recip_table_bits <= 14, "recip_table_bits", "4..14");
  check(recip_guard_bits <= 4, "recip_guard_bits", "0..4");
  check(recip_width >= recip_table_bits + recip_guard_bits + 2 && recip_width <= 40, "recip_width",
        "k+g+2..40");
  check(setup_nr_steps <= 3 && pixel_nr_steps <= 3, "nr_steps", "0..3");
  check(recip_issue_interval >= 1, "recip_issue_interval", ">= 1");
  check(texcoord_frac_bits >= 10 && texcoord_frac_bits <= 20, "texcoord_frac_bits", "10..20");
  // AUTO's cost table and price travel as 16-bit fields (fw::AutoConfig).
  for (const unsigned v : {auto_pixel_cost16, auto_lut_divide_cost16, auto_nr_divide_cost16, auto_affine_setup_cost16,
                           auto_choice_cycles})
    check(v <= 0xFFFF, "auto_* (AUTO's costs and price)", "0..65535");
  check(divfree_frac_bits <= 8, "divfree_frac_bits", "0..8");
  check(divfree_cap >= 1 && divfree_cap <= 4096, "divfree_cap", "1..4096");
  check(lod_frac_bits >= 4 && lod_frac_bits <= 8, "lod_frac_bits", "4..8");
  check(lod_log_index_bits >= 4 && lod_log_index_bits <= 12, "lod_log_index_bits", "4..12");
  check(lod_grad_bits >= 12 && lod_grad_bits <= 32, "lod_grad_bits", "12..32");
  check(filter_weight_bits == 8, "filter_weight_bits", "8");
}

const ModelConfig& model_config(std::string_view name) {
  static const ModelConfig full = make_full();
  static const ModelConfig icebreaker = make_icebreaker();
  if (name == "full") return full;
  if (name == "icebreaker") return icebreaker;
  throw std::invalid_argument("unknown model configuration '" + std::string(name) +
                              "' (known: icebreaker, full)");
}

std::vector<std::string> model_config_names() { return {"icebreaker", "full"}; }

uint32_t icebreaker_board_methods() {
  return (1u << static_cast<unsigned>(Method::Affine)) | (1u << static_cast<unsigned>(Method::RecipLut));
}

ModelConfig icebreaker_board_config(ModelConfig icebreaker) {
  icebreaker.methods &= icebreaker_board_methods();
  icebreaker.name = kIcebreakerBoard;
  return icebreaker;
}

std::string_view config_base_name(const ModelConfig& c) {
  return c.name == kIcebreakerBoard ? std::string_view("icebreaker") : std::string_view(c.name);
}

}  // namespace htx
