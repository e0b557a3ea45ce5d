// Texture combine of the colour channels r, g, b one channel per clock on one multiplier, with
// the result quantised to the framebuffer's RGB565 as each channel is formed (the `icebreaker`
// fragment path, which has no alpha): per channel the same result as htx_tex_combine's, then
// htx_rgb565_pkg::quantise, the fragment stage's quantisation, on one quantiser. A valid/ready
// stage holding one fragment and its payload; every fragment leaves it 3 clocks after it entered
// (r and g go into their fields, b is quantised as the fragment leaves). abort_i empties it.
module htx_tex_combine_serial #(
  parameter int unsigned PayW = 8
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic            abort_i,

  input  logic            in_valid_i,
  output logic            in_ready_o,
  input  logic            textured_i,
  input  logic            modulate_i,
  input  logic [23:0]     texel_i,    // r 7:0, g 15:8, b 23:16
  input  logic [23:0]     color_i,    // the fragment's colour, same layout
  input  logic [PayW-1:0] pay_i,

  output logic            out_valid_o,
  input  logic            out_ready_i,
  output logic [15:0]     rgb565_o,   // r 15:11, g 10:5, b 4:0
  output logic [PayW-1:0] pay_o,
  output logic            busy_o
);
  logic            valid_q, mod_q, tex_q;
  logic [1:0]      ch_q;
  logic [23:0]     t_q, c_q;
  logic [PayW-1:0] pay_q;

  // The channel ch_q modulated by htx_tex_combine itself, in its lowest lane (the other three
  // lanes multiply zeros, which synthesis removes).
  logic [7:0]  m_ch;
  logic [31:0] m_rgba;
  htx_tex_combine u_modulate (
    .textured_i(1'b1),
    .modulate_i(1'b1),
    .texel_i   ({24'b0, t_q[8*ch_q +: 8]}),
    .color_i   ({24'b0, c_q[8*ch_q +: 8]}),
    .rgba_o    (m_rgba)
  );
  assign m_ch = m_rgba[7:0];
  logic unused_lanes;
  assign unused_lanes = ^m_rgba[31:8];

  logic last_ch;
  assign last_ch     = (ch_q == 2'd2);
  assign out_valid_o = valid_q && last_ch;
  assign in_ready_o  = !valid_q || (out_valid_o && out_ready_i);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
      mod_q   <= 1'b0;
      ch_q    <= '0;
    end else if (abort_i) begin
      valid_q <= 1'b0;
      mod_q   <= 1'b0;
    end else if (in_ready_o) begin
      valid_q <= in_valid_i;
      mod_q   <= in_valid_i && textured_i && modulate_i;
      ch_q    <= '0;
    end else if (valid_q && !last_ch) begin
      ch_q <= ch_q + 2'd1;
    end
  end

  // This clock's channel, quantised: the product, the texel's (replace) or the colour's
  // (untextured).
  logic [7:0] ch_value, q_ch;
  logic [4:0] r5_q;
  logic [5:0] g6_q;
  assign ch_value = mod_q ? m_ch : (tex_q ? t_q[8*ch_q +: 8] : c_q[8*ch_q +: 8]);
  assign q_ch     = htx_rgb565_pkg::quantise(ch_value, (ch_q == 2'd1) ? 3'd6 : 3'd5);

  always_ff @(posedge clk_i) begin
    if (in_ready_o && in_valid_i) begin
      t_q   <= texel_i;
      c_q   <= color_i;
      tex_q <= textured_i;
      pay_q <= pay_i;
    end
    if (valid_q && (ch_q == 2'd0)) r5_q <= q_ch[4:0];
    if (valid_q && (ch_q == 2'd1)) g6_q <= q_ch[5:0];
  end

  assign rgb565_o = {r5_q, g6_q, q_ch[4:0]};
  assign pay_o    = pay_q;
  assign busy_o   = valid_q;
  logic unused_q;
  assign unused_q = ^q_ch[7:6];
endmodule
