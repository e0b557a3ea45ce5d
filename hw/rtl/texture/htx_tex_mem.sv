// Texture memory (docs/texture.md, Memory layout): four banks by texel (u, v) parity, so any 2x2
// footprint reads in one clock, and the bus window at 0x4000_0000. Window word w (byte offset / 4)
// is bank w[1:0] = {v & 1, u & 1}, block w >> 2; one texel per 32-bit word (TexW low bits).
// Writes take one clock and wait only while the sampler reads, so no bank is ever written and read
// in the same clock (htx_tex_bank). Reads share each bank's read port with the sampler: one is
// accepted only in a clock where the sampler neither reads nor holds read data. A word beyond the
// memory, or a write whose byte enables do not cover the texel, answers rsp_err and does nothing.
// CpuRead = 0 (the board's builds) leaves the window's reads out: a read is taken at once and
// answers rsp_err with 0, the banks' read ports are the sampler's alone (no address multiplexer)
// and there is no read-data multiplexer: texture memory is written only (docs/texture.md, "Memory
// layout").
module htx_tex_mem #(
  parameter int unsigned TexW    = 16,
  parameter int unsigned BAW     = 10,   // block address bits (blocks per bank = 2^BAW)
  parameter bit          CpuRead = 1'b1
) (
  input  logic              clk_i,
  input  logic              rst_ni,

  input  logic              req_valid_i,
  output logic              req_ready_o,
  input  logic [31:0]       req_addr_i,
  input  logic              req_we_i,
  input  logic [3:0]        req_be_i,
  input  logic [31:0]       req_wdata_i,
  output logic              rsp_valid_o,
  output logic [31:0]       rsp_rdata_o,
  output logic              rsp_err_o,

  // Sampler read port: one address per bank; s_hold_i: the sampler still needs the data read last.
  input  logic              s_re_i,
  input  logic              s_hold_i,
  input  logic [4*BAW-1:0]  s_addr_i,
  output logic [4*TexW-1:0] s_rdata_o
);
  logic [17:0] word;
  logic [1:0]  bank;
  logic        in_range, be_ok, cpu_rd_ok, accept, cpu_re, cpu_we;
  assign word      = req_addr_i[19:2];
  assign bank      = word[1:0];
  assign in_range  = (BAW >= 16) || ((word >> (BAW + 2)) == 18'd0);
  assign be_ok     = (TexW > 16) ? (&req_be_i) : (&req_be_i[1:0]);
  assign cpu_rd_ok = !s_re_i && !s_hold_i;
  assign req_ready_o = (req_we_i ? !s_re_i : (cpu_rd_ok || !CpuRead)) || !in_range;
  assign accept    = req_valid_i && req_ready_o;
  assign cpu_we    = accept && req_we_i && in_range && be_ok;
  assign cpu_re    = CpuRead && accept && !req_we_i && in_range;

  logic [BAW-1:0] blk;
  assign blk = BAW'(word >> 2);

  logic [TexW-1:0] rdata [4];
  for (genvar b = 0; b < 4; b++) begin : g_bank
    htx_tex_bank #(.W(TexW), .AW(BAW)) u_bank (
      .clk_i,
      .we_i   (cpu_we && (bank == 2'(b))),
      .waddr_i(blk),
      .wdata_i(req_wdata_i[TexW-1:0]),
      .re_i   (s_re_i || (cpu_re && (bank == 2'(b)))),
      .raddr_i((s_re_i || !CpuRead) ? s_addr_i[b*BAW +: BAW] : blk),
      .rdata_o(rdata[b])
    );
    assign s_rdata_o[b*TexW +: TexW] = rdata[b];
  end

  logic       rsp_q, rsp_err_q, rsp_rd_q;
  logic [1:0] rsp_bank_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rsp_q      <= 1'b0;
      rsp_err_q  <= 1'b0;
      rsp_rd_q   <= 1'b0;
      rsp_bank_q <= '0;
    end else begin
      rsp_q      <= accept;
      rsp_err_q  <= accept && (!in_range || (req_we_i && !be_ok) || (!req_we_i && !CpuRead));
      rsp_rd_q   <= cpu_re;
      rsp_bank_q <= bank;
    end
  end
  assign rsp_valid_o = rsp_q;
  assign rsp_err_o   = rsp_err_q;
  assign rsp_rdata_o = rsp_rd_q ? 32'(rdata[rsp_bank_q]) : 32'd0;  // (cpu_re carries CpuRead)

  logic unused;
  assign unused = ^{req_addr_i[31:20], req_addr_i[1:0], req_wdata_i, req_be_i};
endmodule
