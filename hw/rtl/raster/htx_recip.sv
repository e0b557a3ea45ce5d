// The shared reciprocal unit (docs/model.md §4, docs/raster.md): normalise X to a W-bit mantissa M
// (truncated), look up the DasSarma-Matula midpoint table (k index bits, g guard bits), then Steps
// Newton-Raphson steps  e = (M R) >> (W-1);  R = (R (2^(W+1) - e) + 2^(W-1)) >> W.
// Result: 1/X ~ r_o * 2^-(W + msb_o). Two multiplications per step go through one multiplier whose
// Iterative parameter sets the throughput (one product per clock, or a shift-and-add unit).
// start_i is taken while idle; done_o pulses once and r_o, msb_o hold until the next start.
// table_only_i (sampled with start_i) stops after the table (RECIP_LUT); r0_o is the table value.
// Pipelined = 1 (the per-pixel divider of `full`): no multiplier sharing, a new X every clock the
// pipeline advances (en_i), the result 2 + 2 Steps advancing clocks later with done_o set (start_i is
// the input's valid bit, table_only_i is ignored: r0_o carries the table value alongside).
// X = 0 yields msb_o = 0 and an unspecified r_o (setup never asks: a zero determinant draws nothing).
// SerialNorm (FSM form only; the `icebreaker` divider's unit) shifts X left one bit a clock until
// its top bit is set, up to XWidth - 1 clocks, instead of a priority encoder and a barrel shifter.
// NormSkip: a start with alt_i clear brings x_i already shifted left by NormSkip (the caller knows
// that many top bits of its X are zero), which the count starts from.
// ExtMul (FSM form only; the `icebreaker` divider's unit) uses the caller's multiplier.
// AltSteps (FSM form only): a start with alt_i set runs AltSteps Newton steps instead of Steps (the
// `icebreaker` divider's unit also serves setup, whose reciprocals take more steps than a pixel's).
module htx_recip #(
  parameter int unsigned XWidth    = 51,
  parameter int unsigned W         = 32,
  parameter int unsigned K         = 10,
  parameter int unsigned G         = 2,
  parameter int unsigned Steps     = 2,
  parameter bit          Iterative = 1'b0,
  parameter bit          Pipelined = 1'b0,
  parameter bit          SerialNorm = 1'b0,  // FSM form: normalise one bit per clock (no barrel shifter)
  parameter bit          ExtMul    = 1'b0,  // FSM form: the Newton products go to the mul_* port
  parameter int unsigned AltSteps  = Steps, // FSM form: Newton steps of a start with alt_i set
  parameter int unsigned NormSkip  = 0,     // SerialNorm: x_i = X 2^NormSkip when alt_i is clear
  parameter int unsigned MsbWidth  = $clog2(XWidth)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                abort_i,
  input  logic                start_i,
  input  logic                en_i,          // Pipelined: the stages advance
  input  logic                table_only_i,  // iterative: no Newton step this time
  input  logic                alt_i,         // iterative: AltSteps Newton steps this time
  input  logic [XWidth-1:0]   x_i,
  output logic                busy_o,
  output logic                done_o,
  output logic [W:0]          r_o,
  output logic [W:0]          r0_o,
  output logic [MsbWidth-1:0] msb_o,

  // ExtMul: a multiplier outside (the caller's, idle while this unit is busy) with the handshake of
  // htx_raster_mul; otherwise unused (outputs 0).
  output logic                mul_start_o,
  output logic [W+2:0]        mul_a_o, mul_b_o,   // signed
  input  logic                mul_done_i,
  input  logic [2*W+5:0]      mul_p_i,            // signed a b

  // SerialNorm: X shifts left by one this clock, so a caller can shift values of its own in step
  // (the `icebreaker` divider's numerators); else 0.
  output logic                norm_shift_o
);
  localparam int unsigned EntryW = K + G + 1;
  localparam int unsigned MulW   = W + 3;
  localparam int unsigned StepW  = 2;

  typedef enum logic [2:0] {StIdle, StNorm, StTable, StMulE, StMulR, StDone} state_e;
  localparam bit Serial = SerialNorm && !Pipelined;

  logic [MsbWidth-1:0] msb;
  logic [W-1:0]        mant;
  if (!Serial) begin : g_norm_comb
    always_comb begin
      msb = '0;
      for (int unsigned i = 0; i < XWidth; i++) begin
        if (x_i[i]) msb = MsbWidth'(i);
      end
    end

    if (XWidth >= W) begin : g_norm_wide
      logic [XWidth-1:0] shifted;
      always_comb begin
        if (32'(msb) >= W - 1) shifted = x_i >> (32'(msb) - (W - 1));
        else                   shifted = x_i << ((W - 1) - 32'(msb));
      end
      logic unused_high;
      assign mant = shifted[W-1:0];
      assign unused_high = ^shifted[XWidth-1:W];
    end else begin : g_norm_narrow
      logic [W-1:0] x_ext;
      assign x_ext = W'(x_i);
      assign mant  = x_ext << ((W - 1) - 32'(msb));
    end
  end

  if (Pipelined) begin : g_pipe
    // Stage 0 registers the normalised mantissa, stage 1 the table value, then two stages per
    // Newton step (c = 2^(W+1) - (M R >> (W-1)); then R = (R c + 2^(W-1)) >> W).
    localparam int unsigned Lat = 2 + 2 * Steps;
    logic                v_p   [Lat];
    logic [W-1:0]        m_p   [Lat];
    logic [MsbWidth-1:0] msb_p [Lat];
    logic [EntryW-1:0]   t_entry;
    logic [W:0]          r1;
    logic [(Steps+1)*(W+1)-1:0] r_chain;  // slice 0: the table value; slice t+1: after step t
    htx_recip_table #(.K(K), .G(G)) u_table (
      .clk_i, .en_i(en_i && !abort_i), .index_i(m_p[0][W-2 -: K]), .entry_o(t_entry)
    );
    assign r1 = (W + 1)'(t_entry) << (W - K - G - 1);
    assign r_chain[W:0] = r1;
    if (Lat > 2) begin : g_r0
      logic [W:0] r0_p [2:Lat-1];
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          for (int i = 2; i < Lat; i++) r0_p[i] <= '0;
        end else if (!abort_i && en_i) begin
          r0_p[2] <= r1;
          for (int i = 3; i < Lat; i++) r0_p[i] <= r0_p[i-1];
        end
      end
      assign r0_o = r0_p[Lat-1];
    end else begin : g_r0_now
      assign r0_o = r1;
    end

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        for (int i = 0; i < Lat; i++) begin
          v_p[i] <= 1'b0; m_p[i] <= '0; msb_p[i] <= '0;
        end
      end else if (abort_i) begin
        for (int i = 0; i < Lat; i++) v_p[i] <= 1'b0;
      end else if (en_i) begin
        v_p[0]   <= start_i;
        m_p[0]   <= mant;
        msb_p[0] <= msb;
        for (int i = 1; i < Lat; i++) begin
          v_p[i]   <= v_p[i-1];
          m_p[i]   <= m_p[i-1];
          msb_p[i] <= msb_p[i-1];
        end
      end
    end

    for (genvar t = 0; t < Steps; t++) begin : g_step
      localparam int unsigned SE = 2 + 2 * t;  // stage holding c
      logic [W+1:0]   c_q;
      logic [W:0]     rm_q, ro_q, r_in;
      logic [2*W:0]   pe;
      logic [W+1:0]   ee;
      logic [2*W+2:0] pr;
      assign r_in = r_chain[t*(W+1) +: W+1];
      assign pe = (2*W+1)'(m_p[SE-1]) * (2*W+1)'(r_in);
      assign ee = (W + 2)'(pe >> (W - 1));
      assign pr = (2*W+3)'(rm_q) * (2*W+3)'(c_q);
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          c_q  <= '0;
          rm_q <= '0;
          ro_q <= '0;
        end else if (en_i) begin
          c_q  <= ee[W+1] ? '0 : ((W + 2)'(1) << (W + 1)) - ee;
          rm_q <= r_in;
          ro_q <= (W + 1)'((pr + ((2*W+3)'(1) << (W - 1))) >> W);
        end
      end
      assign r_chain[(t+1)*(W+1) +: W+1] = ro_q;
      logic unused_p;
      assign unused_p = ^{pe[2*W:2*W], pr[2*W+2:2*W+1]};
    end

    assign busy_o = 1'b0;
    assign done_o = v_p[Lat-1];
    assign r_o    = r_chain[Steps*(W+1) +: W+1];
    assign msb_o  = msb_p[Lat-1];
    logic unused_pipe;
    assign unused_pipe = ^{table_only_i, alt_i, m_p[Lat-1], mul_done_i, mul_p_i};
    assign mul_start_o = 1'b0;
    assign mul_a_o     = '0;
    assign mul_b_o     = '0;
    assign norm_shift_o = 1'b0;
  end else begin : g_fsm
  state_e              state_q;
  logic [StepW-1:0]    step_q;
  logic [W-1:0]        m_q;
  logic [W:0]          r_q;
  logic [W+1:0]        c_q;
  logic [MsbWidth-1:0] msb_q;
  logic [EntryW-1:0]   entry_q;
  logic                mul_start, mul_done;
  logic signed [MulW-1:0]   mul_a, mul_b;
  logic signed [2*MulW-1:0] mul_p;
  logic [2*MulW-1:0]   prod;
  logic [W+1:0]        e;

  logic                only_q, alt_q;
  logic                last_step, no_steps;
  logic                norm_done;  // mant and msb hold x_i's normalised form (StNorm)
  if (Serial) begin : g_norm_serial
    localparam int unsigned NW = (XWidth > W) ? XWidth : W;
    localparam int unsigned CW = $clog2(NW);
    logic [NW-1:0] nx_q;
    logic [CW-1:0] ncnt_q;  // shifts so far
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        nx_q   <= '0;
        ncnt_q <= '0;
      end else if ((state_q == StIdle) && start_i) begin
        nx_q   <= NW'(x_i);
        ncnt_q <= alt_i ? '0 : CW'(NormSkip);
      end else if ((state_q == StNorm) && !norm_done) begin
        nx_q   <= nx_q << 1;
        ncnt_q <= ncnt_q + 1'b1;
      end
    end
    // X = 0 stops after NW - 1 shifts with msb 0 and a zero mantissa, as the combinational form.
    assign norm_done = nx_q[NW-1] || (ncnt_q == CW'(NW - 1));
    assign mant      = nx_q[NW-1 -: W];
    assign msb       = MsbWidth'(CW'(NW - 1) - ncnt_q);
    assign norm_shift_o = (state_q == StNorm) && !norm_done;
    if (NW > W) begin : g_low
      logic unused_low;
      assign unused_low = ^nx_q[NW-W-1:0];
    end
  end else begin : g_norm_at_start
    assign norm_done    = 1'b1;
    assign norm_shift_o = 1'b0;
  end
  assign last_step = alt_q ? (32'(step_q) + 1 == AltSteps) : (32'(step_q) + 1 == Steps);
  assign no_steps  = only_q || (alt_q ? (AltSteps == 0) : (Steps == 0));
  assign mul_start = (state_q == StMulE) || (state_q == StMulR);
  // e = m r, then r c: r is the b operand of both, so b has one source (the divider's shared
  // multiplier takes b whole and a in digits; its other b is a reciprocal too).
  assign mul_a = (state_q == StMulE) ? MulW'(m_q) : MulW'(c_q);
  assign mul_b = MulW'(r_q);

  if (ExtMul) begin : g_ext_mul
    assign mul_start_o = mul_start;
    assign mul_a_o     = mul_a;
    assign mul_b_o     = mul_b;
    assign mul_done    = mul_done_i;
    assign mul_p       = mul_p_i;
  end else begin : g_own_mul
    htx_raster_mul #(.AWidth(MulW), .BWidth(MulW), .Iterative(Iterative), .ExtraW(1)) u_mul (
      .clk_i, .rst_ni, .abort_i,
      .start_i(mul_start),
      .a_i    (mul_a),
      .b_i    (mul_b),
      .neg_i  (1'b0),
      .extra_i(1'b0),
      .done_o (mul_done),
      .p_o    (mul_p)
    );
    assign mul_start_o = 1'b0;
    assign mul_a_o     = '0;
    assign mul_b_o     = '0;
    logic unused_ext;
    assign unused_ext = ^{mul_done_i, mul_p_i};
  end
  assign prod = mul_p;
  assign e    = (W + 2)'(prod >> (W - 1));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      step_q  <= '0;
      m_q     <= '0;
      r_q     <= '0;
      c_q     <= '0;
      msb_q   <= '0;
      only_q  <= 1'b0;
      alt_q   <= 1'b0;
    end else if (abort_i) begin
      state_q <= StIdle;
    end else begin
      unique case (state_q)
        StIdle: if (start_i) begin
          only_q  <= table_only_i;
          alt_q   <= alt_i;
          step_q  <= '0;
          if (Serial) begin
            state_q <= StNorm;
          end else begin
            m_q     <= mant;
            msb_q   <= msb;
            state_q <= StTable;
          end
        end
        StNorm: if (norm_done) begin
          m_q     <= mant;
          msb_q   <= msb;
          state_q <= StTable;
        end
        StTable: begin
          r_q     <= (W + 1)'(entry_q) << (W - K - G - 1);
          state_q <= no_steps ? StDone : StMulE;
        end
        StMulE: if (mul_done) begin
          // e < 2^(W+1) always (M < 2^W, R <= 2^W); the guard keeps 2 - m r non-negative anyway.
          c_q     <= (e[W+1]) ? '0 : ((W + 2)'(1) << (W + 1)) - e;
          state_q <= StMulR;
        end
        StMulR: if (mul_done) begin
          r_q     <= (W + 1)'((prod + ((2*MulW)'(1) << (W - 1))) >> W);
          step_q  <= step_q + 1'b1;
          state_q <= last_step ? StDone : StMulE;
        end
        StDone: state_q <= StIdle;
        default: state_q <= StIdle;
      endcase
    end
  end

  // The table read is registered (htx_recip_table: one block RAM).
  htx_recip_table #(.K(K), .G(G)) u_table (
    .clk_i,
    .en_i   (!abort_i && (Serial ? ((state_q == StNorm) && norm_done)
                                     : ((state_q == StIdle) && start_i))),
    .index_i(mant[W-2 -: K]),
    .entry_o(entry_q)
  );

  assign busy_o = (state_q != StIdle);
  assign done_o = (state_q == StDone);
  assign r_o    = r_q;
  assign r0_o   = (W + 1)'(entry_q) << (W - K - G - 1);
  assign msb_o  = msb_q;
  logic unused_en;
  assign unused_en = en_i;
  end
endmodule
