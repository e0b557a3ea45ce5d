// The raster subsystem as the `rtl` engine and the SoC see it: the raster unit and its framebuffer
// and depth memories, with two bus slave ports (registers at RASTER, memories at the framebuffer
// and depth windows; docs/contracts.md). Without a texture unit the raster's texture port is looped
// back through a register slice with texel 0: only untextured fragments are meaningful here
// (docs/contracts.md, GPU join §1). The looped-back request signals are public to the Verilated model,
// so the tests can record the texel coordinates of every fragment.
module htx_raster_subsys #(
  parameter int unsigned XyIntBits  = 16,
  parameter int unsigned ZBits      = 24,
  parameter int unsigned GF         = 24,
  parameter int unsigned RecipW     = 32,
  parameter int unsigned RecipK     = 10,
  parameter int unsigned RecipG     = 2,
  parameter int unsigned SetupSteps = 2,
  parameter bit          Iterative  = 1'b0,
  parameter int unsigned FifoDepth  = 64,
  parameter int unsigned FbPixels   = 76800,
  parameter int unsigned QBits      = 32,
  parameter int unsigned UvIntBits  = 16,
  parameter int unsigned TF         = 16,
  parameter int unsigned PixelSteps = 2,
  parameter logic [4:0]  Methods    = 5'b01111,
  parameter bit          PerspColor = 1'b1,
  parameter bit          PixelPipelined = 1'b1,
  parameter bit          PixelMulIterative = 1'b0,
  parameter int unsigned SubdivDepth = 128,
  parameter int unsigned DfFracBits  = 4,
  parameter int unsigned DfCap       = 64,
  parameter int unsigned LF          = 8,
  parameter int unsigned LogIdx      = 10,
  parameter int unsigned CoordW     = 48,
  parameter int unsigned GradW      = 24,
  parameter bit          FwSetup    = 1'b0   // setup is the firmware's (plane records)
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
  output logic        mem_rsp_err_o
);
  // Pixel addresses as wide as the memory needs, with one value beyond it (as htx_gpu_subsys).
  localparam int unsigned AddrW   = $clog2(FbPixels + 1);
  localparam int unsigned QW      = QBits + GF + 2;
  localparam int unsigned LocW    = UvIntBits + TF;
  localparam int unsigned TexTagW = htx_raster_pkg::tex_tag_w(AddrW, ZBits);

  // Texture port, looped back (public for the tests' fragment recorder).
  logic               tex_req_valid /* verilator public_flat_rd */;
  logic               tex_req_ready /* verilator public_flat_rd */;
  logic [CoordW-1:0]  tex_req_u /* verilator public_flat_rd */;
  logic [CoordW-1:0]  tex_req_v /* verilator public_flat_rd */;
  logic [1:0]         tex_req_filter /* verilator public_flat_rd */;
  logic [1:0]         tex_req_wrap_u /* verilator public_flat_rd */;
  logic [1:0]         tex_req_wrap_v /* verilator public_flat_rd */;
  logic [7:0]         tex_req_slot /* verilator public_flat_rd */;
  logic               tex_req_lod_direct;
  logic [23:0]        tex_req_lod;
  logic [QW-1:0]      tex_req_lod_q /* verilator public_flat_rd */;
  logic [GradW-1:0]   tex_req_lod_g [6] /* verilator public_flat_rd */;
  logic [7:0]         tex_req_lod_shift /* verilator public_flat_rd */;
  logic [LocW-1:0]    tex_req_lod_u /* verilator public_flat_rd */;
  logic [LocW-1:0]    tex_req_lod_v /* verilator public_flat_rd */;
  logic [TexTagW-1:0] tex_req_tag /* verilator public_flat_rd */;
  logic               tex_out_valid, tex_out_ready;
  logic [TexTagW-1:0] tex_out_tag;

  logic             zr_en, wc_en, wz_en;
  logic [AddrW-1:0] zr_addr, w_addr;
  logic [ZBits-1:0] zr_data, wz_data;
  logic [1:0]       draw_page;  // (one colour page: always 0)
  logic [15:0]      wc_data;

  htx_raster #(
    .XyIntBits(XyIntBits), .ZBits(ZBits), .GF(GF), .RecipW(RecipW), .RecipK(RecipK),
    .RecipG(RecipG), .SetupSteps(SetupSteps), .Iterative(Iterative), .FifoDepth(FifoDepth),
    .FbPixels(FbPixels), .AddrW(AddrW), .QBits(QBits), .UvIntBits(UvIntBits), .TF(TF),
    .PixelSteps(PixelSteps), .Methods(Methods), .PerspColor(PerspColor),
    .PixelPipelined(PixelPipelined), .PixelMulIterative(PixelMulIterative),
    .SubdivDepth(SubdivDepth), .DfFracBits(DfFracBits), .DfCap(DfCap), .LF(LF), .LogIdx(LogIdx), .CoordW(CoordW), .GradW(GradW),
    .FwSetup(FwSetup)
  ) u_raster (
    .clk_i, .rst_ni,
    .req_valid_i(reg_req_valid_i), .req_ready_o(reg_req_ready_o), .req_addr_i(reg_req_addr_i),
    .req_we_i(reg_req_we_i), .req_be_i(reg_req_be_i), .req_wdata_i(reg_req_wdata_i),
    .rsp_valid_o(reg_rsp_valid_o), .rsp_rdata_o(reg_rsp_rdata_o), .rsp_err_o(reg_rsp_err_o),
    .clear_hold_i(1'b0),
    .zr_en_o(zr_en), .zr_addr_o(zr_addr), .zr_data_i(zr_data),
    .wc_en_o(wc_en), .wz_en_o(wz_en), .w_addr_o(w_addr), .wc_data_o(wc_data), .wz_data_o(wz_data),
    .draw_page_o(draw_page),
    .tex_req_valid_o(tex_req_valid), .tex_req_ready_i(tex_req_ready),
    .tex_req_u_o(tex_req_u), .tex_req_v_o(tex_req_v), .tex_req_filter_o(tex_req_filter),
    .tex_req_wrap_u_o(tex_req_wrap_u), .tex_req_wrap_v_o(tex_req_wrap_v), .tex_req_slot_o(tex_req_slot),
    .tex_req_lod_direct_o(tex_req_lod_direct), .tex_req_lod_o(tex_req_lod),
    .tex_req_lod_q_o(tex_req_lod_q),
    .tex_req_lod_gux_o(tex_req_lod_g[0]), .tex_req_lod_guy_o(tex_req_lod_g[1]),
    .tex_req_lod_gvx_o(tex_req_lod_g[2]), .tex_req_lod_gvy_o(tex_req_lod_g[3]),
    .tex_req_lod_gqx_o(tex_req_lod_g[4]), .tex_req_lod_gqy_o(tex_req_lod_g[5]),
    .tex_req_lod_shift_o(tex_req_lod_shift), .tex_req_lod_u_o(tex_req_lod_u),
    .tex_req_lod_v_o(tex_req_lod_v), .tex_req_tag_o(tex_req_tag),
    .tex_out_valid_i(tex_out_valid), .tex_out_ready_o(tex_out_ready),
    .tex_out_rgba_i(32'd0), .tex_out_tag_i(tex_out_tag)
  );

  // Loop-back: a register slice returning each request's tag with texel 0.
  logic               lb_valid_q;
  logic [TexTagW-1:0] lb_tag_q;
  assign tex_req_ready = !lb_valid_q || tex_out_ready;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      lb_valid_q <= 1'b0;
      lb_tag_q   <= '0;
    end else if (tex_req_ready) begin
      lb_valid_q <= tex_req_valid;
      if (tex_req_valid) lb_tag_q <= tex_req_tag;
    end
  end
  assign tex_out_valid = lb_valid_q;
  assign tex_out_tag   = lb_tag_q;

  logic unused_tex;
  always_comb begin
    unused_tex = ^{tex_req_u, tex_req_v, tex_req_filter, tex_req_wrap_u, tex_req_wrap_v, tex_req_slot,
                   tex_req_lod_direct, tex_req_lod, tex_req_lod_q, tex_req_lod_shift, tex_req_lod_u,
                   tex_req_lod_v};
    for (int i = 0; i < 6; i++) unused_tex = unused_tex ^ (^tex_req_lod_g[i]);
  end

  logic        vr_gnt_unused;      // (no video scan-out on the raster unit's own tests)
  logic [31:0] vr_data_unused;
  logic        unused_vr;
  assign unused_vr = ^{vr_gnt_unused, vr_data_unused};
  htx_fb #(.ZBits(ZBits), .AddrW(AddrW), .FbPixels(FbPixels)) u_fb (
    .clk_i, .rst_ni,
    .zr_en_i(zr_en), .zr_addr_i(zr_addr), .zr_data_o(zr_data),
    .wc_en_i(wc_en), .wz_en_i(wz_en), .w_addr_i(w_addr), .wc_data_i(wc_data), .wz_data_i(wz_data),
    .c_page_i(draw_page),
    .vr_req_i(1'b0), .vr_addr_i('0), .vr_gnt_o(vr_gnt_unused), .vr_data_o(vr_data_unused),
    .req_valid_i(mem_req_valid_i), .req_ready_o(mem_req_ready_o), .req_addr_i(mem_req_addr_i),
    .req_we_i(mem_req_we_i), .req_be_i(mem_req_be_i), .req_wdata_i(mem_req_wdata_i),
    .rsp_valid_o(mem_rsp_valid_o), .rsp_rdata_o(mem_rsp_rdata_o), .rsp_err_o(mem_rsp_err_o)
  );
endmodule
