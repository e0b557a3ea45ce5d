// Simple dual-port RAM for the framebuffer and depth buffer: one synchronous read port, one write
// port with per-lane enables. A read of the address being written returns the old value.
module htx_fb_ram #(
  parameter int unsigned LaneW = 16,
  parameter int unsigned Lanes = 1,
  parameter int unsigned Words = 1024,
  parameter int unsigned AW    = $clog2(Words)
) (
  input  logic                   clk_i,
  input  logic                   re_i,
  input  logic [AW-1:0]          raddr_i,
  output logic [LaneW*Lanes-1:0] rdata_o,
  input  logic [Lanes-1:0]       we_i,
  input  logic [AW-1:0]          waddr_i,
  input  logic [LaneW*Lanes-1:0] wdata_i
);
  logic [LaneW*Lanes-1:0] mem_q [Words] /* verilator public_flat_rw */;

  always_ff @(posedge clk_i) begin
    for (int l = 0; l < Lanes; l++) begin
      if (we_i[l]) mem_q[waddr_i][LaneW*l +: LaneW] <= wdata_i[LaneW*l +: LaneW];
    end
    if (re_i) rdata_o <= mem_q[raddr_i];
  end
endmodule
