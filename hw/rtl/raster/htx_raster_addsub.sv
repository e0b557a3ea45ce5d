// a + b or a - b on one adder: a - b is a + ~b + 1, and the + 1 goes in through an extra low bit
// ({a, 1} + {~b, 1}), so one carry chain serves both (written as a + b : a - b, synthesis builds two
// adders and a multiplexer). Used by the traversal's steps and the one-bit multiplier.
module htx_raster_addsub #(
  parameter int unsigned W = 32
) (
  input  logic [W-1:0] a_i,
  input  logic [W-1:0] b_i,
  input  logic         sub_i,
  output logic [W-1:0] sum_o
);
  logic [W:0] sum;
  assign sum   = {a_i, 1'b1} + {b_i ^ {W{sub_i}}, sub_i};
  assign sum_o = sum[W:1];
  logic unused;
  assign unused = sum[0];
endmodule
