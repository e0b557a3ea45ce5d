// Triangle setup (docs/model.md §2, docs/raster.md): determinant, winding (the model swaps vertices
// 1 and 2 for a negative determinant: both windings are drawn), edge functions with the top-left rule, the pixel
// box clipped to the screen, 1/det from the shared reciprocal unit, and the planes of z, the colour
// channels (c q with PerspColor), q, uq, vq (with some method built) and, for AFFINE, the vertex
// texel coordinates u_i = uq_i / q_i (three more reciprocals from the same unit, docs/model.md §5.1), and the LOD
// unit's block-shifted gradients (§6). Edge values and plane values are delivered at the box's first pixel centre
// (256 x_lo + 128, 256 y_lo + 128), where traversal starts. Zero-area triangles and triangles whose
// box holds no pixel centre of the screen are consumed here and never reach traversal.
module htx_raster_setup #(
  parameter int unsigned XyIntBits = 16,
  parameter int unsigned ZBits     = 24,
  parameter int unsigned GF        = 24,
  parameter int unsigned RecipW    = 32,
  parameter int unsigned RecipK    = 10,
  parameter int unsigned RecipG    = 2,
  parameter int unsigned NrSteps   = 2,
  parameter bit          Iterative = 1'b0,
  parameter int unsigned QBits     = 32,
  parameter int unsigned UvIntBits = 16,
  parameter int unsigned TF        = 16,
  parameter int unsigned GradW     = 24,       // lod_grad_bits
  parameter logic [4:0]  Methods   = 5'b01111, // bit m: method m built (htx::Method order)
  parameter bit          PerspColor = 1'b1,
  // The LOD gradients are built (a trilinear texture unit or DIVFREE takes them); 0: tri_lod_*_o
  // are 0 and the LOD block is left out.
  parameter bit          Lod       = 1'b1,
  // The reciprocals go to a unit outside (rq_*: the `icebreaker` divider's, shared) instead of a
  // unit of setup's own.
  parameter bit          ExtRecip  = 1'b0,
  // Setup works on the input stage's registers, which hold the record until setup releases it
  // (rec_ready_o), instead of on a copy of its own taken at the start. The input stage then
  // assembles the next record only after the release (31 clocks a triangle, hidden whenever
  // traversal or setup itself takes longer), and setup has no vertex registers.
  parameter bit          HoldRecord = 1'b0,
  // With HoldRecord, Iterative and not PerspColor: the record's words stay in the FIFO's block RAM
  // until setup releases the record, and the plane values and AFFINE's q_i, uq_i, vq_i are read
  // from there (vr_*) instead of from the input stage's registers through multiplexers, which
  // synthesis then removes with the registers (the input stage keeps x, y, the state word, the
  // offsets and the colours, which setup takes without a multiplexer).
  parameter bit          ValuesInFifo = 1'b0,
  // With Iterative: AFFINE's u, v planes (7, 8) go to the traversal's RAM in the places of the uq,
  // vq planes (5, 6), which an AFFINE triangle does not use; the traversal keeps seven planes.
  parameter bit          FoldUv = 1'b0,
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
  // Iterative: the planes go instead (tri_p_o is zero) to the traversal's plane RAM, one word a
  // clock as each is done: pl_sel_o 0 gx, 1 gy, 2 start of plane pl_idx_o (mod 2^AW). They are all
  // written before tri_valid_o rises, into the next triangle's regions of that RAM. The
  // edges go there too, as planes 0..2 (a_k, b_k and E_k, the threshold-1 ones negated; tri_e_o
  // then matters only for its signs), and the attribute planes follow at 3 on.
  output logic                 pl_we_o,
  output logic [1:0]           pl_sel_o,
  output logic [3:0]           pl_idx_o,
  output logic [AW:0]          pl_data_o,     // a gradient at [AW:1], a start value at [AW-1:0]
  output logic [31:0]          tri_u_off_o, tri_v_off_o,
  output logic [6*GradW-1:0]   tri_lod_g_o,   // g_ux, g_uy, g_vx, g_vy, g_qx, g_qy (block-shifted)
  output logic [7:0]           tri_lod_shift_o,
  output logic [6*(UQ+DW+2+GF+1)-1:0] tri_dfg_o, // the six at full precision (signed): DIVFREE's seed

  output logic                 busy_o,        // computing (not waiting for input or traversal)
  output logic                 stall_o,       // a finished triangle waits for traversal
  output logic                 taken_o,       // a triangle was taken from the input (pulse)
  output logic                 err_o,         // a triangle asked for what is not built (pulse)

  // ExtRecip: a reciprocal request (a pulse with its operand) and its result (rq_done_i pulses with
  // rq_r_i and rq_msb_i, as htx_recip's done_o, r_o and msb_o with NrSteps Newton steps).
  output logic                 rq_start_o,
  output logic [DetW-1:0]      rq_x_o,
  input  logic                 rq_done_i,
  input  logic [RecipW:0]      rq_r_i,
  input  logic [MsbW-1:0]      rq_msb_i,

  // ValuesInFifo: read word vr_off_o of the record (0 the state word, then vertex_record.h's
  // order); it is on vr_data_i in the next clock.
  output logic                 vr_req_o,
  output logic [4:0]           vr_off_o,
  input  logic [31:0]          vr_data_i
);
  localparam int unsigned BoxW   = XW - 7;      // signed pixel index of a box bound
  localparam int unsigned ShiftW = 8;

  // StCoef (ValuesInFifo): the edge coefficients are read from the record in the FIFO.
  typedef enum logic [2:0] {StIdle, StCoef, StDet0, StDet1, StDetChk, StEdges, StWait, StOut} state_e;

  state_e state_q;
  logic [31:0]            st_v;      // the record's values (HoldRecord: the input stage's)
  logic signed [XW-1:0]   x_v [3];
  logic signed [XW-1:0]   y_v [3];
  logic [ZBits-1:0]       z_v [3];
  logic [31:0]            rgba_v [3];
  logic [QBits-1:0]       q_v [3];
  logic [UQ-1:0]          uq_v [3];
  logic [UQ-1:0]          vq_v [3];
  logic [31:0]            u_off_v, v_off_v;
  logic signed [DetW-1:0] det_q;     // |det|, from StDet1 on (edge 1 starts from it)
  logic                   det_neg_q;
  logic [3:0]             edge_k_q;
  logic                   edge_half_q;
  logic signed [EW-1:0]   e_q [3];
  logic signed [EW-1:0]   part_q;    // the first product of det or of an edge value

  // ---- Accept and check the state word --------------------------------------------------------
  // A method this build leaves out, a subdivision length outside 2..64 or a depth function beyond
  // `always` is consumed, draws nothing and raises ERR_STATE.
  localparam bit Textured = |Methods;  // texture mapping built (some perspective method)
  logic take, state_bad, tri_skip;
  logic [2:0] rec_method;
  assign rec_method  = rec_state_i[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3];
  // take: setup starts on a record. Without HoldRecord it copies the record and releases it at
  // once; with it, it releases it when nothing reads it any more: a bad state word at once, a
  // triangle that draws nothing after the determinant, any other when traversal takes it.
  assign take        = rec_valid_i && (state_q == StIdle) && !hold_i;
  assign rec_ready_o = HoldRecord ? ((take && state_bad) || tri_skip || ((state_q == StOut) && tri_ready_i))
                                  : ((state_q == StIdle) && !hold_i);
  htx_raster_state_check #(.Methods(Methods)) u_state_check (.state_i(rec_state_i), .bad_o(state_bad));
  assign taken_o     = take;
  assign err_o       = take && state_bad;

  // ---- The record's values -------------------------------------------------------------------
  if (HoldRecord) begin : g_rec_held
    assign st_v    = rec_state_i;
    assign u_off_v = rec_u_off_i;
    assign v_off_v = rec_v_off_i;
    for (genvar i = 0; i < 3; i++) begin : g_v
      assign x_v[i]    = rec_x_i[XW*i +: XW];
      assign y_v[i]    = rec_y_i[XW*i +: XW];
      assign z_v[i]    = rec_z_i[ZBits*i +: ZBits];
      assign rgba_v[i] = rec_rgba_i[32*i +: 32];
      assign q_v[i]    = rec_q_i[QBits*i +: QBits];
      assign uq_v[i]   = rec_uq_i[UQ*i +: UQ];
      assign vq_v[i]   = rec_vq_i[UQ*i +: UQ];
    end
  end else begin : g_rec_copy
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        st_v    <= '0;
        u_off_v <= '0;
        v_off_v <= '0;
        for (int i = 0; i < 3; i++) begin
          x_v[i] <= '0; y_v[i] <= '0; z_v[i] <= '0; rgba_v[i] <= '0;
          q_v[i] <= '0; uq_v[i] <= '0; vq_v[i] <= '0;
        end
      end else if (take && !state_bad && !abort_i) begin
        st_v    <= rec_state_i;
        u_off_v <= rec_u_off_i;
        v_off_v <= rec_v_off_i;
        for (int i = 0; i < 3; i++) begin
          x_v[i]    <= rec_x_i[XW*i +: XW];
          y_v[i]    <= rec_y_i[XW*i +: XW];
          z_v[i]    <= rec_z_i[ZBits*i +: ZBits];
          rgba_v[i] <= rec_rgba_i[32*i +: 32];
          q_v[i]    <= rec_q_i[QBits*i +: QBits];
          uq_v[i]   <= rec_uq_i[UQ*i +: UQ];
          vq_v[i]   <= rec_vq_i[UQ*i +: UQ];
        end
      end
    end
  end

  // ---- Deltas, box -----------------------------------------------------------------------------

  // Pixel centres 256 i + 128 inside [min, max]: ceil((min - 128) / 256) .. floor((max - 128) / 256),
  // clipped to the screen. The bounds come from the vertices the edges' signs pick (below): at once
  // through multiplexers, or (ValuesInFifo) one at a time from the record's words in the FIFO.
  logic signed [BoxW-1:0] x_lo, x_hi, y_lo, y_hi;
  logic                   box_empty;
  logic [4:0]             bx_off;     // ValuesInFifo: the word of the bound rd_idx[1:0]
  assign box_empty = (x_lo > x_hi) || (y_lo > y_hi);

  // First pixel centre of the box, relative to each vertex.
  logic signed [DW-1:0] pxs, pys;
  assign pxs = (DW'(x_lo) <<< 8) + DW'(128);
  assign pys = (DW'(y_lo) <<< 8) + DW'(128);
  logic signed [DW-1:0] dxs, dys;  // the first pixel centre relative to vertex 0
  logic signed [XW-1:0] x0_v, y0_v; // vertex 0
  assign dxs = pxs - DW'(x0_v);
  assign dys = pys - DW'(y0_v);

  // The edges of the triangle as given, in the order v0 v1, v1 v2, v2 v0. The model swaps v1 and v2
  // when det < 0, which reverses every edge: E' = -E and, the top-left rule being antisymmetric,
  // threshold' = 1 - threshold (an edge of zero length has det = 0 and is never drawn). Traversal
  // takes the winding (tri_dneg_o) and tests the reversed edges from these (docs/raster.md), so
  // setup swaps nothing: no vertex multiplexers.
  logic signed [DW-1:0] ea [3];
  logic signed [DW-1:0] eb [3];
  logic [2:0]           ethr, ea_zero;
  // Each coefficient's sign and whether it is zero (the thresholds and the box take only these).
  logic [2:0]           ea_neg, eb_neg, eb_zero;
  // ValuesInFifo keeps the coefficients in a ring of registers (g_coef_read): ea, eb are its taps
  // while it is at home (ring_pos 0), and the jobs take their a operand from its head (ring_head),
  // the coefficient whose home index is ring_pos (0..5: b_0, b_1, b_2, a_2, a_1, a_0); the job
  // logic turns it (ring_turn) to the one a job needs.
  logic signed [DW-1:0] ring_head;
  logic [2:0]           ring_pos;
  logic                 ring_turn;
  // The position the shared plane unit wants the ring at (ValuesInFifo: it takes the b operand
  // of n's products from ring_q[3], htx_raster_plane Ring); 0 (home) while it is idle.
  logic [2:0]           plane_ring_want;
  // ValuesInFifo: the record reader asks for word rd_off (rd_req) and takes it from vr_data_i a
  // clock later (rd_take); rd_idx counts the words: 0..7 the edge coefficients', 8..11 the box's.
  logic                 rd_req, rd_take;
  logic [4:0]           rd_off;
  logic [3:0]           rd_idx;
  logic                 cf_done;  // the coefficients are ready (a pulse; at take without a reader)
  if (!ValuesInFifo) begin : g_coef_comb
    // Six subtractors on the vertex registers.
    for (genvar k = 0; k < 3; k++) begin : g_k
      localparam int unsigned K1 = (k + 1) % 3;
      // a = -(y_k1 - y_k), formed as y_k - y_k1: one subtractor, not a subtractor and a negation.
      assign ea[k] = DW'(y_v[k]) - DW'(y_v[K1]);
      assign eb[k] = DW'(x_v[K1]) - DW'(x_v[k]);
    end
    for (genvar k = 0; k < 3; k++) begin : g_flags
      assign ea_neg[k]  = ea[k][DW-1];
      assign eb_neg[k]  = eb[k][DW-1];
      assign ea_zero[k] = (ea[k] == 0);
      assign eb_zero[k] = (eb[k] == 0);
    end
    assign ring_head = '0;
    assign ring_pos  = '0;
    logic unused_ring;
    assign unused_ring = ring_turn;
    assign x0_v    = x_v[0];
    assign y0_v    = y_v[0];
    assign rd_req  = 1'b0;
    assign rd_take = 1'b0;
    assign rd_off  = '0;
    assign rd_idx  = 4'd12;
    assign cf_done = take && !state_bad;
  end else begin : g_coef_read
    // One subtractor, on the record's words in the FIFO: x0 x1 x2 x0, then y0 y2 y1 y0, a word
    // every two clocks (ask, take). From the second word of each four on, the word minus the one
    // before is b_0, b_1, b_2 (x_k1 - x_k), then a_2, a_1, a_0 (y_k - y_k1, read backwards), each
    // into its register. Vertex 0 is kept for dxs, dys. 16 clocks a triangle, before the
    // determinant, which needs the coefficients. The same reader then reads the box's four bounds
    // (words 8..11, g_box_read), whose vertices the coefficients' signs pick.
    logic [3:0]           cf_q;     // the word being read (0 .. 11); 12: done
    logic                 cf_got_q; // its word is on vr_data_i
    logic signed [XW-1:0] cf_prev_q, cf_x0_q, cf_y0_q, cf_word;
    logic signed [DW-1:0] cf_diff;
    logic [1:0]           cf_v;     // the vertex read
    // The coefficients in a ring of six registers, shifted in as they are formed (b_0, b_1, b_2,
    // a_2, a_1, a_0: ring_q[0] ends with b_0), so a job's a operand is always the head and needs no
    // six-way multiplexer: the ring turns by one a clock (ring_q[i] <= ring_q[i + 1], the head to
    // the tail) until the coefficient a job needs is at the head. A coefficient and its partner in
    // the determinant are three apart (b_0 a_2, b_2 a_0), so ring_q[3] is the other factor of a
    // determinant product (the plane unit's dy2 input). The plane unit then turns it to the
    // coefficient each of n's products takes from ring_q[3] (plane_ring_want), and it turns home
    // before the triangle is handed over, whose taps (ea, eb) the traversal reads. The signs and
    // zero flags shift in alongside and do not turn (one zero detector on cf_diff instead of six on
    // the registers).
    logic signed [DW-1:0] ring_q [6];
    logic [2:0]           ring_pos_q;
    logic [5:0]           cneg_q, czero_q;  // by home index
    logic                 c_load;
    assign c_load = cf_got_q && !cf_q[3] && (cf_q[1:0] != 2'd0);  // words 1-3 and 5-7
    always_comb begin
      unique case (cf_q[2:0])
        3'd1, 3'd6: cf_v = 2'd1;
        3'd2, 3'd5: cf_v = 2'd2;
        default:    cf_v = 2'd0;
      endcase
    end
    assign rd_req  = (cf_q != 4'd12) && !cf_got_q;
    assign rd_take = cf_got_q;
    assign rd_idx  = cf_q;
    // x: word 0 of a vertex, y: word 1
    assign rd_off  = cf_q[3] ? bx_off : htx_raster_pkg::rec_vert_word(cf_v, {3'd0, cf_q[2]});
    assign cf_word = $signed(vr_data_i[XW-1:0]);
    assign cf_diff = DW'(cf_word) - DW'(cf_prev_q);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        cf_q      <= 4'd12;
        cf_got_q  <= 1'b0;
        cf_prev_q <= '0;
        cf_x0_q   <= '0;
        cf_y0_q   <= '0;
      end else if (abort_i) begin
        cf_q     <= 4'd12;
        cf_got_q <= 1'b0;
      end else if (take && !state_bad) begin
        cf_q     <= '0;
        cf_got_q <= 1'b0;
      end else if (cf_q != 4'd12) begin
        cf_got_q <= !cf_got_q;
        if (cf_got_q) begin
          if (!cf_q[3]) cf_prev_q <= cf_word;
          if (cf_q == 4'd0) cf_x0_q <= cf_word;
          if (cf_q == 4'd4) cf_y0_q <= cf_word;
          cf_q <= cf_q + 4'd1;
        end
      end
    end
    // A triangle taken starts at home: the six words shifted in then replace whatever the ring held.
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ring_pos_q <= '0;
      end else if (abort_i || (take && !state_bad)) begin
        ring_pos_q <= '0;
      end else if (ring_turn) begin
        ring_pos_q <= (ring_pos_q == 3'd5) ? 3'd0 : ring_pos_q + 3'd1;
      end
    end
    // (No reset: the ring is written before it is read, six words for every triangle.)
    always_ff @(posedge clk_i) begin
      if (c_load || ring_turn) begin
        for (int i = 0; i < 5; i++) ring_q[i] <= ring_q[i + 1];
        ring_q[5] <= c_load ? cf_diff : ring_q[0];
      end
      if (c_load) begin
        cneg_q  <= {cf_diff[DW-1], cneg_q[5:1]};
        czero_q <= {cf_diff == '0, czero_q[5:1]};
      end
    end
    assign cf_done = (cf_q == 4'd7) && cf_got_q && !abort_i;
    for (genvar k = 0; k < 3; k++) begin : g_k
      assign eb[k]      = ring_q[k];      // (at home)
      assign ea[k]      = ring_q[5 - k];
      assign eb_neg[k]  = cneg_q[k];
      assign ea_neg[k]  = cneg_q[5 - k];
      assign eb_zero[k] = czero_q[k];
      assign ea_zero[k] = czero_q[5 - k];
    end
    assign ring_head = ring_q[0];
    assign ring_pos  = ring_pos_q;
    assign x0_v = cf_x0_q;
    assign y0_v = cf_y0_q;
    logic unused_xy;
    assign unused_xy = ^{x_v[0], x_v[1], x_v[2], y_v[0], y_v[1], y_v[2]};
  end
  for (genvar k = 0; k < 3; k++) begin : g_edge
    // y points down and inside is E > 0: an edge going up is a left edge, a horizontal edge going
    // right a top edge; pixel centres exactly on them belong to this triangle (threshold 0).
    // (Signs and zero tests rather than "> 0": Yosys 0.23 builds a comparison as a carry chain,
    // a LUT and a carry a bit; docs/area.md.)
    assign ethr[k] = !((!ea_neg[k] && !ea_zero[k]) ||
                       (ea_zero[k] && !eb_neg[k] && !eb_zero[k]));
  end
  // Iterative: the thresholds a clock later from a register (the coefficients hold from StDet0,
  // and the first use is in StEdges), so their tests do not run on into the products that take
  // them as a negation (`icebreaker`'s critical path, docs/raster.md).
  logic [2:0] ethr_s;
  if (Iterative) begin : g_thr_q
    logic [2:0] ethr_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) ethr_q <= '0;
      else         ethr_q <= ethr;
    end
    assign ethr_s = ethr_q;
  end else begin : g_thr
    assign ethr_s = ethr;
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
  // height). A limit of 2^(BoxW-1) or more exceeds every bound b can hold (the icebreaker
  // configuration's boxes are 13 bits signed), so it clips nothing; in BoxW bits its lim - 1
  // would wrap negative and empty the box.
  function automatic logic signed [BoxW-1:0] clip_hi(input logic signed [BoxW-1:0] b,
                                                     input logic [12:0] lim);
    logic signed [BoxW-1:0] top;
    logic                   beyond;
    top = $signed(BoxW'({1'b0, lim}) - BoxW'(1));
    if (BoxW <= 13) beyond = (32'(lim) >> (BoxW - 1)) != 0;
    else beyond = 1'b0;
    clip_hi = (!beyond && (b > top)) ? top : b;
  endfunction

  if (!ValuesInFifo) begin : g_box_mux
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
    assign bx_off = '0;
    logic unused_rd;
    assign unused_rd = ^{bx_off, rd_idx, rd_take};
  end else begin : g_box_read
    // minx, maxx, miny, maxy in turn, as the record reader's words 8..11 (after the edge
    // coefficients, g_coef_read), on one adder and one comparison; setup needs them only when the
    // determinant is done (tens of clocks later). They hold until the next triangle is taken.
    logic [1:0]             bx_q;      // the bound being read
    logic                   bx_min, bx_y;
    logic [1:0]             bx_sel;
    logic signed [XW-1:0]   bv;
    logic signed [BoxW-1:0] bb, bres;
    logic signed [BoxW-1:0] x_lo_q, x_hi_q, y_lo_q, y_hi_q;
    assign bx_q   = rd_idx[1:0];  // (words 8..11: rd_idx[3] set, rd_idx[2] clear)
    logic unused_idx;
    assign unused_idx = rd_idx[2];
    assign bx_min = !bx_q[0];  // 0 minx, 1 maxx, 2 miny, 3 maxy
    assign bx_y   = bx_q[1];
    assign bx_sel = (bx_q == 2'd0) ? minx_sel : (bx_q == 2'd1) ? maxx_sel
                  : (bx_q == 2'd2) ? miny_sel : maxy_sel;
    assign bx_off = htx_raster_pkg::rec_vert_word(bx_sel, bx_y ? 4'd1 : 4'd0);  // x, y: words 0, 1 of a vertex
    assign bv     = $signed(vr_data_i[XW-1:0]);
    assign bb     = BoxW'((bv + (bx_min ? XW'(127) : -XW'(128))) >>> 8);
    assign bres   = bx_min ? (bb[BoxW-1] ? '0 : bb) : clip_hi(bb, bx_y ? height_i : width_i);
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        x_lo_q <= '0;
        x_hi_q <= '0;
        y_lo_q <= '0;
        y_hi_q <= '0;
      end else if (!abort_i && rd_take && rd_idx[3]) begin
        unique case (bx_q)
          2'd0:    x_lo_q <= bres;
          2'd1:    x_hi_q <= bres;
          2'd2:    y_lo_q <= bres;
          default: y_hi_q <= bres;
        endcase
      end
    end
    assign x_lo = x_lo_q;
    assign x_hi = x_hi_q;
    assign y_lo = y_lo_q;
    assign y_hi = y_hi_q;
  end

  // ---- Determinant and edge values -------------------------------------------------------------
  // Nine plane units in parallel (`full`): a multiplier of setup's own, eight products. One plane
  // unit for all planes (Iterative, `icebreaker`): the products run on that unit's multiplier and
  // accumulator as jobs before the planes start (its job_* port), ten of them, and setup has no
  // multiplier or adder for them.
  localparam bit SharedPlanes = Iterative;
  logic                     emul_done;
  logic signed [EW-1:0]     part_sum;
  logic [1:0]               ek;
  logic                     job_req, job_neg, job_acc, job_done;
  logic signed [DW-1:0]     job_a;
  logic [2:0]               job_bsel;
  logic                     job_we;    // SharedPlanes: the job's sum is a word for the plane RAM
  logic [1:0]               job_wsel;
  logic [1:0]               job_widx;
  logic [EW-1:0]            job_sum;
  assign ek = edge_k_q[1:0];
  if (!SharedPlanes) begin : g_edge_mul
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
          if (!edge_half_q) begin emul_a = ea[ek]; emul_b = dxs; end
          else              begin emul_a = eb[ek]; emul_b = dys; end
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
      // (This branch is `full`'s, which negates |det| instead of redoing det: no redo_q term.)
      .neg_i  ((state_q == StEdges) ? ethr_s[ek] : (state_q == StDet1)),
      .extra_i(1'b0),
      .done_o (emul_done),
      .p_o    (emul_p)
    );

    // det = dx1 dy2 + (-(dx2 dy1)) and E_k = a_k (px - x_k) + b_k (py - y_k): the multiplier
    // negates det's second product itself (neg_i), so one adder serves both.
    logic signed [EW-1:0]   part_base;
    always_comb begin
      if ((state_q == StDet0) || ((state_q == StEdges) && !edge_half_q)) begin
        part_base = ((state_q == StEdges) && (ek == 2'd1)) ? EW'(det_q) : '0;  // det_q: |det|
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
      .sub_i((state_q == StEdges) && !edge_half_q && (ethr_s[ek] ^ det_neg_q)),
      .sum_o(part_sum)
    );
    assign job_req  = 1'b0;
    assign job_neg  = 1'b0;
    assign job_acc  = 1'b0;
    assign job_a    = '0;
    assign job_bsel = '0;
    assign ring_turn = 1'b0;
    logic unused_ring_head;
    assign unused_ring_head = ^{ring_head, ring_pos, plane_ring_want};
    assign job_we   = 1'b0;
    assign job_wsel = '0;
    assign job_widx = '0;
    logic unused_job;
    assign unused_job = ^{job_done, job_sum, edge_k_q[3:2]};
  end else begin : g_edge_jobs
    // The jobs (job_bsel: 0 dy2, 1 -dy1 = a_0, 2 dxs, 3 dys, 4 the constant 2). det = b_0 a_2 -
    // b_2 a_0 (StDet0, StDet1; both negated for DetRedo). Then, by edge_k_q = j: E_0 = a_0 dxs +
    // b_0 dys (j 0, 1); E_1 = a_1 dxs + b_1 dys + det, det's two products again instead of a
    // register and an adder for +-det (j 2 .. 5); E_2 = a_2 dxs + b_2 dys (j 6, 7); then the
    // edges' gradients a_k, b_k as words for the plane RAM (j 8 .. 13: 2 a_0, 2 b_0, 2 a_1, ...).
    // An edge whose threshold is 1 has all its products negated (traversal takes it negated, -E,
    // and steps it by -a, -b).
    // Each job's a operand is a coefficient, named by its home index tgt (0..2 b_k, 3..5 a_(5-k)).
    // ValuesInFifo takes it from the ring's head (g_coef_read), turning the ring to it first (the
    // job waits meanwhile); j 14 turns the ring home before the planes start. b_2 a_0's a_0 is then
    // the ring's ring_q[3], the dy2 input (job_bsel 0), as a_2 is for b_0 a_2.
    localparam logic [2:0] BselPartner = ValuesInFifo ? 3'd0 : 3'd1;  // a_0 for b_2 a_0
    logic [3:0] j;
    logic [2:0] tgt;
    logic       job_want;
    assign j = edge_k_q;
    always_comb begin
      job_acc  = 1'b1;
      job_neg  = ethr_s[1];
      tgt      = 3'd2;  // b_2
      job_bsel = BselPartner;
      unique case (state_q)
        StDet0: begin tgt = 3'd0; job_bsel = 3'd0; job_neg = redo_q; job_acc = 1'b0; end
        StDet1: begin job_neg = !redo_q; end
        default: begin
          unique case (j)
            4'd0: begin tgt = 3'd5; job_bsel = 3'd2; job_neg = ethr_s[0]; job_acc = 1'b0; end
            4'd1: begin tgt = 3'd0; job_bsel = 3'd3; job_neg = ethr_s[0]; end
            4'd2: begin tgt = 3'd4; job_bsel = 3'd2; job_acc = 1'b0; end
            4'd3: begin tgt = 3'd1; job_bsel = 3'd3; end
            4'd4: begin tgt = 3'd0; job_bsel = 3'd0; end
            4'd5: begin job_neg = !ethr_s[1]; end
            4'd6: begin tgt = 3'd3; job_bsel = 3'd2; job_neg = ethr_s[2]; job_acc = 1'b0; end
            4'd7: begin job_bsel = 3'd3; job_neg = ethr_s[2]; end
            4'd14: tgt = 3'd0;  // (no job: home)
            default: begin
              tgt      = j[0] ? {1'b0, j[2:1]} : 3'd5 - {1'b0, j[2:1]};
              job_bsel = 3'd4;
              job_neg  = ethr_s[j[2:1]];
              job_acc  = 1'b0;
            end
          endcase
        end
      endcase
    end
    assign job_want = (state_q == StDet0) || (state_q == StDet1) || (state_q == StEdges);
    if (ValuesInFifo) begin : g_ring_jobs
      logic at_tgt;
      logic [2:0] ring_tgt;
      assign job_a     = ring_head;
      assign at_tgt    = (ring_pos == tgt);
      // The jobs turn the ring to their coefficient; while the planes run (StWait) it turns to
      // where the plane unit wants it, and home when the planes are done (StOut waits for that:
      // the traversal takes the coefficients' taps at home).
      assign ring_tgt  = job_want ? tgt : plane_ring_want;
      assign ring_turn = (job_want || (state_q == StWait)) && (ring_pos != ring_tgt);
      assign job_req   = job_want && at_tgt && !((state_q == StEdges) && (j == 4'd14));
    end else begin : g_mux_jobs
      // The coefficients by home index, and the job's one among them.
      logic signed [DW-1:0] coef_home [6];
      for (genvar k = 0; k < 3; k++) begin : g_home
        assign coef_home[k]     = eb[k];
        assign coef_home[5 - k] = ea[k];
      end
      assign job_a     = coef_home[tgt];
      assign ring_turn = 1'b0;
      assign job_req   = job_want;
      logic unused_ring_head;
      assign unused_ring_head = ^{ring_head, ring_pos, plane_ring_want};
    end
    assign emul_done = job_done;
    // Words for the plane RAM: E_k where its last product is done (j 1, 5, 7: start, plane k),
    // and the gradients (j 8 .. 13: g_x for a, g_y for b, plane j[2:1]).
    assign job_we   = job_done && (state_q == StEdges) &&
                      ((j == 4'd1) || (j == 4'd5) || (j == 4'd7) || j[3]);
    assign job_wsel = j[3] ? {1'b0, j[0]} : 2'd2;
    assign job_widx = j[3] ? j[2:1] : (j == 4'd1) ? 2'd0 : (j == 4'd5) ? 2'd1 : 2'd2;
    assign part_sum  = $signed(job_sum);
    logic unused_det;
    assign unused_det = ^{det_q, part_q, edge_half_q};
  end
  logic signed [DetW-1:0] det_next;
  assign det_next = DetW'(part_sum);

  // ---- Reciprocals: 1/|det|, then (AFFINE) 1/q_i of each vertex -------------------------------
  localparam bit HasAffine = Methods[0];
  logic                recip_start, recip_done, recip_valid_q, det_pend_q;
  logic [RecipW:0]     recip_r, rdet_q;
  logic [MsbW-1:0]     recip_msb, msbdet_q;
  logic [DetW-1:0]     det_abs, recip_x;
  logic [ShiftW-1:0]   grad_shift;
  logic                planes_abort, det_start, av_start, affine_q;
  logic [1:0]          av_i;
  // Iterative (DetRedo): a negative det is computed again with the other product negated,
  // -dx1 dy2 + dx2 dy1 = |det| (two more serial products, for half the triangles), instead of
  // through a negator; then det_next is |det| when det_start rises.
  localparam bit DetRedo = Iterative;
  // Iterative (DetCheck): det is registered (det_q) and judged in the clock after (StDetChk), so
  // the plane unit's adder that forms it does not reach the record's release and the input stage
  // in one clock (`icebreaker`'s critical path, docs/raster.md); one clock a triangle.
  localparam bit DetCheck = Iterative;
  logic                   redo_q, det_again, det_judge;
  logic signed [DetW-1:0] det_j;  // the det judged
  assign det_judge = DetCheck ? (state_q == StDetChk) : ((state_q == StDet1) && emul_done);
  assign det_j     = DetCheck ? det_q : det_next;
  assign det_again = DetRedo && !redo_q && det_j[DetW-1];
  assign det_abs   = (det_next[DetW-1] && !DetRedo) ? DetW'(-det_next) : DetW'(det_next);
  assign tri_skip  = det_judge && ((det_j == 0) || box_empty);
  assign det_start = det_judge && (det_j != 0) && !box_empty && !det_again;
  assign recip_start = det_start || av_start;
  // AFFINE's q_i: read from the FIFO in the clock before (ValuesInFifo), or the record's register.
  assign recip_x = det_start ? (DetCheck ? det_q : det_abs)
                 : ValuesInFifo ? DetW'(vr_data_i[QBits-1:0]) : DetW'(q_v[av_i]);
  assign planes_abort = abort_i || tri_skip;
  assign grad_shift = ShiftW'(RecipW) + ShiftW'(msbdet_q) - ShiftW'(GF);

  if (ExtRecip) begin : g_ext_recip
    assign rq_start_o  = recip_start;
    assign rq_x_o      = recip_x;
    assign recip_done  = rq_done_i;
    assign recip_r     = rq_r_i;
    assign recip_msb   = rq_msb_i;
  end else begin : g_own_recip
    logic                recip_mul_start;      // (setup's unit has its own multiplier)
    logic [RecipW+2:0]   recip_mul_a, recip_mul_b;
    logic                recip_busy;           // (setup waits for done_o)
    logic [RecipW:0]     recip_r0;             // (the table value: setup always takes Newton steps)
    logic                recip_norm_shift;     // (nothing shifts in step)
    htx_recip #(.XWidth(DetW), .W(RecipW), .K(RecipK), .G(RecipG), .Steps(NrSteps),
                .Iterative(Iterative), .SerialNorm(Iterative)) u_recip (
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
    assign rq_start_o = 1'b0;
    assign rq_x_o     = '0;
    logic unused_recip_mul;
    assign unused_recip_mul = ^{recip_mul_start, recip_mul_a, recip_mul_b, recip_busy, recip_r0,
                                recip_norm_shift, rq_done_i, rq_r_i, rq_msb_i};
  end

  // ---- Reads of the record in the FIFO (ValuesInFifo) -----------------------------------------
  // Three readers: the record reader (the edge coefficients, then the box, in the clocks after
  // setup takes a triangle), AFFINE (q_i, uq_i, vq_i, after the determinant's reciprocal: never
  // beside the record reader, so it is never held) and the plane values' loader, which waits while
  // either of the others reads.
  logic       av_req, ld_req;
  logic [4:0] av_off, ld_off;
  assign vr_req_o = ValuesInFifo && (rd_req || av_req || ld_req);
  assign vr_off_o = rd_req ? rd_off : av_req ? av_off : ld_off;

  // ---- Planes: z, r, g, b, q, uq, vq, and for AFFINE ua, va -------------------------------------
  // Nine plane units working in parallel, or (Iterative, the `icebreaker` configuration) one unit
  // taking the planes in turn (htx_raster_plane_seq).
  // Planes built: ua, va only for AFFINE; q, uq, vq only with texture mapping.
  localparam int unsigned NS  = HasAffine ? NP : Textured ? 7 : 4;
  logic                 apl_start;         // AFFINE's vertex coordinates are ready (pulse)
  logic [1:0]           apl_done;          // the ua, va planes are done
  logic [LocW-1:0]      ua_v [3];
  logic [LocW-1:0]      va_v [3];
  // ValuesInFifo: AFFINE's u_i and v_i wait in two shift chains (vertex 0 at the head), which the
  // loader takes one a clock from the head (ua_take, va_take): no multiplexer over the vertices.
  logic                 ua_take, va_take;
  logic                 plane_start_q;
  logic [NP-1:0]        plane_done;
  logic [AW-1:0]        pgx [NP];
  logic [AW-1:0]        pgy [NP];
  logic [AW-1:0]        pst [NP];

  localparam int unsigned GWU = UQ + DW + 2 + GF + 1;     // full-precision gradient of uq, vq
  localparam int unsigned GWQ = QBits + DW + 2 + GF + 1;  // and of q
  logic [GWU-1:0] lg [6];                                  // uq x, uq y, vq x, vq y, q x, q y


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

  // Every plane's vertex values widened to VSW signed bits (unsigned ones zero-extended): plane p,
  // vertex i at 3 p + i, in the order z, r, g, b, q, uq, vq, ua, va. Plane p's own value width is
  // plane_vb(p); its low bits of the widened word are its values.
  // Without texture mapping only z and the colour channels have planes. The shared unit's jobs
  // (the determinant and the edge values, 2 DW + 2 bits) bound the width from below as well: its
  // accumulator is VSW + DW + 2 bits, and its words, VSW + GF + 3 bits, fill the plane RAM's AW + 1.
  localparam int unsigned VZC = (ZBits > CB ? ZBits : CB) + 1;       // z, colour
  localparam int unsigned VQU = (QBits > UQ ? QBits : UQ) + 1;        // q, uq, vq
  localparam int unsigned VS  = (Textured && (VQU > VZC)) ? VQU : VZC;
  localparam int unsigned VSL = (Textured && (LocW + 1 > VS)) ? LocW + 1 : VS;  // ua, va
  localparam int unsigned VSJ = (AW - GF - 2 > DW) ? AW - GF - 2 : DW;
  localparam int unsigned VSW = (VSL > VSJ) ? VSL : VSJ;
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
    assign sv[VSW*(15+i) +: VSW] = VSW'($signed(uq_v[i]));
    assign sv[VSW*(18+i) +: VSW] = VSW'($signed(vq_v[i]));
    assign sv[VSW*(21+i) +: VSW] = VSW'($signed(ua_v[i]));
    assign sv[VSW*(24+i) +: VSW] = VSW'($signed(va_v[i]));
  end

  // Planes not built (ua, va without AFFINE), and every plane with the shared unit (its planes go
  // to the traversal's RAM instead), give zeros on tri_p_o.
  for (genvar p = SharedPlanes ? 0 : NS; p < NP; p++) begin : g_plane_off
    assign pgx[p] = '0;
    assign pgy[p] = '0;
    assign pst[p] = '0;
  end

  if (!SharedPlanes) begin : g_planes_par
    // One plane unit per plane; ua and va (planes 7, 8) start when AFFINE's vertex coordinates are
    // ready. The unit of q, uq, vq also gives its gradients at full precision to the LOD shift.
    assign plane_ring_want = 3'd0;  // (the ring is never turned without shared planes)
    for (genvar p = 0; p < NS; p++) begin : g_plane
      localparam int unsigned VBP = plane_vb(p);
      localparam int unsigned AP  = VBP + GF + 2;
      localparam int unsigned GP  = VBP + DW + 2 + GF + 1;
      logic [AP-1:0] gx, gy, st;
      logic [GP-1:0] gxw, gyw;
      logic          w_we;
      logic [1:0]    w_sel;
      logic [AP:0]   w_word;
      logic          w_job_done;   // (no jobs: setup has its own multiplier for them)
      logic [2*DW+1:0] w_job_sum;
      logic [2:0]    w_ring_want;    // (no ring: setup's coefficients are wires here)
      logic          w_val_turn;
      logic          unused_w_word;
      htx_raster_plane #(.VB(VBP), .Signed(p >= 5), .DW(DW), .W(RecipW), .GF(GF),
                         .Iterative(Iterative), .ShiftW(ShiftW)) u_plane (
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
        .ring_pos_i   (3'd0),
        .ring_want_o  (w_ring_want),
        .val_turn_o   (w_val_turn),
        .done_o       (plane_done[p]),
        .gx_o(gx), .gy_o(gy), .start_o(st),
        .gxw_o(gxw), .gyw_o(gyw),
        .word_we_o(w_we), .word_sel_o(w_sel), .word_o(w_word),
        .job_i(1'b0), .job_a_i('0), .job_bsel_i('0), .job_neg_i(1'b0), .job_acc_i(1'b0),
        .job_done_o(w_job_done), .job_sum_o(w_job_sum)
      );
      // (The parallel units hand over on tri_p_o.)
      assign unused_w_word = ^{w_we, w_sel, w_word, w_job_done, w_job_sum, w_ring_want, w_val_turn};
      assign pgx[p] = AW'(gx);
      assign pgy[p] = AW'(gy);
      assign pst[p] = AW'(st);
      if ((p >= 4) && (p <= 6)) begin : g_lod
        localparam int unsigned L = (p == 4) ? 4 : 2 * (p - 5);  // lg: uq x, y, vq x, y, q x, y
        assign lg[L]   = GWU'($signed(gxw));
        assign lg[L+1] = GWU'($signed(gyw));
      end else begin : g_no_lod
        logic unused_w;
        assign unused_w = ^{gxw, gyw};
      end
    end
    if (NS < NP) begin : g_done_off
      assign plane_done[NP-1:NS] = '0;
    end
    assign apl_done = plane_done[8:7];
    assign job_done  = 1'b0;  // (setup's own multiplier: g_edge_mul)
    assign job_sum   = '0;
    logic unused_jobs;
    assign unused_jobs = ^{job_req, job_neg, job_acc, job_a, job_bsel,
                          job_we, job_wsel, job_widx};
    assign ua_take   = 1'b0;
    assign va_take   = 1'b0;
    assign ld_req    = 1'b0;
    assign ld_off    = '0;
    assign pl_we_o   = 1'b0;
    assign pl_sel_o  = '0;
    assign pl_idx_o  = '0;
    assign pl_data_o = '0;
  end else begin : g_planes_shared
    // One plane unit for all nine, in turn (Iterative: area over clocks); its results go straight
    // to the traversal's plane RAM (pl_*_o), none is kept here.
    localparam int unsigned AS  = VSW + GF + 2;
    localparam int unsigned GS  = VSW + DW + 2 + GF + 1;
    logic                s_valid, s_first, s_late, s_want, s_have, s_wwe;
    logic                s_val_turn;  // rotate the plane's loaded values (Ring, g_load)
    logic [1:0]          s_wsel;
    logic [AS:0]         s_word;
    logic [3:0]          s_idx;
    logic [NS*3*VSW-1:0] s_values;
    logic [GS-1:0]       s_gxw, s_gyw;
    htx_raster_plane_seq #(.NP(NS), .NFirst((NS < 7) ? NS : 7), .VB(VSW), .DW(DW), .W(RecipW), .GF(GF), .ShiftW(ShiftW),
                           .AccW(AS), .GW(GS), .IdxW(4), .Load(ValuesInFifo), .Jobs(1'b1),
                           .Ring(ValuesInFifo)) u_seq (
      .clk_i, .rst_ni,
      .abort_i      (planes_abort),
      .start_i      (plane_start_q),
      .late_start_i (apl_start),
      .values_i     (s_values),
      .want_o       (s_want),
      .have_i       (s_have),
      .dx1_i(dx1), .ndy1_i(ea[0]), .ndx2_i(eb[2]), .dy2_i(dy2),
      .dxs_i(dxs), .dys_i(dys),
      .recip_valid_i(recip_valid_q),
      .r_i          (rdet_q),
      .shift_i      (grad_shift),
      .det_neg_i    (det_neg_q),
      .ring_pos_i   (ring_pos),
      .ring_want_o  (plane_ring_want),
      .val_turn_o   (s_val_turn),
      .res_valid_o  (s_valid),
      .res_idx_o    (s_idx),
      .gxw_o(s_gxw), .gyw_o(s_gyw),
      .word_we_o    (s_wwe),
      .word_sel_o   (s_wsel),
      .word_o       (s_word),
      .first_done_o (s_first),
      .late_done_o  (s_late),
      .job_i        (job_req),
      .job_a_i      (job_a),
      .job_bsel_i   (job_bsel),
      .job_neg_i    (job_neg),
      .job_acc_i    (job_acc),
      .job_done_o   (job_done),
      .job_sum_o    (job_sum)
    );
    if (ValuesInFifo) begin : g_load
      // The plane's three vertex values, loaded a word every two clocks (ask, take) into a shift
      // chain (vertex 0 ends in a_q[0]): the FIFO's read port is the multiplexer over planes and
      // vertices. AFFINE's u_i, v_i (planes 7, 8) come from their shift chains, a clock each.
      // While the plane unit works the chain rotates on s_val_turn (a_q[0], its a operand, takes
      // the next vertex; htx_raster_plane Ring), six times a plane, which brings it home.
      // (Asking for the next word in the clock that takes one saves about 20 clocks a triangle
      // and cost 37 LUT4: not done.)
      typedef enum logic [1:0] {LdIdle, LdReq, LdData, LdDone} ld_e;
      ld_e             ld_q;
      logic [1:0]      lv_q;      // the vertex being loaded
      logic            lhi_q;     // the high word of uq or vq
      logic [VSW-1:0]  a_q [3];
      logic            late, two_words, last_word;
      logic [3:0]      field;
      logic [VSW-1:0]  lo_value, late_value;
      assign late      = (s_idx >= 4'd7);
      assign two_words = (s_idx == 4'd5) || (s_idx == 4'd6);
      assign last_word = !two_words || lhi_q;
      always_comb begin
        if (s_idx == 4'd0)      field = 4'd2;                 // z
        else if (s_idx <= 4'd3) field = 4'd8;                 // r, g, b: a byte of rgba
        else if (s_idx == 4'd4) field = 4'd3;                 // q
        else if (s_idx == 4'd5) field = 4'd4 + {3'd0, lhi_q}; // uq
        else                    field = 4'd6 + {3'd0, lhi_q}; // vq
      end
      assign ld_req = (ld_q == LdReq) && !late;
      assign ld_off = htx_raster_pkg::rec_vert_word(lv_q, field);
      // The low word as an AND-OR of one-hot selects decoded once: the word under the plane's
      // mask (z, q, the low word of uq or vq), or one byte of rgba (r, g, b).
      logic        is_z, is_q, is_uv;
      logic [2:0]  is_c;
      logic [31:0] wmask;
      logic [7:0]  cbyte;
      assign is_z  = (s_idx == 4'd0);
      assign is_c  = {s_idx == 4'd3, s_idx == 4'd2, s_idx == 4'd1};
      assign is_q  = (s_idx == 4'd4);
      assign is_uv = (s_idx == 4'd5) || (s_idx == 4'd6);  // the high word follows
      for (genvar b = 0; b < 32; b++) begin : g_wmask
        assign wmask[b] = (is_z && (b < ZBits)) || (is_q && (b < QBits)) || is_uv;
      end
      assign cbyte    = ({8{is_c[0]}} & vr_data_i[7:0]) | ({8{is_c[1]}} & vr_data_i[15:8]) |
                        ({8{is_c[2]}} & vr_data_i[23:16]);
      logic [31:0] wsel;
      assign wsel     = vr_data_i & wmask;
      assign lo_value = VSW'(wsel) | VSW'(cbyte);
      if (VSW < 32) begin : g_narrow
        logic unused_wsel;
        assign unused_wsel = ^wsel[31:VSW];  // (above every plane's value without texture mapping)
      end
      assign late_value = (s_idx == 4'd7) ? VSW'($signed(ua_v[0])) : VSW'($signed(va_v[0]));
      // The value with the high word of uq or vq above its low word (texture mapping only).
      logic [VSW-1:0] hi_value;
      if (Textured) begin : g_hi
        assign hi_value = {(VSW-32)'($signed(vr_data_i[UQ-33:0])), a_q[2][31:0]};
      end else begin : g_no_hi
        assign hi_value = a_q[2];
      end
      assign ua_take    = (ld_q == LdReq) && (s_idx == 4'd7);
      assign va_take    = (ld_q == LdReq) && (s_idx == 4'd8);

      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          ld_q  <= LdIdle;
          lv_q  <= '0;
          lhi_q <= 1'b0;
          for (int i = 0; i < 3; i++) a_q[i] <= '0;
        end else if (planes_abort) begin
          ld_q  <= LdIdle;
        end else begin
          unique case (ld_q)
            LdIdle: begin
              if (s_want) begin
                ld_q <= LdReq; lv_q <= '0; lhi_q <= 1'b0;
              end else if (s_val_turn) begin
                a_q[0] <= a_q[1]; a_q[1] <= a_q[2]; a_q[2] <= a_q[0];
              end
            end
            LdReq: begin
              if (late) begin
                a_q[0] <= a_q[1]; a_q[1] <= a_q[2]; a_q[2] <= late_value;
                lv_q <= lv_q + 2'd1;
                if (lv_q == 2'd2) ld_q <= LdDone;
              end else if (!av_req && !rd_req) begin
                ld_q <= LdData;  // the word is on vr_data_i next clock
              end
            end
            LdData: begin
              if (!lhi_q) begin
                a_q[0] <= a_q[1]; a_q[1] <= a_q[2]; a_q[2] <= lo_value;
              end else begin
                a_q[2] <= hi_value;
              end
              lhi_q <= !last_word;
              if (last_word) lv_q <= lv_q + 2'd1;
              ld_q <= (last_word && (lv_q == 2'd2)) ? LdDone : LdReq;
            end
            LdDone: ld_q <= LdIdle;
            default: ld_q <= LdIdle;
          endcase
        end
      end
      assign s_have   = (ld_q == LdDone);
      assign s_values = (NS*3*VSW)'({a_q[2], a_q[1], a_q[0]});
    end else begin : g_no_load
      assign ua_take  = 1'b0;
      assign va_take  = 1'b0;
      assign ld_req   = 1'b0;
      assign ld_off   = '0;
      assign s_have   = 1'b0;
      assign s_values = sv[NS*3*VSW-1:0];
      logic unused_want;
      assign unused_want = ^{s_want, s_val_turn};  // (Ring is off without Load)
    end
    assign plane_done = {{2{s_late}}, {7{s_first}}};
    assign apl_done   = {2{s_late}};
    // Each plane's three words go to the traversal's plane RAM as the unit forms them: gx,
    // gy, start, each in the clock its product is done. (Planes not built are not written; the
    // traversal steps whatever its RAM holds there, which nothing reads.)
    // The edges' words (jobs) at 0..2, the planes' from 3 on.
    assign pl_we_o   = s_wwe || job_we;
    assign pl_sel_o  = job_we ? job_wsel : s_wsel;
    assign pl_idx_o  = job_we ? {2'b00, job_widx}
                     : (FoldUv && (s_idx >= 4'd7)) ? s_idx + 4'd1 : s_idx + 4'd3;
    assign pl_data_o = (AW+1)'(s_word);
    if (Textured) begin : g_lg
      // Full-precision gradients of uq, vq (GWU bits) and q (GWQ bits, sign-extended) for the LOD unit.
      logic [GWU-1:0] lgx_q [3];
      logic [GWU-1:0] lgy_q [3];
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          for (int k = 0; k < 3; k++) begin lgx_q[k] <= '0; lgy_q[k] <= '0; end
        end else if (s_valid && (s_idx >= 4'd4) && (s_idx <= 4'd6)) begin
          if (s_idx == 4'd4) begin
            lgx_q[2] <= GWU'($signed(s_gxw[GWQ-1:0]));
            lgy_q[2] <= GWU'($signed(s_gyw[GWQ-1:0]));
          end else begin
            lgx_q[{1'b0, s_idx[1]}] <= s_gxw[GWU-1:0];  // 5 (uq) -> 0, 6 (vq) -> 1
            lgy_q[{1'b0, s_idx[1]}] <= s_gyw[GWU-1:0];
          end
        end
      end
      assign lg[0] = lgx_q[0];
      assign lg[1] = lgy_q[0];
      assign lg[2] = lgx_q[1];
      assign lg[3] = lgy_q[1];
      assign lg[4] = lgx_q[2];
      assign lg[5] = lgy_q[2];
    end else begin : g_no_lg
      for (genvar k = 0; k < 6; k++) begin : g_zero
        assign lg[k] = '0;
      end
      logic unused_res;
      assign unused_res = ^{s_valid, apl_done};  // (no LOD gradients, no AFFINE planes)
    end
    logic unused_s;
    // ((AW+1)'() may drop a top bit of s_word)
    assign unused_s = ^{s_gxw, s_gyw, s_word};
  end

  // ---- LOD gradients: one block shift for all six (htx_raster_setup_lod) -----------------------
  logic           lod_done;
  logic [6*GWU-1:0] lg_flat;
  for (genvar i = 0; i < 6; i++) begin : g_lg_flat
    assign lg_flat[GWU*i +: GWU] = lg[i];
  end
  htx_raster_setup_lod #(.GWU(GWU), .GradW(GradW), .Lod(Lod), .Serial(SharedPlanes)) u_lod (
    .clk_i, .rst_ni,
    .abort_i      (planes_abort),
    .start_i      (plane_start_q),
    .planes_done_i(&plane_done[6:4]),
    .grad_i       (lg_flat),
    .grad_o       (tri_lod_g_o),
    .shift_o      (tri_lod_shift_o),
    .done_o       (lod_done)
  );
  assign tri_dfg_o = lg_flat;  // (DIVFREE takes them at full precision)

  // ---- AFFINE: the vertices' u_i, v_i and their planes (htx_raster_setup_affine) ---------------
  logic av_done;
  if (HasAffine) begin : g_affine
    logic [3*UQ-1:0]   uq_flat, vq_flat;
    logic [3*LocW-1:0] ua_flat, va_flat;
    for (genvar i = 0; i < 3; i++) begin : g_flat
      assign uq_flat[UQ*i +: UQ] = uq_v[i];
      assign vq_flat[UQ*i +: UQ] = vq_v[i];
      assign ua_v[i] = ua_flat[LocW*i +: LocW];
      assign va_v[i] = va_flat[LocW*i +: LocW];
    end
    htx_raster_setup_affine #(.RecipW(RecipW), .TF(TF), .UQ(UQ), .LocW(LocW), .MsbW(MsbW),
                              .Iterative(Iterative), .ValuesInFifo(ValuesInFifo)) u_affine (
      .clk_i, .rst_ni,
      .abort_i       (planes_abort),
      .start_i       (recip_done && det_pend_q && affine_q),
      .recip_start_o (av_start),
      .vtx_o         (av_i),
      .recip_done_i  (recip_done),
      .recip_r_i     (recip_r),
      .recip_msb_i   (recip_msb),
      .rd_req_o      (av_req),
      .rd_off_o      (av_off),
      .rd_data_i     (vr_data_i),
      .uq_i          (uq_flat),
      .vq_i          (vq_flat),
      .late_ok_i     ((state_q == StWait) && !plane_start_q),
      .planes_start_o(apl_start),
      .planes_done_i (apl_done),
      .release_i     ((state_q == StOut) && tri_ready_i),
      .ua_take_i     (ua_take),
      .va_take_i     (va_take),
      .ua_o          (ua_flat),
      .va_o          (va_flat),
      .done_o        (av_done)
    );
  end else begin : g_no_affine
    logic unused_take;
    assign unused_take = ua_take ^ va_take;
    assign av_req   = 1'b0;
    assign av_off   = '0;
    assign av_start = 1'b0;
    assign av_i     = 2'd0;
    assign av_done  = 1'b0;
    assign apl_start = 1'b0;
    for (genvar i = 0; i < 3; i++) begin : g_uv_out
      assign ua_v[i] = '0;
      assign va_v[i] = '0;
    end
    logic unused_a;
    assign unused_a = affine_q;
  end

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
      redo_q        <= 1'b0;
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
          affine_q <= HasAffine && (rec_method == htx_raster_pkg::MethodAffine);
          // With SharedPlanes the planes start after the edges, whose products run on their unit.
          plane_start_q <= !SharedPlanes;
          recip_valid_q <= 1'b0;
          redo_q        <= 1'b0;
          state_q       <= ValuesInFifo ? StCoef : StDet0;
        end
        StCoef: if (cf_done) state_q <= StDet0;
        StDet0: if (emul_done) begin part_q <= part_sum; state_q <= StDet1; end
        StDet1: if (emul_done) begin
          det_q     <= det_abs;
          det_neg_q <= redo_q || det_next[DetW-1];
          edge_k_q  <= '0;
          edge_half_q <= 1'b0;
          if (DetCheck) state_q <= StDetChk;  // (else judged in this clock: det_judge below)
        end
        StDetChk: begin end  // (det_judge below)
        StEdges: if (emul_done && SharedPlanes) begin
          // Jobs 1, 5, 7 end an edge, 13 the gradients (g_edge_jobs). (Only the signs of e_q are
          // taken: the values go to the plane RAM.)
          if (edge_k_q == 4'd1) e_q[0] <= part_sum;
          if (edge_k_q == 4'd5) e_q[1] <= part_sum;
          if (edge_k_q == 4'd7) e_q[2] <= part_sum;
          if ((edge_k_q == 4'd13) && !ValuesInFifo) begin
            plane_start_q <= 1'b1;
            state_q       <= StWait;
          end
          edge_k_q <= edge_k_q + 1'b1;
        end else if ((edge_k_q == 4'd14) && ValuesInFifo && (ring_pos == 3'd0)) begin
          // The ring is home (j 14 turned it): the plane unit turns it from there.
          plane_start_q <= 1'b1;
          state_q       <= StWait;
        end else if (emul_done) begin
          if (!edge_half_q) begin
            part_q      <= part_sum;
            edge_half_q <= 1'b1;
          end else begin
            e_q[ek]     <= part_sum;
            edge_half_q <= 1'b0;
            edge_k_q    <= edge_k_q + 1'b1;
            if (ek == 2'd2) state_q <= StWait;
          end
        end
        // (Not in the clock the planes start: their done flags still show the last triangle's.)
        StWait: begin
          if (!plane_start_q && (&plane_done[6:0]) && lod_done && (!affine_q || av_done) &&
              (ring_pos == 3'd0)) begin
            state_q <= StOut;
          end
        end
        StOut: if (tri_ready_i) state_q <= StIdle;
        default: state_q <= StIdle;
      endcase
      // The determinant judged (StDet1's last clock, or DetCheck's StDetChk): skip the triangle,
      // form |det| again, or go on to the edges.
      if (det_judge) begin
        if (tri_skip) state_q <= StIdle;
        else if (det_again) begin redo_q <= 1'b1; state_q <= StDet0; end
        else state_q <= StEdges;
      end
    end
  end

  // ---- Outputs ---------------------------------------------------------------------------------
  logic unused;
  assign unused = ^{rec_state_i, plane_done[8:7]};

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
  assign tri_thr_o = ethr_s;
  assign tri_a_zero_o = ea_zero;
  assign tri_dneg_o = det_neg_q;
  assign busy_o    = (state_q != StIdle) && (state_q != StOut);
  assign stall_o   = (state_q == StOut) && !tri_ready_i;
endmodule
