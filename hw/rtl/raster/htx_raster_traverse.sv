// Traversal (docs/raster.md): walks each row of the pixel box with the three edge functions and
// the attribute planes, stepping by exact integer additions only (256 a, 256 b per pixel; 256 g_x,
// 256 g_y for the planes). Per row it finds the span start from the previous row's start column
// (one column per clock, guided by which edge rejects the pixel), then emits the covered pixels
// left to right, one per clock. Coverage of the pixel one column left and right is looked at in the
// same clock, so a row costs its span length plus how far its start moved; an empty row costs one.
// LookBehind = 0 (`icebreaker`) leaves out the left look (three edge adders and their tests): a row
// whose start is found by walking left steps one column past it and back, two clocks more.
// Framebuffer addresses are AddrW bits (the subsystem sizes them to its memory): each fragment's
// y * stride + x is one multiply-add (an iCE40 DSP, 13 x 13 bits and a 13-bit addend), and an
// address that does not fit (a large stride x height) is all ones, beyond any memory of fewer than
// 2^AddrW - 1 pixels, so the fragment stage writes nothing there (rather than at the address
// modulo 2^AddrW). (Until 2026-12-04 a row offset register stepped by the stride, formed for the
// first row by a multiplier in `full` and by shift and add in `icebreaker`: about 100 LUT4 more.)
// SerialPlanes = 1 (`icebreaker`) keeps the plane accumulators in one block RAM and steps them one
// plane a clock on one adder: a step costs NP + 3 clocks (the edges are planes there too), not one.
// The row's saved copy needs no copy: the RAM holds two banks, and the step that leaves a span's
// first pixel writes the other bank, so the bank it leaves keeps that pixel's values. Setup then
// writes the planes into that RAM (pl_*_i) instead of handing them over on tri_p_i. The three edge
// functions are planes of that RAM too (indices 0..2, before the NP attribute planes: a the
// gradient in x, b in y, the value at the first pixel the start), stepped by the same adder in the
// same pass, so a step costs NP + 3 clocks and the traversal keeps only their signs. Without a look
// at x + 1, a span is left by stepping right once past it: the pass that captures a pixel steps to
// the next one and learns from the signs whether the pixel was its span's last.
// The covered set is exactly the model's: E_k >= threshold_k for all k, cov the clipped box.
// Each fragment carries its plane values (NP planes, modulo 2^AW), the triangle's sideband (state,
// flat colour, texel offsets, LOD gradients) and whether it is its span's first or last pixel.
module htx_raster_traverse #(
  parameter int unsigned DW    = 25,
  parameter int unsigned EW    = 52,
  parameter int unsigned NP    = 9,
  parameter int unsigned AW    = 74,
  parameter int unsigned SideW = 64,
  parameter int unsigned AddrW = 24,
  parameter bit          LookBehind = 1'b1,
  parameter bit          SerialPlanes = 1'b0
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              abort_i,
  input  logic [12:0]       stride_i,

  input  logic              tri_valid_i,
  output logic              tri_ready_o,
  input  logic [SideW-1:0]  tri_side_i,
  input  logic [12:0]       tri_x_lo_i, tri_x_hi_i, tri_y_lo_i, tri_y_hi_i,
  input  logic [3*DW-1:0]   tri_a_i, tri_b_i,  // (SerialPlanes: only a's sign)
  input  logic [2:0]        tri_a_zero_i,  // a_k = 0 (setup has the test for the threshold)
  input  logic [2:0]        tri_thr_i,
  input  logic              tri_dneg_i,  // det < 0: the edges are to be taken reversed
  input  logic [3*EW-1:0]   tri_e_i,     // (SerialPlanes: only the signs)
  input  logic [3*NP*AW-1:0] tri_p_i,
  // SerialPlanes: the planes come instead through this write port into the plane RAM (setup's
  // pl_*_o: 0 gx, 1 gy, 2 start of plane idx; the edges k at idx k, the attribute planes p at
  // p + 3); a write holds the traversal for that clock.
  input  logic              pl_we_i,
  input  logic [1:0]        pl_sel_i,
  input  logic [3:0]        pl_idx_i,
  input  logic [AW:0]       pl_data_i,   // a gradient at [AW:1], a start value at [AW-1:0]

  // Fragment: pixel, framebuffer address, raw plane values and the triangle's state.
  output logic              frag_valid_o,
  input  logic              frag_ready_i,
  output logic [12:0]       frag_x_o, frag_y_o,
  output logic [AddrW-1:0]  frag_addr_o,
  output logic              frag_first_o,
  output logic              frag_last_o,
  output logic              frag_tfirst_o,  // the triangle's first fragment
  output logic [NP*AW-1:0]  frag_p_o,
  output logic [SideW-1:0]  frag_side_o,

  output logic              busy_o,
  output logic              stall_o   // a fragment is ready but the output is blocked
);
  localparam int unsigned XCW = 15;  // signed column, the walk reaches x_lo - 1 .. x_hi + 1

  // StBack (LookBehind = 0): walking left over covered pixels to the first one of the span.
  // StBase (SerialPlanes = 1): the clock after the triangle is taken, in which the relations of x
  // to the box reach their register (g_xrel_q).
  // StLoad (SerialPlanes = 1): the one clock in which the triangle is taken, once the last step's
  // planes are written and the last fragment has left.
  typedef enum logic [2:0] {StIdle, StSeek, StSeekL, StSeekR, StEmit, StBack, StBase, StLoad} state_e;

  state_e state_q;
  logic [SideW-1:0]        side_q;
  logic signed [XCW-1:0]   x_lo_q, x_hi_q, x_q, xs_q;
  logic [12:0]             y_q, y_hi_q;
  logic [2:0]              thr_q;
  logic                    dneg_q;
  logic                    sweep_q;   // SerialPlanes: the planes are being stepped (0 otherwise)
  logic                    hold;      // SerialPlanes: setup writes the plane RAM; nothing moves
  logic                    load_last; // SerialPlanes: StLoad takes the triangle
  logic                    accept;    // the triangle is taken this clock
  logic [2:0]              esgn_we;   // SerialPlanes: the pass writes edge k's new value ...
  logic                    esgn_d;    // ... whose sign bit is this

  // ---- Coverage at x - 1, x, x + 1 ---------------------------------------------------------------
  logic [2:0] in_cur, in_prev_e, in_next_e, fail_pos, fail_neg, fail_zero, a_neg;
  logic [2:0] a_zero_q;  // a_k = 0, from setup (it has the test for the threshold)
  // An edge value covers its pixel: E >= 0, and E > 0 where the edge's threshold is 1. Setup
  // delivers an edge whose threshold is 1 negated (-E; its steps subtract), so both tests are a
  // sign: E >= 0 is a clear sign bit of E, E >= 1 a set sign bit of -E. No comparison with zero.
  // A triangle with det < 0 comes with its edges as given, where the model reverses them
  // (E' = -E, threshold' = 1 - threshold): the stored value is then the same and only the sign
  // tested flips (pol).
  logic [2:0] pol;
  assign pol = thr_q ^ {3{dneg_q}};
  for (genvar k = 0; k < 3; k++) begin : g_cov
    // Coverage grows to the right where a > 0 (a < 0 for a reversed edge).
    // (Sign and zero tests, not comparisons: Yosys 0.23 builds those as carry chains.)
    logic a_pos;
    assign a_pos = !a_neg[k] && !a_zero_q[k];
    assign fail_pos[k]  = !in_cur[k] && (dneg_q ? a_neg[k] : a_pos);
    assign fail_neg[k]  = !in_cur[k] && (dneg_q ? a_pos : a_neg[k]);
    assign fail_zero[k] = !in_cur[k] && a_zero_q[k];
  end

  // Two magnitude comparisons and two equalities give every relation of x to the box's columns
  // (x - 1 >= lo is x > lo, x + 1 <= hi is x < hi): a comparison is a carry chain, an equality a
  // few LUTs.
  logic cov, in_prev, in_next, left_of, right_of, empty_row, at_lo;
  logic below_lo, above_hi, on_lo, on_hi;
  if (SerialPlanes) begin : g_xrel_q
    // x moves only in a deciding clock that starts a pass (NP + 3 clocks without a decision), and
    // the first decision of a triangle comes after StBase: the relations can come from a register
    // a clock behind x, which takes their carry chains off the decision's path (docs/raster.md).
    logic [3:0] xrel_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) xrel_q <= '0;
      else         xrel_q <= {x_q < x_lo_q, x_q > x_hi_q, x_q == x_lo_q, x_q == x_hi_q};
    end
    assign {below_lo, above_hi, on_lo, on_hi} = xrel_q;
  end else begin : g_xrel
    assign below_lo  = (x_q < x_lo_q);
    assign above_hi  = (x_q > x_hi_q);
    assign on_lo     = (x_q == x_lo_q);
    assign on_hi     = (x_q == x_hi_q);
  end
  assign cov       = (&in_cur) && !below_lo && !above_hi;
  assign in_prev   = (&in_prev_e) && !below_lo && !on_lo;
  assign in_next   = (&in_next_e) && !above_hi && !on_hi;
  assign left_of   = below_lo || (|fail_pos);
  assign right_of  = above_hi || (|fail_neg);
  assign empty_row = (|fail_zero) || (left_of && right_of);
  assign at_lo     = below_lo || on_lo;  // the pixel to the left is outside the box

  // ---- Decision ---------------------------------------------------------------------------------
  typedef enum logic [2:0] {ActNone, ActLeft, ActRight, ActRowCur, ActRowSaved} act_e;
  act_e act;
  logic emit, save, can_emit, want_emit, out_valid_q, first, tnew_q;
  state_e mode_next;
  assign can_emit = !out_valid_q || frag_ready_i;

  logic start_span;  // the pixel is covered and its span's first: emit it
  // SerialPlanes: the walk stepped right past its span's end; the next row steps from the bank
  // saved at the span's first pixel (the decision's act, and the RAM's read-ahead before it).
  logic past_end;
  assign past_end = SerialPlanes && (state_q == StEmit) && !cov;
  always_comb begin
    act        = ActNone;
    want_emit  = 1'b0;
    emit       = 1'b0;
    save       = 1'b0;
    first      = 1'b0;
    start_span = 1'b0;
    mode_next  = state_q;
    unique case (state_q)
      StSeek, StSeekL, StSeekR, StBack: begin
        if ((state_q == StBack) && !cov) begin
          // Walked one column past the span's start (never an empty row: the pixel to the right is
          // covered); its first pixel is the next one.
          act = ActRight; mode_next = StSeekR;
        end else if (empty_row) begin
          act = ActRowCur;
        end else if (cov && (LookBehind ? !in_prev : ((state_q == StSeekR) || at_lo))) begin
          // Without the left look a covered pixel is known to be first when the walk arrived at it
          // moving right (from an uncovered pixel) or it is the box's first column.
          start_span = 1'b1;
        end else if (cov) begin
          act = ActLeft; mode_next = LookBehind ? StSeekL : StBack;
        end else if (left_of) begin
          if (state_q == StSeekL) act = ActRowCur;  // moved left past a span that is not there
          else begin act = ActRight; mode_next = StSeekR; end
        end else begin  // right_of
          if (state_q == StSeekR) act = ActRowCur;
          else begin act = ActLeft; mode_next = StSeekL; end
        end
      end
      StEmit: begin
        if (past_end) begin
          act = ActRowSaved;  // stepped past the span's end: the next row from its first pixel
        end else begin
          emit = 1'b1;
          act  = (SerialPlanes || in_next) ? ActRight : ActRowSaved;
        end
      end
      default: ;
    endcase
    if (start_span) begin
      emit  = 1'b1;
      first = 1'b1;
      if (SerialPlanes || in_next) begin  // (SerialPlanes: always; its pass finds the span end)
        save = 1'b1; act = ActRight; mode_next = StEmit;
      end else begin
        act = ActRowCur;
      end
    end
    if (SerialPlanes && (sweep_q || hold)) begin
      // The planes of the last step are still being stepped, or setup writes the plane RAM: no
      // decision this clock.
      act = ActNone; emit = 1'b0; save = 1'b0; first = 1'b0; mode_next = state_q;
    end
    want_emit = emit;
    if (emit && !can_emit) begin
      act  = ActNone;
      save = 1'b0;
      emit = 1'b0;
      mode_next = state_q;
    end
  end

  logic last_row;
  assign last_row = (y_q == y_hi_q);

  // ---- Steps: one adder per edge and per plane ---------------------------------------------------
  // A step to the left or right adds -/+ 256 a (256 g_x) to the edge (plane) value; a step to the
  // next row adds 256 b (256 g_y) to it or to the row's saved copy. Both go through one
  // htx_raster_addsub (two adders and a multiplexer before: 5,457 -> 3,232 LUT4 for the planes of
  // the traversal alone with the `icebreaker` widths).
  logic step_row, step_neg, step_saved;
  assign step_row   = (act == ActRowCur) || (act == ActRowSaved);
  assign step_neg   = (act == ActLeft);
  assign step_saved = (act == ActRowSaved);
  // decide: the state machine acts on act, emit and save this clock; plane_step: it moves (the edges
  // and planes step).
  logic decide, plane_step;
  assign decide     = !abort_i && (state_q != StIdle) && (state_q != StLoad) && (state_q != StBase);
  assign plane_step = decide && ((act == ActLeft) || (act == ActRight) || (step_row && !last_row));

  if (!SerialPlanes) begin : g_edges_reg
    // The edge values in registers, each stepped by an adder of its own in the deciding clock, with
    // the row's saved copy (es_q) and combinational looks at x - 1 and x + 1.
    logic signed [DW-1:0] a_q [3];
    logic signed [DW-1:0] b_q [3];
    logic signed [EW-1:0] e_q [3];
    logic signed [EW-1:0] es_q [3];
    logic signed [EW-1:0] e_next [3];
    for (genvar k = 0; k < 3; k++) begin : g_edge
      logic signed [EW-1:0] step_a, step_b, en;
      assign step_a = EW'(a_q[k]) <<< 8;
      assign step_b = EW'(b_q[k]) <<< 8;
      assign in_cur[k] = (e_q[k][EW-1] == pol[k]);
      assign en = thr_q[k] ? e_q[k] - step_a : e_q[k] + step_a;
      assign in_next_e[k] = (en[EW-1] == pol[k]);
      if (LookBehind) begin : g_prev
        logic signed [EW-1:0] ep;
        assign ep = thr_q[k] ? e_q[k] + step_a : e_q[k] - step_a;
        assign in_prev_e[k] = (ep[EW-1] == pol[k]);
      end else begin : g_no_prev
        assign in_prev_e[k] = 1'b0;
      end
      assign a_neg[k]  = a_q[k][DW-1];
      htx_raster_addsub #(.W(EW), .ZeroLsbs(8)) u_step (
        .a_i  (step_saved ? es_q[k] : e_q[k]),
        .b_i  (step_row ? step_b : step_a),
        .sub_i(step_neg ^ thr_q[k]),  // a negated edge steps the other way
        .sum_o(e_next[k])
      );
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        for (int k = 0; k < 3; k++) begin
          a_q[k] <= '0; b_q[k] <= '0; e_q[k] <= '0; es_q[k] <= '0;
        end
      end else if (abort_i) begin
        // (nothing: a new triangle loads them all)
      end else if (accept) begin
        for (int k = 0; k < 3; k++) begin
          a_q[k] <= tri_a_i[DW*k +: DW];
          b_q[k] <= tri_b_i[DW*k +: DW];
          e_q[k] <= tri_e_i[EW*k +: EW];
        end
      end else if (decide) begin
        if (save) for (int k = 0; k < 3; k++) es_q[k] <= e_q[k];
        if (plane_step) for (int k = 0; k < 3; k++) e_q[k] <= e_next[k];
      end
    end
    logic unused_esgn;
    assign unused_esgn = ^{esgn_we, esgn_d};
  end else begin : g_edges_ram
    // The edges are planes 0..2 of the plane RAM (g_planes_ser steps them); only their signs are
    // kept, as the pass writes each new value (esgn_*), and a's sign for the seek's direction
    // (a_zero_q is common). No look at x + 1: the decisions step right past a span's end instead.
    logic [2:0] sgn_q, aneg_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        sgn_q   <= '0;
        aneg_q  <= '0;
      end else if (accept) begin
        for (int k = 0; k < 3; k++) begin
          sgn_q[k]   <= tri_e_i[EW*k + EW - 1];
          aneg_q[k]  <= tri_a_i[DW*k + DW - 1];
        end
      end else begin
        for (int k = 0; k < 3; k++) if (esgn_we[k]) sgn_q[k] <= esgn_d;
      end
    end
    assign in_cur    = ~(sgn_q ^ pol);
    assign in_next_e = '0;
    assign in_prev_e = '0;
    assign a_neg     = aneg_q;
    logic [3*EW-1:0] e_rest;
    logic [3*DW-1:0] a_rest;
    for (genvar k = 0; k < 3; k++) begin : g_rest
      assign e_rest[EW*k +: EW] = {1'b0, tri_e_i[EW*k +: EW-1]};
      assign a_rest[DW*k +: DW] = {1'b0, tri_a_i[DW*k +: DW-1]};
    end
    logic unused_tri;
    assign unused_tri = ^{tri_b_i, e_rest, a_rest};
  end

  // ---- State -----------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q    <= StIdle;
      tnew_q     <= 1'b0;
      side_q     <= '0;
      x_lo_q     <= '0;
      x_hi_q     <= '0;
      x_q        <= '0;
      xs_q       <= '0;
      y_q        <= '0;
      y_hi_q     <= '0;
      thr_q      <= '0;
      dneg_q     <= 1'b0;
      a_zero_q   <= '0;
    end else if (abort_i) begin
      state_q <= StIdle;
    end else if ((state_q == StIdle) || (state_q == StLoad)) begin
      // SerialPlanes: the triangle is taken in StLoad, after the last step's planes and once the
      // last fragment has left (its side band is side_q: no copy in the output).
      if (SerialPlanes && (state_q == StIdle) && tri_valid_i && !sweep_q && !out_valid_q) begin
        state_q <= StLoad;
      end
      if (accept) begin
        tnew_q     <= 1'b1;
        side_q     <= tri_side_i;
        x_lo_q     <= XCW'(tri_x_lo_i);
        x_hi_q     <= XCW'(tri_x_hi_i);
        x_q        <= XCW'(tri_x_lo_i);
        y_q        <= tri_y_lo_i;
        y_hi_q     <= tri_y_hi_i;
        thr_q      <= tri_thr_i;
        dneg_q     <= tri_dneg_i;
        a_zero_q   <= tri_a_zero_i;
        state_q <= SerialPlanes ? StBase : StSeek;
      end
    end else if (SerialPlanes && (state_q == StBase)) begin
      state_q <= StSeek;
    end else begin
      if (emit) tnew_q <= 1'b0;
      if (save) xs_q <= x_q;
      unique case (act)
        ActLeft, ActRight: begin
          x_q <= (act == ActRight) ? x_q + 1'b1 : x_q - 1'b1;
          state_q <= mode_next;
        end
        ActRowCur, ActRowSaved: begin
          if (last_row) begin
            state_q <= StIdle;
          end else begin
            y_q        <= y_q + 1'b1;
            if (act == ActRowSaved) x_q <= xs_q;
            state_q <= StSeek;
          end
        end
        default: ;
      endcase
    end
  end

  // ---- Planes ----------------------------------------------------------------------------------
  logic out_load, out_last;  // the fragment is complete; it is its span's last
  logic [NP*AW-1:0] out_p_q;

  if (!SerialPlanes) begin : g_planes_par
    // One adder per plane: every plane steps in the clock its pixel is decided.
    logic [AW-1:0] gx_q [NP];
    logic [AW-1:0] gy_q [NP];
    logic [AW-1:0] acc_q [NP];
    logic [AW-1:0] accs_q [NP];
    logic [AW-1:0] acc_next [NP];
    for (genvar p = 0; p < NP; p++) begin : g_step
      htx_raster_addsub #(.W(AW), .ZeroLsbs(8)) u_step (
        .a_i  (step_saved ? accs_q[p] : acc_q[p]),
        .b_i  (step_row ? (gy_q[p] << 8) : (gx_q[p] << 8)),
        .sub_i(step_neg),
        .sum_o(acc_next[p])
      );
    end
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        for (int p = 0; p < NP; p++) begin
          gx_q[p] <= '0; gy_q[p] <= '0; acc_q[p] <= '0; accs_q[p] <= '0;
        end
        out_p_q <= '0;
      end else begin
        if (accept) begin
          for (int p = 0; p < NP; p++) begin
            gx_q[p]  <= tri_p_i[3*AW*p +: AW];
            gy_q[p]  <= tri_p_i[3*AW*p + AW +: AW];
            acc_q[p] <= tri_p_i[3*AW*p + 2*AW +: AW];
          end
        end
        if (decide && save) begin
          for (int p = 0; p < NP; p++) accs_q[p] <= acc_q[p];
        end
        if (plane_step) begin
          for (int p = 0; p < NP; p++) acc_q[p] <= acc_next[p];
        end
        if (decide && emit) begin
          for (int p = 0; p < NP; p++) out_p_q[AW*p +: AW] <= acc_q[p];
        end
      end
    end
    assign sweep_q   = 1'b0;
    assign hold      = 1'b0;
    assign load_last = 1'b1;
    assign out_load  = decide && emit;
    assign out_last  = !in_next;
    assign esgn_we   = '0;
    assign esgn_d    = 1'b0;
    logic unused_pl;
    assign unused_pl = ^{pl_we_i, pl_sel_i, pl_idx_i, pl_data_i};
  end else begin : g_planes_ser
    // The edges and planes in one block RAM, stepped one a clock on one adder: the three edges at
    // indices 0..2, then the NP attribute planes. Its regions (the top address bits): 1 the
    // second bank of values; 4 and 5 the start values, which setup writes into the one the current
    // triangle does not use and which are then that triangle's first bank; 2 and 3, or 6 and 7,
    // the gradients g_x and g_y (a and b of the edges), likewise a pair of regions a triangle.
    // A second read port (synthesis duplicates the block RAMs for it) reads each word's gradient
    // in the clock its value is read, so no gradient is held in registers.
    // The deciding clock only decides, and reads word 0 of the bank the step goes from with the
    // gradient of the step's direction; the NR words then follow one a clock (a pass): NR + 1
    // clocks a step. (The deciding clock had stepped word 0 itself, from a register holding it and
    // copies of its two gradients: NR clocks a step, but the decision then ran on through the
    // step's adder into the RAM in one clock, `icebreaker`'s critical path; docs/raster.md.)
    // Every pass steps (writes); a pass that leaves an emitted pixel also
    // captures its plane values into the fragment, and by its end the edges' signs tell whether the
    // next pixel is covered, that is whether the emitted one was its span's last. A row end after
    // a span steps the saved bank's values into the current one.
    // A clock in which setup writes (hold) changes nothing here.
    localparam int unsigned NR = NP + 3;
    localparam int unsigned IW = $clog2(NR);
    if (IW < 4) begin : g_idx_unused
      logic unused_idx;
      assign unused_idx = ^pl_idx_i[3:IW];
    end
    localparam logic [2:0]  RegSt = 3'd4;  // RegSt and RegSt + 1
    // Setup writes a triangle's start values and gradients into the regions of its parity, and
    // the start region is the triangle's bank 0. par_q is the parity of the triangle taken last;
    // setup's words go to the other regions (the next triangle's). Setup writes a triangle's words
    // only after the traversal took the one before.
    logic          par_q;
    function automatic logic [2:0] bank_reg(input logic b, input logic par);
      bank_reg = b ? 3'd1 : (RegSt | {2'b00, par});
    endfunction
    function automatic logic [2:0] grad_reg(input logic row, input logic par);
      grad_reg = {par, 1'b1, row};  // row 0: g_x, 1: g_y
    endfunction
    // A word is AW + 1 bits: a value at [AW-1:0], a gradient from setup at [AW:1] (the plane
    // unit's word with the bit below g, taken here by wiring).
    (* ram_style = "block" *) logic [AW:0] mem_q [2**(IW+3)];
    logic [AW-1:0] base_q;  // a value
    logic [AW:0]   grad_q;
    logic [AW-1:0] sum, grad;
    logic [IW-1:0] idx_q;
    logic [IW+2:0] raddr, graddr, waddr;
    logic          cur_q;                 // bank of the current pixel's values
    logic          rd_bank_q;             // the bank the pass reads
    logic          cap_q, row_q, neg_q;   // the pass captures, steps a row, subtracts
    logic          start_pass, active, pass_end;
    logic          loading;
    // This clock's word (a pass's), and the row flag of the gradients read now (the pass's, or in
    // the deciding clock the decision's).
    logic [IW-1:0] c_idx, n_idx;  // n_idx: the word after c_idx, which the RAM reads now
    logic          c_row;

    assign hold       = pl_we_i;
    assign loading    = (state_q == StLoad) && !hold;
    assign start_pass = !hold && !sweep_q && plane_step;
    assign active     = !hold && sweep_q;
    assign pass_end   = !hold && sweep_q && (idx_q == IW'(NR - 1));
    assign c_idx      = sweep_q ? idx_q : '0;
    assign n_idx      = c_idx + 1'b1;
    assign c_row      = sweep_q ? row_q : step_row;

    // The gradient read with the value (word 0's in the deciding clock, for the pass's first step).
    assign grad    = grad_q[AW:1];
    logic unused_grad_lsb;
    assign unused_grad_lsb = grad_q[0];  // (a value's bit in a start word)
    htx_raster_addsub #(.W(AW), .ZeroLsbs(8)) u_step (
      .a_i  (base_q[AW-1:0]),
      .b_i  (grad << 8),
      .sub_i(neg_q),  // (the pass's: only a pass steps)
      .sum_o(sum)
    );
    // The edges' new signs, as their words are written.
    for (genvar k = 0; k < 3; k++) begin : g_esgn
      assign esgn_we[k] = active && (c_idx == IW'(k));
    end
    assign esgn_d = sum[AW-1];

    // Read: in a pass its next word; otherwise word 0 of the bank a step would go from (the deciding
    // clock's read; what is read in any other clock between passes, or at a pass's end, is unused).
    assign raddr = sweep_q ? {bank_reg(rd_bank_q, par_q), n_idx}
                           : {bank_reg(step_saved ? !cur_q : cur_q, par_q), IW'(0)};
    // Write: setup's words (start values into the next triangle's region); the steps.
    logic          we;
    logic [AW:0]   wdata;
    always_comb begin
      if (hold) begin
        we    = 1'b1;
        waddr = {pl_sel_i[1] ? bank_reg(1'b0, !par_q) : grad_reg(pl_sel_i[0], !par_q),
                 IW'(pl_idx_i)};  // pl_sel_i: 0 g_x, 1 g_y, 2 start
        wdata = pl_data_i;
      end else begin
        we    = active;
        // A pass writes the current bank: the one its decision left for (save: the other one),
        // which cur_q holds from then on.
        waddr = {bank_reg(cur_q, par_q), c_idx};
        wdata = {1'b0, sum};
      end
    end
    // The gradient of the word the value port reads (the next word of the pass).
    assign graddr = {grad_reg(c_row, par_q), sweep_q ? n_idx : IW'(0)};
    always_ff @(posedge clk_i) begin
      if (we) mem_q[waddr] <= wdata;
      if (!hold) begin
        base_q <= mem_q[raddr][AW-1:0];
        grad_q <= mem_q[graddr];
      end
    end

    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        sweep_q   <= 1'b0;
        idx_q     <= '0;
        cur_q     <= 1'b0;
        rd_bank_q <= 1'b0;
        cap_q     <= 1'b0;
        row_q     <= 1'b0;
        neg_q     <= 1'b0;
        par_q     <= 1'b1;  // the first triangle's start values go to region RegSt
        out_p_q   <= '0;
      end else if (abort_i) begin
        sweep_q  <= 1'b0;
        par_q    <= 1'b1;  // setup starts over too
      end else begin
        if (state_q == StIdle) cur_q <= 1'b0;  // bank 0 holds the start values
        if (load_last) par_q <= !par_q;
        for (int p = 0; p < NP; p++) begin
          if (active && cap_q && (c_idx == IW'(p + 3))) out_p_q[AW*p +: AW] <= base_q[AW-1:0];
        end
        if (start_pass) begin
          // The pass steps as its deciding clock decided.
          sweep_q   <= 1'b1;
          idx_q     <= '0;
          rd_bank_q <= step_saved ? !cur_q : cur_q;
          cap_q     <= emit;
          row_q     <= c_row;
          neg_q     <= step_neg;
          // Leaving a span's first pixel: the step goes to the other bank, which becomes the
          // current one; the bank left behind keeps the first pixel's values for the next row.
          if (save) cur_q <= !cur_q;
        end else if (pass_end) begin
          idx_q   <= '0;
          sweep_q <= 1'b0;
        end else if (active) begin
          idx_q <= n_idx;
        end
      end
    end
    // The triangle is taken in StLoad's one clock.
    assign load_last = loading;
    // The fragment is complete when its capture pass ends; the edges' signs are the next pixel's.
    assign out_load  = pass_end && cap_q;
    assign out_last  = !cov;
    logic unused_tri_p;
    assign unused_tri_p = ^tri_p_i;
  end
  assign accept = tri_valid_i && tri_ready_o;

  // ---- Output register -------------------------------------------------------------------------
  logic [12:0]       out_x_q, out_y_q;
  logic [AddrW-1:0]  out_addr_q;
  // y * stride + x, wide enough not to wrap (x is on the screen when emitted: 0 <= x < 2^13).
  localparam int unsigned AFW = (AddrW + 1 > 27) ? AddrW + 1 : 27;
  logic [AFW-1:0]    addr_full;
  assign addr_full = AFW'(y_q) * AFW'(stride_i) + AFW'(x_q[12:0]);
  logic              out_first_q, out_last_q, out_tfirst_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      out_valid_q <= 1'b0;
      out_x_q     <= '0;
      out_y_q     <= '0;
      out_addr_q  <= '0;
      out_first_q <= 1'b0;
      out_last_q  <= 1'b0;
      out_tfirst_q <= 1'b0;
    end else if (abort_i) begin
      out_valid_q <= 1'b0;
    end else begin
      if (frag_ready_i) out_valid_q <= 1'b0;
      if (out_load) begin
        out_valid_q <= 1'b1;
        out_last_q  <= out_last;
      end
      if (emit) begin
        out_x_q     <= 13'(x_q);
        out_y_q     <= y_q;
        out_addr_q  <= ((addr_full >> AddrW) != '0) ? '1 : AddrW'(addr_full);
        out_first_q <= first;
        out_tfirst_q <= tnew_q;
      end
    end
  end

  assign tri_ready_o      = (SerialPlanes ? ((state_q == StLoad) && load_last) : (state_q == StIdle)) &&
                            !abort_i;
  assign frag_valid_o     = out_valid_q;
  assign frag_x_o         = out_x_q;
  assign frag_y_o         = out_y_q;
  assign frag_addr_o      = out_addr_q;
  assign frag_p_o         = out_p_q;
  // The triangle's side band: SerialPlanes takes the next triangle only once the output is empty,
  // so the side band needs no copy per fragment there.
  if (SerialPlanes) begin : g_side_tri
    assign frag_side_o = side_q;
  end else begin : g_side_frag
    logic [SideW-1:0] out_side_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) out_side_q <= '0;
      else if (!abort_i && emit) out_side_q <= side_q;
    end
    assign frag_side_o = out_side_q;
  end
  assign frag_first_o     = out_first_q;
  assign frag_last_o      = out_last_q;
  assign frag_tfirst_o    = out_tfirst_q;
  assign busy_o           = (state_q != StIdle) || out_valid_q || sweep_q;
  assign stall_o          = want_emit && !can_emit;
endmodule
