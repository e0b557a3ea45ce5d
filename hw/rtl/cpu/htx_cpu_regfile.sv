// 31 x 32-bit register file with two synchronous read ports and one write port, written so that
// Yosys maps it to iCE40 block RAM (one copy per read port). A read returns the contents from
// before a write to the same address in the same cycle; the pipeline bypasses that write itself.
// Entry 0 is never written and reads 0.
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

  // A same-cycle read of the address being written may return anything (the pipeline forwards that
  // write itself), so synthesis adds no collision logic around the block RAM.
  (* no_rw_check *) logic [31:0] mem_q [32];

  initial begin
    for (int i = 0; i < 32; i++) begin
      mem_q[i] = 32'b0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (we_i && (waddr_i != 5'd0)) begin
      mem_q[waddr_i] <= wdata_i;
    end
    rdata_a_o <= mem_q[raddr_a_i];
    rdata_b_o <= mem_q[raddr_b_i];
  end

endmodule
