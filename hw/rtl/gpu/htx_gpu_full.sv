// The GPU in the `full` configuration (docs/gpu.md): htx_raster_full's raster parameters and
// htx_texture_full's texture parameters (every format and filter, trilinear with the LOD unit, four
// channels blended per clock), which equal htx::model_config("full") field by field.
module htx_gpu_full #(
  parameter int unsigned FbPixels = 19200,  // 160 x 120; the rtl engine uses 262144 (the depth window)
  parameter logic [4:0]  Methods  = 5'b11111,  // bit m: htx::Method m built (as htx_raster_full)
  parameter int unsigned TexBAW   = 15      // blocks per bank = 2^TexBAW: 128K texels
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
    .XyIntBits(16), .ZBits(24), .GF(24), .RecipW(32), .RecipK(10), .RecipG(2), .SetupSteps(2),
    .Iterative(1'b0), .QBits(32), .UvIntBits(16), .PixelSteps(2), .PerspColor(1'b1),
    .PixelPipelined(1'b1), .PixelMulIterative(1'b0), .SubdivDepth(128), .DfFracBits(4), .DfCap(64), .FifoDepth(64),
    .CoordW(48), .TF(16), .GradW(24), .LF(8), .TexFormats(3'b111), .TexFilters(3'b111),
    .TexSlots(8), .TexLanes(4), .TexShiftAdd(1'b0), .TexCounters(1'b1), .LogIdx(10),
    .FbPixels(FbPixels), .TexBAW(TexBAW), .Methods(Methods)
  ) u_subsys (.*);
endmodule
