// The raster subsystem in the `icebreaker` configuration (narrow, shift-and-add setup multipliers): the parameters equal
// htx::model_config("icebreaker") (hw/model/src/model/config.cpp) field by field; the `rtl` engine
// checks that before it renders.
module htx_raster_icebreaker #(
  parameter int unsigned FbPixels = 19200,  // 160 x 120; the rtl engine uses 262144 (the depth window)
  // The methods built; 5'b00000 is the build without texture mapping (raster_untextured_test.cpp).
  parameter logic [4:0]  Methods  = 5'b11111
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
  htx_raster_subsys #(
    .XyIntBits(12), .ZBits(16), .GF(16), .RecipW(24), .RecipK(8), .RecipG(2), .SetupSteps(2),
    .Iterative(1'b1), .QBits(24), .UvIntBits(13), .TF(10), .PixelSteps(1), .Methods(Methods),
    .PerspColor(1'b0), .PixelPipelined(1'b0), .PixelMulIterative(1'b0), .SubdivDepth(64), .DfFracBits(2), .DfCap(64), .LF(6), .LogIdx(6),
    .CoordW(20), .GradW(16),
    .FifoDepth(64), .FbPixels(FbPixels), .FwSetup(1'b1)
  ) u_subsys (
    .clk_i,
    .rst_ni,
    .reg_req_valid_i,
    .reg_req_ready_o,
    .reg_req_addr_i,
    .reg_req_we_i,
    .reg_req_be_i,
    .reg_req_wdata_i,
    .reg_rsp_valid_o,
    .reg_rsp_rdata_o,
    .reg_rsp_err_o,
    .mem_req_valid_i,
    .mem_req_ready_o,
    .mem_req_addr_i,
    .mem_req_we_i,
    .mem_req_be_i,
    .mem_req_wdata_i,
    .mem_rsp_valid_o,
    .mem_rsp_rdata_o,
    .mem_rsp_err_o
  );
endmodule
