// Texture combine (docs/model.md §8): replace takes the texel; modulate takes round(t c / 255) per
// channel, computed as x = t c + 128, (x + (x >> 8)) >> 8 (exact for 8-bit t, c); an untextured
// fragment keeps its colour. Combinational; the raster's fragment path instantiates it after the
// texture unit (docs/texture.md, Joining the raster unit).
module htx_tex_combine (
  input  logic        textured_i,
  input  logic        modulate_i,
  input  logic [31:0] texel_i,    // r 7:0, g 15:8, b 23:16, a 31:24
  input  logic [31:0] color_i,    // the fragment's colour, same layout
  output logic [31:0] rgba_o
);
  function automatic logic [7:0] modulate8(input logic [7:0] t, input logic [7:0] c);
    logic [15:0] x;
    x = 16'(t) * 16'(c) + 16'd128;             // <= 65153
    modulate8 = 8'((x + 16'(x[15:8])) >> 8);    // the sum stays below 2^16
  endfunction

  logic [31:0] mod;
  for (genvar ch = 0; ch < 4; ch++) begin : g_ch
    assign mod[8*ch +: 8] = modulate8(texel_i[8*ch +: 8], color_i[8*ch +: 8]);
  end
  assign rgba_o = !textured_i ? color_i : (modulate_i ? mod : texel_i);
endmodule
