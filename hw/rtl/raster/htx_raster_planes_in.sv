// Plane-record reader (FwSetup, the `icebreaker` configuration; docs/raster.md, "Plane record"):
// in place of the input stage and setup, it takes triangles that the firmware has set up
// (firmware/lib htx/fw/plane_record.h). It pops the record from the FIFO a word every two clocks,
// keeps the header for the traversal, writes each plane pair into the traversal's plane RAM as it
// arrives (the next triangle's regions, as setup would), and hands the triangle over at the pair
// marked LAST. It starts a record only when the traversal has taken the last one and no clear is
// pending. A record whose state word the build refuses, or whose box is empty or leaves the
// screen, is read to its end, writes nothing, draws nothing and raises ERR_STATE.
module htx_raster_planes_in #(
  parameter logic [4:0]  Methods = 5'b00101,
  parameter int unsigned DW      = 21,   // edge coefficients (only their signs go out)
  parameter int unsigned EW      = 44,   // edge values (likewise)
  parameter int unsigned AW      = 55,   // plane-RAM values; a word is AW + 1 bits (at most 56)
  parameter int unsigned GradW   = 16,   // DIVFREE's side band: LOD gradients ...
  parameter int unsigned GWU     = 77    // ... and the six gradients at full precision
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               abort_i,
  input  logic               enable_i,
  input  logic               hold_i,        // a clear is pending: start no record
  input  logic [12:0]        width_i,
  input  logic [12:0]        height_i,

  input  logic               fifo_empty_i,  // nothing to pop
  output logic               fifo_pop_o,
  input  logic [31:0]        fifo_rdata_i,  // the popped word, a clock after the pop

  output logic               tri_valid_o,
  input  logic               tri_ready_i,
  output logic [31:0]        tri_state_o,
  output logic [31:0]        tri_flat_rgba_o,
  output logic [12:0]        tri_x_lo_o, tri_x_hi_o, tri_y_lo_o, tri_y_hi_o,
  output logic [3*DW-1:0]    tri_a_o,       // only the signs are set
  output logic [2:0]         tri_a_zero_o,
  output logic [2:0]         tri_thr_o,
  output logic               tri_dneg_o,
  output logic [3*EW-1:0]    tri_e_o,       // only the signs are set
  output logic [31:0]        tri_u_off_o, tri_v_off_o,
  output logic [6*GradW-1:0] tri_lod_g_o,
  output logic [7:0]         tri_lod_shift_o,
  output logic [6*GWU-1:0]   tri_dfg_o,

  output logic               pl_we_o,
  output logic [1:0]         pl_sel_o,
  output logic [3:0]         pl_idx_o,
  output logic [AW:0]        pl_data_o,

  output logic               busy_o,        // inside a record
  output logic               stall_o,       // a triangle waits for the traversal
  output logic               partial_o,     // inside a record, and the FIFO has no word
  output logic               taken_o,       // a record's state word arrived (pulse)
  output logic               err_o          // a record refused (pulse)
);
  localparam bit          HasDf     = Methods[htx_raster_pkg::MethodDivFree];
  localparam int unsigned SideBits  = 6 * GradW + 8 + 6 * GWU;
  localparam int unsigned SideWords = 18;  // plane_record.h kPlaneSideWords

  // Where in the record the next word goes: the header's words 0..6, DIVFREE's side band, then
  // plane pairs (low word, high word) to the end.
  typedef enum logic [1:0] {PhHead, PhSide, PhPlanes} phase_e;
  phase_e      phase_q;
  logic        in_rec_q;   // a record's state word has arrived and its LAST pair has not
  logic        pend_q;     // a word popped last clock is on fifo_rdata_i
  logic [4:0]  cnt_q;      // the header's word, or the side band's
  logic        half_q;     // the low word of a pair is in lo_q
  logic        drop_q;     // the record is refused
  logic        valid_q;
  logic [31:0] lo_q;
  logic [31:0] st_q, flat_q, u_off_q, v_off_q;
  logic [12:0] x_lo_q, x_hi_q, y_lo_q, y_hi_q;
  logic [12:0] flags_q;

  // One word every two clocks (no pop while a popped word is on its way), so the reader never
  // pops a word past the record's end. A record starts only once the last one was taken.
  assign fifo_pop_o = enable_i && !abort_i && !fifo_empty_i && !pend_q && !valid_q &&
                      (in_rec_q || !hold_i);

  // The box words: lo [12:0] <= hi [28:16] < the screen's size.
  logic [12:0] w_lo, w_hi, w_lim;
  logic        box_ok;
  assign w_lo   = fifo_rdata_i[12:0];
  assign w_hi   = fifo_rdata_i[28:16];
  assign w_lim  = (cnt_q == 5'd2) ? width_i : height_i;
  assign box_ok = (w_lo <= w_hi) && (w_hi < w_lim);

  logic state_bad;  // of the word on fifo_rdata_i, taken as a state word
  htx_raster_state_check #(.Methods(Methods)) u_state_check (.state_i(fifo_rdata_i), .bad_o(state_bad));

  logic got_state, got_pair, got_last;
  assign got_state = pend_q && !in_rec_q;
  assign got_pair  = pend_q && in_rec_q && (phase_q == PhPlanes) && half_q;
  assign got_last  = got_pair && fifo_rdata_i[31];

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      phase_q  <= PhHead;
      in_rec_q <= 1'b0;
      pend_q   <= 1'b0;
      cnt_q    <= '0;
      half_q   <= 1'b0;
      drop_q   <= 1'b0;
      valid_q  <= 1'b0;
    end else if (abort_i) begin
      phase_q  <= PhHead;
      in_rec_q <= 1'b0;
      pend_q   <= 1'b0;
      half_q   <= 1'b0;
      valid_q  <= 1'b0;
    end else begin
      pend_q <= fifo_pop_o;
      if (valid_q && tri_ready_i) valid_q <= 1'b0;
      if (got_state) begin
        in_rec_q <= 1'b1;
        phase_q  <= PhHead;
        cnt_q    <= 5'd1;
        half_q   <= 1'b0;
        drop_q   <= state_bad;
      end else if (pend_q) begin
        unique case (phase_q)
          PhHead: begin
            if (((cnt_q == 5'd2) || (cnt_q == 5'd3)) && !box_ok) drop_q <= 1'b1;
            cnt_q <= cnt_q + 5'd1;
            if (cnt_q == 5'd6) begin
              cnt_q   <= '0;
              phase_q <= (st_q[htx_raster_reg_pkg::RASTER_STATE_METHOD_LSB +: 3] ==
                          htx_raster_pkg::MethodDivFree) ? PhSide : PhPlanes;
            end
          end
          PhSide: begin
            cnt_q <= cnt_q + 5'd1;
            if (cnt_q == 5'(SideWords - 1)) phase_q <= PhPlanes;
          end
          default: begin
            half_q <= !half_q;
            if (got_last) begin
              in_rec_q <= 1'b0;
              phase_q  <= PhHead;
              valid_q  <= !drop_q;
            end
          end
        endcase
      end
    end
  end

  // The header (no reset: every record writes it before the triangle goes out).
  logic head;
  assign head = pend_q && in_rec_q && (phase_q == PhHead);
  always_ff @(posedge clk_i) begin
    if (got_state) st_q <= fifo_rdata_i;
    if (head && (cnt_q == 5'd1)) flat_q <= fifo_rdata_i;
    if (head && (cnt_q == 5'd2)) begin x_lo_q <= w_lo; x_hi_q <= w_hi; end
    if (head && (cnt_q == 5'd3)) begin y_lo_q <= w_lo; y_hi_q <= w_hi; end
    if (head && (cnt_q == 5'd4)) flags_q <= fifo_rdata_i[12:0];
    if (head && (cnt_q == 5'd5)) u_off_q <= fifo_rdata_i;
    if (head && (cnt_q == 5'd6)) v_off_q <= fifo_rdata_i;
    if (pend_q && in_rec_q && (phase_q == PhPlanes) && !half_q) lo_q <= fifo_rdata_i;
  end

  // DIVFREE's side band, shifted in LSB first; zero for a record of another method, whose side band
  // (the texture port's LOD inputs) is then zero, as where nothing computes it. (The texture unit
  // beside a FwSetup raster takes no LOD inputs, docs/raster.md "Plane record".)
  if (HasDf) begin : g_side
    logic [32*SideWords-1:0] side_q;
    always_ff @(posedge clk_i) begin
      if (got_state) side_q <= '0;
      else if (pend_q && in_rec_q && (phase_q == PhSide)) side_q <= {fifo_rdata_i, side_q[32*SideWords-1:32]};
    end
    assign tri_lod_g_o     = side_q[0 +: 6*GradW];
    assign tri_lod_shift_o = side_q[6*GradW +: 8];
    assign tri_dfg_o       = side_q[6*GradW + 8 +: 6*GWU];
    logic unused_side;
    assign unused_side = ^side_q[32*SideWords-1:SideBits];
  end else begin : g_no_side
    assign tri_lod_g_o     = '0;
    assign tri_lod_shift_o = '0;
    assign tri_dfg_o       = '0;
  end

  // A pair's high word: data [55:32] in [23:0], index [27:24], select [29:28], LAST [31].
  logic [55:0] pair;
  assign pair      = {fifo_rdata_i[23:0], lo_q};
  assign pl_we_o   = got_pair && !drop_q;
  assign pl_sel_o  = fifo_rdata_i[29:28];
  assign pl_idx_o  = fifo_rdata_i[27:24];
  assign pl_data_o = pair[AW:0];

  assign tri_valid_o     = valid_q;
  assign tri_state_o     = st_q;
  assign tri_flat_rgba_o = flat_q;
  assign tri_x_lo_o      = x_lo_q;
  assign tri_x_hi_o      = x_hi_q;
  assign tri_y_lo_o      = y_lo_q;
  assign tri_y_hi_o      = y_hi_q;
  assign tri_thr_o       = flags_q[2:0];
  assign tri_a_zero_o    = flags_q[8:6];
  assign tri_dneg_o      = flags_q[12];
  for (genvar k = 0; k < 3; k++) begin : g_signs
    assign tri_a_o[DW*k +: DW] = {flags_q[3 + k], {(DW-1){1'b0}}};
    assign tri_e_o[EW*k +: EW] = {flags_q[9 + k], {(EW-1){1'b0}}};
  end
  assign tri_u_off_o = u_off_q;
  assign tri_v_off_o = v_off_q;

  assign busy_o    = in_rec_q;
  assign stall_o   = valid_q && !tri_ready_i;
  assign partial_o = in_rec_q && fifo_empty_i;
  assign taken_o   = got_state;
  assign err_o     = got_last && drop_q;

  logic unused;
  assign unused = ^{fifo_rdata_i[30], pair};
endmodule
