// Bilinear blend of one 8-bit channel (model bilinear_blend):
//   ((256-wu)(256-wv) c00 + wu (256-wv) c10 + (256-wu) wv c01 + wu wv c11 + 2^15) >> 16,
// computed exactly as two row interpolations h = 256 c0 + wu (c1 - c0) and one column
// interpolation 256 h0 + wv (h1 - h0) (the same sum, regrouped; nothing is rounded in between).
module htx_tex_bilerp #(
  parameter bit ShiftAdd = 1'b0
) (
  input  logic [7:0] c00_i, c10_i, c01_i, c11_i,
  input  logic [7:0] wu_i, wv_i,
  output logic [7:0] c_o
);
  logic signed [8:0]  d0, d1;
  logic signed [17:0] p0, p1;
  logic [15:0]        h0, h1;
  logic signed [16:0] dh;
  logic signed [25:0] ph;
  logic [23:0]        tot;

  assign d0 = $signed({1'b0, c10_i}) - $signed({1'b0, c00_i});
  assign d1 = $signed({1'b0, c11_i}) - $signed({1'b0, c01_i});
  htx_tex_mul #(.AW(9), .ShiftAdd(ShiftAdd)) u_m0 (.a_i(d0), .w_i(wu_i), .p_o(p0));
  htx_tex_mul #(.AW(9), .ShiftAdd(ShiftAdd)) u_m1 (.a_i(d1), .w_i(wu_i), .p_o(p1));
  assign h0 = 16'({c00_i, 8'd0} + 16'(p0));
  assign h1 = 16'({c01_i, 8'd0} + 16'(p1));
  assign dh = $signed({1'b0, h1}) - $signed({1'b0, h0});
  htx_tex_mul #(.AW(17), .ShiftAdd(ShiftAdd)) u_m2 (.a_i(dh), .w_i(wv_i), .p_o(ph));
  assign tot = 24'({h0, 8'd0} + 24'(ph));
  assign c_o = 8'((25'(tot) + 25'd32768) >> 16);

  logic unused;
  assign unused = ^{p0[17:16], p1[17:16], ph[25:24]};
endmodule
