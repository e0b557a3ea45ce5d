// Dual-ported RAM with two bus slave ports: port A for instruction fetch, port B for data. Both are
// always ready and answer one cycle after acceptance, so fetch and data accesses proceed in parallel,
// one each per clock. Port A is read-only (a write there is answered with rsp_err), which maps to one write
// and two read ports (on iCE40: the RAM duplicated across EBRs). The simulation harness fills mem_q
// directly before reset; on a board, InitFile (a $readmemh image) preloads it.
module htx_ram_dp #(
  parameter int unsigned Bytes    = 4096,   // power of two
  parameter              InitFile = ""
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        a_req_valid_i,
  output logic        a_req_ready_o,
  input  logic [31:0] a_req_addr_i,
  input  logic        a_req_we_i,
  input  logic [3:0]  a_req_be_i,
  input  logic [31:0] a_req_wdata_i,
  output logic        a_rsp_valid_o,
  output logic [31:0] a_rsp_rdata_o,
  output logic        a_rsp_err_o,

  input  logic        b_req_valid_i,
  output logic        b_req_ready_o,
  input  logic [31:0] b_req_addr_i,
  input  logic        b_req_we_i,
  input  logic [3:0]  b_req_be_i,
  input  logic [31:0] b_req_wdata_i,
  output logic        b_rsp_valid_o,
  output logic [31:0] b_rsp_rdata_o,
  output logic        b_rsp_err_o
);
  localparam int unsigned Words     = Bytes / 4;
  localparam int unsigned WordWidth = $clog2(Words);

  // no_rw_check: a fetch from the word that port B writes in the same clock may read anything on a
  // board (the block RAMs' collision behaviour) and reads the old word in simulation. Only code
  // that stores into the instruction stream without FENCE.I does that (FENCE.I refetches after the
  // store has completed). Without it Yosys emulates read-before-write: on the ECP5 two copies of
  // the RAM (128 block RAMs instead of 64) and collision logic (docs/boards.md).
  (* no_rw_check *) logic [31:0] mem_q [Words] /* verilator public_flat_rw */;
  logic [WordWidth-1:0] a_word, b_word;
  logic [31:0] a_rdata_q;
  logic a_valid_q, a_err_q, b_valid_q;

  if (InitFile != "") begin : g_init
    initial $readmemh(InitFile, mem_q);
  end

  // Addresses wrap modulo the RAM size (the interconnect only routes in-range addresses here);
  // port A never writes.
  logic unused_req;
  assign unused_req = ^{a_req_addr_i[31:WordWidth+2], a_req_addr_i[1:0], a_req_be_i, a_req_wdata_i,
                        b_req_addr_i[31:WordWidth+2], b_req_addr_i[1:0]};
  assign a_req_ready_o = 1'b1;
  assign b_req_ready_o = 1'b1;
  assign a_word = a_req_addr_i[WordWidth+1:2];
  assign b_word = b_req_addr_i[WordWidth+1:2];

  always_ff @(posedge clk_i) begin
    if (a_req_valid_i && !a_req_we_i) begin
      a_rdata_q <= mem_q[a_word];
    end
    if (b_req_valid_i) begin
      if (b_req_we_i) begin
        for (int i = 0; i < 4; i++) begin
          if (b_req_be_i[i]) mem_q[b_word][i*8 +: 8] <= b_req_wdata_i[i*8 +: 8];
        end
      end else begin
        b_rsp_rdata_o <= mem_q[b_word];
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      a_valid_q <= 1'b0;
      a_err_q   <= 1'b0;
      b_valid_q <= 1'b0;
    end else begin
      a_valid_q <= a_req_valid_i;
      a_err_q   <= a_req_valid_i && a_req_we_i;
      b_valid_q <= b_req_valid_i;
    end
  end

  assign a_rsp_valid_o = a_valid_q;
  assign b_rsp_valid_o = b_valid_q;
  assign a_rsp_err_o   = a_err_q;
  assign a_rsp_rdata_o = a_err_q ? '0 : a_rdata_q;
  assign b_rsp_err_o   = 1'b0;
endmodule
