// The raster subsystem in the `full` configuration with perspective-correct Gouraud colour
// (model_config("full") field by field, perspective_color included): htx_raster_full with
// PerspColor = 1, a Verilated top of its own for the tests (tests/rtl/raster/raster_color_test.cpp).
module htx_raster_full_pc #(
  parameter int unsigned FbPixels = 19200
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
  htx_raster_full #(.FbPixels(FbPixels), .PerspColor(1'b1)) u_full (
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
