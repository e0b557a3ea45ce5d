// Three-cycle 32x32 multiplier for MUL/MULH/MULHSU/MULHU built from four unsigned 16x16 partial
// products, so that synth_ice40 -dsp maps exactly four SB_MAC16. Signed high halves come from the
// unsigned product: hi_signed = hi_unsigned - corr (mod 2^32), corr = (a<0 ? b : 0) + (b<0 ? a : 0).
// The unit forms no part of the correction itself: execute's ALU adds its two terms (decode
// registers a MUL-class instruction's ALU operands as those terms, each rs1 or rs2 or zero) and
// inverts the sum, so ncorr_i is ~corr (docs/cpu.md, "Multiply"). Nor does it subtract: the high
// partial product's DSP adds ~corr as it forms hh (hh - corr = hh + ~corr + 1), and the 1 rides on
// the lh product's DSP, which adds 2^16 to it, so that mid's upper half carries it into the high
// word (both sums fit their 32 bits: lh + 2^16 <= 0xFFFF_0001, and mid < 2^33 still). The two
// DSP adders replace a 32-bit subtractor and the correction's register.
//   cycle 1 (start_i): the partial products (hh with the correction, lh with 2^16) are registered
//                      in the DSPs;
//   cycle 2:           mid = lh + hl, then the low word ll + mid[15:0] << 16 and the high word
//                      hh' + mid[32:16] + the low word's carry are registered (two carry chains
//                      in series, starting from the DSP output registers);
//   cycle 3:           the selected word comes straight from a register (done_next_o was high in
//                      cycle 2; execute registers it into its own stall flip-flop).
module htx_cpu_mul (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        start_i,
  input  logic        high_i,   // the instruction in execute reads the high word (funct3 != 00)
  input  logic [31:0] a_i,
  input  logic [31:0] b_i,
  // ~corr for the instruction's signedness (MUL takes MULH's: its low word does not depend on it,
  // and its high word is then the one a fused MULH after it reads; see htx_cpu)
  input  logic [31:0] ncorr_i,
  output logic        busy_o,   // an operation is in flight: start_i is ignored
  output logic        done_next_o,  // result_o is the result from the next cycle on
  output logic [31:0] result_o
);

  logic [31:0] p_ll_q, p_lh_q, p_hl_q, p_hh_q;
  logic [31:0] lo_q, hi_q;
  logic [32:0] mid;
  logic [16:0] lo_upper;
  assign mid      = {1'b0, p_lh_q} + {1'b0, p_hl_q};
  assign lo_upper = {1'b0, p_ll_q[31:16]} + {1'b0, mid[15:0]};
  logic        step1_q, step2_q;

  always_ff @(posedge clk_i) begin
    if (start_i) begin
      p_ll_q <= a_i[15:0]  * b_i[15:0];
      p_lh_q <= a_i[15:0]  * b_i[31:16] + 32'h0001_0000;  // the 1 of -corr, at mid's bit 16
      p_hl_q <= a_i[31:16] * b_i[15:0];
      p_hh_q <= a_i[31:16] * b_i[31:16] + ncorr_i;        // hh - corr - 1
    end
    if (step1_q) begin
      lo_q <= {lo_upper[15:0], p_ll_q[15:0]};
      hi_q <= p_hh_q + {15'b0, mid[32:16]} + {31'b0, lo_upper[16]};
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      step1_q <= 1'b0;
      step2_q <= 1'b0;
    end else begin
      step1_q <= start_i && !busy_o;
      step2_q <= step1_q;
    end
  end

  assign busy_o   = step1_q || step2_q;
  assign done_next_o = step1_q;
  // Selected by the instruction now in execute (a fused instruction reads the half its
  // predecessor did not).
  assign result_o = high_i ? hi_q : lo_q;

endmodule
