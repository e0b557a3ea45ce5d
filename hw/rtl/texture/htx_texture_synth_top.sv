// Place-and-route harness for the icebreaker texture unit: the unit's many inputs come from a
// shift register fed by one pin, its outputs fold into one pin, so nextpnr fits it in the UP5K
// package while every path of the unit stays (no input is a constant).
module htx_texture_synth_top (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  output logic sdo_o
);
  localparam int unsigned CoordW = 20;
  localparam int unsigned InBits = 2 * 32 + 2 + 4 + 2 * 32 + 2 + 4 + 2 + 2 * CoordW + 6 + 8 + 1 + 1;
  logic [InBits-1:0] sr_q;
  always_ff @(posedge clk_i) sr_q <= {sr_q[InBits-2:0], sdi_i};

  logic [31:0]       reg_addr, reg_wdata, mem_addr, mem_wdata;
  logic              reg_valid, reg_we, mem_valid, mem_we, req_valid, out_ready;
  logic [3:0]        reg_be, mem_be;
  logic [CoordW-1:0] u, v;
  logic [1:0]        filter, wrap_u, wrap_v;
  logic [7:0]        slot;
  assign {reg_addr, reg_wdata, reg_valid, reg_we, reg_be, mem_addr, mem_wdata, mem_valid, mem_we,
          mem_be, req_valid, out_ready, u, v, filter, wrap_u, wrap_v, slot} = sr_q[InBits-3:0];

  logic        reg_ready, reg_rsp_valid, reg_rsp_err, mem_ready, mem_rsp_valid, mem_rsp_err;
  logic        req_ready, out_valid, busy;
  logic [31:0] reg_rdata, mem_rdata, rgba;
  logic [3:0]  level;
  logic [15:0] lod;
  logic [0:0]  tag;
  htx_texture_icebreaker #(.TagW(1)) u_tex (
    .clk_i, .rst_ni,
    .reg_req_valid_i(reg_valid), .reg_req_ready_o(reg_ready), .reg_req_addr_i(reg_addr),
    .reg_req_we_i(reg_we), .reg_req_be_i(reg_be), .reg_req_wdata_i(reg_wdata),
    .reg_rsp_valid_o(reg_rsp_valid), .reg_rsp_rdata_o(reg_rdata), .reg_rsp_err_o(reg_rsp_err),
    .mem_req_valid_i(mem_valid), .mem_req_ready_o(mem_ready), .mem_req_addr_i(mem_addr),
    .mem_req_we_i(mem_we), .mem_req_be_i(mem_be), .mem_req_wdata_i(mem_wdata),
    .mem_rsp_valid_o(mem_rsp_valid), .mem_rsp_rdata_o(mem_rdata), .mem_rsp_err_o(mem_rsp_err),
    .req_valid_i(req_valid), .req_ready_o(req_ready), .req_u_i(u), .req_v_i(v),
    .req_filter_i(filter), .req_wrap_u_i(wrap_u), .req_wrap_v_i(wrap_v), .req_slot_i(slot),
    .req_lod_direct_i(1'b0), .req_lod_i('0), .req_lod_q_i('0),
    .req_lod_gux_i('0), .req_lod_guy_i('0), .req_lod_gvx_i('0), .req_lod_gvy_i('0),
    .req_lod_gqx_i('0), .req_lod_gqy_i('0), .req_lod_shift_i('0), .req_lod_u_i('0), .req_lod_v_i('0),
    .req_tag_i(sr_q[InBits-1]),
    .out_valid_o(out_valid), .out_ready_i(out_ready), .out_rgba_o(rgba), .out_level_o(level),
    .out_lod_o(lod), .out_tag_o(tag), .busy_o(busy));

  always_ff @(posedge clk_i) begin
    sdo_o <= ^{reg_ready, reg_rsp_valid, reg_rsp_err, reg_rdata, mem_ready, mem_rsp_valid,
               mem_rsp_err, mem_rdata, req_ready, out_valid, rgba, level, lod, tag, busy, sr_q[InBits-2]};
  end
endmodule
