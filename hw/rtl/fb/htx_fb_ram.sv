// Dual-port RAM for the framebuffer and depth buffer: one synchronous read port, one write port
// with per-lane enables. A read of the address being written returns the old value.
// Spram = 1 (the board's builds, read by Yosys with HTX_ICE40): the memory is the UP5K's
// single-ported SB_SPRAM256KA blocks (16 bits x 16K words each: one column per lane, banks of 16K
// words stacked by address), so a read and a write must never come in the same clock (htx_fb's
// SinglePort arbitration guarantees it). rdata_o holds its value between reads in both forms.
// Simulators see the behavioural memory unless they define HTX_ICE40 too (the SPRAM form's own
// test does, with a behavioural model of the cell: tests/rtl/fb).
module htx_fb_ram #(
  parameter int unsigned LaneW = 16,
  parameter int unsigned Lanes = 1,
  parameter int unsigned Words = 1024,
  parameter bit          Spram = 1'b0,   // LaneW must be 16
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
`ifdef HTX_ICE40
  localparam bit UseSpram = Spram;
`else
  localparam bit UseSpram = Spram && 1'b0;  // (the behavioural memory everywhere else)
`endif

  if (UseSpram) begin : g_spram
    localparam int unsigned BankW = 14;                      // 16K words a block
    localparam int unsigned Banks = (Words + (1 << BankW) - 1) >> BankW;
    localparam int unsigned SelW  = (Banks > 1) ? $clog2(Banks) : 1;
    logic          wr;
    logic [AW-1:0] addr;
    logic [SelW-1:0] bank, bank_q;
    assign wr   = |we_i;
    assign addr = wr ? waddr_i : raddr_i;
    if (Banks > 1) begin : g_bank
      assign bank = SelW'(addr >> BankW);
    end else begin : g_one_bank
      assign bank = '0;
    end
    // The bank a read came from chooses the read data until the next read.
    always_ff @(posedge clk_i) begin
      if (re_i && !wr) bank_q <= bank;
    end
    for (genvar l = 0; l < Lanes; l++) begin : g_lane
      logic [15:0] dout [Banks];
      for (genvar b = 0; b < Banks; b++) begin : g_blk
        logic sel;
        assign sel = (bank == SelW'(b));
        // Selected only to read or to write its own lane, so DATAOUT holds between reads.
        SB_SPRAM256KA u_spram (
          .ADDRESS(14'(addr)), .DATAIN(wdata_i[16*l +: 16]), .MASKWREN(4'b1111),
          .WREN(we_i[l]), .CHIPSELECT(sel && (we_i[l] || (re_i && !wr))), .CLOCK(clk_i),
          .STANDBY(1'b0), .SLEEP(1'b0), .POWEROFF(1'b1), .DATAOUT(dout[b])
        );
      end
      assign rdata_o[16*l +: 16] = dout[bank_q];
    end
  end else begin : g_behav
    logic [LaneW*Lanes-1:0] mem_q [Words] /* verilator public_flat_rw */;

    always_ff @(posedge clk_i) begin
      for (int l = 0; l < Lanes; l++) begin
        if (we_i[l]) mem_q[waddr_i][LaneW*l +: LaneW] <= wdata_i[LaneW*l +: LaneW];
      end
      if (re_i) rdata_o <= mem_q[raddr_i];
    end
  end
endmodule
