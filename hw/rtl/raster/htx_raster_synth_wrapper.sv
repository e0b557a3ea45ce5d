// Place-and-route harness for measuring the raster unit alone (without its framebuffer memories,
// which are SPRAM or external on a board) on a small package: every input comes from a register
// chain fed by one pin, every output is registered and folded into one pin, so all paths are timed
// register to register. Full selects the `full` parameters, else `icebreaker`. Not part of any SoC.
module htx_raster_synth_wrapper #(
  parameter bit Full = 1'b0
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic din_i,
  output logic dout_o
);
  localparam int unsigned ZBits  = Full ? 24 : 16;
  localparam int unsigned AddrW  = 24;
  localparam int unsigned InBits = 1 + 32 + 1 + 4 + 32 + ZBits;
  localparam int unsigned OutBits = 1 + 1 + 32 + 1 + 1 + AddrW + 1 + 1 + AddrW + 16 + ZBits;

  logic [InBits-1:0] in_q;
  always_ff @(posedge clk_i) in_q <= {in_q[InBits-2:0], din_i};

  logic             req_ready, rsp_valid, rsp_err, zr_en, wc_en, wz_en;
  logic [31:0]      rsp_rdata;
  logic [AddrW-1:0] zr_addr, w_addr;
  logic [15:0]      wc_data;
  logic [ZBits-1:0] wz_data;

  htx_raster #(
    .XyIntBits(Full ? 16 : 14), .ZBits(ZBits), .GF(Full ? 24 : 16), .RecipW(Full ? 32 : 24),
    .RecipK(Full ? 10 : 8), .RecipG(2), .SetupSteps(2), .Iterative(!Full), .FifoDepth(64),
    .FbPixels(Full ? 76800 : 19200), .AddrW(AddrW)
  ) u_raster (
    .clk_i, .rst_ni,
    .req_valid_i(in_q[0]),
    .req_ready_o(req_ready),
    .req_addr_i (in_q[32:1]),
    .req_we_i   (in_q[33]),
    .req_be_i   (in_q[37:34]),
    .req_wdata_i(in_q[69:38]),
    .rsp_valid_o(rsp_valid),
    .rsp_rdata_o(rsp_rdata),
    .rsp_err_o  (rsp_err),
    .zr_en_o    (zr_en),
    .zr_addr_o  (zr_addr),
    .zr_data_i  (in_q[70 +: ZBits]),
    .wc_en_o    (wc_en),
    .wz_en_o    (wz_en),
    .w_addr_o   (w_addr),
    .wc_data_o  (wc_data),
    .wz_data_o  (wz_data)
  );

  logic [OutBits-1:0] out_q;
  always_ff @(posedge clk_i) begin
    out_q  <= {req_ready, rsp_valid, rsp_rdata, rsp_err, zr_en, zr_addr, wc_en, wz_en, w_addr,
               wc_data, wz_data};
    dout_o <= ^out_q;
  end
endmodule
