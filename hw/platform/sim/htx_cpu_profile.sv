// Cycle accounting of the CPU (simulation only, `htx sim --profile`): every clock after reset is
// charged to exactly one cause, judged at the execute stage (E), so the counts add up to the
// clocks run. A clock in which E completes an instruction is `Execute`; a clock in which E holds
// one that cannot complete is charged to what it waits for; a clock in which E is empty is charged
// to why no instruction reached it, a cause carried down with the bubble from where it began (D's
// hazard, or why D was empty: a redirect and its refill, a predicted jump's bubble, or fetch).
// The inputs are the core's own control signals, taken by hierarchical reference (htx_soc_sim_top).
module htx_cpu_profile (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        e_valid_i,      // E holds an instruction (it may be squashed)
  input  logic        e_done_i,       // E completes its instruction this clock
  input  logic        e_accept_i,     // E's register takes what D hands over (or a bubble)
  input  logic        e_load_i,       // E's instruction is a load (the producer of a D hazard)
  input  logic        e_block_i,      // E waits for its multiply/divide, or its CSR instruction for W
                                      // and the counters (the core's own e_block)
  input  logic        unit_wait_i,    // E's multiply or divide is still working
  input  logic        w_ready_i,      // W completes (no data response outstanding)
  input  logic        w_trap_i,       // W takes a trap (everything younger is squashed)
  input  logic        redirect_i,     // a registered redirect acts: D and E are squashed
  input  logic        d_valid_i,      // D holds an instruction (it may be squashed)
  input  logic        d_go_i,         // D hands its instruction to E
  input  logic        d_hazard_i,     // D waits for a late result of E's instruction
  input  logic        d_free_i,       // D's register loads this clock
  input  logic        d_jump_i,       // D's predicted jump redirects fetch this clock
  input  logic        f_take_i,       // D takes fetch's output if valid
  input  logic        f_valid_i       // fetch has an instruction for D
);

  typedef enum logic [3:0] {
    CauseExecute    = 4'd0,  // E completes an instruction
    CauseDataBus    = 4'd1,  // a load/store waits for the data bus (request or response)
    CauseMulDiv     = 4'd2,  // a multiply or divide is working
    CauseCsrOrder   = 4'd3,  // a CSR instruction waits for W to drain and the counters to settle
    CauseLoadUse    = 4'd4,  // the next instruction waited for a load's data
    CauseLateResult = 4'd5,  // ... for a shift, SLT, link, CSR, MUL or DIV result (from W only)
    CauseRedirect   = 4'd6,  // squashed or refilling after a mispredicted branch, JALR, trap, MRET, FENCE.I
    CauseJump       = 4'd7,  // the bubble of a predicted-taken branch or JAL
    CauseFetch      = 4'd8   // fetch had no instruction (instruction-bus wait states)
  } cause_e;

  localparam int unsigned NumCauses = 9;

  // Public so the harness reads the counts after the run.
  logic [63:0] count_q [NumCauses] /* verilator public_flat_rd */;

  cause_e d_cause_q, e_cause_q;    // why D, E are empty (valid while they are)
  cause_e refill_cause_q;
  logic   refill_q;                // fetch is refilling after a redirect or a predicted jump

  logic   d_takes;                 // D takes an instruction from fetch this clock
  assign d_takes = d_free_i && f_take_i && f_valid_i;

  cause_e d_empty_cause, e_empty_cause, now;
  assign d_empty_cause = redirect_i ? CauseRedirect :
                         d_jump_i   ? CauseJump     :
                         refill_q   ? refill_cause_q : CauseFetch;
  // (A live D without a hazard hands over whenever E accepts, so its CauseFetch is not reached.)
  assign e_empty_cause = redirect_i ? CauseRedirect :
                         d_valid_i  ? (d_hazard_i ? (e_load_i ? CauseLoadUse : CauseLateResult)
                                                  : CauseFetch) :
                         d_cause_q;

  always_comb begin
    if (e_valid_i && redirect_i) begin
      now = CauseRedirect;
    end else if (!e_valid_i) begin
      now = e_cause_q;
    end else if (e_done_i) begin
      now = CauseExecute;
    end else if (w_trap_i) begin
      now = CauseRedirect;
    end else if (!w_ready_i) begin
      now = CauseDataBus;
    end else if (unit_wait_i) begin
      now = CauseMulDiv;
    end else if (e_block_i) begin
      now = CauseCsrOrder;  // (a CSR instruction is never a multiply or divide)
    end else begin
      now = CauseDataBus;  // the request is not accepted yet
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      d_cause_q      <= CauseFetch;
      e_cause_q      <= CauseFetch;
      refill_cause_q <= CauseFetch;
      refill_q       <= 1'b0;
      for (int i = 0; i < NumCauses; i++) begin
        count_q[i] <= 64'd0;
      end
    end else begin
      count_q[now] <= count_q[now] + 64'd1;
      if (d_free_i && !d_takes) begin
        d_cause_q <= d_empty_cause;
      end
      if (e_accept_i && !d_go_i) begin
        e_cause_q <= e_empty_cause;
      end
      if (redirect_i || d_jump_i) begin
        refill_q       <= 1'b1;
        refill_cause_q <= redirect_i ? CauseRedirect : CauseJump;
      end else if (d_takes) begin
        refill_q <= 1'b0;
      end
    end
  end

endmodule
