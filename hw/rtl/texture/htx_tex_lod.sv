// LOD unit (docs/model.md §6, model compute_lod): from the six block-floating-point plane gradients
// (uq, vq, q along x and y, shifted right by grad_shift), the Q plane value and the local texel
// coordinates u, v (TF fraction bits) of a pixel:
//   n_ux = g_ux 2^TF - u g_qx (likewise n_vx, n_uy, n_vy), all shifted right by
//   s = max(0, msb(max |n|) - 30), len = max(n_ux^2 + n_vx^2, n_uy^2 + n_vy^2),
//   l = (log2(len) >> 1) + (s + grad_shift + 8 - TF) 2^F - log2(Q), lod = round(l >> 2),
// with F = LF + 2 fraction bits in the log2 unit. zero_o: all four numerators are 0 (the model's
// INT32_MIN, which the sampler takes as LOD 0). Three stages; all advance together when the output
// is free (in_ready_o), carrying an opaque payload. q_i = 0 is taken as 1.
module htx_tex_lod #(
  parameter int unsigned QW      = 58,
  parameter int unsigned GradW   = 24,
  parameter int unsigned LocW    = 32,
  parameter int unsigned TF      = 16,
  parameter int unsigned LF      = 8,
  parameter int unsigned IdxBits = 10,
  parameter int unsigned PW      = 8,    // payload bits
  parameter int unsigned LodW    = 24    // signed LOD output width
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   in_valid_i,
  output logic                   in_ready_o,
  input  logic [QW-1:0]          q_i,
  input  logic [GradW-1:0]       gux_i, guy_i, gvx_i, gvy_i, gqx_i, gqy_i,
  input  logic [7:0]             grad_shift_i,
  input  logic [LocW-1:0]        u_i, v_i,
  input  logic [PW-1:0]          payload_i,
  output logic                   out_valid_o,
  input  logic                   out_ready_i,
  output logic signed [LodW-1:0] lod_o,
  output logic                   zero_o,
  output logic [PW-1:0]          payload_o,
  output logic                   busy_o
);
  localparam int unsigned F   = LF + 2;
  localparam int unsigned PRW = LocW + GradW;
  localparam int unsigned NW  = ((GradW + TF > PRW) ? GradW + TF : PRW) + 1;
  localparam int unsigned LW  = 20;  // log2 outputs: up to 127 2^F < 2^(7+F+1)

  logic en;
  assign en = !out_valid_o || out_ready_i;
  assign in_ready_o = en;

  // ---- Stage 1: numerators ---------------------------------------------------------------------
  function automatic logic signed [NW-1:0] numer(input logic [GradW-1:0] g, input logic [LocW-1:0] c,
                                                 input logic [GradW-1:0] gq);
    logic signed [PRW-1:0] prod;
    prod  = PRW'($signed(c)) * PRW'($signed(gq));
    numer = (NW'($signed(g)) <<< TF) - NW'(prod);
  endfunction

  logic                 v1_q;
  logic signed [NW-1:0] n_q [4];  // ux, vx, uy, vy
  logic [QW-1:0]        q1_q;
  logic [7:0]           sh1_q;
  logic [PW-1:0]        p1_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v1_q <= 1'b0;
    end else if (en) begin
      v1_q <= in_valid_i;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && in_valid_i) begin
      n_q[0] <= numer(gux_i, u_i, gqx_i);
      n_q[1] <= numer(gvx_i, v_i, gqx_i);
      n_q[2] <= numer(guy_i, u_i, gqy_i);
      n_q[3] <= numer(gvy_i, v_i, gqy_i);
      q1_q   <= (q_i == '0) ? QW'(1) : q_i;
      sh1_q  <= grad_shift_i;
      p1_q   <= payload_i;
    end
  end

  // ---- Stage 2: normalise and square -----------------------------------------------------------
  logic [NW-1:0] mag [4];
  logic [NW-1:0] big;
  logic [6:0]    pbig;
  logic [6:0]    s2;
  logic [63:0]   sq [4];
  logic signed [NW-1:0] rn [4];
  logic signed [31:0]   r32 [4];
  always_comb begin
    big = '0;
    for (int k = 0; k < 4; k++) begin
      mag[k] = n_q[k][NW-1] ? NW'(-n_q[k]) : NW'(n_q[k]);
      if (mag[k] > big) big = mag[k];
    end
    pbig = '0;
    for (int k = 0; k < NW; k++) begin
      if (big[k]) pbig = 7'(k);
    end
    s2 = (pbig > 7'd30) ? pbig - 7'd30 : 7'd0;
    for (int k = 0; k < 4; k++) begin
      rn[k]  = n_q[k] >>> s2;
      r32[k] = 32'(rn[k]);
      sq[k]  = 64'(r32[k]) * 64'(r32[k]);
    end
  end

  logic          v2_q, zero2_q;
  logic [63:0]   lx_q, ly_q;
  logic [6:0]    s2_q;
  logic [QW-1:0] q2_q;
  logic [7:0]    sh2_q;
  logic [PW-1:0] p2_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v2_q <= 1'b0;
    end else if (en) begin
      v2_q <= v1_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && v1_q) begin
      lx_q    <= sq[0] + sq[1];
      ly_q    <= sq[2] + sq[3];
      zero2_q <= (big == '0);
      s2_q    <= s2;
      q2_q    <= q1_q;
      sh2_q   <= sh1_q;
      p2_q    <= p1_q;
    end
  end

  // ---- Stage 3: logarithms ---------------------------------------------------------------------
  logic [63:0]  len2;
  logic [LW-1:0] lg_len, lg_q;
  assign len2 = (lx_q > ly_q) ? lx_q : ly_q;
  htx_tex_log2 #(.InW(64), .IdxBits(IdxBits), .F(F), .OutW(LW)) u_log_len (.x_i(len2), .log2_o(lg_len));
  htx_tex_log2 #(.InW(QW), .IdxBits(IdxBits), .F(F), .OutW(LW)) u_log_q (.x_i(q2_q), .log2_o(lg_q));

  logic signed [LodW+1:0] l, r3;
  assign l  = (LodW+2)'(lg_len[LW-1:1]) + (((LodW+2)'(s2_q) + (LodW+2)'(sh2_q) + (LodW+2)'(8)) <<< F)
            - ((LodW+2)'(TF) <<< F) - (LodW+2)'(lg_q);
  assign r3 = (l + (LodW+2)'(2)) >>> 2;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_valid_o <= 1'b0;
    end else if (en) begin
      out_valid_o <= v2_q;
    end
  end
  always_ff @(posedge clk_i) begin
    if (en && v2_q) begin
      lod_o     <= LodW'(r3);
      zero_o    <= zero2_q;
      payload_o <= p2_q;
    end
  end
  assign busy_o = v1_q || v2_q || out_valid_o;

  logic unused;
  assign unused = ^{r3, lg_len[0]};
endmodule
