// The raster subsystem as the `rtl` engine and the SoC see it: the raster unit and its framebuffer
// and depth memories, with two bus slave ports (registers at RASTER, memories at the framebuffer
// and depth windows; docs/contracts.md).
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
  parameter int unsigned FbPixels   = 76800
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
  localparam int unsigned AddrW = 24;

  logic             zr_en, wc_en, wz_en;
  logic [AddrW-1:0] zr_addr, w_addr;
  logic [ZBits-1:0] zr_data, wz_data;
  logic [15:0]      wc_data;

  htx_raster #(
    .XyIntBits(XyIntBits), .ZBits(ZBits), .GF(GF), .RecipW(RecipW), .RecipK(RecipK),
    .RecipG(RecipG), .SetupSteps(SetupSteps), .Iterative(Iterative), .FifoDepth(FifoDepth),
    .FbPixels(FbPixels), .AddrW(AddrW)
  ) u_raster (
    .clk_i, .rst_ni,
    .req_valid_i(reg_req_valid_i), .req_ready_o(reg_req_ready_o), .req_addr_i(reg_req_addr_i),
    .req_we_i(reg_req_we_i), .req_be_i(reg_req_be_i), .req_wdata_i(reg_req_wdata_i),
    .rsp_valid_o(reg_rsp_valid_o), .rsp_rdata_o(reg_rsp_rdata_o), .rsp_err_o(reg_rsp_err_o),
    .zr_en_o(zr_en), .zr_addr_o(zr_addr), .zr_data_i(zr_data),
    .wc_en_o(wc_en), .wz_en_o(wz_en), .w_addr_o(w_addr), .wc_data_o(wc_data), .wz_data_o(wz_data)
  );

  htx_fb #(.ZBits(ZBits), .AddrW(AddrW), .FbPixels(FbPixels)) u_fb (
    .clk_i, .rst_ni,
    .zr_en_i(zr_en), .zr_addr_i(zr_addr), .zr_data_o(zr_data),
    .wc_en_i(wc_en), .wz_en_i(wz_en), .w_addr_i(w_addr), .wc_data_i(wc_data), .wz_data_i(wz_data),
    .req_valid_i(mem_req_valid_i), .req_ready_o(mem_req_ready_o), .req_addr_i(mem_req_addr_i),
    .req_we_i(mem_req_we_i), .req_be_i(mem_req_be_i), .req_wdata_i(mem_req_wdata_i),
    .rsp_valid_o(mem_rsp_valid_o), .rsp_rdata_o(mem_rsp_rdata_o), .rsp_err_o(mem_rsp_err_o)
  );
endmodule
