// Interpolation output (docs/model.md §3, §5): takes a fragment's raw plane values and rounds what
// needs no division: depth z = clamp(round(Z 2^-GF), 0, 2^ZBits - 1); the colour, per channel
// clamp(round(C 2^-GF), 0, 255) when it is linear in screen space (or vertex 0's colour for flat
// shading); AFFINE's coordinates round(U_a 2^-GF). It passes Q, U, V (and C q with PerspColor) on
// to the divider, and marks SUBDIV's exact points: a span's first pixel, every n-th after it, and
// its last pixel (Subdiv = 0, a unit without SUBDIV: none). Alpha has no plane: the framebuffer
// is RGB565, so alpha never reaches a pixel.
module htx_raster_shade #(
  parameter int unsigned ZBits      = 24,
  parameter int unsigned GF         = 24,
  parameter int unsigned NP         = 9,
  parameter int unsigned AW         = 74,
  parameter int unsigned SideW      = 64,
  parameter int unsigned AccZ       = ZBits + GF + 2,
  parameter int unsigned AccC       = 8 + GF + 2,
  parameter int unsigned AccQ       = 32 + GF + 2,
  parameter int unsigned AccU       = 48 + GF + 2,
  parameter int unsigned LocW       = 32,
  parameter bit          PerspColor = 1'b1,
  parameter bit          Subdiv     = 1'b1,
  parameter int unsigned AddrW      = 24,
  // 1: the results are registered (a pipeline stage). 0: they are combinational from the input
  // and the stage only passes the hand-shake through: for a traversal that already holds its
  // fragment in a register and emits one every few clocks (`icebreaker`), where a second copy of
  // the fragment buys nothing but flip-flops.
  parameter bit          Registered = 1'b1
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              abort_i,

  input  logic              in_valid_i,
  output logic              in_ready_o,
  input  logic [AddrW-1:0]  in_addr_i,
  input  logic [12:0]       in_x_i,
  input  logic              in_first_i,
  input  logic              in_last_i,
  input  logic [12:0]       in_y_i,
  input  logic              in_tfirst_i,
  input  logic [NP*AW-1:0]  in_p_i,        // z, r, g, b, q, uq, vq, ua, va
  input  logic [SideW-1:0]  in_side_i,     // state word in 31:0, flat colour in 63:32

  output logic              out_valid_o,
  input  logic              out_ready_i,
  output logic [AddrW-1:0]  out_addr_o,
  output logic [12:0]       out_x_o,
  output logic [12:0]       out_y_o,
  output logic              out_first_o, out_last_o, out_tfirst_o,
  output logic [ZBits-1:0]  out_z_o,
  output logic [23:0]       out_rgb_o,     // r in 7:0, g 15:8, b 23:16 (linear or flat)
  output logic              out_div_color_o, // the colour comes from the divider (C q / Q)
  output logic              out_exact_o,   // SUBDIV exact point
  output logic [LocW-1:0]   out_ua_o, out_va_o,
  output logic [AccQ-1:0]   out_q_o,
  output logic [AccU-1:0]   out_u_o, out_v_o,
  output logic [3*AccC-1:0] out_c_o,
  output logic [SideW-1:0]  out_side_o
);
  localparam int unsigned ZR = AccZ - GF;  // signed width after the shift
  localparam int unsigned CR = AccC - GF;
  localparam int unsigned AccA = LocW + GF + 2;

  logic [31:0] st, flat;
  logic        gouraud;
  assign st      = in_side_i[31:0];
  assign flat    = in_side_i[63:32];
  assign gouraud = st[htx_raster_reg_pkg::RASTER_STATE_GOURAUD_LSB];

  logic [AccZ-1:0] zacc;
  assign zacc = in_p_i[0 +: AccZ];
  logic signed [AccZ-1:0] z_round_full;
  logic signed [ZR-1:0]   z_round;
  logic [ZBits-1:0]       z_clamped;
  logic [23:0]            rgb;

  assign z_round_full = ($signed(zacc) + $signed(AccZ'(1) << (GF - 1))) >>> GF;
  assign z_round      = ZR'(z_round_full);
  assign z_clamped    = z_round[ZR-1] ? '0 :
                        (((ZR'(z_round) >> ZBits) != '0) ? {ZBits{1'b1}} : ZBits'(z_round));

  for (genvar c = 0; c < 3; c++) begin : g_ch
    logic signed [AccC-1:0] full;
    logic signed [CR-1:0]   r;
    logic unused;
    assign full = ($signed(in_p_i[AW*(c+1) +: AccC]) + $signed(AccC'(1) << (GF - 1))) >>> GF;
    assign r    = CR'(full);
    assign unused = ^full[AccC-1:CR];
    assign rgb[8*c +: 8] = (gouraud && !PerspColor)
                           ? (r[CR-1] ? 8'd0 : (((CR'(r) >> 8) != '0) ? 8'd255 : 8'(r)))
                           : flat[8*c +: 8];
  end

  logic [LocW-1:0] ua, va;
  for (genvar a = 0; a < 2; a++) begin : g_aff
    logic signed [AccA-1:0] full;
    assign full = ($signed(in_p_i[AW*(7+a) +: AccA]) + $signed(AccA'(1) << (GF - 1))) >>> GF;
    if (a == 0) begin : g_u
      assign ua = LocW'(full);
    end else begin : g_v
      assign va = LocW'(full);
    end
    logic unused;
    assign unused = ^full[AccA-1:LocW];
  end

  // SUBDIV: position in the span modulo n.
  logic [6:0] n, k_q, k;
  logic       exact;
  assign n = st[htx_raster_reg_pkg::RASTER_STATE_SUBDIV_N_LSB +: 7];
  assign k = in_first_i ? 7'd0 : k_q;
  assign exact = Subdiv && ((k == 7'd0) || in_last_i);

  logic unused;
  assign unused = ^{z_round_full[AccZ-1:ZR], flat[31:24], in_p_i};

  // Everything the stage gives, computed once; registered (Registered) or passed on as it is.
  localparam int unsigned RW = AddrW + 2 * 13 + 3 + ZBits + 24 + 2 + 2 * LocW + AccQ + 2 * AccU +
                               3 * AccC + SideW;
  logic [RW-1:0] res_d, res;
  assign res_d = {in_addr_i, in_x_i, in_y_i, in_first_i, in_last_i, in_tfirst_i, z_clamped, rgb,
                  gouraud && PerspColor, exact, ua, va,
                  in_p_i[AW*4 +: AccQ], in_p_i[AW*5 +: AccU], in_p_i[AW*6 +: AccU],
                  in_p_i[AW*3 +: AccC], in_p_i[AW*2 +: AccC], in_p_i[AW*1 +: AccC], in_side_i};
  assign {out_addr_o, out_x_o, out_y_o, out_first_o, out_last_o, out_tfirst_o, out_z_o, out_rgb_o,
          out_div_color_o, out_exact_o, out_ua_o, out_va_o, out_q_o, out_u_o, out_v_o, out_c_o,
          out_side_o} = res;

  logic advance;  // a fragment goes through this clock
  if (Registered) begin : g_reg
    logic          valid_q;
    logic [RW-1:0] res_q;
    assign in_ready_o  = !valid_q || out_ready_i;
    assign out_valid_o = valid_q;
    assign res         = res_q;
    assign advance     = in_ready_o && in_valid_i;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        valid_q <= 1'b0;
        res_q   <= '0;
      end else if (abort_i) begin
        valid_q <= 1'b0;
      end else if (in_ready_o) begin
        valid_q <= in_valid_i;
        if (in_valid_i) res_q <= res_d;
      end
    end
  end else begin : g_comb
    assign in_ready_o  = out_ready_i;
    assign out_valid_o = in_valid_i;
    assign res         = res_d;
    assign advance     = in_valid_i && out_ready_i;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      k_q <= '0;
    end else if (Subdiv && !abort_i && advance) begin
      k_q <= (k + 7'd1 >= n) ? 7'd0 : k + 7'd1;
    end
  end
endmodule
