// 64-bit writable counter (the CPU's mcycle and minstret, the timer's mtime). Each 32-bit half can
// be written; the other half keeps counting.
//
// CarryReg = 1 registers the carry from the low half into the high half, so each 32-bit carry
// chain starts at a flip-flop (the CPU's counters, where a 64-bit chain would not meet the core's
// clock): the high half follows a wrap one cycle later, and carry_pending_o is high in that cycle.
// CarryReg = 0 carries through in the same cycle (the timer, whose compare sees every value).
//
// With HTX_ICE40 defined (the iCE40 synthesis flows) each bit is one SB_LUT4 and one SB_CARRY:
// the write enable is the carry cell's second operand, so the chain computes garbage while the
// half is written, which does not matter since the written value is taken (and the carry into a
// high half that is not written is masked while the low half is). Yosys builds the same function
// from the behavioural code with a second LUT per bit for the write multiplexer.
module htx_counter64 #(
  parameter bit CarryReg = 1'b1
) (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        inc_i,     // add one this cycle
  input  logic        wr_lo_i,   // write wdata_i to bits 31:0 instead of counting
  input  logic        wr_hi_i,   // write wdata_i to bits 63:32 instead of counting
  input  logic [31:0] wdata_i,
  output logic [63:0] count_o,
  output logic        carry_pending_o
);

  logic [31:0] lo_q, hi_q, lo_d, hi_d;
  logic        carry_q, lo_carry, hi_cin;

  // The carry into the high half: this cycle's (CarryReg = 0) or the last cycle's.
  assign hi_cin = CarryReg ? carry_q : lo_carry;

`ifdef HTX_ICE40
  logic [32:0] lo_c, hi_c;
  assign lo_c[0] = inc_i;
  assign hi_c[0] = hi_cin;
  for (genvar i = 0; i < 32; i++) begin : g_bit
    // O = I2 ? I0 : I1 ^ I3  (I0 write data, I1 count bit, I2 write enable, I3 carry in)
    SB_LUT4 #(.LUT_INIT(16'hA3AC)) u_lo_lut (
      .O(lo_d[i]), .I0(wdata_i[i]), .I1(lo_q[i]), .I2(wr_lo_i), .I3(lo_c[i]));
    SB_CARRY u_lo_carry (.CO(lo_c[i+1]), .I0(lo_q[i]), .I1(wr_lo_i), .CI(lo_c[i]));
    SB_LUT4 #(.LUT_INIT(16'hA3AC)) u_hi_lut (
      .O(hi_d[i]), .I0(wdata_i[i]), .I1(hi_q[i]), .I2(wr_hi_i), .I3(hi_c[i]));
    SB_CARRY u_hi_carry (.CO(hi_c[i+1]), .I0(hi_q[i]), .I1(wr_hi_i), .CI(hi_c[i]));
  end
  assign lo_carry = lo_c[32] && !wr_lo_i;
  logic unused_hi_carry;
  assign unused_hi_carry = hi_c[32];
`else
  logic [32:0] lo_sum;
  assign lo_sum   = {1'b0, lo_q} + {32'b0, inc_i};
  assign lo_d     = wr_lo_i ? wdata_i : lo_sum[31:0];
  assign lo_carry = lo_sum[32] && !wr_lo_i;
  assign hi_d     = wr_hi_i ? wdata_i : (hi_q + {31'b0, hi_cin});
`endif

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      lo_q    <= 32'b0;
      hi_q    <= 32'b0;
      carry_q <= 1'b0;
    end else begin
      lo_q    <= lo_d;
      hi_q    <= hi_d;
      carry_q <= CarryReg && lo_carry;
    end
  end

  assign count_o         = {hi_q, lo_q};
  assign carry_pending_o = carry_q;

endmodule
