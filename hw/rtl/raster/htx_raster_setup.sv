// Triangle setup (docs/model.md §2, docs/raster.md): determinant, winding (a negative determinant
// swaps vertices 1 and 2: both windings are drawn), edge functions with the top-left rule, the pixel
// box clipped to the screen, 1/det from the shared reciprocal unit, and the planes of z and the
// colour channels. Edge values and plane values are delivered at the box's first pixel centre
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
  // Derived widths (docs/raster.md).
  parameter int unsigned XW   = XyIntBits + 8,   // vertex x, y (signed, 1/256 pixel)
  parameter int unsigned DW   = XW + 1,          // coordinate deltas
  parameter int unsigned EW   = 2 * DW + 2,      // edge function values
  parameter int unsigned AccZ = ZBits + GF + 2,  // z plane
  parameter int unsigned AccC = 8 + GF + 2       // colour planes
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

  // Set-up triangle to traversal; held until taken.
  output logic                 tri_valid_o,
  input  logic                 tri_ready_i,
  output logic [31:0]          tri_state_o,
  output logic [31:0]          tri_flat_rgba_o,
  output logic [12:0]          tri_x_lo_o, tri_x_hi_o, tri_y_lo_o, tri_y_hi_o,
  output logic [3*DW-1:0]      tri_a_o, tri_b_o,
  output logic [2:0]           tri_thr_o,
  output logic [3*EW-1:0]      tri_e_o,
  output logic [3*AccZ-1:0]    tri_z_o,       // {start, gy, gx}
  output logic [9*AccC-1:0]    tri_c_o,       // per channel r, g, b: {start, gy, gx}

  output logic                 busy_o,        // computing (not waiting for input or traversal)
  output logic                 stall_o,       // a finished triangle waits for traversal
  output logic                 taken_o,       // a triangle was taken from the input (pulse)
  output logic                 err_o          // a triangle asked for what is not built (pulse)
);
  localparam int unsigned DetW   = 2 * DW + 1;
  localparam int unsigned BoxW   = XW - 7;      // signed pixel index of a box bound
  localparam int unsigned ShiftW = 8;
  localparam int unsigned MsbW   = $clog2(DetW);

  typedef enum logic [2:0] {StIdle, StDet0, StDet1, StEdges, StWait, StOut} state_e;

  state_e state_q;
  logic [31:0]            st_q;
  logic signed [XW-1:0]   x_q [3];
  logic signed [XW-1:0]   y_q [3];
  logic [ZBits-1:0]       z_q [3];
  logic [31:0]            rgba_q [3];
  logic signed [DetW-1:0] det_q, p0_q;
  logic                   det_neg_q;
  logic [2:0]             edge_k_q;
  logic                   edge_half_q;
  logic signed [EW-1:0]   e_q [3];
  logic signed [EW-1:0]   e_part_q;

  // ---- Accept and check the state word --------------------------------------------------------
  logic take, state_bad;
  assign rec_ready_o = (state_q == StIdle) && !hold_i;
  assign take        = rec_valid_i && rec_ready_o;
  assign state_bad   = rec_state_i[htx_raster_reg_pkg::RASTER_STATE_TEXTURED_LSB] ||
                       (rec_state_i[htx_raster_reg_pkg::RASTER_STATE_DEPTH_FUNC_LSB +: 3] > 3'd5);
  assign taken_o     = take;
  assign err_o       = take && state_bad;

  // ---- Deltas, box -----------------------------------------------------------------------------
  logic signed [DW-1:0] dx1, dy1, dx2, dy2;
  assign dx1 = DW'(x_q[1]) - DW'(x_q[0]);
  assign dy1 = DW'(y_q[1]) - DW'(y_q[0]);
  assign dx2 = DW'(x_q[2]) - DW'(x_q[0]);
  assign dy2 = DW'(y_q[2]) - DW'(y_q[0]);

  logic signed [XW-1:0]   minx, maxx, miny, maxy;
  logic signed [BoxW-1:0] xl, xh, yl, yh;
  logic signed [BoxW-1:0] x_lo, x_hi, y_lo, y_hi;
  logic                   box_empty;
  always_comb begin
    minx = x_q[0]; maxx = x_q[0]; miny = y_q[0]; maxy = y_q[0];
    for (int i = 1; i < 3; i++) begin
      if (x_q[i] < minx) minx = x_q[i];
      if (x_q[i] > maxx) maxx = x_q[i];
      if (y_q[i] < miny) miny = y_q[i];
      if (y_q[i] > maxy) maxy = y_q[i];
    end
    // Pixel centres 256 i + 128 inside [min, max]: ceil((min - 128) / 256) .. floor((max - 128) / 256).
    xl = BoxW'((XW'(minx) + XW'(127)) >>> 8);
    xh = BoxW'((XW'(maxx) - XW'(128)) >>> 8);
    yl = BoxW'((XW'(miny) + XW'(127)) >>> 8);
    yh = BoxW'((XW'(maxy) - XW'(128)) >>> 8);
    x_lo = (xl < 0) ? '0 : xl;
    y_lo = (yl < 0) ? '0 : yl;
    x_hi = (xh > $signed(BoxW'({1'b0, width_i}) - BoxW'(1)))  ? $signed(BoxW'({1'b0, width_i}) - BoxW'(1))  : xh;
    y_hi = (yh > $signed(BoxW'({1'b0, height_i}) - BoxW'(1))) ? $signed(BoxW'({1'b0, height_i}) - BoxW'(1)) : yh;
    box_empty = (x_lo > x_hi) || (y_lo > y_hi);
  end

  // First pixel centre of the box, relative to each vertex.
  logic signed [DW-1:0] pxs, pys;
  assign pxs = (DW'(x_lo) <<< 8) + DW'(128);
  assign pys = (DW'(y_lo) <<< 8) + DW'(128);

  // Vertices after the winding swap, for the edges.
  logic signed [XW-1:0] sx [3];
  logic signed [XW-1:0] sy [3];
  assign sx[0] = x_q[0];
  assign sy[0] = y_q[0];
  assign sx[1] = det_neg_q ? x_q[2] : x_q[1];
  assign sy[1] = det_neg_q ? y_q[2] : y_q[1];
  assign sx[2] = det_neg_q ? x_q[1] : x_q[2];
  assign sy[2] = det_neg_q ? y_q[1] : y_q[2];

  logic signed [DW-1:0] ea [3];
  logic signed [DW-1:0] eb [3];
  logic [2:0]           ethr;
  for (genvar k = 0; k < 3; k++) begin : g_edge
    localparam int unsigned K1 = (k + 1) % 3;
    logic signed [DW-1:0] edx, edy;
    assign edx = DW'(sx[K1]) - DW'(sx[k]);
    assign edy = DW'(sy[K1]) - DW'(sy[k]);
    assign ea[k] = -edy;
    assign eb[k] = edx;
    // y points down and inside is E > 0: an edge going up is a left edge, a horizontal edge going
    // right a top edge; pixel centres exactly on them belong to this triangle (threshold 0).
    assign ethr[k] = !((edy < 0) || ((edy == 0) && (edx > 0)));
  end

  // ---- Determinant and edge values: one multiplier, eight products ------------------------------
  logic                     emul_start, emul_done;
  logic signed [DW-1:0]     emul_a, emul_b;
  logic signed [2*DW-1:0]   emul_p;
  logic [1:0]               ek;
  assign ek = edge_k_q[1:0];
  always_comb begin
    emul_a = '0;
    emul_b = '0;
    unique case (state_q)
      StDet0: begin emul_a = dx1; emul_b = dy2; end
      StDet1: begin emul_a = dx2; emul_b = dy1; end
      StEdges: begin
        if (!edge_half_q) begin emul_a = ea[ek]; emul_b = pxs - DW'(sx[ek]); end
        else              begin emul_a = eb[ek]; emul_b = pys - DW'(sy[ek]); end
      end
      default: ;
    endcase
  end
  assign emul_start = (state_q == StDet0) || (state_q == StDet1) || (state_q == StEdges);

  htx_raster_mul #(.AWidth(DW), .BWidth(DW), .Iterative(Iterative)) u_edge_mul (
    .clk_i, .rst_ni,
    .start_i(emul_start),
    .a_i    (emul_a),
    .b_i    (emul_b),
    .done_o (emul_done),
    .p_o    (emul_p)
  );

  logic signed [DetW-1:0] det_next;
  assign det_next = p0_q - DetW'(emul_p);

  // ---- Reciprocal of |det| ---------------------------------------------------------------------
  logic                recip_start, recip_done, recip_busy, recip_valid_q;
  logic [RecipW:0]     recip_r;
  logic [MsbW-1:0]     recip_msb;
  logic [DetW-1:0]     det_abs;
  logic [ShiftW-1:0]   grad_shift;
  logic                planes_abort;
  assign det_abs = det_next[DetW-1] ? DetW'(-det_next) : DetW'(det_next);
  assign recip_start = (state_q == StDet1) && emul_done && (det_next != 0) && !box_empty;
  assign planes_abort = abort_i || ((state_q == StDet1) && emul_done && ((det_next == 0) || box_empty));
  assign grad_shift = ShiftW'(RecipW) + ShiftW'(recip_msb) - ShiftW'(GF);

  htx_recip #(.XWidth(DetW), .W(RecipW), .K(RecipK), .G(RecipG), .Steps(NrSteps),
              .Iterative(Iterative)) u_recip (
    .clk_i, .rst_ni,
    .abort_i,
    .start_i(recip_start),
    .x_i    (det_abs),
    .busy_o (recip_busy),
    .done_o (recip_done),
    .r_o    (recip_r),
    .msb_o  (recip_msb)
  );

  // ---- Planes: z and r, g, b -------------------------------------------------------------------
  logic                 plane_start_q;
  logic [3:0]           plane_done;
  logic signed [DW-1:0] dxs, dys;
  assign dxs = pxs - DW'(x_q[0]);
  assign dys = pys - DW'(y_q[0]);

  htx_raster_plane #(.VB(ZBits), .DW(DW), .W(RecipW), .GF(GF), .Iterative(Iterative),
                     .ShiftW(ShiftW)) u_plane_z (
    .clk_i, .rst_ni,
    .abort_i      (planes_abort),
    .start_i      (plane_start_q),
    .a0_i(z_q[0]), .a1_i(z_q[1]), .a2_i(z_q[2]),
    .dx1_i(dx1), .dy1_i(dy1), .dx2_i(dx2), .dy2_i(dy2),
    .dxs_i(dxs), .dys_i(dys),
    .recip_valid_i(recip_valid_q),
    .r_i          (recip_r),
    .shift_i      (grad_shift),
    .det_neg_i    (det_neg_q),
    .done_o       (plane_done[0]),
    .gx_o         (tri_z_o[0 +: AccZ]),
    .gy_o         (tri_z_o[AccZ +: AccZ]),
    .start_o      (tri_z_o[2*AccZ +: AccZ])
  );

  for (genvar c = 0; c < 3; c++) begin : g_color_plane
    htx_raster_plane #(.VB(8), .DW(DW), .W(RecipW), .GF(GF), .Iterative(Iterative),
                       .ShiftW(ShiftW)) u_plane (
      .clk_i, .rst_ni,
      .abort_i      (planes_abort),
      .start_i      (plane_start_q),
      .a0_i(rgba_q[0][8*c +: 8]), .a1_i(rgba_q[1][8*c +: 8]), .a2_i(rgba_q[2][8*c +: 8]),
      .dx1_i(dx1), .dy1_i(dy1), .dx2_i(dx2), .dy2_i(dy2),
      .dxs_i(dxs), .dys_i(dys),
      .recip_valid_i(recip_valid_q),
      .r_i          (recip_r),
      .shift_i      (grad_shift),
      .det_neg_i    (det_neg_q),
      .done_o       (plane_done[c+1]),
      .gx_o         (tri_c_o[3*AccC*c +: AccC]),
      .gy_o         (tri_c_o[3*AccC*c + AccC +: AccC]),
      .start_o      (tri_c_o[3*AccC*c + 2*AccC +: AccC])
    );
  end

  // ---- Sequencer -------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q       <= StIdle;
      st_q          <= '0;
      for (int i = 0; i < 3; i++) begin
        x_q[i] <= '0; y_q[i] <= '0; z_q[i] <= '0; rgba_q[i] <= '0; e_q[i] <= '0;
      end
      det_q         <= '0;
      p0_q          <= '0;
      det_neg_q     <= 1'b0;
      edge_k_q      <= '0;
      edge_half_q   <= 1'b0;
      e_part_q      <= '0;
      plane_start_q <= 1'b0;
      recip_valid_q <= 1'b0;
    end else if (abort_i) begin
      state_q       <= StIdle;
      plane_start_q <= 1'b0;
      recip_valid_q <= 1'b0;
    end else begin
      plane_start_q <= 1'b0;
      if (recip_done) recip_valid_q <= 1'b1;
      unique case (state_q)
        StIdle: if (take && !state_bad) begin
          st_q <= rec_state_i;
          for (int i = 0; i < 3; i++) begin
            x_q[i]    <= rec_x_i[XW*i +: XW];
            y_q[i]    <= rec_y_i[XW*i +: XW];
            z_q[i]    <= rec_z_i[ZBits*i +: ZBits];
            rgba_q[i] <= rec_rgba_i[32*i +: 32];
          end
          plane_start_q <= 1'b1;
          recip_valid_q <= 1'b0;
          state_q       <= StDet0;
        end
        StDet0: if (emul_done) begin p0_q <= DetW'(emul_p); state_q <= StDet1; end
        StDet1: if (emul_done) begin
          det_q     <= det_next;
          det_neg_q <= det_next[DetW-1];
          edge_k_q  <= '0;
          edge_half_q <= 1'b0;
          state_q   <= ((det_next == 0) || box_empty) ? StIdle : StEdges;
        end
        StEdges: if (emul_done) begin
          if (!edge_half_q) begin
            e_part_q    <= EW'(emul_p);
            edge_half_q <= 1'b1;
          end else begin
            e_q[ek]     <= e_part_q + EW'(emul_p);
            edge_half_q <= 1'b0;
            edge_k_q    <= edge_k_q + 1'b1;
            if (ek == 2'd2) state_q <= StWait;
          end
        end
        StWait: if (&plane_done) state_q <= StOut;
        StOut: if (tri_ready_i) state_q <= StIdle;
        default: state_q <= StIdle;
      endcase
    end
  end

  // ---- Outputs ---------------------------------------------------------------------------------
  logic unused;
  assign unused = ^{det_q, recip_busy, rec_state_i};

  assign tri_valid_o     = (state_q == StOut);
  assign tri_state_o     = st_q;
  assign tri_flat_rgba_o = rgba_q[0];  // vertex 0 is never reordered
  assign tri_x_lo_o      = 13'(x_lo);
  assign tri_x_hi_o      = 13'(x_hi);
  assign tri_y_lo_o      = 13'(y_lo);
  assign tri_y_hi_o      = 13'(y_hi);
  for (genvar k = 0; k < 3; k++) begin : g_edge_out
    assign tri_a_o[DW*k +: DW] = ea[k];
    assign tri_b_o[DW*k +: DW] = eb[k];
    assign tri_e_o[EW*k +: EW] = e_q[k];
  end
  assign tri_thr_o = ethr;
  assign busy_o    = (state_q != StIdle) && (state_q != StOut);
  assign stall_o   = (state_q == StOut) && !tri_ready_i;
endmodule
