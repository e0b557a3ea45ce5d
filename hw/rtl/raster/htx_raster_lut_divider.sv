// The per-pixel divider when RECIP_LUT is the only perspective method that divides (the board's
// `icebreaker` GPU: AFFINE and RECIP_LUT): no Newton step, no perspective-correct colour, no
// second client. The model's divide_fixed with the table value alone (docs/model.md §5.2), bit
// for bit:
//   Q (raised to 1 when below) = M 2^s with M's top bit at W - 1, s = msb - (W - 1);
//   N' = round(N 2^-s) (s > 0) or N 2^-s; u = round(N' R 2^(TF - 2W + 1)), R = e 2^(W - K - G - 1)
// for the table entry e, i.e. u = floor((N' e + 2^(Sh - 1)) / 2^Sh) with Sh = W + K + G - TF.
// One fragment at a time: Q shifts left a bit a clock until its top bit is set (no priority
// encoder, no barrel shifter), the two numerators shift with it; then the table; then each
// numerator's product N' e in three digits of N' on one DSP (digits of Sh / 2, Sh / 2 and the
// rest, low first; 6 clocks and one to hand over), accumulated with the rounding term and the
// carry of N''s own rounding (N' = T + rb: rb e is added, not rb to T, so no incrementer).
// Fragments whose need_i is clear pass in one clock and leave out_u_o, out_v_o as they were. A
// payload travels with each fragment. docs/raster.md, "The board's divider".
module htx_raster_lut_divider #(
  parameter int unsigned AccQ      = 42,
  parameter int unsigned AccU      = 55,
  parameter int unsigned UvIntBits = 13,
  parameter int unsigned W         = 24,
  parameter int unsigned K         = 8,
  parameter int unsigned G         = 2,
  parameter int unsigned TF        = 10,
  parameter int unsigned LocW      = 32,
  parameter int unsigned PayW      = 8
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                abort_i,

  input  logic                in_valid_i,
  output logic                in_ready_o,
  input  logic                in_need_i,
  input  logic [AccQ-1:0]     in_q_i,
  input  logic [AccU-1:0]     in_u_i, in_v_i,
  input  logic [PayW-1:0]     in_pay_i,

  output logic                out_valid_o,
  input  logic                out_ready_i,
  output logic [LocW-1:0]     out_u_o, out_v_o,
  output logic [PayW-1:0]     out_pay_o
);
  localparam int unsigned EntryW = K + G + 1;
  localparam int unsigned Sh     = W + K + G - TF;      // u = (N' e + 2^(Sh-1)) >> Sh
  localparam int unsigned D0     = Sh / 2;              // the low digits' width
  localparam int unsigned D1     = Sh - D0;
  localparam int unsigned MA     = UvIntBits + W + 2;   // |N'| < 2^(MA-1)
  localparam int unsigned D2     = MA - Sh;             // the top digit, signed
  // The numerators shift in step with Q: register i holds N_i 2^c after c shifts (its low NL + MA
  // bits, all the MA-bit N' depends on); msb = AccQ - 1 - c, so s = NL - c, N' is its bits from NL
  // up plus, for s > 0 (c < NL), its bit NL - 1 (round(N 2^-s) = (floor(N 2^(1-s)) + 1) >> 1).
  localparam int unsigned NL     = AccQ - W;
  localparam int unsigned NRW    = NL + MA;
  localparam int unsigned CW     = $clog2(AccQ);
  localparam int unsigned AccW   = MA + EntryW - Sh + 2;  // |u| < 2^(MA + EntryW - Sh) with room
  localparam int unsigned DigW   = (D2 > D1) ? D2 + 1 : D1 + 1;  // a digit as a signed number

  typedef enum logic [1:0] {StIdle, StNorm, StMul, StOut} state_e;
  state_e               state_q;
  logic [AccQ-1:0]      nx_q;
  logic [CW-1:0]        c_q;
  logic                 pos_q;      // s > 0: N' rounds
  logic [NRW-1:0]       nu_q, nv_q;
  logic [2:0]           k_q;        // StMul: digit k % 3 of numerator k / 3; 6: v's product done
  logic [PayW-1:0]      pay_q;
  logic [LocW-1:0]      u_q, v_q;
  logic [EntryW-1:0]    entry;
  logic signed [AccW-1:0] acc_q;
  logic                 take, norm_done;

  assign in_ready_o  = (state_q == StIdle) || ((state_q == StOut) && out_ready_i);
  assign take        = in_valid_i && in_ready_o;
  // Q >= 1, so its top bit is set after at most AccQ - 1 shifts.
  assign norm_done   = nx_q[AccQ-1];

  logic [AccQ-1:0] q_eff;
  // Q < 1 (signed) as its sign or zero, not a comparison (a carry chain in Yosys 0.23).
  assign q_eff = (in_q_i[AccQ-1] || (in_q_i == '0)) ? AccQ'(1) : in_q_i;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      nx_q <= '0; c_q <= '0; pos_q <= 1'b0; nu_q <= '0; nv_q <= '0; k_q <= '0; pay_q <= '0;
      u_q <= '0; v_q <= '0;
    end else if (abort_i) begin
      state_q <= StIdle;
    end else if (take) begin
      pay_q   <= in_pay_i;
      nx_q    <= q_eff;
      c_q     <= '0;
      nu_q    <= NRW'($signed(in_u_i));
      nv_q    <= NRW'($signed(in_v_i));
      k_q     <= '0;
      state_q <= in_need_i ? StNorm : StOut;
    end else begin
      unique case (state_q)
        StNorm: begin
          if (norm_done) begin
            pos_q   <= (c_q < CW'(NL));  // s = NL - c > 0
            state_q <= StMul;  // the table's entry is read as this clock ends
          end else begin
            nx_q <= nx_q << 1;
            nu_q <= nu_q << 1;
            nv_q <= nv_q << 1;
            c_q  <= c_q + 1'b1;
          end
        end
        StMul: begin
          // acc_q holds u's product in the clock after its last digit, v's in the last clock.
          if (k_q == 3'd3) u_q <= LocW'(acc_q);
          if (k_q == 3'd6) begin
            v_q     <= LocW'(acc_q);
            state_q <= StOut;
          end
          k_q <= k_q + 1'b1;
        end
        StOut: if (out_ready_i) state_q <= StIdle;
        default: state_q <= StIdle;
      endcase
    end
  end

  htx_recip_table #(.K(K), .G(G)) u_table (
    .clk_i,
    .en_i   (!abort_i && (state_q == StNorm) && norm_done),
    .index_i(nx_q[AccQ-2 -: K]),
    .entry_o(entry)
  );

  // The digit of this clock and the accumulator's base: the rounding term 2^(Sh-1) and rb e at a
  // numerator's first digit (the two do not overlap: e < 2^(Sh-1)), the carry acc >>> width after.
  logic [NRW-1:0]       n_sel;
  logic [1:0]           dig;
  logic signed [DigW-1:0] d;
  logic signed [AccW-1:0] base;
  logic signed [DigW+EntryW:0] prod;
  logic                 rb;
  assign n_sel = (k_q < 3'd3) ? nu_q : nv_q;
  always_comb begin
    unique case (k_q)
      3'd0, 3'd3: dig = 2'd0;
      3'd1, 3'd4: dig = 2'd1;
      default:    dig = 2'd2;
    endcase
  end
  always_comb begin
    unique case (dig)
      2'd0:    d = $signed(DigW'(n_sel[NL +: D0]));
      2'd1:    d = $signed(DigW'(n_sel[NL + D0 +: D1]));
      default: d = DigW'($signed(n_sel[NL + Sh +: D2]));
    endcase
  end
  assign prod = d * $signed({1'b0, entry});
  assign rb = pos_q && n_sel[NL-1];
  always_comb begin
    if (dig == 2'd0)      base = $signed((AccW'(1) << (Sh - 1)) | (rb ? AccW'(entry) : '0));
    else if (dig == 2'd1) base = acc_q >>> D0;
    else                  base = acc_q >>> D1;
  end
  // No reset: the multiply-add and this register can be one SB_MAC16.
  always_ff @(posedge clk_i) begin
    if (state_q == StMul) acc_q <= base + AccW'(prod);
  end

  assign out_valid_o = (state_q == StOut);
  assign out_u_o     = u_q;
  assign out_v_o     = v_q;
  assign out_pay_o   = pay_q;
endmodule
