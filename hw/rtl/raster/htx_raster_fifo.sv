// The vertex FIFO: synchronous, registered read port (block RAM on iCE40), with a flush for abort.
// A pop presents the word on rdata_o in the next cycle. (htx_fifo_sync, the UART's FIFO, has
// neither the flush nor the hold below.)
//
// Hold = 1 (`icebreaker`): a popped word keeps its place until release_i, so the record the input
// stage has popped stays in the RAM for setup to read again at random (peek_i: the word peek_off_i
// after the first one not yet released, on rdata_o in the next cycle, in a clock without a pop).
// release_i frees every word popped so far. full_o, empty_o and level_o count the words not yet
// released (the bus sees a held record as FIFO words); none_o is "nothing left to pop". Hold = 0
// releases each word as it is popped (peek_i and release_i are ignored; none_o is empty_o).
//
// No read is of the word being written: a push writes at wptr_q, a pop reads a word pushed before
// (avail > 0) and a peek a word of the held record, already popped. So what the RAM returns for a
// read of the address being written is left to it (no_rw_check: Yosys builds no bypass, 40 LUT4
// and 40 flip-flops on the board's GPU).
module htx_raster_fifo #(
  parameter int unsigned Depth = 64,  // power of two
  parameter bit          Hold  = 1'b0
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic                     flush_i,
  input  logic                     push_i,   // ignored when full
  input  logic [31:0]              wdata_i,
  input  logic                     pop_i,    // ignored when none_o
  output logic [31:0]              rdata_o,
  input  logic                     peek_i,
  input  logic [$clog2(Depth)-1:0] peek_off_i,
  input  logic                     release_i,
  output logic                     full_o,
  output logic                     empty_o,
  output logic                     none_o,
  output logic [$clog2(Depth):0]   level_o
);
  localparam int unsigned PtrW = $clog2(Depth);

  (* no_rw_check *) logic [31:0] mem_q [Depth];
  // Pointers with a wrap bit: written, popped, and released (the popped one without Hold).
  logic [PtrW:0]   wptr_q, rptr_q, fptr, level, avail;
  logic [PtrW-1:0] raddr;
  logic            do_push, do_pop, do_read;

  assign level   = wptr_q - fptr;
  assign avail   = wptr_q - rptr_q;
  assign full_o  = level[PtrW];  // level <= Depth: its top bit is "== Depth"
  assign empty_o = (level == '0);
  assign none_o  = (avail == '0);
  assign level_o = level;
  assign do_push = push_i && !full_o && !flush_i;
  assign do_pop  = pop_i && !none_o && !flush_i;

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

  if (Hold) begin : g_hold
    logic [PtrW:0] fptr_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        fptr_q <= '0;
      end else if (flush_i) begin
        fptr_q <= '0;
      end else if (release_i) begin
        fptr_q <= rptr_q + (PtrW+1)'(do_pop);
      end
    end
    assign fptr    = fptr_q;
    assign do_read = do_pop || (peek_i && !flush_i);
    assign raddr   = do_pop ? rptr_q[PtrW-1:0] : fptr_q[PtrW-1:0] + peek_off_i;
  end else begin : g_release_on_pop
    assign fptr    = rptr_q;
    assign do_read = do_pop;
    assign raddr   = rptr_q[PtrW-1:0];
    logic unused_hold;
    assign unused_hold = ^{peek_i, peek_off_i, release_i};
  end

  always_ff @(posedge clk_i) begin
    if (do_push) mem_q[wptr_q[PtrW-1:0]] <= wdata_i;
    if (do_read) rdata_o <= mem_q[raddr];
  end
endmodule
