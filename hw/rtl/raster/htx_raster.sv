// The raster unit (docs/raster.md): register block (hw/regs/raster.json), vertex FIFO with bus
// back-pressure, input assembly, setup, traversal, interpolation output and the fragment stage with
// the fast clear. The framebuffer and depth memories sit outside (hw/rtl/fb/htx_fb.sv).
// Parameters are the fields of the model's ModelConfig (docs/model.md) that this slice builds.
module htx_raster #(
  parameter int unsigned XyIntBits  = 16,
  parameter int unsigned ZBits      = 24,
  parameter int unsigned GF         = 24,
  parameter int unsigned RecipW     = 32,
  parameter int unsigned RecipK     = 10,
  parameter int unsigned RecipG     = 2,
  parameter int unsigned SetupSteps = 2,
  parameter bit          Iterative  = 1'b0,  // setup multipliers: 0 one product per clock, 1 shift-add
  parameter int unsigned FifoDepth  = 64,
  parameter int unsigned FbPixels   = 76800,
  parameter int unsigned AddrW      = 24
) (
  input  logic              clk_i,
  input  logic              rst_ni,

  // Register block (bus slave).
  input  logic              req_valid_i,
  output logic              req_ready_o,
  input  logic [31:0]       req_addr_i,
  input  logic              req_we_i,
  input  logic [3:0]        req_be_i,
  input  logic [31:0]       req_wdata_i,
  output logic              rsp_valid_o,
  output logic [31:0]       rsp_rdata_o,
  output logic              rsp_err_o,

  // Memory ports to htx_fb.
  output logic              zr_en_o,
  output logic [AddrW-1:0]  zr_addr_o,
  input  logic [ZBits-1:0]  zr_data_i,
  output logic              wc_en_o,
  output logic              wz_en_o,
  output logic [AddrW-1:0]  w_addr_o,
  output logic [15:0]       wc_data_o,
  output logic [ZBits-1:0]  wz_data_o
);
  localparam int unsigned XW   = XyIntBits + 8;
  localparam int unsigned DW   = XW + 1;
  localparam int unsigned EW   = 2 * DW + 2;
  localparam int unsigned AccZ = ZBits + GF + 2;
  localparam int unsigned AccC = 8 + GF + 2;
  localparam int unsigned LvlW = $clog2(FifoDepth) + 1;

  // ---- Registers -------------------------------------------------------------------------------
  logic [11:0] offset;
  logic        accept, wr, is_fifo, fifo_full, fifo_empty;
  logic        enable_q, err_state_q;
  logic [15:0] clear_color_q;
  logic [23:0] clear_depth_q;
  logic [12:0] width_q, height_q, stride_q;
  logic        abort, clear_req, cnt_reset;
  logic        clr_pend_q, clr_color_q, clr_depth_q;
  logic [LvlW-1:0] fifo_level;

  assign offset  = req_addr_i[11:0];
  assign wr      = req_we_i && (&req_be_i);
  assign is_fifo = (offset == htx_raster_reg_pkg::RASTER_FIFO_OFFSET);
  // A full FIFO holds the write on the bus until a word leaves: back-pressure, never a drop.
  assign req_ready_o = !(is_fifo && req_we_i && fifo_full);
  assign accept = req_valid_i && req_ready_o;

  logic ctrl_wr;
  assign ctrl_wr   = accept && wr && (offset == htx_raster_reg_pkg::RASTER_CTRL_OFFSET);
  assign abort     = ctrl_wr && req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_ABORT_LSB];
  assign clear_req = ctrl_wr && (req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_COLOR_LSB] ||
                                 req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_DEPTH_LSB]);
  assign cnt_reset = ctrl_wr && req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_COUNTERS_RESET_LSB];

  // ---- FIFO and input --------------------------------------------------------------------------
  logic        fifo_pop;
  logic [31:0] fifo_rdata;
  htx_raster_fifo #(.Depth(FifoDepth)) u_fifo (
    .clk_i, .rst_ni,
    .flush_i(abort),
    .push_i (accept && is_fifo && req_we_i),
    .wdata_i(req_wdata_i),
    .pop_i  (fifo_pop),
    .rdata_o(fifo_rdata),
    .full_o (fifo_full),
    .empty_o(fifo_empty),
    .level_o(fifo_level)
  );

  logic               rec_valid, rec_ready, in_partial, in_busy;
  logic [31:0]        rec_state;
  logic [3*XW-1:0]    rec_x, rec_y;
  logic [3*ZBits-1:0] rec_z;
  logic [3*32-1:0]    rec_rgba;
  htx_raster_input #(.XW(XW), .ZBits(ZBits)) u_input (
    .clk_i, .rst_ni,
    .abort_i     (abort),
    .enable_i    (enable_q),
    .fifo_empty_i(fifo_empty),
    .fifo_pop_o  (fifo_pop),
    .fifo_rdata_i(fifo_rdata),
    .rec_valid_o (rec_valid),
    .rec_ready_i (rec_ready),
    .rec_state_o (rec_state),
    .rec_x_o     (rec_x),
    .rec_y_o     (rec_y),
    .rec_z_o     (rec_z),
    .rec_rgba_o  (rec_rgba),
    .busy_o      (in_busy),
    .partial_o   (in_partial)
  );

  // ---- Setup -----------------------------------------------------------------------------------
  logic               tri_valid, tri_ready;
  logic [31:0]        tri_state, tri_flat;
  logic [12:0]        tri_x_lo, tri_x_hi, tri_y_lo, tri_y_hi;
  logic [3*DW-1:0]    tri_a, tri_b;
  logic [2:0]         tri_thr;
  logic [3*EW-1:0]    tri_e;
  logic [3*AccZ-1:0]  tri_z;
  logic [9*AccC-1:0]  tri_c;
  logic               setup_busy, setup_stall, setup_taken, setup_err;
  htx_raster_setup #(
    .XyIntBits(XyIntBits), .ZBits(ZBits), .GF(GF), .RecipW(RecipW), .RecipK(RecipK),
    .RecipG(RecipG), .NrSteps(SetupSteps), .Iterative(Iterative)
  ) u_setup (
    .clk_i, .rst_ni,
    .abort_i        (abort),
    .width_i        (width_q),
    .height_i       (height_q),
    .rec_valid_i    (rec_valid),
    .rec_ready_o    (rec_ready),
    .hold_i         (clr_pend_q),
    .rec_state_i    (rec_state),
    .rec_x_i        (rec_x),
    .rec_y_i        (rec_y),
    .rec_z_i        (rec_z),
    .rec_rgba_i     (rec_rgba),
    .tri_valid_o    (tri_valid),
    .tri_ready_i    (tri_ready),
    .tri_state_o    (tri_state),
    .tri_flat_rgba_o(tri_flat),
    .tri_x_lo_o     (tri_x_lo),
    .tri_x_hi_o     (tri_x_hi),
    .tri_y_lo_o     (tri_y_lo),
    .tri_y_hi_o     (tri_y_hi),
    .tri_a_o        (tri_a),
    .tri_b_o        (tri_b),
    .tri_thr_o      (tri_thr),
    .tri_e_o        (tri_e),
    .tri_z_o        (tri_z),
    .tri_c_o        (tri_c),
    .busy_o         (setup_busy),
    .stall_o        (setup_stall),
    .taken_o        (setup_taken),
    .err_o          (setup_err)
  );

  // ---- Traversal -------------------------------------------------------------------------------
  logic              tv_valid, tv_ready, trav_busy, trav_stall;
  logic [12:0]       tv_x, tv_y;
  logic [AddrW-1:0]  tv_addr;
  logic [AccZ-1:0]   tv_z;
  logic [3*AccC-1:0] tv_c;
  logic [31:0]       tv_state, tv_flat;
  htx_raster_traverse #(.DW(DW), .EW(EW), .AccZ(AccZ), .AccC(AccC), .AddrW(AddrW)) u_traverse (
    .clk_i, .rst_ni,
    .abort_i         (abort),
    .stride_i        (stride_q),
    .tri_valid_i     (tri_valid),
    .tri_ready_o     (tri_ready),
    .tri_state_i     (tri_state),
    .tri_flat_rgba_i (tri_flat),
    .tri_x_lo_i      (tri_x_lo),
    .tri_x_hi_i      (tri_x_hi),
    .tri_y_lo_i      (tri_y_lo),
    .tri_y_hi_i      (tri_y_hi),
    .tri_a_i         (tri_a),
    .tri_b_i         (tri_b),
    .tri_thr_i       (tri_thr),
    .tri_e_i         (tri_e),
    .tri_z_i         (tri_z),
    .tri_c_i         (tri_c),
    .frag_valid_o    (tv_valid),
    .frag_ready_i    (tv_ready),
    .frag_x_o        (tv_x),
    .frag_y_o        (tv_y),
    .frag_addr_o     (tv_addr),
    .frag_z_o        (tv_z),
    .frag_c_o        (tv_c),
    .frag_state_o    (tv_state),
    .frag_flat_rgba_o(tv_flat),
    .busy_o          (trav_busy),
    .stall_o         (trav_stall)
  );

  // ---- Interpolation output, then the fragment stage (a texture stage goes between them) -------
  logic              sh_valid, sh_ready;
  logic [12:0]       sh_x, sh_y;
  logic [AddrW-1:0]  sh_addr;
  logic [ZBits-1:0]  sh_z;
  logic [23:0]       sh_rgb;
  logic [31:0]       sh_state;
  htx_raster_shade #(.ZBits(ZBits), .GF(GF), .AddrW(AddrW)) u_shade (
    .clk_i, .rst_ni,
    .abort_i       (abort),
    .in_valid_i    (tv_valid),
    .in_ready_o    (tv_ready),
    .in_x_i        (tv_x),
    .in_y_i        (tv_y),
    .in_addr_i     (tv_addr),
    .in_z_i        (tv_z),
    .in_c_i        (tv_c),
    .in_state_i    (tv_state),
    .in_flat_rgba_i(tv_flat),
    .out_valid_o   (sh_valid),
    .out_ready_i   (sh_ready),
    .out_x_o       (sh_x),
    .out_y_o       (sh_y),
    .out_addr_o    (sh_addr),
    .out_z_o       (sh_z),
    .out_rgb_o     (sh_rgb),
    .out_state_o   (sh_state)
  );

  logic frag_busy, clearing, pixel, clear_start;
  htx_raster_fragment #(.ZBits(ZBits), .AddrW(AddrW), .FbPixels(FbPixels)) u_fragment (
    .clk_i, .rst_ni,
    .abort_i       (abort),
    .in_valid_i    (sh_valid),
    .in_ready_o    (sh_ready),
    .in_addr_i     (sh_addr),
    .in_z_i        (sh_z),
    .in_rgb_i      (sh_rgb),
    .in_state_i    (sh_state),
    .clear_start_i (clear_start),
    .clear_color_i (clr_color_q),
    .clear_depth_i (clr_depth_q),
    .clear_rgb565_i(clear_color_q),
    .clear_z_i     (clear_depth_q),
    .height_i      (height_q),
    .stride_i      (stride_q),
    .clearing_o    (clearing),
    .zr_en_o, .zr_addr_o, .zr_data_i,
    .wc_en_o, .wz_en_o, .w_addr_o, .wc_data_o, .wz_data_o,
    .busy_o        (frag_busy),
    .pixel_o       (pixel)
  );

  // A clear waits until setup holds nothing and every later stage is empty; setup takes no new
  // triangle meanwhile (hold_i), so the clear lands between the triangles before and after it.
  logic pipe_idle;
  assign pipe_idle   = !setup_busy && !tri_valid && !trav_busy && !sh_valid && !frag_busy;
  assign clear_start = clr_pend_q && pipe_idle && !clearing;

  logic busy;
  assign busy = !fifo_empty || in_busy || setup_busy || tri_valid || trav_busy || sh_valid ||
                frag_busy || clr_pend_q;

  // ---- Counters --------------------------------------------------------------------------------
  logic [31:0] cnt_busy_q, cnt_stall_in_q, cnt_stall_setup_q, cnt_stall_frag_q, cnt_setup_q;
  logic [31:0] cnt_tri_q, cnt_frag_q, cnt_pix_q;

  // ---- Register writes and reads ---------------------------------------------------------------
  logic [31:0] rdata_d, rsp_rdata_q;
  logic        rsp_valid_q;
  logic [31:0] last_state_q;
  always_comb begin
    rdata_d = '0;
    unique case (offset)
      htx_raster_reg_pkg::RASTER_CTRL_OFFSET:
        rdata_d[htx_raster_reg_pkg::RASTER_CTRL_ENABLE_LSB] = enable_q;
      htx_raster_reg_pkg::RASTER_STATUS_OFFSET: begin
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_BUSY_LSB]       = busy;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_CLEARING_LSB]   = clearing || clr_pend_q;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_FIFO_EMPTY_LSB] = fifo_empty;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_FIFO_FULL_LSB]  = fifo_full;
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_FIFO_LEVEL_LSB +: 8] =
          (32'(fifo_level) > 255) ? 8'hFF : 8'(fifo_level);
        rdata_d[htx_raster_reg_pkg::RASTER_STATUS_ERR_STATE_LSB]  = err_state_q;
      end
      htx_raster_reg_pkg::RASTER_CLEAR_COLOR_OFFSET: rdata_d = 32'(clear_color_q);
      htx_raster_reg_pkg::RASTER_CLEAR_DEPTH_OFFSET: rdata_d = 32'(clear_depth_q);
      htx_raster_reg_pkg::RASTER_FB_SIZE_OFFSET: begin
        rdata_d[htx_raster_reg_pkg::RASTER_FB_SIZE_WIDTH_LSB +: 13]  = width_q;
        rdata_d[htx_raster_reg_pkg::RASTER_FB_SIZE_HEIGHT_LSB +: 13] = height_q;
      end
      htx_raster_reg_pkg::RASTER_FB_STRIDE_OFFSET: rdata_d = 32'(stride_q);
      htx_raster_reg_pkg::RASTER_STATE_OFFSET: rdata_d = last_state_q;
      htx_raster_reg_pkg::RASTER_CNT_BUSY_OFFSET:           rdata_d = cnt_busy_q;
      htx_raster_reg_pkg::RASTER_CNT_STALL_INPUT_OFFSET:    rdata_d = cnt_stall_in_q;
      htx_raster_reg_pkg::RASTER_CNT_STALL_SETUP_OFFSET:    rdata_d = cnt_stall_setup_q;
      htx_raster_reg_pkg::RASTER_CNT_STALL_FRAGMENT_OFFSET: rdata_d = cnt_stall_frag_q;
      htx_raster_reg_pkg::RASTER_CNT_SETUP_BUSY_OFFSET:     rdata_d = cnt_setup_q;
      htx_raster_reg_pkg::RASTER_CNT_TRIANGLES_OFFSET:      rdata_d = cnt_tri_q;
      htx_raster_reg_pkg::RASTER_CNT_FRAGMENTS_OFFSET:      rdata_d = cnt_frag_q;
      htx_raster_reg_pkg::RASTER_CNT_PIXELS_OFFSET:         rdata_d = cnt_pix_q;
      default: ;  // CNT_DIVFREE_STEPS: no DIVFREE is built in this slice
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      enable_q      <= 1'(htx_raster_reg_pkg::RASTER_CTRL_ENABLE_RESET >> htx_raster_reg_pkg::RASTER_CTRL_ENABLE_LSB);
      err_state_q   <= 1'b0;
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
      rsp_rdata_q   <= '0;
      cnt_busy_q <= '0; cnt_stall_in_q <= '0; cnt_stall_setup_q <= '0; cnt_stall_frag_q <= '0;
      cnt_setup_q <= '0; cnt_tri_q <= '0; cnt_frag_q <= '0; cnt_pix_q <= '0;
    end else begin
      rsp_valid_q <= accept;
      if (accept && !req_we_i) rsp_rdata_q <= rdata_d;
      if (setup_taken) last_state_q <= rec_state;
      if (setup_err) err_state_q <= 1'b1;
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
          default: ;
        endcase
      end
      // Clear: requested, then started by the fragment stage once the pipeline is empty.
      if (abort) begin
        clr_pend_q <= 1'b0;
      end else if (clear_req) begin
        clr_pend_q  <= 1'b1;
        clr_color_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_COLOR_LSB];
        clr_depth_q <= req_wdata_i[htx_raster_reg_pkg::RASTER_CTRL_CLEAR_DEPTH_LSB];
      end else if (clear_start) begin
        clr_pend_q <= 1'b0;
      end
      if (cnt_reset) begin
        cnt_busy_q <= '0; cnt_stall_in_q <= '0; cnt_stall_setup_q <= '0; cnt_stall_frag_q <= '0;
        cnt_setup_q <= '0; cnt_tri_q <= '0; cnt_frag_q <= '0; cnt_pix_q <= '0;
      end else begin
        cnt_busy_q        <= cnt_busy_q + 32'(busy);
        cnt_stall_in_q    <= cnt_stall_in_q + 32'(in_partial);
        cnt_stall_setup_q <= cnt_stall_setup_q + 32'(setup_stall);
        cnt_stall_frag_q  <= cnt_stall_frag_q + 32'(trav_stall);
        cnt_setup_q       <= cnt_setup_q + 32'(setup_busy);
        cnt_tri_q         <= cnt_tri_q + 32'(setup_taken);
        cnt_frag_q        <= cnt_frag_q + 32'(tv_valid && tv_ready);
        cnt_pix_q         <= cnt_pix_q + 32'(pixel);
      end
    end
  end

  assign rsp_valid_o = rsp_valid_q;
  assign rsp_rdata_o = rsp_rdata_q;
  assign rsp_err_o   = 1'b0;

  logic unused;
  assign unused = ^{req_addr_i[31:12], sh_x, sh_y, clearing};
endmodule
