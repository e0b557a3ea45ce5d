// TEXTURE register block (hw/regs/texture.json): capabilities, status, counters and the texture
// descriptors. An access is answered the clock after it is accepted; an offset with no register
// reads 0 and ignores writes. Descriptor size fields are clamped into 3..8 when written. Every
// access is accepted at once, except with SharedDescMux a descriptor read in a clock in which the
// unit takes a request (slot_take_i): the read and the requests then share one multiplexer over the
// descriptors, which shows the request's slot in that clock, so the read waits (for as long as
// requests are taken back to back: a unit that takes at most one request every few clocks, as
// `icebreaker`'s, where the raster unit's fragments are far apart, is the one to build it in).
module htx_tex_regs #(
  parameter logic [2:0]  Formats  = 3'b011,
  parameter logic [2:0]  Filters  = 3'b011,
  parameter int unsigned NumSlots = 2,
  parameter int unsigned BAW      = 10,
  parameter int unsigned TexW     = 16,
  parameter bit          Counters = 1'b1,  // 0: CNT_* read 0 (saves two 32-bit counters)
  parameter bit          WindowRead = 1'b1, // announced in CAPS.WINDOW_READ (htx_tex_mem CpuRead)
  parameter bit          SharedDescMux = 1'b0
) (
  input  logic               clk_i,
  input  logic               rst_ni,

  input  logic               req_valid_i,
  output logic               req_ready_o,
  input  logic [31:0]        req_addr_i,
  input  logic               req_we_i,
  input  logic [3:0]         req_be_i,
  input  logic [31:0]        req_wdata_i,
  output logic               rsp_valid_o,
  output logic [31:0]        rsp_rdata_o,
  output logic               rsp_err_o,

  input  logic [7:0]          slot_i,    // taken modulo NumSlots
  input  logic                slot_take_i, // the unit takes a request (desc_o for slot_i) this clock
  output logic [25:0]         desc_o,    // that slot's {format[1:0], log2_h[3:0], log2_w[3:0], base[15:0]}
  input  logic               busy_i,
  input  logic               err_format_i,
  input  logic               err_filter_i,
  input  logic               sample_i
);
  localparam int unsigned SW = (NumSlots > 1) ? $clog2(NumSlots) : 1;

  logic [11:0] offset;
  logic        accept, wr;
  assign offset = {req_addr_i[11:2], 2'b00};  // by word: a narrower read gets its word's lanes
  assign accept = req_valid_i && req_ready_o;
  assign wr     = accept && req_we_i && (&req_be_i);

  function automatic logic [3:0] clamp_log2(input logic [3:0] v);
    clamp_log2 = (v < 4'd3) ? 4'd3 : ((v > 4'd8) ? 4'd8 : v);
  endfunction

  logic [25:0] desc_q [NumSlots];
  logic        err_format_q, err_filter_q;
  logic [31:0] cnt_samples_q, cnt_busy_q;
  logic        is_desc;
  logic [2:0]  desc_idx;
  assign is_desc  = (offset[11:5] == 7'b0001000);  // 0x100..0x11C
  assign desc_idx = offset[4:2];
  assign req_ready_o = !(SharedDescMux && is_desc && !req_we_i && slot_take_i);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      for (int s = 0; s < NumSlots; s++) desc_q[s] <= {2'd0, 4'd3, 4'd3, 16'd0};
      err_format_q  <= 1'b0;
      err_filter_q  <= 1'b0;
      cnt_samples_q <= '0;
      cnt_busy_q    <= '0;
    end else begin
      if (wr && is_desc && (32'(desc_idx) < NumSlots)) begin
        desc_q[SW'(desc_idx)] <= {req_wdata_i[25:24], clamp_log2(req_wdata_i[23:20]),
                                  clamp_log2(req_wdata_i[19:16]), req_wdata_i[15:0]};
      end
      if (err_format_i) err_format_q <= 1'b1;
      else if (wr && offset == htx_texture_reg_pkg::TEXTURE_STATUS_OFFSET &&
               req_wdata_i[htx_texture_reg_pkg::TEXTURE_STATUS_ERR_FORMAT_LSB]) err_format_q <= 1'b0;
      if (err_filter_i) err_filter_q <= 1'b1;
      else if (wr && offset == htx_texture_reg_pkg::TEXTURE_STATUS_OFFSET &&
               req_wdata_i[htx_texture_reg_pkg::TEXTURE_STATUS_ERR_FILTER_LSB]) err_filter_q <= 1'b0;
      if (wr && offset == htx_texture_reg_pkg::TEXTURE_CNT_RESET_OFFSET && req_wdata_i[0]) begin
        cnt_samples_q <= '0;
        cnt_busy_q    <= '0;
      end else begin
        cnt_samples_q <= Counters ? cnt_samples_q + 32'(sample_i) : 32'd0;
        cnt_busy_q    <= Counters ? cnt_busy_q + 32'(busy_i) : 32'd0;
      end
    end
  end

  logic [25:0] desc_rd;  // the descriptor a read of slot desc_idx returns
  if (NumSlots > 1 && SharedDescMux) begin : g_slot_shared
    // The request's slot when a request is taken, else the read's (a descriptor read waits then).
    assign desc_o  = desc_q[slot_take_i ? slot_i[SW-1:0] : desc_idx[SW-1:0]];
    assign desc_rd = desc_o;
  end else if (NumSlots > 1) begin : g_slot
    assign desc_o  = desc_q[slot_i[SW-1:0]];
    assign desc_rd = desc_q[desc_idx[SW-1:0]];
  end else begin : g_one_slot
    assign desc_o  = desc_q[0];
    assign desc_rd = desc_q[0];
  end

  logic [31:0] rdata;
  always_comb begin
    rdata = '0;
    if (is_desc) begin
      if (32'(desc_idx) < NumSlots) rdata = 32'(desc_rd);
    end else begin
      unique case (offset)
        htx_texture_reg_pkg::TEXTURE_CAPS_OFFSET:
          rdata = {2'd0, 6'(TexW), 3'd0, 5'(BAW), 3'd0, WindowRead, 4'(NumSlots), Counters, Filters, 1'b0,
                   Formats};
        htx_texture_reg_pkg::TEXTURE_STATUS_OFFSET:
          rdata = {22'd0, err_filter_q, err_format_q, 7'd0, busy_i};
        htx_texture_reg_pkg::TEXTURE_CNT_SAMPLES_OFFSET: rdata = cnt_samples_q;
        htx_texture_reg_pkg::TEXTURE_CNT_BUSY_OFFSET:    rdata = cnt_busy_q;
        default: rdata = '0;
      endcase
    end
  end

  logic        rsp_q;
  logic [31:0] rdata_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rsp_q   <= 1'b0;
      rdata_q <= '0;
    end else begin
      rsp_q   <= accept;
      rdata_q <= req_we_i ? 32'd0 : rdata;
    end
  end
  assign rsp_valid_o = rsp_q;
  assign rsp_rdata_o = rdata_q;
  assign rsp_err_o   = 1'b0;

  logic unused;
  assign unused = ^{req_addr_i[31:12], req_addr_i[1:0], req_wdata_i[31:26], slot_i};
endmodule
