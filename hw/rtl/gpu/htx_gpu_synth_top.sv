// Place-and-route harness for the GPU (raster unit + texture unit with both bus ports): the bus
// inputs come from a shift register fed by one pin, the outputs fold into one registered pin, so
// the design fits the UP5K package while no input is a constant. The framebuffer and depth
// memories are the board's: 160 x 120 pixels of RGB565 and 16-bit depth in the UP5K's four SPRAM
// blocks (`icebreaker`); `full`'s (24-bit depth, no SPRAM form) shrink to 4 pixels (docs/gpu.md,
// Synthesis). So the cells counted are the two units, the bus decode and the memory ports.
// Full selects htx_gpu_full, else htx_gpu_icebreaker (board texture memory in both).
module htx_gpu_synth_top #(
  parameter bit Full = 1'b0
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  output logic sdo_o
);
  localparam int unsigned InBits = 2 * (1 + 32 + 1 + 4 + 32);
  logic [InBits-1:0] sr_q;
  always_ff @(posedge clk_i) sr_q <= {sr_q[InBits-2:0], sdi_i};

  logic        reg_valid, reg_we, mem_valid, mem_we;
  logic [3:0]  reg_be, mem_be;
  logic [31:0] reg_addr, reg_wdata, mem_addr, mem_wdata;
  assign {reg_valid, reg_addr, reg_we, reg_be, reg_wdata, mem_valid, mem_addr, mem_we, mem_be,
          mem_wdata} = sr_q;

  logic        reg_ready, reg_rsp_valid, reg_rsp_err, mem_ready, mem_rsp_valid, mem_rsp_err;
  logic [31:0] reg_rdata, mem_rdata;
  logic        fbv_gnt_unused;     // (no video scan-out here)
  logic [31:0] fbv_data_unused;
  logic        unused_fbv;
  assign unused_fbv = ^{fbv_gnt_unused, fbv_data_unused};
  if (Full) begin : g_full
    htx_gpu_full #(.FbPixels(4)) u_gpu (
      .clk_i, .rst_ni,
      .reg_req_valid_i(reg_valid), .reg_req_ready_o(reg_ready), .reg_req_addr_i(reg_addr),
      .reg_req_we_i(reg_we), .reg_req_be_i(reg_be), .reg_req_wdata_i(reg_wdata),
      .reg_rsp_valid_o(reg_rsp_valid), .reg_rsp_rdata_o(reg_rdata), .reg_rsp_err_o(reg_rsp_err),
      .mem_req_valid_i(mem_valid), .mem_req_ready_o(mem_ready), .mem_req_addr_i(mem_addr),
      .mem_req_we_i(mem_we), .mem_req_be_i(mem_be), .mem_req_wdata_i(mem_wdata),
      .mem_rsp_valid_o(mem_rsp_valid), .mem_rsp_rdata_o(mem_rdata), .mem_rsp_err_o(mem_rsp_err),
      .fbv_req_i(1'b0), .fbv_addr_i(24'd0), .fbv_gnt_o(fbv_gnt_unused),
      .fbv_data_o(fbv_data_unused));
  end else begin : g_icebreaker
    // One perspective method besides AFFINE on the board: RECIP_LUT (table reciprocal, no Newton
    // step); no raster event counters and a texture memory written only, as the board's SoC
    // builds it.
    htx_gpu_icebreaker #(.FbPixels(19200), .Methods(htx_raster_pkg::board_methods()),
                         .RasterCounters(1'b0), .TexWindowRead(1'b0), .FbSpram(1'b1)) u_gpu (
      .clk_i, .rst_ni,
      .reg_req_valid_i(reg_valid), .reg_req_ready_o(reg_ready), .reg_req_addr_i(reg_addr),
      .reg_req_we_i(reg_we), .reg_req_be_i(reg_be), .reg_req_wdata_i(reg_wdata),
      .reg_rsp_valid_o(reg_rsp_valid), .reg_rsp_rdata_o(reg_rdata), .reg_rsp_err_o(reg_rsp_err),
      .mem_req_valid_i(mem_valid), .mem_req_ready_o(mem_ready), .mem_req_addr_i(mem_addr),
      .mem_req_we_i(mem_we), .mem_req_be_i(mem_be), .mem_req_wdata_i(mem_wdata),
      .mem_rsp_valid_o(mem_rsp_valid), .mem_rsp_rdata_o(mem_rdata), .mem_rsp_err_o(mem_rsp_err),
      .fbv_req_i(1'b0), .fbv_addr_i(24'd0), .fbv_gnt_o(fbv_gnt_unused),
      .fbv_data_o(fbv_data_unused));
  end

  always_ff @(posedge clk_i) begin
    sdo_o <= ^{reg_ready, reg_rsp_valid, reg_rsp_err, reg_rdata, mem_ready, mem_rsp_valid,
               mem_rsp_err, mem_rdata};
  end
endmodule
