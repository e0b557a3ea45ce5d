// The per-pixel divider (docs/model.md §5.2) on the shared reciprocal unit htx_recip: Q (raised to
// 1 when below) is normalised to M 2^s, s = msb - (W - 1); each numerator is shifted by the same s,
// N' = round(N 2^-s) (or N << -s); one reciprocal R of M serves every numerator:
//   u = round(U' R 2^(TF - 2W + 1)), v likewise (R from the table only for RECIP_LUT),
//   c = clamp(round(C' R 2^(-2W + 1)), 0, 255) per colour channel (Color: perspective-correct
//   Gouraud colour, C = c q plane, always with the Newton steps).
// Pipelined = 1: a new fragment every clock, 4 + 2 Steps clocks of latency, one stall for all
// stages. Pipelined = 0: one fragment at a time through an iterative htx_recip, whose serial
// normaliser also shifts the numerators (no barrel shifter), and one multiplier (MulIterative:
// shift-and-add); fragments whose need_i is clear pass in one clock. A payload
// travels with each fragment; order is kept.
module htx_raster_divider #(
  parameter int unsigned AccQ         = 58,
  parameter int unsigned AccU         = 74,
  parameter int unsigned AccC         = 66,
  parameter int unsigned UvIntBits    = 16,
  parameter int unsigned W            = 32,
  parameter int unsigned K            = 10,
  parameter int unsigned G            = 2,
  parameter int unsigned Steps        = 2,
  parameter int unsigned TF           = 16,
  parameter int unsigned LocW         = 32,
  parameter int unsigned PayW         = 8,
  parameter bit          Pipelined    = 1'b1,
  parameter bit          Color        = 1'b1,
  parameter bit          MulIterative = 1'b0,
  parameter bit          MulDigits    = 1'b0    // Pipelined = 0: the multiplier digit-serial (2 DSPs)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                abort_i,

  input  logic                in_valid_i,
  output logic                in_ready_o,
  input  logic                in_need_i,    // Pipelined = 0: divide (else the results are unused)
  input  logic                in_lut_i,     // u, v from the table value only (RECIP_LUT)
  input  logic [AccQ-1:0]     in_q_i,
  input  logic [AccU-1:0]     in_u_i, in_v_i,
  input  logic [3*AccC-1:0]   in_c_i,
  input  logic [PayW-1:0]     in_pay_i,

  output logic                out_valid_o,
  input  logic                out_ready_i,
  output logic [LocW-1:0]     out_u_o, out_v_o,
  output logic [23:0]         out_rgb_o,
  output logic [PayW-1:0]     out_pay_o
);
  localparam int unsigned MsbW = $clog2(AccQ);
  localparam int unsigned NIN  = (AccU > AccC) ? AccU : AccC;   // numerator input width
  localparam int unsigned WSH  = NIN + W;                       // after a left shift by < W
  localparam int unsigned NSU  = UvIntBits + W + 2;             // |U'| < |u| 2^W
  localparam int unsigned NSC  = 8 + W + 3;                     // |C'| < 256 2^W
  localparam int unsigned RSU  = 2 * W - 1 - TF;
  localparam int unsigned RSC  = 2 * W - 1;
  localparam int unsigned NN   = Color ? 5 : 2;

  // N 2^-s rounded (s > 0) or N 2^-s exactly (s <= 0), s = msb - (W - 1), as one right shift of
  // (N + rounding) 2^(W-1) by msb: exact for msb <= W - 1, where the rounding term is 0 (one
  // shifter instead of a left and a right one and a multiplexer).
  function automatic logic signed [WSH-1:0] shift_num(input logic signed [NIN-1:0] num,
                                                      input logic [MsbW-1:0] msb);
    logic signed [WSH-1:0]     nr;
    logic signed [WSH+W-2:0]   x;
    nr = WSH'(num);
    if (32'(msb) >= W) nr = nr + $signed(WSH'(1) << (32'(msb) - W));
    x = {nr, {(W - 1){1'b0}}};
    shift_num = WSH'(x >>> msb);
  endfunction

  // round(N' R 2^-rs) for the u, v numerators (LocW bits kept) and the colour channels (clamped).
  function automatic logic [LocW-1:0] coord(input logic signed [NSU-1:0] n, input logic [W:0] r);
    logic signed [NSU+W+1:0] p;
    p = (NSU+W+2)'(n) * $signed({1'b0, r});
    coord = LocW'((p + $signed((NSU+W+2)'(1) << (RSU - 1))) >>> RSU);
  endfunction
  function automatic logic [7:0] channel(input logic signed [NSC-1:0] n, input logic [W:0] r);
    logic signed [NSC+W+1:0] p, q;
    p = (NSC+W+2)'(n) * $signed({1'b0, r});
    q = (p + $signed((NSC+W+2)'(1) << (RSC - 1))) >>> RSC;
    channel = q[NSC+W+1] ? 8'd0 : ((q > (NSC+W+2)'(255)) ? 8'd255 : 8'(q));
  endfunction

  logic [AccQ-1:0] q_eff;
  // Q < 1 (signed) as its sign or zero, not a comparison (a carry chain in Yosys 0.23).
  assign q_eff = (in_q_i[AccQ-1] || (in_q_i == '0)) ? AccQ'(1) : in_q_i;

  logic [NIN-1:0] nin [NN];
  assign nin[0] = NIN'($signed(in_u_i));
  assign nin[1] = NIN'($signed(in_v_i));
  if (Color) begin : g_cin
    for (genvar c = 0; c < 3; c++) begin : g_c
      assign nin[2+c] = NIN'($signed(in_c_i[AccC*c +: AccC]));
    end
  end else begin : g_nocin
    logic unused_c;
    assign unused_c = ^in_c_i;
  end

  if (Pipelined) begin : g_pipe
    localparam int unsigned Lat = 2 + 2 * Steps;  // htx_recip's
    logic                en;
    logic                va_q, lut_a_q;
    logic [AccQ-1:0]     qa_q;
    logic [NIN-1:0]      na_q [NN];
    logic [PayW-1:0]     pa_q;
    // Delay line beside the reciprocal pipeline.
    logic                dl_lut [Lat];
    logic [NIN-1:0]      dl_n   [Lat][NN];
    logic [PayW-1:0]     dl_pay [Lat];
    logic                r_done;
    logic [W:0]          r_nr, r_t;
    logic [MsbW-1:0]     r_msb;
    logic                out_valid_q, r_busy;
    logic [LocW-1:0]     u_q, v_q;
    logic [23:0]         rgb_q;
    logic [PayW-1:0]     pay_q;

    assign en = !out_valid_q || out_ready_i;
    assign in_ready_o = en;

    logic         r_mul_start;  // (the pipelined unit has its own products)
    logic [W+2:0] r_mul_a, r_mul_b;
    logic         r_norm_shift;  // (no serial normaliser)
    htx_recip #(.XWidth(AccQ), .W(W), .K(K), .G(G), .Steps(Steps), .Pipelined(1'b1)) u_recip (
      .clk_i, .rst_ni, .abort_i,
      .start_i(va_q), .en_i(en), .table_only_i(1'b0), .alt_i(1'b0), .x_i(qa_q),
      .busy_o(r_busy), .done_o(r_done), .r_o(r_nr), .r0_o(r_t), .msb_o(r_msb),
      .mul_start_o(r_mul_start), .mul_a_o(r_mul_a), .mul_b_o(r_mul_b), .mul_done_i(1'b0), .mul_p_i('0),
      .norm_shift_o(r_norm_shift)
    );
    logic unused_r_mul;
    assign unused_r_mul = ^{r_mul_start, r_mul_a, r_mul_b, r_norm_shift};

    logic [WSH-1:0] sh [NN];
    logic unused_sh;
    always_comb begin
      unused_sh = r_busy;
      for (int i = 0; i < NN; i++) unused_sh = unused_sh ^ (^sh[i]);
    end
    for (genvar i = 0; i < NN; i++) begin : g_sh
      assign sh[i] = shift_num(dl_n[Lat-1][i], r_msb);
    end

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        va_q <= 1'b0; lut_a_q <= 1'b0; qa_q <= '0; pa_q <= '0;
        for (int i = 0; i < NN; i++) na_q[i] <= '0;
        for (int s = 0; s < Lat; s++) begin
          dl_lut[s] <= 1'b0; dl_pay[s] <= '0;
          for (int i = 0; i < NN; i++) dl_n[s][i] <= '0;
        end
        out_valid_q <= 1'b0; u_q <= '0; v_q <= '0; rgb_q <= '0; pay_q <= '0;
      end else if (abort_i) begin
        va_q <= 1'b0;
        out_valid_q <= 1'b0;
      end else if (en) begin
        va_q    <= in_valid_i;
        lut_a_q <= in_lut_i;
        qa_q    <= q_eff;
        pa_q    <= in_pay_i;
        for (int i = 0; i < NN; i++) na_q[i] <= nin[i];
        dl_lut[0] <= lut_a_q;
        dl_pay[0] <= pa_q;
        for (int i = 0; i < NN; i++) dl_n[0][i] <= na_q[i];
        for (int s = 1; s < Lat; s++) begin
          dl_lut[s] <= dl_lut[s-1];
          dl_pay[s] <= dl_pay[s-1];
          for (int i = 0; i < NN; i++) dl_n[s][i] <= dl_n[s-1][i];
        end
        out_valid_q <= r_done;
        u_q   <= coord(NSU'(sh[0]), dl_lut[Lat-1] ? r_t : r_nr);
        v_q   <= coord(NSU'(sh[1]), dl_lut[Lat-1] ? r_t : r_nr);
        pay_q <= dl_pay[Lat-1];
        if (Color) begin
          for (int c = 0; c < 3; c++) rgb_q[8*c +: 8] <= channel(NSC'(sh[(2+c) % NN]), r_nr);
        end
      end
    end
    assign out_valid_o = out_valid_q;
    assign out_u_o     = u_q;
    assign out_v_o     = v_q;
    assign out_rgb_o   = rgb_q;
    assign out_pay_o   = pay_q;
    logic unused_p;
    assign unused_p = in_need_i;
  end else begin : g_iter
    typedef enum logic [1:0] {StIdle, StRecip, StMul, StOut} state_e;
    state_e              state_q;
    logic                lut_q, take;
    logic [PayW-1:0]     pay_q;
    logic [2:0]          k_q;
    logic                r_start, r_done, r_busy;
    logic [W:0]          r_nr, r_t, r_sel;
    logic [MsbW-1:0]     r_msb;
    logic [LocW-1:0]     u_q, v_q;
    logic [23:0]         rgb_q;

    assign in_ready_o = (state_q == StIdle) || ((state_q == StOut) && out_ready_i);
    assign take       = in_valid_i && in_ready_o;
    // The reciprocal starts as the fragment is taken (it is idle then: the last one finished before
    // the products).
    assign r_start    = take && in_need_i;

    // The reciprocal's Newton products go through the numerators' multiplier (ExtMul): the two
    // never work at once (the numerators wait for the reciprocal), so one multiplier serves both.
    logic                   r_mul_start, r_mul_done;
    logic signed [W+2:0]    r_mul_a, r_mul_b;
    logic signed [2*W+5:0]  r_mul_p;
    logic                   r_shift;
    htx_recip #(.XWidth(AccQ), .W(W), .K(K), .G(G), .Steps(Steps), .Iterative(MulIterative),
                .Pipelined(1'b0), .SerialNorm(1'b1), .ExtMul(1'b1)) u_recip (
      .clk_i, .rst_ni, .abort_i,
      .start_i(r_start), .en_i(1'b1), .table_only_i(in_lut_i && !Color),
      .alt_i(1'b0), .x_i(q_eff),
      .busy_o(r_busy), .done_o(r_done), .r_o(r_nr), .r0_o(r_t), .msb_o(r_msb),
      .mul_start_o(r_mul_start), .mul_a_o(r_mul_a), .mul_b_o(r_mul_b), .mul_done_i(r_mul_done),
      .mul_p_i(r_mul_p), .norm_shift_o(r_shift)
    );

    // One multiplier for the numerators in turn: u, v, then the colour channels.
    logic                   m_start, m_done;
    localparam int unsigned MA = Color ? ((NSU > NSC) ? NSU : NSC) : NSU;
    // The numerators shift in step with the unit's serial normaliser instead of through a barrel
    // shifter keyed to msb. Q shifts left c times in all, so msb = AccQ - 1 - c and
    // s = msb - (W - 1) = NL - c with NL = AccQ - W. Register i holds N_i 2^c (its low NL + MA
    // bits, which is all the MA-bit result depends on): N 2^-s is its bits from NL up, and for
    // s > 0 round(N 2^-s) = (floor(N 2^(1-s)) + 1) >> 1 adds its bit NL - 1 to them. (The model's
    // divide_fixed, bit for bit; NL >= 1 as AccQ > W.)
    localparam int unsigned NL = AccQ - W;
    localparam int unsigned NRW = NL + MA;
    logic [NRW-1:0]         nr_q [NN];
    logic [NRW-1:0]         nr_sel;
    logic [MA-1:0]          shn;
    localparam int unsigned SA = (MA > W + 3) ? MA : W + 3;  // the shared multiplier's operands
    localparam int unsigned SB = W + 3;
    logic signed [MA-1:0]   m_a;  // wide enough for both numerator kinds
    logic signed [W+1:0]    m_b;
    logic signed [MA+W+1:0] m_p;
    logic signed [SA-1:0]   s_a;
    logic signed [SB-1:0]   s_b;
    logic signed [SA+SB-1:0] s_p;
    logic                   s_done;
    logic [2:0]             kmax;
    assign kmax  = 3'(NN - 1);
    always_comb begin
      nr_sel = nr_q[0];
      for (int i = 1; i < NN; i++) if (32'(k_q) == i) nr_sel = nr_q[i];
    end
    assign shn   = nr_sel[NL +: MA] + MA'((32'(r_msb) >= W) && nr_sel[NL-1]);
    assign r_sel = (k_q < 3'd2 && lut_q) ? r_t : r_nr;
    assign m_a   = (k_q < 3'd2) ? MA'($signed(NSU'(shn))) : MA'($signed(NSC'(shn)));
    assign m_b   = $signed({1'b0, r_sel});
    assign m_start = (state_q == StMul);
    assign s_a = r_mul_start ? SA'(r_mul_a) : SA'(m_a);
    assign s_b = r_mul_start ? SB'(r_mul_b) : SB'(m_b);
    // MulDigits: a in three 15-bit digits, b whole (27 bits: 2 DSPs), 3 clocks a product.
    htx_raster_mul #(.AWidth(SA), .BWidth(SB), .Iterative(MulIterative), .DigitSerial(MulDigits),
                     .DigitSplitB(1'b0), .ExtraW(1)) u_mul (
      .clk_i, .rst_ni, .abort_i, .start_i(m_start || r_mul_start), .a_i(s_a), .b_i(s_b),
      .neg_i(1'b0), .extra_i(1'b0), .done_o(s_done), .p_o(s_p)
    );
    // Both products fit their own widths, so the low bits of the wider product are exact.
    assign m_p        = (MA+W+2)'(s_p);
    assign m_done     = s_done && m_start;
    assign r_mul_p    = (2*W+6)'(s_p);
    assign r_mul_done = s_done && r_mul_start;
    logic unused_s;
    assign unused_s = ^{s_p, r_busy};  // (the reciprocal is idle whenever a fragment is taken)
    logic signed [MA+W+1:0] m_ru, m_rc;
    assign m_ru = (m_p + $signed((MA+W+2)'(1) << (RSU - 1))) >>> RSU;
    assign m_rc = (m_p + $signed((MA+W+2)'(1) << (RSC - 1))) >>> RSC;
    logic unused_m;
    assign unused_m = ^{shn, m_ru};

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        state_q <= StIdle; lut_q <= 1'b0; pay_q <= '0; k_q <= '0;
        for (int i = 0; i < NN; i++) nr_q[i] <= '0;
        u_q <= '0; v_q <= '0; rgb_q <= '0;
      end else if (abort_i) begin
        state_q <= StIdle;
      end else begin
        if (take) begin
          lut_q <= in_lut_i;
          pay_q <= in_pay_i;
          k_q   <= '0;
          for (int i = 0; i < NN; i++) nr_q[i] <= NRW'($signed(nin[i]));
          state_q <= in_need_i ? StRecip : StOut;
        end else begin
          if (r_shift) begin
            for (int i = 0; i < NN; i++) nr_q[i] <= nr_q[i] << 1;
          end
          unique case (state_q)
            StRecip: if (r_done) state_q <= StMul;
            StMul: if (m_done) begin
              if (k_q == 3'd0) u_q <= LocW'(m_ru);
              else if (k_q == 3'd1) v_q <= LocW'(m_ru);
              else rgb_q[8*(k_q-3'd2) +: 8] <= m_rc[MA+W+1] ? 8'd0
                                              : ((m_rc > (MA+W+2)'(255)) ? 8'd255 : 8'(m_rc));
              k_q <= k_q + 3'd1;
              if (k_q == kmax) state_q <= StOut;
            end
            StOut: if (out_ready_i) state_q <= StIdle;
            default: state_q <= StIdle;
          endcase
        end
      end
    end
    assign out_valid_o = (state_q == StOut);
    assign out_u_o     = u_q;
    assign out_v_o     = v_q;
    assign out_rgb_o   = rgb_q;
    assign out_pay_o   = pay_q;
  end
endmodule
