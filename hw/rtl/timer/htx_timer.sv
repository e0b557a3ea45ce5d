// 64-bit time counter with a 64-bit compare (hw/regs/timer.json). The counter advances once per
// clock while CTRL.ENABLE is set; STATUS.MATCH is mtime >= mtimecmp and, with CTRL.IRQ_ENABLE,
// drives irq_o. Only whole-word writes take effect (partial writes are ignored): byte merging would
// double the 64-bit datapath on an iCE40. A write to MTIME_LO/HI replaces that half and the counter
// resumes counting from the written value.
module htx_timer (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        req_valid_i,
  output logic        req_ready_o,
  input  logic [31:0] req_addr_i,
  input  logic        req_we_i,
  input  logic [3:0]  req_be_i,
  input  logic [31:0] req_wdata_i,
  output logic        rsp_valid_o,
  output logic [31:0] rsp_rdata_o,
  output logic        rsp_err_o,

  output logic        irq_o
);
  logic [63:0] mtime_q, mtime_d, cmp_q, cmp_d;
  logic        enable_q, irq_en_q, match;
  logic [11:0] offset;
  logic        accept, write;
  logic [31:0] rdata_d, rsp_rdata_q;
  logic        rsp_valid_q;

  logic unused_addr;
  assign unused_addr = ^req_addr_i[31:12];
  assign offset      = req_addr_i[11:0];
  assign req_ready_o = 1'b1;
  assign accept      = req_valid_i;
  assign write       = accept && req_we_i && (req_be_i == 4'b1111);
  assign match       = (mtime_q >= cmp_q);
  assign irq_o       = match && irq_en_q;

  always_comb begin
    mtime_d = enable_q ? mtime_q + 64'd1 : mtime_q;
    cmp_d   = cmp_q;
    if (write) begin
      unique case (offset)
        htx_timer_reg_pkg::TIMER_MTIME_LO_OFFSET:
          mtime_d[31:0] = req_wdata_i;
        htx_timer_reg_pkg::TIMER_MTIME_HI_OFFSET:
          mtime_d[63:32] = req_wdata_i;
        htx_timer_reg_pkg::TIMER_MTIMECMP_LO_OFFSET:
          cmp_d[31:0] = req_wdata_i;
        htx_timer_reg_pkg::TIMER_MTIMECMP_HI_OFFSET:
          cmp_d[63:32] = req_wdata_i;
        default: ;
      endcase
    end
  end

  always_comb begin
    rdata_d = '0;
    unique case (offset)
      htx_timer_reg_pkg::TIMER_MTIME_LO_OFFSET:    rdata_d = mtime_q[31:0];
      htx_timer_reg_pkg::TIMER_MTIME_HI_OFFSET:    rdata_d = mtime_q[63:32];
      htx_timer_reg_pkg::TIMER_MTIMECMP_LO_OFFSET: rdata_d = cmp_q[31:0];
      htx_timer_reg_pkg::TIMER_MTIMECMP_HI_OFFSET: rdata_d = cmp_q[63:32];
      htx_timer_reg_pkg::TIMER_CTRL_OFFSET: begin
        rdata_d[htx_timer_reg_pkg::TIMER_CTRL_ENABLE_LSB]     = enable_q;
        rdata_d[htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_LSB] = irq_en_q;
      end
      htx_timer_reg_pkg::TIMER_STATUS_OFFSET:
        rdata_d[htx_timer_reg_pkg::TIMER_STATUS_MATCH_LSB] = match;
      default: ;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      mtime_q     <= {htx_timer_reg_pkg::TIMER_MTIME_HI_RESET, htx_timer_reg_pkg::TIMER_MTIME_LO_RESET};
      cmp_q       <= {htx_timer_reg_pkg::TIMER_MTIMECMP_HI_RESET,
                      htx_timer_reg_pkg::TIMER_MTIMECMP_LO_RESET};
      enable_q    <= htx_timer_reg_pkg::TIMER_CTRL_ENABLE_RESET[htx_timer_reg_pkg::TIMER_CTRL_ENABLE_LSB];
      irq_en_q    <= htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_RESET[
                       htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_LSB];
      rsp_valid_q <= 1'b0;
      rsp_rdata_q <= '0;
    end else begin
      mtime_q     <= mtime_d;
      cmp_q       <= cmp_d;
      rsp_valid_q <= accept;
      if (accept && !req_we_i) rsp_rdata_q <= rdata_d;
      if (write && offset == htx_timer_reg_pkg::TIMER_CTRL_OFFSET) begin
        enable_q <= req_wdata_i[htx_timer_reg_pkg::TIMER_CTRL_ENABLE_LSB];
        irq_en_q <= req_wdata_i[htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_LSB];
      end
    end
  end

  assign rsp_valid_o = rsp_valid_q;
  assign rsp_rdata_o = rsp_rdata_q;
  assign rsp_err_o   = 1'b0;
endmodule
