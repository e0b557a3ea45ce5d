// Place-and-route harness for measuring the raster unit alone (without its framebuffer memories,
// which are SPRAM or external on a board) on a small package: every input comes from a register
// chain fed by one pin, every output is registered and folded into one pin, so all paths are timed
// register to register. Full selects the `full` parameters, else `icebreaker`. Not part of any SoC.
// The texture request's LOD fields (direct LOD, level, q, gradients, shift, LOD coordinates) are
// kept only with Full: the board's `icebreaker` texture unit has no LOD unit and drops them, so the
// GPU's synthesis removes their logic, and this harness must too to count what the board builds.
module htx_raster_synth_wrapper #(
  parameter bit         Full    = 1'b0,
  parameter logic [4:0] Methods = 5'b01111, // the synth-report designs leave DIVFREE out
  parameter bit         Counters = 1'b1     // the CNT_* event counters
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic din_i,
  output logic dout_o
);
  localparam int unsigned ZBits  = Full ? 24 : 16;
  localparam int unsigned AddrW  = 24;
  localparam int unsigned InBits = 1 + 32 + 1 + 4 + 32 + ZBits + 1;
  localparam int unsigned OutBits = 1 + 1 + 32 + 1 + 1 + AddrW + 1 + 1 + AddrW + 16 + ZBits;
  localparam int unsigned CoordW  = Full ? 48 : 20;
  localparam int unsigned QW      = Full ? 58 : 42;
  localparam int unsigned GradW   = Full ? 24 : 16;
  localparam int unsigned LocW    = Full ? 32 : 23;
  localparam int unsigned TagW    = htx_raster_pkg::tex_tag_w(AddrW, ZBits);
  // The texture port: requests are folded into the output; responses return the last request's
  // tag one clock later with a texel from the input chain (a stand-in for the texture unit).
  // The request's fields in tq_bits: u, v, filter, wraps, slot, then the LOD fields from LodAt
  // (direct LOD, level 24, q, six gradients, shift 8, LOD u and v) up to LodEnd, then the tag.
  localparam int unsigned LodAt   = 2 * CoordW + 14;
  localparam int unsigned LodGrad = LodAt + 25 + QW;              // the first gradient
  localparam int unsigned LodLoc  = LodGrad + 6 * GradW + 8;      // lod_u, past the shift
  localparam int unsigned LodEnd  = LodLoc + 2 * LocW;
  localparam int unsigned ReqBits = LodEnd + TagW;

  logic [InBits-1:0] in_q;
  always_ff @(posedge clk_i) in_q <= {in_q[InBits-2:0], din_i};

  logic             req_ready, rsp_valid, rsp_err, zr_en, wc_en, wz_en;
  logic [31:0]      rsp_rdata;
  logic [AddrW-1:0] zr_addr, w_addr;
  logic [15:0]      wc_data;
  logic [ZBits-1:0] wz_data;
  logic [1:0]       draw_page;  // (one colour page: always 0)
  logic             unused_draw_page;
  assign unused_draw_page = ^draw_page;
  logic              tq_valid, tq_lod_direct, to_ready;
  logic [ReqBits-1:0] tq_bits;
  logic [TagW-1:0]   tq_tag, to_tag_q;
  logic              to_valid_q;

  htx_raster #(
    .XyIntBits(Full ? 16 : 12), .ZBits(ZBits), .GF(Full ? 24 : 16), .RecipW(Full ? 32 : 24),
    .RecipK(Full ? 10 : 8), .RecipG(2), .SetupSteps(2), .Iterative(!Full), .FifoDepth(64),
    .FbPixels(Full ? 76800 : 19200), .AddrW(AddrW),
    .QBits(Full ? 32 : 24), .UvIntBits(Full ? 16 : 13), .TF(Full ? 16 : 10),
    .PixelSteps(Full ? 2 : 1), .Methods(Methods), .PerspColor(Full),
    .PixelPipelined(Full),
    .PixelMulIterative(1'b0), .SubdivDepth(Full ? 128 : 64), .DfFracBits(Full ? 4 : 2), .DfCap(64),
    .LF(Full ? 8 : 6), .LogIdx(Full ? 10 : 6), .CoordW(CoordW), .GradW(GradW), .Counters(Counters), .FwSetup(!Full)
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
    .clear_hold_i(1'b0),
    .zr_en_o    (zr_en),
    .zr_addr_o  (zr_addr),
    .zr_data_i  (in_q[70 +: ZBits]),
    .wc_en_o    (wc_en),
    .wz_en_o    (wz_en),
    .w_addr_o   (w_addr),
    .wc_data_o  (wc_data),
    .wz_data_o  (wz_data),
    .draw_page_o(draw_page),
    .tex_req_valid_o(tq_valid),
    .tex_req_ready_i(in_q[70 + ZBits]),
    .tex_req_u_o(tq_bits[0 +: CoordW]),
    .tex_req_v_o(tq_bits[CoordW +: CoordW]),
    .tex_req_filter_o(tq_bits[2*CoordW +: 2]),
    .tex_req_wrap_u_o(tq_bits[2*CoordW+2 +: 2]),
    .tex_req_wrap_v_o(tq_bits[2*CoordW+4 +: 2]),
    .tex_req_slot_o(tq_bits[2*CoordW+6 +: 8]),
    .tex_req_lod_direct_o(tq_lod_direct),
    .tex_req_lod_o(tq_bits[LodAt+1 +: 24]),
    .tex_req_lod_q_o(tq_bits[LodAt+25 +: QW]),
    .tex_req_lod_gux_o(tq_bits[LodGrad +: GradW]),
    .tex_req_lod_guy_o(tq_bits[LodGrad+GradW +: GradW]),
    .tex_req_lod_gvx_o(tq_bits[LodGrad+2*GradW +: GradW]),
    .tex_req_lod_gvy_o(tq_bits[LodGrad+3*GradW +: GradW]),
    .tex_req_lod_gqx_o(tq_bits[LodGrad+4*GradW +: GradW]),
    .tex_req_lod_gqy_o(tq_bits[LodGrad+5*GradW +: GradW]),
    .tex_req_lod_shift_o(tq_bits[LodGrad+6*GradW +: 8]),
    .tex_req_lod_u_o(tq_bits[LodLoc +: LocW]),
    .tex_req_lod_v_o(tq_bits[LodLoc+LocW +: LocW]),
    .tex_req_tag_o(tq_tag),
    .tex_out_valid_i(to_valid_q),
    .tex_out_ready_o(to_ready),
    .tex_out_rgba_i(in_q[38 +: 32]),
    .tex_out_tag_i(to_tag_q)
  );
  assign tq_bits[LodAt] = tq_lod_direct;
  assign tq_bits[LodEnd +: TagW] = tq_tag;

  always_ff @(posedge clk_i) begin
    if (!to_valid_q || to_ready) begin
      to_valid_q <= tq_valid;
      to_tag_q   <= tq_tag;
    end
  end

  logic [ReqBits-1:0] req_kept;
  always_comb begin
    req_kept = tq_bits;
    if (!Full) req_kept[LodEnd-1:LodAt] = '0;
  end

  logic [OutBits-1:0] out_q;
  logic [ReqBits-1:0] req_q;
  always_ff @(posedge clk_i) begin
    out_q  <= {req_ready, rsp_valid, rsp_rdata, rsp_err, zr_en, zr_addr, wc_en, wz_en, w_addr,
               wc_data, wz_data};
    req_q  <= req_kept;
    dout_o <= ^out_q ^ ^req_q ^ tq_valid;
  end
endmodule
