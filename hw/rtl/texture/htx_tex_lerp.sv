// Linear blend of one 8-bit channel between two levels (model linear_blend):
// (a (256 - w) + b w + 128) >> 8, computed as (256 a + w (b - a) + 128) >> 8.
module htx_tex_lerp #(
  parameter bit ShiftAdd = 1'b0
) (
  input  logic [7:0] a_i, b_i, w_i,
  output logic [7:0] c_o
);
  logic signed [8:0]  d;
  logic signed [17:0] p;
  logic [15:0]        s;
  assign d = $signed({1'b0, b_i}) - $signed({1'b0, a_i});
  htx_tex_mul #(.AW(9), .ShiftAdd(ShiftAdd)) u_m (.a_i(d), .w_i(w_i), .p_o(p));
  assign s   = 16'({a_i, 8'd0} + 16'(p) + 16'd128);
  assign c_o = s[15:8];

  logic unused;
  assign unused = ^{p[17:16], s[7:0]};
endmodule
