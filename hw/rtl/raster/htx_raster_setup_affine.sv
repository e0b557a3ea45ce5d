// Setup's AFFINE vertex coordinates (docs/raster.md, "Setup"): for each vertex i,
// u_i = round(uq_i R(q_i) 2^(TF - 2W + 1)) and likewise v_i, with R(q_i) from setup's reciprocal
// unit, then the start of the planes of u_i and v_i once setup's first planes are under way.
// q_i < 2^W, so the numerator shift s = msb - (W - 1) is never positive: uq_i << (W - 1 - msb).
module htx_raster_setup_affine #(
  parameter int unsigned RecipW       = 32,
  parameter int unsigned TF           = 16,
  parameter int unsigned UQ           = 48,   // uq_i, vq_i width (signed)
  parameter int unsigned LocW         = 32,   // u_i, v_i width
  parameter int unsigned MsbW         = 6     // the reciprocal's msb index width
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               abort_i,        // setup's planes are abandoned
  input  logic               start_i,        // an AFFINE triangle's 1/|det| is done
  // Setup's reciprocal unit: recip_start_o asks for 1/q of vertex vtx_o (setup puts q_i on it).
  output logic               recip_start_o,
  output logic [1:0]         vtx_o,
  input  logic               recip_done_i,
  input  logic [RecipW:0]    recip_r_i,
  input  logic [MsbW-1:0]    recip_msb_i,
  // The record's values, vertex i at UQ i.
  input  logic [3*UQ-1:0]    uq_i,
  input  logic [3*UQ-1:0]    vq_i,
  // The planes of u_i, v_i: started (a pulse) once late_ok_i (setup waits for its first planes,
  // which have started), and done.
  input  logic               late_ok_i,
  output logic               planes_start_o,
  input  logic [1:0]         planes_done_i,
  input  logic               release_i,      // the triangle leaves setup
  output logic [3*LocW-1:0]  ua_o,           // u_i at LocW i
  output logic [3*LocW-1:0]  va_o,
  output logic               done_o          // coordinates and their planes are done
);
  localparam int unsigned RS = 2 * RecipW - 1 - TF;
  typedef enum logic [2:0] {
    AvIdle, AvStart, AvRecip, AvMulU, AvMulV, AvPlanes, AvWait, AvDone
  } av_e;
  av_e av_q;
  logic [1:0]           ai_q;
  logic [RecipW:0]      r_q;
  logic [MsbW-1:0]      m_q;
  logic [LocW-1:0]      ua_q [3];
  logic [LocW-1:0]      va_q [3];
  logic                 amul_start, amul_done, apl_start_q;
  logic [LocW-1:0]      av_coord;                 // u_i or v_i of the product just done
  assign amul_start = (av_q == AvMulU) || (av_q == AvMulV);
  // (uq_i 2^s) R rounded by RS bits is uq_i R rounded by RS - s bits (s = W - 1 - msb): the
  // multiplier shifts the product right by RS - s - 1 itself (extra_i) and only the last halving
  // with its rounding is left. No shifter on the operand.
  localparam int unsigned AE = $clog2(2 * RecipW);
  logic signed [UQ-1:0]        amul_a;
  logic signed [UQ+RecipW+1:0] amul_p, arnd;
  logic [AE-1:0]               amul_extra;
  assign amul_a = (av_q == AvMulU) ? $signed(uq_i[UQ*ai_q +: UQ]) : $signed(vq_i[UQ*ai_q +: UQ]);
  assign amul_extra = AE'(RS - RecipW) + AE'(m_q);
  htx_raster_mul #(.AWidth(UQ), .BWidth(RecipW + 2), .Iterative(1'b0), .ExtraW(AE)) u_amul (
    .clk_i, .rst_ni, .abort_i(abort_i),
    .start_i(amul_start),
    .a_i    (amul_a),
    .b_i    ($signed({1'b0, r_q})),
    .neg_i  (1'b0),
    .extra_i(amul_extra),
    .done_o (amul_done),
    .p_o    (amul_p)
  );
  assign arnd     = (amul_p + $signed((UQ+RecipW+2)'(1))) >>> 1;
  assign av_coord = LocW'(arnd);
  logic unused_arnd;
  assign unused_arnd = ^arnd[UQ+RecipW+1:LocW];
  assign recip_start_o = (av_q == AvStart);
  assign vtx_o         = ai_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      av_q <= AvIdle; ai_q <= '0; r_q <= '0; m_q <= '0; apl_start_q <= 1'b0;
      for (int i = 0; i < 3; i++) begin ua_q[i] <= '0; va_q[i] <= '0; end
    end else if (abort_i) begin
      av_q <= AvIdle; apl_start_q <= 1'b0;
    end else begin
      apl_start_q <= 1'b0;
      unique case (av_q)
        AvIdle: if (start_i) begin
          ai_q <= '0;
          av_q <= AvStart;
        end
        AvStart: av_q <= AvRecip;
        AvRecip: if (recip_done_i) begin
          r_q <= recip_r_i; m_q <= recip_msb_i;
          av_q <= AvMulU;
        end
        AvMulU: if (amul_done) begin
          ua_q[ai_q] <= av_coord;
          av_q <= AvMulV;
        end
        AvMulV: if (amul_done) begin
          va_q[ai_q] <= av_coord;
          ai_q <= ai_q + 1'b1;
          av_q <= (ai_q == 2'd2) ? AvPlanes : AvStart;
        end
        // (The late planes start only after setup's first ones have started.)
        AvPlanes: if (late_ok_i) begin
          apl_start_q <= 1'b1;
          av_q <= AvWait;
        end
        AvWait: if (!apl_start_q && (&planes_done_i)) av_q <= AvDone;
        AvDone: if (release_i) av_q <= AvIdle;
        default: av_q <= AvIdle;
      endcase
    end
  end
  assign done_o         = (av_q == AvDone);
  assign planes_start_o = apl_start_q;
  for (genvar i = 0; i < 3; i++) begin : g_uv_out
    assign ua_o[LocW*i +: LocW] = ua_q[i];
    assign va_o[LocW*i +: LocW] = va_q[i];
  end
endmodule
