// The shared reciprocal unit (docs/model.md §4, docs/raster.md): normalise X to a W-bit mantissa M
// (truncated), look up the DasSarma-Matula midpoint table (k index bits, g guard bits), then Steps
// Newton-Raphson steps  e = (M R) >> (W-1);  R = (R (2^(W+1) - e) + 2^(W-1)) >> W.
// Result: 1/X ~ r_o * 2^-(W + msb_o). Two multiplications per step go through one multiplier whose
// Iterative parameter sets the throughput (one product per clock, or a shift-and-add unit).
// start_i is taken while idle; done_o pulses once and r_o, msb_o hold until the next start.
// X = 0 yields msb_o = 0 and an unspecified r_o (setup never asks: a zero determinant draws nothing).
module htx_recip #(
  parameter int unsigned XWidth    = 51,
  parameter int unsigned W         = 32,
  parameter int unsigned K         = 10,
  parameter int unsigned G         = 2,
  parameter int unsigned Steps     = 2,
  parameter bit          Iterative = 1'b0,
  parameter int unsigned MsbWidth  = $clog2(XWidth)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                abort_i,
  input  logic                start_i,
  input  logic [XWidth-1:0]   x_i,
  output logic                busy_o,
  output logic                done_o,
  output logic [W:0]          r_o,
  output logic [MsbWidth-1:0] msb_o
);
  localparam int unsigned EntryW = K + G + 1;
  localparam int unsigned MulW   = W + 3;
  localparam int unsigned StepW  = 2;

  typedef enum logic [2:0] {StIdle, StTable, StMulE, StMulR, StDone} state_e;

  // Table entry i: round(2^(2k+g+2) / (2^(k+1) + 2i + 1)); the odd divisor never ties.
  function automatic logic [EntryW-1:0] table_entry(input int unsigned i);
    logic [63:0] num, den;
    num = 64'd1 << (2 * K + G + 2);
    den = (64'd1 << (K + 1)) + 64'(2 * i + 1);
    table_entry = EntryW'((2 * num + den) / (2 * den));
  endfunction

  logic [EntryW-1:0] rom [2**K];
  initial begin
    for (int unsigned i = 0; i < 2**K; i++) rom[i] = table_entry(i);
  end

  state_e              state_q;
  logic [StepW-1:0]    step_q;
  logic [W-1:0]        m_q;
  logic [W:0]          r_q;
  logic [W+1:0]        c_q;
  logic [MsbWidth-1:0] msb_q, msb;
  logic [W-1:0]        mant;
  logic [EntryW-1:0]   entry_q;
  logic                mul_start, mul_done;
  logic signed [MulW-1:0]   mul_a, mul_b;
  logic signed [2*MulW-1:0] mul_p;
  logic [2*MulW-1:0]   prod;
  logic [W+1:0]        e;

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

  assign mul_start = (state_q == StMulE) || (state_q == StMulR);
  assign mul_a = (state_q == StMulE) ? MulW'(m_q) : MulW'(r_q);
  assign mul_b = (state_q == StMulE) ? MulW'(r_q) : MulW'(c_q);

  htx_raster_mul #(.AWidth(MulW), .BWidth(MulW), .Iterative(Iterative)) u_mul (
    .clk_i, .rst_ni,
    .start_i(mul_start),
    .a_i    (mul_a),
    .b_i    (mul_b),
    .done_o (mul_done),
    .p_o    (mul_p)
  );
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
      entry_q <= '0;
    end else if (abort_i) begin
      state_q <= StIdle;
    end else begin
      unique case (state_q)
        StIdle: if (start_i) begin
          m_q     <= mant;
          msb_q   <= msb;
          entry_q <= rom[mant[W-2 -: K]];
          step_q  <= '0;
          state_q <= StTable;
        end
        StTable: begin
          r_q     <= (W + 1)'(entry_q) << (W - K - G - 1);
          state_q <= (Steps == 0) ? StDone : StMulE;
        end
        StMulE: if (mul_done) begin
          // e < 2^(W+1) always (M < 2^W, R <= 2^W); the guard keeps 2 - m r non-negative anyway.
          c_q     <= (e[W+1]) ? '0 : ((W + 2)'(1) << (W + 1)) - e;
          state_q <= StMulR;
        end
        StMulR: if (mul_done) begin
          r_q     <= (W + 1)'((prod + ((2*MulW)'(1) << (W - 1))) >> W);
          step_q  <= step_q + 1'b1;
          state_q <= (32'(step_q) + 1 == Steps) ? StDone : StMulE;
        end
        StDone: state_q <= StIdle;
        default: state_q <= StIdle;
      endcase
    end
  end

  assign busy_o = (state_q != StIdle);
  assign done_o = (state_q == StDone);
  assign r_o    = r_q;
  assign msb_o  = msb_q;
endmodule
