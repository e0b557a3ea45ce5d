// The raster unit's event counters (CNT_BUSY ... CNT_PIXELS) in one block RAM instead of N W-bit
// registers, each with its own adder (docs/area.md: the registers, adders and read multiplexer
// took about 480 LUT4 of the `icebreaker` GPU). Each counter keeps a small pending count in
// flip-flops; one adder folds the pending counts into the RAM words in turn, one counter a clock,
// so a pending count never exceeds N.
//
// A read of counter k waits (rd_ack_o low) until k's turn is in the write-back stage and returns
// the value written back then: every event up to two clocks before the acknowledge, so at most
// N + 1 clocks late, and exact whenever the counted events have stopped (an idle unit).
// clear_i zeroes every counter; the events of its own clock are not counted (as the registers did).
// After reset and after a clear, a word is taken as zero until its next turn has rewritten it
// (stale_q), so the RAM needs no initialisation. The turns advance only while there is something to
// fold in or a read waits: an idle unit's state stands still, as the simulated SoC's GPU clock gate
// requires (it stops the clock of an idle GPU and must not change the run).
module htx_raster_counters #(
  parameter int unsigned N  = 8,          // counters (a power of two)
  parameter int unsigned W  = 32,
  parameter int unsigned IW = $clog2(N)
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  input  logic          clear_i,
  input  logic [N-1:0]  inc_i,            // counter i counts one event this clock
  input  logic          rd_i,             // a read of counter rd_idx_i is waiting
  input  logic [IW-1:0] rd_idx_i,
  output logic          rd_ack_o,         // counter rd_idx_i's value is on rd_data_o (rd_i or not)
  output logic [W-1:0]  rd_data_o
);
  localparam int unsigned PW = IW + 1;    // a pending count reaches N between two turns

  logic [IW-1:0] turn_q;                  // the counter whose word is read this clock
  logic [PW-1:0] pend_q [N];
  logic [N-1:0]  stale_q;
  // Write-back stage: the counter whose word was read last (wb_valid_q until it is written).
  logic          wb_valid_q;
  logic [IW-1:0] wb_idx_q;
  logic [PW-1:0] wb_pend_q;
  logic          wb_stale_q;
  logic [W-1:0]  word_q, sum;
  logic          go, pending;

  always_comb begin
    pending = 1'b0;
    for (int i = 0; i < N; i++) pending = pending || (pend_q[i] != '0);
  end
  assign go = rd_i || (inc_i != '0) || pending;

  (* ram_style = "block" *) logic [W-1:0] mem_q [N];
  always_ff @(posedge clk_i) begin
    if (go) word_q <= mem_q[turn_q];
    if (wb_valid_q) mem_q[wb_idx_q] <= sum;  // another word than the one read (N > 1)
  end

  assign sum = (wb_stale_q ? '0 : word_q) + W'(wb_pend_q);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      turn_q     <= '0;
      stale_q    <= '1;
      wb_valid_q <= 1'b0;
      wb_idx_q   <= '0;
      wb_pend_q  <= '0;
      wb_stale_q <= 1'b1;
      for (int i = 0; i < N; i++) pend_q[i] <= '0;
    end else begin
      wb_valid_q <= go;
      if (go) begin
        turn_q     <= turn_q + 1'b1;
        wb_idx_q   <= turn_q;
        wb_pend_q  <= clear_i ? '0 : pend_q[turn_q];
        wb_stale_q <= clear_i || stale_q[turn_q];
      end
      if (clear_i) begin
        stale_q <= '1;
      end else if (go) begin
        stale_q[turn_q] <= 1'b0;
      end
      for (int i = 0; i < N; i++) begin
        if (clear_i) begin
          pend_q[i] <= '0;
        end else if (go && (turn_q == IW'(i))) begin
          pend_q[i] <= PW'(inc_i[i]);     // the old count goes to the write-back stage
        end else begin
          pend_q[i] <= pend_q[i] + PW'(inc_i[i]);
        end
      end
    end
  end

  assign rd_ack_o  = wb_valid_q && (wb_idx_q == rd_idx_i);
  assign rd_data_o = sum;
endmodule
