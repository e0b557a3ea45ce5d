// The texture unit (docs/texture.md): TEXTURE registers (hw/regs/texture.json), the banked texture
// memory behind the window at 0x4000_0000, and the sampling path: descriptor look-up, the LOD unit
// (built with trilinear), level choice, then htx_tex_sampler. Parameters are the model's
// ModelConfig fields this unit uses (docs/model.md): what is built and the widths.
module htx_texture #(
  parameter int unsigned CoordW   = 48,       // request coordinates: signed, TF fraction bits
  parameter int unsigned TF       = 16,       // texcoord_frac_bits
  parameter int unsigned LF       = 8,        // lod_frac_bits
  parameter logic [2:0]  Formats  = 3'b111,   // bit i: TexFormat i built
  parameter logic [2:0]  Filters  = 3'b111,   // bit i: Filter i built (nearest is always built)
  parameter int unsigned NumSlots = 8,        // texture descriptors, 1..8
  parameter int unsigned BAW      = 15,       // blocks per bank = 2^BAW (<= 16)
  parameter int unsigned Lanes    = 4,        // 4: all channels blended a clock; 1: one product a clock
  parameter bit          ShiftAdd = 1'b0,     // filter products in logic instead of DSPs
  parameter int unsigned TagW     = 32,       // request sideband carried to the output
  parameter bit          Counters = 1'b1,     // CNT_SAMPLES, CNT_BUSY built
  parameter bit          WindowRead = 1'b1,   // reads of the memory window built (CAPS.WINDOW_READ)
  // LOD unit (trilinear only): q plane, gradients, local coordinates, log2 table.
  parameter int unsigned QW       = 58,
  parameter int unsigned GradW    = 24,
  parameter int unsigned LocW     = 32,
  parameter int unsigned LogIdx   = 10
) (
  input  logic              clk_i,
  input  logic              rst_ni,

  input  logic              reg_req_valid_i,
  output logic              reg_req_ready_o,
  input  logic [31:0]       reg_req_addr_i,
  input  logic              reg_req_we_i,
  input  logic [3:0]        reg_req_be_i,
  input  logic [31:0]       reg_req_wdata_i,
  output logic              reg_rsp_valid_o,
  output logic [31:0]       reg_rsp_rdata_o,
  output logic              reg_rsp_err_o,

  input  logic              mem_req_valid_i,
  output logic              mem_req_ready_o,
  input  logic [31:0]       mem_req_addr_i,
  input  logic              mem_req_we_i,
  input  logic [3:0]        mem_req_be_i,
  input  logic [31:0]       mem_req_wdata_i,
  output logic              mem_rsp_valid_o,
  output logic [31:0]       mem_rsp_rdata_o,
  output logic              mem_rsp_err_o,

  // Sample requests (docs/texture.md, Request interface).
  input  logic              req_valid_i,
  output logic              req_ready_o,
  input  logic [CoordW-1:0] req_u_i,          // level-0 texels incl. the offset, TF fraction bits
  input  logic [CoordW-1:0] req_v_i,
  input  logic [1:0]        req_filter_i,     // 0 nearest, 1 bilinear, 2 trilinear
  input  logic [1:0]        req_wrap_u_i,     // 0 repeat, 1 clamp, 2 mirror
  input  logic [1:0]        req_wrap_v_i,
  input  logic [7:0]        req_slot_i,       // descriptor slot (modulo NumSlots)
  input  logic              req_lod_direct_i, // 1: req_lod_i is the LOD; 0: compute it
  input  logic [23:0]       req_lod_i,        // signed, LF fraction bits
  input  logic [QW-1:0]     req_lod_q_i,      // Q plane value (0 taken as 1)
  input  logic [GradW-1:0]  req_lod_gux_i, req_lod_guy_i, req_lod_gvx_i,
  input  logic [GradW-1:0]  req_lod_gvy_i, req_lod_gqx_i, req_lod_gqy_i,
  input  logic [7:0]        req_lod_shift_i,  // the gradients' block shift
  input  logic [LocW-1:0]   req_lod_u_i,      // local coordinates (before the offset), TF bits
  input  logic [LocW-1:0]   req_lod_v_i,
  input  logic [TagW-1:0]   req_tag_i,

  output logic              out_valid_o,
  input  logic              out_ready_i,
  output logic [31:0]       out_rgba_o,       // r 7:0, g 15:8, b 23:16, a 31:24
  output logic [3:0]        out_level_o,      // level sampled (the finer one for trilinear)
  output logic [15:0]       out_lod_o,        // LOD used, clamped to [0, top], LF fraction bits
  output logic [TagW-1:0]   out_tag_o,

  output logic              busy_o
);
  localparam bit          HasTri = Filters[2];
  localparam bit          HasBil = Filters[1];
  localparam int unsigned TexW   = Formats[2] ? 32 : 16;
  localparam int unsigned LodW   = 24;

  // ---- Registers and memory --------------------------------------------------------------------
  logic [25:0]            desc;
  logic                   err_format, err_filter, busy, sample;
  htx_tex_regs #(.Formats(Formats), .Filters(Filters), .NumSlots(NumSlots), .BAW(BAW), .TexW(TexW),
                 .Counters(Counters), .WindowRead(WindowRead), .SharedDescMux(Lanes == 1)) u_regs (
    .clk_i, .rst_ni,
    .req_valid_i(reg_req_valid_i), .req_ready_o(reg_req_ready_o), .req_addr_i(reg_req_addr_i),
    .req_we_i(reg_req_we_i), .req_be_i(reg_req_be_i), .req_wdata_i(reg_req_wdata_i),
    .rsp_valid_o(reg_rsp_valid_o), .rsp_rdata_o(reg_rsp_rdata_o), .rsp_err_o(reg_rsp_err_o),
    .slot_i(req_slot_i), .slot_take_i(req_valid_i && req_ready_o), .desc_o(desc), .busy_i(busy),
    .err_format_i(err_format), .err_filter_i(err_filter),
    .sample_i(sample));

  logic              s_re, s_hold;
  logic [4*BAW-1:0]  s_addr;
  logic [4*TexW-1:0] s_rdata;
  htx_tex_mem #(.TexW(TexW), .BAW(BAW), .CpuRead(WindowRead)) u_mem (
    .clk_i, .rst_ni,
    .req_valid_i(mem_req_valid_i), .req_ready_o(mem_req_ready_o), .req_addr_i(mem_req_addr_i),
    .req_we_i(mem_req_we_i), .req_be_i(mem_req_be_i), .req_wdata_i(mem_req_wdata_i),
    .rsp_valid_o(mem_rsp_valid_o), .rsp_rdata_o(mem_rsp_rdata_o), .rsp_err_o(mem_rsp_err_o),
    .s_re_i(s_re), .s_hold_i(s_hold), .s_addr_i(s_addr), .s_rdata_o(s_rdata));

  // ---- Front: descriptor, filter actually built ------------------------------------------------
  logic [1:0]  filter;
  logic        bad_filter;
  always_comb begin
    bad_filter = 1'b0;
    unique case (req_filter_i)
      2'd0: filter = 2'd0;
      2'd1: begin filter = HasBil ? 2'd1 : 2'd0; bad_filter = !HasBil; end
      2'd2: begin
        filter = HasTri ? 2'd2 : (HasBil ? 2'd1 : 2'd0);
        bad_filter = !HasTri;
      end
      default: begin filter = HasBil ? 2'd1 : 2'd0; bad_filter = 1'b1; end
    endcase
  end
  assign err_filter = req_valid_i && req_ready_o && bad_filter;

  // Sampler input.
  logic              sp_valid, sp_ready, sp_nearest;
  logic [CoordW-1:0] sp_u, sp_v;
  logic [1:0]        sp_wrap_u, sp_wrap_v;
  logic [25:0]       sp_desc;
  logic [3:0]        sp_l0;
  logic [7:0]        sp_wtri;
  logic [15:0]       sp_lod;
  logic [TagW-1:0]   sp_tag;
  logic              front_busy;

  if (HasTri) begin : g_lod
    localparam int unsigned PW = 2 * CoordW + 2 + 4 + 26 + 1 + LodW + TagW;
    logic [PW-1:0]          pay_in, pay_out;
    logic signed [LodW-1:0] lod_calc, lod_raw, lod_top, lod_c;
    logic                   lod_zero;
    logic [CoordW-1:0]      p_u, p_v;
    logic [1:0]             p_filter;
    logic [3:0]             p_wraps;
    logic [25:0]            p_desc;
    logic                   p_direct;
    logic [LodW-1:0]        p_lod;
    logic [TagW-1:0]        p_tag;
    logic [3:0]             top;
    logic                   lod_busy;
    assign pay_in = {req_u_i, req_v_i, filter, req_wrap_v_i, req_wrap_u_i, desc, req_lod_direct_i,
                     req_lod_i, req_tag_i};
    htx_tex_lod #(.QW(QW), .GradW(GradW), .LocW(LocW), .TF(TF), .LF(LF), .IdxBits(LogIdx), .PW(PW),
                  .LodW(LodW)) u_lod (
      .clk_i, .rst_ni,
      .in_valid_i(req_valid_i), .in_ready_o(req_ready_o),
      .q_i(req_lod_q_i), .gux_i(req_lod_gux_i), .guy_i(req_lod_guy_i), .gvx_i(req_lod_gvx_i),
      .gvy_i(req_lod_gvy_i), .gqx_i(req_lod_gqx_i), .gqy_i(req_lod_gqy_i),
      .grad_shift_i(req_lod_shift_i), .u_i(req_lod_u_i), .v_i(req_lod_v_i), .payload_i(pay_in),
      .out_valid_o(sp_valid), .out_ready_i(sp_ready), .lod_o(lod_calc), .zero_o(lod_zero),
      .payload_o(pay_out), .busy_o(lod_busy));
    assign {p_u, p_v, p_filter, p_wraps, p_desc, p_direct, p_lod, p_tag} = pay_out;
    // The sampler's LOD: 0 for all-zero derivatives, else clamped to [0, top 2^LF]; level
    // floor(lod), weight its fraction scaled to 8 bits (0 at the top level).
    assign top     = (p_desc[19:16] > p_desc[23:20]) ? p_desc[19:16] : p_desc[23:20];
    assign lod_raw = p_direct ? $signed(p_lod) : (lod_zero ? '0 : lod_calc);
    assign lod_top = $signed(LodW'(top) << LF);
    assign lod_c   = (lod_raw < 0) ? '0 : ((lod_raw > lod_top) ? lod_top : lod_raw);
    assign sp_u      = p_u;
    assign sp_v      = p_v;
    assign sp_nearest = (p_filter == 2'd0);
    assign {sp_wrap_v, sp_wrap_u} = p_wraps;
    assign sp_desc   = p_desc;
    assign sp_l0     = (p_filter == 2'd2) ? 4'(lod_c >>> LF) : 4'd0;
    assign sp_wtri   = (p_filter == 2'd2) ? 8'(lod_c[LF-1:0]) << (8 - LF) : 8'd0;
    assign sp_lod    = 16'(lod_c);
    assign sp_tag    = p_tag;
    assign front_busy = lod_busy;
  end else begin : g_no_lod
    assign sp_valid   = req_valid_i;
    assign req_ready_o = sp_ready;
    assign sp_u       = req_u_i;
    assign sp_v       = req_v_i;
    assign sp_nearest = (filter == 2'd0);
    assign sp_wrap_u  = req_wrap_u_i;
    assign sp_wrap_v  = req_wrap_v_i;
    assign sp_desc    = desc;
    assign sp_l0      = 4'd0;
    assign sp_wtri    = 8'd0;
    assign sp_lod     = 16'd0;
    assign sp_tag     = req_tag_i;
    assign front_busy = 1'b0;
    logic unused_lod;
    assign unused_lod = ^{req_lod_direct_i, req_lod_i, req_lod_q_i, req_lod_gux_i, req_lod_guy_i,
                          req_lod_gvx_i, req_lod_gvy_i, req_lod_gqx_i, req_lod_gqy_i, req_lod_shift_i,
                          req_lod_u_i, req_lod_v_i};
  end

  logic s_busy;
  htx_tex_sampler #(.CoordW(CoordW), .TF(TF), .Formats(Formats), .HasTri(HasTri), .TexW(TexW),
                    .BAW(BAW), .Lanes(Lanes), .ShiftAdd(ShiftAdd), .TagW(TagW)) u_sampler (
    .clk_i, .rst_ni,
    .in_valid_i(sp_valid), .in_ready_o(sp_ready), .in_u_i(sp_u), .in_v_i(sp_v),
    .in_nearest_i(sp_nearest), .in_wrap_u_i(sp_wrap_u), .in_wrap_v_i(sp_wrap_v), .in_desc_i(sp_desc),
    .in_l0_i(sp_l0), .in_wtri_i(sp_wtri), .in_lod_i(sp_lod), .in_tag_i(sp_tag),
    .s_re_o(s_re), .s_hold_o(s_hold), .s_addr_o(s_addr), .s_rdata_i(s_rdata),
    .out_valid_o, .out_ready_i, .out_rgba_o, .out_level_o, .out_lod_o, .out_tag_o,
    .err_format_o(err_format), .busy_o(s_busy));

  assign busy   = s_busy || front_busy;
  assign busy_o = busy;
  assign sample = out_valid_o && out_ready_i;
endmodule
