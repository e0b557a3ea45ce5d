// The GPU as the SoC and the `rtl` engine see it (docs/gpu.md): the raster unit, the texture unit
// between the raster's early depth test and its fragment write, and the framebuffer and depth
// memories, behind two bus slave ports (docs/contracts.md):
//   reg_*: RASTER registers (0x2000_3000) and TEXTURE registers (0x2000_4000), decoded on bits
//          14:12; any other address in the port's range answers rsp_err.
//   mem_*: framebuffer colour (0x3000_0000) and depth (0x3010_0000) windows when bit 30 is 0, the
//          texture memory window (0x4000_0000) when it is 1.
// Parameters: the raster subsystem's (htx_raster_subsys) and the texture unit's (htx_texture,
// prefixed Tex where the names would clash).
module htx_gpu_subsys #(
  // Raster unit.
  parameter int unsigned XyIntBits   = 16,
  parameter int unsigned ZBits       = 24,
  parameter int unsigned GF          = 24,
  parameter int unsigned RecipW      = 32,
  parameter int unsigned RecipK      = 10,
  parameter int unsigned RecipG      = 2,
  parameter int unsigned SetupSteps  = 2,
  parameter bit          Iterative   = 1'b0,
  parameter int unsigned FifoDepth   = 64,
  parameter int unsigned FbPixels    = 76800,
  parameter bit          FbSpram     = 1'b0,   // htx_fb's Spram (needs Iterative)
  parameter int unsigned ColorPages  = 1,      // htx_fb's colour pages (2 or 3: double or triple buffering)
  parameter int unsigned QBits       = 32,
  parameter int unsigned UvIntBits   = 16,
  parameter int unsigned PixelSteps  = 2,
  parameter logic [4:0]  Methods     = 5'b01111,
  parameter bit          PerspColor  = 1'b0,
  parameter bit          PixelPipelined    = 1'b1,
  parameter bit          PixelMulIterative = 1'b0,
  parameter int unsigned SubdivDepth = 128,
  parameter int unsigned DfFracBits  = 4,
  parameter int unsigned DfCap       = 64,
  // Texture port, shared by both units (the Q plane and local coordinate widths follow).
  parameter int unsigned CoordW      = 48,
  parameter int unsigned TF          = 16,
  parameter int unsigned GradW       = 24,
  // Texture unit.
  parameter int unsigned LF          = 8,
  parameter logic [2:0]  TexFormats  = 3'b111,
  parameter logic [2:0]  TexFilters  = 3'b111,
  parameter int unsigned TexSlots    = 8,
  parameter int unsigned TexBAW      = 15,
  parameter int unsigned TexLanes    = 4,
  parameter bit          TexShiftAdd = 1'b0,
  parameter bit          TexCounters = 1'b1,
  parameter bit          TexWindowRead = 1'b1,   // reads of the texture memory window
  parameter bit          FwSetup = 1'b0,  // the raster unit takes plane records (CAPS.FW_SETUP)
  parameter bit          RasterCounters = 1'b1,  // the raster unit's CNT_* (CAPS.COUNTERS)
  parameter int unsigned LogIdx      = 10
) (
  input  logic        clk_i,
  input  logic        rst_ni,

  input  logic        reg_req_valid_i,
  output logic        reg_req_ready_o,
  input  logic [31:0] reg_req_addr_i,
  input  logic        reg_req_we_i,
  input  logic [3:0]  reg_req_be_i,
  input  logic [31:0] reg_req_wdata_i,
  output logic        reg_rsp_valid_o,
  output logic [31:0] reg_rsp_rdata_o,
  output logic        reg_rsp_err_o,

  input  logic        mem_req_valid_i,
  output logic        mem_req_ready_o,
  input  logic [31:0] mem_req_addr_i,
  input  logic        mem_req_we_i,
  input  logic [3:0]  mem_req_be_i,
  input  logic [31:0] mem_req_wdata_i,
  output logic        mem_rsp_valid_o,
  output logic [31:0] mem_rsp_rdata_o,
  output logic        mem_rsp_err_o,

  // The video scan-out's colour reads (htx_fb's vr_* port): word index, data a clock after gnt.
  input  logic        fbv_req_i,
  input  logic [23:0] fbv_addr_i,
  output logic        fbv_gnt_o,
  output logic [31:0] fbv_data_o
);
  // Pixel addresses as wide as the memory needs, with one value beyond it: the traversal makes
  // an address that does not fit all ones, which the fragment stage does not write.
  localparam int unsigned AddrW = $clog2(FbPixels + 1);
  localparam int unsigned TagW  = htx_raster_pkg::tex_tag_w(AddrW, ZBits);
  localparam int unsigned QW    = QBits + GF + 2;   // the raster's Q plane accumulator
  localparam int unsigned LocW  = UvIntBits + TF;   // local texel coordinates

  // ---- Register port: slave 0 RASTER (bits 14:12 = 3), slave 1 TEXTURE (= 4), else error -------
  logic [1:0]  rs_valid, rs_ready, rs_rsp_valid, rs_rsp_err;
  logic [63:0] rs_rsp_rdata;
  logic [31:0] rs_addr, rs_wdata;
  logic        rs_we;
  logic [3:0]  rs_be;
  htx_bus_demux #(
    .NumSlaves(2),
    .SlaveBase({32'h0000_4000, 32'h0000_3000}),
    .SlaveMask({32'h0000_7000, 32'h0000_7000})
  ) u_reg_demux (
    .clk_i, .rst_ni,
    .m_req_valid_i(reg_req_valid_i), .m_req_ready_o(reg_req_ready_o), .m_req_addr_i(reg_req_addr_i),
    .m_req_we_i(reg_req_we_i), .m_req_be_i(reg_req_be_i), .m_req_wdata_i(reg_req_wdata_i),
    .m_rsp_valid_o(reg_rsp_valid_o), .m_rsp_rdata_o(reg_rsp_rdata_o), .m_rsp_err_o(reg_rsp_err_o),
    .s_req_valid_o(rs_valid), .s_req_ready_i(rs_ready), .s_req_addr_o(rs_addr), .s_req_we_o(rs_we),
    .s_req_be_o(rs_be), .s_req_wdata_o(rs_wdata), .s_rsp_valid_i(rs_rsp_valid),
    .s_rsp_rdata_i(rs_rsp_rdata), .s_rsp_err_i(rs_rsp_err)
  );

  // ---- Memory port: slave 0 framebuffer/depth (bit 30 = 0), slave 1 texture memory (= 1) -------
  logic [1:0]  ms_valid, ms_ready, ms_rsp_valid, ms_rsp_err;
  logic [63:0] ms_rsp_rdata;
  logic [31:0] ms_addr, ms_wdata;
  logic        ms_we;
  logic [3:0]  ms_be;
  htx_bus_demux #(
    .NumSlaves(2),
    .SlaveBase({32'h4000_0000, 32'h0000_0000}),
    .SlaveMask({32'h4000_0000, 32'h4000_0000})
  ) u_mem_demux (
    .clk_i, .rst_ni,
    .m_req_valid_i(mem_req_valid_i), .m_req_ready_o(mem_req_ready_o), .m_req_addr_i(mem_req_addr_i),
    .m_req_we_i(mem_req_we_i), .m_req_be_i(mem_req_be_i), .m_req_wdata_i(mem_req_wdata_i),
    .m_rsp_valid_o(mem_rsp_valid_o), .m_rsp_rdata_o(mem_rsp_rdata_o), .m_rsp_err_o(mem_rsp_err_o),
    .s_req_valid_o(ms_valid), .s_req_ready_i(ms_ready), .s_req_addr_o(ms_addr), .s_req_we_o(ms_we),
    .s_req_be_o(ms_be), .s_req_wdata_o(ms_wdata), .s_rsp_valid_i(ms_rsp_valid),
    .s_rsp_rdata_i(ms_rsp_rdata), .s_rsp_err_i(ms_rsp_err)
  );

  // ---- Raster unit -----------------------------------------------------------------------------
  logic             zr_en, wc_en, wz_en;
  logic [AddrW-1:0] zr_addr, w_addr;
  logic [ZBits-1:0] zr_data, wz_data;
  logic [1:0]       draw_page;
  logic [15:0]      wc_data;

  logic              tq_valid, tq_ready, tq_direct;
  logic [CoordW-1:0] tq_u, tq_v;
  logic [1:0]        tq_filter, tq_wrap_u, tq_wrap_v;
  logic [7:0]        tq_slot, tq_shift;
  logic [23:0]       tq_lod;
  logic [QW-1:0]     tq_q;
  logic [GradW-1:0]  tq_gux, tq_guy, tq_gvx, tq_gvy, tq_gqx, tq_gqy;
  logic [LocW-1:0]   tq_lu, tq_lv;
  logic [TagW-1:0]   tq_tag, to_tag;
  logic              to_valid, to_ready;
  logic [31:0]       to_rgba;

  htx_raster #(
    .XyIntBits(XyIntBits), .ZBits(ZBits), .GF(GF), .RecipW(RecipW), .RecipK(RecipK),
    .RecipG(RecipG), .SetupSteps(SetupSteps), .Iterative(Iterative), .FifoDepth(FifoDepth),
    .FbPixels(FbPixels), .AddrW(AddrW), .QBits(QBits), .UvIntBits(UvIntBits), .TF(TF),
    .PixelSteps(PixelSteps), .Methods(Methods), .PerspColor(PerspColor),
    .PixelPipelined(PixelPipelined), .PixelMulIterative(PixelMulIterative),
    .SubdivDepth(SubdivDepth), .DfFracBits(DfFracBits), .DfCap(DfCap), .LF(LF), .LogIdx(LogIdx),
    .CoordW(CoordW), .QW(QW), .GradW(GradW), .LocW(LocW), .Counters(RasterCounters),
    .FwSetup(FwSetup), .TexTagW(TagW), .ColorPages(ColorPages)
  ) u_raster (
    .clk_i, .rst_ni,
    .req_valid_i(rs_valid[0]), .req_ready_o(rs_ready[0]), .req_addr_i(rs_addr),
    .req_we_i(rs_we), .req_be_i(rs_be), .req_wdata_i(rs_wdata),
    .rsp_valid_o(rs_rsp_valid[0]), .rsp_rdata_o(rs_rsp_rdata[31:0]), .rsp_err_o(rs_rsp_err[0]),
    .clear_hold_i(fbv_req_i),
    .zr_en_o(zr_en), .zr_addr_o(zr_addr), .zr_data_i(zr_data),
    .wc_en_o(wc_en), .wz_en_o(wz_en), .w_addr_o(w_addr), .wc_data_o(wc_data), .wz_data_o(wz_data),
    .draw_page_o(draw_page),
    .tex_req_valid_o(tq_valid), .tex_req_ready_i(tq_ready),
    .tex_req_u_o(tq_u), .tex_req_v_o(tq_v),
    .tex_req_filter_o(tq_filter), .tex_req_wrap_u_o(tq_wrap_u), .tex_req_wrap_v_o(tq_wrap_v),
    .tex_req_slot_o(tq_slot), .tex_req_lod_direct_o(tq_direct), .tex_req_lod_o(tq_lod),
    .tex_req_lod_q_o(tq_q),
    .tex_req_lod_gux_o(tq_gux), .tex_req_lod_guy_o(tq_guy), .tex_req_lod_gvx_o(tq_gvx),
    .tex_req_lod_gvy_o(tq_gvy), .tex_req_lod_gqx_o(tq_gqx), .tex_req_lod_gqy_o(tq_gqy),
    .tex_req_lod_shift_o(tq_shift), .tex_req_lod_u_o(tq_lu), .tex_req_lod_v_o(tq_lv),
    .tex_req_tag_o(tq_tag),
    .tex_out_valid_i(to_valid), .tex_out_ready_o(to_ready), .tex_out_rgba_i(to_rgba),
    .tex_out_tag_i(to_tag)
  );

  // ---- Texture unit ----------------------------------------------------------------------------
  // An untextured fragment passes through the texture unit only to stay in order (the combine
  // ignores its texel): it is sampled nearest, the fastest path in every configuration, whatever
  // filter its state word names (so an unbuilt filter on an untextured triangle is no error).
  localparam int unsigned TexturedBit = AddrW + ZBits + htx_raster_pkg::TagRgbBits;
  logic [1:0] tq_filter_eff;
  assign tq_filter_eff = tq_tag[TexturedBit] ? tq_filter : 2'd0;

  logic [3:0]  to_level;
  logic [15:0] to_lod;
  logic        tex_busy;
  htx_texture #(
    .CoordW(CoordW), .TF(TF), .LF(LF), .Formats(TexFormats), .Filters(TexFilters),
    .NumSlots(TexSlots), .BAW(TexBAW), .Lanes(TexLanes), .ShiftAdd(TexShiftAdd), .TagW(TagW),
    .Counters(TexCounters), .WindowRead(TexWindowRead), .QW(QW), .GradW(GradW), .LocW(LocW),
    .LogIdx(LogIdx)
  ) u_texture (
    .clk_i, .rst_ni,
    .reg_req_valid_i(rs_valid[1]), .reg_req_ready_o(rs_ready[1]), .reg_req_addr_i(rs_addr),
    .reg_req_we_i(rs_we), .reg_req_be_i(rs_be), .reg_req_wdata_i(rs_wdata),
    .reg_rsp_valid_o(rs_rsp_valid[1]), .reg_rsp_rdata_o(rs_rsp_rdata[63:32]),
    .reg_rsp_err_o(rs_rsp_err[1]),
    .mem_req_valid_i(ms_valid[1]), .mem_req_ready_o(ms_ready[1]), .mem_req_addr_i(ms_addr),
    .mem_req_we_i(ms_we), .mem_req_be_i(ms_be), .mem_req_wdata_i(ms_wdata),
    .mem_rsp_valid_o(ms_rsp_valid[1]), .mem_rsp_rdata_o(ms_rsp_rdata[63:32]),
    .mem_rsp_err_o(ms_rsp_err[1]),
    .req_valid_i(tq_valid), .req_ready_o(tq_ready), .req_u_i(tq_u), .req_v_i(tq_v),
    .req_filter_i(tq_filter_eff), .req_wrap_u_i(tq_wrap_u), .req_wrap_v_i(tq_wrap_v),
    .req_slot_i(tq_slot), .req_lod_direct_i(tq_direct), .req_lod_i(tq_lod), .req_lod_q_i(tq_q),
    .req_lod_gux_i(tq_gux), .req_lod_guy_i(tq_guy), .req_lod_gvx_i(tq_gvx),
    .req_lod_gvy_i(tq_gvy), .req_lod_gqx_i(tq_gqx), .req_lod_gqy_i(tq_gqy),
    .req_lod_shift_i(tq_shift), .req_lod_u_i(tq_lu), .req_lod_v_i(tq_lv), .req_tag_i(tq_tag),
    .out_valid_o(to_valid), .out_ready_i(to_ready), .out_rgba_o(to_rgba), .out_level_o(to_level),
    .out_lod_o(to_lod), .out_tag_o(to_tag),
    .busy_o(tex_busy)
  );

  // ---- Framebuffer and depth memories ----------------------------------------------------------
  // The iterative raster's fragment stage never reads and writes depth in one clock (its Forward
  // = 0 schedule), so its memories can be single-ported.
  htx_fb #(.ZBits(ZBits), .AddrW(AddrW), .FbPixels(FbPixels), .SinglePort(Iterative),
           .Spram(FbSpram), .ColorPages(ColorPages)) u_fb (
    .clk_i, .rst_ni,
    .zr_en_i(zr_en), .zr_addr_i(zr_addr), .zr_data_o(zr_data),
    .wc_en_i(wc_en), .wz_en_i(wz_en), .w_addr_i(w_addr), .wc_data_i(wc_data), .wz_data_i(wz_data),
    .c_page_i(draw_page),
    .vr_req_i(fbv_req_i), .vr_addr_i(AddrW'(fbv_addr_i)), .vr_gnt_o(fbv_gnt_o), .vr_data_o(fbv_data_o),
    .req_valid_i(ms_valid[0]), .req_ready_o(ms_ready[0]), .req_addr_i(ms_addr),
    .req_we_i(ms_we), .req_be_i(ms_be), .req_wdata_i(ms_wdata),
    .rsp_valid_o(ms_rsp_valid[0]), .rsp_rdata_o(ms_rsp_rdata[31:0]), .rsp_err_o(ms_rsp_err[0])
  );

  // The raster's STATUS.BUSY covers fragments inside the texture unit (they are in flight on its
  // port); the texture unit's own busy and level/LOD outputs are for its registers and tests.
  logic unused;
  assign unused = ^{to_level, to_lod, tex_busy, fbv_addr_i};
endmodule
