// One texture memory bank: a simple dual-port RAM (one write port, one registered read port with
// enable, so the read data holds while the sampler stalls). Block RAM on iCE40. The caller never
// reads in a clock in which it writes (htx_tex_mem), so what a read of the address being written
// returns is left to the RAM (no_rw_check: Yosys builds no bypass for it, about 29 LUT4 and 18
// flip-flops a bank on the board's GPU).
module htx_tex_bank #(
  parameter int unsigned W  = 16,
  parameter int unsigned AW = 10
) (
  input  logic          clk_i,
  input  logic          we_i,
  input  logic [AW-1:0] waddr_i,
  input  logic [W-1:0]  wdata_i,
  input  logic          re_i,
  input  logic [AW-1:0] raddr_i,
  output logic [W-1:0]  rdata_o
);
  (* no_rw_check *) logic [W-1:0] mem_q [2**AW];
  always_ff @(posedge clk_i) begin
    if (we_i) mem_q[waddr_i] <= wdata_i;
  end
  always_ff @(posedge clk_i) begin
    if (re_i) rdata_o <= mem_q[raddr_i];
  end
endmodule
