// Deliberately bad: assigns a 9-bit sum to an 8-bit output (Verilator -Wall: WIDTHTRUNC).
module lint_bad_width (
  input  logic [7:0] a_i,
  input  logic [7:0] b_i,
  output logic [7:0] sum_o
);
  logic [8:0] sum;
  assign sum = {1'b0, a_i} + {1'b0, b_i};
  assign sum_o = sum;
endmodule
