// 31 x 32-bit register file with two synchronous read ports and one write port, written so that
// Yosys maps it to iCE40 block RAM (one copy per read port). The write port is clocked on the
// falling edge, so a read on the next rising edge already returns the value written in the same
// cycle: the pipeline needs no bypass for a write that coincides with a read (it forwards only E's
// and W's results). The write data and enable therefore have half a cycle (htx_cpu arranges them
// for it). Entry 0 is never written (the pipeline's rd_we is false for x0) and reads 0.
module htx_cpu_regfile (
  input  logic        clk_i,
  input  logic [4:0]  raddr_a_i,
  input  logic [4:0]  raddr_b_i,
  output logic [31:0] rdata_a_o,
  output logic [31:0] rdata_b_o,
  input  logic        we_i,
  input  logic [4:0]  waddr_i,
  input  logic [31:0] wdata_i
);

  // Reads and writes never meet on one edge, so synthesis adds no collision logic.
  (* no_rw_check *) logic [31:0] mem_q [32];

  initial begin
    for (int i = 0; i < 32; i++) begin
      mem_q[i] = 32'b0;
    end
  end

  always_ff @(negedge clk_i) begin
    if (we_i) begin
      mem_q[waddr_i] <= wdata_i;
    end
  end

  always_ff @(posedge clk_i) begin
    rdata_a_o <= mem_q[raddr_a_i];
    rdata_b_o <= mem_q[raddr_b_i];
  end

endmodule
