// Triangle setup (docs/model.md §2, docs/raster.md): determinant, winding (the model swaps
// vertices 1 and 2 for a negative determinant: both windings are drawn), edge functions with the
// top-left rule, the pixel box clipped to the screen, 1/det from its reciprocal unit, and the
// planes of z, the colour channels (c q with PerspColor), q, uq, vq and, for AFFINE, the vertex
// texel coordinates u_i = uq_i / q_i (three more reciprocals from the same unit, docs/model.md
// §5.1; htx_raster_setup_affine), and the LOD unit's block-shifted gradients (§6;
// htx_raster_setup_lod). Nine plane units work in parallel. This is the `full` configuration's
// setup; the iterative configurations take plane records instead (htx_raster FwSetup). Edge
// values and plane values are delivered at the box's first pixel centre (256 x_lo + 128,
// 256 y_lo + 128), where traversal starts. Zero-area triangles and triangles whose box holds no
// pixel centre of the screen are consumed here and never reach traversal.
module htx_raster_setup #(
  parameter int unsigned XyIntBits = 16,
  parameter int unsigned ZBits     = 24,
  parameter int unsigned GF        = 24,
  parameter int unsigned RecipW    = 32,
  parameter int unsigned RecipK    = 10,
  parameter int unsigned RecipG    = 2,
  parameter int unsigned NrSteps   = 2,
  parameter int unsigned QBits     = 32,
  parameter int unsigned UvIntBits = 16,
  parameter int unsigned TF        = 16,
  parameter int unsigned GradW     = 24,       // lod_grad_bits
  parameter logic [4:0]  Methods   = 5'b01111, // bit m: method m built (htx::Method order)
  parameter bit          PerspColor = 1'b1,
  // Derived widths (docs/raster.md).
  parameter int unsigned UQ   = QBits + UvIntBits,            // uq, vq vertex values (signed)
  parameter int unsigned LocW = UvIntBits + TF,               // local texel coordinates (signed)
  parameter int unsigned CB   = PerspColor ? 8 + QBits : 8,   // colour plane values
  parameter int unsigned AW   = UQ + GF + 2,                  // widest plane accumulator
  parameter int unsigned NP   = 9,                            // z, r, g, b, q, uq, vq, ua, va
  parameter int unsigned XW   = XyIntBits + 8,   // vertex x, y (signed, 1/256 pixel)
  parameter int unsigned DW   = XW + 1,          // coordinate deltas
  parameter int unsigned EW   = 2 * DW + 2,      // edge function values
  parameter int unsigned DetW = 2 * DW + 1,      // determinant
  parameter int unsigned MsbW = $clog2(DetW)
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 abort_i,
  input  logic [12:0]          width_i,
  input  logic [12:0]          height_i,

  // Triangle record from the input stage.
  input  logic                 rec_valid_i,
  output logic                 rec_ready_o,
  input  logic                 hold_i,        // do not take a new triangle (a clear is pending)
  input  logic [31:0]          rec_state_i,
  input  logic [3*XW-1:0]      rec_x_i,
  input  logic [3*XW-1:0]      rec_y_i,
  input  logic [3*ZBits-1:0]   rec_z_i,
  input  logic [3*32-1:0]      rec_rgba_i,
  input  logic [3*QBits-1:0]   rec_q_i,
  input  logic [3*UQ-1:0]      rec_uq_i,
  input  logic [3*UQ-1:0]      rec_vq_i,
  input  logic [31:0]          rec_u_off_i,
  input  logic [31:0]          rec_v_off_i,

  // Set-up triangle to traversal; held until taken.
  output logic                 tri_valid_o,
  input  logic                 tri_ready_i,
  output logic [31:0]          tri_state_o,
  output logic [31:0]          tri_flat_rgba_o,
  output logic [12:0]          tri_x_lo_o, tri_x_hi_o, tri_y_lo_o, tri_y_hi_o,
  output logic [3*DW-1:0]      tri_a_o, tri_b_o,
  output logic [2:0]           tri_a_zero_o,  // a_k = 0
  output logic [2:0]           tri_thr_o,     // of the edges as given (see tri_dneg_o)
  output logic                 tri_dneg_o,    // det < 0: the model's edges are these reversed
  output logic [3*EW-1:0]      tri_e_o,
  output logic [3*NP*AW-1:0]   tri_p_o,       // plane p at 3 AW p: {start, gy, gx}, mod 2^AW
  output logic [31:0]          tri_u_off_o, tri_v_off_o,
  output logic [6*GradW-1:0]   tri_lod_g_o,   // g_ux, g_uy, g_vx, g_vy, g_qx, g_qy (block-shifted)
  output logic [7:0]           tri_lod_shift_o,
  output logic [6*(UQ+DW+2+GF+1)-1:0] tri_dfg_o, // the six at full precision (signed): DIVFREE's seed

  output logic                 busy_o,        // computing (not waiting for input or traversal)
  output logic                 stall_o,       // a finished triangle waits for traversal
  output logic                 taken_o,       // a triangle was taken from the input (pulse)
  output logic                 err_o          // a triangle asked for what is not built (pulse)
);
  localparam int unsigned BoxW   = XW - 7;      // signed pixel index of a box bound
  localparam int unsigned ShiftW = 8;

  typedef enum logic [2:0] {StIdle, StDet0, StDet1, StEdges, StWait, StOut} state_e;

  state_e state_q;
  logic [31:0]            st_v;      // the record's values, copied as setup takes it
  logic signed [XW-1:0]   x_v [3];
  logic signed [XW-1:0]   y_v [3];
  logic [ZBits-1:0]       z_v [3];
  logic [31:0]            rgba_v [3];
  logic [QBits-1:0]       q_v [3];
  logic [3*UQ-1:0]        uq_v, vq_v;  // vertex i at UQ i, as the record and the AFFINE unit have them
  logic [31:0]            u_off_v, v_off_v;
  logic signed [DetW-1:0] det_q;     // |det|, from StDet1 on (edge 1 starts from it)
  logic                   det_neg_q;
  logic [1:0]             edge_k_q;  // the edge whose value is formed
  logic                   edge_half_q;
  logic signed [EW-1:0]   e_q [3];
  logic signed [EW-1:0]   part_q;    // the first product of det or of an edge value

  // ---- Accept and check the state word --------------------------------------------------------
  // A method this build leaves out, a subdivision length outside 2..64 or a depth function beyond
  // `always` is consumed, draws nothing and raises ERR_STATE.
  // Setup in hardware is the `full` configuration's, with AFFINE among its methods (the builds
  // without texture mapping or without AFFINE take plane records: htx_raster FwSetup).
  if (!Methods[0]) begin : g_bad_methods
    $error("htx_raster_setup: AFFINE must be built (other configurations take plane records)");
  end
  logic take, state_bad, tri_skip;
  logic [2:0] rec_method;
  assign rec_method  = rec_state_i[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3];
  // take: setup starts on a record, which it copies (and so releases at once).
  assign take        = rec_valid_i && (state_q == StIdle) && !hold_i;
  assign rec_ready_o = (state_q == StIdle) && !hold_i;
  htx_raster_state_check #(.Methods(Methods)) u_state_check (.state_i(rec_state_i), .bad_o(state_bad));
  assign taken_o     = take;
  assign err_o       = take && state_bad;

  // ---- The record's values -------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_v    <= '0;
      u_off_v <= '0;
      v_off_v <= '0;
      uq_v    <= '0;
      vq_v    <= '0;
      for (int i = 0; i < 3; i++) begin
        x_v[i] <= '0; y_v[i] <= '0; z_v[i] <= '0; rgba_v[i] <= '0;
        q_v[i] <= '0;
      end
    end else if (take && !state_bad && !abort_i) begin
      st_v    <= rec_state_i;
      u_off_v <= rec_u_off_i;
      v_off_v <= rec_v_off_i;
      uq_v    <= rec_uq_i;
      vq_v    <= rec_vq_i;
      for (int i = 0; i < 3; i++) begin
        x_v[i]    <= rec_x_i[XW*i +: XW];
        y_v[i]    <= rec_y_i[XW*i +: XW];
        z_v[i]    <= rec_z_i[ZBits*i +: ZBits];
        rgba_v[i] <= rec_rgba_i[32*i +: 32];
        q_v[i]    <= rec_q_i[QBits*i +: QBits];
      end
    end
  end

  // ---- Deltas, box -----------------------------------------------------------------------------

  // Pixel centres 256 i + 128 inside [min, max]: ceil((min - 128) / 256) .. floor((max - 128) / 256),
  // clipped to the screen. The bounds come from the vertices the edges' signs pick (below).
  logic signed [BoxW-1:0] x_lo, x_hi, y_lo, y_hi;
  logic                   box_empty;
  assign box_empty = (x_lo > x_hi) || (y_lo > y_hi);

  // First pixel centre of the box, relative to each vertex.
  logic signed [DW-1:0] pxs, pys;
  assign pxs = (DW'(x_lo) <<< 8) + DW'(128);
  assign pys = (DW'(y_lo) <<< 8) + DW'(128);
  logic signed [DW-1:0] dxs, dys;  // the first pixel centre relative to vertex 0
  assign dxs = pxs - DW'(x_v[0]);
  assign dys = pys - DW'(y_v[0]);

  // The edges of the triangle as given, in the order v0 v1, v1 v2, v2 v0. The model swaps v1 and v2
  // when det < 0, which reverses every edge: E' = -E and, the top-left rule being antisymmetric,
  // threshold' = 1 - threshold (an edge of zero length has det = 0 and is never drawn). Traversal
  // takes the winding (tri_dneg_o) and tests the reversed edges from these (docs/raster.md), so
  // setup swaps nothing: no vertex multiplexers. Six subtractors on the vertex registers.
  logic signed [DW-1:0] ea [3];
  logic signed [DW-1:0] eb [3];
  logic [2:0]           ethr, ea_zero;
  // Each coefficient's sign and whether it is zero (the thresholds and the box take only these).
  logic [2:0]           ea_neg, eb_neg, eb_zero;
  for (genvar k = 0; k < 3; k++) begin : g_k
    localparam int unsigned K1 = (k + 1) % 3;
    // a = -(y_k1 - y_k), formed as y_k - y_k1: one subtractor, not a subtractor and a negation.
    assign ea[k]      = DW'(y_v[k]) - DW'(y_v[K1]);
    assign eb[k]      = DW'(x_v[K1]) - DW'(x_v[k]);
    assign ea_neg[k]  = ea[k][DW-1];
    assign eb_neg[k]  = eb[k][DW-1];
    assign ea_zero[k] = (ea[k] == 0);
    assign eb_zero[k] = (eb[k] == 0);
  end
  for (genvar k = 0; k < 3; k++) begin : g_edge
    // y points down and inside is E > 0: an edge going up is a left edge, a horizontal edge going
    // right a top edge; pixel centres exactly on them belong to this triangle (threshold 0).
    // (Signs and zero tests rather than "> 0": Yosys 0.23 builds a comparison as a carry chain,
    // a LUT and a carry a bit; docs/area.md.)
    assign ethr[k] = !((!ea_neg[k] && !ea_zero[k]) ||
                       (ea_zero[k] && !eb_neg[k] && !eb_zero[k]));
  end
  // The vertex deltas are edge coefficients: dx1 = x1 - x0 = b_0 and dy2 = y2 - y0 = a_2, and dy1,
  // dx2 only negated, as a_0 = y0 - y1 and b_2 = x0 - x2: the plane units take those, and
  // det = dx1 dy2 - dx2 dy1 = b_0 a_2 - b_2 a_0. No subtractors of their own.
  logic signed [DW-1:0] dx1, dy2;
  assign dx1 = eb[0];
  assign dy2 = ea[2];

  // The box's bounds without comparators of their own: the edges' coefficients are the vertices'
  // differences around the triangle, so their signs order the vertices (b_k = x_k1 - x_k and
  // a_k = y_k - y_k1).
  // Vertex k is the least of three when it is not above its successor and below its predecessor;
  // when none is (all equal) vertex 0 is.
  function automatic logic [1:0] least(input logic [2:0] next_lt);  // bit k: v_k1 < v_k
    if (!next_lt[1] && next_lt[0])      least = 2'd1;
    else if (!next_lt[2] && next_lt[1]) least = 2'd2;
    else                                least = 2'd0;
  endfunction
  logic [2:0] xs_lt, ys_gt;  // bit k: x_k1 < x_k; y_k1 > y_k (the order of -y)
  logic [1:0] minx_sel, maxx_sel, miny_sel, maxy_sel;
  for (genvar k = 0; k < 3; k++) begin : g_order
    assign xs_lt[k] = eb_neg[k];
    assign ys_gt[k] = ea_neg[k];
  end
  assign minx_sel = least(xs_lt);
  assign maxx_sel = least(~xs_lt);
  assign miny_sel = least(~ys_gt);
  assign maxy_sel = least(ys_gt);
  // A box's upper bound clipped to the screen, min(b, lim - 1) (lim: FB_SIZE's 13-bit width or
  // height). A limit of 2^(BoxW-1) or more exceeds every bound b can hold (a configuration with
  // 13-bit signed boxes), so it clips nothing; in BoxW bits its lim - 1 would wrap negative and
  // empty the box.
  function automatic logic signed [BoxW-1:0] clip_hi(input logic signed [BoxW-1:0] b,
                                                     input logic [12:0] lim);
    logic signed [BoxW-1:0] top;
    logic                   beyond;
    top = $signed(BoxW'({1'b0, lim}) - BoxW'(1));
    if (BoxW <= 13) beyond = (32'(lim) >> (BoxW - 1)) != 0;
    else beyond = 1'b0;
    clip_hi = (!beyond && (b > top)) ? top : b;
  endfunction

  logic signed [XW-1:0]   minx, maxx, miny, maxy;
  logic signed [BoxW-1:0] xl, xh, yl, yh;
  assign minx = (minx_sel == 2'd1) ? x_v[1] : (minx_sel == 2'd2) ? x_v[2] : x_v[0];
  assign maxx = (maxx_sel == 2'd1) ? x_v[1] : (maxx_sel == 2'd2) ? x_v[2] : x_v[0];
  assign miny = (miny_sel == 2'd1) ? y_v[1] : (miny_sel == 2'd2) ? y_v[2] : y_v[0];
  assign maxy = (maxy_sel == 2'd1) ? y_v[1] : (maxy_sel == 2'd2) ? y_v[2] : y_v[0];
  always_comb begin
    xl = BoxW'((XW'(minx) + XW'(127)) >>> 8);
    xh = BoxW'((XW'(maxx) - XW'(128)) >>> 8);
    yl = BoxW'((XW'(miny) + XW'(127)) >>> 8);
    yh = BoxW'((XW'(maxy) - XW'(128)) >>> 8);
    x_lo = xl[BoxW-1] ? '0 : xl;  // (the sign bit, not "< 0": see ethr)
    y_lo = yl[BoxW-1] ? '0 : yl;
    x_hi = clip_hi(xh, width_i);
    y_hi = clip_hi(yh, height_i);
  end

  // ---- Determinant and edge values -------------------------------------------------------------
  // A multiplier of setup's own, eight products: det's two and two for each edge value.
  logic                     emul_done;
  logic signed [EW-1:0]     part_sum;
  logic                     emul_start;
  logic signed [DW-1:0]     emul_a, emul_b;
  logic signed [2*DW-1:0]   emul_p;
  always_comb begin
    emul_a = '0;
    emul_b = '0;
    unique case (state_q)
      StDet0: begin emul_a = dx1; emul_b = dy2; end
      StDet1: begin emul_a = eb[2]; emul_b = ea[0]; end  // (-dx2)(-dy1)
      // E_k = a_k (px - x_k) + b_k (py - y_k) = a_k dxs + b_k dys + E_k(v0), exactly, and E_k(v0)
      // is 0 for the two edges through vertex 0 and det for edge 1 (the first product is added
      // to it): every edge multiplies the deltas that the planes use, no per-edge subtraction.
      StEdges: begin
        if (!edge_half_q) begin emul_a = ea[edge_k_q]; emul_b = dxs; end
        else              begin emul_a = eb[edge_k_q]; emul_b = dys; end
      end
      default: ;
    endcase
  end
  assign emul_start = (state_q == StDet0) || (state_q == StDet1) || (state_q == StEdges);

  htx_raster_mul #(.AWidth(DW), .BWidth(DW), .Iterative(1'b0), .ExtraW(1)) u_edge_mul (
    .clk_i, .rst_ni, .abort_i,
    .start_i(emul_start),
    .a_i    (emul_a),
    .b_i    (emul_b),
    .neg_i  ((state_q == StEdges) ? ethr[edge_k_q] : (state_q == StDet1)),
    .extra_i(1'b0),
    .done_o (emul_done),
    .p_o    (emul_p)
  );

  // det = dx1 dy2 + (-(dx2 dy1)) and E_k = a_k (px - x_k) + b_k (py - y_k): the multiplier
  // negates det's second product itself (neg_i), so one adder serves both.
  logic signed [EW-1:0]   part_base;
  always_comb begin
    if ((state_q == StDet0) || ((state_q == StEdges) && !edge_half_q)) begin
      part_base = ((state_q == StEdges) && (edge_k_q == 2'd1)) ? EW'(det_q) : '0;  // det_q: |det|
    end else begin
      part_base = part_q;
    end
  end
  // An edge whose threshold is 1 goes to traversal negated (-E: its coverage test is then a
  // sign, docs/raster.md): both products negated (neg_i). Edge 1's value at v0 is det itself,
  // |det| or -|det|: added or subtracted by the sign of det and the negation.
  htx_raster_addsub #(.W(EW)) u_part (
    .a_i  (EW'(emul_p)),
    .b_i  (part_base),
    .sub_i((state_q == StEdges) && !edge_half_q && (ethr[edge_k_q] ^ det_neg_q)),
    .sum_o(part_sum)
  );
  logic signed [DetW-1:0] det_next;
  assign det_next = DetW'(part_sum);

  // ---- Reciprocals: 1/|det|, then (AFFINE) 1/q_i of each vertex -------------------------------
  logic                recip_start, recip_done, recip_valid_q, det_pend_q;
  logic [RecipW:0]     recip_r, rdet_q;
  logic [MsbW-1:0]     recip_msb, msbdet_q;
  logic [DetW-1:0]     det_abs, recip_x;
  logic [ShiftW-1:0]   grad_shift;
  logic                planes_abort, det_start, av_start, affine_q;
  logic [1:0]          av_i;
  // The determinant is judged in StDet1's last clock: a triangle that covers nothing (det = 0 or
  // an empty box) is skipped, any other goes on with |det|.
  logic                det_judge;
  assign det_judge   = (state_q == StDet1) && emul_done;
  assign det_abs     = det_next[DetW-1] ? DetW'(-det_next) : DetW'(det_next);
  assign tri_skip    = det_judge && ((det_next == 0) || box_empty);
  assign det_start   = det_judge && (det_next != 0) && !box_empty;
  assign recip_start = det_start || av_start;
  assign recip_x     = det_start ? det_abs : DetW'(q_v[av_i]);  // AFFINE's q_i
  assign planes_abort = abort_i || tri_skip;
  assign grad_shift = ShiftW'(RecipW) + ShiftW'(msbdet_q) - ShiftW'(GF);

  logic                recip_mul_start;      // (setup's unit has its own multiplier)
  logic [RecipW+2:0]   recip_mul_a, recip_mul_b;
  logic                recip_busy;           // (setup waits for done_o)
  logic [RecipW:0]     recip_r0;             // (the table value: setup always takes Newton steps)
  logic                recip_norm_shift;     // (nothing shifts in step)
  htx_recip #(.XWidth(DetW), .W(RecipW), .K(RecipK), .G(RecipG), .Steps(NrSteps),
              .Iterative(1'b0), .SerialNorm(1'b0)) u_recip (
    .clk_i, .rst_ni,
    .abort_i,
    .start_i     (recip_start),
    .en_i        (1'b1),
    .table_only_i(1'b0),
    .alt_i       (1'b0),
    .x_i         (recip_x),
    .busy_o      (recip_busy),
    .done_o      (recip_done),
    .r_o         (recip_r),
    .r0_o        (recip_r0),
    .msb_o       (recip_msb),
    .mul_start_o (recip_mul_start),
    .mul_a_o     (recip_mul_a),
    .mul_b_o     (recip_mul_b),
    .mul_done_i  (1'b0),
    .mul_p_i     ('0),
    .norm_shift_o(recip_norm_shift)
  );
  logic unused_recip_mul;
  assign unused_recip_mul = ^{recip_mul_start, recip_mul_a, recip_mul_b, recip_busy, recip_r0,
                              recip_norm_shift};

  // ---- Planes: z, r, g, b, q, uq, vq, and for AFFINE ua, va -------------------------------------
  // Nine plane units working in parallel.
  logic                 apl_start;         // AFFINE's vertex coordinates are ready (pulse)
  logic [1:0]           apl_done;          // the ua, va planes are done
  logic [3*LocW-1:0]    ua_v, va_v;        // AFFINE's u_i, v_i, vertex i at LocW i
  logic                 plane_start_q;
  logic [NP-1:0]        plane_done;
  logic [AW-1:0]        pgx [NP];
  logic [AW-1:0]        pgy [NP];
  logic [AW-1:0]        pst [NP];

  localparam int unsigned GWU = UQ + DW + 2 + GF + 1;     // full-precision gradient of uq, vq
  logic [6*GWU-1:0] lg;  // uq x, uq y, vq x, vq y, q x, q y, gradient k at GWU k

  // Colour channel values of the colour planes: channel c of vertex i at 3 c + i.
  logic [CB-1:0] cv [9];
  for (genvar c = 0; c < 3; c++) begin : g_cv
    for (genvar i = 0; i < 3; i++) begin : g_v
      if (PerspColor) begin : g_cq
        assign cv[3*c+i] = CB'(rgba_v[i][8*c +: 8]) * CB'(q_v[i]);  // c q: 8 x q_bits at setup
      end else begin : g_c
        assign cv[3*c+i] = CB'(rgba_v[i][8*c +: 8]);
      end
    end
  end

  // Every plane's vertex values in VSW bits, the widest plane's: plane p, vertex i at 3 p + i, in
  // the order z, r, g, b, q, uq, vq, ua, va. Plane p's own value width is plane_vb(p); the low
  // bits of its words are its values.
  localparam int unsigned VZC = (ZBits > CB) ? ZBits : CB;     // z, colour
  localparam int unsigned VQU = (QBits > UQ) ? QBits : UQ;     // q, uq, vq
  localparam int unsigned VS  = (VQU > VZC) ? VQU : VZC;
  localparam int unsigned VSW = (LocW > VS) ? LocW : VS;       // ua, va
  function automatic int unsigned plane_vb(input int unsigned p);
    if (p == 0)      plane_vb = ZBits;
    else if (p <= 3) plane_vb = CB;
    else if (p == 4) plane_vb = QBits;
    else if (p <= 6) plane_vb = UQ;
    else             plane_vb = LocW;
  endfunction
  logic [NP*3*VSW-1:0] sv;
  logic                unused_sv;
  assign unused_sv = ^sv;  // the parallel units take only their planes' low bits
  for (genvar i = 0; i < 3; i++) begin : g_sv
    assign sv[VSW*(0+i) +: VSW] = VSW'(z_v[i]);
    for (genvar c = 0; c < 3; c++) begin : g_c
      assign sv[VSW*(3*(1+c)+i) +: VSW] = VSW'(cv[3*c+i]);
    end
    assign sv[VSW*(12+i) +: VSW] = VSW'(q_v[i]);
    assign sv[VSW*(15+i) +: VSW] = VSW'($signed(uq_v[UQ*i +: UQ]));
    assign sv[VSW*(18+i) +: VSW] = VSW'($signed(vq_v[UQ*i +: UQ]));
    assign sv[VSW*(21+i) +: VSW] = VSW'($signed(ua_v[LocW*i +: LocW]));
    assign sv[VSW*(24+i) +: VSW] = VSW'($signed(va_v[LocW*i +: LocW]));
  end

  // One plane unit per plane; ua and va (planes 7, 8) start when AFFINE's vertex coordinates are
  // ready. The unit of q, uq, vq also gives its gradients at full precision to the LOD shift.
  for (genvar p = 0; p < NP; p++) begin : g_plane
    localparam int unsigned VBP = plane_vb(p);
    localparam int unsigned AP  = VBP + GF + 2;
    localparam int unsigned GP  = VBP + DW + 2 + GF + 1;
    logic [AP-1:0] gx, gy, st;
    logic [GP-1:0] gxw, gyw;
    htx_raster_plane #(.VB(VBP), .Signed(p >= 5), .DW(DW), .W(RecipW), .GF(GF),
                       .ShiftW(ShiftW)) u_plane (
      .clk_i, .rst_ni,
      .abort_i      (planes_abort),
      .start_i      ((p < 7) ? plane_start_q : apl_start),
      .a0_i(sv[VSW*(3*p) +: VBP]), .a1_i(sv[VSW*(3*p+1) +: VBP]), .a2_i(sv[VSW*(3*p+2) +: VBP]),
      .dx1_i(dx1), .ndy1_i(ea[0]), .ndx2_i(eb[2]), .dy2_i(dy2),
      .dxs_i(dxs), .dys_i(dys),
      .recip_valid_i(recip_valid_q),
      .r_i          (rdet_q),
      .shift_i      (grad_shift),
      .det_neg_i    (det_neg_q),
      .done_o       (plane_done[p]),
      .gx_o(gx), .gy_o(gy), .start_o(st),
      .gxw_o(gxw), .gyw_o(gyw)
    );
    assign pgx[p] = AW'(gx);
    assign pgy[p] = AW'(gy);
    assign pst[p] = AW'(st);
    if ((p >= 4) && (p <= 6)) begin : g_lod
      localparam int unsigned L = (p == 4) ? 4 : 2 * (p - 5);  // lg: uq x, y, vq x, y, q x, y
      assign lg[GWU*L +: GWU]     = GWU'($signed(gxw));
      assign lg[GWU*(L+1) +: GWU] = GWU'($signed(gyw));
    end else begin : g_no_lod
      logic unused_w;
      assign unused_w = ^{gxw, gyw};
    end
  end
  assign apl_done = plane_done[8:7];

  // ---- LOD gradients: one block shift for all six (htx_raster_setup_lod) -----------------------
  htx_raster_setup_lod #(.GWU(GWU), .GradW(GradW)) u_lod (
    .grad_i (lg),
    .grad_o (tri_lod_g_o),
    .shift_o(tri_lod_shift_o)
  );
  assign tri_dfg_o = lg;  // (DIVFREE takes them at full precision)

  // ---- AFFINE: the vertices' u_i, v_i and their planes (htx_raster_setup_affine) ---------------
  logic av_done;
  htx_raster_setup_affine #(.RecipW(RecipW), .TF(TF), .UQ(UQ), .LocW(LocW), .MsbW(MsbW)) u_affine (
    .clk_i, .rst_ni,
    .abort_i       (planes_abort),
    .start_i       (recip_done && det_pend_q && affine_q),
    .recip_start_o (av_start),
    .vtx_o         (av_i),
    .recip_done_i  (recip_done),
    .recip_r_i     (recip_r),
    .recip_msb_i   (recip_msb),
    .uq_i          (uq_v),
    .vq_i          (vq_v),
    .late_ok_i     ((state_q == StWait) && !plane_start_q),
    .planes_start_o(apl_start),
    .planes_done_i (apl_done),
    .release_i     ((state_q == StOut) && tri_ready_i),
    .ua_o          (ua_v),
    .va_o          (va_v),
    .done_o        (av_done)
  );

  // ---- Sequencer -------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q       <= StIdle;
      for (int i = 0; i < 3; i++) e_q[i] <= '0;
      rdet_q        <= '0;
      msbdet_q      <= '0;
      det_pend_q    <= 1'b0;
      affine_q      <= 1'b0;
      det_q         <= '0;
      det_neg_q     <= 1'b0;
      edge_k_q      <= '0;
      edge_half_q   <= 1'b0;
      part_q        <= '0;
      plane_start_q <= 1'b0;
      recip_valid_q <= 1'b0;
    end else if (abort_i) begin
      state_q       <= StIdle;
      plane_start_q <= 1'b0;
      recip_valid_q <= 1'b0;
      det_pend_q    <= 1'b0;
    end else begin
      plane_start_q <= 1'b0;
      if (det_start) det_pend_q <= 1'b1;
      if (recip_done && det_pend_q) begin
        recip_valid_q <= 1'b1;
        det_pend_q    <= 1'b0;
        rdet_q        <= recip_r;
        msbdet_q      <= recip_msb;
      end
      unique case (state_q)
        StIdle: if (take && !state_bad) begin
          affine_q <= (rec_method == htx_raster_pkg::MethodAffine);
          plane_start_q <= 1'b1;  // (n_x, n_y do not wait for the determinant)
          recip_valid_q <= 1'b0;
          state_q       <= StDet0;
        end
        StDet0: if (emul_done) begin part_q <= part_sum; state_q <= StDet1; end
        StDet1: if (emul_done) begin
          det_q     <= det_abs;
          det_neg_q <= det_next[DetW-1];
          edge_k_q  <= '0;
          edge_half_q <= 1'b0;
          // (judged in this clock: det_judge below)
        end
        StEdges: if (emul_done) begin
          if (!edge_half_q) begin
            part_q      <= part_sum;
            edge_half_q <= 1'b1;
          end else begin
            e_q[edge_k_q]     <= part_sum;
            edge_half_q <= 1'b0;
            edge_k_q    <= edge_k_q + 1'b1;
            if (edge_k_q == 2'd2) state_q <= StWait;
          end
        end
        // (Not in the clock the planes start: their done flags still show the last triangle's.)
        StWait: begin
          if (!plane_start_q && (&plane_done[6:0]) && (!affine_q || av_done)) begin
            state_q <= StOut;
          end
        end
        StOut: if (tri_ready_i) state_q <= StIdle;
        default: state_q <= StIdle;
      endcase
      // The determinant judged (StDet1's last clock): skip the triangle or go on to the edges.
      if (det_judge) begin
        if (tri_skip) state_q <= StIdle;
        else state_q <= StEdges;
      end
    end
  end

  // ---- Outputs ---------------------------------------------------------------------------------
  assign tri_valid_o     = (state_q == StOut);
  assign tri_state_o     = st_v;
  assign tri_flat_rgba_o = rgba_v[0];  // vertex 0 is never reordered
  assign tri_x_lo_o      = 13'(x_lo);
  assign tri_x_hi_o      = 13'(x_hi);
  assign tri_y_lo_o      = 13'(y_lo);
  assign tri_y_hi_o      = 13'(y_hi);
  for (genvar k = 0; k < 3; k++) begin : g_edge_out
    assign tri_a_o[DW*k +: DW] = ea[k];
    assign tri_b_o[DW*k +: DW] = eb[k];
    assign tri_e_o[EW*k +: EW] = e_q[k];
  end
  for (genvar p = 0; p < NP; p++) begin : g_plane_out
    assign tri_p_o[3*AW*p +: 3*AW] = {pst[p], pgy[p], pgx[p]};
  end
  assign tri_u_off_o = u_off_v;
  assign tri_v_off_o = v_off_v;
  assign tri_thr_o = ethr;
  assign tri_a_zero_o = ea_zero;
  assign tri_dneg_o = det_neg_q;
  assign busy_o    = (state_q != StIdle) && (state_q != StOut);
  assign stall_o   = (state_q == StOut) && !tri_ready_i;
endmodule
