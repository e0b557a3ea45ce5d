// Interpolation output (docs/model.md §3): rounds the raw plane values of a fragment to its depth,
// z = clamp(round(Z 2^-GF), 0, 2^ZBits - 1), and its colour, per channel clamp(round(C 2^-GF), 0, 255)
// (or vertex 0's colour for flat shading). This registered stage's output is where a texture stage
// attaches: a fragment here carries x, y, its address, z, colour and the triangle's state.
// Alpha has no plane in this slice: the framebuffer is RGB565, so alpha never reaches a pixel.
module htx_raster_shade #(
  parameter int unsigned ZBits = 24,
  parameter int unsigned GF    = 24,
  parameter int unsigned AccZ  = ZBits + GF + 2,
  parameter int unsigned AccC  = 8 + GF + 2,
  parameter int unsigned AddrW = 24
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              abort_i,

  input  logic              in_valid_i,
  output logic              in_ready_o,
  input  logic [12:0]       in_x_i, in_y_i,
  input  logic [AddrW-1:0]  in_addr_i,
  input  logic [AccZ-1:0]   in_z_i,
  input  logic [3*AccC-1:0] in_c_i,
  input  logic [31:0]       in_state_i,
  input  logic [31:0]       in_flat_rgba_i,

  output logic              out_valid_o,
  input  logic              out_ready_i,
  output logic [12:0]       out_x_o, out_y_o,
  output logic [AddrW-1:0]  out_addr_o,
  output logic [ZBits-1:0]  out_z_o,
  output logic [23:0]       out_rgb_o,     // r in 7:0, g 15:8, b 23:16
  output logic [31:0]       out_state_o
);
  localparam int unsigned ZR = AccZ - GF;  // signed width after the shift
  localparam int unsigned CR = AccC - GF;

  logic signed [AccZ-1:0] z_round_full;
  logic signed [ZR-1:0]   z_round;
  logic [ZBits-1:0]       z_clamped;
  logic [23:0]            rgb;

  assign z_round_full = ($signed(in_z_i) + $signed(AccZ'(1) << (GF - 1))) >>> GF;
  assign z_round      = ZR'(z_round_full);
  assign z_clamped    = z_round[ZR-1] ? '0 :
                        (z_round > $signed(ZR'({ZBits{1'b1}})) ? {ZBits{1'b1}} : ZBits'(z_round));

  for (genvar c = 0; c < 3; c++) begin : g_ch
    logic signed [AccC-1:0] full;
    logic signed [CR-1:0]   r;
    logic unused;
    assign full = ($signed(in_c_i[AccC*c +: AccC]) + $signed(AccC'(1) << (GF - 1))) >>> GF;
    assign r    = CR'(full);
    assign unused = ^full[AccC-1:CR];
    assign rgb[8*c +: 8] = in_state_i[htx_raster_reg_pkg::RASTER_STATE_GOURAUD_LSB]
                           ? (r[CR-1] ? 8'd0 : (r > $signed(CR'(255)) ? 8'd255 : 8'(r)))
                           : in_flat_rgba_i[8*c +: 8];
  end

  logic unused;
  assign unused = ^{z_round_full[AccZ-1:ZR], in_flat_rgba_i[31:24]};

  logic valid_q;
  assign in_ready_o = !valid_q || out_ready_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q     <= 1'b0;
      out_x_o     <= '0;
      out_y_o     <= '0;
      out_addr_o  <= '0;
      out_z_o     <= '0;
      out_rgb_o   <= '0;
      out_state_o <= '0;
    end else if (abort_i) begin
      valid_q <= 1'b0;
    end else if (in_ready_o) begin
      valid_q <= in_valid_i;
      if (in_valid_i) begin
        out_x_o     <= in_x_i;
        out_y_o     <= in_y_i;
        out_addr_o  <= in_addr_i;
        out_z_o     <= z_clamped;
        out_rgb_o   <= rgb;
        out_state_o <= in_state_i;
      end
    end
  end
  assign out_valid_o = valid_q;
endmodule
