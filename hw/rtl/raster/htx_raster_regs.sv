// RASTER register block (hw/regs/raster.json): control, status, clear values, framebuffer size and
// page, capabilities, the STATE diagnostic and the CNT_* event counters. Registers are decoded by
// word (a byte or half-word read gets its word's lanes); only whole words are written, and a
// narrower write is refused with a bus error. An access is answered the clock after it is
// accepted; an offset with no register reads 0 and ignores writes. Two accesses wait: a whole-word
// FIFO write while the FIFO is full and the unit enabled (back-pressure, never a drop), and a
// counter read until its counter's turn in the counter RAM (htx_raster_counters).
module htx_raster_regs #(
  parameter int unsigned LvlW       = 7,        // the FIFO's level width
  parameter int unsigned FbPixels   = 76800,    // FB_MEM.PIXELS
  parameter int unsigned ColorPages = 1,        // FB_MEM.PAGES
  parameter logic [4:0]  Methods    = 5'b01111, // CAPS.METHODS
  parameter bit          Counters   = 1'b1,     // CAPS.COUNTERS and CAPS.STATE
  parameter bit          FwSetup    = 1'b0      // CAPS.FW_SETUP
) (
  input  logic            clk_i,
  input  logic            rst_ni,

  input  logic            req_valid_i,
  output logic            req_ready_o,
  input  logic [31:0]     req_addr_i,
  input  logic            req_we_i,
  input  logic [3:0]      req_be_i,
  input  logic [31:0]     req_wdata_i,
  output logic            rsp_valid_o,
  output logic [31:0]     rsp_rdata_o,
  output logic            rsp_err_o,

  // The vertex FIFO: a whole word written to FIFO with room is pushed.
  output logic            fifo_push_o,
  input  logic            fifo_full_i,
  input  logic            fifo_empty_i,
  input  logic [LvlW-1:0] fifo_level_i,

  // Control of the pipeline.
  output logic            abort_o,        // CTRL.ABORT written (a pulse)
  output logic            enable_o,       // CTRL.ENABLE
  output logic [12:0]     width_o,        // FB_SIZE
  output logic [12:0]     height_o,
  output logic [12:0]     stride_o,       // FB_STRIDE
  output logic [1:0]      draw_page_o,    // FB_PAGE.DRAW
  output logic [15:0]     clear_color_o,  // CLEAR_COLOR (RGB565)
  output logic [23:0]     clear_depth_o,  // CLEAR_DEPTH
  // A clear requested (CTRL.CLEAR_*) and not yet started, and what it clears.
  output logic            clr_pend_o,
  output logic            clr_color_o,
  output logic            clr_depth_o,
  input  logic            clear_start_i,  // the fragment stage starts the pending clear
  input  logic            clearing_i,

  // Status and diagnostics.
  input  logic            busy_i,
  input  logic            setup_taken_i,  // a triangle's record was taken (its state word is STATE)
  input  logic [31:0]     rec_state_i,
  input  logic            setup_err_i,    // a record's state word was refused (STATUS.ERR_STATE)
  // CNT_PIXELS .. CNT_BUSY (bit 7 .. 0), each counting the clocks (or events) it is high.
  input  logic [7:0]      events_i,
  input  logic            df_steps_valid_i,  // CNT_DIVFREE_STEPS adds df_steps_i
  input  logic [15:0]     df_steps_i
);
  logic [11:0] offset;
  logic        accept, wr, is_fifo, ctrl_wr, clear_req, cnt_reset;
  logic        cnt_read, cnt_ack;
  logic        enable_q, err_state_q;
  logic [1:0]  draw_page_q /* verilator public_flat_rd */;  // (htx sim reads the page drawn)
  logic [15:0] clear_color_q;
  logic [23:0] clear_depth_q;
  logic [12:0] width_q, height_q, stride_q;
  logic        clr_pend_q, clr_color_q, clr_depth_q;

  assign offset  = {req_addr_i[11:2], 2'b00};
  assign wr      = req_we_i && (&req_be_i);
  assign is_fifo = (offset == htx_raster_reg_pkg::RASTER_FIFO_OFFSET);
  // With the unit disabled nothing leaves a full FIFO, so a write to it is refused with a bus
  // error instead of holding the bus (and the CPU, the only master that could enable the unit)
  // for ever. (Only a whole word waits for room: a narrower write is refused at once, full or not.)
  logic fifo_refused;
  assign fifo_refused = is_fifo && req_we_i && fifo_full_i && !enable_q;
  assign req_ready_o  = !(is_fifo && wr && fifo_full_i && enable_q) && !(cnt_read && !cnt_ack);
  assign accept       = req_valid_i && req_ready_o;
  assign fifo_push_o  = accept && is_fifo && wr && !fifo_full_i;

  assign ctrl_wr   = accept && wr && (offset == htx_raster_reg_pkg::RASTER_CTRL_OFFSET);
  assign abort_o   = ctrl_wr && req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_ABORT_LSB];
  assign clear_req = ctrl_wr && (req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_COLOR_LSB] ||
                                 req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_DEPTH_LSB]);
  assign cnt_reset = ctrl_wr && req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_COUNTERS_RESET_LSB];

  // ---- Counters --------------------------------------------------------------------------------
  // CNT_BUSY .. CNT_PIXELS are eight consecutive words from a 32-byte boundary, counter i at
  // CNT_BUSY + 4 i, kept in one block RAM; CNT_DIVFREE_STEPS adds several a clock and stays a register.
  // Without Counters every CNT_* reads 0 at once (CAPS.COUNTERS = 0).
  logic [31:0] cnt_rdata, cnt_df_q;
  assign cnt_read = !req_we_i &&
                    ((offset & ~12'h01F) == htx_raster_reg_pkg::RASTER_CNT_BUSY_OFFSET);
  if (Counters) begin : g_counters
    htx_raster_counters #(.N(8)) u_counters (
      .clk_i, .rst_ni,
      .clear_i  (cnt_reset),
      .inc_i    (events_i),
      .rd_i     (req_valid_i && cnt_read),
      .rd_idx_i (offset[4:2]),
      .rd_ack_o (cnt_ack),
      .rd_data_o(cnt_rdata)
    );
  end else begin : g_no_counters
    assign cnt_ack   = 1'b1;
    assign cnt_rdata = '0;
    logic unused_events;
    assign unused_events = ^events_i;
  end

  // ---- Reads -----------------------------------------------------------------------------------
  logic [31:0] rdata_d, rsp_rdata_q;
  logic        rsp_valid_q, rsp_err_q;
  logic [31:0] last_state_q;
  always_comb begin
    rdata_d = '0;
    unique case (offset)
      htx_raster_reg_pkg::RASTER_CTRL_OFFSET:
        rdata_d[htx_raster_reg_pkg::RASTER_CTRL_ENABLE_LSB] = enable_q;
      htx_raster_reg_pkg::RASTER_STATUS_OFFSET: begin
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_BUSY_LSB]       = busy_i;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_CLEARING_LSB]   = clearing_i || clr_pend_q;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_FIFO_EMPTY_LSB] = fifo_empty_i;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_FIFO_FULL_LSB]  = fifo_full_i;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_FIFO_LEVEL_LSB +: 8] =
          ((32'(fifo_level_i) >> 8) != 0) ? 8'hFF : 8'(fifo_level_i);
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_ERR_STATE_LSB]  = err_state_q;
      end
      htx_raster_reg_pkg::RASTER_CLEAR_COLOR_OFFSET: rdata_d = 32'(clear_color_q);
      htx_raster_reg_pkg::RASTER_CLEAR_DEPTH_OFFSET: rdata_d = 32'(clear_depth_q);
      htx_raster_reg_pkg::RASTER_FB_SIZE_OFFSET: begin
        rdata_d[htx_raster_reg_pkg::RASTER_FB_SIZE_WIDTH_LSB +: 13]  = width_q;
        rdata_d[htx_raster_reg_pkg::RASTER_FB_SIZE_HEIGHT_LSB +: 13] = height_q;
      end
      htx_raster_reg_pkg::RASTER_FB_STRIDE_OFFSET: rdata_d = 32'(stride_q);
      // A diagnostic, built with the counters (CAPS.STATE): the board's build leaves both out.
      htx_raster_reg_pkg::RASTER_STATE_OFFSET: rdata_d = Counters ? last_state_q : 32'd0;
      htx_raster_reg_pkg::RASTER_FB_MEM_OFFSET: begin
        rdata_d[htx_raster_reg_pkg::RASTER_FB_MEM_PIXELS_LSB +: 20] = 20'(FbPixels);
        rdata_d[htx_raster_reg_pkg::RASTER_FB_MEM_PAGES_LSB +: 2]   = 2'(ColorPages);
      end
      htx_raster_reg_pkg::RASTER_FB_PAGE_OFFSET:
        rdata_d[htx_raster_reg_pkg::RASTER_FB_PAGE_DRAW_LSB +: 2] = draw_page_q;
      htx_raster_reg_pkg::RASTER_CAPS_OFFSET: begin
        rdata_d[htx_raster_reg_pkg::RASTER_CAPS_METHODS_LSB +: 5]  = Methods;
        rdata_d[htx_raster_reg_pkg::RASTER_CAPS_COUNTERS_LSB]      = Counters;
        rdata_d[htx_raster_reg_pkg::RASTER_CAPS_STATE_LSB]         = Counters;
        rdata_d[htx_raster_reg_pkg::RASTER_CAPS_FW_SETUP_LSB]      = FwSetup;
      end
      htx_raster_reg_pkg::RASTER_CNT_BUSY_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_STALL_INPUT_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_STALL_SETUP_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_STALL_FRAGMENT_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_SETUP_BUSY_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_TRIANGLES_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_FRAGMENTS_OFFSET,
      htx_raster_reg_pkg::RASTER_CNT_PIXELS_OFFSET:         rdata_d = cnt_rdata;
      htx_raster_reg_pkg::RASTER_CNT_DIVFREE_STEPS_OFFSET:  rdata_d = cnt_df_q;
      default: ;
    endcase
  end

  // ---- Writes ----------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      enable_q      <= 1'(htx_raster_reg_pkg::RASTER_CTRL_ENABLE_RESET >> htx_raster_reg_pkg::RASTER_CTRL_ENABLE_LSB);
      err_state_q   <= 1'b0;
      draw_page_q   <= 2'd0;
      clear_color_q <= '0;
      clear_depth_q <= 24'(htx_raster_reg_pkg::RASTER_CLEAR_DEPTH_RESET);
      width_q       <= 13'(htx_raster_reg_pkg::RASTER_FB_SIZE_WIDTH_RESET >> htx_raster_reg_pkg::RASTER_FB_SIZE_WIDTH_LSB);
      height_q      <= 13'(htx_raster_reg_pkg::RASTER_FB_SIZE_HEIGHT_RESET >> htx_raster_reg_pkg::RASTER_FB_SIZE_HEIGHT_LSB);
      stride_q      <= 13'(htx_raster_reg_pkg::RASTER_FB_STRIDE_RESET);
      clr_pend_q    <= 1'b0;
      clr_color_q   <= 1'b0;
      clr_depth_q   <= 1'b0;
      last_state_q  <= '0;
      rsp_valid_q   <= 1'b0;
      rsp_err_q     <= 1'b0;
      rsp_rdata_q   <= '0;
      cnt_df_q      <= '0;
    end else begin
      rsp_valid_q <= accept;
      rsp_err_q   <= accept && ((req_we_i && !wr) || fifo_refused);
      if (accept && !req_we_i) rsp_rdata_q <= rdata_d;
      if (setup_taken_i) last_state_q <= rec_state_i;
      if (accept && wr) begin
        unique case (offset)
          htx_raster_reg_pkg::RASTER_CTRL_OFFSET:
            enable_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_ENABLE_LSB];
          htx_raster_reg_pkg::RASTER_STATUS_OFFSET:
            if (req_wdata_i[htx_raster_reg_pkg::RASTER_STATUS_ERR_STATE_LSB]) err_state_q <= 1'b0;
          htx_raster_reg_pkg::RASTER_CLEAR_COLOR_OFFSET: clear_color_q <= req_wdata_i[15:0];
          htx_raster_reg_pkg::RASTER_CLEAR_DEPTH_OFFSET: clear_depth_q <= req_wdata_i[23:0];
          htx_raster_reg_pkg::RASTER_FB_SIZE_OFFSET: begin
            width_q  <= req_wdata_i[htx_raster_reg_pkg::RASTER_FB_SIZE_WIDTH_LSB +: 13];
            height_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_FB_SIZE_HEIGHT_LSB +: 13];
          end
          htx_raster_reg_pkg::RASTER_FB_STRIDE_OFFSET: stride_q <= req_wdata_i[12:0];
          htx_raster_reg_pkg::RASTER_FB_PAGE_OFFSET:
            // A page the memory does not have leaves the register as it was.
            if (32'(req_wdata_i[htx_raster_reg_pkg::RASTER_FB_PAGE_DRAW_LSB +: 2]) < ColorPages) begin
              draw_page_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_FB_PAGE_DRAW_LSB +: 2];
            end
          default: ;
        endcase
      end
      // After the write-one-to-clear above, so an error in the clearing clock is not lost.
      if (setup_err_i) err_state_q <= 1'b1;
      // Clear: requested, then started by the fragment stage once the pipeline is empty.
      if (abort_o) begin
        clr_pend_q <= 1'b0;
      end else if (clear_req) begin
        clr_pend_q  <= 1'b1;
        clr_color_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_COLOR_LSB];
        clr_depth_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_DEPTH_LSB];
      end else if (clear_start_i) begin
        clr_pend_q <= 1'b0;
      end
      if (cnt_reset || !Counters) begin
        cnt_df_q <= '0;
      end else begin
        cnt_df_q <= cnt_df_q + (df_steps_valid_i ? 32'(df_steps_i) : 32'd0);
      end
    end
  end

  assign rsp_valid_o   = rsp_valid_q;
  assign rsp_rdata_o   = rsp_rdata_q;
  assign rsp_err_o     = rsp_err_q;
  assign enable_o      = enable_q;
  assign width_o       = width_q;
  assign height_o      = height_q;
  assign stride_o      = stride_q;
  assign draw_page_o   = draw_page_q;
  assign clear_color_o = clear_color_q;
  assign clear_depth_o = clear_depth_q;
  assign clr_pend_o    = clr_pend_q;
  assign clr_color_o   = clr_color_q;
  assign clr_depth_o   = clr_depth_q;

  logic unused_addr;
  assign unused_addr = ^{req_addr_i[31:12], req_addr_i[1:0]};
endmodule
