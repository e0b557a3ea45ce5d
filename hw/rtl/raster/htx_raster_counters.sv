// The raster unit's event counters (CNT_BUSY ... CNT_PIXELS) in one block RAM instead of N 32-bit
// registers, each with its own adder (docs/area.md: the registers, adders and read multiplexer
// took about 480 LUT4 of the `icebreaker` GPU). Each counter keeps a small pending count in
// flip-flops; one 16-bit adder folds the pending counts into the RAM in turn, a counter's low half
// and then its high half (with the low half's carry) in consecutive clocks, so the N counters take
// 2N clocks a round and the RAM is one EBR (256 x 16). A pending count never exceeds 2N.
//
// A read of counter k waits (rd_ack_o low) until k's high half is in the write-back stage and
// returns both halves as written back: every event up to three clocks before the acknowledge, so at
// most 2N + 1 clocks late, and exact whenever the counted events have stopped (an idle unit).
// clear_i zeroes every counter (a read acknowledged in the two clocks after it returns 0); the
// events of its own clock are not counted (as the registers did). After reset and after a clear, a
// counter's words are taken as zero until its next round has rewritten them (stale_q), so the RAM
// needs no initialisation. The rounds advance only while there is something to fold in or a read
// waits (and never stop between a counter's two halves): an idle unit's state stands still, as the
// simulated SoC's GPU clock gate requires (it stops the clock of an idle GPU and must not change
// the run).
module htx_raster_counters #(
  parameter int unsigned N  = 8,          // counters (a power of two)
  parameter int unsigned IW = $clog2(N)
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  input  logic          clear_i,
  input  logic [N-1:0]  inc_i,            // counter i counts one event this clock
  input  logic          rd_i,             // a read of counter rd_idx_i is waiting
  input  logic [IW-1:0] rd_idx_i,
  output logic          rd_ack_o,         // counter rd_idx_i's value is on rd_data_o (rd_i or not)
  output logic [31:0]   rd_data_o
);
  localparam int unsigned PW = IW + 2;    // a pending count reaches 2N between two rounds

  logic [IW:0]   turn_q;                  // {counter, half} whose word is read this clock
  logic [PW-1:0] pend_q [N];
  logic [N-1:0]  stale_q;
  // Write-back stage: the word read last (wb_valid_q until it is written) and what it gets added.
  logic          wb_valid_q, wb_stale_q;
  logic [IW:0]   wb_slot_q;
  logic [PW-1:0] wb_add_q;
  logic [15:0]   word_q, lo_q;
  logic [16:0]   sum;
  logic          go, pending, carry;
  logic [IW-1:0] turn_ctr;

  assign turn_ctr = turn_q[IW:1];
  always_comb begin
    pending = 1'b0;
    for (int i = 0; i < N; i++) pending = pending || (pend_q[i] != '0);
  end
  // A high half is always read in the clock after its low half, so the low half's carry comes
  // straight from the write-back stage.
  assign go    = rd_i || (inc_i != '0) || pending || turn_q[0];
  assign sum   = {1'b0, wb_stale_q ? 16'b0 : word_q} + 17'(wb_add_q);
  assign carry = sum[16];

  (* ram_style = "block" *) logic [15:0] mem_q [2 * N];
  always_ff @(posedge clk_i) begin
    if (go) word_q <= mem_q[turn_q];
    if (wb_valid_q) mem_q[wb_slot_q] <= sum[15:0];  // another word than the one read (N > 0)
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      turn_q     <= '0;
      stale_q    <= '1;
      wb_valid_q <= 1'b0;
      wb_slot_q  <= '0;
      wb_add_q   <= '0;
      wb_stale_q <= 1'b1;
      lo_q       <= '0;
      for (int i = 0; i < N; i++) pend_q[i] <= '0;
    end else begin
      wb_valid_q <= go;
      if (go) begin
        turn_q     <= turn_q + 1'b1;
        wb_slot_q  <= turn_q;
        wb_stale_q <= clear_i || stale_q[turn_ctr];
        wb_add_q   <= clear_i ? '0 : (turn_q[0] ? PW'(carry) : pend_q[turn_ctr]);
      end
      if (clear_i) begin
        stale_q <= '1;
      end else if (go && turn_q[0]) begin
        stale_q[turn_ctr] <= 1'b0;        // both halves rewritten by this round
      end
      if (clear_i) begin
        lo_q <= '0;
      end else if (wb_valid_q && !wb_slot_q[0]) begin
        lo_q <= sum[15:0];
      end
      for (int i = 0; i < N; i++) begin
        if (clear_i) begin
          pend_q[i] <= '0;
        end else if (go && !turn_q[0] && (turn_ctr == IW'(i))) begin
          pend_q[i] <= PW'(inc_i[i]);     // the old count goes to the write-back stage
        end else begin
          pend_q[i] <= pend_q[i] + PW'(inc_i[i]);
        end
      end
    end
  end

  assign rd_ack_o  = wb_valid_q && (wb_slot_q == {rd_idx_i, 1'b1});
  assign rd_data_o = {sum[15:0], lo_q};
endmodule
