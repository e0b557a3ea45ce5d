// a + b or a - b on one adder: a - b is a + ~b + 1, and the + 1 goes in through an extra low bit
// ({a, 1} + {~b, 1}), so one carry chain serves both (written as a + b : a - b, synthesis builds two
// adders and a multiplexer). Used by the traversal's steps and the one-bit multiplier.
// ZeroLsbs: b's low bits that are always zero (a step of 256 g): the sum's low bits are a's, and
// only the bits above them are added (a - b = {a_hi - b_hi, a_lo} exactly: ~0 + 1 carries out),
// which Yosys does not find by itself.
module htx_raster_addsub #(
  parameter int unsigned W        = 32,
  parameter int unsigned ZeroLsbs = 0
) (
  input  logic [W-1:0] a_i,
  input  logic [W-1:0] b_i,
  input  logic         sub_i,
  output logic [W-1:0] sum_o
);
  localparam int unsigned HW = W - ZeroLsbs;
  logic [HW:0] sum;
  assign sum = {a_i[W-1:ZeroLsbs], 1'b1} + {b_i[W-1:ZeroLsbs] ^ {HW{sub_i}}, sub_i};
  if (ZeroLsbs > 0) begin : g_low
    assign sum_o = {sum[HW:1], a_i[ZeroLsbs-1:0]};
    logic unused_b;
    assign unused_b = ^b_i[ZeroLsbs-1:0];
  end else begin : g_all
    assign sum_o = sum[HW:1];
  end
  logic unused;
  assign unused = sum[0];
endmodule
