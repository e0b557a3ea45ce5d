// Setup of one attribute plane (docs/model.md §2): from vertex values a0..a2 (unsigned, or signed
// with Signed) and the vertex deltas,
//   n_x = da1 dy2 - da2 dy1,  n_y = da2 dx1 - da1 dx2   (before any vertex swap),
//   g = round(n R 2^-(W + msb - GF))                     (negated when setup swapped vertices 1, 2),
//   start = a0 2^GF + g_x dxs + g_y dys                  (value at the first pixel centre visited).
// dy1 and dx2 come negated (ndy1 = y0 - y1, ndx2 = x0 - x2: setup's edge coefficients a_0 and b_2,
// so setup forms no subtractors for them), which makes each n a sum of two products.
// n_x, n_y do not depend on the determinant, so they are formed while the reciprocal unit works
// (Iterative: n_x, then g_x, then n_y and g_y, so that only the accumulator holds an n).
// Gradients and the start value are kept modulo 2^AccW (AccW = VB + GF + 2): traversal only
// evaluates the plane inside the triangle, where the true value fits (docs/model.md §3). gxw_o and
// gyw_o are the gradients at full precision (GW bits, signed) for the LOD unit's block shift.
// Jobs = 1: between planes the unit also runs setup's other products on its multiplier and
// accumulator (job_*: the determinant and the edge values, one product a job), so setup has no
// multiplier of its own for them.
// Ring = 1 (with Iterative; setup's `icebreaker` form): n takes the symmetric form
//   n_x = a0 a_1 + a1 a_2 + a2 a_0,  n_y = a0 b_1 + a1 b_2 + a2 b_0
// with setup's edge coefficients a_k = y_k - y_k1, b_k = x_k1 - x_k (k1 = k + 1 mod 3), equal to
// the form above (expand da1 = a1 - a0, da2 = a2 - a0): three products each, and no subtractors.
// The a operand is always a0_i, the head of the caller's vertex values, which the caller rotates
// by one vertex (a0 <- a1 <- a2 <- a0) on each val_turn_o pulse, one after each of these six
// products, so they are back home when the start value reads a0. The b operand is always dy2_i,
// one place of setup's ring of edge coefficients (htx_raster_setup, g_coef_read): the unit names
// the ring position each product needs on ring_want_o and starts it only when ring_pos_i is
// there; the multiplier takes its operands at the start, so the ring turns on to the next
// product's position during a product. One source each for the multiplier's a and b operands
// where the differences' form has two and four; a1_i, a2_i, dx1_i, ndy1_i, ndx2_i are unused.
// The start value's a0 2^GF is a product as well (a0 times the constant 2^GF, StS0), and the
// accumulator's adder always adds acc_q: the unit clears acc_q before each sum's first product and
// sets it to 1 for a gradient's rounding as that product takes n from it, which flip-flops with
// synchronous set and reset do without a multiplexer.
module htx_raster_plane #(
  parameter int unsigned VB        = 8,    // value bits
  parameter bit          Signed    = 1'b0, // vertex values are signed
  parameter int unsigned DW        = 25,   // vertex coordinate delta width (signed)
  parameter int unsigned W         = 32,   // reciprocal width
  parameter int unsigned GF        = 24,   // gradient fraction bits
  parameter bit          Iterative = 1'b0,
  parameter bit          Jobs      = 1'b0,
  parameter int unsigned ShiftW    = 7,
  parameter bit          Ring      = 1'b0,
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
  input  logic [2:0]             ring_pos_i,   // Ring: the ring's position (see above)
  output logic [2:0]             ring_want_o,  // Ring: the position the unit wants (0: home)
  output logic                   val_turn_o,   // Ring: rotate the vertex values (a pulse)
  output logic                   done_o,
  output logic [AccW-1:0]        gx_o, gy_o, start_o,
  output logic [GW-1:0]          gxw_o, gyw_o,
  // Each result word as it is formed (a pulse; sel 0 g_x, 1 g_y, 2 start), for a caller that
  // stores them one at a time without a multiplexer over gx_o, gy_o, start_o. A gradient's word
  // is 2 g or 2 g + 1 (g with the bit below it: g is word_o[AccW:1]); the start value's is
  // word_o[AccW-1:0]. The caller takes each part by its wiring: no multiplexer here.
  output logic                   word_we_o,
  output logic [1:0]             word_sel_o,
  output logic [AccW:0]          word_o,
  // Jobs: while the unit is idle (StIdle or StDone, not being started), job_i runs one product
  // job_a_i times the operand job_bsel_i picks (0 dy2_i, 1 ndy1_i, 2 dxs_i, 3 dys_i, 4 the
  // constant 2, which gives job_a_i as a gradient word: 2 g with g = job_a_i), negated
  // with job_neg_i, added to the previous job's sum with job_acc_i (else to 0). job_done_o pulses
  // with the sum on job_sum_o (valid in that clock). The inputs hold until then; a job_i still
  // high after job_done_o asks for the next job. (MA >= 2 DW + 2 where Jobs is used.)
  input  logic                   job_i,
  input  logic signed [DW-1:0]   job_a_i,
  input  logic [2:0]             job_bsel_i,
  input  logic                   job_neg_i,
  input  logic                   job_acc_i,
  output logic                   job_done_o,
  output logic [2*DW+1:0]        job_sum_o
);
  localparam int unsigned NW = VB + DW + 2;
  // Also the accumulator (n, then start), and the gradients' rounding: at least AccW + 1 bits.
  localparam int unsigned MA = (NW > AccW) ? NW : AccW + 1;
  localparam int unsigned MB = (DW > W + 2) ? DW : W + 2;
  localparam int unsigned PW = MA + MB;

  typedef enum logic [3:0] {
    StIdle, StNx0, StNx1, StNx2, StNy0, StNy1, StNy2, StWait, StGx, StGy, StS0, StSx, StSy, StDone,
    StJob
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
  // In parallel (`full`) n_x waits in nx_q and n_y in the accumulator for the reciprocal. Iterative
  // units take g_x straight after n_x and only then form n_y: each n is in the accumulator when
  // its gradient is taken, and nx_q and its multiplexer are left out.
  localparam bit NyAfterGx = Iterative;
  assign nxy     = ((state_q == StGx) && !NyAfterGx) ? nx_q : NW'(acc_q);
  assign mul_neg = (state_q == StJob) ? job_neg_i
                 : (det_neg_i && ((state_q == StGx) || (state_q == StGy)));

  // n's products (StNx2 and StNy2 only with Ring).
  logic n_state;
  assign n_state = (state_q == StNx0) || (state_q == StNx1) || (state_q == StNx2) ||
                   (state_q == StNy0) || (state_q == StNy1) || (state_q == StNy2);
  logic ring_ok;
  logic prod_first;  // Ring: the state's product takes its operands in this clock
  if (Ring) begin : g_ring
    // Ring place 3 holds the coefficient of home index (position + 3) mod 6, home indices 0..5
    // being b_0, b_1, b_2, a_2, a_1, a_0. Each product's position (pos_now) and, once its operands
    // are taken (started_q), the next product's (pos_next); home while the planes end.
    logic       started_q;
    logic [2:0] pos_now, pos_next;
    always_comb begin
      unique case (state_q)
        StNx0:        begin pos_now = 3'd1; pos_next = 3'd0; end  // a0 a_1, then a_2
        StNx1:        begin pos_now = 3'd0; pos_next = 3'd2; end  // a1 a_2, then a_0
        StNx2:        begin pos_now = 3'd2; pos_next = 3'd4; end  // a2 a_0, then b_1
        StWait, StGx: begin pos_now = 3'd4; pos_next = 3'd4; end
        StNy0:        begin pos_now = 3'd4; pos_next = 3'd5; end  // a0 b_1, then b_2
        StNy1:        begin pos_now = 3'd5; pos_next = 3'd3; end  // a1 b_2, then b_0
        StNy2:        begin pos_now = 3'd3; pos_next = 3'd0; end  // a2 b_0, then home
        default:      begin pos_now = 3'd0; pos_next = 3'd0; end
      endcase
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        started_q <= 1'b0;
      end else if (abort_i || mul_done) begin
        started_q <= 1'b0;
      end else if (mul_start) begin
        started_q <= 1'b1;
      end
    end
    assign ring_want_o = started_q ? pos_next : pos_now;
    assign prod_first  = mul_start && !started_q;
    assign ring_ok     = (ring_pos_i == pos_now);
    assign val_turn_o  = n_state && mul_done;
    logic unused_ring;
    assign unused_ring = ^{ndy1_i, dx1_i, ndx2_i, da1, da2};
  end else begin : g_no_ring
    assign ring_want_o = 3'd0;
    assign ring_ok     = 1'b1;
    assign val_turn_o  = 1'b0;
    assign prod_first  = 1'b0;
    logic unused_ring_pos;
    assign unused_ring_pos = ^ring_pos_i;
  end

  always_comb begin
    mul_a = '0;
    mul_b = '0;
    unique case (state_q)
      StNx0, StNx1, StNx2, StNy0, StNy1, StNy2: begin
        if (Ring) begin
          mul_a = MA'(a0e);
          mul_b = MB'(dy2_i);
        end else begin
          unique case (state_q)
            StNx0:   begin mul_a = MA'(da1); mul_b = MB'(dy2_i); end
            StNx1:   begin mul_a = MA'(da2); mul_b = MB'(ndy1_i); end
            StNy0:   begin mul_a = MA'(da2); mul_b = MB'(dx1_i); end
            default: begin mul_a = MA'(da1); mul_b = MB'(ndx2_i); end  // StNy1
          endcase
        end
      end
      StGx, StGy: begin mul_a = MA'(nxy); mul_b = MB'($signed({1'b0, r_i})); end
      StS0: begin mul_a = MA'(a0e); mul_b = MB'(1) << GF; end  // (Ring; 2^GF < 2^(MB-1))
      StSx: begin mul_a = MA'($signed(sg_q)); mul_b = MB'(dxs_i); end
      StSy: begin mul_a = MA'($signed(sg_q)); mul_b = MB'(dys_i); end
      StJob: begin
        mul_a = MA'(job_a_i);
        unique case (job_bsel_i)
          3'd0:    mul_b = MB'(dy2_i);
          3'd1:    mul_b = Ring ? MB'(dy2_i) : MB'(ndy1_i);
          3'd2:    mul_b = MB'(dxs_i);
          3'd3:    mul_b = MB'(dys_i);
          default: mul_b = MB'(2);
        endcase
      end
      default: ;
    endcase
  end
  // An n product waits until the ring is at its position (Ring); no other product waits.
  assign mul_start = (state_q != StIdle) && (state_q != StWait) && (state_q != StDone) &&
                     (!n_state || ring_ok);

  // The multiplier shifts the gradient products right by shift - 1 itself (the iterative one in
  // its own registers, no barrel shifter), and only the last halving and its rounding are left here.
  logic [ShiftW-1:0] mul_extra;
  assign mul_extra = ((state_q == StGx) || (state_q == StGy)) ? shift_i - 1'b1 : '0;

  htx_raster_mul #(.AWidth(MA), .BWidth(MB), .Iterative(Iterative), .ExtraW(ShiftW)) u_mul (
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
  // (Ring: three products for each n and for the start value, each sum started from a cleared
  // acc_q, and the rounding's 1 set in acc_q; see above.)
  logic [MA-1:0] acc_base, acc_sum;
  logic          acc_clear, acc_one, acc_load;
  if (Ring) begin : g_acc_ring
    assign acc_base  = acc_q;
    assign acc_clear = (((state_q == StIdle) || (state_q == StDone)) &&
                        (start_i || (Jobs && job_i && !job_acc_i))) ||
                       (mul_done && ((state_q == StGx) || (state_q == StGy)));
    assign acc_one   = prod_first && ((state_q == StGx) || (state_q == StGy));
  end else begin : g_acc_mux
    always_comb begin
      if (state_q == StSx)                               acc_base = MA'(a0e) << GF;
      else if ((state_q == StNx0) || (state_q == StNy0) || ((state_q == StJob) && !job_acc_i))
        acc_base = '0;
      else if ((state_q == StGx) || (state_q == StGy))   acc_base = MA'(1);
      else                                               acc_base = acc_q;
    end
    assign acc_clear = 1'b0;
    assign acc_one   = 1'b0;
    logic unused_first;
    assign unused_first = prod_first;
  end
  assign acc_sum  = acc_base + MA'(mul_p);
  // Where a product's sum goes to acc_q (n_x in nx_q instead without NyAfterGx).
  assign acc_load = mul_done &&
                    ((state_q == StJob) || (state_q == StNx0) || (state_q == StNx2) ||
                     ((state_q == StNx1) && (Ring || NyAfterGx)) || (state_q == StNy0) ||
                     (state_q == StNy1) || (state_q == StNy2) || (state_q == StS0) ||
                     (state_q == StSx) || (state_q == StSy));

  // (No reset: every sum starts from a cleared acc_q or a zero base.)
  always_ff @(posedge clk_i) begin
    if (acc_clear) begin
      acc_q <= '0;
    end else if (acc_one) begin
      acc_q <= MA'(1);
    end else if (acc_load) begin
      acc_q <= acc_sum;
    end
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
                        else if (Jobs && job_i) state_q <= StJob;
        StJob: if (mul_done) state_q <= StIdle;
        StNx0: if (mul_done) state_q <= StNx1;
        StNx1: if (mul_done) begin
          if (Ring) state_q <= StNx2;
          else if (NyAfterGx) state_q <= StWait;
          else begin nx_q <= NW'(acc_sum); state_q <= StNy0; end
        end
        StNx2: if (mul_done) state_q <= StWait;
        StNy0: if (mul_done) state_q <= StNy1;
        StNy1: if (mul_done) state_q <= Ring ? StNy2 : (NyAfterGx ? StGy : StWait);
        StNy2: if (mul_done) state_q <= StGy;
        StWait: if (recip_valid_i) state_q <= StGx;
        StGx: if (mul_done) begin
          gx_q <= acc_sum[AccW:1]; gxw_q <= GW'(rounded); state_q <= NyAfterGx ? StNy0 : StGy;
          sg_next_q <= acc_sum[AccW:1];
        end
        StGy: if (mul_done) begin
          gy_q <= acc_sum[AccW:1]; gyw_q <= GW'(rounded); state_q <= Ring ? StS0 : StSx;
          sg_next_q <= acc_sum[AccW:1];
          sg_q      <= sg_next_q;  // g_x
        end
        StS0: if (mul_done) state_q <= StSx;
        StSx: if (mul_done) begin state_q <= StSy; sg_q <= sg_next_q; end  // g_y
        StSy: if (mul_done) state_q <= StDone;
        default: state_q <= StIdle;
      endcase
    end
  end

  assign word_we_o  = mul_done && ((state_q == StGx) || (state_q == StGy) || (state_q == StSy));
  assign word_sel_o = (state_q == StGx) ? 2'd0 : (state_q == StGy) ? 2'd1 : 2'd2;
  assign word_o     = acc_sum[AccW:0];

  assign job_done_o = (state_q == StJob) && mul_done;
  assign job_sum_o  = (2*DW+2)'(acc_sum);

  assign done_o  = (state_q == StDone);
  assign gx_o    = gx_q;
  assign gy_o    = gy_q;
  assign start_o = AccW'(acc_q);
  assign gxw_o   = gxw_q;
  assign gyw_o   = gyw_q;
endmodule
