// The vertex FIFO: synchronous, registered read port (block RAM on iCE40), with a flush for abort.
// A pop presents the word on rdata_o in the next cycle. (htx_fifo_sync, the UART's FIFO, has
// no flush.)
//
// No read is of the word being written: a push writes at wptr_q and a pop reads a word pushed
// before (level > 0). So what the RAM returns for a read of the address being written is left to
// it (no_rw_check: Yosys builds no bypass, 40 LUT4 and 40 flip-flops on the board's GPU).
module htx_raster_fifo #(
  parameter int unsigned Depth = 64   // power of two
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic                     flush_i,
  input  logic                     push_i,   // ignored when full
  input  logic [31:0]              wdata_i,
  input  logic                     pop_i,    // ignored when empty
  output logic [31:0]              rdata_o,
  output logic                     full_o,
  output logic                     empty_o,
  output logic [$clog2(Depth):0]   level_o
);
  localparam int unsigned PtrW = $clog2(Depth);

  (* no_rw_check *) logic [31:0] mem_q [Depth];
  // Pointers with a wrap bit: written and popped.
  logic [PtrW:0]   wptr_q, rptr_q, level;
  logic            do_push, do_pop;

  assign level   = wptr_q - rptr_q;
  assign full_o  = level[PtrW];  // level <= Depth: its top bit is "== Depth"
  assign empty_o = (level == '0);
  assign level_o = level;
  assign do_push = push_i && !full_o && !flush_i;
  assign do_pop  = pop_i && !empty_o && !flush_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wptr_q <= '0;
      rptr_q <= '0;
    end else if (flush_i) begin
      wptr_q <= '0;
      rptr_q <= '0;
    end else begin
      if (do_push) wptr_q <= wptr_q + 1'b1;
      if (do_pop)  rptr_q <= rptr_q + 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (do_push) mem_q[wptr_q[PtrW-1:0]] <= wdata_i;
    if (do_pop)  rdata_o <= mem_q[rptr_q[PtrW-1:0]];
  end
endmodule
