// Iterative divider for DIV/DIVU/REM/REMU: one restoring step per cycle on the magnitudes, signs
// fixed in a final cycle into a result register, 35 cycles from start_i to done_o. Division by zero gives quotient all ones and
// remainder = dividend; -2^31 / -1 gives quotient -2^31 and remainder 0 (the RISC-V results).
module htx_cpu_div (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic        start_i,
  input  logic        kill_i,   // abandon an operation in flight
  input  logic [1:0]  op_i,     // funct3[1:0]: 00 DIV, 01 DIVU, 10 REM, 11 REMU
  input  logic [31:0] a_i,
  input  logic [31:0] b_i,
  output logic        busy_o,   // not idle: ignores start_i
  output logic        done_o,
  output logic [31:0] result_o
);

  typedef enum logic [1:0] {
    DivIdle = 2'd0,
    DivRun  = 2'd1,
    DivSign = 2'd2,
    DivDone = 2'd3
  } div_state_e;

  div_state_e  state_q;
  logic [4:0]  count_q;
  logic [31:0] rem_q, quo_q, divisor_q;
  logic        neg_result_q, want_rem_q;

  logic        is_signed, a_neg, b_neg;
  assign is_signed = ~op_i[0];
  assign a_neg     = is_signed & a_i[31];
  assign b_neg     = is_signed & b_i[31];

  // One restoring step: shift the next dividend bit into the partial remainder and subtract.
  logic [32:0] trial;
  logic [31:0] shifted;
  assign shifted = {rem_q[30:0], quo_q[31]};
  assign trial   = {rem_q[31], shifted} - {1'b0, divisor_q};

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= DivIdle;
      count_q <= 5'd0;
    end else if (kill_i) begin
      state_q <= DivIdle;
    end else begin
      unique case (state_q)
        DivIdle: if (start_i) begin
          state_q <= DivRun;
          count_q <= 5'd0;
        end
        DivRun: begin
          count_q <= count_q + 5'd1;
          if (count_q == 5'd31) begin
            state_q <= DivSign;
          end
        end
        DivSign: state_q <= DivDone;
        default: state_q <= DivIdle;
      endcase
    end
  end

  always_ff @(posedge clk_i) begin
    if (state_q == DivIdle && start_i) begin
      rem_q        <= 32'b0;
      quo_q        <= a_neg ? (32'b0 - a_i) : a_i;
      divisor_q    <= b_neg ? (32'b0 - b_i) : b_i;
      want_rem_q   <= op_i[1];
      // Remainder takes the dividend's sign; a quotient of a division by zero stays all ones.
      neg_result_q <= op_i[1] ? a_neg : ((a_neg ^ b_neg) && (b_i != 32'b0));
    end else if (state_q == DivRun) begin
      if (!trial[32]) begin
        rem_q <= trial[31:0];
        quo_q <= {quo_q[30:0], 1'b1};
      end else begin
        rem_q <= shifted;
        quo_q <= {quo_q[30:0], 1'b0};
      end
    end
  end

  logic [31:0] magnitude, result_q;
  assign magnitude = want_rem_q ? rem_q : quo_q;
  always_ff @(posedge clk_i) begin
    if (state_q == DivSign) begin
      result_q <= neg_result_q ? (32'b0 - magnitude) : magnitude;
    end
  end
  assign result_o  = result_q;
  assign done_o    = (state_q == DivDone);
  assign busy_o    = (state_q != DivIdle);

endmodule
