// The raster subsystem in the `full` configuration (wide, one setup product per clock): the parameters equal
// htx::model_config("full") (hw/model/src/model/config.cpp) field by field; the `rtl` engine
// checks that before it renders.
// PerspColor is model_config("full").perspective_color: perspective-correct Gouraud colour (0
// until 2026-12-07, when the rtl engine still drew `full` with it off).
module htx_raster_full #(
  parameter int unsigned FbPixels   = 19200,  // 160 x 120; the rtl engine uses 262144 (the depth window)
  parameter bit          PerspColor = 1'b1
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
    .XyIntBits(16), .ZBits(24), .GF(24), .RecipW(32), .RecipK(10), .RecipG(2), .SetupSteps(2),
    .Iterative(1'b0), .QBits(32), .UvIntBits(16), .TF(16), .PixelSteps(2), .Methods(5'b11111),
    .PerspColor(PerspColor), .PixelPipelined(1'b1), .PixelMulIterative(1'b0), .SubdivDepth(128), .DfFracBits(4), .DfCap(64), .LF(8), .LogIdx(10),
    .CoordW(48), .GradW(24),
    .FifoDepth(64), .FbPixels(FbPixels)
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
