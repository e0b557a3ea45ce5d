// Deliberately bad for Yosys 0.23: a multi-dimensional packed array, which it cannot read.
module lint_bad_packed2d (
  input  logic [1:0][7:0] pair_i,
  output logic [7:0]      first_o
);
  assign first_o = pair_i[0];
endmodule
