// Setup of one attribute plane (docs/model.md §2): from vertex values a0..a2 (unsigned, or signed
// with Signed) and the vertex deltas,
//   n_x = da1 dy2 - da2 dy1,  n_y = da2 dx1 - da1 dx2   (before any vertex swap),
//   g = round(n R 2^-(W + msb - GF))                     (negated when setup swapped vertices 1, 2),
//   start = a0 2^GF + g_x dxs + g_y dys                  (value at the first pixel centre visited).
// dy1 and dx2 come negated (ndy1 = y0 - y1, ndx2 = x0 - x2: setup's edge coefficients a_0 and b_2,
// so setup forms no subtractors for them), which makes each n a sum of two products.
// n_x, n_y do not depend on the determinant, so they are formed while the reciprocal unit works:
// n_x waits in nx_q and n_y in the accumulator for the reciprocal.
// Gradients and the start value are kept modulo 2^AccW (AccW = VB + GF + 2): traversal only
// evaluates the plane inside the triangle, where the true value fits (docs/model.md §3). gxw_o and
// gyw_o are the gradients at full precision (GW bits, signed) for the LOD unit's block shift.
module htx_raster_plane #(
  parameter int unsigned VB        = 8,    // value bits
  parameter bit          Signed    = 1'b0, // vertex values are signed
  parameter int unsigned DW        = 25,   // vertex coordinate delta width (signed)
  parameter int unsigned W         = 32,   // reciprocal width
  parameter int unsigned GF        = 24,   // gradient fraction bits
  parameter int unsigned ShiftW    = 7,
  parameter int unsigned AccW      = VB + GF + 2,
  parameter int unsigned GW        = VB + DW + 2 + GF + 1  // bounds |n R 2^-shift| (msb(det) >= 0)
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  input  logic                   abort_i,
  input  logic                   start_i,      // vertex values and deltas are valid from now on
  input  logic [VB-1:0]          a0_i, a1_i, a2_i,
  input  logic signed [DW-1:0]   dx1_i, ndy1_i, ndx2_i, dy2_i,
  input  logic signed [DW-1:0]   dxs_i, dys_i, // first pixel centre minus vertex 0 (after the box)
  input  logic                   recip_valid_i,
  input  logic [W:0]             r_i,
  input  logic [ShiftW-1:0]      shift_i,      // W + msb(det) - GF, at least 1
  input  logic                   det_neg_i,
  output logic                   done_o,
  output logic [AccW-1:0]        gx_o, gy_o, start_o,
  output logic [GW-1:0]          gxw_o, gyw_o
);
  localparam int unsigned NW = VB + DW + 2;
  // Also the accumulator (n, then start), and the gradients' rounding: at least AccW + 1 bits.
  localparam int unsigned MA = (NW > AccW) ? NW : AccW + 1;
  localparam int unsigned MB = (DW > W + 2) ? DW : W + 2;
  localparam int unsigned PW = MA + MB;

  typedef enum logic [3:0] {
    StIdle, StNx0, StNx1, StNy0, StNy1, StWait, StGx, StGy, StSx, StSy, StDone
  } state_e;

  state_e state_q;
  logic signed [VB:0]   da1, da2;
  logic signed [NW-1:0] nx_q;
  logic [AccW-1:0]      gx_q, gy_q;
  // The start value's products take their gradient from one register, sg_q: each gradient is
  // formed into sg_next_q, which passes it on to sg_q when the next is formed (g_y) and again after
  // the first start product, so sg_q holds g_x for StSx and g_y for StSy. Two registers that only
  // load each other and the accumulator's sum, instead of a second gradient source on the
  // multiplier's operand (gx_q and gy_q stay for the outputs; synthesis removes them unused).
  logic [AccW-1:0]      sg_q, sg_next_q;
  logic [MA-1:0]        acc_q;
  logic [GW-1:0]        gxw_q, gyw_q;
  logic signed [VB:0]   a0e, a1e, a2e;
  logic signed [MA-1:0] mul_a;
  logic signed [MB-1:0] mul_b;
  logic signed [PW-1:0] mul_p, rounded;
  logic                 mul_start, mul_done;
  logic                 unused;

  assign unused = ^rounded[PW-1:AccW];

  assign a0e = Signed ? $signed({a0_i[VB-1], a0_i}) : $signed({1'b0, a0_i});
  assign a1e = Signed ? $signed({a1_i[VB-1], a1_i}) : $signed({1'b0, a1_i});
  assign a2e = Signed ? $signed({a2_i[VB-1], a2_i}) : $signed({1'b0, a2_i});
  assign da1 = a1e - a0e;
  assign da2 = a2e - a0e;
  // The numerator of this gradient. When setup swapped vertices 1 and 2 the multiplier negates
  // the product n R itself (neg_i: the model's -n times R, before the rounding), so n is never
  // negated here. n = da1 dy2 + da2 ndy1 (n_y likewise) goes through the accumulator's adder.
  logic signed [NW-1:0] nxy;
  logic                 mul_neg;
  assign nxy     = (state_q == StGx) ? nx_q : NW'(acc_q);
  assign mul_neg = det_neg_i && ((state_q == StGx) || (state_q == StGy));

  always_comb begin
    mul_a = '0;
    mul_b = '0;
    unique case (state_q)
      StNx0: begin mul_a = MA'(da1); mul_b = MB'(dy2_i); end
      StNx1: begin mul_a = MA'(da2); mul_b = MB'(ndy1_i); end
      StNy0: begin mul_a = MA'(da2); mul_b = MB'(dx1_i); end
      StNy1: begin mul_a = MA'(da1); mul_b = MB'(ndx2_i); end
      StGx, StGy: begin mul_a = MA'(nxy); mul_b = MB'($signed({1'b0, r_i})); end
      StSx: begin mul_a = MA'($signed(sg_q)); mul_b = MB'(dxs_i); end
      StSy: begin mul_a = MA'($signed(sg_q)); mul_b = MB'(dys_i); end
      default: ;
    endcase
  end
  assign mul_start = (state_q != StIdle) && (state_q != StWait) && (state_q != StDone);

  // The multiplier shifts the gradient products right by shift - 1 itself (no barrel shifter
  // here), and only the last halving and its rounding are left.
  logic [ShiftW-1:0] mul_extra;
  assign mul_extra = ((state_q == StGx) || (state_q == StGy)) ? shift_i - 1'b1 : '0;

  htx_raster_mul #(.AWidth(MA), .BWidth(MB), .Iterative(1'b0), .ExtraW(ShiftW)) u_mul (
    .clk_i, .rst_ni, .abort_i,
    .start_i(mul_start),
    .a_i    (mul_a),
    .b_i    (mul_b),
    .neg_i  (mul_neg),
    .extra_i(mul_extra),
    .done_o (mul_done),
    .p_o    (mul_p)
  );
  // Round to nearest, ties up: (p + 2^(shift-1)) >>> shift = ((p >>> (shift - 1)) + 1) >>> 1.
  // The gradients kept modulo 2^AccW take the + 1 from the accumulator's adder (idle while they
  // are formed); only the full-precision ones for the LOD unit (gxw_o, gyw_o) need an adder of
  // their own, which synthesis removes where nothing takes them.
  assign rounded = (mul_p + $signed(PW'(1))) >>> 1;

  // One adder for both sums of two products: n_x = da1 dy2 + da2 ndy1 (n_y likewise), then
  // start = a0 2^GF + g_x dxs + g_y dys (kept modulo 2^AccW), and the gradients' rounding p + 1.
  logic [MA-1:0] acc_base, acc_sum;
  logic          acc_load;
  always_comb begin
    if (state_q == StSx)                               acc_base = MA'(a0e) << GF;
    else if ((state_q == StNx0) || (state_q == StNy0)) acc_base = '0;
    else if ((state_q == StGx) || (state_q == StGy))   acc_base = MA'(1);
    else                                               acc_base = acc_q;
  end
  assign acc_sum  = acc_base + MA'(mul_p);
  // Where a product's sum goes to acc_q (n_x goes to nx_q, the gradients to their registers).
  assign acc_load = mul_done &&
                    ((state_q == StNx0) || (state_q == StNy0) || (state_q == StNy1) ||
                     (state_q == StSx) || (state_q == StSy));

  // (No reset: every sum starts from a zero base.)
  always_ff @(posedge clk_i) begin
    if (acc_load) acc_q <= acc_sum;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      nx_q    <= '0;
      gx_q    <= '0;
      gy_q    <= '0;
      sg_q    <= '0;
      sg_next_q <= '0;
      gxw_q   <= '0;
      gyw_q   <= '0;
    end else if (abort_i) begin
      state_q <= StIdle;
    end else begin
      unique case (state_q)
        StIdle, StDone: if (start_i) state_q <= StNx0;
        StNx0: if (mul_done) state_q <= StNx1;
        StNx1: if (mul_done) begin nx_q <= NW'(acc_sum); state_q <= StNy0; end
        StNy0: if (mul_done) state_q <= StNy1;
        StNy1: if (mul_done) state_q <= StWait;
        StWait: if (recip_valid_i) state_q <= StGx;
        StGx: if (mul_done) begin
          gx_q <= acc_sum[AccW:1]; gxw_q <= GW'(rounded); state_q <= StGy;
          sg_next_q <= acc_sum[AccW:1];
        end
        StGy: if (mul_done) begin
          gy_q <= acc_sum[AccW:1]; gyw_q <= GW'(rounded); state_q <= StSx;
          sg_next_q <= acc_sum[AccW:1];
          sg_q      <= sg_next_q;  // g_x
        end
        StSx: if (mul_done) begin state_q <= StSy; sg_q <= sg_next_q; end  // g_y
        StSy: if (mul_done) state_q <= StDone;
        default: state_q <= StIdle;
      endcase
    end
  end

  assign done_o  = (state_q == StDone);
  assign gx_o    = gx_q;
  assign gy_o    = gy_q;
  assign start_o = AccW'(acc_q);
  assign gxw_o   = gxw_q;
  assign gyw_o   = gyw_q;
endmodule
