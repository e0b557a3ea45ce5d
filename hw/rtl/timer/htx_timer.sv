// 64-bit time counter with a 64-bit compare (hw/regs/timer.json). The counter advances once per
// clock while CTRL.ENABLE is set; STATUS.MATCH is mtime >= mtimecmp and, with CTRL.IRQ_ENABLE,
// drives irq_o. Only whole-word writes take effect (partial writes are ignored): byte merging would
// double the 64-bit datapath on an iCE40. A write to MTIME_LO/HI replaces that half (a carry out
// of a low half being replaced is dropped) and the counter resumes counting from the written value.
//
// A request is registered as it is accepted and acts in the next clock, with its response in the
// clock after (htx_reg_port: two clocks' latency, one request a clock). So the counter's write
// enables come from flip-flops and can enter its carry chains (htx_counter64: one LUT4 a bit with
// the write, where a write multiplexer after an incrementer costs two), and responses stay in
// request order: a read accepted right after a write acts after it.
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
  logic [63:0] mtime, cmp_q;  // (mtime resets to 0 in htx_counter64, as hw/regs/timer.json says)
  logic        enable_q, irq_en_q, match;
  logic [31:0] rdata_d;

  // The request, registered as it is accepted.
  logic        act_write_q;
  logic [11:0] act_offset_q;
  logic [31:0] act_wdata_q;
  htx_reg_port u_port (
    .clk_i, .rst_ni, .req_valid_i, .req_ready_o, .req_addr_i, .req_we_i, .req_be_i, .req_wdata_i,
    .rsp_valid_o, .rsp_rdata_o, .rsp_err_o,
    .act_write_o(act_write_q), .act_offset_o(act_offset_q), .act_wdata_o(act_wdata_q),
    .rdata_i(rdata_d)
  );

  logic wr_time_lo, wr_time_hi;
  assign wr_time_lo = act_write_q && (act_offset_q == htx_timer_reg_pkg::TIMER_MTIME_LO_OFFSET);
  assign wr_time_hi = act_write_q && (act_offset_q == htx_timer_reg_pkg::TIMER_MTIME_HI_OFFSET);

  logic unused_carry;
  htx_counter64 #(.CarryReg(1'b0)) u_mtime (
    .clk_i, .rst_ni,
    .inc_i          (enable_q),
    .wr_lo_i        (wr_time_lo),
    .wr_hi_i        (wr_time_hi),
    .wdata_i        (act_wdata_q),
    .count_o        (mtime),
    .carry_pending_o(unused_carry)
  );

  assign match = (mtime >= cmp_q);
  assign irq_o = match && irq_en_q;

  always_comb begin
    rdata_d = '0;
    unique case (act_offset_q)
      htx_timer_reg_pkg::TIMER_MTIME_LO_OFFSET:    rdata_d = mtime[31:0];
      htx_timer_reg_pkg::TIMER_MTIME_HI_OFFSET:    rdata_d = mtime[63:32];
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
      cmp_q        <= {htx_timer_reg_pkg::TIMER_MTIMECMP_HI_RESET,
                       htx_timer_reg_pkg::TIMER_MTIMECMP_LO_RESET};
      enable_q     <= htx_timer_reg_pkg::TIMER_CTRL_ENABLE_RESET[htx_timer_reg_pkg::TIMER_CTRL_ENABLE_LSB];
      irq_en_q     <= htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_RESET[
                        htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_LSB];
    end else if (act_write_q) begin
      unique case (act_offset_q)
        htx_timer_reg_pkg::TIMER_MTIMECMP_LO_OFFSET: cmp_q[31:0]  <= act_wdata_q;
        htx_timer_reg_pkg::TIMER_MTIMECMP_HI_OFFSET: cmp_q[63:32] <= act_wdata_q;
        htx_timer_reg_pkg::TIMER_CTRL_OFFSET: begin
          enable_q <= act_wdata_q[htx_timer_reg_pkg::TIMER_CTRL_ENABLE_LSB];
          irq_en_q <= act_wdata_q[htx_timer_reg_pkg::TIMER_CTRL_IRQ_ENABLE_LSB];
        end
        default: ;
      endcase
    end
  end
endmodule
