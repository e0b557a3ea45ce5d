// Texel decode (docs/model.md §7, model decode_texel): RGB565, RGBA4444 (low 16 bits) and RGBA8888
// (r in bits 7:0) to 8 bits per channel by bit replication; RGB565 decodes with alpha 255. A format
// the configuration does not build (or 3) decodes as 0 and raises bad_o. Combinational.
module htx_tex_decode #(
  parameter int unsigned TexW    = 32,
  parameter logic [2:0]  Formats = 3'b111
) (
  input  logic [TexW-1:0] texel_i,
  input  logic [1:0]      format_i,
  output logic [31:0]     rgba_o,    // r 7:0, g 15:8, b 23:16, a 31:24
  output logic            bad_o
);
  logic [31:0] t;
  assign t = 32'(texel_i);
  always_comb begin
    rgba_o = '0;
    bad_o  = 1'b0;
    if (format_i == 2'd0 && Formats[0]) begin
      rgba_o = {8'hFF, t[4:0], t[4:2], t[10:5], t[10:9], t[15:11], t[15:13]};
    end else if (format_i == 2'd1 && Formats[1]) begin
      rgba_o = {t[3:0], t[3:0], t[7:4], t[7:4], t[11:8], t[11:8], t[15:12], t[15:12]};
    end else if (format_i == 2'd2 && Formats[2]) begin
      rgba_o = t;
    end else begin
      bad_o = 1'b1;
    end
  end
endmodule
