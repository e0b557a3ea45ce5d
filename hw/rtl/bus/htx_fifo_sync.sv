// Synchronous FIFO whose storage has a registered read port, so synthesis can place it in block RAM
// (iCE40 EBR) instead of flip-flops. A pop presents the popped word on rdata_o in the next cycle.
// A pop never reads the word being pushed (it reads only while the FIFO is not empty, and a push
// happens only while it is not full), so what the RAM returns then is left to it (no_rw_check:
// Yosys builds no bypass registers and multiplexer for it).
module htx_fifo_sync #(
  parameter int unsigned Width = 8,
  parameter int unsigned Depth = 16   // power of two
) (
  input  logic                     clk_i,
  input  logic                     rst_ni,
  input  logic                     push_i,   // ignored when full
  input  logic [Width-1:0]         wdata_i,
  input  logic                     pop_i,    // ignored when empty
  output logic [Width-1:0]         rdata_o,
  output logic                     full_o,
  output logic                     empty_o,
  output logic [$clog2(Depth):0]   level_o
);
  localparam int unsigned PtrWidth = $clog2(Depth);

  (* no_rw_check *) logic [Width-1:0] mem_q [Depth];
  logic [PtrWidth-1:0] wptr_q, rptr_q;
  logic [PtrWidth:0]   level_q;
  logic                do_push, do_pop;

  assign full_o  = (level_q == (PtrWidth+1)'(Depth));
  assign empty_o = (level_q == '0);
  assign level_o = level_q;
  assign do_push = push_i && !full_o;
  assign do_pop  = pop_i && !empty_o;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      wptr_q  <= '0;
      rptr_q  <= '0;
      level_q <= '0;
    end else begin
      if (do_push) wptr_q <= wptr_q + 1'b1;
      if (do_pop)  rptr_q <= rptr_q + 1'b1;
      level_q <= level_q + (PtrWidth+1)'(do_push) - (PtrWidth+1)'(do_pop);
    end
  end

  always_ff @(posedge clk_i) begin
    if (do_push) mem_q[wptr_q] <= wdata_i;
    if (do_pop)  rdata_o <= mem_q[rptr_q];
  end
endmodule
