// The vertex FIFO: synchronous, registered read port (block RAM on iCE40), with a flush for abort.
// A pop presents the word on rdata_o in the next cycle.
//
// Hold = 1 (`icebreaker`): a popped word keeps its place until release_i, so the record the input
// stage has popped stays in the RAM for setup to read again at random (peek_i: the word peek_off_i
// after the first one not yet released, on rdata_o in the next cycle, in a clock without a pop).
// release_i frees every word popped so far. full_o, empty_o and level_o count the words not yet
// released (the bus sees a held record as FIFO words); none_o is "nothing left to pop".
module htx_raster_fifo #(
  parameter int unsigned Depth = 64,  // power of two
  parameter bit          Hold  = 1'b0
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   flush_i,
  input  logic                   push_i,   // ignored when full
  input  logic [31:0]            wdata_i,
  input  logic                   pop_i,    // ignored when none_o
  output logic [31:0]            rdata_o,
  input  logic                   peek_i,
  input  logic [$clog2(Depth)-1:0] peek_off_i,
  input  logic                   release_i,
  output logic                   full_o,
  output logic                   empty_o,
  output logic                   none_o,
  output logic [$clog2(Depth):0] level_o
);
  localparam int unsigned PtrW = $clog2(Depth);

  logic [31:0]     mem_q [Depth];
  logic [PtrW-1:0] raddr, waddr;
  logic            do_push, do_pop, do_read;

  if (!Hold) begin : g_plain
    logic [PtrW-1:0] wptr_q, rptr_q;
    logic [PtrW:0]   level_q;
    assign full_o  = level_q[PtrW];  // level_q <= Depth: its top bit is "== Depth"
    assign empty_o = (level_q == '0);
    assign none_o  = empty_o;
    assign level_o = level_q;
    assign do_push = push_i && !full_o && !flush_i;
    assign do_pop  = pop_i && !empty_o && !flush_i;
    assign do_read = do_pop;
    assign raddr   = rptr_q;
    assign waddr   = wptr_q;

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        wptr_q  <= '0;
        rptr_q  <= '0;
        level_q <= '0;
      end else if (flush_i) begin
        wptr_q  <= '0;
        rptr_q  <= '0;
        level_q <= '0;
      end else begin
        if (do_push) wptr_q <= wptr_q + 1'b1;
        if (do_pop)  rptr_q <= rptr_q + 1'b1;
        level_q <= level_q + (PtrW+1)'(do_push) - (PtrW+1)'(do_pop);
      end
    end
    logic unused_hold;
    assign unused_hold = ^{peek_i, peek_off_i, release_i};
  end else begin : g_hold
    // Pointers with a wrap bit: written, popped, released.
    logic [PtrW:0] wptr_q, rptr_q, fptr_q, level, avail;
    assign level   = wptr_q - fptr_q;
    assign avail   = wptr_q - rptr_q;
    assign full_o  = level[PtrW];
    assign empty_o = (level == '0);
    assign none_o  = (avail == '0);
    assign level_o = level;
    assign do_push = push_i && !full_o && !flush_i;
    assign do_pop  = pop_i && !none_o && !flush_i;
    assign do_read = do_pop || (peek_i && !flush_i);
    assign raddr   = do_pop ? rptr_q[PtrW-1:0] : fptr_q[PtrW-1:0] + peek_off_i;
    assign waddr   = wptr_q[PtrW-1:0];

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        wptr_q <= '0;
        rptr_q <= '0;
        fptr_q <= '0;
      end else if (flush_i) begin
        wptr_q <= '0;
        rptr_q <= '0;
        fptr_q <= '0;
      end else begin
        if (do_push)   wptr_q <= wptr_q + 1'b1;
        if (do_pop)    rptr_q <= rptr_q + 1'b1;
        if (release_i) fptr_q <= rptr_q + (PtrW+1)'(do_pop);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (do_push) mem_q[waddr] <= wdata_i;
    if (do_read) rdata_o <= mem_q[raddr];
  end
endmodule
