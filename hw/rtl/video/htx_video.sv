// VIDEO (hw/regs/video.json, docs/video.md): scans the colour framebuffer out as a 640x480 picture
// at 60 Hz, each framebuffer pixel a Scale x Scale block, on the SoC's clock (the pixel clock, 25
// MHz on the ULX3S). A line buffer of two framebuffer lines decouples the picture from the
// memory: while source line L is shown (Scale picture lines, 3,200 clocks at the defaults) line
// L + 1 is read into the other half through htx_fb's video port, which waits only for the
// raster's colour writes and goes before the CPU's reads. A read that has not finished when its
// line is due sets STATUS.UNDERRUN and the line shows the half's old words. The output is RGB888
// (RGB565 widened by bit replication, as `htx render` writes PNGs), the display enable and both
// syncs (active low), two clocks after the timing counters.
// Pages = 2 or 3 (the GPU double- or triple-buffers): the colour memory holds that many frames, page
// p at word p * PageWords; CTRL.PAGE chooses the one shown and, like ENABLE, is taken at a frame's
// start, so firmware draws into another page and a flip never splits a frame.
module htx_video #(
  parameter int unsigned SrcW    = 160,   // even
  parameter int unsigned SrcH    = 120,
  parameter int unsigned Scale   = 4,
  parameter int unsigned HActive = 640,   // = SrcW * Scale
  parameter int unsigned HFront  = 16,
  parameter int unsigned HSync   = 96,
  parameter int unsigned HBack   = 48,
  parameter int unsigned VActive = 480,   // = SrcH * Scale
  parameter int unsigned VFront  = 10,
  parameter int unsigned VSync   = 2,
  parameter int unsigned VBack   = 33,    // VFront + VSync + VBack > Scale
  parameter int unsigned AddrW   = 24,    // framebuffer word addresses
  parameter int unsigned Pages   = 1,     // colour pages (1, 2 or 3)
  parameter int unsigned PageWords = SrcW / 2 * SrcH  // words from a page's start to the next's (>= those shown)
) (
  input  logic             clk_i,
  input  logic             rst_ni,

  input  logic             req_valid_i,
  output logic             req_ready_o,
  input  logic [31:0]      req_addr_i,
  input  logic             req_we_i,
  input  logic [3:0]       req_be_i,
  input  logic [31:0]      req_wdata_i,
  output logic             rsp_valid_o,
  output logic [31:0]      rsp_rdata_o,
  output logic             rsp_err_o,

  // htx_fb's video port: a word (two pixels) at fb_addr_o is read in a clock with fb_gnt_i; its
  // data is on fb_data_i in the next clock.
  output logic             fb_req_o,
  output logic [AddrW-1:0] fb_addr_o,
  input  logic             fb_gnt_i,
  input  logic [31:0]      fb_data_i,

  output logic             de_o,
  output logic             hsync_no,
  output logic             vsync_no,
  output logic [23:0]      rgb_o,      // red 23:16, green 15:8, blue 7:0
  output logic             busy_o      // reading the framebuffer (the simulation's GPU clock gate)
);
  localparam int unsigned Wpl    = SrcW / 2;          // framebuffer words a line
  localparam int unsigned FAW    = $clog2(PageWords * (Pages - 1) + Wpl * SrcH);  // the words read
  localparam int unsigned LbAW   = $clog2(Wpl);
  localparam int unsigned XW     = $clog2(SrcW + 1);
  localparam int unsigned YW     = $clog2(SrcH + 2);
  localparam int unsigned SW     = (Scale > 1) ? $clog2(Scale) : 1;
  localparam int unsigned VTotal = VActive + VFront + VSync + VBack;

  // ---- Timing --------------------------------------------------------------------------------
  logic [9:0] h, v;
  logic       line_end, frame_end, active, hsync, vsync;
  htx_video_timing #(
    .HActive(HActive), .HFront(HFront), .HSync(HSync), .HBack(HBack),
    .VActive(VActive), .VFront(VFront), .VSync(VSync), .VBack(VBack)
  ) u_timing (
    .clk_i, .rst_ni, .h_o(h), .v_o(v), .line_end_o(line_end), .frame_end_o(frame_end),
    .active_o(active), .hsync_o(hsync), .vsync_o(vsync)
  );

  // The source pixel (xs, ys) under (h, v), stepped by sub-pixel counters (no division).
  logic [XW-1:0] xs_q;
  logic [YW-1:0] ys_q;
  logic [SW-1:0] xsub_q, ysub_q;
  logic          v_active;
  assign v_active = (v < 10'(VActive));
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      xs_q   <= '0;
      xsub_q <= '0;
      ys_q   <= '0;
      ysub_q <= '0;
    end else begin
      if (line_end) begin
        xs_q   <= '0;
        xsub_q <= '0;
      end else if (active) begin
        xsub_q <= (xsub_q == SW'(Scale - 1)) ? '0 : xsub_q + SW'(1);
        if (xsub_q == SW'(Scale - 1)) xs_q <= xs_q + XW'(1);
      end
      if (frame_end) begin
        ys_q   <= '0;
        ysub_q <= '0;
      end else if (line_end && v_active) begin
        ysub_q <= (ysub_q == SW'(Scale - 1)) ? '0 : ysub_q + SW'(1);
        if (ysub_q == SW'(Scale - 1)) ys_q <= ys_q + YW'(1);
      end
    end
  end

  // ---- Registers -------------------------------------------------------------------------------
  logic        enable_q, underrun_q, show_q;
  logic [1:0]  page_q, shown_page_q;
  logic [31:0] frame_count_q;
  logic        act_write_q;
  logic [11:0] act_offset_q;
  logic [31:0] act_wdata_q, rdata_d;
  htx_reg_port u_port (
    .clk_i, .rst_ni, .req_valid_i, .req_ready_o, .req_addr_i, .req_we_i, .req_be_i, .req_wdata_i,
    .rsp_valid_o, .rsp_rdata_o, .rsp_err_o,
    .act_write_o(act_write_q), .act_offset_o(act_offset_q), .act_wdata_o(act_wdata_q),
    .rdata_i(rdata_d)
  );

  always_comb begin
    rdata_d = '0;
    unique case (act_offset_q)
      htx_video_reg_pkg::VIDEO_CTRL_OFFSET: begin
        rdata_d[htx_video_reg_pkg::VIDEO_CTRL_ENABLE_LSB] = enable_q;
        rdata_d[htx_video_reg_pkg::VIDEO_CTRL_PAGE_LSB +: 2] = page_q;
      end
      htx_video_reg_pkg::VIDEO_STATUS_OFFSET: begin
        rdata_d[htx_video_reg_pkg::VIDEO_STATUS_VBLANK_LSB]   = !v_active;
        rdata_d[htx_video_reg_pkg::VIDEO_STATUS_UNDERRUN_LSB] = underrun_q;
        rdata_d[htx_video_reg_pkg::VIDEO_STATUS_SHOWING_LSB]  = show_q;
        rdata_d[htx_video_reg_pkg::VIDEO_STATUS_PAGE_LSB +: 2] = shown_page_q;
      end
      htx_video_reg_pkg::VIDEO_FRAME_OFFSET: rdata_d = frame_count_q;
      htx_video_reg_pkg::VIDEO_LINE_OFFSET:  rdata_d = 32'(v);
      htx_video_reg_pkg::VIDEO_MODE_OFFSET:
        rdata_d = (32'(Pages) << htx_video_reg_pkg::VIDEO_MODE_PAGES_LSB) |
                  (32'(Scale) << htx_video_reg_pkg::VIDEO_MODE_SCALE_LSB) |
                  (32'(SrcH) << htx_video_reg_pkg::VIDEO_MODE_SRC_HEIGHT_LSB) |
                  (32'(SrcW) << htx_video_reg_pkg::VIDEO_MODE_SRC_WIDTH_LSB);
      default: ;
    endcase
  end

  logic clear_underrun;
  assign clear_underrun = act_write_q && (act_offset_q == htx_video_reg_pkg::VIDEO_STATUS_OFFSET) &&
                          act_wdata_q[htx_video_reg_pkg::VIDEO_STATUS_UNDERRUN_LSB];

  // ---- Line fetch ------------------------------------------------------------------------------
  // Line 0 is read during the last Scale lines of blanking, where the frame's enable is taken;
  // line L + 1 while line L is shown, from the end of the line before L's first (line_due: a
  // source line's first picture line comes next, so its read must be over).
  logic             start_frame, line_due, start_next, start;
  logic             f_busy_q, f_bank_q, w_pend_q, w_bank_q;
  logic [FAW-1:0]   f_addr_q, next_base_q, page_base;
  logic [LbAW-1:0]  f_idx_q, w_idx_q;
  logic             f_last;
  assign start_frame = line_end && (v == 10'(VTotal - Scale - 1));
  // (comparisons with constants, SrcH - 1 and SrcH - 2, so no adder: SrcH > 1 guards the second)
  assign line_due    = show_q && (frame_end || (line_end && v_active && (ysub_q == SW'(Scale - 1)) &&
                                                 (32'(ys_q) < 32'(SrcH - 1))));
  assign start_next  = line_due && (SrcH > 1) && (frame_end || (32'(ys_q) < 32'(SrcH - 2)));
  assign start  = (start_frame && enable_q) || start_next;
  assign f_last = (f_idx_q == LbAW'(Wpl - 1));
  // The page a frame shows is taken at its start, with the enable (page_q is below Pages).
  assign page_base = (page_q[0] ? FAW'(PageWords) : '0) + (page_q[1] ? FAW'(2 * PageWords) : '0);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      f_busy_q    <= 1'b0;
      f_bank_q    <= 1'b0;
      f_addr_q    <= '0;
      next_base_q <= '0;
      f_idx_q     <= '0;
      w_pend_q    <= 1'b0;
      w_bank_q    <= 1'b0;
      w_idx_q     <= '0;
      show_q      <= 1'b0;
      shown_page_q <= 2'd0;
    end else begin
      w_pend_q <= f_busy_q && fb_gnt_i;
      if (f_busy_q && fb_gnt_i) begin
        w_bank_q <= f_bank_q;
        w_idx_q  <= f_idx_q;
        f_addr_q <= f_addr_q + FAW'(1);
        f_idx_q  <= f_idx_q + LbAW'(1);
        if (f_last) f_busy_q <= 1'b0;
      end
      if (start_frame) begin
        show_q       <= enable_q;
        shown_page_q <= page_q;
      end
      if (start) begin
        f_busy_q    <= 1'b1;
        f_idx_q     <= '0;
        // The half a line goes to is its parity, as the scan reads it (ys_q[0]): line 0, line 1
        // at the frame's end, else line ys_q + 2.
        f_bank_q    <= start_frame ? 1'b0 : (frame_end ? 1'b1 : ys_q[0]);
        f_addr_q    <= start_frame ? page_base : next_base_q;
        next_base_q <= (start_frame ? page_base : next_base_q) + FAW'(Wpl);
      end
    end
  end
  assign fb_req_o  = f_busy_q;
  assign fb_addr_o = AddrW'(f_addr_q);
  assign busy_o    = f_busy_q || w_pend_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      enable_q      <= 1'b0;
      page_q        <= 2'd0;
      underrun_q    <= 1'b0;
      frame_count_q <= '0;
    end else begin
      if (act_write_q && (act_offset_q == htx_video_reg_pkg::VIDEO_CTRL_OFFSET)) begin
        enable_q <= act_wdata_q[htx_video_reg_pkg::VIDEO_CTRL_ENABLE_LSB];
        // A page the memory does not have leaves the field as it was.
        if (32'(act_wdata_q[htx_video_reg_pkg::VIDEO_CTRL_PAGE_LSB +: 2]) < Pages) begin
          page_q <= act_wdata_q[htx_video_reg_pkg::VIDEO_CTRL_PAGE_LSB +: 2];
        end
      end
      // A line due while its read is unfinished (this wins over a clear).
      if (line_due && f_busy_q) begin
        underrun_q <= 1'b1;
      end else if (clear_underrun) begin
        underrun_q <= 1'b0;
      end
      if (line_end && (v == 10'(VActive - 1))) frame_count_q <= frame_count_q + 32'd1;
    end
  end
  // ---- Line buffer: two halves of Wpl words, written by the fetch, read by the scan ------------
  logic [31:0] lb_q [2 << LbAW];
  logic [31:0] lb_rdata_q;
  always_ff @(posedge clk_i) begin
    if (w_pend_q) lb_q[{w_bank_q, w_idx_q}] <= fb_data_i;
    lb_rdata_q <= lb_q[{ys_q[0], LbAW'(xs_q >> 1)}];
  end

  // ---- Output: the line buffer's word in stage 1, the pixel in stage 2 --------------------------
  logic s1_de_q, s1_hs_q, s1_vs_q, s1_lane_q;
  logic [15:0] pix;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      s1_de_q   <= 1'b0;
      s1_hs_q   <= 1'b0;
      s1_vs_q   <= 1'b0;
      s1_lane_q <= 1'b0;
      de_o      <= 1'b0;
      hsync_no  <= 1'b1;
      vsync_no  <= 1'b1;
      rgb_o     <= '0;
    end else begin
      s1_de_q   <= active;
      s1_hs_q   <= hsync;
      s1_vs_q   <= vsync;
      s1_lane_q <= xs_q[0];
      de_o      <= s1_de_q;
      hsync_no  <= !s1_hs_q;
      vsync_no  <= !s1_vs_q;
      rgb_o     <= (s1_de_q && show_q) ? {pix[15:11], pix[15:13], pix[10:5], pix[10:9],
                                          pix[4:0], pix[4:2]} : 24'd0;
    end
  end
  assign pix = s1_lane_q ? lb_rdata_q[31:16] : lb_rdata_q[15:0];

  logic unused;
  assign unused = ^h;
endmodule
