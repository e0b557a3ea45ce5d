// Iterative divider for DIV/DIVU/REM/REMU: one restoring step per cycle on the magnitudes, 37
// cycles from start_i to the result (done_next_o is high in the cycle before it). Division by zero
// gives quotient all ones and remainder = dividend; -2^31 / -1 gives quotient -2^31 and remainder 0
// (the RISC-V results).
//
// One 33-bit adder does all the arithmetic: sum = {partial remainder, next dividend bit} + {1, addend}
// + carry. The two sign negations go through it as well, each in a cycle of its own with the
// remainder cleared (so the first operand is 0 and sum is (x ^ mask) + carry, i.e. x or -x): |a|
// before the steps and the signed result after them, both from addend_q. The divisor is never
// negated: during the steps the addend is the 33-bit value that subtracts its magnitude (-|b| is b
// itself when b < 0, ~b plus a carry-in of 1 otherwise), taken straight from b_i, which stays
// unchanged while execute holds the instruction (a register of its own for it cost 51 LUT4 more).
// Compared with separate negators this saves about 100 LUT4 for two cycles per division.
//
// a_i, b_i and op_i must stay unchanged from start_i until the result (execute holds the
// instruction). Execute registers done_next_o into its own stall flip-flop, so the unit keeps no
// done flag of its own. result_o is 0 from the edge at which execute takes a new instruction
// (clear_i) until a result replaces it, so execute ORs it into its result without a select.
module htx_cpu_div (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        start_i,
  input  logic        kill_i,   // abandon an operation in flight
  input  logic        clear_i,  // execute takes a new instruction: result_o becomes 0
  input  logic [1:0]  op_i,     // funct3[1:0]: 00 DIV, 01 DIVU, 10 REM, 11 REMU
  input  logic [31:0] a_i,
  input  logic [31:0] b_i,
  input  logic        b_zero_i,  // b_i == 0 (execute's adder tests it), valid with start_i
  output logic        busy_o,   // not idle: ignores start_i
  output logic        done_next_o,  // result_o is the result from the next cycle on
  output logic [31:0] result_o
);

  typedef enum logic [2:0] {
    DivIdle = 3'd0,
    DivAbsA = 3'd1,  // quo_q <= |a|
    DivRun  = 3'd2,  // 32 restoring steps
    DivSign = 3'd3,  // addend_q <= magnitude with the result's sign mask, remainder cleared
    DivFix  = 3'd4,  // quo_q <= signed result
    DivDone = 3'd5
  } div_state_e;

  div_state_e  state_q;
  logic [4:0]  count_q;
  logic [31:0] rem_q, quo_q;
  logic [31:0] addend_q;
  logic        carry_q;
  logic        neg_result_q, want_rem_q;

  logic        is_signed, a_neg, b_neg;
  assign is_signed = ~op_i[0];
  assign a_neg     = is_signed & a_i[31];
  assign b_neg     = is_signed & b_i[31];

  // During the steps: shift the next dividend bit into the partial remainder and subtract |b|.
  logic [32:0] sum;
  logic [31:0] shifted;
  assign shifted = {rem_q[30:0], quo_q[31]};
  // The divisor's addend comes straight from b_i during the steps (it is stable while execute
  // holds the instruction), so addend_q only ever takes |a| and the signed result's operand.
  logic [31:0] addend;
  logic        carry_in;
  assign addend   = (state_q == DivRun) ? (b_neg ? b_i : ~b_i) : addend_q;
  assign carry_in = (state_q == DivRun) ? !b_neg : carry_q;
  assign sum      = {rem_q[31], shifted} + {1'b1, addend} + {32'b0, carry_in};

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= DivIdle;
      count_q <= 5'd0;
    end else if (kill_i) begin
      state_q <= DivIdle;
    end else begin
      unique case (state_q)
        DivIdle: if (start_i) begin
          state_q <= DivAbsA;
          count_q <= 5'd0;
        end
        DivAbsA: state_q <= DivRun;
        DivRun: begin
          count_q <= count_q + 5'd1;
          if (count_q == 5'd31) begin
            state_q <= DivSign;
          end
        end
        DivSign: state_q <= DivFix;
        DivFix:  state_q <= DivDone;
        default: state_q <= DivIdle;
      endcase
    end
  end

  logic [31:0] magnitude;
  assign magnitude = want_rem_q ? rem_q : quo_q;

  always_ff @(posedge clk_i) begin
    unique case (state_q)
      DivIdle: if (start_i) begin
        rem_q        <= 32'b0;
        quo_q        <= 32'b0;
        addend_q     <= a_i ^ {32{a_neg}};
        carry_q      <= a_neg;
        want_rem_q   <= op_i[1];
        // Remainder takes the dividend's sign; a quotient of a division by zero stays all ones.
        neg_result_q <= op_i[1] ? a_neg : ((a_neg ^ b_neg) && !b_zero_i);
      end
      DivAbsA: quo_q <= sum[31:0];
      DivRun: begin
        if (!sum[32]) begin
          rem_q <= sum[31:0];
          quo_q <= {quo_q[30:0], 1'b1};
        end else begin
          rem_q <= shifted;
          quo_q <= {quo_q[30:0], 1'b0};
        end
      end
      DivSign: begin
        rem_q    <= 32'b0;
        quo_q    <= 32'b0;
        addend_q <= magnitude ^ {32{neg_result_q}};
        carry_q  <= neg_result_q;
      end
      DivFix: quo_q <= sum[31:0];
      default: ;
    endcase
    if (clear_i) begin
      quo_q <= 32'b0;
    end
  end

  assign result_o = quo_q;
  assign done_next_o = !kill_i && (state_q == DivFix);
  assign busy_o   = (state_q != DivIdle);

endmodule
