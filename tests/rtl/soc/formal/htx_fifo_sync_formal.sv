// Formal harness (Yosys `sat`): htx_fifo_sync (the UART's FIFOs) under any sequence of pushes and
// pops. One pushed word, chosen by the solver (mark_i), is followed through the FIFO: it comes
// out unchanged, one cycle after the pop that finds it at the head, which is the pop after every
// word pushed before it has gone. Because the solver may mark any push, this covers every word.
// A push while full and a pop while empty change nothing; full, empty and the level agree with a
// count kept here.
module htx_fifo_sync_formal (
  input logic       clk_i,
  input logic       rst_ni,
  input logic       push_i,
  input logic [7:0] wdata_i,
  input logic       pop_i,
  input logic       mark_i
);
  localparam int unsigned Depth = 4;

  logic [7:0] rdata;
  logic       full, empty;
  logic [2:0] level;

  htx_fifo_sync #(.Width(8), .Depth(Depth)) u_fifo (
    .clk_i,
    .rst_ni,
    .push_i,
    .wdata_i,
    .pop_i,
    .rdata_o (rdata),
    .full_o  (full),
    .empty_o (empty),
    .level_o (level)
  );

  logic past_valid_q = 1'b0;
  always_ff @(posedge clk_i) begin
    past_valid_q <= 1'b1;
  end

  logic [2:0] n_q = 3'd0;       // words in the FIFO
  logic       accepted, taken;  // a push that is kept, a pop that takes a word
  assign accepted = push_i && n_q != 3'(Depth);
  assign taken    = pop_i && n_q != 3'd0;

  // The marked word: pending while in the FIFO, with the number of words ahead of it.
  logic       marked_q = 1'b0;
  logic       pending_q = 1'b0;
  logic [2:0] ahead_q;
  logic [7:0] word_q;
  logic       out_q = 1'b0;     // the marked word was popped last cycle
  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      n_q       <= 3'd0;
      marked_q  <= 1'b0;
      pending_q <= 1'b0;
      out_q     <= 1'b0;
    end else begin
      n_q   <= n_q + 3'(accepted) - 3'(taken);
      out_q <= pending_q && taken && ahead_q == 3'd0;
      if (pending_q && taken) begin
        if (ahead_q == 3'd0) begin
          pending_q <= 1'b0;
        end else begin
          ahead_q <= ahead_q - 3'd1;
        end
      end
      if (mark_i) begin
        marked_q  <= 1'b1;
        pending_q <= 1'b1;
        word_q    <= wdata_i;
        ahead_q   <= n_q - 3'(taken);
      end
    end
  end

  always_comb begin
    if (!past_valid_q) begin
      assume (!rst_ni);
    end
    // Only one word is marked, and only a push that is kept.
    if (mark_i) begin
      assume (rst_ni && accepted && !marked_q);
    end
    if (rst_ni) begin
      assert (level == n_q);
      assert (full == (n_q == 3'(Depth)));
      assert (empty == (n_q == 3'd0));
      if (out_q) begin
        assert (rdata == word_q);
      end
    end
  end

  // Reachability: the marked word comes out after the FIFO was full with it inside.
  (* keep *) logic cov_marked_out_after_full;
  logic full_with_mark_q = 1'b0;
  always_ff @(posedge clk_i) begin
    full_with_mark_q <= rst_ni && (full_with_mark_q || (pending_q && full));
  end
  assign cov_marked_out_after_full = rst_ni && full_with_mark_q && out_q;
endmodule
