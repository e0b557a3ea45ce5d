// Sampling pipeline (docs/model.md §7, model sample()): texel addresses, one read of the four
// banks per level, decode, bilinear blend, trilinear blend. Stages, each a valid/ready register:
//   R  request: per-axis indices and weights at level l0 + pass. A trilinear request with a
//      non-zero level weight makes two passes (levels l0 and l0 + 1, one clock each); every other
//      request one. Lanes = 1 has one axis unit for both axes: two clocks a pass.
//   A  the four bank addresses of a pass; the read is issued when B takes it.
//   B  bank data (held in the RAMs' output registers): select each footprint texel, decode.
//   C  blend: Lanes = 4 blends all channels in one clock; Lanes = 1 one channel at a time, one
//      product per clock through one multiplier (3 clocks a channel, 12 a bilinear texel, nearest
//      passes in one).
//   D  output; the first pass of a trilinear request waits in D for the second, then
//      (a (256 - w) + b w + 128) >> 8 per channel.
// Nearest uses the same path with both indices equal and zero weights, which the blend returns
// unchanged.
module htx_tex_sampler #(
  parameter int unsigned CoordW   = 48,
  parameter int unsigned TF       = 16,
  parameter logic [2:0]  Formats  = 3'b111,
  parameter bit          HasTri   = 1'b1,
  parameter int unsigned TexW     = 32,
  parameter int unsigned BAW      = 15,
  parameter int unsigned Lanes    = 4,      // 4 or 1
  parameter bit          ShiftAdd = 1'b0,
  parameter int unsigned TagW     = 32
) (
  input  logic              clk_i,
  input  logic              rst_ni,

  input  logic              in_valid_i,
  output logic              in_ready_o,
  input  logic [CoordW-1:0] in_u_i,
  input  logic [CoordW-1:0] in_v_i,
  input  logic              in_nearest_i,
  input  logic [1:0]        in_wrap_u_i,
  input  logic [1:0]        in_wrap_v_i,
  input  logic [25:0]       in_desc_i,     // {format, log2_h, log2_w, base}
  input  logic [3:0]        in_l0_i,       // finer level
  input  logic [7:0]        in_wtri_i,     // weight of level l0 + 1; 0: one pass
  input  logic [15:0]       in_lod_i,      // carried to the output
  input  logic [TagW-1:0]   in_tag_i,

  output logic              s_re_o,
  output logic              s_hold_o,
  output logic [4*BAW-1:0]  s_addr_o,
  input  logic [4*TexW-1:0] s_rdata_i,

  output logic              out_valid_o,
  input  logic              out_ready_i,
  output logic [31:0]       out_rgba_o,
  output logic [3:0]        out_level_o,
  output logic [15:0]       out_lod_o,
  output logic [TagW-1:0]   out_tag_o,

  output logic              err_format_o,
  output logic              busy_o
);
  // ---- Stage R: request, passes, per-axis indices ---------------------------------------------------------------------------------
  logic              r_valid_q, r_pass_q, r_nearest_q;
  logic [CoordW-1:0] r_u_q, r_v_q;
  logic [1:0]        r_wrap_u_q, r_wrap_v_q;
  logic [25:0]       r_desc_q;
  logic [3:0]        r_l0_q;
  logic [7:0]        r_wtri_q;
  logic [15:0]       r_lod_q;
  logic [TagW-1:0]   r_tag_q;
  logic              a_ready, r_issue, r_last, r_two;
  logic              r_axes_done;  // both axes' indices are there (Lanes = 1: the second clock)
  logic [3:0]        level;

  assign r_two   = HasTri && (r_wtri_q != 8'd0);
  assign r_last  = !r_two || r_pass_q;
  assign r_issue = r_valid_q && a_ready && r_axes_done;
  assign in_ready_o = !r_valid_q || (r_issue && r_last);
  assign level   = HasTri ? r_l0_q + 4'(r_pass_q) : 4'd0;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      r_valid_q <= 1'b0;
      r_pass_q  <= 1'b0;
    end else if (in_ready_o) begin
      r_valid_q <= in_valid_i;
      r_pass_q  <= 1'b0;
    end else if (r_issue) begin
      r_pass_q  <= 1'b1;  // first of two passes issued
    end
  end
  always_ff @(posedge clk_i) begin
    if (in_ready_o && in_valid_i) begin
      r_u_q       <= in_u_i;
      r_v_q       <= in_v_i;
      r_nearest_q <= in_nearest_i;
      r_wrap_u_q  <= in_wrap_u_i;
      r_wrap_v_q  <= in_wrap_v_i;
      r_desc_q    <= in_desc_i;
      r_l0_q      <= HasTri ? in_l0_i : 4'd0;
      r_wtri_q    <= HasTri ? in_wtri_i : 8'd0;
      r_lod_q     <= in_lod_i;
      r_tag_q     <= in_tag_i;
    end
  end

  logic [3:0]  row_shift;
  logic [13:0] row0, row1;
  logic [7:0] x0, x1, y0, y1, wu, wv;
  logic [3:0] lwu, lwv;
  if (Lanes >= 4) begin : g_axes
    // One axis unit per axis: a request (pass) a clock.
    htx_tex_axis #(.CoordW(CoordW), .TF(TF)) u_axis_u (
      .coord_i(r_u_q), .level_i(level), .log2_size_i(r_desc_q[19:16]), .wrap_i(r_wrap_u_q),
      .nearest_i(r_nearest_q), .i0_o(x0), .i1_o(x1), .weight_o(wu), .log2_level_o(lwu));
    htx_tex_axis #(.CoordW(CoordW), .TF(TF)) u_axis_v (
      .coord_i(r_v_q), .level_i(level), .log2_size_i(r_desc_q[23:20]), .wrap_i(r_wrap_v_q),
      .nearest_i(r_nearest_q), .i0_o(y0), .i1_o(y1), .weight_o(wv), .log2_level_o(lwv));
    assign r_axes_done = 1'b1;
  end else begin : g_axis_shared
    // Lanes = 1 (`icebreaker`, area first): one axis unit, u in a pass's first clock (its results
    // registered), v in the second, which issues the pass: two clocks a pass (the blend takes 12
    // for a bilinear texel, and the board's raster delivers a fragment every 9 clocks at most).
    logic       r_phase_q;  // 0: the u axis this clock; 1: the v axis (u's results registered)
    logic [7:0]  ax_i0, ax_i1, ax_w;
    logic [3:0]  ax_lw;
    logic [27:0] u_q;       // u's i0, i1, weight, level size
    htx_tex_axis #(.CoordW(CoordW), .TF(TF)) u_axis (
      .coord_i(r_phase_q ? r_v_q : r_u_q), .level_i(level),
      .log2_size_i(r_phase_q ? r_desc_q[23:20] : r_desc_q[19:16]),
      .wrap_i(r_phase_q ? r_wrap_v_q : r_wrap_u_q),
      .nearest_i(r_nearest_q), .i0_o(ax_i0), .i1_o(ax_i1), .weight_o(ax_w), .log2_level_o(ax_lw));
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) r_phase_q <= 1'b0;
      else if (in_ready_o || r_issue) r_phase_q <= 1'b0;  // a new request, or the next pass
      else if (r_valid_q) r_phase_q <= 1'b1;
    end
    always_ff @(posedge clk_i) begin
      if (r_valid_q && !r_phase_q) u_q <= {ax_i0, ax_i1, ax_w, ax_lw};
    end
    assign {x0, x1, wu, lwu} = u_q;
    assign {y0, y1, wv, lwv} = {ax_i0, ax_i1, ax_w, ax_lw};
    assign r_axes_done = r_phase_q;
  end

  // ---- Stage A: bank addresses, read issue ---------------------------------------------------------
  logic              a_valid_q, a_first_q, a_second_q, a_nearest_q;
  logic [7:0]        a_x0_q, a_x1_q, a_y0_q, a_y1_q, a_wu_q, a_wv_q, a_wtri_q;
  logic [3:0]        a_level_q, a_l0_q;
  logic [13:0]       a_row0_q, a_row1_q;
  logic [25:0]       a_desc_q;
  logic [15:0]       a_lod_q;
  logic [TagW-1:0]   a_tag_q;
  logic              b_ready, a_issue;
  assign a_ready = !a_valid_q || b_ready;
  assign a_issue = a_valid_q && b_ready;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) a_valid_q <= 1'b0;
    else if (a_ready) a_valid_q <= r_issue;  // A takes a pass only when R issues it
  end
  always_ff @(posedge clk_i) begin
    if (r_issue) begin
      a_first_q   <= r_two && !r_pass_q;
      a_second_q  <= r_two && r_pass_q;
      a_nearest_q <= r_nearest_q;
      a_x0_q      <= x0;
      a_x1_q      <= x1;
      a_y0_q      <= y0;
      a_y1_q      <= y1;
      a_wu_q      <= wu;
      a_wv_q      <= wv;
      a_wtri_q    <= r_wtri_q;
      a_row0_q    <= row0;
      a_row1_q    <= row1;
      a_level_q   <= level;
      a_l0_q      <= r_l0_q;
      a_desc_q    <= r_desc_q;
      a_lod_q     <= r_lod_q;
      a_tag_q     <= r_tag_q;
    end
  end

  // Blocks (2x2 texels, one word per bank) before level lvl of a 2^a x 2^b chain.
  function automatic logic [16:0] level_offset(input logic [3:0] a, input logic [3:0] b,
                                               input logic [3:0] lvl);
    logic [3:0] sa, sb;
    level_offset = '0;
    for (int l = 0; l < 8; l++) begin
      sa = (a > 4'(l + 1)) ? a - 4'(l + 1) : 4'd0;
      sb = (b > 4'(l + 1)) ? b - 4'(l + 1) : 4'd0;
      if (4'(l) < lvl) level_offset = level_offset + (17'd1 << (sa + sb));
    end
  endfunction

  logic [16:0] lvl_base;
  assign lvl_base  = 17'(a_desc_q[15:0]) + (HasTri ? level_offset(a_desc_q[19:16], a_desc_q[23:20], a_level_q)
                                                   : 17'd0);
  assign row_shift = (lwu > 4'd0) ? lwu - 4'd1 : 4'd0;
  // Row offsets of the two footprint rows; a block column never reaches the row stride, so the
  // column joins the row offset by OR.
  assign row0 = 14'(y0[7:1]) << row_shift;   // computed in R, registered into A
  assign row1 = 14'(y1[7:1]) << row_shift;
  for (genvar b = 0; b < 4; b++) begin : g_addr
    logic [6:0]  xs;
    logic [13:0] ro;
    logic [13:0] rc;
    logic [16:0] a;
    assign xs = (a_x0_q[0] == b[0]) ? a_x0_q[7:1] : a_x1_q[7:1];
    assign ro = (a_y0_q[0] == b[1]) ? a_row0_q : a_row1_q;
    assign rc = ro | 14'(xs);
    assign a  = lvl_base + 17'(rc);
    assign s_addr_o[b*BAW +: BAW] = BAW'(a);  // beyond the memory: wraps (docs/texture.md)
    logic unused_a;
    assign unused_a = ^a;
  end
  assign s_re_o = a_issue;

  // ---- Stage B ---------------------------------------------------------------------------------
  logic            b_valid_q, b_first_q, b_second_q, b_nearest_q;
  logic [3:0]      b_par_q;  // x0, x1, y0, y1 parities
  logic [7:0]      b_wu_q, b_wv_q, b_wtri_q;
  logic [1:0]      b_fmt_q;
  logic [3:0]      b_l0_q;
  logic [15:0]     b_lod_q;
  logic [TagW-1:0] b_tag_q;
  logic            c_ready;

  assign b_ready  = !b_valid_q || c_ready;
  assign s_hold_o = b_valid_q && !c_ready;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) b_valid_q <= 1'b0;
    else if (b_ready) b_valid_q <= a_issue;
  end
  always_ff @(posedge clk_i) begin
    if (a_issue) begin
      b_first_q   <= a_first_q;
      b_second_q  <= a_second_q;
      b_nearest_q <= a_nearest_q;
      b_par_q     <= {a_y1_q[0], a_y0_q[0], a_x1_q[0], a_x0_q[0]};
      b_wu_q      <= a_wu_q;
      b_wv_q      <= a_wv_q;
      b_wtri_q    <= a_wtri_q;
      b_fmt_q     <= a_desc_q[25:24];
      b_l0_q      <= a_l0_q;
      b_lod_q     <= a_lod_q;
      b_tag_q     <= a_tag_q;
    end
  end

  // What stage C holds: Lanes = 4 the footprint's texels as read (c00, c10, c01, c11), picked
  // from the banks by the parities; Lanes = 1 the banks' words themselves, from which stage C picks
  // the two texels it blends in each clock (two bank multiplexers instead of four, 2026-12-03,
  // sixth session). Stage C decodes after its register (2026-12-03: it held all four decoded, 64
  // flip-flops and two decoders more).
  logic [TexW-1:0] raw [4];
  logic [31:0]     unused_rgba;
  logic            bad;
  for (genvar k = 0; k < 4; k++) begin : g_pick
    if (Lanes >= 4) begin : g_texel
      logic [1:0] bk;
      assign bk = {k[1] ? b_par_q[3] : b_par_q[2], k[0] ? b_par_q[1] : b_par_q[0]};
      assign raw[k] = s_rdata_i[32'(bk)*TexW +: TexW];
    end else begin : g_bank
      assign raw[k] = s_rdata_i[k*TexW +: TexW];
    end
  end
  // (bad_o depends on the format alone.)
  htx_tex_decode #(.TexW(TexW), .Formats(Formats)) u_check (
    .texel_i('0), .format_i(b_fmt_q), .rgba_o(unused_rgba), .bad_o(bad));
  assign err_format_o = b_valid_q && c_ready && bad;

  // ---- Stage C ---------------------------------------------------------------------------------
  logic            c_valid_q, c_first_q, c_second_q, c_nearest_q;
  logic [TexW-1:0] c_raw_q [4];  // Lanes = 4: c00, c10, c01, c11; Lanes = 1: banks 0 .. 3
  logic [3:0]      c_par_q;      // Lanes = 1: b_par_q
  logic [1:0]      c_fmt_q;
  logic [7:0]      c_wu_q, c_wv_q, c_wtri_q;
  logic [3:0]      c_l0_q;
  logic [15:0]     c_lod_q;
  logic [TagW-1:0] c_tag_q;
  logic            c_ready_l;
  // Final item of stage C (Lanes = 4: C itself; Lanes = 1: its second half C2) and whether D takes it.
  logic            f_valid, f_first, f_second, f_take;
  logic [31:0]     f_res;
  logic [7:0]      f_wtri;
  logic [3:0]      f_l0;
  logic [15:0]     f_lod;
  logic [TagW-1:0] f_tag;
  logic            out_free;

  assign out_free = !out_valid_o || out_ready_i;
  assign f_take   = f_first || out_free;   // a first pass always fits in D's holding register
  assign c_ready  = c_ready_l;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) c_valid_q <= 1'b0;
    else if (c_ready) c_valid_q <= b_valid_q;
  end
  always_ff @(posedge clk_i) begin
    if (c_ready && b_valid_q) begin
      c_first_q   <= b_first_q;
      c_second_q  <= b_second_q;
      c_nearest_q <= b_nearest_q;
      for (int k = 0; k < 4; k++) c_raw_q[k] <= raw[k];
      c_par_q     <= b_par_q;
      c_fmt_q     <= b_fmt_q;
      c_wu_q      <= b_wu_q;
      c_wv_q      <= b_wv_q;
      c_wtri_q    <= b_wtri_q;
      c_l0_q      <= b_l0_q;
      c_lod_q     <= b_lod_q;
      c_tag_q     <= b_tag_q;
    end
  end

  if (Lanes >= 4) begin : g_lanes4
    logic [31:0] c_tex_q [4];
    logic [3:0]  unused_bad;
    for (genvar k = 0; k < 4; k++) begin : g_decode
      htx_tex_decode #(.TexW(TexW), .Formats(Formats)) u_decode (
        .texel_i(c_raw_q[k]), .format_i(c_fmt_q), .rgba_o(c_tex_q[k]), .bad_o(unused_bad[k]));
    end
    for (genvar ch = 0; ch < 4; ch++) begin : g_ch
      htx_tex_bilerp #(.ShiftAdd(ShiftAdd)) u_bilerp (
        .c00_i(c_tex_q[0][8*ch +: 8]), .c10_i(c_tex_q[1][8*ch +: 8]),
        .c01_i(c_tex_q[2][8*ch +: 8]), .c11_i(c_tex_q[3][8*ch +: 8]),
        .wu_i(c_wu_q), .wv_i(c_wv_q), .c_o(f_res[8*ch +: 8]));
    end
    assign f_valid   = c_valid_q;
    assign f_first   = c_first_q;
    assign f_second  = c_second_q;
    assign f_wtri    = c_wtri_q;
    assign f_l0      = c_l0_q;
    assign f_lod     = c_lod_q;
    assign f_tag     = c_tag_q;
    assign c_ready_l = !c_valid_q || f_take;
    logic unused_l4;
    assign unused_l4 = ^{c_nearest_q, unused_bad, c_par_q};
  end else begin : g_lane1
    // One channel at a time, one product per clock on one multiplier (one iCE40 DSP):
    //   step 0: h0 = 256 c00 + wu (c10 - c00);  step 1: h1 = 256 c01 + wu (c11 - c01);
    //   step 2: (256 h0 + wv (h1 - h0) + 2^15) >> 16, the channel's result (htx_tex_bilerp's
    //   integers), in 3 clocks a channel; nearest takes 1 clock. (Until 2026-12-02 this was a
    //   two-step pipeline with three multipliers, 4 clocks a bilinear texel: 3 DSPs.)
    // Every step is one sum, product + addend (one adder, not three): steps 0 and 1 add 256 c +
    // 128, so h0_q and h1_q hold h + 128 (h <= 255 * 256, so no wrap; their difference is still
    // h1 - h0), and step 2 adds 256 (h0 + 128), whose 2^15 is the rounding. (The DSP's own adder
    // cannot take the sum: the 17-bit signed operand makes Yosys split the product.)
    logic [1:0]         ch_q, st_q;
    logic [7:0]         e_lo, e_hi;  // this clock's channel of c00 and c10 (step 0) or c01 and c11
    logic [15:0]        h0_q, h1_q;
    logic [23:0]        part_q;
    logic signed [16:0] m_a;
    logic [7:0]         m_w;
    logic signed [25:0] m_p;
    logic [25:0]        m_add, m_sum;
    logic               fin;
    // A nearest item finishes in the clock it enters (st_q 0), so t_lo is then c00 decoded.
    logic [31:0] t_lo, t_hi;
    logic [1:0]  unused_bad;
    // c00 and c10 (step 0) or c01 and c11: the row's bank by y0 or y1, the column's by x0 or x1.
    logic [1:0]  bk_lo, bk_hi;
    assign bk_lo = {st_q[0] ? c_par_q[3] : c_par_q[2], c_par_q[0]};
    assign bk_hi = {st_q[0] ? c_par_q[3] : c_par_q[2], c_par_q[1]};
    htx_tex_decode #(.TexW(TexW), .Formats(Formats)) u_decode_lo (
      .texel_i(c_raw_q[bk_lo]), .format_i(c_fmt_q), .rgba_o(t_lo), .bad_o(unused_bad[0]));
    htx_tex_decode #(.TexW(TexW), .Formats(Formats)) u_decode_hi (
      .texel_i(c_raw_q[bk_hi]), .format_i(c_fmt_q), .rgba_o(t_hi), .bad_o(unused_bad[1]));
    assign e_lo = t_lo[8*ch_q +: 8];
    assign e_hi = t_hi[8*ch_q +: 8];
    always_comb begin
      if (st_q == 2'd2) begin
        m_a = $signed({1'b0, h1_q}) - $signed({1'b0, h0_q});
        m_w = c_wv_q;
      end else begin
        m_a = $signed(17'(e_hi)) - $signed(17'(e_lo));  // c10 - c00, then c11 - c01
        m_w = c_wu_q;
      end
    end
    htx_tex_mul #(.AW(17), .ShiftAdd(ShiftAdd)) u_m (.a_i(m_a), .w_i(m_w), .p_o(m_p));
    assign m_add = (st_q == 2'd2) ? {2'b0, h0_q, 8'd0} : {10'b0, e_lo, 8'h80};
    assign m_sum = 26'(m_p) + m_add;
    // The quad's last clock: nearest, or the last channel's step 2.
    assign fin = c_nearest_q || ((ch_q == 2'd3) && (st_q == 2'd2));
    assign c_ready_l = !c_valid_q || (fin && f_take);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ch_q <= '0;
        st_q <= '0;
      end else if (c_ready_l) begin
        ch_q <= '0;
        st_q <= '0;
      end else if (!fin) begin
        st_q <= (st_q == 2'd2) ? 2'd0 : st_q + 2'd1;
        if (st_q == 2'd2) ch_q <= ch_q + 2'd1;
      end
    end
    always_ff @(posedge clk_i) begin
      if (c_valid_q && !fin) begin
        if (st_q == 2'd0) h0_q <= m_sum[15:0];
        if (st_q == 2'd1) h1_q <= m_sum[15:0];
        if (st_q == 2'd2) part_q[8*ch_q +: 8] <= m_sum[23:16];
      end
    end
    assign f_valid  = c_valid_q && fin;
    assign f_res    = c_nearest_q ? t_lo : {m_sum[23:16], part_q};
    assign f_first  = c_first_q;
    assign f_second = c_second_q;
    assign f_wtri   = c_wtri_q;
    assign f_l0     = c_l0_q;
    assign f_lod    = c_lod_q;
    assign f_tag    = c_tag_q;
    logic unused_ls;
    assign unused_ls = ^{m_sum[25:24], unused_bad};
  end

  // ---- Stage D ---------------------------------------------------------------------------------
  logic        f_fire;
  logic [31:0] first_q, tri_res;
  assign f_fire = f_valid && f_take;

  if (HasTri) begin : g_tri
    for (genvar ch = 0; ch < 4; ch++) begin : g_ch
      htx_tex_lerp #(.ShiftAdd(ShiftAdd)) u_lerp (
        .a_i(first_q[8*ch +: 8]), .b_i(f_res[8*ch +: 8]), .w_i(f_wtri), .c_o(tri_res[8*ch +: 8]));
    end
  end else begin : g_no_tri
    assign tri_res = f_res;
  end

  always_ff @(posedge clk_i) begin
    if (f_fire && f_first) first_q <= f_res;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_valid_o <= 1'b0;
    end else if (f_fire && !f_first) begin
      out_valid_o <= 1'b1;
    end else if (out_ready_i) begin
      out_valid_o <= 1'b0;
    end
  end
  always_ff @(posedge clk_i) begin
    if (f_fire && !f_first) begin
      out_rgba_o  <= (HasTri && f_second) ? tri_res : f_res;
      out_level_o <= f_l0;
      out_lod_o   <= f_lod;
      out_tag_o   <= f_tag;
    end
  end

  assign busy_o = r_valid_q || a_valid_q || b_valid_q || c_valid_q || out_valid_o;

  logic unused;
  assign unused = ^{lwv, unused_rgba, f_wtri, first_q, a_y0_q[7:1], a_y1_q[7:1], a_x0_q[0], a_x1_q[0], a_y0_q[0], a_y1_q[0]};
endmodule
