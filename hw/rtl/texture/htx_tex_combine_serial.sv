// Texture combine of the colour channels r, g, b one channel per clock on one multiplier (the
// `icebreaker` fragment path, which has no alpha): the same results as htx_tex_combine's low 24
// bits. A valid/ready stage holding one fragment and its payload; a modulated fragment leaves it
// 3 clocks after it entered (r and g go into the result register, b is formed as the fragment
// leaves), any other after 1. abort_i empties it.
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
  output logic [23:0]     rgb_o,
  output logic [PayW-1:0] pay_o,
  output logic            busy_o
);
  logic            valid_q, mod_q;
  logic [1:0]      ch_q;
  logic [23:0]     t_q, c_q, res_q;
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
  assign out_valid_o = valid_q && (!mod_q || last_ch);
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
    end else if (mod_q && !last_ch) begin
      ch_q <= ch_q + 2'd1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (in_ready_o && in_valid_i) begin
      t_q   <= texel_i;
      c_q   <= color_i;
      pay_q <= pay_i;
      res_q <= textured_i ? texel_i : color_i;
    end else if (mod_q && !last_ch) begin
      res_q[8*ch_q +: 8] <= m_ch;
    end
  end

  assign rgb_o  = mod_q ? {m_ch, res_q[15:0]} : res_q;
  assign pay_o  = pay_q;
  assign busy_o = valid_q;
endmodule
