// The raster unit (docs/raster.md): register block (htx_raster_regs), vertex FIFO with bus
// back-pressure, input assembly, setup, traversal, interpolation output and the fragment stage with
// the fast clear. The framebuffer and depth memories sit outside (hw/rtl/fb/htx_fb.sv).
// Parameters are the fields of the model's ModelConfig (docs/model.md) that this unit builds.
// Every fragment that leaves traversal gets its texel coordinates from the perspective method
// (shade: AFFINE; divider: RECIP_LUT, RECIP_NR, SUBDIV's exact points, perspective colour; subdiv:
// SUBDIV's inner pixels) and leaves on the texture request port (docs/raster.md, "Texture port";
// docs/contracts.md); the texel comes back in order with the fragment in its tag, then htx_tex_combine
// and the fragment stage. Built without any method (Methods = 0) the unit has no texture mapping:
// fragments go from the request stage to the fragment stage, and textured triangles are refused.
module htx_raster #(
  parameter int unsigned XyIntBits  = 16,
  parameter int unsigned ZBits      = 24,
  parameter int unsigned GF         = 24,
  parameter int unsigned RecipW     = 32,
  parameter int unsigned RecipK     = 10,
  parameter int unsigned RecipG     = 2,
  parameter int unsigned SetupSteps = 2,
  // The `icebreaker` datapath: the iterative per-pixel divider, the traversal's planes in RAM,
  // the serial combine; needs FwSetup (setup in firmware) and only it does.
  parameter bit          Iterative  = 1'b0,
  parameter int unsigned FifoDepth  = 64,
  parameter int unsigned FbPixels   = 76800,
  parameter int unsigned AddrW      = 24,
  parameter int unsigned QBits      = 32,
  parameter int unsigned UvIntBits  = 16,
  parameter int unsigned TF         = 16,       // texcoord_frac_bits
  parameter int unsigned PixelSteps = 2,        // pixel_nr_steps
  parameter logic [4:0]  Methods    = 5'b01111, // bit m: htx::Method m built (4: DIVFREE)
  parameter bit          PerspColor = 1'b1,     // perspective_color
  parameter bit          PixelPipelined = 1'b1, // per-pixel divider: pipelined, else iterative
  parameter bit          PixelMulIterative = 1'b0, // iterative divider's multiplier: shift-and-add
  parameter int unsigned SubdivDepth = 128,     // SUBDIV fragment FIFO (>= 64)
  parameter int unsigned DfFracBits = 4,        // divfree_frac_bits
  parameter int unsigned DfCap      = 64,       // divfree_cap
  parameter int unsigned LF         = 8,        // lod_frac_bits (DIVFREE's level choice)
  parameter int unsigned LogIdx     = 10,       // lod_log_index_bits
  parameter int unsigned CoordW     = 48,
  parameter int unsigned QW         = QBits + GF + 2,
  parameter int unsigned GradW      = 24,       // lod_grad_bits
  parameter int unsigned LocW       = UvIntBits + TF,
  parameter int unsigned TexTagW    = htx_raster_pkg::tex_tag_w(AddrW, ZBits),
  // The CNT_* event counters (CAPS.COUNTERS); the board's build leaves them out (docs/area.md).
  parameter bit          Counters   = 1'b1,
  // Setup is the firmware's (CAPS.FW_SETUP; `icebreaker`, docs/raster.md "Plane record"): the FIFO
  // takes plane records, which htx_raster_planes_in writes into the traversal's plane RAM, in place
  // of the input stage and htx_raster_setup. Needs Iterative (the traversal's planes in RAM).
  parameter bit          FwSetup    = 1'b0,
  // Colour pages in htx_fb (FB_MEM.PAGES; 2 or 3: double or triple buffering, FB_PAGE.DRAW chooses
  // the one written).
  parameter int unsigned ColorPages = 1
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
  input  logic              clear_hold_i,   // the fast clear waits (the video scan-out reads)
  output logic              zr_en_o,
  output logic [AddrW-1:0]  zr_addr_o,
  input  logic [ZBits-1:0]  zr_data_i,
  output logic              wc_en_o,
  output logic              wz_en_o,
  output logic [AddrW-1:0]  w_addr_o,
  output logic [15:0]       wc_data_o,
  output logic [ZBits-1:0]  wz_data_o,
  output logic [1:0]        draw_page_o,    // FB_PAGE.DRAW: the colour page wc_* writes

  // Texture request / response (docs/contracts.md, GPU join §1; mirrors htx_texture's req_* / out_*).
  output logic               tex_req_valid_o,
  input  logic               tex_req_ready_i,
  output logic [CoordW-1:0]  tex_req_u_o,
  output logic [CoordW-1:0]  tex_req_v_o,
  output logic [1:0]         tex_req_filter_o,
  output logic [1:0]         tex_req_wrap_u_o,
  output logic [1:0]         tex_req_wrap_v_o,
  output logic [7:0]         tex_req_slot_o,
  output logic               tex_req_lod_direct_o,
  output logic [23:0]        tex_req_lod_o,
  output logic [QW-1:0]      tex_req_lod_q_o,
  output logic [GradW-1:0]   tex_req_lod_gux_o, tex_req_lod_guy_o, tex_req_lod_gvx_o,
  output logic [GradW-1:0]   tex_req_lod_gvy_o, tex_req_lod_gqx_o, tex_req_lod_gqy_o,
  output logic [7:0]         tex_req_lod_shift_o,
  output logic [LocW-1:0]    tex_req_lod_u_o, tex_req_lod_v_o,
  output logic [TexTagW-1:0] tex_req_tag_o,
  input  logic               tex_out_valid_i,
  output logic               tex_out_ready_o,
  input  logic [31:0]        tex_out_rgba_i,
  input  logic [TexTagW-1:0] tex_out_tag_i
);
  localparam int unsigned XW   = XyIntBits + 8;
  localparam int unsigned DW   = XW + 1;
  localparam int unsigned EW   = 2 * DW + 2;
  localparam int unsigned UQ   = QBits + UvIntBits;
  localparam int unsigned CB   = PerspColor ? 8 + QBits : 8;
  localparam int unsigned AccZ = ZBits + GF + 2;
  localparam int unsigned AccC = CB + GF + 2;
  localparam int unsigned AccQ = QBits + GF + 2;
  localparam int unsigned AccU = UQ + GF + 2;
  localparam int unsigned AW   = (AccU > AccC) ? ((AccU > AccZ) ? AccU : AccZ)
                                               : ((AccC > AccZ) ? AccC : AccZ);
  localparam int unsigned NP   = 9;
  // Methods = 0 builds no texture mapping (CAPS.METHODS reads 0): the planes are z and the colour
  // channels only, at the width of the edge values that share their RAM (AWP), no per-pixel
  // divider (setup has its own reciprocal unit), and fragments go from the request stage straight
  // to the fragment stage; the texture port stays idle. Setup refuses textured triangles.
  localparam bit          Textured = |Methods;
  localparam int unsigned AWZC = (AccC > AccZ) ? AccC : AccZ;
  localparam int unsigned AWP  = Textured ? AW : ((AWZC > EW) ? AWZC : EW);
  localparam int unsigned SideW = 136 + 6 * GradW;  // state, flat, u_off, v_off, LOD gradients, shift
  // DIVFREE's seed takes the uq, vq, q gradients at full precision; they travel beside the side band
  // as far as the DIVFREE stage.
  localparam int unsigned GWU   = UQ + DW + 2 + GF + 1;
  localparam bit          HasDf = Methods[4];
  localparam int unsigned DfgW  = HasDf ? 6 * GWU : 1;
  localparam int unsigned SideT = SideW + DfgW;
  localparam int unsigned LvlW = $clog2(FifoDepth) + 1;

  // ---- Registers -------------------------------------------------------------------------------
  // The register block (htx_raster_regs) is instantiated below, once the status it reads is named.
  logic        abort, enable, fifo_push, fifo_full, fifo_empty;
  logic [12:0] fb_width, fb_height, fb_stride;
  logic [15:0] clear_color;
  logic [23:0] clear_depth;
  logic        clr_pend, clr_color, clr_depth;
  logic [LvlW-1:0] fifo_level;

  // ---- FIFO and input --------------------------------------------------------------------------
  logic        fifo_pop;
  logic [31:0] fifo_rdata;
  // `icebreaker` (Iterative): an AFFINE triangle's u, v planes take the places of its uq, vq
  // planes, which it does not use (its plane record puts them there, FoldUv), so the traversal
  // steps seven planes a pass instead of nine; planes 7 and 8 of the fragment are its planes 5, 6.
  localparam bit          FoldUv = Iterative && Textured;
  localparam int unsigned NPT    = !Textured ? 4 : FoldUv ? 7 : NP;
  htx_raster_fifo #(.Depth(FifoDepth)) u_fifo (
    .clk_i, .rst_ni,
    .flush_i   (abort),
    .push_i    (fifo_push),
    .wdata_i   (req_wdata_i),
    .pop_i     (fifo_pop),
    .rdata_o   (fifo_rdata),
    .full_o    (fifo_full),
    .empty_o   (fifo_empty),
    .level_o   (fifo_level)
  );

  logic               in_partial, in_busy;
  logic [31:0]        rec_state;
  // ---- Setup -----------------------------------------------------------------------------------
  logic               tri_valid, tri_ready;
  logic [31:0]        tri_state, tri_flat, tri_u_off, tri_v_off;
  logic [12:0]        tri_x_lo, tri_x_hi, tri_y_lo, tri_y_hi;
  logic [3*DW-1:0]    tri_a, tri_b;
  logic [2:0]         tri_thr, tri_a_zero;
  logic               tri_dneg;
  logic [3*EW-1:0]    tri_e;
  logic [3*NP*AWP-1:0] tri_p;
  logic               pl_we;
  logic [1:0]         pl_sel;
  logic [3:0]         pl_idx;
  logic [AWP:0]       pl_data;
  logic [6*GradW-1:0] tri_lod_g;
  logic [7:0]         tri_lod_shift;
  logic [6*GWU-1:0]   tri_dfg;
  logic [DfgW-1:0]    tri_dfg_side;
  logic               setup_busy, setup_stall, setup_taken, setup_err;
  // Setup in hardware is the `full` configuration's (Iterative = 0); the configuration with the
  // iterative units takes plane records (FwSetup), whose planes only its traversal (planes in RAM)
  // reads. The time-multiplexed hardware setup that once served it is in the history
  // (docs/raster.md, "Setup").
  if (Iterative != FwSetup) begin : g_bad_config
    $error("htx_raster: Iterative and FwSetup go together (setup in firmware for the iterative units)");
  end

  if (FwSetup) begin : g_fw_setup
    // The firmware did setup: the reader takes the plane records.
    htx_raster_planes_in #(.Methods(Methods), .DW(DW), .EW(EW), .AW(AWP), .GradW(GradW), .GWU(GWU)) u_planes_in (
      .clk_i, .rst_ni,
      .abort_i        (abort),
      .enable_i       (enable),
      .hold_i         (clr_pend),
      .width_i        (fb_width),
      .height_i       (fb_height),
      .fifo_empty_i   (fifo_empty),
      .fifo_pop_o     (fifo_pop),
      .fifo_rdata_i   (fifo_rdata),
      .tri_valid_o    (tri_valid),
      .tri_ready_i    (tri_ready),
      .tri_state_o    (tri_state),
      .tri_flat_rgba_o(tri_flat),
      .tri_x_lo_o     (tri_x_lo),
      .tri_x_hi_o     (tri_x_hi),
      .tri_y_lo_o     (tri_y_lo),
      .tri_y_hi_o     (tri_y_hi),
      .tri_a_o        (tri_a),
      .tri_a_zero_o   (tri_a_zero),
      .tri_thr_o      (tri_thr),
      .tri_dneg_o     (tri_dneg),
      .tri_e_o        (tri_e),
      .tri_u_off_o    (tri_u_off),
      .tri_v_off_o    (tri_v_off),
      .tri_lod_g_o    (tri_lod_g),
      .tri_lod_shift_o(tri_lod_shift),
      .tri_dfg_o      (tri_dfg),
      .pl_we_o        (pl_we),
      .pl_sel_o       (pl_sel),
      .pl_idx_o       (pl_idx),
      .pl_data_o      (pl_data),
      .busy_o         (setup_busy),
      .stall_o        (setup_stall),
      .partial_o      (in_partial),
      .taken_o        (setup_taken),
      .err_o          (setup_err)
    );
    assign in_busy     = 1'b0;
    assign rec_state   = fifo_rdata;  // (the state word, in the clock taken_o rises)
    assign tri_b       = '0;
    assign tri_p       = '0;
  end else begin : g_hw_setup
    logic               rec_valid, rec_ready;
    logic [31:0]        rec_u_off, rec_v_off;
    logic [3*XW-1:0]    rec_x, rec_y;
    logic [3*ZBits-1:0] rec_z;
    logic [3*32-1:0]    rec_rgba;
    logic [3*QBits-1:0] rec_q;
    logic [3*UQ-1:0]    rec_uq, rec_vq;
    htx_raster_input #(.XW(XW), .ZBits(ZBits), .QBits(QBits), .UQ(UQ)) u_input (
      .clk_i, .rst_ni,
      .abort_i     (abort),
      .enable_i    (enable),
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
      .rec_q_o     (rec_q),
      .rec_uq_o    (rec_uq),
      .rec_vq_o    (rec_vq),
      .rec_u_off_o (rec_u_off),
      .rec_v_off_o (rec_v_off),
      .busy_o      (in_busy),
      .partial_o   (in_partial)
    );

    htx_raster_setup #(
      .XyIntBits(XyIntBits), .ZBits(ZBits), .GF(GF), .RecipW(RecipW), .RecipK(RecipK),
      .RecipG(RecipG), .NrSteps(SetupSteps), .QBits(QBits),
      .UvIntBits(UvIntBits), .TF(TF), .GradW(GradW), .Methods(Methods), .PerspColor(PerspColor),
      .AW(AWP), .NP(NP)
    ) u_setup (
      .clk_i, .rst_ni,
      .abort_i        (abort),
      .width_i        (fb_width),
      .height_i       (fb_height),
      .rec_valid_i    (rec_valid),
      .rec_ready_o    (rec_ready),
      .hold_i         (clr_pend),
      .rec_state_i    (rec_state),
      .rec_x_i        (rec_x),
      .rec_y_i        (rec_y),
      .rec_z_i        (rec_z),
      .rec_rgba_i     (rec_rgba),
      .rec_q_i        (rec_q),
      .rec_uq_i       (rec_uq),
      .rec_vq_i       (rec_vq),
      .rec_u_off_i    (rec_u_off),
      .rec_v_off_i    (rec_v_off),
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
      .tri_a_zero_o   (tri_a_zero),
      .tri_thr_o      (tri_thr),
      .tri_dneg_o     (tri_dneg),
      .tri_e_o        (tri_e),
      .tri_p_o        (tri_p),
      .tri_u_off_o    (tri_u_off),
      .tri_v_off_o    (tri_v_off),
      .tri_lod_g_o    (tri_lod_g),
      .tri_lod_shift_o(tri_lod_shift),
      .tri_dfg_o      (tri_dfg),
      .busy_o         (setup_busy),
      .stall_o        (setup_stall),
      .taken_o        (setup_taken),
      .err_o          (setup_err)
    );
    // (The planes go on tri_p; the traversal's plane RAM is the plane records'.)
    assign pl_we   = 1'b0;
    assign pl_sel  = '0;
    assign pl_idx  = '0;
    assign pl_data = '0;
  end

  // ---- Traversal -------------------------------------------------------------------------------
  logic              tv_valid, tv_ready, trav_busy, trav_stall, tv_first, tv_last, tv_tfirst;
  logic [12:0]       tv_x, tv_y;
  logic [AddrW-1:0]  tv_addr;
  logic [NP*AW-1:0]  tv_p;
  logic [SideT-1:0]  tv_side;
  logic [NPT*AWP-1:0] tv_pt;
  if (!Textured) begin : g_zc_planes
    // z, r, g, b widened to the shade stage's plane width (it takes each plane's low bits).
    for (genvar p = 0; p < NP; p++) begin : g_p
      if (p < NPT) begin : g_built
        assign tv_p[AW*p +: AW] = AW'(tv_pt[AWP*p +: AWP]);
      end else begin : g_none
        assign tv_p[AW*p +: AW] = '0;
      end
    end
    logic unused_tri_p;
    assign unused_tri_p = ^tri_p[3*NP*AWP-1:3*NPT*AWP];
  end else if (FoldUv) begin : g_fold_uv
    assign tv_p = {tv_pt[AW*6 +: AW], tv_pt[AW*5 +: AW], tv_pt};
    logic unused_tri_p;
    assign unused_tri_p = ^tri_p[3*NP*AW-1:3*NPT*AW];  // (zero: the planes go through the RAM)
  end else begin : g_all_planes
    assign tv_p = tv_pt;
  end
  if (HasDf) begin : g_dfg
    assign tri_dfg_side = tri_dfg;
  end else begin : g_no_dfg
    assign tri_dfg_side = 1'b0;
    logic unused_dfg;
    assign unused_dfg = ^tri_dfg;
  end
  // `icebreaker` (Iterative) trades two clocks on some rows for the traversal's left look, 13
  // clocks per triangle for the row-offset multiplier, and NP + 3 clocks per step for the edges'
  // and planes' values (in block RAM, on one adder; setup writes each triangle's edges and planes
  // straight into that RAM, so neither keeps them in registers).
  htx_raster_traverse #(.DW(DW), .EW(EW), .NP(NPT), .AW(AWP), .SideW(SideT), .AddrW(AddrW),
                        .LookBehind(!Iterative),
                        .SerialPlanes(Iterative)) u_traverse (
    .clk_i, .rst_ni,
    .abort_i         (abort),
    .stride_i        (fb_stride),
    .tri_valid_i     (tri_valid),
    .tri_ready_o     (tri_ready),
    .tri_side_i      ({tri_dfg_side, tri_lod_shift, tri_lod_g, tri_v_off, tri_u_off, tri_flat, tri_state}),
    .tri_x_lo_i      (tri_x_lo),
    .tri_x_hi_i      (tri_x_hi),
    .tri_y_lo_i      (tri_y_lo),
    .tri_y_hi_i      (tri_y_hi),
    .tri_a_i         (tri_a),
    .tri_b_i         (tri_b),
    .tri_a_zero_i    (tri_a_zero),
    .tri_thr_i       (tri_thr),
    .tri_dneg_i      (tri_dneg),
    .tri_e_i         (tri_e),
    .tri_p_i         (tri_p[3*NPT*AWP-1:0]),
    .pl_we_i         (pl_we),
    .pl_sel_i        (pl_sel),
    .pl_idx_i        (pl_idx),
    .pl_data_i       (pl_data),
    .frag_valid_o    (tv_valid),
    .frag_ready_i    (tv_ready),
    .frag_x_o        (tv_x),
    .frag_y_o        (tv_y),
    .frag_addr_o     (tv_addr),
    .frag_first_o    (tv_first),
    .frag_last_o     (tv_last),
    .frag_tfirst_o   (tv_tfirst),
    .frag_p_o        (tv_pt),
    .frag_side_o     (tv_side),
    .busy_o          (trav_busy),
    .stall_o         (trav_stall)
  );

  // ---- Shade: depth, linear colour, AFFINE coordinates, SUBDIV exact points --------------------
  logic              sh_valid, sh_ready, sh_div_color, sh_exact, sh_first, sh_last, sh_tfirst;
  logic [12:0]       sh_x, sh_y;
  logic [AddrW-1:0]  sh_addr;
  logic [ZBits-1:0]  sh_z;
  logic [23:0]       sh_rgb;
  logic [LocW-1:0]   sh_ua, sh_va;
  logic [AccQ-1:0]   sh_q;
  logic [AccU-1:0]   sh_u, sh_v;
  logic [3*AccC-1:0] sh_c;
  logic [SideT-1:0]  sh_side;
  htx_raster_shade #(.ZBits(ZBits), .GF(GF), .NP(NP), .AW(AW), .SideW(SideT), .AccC(AccC),
                     .AccQ(AccQ), .AccU(AccU), .LocW(LocW), .PerspColor(PerspColor),
                     .Subdiv(Methods[1]),
                     .AddrW(AddrW), .Registered(!Iterative)) u_shade (
    .clk_i, .rst_ni,
    .abort_i        (abort),
    .in_valid_i     (tv_valid),
    .in_ready_o     (tv_ready),
    .in_addr_i      (tv_addr),
    .in_x_i         (tv_x),
    .in_first_i     (tv_first),
    .in_last_i      (tv_last),
    .in_y_i         (tv_y),
    .in_tfirst_i    (tv_tfirst),
    .in_p_i         (tv_p),
    .in_side_i      (tv_side),
    .out_valid_o    (sh_valid),
    .out_ready_i    (sh_ready),
    .out_addr_o     (sh_addr),
    .out_x_o        (sh_x),
    .out_y_o        (sh_y),
    .out_first_o    (sh_first),
    .out_last_o     (sh_last),
    .out_tfirst_o   (sh_tfirst),
    .out_z_o        (sh_z),
    .out_rgb_o      (sh_rgb),
    .out_div_color_o(sh_div_color),
    .out_exact_o    (sh_exact),
    .out_ua_o       (sh_ua),
    .out_va_o       (sh_va),
    .out_q_o        (sh_q),
    .out_u_o        (sh_u),
    .out_v_o        (sh_v),
    .out_c_o        (sh_c),
    .out_side_o     (sh_side)
  );

  // ---- DIVFREE ---------------------------------------------------------------------------------
  // Its cell centres replace the AFFINE coordinates (ua, va) of a DIVFREE fragment; the fragment
  // then needs the divider only for perspective-correct colour.
  localparam int unsigned PayF = SideW + AddrW + ZBits + 24 + 2 * LocW + AccQ + 2 * AccU + 3 * AccC +
                                 1 + 13 + 1;
  logic              df_valid, df_ready, df_div_color, df_exact, df_is;
  logic [12:0]       df_x;
  logic [AddrW-1:0]  df_addr;
  logic [ZBits-1:0]  df_z;
  logic [23:0]       df_rgb;
  logic [LocW-1:0]   df_ua, df_va, df_cu, df_cv;
  logic [AccQ-1:0]   df_q;
  logic [AccU-1:0]   df_u, df_v;
  logic [3*AccC-1:0] df_c;
  logic [SideW-1:0]  df_side;
  logic              df_steps_valid;
  logic [15:0]       df_steps;
  logic [2:0]        sh_method0;
  assign sh_method0 = sh_side[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3];
  if (HasDf) begin : g_divfree
    logic [PayF-1:0] df_pay;
    htx_raster_divfree #(
      .AccQ(AccQ), .AccU(AccU), .UvIntBits(UvIntBits), .TF(TF), .LocW(LocW), .W(RecipW), .K(RecipK),
      .G(RecipG), .Steps(PixelSteps), .FracBits(DfFracBits), .Cap(DfCap), .GWU(GWU), .GradW(GradW),
      .LF(LF), .LogIdx(LogIdx), .PayW(PayF), .MulIterative(PixelMulIterative)
    ) u_divfree (
      .clk_i, .rst_ni,
      .abort_i      (abort),
      .in_valid_i   (sh_valid),
      .in_ready_o   (sh_ready),
      .in_df_i      (sh_method0 == htx_raster_pkg::MethodDivFree),
      .in_fine_i    (sh_side[htx_raster_reg_pkg::RASTER_STATE_FILTER_LSB +: 2] != 2'd0),
      // Level per span for textured bilinear/trilinear; the state word's SUBDIV_N field carries the
      // texture's last mip level for DIVFREE (docs/raster.md).
      .in_track_i   (sh_side[htx_raster_reg_pkg::RASTER_STATE_TEXTURED_LSB] &&
                     (sh_side[htx_raster_reg_pkg::RASTER_STATE_FILTER_LSB +: 2] != 2'd0)),
      .in_top_i     (sh_side[htx_raster_reg_pkg::RASTER_STATE_SUBDIV_N_LSB +: 4]),
      .in_lod_g_i   (sh_side[128 +: 6*GradW]),
      .in_lod_shift_i(sh_side[128 + 6*GradW +: 8]),
      .in_tfirst_i  (sh_tfirst),
      .in_first_i   (sh_first),
      .in_last_i    (sh_last),
      .in_x_i       (sh_x),
      .in_y_i       (sh_y),
      .in_q_i       (sh_q),
      .in_u_i       (sh_u),
      .in_v_i       (sh_v),
      .in_g_i       (sh_side[SideW +: DfgW]),
      .in_pay_i     ({sh_side[SideW-1:0], sh_addr, sh_z, sh_rgb, sh_ua, sh_va, sh_q, sh_u, sh_v, sh_c,
                      sh_exact, sh_x, sh_div_color}),
      .out_valid_o  (df_valid),
      .out_ready_i  (df_ready),
      .out_df_o     (df_is),
      .out_u_o      (df_cu),
      .out_v_o      (df_cv),
      .out_pay_o    (df_pay),
      .steps_valid_o(df_steps_valid),
      .steps_o      (df_steps)
    );
    logic [LocW-1:0] p_ua, p_va;
    assign {df_side, df_addr, df_z, df_rgb, p_ua, p_va, df_q, df_u, df_v, df_c, df_exact, df_x,
            df_div_color} = df_pay;
    assign df_ua = df_is ? df_cu : p_ua;
    assign df_va = df_is ? df_cv : p_va;
  end else begin : g_no_divfree
    assign df_valid = sh_valid;
    assign sh_ready = df_ready;
    assign {df_side, df_addr, df_z, df_rgb, df_ua, df_va, df_q, df_u, df_v, df_c, df_exact, df_x,
            df_div_color} = {sh_side[SideW-1:0], sh_addr, sh_z, sh_rgb, sh_ua, sh_va, sh_q, sh_u, sh_v,
                             sh_c, sh_exact, sh_x, sh_div_color};
    assign df_is = 1'b0;
    assign df_cu = '0;
    assign df_cv = '0;
    assign df_steps_valid = 1'b0;
    assign df_steps = '0;
    logic unused_df;
    assign unused_df = ^{sh_y, sh_first, sh_last, sh_tfirst, sh_side[SideT-1:SideW], df_is, df_cu, df_cv,
                         sh_method0};
  end

  // ---- Per-pixel divider -----------------------------------------------------------------------
  logic [2:0] sh_method;
  logic       sh_need;
  assign sh_method = df_side[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3];
  // Untextured fragments need no texel coordinates (the iterative divider skips them).
  // (Only built methods count: setup refuses the others, so their tests would be dead logic.)
  assign sh_need   = (df_side[htx_raster_reg_pkg::RASTER_STATE_TEXTURED_LSB] &&
                      ((Methods[2] && (sh_method == htx_raster_pkg::MethodRecipLut)) ||
                       (Methods[3] && (sh_method == htx_raster_pkg::MethodRecipNr)) ||
                       (Methods[1] && (sh_method == htx_raster_pkg::MethodSubdiv) && df_exact))) ||
                     df_div_color;
  // Payload past the divider: {side, addr, z, rgb, ua, va, q, exact, x, div_color}.
  localparam int unsigned PayD = SideW + AddrW + ZBits + 24 + 2 * LocW + AccQ + 1 + 13 + 1;
  logic              dv_valid, dv_ready;
  logic [LocW-1:0]   dv_u, dv_v;
  logic [23:0]       dv_rgb;
  logic [PayD-1:0]   dv_pay;
  // RECIP_LUT as the only method that divides per pixel and no perspective-correct colour (the
  // board's GPU): the divider without Newton steps (htx_raster_lut_divider).
  localparam bit LutDivider = Textured && !PixelPipelined && !PerspColor &&
                              !Methods[1] && !Methods[3] && !Methods[4];
  if (LutDivider) begin : g_lut_divider
    htx_raster_lut_divider #(
      .AccQ(AccQ), .AccU(AccU), .UvIntBits(UvIntBits), .W(RecipW), .K(RecipK), .G(RecipG), .TF(TF),
      .LocW(LocW), .PayW(PayD)
    ) u_divider (
      .clk_i, .rst_ni,
      .abort_i    (abort),
      .in_valid_i (df_valid),
      .in_ready_o (df_ready),
      .in_need_i  (sh_need),
      .in_q_i     (df_q),
      .in_u_i     (df_u),
      .in_v_i     (df_v),
      .in_pay_i   ({df_side, df_addr, df_z, df_rgb, df_ua, df_va, df_q, df_exact, df_x, df_div_color}),
      .out_valid_o(dv_valid),
      .out_ready_i(dv_ready),
      .out_u_o    (dv_u),
      .out_v_o    (dv_v),
      .out_pay_o  (dv_pay)
    );
    assign dv_rgb  = '0;
    logic unused_lut_div;
    assign unused_lut_div = ^df_c;
  end else if (Textured) begin : g_divider
    htx_raster_divider #(
      .AccQ(AccQ), .AccU(AccU), .AccC(AccC), .UvIntBits(UvIntBits), .W(RecipW), .K(RecipK), .G(RecipG),
      .Steps(PixelSteps), .TF(TF), .LocW(LocW), .PayW(PayD), .Pipelined(PixelPipelined),
      .Color(PerspColor), .MulIterative(PixelMulIterative), .MulDigits(Iterative)
    ) u_divider (
      .clk_i, .rst_ni,
      .abort_i    (abort),
      .in_valid_i (df_valid),
      .in_ready_o (df_ready),
      .in_need_i  (sh_need),
      .in_lut_i   (sh_method == htx_raster_pkg::MethodRecipLut),
      .in_q_i     (df_q),
      .in_u_i     (df_u),
      .in_v_i     (df_v),
      .in_c_i     (df_c),
      .in_pay_i   ({df_side, df_addr, df_z, df_rgb, df_ua, df_va, df_q, df_exact, df_x, df_div_color}),
      .out_valid_o(dv_valid),
      .out_ready_i(dv_ready),
      .out_u_o    (dv_u),
      .out_v_o    (dv_v),
      .out_rgb_o  (dv_rgb),
      .out_pay_o  (dv_pay)
    );
  end else begin : g_no_divider
    // No texel coordinates to divide for.
    assign dv_valid = df_valid;
    assign df_ready = dv_ready;
    assign dv_u     = '0;
    assign dv_v     = '0;
    assign dv_rgb   = '0;
    assign dv_pay   = {df_side, df_addr, df_z, df_rgb, df_ua, df_va, df_q, df_exact, df_x, df_div_color};
    logic unused_div;
    assign unused_div = ^{sh_need, df_u, df_v, df_c};
  end

  logic [SideW-1:0] dv_side;
  logic [AddrW-1:0] dv_addr;
  logic [ZBits-1:0] dv_z;
  logic [23:0]      dv_lin;
  logic [LocW-1:0]  dv_ua, dv_va;
  logic [AccQ-1:0]  dv_q;
  logic             dv_exact, dv_div_color;
  logic [12:0]      dv_x;
  assign {dv_side, dv_addr, dv_z, dv_lin, dv_ua, dv_va, dv_q, dv_exact, dv_x, dv_div_color} = dv_pay;
  logic [2:0] dv_method;
  assign dv_method = dv_side[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3];

  // ---- SUBDIV inner pixels ---------------------------------------------------------------------
  localparam int unsigned PayS = SideW + AddrW + ZBits + 24 + AccQ;
  logic             sd_valid, sd_ready;
  logic [LocW-1:0]  sd_u, sd_v;
  logic [PayS-1:0]  sd_pay;
  logic             dv_affine;
  // AFFINE's coordinates and DIVFREE's cell centres travel in ua, va.
  assign dv_affine = (dv_method == htx_raster_pkg::MethodAffine) ||
                     (HasDf && (dv_method == htx_raster_pkg::MethodDivFree));
  if (Methods[1]) begin : g_subdiv
    htx_raster_subdiv #(.LocW(LocW), .PayW(PayS), .Depth(SubdivDepth)) u_subdiv (
      .clk_i, .rst_ni,
      .abort_i    (abort),
      .in_valid_i (dv_valid),
      .in_ready_o (dv_ready),
      .in_subdiv_i(dv_method == htx_raster_pkg::MethodSubdiv),
      .in_exact_i (dv_exact),
      .in_x_i     (dv_x),
      .in_u_i     (dv_affine ? dv_ua : dv_u),
      .in_v_i     (dv_affine ? dv_va : dv_v),
      .in_pay_i   ({dv_side, dv_addr, dv_z, dv_div_color ? dv_rgb : dv_lin, dv_q}),
      .out_valid_o(sd_valid),
      .out_ready_i(sd_ready),
      .out_u_o    (sd_u),
      .out_v_o    (sd_v),
      .out_pay_o  (sd_pay)
    );
  end else begin : g_no_subdiv
    assign sd_valid = dv_valid;
    assign dv_ready = sd_ready;
    assign sd_u     = dv_affine ? dv_ua : dv_u;
    assign sd_v     = dv_affine ? dv_va : dv_v;
    assign sd_pay   = {dv_side, dv_addr, dv_z, dv_div_color ? dv_rgb : dv_lin, dv_q};
    logic unused_sd;
    assign unused_sd = ^{dv_exact, dv_x};
  end

  // ---- Texture request (registered) ------------------------------------------------------------
  logic [SideW-1:0] sd_side;
  logic [AddrW-1:0] sd_addr;
  logic [ZBits-1:0] sd_z;
  logic [23:0]      sd_rgb;
  logic [AccQ-1:0]  sd_q;
  assign {sd_side, sd_addr, sd_z, sd_rgb, sd_q} = sd_pay;
  logic [31:0] sd_st;
  assign sd_st = sd_side[31:0];

  // Level-0 coordinate u_l + (u_offset << TF); clamp saturates it to CoordW bits, repeat and
  // mirror keep its low CoordW bits (the period divides 2^CoordW; docs/texture.md).
  localparam int unsigned CWide = 32 + TF + 2;
  // Where CoordW <= LocW (`icebreaker`) the sum is formed only as wide as u_l's integer part needs
  // (LI bits, and the offset's low LI + 1): an offset beyond LI + 1 signed bits puts the sum
  // beyond +-2^(LI-1) >= 2^(CoordW-TF-1), so clamp saturates it by the offset's sign, and repeat
  // and mirror keep low bits, which the narrow sum has exactly (19 adder bits fewer an axis).
  localparam int unsigned LI = LocW - TF;
  localparam bit          NarrowSum = (CoordW <= LocW);
  localparam int unsigned SumW = NarrowSum ? LI + 2 : CWide - TF;
  function automatic logic [CoordW-1:0] level0(input logic [LocW-1:0] loc, input logic [31:0] off,
                                               input logic clamp);
    logic signed [SumW+TF-1:0] c, hi;
    logic signed [SumW-1:0] c_hi;
    logic off_big, off_neg;
    // The offset's shifted low bits are zero: only the bits from TF up are added.
    c_hi = SumW'($signed(loc[LocW-1:TF])) + SumW'($signed(off));
    c = {c_hi, loc[TF-1:0]};
    hi = c >>> (CoordW-1);  // (shifted on its own: in a comparison with '1 it would be unsigned)
    // (reductions, not comparisons with constants: Yosys 0.23 builds those as carry chains)
    off_neg = off[31];
    off_big = NarrowSum && ((off >> (SumW - 2)) != '0) &&
              ((off >> (SumW - 2)) != (32'hFFFF_FFFF >> (SumW - 2)));
    if (SumW + TF <= CoordW) level0 = CoordW'(c);
    else if (clamp && off_big) level0 = off_neg ? {1'b1, {(CoordW-1){1'b0}}}
                                                : {1'b0, {(CoordW-1){1'b1}}};
    // c beyond +-2^(CoordW-1): its bits from CoordW - 1 up are not all copies of its sign.
    else if (clamp && !c[SumW+TF-1] && (hi != '0)) level0 = {1'b0, {(CoordW-1){1'b1}}};
    else if (clamp && c[SumW+TF-1] && (hi != '1)) level0 = {1'b1, {(CoordW-1){1'b0}}};
    else level0 = CoordW'(c);
  endfunction

  logic [1:0] sd_wrap_u, sd_wrap_v;
  assign sd_wrap_u = sd_st[htx_raster_reg_pkg::RASTER_STATE_WRAP_U_LSB +: 2];
  assign sd_wrap_v = sd_st[htx_raster_reg_pkg::RASTER_STATE_WRAP_V_LSB +: 2];

  logic             rq_valid_q;
  logic [CoordW-1:0] rq_u_q, rq_v_q;
  logic [31:0]      rq_st_q;
  logic [AccQ-1:0]  rq_q_q;
  logic [6*GradW-1:0] rq_g_q;
  logic [7:0]       rq_shift_q;
  logic [LocW-1:0]  rq_lu_q, rq_lv_q;
  logic [TexTagW-1:0] rq_tag_q;
  // The request stage hands its fragment to the texture unit, or without texture mapping straight
  // to the fragment path (rq_take: taken this clock).
  logic rq_take;
  assign sd_ready = !rq_valid_q || rq_take;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rq_valid_q <= 1'b0; rq_u_q <= '0; rq_v_q <= '0; rq_st_q <= '0; rq_q_q <= '0; rq_g_q <= '0;
      rq_shift_q <= '0; rq_lu_q <= '0; rq_lv_q <= '0; rq_tag_q <= '0;
    end else if (abort) begin
      rq_valid_q <= 1'b0;
    end else if (sd_ready) begin
      rq_valid_q <= sd_valid;
      if (sd_valid) begin
        // Without texture mapping the request's fields stay 0 (the port is idle).
        if (Textured) begin
          rq_u_q     <= level0(sd_u, sd_side[95:64], sd_wrap_u == 2'd1);
          rq_v_q     <= level0(sd_v, sd_side[127:96], sd_wrap_v == 2'd1);
          rq_st_q    <= sd_st;
          rq_q_q     <= sd_q;
          rq_g_q     <= sd_side[128 +: 6*GradW];
          rq_shift_q <= sd_side[128 + 6*GradW +: 8];
          rq_lu_q    <= sd_u;
          rq_lv_q    <= sd_v;
        end
        rq_tag_q   <= {sd_st[htx_raster_reg_pkg::RASTER_STATE_DEPTH_WRITE_LSB],
                       sd_st[htx_raster_reg_pkg::RASTER_STATE_DEPTH_FUNC_LSB +: 3],
                       sd_st[htx_raster_reg_pkg::RASTER_STATE_COMBINE_LSB],
                       sd_st[htx_raster_reg_pkg::RASTER_STATE_TEXTURED_LSB],
                       sd_rgb, sd_z, sd_addr};
      end
    end
  end
  logic               ret_valid, ret_ready;
  logic [31:0]        ret_rgba;
  logic [TexTagW-1:0] ret_tag;
  assign tex_req_valid_o      = Textured && rq_valid_q;
  assign tex_req_u_o          = rq_u_q;
  assign tex_req_v_o          = rq_v_q;
  assign tex_req_filter_o     = rq_st_q[htx_raster_reg_pkg::RASTER_STATE_FILTER_LSB +: 2];
  assign tex_req_wrap_u_o     = rq_st_q[htx_raster_reg_pkg::RASTER_STATE_WRAP_U_LSB +: 2];
  assign tex_req_wrap_v_o     = rq_st_q[htx_raster_reg_pkg::RASTER_STATE_WRAP_V_LSB +: 2];
  assign tex_req_slot_o       = rq_st_q[htx_raster_reg_pkg::RASTER_STATE_TEXTURE_LSB +: 8];
  assign tex_req_lod_direct_o = 1'b0;
  assign tex_req_lod_o        = '0;
  // The LOD's Q is max(Q, 1) (docs/model.md §6, lod_at).
  assign tex_req_lod_q_o      = ($signed(rq_q_q) < $signed(AccQ'(1))) ? QW'(1) : QW'(rq_q_q);
  assign tex_req_lod_gux_o    = rq_g_q[0*GradW +: GradW];
  assign tex_req_lod_guy_o    = rq_g_q[1*GradW +: GradW];
  assign tex_req_lod_gvx_o    = rq_g_q[2*GradW +: GradW];
  assign tex_req_lod_gvy_o    = rq_g_q[3*GradW +: GradW];
  assign tex_req_lod_gqx_o    = rq_g_q[4*GradW +: GradW];
  assign tex_req_lod_gqy_o    = rq_g_q[5*GradW +: GradW];
  assign tex_req_lod_shift_o  = rq_shift_q;
  assign tex_req_lod_u_o      = rq_lu_q;
  assign tex_req_lod_v_o      = rq_lv_q;
  assign tex_req_tag_o        = Textured ? rq_tag_q : '0;  // (the tag also serves the return path)
  if (Textured) begin : g_tex_port
    assign rq_take         = tex_req_ready_i;
    assign ret_valid       = tex_out_valid_i;
    assign ret_rgba        = tex_out_rgba_i;
    assign ret_tag         = tex_out_tag_i;
    assign tex_out_ready_o = ret_ready;
  end else begin : g_no_tex_port
    // The fragment returns at once with its tag and no texel (textured is 0 in every tag).
    assign tex_out_ready_o = 1'b0;
    assign rq_take   = ret_ready;
    assign ret_valid = rq_valid_q;
    assign ret_rgba  = '0;
    assign ret_tag   = rq_tag_q;
    logic unused_tex;
    assign unused_tex = ^{tex_req_ready_i, tex_out_valid_i, tex_out_rgba_i, tex_out_tag_i};
  end

  // ---- Texel back: drop what an abort left in the texture unit, combine, fragment stage ----------
  logic       req_fire, ret_fire, ret_keep, frag_ready;
  // Requests in the texture unit (out_cnt_q) and those an abort left there to drop (drop_q). The
  // board's texture unit (Iterative's) holds at most five, one a sampler stage, so four bits do;
  // simulation checks that the count never wraps.
  localparam int unsigned OutW = Iterative ? 4 : 8;
  logic [OutW-1:0] out_cnt_q, drop_q, out_cnt_next;
  // Fragments between the traversal's output and the texture request. With SUBDIV's fragment
  // FIFO, DIVFREE's unit or the pipelined divider that can be many; otherwise a handful (the
  // iterative divider holds one, the request stage one, the shade stage at most one), so four
  // bits do (the board's build). Simulation checks that the count never wraps.
  localparam int unsigned PendW = (Methods[1] || HasDf || PixelPipelined) ? 16 : 4;
  logic [PendW-1:0] pend_q;
  assign req_fire = rq_valid_q && rq_take;
  assign ret_fire = ret_valid && ret_ready;
  assign out_cnt_next = out_cnt_q + OutW'(req_fire) - OutW'(ret_fire);
  assign ret_ready = (drop_q != 0) || c_in_ready;
  assign ret_keep = ret_valid && (drop_q == 0) && !abort;

  logic [AddrW-1:0] t_addr;
  logic [ZBits-1:0] t_z;
  logic [23:0]      t_rgb;
  logic             t_textured, t_modulate, t_zwrite;
  logic [2:0]       t_func;
  logic [31:0]      t_state;
  assign {t_zwrite, t_func, t_modulate, t_textured, t_rgb, t_z, t_addr} = ret_tag;
  // Combine, then the fragment stage's input (c_*). `icebreaker` (Iterative) modulates one channel
  // per clock on one multiplier in a stage of its own; otherwise all channels at once, in place.
  logic             c_valid, c_in_ready, c_zwrite, cmb_busy;
  logic [2:0]       c_func;
  logic [AddrW-1:0] c_addr;
  logic [ZBits-1:0] c_z;
  logic [23:0]      c_rgb;
  if (!Textured) begin : g_no_combine
    assign c_valid    = ret_keep;
    assign c_in_ready = frag_ready;
    assign c_rgb      = t_rgb;
    assign {c_zwrite, c_func, c_z, c_addr} = {t_zwrite, t_func, t_z, t_addr};
    assign cmb_busy   = 1'b0;
    logic unused_t;
    assign unused_t = ^{t_modulate, t_textured, ret_rgba};
  end else if (Iterative) begin : g_combine_serial
    // (It also quantises to RGB565, a channel a clock: the fragment stage takes that, InRgb565.)
    logic [15:0] c_rgb565;
    htx_tex_combine_serial #(.PayW(4 + ZBits + AddrW)) u_combine (
      .clk_i, .rst_ni,
      .abort_i    (abort),
      .in_valid_i (ret_keep),
      .in_ready_o (c_in_ready),
      .textured_i (t_textured),
      .modulate_i (t_modulate),
      .texel_i    (ret_rgba[23:0]),
      .color_i    (t_rgb),
      .pay_i      ({t_zwrite, t_func, t_z, t_addr}),
      .out_valid_o(c_valid),
      .out_ready_i(frag_ready),
      .rgb565_o   (c_rgb565),
      .pay_o      ({c_zwrite, c_func, c_z, c_addr}),
      .busy_o     (cmb_busy)
    );
    assign c_rgb = {8'd0, c_rgb565};
    logic unused_alpha;
    assign unused_alpha = ^ret_rgba[31:24];  // the fragment path has no alpha
  end else begin : g_combine
    logic [31:0] t_rgba;
    logic        unused_alpha;
    assign unused_alpha = ^t_rgba[31:24];  // the fragment path has no alpha
    htx_tex_combine u_combine (
      .textured_i(t_textured),
      .modulate_i(t_modulate),
      .texel_i   (ret_rgba),
      .color_i   ({8'h00, t_rgb}),
      .rgba_o    (t_rgba)
    );
    assign c_valid    = ret_keep;
    assign c_in_ready = frag_ready;
    assign c_rgb      = t_rgba[23:0];
    assign {c_zwrite, c_func, c_z, c_addr} = {t_zwrite, t_func, t_z, t_addr};
    assign cmb_busy   = 1'b0;
  end
  always_comb begin
    t_state = '0;
    t_state[htx_raster_reg_pkg::RASTER_STATE_DEPTH_FUNC_LSB +: 3] = c_func;
    t_state[htx_raster_reg_pkg::RASTER_STATE_DEPTH_WRITE_LSB]     = c_zwrite;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_cnt_q <= '0;
      drop_q    <= '0;
      pend_q    <= '0;
    end else begin
      out_cnt_q <= out_cnt_next;
      if (abort) begin
        drop_q <= out_cnt_next;
        pend_q <= '0;
      end else begin
        if (ret_fire && (drop_q != 0)) drop_q <= drop_q - 1'b1;
        pend_q <= pend_q + PendW'(tv_valid && tv_ready) - PendW'(req_fire);
      end
    end
  end
`ifndef SYNTHESIS
  always_ff @(posedge clk_i) begin
    if (!abort && (tv_valid && tv_ready) && !req_fire && (&pend_q))
      $error("htx_raster: the pending-fragment count would wrap (PendW too narrow)");
    if (req_fire && !ret_fire && (&out_cnt_q))
      $error("htx_raster: the texture unit's request count would wrap (OutW too narrow)");
  end
`endif

  logic frag_busy, clearing, pixel, clear_start;
  htx_raster_fragment #(.ZBits(ZBits), .AddrW(AddrW), .FbPixels(FbPixels), .Forward(!Iterative),
                        .InRgb565(Textured && Iterative))
  u_fragment (
    .clk_i, .rst_ni,
    .abort_i       (abort),
    .in_valid_i    (c_valid),
    .in_ready_o    (frag_ready),
    .in_addr_i     (c_addr),
    .in_z_i        (c_z),
    .in_rgb_i      (c_rgb),
    .in_state_i    (t_state),
    .clear_start_i (clear_start),
    .clear_color_i (clr_color),
    .clear_depth_i (clr_depth),
    .clear_rgb565_i(clear_color),
    .clear_z_i     (clear_depth),
    .height_i      (fb_height),
    .stride_i      (fb_stride),
    .clear_hold_i,
    .clearing_o    (clearing),
    .zr_en_o, .zr_addr_o, .zr_data_i,
    .wc_en_o, .wz_en_o, .w_addr_o, .wc_data_o, .wz_data_o,
    .busy_o        (frag_busy),
    .pixel_o       (pixel)
  );

  // A clear waits until setup holds nothing and every later stage is empty; setup takes no new
  // triangle meanwhile (hold_i), so the clear lands between the triangles before and after it.
  logic pipe_idle;
  assign pipe_idle   = !setup_busy && !tri_valid && !trav_busy && (pend_q == 0) && (out_cnt_q == 0) &&
                       !cmb_busy && !frag_busy;
  assign clear_start = clr_pend && pipe_idle && !clearing;

  logic busy;
  assign busy = !fifo_empty || in_busy || setup_busy || tri_valid || trav_busy || (pend_q != 0) ||
                (out_cnt_q != 0) || cmb_busy || frag_busy || clr_pend;

  // ---- Register block --------------------------------------------------------------------------
  htx_raster_regs #(.LvlW(LvlW), .FbPixels(FbPixels), .ColorPages(ColorPages), .Methods(Methods),
                    .Counters(Counters), .FwSetup(FwSetup)) u_regs (
    .clk_i, .rst_ni,
    .req_valid_i, .req_ready_o, .req_addr_i, .req_we_i, .req_be_i, .req_wdata_i,
    .rsp_valid_o, .rsp_rdata_o, .rsp_err_o,
    .fifo_push_o     (fifo_push),
    .fifo_full_i     (fifo_full),
    .fifo_empty_i    (fifo_empty),
    .fifo_level_i    (fifo_level),
    .abort_o         (abort),
    .enable_o        (enable),
    .width_o         (fb_width),
    .height_o        (fb_height),
    .stride_o        (fb_stride),
    .draw_page_o,
    .clear_color_o   (clear_color),
    .clear_depth_o   (clear_depth),
    .clr_pend_o      (clr_pend),
    .clr_color_o     (clr_color),
    .clr_depth_o     (clr_depth),
    .clear_start_i   (clear_start),
    .clearing_i      (clearing),
    .busy_i          (busy),
    .setup_taken_i   (setup_taken),
    .rec_state_i     (rec_state),
    .setup_err_i     (setup_err),
    .events_i        ({pixel, tv_valid && tv_ready, setup_taken, setup_busy, trav_stall, setup_stall,
                       in_partial, busy}),
    .df_steps_valid_i(df_steps_valid),
    .df_steps_i      (df_steps)
  );

  logic unused;
  assign unused = ^{tv_y, tri_state, tri_flat,
                    sd_side[63:32], rq_st_q[23:16], rq_st_q[9:0]};
endmodule
