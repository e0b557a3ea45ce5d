// The GPU in the `icebreaker` configuration (docs/gpu.md): htx_raster_icebreaker's raster
// parameters and htx_texture_icebreaker's texture parameters (RGB565 and RGBA4444, nearest and
// bilinear, one channel blended per clock, 4 slots, no texture counters), which equal
// htx::model_config("icebreaker") field by field.
module htx_gpu_icebreaker #(
  parameter int unsigned FbPixels = 19200,  // 160 x 120; the rtl engine uses 262144 (the depth window)
  parameter logic [4:0]  Methods  = 5'b11111,  // bit m: htx::Method m built (as htx_raster_icebreaker)
  parameter int unsigned TexBAW   = 10,     // blocks per bank = 2^TexBAW: 4K texels, 16 EBR (engine: 2^12)
  // The raster unit's CNT_* counters: the Verilated models keep them (the rtl engine's metrics and
  // the firmware's figures read them); the board's builds leave them out (docs/area.md).
  parameter bit          RasterCounters = 1'b1,
  // Reads of the texture memory window (CAPS.WINDOW_READ): the board's builds leave them out (the
  // memory is written only; docs/texture.md), the Verilated models keep them for the tests.
  parameter bit          TexWindowRead = 1'b1,
  // Framebuffer and depth in the UP5K's SPRAM (the board's builds; Yosys only, docs/gpu.md). The
  // memories are single-ported in every build, so simulation arbitrates as the board does.
  parameter bit          FbSpram = 1'b0,
  // Colour pages (3: triple buffering; the SoC's simulated and ULX3S builds). With FbSpram, 1.
  parameter int unsigned ColorPages = 1
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
  input  logic        fbv_req_i,      // the video scan-out's colour reads (htx_gpu_subsys)
  input  logic [23:0] fbv_addr_i,
  output logic        fbv_gnt_o,
  output logic [31:0] fbv_data_o
);
  htx_gpu_subsys #(
    .XyIntBits(12), .ZBits(16), .GF(16), .RecipW(24), .RecipK(8), .RecipG(2), .SetupSteps(2),
    .Iterative(1'b1), .QBits(24), .UvIntBits(13), .PixelSteps(1), .PerspColor(1'b0),
    .PixelPipelined(1'b0), .PixelMulIterative(1'b0), .SubdivDepth(64), .DfFracBits(2), .DfCap(64), .FifoDepth(64),
    .CoordW(20), .TF(10), .GradW(16), .LF(6), .TexFormats(3'b011), .TexFilters(3'b011),
    .TexSlots(4), .TexLanes(1), .TexShiftAdd(1'b0), .TexCounters(1'b0), .LogIdx(6),
    .RasterCounters(RasterCounters), .TexWindowRead(TexWindowRead), .FwSetup(1'b1),
    .FbPixels(FbPixels), .FbSpram(FbSpram), .ColorPages(ColorPages), .TexBAW(TexBAW), .Methods(Methods)
  ) u_subsys (.*);
endmodule
