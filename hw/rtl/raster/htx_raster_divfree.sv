// DIVFREE (docs/model.md §5.5, reference 004) between shade and the divider: per fragment and axis a
// grid index j on cells of 2^-f texels of mip level L (f = 0 for nearest, FracBits otherwise; L = 0
// for nearest and untextured triangles, else chosen per span, below), P = TF + L - f. The cell is
// the j with
//   N(j) = 2^(TF+1) U - (2^(P+1) j + 1) Q >= 0   and   N(j) < B = 2^(P+1) Q
// (Q raised to 1 when below). Each pixel starts from a prediction and walks j by +-1 while N < 0 or
// N >= B, at most Cap steps per axis (both axes in parallel); an axis the cap stops takes the cell of
// the divided coordinate c = U / Q (the divider of §5.2 on its own iterative htx_recip, PixelSteps
// Newton steps): (c - 1) >> P. Predictions: inside a span the previous j plus its movement; the
// span's second pixel round(s >> 16); a span's first pixel j_a + round((dy m + dx s) >> 16) from the
// previous span start; the triangle's first pixel (the seed) the divided cell, with m, s from the
// seed's derivatives (four more numerators through the divider's product). After a span start,
// m = round(((j - j_a) 2^16 - dx s) inv(dy) >> 16) (dy <= 64); after a span's first min(n - 1, 64)
// pixel steps, s = (j_L - j_0) inv(L) (inv: the 64-entry round(2^16 / L) table of SUBDIV).
// Bilinear and trilinear (textured): at each span's first pixel the LOD unit (htx_tex_lod, the
// texture unit's) gives L = clamp(floor(lod), 0, top) from the previous span start's cell centre
// (the seed: its divided coordinate), top = the texture's last level (state word); a change of L
// rescales the carried j_a, m and s by 2^(old - new).
// N(j) is formed with one product (j times Q) per axis and clock; a clock checks j and one step on,
// so a pixel takes max(1, larger step count) clocks when nothing is capped (+1 at a span start).
// Fragments of other methods pass in one clock. Order is kept; one fragment is inside at a time.
module htx_raster_divfree #(
  parameter int unsigned AccQ         = 58,
  parameter int unsigned AccU         = 74,
  parameter int unsigned UvIntBits    = 16,
  parameter int unsigned TF           = 16,
  parameter int unsigned LocW         = 32,
  parameter int unsigned W            = 32,
  parameter int unsigned K            = 10,
  parameter int unsigned G            = 2,
  parameter int unsigned Steps        = 2,
  parameter int unsigned FracBits     = 4,    // divfree_frac_bits
  parameter int unsigned Cap          = 64,   // divfree_cap
  parameter int unsigned GWU          = 100,  // full-precision gradient width (signed)
  parameter int unsigned GradW        = 24,   // lod_grad_bits
  parameter int unsigned LF           = 8,    // lod_frac_bits
  parameter int unsigned LogIdx       = 10,   // lod_log_index_bits
  parameter int unsigned PayW         = 8,
  parameter bit          MulIterative = 1'b0
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                abort_i,

  input  logic                in_valid_i,
  output logic                in_ready_o,
  input  logic                in_df_i,      // the fragment's triangle uses DIVFREE
  input  logic                in_fine_i,    // grid of 2^-FracBits texels (filter not nearest)
  input  logic                in_track_i,   // level per span (textured, bilinear or trilinear)
  input  logic [3:0]          in_top_i,     // the texture's last mip level
  input  logic [6*GradW-1:0]  in_lod_g_i,   // the LOD unit's block-shifted gradients
  input  logic [7:0]          in_lod_shift_i,
  input  logic                in_tfirst_i,  // the triangle's first fragment
  input  logic                in_first_i,   // its span's first pixel
  input  logic                in_last_i,    // its span's last pixel
  input  logic [12:0]         in_x_i, in_y_i,
  input  logic [AccQ-1:0]     in_q_i,
  input  logic [AccU-1:0]     in_u_i, in_v_i,
  input  logic [6*GWU-1:0]    in_g_i,       // gradients per subpixel: uq x, uq y, vq x, vq y, q x, q y
  input  logic [PayW-1:0]     in_pay_i,

  output logic                out_valid_o,
  input  logic                out_ready_i,
  output logic                out_df_o,
  output logic [LocW-1:0]     out_u_o, out_v_o,  // DIVFREE: the cell centres
  output logic [PayW-1:0]     out_pay_o,

  output logic                steps_valid_o,     // a DIVFREE pixel finished (pulse)
  output logic [15:0]         steps_o            // its u + v steps
);
  localparam int unsigned CapW  = $clog2(Cap + 1);
  localparam int unsigned JW    = UvIntBits + FracBits + 4;            // grid indices (signed)
  localparam int unsigned MW    = UvIntBits + FracBits + 34;           // m, s: cells, 16 fraction bits
  localparam int unsigned SPW   = MW + 16;                             // dy m + dx s
  localparam int unsigned NW    = ((AccU + TF + 1 > JW + TF + 10 + AccQ) ? AccU + TF + 1
                                                                         : JW + TF + 10 + AccQ) + 2;
  localparam int unsigned CW    = LocW + 2;                            // divided coordinate
  localparam int unsigned NUMW  = ((GWU + TF > LocW + GWU) ? GWU + TF : LocW + GWU) + 12;
  localparam int unsigned SHW   = UvIntBits + TF + W + 4;              // numerator after the shift
  localparam int unsigned DDW   = UvIntBits + TF + 22;                 // derivatives, 16 fraction bits
  localparam int unsigned MsbW  = $clog2(AccQ);
  localparam int unsigned PBW   = 6;                                   // P, shift amounts

  // ---- Helpers ---------------------------------------------------------------------------------
  // round(x 2^-s), s >= 1 (ties toward +inf, arithmetic shift).
  function automatic logic signed [SPW-1:0] sr(input logic signed [SPW-1:0] x, input logic [PBW-1:0] s);
    sr = (x + (SPW'(1) <<< (s - 1'b1))) >>> s;
  endfunction

  // The divider's numerator shift: round(N 2^-s) for s = msb - (W - 1) > 0, else N << -s.
  function automatic logic signed [SHW-1:0] shift_num(input logic signed [NUMW-1:0] num,
                                                      input logic [MsbW-1:0] msb);
    logic signed [NUMW+W-1:0] wide;
    wide = (NUMW+W)'(num);
    if (32'(msb) >= W) shift_num = SHW'((wide + ((NUMW+W)'(1) <<< (32'(msb) - W))) >>> (32'(msb) - (W - 1)));
    else shift_num = SHW'(wide <<< ((W - 1) - 32'(msb)));
  endfunction

  // round(N' R 2^-(2W - 1 - fb)).
  function automatic logic signed [DDW-1:0] div_round(input logic signed [SHW-1:0] n, input logic [W:0] r,
                                                      input logic [5:0] fb);
    logic signed [SHW+W+1:0] p;
    int unsigned rs;
    rs = 2 * W - 1 - 32'(fb);
    p = (SHW+W+2)'(n) * $signed({1'b0, r});
    div_round = DDW'((p + ((SHW+W+2)'(1) <<< (rs - 1))) >>> rs);
  endfunction

  // Grid cell centre: (2j + 1) 2^(P - 1).
  function automatic logic [LocW-1:0] centre(input logic signed [JW-1:0] j, input logic [PBW-1:0] p);
    logic signed [LocW+JW:0] c;
    c = ((LocW+JW+1)'(j) <<< 1) + (LocW+JW+1)'(1);
    centre = LocW'(c <<< (p - 1'b1));
  endfunction

  // round(2^16 / L), L = 1..64 (index L - 1): SUBDIV's table.
  logic [16:0] inv_rom [64];
  initial begin
    for (int unsigned l = 1; l <= 64; l++) inv_rom[l-1] = 17'(((1 << 17) + l) / (2 * l));
  end

  // ---- The fragment inside ---------------------------------------------------------------------
  typedef enum logic [3:0] {StIdle, StPass, StSpan, StRun, StSeed, StRecip, StMul, StFin, StLodReq,
                            StLodWait, StSeedCell} state_e;
  state_e                 st_q;
  logic                   fine_q, track_q, tfirst_q, first_q, last_q;
  logic [3:0]             top_q;
  logic [6*GradW-1:0]     lg_q;
  logic [7:0]             lsh_q;
  logic [3:0]             lvl_q;          // the triangle's tracking level
  logic [12:0]            x_q, y_q;
  logic [AccQ-1:0]        q_q;
  logic signed [AccU-1:0] u_q, v_q;
  logic [6*GWU-1:0]       g_q;
  logic [PayW-1:0]        pay_q;

  // Walk state of the fragment inside.
  logic                   inner_q;        // first run clock predicts j_prev + du
  logic                   seeded_q;       // the seed's division is done
  logic signed [JW-1:0]   jw_q [2];
  logic [CapW-1:0]        sc_q [2];
  logic                   done_q [2], cap_q [2];
  logic [2:0]             k_q;
  logic signed [CW-1:0]   c_q [2];
  logic signed [DDW-1:0]  d_q [4];        // seed derivatives: u x, u y, v x, v y

  // Per triangle, carried from pixel to pixel and span to span.
  logic signed [JW-1:0]   jprev_q [2], du_q [2], ja_q [2], jfirst_q [2];
  logic signed [MW-1:0]   row_q [2], slope_q [2];
  logic [12:0]            x0a_q, rowa_q;
  logic [6:0]             kidx_q;         // pixel index in the span (saturates at 65)

  // Output register.
  logic                   out_valid_q, out_df_q;
  logic [LocW-1:0]        out_u_q, out_v_q;
  logic [PayW-1:0]        out_pay_q;
  logic                   steps_valid_q;
  logic [15:0]            steps_q;

  logic [PBW-1:0] p_bits;
  assign p_bits = PBW'(TF) + PBW'(lvl_q) - (fine_q ? PBW'(FracBits) : PBW'(0));

  logic [AccQ-1:0] q_eff;
  assign q_eff = ($signed(q_q) < $signed(AccQ'(1))) ? AccQ'(1) : q_q;

  // ---- Reciprocal of Q and the divider's product --------------------------------------------------
  logic           r_start, r_done, r_busy;
  logic [W:0]     r_nr, r_t;
  logic [MsbW-1:0] r_msb;
  logic             r_mul_start;  // (its own multiplier)
  logic [W+2:0]     r_mul_a, r_mul_b;
  logic             r_norm_shift;  // (no serial normaliser)
  htx_recip #(.XWidth(AccQ), .W(W), .K(K), .G(G), .Steps(Steps), .Iterative(MulIterative),
              .Pipelined(1'b0)) u_recip (
    .clk_i, .rst_ni, .abort_i,
    .start_i(r_start), .en_i(1'b1), .table_only_i(1'b0), .alt_i(1'b0), .x_i(q_eff),
    .busy_o(r_busy), .done_o(r_done), .r_o(r_nr), .r0_o(r_t), .msb_o(r_msb),
    .mul_start_o(r_mul_start), .mul_a_o(r_mul_a), .mul_b_o(r_mul_b), .mul_done_i(1'b0), .mul_p_i('0),
    .norm_shift_o(r_norm_shift)
  );
  logic             unused_r_mul;
  assign unused_r_mul = ^{r_mul_start, r_mul_a, r_mul_b, r_norm_shift};

  // Product k: 0 c_u = U / Q, 1 c_v, 2..5 the seed derivatives (u x, u y, v x, v y), 16 fraction bits:
  // round(((256 (g_num 2^TF - c g_q)) clamped to +-2^(UvIntBits+TF+1) Q) / Q).
  logic signed [NUMW-1:0] num_k, dnum, limit;
  logic signed [GWU-1:0]  g_num, g_den;
  logic signed [CW-1:0]   c_sel;
  logic signed [DDW-1:0]  div_k;
  function automatic logic signed [GWU-1:0] in_g(input logic [6*GWU-1:0] g, input int unsigned i);
    in_g = $signed(g[GWU*i +: GWU]);
  endfunction
  always_comb begin
    g_num = GWU'(0);
    g_den = GWU'(0);
    c_sel = c_q[0];
    unique case (k_q)
      3'd2: begin g_num = in_g(g_q, 0); g_den = in_g(g_q, 4); c_sel = c_q[0]; end
      3'd3: begin g_num = in_g(g_q, 1); g_den = in_g(g_q, 5); c_sel = c_q[0]; end
      3'd4: begin g_num = in_g(g_q, 2); g_den = in_g(g_q, 4); c_sel = c_q[1]; end
      3'd5: begin g_num = in_g(g_q, 3); g_den = in_g(g_q, 5); c_sel = c_q[1]; end
      default: ;
    endcase
    dnum  = ((NUMW'(g_num) <<< TF) - NUMW'(c_sel) * NUMW'(g_den)) <<< 8;
    limit = $signed(NUMW'(q_eff)) <<< (UvIntBits + TF + 1);
    if (dnum > limit) dnum = limit;
    else if (dnum < -limit) dnum = -limit;
    unique case (k_q)
      3'd0: num_k = NUMW'(u_q);
      3'd1: num_k = NUMW'(v_q);
      default: num_k = dnum;
    endcase
    div_k = div_round(shift_num(num_k, r_msb), r_nr, (k_q < 3'd2) ? 6'(TF) : 6'd16);
  end

  // ---- The walk: per axis, N at the current j and one step on ------------------------------------
  logic signed [NW-1:0]  big_b;
  assign big_b = $signed(NW'(q_eff)) <<< (p_bits + 1'b1);

  logic signed [JW-1:0]  jc [2], j1 [2], jres [2];
  logic [CapW-1:0]       s1 [2], sres [2];
  logic                  res [2], capnow [2], conv1 [2];
  logic signed [NW-1:0]  n0 [2], n1 [2];
  for (genvar a = 0; a < 2; a++) begin : g_axis
    logic signed [AccU-1:0] num;
    assign num = (a == 0) ? u_q : v_q;
    always_comb begin
      jc[a] = inner_q ? jprev_q[a] + du_q[a] : jw_q[a];
      n0[a] = (NW'(num) <<< (TF + 1)) -
              ((NW'(jc[a]) <<< (p_bits + 1'b1)) + NW'(1)) * $signed(NW'(q_eff));
      n1[a] = (n0[a] < 0) ? n0[a] + big_b : n0[a] - big_b;
      j1[a] = (n0[a] < 0) ? jc[a] - JW'(1) : jc[a] + JW'(1);
      s1[a] = sc_q[a] + 1'b1;
      conv1[a] = (n1[a] >= 0) && (n1[a] < big_b);
      res[a] = 1'b0; capnow[a] = 1'b0; jres[a] = jc[a]; sres[a] = sc_q[a];
      if (done_q[a]) begin
        res[a] = 1'b1; capnow[a] = cap_q[a]; jres[a] = jw_q[a];
      end else if ((n0[a] >= 0) && (n0[a] < big_b)) begin
        res[a] = 1'b1;
      end else if (32'(sc_q[a]) == Cap) begin
        res[a] = 1'b1; capnow[a] = 1'b1;
      end else begin
        jres[a] = j1[a]; sres[a] = s1[a];
        res[a] = conv1[a];
      end
    end
  end

  // ---- Span-start prediction ---------------------------------------------------------------------
  logic signed [13:0]    dx, dy;
  assign dx = $signed({1'b0, x_q}) - $signed({1'b0, x0a_q});
  assign dy = $signed({1'b0, y_q}) - $signed({1'b0, rowa_q});
  logic signed [JW-1:0]  jspan [2];
  for (genvar a = 0; a < 2; a++) begin : g_span
    logic signed [SPW-1:0] t, wide;
    localparam logic signed [SPW-1:0] Lim = SPW'(1) <<< (JW - 2);
    always_comb begin
      t    = sr(SPW'(dy) * SPW'(row_q[a]) + SPW'(dx) * SPW'(slope_q[a]), PBW'(16));
      wide = t + SPW'(ja_q[a]);
      jspan[a] = (wide > Lim) ? JW'(Lim) : ((wide < -Lim) ? JW'(-Lim) : JW'(wide));
    end
  end

  // ---- Level choice at a span's first pixel (bilinear, trilinear) -------------------------------
  logic                 lod_in_ready, lod_out_valid, lod_zero, lod_busy, lod_pay;
  logic signed [23:0]   lod;
  logic [LocW-1:0]      lod_u, lod_v;
  assign lod_u = tfirst_q ? LocW'(c_q[0]) : centre(ja_q[0], p_bits);
  assign lod_v = tfirst_q ? LocW'(c_q[1]) : centre(ja_q[1], p_bits);
  htx_tex_lod #(.QW(AccQ), .GradW(GradW), .LocW(LocW), .TF(TF), .LF(LF), .IdxBits(LogIdx), .PW(1),
                .LodW(24)) u_lod (
    .clk_i, .rst_ni,
    .in_valid_i  (st_q == StLodReq),
    .in_ready_o  (lod_in_ready),
    .q_i         (q_eff),
    .gux_i(lg_q[0*GradW +: GradW]), .guy_i(lg_q[1*GradW +: GradW]), .gvx_i(lg_q[2*GradW +: GradW]),
    .gvy_i(lg_q[3*GradW +: GradW]), .gqx_i(lg_q[4*GradW +: GradW]), .gqy_i(lg_q[5*GradW +: GradW]),
    .grad_shift_i(lsh_q),
    .u_i         (lod_u),
    .v_i         (lod_v),
    .payload_i   (1'b0),
    .out_valid_o (lod_out_valid),
    // Always taken: a result is used in StLodWait only, so one still in flight at an abort drains.
    .out_ready_i (1'b1),
    .lod_o       (lod),
    .zero_o      (lod_zero),
    .payload_o   (lod_pay),
    .busy_o      (lod_busy)
  );
  // L = clamp(floor(lod), 0, top); the all-zero derivatives' LOD is 0.
  logic signed [23:0] lod_int;
  logic [3:0]         lvl_new;
  assign lod_int = lod >>> LF;
  assign lvl_new = (lod_zero || (lod_int < 0)) ? 4'd0
                   : ((lod_int > $signed({20'd0, top_q})) ? top_q : 4'(lod_int));
  // A level change rescales the carried j_a, m and s by 2^(old - new).
  function automatic logic signed [MW-1:0] rescale(input logic signed [MW-1:0] x, input logic [3:0] from,
                                                   input logic [3:0] to);
    if (to > from) rescale = x >>> (to - from);
    else rescale = x <<< (from - to);
  endfunction

  // ---- Finishing a DIVFREE pixel: the carried state ---------------------------------------------
  logic                  fin_now, pass_now, out_free, fin_fire;
  logic signed [JW-1:0]  jfin [2];
  logic [CapW-1:0]       sfin [2];
  logic signed [JW-1:0]  du_n [2];
  logic signed [MW-1:0]  row_n [2], slope_n [2];
  logic [6:0]            kk;
  logic                  slope_upd;
  logic [16:0]           inv_dy, inv_k;
  assign kk        = first_q ? 7'd0 : kidx_q;
  assign slope_upd = (kk != 7'd0) && ((kk == 7'd64) || (last_q && (kk < 7'd64)));
  assign inv_dy    = inv_rom[6'(dy - 14'sd1)];
  assign inv_k     = inv_rom[6'(kk - 7'd1)];
  for (genvar a = 0; a < 2; a++) begin : g_fin
    logic signed [SPW+18:0] rest;
    logic signed [SPW-1:0]  sl_used;
    always_comb begin
      row_n[a]   = row_q[a];
      slope_n[a] = slope_q[a];
      rest = '0;
      if (first_q) begin
        if (tfirst_q) begin
          row_n[a]   = MW'(sr(SPW'(d_q[2*a+1]), p_bits));
          slope_n[a] = MW'(sr(SPW'(d_q[2*a]), p_bits));
        end else if (dy <= 14'sd64) begin
          rest = (((SPW+19)'(jfin[a]) - (SPW+19)'(ja_q[a])) <<< 16) - (SPW+19)'(dx) * (SPW+19)'(slope_q[a]);
          rest = (rest * $signed({2'b0, inv_dy}) + ((SPW+19)'(1) <<< 15)) >>> 16;
          row_n[a] = MW'(rest);
        end
        sl_used  = SPW'(slope_n[a]);
        du_n[a]  = JW'(sr(sl_used, PBW'(16)));
      end else begin
        sl_used  = '0;
        du_n[a]  = jfin[a] - jprev_q[a];
      end
      if (slope_upd) slope_n[a] = MW'((SPW'(jfin[a]) - SPW'(jfirst_q[a])) * SPW'($signed({1'b0, inv_k})));
    end
  end

  assign out_free = !out_valid_q || out_ready_i;
  always_comb begin
    fin_now = 1'b0;
    for (int a = 0; a < 2; a++) begin
      jfin[a] = jres[a];
      sfin[a] = sres[a];
    end
    if (st_q == StRun) begin
      fin_now = res[0] && res[1] && !capnow[0] && !capnow[1];
    end else if (st_q == StFin) begin
      fin_now = 1'b1;
      for (int a = 0; a < 2; a++) begin
        jfin[a] = cap_q[a] ? JW'((c_q[a] - CW'(1)) >>> p_bits) : jw_q[a];
        sfin[a] = sc_q[a];
      end
    end
  end
  assign pass_now   = (st_q == StPass);
  assign fin_fire   = out_free && (fin_now || pass_now);
  assign in_ready_o = (st_q == StIdle) || fin_fire;

  logic take;
  assign take = in_valid_i && in_ready_o;

  // The reciprocal starts on entering StRecip (seed on take, cap when the walk stops).
  logic run_capped;
  assign run_capped = (st_q == StRun) && res[0] && res[1] && (capnow[0] || capnow[1]);
  assign r_start    = (st_q == StSeed) || run_capped;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q <= StIdle;
      fine_q <= 1'b0; track_q <= 1'b0; tfirst_q <= 1'b0; first_q <= 1'b0; last_q <= 1'b0;
      top_q <= '0; lg_q <= '0; lsh_q <= '0; lvl_q <= '0;
      x_q <= '0; y_q <= '0; q_q <= '0; u_q <= '0; v_q <= '0; g_q <= '0; pay_q <= '0;
      inner_q <= 1'b0; seeded_q <= 1'b0; k_q <= '0;
      for (int a = 0; a < 2; a++) begin
        jw_q[a] <= '0; sc_q[a] <= '0; done_q[a] <= 1'b0; cap_q[a] <= 1'b0; c_q[a] <= '0;
        jprev_q[a] <= '0; du_q[a] <= '0; ja_q[a] <= '0; jfirst_q[a] <= '0;
        row_q[a] <= '0; slope_q[a] <= '0;
      end
      for (int i = 0; i < 4; i++) d_q[i] <= '0;
      x0a_q <= '0; rowa_q <= '0; kidx_q <= '0;
      out_valid_q <= 1'b0; out_df_q <= 1'b0; out_u_q <= '0; out_v_q <= '0; out_pay_q <= '0;
      steps_valid_q <= 1'b0; steps_q <= '0;
    end else if (abort_i) begin
      st_q <= StIdle;
      out_valid_q <= 1'b0;
      steps_valid_q <= 1'b0;
    end else begin
      steps_valid_q <= 1'b0;
      if (out_ready_i) out_valid_q <= 1'b0;
      // Leaving: a passed fragment or a finished DIVFREE pixel goes to the output register.
      if (fin_fire) begin
        out_valid_q <= 1'b1;
        out_df_q    <= fin_now;
        out_pay_q   <= pay_q;
        out_u_q     <= centre(jfin[0], p_bits);
        out_v_q     <= centre(jfin[1], p_bits);
        st_q        <= StIdle;
      end
      if (fin_fire && fin_now) begin
        steps_valid_q <= 1'b1;
        steps_q       <= 16'(sfin[0]) + 16'(sfin[1]);
        for (int a = 0; a < 2; a++) begin
          jprev_q[a] <= jfin[a];
          du_q[a]    <= du_n[a];
          row_q[a]   <= row_n[a];
          slope_q[a] <= slope_n[a];
          if (first_q) begin
            ja_q[a]     <= jfin[a];
            jfirst_q[a] <= jfin[a];
          end
        end
        if (first_q) begin
          x0a_q  <= x_q;
          rowa_q <= y_q;
          kidx_q <= 7'd1;
        end else if (kidx_q < 7'd65) begin
          kidx_q <= kidx_q + 7'd1;
        end
      end
      // Taking the next fragment (possibly in the clock the last one leaves).
      if (take) begin
        fine_q   <= in_fine_i;
        track_q  <= in_track_i;
        top_q    <= in_top_i;
        lg_q     <= in_lod_g_i;
        lsh_q    <= in_lod_shift_i;
        if (in_df_i && in_tfirst_i) lvl_q <= '0;
        tfirst_q <= in_tfirst_i;
        first_q  <= in_first_i;
        last_q   <= in_last_i;
        x_q      <= in_x_i;
        y_q      <= in_y_i;
        q_q      <= in_q_i;
        u_q      <= $signed(in_u_i);
        v_q      <= $signed(in_v_i);
        g_q      <= in_g_i;
        pay_q    <= in_pay_i;
        inner_q  <= in_df_i && !in_tfirst_i && !in_first_i;
        seeded_q <= 1'b0;
        k_q      <= '0;
        for (int a = 0; a < 2; a++) begin
          sc_q[a] <= '0; done_q[a] <= 1'b0; cap_q[a] <= 1'b0;
        end
        st_q <= !in_df_i ? StPass
                : (in_tfirst_i ? StSeed : (in_first_i ? (in_track_i ? StLodReq : StSpan) : StRun));
      end else begin
        unique case (st_q)
          StSpan: begin
            for (int a = 0; a < 2; a++) jw_q[a] <= jspan[a];
            st_q <= StRun;
          end
          StRun: if (!fin_now) begin
            inner_q <= 1'b0;
            for (int a = 0; a < 2; a++) begin
              jw_q[a]   <= jres[a];
              sc_q[a]   <= sres[a];
              done_q[a] <= res[a];
              cap_q[a]  <= capnow[a];
            end
            if (run_capped) begin
              k_q  <= '0;
              st_q <= StRecip;
            end
          end
          StSeed: st_q <= StRecip;
          StSeedCell: begin
            seeded_q <= 1'b1;
            for (int a = 0; a < 2; a++) jw_q[a] <= JW'((c_q[a] - CW'(1)) >>> p_bits);
            st_q <= StRun;
          end
          StLodReq: if (lod_in_ready) st_q <= StLodWait;
          StLodWait: if (lod_out_valid) begin
            lvl_q <= lvl_new;
            if (!tfirst_q && (lvl_new != lvl_q)) begin
              for (int a = 0; a < 2; a++) begin
                ja_q[a]    <= JW'(rescale(MW'(ja_q[a]), lvl_q, lvl_new));
                row_q[a]   <= rescale(row_q[a], lvl_q, lvl_new);
                slope_q[a] <= rescale(slope_q[a], lvl_q, lvl_new);
              end
            end
            st_q <= tfirst_q ? StSeedCell : StSpan;
          end
          StRecip: if (r_done) st_q <= StMul;
          StMul: begin
            if (k_q < 3'd2) c_q[k_q[0]] <= CW'(div_k);
            else d_q[2'(k_q - 3'd2)] <= div_k;
            k_q <= k_q + 3'd1;
            if (tfirst_q && !seeded_q && (k_q == 3'd5)) begin
              // The seed: its level (tracking), then the walk starts from the divided cells.
              st_q <= track_q ? StLodReq : StSeedCell;
            end else if (!(tfirst_q && !seeded_q) && (k_q == 3'd1)) begin
              st_q <= StFin;
            end
          end
          default: ;
        endcase
      end
    end
  end

  assign out_valid_o   = out_valid_q;
  assign out_df_o      = out_df_q;
  assign out_u_o       = out_u_q;
  assign out_v_o       = out_v_q;
  assign out_pay_o     = out_pay_q;
  assign steps_valid_o = steps_valid_q;
  assign steps_o       = steps_q;

  logic unused;
  assign unused = ^{r_busy, r_t, lod_busy, lod_pay};
endmodule
